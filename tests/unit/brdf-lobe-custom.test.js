// brdf-lobe's user-written terms as the views read them: tables of values (here computed by the catalogue's JS
// in place of the GPU) looked up by the model. The truth: the catalogue terms themselves and closed forms.
import { describe, expect, it } from 'vitest';
import { customPlan } from '../../src/widgets/brdf-lobe/custom-tables.js';
import { brdfSpec, lobeScene, albedoCurve, factorsAt, halfDiffFunction } from '../../src/widgets/brdf-lobe/model.js';
import { defaultState } from '../../src/core/framework/state.js';
import { schema } from '../../src/widgets/brdf-lobe/schema.js';
import { microfacetBRDF, brdfAngles } from '../../src/math/brdf.js';
import { ndfGGX } from '../../src/math/ndf.js';
import { visibilitySmithGGXCorrelated } from '../../src/math/visibility.js';
import { fresnelSchlick } from '../../src/math/fresnel.js';

/** evaluateCustom's output for `plan` with f (over one input's numbers) in place of the GPU: f in .x, .y, .z. */
function fakeGpu(plan, f) {
  const out = new Float32Array(plan.inputs.length * 4);
  plan.inputs.forEach((args, i) => out.fill(f(...args), 4 * i, 4 * i + 3));
  return out;
}

const state = (partial) => ({ ...defaultState(schema), lightTheta: 30, ...partial });
const ggxA = (s) => ({ D: 'ggx', V: 'smithGGXCorrelated', F: 'schlick', f0: s.f0, alpha: s.alpha });

/** The largest relative difference of two lobes ([θ, value] lists) against the larger one's peak. */
function lobeDifference(a, b) {
  const peak = Math.max(...a.map((x) => x[1]), ...b.map((x) => x[1]));
  return Math.max(...a.map((x, i) => Math.abs(x[1] - b[i][1]))) / peak;
}

describe('brdf-lobe: a custom term read from its table', () => {
  for (const alpha of [0.02, 0.3, 1]) {
    it(`a D table of GGX at α = ${alpha} draws GGX's lobe (catalogue ndfGGX; within 0.5 % of the peak)`, () => {
      const s = state({ D: 'custom', alpha });
      const D = customPlan('D', s).read(fakeGpu(customPlan('D', s), (nh, a) => ndfGGX(nh, a)));
      const custom = lobeScene(s, { D }).lobeA;
      expect(lobeDifference(custom, lobeScene(state({ alpha })).lobeA)).toBeLessThan(5e-3);
    });
  }

  it('a D scaled by 2 doubles the lobe at every angle (f is linear in D)', () => {
    const s = state({ D: 'custom' });
    const plan = customPlan('D', s);
    const D = plan.read(fakeGpu(plan, (nh, a) => 2 * ndfGGX(nh, a)));
    const [twice, once] = [lobeScene(s, { D }).lobeA, lobeScene(state({})).lobeA];
    twice.forEach(([, value], i) => expect(value).toBeCloseTo(2 * once[i][1], 1));
    expect(Math.max(...twice.map((x) => x[1]))).toBeCloseTo(2 * Math.max(...once.map((x) => x[1])), 1);
  });

  it('V and F tables of height-correlated Smith and Schlick draw the catalogue lobe (within 0.5 %)', () => {
    const s = state({ V: 'custom', F: 'custom', alpha: 0.5, f0: 0.3 });
    const [pv, pf] = [customPlan('V', s), customPlan('F', s)];
    const V = pv.read(fakeGpu(pv, (nl, nv, a) => visibilitySmithGGXCorrelated(nl, nv, a)));
    const F = pf.read(fakeGpu(pf, (f0, _g, _b, lh) => fresnelSchlick(f0, lh)));
    const ref = lobeScene(state({ alpha: 0.5, f0: 0.3 })).lobeA;
    expect(lobeDifference(lobeScene(s, { V, F }).lobeA, ref)).toBeLessThan(5e-3);
  });

  it("a V singular at the grazing corner (the starter at float32 cos 90°) draws the catalogue's (θh, θd) image", () => {
    const s = state({ V: 'custom' });
    const plan = customPlan('V', s);
    // slots.js's starter V as the GPU runs it: no guard but n·l, n·v > 0, and cos 90° = 6e-17 > 0 in float32
    const starter = (nl, nv, a) => {
      const [l, v] = [Math.fround(nl), Math.fround(nv)];
      if (!(l > 0 && v > 0)) return 0;
      return 2 / (l * Math.sqrt(v * v + a * a * (1 - v * v)) + v * Math.sqrt(l * l + a * a * (1 - l * l)));
    };
    const V = plan.read(fakeGpu(plan, starter));
    const custom = halfDiffFunction(s, brdfSpec(s, 'A', { V }));
    const catalogue = halfDiffFunction(state({}), brdfSpec(state({}), 'A'));
    // within 2 % of the catalogue, and within 10 % for θd ≥ 85°, where l and v may both graze (V ~ 1/(n·l + n·v))
    for (let i = 0; i < 90; i++)
      for (let j = 0; j < 90; j++) {
        const [th, td] = [((i + 0.5) * Math.PI) / 180, ((j + 0.5) * Math.PI) / 180];
        const [got, want] = [custom(th, td), catalogue(th, td)];
        expect(Math.abs(got - want)).toBeLessThanOrEqual((j < 85 ? 0.02 : 0.1) * want + 1e-12);
      }
  });

  it("a whole BRDF's table of the microfacet BRDF gives its lobe, f at (l, v) and its (θh, θd) image", () => {
    const s = state({ brdf: 'custom', viewTheta: 20 });
    const plan = customPlan('brdf', s);
    const f = (lx, ly, lz, vx, vy, vz) => microfacetBRDF([lx, ly, lz], [vx, vy, vz], ggxA(s));
    const brdf = plan.read(fakeGpu(plan, f));
    const scene = lobeScene(s, { brdf });
    expect(lobeDifference(scene.lobeA, lobeScene(state({ viewTheta: 20 })).lobeA)).toBeLessThan(5e-3);
    const at = factorsAt(scene.l, scene.v, brdfAngles(scene.l, scene.v), scene.A);
    expect(at.F).toBeNull();
    expect(at.f).toBeCloseTo(microfacetBRDF(scene.l, scene.v, ggxA(s)), 3);
  });

  it('the albedo of a Lambertian whole BRDF a/π is a at every angle (closed form; quadrature on the table)', () => {
    const s = state({ brdf: 'custom' });
    const plan = customPlan('brdf', s);
    const brdf = plan.read(fakeGpu(plan, (lx, ly, lz, vx, vy, vz) => (lz > 0 && vz > 0 ? 0.7 / Math.PI : 0)));
    for (const e of albedoCurve(brdfSpec(s, 'A', { brdf }))) expect(e).toBeCloseTo(0.7, 6);
  });

  it('NaN, Inf and negative values are drawn as 0, never as a broken lobe', () => {
    const s = state({ D: 'custom' });
    const plan = customPlan('D', s);
    const D = plan.read(fakeGpu(plan, (nh) => (nh > 0.99 ? NaN : nh > 0.9 ? -1 : Infinity)));
    const scene = lobeScene(s, { D });
    expect(scene.lobeA.every((x) => x[1] === 0)).toBe(true);
    expect(Number.isFinite(scene.max)).toBe(true);
  });

  it('before its code has run, a custom slot draws its starter term (the slot reference); B is never custom', () => {
    const s = state({ D: 'custom', compare: true, D2: 'ggx', V2: 'smithGGXCorrelated', alpha2: 0.3 });
    const scene = lobeScene(s, {});
    expect(lobeDifference(scene.lobeA, scene.lobeB)).toBeLessThan(1e-12);
    expect(scene.A.label).toMatch(/^A: your D \+ /);
  });
});
