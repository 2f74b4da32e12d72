// The note under the visibility explorer's spheres: each term against height-correlated Smith on the lit side.
// Recomputed here from src/math/visibility.js at the point's angles in closed form: n 60° from the view towards
// a light 75° from it, so l is 15° past n, h halfway between l and v (22.5° from n), l·h = v·h = cos 37.5°.
import { describe, expect, it } from 'vitest';
import * as V from '../../src/math/visibility.js';
import { RIM_DEG, rimRatios } from '../../src/widgets/visibility-explorer/model.js';
import { describeRim } from '../../src/widgets/visibility-explorer/words.js';
import { schema } from '../../src/widgets/visibility-explorer/schema.js';

const DEFAULTS = Object.fromEntries(Object.entries(schema).map(([k, f]) => [k, f.default]));
const c = (deg) => Math.cos((deg * Math.PI) / 180);
const [nl, nv, nh, lh] = [c(15), c(60), c(22.5), c(37.5)];

describe('what to look for on the visibility spheres', () => {
  it('by default the light is 75° from the view, α = 0.8, the point 60° from the view', () => {
    expect([DEFAULTS.lightTheta, DEFAULTS.alpha, RIM_DEG]).toEqual([75, 0.8, 60]);
  });

  it('each ratio is V over height-correlated Smith from src/math/visibility.js at the closed-form angles', () => {
    const a = DEFAULTS.alpha;
    const reference = V.visibilitySmithGGXCorrelated(nl, nv, a);
    const expected = {
      implicit: V.visibilityImplicit(nl, nv),
      cookTorrance: V.visibilityCookTorrance(nl, nv, nh, lh),
      kelemen: V.visibilityKelemen(lh),
      smithGGXSeparable: V.visibilitySmithGGXSeparable(nl, nv, a),
      smithGGXCorrelatedFast: V.visibilitySmithGGXCorrelatedFast(nl, nv, a),
      schlickGGX: V.visibilitySchlickGGX(nl, nv, a),
    };
    const ratios = rimRatios(DEFAULTS);
    expect(ratios.map((r) => r.key)).toEqual(Object.keys(expected));
    for (const r of ratios) expect(r.ratio).toBeCloseTo(expected[r.key] / reference, 12);
  });

  it('the words give the percentages: Cook–Torrance brighter, the implicit term darker', () => {
    const text = describeRim(rimRatios(DEFAULTS), DEFAULTS, RIM_DEG);
    const pct = (v) => Math.round((v / V.visibilitySmithGGXCorrelated(nl, nv, 0.8) - 1) * 100);
    expect(pct(V.visibilityCookTorrance(nl, nv, nh, lh))).toBeGreaterThan(20);
    expect(text).toContain(`Cook–Torrance +${pct(V.visibilityCookTorrance(nl, nv, nh, lh))}%`);
    expect(text).toContain(`Implicit (V = 1) −${-pct(V.visibilityImplicit())}%`);
    expect(text).toMatch(/turns 60° from you towards the light \(75° from you\)/);
  });
});
