// The NDF explorer's numbers, from src/math only: each chosen NDF at the matched width, sampled over θh, its
// normalisation integral, and a measured slice placed on the same angles.
import { NDF_TERMS } from '../../math/brdf.js';
import { matchNdfWidths } from '../../math/ndf-width.js';
import { ndfProjectedIntegral } from '../../math/integrate.js';
import { DEG } from '../../math/angles.js';
import { SERIES_DASHES, seriesStyle } from '../../core/ui/palettes.js';
import { THETA_H_DEG } from '../measured-brdf/model.js';
import { termLabel } from '../../math/catalogue/index.js';
import { anisotropicForm } from '../../math/catalogue/anisotropic-forms.js';
import { anisotropicAlphas } from '../../math/anisotropic.js';
import { ndfHalfWidthsAlongAxes } from '../../math/anisotropic-width.js';
import { NDF_KEYS } from './schema.js';

/**
 * An NDF's anisotropic lobe at its matched α: { key (the catalogue's), label, D (its float64 function of h in the
 * tangent frame and the α pair), pair [αx, αy] by the state's convention, widths [along t, along b] in degrees },
 * or null for an NDF without one. At anisotropy 0 every convention gives αx = αy = α.
 */
export function anisotropicLobe(key, p, state) {
  const entry = anisotropicForm('ndf', key); // the catalogue's anisotropic form of the NDF
  if (!entry) return null;
  const pair = anisotropicAlphas(p.alpha, state.anisotropy, state.convention);
  let widths = null;
  return {
    key: entry.key,
    label: entry.label,
    D: entry.js,
    pair,
    /** Computed when first read: two bisections. */
    get widths() {
      widths ??= ndfHalfWidthsAlongAxes(entry.js, ...pair);
      return widths;
    },
  };
}

/** Whether the spheres draw an NDF's anisotropic lobe: it has one and the anisotropy is above 0. */
export const drawsAnisotropic = (c, state) => Boolean(c.aniso) && state.anisotropy > 0;

/**
 * D over slope space for the slope map: n × n values at slopes (x, y) = (hx/hz, hy/hz) from -extent to extent (row
 * j = 0 at y = -extent), the microfacet normal h = normalize(x, y, 1); D in 1/sr.
 */
export function slopeMapValues(lobe, n, extent) {
  const out = new Float64Array(n * n);
  for (let j = 0; j < n; j++)
    for (let i = 0; i < n; i++) {
      const [x, y] = [(((i + 0.5) / n) * 2 - 1) * extent, (((j + 0.5) / n) * 2 - 1) * extent];
      const len = Math.hypot(x, y, 1);
      out[j * n + i] = lobe.D(x / len, y / len, 1 / len, ...lobe.pair);
    }
  return out;
}

/** The slope map's half extent: 2.5 times the wider α, at a round value (the lobe, and the tail's start). */
export function slopeExtent(pair) {
  const raw = Math.min(Math.max(2.5 * Math.max(...pair), 0.05), 8);
  const step = 10 ** Math.floor(Math.log10(raw));
  return Number((Math.ceil(raw / step) * step).toPrecision(6));
}

/** A curve's label and series style: the five NDFs in the talk's order, then the user's, dashed (over GGX's). */
export const withStyle = (key) =>
  NDF_KEYS.includes(key)
    ? { label: termLabel('ndf', key), ...seriesStyle(NDF_KEYS.indexOf(key)) }
    : { label: termLabel('ndf', key), ...seriesStyle(NDF_KEYS.length), dash: SERIES_DASHES[1] };

/** θh in degrees: every 0.25° and the θh nodes of a MERL table (where a measured slice has its values), in order. */
export const ANGLES = Float64Array.from(
  new Set([...Array.from({ length: 361 }, (_, i) => i * 0.25), ...THETA_H_DEG]),
).sort();
const NODE_AT = new Map(Array.from(THETA_H_DEG, (deg, i) => [deg, i]));

/** The plots' θh axis. */
export const THETA_AXIS = {
  xLabel: 'Angle of the microfacet normal from n, θh (degrees)',
  x: { min: 0, max: 90 },
  xValues: (u, t) => t.map((v) => `${v}°`),
};

/**
 * The log plot's axes for `curves` (D in 1/sr over θh, down to 1e-7 of the highest peak), and `clip`, which leaves
 * out the values below that floor. The NDF exercise draws its hidden highlight on these same axes.
 */
export function logAxes(curves) {
  const peak = Math.max(...curves.map((c) => c.values[0]), 1e-3);
  const clip = (values) => Array.from(values, (v) => (v > peak * 1e-7 ? v : null));
  return { ...THETA_AXIS, yLabel: 'D (1/sr)', y: { min: peak * 1e-7, max: peak * 2, log: true }, clip };
}

/** The measured slice on ANGLES: its value at each node, null between nodes and where it is 0 (missing). */
export const measuredOnAngles = (slice) =>
  Array.from(ANGLES, (deg) => (NODE_AT.has(deg) && slice[NODE_AT.get(deg)] > 0 ? slice[NODE_AT.get(deg)] : null));

/**
 * One curve per chosen NDF: { key, p (its parameters at the matched width, as NDF_TERMS read them), label,
 * stroke, dash, values (D over ANGLES, 1/sr), integral (∫ D (n·m) dω, 1 for a density) }. The user's D (`custom`)
 * is not among them: its values come from the GPU (custom.js), and `withStyle` dresses its curve like these.
 */
export function ndfCurves(state) {
  const params = matchNdfWidths(state.hwhm, { abcA2: state.abcA2, sgdP: state.sgdP });
  return state.D.filter((key) => NDF_KEYS.includes(key)).map((key) => {
    const p = params[key];
    const D = (c) => NDF_TERMS[key](c, p);
    let integral = null;
    return {
      key,
      p,
      aniso: anisotropicLobe(key, p, state),
      ...withStyle(key),
      values: ANGLES.map((deg) => D(Math.cos(deg * DEG))),
      /** Computed when first read: only the table shows it, and it costs more than a frame while dragging. */
      get integral() {
        integral ??= ndfProjectedIntegral(D);
        return integral;
      },
    };
  });
}

/** Where the tails are compared: beyond every matched width (1°–40°), short of grazing. One of ANGLES. */
export const TAIL_DEG = 60;

/** The curves by their tail, longest first: D(TAIL_DEG) / D(0), how much of its peak each keeps that far out. */
export function tailsAt(curves) {
  const i = ANGLES.indexOf(TAIL_DEG);
  return curves
    .map((c) => ({ key: c.key, label: c.label, ratio: c.values[i] / c.values[0] }))
    .sort((a, b) => b.ratio - a.ratio);
}
