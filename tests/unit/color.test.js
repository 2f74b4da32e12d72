import { describe, expect, it } from 'vitest';
import { linearToSrgb, srgbToLinear } from '../../src/math/color.js';
import { METALS, NON_METALS } from '../../src/math/materials.js';

describe('sRGB transfer (IEC 61966-2-1)', () => {
  it('matches published reference points', () => {
    // 8-bit mid grey 128/255 -> 0.2158605 linear, and the curve's joins
    expect(srgbToLinear(128 / 255)).toBeCloseTo(0.2158605, 6);
    expect(srgbToLinear(0.04045)).toBeCloseTo(0.04045 / 12.92, 12);
    expect(linearToSrgb(0.0031308)).toBeCloseTo(0.0031308 * 12.92, 9);
    expect(linearToSrgb(0.18)).toBeCloseTo(0.4613561, 6);
  });
  it('round-trips and is monotonic', () => {
    let prev = -1;
    for (let i = 0; i <= 1000; i++) {
      const x = i / 1000;
      expect(linearToSrgb(srgbToLinear(x))).toBeCloseTo(x, 12);
      expect(srgbToLinear(x)).toBeGreaterThan(prev);
      prev = srgbToLinear(x);
    }
  });
  it('clamps out-of-range input to [0, 1]', () => {
    expect(srgbToLinear(-0.5)).toBe(0);
    expect(srgbToLinear(1.5)).toBeCloseTo(1, 15);
    expect(linearToSrgb(-1)).toBe(0);
    expect(linearToSrgb(2)).toBeCloseTo(1, 15);
  });
  it("agrees with the talk's linear/sRGB table pairs to the table's two-decimal rounding", () => {
    // Each printed value stands for an interval of width 0.01; the sRGB of the linear interval must
    // overlap the printed sRGB interval.
    for (const m of [...METALS, ...NON_METALS]) {
      m.linear.forEach((lin, i) => {
        const lo = linearToSrgb(Math.max(lin - 0.005, 0));
        const hi = linearToSrgb(Math.min(lin + 0.005, 1));
        const s = m.srgb[i];
        expect(hi >= s - 0.005 && lo <= s + 0.005, `${m.name} channel ${i}: sRGB(${lin}) in [${lo}, ${hi}] vs ${s}`).toBe(true);
      });
    }
  });
});
