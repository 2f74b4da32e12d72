// The measured-BRDF widget in words: the about text, the captions of its images, the status of the fits and
// the table, and the pictures described for screen readers.
import { declareFormula, texNumber, texText } from '../../core/framework/formula-registry.js';
import { termEntry } from '../../math/catalogue/index.js';
import { FIT_MODELS } from '../../measured/fit.js';
import { MERL_TEXTURE_BYTES } from './texture-size.js';
import { bestFit } from './model.js';

export const TITLE = 'Measured BRDF';

const MB = (bytes) => `${(bytes / 1e6).toFixed(1)} MB`;
const label = (model) => FIT_MODELS[model].label;

export const ABOUT =
  'Drop a file from the MERL BRDF database (Matusik et al. 2003; not shipped here) or keep a synthetic example. ' +
  'It is drawn as a lobe in the plane of incidence, as a 3-D lobe (green channel; drag to orbit) and on spheres. ' +
  'The five models of the talk are fitted to it in the background, each with Schlick Fresnel and a Lambert ' +
  'diffuse per colour channel (an example’s fits were made ahead by the same fitter, so they show at once). ' +
  'The log plot of the NDF slice shows whether a model’s tail follows the data: ' +
  'on real materials GGX, ABC and shifted gamma keep up where Beckmann and Blinn-Phong fall away (Löw et al. ' +
  `2012, Bagher et al. 2012). Each table is a 3-D texture of ${MB(MERL_TEXTURE_BYTES)} on the GPU.`;

export const LOBE_3D_EMPTY = '3-D lobe of the measured table: no table yet (drop a file, or wait for the example).';
export const IMAGE_TITLE = 'Measured (G) over (θh, θd)';
export const residualTitle = (model) => `${label(model)}: |∛f_fit − ∛f_meas|`;

/** The (θh, θd) image's caption at φd = phiD°, with or without a table. */
export const imageCaption = (hasTable, phiD) =>
  hasTable ? `green channel at φd ${phiD}°` : `no table yet (at φd ${phiD}°)`;

/** A residual image's caption: of the fit of `model` at φd = phiD°, or that it is not fitted yet. */
export const residualCaption = (model, fitted, phiD) =>
  fitted
    ? `residual of the ${label(model)} fit at φd ${phiD}° (green; between nodes it holds the table's ` +
      'interpolation error too), one scale for all five'
    : `not fitted yet (at φd ${phiD}°)`;

/** The 3-D lobe described: the table, the fit overlaid (if any), the light, the scale. */
export function describeLobe3d(fit, lightTheta, max) {
  const fitWords = fit ? ` and the ${label(fit.model)} fit (wireframe)` : '';
  return (
    `3-D lobe of the measured table's green channel (solid)${fitWords}, light ${lightTheta}° ` +
    `from n; each direction's distance from the centre is f, scaled to ${max.toPrecision(3)} /sr.`
  );
}

/** The widget described: the table shown, the fits so far, the spheres. */
export function describeMeasured({ fits, sourceWords }, state) {
  const best = bestFit(fits);
  const bestWords = best ? `; best: ${label(best.model)}, error ${best.error.toExponential(2)}` : '';
  const fitted = `${Object.keys(fits).length} of 5 models fitted${bestWords}`;
  return (
    `${sourceWords || 'No table yet'}: ${fitted}. ` +
    `Spheres: the measured table (left) and the ${label(state.overlay)} fit (right) ` +
    `under a light ${state.sphereLight}° from the view, exposure ${state.exposure}.`
  );
}

/** What the drop zone says of a table read: its source, how long the worker took, how many nodes are missing. */
export const tableReadWords = (words, { ms, missing }) =>
  `${words}. Read in ${ms.toFixed(0)} ms in a worker; ${(missing / 3).toLocaleString('en')} ` +
  'of 1,458,000 nodes per channel missing (below the horizon or not measured).';

/** The status line of an example, whose fits were made ahead (scripts/example-fits.js). */
export const shippedFitsWords = '5 fits made ahead with the same fitter; a file you drop is fitted here, live';

/** The progress line while fitting: the model under way, or the time all five took. */
export const fitStatusWords = (done, running, seconds) =>
  running ? `fitting ${label(running)} (${done} of 5 done)…` : `5 fits in ${seconds.toFixed(1)} s`;

/** Why a file is refused before it is read: larger than a MERL file. */
export function tooLargeWords(file, limitBytes) {
  const [size, limit] = [file.size, limitBytes].map((n) => n.toLocaleString('en'));
  return `${file.name}: ${size} bytes, more than a MERL file’s ${limit}. The BRDF shown before is kept.`;
}

const CUBE_ROOT = (which) => `(f_{\\text{${which}}}\\cos\\theta)^{1/3}`;

/** The model fitted per channel (src/measured/fit.js), with the overlaid fit's D and V, and the error it minimises. */
export const FORMULA = declareFormula('measured-brdf', (state) => {
  const m = FIT_MODELS[state.overlay];
  const V = texText(termEntry('visibility', m.V).short);
  const f =
    `f_c(\\mathbf{l},\\mathbf{v}) = \\frac{c_{\\text{diff},c}}{\\pi} + ` +
    `\\frac{F_{\\text{Schlick}}(F_{0,c},` +
    ` \\mathbf{l}\\cdot\\mathbf{h})\\,V_{${V}}\\,\\sym{overlay}{D_{\\text{${m.label}}}}(\\mathbf{h})}{4}`;
  const error =
    `E = \\sqrt{\\frac{\\sum w\\left[${CUBE_ROOT('model')} - ${CUBE_ROOT('measured')}\\right]^2}{\\sum w}}` +
    `,\\quad \\sym{lightTheta}{\\theta_l = ${texNumber(state.lightTheta, 0)}^\\circ}`;
  return `\\begin{gathered}${f}\\\\ ${error}\\end{gathered}`;
});
