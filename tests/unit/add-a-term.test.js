// Adding a term is its JS function, its GLSL function and one catalogue entry. This test adds a made-up NDF, a
// normalised cosine power lobe (n + 2)/(2π) (n·h)^n, to the catalogue as its own module would (vi.doMock of
// src/math/catalogue/ndf-terms.js) and finds it, with no other edit, everywhere the catalogue feeds.
import { afterAll, beforeAll, describe, expect, it, vi } from 'vitest';
import { ndfBlinnPhong } from '../../src/math/ndf.js';

const ndfCosinePower = (c, n) => (c > 0 ? ((n + 2) / (2 * Math.PI)) * Math.min(c, 1) ** n : 0);
const GLSL = `float ndfCosinePower(float c, float n) {
  return c > 0.0 ? (n + 2.0) / (2.0 * PI) * pow(min(c, 1.0), n) : 0.0;
}`;
const ENTRY = {
  key: 'cosinePower',
  label: 'Cosine power',
  short: 'cosⁿ',
  cite: 'Phong 1975',
  js: ndfCosinePower,
  evaluate: (c, p) => ndfCosinePower(c, p.exponent),
  glsl: 'ndfCosinePower',
  chunk: 'ndf-cosine-power.glsl',
  define: 'NDF_COSINE_POWER',
  args: ['nh', 'exponent'],
  params: { exponent: { min: 0, max: 1e4, unit: '', label: 'Exponent n', clamped: false, uniform: 'uExponent' } },
};

let app;
beforeAll(async () => {
  vi.resetModules();
  vi.doMock('../../src/math/catalogue/ndf-terms.js', async (importOriginal) => {
    const { NDF_FAMILY } = await importOriginal();
    return { NDF_FAMILY: { ...NDF_FAMILY, terms: { ...NDF_FAMILY.terms, cosinePower: ENTRY } } };
  });
  app = {
    catalogue: await import('../../src/math/catalogue/index.js'),
    brdf: await import('../../src/math/brdf.js'),
    glsl: await import('../../src/core/gpu/glsl.js'),
    chunks: (await import('../../src/core/gpu/shader-chunks.js')).SHADER_CHUNKS,
    parity: await import('../../src/core/gpu/parity-cases.js'),
    graders: await import('../../src/exercises/graders.js'),
    families: (await import('../../bench/families.js')).FAMILIES,
    stress: (await import('../support/stress-domains.js')).STRESS_DOMAINS,
    widths: await import('../../src/math/ndf-width.js'),
  };
});
afterAll(() => {
  vi.doUnmock('../../src/math/catalogue/ndf-terms.js');
  vi.resetModules();
});

describe('adding an NDF: one catalogue entry, its JS and its GLSL function, no other edit', () => {
  it('the made-up term is a true NDF: it equals normalised Blinn–Phong at every exponent (Blinn 1977)', () => {
    for (const n of [0, 1, 10, 300])
      for (const c of [0.1, 0.5, 0.99, 1]) {
        expect(ndfCosinePower(c, n)).toBeCloseTo(ndfBlinnPhong(c, n), 10);
      }
  });
  it('appears in termOptions, termDefines and the microfacet BRDF of src/math', () => {
    const { termOptions, termDefines } = app.catalogue;
    expect(termOptions('ndf').cosinePower).toBe('Cosine power');
    expect(Object.keys(termOptions('ndf'))).toHaveLength(6);
    expect(termDefines({ D: 'cosinePower' })).toEqual({ NDF_COSINE_POWER: 1 });
    const p = { F: 'one', D: 'cosinePower', V: 'implicit', exponent: 20 };
    const a = { nl: 0.8, nv: 0.8, nh: 0.9, lh: 0.8, h: null };
    expect(app.brdf.NDF_TERMS.cosinePower(0.9, p)).toBe(ndfCosinePower(0.9, 20));
    expect(app.brdf.microfacetBRDFAt({ ...a, h: undefined }, p)).toBeCloseTo(ndfCosinePower(0.9, 20) / 4, 12);
  });
  it('appears in a schema’s options: the which-NDF exercise’s hidden enum and its choices', () => {
    const { GRADERS, NDF_NAMES } = app.graders;
    expect(NDF_NAMES.cosinePower).toBe('Cosine power');
    const whichNdf = Object.values(GRADERS).find((t) => t.params?.hidden?.options?.random);
    expect(whichNdf.params.hidden.options.cosinePower).toBe('Cosine power');
    expect(whichNdf.answer.choices({}).cosinePower).toBe('Cosine power');
  });
  it('the assembled BRDF program with its define calls its GLSL function, with its uniform only', () => {
    const { assembleGlsl } = app.glsl;
    const { termDefines } = app.catalogue;
    const defines = termDefines({ F: 'schlick', D: 'cosinePower', V: 'smithGGXCorrelated' });
    const chunks = { ...app.chunks, 'ndf-cosine-power.glsl': GLSL };
    const text = assembleGlsl(app.chunks['brdf-sphere.frag.glsl'], { defines, chunks });
    expect(text).toContain('return ndfCosinePower(m.nh, uExponent);');
    expect(text).toContain('float ndfCosinePower(float c, float n)');
    expect(text).toMatch(/uniform float uExponent;/);
    expect(text).not.toMatch(/uniform float uA1;|float ndfTerm\(.*ndf(ABC|GGX)/);
  });
  it('has a parity row, a stress domain, a bench variant and matched widths', () => {
    const row = app.parity.PARITY_CASES.find((c) => c.name === 'ndfCosinePower');
    expect(row).toMatchObject({ chunk: 'ndf-cosine-power.glsl', glsl: 'ndfCosinePower(a.x, a.y)', js: ndfCosinePower });
    expect(new Set(row.args.map((args) => args[1]))).toEqual(new Set([0, 1, 10, 100, 1000, 1e4])); // the decades
    expect(app.stress.ndfCosinePower.fn).toBe(ndfCosinePower);
    const ndf = app.families.find((f) => f.key === 'ndf');
    const variant = ndf.variants.find((v) => v.key === 'cosine-power');
    expect(variant).toMatchObject({ kind: 'difference', against: 'beckmann', label: 'Cosine power' });
    expect(variant.glsl).toBe('ndfCosinePower(x, 10.0 + 100.0 * y)');
    // its matched exponent gives the half width asked for, as Blinn–Phong's closed form cos^p = 1/2 does
    const m = app.widths.matchNdfWidths(10);
    expect(m.cosinePower.exponent).toBeCloseTo(m.blinnPhong.exponent, 6);
  });
});
