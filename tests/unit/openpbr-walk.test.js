// The coat over a base: OpenPBR's albedo scaling (openPbrBRDF, its directional albedo by quadrature) against light
// followed through the layers by Monte Carlo (layeredWalkAlbedo, position-free as in Guo, Hašan & Zhao 2018). The
// walk is first held to a closed form (a smooth clear coat over Lambert, the "interfaced Lambertian" of Elias 2001
// and d'Eon 2021, the formula the specification's darkening is built on); then the differences the albedo scaling
// makes are printed and bounded: what it misses.
import { describe, expect, it } from 'vitest';
import { layeredWalkAlbedo } from '../../src/math/openpbr-walk.js';
import { openPbrCoatDarkening, openPbrMaterial } from '../../src/math/openpbr.js';
import { fresnelDielectric } from '../../src/math/fresnel.js';
import { fresnelDielectricAverage } from '../../src/math/openpbr-albedo.js';
import { gaussLegendreVector } from '../../src/math/quadrature.js';
import { openPbrAlbedo } from '../support/openpbr-albedo.js';

const SAMPLES = 100000; // per angle: standard error ≤ 1.4e-3 (printed), each angle its own seed
const MUS = [1, 0.5, 0.2];
const sigma = (coatColor) => coatColor.map((t) => -Math.log(t) / 2); // a normal-incidence round trip: coat_color

/** The model's albedo, [r, g, b], with the specification's darkening or (referenceGraph) MaterialX graph's. */
function modelAlbedo(material, mu, referenceGraph = false) {
  const m = openPbrMaterial(material);
  const a = openPbrAlbedo(m, mu, 24);
  const [spec, graph] = [false, true].map((g) => openPbrCoatDarkening(m, mu, g));
  const ratio = referenceGraph ? graph.map((x, c) => x / spec[c]) : [1, 1, 1];
  return a.total.map((t, c) => a.coat[c] + a.fuzz[c] + ratio[c] * (t - a.coat[c] - a.fuzz[c]));
}

const CASES = {
  'tinted rough coat over Lambert': {
    material: { coat_weight: 1, coat_roughness: 0.3, coat_color: [0.9, 0.6, 0.3], specular_weight: 0, base_color: 0.8 },
    stack: {
      coat: { alpha: 0.09, eta: 1.6, sigma: sigma([0.9, 0.6, 0.3]) },
      base: { kind: 'lambert', albedo: [0.8, 0.8, 0.8] },
    },
  },
  'clear rough coat over gold': {
    material: {
      coat_weight: 1,
      coat_roughness: 0.3,
      base_metalness: 1,
      base_color: [1, 0.78, 0.34],
      specular_color: [0.95, 0.9, 0.8],
    },
    stack: {
      coat: { alpha: 0.09, eta: 1.6, sigma: [0, 0, 0] },
      base: { kind: 'conductor', alpha: 0.09, f0: [1, 0.78, 0.34], tint: [0.95, 0.9, 0.8] },
    },
  },
};

describe('the layered random walk', () => {
  it('equals the interfaced Lambertian closed form, F + (1 − F) ρ (1 − K)/(1 − ρK), within 4 standard errors', () => {
    const eta = 1.6;
    // K: the diffuse light a smooth interface sends back inside, 1 − (1 − F̄)/η², F̄ by quadrature here
    const fAvg = gaussLegendreVector((s) => [4 * fresnelDielectric(s * s, eta) * s ** 3], 0, 1, 200, 1)[0];
    expect(fresnelDielectricAverage(eta)).toBeCloseTo(fAvg, 13);
    const K = 1 - (1 - fAvg) / (eta * eta);
    const rho = [1, 0.5, 0.2];
    MUS.forEach((mu, i) => {
      const stack = { coat: { alpha: 1e-4, eta, sigma: [0, 0, 0] }, base: { kind: 'lambert', albedo: rho } };
      const { albedo, standardError } = layeredWalkAlbedo(mu, stack, SAMPLES, 11 + i);
      const F = fresnelDielectric(mu, eta);
      rho.forEach((r, c) => {
        const exact = F + ((1 - F) * r * (1 - K)) / (1 - r * K);
        // at ρ = 1 the weights barely vary: the slack is the 1e-7 the microsurface shadows
        expect(Math.abs(albedo[c] - exact)).toBeLessThanOrEqual(4 * standardError[c] + 1e-6);
      });
      expect(albedo[0]).toBeCloseTo(1, 6); // white: all but the ~1e-7 a microsurface of α = 1e-4 shadows comes out
    });
  });

  it("the specification's albedo scaling and darkening give that closed form too (a smooth coat over Lambert)", () => {
    const eta = 1.6;
    const K = 1 - (1 - fresnelDielectricAverage(eta)) / (eta * eta);
    for (const mu of MUS) {
      const got = modelAlbedo({ coat_weight: 1, specular_weight: 0, base_color: [1, 0.5, 0.2] }, mu);
      const F = fresnelDielectric(mu, eta);
      // within the albedo table's error at α = 1e-4 (measured 6.7e-4)
      [1, 0.5, 0.2].forEach((r, c) =>
        expect(Math.abs(got[c] - F - ((1 - F) * r * (1 - K)) / (1 - r * K))).toBeLessThan(1.5e-3),
      );
    }
  });
});

describe('what albedo scaling misses, against the walk', () => {
  const rows = [];
  for (const [name, { material, stack }] of Object.entries(CASES)) {
    it(`${name}`, () => {
      MUS.forEach((mu, i) => {
        const walk = layeredWalkAlbedo(mu, stack, SAMPLES, 101 + i);
        const [spec, graph] = [false, true].map((g) => modelAlbedo(material, mu, g));
        const fmt = (x) => x.map((y) => y.toFixed(3)).join(' ');
        const se = Math.max(...walk.standardError);
        rows.push(
          `${name.padEnd(32)} μ=${mu} walk ${fmt(walk.albedo)} (se ${se.toExponential(1)}) ` +
            `spec ${fmt(spec)} graph ${fmt(graph)}`,
        );
        expect(se).toBeLessThan(1.5e-3);
        // bounded: within 0.15 of the walk in every channel (the coat's absorption along the inner bounces is what
        // it misses most, up to 0.11 here)
        spec.forEach((x, c) => expect(Math.abs(x - walk.albedo[c])).toBeLessThan(0.15));
        if (name.includes('gold') && mu === 1) {
          // a smooth metal under a clear coat: the specification's K (K_s, by the base's roughness) is nearer the
          // walk than the graph's Lambertian K, which darkens the green and blue by 0.15
          spec.forEach((x, c) => expect(Math.abs(x - walk.albedo[c])).toBeLessThan(0.03));
          expect(Math.abs(graph[1] - walk.albedo[1])).toBeGreaterThan(0.1);
        }
      });
    });
  }
  it('prints them', () => {
    console.log(rows.join('\n'));
    expect(rows).toHaveLength(2 * MUS.length);
  });
});
