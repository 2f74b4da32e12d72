// The white furnace's numbers, from src/math only: for each roughness of the sweep, the directional albedo
// E(θv) with F = 1 (GGX, height-correlated Smith), the energy lost 1 − E, E head-on and its average.
import { albedoGGX, averageAlbedo } from '../../math/integrate.js';
import { DEG } from '../../math/angles.js';
import { seriesStyle } from '../../core/ui/palettes.js';

export const ANGLES = Float64Array.from({ length: 90 }, (_, i) => i + 0.5); // view angles 0.5°..89.5°

// the plots' curves: 24 Gauss-Legendre nodes per piece, within 2e-5 of the adaptive quadrature (unit-tested)
const PLOT_QUADRATURE = { nodes: 24 };

/** Per chosen α, smallest first: { alpha, E and loss over ANGLES, avg, atNormal, stroke, dash }. */
export function albedoSweep(state) {
  return state.alphas
    .map(Number)
    .sort((a, b) => a - b)
    .map((alpha, i) => {
      const E = ANGLES.map((deg) => albedoGGX(Math.cos(deg * DEG), alpha, {}, PLOT_QUADRATURE));
      const avg = averageAlbedo((mu) => albedoGGX(mu, alpha));
      return { alpha, E, loss: E.map((e) => 1 - e), avg, ...seriesStyle(i), atNormal: albedoGGX(1, alpha) };
    });
}
