// Numbers and claims in the tour's steps, read out of the sentences that state them (a changed sentence fails here)
// and recomputed from src/math with the step's own state: Beer–Lambert for the glass of water, the exact Fresnel
// split and the microfacet reflected-angle density for the flat surface, the brdf-lobe widget's BRDF (GGX,
// height-correlated Smith, Schlick), the white furnace with Kulla–Conty's compensation and the random walk on the
// Smith microsurface, and Oren–Nayar (1994) against Lambert on a sphere lit from the viewer.
import { describe, expect, it } from 'vitest';
import { quoted, reads, stepText as step } from '../support/quoted-text.js';
import { transmittance } from '../../src/math/media.js';
import { MEDIA } from '../../src/widgets/media/schema.js';
import { fresnelDielectric } from '../../src/math/fresnel.js';
import { fresnelParams, METALS } from '../../src/math/materials.js';
import { reflectedAngleDensity } from '../../src/math/microsurface.js';
import { smithG1Beckmann } from '../../src/math/visibility.js';
import { schema as SURFACES } from '../../src/widgets/surfaces/schema.js';
import { microfacetBRDF } from '../../src/math/brdf.js';
import { schema as LOBE } from '../../src/widgets/brdf-lobe/schema.js';
import { schema as ENERGY } from '../../src/widgets/energy/schema.js';
import { buildAlbedoTableGGX, specularAlbedoFromTable } from '../../src/math/albedo-table.js';
import { randomWalkAlbedoGGX } from '../../src/math/random-walk.js';
import { WALK_PATHS } from '../../src/widgets/energy/compensation.js';
import { diffuseOrenNayar, diffuseOrenNayarQualitative } from '../../src/math/diffuse.js';
import { DEG } from '../../src/math/angles.js';

describe('tour, media-straight-line: a metre of clean water (Beer–Lambert, the media widget’s σa)', () => {
  it('the glass shown lets 73/96/97% of red/green/blue through; 5 cm would let 98% of red through', () => {
    const s = step('media-straight-line');
    const [r, g, b] = quoted(s.text, /lets (\d+)% of red light through, (\d+)% of\s+green and (\d+)% of blue/);
    const [red5] = quoted(s.text, /Five centimetres would leave the glass invisible: (\d+)% of red/);
    const { sigmaA, sigmaS } = MEDIA[s.state.medium];
    expect(sigmaS).toEqual([0, 0, 0]); // a pure absorber: the wall seen through it stays sharp
    expect(10 ** s.state.distance).toBe(1); // "a metre"
    [r, g, b].forEach((p, c) => reads(100 * transmittance(sigmaA[c], 1), p));
    reads(100 * transmittance(sigmaA[0], 0.05), red5);
    // visible: the red channel loses more than a quarter, against 2% for 5 cm
    expect(transmittance(sigmaA[0], 1)).toBeLessThan(0.75);
  });
});

describe('tour, surfaces-flat: exact Fresnel and the microfacet reflected-angle density (Beckmann)', () => {
  const s = step('surfaces-flat');
  it('splits 8.7% / 91.3% at 40° (green channel, as drawn), at the smallest roughness the widget has', () => {
    const [reflected, refracted] = quoted(s.text, /here ([\d.]+)% and ([\d.]+)%/);
    const F = fresnelDielectric(Math.cos(s.state.theta * DEG), fresnelParams(s.state.material).eta[1]);
    reads(100 * F, reflected, 1);
    reads(100 * (1 - F), refracted, 1);
    const [alpha] = quoted(s.text, /α = ([\d.]+), nearly flat/);
    expect(s.state.alpha).toBe(alpha);
    expect(alpha).toBe(SURFACES.alpha.min);
  });
  it('reflects into one narrow spike at −40°: over 95% of the predicted density within 5° of it', () => {
    const [mirror] = quoted(s.text, /spike at the mirror direction, −(\d+)°/);
    expect(mirror).toBe(s.state.theta);
    const density = (deg) =>
      reflectedAngleDensity(deg * DEG, s.state.theta * DEG, 'beckmann', s.state.alpha, smithG1Beckmann);
    const share = (lo, hi) => {
      let sum = 0;
      for (let deg = lo + 0.005; deg < hi; deg += 0.01) sum += density(deg) * 0.01 * DEG;
      return sum;
    };
    expect(share(-mirror - 5, -mirror + 5) / share(-90, 90)).toBeGreaterThan(0.95);
  });
});

describe('tour, brdf-lobe: the widget’s BRDF (GGX, height-correlated Smith, Schlick) at the step’s state', () => {
  it('peaks near the mirror direction, 0.11/sr at 31°, and falls to 0.03 towards the horizon', () => {
    const s = step('brdf-lobe');
    const [lightDeg, alpha] = quoted(s.text, /light \(here at\s+(\d+)°, on a fairly smooth surface, α = ([\d.]+)\)/);
    const [peak, peakDeg, horizon] = quoted(
      s.text,
      /around the mirror\s+direction: ([\d.]+) per steradian at its peak, at (\d+)°, and ([\d.]+) towards/,
    );
    expect([s.state.lightTheta, s.state.alpha]).toEqual([lightDeg, alpha]);
    const params = { F: LOBE.F.default, D: LOBE.D.default, V: LOBE.V.default, f0: LOBE.f0.default, alpha };
    const l = [-Math.sin(lightDeg * DEG), 0, Math.cos(lightDeg * DEG)];
    const f = (deg) => microfacetBRDF(l, [Math.sin(deg * DEG), 0, Math.cos(deg * DEG)], params);
    let best = -89;
    for (let deg = -89; deg <= 89; deg += 0.1) if (f(deg) > f(best)) best = deg;
    expect(Math.abs(best - peakDeg)).toBeLessThan(0.5);
    expect(Math.abs(best - lightDeg)).toBeLessThan(3); // "around the mirror direction"
    reads(f(best), peak, 2);
    reads(f(89), horizon, 2);
  });
});

describe('tour, microfacets-furnace-fixed: Kulla–Conty in the white furnace, gold against the random walk', () => {
  const s = step('microfacets-furnace-fixed');
  const table = buildAlbedoTableGGX();
  it('every sphere of the sweep reflects all the light (the probe’s compensated albedo reads 1.0000)', () => {
    expect(s.text).toMatch(/compensated albedo reads 1\.0000/);
    for (const a of ENERGY.alphas.default)
      for (const mu of [1, 0.7, 0.4, 0.1])
        expect(specularAlbedoFromTable(table, mu, Number(a), 1, s.state.compensation).toFixed(4)).toBe('1.0000');
  });
  it('rough gold head-on: 43/30/12% in one bounce, 100/56/16% by the walk; Kulla–Conty within 0.02', () => {
    const [alpha] = quoted(s.text, /rough gold \(α = ([\d.]+)\)/);
    const single = quoted(s.text, /reflects (\d+)% of red, (\d+)% of green and (\d+)% of\s+blue light in one bounce/);
    const walked = quoted(s.text, /every bounce \(the random walk\) it reflects (\d+)%, (\d+)% and (\d+)%/);
    const [within] = quoted(s.text, /Kulla–Conty\s+comes within ([\d.]+) of the walk/);
    const [over] = quoted(s.text, /Turquin overshoots green by (\d\.\d\d)/);
    expect(s.state.metalAlpha).toBe(alpha);
    const f0 = METALS.find((m) => m.key === s.state.metal).linear;
    const at = (c, compensation) => specularAlbedoFromTable(table, 1, alpha, f0[c], compensation);
    const walk = randomWalkAlbedoGGX(1, alpha, f0, WALK_PATHS, 1).albedo; // the widget's seed for 0°
    single.forEach((p, c) => reads(100 * at(c, 'none'), p));
    walked.forEach((p, c) => reads(100 * walk[c], p));
    for (let c = 0; c < 3; c++) expect(Math.abs(at(c, 'kullaConty') - walk[c])).toBeLessThanOrEqual(within);
    reads(at(1, 'turquin') - walk[1], over, 2);
  });
});

describe('tour, diffuse-full-moon: Oren–Nayar (1994) against Lambert, a sphere lit from the viewer', () => {
  it('at 95% of the radius: 0.71 of the centre (qualitative form 0.80), Lambert 0.31, at the step’s σ', () => {
    const s = step('diffuse-full-moon');
    const [r, sigma, full] = quoted(
      s.text,
      /near the rim, (\d+)% of the radius out, Oren–Nayar at σ = (\d+)° is still ([\d.]+) as bright as/,
    );
    const [qualitative, lambert] = quoted(
      s.text,
      /the centre \(its qualitative form ([\d.]+)\), where Lambert, following n·l, has fallen to (\d\.\d\d)/,
    );
    expect([s.state.sigma, s.state.lightTheta]).toEqual([sigma, 0]);
    // orthographic view, light at the viewer: n·l = n·v = sqrt(1 − r²) and l, v share their azimuth (cos φ = 1)
    const c = Math.sqrt(1 - (r / 100) ** 2);
    const ratio = (brdf) => (brdf(c, c, 1, sigma * DEG, 0.8) * c) / brdf(1, 1, 1, sigma * DEG, 0.8);
    reads(ratio(diffuseOrenNayar), full, 2);
    reads(ratio(diffuseOrenNayarQualitative), qualitative, 2);
    reads(c, lambert, 2);
  });
});
