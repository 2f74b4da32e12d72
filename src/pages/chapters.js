// The chapters, for the pages: the data lives in src/widgets/chapters.js, a room below the exercises and the tour,
// which read it too.
export { CHAPTERS } from '../widgets/chapters.js';
