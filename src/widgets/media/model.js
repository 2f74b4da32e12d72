// media's model, as pure functions: the glasses the tracer draws, and the light a depth of a medium lets through.
import { transmittance } from '../../math/media.js';
import { MEDIA } from './schema.js';

// the talk's grid: absorption (more in blue: a red look) grows upwards, scattering to the right, so the
// milk-like glass (high scattering, low absorption) sits at the lower right as on the talk's slide
const GRID_ABSORB = [0, 1.5, 6].map((k) => [0.15 * k, 0.8 * k, 1.4 * k]);
const GRID_SCATTER = [0, 3, 40];

/** The depths the transmittance plot is drawn at: a millimetre to a hundred metres, evenly on a log scale. */
export const DISTANCES = Float64Array.from({ length: 241 }, (_, i) => 10 ** (-3 + i * (5 / 240)));

/** Glasses across and up: the grid's 3 × 3, or one. */
export const cellLayout = (state) => (state.view === 'grid' ? [3, 3] : [1, 1]);

/** Each glass's { sigmaA, sigmaS } per RGB channel, per unit depth of the drawn cube; cell 0 at the bottom left. */
export function cellsFor(state) {
  if (state.view === 'grid') {
    return GRID_ABSORB.flatMap((a) => GRID_SCATTER.map((sc) => ({ sigmaA: a, sigmaS: [sc, sc, sc] })));
  }
  const m = MEDIA[state.medium];
  const d = 10 ** state.distance;
  return [{ sigmaA: m.sigmaA.map((x) => x * d), sigmaS: m.sigmaS.map((x) => x * d) }];
}

/** σt = σa + σs per RGB channel of a medium. */
export const extinction = (medium) => medium.sigmaA.map((a, i) => a + medium.sigmaS[i]);

/** The share of light per RGB channel that passes `depth` metres of `medium` neither absorbed nor scattered. */
export const unscattered = (medium, depth) => extinction(medium).map((sigma) => transmittance(sigma, depth));

/** The transmittance curves over DISTANCES, one per RGB channel. */
export const transmittanceCurves = (medium) =>
  extinction(medium).map((sigma) => DISTANCES.map((x) => transmittance(sigma, x)));
