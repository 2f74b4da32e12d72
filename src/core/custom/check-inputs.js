// @ts-check
// Where the live checks evaluate a slot's code: the parity grid of its family (stress inputs included: cos = 0,
// 1e-7, 1, just above 1, below the horizon, α down to 1e-4), the quadrature nodes of the integrals (D's
// normalisation, over the 2-D hemisphere for the anisotropic D, whose nodes also give Heitz's weak furnace; a
// BRDF's white furnace), the swapped pairs of reciprocity and the points of the plotted curve.
// Pure: one list of inputs for one GPU evaluation, and where each check's part of it starts.
import { GRIDS } from '../gpu/parity-cases.js';
import { ALPHA } from '../../math/catalogue/term.js';
import { gaussLegendre } from '../../math/quadrature.js';
import { slotOf } from './slots.js';

/** α of the stress grid: the slot's domain, its ends and the catalogue's delicate values inside it. */
export const CHECK_ALPHAS = [ALPHA.min, ...ALPHA.delicate.filter((a) => a > ALPHA.min && a < ALPHA.max), ALPHA.max];
/**
 * α at which D's normalisation is measured. Below 0.01 it is not measurable through a float32 n·h: n·h steps by
 * 6e-8 near 1, so sin²θ by 1.2e-7, while GGX's peak is α² wide (1e-8 at α = 1e-4); at α = 1e-3 the rounding of n·h
 * alone moves the integral by 3e-3 (tests/unit/custom-checks.test.js).
 */
export const NORMALISATION_ALPHAS = [0.01, 0.03, 0.1, 0.3, 0.5, 1];
const NORMALISATION_RULE = { nodes: 32, panels: 8 };
/**
 * The white furnace: Gauss–Legendre in cos θl and evenly spaced azimuths, at these view angles. Exact for Lambert;
 * for GGX (F = 1, α = 0.5) within 1e-4 of the float64 albedo up to θv = 80° and 2.6e-3 low at 89°, where the lobe
 * lies at the horizon between the azimuths; sharper lobes at grazing views read lower still (unit test).
 */
export const FURNACE_VIEWS_DEG = [0, 30, 60, 80, 89];
const FURNACE_RULE = { cosNodes: 32, azimuths: 64 };
/**
 * The anisotropic D's (αx, αy): round, stretched along t and along b, and past α = 1 on one axis (the anisotropic
 * forms take up to ALPHA_ANISO_MAX). At least 0.05: h is float32, and its rounding moves a sharper peak's integral.
 */
export const ANISOTROPIC_PAIRS = [
  [0.1, 0.1],
  [0.05, 0.5],
  [0.3, 0.1],
  [1, 0.3],
  [2, 0.2],
];
/**
 * The 2-D rule over h (slope space): u = 1 - (1 - t)² in panels of Gauss–Legendre in t, evenly spaced azimuths.
 * For GGX and Beckmann the normalisation comes out within 1e-14 and the weak furnace within 1e-3 (unit test).
 */
const ANISOTROPIC_RULE = { nodes: 16, panels: 4, azimuths: 32 };
/** The views of the weak furnace, [θv, φv] in degrees: n, then three elevations at three azimuths from t. */
export const WEAK_FURNACE_VIEWS_DEG = [[0, 0], ...[40, 70, 85].flatMap((t) => [0, 60, 90].map((p) => [t, p]))];
/** The anisotropic D's stress directions: h from n to below the horizon, along t, along b and between. */
const H_THETAS = [0, 1e-3, 0.2, 0.6, 1, 1.4, 1.55, Math.PI / 2, 1.9];
const H_PHIS = [0, Math.PI / 4, Math.PI / 2, 2, Math.PI, 4.5];
/** The curve of the anisotropic D: along t, at this pair. */
const ANISOTROPIC_CURVE_PAIR = [0.3, 0.1];

/** The angles of the direction pairs: GRIDS.theta (n to grazing) and one below the horizon. */
const PAIR_THETAS = [...GRIDS.theta, 1.9];
const PAIR_PHIS = [0, 1, Math.PI / 2, 3, Math.PI];
/** The curve: at this α, c_diff and F0 (a plot of the custom term beside the reference). */
export const CURVE_AT = { alpha: 0.3, cdiff: 1, f0: 0.04, lightDeg: 45 };

/** @param {...number[]} lists @returns {number[][]} */
const cartesian = (...lists) =>
  lists.reduce((/** @type {number[][]} */ acc, list) => acc.flatMap((a) => list.map((x) => [...a, x])), [[]]);
/** @param {number} theta @param {number} phi */
const direction = (theta, phi) => [Math.sin(theta) * Math.cos(phi), Math.sin(theta) * Math.sin(phi), Math.cos(theta)];
const DEG = Math.PI / 180;

/** (l, v) pairs: l at azimuth 0, v at each azimuth, both over PAIR_THETAS. @returns {number[][][]} */
const directionPairs = () =>
  cartesian(PAIR_THETAS, PAIR_THETAS, PAIR_PHIS).map(([tl, tv, phi]) => [direction(tl, 0), direction(tv, phi)]);

/**
 * One input of a slot from l and v (and c_diff, α for the diffuse slot).
 * @param {string} key @param {number[]} l @param {number[]} v @param {number} cdiff @param {number} alpha
 */
const pairInput = (key, l, v, cdiff, alpha) => (key === 'diffuse' ? [cdiff, ...l, ...v, alpha] : [...l, ...v]);

/**
 * The stress grid of a slot.
 * @param {string} key
 * @returns {number[][]}
 */
export function stressInputs(key) {
  if (key === 'D') return cartesian(GRIDS.cos, CHECK_ALPHAS);
  const pairs = [...CHECK_ALPHAS.map((a) => [a, a]), [1e-4, 1], [1, 1e-4], [0.01, 0.5], [4, 0.1], ...ANISOTROPIC_PAIRS];
  if (key === 'DAniso') {
    return cartesian(H_THETAS, H_PHIS).flatMap(([t, p]) => pairs.map((pair) => [...direction(t, p), ...pair]));
  }
  if (key === 'VAniso') return pairs.flatMap((pair) => directionPairs().map(([l, v]) => [...l, ...v, ...pair]));
  if (key === 'V') return cartesian(GRIDS.cosCoarse, GRIDS.cosCoarse, CHECK_ALPHAS);
  if (key === 'F') return cartesian(GRIDS.f0, GRIDS.cos).map(([f0, lh]) => [f0, 0.5 * f0, 1 - f0, lh]);
  if (key === 'diffuse')
    return cartesian([0, 0.5, 1], [1e-4, 0.1, 0.5, 1]).flatMap(([c, a]) =>
      directionPairs().map(([l, v]) => pairInput(key, l, v, c, a)),
    );
  return directionPairs().map(([l, v]) => pairInput(key, l, v, 1, 1));
}

/**
 * D's normalisation ∫ D(m)(n·m) dω = π ∫₀¹ D(√(1 − s)) ds (s = sin²θm), with s = α² x / (1 − x): a GGX D is then
 * nearly flat in x, and Gauss–Legendre panels over x ∈ [0, 1/(1 + α²)] converge to 1e-8 (unit test).
 * @param {number} alpha
 * @returns {{ nh: number, weight: number }[]}
 */
export function normalisationNodes(alpha) {
  const a2 = alpha * alpha;
  const top = 1 / (1 + a2);
  const { x, w } = gaussLegendre(NORMALISATION_RULE.nodes);
  const nodes = [];
  for (let p = 0; p < NORMALISATION_RULE.panels; p++) {
    const [lo, hi] = [(top * p) / NORMALISATION_RULE.panels, (top * (p + 1)) / NORMALISATION_RULE.panels];
    for (let i = 0; i < x.length; i++) {
      const t = lo + ((hi - lo) * (1 + x[i])) / 2;
      const s = (a2 * t) / (1 - t);
      const weight = (Math.PI * w[i] * ((hi - lo) / 2) * a2) / (1 - t) ** 2;
      nodes.push({ nh: Math.sqrt(Math.max(1 - s, 0)), weight });
    }
  }
  return nodes;
}

/**
 * The anisotropic D's normalisation ∫ D(h)(n·h) dω = ∫ D hz⁴ d²s over the slopes s = (hx, hy)/hz (dω = hz³ d²s),
 * with s = (αx r cos φ, αy r sin φ) and r² = u/(1 − u): a GGX D is then flat in (u, φ), and u = 1 − (1 − t)²
 * leaves the weak furnace's tail, which grows as 1/√(1 − u) towards the horizon, smooth in t. Nodes h, weights w
 * with Σ w D(h) = ∫ D(h)(n·h) dω; w / hz weighs D alone (the weak furnace).
 * @param {number[]} pair [αx, αy]
 * @returns {{ h: number[], weight: number }[]}
 */
export function anisotropicNormalisationNodes([ax, ay]) {
  const { nodes: n, panels, azimuths } = ANISOTROPIC_RULE;
  const { x, w } = gaussLegendre(n);
  const dPhi = (2 * Math.PI) / azimuths;
  const out = [];
  for (let p = 0; p < panels; p++) {
    for (let i = 0; i < n; i++) {
      const t = (p + (1 + x[i]) / 2) / panels;
      const u = 1 - (1 - t) ** 2;
      const r = Math.sqrt(u / (1 - u));
      // dt → du → r dr: w/(2 panels) · 2(1 − t) · 1/(2 (1 − u)²), times αx αy hz⁴ below
      const radial = (w[i] / (2 * panels)) * ((1 - t) / (1 - u) ** 2);
      for (let k = 0; k < azimuths; k++) {
        const phi = (k + 0.5) * dPhi;
        const [sx, sy] = [ax * r * Math.cos(phi), ay * r * Math.sin(phi)];
        const len = Math.hypot(sx, sy, 1);
        const hz = 1 / len;
        out.push({ h: [sx * hz, sy * hz, hz], weight: radial * dPhi * ax * ay * hz ** 4 });
      }
    }
  }
  return out;
}

/**
 * The white furnace at view angle θv: albedo(v) = ∫ f(l, v)(n·l) dω_l, as nodes l with weights (n·l included).
 * @param {number} thetaV radians
 * @returns {{ l: number[], v: number[], weight: number }[]}
 */
export function furnaceNodes(thetaV) {
  const { x, w } = gaussLegendre(FURNACE_RULE.cosNodes);
  const v = direction(thetaV, 0);
  const dPhi = (2 * Math.PI) / FURNACE_RULE.azimuths;
  const nodes = [];
  for (let i = 0; i < x.length; i++) {
    const mu = (1 + x[i]) / 2; // [0, 1]
    for (let k = 0; k < FURNACE_RULE.azimuths; k++) {
      const phi = (k + 0.5) * dPhi;
      nodes.push({ l: direction(Math.acos(mu), phi), v, weight: (w[i] / 2) * dPhi * mu });
    }
  }
  return nodes;
}

/**
 * The curve of a slot: x in degrees and the inputs there.
 * @param {string} key
 * @returns {{ x: number[], xLabel: string, inputs: number[][] }}
 */
export function curveInputs(key) {
  const { alpha, cdiff, f0, lightDeg } = CURVE_AT;
  if (key === 'DAniso') {
    const x = Array.from({ length: 91 }, (_, i) => i);
    const [ax, ay] = ANISOTROPIC_CURVE_PAIR;
    return {
      x,
      xLabel: `θh (°) along t, (αx, αy) = (${ax}, ${ay})`,
      inputs: x.map((d) => [...direction(d * DEG, 0), ax, ay]),
    };
  }
  if (key === 'VAniso') {
    const x = Array.from({ length: 90 }, (_, i) => i);
    const [ax, ay] = ANISOTROPIC_CURVE_PAIR;
    return {
      x,
      xLabel: `θ (°), l = v along t, (αx, αy) = (${ax}, ${ay})`,
      inputs: x.map((d) => [...direction(d * DEG, 0), ...direction(d * DEG, 0), ax, ay]),
    };
  }
  if (key === 'D' || key === 'V' || key === 'F') {
    const x = Array.from({ length: 91 }, (_, i) => i);
    const c = (/** @type {number} */ deg) => Math.cos(deg * DEG);
    const at = {
      D: (/** @type {number} */ d) => [c(d), alpha],
      V: (/** @type {number} */ d) => [c(d), c(d), alpha],
      F: (/** @type {number} */ d) => [f0, f0, f0, c(d)],
    }[key];
    const xLabel = { D: `θh (°), α = ${alpha}`, V: `θ (°), n·l = n·v = cos θ, α = ${alpha}`, F: `θd (°), F0 = ${f0}` };
    return { x, xLabel: xLabel[key], inputs: x.map(at) };
  }
  const x = Array.from({ length: 90 }, (_, i) => -89 + 2 * i);
  const l = direction(lightDeg * DEG, Math.PI);
  const inputs = x.map((deg) => pairInput(key, l, direction(Math.abs(deg) * DEG, deg < 0 ? Math.PI : 0), cdiff, 0.5));
  return { x, xLabel: `θv (°) in the plane of l, l at ${lightDeg}°`, inputs };
}

/**
 * Every input of a slot's checks, in one list, and where each part lies in it.
 * @param {string} slotKey
 */
export function checkPlan(slotKey) {
  const { key } = slotOf(slotKey);
  /** @type {number[][]} */
  const inputs = [];
  /** @param {number[][]} list */
  const part = (list) => {
    const start = inputs.length;
    inputs.push(...list);
    return { start, count: list.length };
  };
  const stress = part(stressInputs(key));
  const normalisation =
    key === 'D'
      ? NORMALISATION_ALPHAS.map((alpha) => {
          const nodes = normalisationNodes(alpha);
          return { alpha, weights: nodes.map((n) => n.weight), ...part(nodes.map((n) => [n.nh, alpha])) };
        })
      : key === 'DAniso'
        ? ANISOTROPIC_PAIRS.map((alpha) => {
            const nodes = anisotropicNormalisationNodes(alpha);
            const [weights, directions] = [nodes.map((n) => n.weight), nodes.map((n) => n.h)];
            return { alpha, weights, directions, ...part(nodes.map((n) => [...n.h, ...alpha])) };
          })
        : null;
  const pairs = directionPairs();
  const swapped = (/** @type {number} */ c, /** @type {number} */ a) => [
    ...pairs.map(([l, v]) => pairInput(key, l, v, c, a)),
    ...pairs.map(([l, v]) => pairInput(key, v, l, c, a)),
  ];
  const reciprocity = key === 'brdf' || key === 'diffuse' ? { pairs: pairs.length, ...part(swapped(1, 0.5)) } : null;
  const furnace =
    key === 'brdf'
      ? FURNACE_VIEWS_DEG.map((deg) => {
          const nodes = furnaceNodes(deg * DEG);
          return { thetaV: deg, weights: nodes.map((n) => n.weight), ...part(nodes.map((n) => [...n.l, ...n.v])) };
        })
      : null;
  const curveAt = curveInputs(key);
  const curve = { x: curveAt.x, xLabel: curveAt.xLabel, ...part(curveAt.inputs) };
  return { key, inputs, stress, normalisation, reciprocity, furnace, curve };
}
