// The stress domains of the anisotropic functions (src/math/anisotropic.js), spread into STRESS_DOMAINS
// (stress-domains.js): unit directions with the degenerate ones (along t and b, grazing, below the horizon) and
// roughness pairs past both clamps, the pairs outermost so that the test suite's first 400 inputs see several.
import { ANISOTROPY_CONVENTIONS } from '../../src/math/anisotropic.js';

const spherical = (theta, phi) => [Math.sin(theta) * Math.cos(phi), Math.sin(theta) * Math.sin(phi), Math.cos(theta)];
const DIRS = [
  [0, 0, 1],
  [1, 0, 0],
  [0, 1, 0],
  [0, 0, -1],
  spherical(Math.PI / 2 - 1e-7, 0),
  spherical(Math.PI / 2 - 1e-7, Math.PI / 2),
  spherical(Math.PI / 2 - 1e-4, 0.93),
  spherical(0.52, 0.93),
  spherical((3 * Math.PI) / 4, 0),
];
const AXIS = [0, 1e-5, 1e-4, 0.3, 1, 4, 10];
const ALPHA_PAIRS = AXIS.flatMap((ax) => AXIS.map((ay) => [ax, ay]));
const one = ALPHA_PAIRS.flatMap(([ax, ay]) => DIRS.map((d) => [...d, ax, ay]));
const two = ALPHA_PAIRS.flatMap(([ax, ay]) => DIRS.flatMap((a) => DIRS.map((b) => [...a, ...b, ax, ay])));
const NON_NEGATIVE = [0, Infinity];

export const ANISOTROPIC_STRESS_DOMAINS = {
  ndfGGXAniso: { tuples: one, range: NON_NEGATIVE },
  ndfBeckmannAniso: { tuples: one, range: NON_NEGATIVE },
  smithG1GGXAniso: { tuples: one, range: [0, 1] },
  smithG1BeckmannAniso: { tuples: one, range: [0, 1] },
  visibilitySmithGGXCorrelatedAniso: { tuples: two, range: NON_NEGATIVE },
  visibleNormalPdfGGXAniso: { tuples: two, range: NON_NEGATIVE },
  reflectedPdfGGXAniso: { tuples: two, range: NON_NEGATIVE },
  anisotropicAlphas: { args: [[0, 1e-4, 0.3, 1], [-1, 0, 0.5, 1, 2], ANISOTROPY_CONVENTIONS], range: [0, 3.2] },
  anisotropicBentReflection: {
    // (v, α, a): a past ±1 (clamped), α past 1
    tuples: DIRS.flatMap((d) =>
      [-2, -1, -0.5, 0, 0.5, 1, 2].flatMap((a) => [0, 1e-4, 0.3, 1, 4].map((alpha) => [...d, alpha, a])),
    ),
    range: [-1, 1],
  },
  sampleVisibleNormalGGXAniso: {
    tuples: one.flatMap((t) => [0, 0.5, 1 - 1e-12, 1].flatMap((u1) => [0, 0.5, 1].map((u2) => [...t, u1, u2]))),
    range: [-1, 1],
  },
};
