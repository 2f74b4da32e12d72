// @ts-check
// The half width at half maximum of an anisotropic NDF along each axis: the polar angle θh at which D, walking from
// n towards the tangent t (φh = 0) or the bitangent b (φh = 90°), falls to half of D(n). Along an axis the
// stretched D is the isotropic one at that axis' α times a constant (αx/αy or αy/αx), so this is the isotropic
// half width of αx, and of αy (Heitz 2014's forms).
import { ndfHalfWidthDeg } from './ndf-width.js';

/**
 * [along t, along b] in degrees for D(hx, hy, hz, αx, αy); null on an axis where D never falls to half (GGX with
 * that α at 1 or more is flat or rises towards the horizon).
 * @param {(hx: number, hy: number, hz: number, ax: number, ay: number) => number} D
 * @param {number} alphaX
 * @param {number} alphaY
 * @returns {(number | null)[]}
 */
export function ndfHalfWidthsAlongAxes(D, alphaX, alphaY) {
  const along = (/** @type {0 | 1} */ axis) => {
    const at = (/** @type {number} */ c) => {
      const s = Math.sqrt(Math.max(0, (1 - c) * (1 + c)));
      return axis === 0 ? D(s, 0, c, alphaX, alphaY) : D(0, s, c, alphaX, alphaY);
    };
    // short of the horizon (89.9°): past it D is 0, which is not the lobe falling to half
    if (at(Math.cos((89.9 * Math.PI) / 180)) > at(1) / 2) return null;
    return ndfHalfWidthDeg(at);
  };
  return [along(0), along(1)];
}
