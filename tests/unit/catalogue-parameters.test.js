// Parameters as data and the microfacet input (issue 27): one table of shared parameters that every entry and the
// GLSL read, each uniform bound to its parameter (against the float64 functions of src/math directly), the
// capability flags against what the app has (the samplers of integrate.glsl, the fits of src/measured/fit.js),
// and the JS dispatch over the input against each term's cosine convention.
import { describe, expect, it } from 'vitest';
import { CATALOGUE } from '../../src/math/catalogue/index.js';
import { PARAMETERS, parametersGlsl } from '../../src/math/catalogue/parameters.js';
import { microfacetInput, termAt } from '../../src/math/catalogue/microfacet-input.js';
import { termUniforms } from '../../src/math/catalogue/uniforms.js';
import { clampAlpha, clampSgd, sgdNormalization } from '../../src/math/ndf.js';
import { SHADER_CHUNKS } from '../../src/core/gpu/shader-chunks.js';
import { termCall, termUniformTypes } from '../../src/core/gpu/term-chunks.js';
import { LAB_TERMS, termsWith } from '../../src/lab/lab-approximations.js';
import { FIT_MODELS } from '../../src/measured/fit.js';
import { SLOTS } from '../../src/core/custom/slots.js';
import { sphereCell } from '../../src/widgets/ndf-explorer/spheres.js';
import { matchNdfWidths } from '../../src/math/ndf-width.js';

const spherical = (t, p) => [Math.sin(t) * Math.cos(p), Math.sin(t) * Math.sin(p), Math.cos(t)];

describe('one table of shared parameters', () => {
  it('F0 is one object in Fresnel, diffuse and compensation entries; α one in D, V and compensation', () => {
    const { fresnel, diffuse, compensation, ndf, visibility } = CATALOGUE;
    for (const entry of [fresnel.terms.schlick, diffuse.terms.fresnelWeighted, compensation.terms.turquin])
      expect(entry.params.f0).toBe(PARAMETERS.f0);
    for (const entry of [ndf.terms.ggx, visibility.terms.smithGGXCorrelated, compensation.terms.kullaConty])
      expect(entry.params.alpha).toBe(PARAMETERS.alpha);
    expect(SLOTS.D.args.find((a) => a.name === 'alpha')).toMatchObject({ min: 1e-4, max: 1 });
  });
  it('the JS clamp and the GLSL defines read α’s range from it: [1e-4, 1]', () => {
    expect([clampAlpha(0), clampAlpha(5)]).toEqual([1e-4, 1]);
    expect(parametersGlsl()).toMatch(/#define ALPHA_MIN 0\.0001\n#define ALPHA_MAX 1\.0/);
    expect(SHADER_CHUNKS['ndf.glsl']).toContain('#include "parameters.glsl"');
    expect(SHADER_CHUNKS['ndf.glsl']).not.toMatch(/#define ALPHA_MIN/);
  });
});

describe('each uniform bound to its parameter', () => {
  it('SGD’s normaliser uniform is Γ(1 - p, α) at the clamped parameters (sgdNormalization of ndf.js)', () => {
    for (const [alpha, p] of [
      [0.3, 0.64],
      [0.05, 1.5],
      [3, -1],
    ]) {
      const u = termUniforms({ D: 'sgd' }, { alpha, p });
      expect(u).toEqual({ uSgdP: p, uSgdNorm: sgdNormalization(...clampSgd(alpha, p)) });
    }
  });
  it('the NDF explorer’s spheres get each NDF’s matched parameters under their uniform names', () => {
    const m = matchNdfWidths(12);
    const state = { lightTheta: 30, exposure: 1 };
    const cell = (key) => sphereCell({ key, p: m[key], cell: undefined }, state).uniforms;
    expect(cell('ggx')).toMatchObject({ uAlphaPair: [m.ggx.alpha, m.ggx.alpha] });
    expect(cell('blinnPhong')).toMatchObject({ uExponent: m.blinnPhong.exponent });
    expect(cell('abc')).toMatchObject({ uA1: m.abc.a1, uA2: m.abc.a2 });
    expect(cell('sgd')).toMatchObject({
      uAlphaPair: [m.sgd.alpha, m.sgd.alpha],
      uSgdP: m.sgd.p,
      uSgdNorm: sgdNormalization(...clampSgd(m.sgd.alpha, m.sgd.p)),
    });
    expect(cell('ggx')).not.toHaveProperty('uSgdNorm'); // a cell sets the uniforms of its own terms only
  });
});

describe('a term’s own parameters: their uniforms, of the parameter’s kind', () => {
  it('a float, a vec2 (a roughness pair) and an RGB colour each declare their uniform in the dispatch', () => {
    const term = {
      ...CATALOGUE.ndf.terms.abc,
      glsl: 'ndfKinds',
      args: ['nh', 'a1', 'pair', 'tint'],
      params: {
        a1: CATALOGUE.ndf.terms.abc.params.a1,
        pair: { min: 0, max: 1, unit: '', label: 'pair', kind: 'vec2', uniform: 'uPair' },
        tint: { min: 0, max: 1, unit: '', label: 'tint', kind: 'colour', uniform: 'uTint' },
      },
    };
    expect(termUniformTypes(term)).toEqual({ uA1: 'float', uPair: 'vec2', uTint: 'vec3' });
    expect(termCall(term)).toBe('ndfKinds(m.nh, uA1, uPair, uTint)');
  });
});

describe('capability flags', () => {
  it('sampler: the NDFs integrate.glsl samples, in the generated sampleLobeNormal', () => {
    expect(termsWith('ndf', 'sampler')).toEqual(['ggx', 'beckmann']);
    const chunk = SHADER_CHUNKS['ndf-sampler.glsl'];
    expect(chunk).toMatch(/defined\(NDF_GGX\)\nvec3 sampleLobeNormal\(vec2 u, float alpha\) \{ return sampleGGXNormal/);
    for (const fn of ['sampleGGXNormal', 'sampleBeckmannNormal']) expect(SHADER_CHUNKS['integrate.glsl']).toContain(fn);
  });
  it('dfgTable: the lab offers the D and V its tables are built for', () => {
    expect(Object.keys(LAB_TERMS.ndf)).toEqual(['ggx', 'beckmann']);
    expect(Object.keys(LAB_TERMS.visibility).sort()).toEqual(
      ['smithGGXCorrelated', 'smithGGXSeparable', 'schlickGGX', 'kelemen', 'cookTorrance', 'implicit'].sort(),
    );
  });
  it('measuredFit: exactly the D and V of the measured-BRDF fit’s models (src/measured/fit.js)', () => {
    const models = Object.values(FIT_MODELS);
    expect(new Set(termsWith('ndf', 'measuredFit'))).toEqual(new Set(models.map((m) => m.D)));
    expect(new Set(termsWith('visibility', 'measuredFit'))).toEqual(new Set(models.map((m) => m.V)));
  });
});

describe('the microfacet input', () => {
  it('takes sin²θh from the half vector: exact 1e-18 at 1e-9 rad from n, where 1 - (n·h)² is 0 in float64', () => {
    const l = spherical(1e-9, 0.4);
    const m = microfacetInput(l, l, 0.3);
    expect(1 - m.nh * m.nh).toBe(0);
    expect(m.sin2h / Math.sin(1e-9) ** 2).toBeCloseTo(1, 12);
    expect(m.alpha).toEqual([0.3, 0.3]);
    expect(
      microfacetInput(
        l,
        l.map((x) => -x),
        0.3,
      ).h,
    ).toBeNull();
  });
  it('termAt over the input is each isotropic D and V term’s own convention (evaluate over the cosines)', () => {
    const params = { alpha: 0.2, exponent: 50, a1: 20, a2: 2.5, p: 0.64 };
    for (const [tl, pl, tv, pv] of [
      [0.3, 0, 0.5, 2],
      [1.2, 1, 0.1, -1],
      [1e-4, 0, 1e-4, Math.PI],
    ]) {
      const m = microfacetInput(spherical(tl, pl), spherical(tv, pv), params.alpha);
      // the anisotropic lobes have no function of the cosines (tests/unit/catalogue-anisotropic.test.js)
      for (const term of Object.values(CATALOGUE.ndf.terms).filter((t) => t.evaluate))
        expect(termAt(term, m, params) / term.evaluate(m.nh, params, m.sin2h), term.key).toBeCloseTo(1, 12);
      for (const term of Object.values(CATALOGUE.visibility.terms).filter((t) => t.evaluate))
        expect(termAt(term, m, params), term.key).toBeCloseTo(term.evaluate(m, params), 12);
    }
  });
});
