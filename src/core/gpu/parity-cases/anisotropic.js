// Parity rows of the anisotropic microfacet functions (shaders/anisotropic.glsl against src/math/anisotropic.js),
// in the row format of parity-cases.js. The stress inputs: alpha pairs down to αx ≪ αy (1e-4 against 1) both ways
// and past the clamps, half vectors exactly along t and b and within 1e-7 of the horizon or 1e-4 rad of n, grazing
// views (n·v = 1e-7) along either axis, sampler numbers at 0 and 1 - 1e-6, and the bent reflection's anisotropy at
// 0 and ±1 with views along, across and at grazing to the grain.
import * as M from '../../../math/index.js';

const cartesian = (...lists) => lists.reduce((acc, list) => acc.flatMap((a) => list.map((x) => [...a, x])), [[]]);
const unit = (x, y, z) => [x, y, z].map((c) => c / Math.hypot(x, y, z));
const spherical = (theta, phi) =>
  unit(Math.sin(theta) * Math.cos(phi), Math.sin(theta) * Math.sin(phi), Math.cos(theta));

/** (alphaX, alphaY): equal, stretched either way down to 1e-4 against 1, and past both clamps (0, 5). */
const ALPHA_PAIRS = [
  [1e-4, 1],
  [1, 1e-4],
  [1e-3, 1],
  [0.01, 0.5],
  [0.1, 0.1],
  [0.3, 0.05],
  [1, 1],
  [4, 0.5],
  [0, 0],
  [5, 1e-3],
];
// polar angles from n to the horizon (1e-7 rad short of it, and on it) × azimuths from t (0) through b (π/2) to -t
const THETAS = [0, 1e-4, 0.01, 0.3, 0.7854, 1.2, 1.5, Math.PI / 2 - 1e-7, Math.PI / 2];
const PHIS = [0, 0.3, Math.PI / 4, 1.2, Math.PI / 2, 2.5, Math.PI];
const HALF_VECTORS = [
  ...cartesian(THETAS, PHIS).map(([t, p]) => spherical(t, p)),
  [1, 0, 0], // exactly along t and b: h.z = 0
  [0, 1, 0],
  [0.6, 0, -0.8], // below the horizon
];
// view and light directions: along n, grazing along t, b and between them, oblique, and one below the horizon
const DIRECTIONS = [
  [0, 0, 1],
  unit(1, 0, 1e-7),
  unit(0, 1, 1e-7),
  unit(0.6, 0.8, 1e-4),
  spherical(0.3, 0.5),
  spherical(1.2, 2),
  spherical(1.5, -0.7),
  [0.6, 0, -0.8],
];
const SAMPLER_DIRECTIONS = DIRECTIONS.slice(0, 7); // v below the horizon has no visible normals
// the sampler's normal comes from the GPU's sines of π u2 (SwiftShader's up to ~1.8e-4 off: 1.4e-4 here, and the
// isotropic samplers' rows allow 3e-4; llvmpipe's within 3.4e-7); near the cap's rim (u1 -> 1) their error enters
// squared, and cos(π u2) is a sine that is exactly 0 at u2 = 1/2 (anisotropic.js)
const SAMPLER_TOLERANCE = { atol: 3e-4, rtol: 1e-4 };

// the forms of the catalogue's entries (ggxAniso, …) have their rows of the catalogue's grids too: these are named
// apart, by their own stress inputs
const VEC_FORM = ' (vec3 form, α pairs to 1e-4 : 1)';
const CATALOGUED = new Set(['ndfGGXAniso', 'ndfBeckmannAniso', 'visibilitySmithGGXCorrelatedAniso']);
const rowName = (name) => (CATALOGUED.has(name) ? `${name}${VEC_FORM}` : name);

// one direction (a.xyz) and (αx, αy) in (a.w, b.x): the NDFs over half vectors, the G1s over directions
const directionRow = (name, range) => ({
  name: rowName(name),
  chunk: 'anisotropic.glsl',
  glsl: `${name}(a.xyz, vec2(a.w, b.x))`,
  outputs: 1,
  js: M[name],
  range,
  args: cartesian(HALF_VECTORS, ALPHA_PAIRS).map(([h, [ax, ay]]) => [...h, ax, ay]),
});

// two directions, a.xyz (l or v) and b.xyz (v or m), with αx in a.w and αy in b.w
const pairRow = (name, seconds) => ({
  name: rowName(name),
  chunk: 'anisotropic.glsl',
  glsl: `${name}(a.xyz, b.xyz, vec2(a.w, b.w))`,
  outputs: 1,
  js: (px, py, pz, ax, qx, qy, qz, ay) => M[name](px, py, pz, qx, qy, qz, ax, ay),
  range: [0, Infinity],
  args: cartesian(DIRECTIONS, seconds, ALPHA_PAIRS).map(([p, q, [ax, ay]]) => [...p, ax, ...q, ay]),
});

const CONVENTIONS = M.ANISOTROPY_CONVENTIONS; // their index is the GLSL's ANISOTROPY_* value

export const ANISOTROPIC_PARITY_CASES = [
  directionRow('ndfGGXAniso', [0, Infinity]),
  directionRow('ndfBeckmannAniso', [0, Infinity]),
  directionRow('smithG1GGXAniso', [0, 1]),
  directionRow('smithG1BeckmannAniso', [0, 1]),
  pairRow('visibilitySmithGGXCorrelatedAniso', DIRECTIONS),
  pairRow('visibleNormalPdfGGXAniso', HALF_VECTORS),
  pairRow('reflectedPdfGGXAniso', HALF_VECTORS),
  {
    name: 'anisotropicAlphas',
    chunk: 'anisotropic.glsl',
    glsl: 'anisotropicAlphas(a.x, a.y, int(a.z))',
    outputs: 2,
    js: (alpha, anisotropy, convention) => M.anisotropicAlphas(alpha, anisotropy, CONVENTIONS[convention]),
    range: [0, 3.2], // Burley at α = 1, a = 1: 1/√0.1
    args: cartesian([0, 1e-4, 0.01, 0.25, 1], [-0.5, 0, 1e-4, 0.3, 0.9, 1, 1.5], [0, 1, 2]),
  },
  {
    // a.xyz = v, a.w = α, b.x = a: both grains (a = ±1), no bend (a = 0), v grazing along t, b and between them,
    // v along t and b exactly (nothing across the grain for one sign: the mirror about n), the tangent ⟂ v
    name: 'anisotropicBentReflection',
    chunk: 'anisotropic.glsl',
    glsl: 'anisotropicBentReflection(a.xyz, a.w, b.x)',
    outputs: 3,
    js: M.anisotropicBentReflection,
    range: [-1, 1],
    args: cartesian(
      [...DIRECTIONS.slice(0, 7), [1, 0, 0], [0, 1, 0], unit(0, 0.8, 0.6), unit(0, 0.05, 1)],
      [0, 1e-4, 0.25, 1],
      [-1, -0.5, 0, 0.3, 1],
    ).map(([v, alpha, a]) => [...v, alpha, a, 0, 0, 0]),
  },
  {
    // a.xyz = v, a.w = αx, b.x = αy, b.yz = (u1, u2)
    name: 'sampleVisibleNormalGGXAniso',
    chunk: 'anisotropic.glsl',
    glsl: 'sampleVisibleNormalGGXAniso(a.xyz, vec2(a.w, b.x), b.yz)',
    outputs: 3,
    js: M.sampleVisibleNormalGGXAniso,
    range: [-1, 1],
    tolerance: SAMPLER_TOLERANCE,
    args: cartesian(SAMPLER_DIRECTIONS, ALPHA_PAIRS, [0, 1e-6, 0.3, 0.9, 0.999, 1 - 1e-6], [0, 0.25, 0.5, 0.7]).map(
      ([v, [ax, ay], u1, u2]) => [...v, ax, ay, u1, u2, 0],
    ),
  },
];
