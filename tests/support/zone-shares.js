// Shared by tests/browser/fresnel.test.js and tests/unit/quoted-figures.test.js.
import { fresnelZone } from '../../src/math/zones.js';
import { ndfGGX } from '../../src/math/ndf.js';
import { visibilitySmithGGXCorrelated } from '../../src/math/visibility.js';

/**
 * Independent float64 reference for the weighted zones on an orthographic sphere (v = z): the widget's 64 light
 * directions (a Fibonacci lattice; on a sphere only each light's angle θ from v matters), each light's reflected
 * light ∫ π D V (n·l)/4 (n·v) dω_n over the visible normals (pixel area = (n·v) dω_n), filed under the zone
 * of l·h = cos(θ/2). Quadrature around h, denser near it where D peaks.
 */
export function weightedSphereShares(alpha, lights = 64, nTheta = 200, nPhi = 96) {
  const totals = [0, 0, 0];
  for (let i = 0; i < lights; i++) {
    const th = Math.acos(1 - (2 * (i + 0.5)) / lights);
    const l = [Math.sin(th), 0, Math.cos(th)];
    const h = [Math.sin(th / 2), 0, Math.cos(th / 2)];
    const [b1, b2] = [
      [Math.cos(th / 2), 0, -Math.sin(th / 2)],
      [0, 1, 0],
    ]; // a frame around h
    let sum = 0;
    for (let j = 0; j < nTheta; j++) {
      const [u0, u1] = [j / nTheta, (j + 1) / nTheta];
      const [t0, t1] = [Math.PI * u0 * u0, Math.PI * u1 * u1];
      const t = (t0 + t1) / 2;
      const dmu = Math.cos(t0) - Math.cos(t1);
      for (let k = 0; k < nPhi; k++) {
        const p = (2 * Math.PI * (k + 0.5)) / nPhi;
        const n = [0, 1, 2].map((c) => h[c] * Math.cos(t) + Math.sin(t) * (Math.cos(p) * b1[c] + Math.sin(p) * b2[c]));
        const [nv, nl] = [n[2], n[0] * l[0] + n[2] * l[2]];
        if (!(nv > 0 && nl > 0)) continue;
        sum +=
          ((Math.PI * ndfGGX(Math.cos(t), alpha) * visibilitySmithGGXCorrelated(nl, nv, alpha)) / 4) * nl * nv * dmu;
      }
    }
    totals[fresnelZone(Math.cos(th / 2))] += (sum * 2 * Math.PI) / nPhi;
  }
  const all = totals[0] + totals[1] + totals[2];
  return totals.map((x) => x / all);
}
