// @ts-check
// A tangent frame that does not swirl: the tangent t is a chosen axis projected on the tangent plane of n, so across
// a sphere it keeps one direction (brushed along that axis), unlike cross(z, n), which turns once around the view
// axis. The JS twin of the frame in shaders/brdf-sphere.frag.glsl (same fallback where n is along the axis).

/** @param {number[]} a @param {number[]} b */
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
/** @param {number[]} a @param {number[]} b */
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
/** @param {number[]} a */
const normalize = (a) => a.map((x) => x / Math.hypot(...a));

/**
 * { t, b } at the unit normal n for the axis (any length): t = normalize(axis - n (n·axis)), b = n × t; where the
 * axis is along n (or 0), the frame around the view axis z the spheres used before, cross(z, n).
 * @param {number[]} n
 * @param {number[]} axis
 */
export function tangentFrameAlong(n, axis) {
  const k = dot(n, axis);
  const tp = axis.map((x, i) => x - n[i] * k);
  const t = dot(tp, tp) > 1e-8 ? normalize(tp) : normalize(cross(Math.abs(n[2]) < 0.999 ? [0, 0, 1] : [1, 0, 0], n));
  return { t, b: cross(n, t) };
}

/**
 * A direction w in the frame (t, b, n): [w·t, w·b, w·n], as the BRDF reads it.
 * @param {number[]} w
 * @param {number[]} n
 * @param {{ t: number[], b: number[] }} frame
 */
export const inTangentFrame = (w, n, { t, b }) => [dot(w, t), dot(w, b), dot(w, n)];
