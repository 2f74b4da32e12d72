// subsurface-scale, in words: the about text, the verdict, the statistics table and the picture described.
import { declareFormula, texNumber, texSignificant } from '../../core/framework/formula-registry.js';
import { meanFreePath, scatteringAlbedo } from '../../math/media.js';
import { MAX_EVENTS, isLocal } from './model.js';

export const TITLE = 'Subsurface scale';

export const ABOUT =
  'Each path is light that entered at the marked point and was scattered until it left the surface again ' +
  '(the yellow ticks) or was absorbed on the way (paths fade with the light they still carry). When the shading ' +
  'sample (a pixel’s footprint on the surface) is much wider than these distances, the light may as well come ' +
  'out where it went in: shading stays local and a diffuse term is enough. Shrink the sample, or lower the ' +
  'scattering, and more of the light leaves outside it: then subsurface scattering has to be rendered. The walks ' +
  'are a flatland illustration: scattering is isotropic and the surface has no Fresnel boundary, so a path ' +
  'leaves the moment it crosses it; the share that comes back out is that model’s, not a material’s diffuse albedo.';

/** The verdict on the shading sample, in a sentence. */
export function verdictWords(stats) {
  const share = `${(stats.insideShare * 100).toFixed(1)}%`;
  return isLocal(stats)
    ? `${share} of the light that comes back out leaves inside the shading sample: treat it as local, a diffuse ` +
        'term is enough.'
    : `Only ${share} of the light that comes back out leaves inside the shading sample: the rest appears ` +
        'elsewhere, so subsurface scattering is needed.';
}

/** The picture described for screen readers. */
export const describeWalks = (s, stats) =>
  `${s.walks} light paths in a material with scattering ${s.sigmaS}/mm and absorption ${s.sigmaA}/mm, entering ` +
  `at one point; median entry-to-exit distance ${stats.median.toFixed(2)} mm against a shading sample of radius ` +
  `${s.pixel} mm. ${verdictWords(stats)}`;

/** The statistics table (HTML). */
export function statisticsTable(s, stats) {
  const rows = [
    ['mean free path 1/σt', `${meanFreePath(s.sigmaS + s.sigmaA).toFixed(3)} mm`],
    ['single-scattering albedo σs/σt', scatteringAlbedo(s.sigmaS, s.sigmaA).toFixed(3)],
    [
      'light that comes back out of this 2-D slab (isotropic scattering, no refraction at the surface: not a real ' +
        'material’s diffuse albedo)',
      `${(stats.reflectance * 100).toFixed(1)}%`,
    ],
    ['median / mean entry-to-exit distance', `${stats.median.toFixed(3)} / ${stats.mean.toFixed(3)} mm`],
    [`paths still inside after ${MAX_EVENTS} events (not counted)`, `${(stats.stuck * 100).toFixed(2)}%`],
  ];
  return (
    '<table class="data-table compact"><caption>From 20 000 paths</caption><tbody>' +
    rows.map(([what, value]) => `<tr><td>${what}</td><td>${value}</td></tr>`).join('') +
    '</tbody></table>'
  );
}

/** The walk's coefficients: extinction, mean free path and single-scattering albedo, against the sample radius. */
export const FORMULA = declareFormula('subsurface-scale', (state) => {
  const sigmaT = state.sigmaS + state.sigmaA;
  const s = `\\sym{sigmaS}{${texSignificant(state.sigmaS)}}`;
  const a = `\\sym{sigmaA}{${texSignificant(state.sigmaA)}}`;
  const t =
    `\\sigma_t = \\sigma_s + \\sigma_a = ${s} + ${a} = ${texSignificant(sigmaT)}\\ \\mathrm{mm}^{-1},\\quad ` +
    `\\ell = \\frac{1}{\\sigma_t} = ${texSignificant(meanFreePath(sigmaT))}\\ \\mathrm{mm}`;
  const albedo =
    `\\varrho = \\frac{\\sigma_s}{\\sigma_t} = ${texNumber(scatteringAlbedo(state.sigmaS, state.sigmaA))},\\quad ` +
    `\\sym{pixel}{r_{\\text{sample}} = ${texSignificant(state.pixel)}\\ \\mathrm{mm}} = ` +
    `${texSignificant(state.pixel * sigmaT)}\\,\\ell`;
  return `\\begin{gathered}${t}\\\\ ${albedo}\\end{gathered}`;
});
