// The OpenPBR chapter (today.html), its tour step and its "which layer" exercise: every figure they quote read out
// of the sentence that states it and recomputed here from src/math (openPbrLayers, the albedo tables, the exact
// conductor and dielectric Fresnel, the fuzz albedo, the split sum's GGX albedo, the layered random walk and
// openPbrBRDF's directional albedo by quadrature, tests/support/openpbr-albedo.js).
import { describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { quoted, reads, stepText } from '../support/quoted-text.js';
import { openPbrLayers, openPbrMaterial, openPbrCoatDarkening, openPbrSpecularEta } from '../../src/math/openpbr.js';
import { openPbrDielectricAlbedo } from '../../src/math/openpbr-albedo.js';
import { albedoFuzzZeltner } from '../../src/math/openpbr-fuzz.js';
import { layeredWalkAlbedo } from '../../src/math/openpbr-walk.js';
import { albedoGGX } from '../../src/math/integrate.js';
import { f82TintFromConductor, fresnelConductor, fresnelF82Tint, fresnelSchlick } from '../../src/math/fresnel.js';
import { measuredRgbNk } from '../../src/math/optical-constants.js';
import { srgbToLinear } from '../../src/math/color.js';
import { GRADERS } from '../../src/exercises/graders.js';
import { openPbrAlbedo } from '../support/openpbr-albedo.js';
import { layerShares } from '../../src/exercises/graders/openpbr-layer.js';

const DEG = Math.PI / 180;
const ROOT = join(import.meta.dirname, '../..');
// the page as a reader sees it: tags dropped, entities and white space as one space
const PAGE = readFileSync(join(ROOT, 'today.html'), 'utf8')
  .replace(/<[^>]+>/g, '')
  .replace(/\s+/g, ' ');
const N = '(\\d+(?:\\.\\d+)?)'; // a number, not the full stop after it
const at = (re) => quoted(PAGE, new RegExp(re));
const Y = ([r, g, b]) => 0.2126 * r + 0.7152 * g + 0.0722 * b;
const linear = (hex) => [1, 3, 5].map((i) => srgbToLinear(parseInt(hex.slice(i, i + 2), 16) / 255));
const dir = (deg) => [Math.sin(deg * DEG), 0, Math.cos(deg * DEG)];
const light = (deg) => [-Math.sin(deg * DEG), 0, Math.cos(deg * DEG)];
/** Each layer's luminance and the whole's, light at θl (left of n), view at θv (+: the mirror side). */
function lum(material, thetaL, thetaV) {
  const p = openPbrLayers(light(thetaL), dir(thetaV), material);
  const y = Object.fromEntries(Object.entries(p).map(([k, x]) => [k, Y(x)]));
  return { ...y, all: Object.values(y).reduce((a, b) => a + b, 0) };
}
const PAINT = { base_color: linear('#b22222'), specular_roughness: 0.5, coat_weight: 1, coat_roughness: 0.3 };

describe('today.html: the car paint of the lobe, layer by layer (openPbrLayers)', () => {
  it('the coat makes 98.7% of the lobe in the mirror direction (1.26 of 1.28 /sr); from 0°, 88% is diffuse', () => {
    const [share, coat, all, diffuseShare, diffuse, all0] = at(
      `the coat makes ${N}% of the lobe \\(${N} of ${N} per steradian\\).*?${N}% of the light is the base’s diffuse ` +
        `lobe \\(${N} of ${N}\\)`,
    );
    const mirror = lum(PAINT, 45, 45);
    reads((100 * mirror.coat) / mirror.all, share, 1);
    reads(mirror.coat, coat, 2);
    reads(mirror.all, all, 2);
    const head = lum(PAINT, 45, 0);
    reads((100 * head.diffuse) / head.all, diffuseShare);
    reads(head.diffuse, diffuse, 4);
    reads(head.all, all0, 4);
  });

  it('under the coat its gloss is 0.0013 /sr against 0.124 without; F0 1.5 → 1.067 falls from 0.04 to 0.001', () => {
    const [gloss, bare] = at(`nearly gone in the lobe above: ${N} per steradian in the mirror direction, against ${N}`);
    reads(lum(PAINT, 45, 45).specular, gloss, 4);
    reads(lum({ ...PAINT, coat_weight: 0 }, 45, 45).specular, bare, 3);
    const [relative, f0, under] = at(`relative index of ${N}, and its F\\(0°\\) falls from ${N} to ${N}`);
    const m = openPbrMaterial(PAINT);
    reads(1.6 / 1.5, relative, 3); // below 1 (1.5 / 1.6), the specification inverts it
    reads(((1.5 - 1) / 2.5) ** 2, f0, 2);
    const eta = openPbrSpecularEta(m);
    reads(((eta - 1) / (eta + 1)) ** 2, under, 3);
    const [dark] = at(`red channel the factor is ${N} seen head-on`);
    reads(openPbrCoatDarkening(m, 1)[0], dark, 2);
  });
});

describe('today.html: the layers’ albedos and the metals’ Fresnel', () => {
  it('the gloss’s E at roughness 0.3, the coat’s 1 − E at 0.1, the fuzz’s R at 0.5 (the albedo tables)', () => {
    const [e1, e5, e2] = at(`E\\s?spec is ${N} seen head-on, ${N} at n·v = 0.5 and ${N} at n·v = 0.2`);
    [1, 0.5, 0.2].forEach((mu, i) => reads(openPbrDielectricAlbedo(mu, 0.09, 1.5), [e1, e5, e2][i], 3));
    const [c1, c2] = at(`At coat roughness 0.1 that is ${N} seen head-on and ${N} at n·v = 0.2`);
    reads(1 - openPbrDielectricAlbedo(1, 0.01, 1.6), c1, 3);
    reads(1 - openPbrDielectricAlbedo(0.2, 0.01, 1.6), c2, 3);
    const [r1, r2] = at(`At fuzz roughness 0.5, R is ${N} seen head-on and ${N} at n·v = 0.2`);
    reads(albedoFuzzZeltner(1, 0.5), r1, 3);
    reads(albedoFuzzZeltner(0.2, 0.5), r2, 3);
    const [coatF0] = at(`coat_ior 1.6 \\(F\\(0°\\) = ${N}\\)`);
    reads(((1.6 - 1) / 2.6) ** 2, coatF0, 3);
  });

  it('aluminium red and gold blue at 80°: Schlick, exact and F82-tint, fitted to measured (n, k)', () => {
    const three = (metal, c) => {
      const [n, k] = measuredRgbNk(metal)[c];
      const { f0, tint } = f82TintFromConductor(n, k);
      const mu = Math.cos(80 * DEG);
      return [fresnelSchlick(f0, mu), fresnelConductor(mu, n, k), fresnelF82Tint(f0, tint, mu)];
    };
    const al = at(`Schlick gives ${N} in red where the exact value is ${N} and F82-tint ${N}`);
    three('aluminum', 0).forEach((x, i) => reads(x, al[i], 3));
    const gold = at(`For gold’s blue channel the three are ${N}, ${N} and ${N}`);
    three('gold', 2).forEach((x, i) => reads(x, gold[i], 3));
  });

  it('the velvet’s fuzz makes 83% of the lobe seen from 80° on the light’s side', () => {
    const [share] = at(`the fuzz makes ${N}% of the lobe seen from 80° on the light’s side`);
    const velvet = { base_color: linear('#3a1f6b'), specular_roughness: 0.6, fuzz_weight: 1, fuzz_roughness: 0.5 };
    const y = lum(velvet, 30, -80);
    reads((100 * y.fuzz) / y.all, share);
  });
});

describe('today.html: how far from the truth', () => {
  it('a white metal of roughness 0.3 loses 0.009, 0.025 and 0.086 (the split sum’s GGX albedo)', () => {
    const lost = at(`loses ${N} seen head-on, ${N} at n·v = 0.5 and ${N} at n·v = 0.2`);
    [1, 0.5, 0.2].forEach((mu, i) => reads(1 - albedoGGX(mu, 0.09), lost[i], 3));
  });

  it('the walk through a tinted coat over Lambert 0.8 gives 0.443, 0.240, 0.130 (within 4 standard errors)', () => {
    const walk = at(`seen head-on, the walk gives ${N}, ${N} and ${N}`);
    const sigma = [0.9, 0.6, 0.3].map((c) => -Math.log(c) / 2); // a round trip at normal incidence transmits c
    const stack = { coat: { alpha: 0.09, eta: 1.6, sigma }, base: { kind: 'lambert', albedo: [0.8, 0.8, 0.8] } };
    const r = layeredWalkAlbedo(1, stack, 20_000, 7);
    walk.forEach((x, c) => expect(Math.abs(r.albedo[c] - x)).toBeLessThan(4 * r.standardError[c] + 5e-4));
  });

  it('albedo scaling gives 0.546, 0.374, 0.207 there (openPbrBRDF’s albedo by quadrature, 24 nodes)', () => {
    const scaled = at(`albedo scaling gives ${N}, ${N} and ${N}`);
    // the walk's stack as OpenPBR's material: no gloss on the Lambertian base (specular_weight 0)
    const m = { coat_weight: 1, coat_roughness: 0.3, coat_color: [0.9, 0.6, 0.3], specular_weight: 0, base_color: 0.8 };
    openPbrAlbedo(openPbrMaterial(m), 1, 24).total.forEach((x, c) => reads(x, scaled[c], 3));
  });
});

describe('tour step today-openpbr-layers (openPbrLayers with the step’s state)', () => {
  it('88% diffuse from 0° and 98.7% coat in the mirror direction', () => {
    const s = stepText('today-openpbr-layers');
    const sentence = new RegExp(
      'Seen from 0°, (\\d+)% of the light is the base’s diffuse lobe; in the\\s+mirror direction, 45°, ' +
        'the coat makes ([\\d.]+)% of it',
    );
    const [diffuse, coat] = quoted(s.text, sentence);
    const m = { ...PAINT, base_color: linear(s.state.base_color) };
    const head = lum(m, s.state.lightTheta, s.state.viewTheta);
    reads((100 * head.diffuse) / head.all, diffuse);
    const mirror = lum(m, 45, 45);
    reads((100 * mirror.coat) / mirror.all, coat, 1);
  });
});

describe('grader openpbr-layer', () => {
  const exercise = JSON.parse(readFileSync(join(ROOT, 'public/exercises/openpbr-which-layer.json'), 'utf8'));
  const grader = GRADERS['openpbr-layer'];
  const { tolerance } = exercise;
  const defaults = Object.fromEntries(Object.entries(grader.params).map(([k, f]) => [k, f.default]));
  const params = { ...defaults, ...exercise.params }; // as the validator fills them in

  it('the shipped question: the widget shows the material and light the grader reads', () => {
    for (const [k, v] of Object.entries(exercise.params)) expect(exercise.state[k], k).toEqual(v);
    expect(exercise.locked).toEqual(expect.arrayContaining(['openpbrParts', 'openpbrLayer']));
    expect(exercise.state).toMatchObject({ openpbrParts: false, openpbrLayer: 'none' });
  });

  it('shares are openPbrLayers’ luminances over their sum; the metal makes 87% at 20°, the coat 72% at 40°', () => {
    const material = {
      base_color: linear(params.base_color),
      base_metalness: 1,
      specular_roughness: 0.6,
      coat_weight: 1,
      coat_roughness: 0.3,
      fuzz_weight: 0.3,
      fuzz_roughness: 0.5,
    };
    for (const view of [20, 40]) {
      const y = lum(material, 40, view);
      const shares = layerShares({ ...params, viewTheta: view });
      for (const k of ['specular', 'diffuse', 'metal', 'coat', 'fuzz']) expect(shares[k]).toBeCloseTo(y[k] / y.all, 12);
    }
    expect(layerShares(params).metal).toBeCloseTo(0.866, 3);
    expect(layerShares({ ...params, viewTheta: 40 }).coat).toBeCloseTo(0.722, 3);
  });

  it('grades the metal right and the coat wrong; refuses a question with no layer above the share', () => {
    expect(grader.grade({ answer: 'metal', params, tolerance }).ok).toBe(true);
    const wrong = grader.grade({ answer: 'coat', params, tolerance });
    expect(wrong.ok).toBe(false);
    expect(wrong.summary).toMatch(/coat makes only 12\.8%/);
    expect(grader.check(params, tolerance)).toEqual([]);
    expect(grader.check(params, 0.4)[0]).toMatch(/not a share from 0.5 to 1/);
    // seen from 80° on the light's side the metal and the fuzz share the lobe (58% and 41%): no single answer
    expect(grader.check({ ...params, viewTheta: -80 }, 0.6)[0]).toMatch(/no layer makes more than 60%/);
  });
});
