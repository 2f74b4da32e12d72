// anisotropicBentReflection against three.js's getIBLAnisotropyRadiance written with its cross products
// (bentNormal = normalize(mix(normalize(cross(cross(grain, v), grain)), n, (1 - a (1 - r))⁴)), r = √α), and
// against the mirror about n where it must be that.
import { describe, expect, it } from 'vitest';
import { anisotropicBentReflection } from '../../src/math/anisotropic.js';

const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const normalize = (a) => a.map((c) => c / Math.hypot(...a));
const reflectAbout = (v, n) => n.map((c, i) => 2 * dot(v, n) * c - v[i]);
const spherical = (theta, phi) => [Math.sin(theta) * Math.cos(phi), Math.sin(theta) * Math.sin(phi), Math.cos(theta)];

/** three.js r160's bent normal, the grain b for a >= 0 and t for a < 0 (Filament's sign convention). */
function threeJsBent(v, alpha, a) {
  const grain = a >= 0 ? [0, 1, 0] : [1, 0, 0];
  const across = normalize(cross(cross(grain, v), grain));
  const w = (1 - Math.abs(a) * (1 - Math.sqrt(alpha))) ** 4;
  return reflectAbout(v, normalize(across.map((c, i) => c * (1 - w) + [0, 0, 1][i] * w)));
}

const VIEWS = [spherical(0.3, 0.5), spherical(1.2, 2), spherical(1.5, -0.7), spherical(Math.PI / 2 - 1e-4, 0.2)];

describe('anisotropicBentReflection: three.js’s cross-product form, the mirror where there is no bend', () => {
  it('matches three.js’s getIBLAnisotropyRadiance bent normal within 1e-12 for a in ±[0.2, 1], α in [0.01, 1]', () => {
    for (const v of VIEWS) {
      for (const a of [-1, -0.6, -0.2, 0.2, 0.6, 1]) {
        for (const alpha of [0.01, 0.09, 0.36, 1]) {
          const got = anisotropicBentReflection(...v, alpha, a);
          threeJsBent(v, alpha, a).forEach((c, i) => expect(got[i]).toBeCloseTo(c, 12));
          expect(Math.hypot(...got)).toBeCloseTo(1, 12);
        }
      }
    }
  });

  it('is the mirror about n at a = 0, at α = 1, and for v along the grain', () => {
    const mirror = (v) => [-v[0], -v[1], v[2]];
    for (const v of VIEWS) {
      for (const [alpha, a] of [
        [0.3, 0],
        [1, 1],
        [1, -1],
      ]) {
        anisotropicBentReflection(...v, alpha, a).forEach((c, i) => expect(c).toBeCloseTo(mirror(v)[i], 14));
      }
    }
    const close = (got, want) => want.forEach((c, i) => expect(got[i]).toBeCloseTo(c, 15));
    close(anisotropicBentReflection(0, 1, 0, 0.2, 1), [0, -1, 0]);
    close(anisotropicBentReflection(1, 0, 0, 0.2, -1), [-1, 0, 0]);
  });

  it('at a = ±1, α = 0 the bent normal lies across the grain: only v’s part along the grain flips', () => {
    for (const v of VIEWS) {
      const [vx, vy, vz] = v;
      const alongT = anisotropicBentReflection(...v, 0, 1); // grain b
      [vx, -vy, vz].forEach((c, i) => expect(alongT[i]).toBeCloseTo(c, 13));
      const alongB = anisotropicBentReflection(...v, 0, -1); // grain t
      [-vx, vy, vz].forEach((c, i) => expect(alongB[i]).toBeCloseTo(c, 13));
    }
  });
});
