// The catalogue side of user-written terms (src/math/catalogue/custom-terms.js, the dispatch chunks of
// src/core/gpu/term-chunks.js): a menu offers `custom` only when asked, its define picks the user's function in the
// family's dispatch, and a program with a custom D and a custom V holds both users' codes, each once.
import { describe, expect, it } from 'vitest';
import { CATALOGUE, CUSTOM_TERMS, termDefines, termOptions } from '../../src/math/catalogue/index.js';
import { SLOTS } from '../../src/core/custom/slots.js';
import { customChunkName, withCustomChunk } from '../../src/core/custom/assemble.js';
import { assembleGlsl } from '../../src/core/gpu/glsl.js';
import { SHADER_CHUNKS } from '../../src/core/gpu/shader-chunks.js';

const SPHERE = SHADER_CHUNKS['brdf-sphere.frag.glsl'];

describe('custom in the catalogue', () => {
  it('is in a menu only when asked, last, for the families with a generated dispatch', () => {
    expect(termOptions('ndf')).not.toHaveProperty('custom');
    expect(Object.entries(termOptions('ndf', undefined, { custom: true })).at(-1)).toEqual([
      'custom',
      'Custom (your GLSL)',
    ]);
    expect(termOptions('visibility', ['implicit'], { custom: true })).toEqual({
      implicit: 'Implicit (V = 1)',
      custom: 'Custom (your GLSL)',
    });
    // the diffuse dispatch is written by hand (shaders/diffuse-term.glsl): its DIFFUSE_CUSTOM branch
    expect(termOptions('diffuse', undefined, { custom: true })).toHaveProperty('custom');
    expect(termDefines({ diffuse: 'custom' })).toEqual({ DIFFUSE_CUSTOM: true });
  });
  it('names the slots’ functions, calls and chunks', () => {
    for (const slot of Object.values(SLOTS).filter((s) => CUSTOM_TERMS[s.family])) {
      const entry = CUSTOM_TERMS[slot.family];
      expect(entry.glsl).toBe(slot.fn);
      expect(entry.glslCall).toBe(slot.call);
      expect(entry.chunk).toBe(customChunkName(slot.key));
      expect(entry.define).toBe(`${CATALOGUE[slot.family].definePrefix}_CUSTOM`);
    }
  });
  it('picks the user’s D and V in the sphere program, each user’s code once, after #line 1 1', () => {
    const defines = termDefines({ F: 'schlick', D: 'custom', V: 'custom' });
    expect(defines).toEqual({ F_SCHLICK: true, NDF_CUSTOM: true, VIS_CUSTOM: true });
    const chunks = withCustomChunk(withCustomChunk(SHADER_CHUNKS, 'D', SLOTS.D.starter), 'V', SLOTS.V.starter);
    const text = assembleGlsl(SPHERE, { defines, chunks });
    expect(text).toMatch(/float ndfTerm\(MicrofacetInput m\) \{ return customD\(m\.nh, m\.alpha\.x\); \}/);
    expect(text).toMatch(/\{ return customV\(m\.nl, m\.nv, m\.alpha\.x\); \}/);
    expect(text.split('#line 1 1')).toHaveLength(3);
    expect(text).toContain(SLOTS.D.starter);
    expect(text).toContain(SLOTS.V.starter);
    expect(text).not.toMatch(/ndfGGXFromSin2\(m\.nh/); // the catalogue's terms are not compiled in
  });
  it('refuses a custom define without the user’s code, naming the missing chunk', () => {
    const defines = termDefines({ F: 'custom', D: 'ggx', V: 'smithGGXCorrelated' });
    expect(() => assembleGlsl(SPHERE, { defines })).toThrow('glsl: unknown chunk "custom-F.glsl"');
  });
});
