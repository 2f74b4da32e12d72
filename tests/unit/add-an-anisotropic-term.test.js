// Adding an anisotropic term (issue 27) is one catalogue entry and its two functions. This test writes an
// anisotropic GGX D and its height-correlated Smith V here, in JS and in GLSL (Burley 2012; Heitz 2014, eq. 85 for
// Λ), adds each to its family as its module would (vi.doMock of ndf-terms.js and visibility-terms.js, the
// GLSL as extra chunks), and finds them, with no other edit, in the dispatch, the parity harness (its function
// rows and its dispatch rows) and the stress grids. The GLSL is checked by a GLSL parser that fails on any
// undeclared function or variable.
import { afterAll, beforeAll, describe, expect, it, vi } from 'vitest';
import { parse } from '@shaderfrog/glsl-parser/index.js';
import { ndfGGXFromSin2 } from '../../src/math/ndf.js';
import { visibilitySmithGGXCorrelated } from '../../src/math/visibility.js';

const clamp = (a) => Math.min(Math.max(a, 1e-4), 1);
/** D(h) = 1 / (π αx αy (hx²/αx² + hy²/αy² + hz²)²), h in the tangent frame, 0 below the surface. */
const ndfGGXAnisoTest = (hx, hy, hz, ax, ay) => {
  if (!(hz > 0)) return 0;
  const [x, y] = [clamp(ax), clamp(ay)];
  const d = (hx / x) ** 2 + (hy / y) ** 2 + Math.min(hz, 1) ** 2;
  return 1 / (Math.PI * x * y * d * d);
};
/** V = 2 / ((n·l) r(v) + (n·v) r(l)), r(w) = sqrt(αx² wx² + αy² wy² + wz²) = wz (1 + 2Λ(w)). */
const root = (x, y, z, ax, ay) => Math.sqrt((clamp(ax) * x) ** 2 + (clamp(ay) * y) ** 2 + z * z);
const visibilityGGXAnisoTest = (lx, ly, lz, vx, vy, vz, ax, ay) =>
  lz > 0 && vz > 0 ? 2 / (lz * root(vx, vy, vz, ax, ay) + vz * root(lx, ly, lz, ax, ay)) : 0;

const GLSL_D = `float ndfGGXAnisoTest(float hx, float hy, float hz, float ax, float ay) {
  if (!(hz > 0.0)) return 0.0;
  float x = clamp(ax, 1e-4, 1.0);
  float y = clamp(ay, 1e-4, 1.0);
  float c = min(hz, 1.0);
  float d = (hx / x) * (hx / x) + (hy / y) * (hy / y) + c * c;
  return 1.0 / (PI * x * y * d * d);
}`;
const GLSL_V = `float anisoRootTest(float x, float y, float z, float ax, float ay) {
  float a = clamp(ax, 1e-4, 1.0) * x;
  float b = clamp(ay, 1e-4, 1.0) * y;
  return sqrt(a * a + b * b + z * z);
}
float visibilityGGXAnisoTest(float lx, float ly, float lz, float vx, float vy, float vz, float ax, float ay) {
  if (!(lz > 0.0 && vz > 0.0)) return 0.0;
  return 2.0 / (lz * anisoRootTest(vx, vy, vz, ax, ay) + vz * anisoRootTest(lx, ly, lz, ax, ay));
}`;
const CHUNKS = { 'ndf-aniso-test.glsl': `#include "common.glsl"\n${GLSL_D}`, 'vis-aniso-test.glsl': GLSL_V };

// The two entries: what a term states (term.js derives its key, define and legend). No `evaluate`: the JS
// dispatch of a term that reads the whole input is termAt(entry, microfacetInput(l, v, [αx, αy]), p).
const D_ENTRY = {
  label: 'GGX, anisotropic (test)',
  cite: 'Burley 2012',
  js: ndfGGXAnisoTest,
  evaluate: null,
  glsl: 'ndfGGXAnisoTest',
  chunk: 'ndf-aniso-test.glsl',
  args: ['hx', 'hy', 'hz', 'alphaX', 'alphaY'],
  params: {},
};
const V_ENTRY = {
  label: 'Smith GGX, anisotropic (test)',
  cite: 'Heitz 2014',
  js: visibilityGGXAnisoTest,
  evaluate: null,
  glsl: 'visibilityGGXAnisoTest',
  chunk: 'vis-aniso-test.glsl',
  args: ['lx', 'ly', 'lz', 'vx', 'vy', 'vz', 'alphaX', 'alphaY'],
  params: {},
};

let app;
beforeAll(async () => {
  vi.resetModules();
  const { term } = await import('../../src/math/catalogue/term.js');
  vi.doMock('../../src/math/catalogue/ndf-terms.js', async (importOriginal) => {
    const { NDF_FAMILY } = await importOriginal();
    const ggxAnisoTest = term(NDF_FAMILY, 'ggxAnisoTest', D_ENTRY);
    return { NDF_FAMILY: { ...NDF_FAMILY, terms: { ...NDF_FAMILY.terms, ggxAnisoTest } } };
  });
  vi.doMock('../../src/math/catalogue/visibility-terms.js', async (importOriginal) => {
    const { VISIBILITY_FAMILY } = await importOriginal();
    const ggxAnisoTest = term({ ...VISIBILITY_FAMILY, chunk: null }, 'ggxAnisoTest', V_ENTRY);
    return { VISIBILITY_FAMILY: { ...VISIBILITY_FAMILY, terms: { ...VISIBILITY_FAMILY.terms, ggxAnisoTest } } };
  });
  app = {
    catalogue: await import('../../src/math/catalogue/index.js'),
    input: await import('../../src/math/catalogue/microfacet-input.js'),
    glsl: await import('../../src/core/gpu/glsl.js'),
    chunks: (await import('../../src/core/gpu/shader-chunks.js')).SHADER_CHUNKS,
    parity: await import('../../src/core/gpu/parity-cases.js'),
    harness: await import('../../src/core/gpu/parity.js'),
    stress: (await import('../support/stress-domains.js')).STRESS_DOMAINS,
    families: (await import('../../bench/families.js')).FAMILIES,
    graders: await import('../../src/exercises/graders.js'),
  };
}, 60_000); // the app's modules, imported afresh with the two entries
afterAll(() => {
  vi.doUnmock('../../src/math/catalogue/ndf-terms.js');
  vi.doUnmock('../../src/math/catalogue/visibility-terms.js');
  vi.resetModules();
});

/** GLSL text as the GPU compiles it, the #defines expanded, for the parser (which has no preprocessor). */
function preprocessed(text) {
  const defines = {};
  const body = text
    .split('\n')
    .filter((line) => {
      const m = /^\s*#\s*define\s+(\w+)\s*(.*)$/.exec(line);
      if (m) defines[m[1]] = m[2] || '1';
      return !/^\s*#/.test(line);
    })
    .join('\n');
  return Object.entries(defines).reduce((s, [k, v]) => s.replace(new RegExp(`\\b${k}\\b`, 'g'), v), body);
}
/** Parses as a fragment shader; throws on a syntax error or an undeclared name. */
const parses = (text) => parse(preprocessed(text), { failOnWarn: true, stage: 'fragment', quiet: true });

const unit = (x, y, z) => [x, y, z].map((c) => c / Math.hypot(x, y, z));

describe('adding an anisotropic term: one catalogue entry and its two functions, no other edit', () => {
  it('the test’s terms are right: at αx = αy they are GGX and Smith GGX height-correlated (closed forms)', () => {
    for (const h of [unit(0, 0, 1), unit(0.3, 0.1, 1), unit(1, -0.5, 0.2)])
      for (const a of [0.01, 0.3, 1]) {
        const want = ndfGGXFromSin2(h[2], h[0] ** 2 + h[1] ** 2, a);
        expect(ndfGGXAnisoTest(...h, a, a) / want).toBeCloseTo(1, 12);
      }
    const [l, v] = [unit(0.5, 0.2, 0.8), unit(-0.3, 0.6, 0.5)];
    for (const a of [0.01, 0.3, 1])
      expect(visibilityGGXAnisoTest(...l, ...v, a, a) / visibilitySmithGGXCorrelated(l[2], v[2], a)).toBeCloseTo(1, 12);
    // the lobe stretches along t when αx > αy: D falls slower towards t than towards b
    const [t, b] = [unit(0.2, 0, 1), unit(0, 0.2, 1)];
    expect(ndfGGXAnisoTest(...t, 0.4, 0.1)).toBeGreaterThan(10 * ndfGGXAnisoTest(...b, 0.4, 0.1));
  });

  it('has its defines and the JS dispatch (termAt) reads it off the microfacet input; no cosine menu offers it', () => {
    const { termOptions, termDefines, termLabel, CATALOGUE } = app.catalogue;
    expect(termLabel('ndf', 'ggxAnisoTest')).toBe('GGX, anisotropic (test)');
    // the menus of the widgets that plot D(n·h) (no widget has αx, αy controls), nor the bench's cosine curves
    expect(termOptions('ndf')).not.toHaveProperty('ggxAnisoTest');
    expect(termOptions('ndf')).toHaveProperty('sgd');
    const ndf = app.families.find((f) => f.key === 'ndf');
    expect(ndf.variants.map((v) => v.key)).not.toContain('ggx-aniso-test');
    expect(app.graders.NDF_NAMES).not.toHaveProperty('ggxAnisoTest'); // the which-NDF exercise's choices
    expect(termDefines({ D: 'ggxAnisoTest', V: 'ggxAnisoTest' })).toEqual({
      NDF_GGX_ANISO_TEST: 1,
      VIS_GGX_ANISO_TEST: 1,
    });
    const [l, v] = [unit(0.5, 0.2, 0.8), unit(-0.3, 0.6, 0.5)];
    const m = app.input.microfacetInput(l, v, [0.4, 0.1]);
    const h = m.h;
    const d = app.input.termAt(CATALOGUE.ndf.terms.ggxAnisoTest, m, {});
    expect(d).toBe(ndfGGXAnisoTest(h[0], h[1], h[2], 0.4, 0.1));
    expect(app.input.termAt(CATALOGUE.visibility.terms.ggxAnisoTest, m, {})).toBe(
      visibilityGGXAnisoTest(...l, ...v, 0.4, 0.1),
    );
  });

  it('the BRDF program with its defines calls both through the input’s fields, and it parses as GLSL', () => {
    const { termDefines } = app.catalogue;
    const defines = termDefines({ F: 'schlick', D: 'ggxAnisoTest', V: 'ggxAnisoTest' });
    const chunks = { ...app.chunks, ...CHUNKS };
    const text = app.glsl.assembleGlsl(app.chunks['brdf-sphere.frag.glsl'], {
      defines: { ...defines, SPHERE_IMPOSTOR: 1 },
      chunks,
    });
    expect(text).toContain(
      'float ndfTerm(MicrofacetInput m) { return ndfGGXAnisoTest(m.h.x, m.h.y, m.h.z, m.alpha.x, m.alpha.y); }',
    );
    expect(text).toContain(
      'return visibilityGGXAnisoTest(m.l.x, m.l.y, m.l.z, m.v.x, m.v.y, m.v.z, m.alpha.x, m.alpha.y); }',
    );
    expect(text).not.toMatch(/ndfGGXFromSin2|visibilitySmithGGXCorrelated\(/);
    expect(() => parses(text)).not.toThrow();
    // the parser is a real check: a call of a function no chunk defines fails
    expect(() => parses(text.replace('return ndfGGXAnisoTest(', 'return ndfGGXAnisoTestX('))).toThrow(
      /ndfGGXAnisoTestX/,
    );
  });

  it('has parity rows: its function over directions and the shared (αx, αy), and through the dispatch', () => {
    const rows = app.parity.PARITY_CASES;
    const d = rows.find((c) => c.name === 'ndfGGXAnisoTest');
    expect(d).toMatchObject({ chunk: 'ndf-aniso-test.glsl', glsl: 'ndfGGXAnisoTest(a.x, a.y, a.z, a.w, b.x)' });
    expect(d.args[0]).toHaveLength(5);
    // αx and αy each over the shared α's stress values (src/math/catalogue/parameters.js), anisotropic pairs too
    expect(new Set(d.args.map((x) => x[3]))).toEqual(new Set([0, 1e-5, 1e-4, 1e-3, 0.01, 0.1, 0.3, 0.5, 1, 2]));
    expect(d.args.some(([, , , ax, ay]) => ax === 1 && ay === 0.01)).toBe(true);
    // h: unit vectors of the upper hemisphere, along t, along b and between
    for (const [hx, hy, hz] of d.args) expect(Math.hypot(hx, hy, hz)).toBeCloseTo(1, 6);
    expect(d.args.some(([hx, hy]) => Math.abs(hx) < 1e-6 && hy > 0.5)).toBe(true);
    const v = rows.find((c) => c.name === 'visibilityGGXAnisoTest');
    expect(v.args[0]).toHaveLength(8);
    expect(v.glsl).toBe('visibilityGGXAnisoTest(a.x, a.y, a.z, a.w, b.x, b.y, b.z, b.w)');
    for (const name of ['ndfTerm (NDF_GGX_ANISO_TEST)', 'visibilityTerm (VIS_GGX_ANISO_TEST)']) {
      const row = rows.find((c) => c.name === name);
      expect(row, name).toBeDefined();
      const fragment = app.harness.parityFragment({ ...row, chunks: { ...app.chunks, ...CHUNKS } });
      expect(() => parses(fragment), name).not.toThrow();
      expect(row.js(...row.args[5])).toBe((name.startsWith('ndf') ? d : v).js(...row.args[5]));
    }
    expect(() => parses(app.harness.parityFragment({ ...d, chunks: { ...app.chunks, ...CHUNKS } }))).not.toThrow();
  });

  it('is in the stress grids, and none of its stress inputs gives NaN, Inf or a negative value', () => {
    for (const [name, fn] of [
      ['ndfGGXAnisoTest', ndfGGXAnisoTest],
      ['visibilityGGXAnisoTest', visibilityGGXAnisoTest],
    ]) {
      const domain = app.stress[name];
      expect(domain.fn, name).toBe(fn);
      // directions below the horizon and grazing, αy over the shared α's stress values past both ends
      expect(domain.tuples.some((t) => t[2] === -1)).toBe(true);
      expect(new Set(domain.tuples.map((t) => t.at(-1)))).toEqual(
        new Set([0, 1e-5, 1e-4, 1e-3, 0.01, 0.1, 0.3, 0.5, 1, 2]),
      );
    }
    // the stress sweep (tests/support/stress-sweep.js, tests/unit/stress.test.js) runs every domain; every tuple of
    // these is finite and non-negative
    for (const [name, fn, count] of [
      ['ndfGGXAnisoTest', ndfGGXAnisoTest, 8 * 100],
      ['visibilityGGXAnisoTest', visibilityGGXAnisoTest, 8 * 8 * 100],
    ]) {
      const { tuples } = app.stress[name];
      expect(tuples).toHaveLength(count);
      expect(tuples.filter((t) => !(Number.isFinite(fn(...t)) && fn(...t) >= 0))).toEqual([]);
    }
  });
});
