// microfacets' model on a surface whose answers are known: a flat profile, where every facet is lit and seen
// when light and eye are above it, only a facet along h = the mean normal is marked, and every ray reflects
// by the mirror law (angle out = angle in) and leaves without a second bounce.
import { describe, expect, it } from 'vitest';
import {
  PROFILE,
  WINDOW,
  dirOf,
  facetsSeen,
  halfAngleDeg,
  surfaceWindow,
  traceRays,
} from '../../src/widgets/microfacets/model.js';
import { heightBounds } from '../../src/math/microsurface.js';

const profile = new Float64Array(PROFILE + 1);
const flat = { profile, bounds: heightBounds(profile) };
const win = surfaceWindow(profile);

describe('microfacets model on a flat surface', () => {
  it('the window is WINDOW facets in the middle, at mean height 0', () => {
    expect(win.x1 - win.x0).toBe(WINDOW);
    expect(win.mean).toBe(0);
  });
  it('every piece is lit and seen; facets are marked along h only when h is the normal (within 3°)', () => {
    const facets = facetsSeen(flat, win, dirOf(40), dirOf(-40));
    expect(facets).toHaveLength(WINDOW);
    expect(facets.every((f) => f.pieces.every((p) => p.lit && p.seen))).toBe(true);
    expect(facets.every((f) => f.normal)).toBe(true);
    expect(facetsSeen(flat, win, dirOf(40), dirOf(-20)).some((f) => f.normal)).toBe(false);
  });
  it('h bisects l and v', () => {
    expect(halfAngleDeg(dirOf(70), dirOf(-40))).toBeCloseTo(15, 12);
  });
  it('each ray meets the surface under its start, reflects at the mirror angle, and never hits it again', () => {
    const l = dirOf(55);
    const rays = traceRays(flat, win, l, 12, 10);
    expect(rays).toHaveLength(12);
    rays.forEach((ray, r) => {
      expect(ray.hit.x).toBeCloseTo(win.x0 + ((r + 0.5) / 12) * WINDOW, 9);
      expect(ray.hit.y).toBe(0);
      const out = [ray.end.x - ray.hit.x, ray.end.y - ray.hit.y];
      expect(Math.atan2(out[0], out[1])).toBeCloseTo(-Math.atan2(l[0], l[1]), 12);
      expect(ray.second).toBeNull();
    });
  });
});
