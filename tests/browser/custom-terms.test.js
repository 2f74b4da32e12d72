// The core of user-written terms on a real GPU (src/core/custom: compile, gpu-eval, checks), on a page of its own
// (tests/browser/custom-terms.html, built here): every starter against its float64 catalogue term; the checks'
// numbers against closed forms (a normalised GGX integrates to 1, without its 1/π to π; Lambert's albedo is its
// c; V = 2/((n·l)(n·v)) puts G = 2 outside [0, 1]); an Inf found at its input; a compile error on the user's line.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { openCustomTermsPage } from './custom-terms-open.js';
import { WAIT_MS } from './helpers.js';
import { CHECK_ALPHAS } from '../../src/core/custom/check-inputs.js';
import { GRIDS } from '../../src/core/gpu/parity-cases.js';
import { withCustomChunk } from '../../src/core/custom/assemble.js';
import { assembleGlsl } from '../../src/core/gpu/glsl.js';
import { SHADER_CHUNKS } from '../../src/core/gpu/shader-chunks.js';
import { SLOTS } from '../../src/core/custom/slots.js';
import { termDefines } from '../../src/math/catalogue/index.js';

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

const check = (slot, code, params = {}, options = {}) =>
  page.evaluate((...a) => window.__customTerms.check(...a), slot, code, params, options);
const starter = (slot) => page.evaluate((s) => window.__customTerms.SLOTS[s].starter, slot);
const D = (body) => `float customD(float nh, float alpha) {\n${body}\n}\n`;

describe('custom terms on the GPU', () => {
  it.each(['D', 'V', 'F', 'diffuse', 'brdf'])(
    'the %s starter matches its float64 catalogue term over the stress grid, with no NaN, Inf or negative value',
    async (slot) => {
      const code = await starter(slot);
      const [report, ms] = await page.evaluate(
        (s, c) => {
          const t0 = performance.now();
          const r = window.__customTerms.check(s, c);
          return [r, performance.now() - t0];
        },
        slot,
        code,
      );
      console.log(
        `custom ${slot} starter vs ${report.reference.key}: maxAbs ${report.reference.maxAbs.toExponential(2)} ` +
          `maxRel ${report.reference.maxRel.toExponential(2)}; runChecks ${ms.toFixed(0)} ms`,
      );
      expect(report.nonFinite).toEqual({ count: 0, negative: 0, first: null });
      expect(report.reference.failures, JSON.stringify(report.reference.worst)).toBe(0);
      expect(page.errors).toEqual([]);
    },
  );
  it('a custom GGX D (the starter) integrates to 1 ± 1e-4; the same without its 1/π to π', async () => {
    const good = await check('D', await starter('D'));
    console.log(`custom D normalisation: ${good.normalisation.byAlpha.map((r) => r.integral.toFixed(6)).join(' ')}`);
    expect(Math.abs(good.normalisation.worst - 1)).toBeLessThan(1e-4);
    const noPi = await check('D', (await starter('D')).replace('return t * t / PI;', 'return t * t;'));
    expect(Math.abs(noPi.normalisation.worst / Math.PI - 1)).toBeLessThan(1e-4);
    expect(noPi.reference.maxRel).toBeCloseTo(Math.PI - 1, 4);
  });
  it('a D that is Inf at n·h = 1 reports Inf there first, once per α at n·h = 1 and just above', async () => {
    const report = await check('D', D('  return 1.0 / (1.0 - min(nh, 1.0));'));
    expect(report.nonFinite.first).toEqual({
      inputs: { nh: 1, alpha: Math.fround(1e-4) },
      value: null,
      text: 'Infinity',
    });
    expect(report.nonFinite.count).toBe(2 * CHECK_ALPHAS.length); // n·h = 1 and 1 + 1e-6
    expect(report.reference.worst).toMatchObject({ inputs: { nh: 1 }, text: 'Infinity' });
  });
  it('V = 2/((n·l)(n·v)) puts G = 2 outside [0, 1] at every input above the horizon', async () => {
    const code =
      'float customV(float nl, float nv, float alpha) {\n  return nl > 0.0 && nv > 0.0 ? 2.0 / (nl * nv) : 0.0;\n}';
    const report = await check('V', code);
    const above = GRIDS.cosCoarse.filter((c) => c > 0).length;
    expect(report.gRange.outside).toBe(above * above * CHECK_ALPHAS.length);
    expect(report.gRange.max).toBeCloseTo(2, 5);
    const good = await check('V', await starter('V'));
    expect(good.gRange.outside).toBe(0);
    expect(good.gRange.max).toBeLessThanOrEqual(1 + 1e-5);
  });
  it('a whole Lambert BRDF reads its albedo in the white furnace (0.7 by its slider) and reciprocity 0', async () => {
    const report = await check('brdf', await starter('brdf'), { albedo: 0.7 });
    expect(Math.abs(report.furnace.max - 0.7)).toBeLessThan(1e-5);
    expect(report.reciprocity).toEqual({ maxRel: 0, first: null });
    const byDefault = await check('brdf', await starter('brdf'));
    expect(Math.abs(byDefault.furnace.max - 1)).toBeLessThan(1e-5); // the slider's default, 1
  });
  it('a compile error lands on the user’s line, with nothing on the console', async () => {
    const result = await check('D', D('  float x = nh;\n  return y * x;'));
    expect(result.errors[0].line).toBe(3);
    expect(result.errors[0].message).toMatch(/'y'/);
    expect(page.errors).toEqual([]);
  });
  it('code that fails the static checks never reaches the GPU: a while loop is refused on its line', async () => {
    const result = await check('D', D('  float s = 0.0;\n  while (s < 1.0) { s += nh; }\n  return s;'));
    expect(result.errors).toEqual([{ line: 3, message: expect.stringMatching(/'while'/) }]);
  });
});

describe('a user-written term is compiled once, by three.js', () => {
  it('new code compiles one fragment program, the one three.js draws with (no raw compile beside it)', async () => {
    const code = D(
      '  float a2 = alpha * alpha * 1.000001;\n  float d = nh * nh * (a2 - 1.0) + 1.0;\n  return a2 / (PI * d * d);',
    );
    const counted = await page.evaluate((c) => {
      const t = window.__customTerms;
      const before = t.fragmentCompiles();
      const out = t.evaluate('D', c, {}, [[0.9, 0.3]]);
      return { compiles: t.fragmentCompiles() - before, out };
    }, code);
    expect(counted.compiles).toBe(1);
    // the value itself: GGX at n·h 0.9, α 0.3 (Walter et al. 2007), a2 scaled by 1.000001
    const a2 = 0.09 * 1.000001;
    const d = 0.81 * (a2 - 1) + 1;
    expect(counted.out[0]).toBeCloseTo(a2 / (Math.PI * d * d), 4);
    const broken = await page.evaluate(
      (c) => {
        const t = window.__customTerms;
        const before = t.fragmentCompiles();
        const out = t.evaluate('D', c, {}, [[0.9, 0.3]]);
        return { compiles: t.fragmentCompiles() - before, out };
      },
      code.replace('return a2', 'return b2'),
    );
    expect(broken.compiles).toBe(1);
    expect(broken.out.errors[0]).toMatchObject({ line: 4, message: expect.stringMatching(/b2/) });
    expect(page.errors).toEqual([]);
  });
});

describe('custom in a family’s dispatch (the sphere program of the widgets)', () => {
  const sphere = (code) =>
    assembleGlsl(SHADER_CHUNKS['brdf-sphere.frag.glsl'], {
      defines: { ...termDefines({ F: 'custom', D: 'custom', V: 'smithGGXCorrelated' }), SPHERE_IMPOSTOR: 1 },
      chunks: withCustomChunk(withCustomChunk(SHADER_CHUNKS, 'F', SLOTS.F.starter), 'D', code),
    });
  it('compiles with a custom D and a custom F; an error in the D lands on its own line', async () => {
    const compile = (source) => page.evaluate((s) => window.__customTerms.compileCustom(s), source);
    expect(await compile(sphere(SLOTS.D.starter))).toEqual({ ok: true, errors: [] });
    const broken = await compile(sphere(D('  float k = 1.0;\n  return k * nh * undefinedThing;')));
    expect(broken.ok).toBe(false);
    expect(broken.errors[0]).toMatchObject({ line: 3, message: expect.stringMatching(/undefinedThing/) });
    expect(page.errors).toEqual([]);
  });
});

describe('a lost WebGL context (watchContext)', () => {
  it('says so, names the new code that was drawing, and brings back the program that drew before', async () => {
    const good = { slot: 'D', code: await starter('D'), params: {} };
    const first = await page.evaluate((p) => window.__customTerms.run(p), good);
    expect(Math.abs(first.normalisation.worst - 1)).toBeLessThan(1e-4);
    const suspect = { slot: 'D', code: D('  return 1.0;'), params: {} };
    await page.evaluate((p) => window.__customTerms.run(p, { draw: false }), suspect);
    await page.evaluate(() => window.__customTerms.lose());
    await page.waitForFunction(() => window.__customTerms.events.some((e) => e.type === 'lost'), {
      timeout: WAIT_MS,
    });
    const lost = await page.evaluate(() => window.__customTerms.events.find((e) => e.type === 'lost'));
    expect(lost.message).toMatch(/while your new code was drawing/);
    expect(lost.suspect).toEqual(suspect);
    expect(await check('D', good.code)).toEqual({ errors: [{ line: 0, message: 'the WebGL context is lost' }] });
    await page.evaluate(() => window.__customTerms.restore());
    await page.waitForFunction(() => window.__customTerms.events.some((e) => e.type === 'restored'), {
      timeout: WAIT_MS,
    });
    const restored = await page.evaluate(() => window.__customTerms.events.find((e) => e.type === 'restored'));
    expect(restored.program).toEqual(good);
    expect(restored.report.normalisation).toEqual(first.normalisation); // the same program, the same GPU numbers
    expect(page.errors).toEqual([]);
  });
});
