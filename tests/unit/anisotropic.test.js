// The anisotropic microfacet functions (src/math/anisotropic.js) against independent truths: the normalisation of
// D by 2-D quadrature, Heitz's weak white furnace for D with its own Λ, the swap of the tangent axes, the isotropic
// functions at αx = αy, and what the three roughness conventions' specifications state.
import { describe, expect, it } from 'vitest';
import * as M from '../../src/math/index.js';
import { gaussLegendre } from '../../src/math/quadrature.js';
import { seededRandom } from '../../src/math/microsurface.js';

/** ∫_a^b f by n-point Gauss–Legendre. */
function gauss(f, a, b, n) {
  const { x, w } = gaussLegendre(n);
  const half = (b - a) / 2;
  let sum = 0;
  for (let i = 0; i < n; i++) sum += w[i] * f(a + half * (1 + x[i]));
  return sum * half;
}

/** The unit half vector of slope (sx, sy): the facet whose tangent plane rises by sx along t and sy along b. */
const halfFromSlope = (sx, sy) => {
  const hz = 1 / Math.sqrt(1 + sx * sx + sy * sy);
  return [-sx * hz, -sy * hz, hz];
};

const NDFS = { ggx: M.ndfGGXAniso, beckmann: M.ndfBeckmannAniso };
const G1S = { ggx: M.smithG1GGXAniso, beckmann: M.smithG1BeckmannAniso };

/**
 * ∫ D(h)(n·h) dω_h = ∫∫ D(h(s)) hz⁴ d²s over the slope plane (D hz dω = D hz⁴ d²s), with the substitution
 * s = (αx ρ cos ψ, αy ρ sin ψ), ρ = tan β: the lobe's ellipse becomes a disc, whatever αx/αy (here to 1e-3).
 * Gauss–Legendre in β, the trapezoid rule in ψ (periodic: spectrally accurate).
 */
function normalisationInSlopeSpace(D, ax, ay, nBeta = 96, nPsi = 64) {
  let sum = 0;
  for (let j = 0; j < nPsi; j++) {
    const psi = (2 * Math.PI * (j + 0.5)) / nPsi;
    sum += gauss(
      (beta) => {
        const rho = Math.tan(beta);
        const h = halfFromSlope(ax * rho * Math.cos(psi), ay * rho * Math.sin(psi));
        return D(...h, ax, ay) * h[2] ** 4 * ax * ay * rho * (1 + rho * rho);
      },
      0,
      Math.PI / 2,
      nBeta,
    );
  }
  return (sum * 2 * Math.PI) / nPsi;
}

/** The same integral over the hemisphere in (θ, φ) with no adaptation to the lobe: for moderate α only. */
function normalisationInAngles(D, ax, ay, n = 200) {
  return gauss(
    (phi) =>
      gauss(
        (theta) => {
          const [s, c] = [Math.sin(theta), Math.cos(theta)];
          return D(s * Math.cos(phi), s * Math.sin(phi), c, ax, ay) * c * s;
        },
        0,
        Math.PI / 2,
        n,
      ),
    0,
    2 * Math.PI,
    n,
  );
}

describe('anisotropic D: ∫ D(h)(n·h) dω = 1 by 2-D quadrature', () => {
  const PAIRS = [
    [1e-3, 1],
    [1, 1e-3],
    [0.01, 0.3],
    [0.2, 0.6],
    [0.5, 0.05],
    [1e-4, 1e-4],
    [3, 0.5],
  ];
  for (const [kind, D] of Object.entries(NDFS)) {
    it(`${kind}: in slope space with the elliptical substitution, within 1e-12 for αx/αy from 1e-3 to 1e3`, () => {
      for (const [ax, ay] of PAIRS)
        expect(Math.abs(normalisationInSlopeSpace(D, ax, ay) - 1), `${ax}, ${ay}`).toBeLessThan(1e-12);
    });
    it(`${kind}: over (θ, φ) by plain Gauss–Legendre (200²), within 1e-6 at αx = 0.2, αy = 0.6`, () => {
      expect(Math.abs(normalisationInAngles(D, 0.2, 0.6) - 1)).toBeLessThan(1e-6);
      expect(Math.abs(normalisationInAngles(D, 0.6, 0.2) - 1)).toBeLessThan(1e-6);
    });
  }
  it('catches a D stretched along the wrong axis (the quadrature sees the shape, not only αx αy)', () => {
    const swapped = (hx, hy, hz, ax, ay) => M.ndfGGXAniso(hx, hy, hz, ay, ax);
    expect(Math.abs(normalisationInSlopeSpace(swapped, 0.05, 0.5) - 1)).toBeGreaterThan(0.1);
  });
});

/**
 * Heitz 2014's weak white furnace: ∫ G1(v) max(0, v·h) D(h) / (v·n) dω_h = 1 for every v, which holds only when G1
 * is D's own Smith function. In slope space (dω = hz³ d²s), after s = (αx u, αy w) and a rotation (p, q) that puts
 * v·h = 0 at p = P = vz / |(αx vx, αy vy)|, the kink is an edge of the domain: p in (-∞, 0] ∪ [0, P], q in ℝ,
 * each by p or q = ±tan of a Gauss–Legendre angle (q scaled by √(1 + p²)).
 */
function weakFurnace(D, G1, v, ax, ay, n = 64) {
  const [vx, vy, vz] = v;
  const [kx, ky] = [ax * vx, ay * vy];
  const mu = Math.hypot(kx, ky);
  const [ex, ey] = mu > 0 ? [kx / mu, ky / mu] : [1, 0];
  const P = mu > 0 ? vz / mu : Infinity;
  const g1 = G1(vx, vy, vz, ax, ay);
  const integrand = (p, q) => {
    const [u, w] = [p * ex - q * ey, p * ey + q * ex];
    const h = halfFromSlope(ax * u, ay * w);
    const vh = Math.max(vx * h[0] + vy * h[1] + vz * h[2], 0);
    return (g1 * vh * D(...h, ax, ay) * h[2] ** 3 * ax * ay) / vz;
  };
  // q scaled by the lobe's width across at p, sqrt(1 + p²): GGX's power-law tail then integrates like its core
  const overQ = (p) => {
    const r = Math.sqrt(1 + p * p);
    return gauss((g) => (r * integrand(p, r * Math.tan(g))) / Math.cos(g) ** 2, -Math.PI / 2, Math.PI / 2, n);
  };
  const below = gauss((b) => overQ(-Math.tan(b)) / Math.cos(b) ** 2, 0, Math.PI / 2, n);
  const above = gauss((b) => overQ(Math.tan(b)) / Math.cos(b) ** 2, 0, Math.atan(P), n);
  return below + above;
}

const spherical = (theta, phi) => [Math.sin(theta) * Math.cos(phi), Math.sin(theta) * Math.sin(phi), Math.cos(theta)];
const VIEWS = [
  [0, 0],
  [0.5, 0.3],
  [1.2, 0],
  [1.2, Math.PI / 2],
  [1.4, 2.2],
  [1.55, -0.8],
  [Math.PI / 2 - 1e-3, 0.4],
].map(([t, p]) => spherical(t, p));

describe('anisotropic G1 with D: Heitz’s weak white furnace ∫ G1(v) ⟨v·h⟩ D(h) / (v·n) dω_h = 1', () => {
  for (const kind of Object.keys(NDFS)) {
    it(`${kind}: within 1e-12 for views from n to 0.06° above the horizon, αx/αy from 1e-3 to 10`, () => {
      for (const v of VIEWS)
        for (const [ax, ay] of [
          [0.05, 0.5],
          [0.8, 0.08],
          [0.3, 0.3],
          [1e-3, 1],
        ]) {
          const e = weakFurnace(NDFS[kind], G1S[kind], v, ax, ay);
          expect(Math.abs(e - 1), `${kind} v = ${v.map((x) => x.toFixed(3))}, α = ${ax}, ${ay}`).toBeLessThan(1e-12);
        }
    });
  }
  it('fails when Λ is not D’s own (GGX D with Beckmann’s G1: 43 % off at 80°)', () => {
    const e = weakFurnace(M.ndfGGXAniso, M.smithG1BeckmannAniso, spherical(1.4, 2.2), 0.8, 0.08);
    expect(Math.abs(e - 1)).toBeGreaterThan(0.01);
  });
  it('fails when G1 ignores the azimuth (the isotropic G1 at the mean α: 16 % off at 74°)', () => {
    const v = spherical(1.3, 0);
    const iso = (wx, wy, wz) => M.smithG1GGX(wz, (0.05 + 0.5) / 2);
    expect(Math.abs(weakFurnace(M.ndfGGXAniso, iso, v, 0.05, 0.5) - 1)).toBeGreaterThan(0.05);
  });
});

// pseudo-random but reproducible directions and alpha pairs
const rand = seededRandom(28);
const randomDirection = () => spherical(Math.acos(1 - 2 * rand()), 2 * Math.PI * rand());
const CASES = Array.from({ length: 200 }, () => ({
  a: randomDirection(),
  b: randomDirection(),
  ax: 10 ** (-3 * rand()),
  ay: 10 ** (-3 * rand()),
}));
const swap = ([x, y, z]) => [y, x, z];
const relClose = (got, want, tol) => Math.abs(got - want) <= tol * Math.abs(want);

describe('anisotropic functions: swapping (x, αx) with (y, αy) changes nothing', () => {
  it('D, G1 and V agree to the last bits or so (1e-15) with the tangent and bitangent exchanged', () => {
    for (const { a, b, ax, ay } of CASES) {
      for (const f of [M.ndfGGXAniso, M.ndfBeckmannAniso, M.smithG1GGXAniso, M.smithG1BeckmannAniso])
        expect(relClose(f(...swap(a), ay, ax), f(...a, ax, ay), 1e-15), f.name).toBe(true);
      for (const f of [M.visibilitySmithGGXCorrelatedAniso, M.visibleNormalPdfGGXAniso, M.reflectedPdfGGXAniso])
        expect(relClose(f(...swap(a), ...swap(b), ay, ax), f(...a, ...b, ax, ay), 1e-15), f.name).toBe(true);
    }
  });
  it('the sampler’s density with the axes exchanged is the density of the exchanged samples', () => {
    for (const { a, ax, ay } of CASES.slice(0, 50)) {
      if (a[2] <= 0) continue;
      const m = M.sampleVisibleNormalGGXAniso(...a, ax, ay, rand(), rand());
      const pdf = M.visibleNormalPdfGGXAniso(...a, ...m, ax, ay);
      expect(relClose(M.visibleNormalPdfGGXAniso(...swap(a), ...swap(m), ay, ax), pdf, 1e-15)).toBe(true);
    }
  });
});

describe('anisotropic functions at αx = αy are the isotropic ones', () => {
  const alphas = [1e-4, 1e-3, 0.01, 0.1, 0.5, 1];
  it('D: ndfGGXFromSin2 and ndfBeckmannFromSin2 (sin² = hx² + hy²) within 1e-14', () => {
    for (const { a } of CASES)
      for (const alpha of alphas) {
        const s2 = a[0] ** 2 + a[1] ** 2;
        const ggx = M.ndfGGXFromSin2(a[2], s2, alpha);
        const beck = M.ndfBeckmannFromSin2(a[2], s2, alpha);
        expect(relClose(M.ndfGGXAniso(...a, alpha, alpha), ggx, 1e-14)).toBe(true);
        if (beck > 1e-280) expect(relClose(M.ndfBeckmannAniso(...a, alpha, alpha), beck, 1e-12)).toBe(true);
        else expect(M.ndfBeckmannAniso(...a, alpha, alpha)).toBeLessThan(1e-280);
      }
  });
  it('G1: smithG1GGX and smithG1Beckmann (from cos θ alone) within 1e-12; V: visibilitySmithGGXCorrelated', () => {
    for (const { a, b } of CASES)
      for (const alpha of alphas) {
        expect(relClose(M.smithG1GGXAniso(...a, alpha, alpha), M.smithG1GGX(a[2], alpha), 1e-12)).toBe(true);
        const beck = M.smithG1Beckmann(a[2], alpha);
        expect(relClose(M.smithG1BeckmannAniso(...a, alpha, alpha), beck, 1e-12)).toBe(true);
        const v = M.visibilitySmithGGXCorrelated(a[2], b[2], alpha);
        expect(relClose(M.visibilitySmithGGXCorrelatedAniso(...a, ...b, alpha, alpha), v, 1e-12)).toBe(true);
      }
  });
  it('Filament’s V_SmithGGXCorrelated_Anisotropic, 0.5 / (NoL |(at ToV, ab BoV, NoV)| + NoV |…L…|), is V / 4', () => {
    const len = (x, y, z) => Math.hypot(x, y, z);
    for (const { a: l, b: v, ax, ay } of CASES) {
      if (l[2] <= 0 || v[2] <= 0) continue;
      const filament = 0.5 / (l[2] * len(ax * v[0], ay * v[1], v[2]) + v[2] * len(ax * l[0], ay * l[1], l[2]));
      expect(relClose(M.visibilitySmithGGXCorrelatedAniso(...l, ...v, ax, ay) / 4, filament, 1e-14)).toBe(true);
    }
  });
});

describe('anisotropicAlphas: what each specification states', () => {
  const ANISO = [0, 0.1, 0.5, 0.9, 1];
  const ALPHA = [0.01, 0.16, 0.5, 1];
  it('every convention is isotropic at a = 0 and stretches along the tangent (αx >= αy)', () => {
    for (const c of M.ANISOTROPY_CONVENTIONS)
      for (const alpha of ALPHA) {
        expect(M.anisotropicAlphas(alpha, 0, c)).toEqual([alpha, alpha]);
        for (const a of ANISO) {
          const [ax, ay] = M.anisotropicAlphas(alpha, a, c);
          expect(ax).toBeGreaterThanOrEqual(ay);
        }
      }
  });
  it('Burley 2012: αx = α / aspect, αy = α aspect with aspect = √(1 − 0.9 a), so αx αy = α²', () => {
    for (const alpha of ALPHA)
      for (const a of ANISO) {
        const [ax, ay] = M.anisotropicAlphas(alpha, a, 'burley2012');
        expect(ax * ay).toBeCloseTo(alpha * alpha, 15);
        expect(ay / ax).toBeCloseTo(1 - 0.9 * a, 14);
      }
    expect(M.anisotropicAlphas(0.25, 1, 'burley2012')[0]).toBeCloseTo(0.25 / Math.sqrt(0.1), 14);
  });
  it('glTF KHR_materials_anisotropy: the tangent’s α = mix(α, 1, strength²), the bitangent’s the material’s', () => {
    expect(M.anisotropicAlphas(0.25, 1, 'gltf')).toEqual([1, 0.25]);
    expect(M.anisotropicAlphas(0.25, 0.5, 'gltf')[0]).toBeCloseTo(0.25 * 0.75 + 0.25, 15);
    for (const a of ANISO) expect(M.anisotropicAlphas(1, a, 'gltf')).toEqual([1, 1]); // no effect at roughness 1
  });
  it('OpenPBR 1.1: αt² + αb² = 2α² (the spec’s stated invariant) and αb = (1 − a) αt', () => {
    for (const alpha of ALPHA)
      for (const a of ANISO) {
        const [at, ab] = M.anisotropicAlphas(alpha, a, 'openpbr');
        expect(at * at + ab * ab).toBeCloseTo(2 * alpha * alpha, 15);
        expect(ab).toBeCloseTo((1 - a) * at, 15);
      }
  });
  it('clamps the anisotropy to [0, 1] and names the conventions it knows when given another', () => {
    expect(M.anisotropicAlphas(0.3, 2, 'openpbr')).toEqual(M.anisotropicAlphas(0.3, 1, 'openpbr'));
    expect(M.anisotropicAlphas(0.3, -1, 'gltf')).toEqual([0.3, 0.3]);
    expect(() => M.anisotropicAlphas(0.3, 0.5, 'disney')).toThrow(/burley2012, gltf or openpbr/);
  });
});

describe('anisotropic functions at their float edges (float64; the float32 twins in the parity rows)', () => {
  it('D is 0 for h along t or b or below the horizon, finite and positive just above it at αx = 1e-4, αy = 1', () => {
    for (const D of Object.values(NDFS)) {
      expect(D(1, 0, 0, 1e-4, 1)).toBe(0);
      expect(D(0, 1, 0, 1e-4, 1)).toBe(0);
      expect(D(0.6, 0, -0.8, 0.5, 0.5)).toBe(0);
    }
    const grazing = M.ndfGGXAniso(0, 1, 1e-7, 1e-4, 1);
    expect(grazing).toBeGreaterThan(0);
    expect(Number.isFinite(M.ndfGGXAniso(0, 0, 1, 1e-4, 1e-4))).toBe(true);
    // GGX along b with αy = 1: (1 + tan²)^-2 / (π αx αy cos⁴) = 1/(π αx) at any angle
    expect(M.ndfGGXAniso(0, Math.sin(1.2), Math.cos(1.2), 1e-4, 1)).toBeCloseTo(1 / (Math.PI * 1e-4), 6);
  });
  it('G1 and V stay in range at grazing views (n·v = 1e-7) along either axis', () => {
    for (const w of [
      [1, 0, 1e-7],
      [0, 1, 1e-7],
    ])
      for (const [ax, ay] of [
        [1e-4, 1],
        [1, 1e-4],
      ]) {
        for (const G1 of Object.values(G1S)) {
          const g = G1(...w, ax, ay);
          expect(g).toBeGreaterThan(0);
          expect(g).toBeLessThanOrEqual(1);
        }
        const v = M.visibilitySmithGGXCorrelatedAniso(...w, 0, 0, 1, ax, ay);
        expect(Number.isFinite(v) && v > 0).toBe(true);
      }
  });
});
