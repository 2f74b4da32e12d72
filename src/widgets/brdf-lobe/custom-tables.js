// A user-written term of BRDF A as the lobe's views read it: its GLSL evaluated on the GPU (never in JS) over
// tables, looked up in JS. D and F are tables over one angle (θh, θd), V over two (θl, θv) at the state's α and
// F0; a whole BRDF is evaluated where the views look (the hemisphere of views for the state's light, the (θh, θd)
// image at its φd, an albedo quadrature). A vec3 result is read as the mean of its three channels.
import { directionsFromHalfDiff } from '../../math/half-diff.js';
import { DEG } from '../../math/angles.js';
import { SLOTS } from '../../core/custom/slots.js';
import { ALBEDO_ANGLES, lightDir } from './model.js';

const ANGLE_STEPS = 1024; // D and F: θ from 0° to 90°, 0.088° apart (GGX at α = 0.02 is ~1.1° wide)
const V_STEPS = 128; // V: θl × θv, from 1.4° apart at n to 0.006° at the horizon
const VIEW_THETA = 181; // whole BRDF: θv every 0.5° and φv every 3.75°, the polar plot's and the 3-D lobe's nodes
const VIEW_PHI = 97;
export const IMAGE_CELLS = 90; // the (θh, θd) image's cells (half-diff-image.js)
const ALBEDO_U = 16; // albedo quadrature: u = (n·l)² × φ, midpoints, so that E = π × the mean of f
const ALBEDO_PHI = 32;

/** θ = (π/2)(1 − (1 − u)²) for u from 0 to 1: nodes crowding towards 90°, and back from θ to u. */
const GRAZING_CROWDED = {
  angle: (u) => (Math.PI / 2) * (1 - (1 - u) ** 2),
  inverse: (theta) => 1 - Math.sqrt(Math.max(1 - theta / (Math.PI / 2), 0)),
};
const EVEN = { angle: (u) => (u * Math.PI) / 2 };
/** `steps` angles from 0 to 90°, evenly spaced in u (`spacing`: even in θ unless said). */
const grid = (steps, spacing = EVEN) => Array.from({ length: steps }, (_, i) => spacing.angle(i / (steps - 1)));

/** Linear interpolation of `values` (nodes 0…steps-1 over [0, π/2]) at θ. */
function lerp1(values, theta) {
  const x = Math.min(Math.max(theta / (Math.PI / 2), 0), 1) * (values.length - 1);
  const i = Math.min(Math.floor(x), values.length - 2);
  return values[i] + (values[i + 1] - values[i]) * (x - i);
}

/** Bilinear interpolation of a rows × cols table over [0, rowSpan] × [0, colSpan] at (r, c). */
function lerp2(values, rows, cols, [r, rowSpan], [c, colSpan]) {
  const y = Math.min(Math.max(r / rowSpan, 0), 1) * (rows - 1);
  const x = Math.min(Math.max(c / colSpan, 0), 1) * (cols - 1);
  const [i, j] = [Math.min(Math.floor(y), rows - 2), Math.min(Math.floor(x), cols - 2)];
  const [fy, fx] = [y - i, x - j];
  const at = (a, b) => values[a * cols + b];
  const top = at(i, j) + (at(i, j + 1) - at(i, j)) * fx;
  const bottom = at(i + 1, j) + (at(i + 1, j + 1) - at(i + 1, j)) * fx;
  return top + (bottom - top) * fy;
}

/** θh of the half vector from its own components (precise near n, where the peak of a small α is). */
const thetaH = (a) => Math.atan2(Math.hypot(a.h[0], a.h[1]), a.h[2]);
const acosClamped = (x) => Math.acos(Math.min(Math.max(x, -1), 1));

const dirFrom = (theta, phi) => [Math.sin(theta) * Math.cos(phi), Math.sin(theta) * Math.sin(phi), Math.cos(theta)];

/** The albedo quadrature's light directions: u = (n·l)² and φ at midpoints. */
const ALBEDO_LIGHTS = Array.from({ length: ALBEDO_U * ALBEDO_PHI }, (_, k) => {
  const mu = Math.sqrt((Math.floor(k / ALBEDO_PHI) + 0.5) / ALBEDO_U);
  return dirFrom(Math.acos(mu), (((k % ALBEDO_PHI) + 0.5) / ALBEDO_PHI) * 2 * Math.PI);
});

/**
 * What to evaluate for each slot, given the state: `inputs` in the slot's order (slots.js), `key` the state it
 * depends on, and `read(values)` → the lookup the model uses (values: one number per input, see channelMeans).
 */
const PLANS = {
  D: (s) => ({
    key: `${s.alpha}`,
    inputs: grid(ANGLE_STEPS).map((t) => [Math.cos(t), s.alpha]),
    read: (values) => (a) => lerp1(values, thetaH(a)),
  }),
  V: (s) => {
    const nodes = grid(V_STEPS, GRAZING_CROWDED);
    const inputs = nodes.flatMap((tl) => nodes.map((tv) => [Math.cos(tl), Math.cos(tv), s.alpha]));
    // interpolated as G = V (n·l)(n·v), bounded: V grows like 1/(n·l + n·v) towards the grazing corner (cos 90° is
    // 6e-17 in float32, not 0, so a node there holds a huge V); the nodes crowd towards 90° (GRAZING_CROWDED),
    // where G turns fastest
    const read = (values) => {
      const g = values.map((v, i) => v * inputs[i][0] * inputs[i][1]);
      const at = (cos) => [GRAZING_CROWDED.inverse(acosClamped(cos)), 1];
      return (a) => lerp2(g, V_STEPS, V_STEPS, at(a.nl), at(a.nv)) / (a.nl * a.nv);
    };
    return { key: `${s.alpha}`, inputs, read };
  },
  F: (s) => ({
    key: `${s.f0}`,
    inputs: grid(ANGLE_STEPS).map((t) => [s.f0, s.f0, s.f0, Math.cos(t)]),
    read: (values) => (a) => lerp1(values, acosClamped(a.lh)),
  }),
  brdf: (s) => brdfPlan(s),
};

/** A whole BRDF: the views for the state's light, the (θh, θd) image at its φd, and E(θv) for ALBEDO_ANGLES. */
function brdfPlan(s) {
  const l = lightDir(s.lightTheta);
  const views = grid(VIEW_THETA).flatMap((t) =>
    Array.from({ length: VIEW_PHI }, (_, j) => dirFrom(t, (j / (VIEW_PHI - 1)) * 2 * Math.PI)),
  );
  const cell = (i) => ((i + 0.5) * Math.PI) / 2 / IMAGE_CELLS;
  const image = Array.from({ length: IMAGE_CELLS * IMAGE_CELLS }, (_, k) => {
    const d = directionsFromHalfDiff(cell(k % IMAGE_CELLS), cell(Math.floor(k / IMAGE_CELLS)), s.phiD * DEG);
    return [...d.l, ...d.v];
  });
  const albedo = Array.from(ALBEDO_ANGLES).flatMap((deg) => {
    const v = dirFrom(deg * DEG, 0);
    return ALBEDO_LIGHTS.map((li) => [...li, ...v]);
  });
  const inputs = [...views.map((v) => [...l, ...v]), ...image, ...albedo];
  return { key: `${s.lightTheta} ${s.phiD}`, inputs, read: (values) => readBrdf(values, views.length) };
}

function readBrdf(values, viewCount) {
  const imageEnd = viewCount + IMAGE_CELLS * IMAGE_CELLS;
  const perAngle = ALBEDO_LIGHTS.length;
  const albedo = Array.from(ALBEDO_ANGLES, (_, i) => {
    let sum = 0;
    for (let k = 0; k < perAngle; k++) sum += values[imageEnd + i * perAngle + k];
    return (Math.PI * sum) / perAngle;
  });
  const phiSpan = 2 * Math.PI;
  return {
    /** f(l, v) for the state's light; v a unit vector of the upper hemisphere. */
    atView: (v) => {
      const phi = Math.atan2(v[1], v[0]);
      return lerp2(
        values,
        VIEW_THETA,
        VIEW_PHI,
        [acosClamped(v[2]), Math.PI / 2],
        [phi < 0 ? phi + phiSpan : phi, phiSpan],
      );
    },
    /** f at the centre of the image cell containing (θh, θd), at the state's φd. */
    halfDiff: (th, td) => {
      const cell = (x) => Math.min(Math.floor((x / (Math.PI / 2)) * IMAGE_CELLS), IMAGE_CELLS - 1);
      return values[viewCount + cell(td) * IMAGE_CELLS + cell(th)];
    },
    albedo,
  };
}

/**
 * The inputs and reader of a slot for the state (see PLANS), as the runner takes them: `read` is given
 * evaluateCustom's four floats per input.
 */
export function customPlan(slotKey, state) {
  const plan = PLANS[slotKey](state);
  const count = plan.inputs.length;
  return { ...plan, read: (out) => plan.read(channelMeans(out, SLOTS[slotKey].outputs, count)) };
}

/**
 * One number per input from evaluateCustom's four floats: .x, or the mean of .xyz. NaN, ±Inf and negative values
 * are drawn as 0 (the panel's checks count and locate them).
 */
function channelMeans(out, outputs, count) {
  const values = new Float64Array(count);
  for (let i = 0; i < count; i++) {
    const x = outputs === 1 ? out[4 * i] : (out[4 * i] + out[4 * i + 1] + out[4 * i + 2]) / 3;
    values[i] = Number.isFinite(x) && x > 0 ? x : 0;
  }
  return values;
}
