// The tour's anisotropy step (issue 28): its numbers read out of its sentence and recomputed here: the matched GGX α
// (src/math/ndf-width.js), Burley 2012's pair α/aspect, α·aspect with aspect = √(1 − 0.9 a), and the half widths of
// anisotropic GGX (Heitz 2014) along each axis by bisection on its closed form, D(θ)/D(0) = 1/(sin²θ/αᵢ² + cos²θ)².
import { describe, expect, it } from 'vitest';
import { quoted, reads, stepText as step } from '../support/quoted-text.js';
import { matchNdfWidths } from '../../src/math/ndf-width.js';
import { DEG } from '../../src/math/angles.js';

/** The θ (degrees) where D falls to half its peak along an axis of roughness a. */
function halfWidthDeg(a) {
  const below = (deg) => {
    const [s, c] = [Math.sin(deg * DEG), Math.cos(deg * DEG)];
    return 1 / ((s * s) / (a * a) + c * c) ** 2 < 0.5;
  };
  let [lo, hi] = [0, 89];
  for (let k = 0; k < 60; k++) [lo, hi] = below((lo + hi) / 2) ? [lo, (lo + hi) / 2] : [(lo + hi) / 2, hi];
  return lo;
}

describe('tour, ndf-anisotropic: GGX stretched by Burley’s mapping at the step’s state', () => {
  it('says it goes beyond the talk; α = 0.21 becomes (0.40, 0.11), half widths 16° and 4°', () => {
    const s = step('ndf-anisotropic');
    expect(s.text).toMatch(/^This goes beyond the talk/);
    const [alpha, ax, ay, along, across] = quoted(
      s.text,
      /GGX’s α = ([\d.]+) becomes \(αx, αy\) = \(([\d.]+), ([\d.]+)\).* half width of (\d+)° against (\d+)°/,
    );
    const a = matchNdfWidths(s.state.hwhm, {}).ggx.alpha;
    const aspect = Math.sqrt(1 - 0.9 * s.state.anisotropy);
    reads(a, alpha, 2);
    reads(a / aspect, ax, 2);
    reads(a * aspect, ay, 2);
    reads(halfWidthDeg(a / aspect), along);
    reads(halfWidthDeg(a * aspect), across);
  });
});
