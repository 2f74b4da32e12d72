// Issue 28's widget exercises on anisotropic highlights, against closed forms written here: GGX on the sphere in
// the talk's isotropic form, and along the picture's middle row and column, where anisotropic GGX depends on one α.
import { describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { GRADERS } from '../../src/exercises/graders.js';
import { anisotropicSphere } from '../../src/exercises/sphere-image.js';
import { ALPHA_PAIRS } from '../../src/exercises/graders/aniso-pair.js';

const shipped = (id) =>
  JSON.parse(readFileSync(join(import.meta.dirname, `../../public/exercises/${id}.json`), 'utf8'));

/** Isotropic GGX (Walter et al. 2007) as the talk writes it, α²/(π((n·h)²(α² − 1) + 1)²). */
const ggx = (nh, a) => (a * a) / (Math.PI * (nh * nh * (a * a - 1) + 1) ** 2);

describe('the anisotropic sphere', () => {
  it('at αx = αy is the talk’s isotropic GGX highlight, π·D/4·(n·l), pixel by pixel', () => {
    const size = 24;
    const theta = 30 * (Math.PI / 180);
    const l = [Math.sin(theta), 0, Math.cos(theta)];
    const h = [l[0], 0, l[2] + 1].map((x) => x / Math.hypot(l[0], l[2] + 1));
    const img = anisotropicSphere(size, 30, [0.3, 0.3]);
    for (let i = 0; i < img.length; i++) {
      const x = ((i % size) + 0.5) / (size / 2) - 1;
      const y = 1 - (Math.floor(i / size) + 0.5) / (size / 2);
      if (x * x + y * y >= 1) continue;
      const n = [x, y, Math.sqrt(1 - x * x - y * y)];
      const nl = n[0] * l[0] + n[2] * l[2];
      const expected = nl > 0 ? (Math.PI * ggx(n[0] * h[0] + n[2] * h[2], 0.3) * nl) / 4 : 0;
      expect(img[i]).toBeCloseTo(expected, 9);
    }
  });
});

/**
 * Where D falls to half its peak along the middle row (y = 0) of a sphere lit from the view: there n = (x, 0, z),
 * the tangent (z, 0, −x) and h = (0, 0, 1), so hx = −x, hy = 0, hz = z and D ∝ 1/(x²/αx² + z²)²: only αx counts.
 * The column's is the same with αy. Returns the half-width in x of D alone (n·l = z changes it little).
 */
const halfWidth = (a) => {
  const half = (x) => 1 / ((x * x) / (a * a) + 1 - x * x) ** 2 - 0.5;
  let [lo, hi] = [0, 1];
  for (let k = 0; k < 60; k++) [lo, hi] = half((lo + hi) / 2) > 0 ? [(lo + hi) / 2, hi] : [lo, (lo + hi) / 2];
  return lo;
};

describe('highlight-stretch', () => {
  const { params, tolerance } = shipped('highlight-stretch');
  const full = { lightTheta: 20, size: 64, ...params };
  const grade = (answer, p = full) => GRADERS['highlight-stretch'].grade({ answer, params: p, tolerance });

  it('αx = 0.4 > αy = 0.1: along the tangent, as the closed-form half-widths along the row and column say', () => {
    expect(halfWidth(params.alphaX) / halfWidth(params.alphaY)).toBeGreaterThan(3);
    expect(grade('tangent').ok).toBe(true);
    expect(grade('bitangent').ok).toBe(false);
    expect(grade('round').ok).toBe(false);
    expect(GRADERS['highlight-stretch'].check(full, tolerance)).toEqual([]);
  });

  it('swapped, across the tangent; equal, round', () => {
    expect(grade('bitangent', { ...full, alphaX: 0.1, alphaY: 0.4 }).ok).toBe(true);
    expect(grade('round', { ...full, alphaX: 0.25, alphaY: 0.25 }).ok).toBe(true);
    // too close to call: refused as a question
    expect(GRADERS['highlight-stretch'].check({ ...full, alphaX: 0.2, alphaY: 0.18 }, tolerance)).not.toEqual([]);
  });
});

describe('aniso-pair', () => {
  const { params, tolerance } = shipped('aniso-pair');
  const full = { lightTheta: 20, size: 64, ...params };
  const grader = GRADERS['aniso-pair'];

  it('accepts the hidden pair only, whichever is hidden, and the question is well posed', () => {
    expect(grader.check(full, tolerance)).toEqual([]);
    for (const hidden of Object.keys(ALPHA_PAIRS))
      for (const answer of Object.keys(ALPHA_PAIRS))
        expect(grader.grade({ answer, params: full, tolerance, hidden }).ok, `${answer} for ${hidden}`).toBe(
          answer === hidden,
        );
  });

  it('says which way a wrong pair’s highlight reaches further, as the row’s and column’s half-widths do', () => {
    const r = grader.grade({ answer: 'wideY', params: full, tolerance, hidden: 'wideX' });
    const [x, y] = [halfWidth(0.1) / halfWidth(0.4), halfWidth(0.4) / halfWidth(0.1)];
    const [, reachX, reachY] = r.details[0].match(/reaches ([\d.]+)× as far left to right .* and ([\d.]+)× as far/);
    expect(Number(reachX)).toBeLessThan(1);
    expect(Number(reachY)).toBeGreaterThan(1);
    expect(Number(reachX)).toBeCloseTo(x, 0);
    expect(Number(reachY) / y).toBeGreaterThan(0.5);
    expect(grader.check(full, 1)).not.toEqual([]); // a tolerance that lets every picture pass is refused
  });
});
