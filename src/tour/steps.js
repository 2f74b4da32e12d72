// The guided tour as plain data: one step per idea of the talk, in its order. A step names the widget that
// shows the idea and the state that sets it up (only the keys that matter: the rest take the widget's
// defaults, so a step looks the same however the reader arrived). Its id is its URL: tour.html#<id>. A step
// whose words are about a view further down its widget names it in `look` (a selector within the widget): the
// tour scrolls it into sight under the step's words.
//
// The steps are in steps/, one file per section (a chapter's key), in order there; a step's `section` is its
// file's. To extend the tour, add steps to their section's file; nothing else changes. A step whose widget is not
// registered yet is left out, and a section without steps is shown as "coming".
import { CHAPTERS } from '../widgets/chapters.js';
import { STEPS as MEDIA } from './steps/media.js';
import { STEPS as SURFACES } from './steps/surfaces.js';
import { STEPS as BRDF } from './steps/brdf.js';
import { STEPS as MICROFACETS } from './steps/microfacets.js';
import { STEPS as FRESNEL } from './steps/fresnel.js';
import { STEPS as NDF } from './steps/ndf.js';
import { STEPS as VISIBILITY } from './steps/visibility.js';
import { STEPS as DIFFUSE } from './steps/diffuse.js';
import { STEPS as RENDERING } from './steps/rendering.js';
import { STEPS as TODAY } from './steps/today.js';

/** The talk's sections the tour walks through, in order (the performance chapter is not part of the talk). */
export const TOUR_SECTIONS = CHAPTERS.filter((c) => c.key !== 'performance').map(({ key, title }) => ({ key, title }));

/** Each section's steps, in the files of steps/, one per section. */
const STEPS_BY_SECTION = {
  media: MEDIA,
  surfaces: SURFACES,
  brdf: BRDF,
  microfacets: MICROFACETS,
  fresnel: FRESNEL,
  ndf: NDF,
  visibility: VISIBILITY,
  diffuse: DIFFUSE,
  rendering: RENDERING,
  today: TODAY,
};

/** Every step in the talk's order, each with the key of its section. */
export const TOUR_STEPS = TOUR_SECTIONS.flatMap(({ key }) =>
  (STEPS_BY_SECTION[key] ?? []).map(({ id, ...step }) => ({ id, section: key, ...step })),
);

/**
 * The tour as shown: the steps whose widget `isAvailable(name)`, and every section with the index of its
 * first step and its number of steps (0: "coming").
 */
export function tourPlan(isAvailable, steps = TOUR_STEPS, sections = TOUR_SECTIONS) {
  const live = steps.filter((s) => isAvailable(s.widget));
  return {
    steps: live,
    sections: sections.map((sec) => {
      const first = live.findIndex((s) => s.section === sec.key);
      return { ...sec, first, count: live.filter((s) => s.section === sec.key).length };
    }),
  };
}
