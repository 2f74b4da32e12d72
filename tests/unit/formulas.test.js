// The formulas: every data-tex of every HTML page parses with KaTeX as MathML, and every widget's live formula
// (declared in its words.js) parses for each of its choices, names only its own state keys as symbols, and
// shows the model's numbers, recomputed here from the closed forms.
import { readFileSync, readdirSync } from 'node:fs';
import { join } from 'node:path';
import katex from 'katex';
import { describe, expect, it } from 'vitest';
import { FORMULA_MACROS, TALK_MACROS, declaredFormula } from '../../src/core/framework/formula-registry.js';
import { coerceState, defaultState } from '../../src/core/framework/state.js';
import { WIDGETS } from '../../src/widgets/registry.js';
import { TOUR_STEPS } from '../../src/tour/steps.js';
import { parseInlineTex, texToPlain } from '../../src/core/ui/inline-tex.js';

const ROOT = join(import.meta.dirname, '../..');
const decode = (s) =>
  s.replaceAll('&quot;', '"').replaceAll('&lt;', '<').replaceAll('&gt;', '>').replaceAll('&amp;', '&');
const PAGES = readdirSync(ROOT).filter((f) => f.endsWith('.html'));
const formulas = PAGES.flatMap((page) =>
  [...readFileSync(join(ROOT, page), 'utf8').matchAll(/data-tex="([^"]*)"/g)].map((m) => ({
    page,
    tex: decode(m[1]),
  })),
);
const mathml = (tex, macros = TALK_MACROS, trust = false) =>
  katex.renderToString(tex, { output: 'mathml', displayMode: true, throwOnError: true, macros: { ...macros }, trust });

describe('formulas on the pages', () => {
  // the pages whose prose has formulas (the exercises page's are in its prompts, below)
  const CHAPTERS = [
    'fresnel',
    'media',
    'microfacets',
    'ndf',
    'visibility',
    'brdf',
    'diffuse',
    'rendering',
    'performance',
  ];
  it.each(CHAPTERS)('%s.html has typeset formulas', (name) => {
    expect(formulas.filter((f) => f.page === `${name}.html`).length).toBeGreaterThan(0);
  });

  for (const { page, tex } of formulas) {
    it(`${page}: ${tex.slice(0, 60)}…`, () => {
      const html = mathml(tex);
      expect(html).toMatch(
        /^<span class="katex"><math xmlns="http:\/\/www.w3.org\/1998\/Math\/MathML" display="block">/,
      );
      expect(html).not.toMatch(/katex-error|\sstyle=/); // MathML only: nothing a strict style policy would block
    });
  }
});

describe('formulas in data: the tour’s step texts and the exercise prompts ($…$ TeX)', () => {
  const EXERCISES = join(ROOT, 'public/exercises');
  const texts = [
    ...TOUR_STEPS.map((s) => ({ where: `tour ${s.id}`, text: s.text })),
    ...readdirSync(EXERCISES)
      .filter((f) => f !== 'index.json')
      .map((f) => ({ where: f, text: JSON.parse(readFileSync(join(EXERCISES, f), 'utf8')).prompt })),
  ];
  const inline = texts.flatMap(({ where, text }) =>
    parseInlineTex(text).flatMap((p) => ('tex' in p ? [{ where, ...p }] : [])),
  );
  it('the formulas of the tour (V = G/((n·l)(n·v)), c_diff/π, …) and of the shader exercises are in TeX', () => {
    expect(inline.filter((f) => f.where.startsWith('tour')).length).toBeGreaterThan(15);
    expect(new Set(inline.map((f) => f.where)).size).toBeGreaterThan(20);
  });
  for (const { where, tex, plain } of inline) {
    it(`${where}: ${plain.slice(0, 60)} parses with KaTeX as MathML, with a plain fallback`, () => {
      expect(mathml(tex)).not.toMatch(/katex-error|\sstyle=/);
      expect(plain).not.toMatch(/[\\{}^]/); // no TeX left in what a reader sees without MathML
    });
  }
  it('no text keeps a stray $ (a literal dollar is written \\$)', () => {
    for (const { where, text } of texts)
      expect(
        parseInlineTex(text).filter((p) => 'text' in p && p.text.includes('$')),
        where,
      ).toEqual([]);
  });
});

describe('inline TeX: $…$ in text, its plain fallback written out from the talk’s TeX', () => {
  it('splits text and formulas; \\$ is a dollar, a lone $ stays text', () => {
    expect(parseInlineTex('costs \\$5, $x^2$ and $ alone')).toEqual([
      { text: 'costs $5, ' },
      { tex: 'x^2', plain: 'x²' },
      { text: ' and $ alone' },
    ]);
    expect(parseInlineTex('$a \\$ b$')).toEqual([{ tex: 'a \\$ b', plain: 'a $ b' }]);
  });
  it.each([
    ['V = \\frac{G}{\\nl\\nv}', 'V = G/((n·l)(n·v))'],
    ['\\frac{\\mathbf{c}_{\\text{diff}}}{\\pi}', 'c_diff/π'],
    ['D = \\frac{\\alpha^2}{\\pi (\\nh^2 (\\alpha^2 - 1) + 1)^2}', 'D = α²/(π ((n·h)² (α² − 1) + 1)²)'],
    ['\\sin^2 45^\\circ = 50\\%', 'sin² 45° = 50%'],
    ['g = \\sqrt{\\eta^2 - 1 + c^2}', 'g = √(η² − 1 + c²)'],
    ['2^{-24} \\approx 6 \\times 10^{-8}', '2⁻²⁴ ≈ 6 × 10⁻⁸'],
  ])('%s reads %s', (tex, plain) => expect(texToPlain(tex)).toBe(plain));
});

/** Each widget's states to try: the default, and every option of each enum and set field on its own. */
function statesOf(schema) {
  const base = defaultState(schema);
  const variants = Object.entries(schema).flatMap(([key, f]) => {
    if (f.type === 'enum') return Object.keys(f.options).map((v) => ({ [key]: v }));
    if (f.type === 'set') return [[], ...Object.keys(f.options).map((v) => [v])].map((v) => ({ [key]: v }));
    if (f.type === 'bool') return [{ [key]: !f.default }];
    if (f.type === 'number') return [{ [key]: f.min }, { [key]: f.max }];
    return [];
  });
  return [base, ...variants.map((v) => coerceState(schema, v, base).state)];
}

const loaded = Object.fromEntries(
  await Promise.all(Object.entries(WIDGETS).map(async ([name, w]) => [name, (await w.load()).widget])),
);
const texOf = (name, partial = {}) => {
  const { schema } = loaded[name];
  return declaredFormula(name)(coerceState(schema, partial, defaultState(schema)).state);
};

describe('live formulas', () => {
  it.each(Object.keys(WIDGETS))('%s: typesets in every choice, its symbols all state keys', (name) => {
    const texOf = declaredFormula(name);
    expect(texOf).toBeTypeOf('function');
    const { schema } = loaded[name];
    for (const state of statesOf(schema)) {
      const tex = texOf(state);
      const html = mathml(tex, FORMULA_MACROS, (c) => c.command === '\\href' && c.url.startsWith('#sym:'));
      expect(html).not.toMatch(/katex-error|\sstyle=/);
      const keys = [...html.matchAll(/href="#sym:([^"]*)"/g)].map((m) => m[1]);
      expect(keys.filter((k) => !Object.hasOwn(schema, k))).toEqual([]);
    }
  });

  // the numbers shown, against closed forms computed here
  const shows = (tex, x, digits = 3) => expect(tex).toContain(x.toFixed(digits));

  it('fresnel-curves: F0 = ((n − 1)/(n + 1))² of the custom n, and Schlick’s 1 − F0', () => {
    const tex = texOf('fresnel-curves', { materials: ['custom'], ior: 1.7 });
    const f0 = ((1.7 - 1) / (1.7 + 1)) ** 2;
    shows(tex, f0);
    shows(tex, 1 - f0);
    expect(tex).toContain('\\sym{ior}{1.70}');
  });

  /** GGX, height-correlated Smith and Schlick at (α, F0, θl, θv) in closed form: F, D, G and f in 1/sr. */
  const lobeClosedForm = ([a, f0, tl, tv]) => {
    const DEG = Math.PI / 180;
    const l = [-Math.sin(tl * DEG), 0, Math.cos(tl * DEG)];
    const v = [Math.sin(tv * DEG), 0, Math.cos(tv * DEG)];
    const h = l.map((x, i) => x + v[i]);
    const len = Math.hypot(...h);
    const [nl, nv, nh] = [l[2], v[2], h[2] / len];
    const lh = (l[0] * h[0] + l[2] * h[2]) / len;
    const F = f0 + (1 - f0) * (1 - lh) ** 5;
    const D = a ** 2 / (Math.PI * (nh ** 2 * (a ** 2 - 1) + 1) ** 2);
    const V = 2 / (nv * Math.sqrt(nl ** 2 + a ** 2 * (1 - nl ** 2)) + nl * Math.sqrt(nv ** 2 + a ** 2 * (1 - nv ** 2)));
    return { F, D, G: V * nl * nv, f: (F * D * V) / 4 };
  };
  const LOBE_AT = [0.4, 0.04, 30, 50];
  const lobeState = ([alpha, f0, lightTheta, viewTheta]) => ({ alpha, f0, lightTheta, viewTheta });

  it('brdf-lobe: f = F G D / (4 (n·l)(n·v)) with GGX, height-correlated Smith and Schlick, in closed form', () => {
    const tex = texOf('brdf-lobe', lobeState(LOBE_AT));
    const { F, D, G, f } = lobeClosedForm(LOBE_AT);
    for (const x of [F, D, G, f]) shows(tex, x);
  });

  it('brdf-lobe: a custom F, D or V is named as the explorers name it, no catalogue number (closed form) shown', () => {
    const closed = lobeClosedForm(LOBE_AT);
    const cases = [
      ['F', 'F_{\\text{yours}}(F_0, \\lh )', closed.F, 'F_{\\text{Schlick}}'],
      ['D', 'D_{\\text{yours}}(\\nh, \\alpha)', closed.D, 'D_{\\text{GGX}}'],
      ['V', 'V_{\\text{yours}}(\\nl, \\nv, \\alpha)', closed.G, 'V_{\\text{Smith'],
    ];
    for (const [slot, named, catalogue, name] of cases) {
      const tex = texOf('brdf-lobe', { ...lobeState(LOBE_AT), [slot]: 'custom' });
      expect(tex, slot).toContain(named);
      expect(tex, slot).toContain('your GLSL, evaluated on the GPU');
      expect(tex, slot).not.toContain(catalogue.toFixed(3));
      expect(tex, slot).not.toContain(closed.f.toFixed(3)); // f follows the user's term: its value is the GPU's
      expect(tex, slot).not.toContain(name);
    }
    // the three explorers name theirs the same way
    expect(texOf('ndf-explorer', { D: ['custom'] })).toContain('D_{\\text{yours}}(\\nm ');
    expect(texOf('visibility-explorer', { V: ['custom'] })).toContain('V_{\\text{yours}}(\\nl, \\nv, \\alpha)');
    expect(texOf('diffuse-explorer', { diffuse: ['custom'] })).toContain('f_{\\text{yours}}(');
  });

  it('brdf-lobe: a whole custom BRDF has no F·D·G/(4 (n·l)(n·v)) and no Lambert 1/π (the starter’s)', async () => {
    const tex = texOf('brdf-lobe', { ...lobeState(LOBE_AT), brdf: 'custom' });
    expect(tex).toContain('f(\\mathbf{l},\\mathbf{v}) = f_{\\text{yours}}(\\mathbf{l}, \\mathbf{v})');
    expect(tex).not.toMatch(/\\frac|D\(|G\(|F_0|\\alpha/);
    expect(tex).not.toContain((1 / Math.PI).toFixed(3));
    // nor does the readout's table head
    const { tableHead } = await import('../../src/widgets/brdf-lobe/readout.js');
    expect(tableHead({ brdf: 'custom' })).not.toMatch(/FDG/);
    expect(tableHead({ brdf: 'microfacet' })).toContain('f = FDG/(4 n·l n·v) (1/sr)');
  });

  it('energy: Kulla–Conty and Turquin both with the Fresnel terms the albedo evaluates (Simpson)', async () => {
    const { compensatedAlbedoGGX } = await import('../../src/math/multiple-scattering.js');
    const { albedoGGX, averageAlbedo, dfgSplitSum } = await import('../../src/math/integrate.js');
    const kc = texOf('energy', { compensation: 'kullaConty' });
    const turquin = texOf('energy', { compensation: 'turquin' });
    expect(kc).toContain('F_{\\text{ms}}\\,f_{\\text{ms}}');
    expect(kc).toContain(
      'F_{\\text{ms}} = \\frac{F_{\\text{avg}}^2\\,E_{\\text{avg}}}{1 - F_{\\text{avg}}(1 - E_{\\text{avg}})}',
    );
    expect(kc).toContain('F_{\\text{avg}} = F_0 + \\frac{1 - F_0}{21}');
    expect(turquin).toContain('1 + F_0\\,\\frac{1 - E(\\mu_o)}{E(\\mu_o)}');
    // what the formulas say, evaluated here: F_avg = 2∫F μ dμ of Schlick by Simpson, E = scale + bias (F = 1)
    const [mu, alpha, f0] = [0.5, 0.6, 0.3];
    const n = 2000;
    const schlick = (m) => f0 + (1 - f0) * (1 - m) ** 5;
    let sum = 0;
    for (let i = 0; i <= n; i++) sum += (i === 0 || i === n ? 1 : i % 2 ? 4 : 2) * schlick(i / n) * (i / n);
    const fAvg = (2 * sum) / (3 * n);
    const eAvg = averageAlbedo((m) => albedoGGX(m, alpha));
    const [scale, bias] = dfgSplitSum(mu, alpha);
    const [single, E] = [f0 * scale + bias, scale + bias];
    const fMs = (fAvg ** 2 * eAvg) / (1 - fAvg * (1 - eAvg));
    expect(compensatedAlbedoGGX(mu, alpha, f0, 'kullaConty', eAvg)).toBeCloseTo(single + fMs * (1 - E), 9);
    expect(compensatedAlbedoGGX(mu, alpha, f0, 'turquin', eAvg)).toBeCloseTo(single * (1 + (f0 * (1 - E)) / E), 9);
  });

  it('ndf-explorer: GGX’s α and Beckmann’s α where D falls to half its peak at the matched half width', () => {
    const t = (10 * Math.PI) / 180;
    // D_tr(t)/D_tr(0) = 1/2 and D_b(t)/D_b(0) = 1/2, solved by bisection here
    const bisect = (g) => {
      let [lo, hi] = [1e-3, 1];
      for (let i = 0; i < 60; i++) [lo, hi] = g((lo + hi) / 2) > 0.5 ? [lo, (lo + hi) / 2] : [(lo + hi) / 2, hi];
      return (lo + hi) / 2;
    };
    const c = Math.cos(t);
    const ggx = bisect((a) => (a * a) ** 2 / (a * a * c * c + 1 - c * c) ** 2); // D(t)/D(0), rising in α
    const beckmann = bisect((a) => Math.exp(-(1 - c * c) / (c * c * a * a)) / c ** 4);
    shows(texOf('ndf-explorer', { hwhm: 10, D: ['ggx'] }), ggx);
    shows(texOf('ndf-explorer', { hwhm: 10, D: ['beckmann'] }), beckmann);
  });

  it('media: Beer–Lambert T = exp(−σt d) for clean water at 10 m', async () => {
    const { MEDIA } = await import('../../src/widgets/media/schema.js');
    const tex = texOf('media', { medium: 'water', distance: 1 });
    const T = MEDIA.water.sigmaA.map((s, i) => Math.exp(-(s + MEDIA.water.sigmaS[i]) * 10));
    for (const x of T) shows(tex, x);
  });

  it('diffuse-explorer: Lambert’s c_diff/π, and Oren–Nayar’s A and B from σ in radians', () => {
    shows(texOf('diffuse-explorer', { diffuse: ['lambert'], cdiff: 0.6 }), 0.6 / Math.PI);
    const s2 = ((30 * Math.PI) / 180) ** 2;
    const tex = texOf('diffuse-explorer', { diffuse: ['orenNayarQualitative'], sigma: 30 });
    shows(tex, 1 - (0.5 * s2) / (s2 + 0.33));
    shows(tex, (0.45 * s2) / (s2 + 0.09));
  });

  it('subsurface-scale: mean free path 1/(σs + σa) and albedo σs/(σs + σa)', () => {
    const tex = texOf('subsurface-scale', { sigmaS: 4, sigmaA: 1 });
    expect(tex).toContain('\\ell = \\frac{1}{\\sigma_t} = 0.2\\');
    shows(tex, 0.8);
  });

  it('radiance: the solid angle 2π(1 − cos θs) of a lamp of radius r at distance d', () => {
    const tex = texOf('radiance', { lampRadius: 0.1, distance: 0.5 });
    const omega = 2 * Math.PI * (1 - Math.sqrt(1 - 0.2 ** 2));
    expect(tex).toContain(String(Number(omega.toPrecision(3))));
  });
});
