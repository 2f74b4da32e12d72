// Numbers quoted to students, read out of the sentences that quote them (so a changed sentence fails here) and
// recomputed from src/math and the widgets' own data: Beer–Lambert (transmittance), the microfacet BRDF with the
// brdf-lobe widget's terms, Rayleigh scattering from Hansen & Travis's (1974) optical depth, and a float64
// quadrature of the Fresnel-zone shares on a sphere.
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { transmittance } from '../../src/math/media.js';
import { microfacetBRDF } from '../../src/math/brdf.js';
import { MEDIA } from '../../src/widgets/media/schema.js';
import { schema as LOBE } from '../../src/widgets/brdf-lobe/brdf-lobe.js';
import { weightedSphereShares } from '../support/zone-shares.js';
import { DEG } from '../../src/math/angles.js';
import { ndfABC } from '../../src/math/ndf.js';
import { LIGHTS, SURFACES, blackBody, colours, coloursOf } from '../../src/widgets/radiance/model.js';
import { schema as RADIANCE } from '../../src/widgets/radiance/schema.js';
import { quoted, reads, stepText } from '../support/quoted-text.js';

/** A page's words as a reader sees them: tags dropped (a typeset formula reads as its plain fallback). */
const text = (file) =>
  readFileSync(new URL(`../../${file}`, import.meta.url), 'utf8')
    .replace(/<[^>]+>/g, '')
    .replace(/\s+/g, ' ');

describe('tour, media-red-absorber: the wine-like absorber (media widget σa) by Beer–Lambert', () => {
  it('1 cm leaves 97/55/41% of red/green/blue and 5 cm 86/5/1%', () => {
    const step = stepText('media-red-absorber');
    const [r1, g1, b1] = quoted(step.text, /1 cm leaves (\d+)% of red, (\d+)% of green and (\d+)% of blue/);
    const [r5, g5, b5] = quoted(step.text, /the 5 cm shown leave (\d+)%, (\d+)% and (\d+)%/);
    const { sigmaA } = MEDIA[step.state.medium];
    [r1, g1, b1].forEach((p, c) => reads(100 * transmittance(sigmaA[c], 0.01), p));
    [r5, g5, b5].forEach((p, c) => reads(100 * transmittance(sigmaA[c], 0.05), p));
    expect(10 ** step.state.distance).toBeCloseTo(0.05, 2); // "the 5 cm shown": the slider is log10 metres
  });
});

describe('tour, brdf-intensity: the brdf-lobe widget’s BRDF (GGX, height-correlated Smith, Schlick)', () => {
  const step = stepText('brdf-intensity');
  const params = (alpha) => ({ F: LOBE.F.default, D: LOBE.D.default, V: LOBE.V.default, f0: LOBE.f0.default, alpha });
  const l = [-Math.sin(step.state.lightTheta * DEG), 0, Math.cos(step.state.lightTheta * DEG)];
  const view = (deg) => [Math.sin(deg * DEG), 0, Math.cos(deg * DEG)]; // +: the mirror side
  const f = (deg, alpha) => microfacetBRDF(l, view(deg), params(alpha));
  const argmax = (g) => {
    let best = 0;
    for (let deg = 0; deg <= 89.9; deg += 0.1) if (g(deg) > g(best)) best = deg;
    return best;
  };
  it('is 1.00/sr at θv 89°, 0.22 at the mirror; × n·v it peaks near 70°; at α 0.1 near the mirror', () => {
    const [atHorizon, horizonDeg] = quoted(step.text, /(\d\.\d\d) per steradian at θv = (\d+)°/);
    const [atMirror] = quoted(step.text, /against (\d\.\d\d) in the mirror direction/);
    const [nearDeg] = quoted(step.text, /drawn here: it peaks near (\d+)°/);
    const alpha = step.state.alpha;
    reads(f(horizonDeg, alpha), atHorizon, 2);
    reads(f(step.state.lightTheta, alpha), atMirror, 2);
    expect(argmax((deg) => f(deg, alpha))).toBeGreaterThan(88); // "largest at the horizon"
    expect(Math.abs(argmax((deg) => f(deg, alpha) * Math.cos(deg * DEG)) - nearDeg)).toBeLessThan(1); // 70.5°
    expect(step.text).toMatch(/at α = 0\.1 it would peak near the mirror direction/);
    expect(Math.abs(argmax((deg) => f(deg, 0.1)) - step.state.lightTheta)).toBeLessThan(3); // 62.5°
  });
});

describe('media.html: Rayleigh scattering of clean air', () => {
  it('τ 0.097 (Hansen & Travis 1974) over 8 km: 1.2e-5 /m; 10 km scatter 11% of green, 24% of blue (1/λ⁴)', () => {
    const page = text('media.html');
    const [perMetre] = quoted(page, /about ([\d.]+) × 10⁻⁵ of green \(550 nm\) light per metre/);
    const [tau] = quoted(page, /optical depth of ([\d.]+), from Hansen &amp; Travis 1974/);
    const [heightKm] = quoted(page, /scale height of about (\d+) km/);
    const [green] = quoted(page, /about (\d+)% of green light and, since Rayleigh scattering grows as 1\/λ⁴/);
    const [blue, blueNm] = quoted(page, /grows as 1\/λ⁴, about (\d+)% of blue \((\d+) nm\)/);
    const sigmaGreen = tau / (heightKm * 1000);
    reads(sigmaGreen * 1e5, perMetre, 1);
    reads(100 * (1 - transmittance(sigmaGreen, 10e3)), green);
    reads(100 * (1 - transmittance(sigmaGreen * (550 / blueNm) ** 4, 10e3)), blue);
    expect(page).toMatch(/Over ten metres that is about one part in ten thousand/);
    expect(1 - transmittance(sigmaGreen, 10)).toBeCloseTo(1.2e-4, 5);
  });
});

describe('fresnel.html: red share of the BRDF-weighted l·h zones on a sphere (float64 quadrature)', () => {
  it('1.4% at α 0.3 over the widget’s 64 lights, 1.5% with light from every direction, 4% at α 0.1', () => {
    const page = text('fresnel.html');
    const [red64] = quoted(page, /about ([\d.]+)% at the default GGX α = 0\.3/);
    const [redAll] = quoted(page, /GGX α = 0\.3 \(([\d.]+)% with light from every direction/);
    const [redSmooth] = quoted(page, /but (\d+)% at α = 0\.1/);
    reads(100 * weightedSphereShares(0.3)[2], red64, 1);
    reads(100 * weightedSphereShares(0.1)[2], redSmooth);
    // every direction: 4096 lights (1024 give 1.55%, 4096 1.53%, 16384 1.54%: the zone edges converge as 1/lights)
    reads(100 * weightedSphereShares(0.3, 4096, 100, 48)[2], redAll, 1);
    // a sum over lights, as the reference here: a numerical integral over all directions, not an exact one
    expect(page).toMatch(/every direction at once, a numerical integral over all directions\)/);
    expect(page).not.toMatch(/integrated exactly/);
  }, 120_000);
});

describe('ndf.html: the ABC formula shown is the one ndfABC evaluates (a Simpson integral over the hemisphere)', () => {
  it('D_abc = D_uabc / ∫ D_uabc (n·m) dω, D_uabc = 1/(1 + a1(1 − n·m))^a2', () => {
    const page = readFileSync(new URL('../../ndf.html', import.meta.url), 'utf8');
    const tex = [...page.matchAll(/data-tex="([^"]*)"/g)].map((m) => m[1]).find((t) => t.includes('uabc'));
    const normalised = '\\frac{D_{uabc}(\\mathbf{m})}{\\int_{\\Omega} D_{uabc}(\\mathbf{m}) \\nm \\, d\\omega_m}';
    expect(tex).toContain(`D_{abc}(\\mathbf{m}) = ${normalised}`);
    expect(tex).toContain('D_{uabc}(\\mathbf{m}) = \\frac{1}{(1 + \\alpha_{abc1}(1 - \\nm))^{\\alpha_{abc2}}}');
    for (const [a1, a2] of [
      [5, 1.5],
      [60, 0.8],
    ]) {
      const unnormalised = (c) => (1 + a1 * (1 - c)) ** -a2;
      // ∫ D_uabc (n·m) dω = 2π ∫_0^1 D_uabc(c) c dc, Simpson in c
      const n = 20000;
      let sum = 0;
      for (let i = 0; i <= n; i++) sum += (i === 0 || i === n ? 1 : i % 2 ? 4 : 2) * unnormalised(i / n) * (i / n);
      const integral = (2 * Math.PI * sum) / (3 * n);
      for (const c of [1, 0.9, 0.5]) expect(ndfABC(c, a1, a2) / (unnormalised(c) / integral)).toBeCloseTo(1, 6);
    }
  });
});

describe('brdf.html: RGB ⊗ against the per-wavelength product (radiance model, Planck black bodies)', () => {
  it('exact under the 6504 K white; green +5%/+14% at 5000/4000 K; ×1.08, ×1.53, blue’s sign at 2856 K', () => {
    const page = text('brdf.html');
    const [white] = quoted(page, /defined against \(here a (\d+) K black body/);
    const [g5, t5, g4, t4] = quoted(
      page,
      /green channel comes out (\d+)% too bright under a (\d+) K black body and (\d+)% under (\d+) K/,
    );
    const [kelvin, red, green] = quoted(
      page,
      /a (\d+) K tungsten bulb, red is ([\d.]+) times and green ([\d.]+) times/,
    );
    const [sodium] = quoted(page, /under a sodium lamp the red channel comes out ([\d.]+) times brighter/);
    expect(page).toMatch(
      /blue, slightly negative in the true colour \(just outside the sRGB gamut\), comes out positive/,
    );
    const paint = SURFACES[RADIANCE.surface.default].reflectance;
    const ratios = (c) => c.product.map((x, i) => x / c.spectral[i]);
    ratios(coloursOf(blackBody(white), paint)).forEach((r) => expect(r).toBeCloseTo(1, 9));
    reads(100 * (ratios(coloursOf(blackBody(t5), paint))[1] - 1), g5);
    reads(100 * (ratios(coloursOf(blackBody(t4), paint))[1] - 1), g4);
    // the widget's default light is the 2856 K black body, on its default (red) paint
    expect(LIGHTS[RADIANCE.light.default].name).toContain(`${kelvin} K`);
    const c = colours(RADIANCE.light.default, RADIANCE.surface.default);
    c.product.forEach((x, i) => expect(x).toBeCloseTo(coloursOf(blackBody(kelvin), paint).product[i], 12));
    reads(ratios(c)[0], red, 2);
    reads(ratios(c)[1], green, 2);
    expect(c.spectral[2]).toBeLessThan(0);
    expect(c.product[2]).toBeGreaterThan(0);
    reads(ratios(colours('sodium', RADIANCE.surface.default))[0], sodium, 1);
  });
});
