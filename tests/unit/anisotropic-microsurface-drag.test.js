// anisotropic-microsurface while a control moves (bench/latency.js): the surface of every other point is the same
// surface, not another one, against the whole surface built at the same seed (model.js).
import { describe, expect, it } from 'vitest';
import { GRID, createSurface } from '../../src/widgets/anisotropic-microsurface/model.js';
import { schema } from '../../src/widgets/anisotropic-microsurface/schema.js';
import { shadedWindow } from '../../src/widgets/anisotropic-microsurface/surface-view.js';

const state = { ...Object.fromEntries(Object.entries(schema).map(([k, f]) => [k, f.default])), alphaX: 0.8 };

describe('anisotropic-microsurface: the surface of every other point', () => {
  it('has the whole surface’s heights at every other point, in cells of twice the size', () => {
    const [whole, half] = [createSurface(state), createSurface(state, 2)];
    expect(half.field.n).toBe(GRID / 2);
    let worst = 0;
    for (let j = 0; j < half.field.n; j++)
      for (let i = 0; i < half.field.n; i++) {
        const fine = whole.field.h[2 * j * GRID + 2 * i] / 2;
        worst = Math.max(worst, Math.abs(half.field.h[j * half.field.n + i] - fine));
      }
    expect(worst).toBeLessThan(1e-9);
    // its facets, over twice the span, a little smoother: within a fifth of the whole surface's pair
    half.alphas.forEach((a, k) => expect(a / whole.alphas[k]).toBeGreaterThan(0.8));
    half.alphas.forEach((a, k) => expect(a).toBeLessThanOrEqual(whole.alphas[k]));
  });
  it('draws nearly the same picture: the share in shadow within 0.05 of the whole surface’s', () => {
    const [whole, half] = [createSurface(state), createSurface(state, 2)];
    const shares = [whole, half].map((s) => shadedWindow(s, 75, 30, 96).shadowShare);
    console.log(`shadow share, whole ${shares[0].toFixed(3)}, every other point ${shares[1].toFixed(3)}`);
    expect(Math.abs(shares[0] - shares[1])).toBeLessThan(0.05);
    expect(shares[0]).toBeGreaterThan(0.05);
  });
});
