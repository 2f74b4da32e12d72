// The float64 truth of the material lab's anisotropic lobe on its sphere, for the browser tests that read the lab's
// images (lab-anisotropic.test.js, lab-own-aniso.test.js): the sphere's normal at a texel, the brushing's frame
// around a pole written out here again (b = axis × n, t = b × n, turned by the rotation), and f (n·l) of GGX
// stretched by (αx, αy) with the height-correlated anisotropic Smith V and F = 1 (src/math/anisotropic.js).
import { ndfGGXAniso, visibilitySmithGGXCorrelatedAniso } from '../../src/math/anisotropic.js';

export const EXTENT = 1.1; // the lab's view half width (src/lab/lab-uniforms.js)
export const RES = 192; // the lab's image size (src/widgets/material-lab/material-lab.js)
export const DEG = Math.PI / 180;

export const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
export const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
export const unit = (a) => a.map((x) => x / Math.hypot(...a));
export const spherical = (theta, phi) => [
  Math.sin(theta * DEG) * Math.cos(phi * DEG),
  Math.sin(theta * DEG) * Math.sin(phi * DEG),
  Math.cos(theta * DEG),
];

/** The sphere's normal at texel [i, j] (i right, j up from the bottom left; the lab shades its centre). */
export const normalAt = ([i, j]) => {
  const [x, y] = [i, j].map((c) => ((2 * (c + 0.5)) / RES - 1) * EXTENT);
  return [x, y, Math.sqrt(1 - x * x - y * y)];
};

/** n ↦ the frame (t, b, n) of the brushing around the pole { theta, phi }, turned by `rotation` degrees about n. */
export const frameAround = (pole, rotation) => (n) => {
  const b0 = unit(cross(spherical(pole.theta, pole.phi), n));
  const t0 = cross(b0, n);
  const [c, s] = [Math.cos(rotation * DEG), Math.sin(rotation * DEG)];
  return [t0.map((x, k) => c * x + s * b0[k]), b0.map((x, k) => c * x - s * t0[k]), n];
};

/** f (n·l) of the specular lobe (F = 1) for view-space l at the frame of a normal, v = z; `pair` the (αx, αy). */
export function lobeCos(frame, l, pair) {
  const [L, V] = [l, [0, 0, 1]].map((d) => frame.map((axis) => dot(d, axis)));
  if (!(L[2] > 0 && V[2] > 0)) return 0;
  const h = unit(L.map((x, k) => x + V[k]));
  return (ndfGGXAniso(...h, ...pair) * visibilitySmithGGXCorrelatedAniso(...L, ...V, ...pair) * L[2]) / 4;
}

// texels on the sphere: centre, towards the pole, across it, and two near the rim
export const TEXELS = [
  [96, 96],
  [96, 140],
  [60, 110],
  [130, 70],
  [150, 100],
];

/** The truth at a texel, averaged over its 3 × 3 block as the tests' reads are. */
export const blockMean = ([i, j], truthAt) => {
  let sum = 0;
  for (let dj = -1; dj <= 1; dj++) for (let di = -1; di <= 1; di++) sum += truthAt([i + di, j + dj]);
  return sum / 9;
};
