// The labels that tell a student a figure is not what it seems: Gulbrandsen's (n, k) marked as fitted (they
// reproduce the talk's F0 and are not the measured constants), and Oren–Nayar's σ past 45° marked as extrapolated
// (the share of a Gaussian of tilts beyond 90°, from erfc, is what the 45° rule rests on).
import { describe, expect, it } from 'vitest';
import { curveSpecs } from '../../src/widgets/fresnel-curves/model.js';
import { f0FromIor } from '../../src/math/fresnel.js';
import { materialByKey, measuredSource } from '../../src/math/materials.js';
import { erfc } from '../../src/math/special.js';
import { SIGMA_MODELLED_DEG, sigmaText } from '../../src/core/ui/sigma-range.js';
import { approximationNotes } from '../../src/lab/lab-approximations.js';

describe('fitted (n, k) flag of the Fresnel curves', () => {
  it('marks f0-tint rows fitted: their F0 is the talk’s table (Fresnel at 0°), their n, k not the measured', () => {
    const fitted = curveSpecs({ materials: ['gold'], conductor: 'f0-tint', ior: 1.5 });
    const measured = curveSpecs({ materials: ['gold'], conductor: 'measured', ior: 1.5 });
    expect(fitted.map((s) => s.fitted)).toEqual([true, true, true]);
    expect(measured.map((s) => s.fitted)).toEqual([false, false, false]);
    fitted.forEach((s, i) => {
      // gold's red F0 of 1.0 is fitted as 0.999 (F0 = 1 needs k = ∞)
      expect(Math.abs(f0FromIor(s.eta, s.k) - materialByKey('gold').linear[i])).toBeLessThanOrEqual(1e-3 + 1e-12);
      expect(Math.abs(s.eta - measured[i].eta) + Math.abs(s.k - measured[i].k)).toBeGreaterThan(1e-3);
    });
    expect(measuredSource('gold')).toBeTruthy();
  });
  it('leaves dielectrics and an n set by hand unflagged', () => {
    const specs = curveSpecs({ materials: ['water', 'manual'], conductor: 'f0-tint', ior: 1.5 });
    expect(specs.map((s) => Boolean(s.fitted))).toEqual([false, false]);
  });
});

describe('Oren–Nayar σ extrapolation label', () => {
  it('rests on 4.6% of a Gaussian of tilts with σ = 45° lying past 90° (2σ, erfc(√2))', () => {
    expect(erfc(90 / SIGMA_MODELLED_DEG / Math.SQRT2)).toBeCloseTo(0.0455, 4);
  });
  it('sigmaText says "extrapolated" above 45° and not at 45°', () => {
    expect(sigmaText(46)).toContain('extrapolated');
    expect(sigmaText(45)).not.toContain('extrapolated');
    expect(sigmaText(45)).toBe('σ = 45° (0.785 rad)');
  });
  it('the material lab adds the same label for either Oren–Nayar form above 45°, and nothing for Lambert', () => {
    const scene = (diffuse, sigmaDeg) => ({
      terms: { F: 'schlick', D: 'ggx', V: 'smithGGXCorrelated', diffuse, layers: 'both' },
      lights: { punctual: { dir: [0, 0, 1] }, sphere: null, env: null, ambient: null },
      methods: { env: 'split-sum', area: 'representative', samples: 16 },
      material: { sigma: (sigmaDeg * Math.PI) / 180 },
    });
    for (const diffuse of ['oren-nayar', 'oren-nayar-qualitative']) {
      expect(approximationNotes(scene(diffuse, 50)).join(' ')).toContain('σ = 50° (0.873 rad, extrapolated)');
      expect(approximationNotes(scene(diffuse, 45)).join(' ')).not.toContain('extrapolated');
    }
    expect(approximationNotes(scene('lambert', 60)).join(' ')).not.toContain('extrapolated');
  });
});
