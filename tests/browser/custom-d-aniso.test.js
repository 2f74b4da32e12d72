// The user's anisotropic D (slot DAniso) on a real GPU, on the page of the custom-terms core
// (tests/browser/custom-terms.html, built here): the starter (anisotropic GGX) matches ndfGGXAniso of
// src/math/anisotropic.js over the stress grid; its normalisation over the 2-D hemisphere is 1 and Heitz's (2014)
// weak furnace with GGX's Λ is 1 at every view; the same D without its π integrates to π, and anisotropic Beckmann
// (a normalised D) fails the weak furnace with GGX's Λ but passes with Beckmann's.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { openCustomTermsPage } from './custom-terms-open.js';

let browser;
let server;
let page;
beforeAll(async () => {
  ({ browser, server, page } = await openCustomTermsPage());
});
afterAll(async () => {
  await browser?.close();
  server?.close();
});

const check = (code, reference) =>
  page.evaluate((c, r) => window.__customTerms.check('DAniso', c, {}, { reference: r }), code, reference);
const starter = () => page.evaluate(() => window.__customTerms.SLOTS.DAniso.starter);
const BECKMANN = `float customDAniso(vec3 h, vec2 alpha) {
  if (!(h.z > 0.0)) return 0.0;
  vec2 a = clamp(alpha, 1e-4, 4.0);
  vec2 s = h.xy / a;
  float q = dot(s, s);
  float c2 = h.z * h.z;
  if (q > 80.0 * c2) return 0.0;
  return exp(-q / c2) / (PI * a.x * a.y * c2 * c2);
}
`;

describe('the user’s anisotropic D on the GPU', () => {
  it('the starter: ndfGGXAniso on the stress grid, normalised (± 1e-3), weak furnace ± 3e-3 (GGX’s Λ)', async () => {
    const report = await check(await starter());
    const norm = report.normalisation.byAlpha.map((r) => `(${r.alpha}) ${r.integral.toFixed(5)}`);
    console.log(
      `custom anisotropic D: normalisation ${norm.join(', ')}; weak furnace worst ${report.weakFurnace.worst}`,
    );
    expect(report.nonFinite).toEqual({ count: 0, negative: 0, first: null });
    expect(report.reference.failures, JSON.stringify(report.reference.worst)).toBe(0);
    expect(Math.abs(report.normalisation.worst - 1)).toBeLessThan(1e-3);
    expect(Math.abs(report.weakFurnace.worst - 1)).toBeLessThan(3e-3);
    expect(page.errors).toEqual([]);
  });

  it('without its π it integrates to π and fails the weak furnace', async () => {
    const noPi = await check((await starter()).replace('1.0 / (PI * a.x', '1.0 / (a.x'));
    expect(Math.abs(noPi.normalisation.worst / Math.PI - 1)).toBeLessThan(1e-3);
    expect(Math.abs(noPi.weakFurnace.worst - 1)).toBeGreaterThan(1);
    expect(noPi.reference.pass).toBe(false);
  });

  it('anisotropic Beckmann: normalised; weak furnace off with GGX’s Λ (> 10 %), 1 with Beckmann’s', async () => {
    const withGgx = await check(BECKMANN, 'ggxAniso');
    const withBeckmann = await check(BECKMANN, 'beckmannAniso');
    console.log(
      `Beckmann D: weak furnace with GGX's Λ ${withGgx.weakFurnace.worst}, ` +
        `Beckmann's ${withBeckmann.weakFurnace.worst}`,
    );
    expect(Math.abs(withGgx.normalisation.worst - 1)).toBeLessThan(1e-3);
    expect(Math.abs(withGgx.weakFurnace.worst - 1)).toBeGreaterThan(0.1);
    expect(Math.abs(withBeckmann.weakFurnace.worst - 1)).toBeLessThan(3e-3);
    expect(withBeckmann.weakFurnace.lambda).toBe('Beckmann’s Λ');
    expect(withBeckmann.reference.failures, JSON.stringify(withBeckmann.reference.worst)).toBe(0);
  });
});
