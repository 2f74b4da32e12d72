// The math behind the anisotropic views (issue 28): the non-swirling tangent frame of the spheres, and the half
// width of an anisotropic NDF along each axis, against closed forms.
import { describe, expect, it } from 'vitest';
import { inTangentFrame, tangentFrameAlong } from '../../src/math/tangent-frame.js';
import { ndfHalfWidthsAlongAxes } from '../../src/math/anisotropic-width.js';
import { ndfBeckmannAniso, ndfGGXAniso } from '../../src/math/anisotropic.js';
import { DEG } from '../../src/math/angles.js';

const unit = (x, y, z) => [x, y, z].map((c) => c / Math.hypot(x, y, z));
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

describe('tangentFrameAlong: the tangent is the axis in the tangent plane', () => {
  it('is orthonormal and right-handed, and t lies in the plane of the axis and n', () => {
    for (const n of [unit(0, 0, 1), unit(0.3, -0.5, 0.8), unit(-0.9, 0.1, 0.2), unit(0, 0.99, 0.1)]) {
      const { t, b } = tangentFrameAlong(n, [1, 0, 0]);
      expect(dot(t, t)).toBeCloseTo(1, 14);
      expect(dot(t, n)).toBeCloseTo(0, 14);
      expect(dot(b, t)).toBeCloseTo(0, 14);
      expect(dot(b, [n[1] * t[2] - n[2] * t[1], n[2] * t[0] - n[0] * t[2], n[0] * t[1] - n[1] * t[0]])).toBeCloseTo(1);
      expect(t[0]).toBeGreaterThan(0); // points along the axis, not against it
      // the axis is a t, n combination: no part of it along b
      expect(dot([1, 0, 0], b)).toBeCloseTo(0, 14);
    }
  });
  it('does not swirl: where the axis is already tangent (n ⟂ x), t is the axis itself', () => {
    // n = (0, sin θ, cos θ) is perpendicular to x for every θ: t = x exactly (cross(z, n) would turn with n)
    for (const theta of [0, 0.3, 1, 1.5]) {
      const { t } = tangentFrameAlong([0, Math.sin(theta), Math.cos(theta)], [1, 0, 0]);
      expect(t.map((x) => x + 0)).toEqual([1, 0, 0]);
    }
  });
  it('falls back to the frame around z where n is along the axis', () => {
    const { t } = tangentFrameAlong([1, 0, 0], [1, 0, 0]);
    expect(t).toEqual([0, 1, 0]); // cross(z, x)
    const w = unit(0.2, 0.4, 0.9);
    const n = unit(0.3, -0.5, 0.8);
    const local = inTangentFrame(w, n, tangentFrameAlong(n, [1, 0, 0]));
    expect(Math.hypot(...local)).toBeCloseTo(1, 14);
    expect(local[2]).toBeCloseTo(dot(w, n), 14);
  });
});

describe('ndfHalfWidthsAlongAxes: each axis has the isotropic half width of its α', () => {
  it('GGX: sin²θ = (√2 − 1) α² / (1 − α²) along each axis (D(θ) = D(0)/2 solved)', () => {
    const closed = (a) => Math.asin(Math.sqrt(((Math.SQRT2 - 1) * a * a) / (1 - a * a))) / DEG;
    for (const [ax, ay] of [
      [0.3, 0.1],
      [0.05, 0.6],
      [0.2, 0.2],
    ]) {
      const [t, b] = ndfHalfWidthsAlongAxes(ndfGGXAniso, ax, ay);
      expect(t).toBeCloseTo(closed(ax), 9);
      expect(b).toBeCloseTo(closed(ay), 9);
    }
  });
  it('Beckmann: α = tan θ / sqrt(ln 2 − 4 ln cos θ) at the half width found', () => {
    const alphaOf = (deg) => Math.tan(deg * DEG) / Math.sqrt(Math.LN2 - 4 * Math.log(Math.cos(deg * DEG)));
    const [t, b] = ndfHalfWidthsAlongAxes(ndfBeckmannAniso, 0.4, 0.08);
    expect(alphaOf(t)).toBeCloseTo(0.4, 9);
    expect(alphaOf(b)).toBeCloseTo(0.08, 9);
  });
  it('is null along an axis where GGX never falls to half (α ≥ 1: flat or rising to the horizon)', () => {
    expect(ndfHalfWidthsAlongAxes(ndfGGXAniso, 1.5, 0.2)[0]).toBeNull();
    expect(ndfHalfWidthsAlongAxes(ndfGGXAniso, 1.5, 0.2)[1]).not.toBeNull();
  });
});
