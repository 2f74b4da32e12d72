import { describe, expect, it } from 'vitest';
import { assembleGlsl } from '../../src/core/gpu/glsl.js';
import { SHADER_CHUNKS } from '../../src/core/gpu/shader-chunks.js';
import { termDefines } from '../../src/math/catalogue/index.js';

const SPHERE = SHADER_CHUNKS['brdf-sphere.frag.glsl'];
const GGX = termDefines({ F: 'schlick', D: 'ggx', V: 'smithGGXCorrelated' });

describe('assembleGlsl refuses what it does not know', () => {
  it('a define no chunk of the program reads throws, naming the define (a misspelt NDF_GGX)', () => {
    expect(() => assembleGlsl(SPHERE, { defines: { ...GGX, NDF_GGXX: true } })).toThrow(
      'glsl: define NDF_GGXX is read by no chunk of this program',
    );
    // read in a chunk that this variant does not include: the furnace has no brdf.glsl
    expect(() => assembleGlsl(SPHERE, { defines: { FURNACE: true, NDF_GGX: true } })).toThrow(/define NDF_GGX is read/);
  });
  it('a define read as a token in code (a value define) or only by an inactive branch counts as read', () => {
    const chunks = { 'a.glsl': '#ifdef UNUSED_HERE\nx\n#endif\nfloat f() { return float(SAMPLES); }' };
    const text = assembleGlsl('#include "a.glsl"', { defines: { SAMPLES: 16 }, chunks });
    expect(text).toContain('#define SAMPLES 16');
    expect(() => assembleGlsl('#include "a.glsl"', { defines: { UNUSED_HERE: 1 }, chunks })).not.toThrow();
    // a comment naming the define is not a read
    expect(() => assembleGlsl('// uses NOTE_ONLY\nvoid main() {}', { defines: { NOTE_ONLY: 1 } })).toThrow(/NOTE_ONLY/);
  });
  it('a term chain without a match stops with its #error, for each family of brdf.glsl', () => {
    const { F_SCHLICK, NDF_GGX, VIS_SMITH_GGX_CORRELATED } = GGX;
    const without = (defines) => () => assembleGlsl(SPHERE, { defines });
    expect(without({ F_SCHLICK, VIS_SMITH_GGX_CORRELATED })).toThrow('glsl: #error brdf.glsl: no NDF_* chosen');
    expect(without({ F_SCHLICK, NDF_GGX })).toThrow('glsl: #error brdf.glsl: no VIS_* chosen');
    expect(without({ NDF_GGX, VIS_SMITH_GGX_CORRELATED })).toThrow('glsl: #error brdf.glsl: no F_* chosen');
    expect(without(GGX)).not.toThrow();
  });
  it('an #error in an inactive branch is no error; a #define in a chunk counts for the conditionals after it', () => {
    const chunks = { 'b.glsl': '#ifdef NO\n#error "never"\n#endif\n#define LATER' };
    const text = assembleGlsl('#ifdef NO\n#endif\n#include "b.glsl"\n#ifdef LATER\nyes\n#else\nno\n#endif', {
      chunks,
    });
    expect(text.split('\n')).toContain('yes');
    expect(text.split('\n')).not.toContain('no');
  });
  it('the chosen term alone is compiled, with its own uniforms (uA1, uA2 only under NDF_ABC)', () => {
    const abc = assembleGlsl(SPHERE, { defines: termDefines({ F: 'schlick', D: 'abc', V: 'smithGGXCorrelated' }) });
    expect(abc).toMatch(/uniform float uA1;/);
    expect(abc).toMatch(/return ndfABC\(m\.nh, uA1, uA2\)/);
    const ggx = assembleGlsl(SPHERE, { defines: GGX });
    expect(ggx).not.toMatch(/uniform float (uA1|uA2|uExponent|uSgdP)/);
    expect(ggx).toMatch(/return ndfGGXFromSin2\(m\.nh, m\.sin2h, m\.alpha\.x\)/);
  });
});
