// fresnel-zones' model against truths of its own: the shader reads every switch the model sets (assembleGlsl
// refuses an unread define and a term chain without a match), the weighted program's terms are the ones the JS
// probe evaluates, and the light directions of the average are uniform on the sphere (Archimedes: z uniform).
import { describe, expect, it } from 'vitest';
import { assembleGlsl } from '../../src/core/gpu/glsl.js';
import { SHADER_CHUNKS } from '../../src/core/gpu/shader-chunks.js';
import { lightDirFromAngles } from '../../src/math/angles.js';
import { termEntry } from '../../src/math/catalogue/index.js';
import { MODES, schema } from '../../src/widgets/fresnel-zones/schema.js';
import { WEIGHT_TERMS, programDefines, sharesOf, sphereLights } from '../../src/widgets/fresnel-zones/model.js';

const FRAG = SHADER_CHUNKS['fresnel-zones.frag.glsl'];
const base = Object.fromEntries(Object.entries(schema).map(([k, f]) => [k, f.default]));
const states = Object.keys(MODES).flatMap((mode) =>
  ['exact', 'schlick'].flatMap((fresnel) =>
    ['glass-low', 'gold'].map((material) => ({ ...base, mode, fresnel, material })),
  ),
);

describe('fresnel-zones programs', () => {
  it.each(states.flatMap((s) => [false, true].map((stats) => [s.mode, s.fresnel, s.material, stats, s])))(
    '%s, %s Fresnel, %s, stats %s: assembles (every define read by the shader, every term chosen)',
    (_mode, _fresnel, _material, stats, state) => {
      expect(() => assembleGlsl(FRAG, { defines: programDefines(state, stats) })).not.toThrow();
    },
  );
  it('weights the zones by the GLSL twins of the terms the probe evaluates in JS (catalogue entries)', () => {
    const weighted = { ...base, mode: 'zones-lh-weighted' };
    for (const stats of [false, true]) {
      const text = assembleGlsl(FRAG, { defines: programDefines(weighted, stats) });
      expect(text).toMatch(new RegExp(`return ${termEntry('ndf', WEIGHT_TERMS.D).glsl}\\(`));
      expect(text).toMatch(new RegExp(`return ${termEntry('visibility', WEIGHT_TERMS.V).glsl}\\(`));
    }
  });
  it('compiles no Fresnel into the stats pass and no BRDF term outside the weighted mode', () => {
    for (const state of states) {
      const stats = assembleGlsl(FRAG, { defines: programDefines(state, true) });
      expect(stats).not.toMatch(/fresnelDielectric|fresnelConductor|fresnelSchlick/);
      const picture = assembleGlsl(FRAG, { defines: programDefines(state, false) });
      if (state.mode !== 'zones-lh-weighted') expect(picture).not.toMatch(/ndfTerm|visibilityTerm/);
    }
  });
});

describe('fresnel-zones measurement', () => {
  it('spreads the average’s lights uniformly: z evenly spaced on (-1, 1) and a mean direction near 0', () => {
    const n = 64;
    const dirs = sphereLights(n).map(([theta, phi]) => lightDirFromAngles(theta, phi));
    const zs = dirs.map((d) => d[2]).sort((a, b) => a - b);
    zs.forEach((z, i) => expect(z).toBeCloseTo(-1 + (2 * (i + 0.5)) / n, 12));
    const mean = [0, 1, 2].map((k) => dirs.reduce((s, d) => s + d[k], 0) / n);
    expect(Math.hypot(...mean)).toBeLessThan(0.02);
  });
  it('turns zone totals into shares that sum to 1, and nothing covered into zeros', () => {
    expect(sharesOf([1, 3, 0])).toEqual([0.25, 0.75, 0]);
    expect(sharesOf([0, 0, 0])).toEqual([0, 0, 0]);
  });
});
