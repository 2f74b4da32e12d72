// The graders (metrics) an exercise file can name. Each computes the right answer from src/math at the moment
// of checking, from its params and the widget's state, and says what is off and by how much.
//
// A grader declares:
//   answer    { kind: 'state' }: the student answers by moving the widget (the keys in `reads`);
//             { kind: 'number', label, unit }: typed into a box; { kind: 'choice', choices(params) }: picked.
//   widget    the widget it reads (null: any widget, or none); reads: state keys the student sets (left free);
//             given: state keys that pose the question (must be locked); requires: locked values it assumes.
//   params    a state-style schema (src/core/framework/state.js) for the file's "params"; `required: true` has no
//             default.
//   tolerance what the file's "tolerance" (a positive number) means.
//   grade({ state, answer, params, tolerance, hidden }) → { ok, summary, details: [text] }
//   hide(params, random) → the secret part of the question, drawn when the exercise opens (optional).
//
// One file per grader in graders/ (its helpers beside it, the feedback's wording in graders/feedback.js); this
// module lists them by the name an exercise file gives.
import { fmt } from './graders/feedback.js';
import { grader as transmittanceDepth } from './graders/transmittance-depth.js';
import { grader as fresnelReflectanceAngle } from './graders/fresnel-reflectance-angle.js';
import { materialSphere, grader as sphereMatch } from './graders/sphere-match.js';
import { grader as smithG1 } from './graders/smith-g1.js';
import { grader as albedoLoss } from './graders/albedo-loss.js';
import { grader as multipleScatteringGain } from './graders/multiple-scattering-gain.js';
import { grader as lightZone } from './graders/light-zone.js';
import { schlickWorstAngle, grader as schlickWorstAngleGrader } from './graders/schlick-worst-angle.js';
import { NDF_NAMES, highlightSphere, ndfProfiles, profileFactor, grader as ndfProfile } from './graders/ndf-profile.js';
import { grader as visibilityRatio } from './graders/visibility-ratio.js';
import { grader as lambertRadiance } from './graders/lambert-radiance.js';
import { grader as f82SchlickGap } from './graders/f82-schlick-gap.js';
import { grader as highlightStretch } from './graders/highlight-stretch.js';
import { grader as anisoPair } from './graders/aniso-pair.js';
import { grader as openPbrLayer } from './graders/openpbr-layer.js';

export const GRADERS = {
  'transmittance-depth': transmittanceDepth,
  'fresnel-reflectance-angle': fresnelReflectanceAngle,
  'sphere-match': sphereMatch,
  'smith-g1': smithG1,
  'albedo-loss': albedoLoss,
  'multiple-scattering-gain': multipleScatteringGain,
  'light-zone': lightZone,
  'schlick-worst-angle': schlickWorstAngleGrader,
  'ndf-profile': ndfProfile,
  'visibility-ratio': visibilityRatio,
  'lambert-radiance': lambertRadiance,
  'f82-schlick-gap': f82SchlickGap,
  'highlight-stretch': highlightStretch,
  'aniso-pair': anisoPair,
  'openpbr-layer': openPbrLayer,
};

export const isGraderName = (name) => Object.hasOwn(GRADERS, name);

export { fmt, materialSphere, schlickWorstAngle, NDF_NAMES, highlightSphere, ndfProfiles, profileFactor };
