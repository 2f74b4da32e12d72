// @ts-check
// A page entry of its own, for a page whose script does not typeset its formulas (chapter.js does): the page's
// data-tex elements become MathML (src/core/framework/formulas.js).
import { typesetFormulas } from './formulas.js';

typesetFormulas();
