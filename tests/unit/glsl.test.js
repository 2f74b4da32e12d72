import { describe, expect, it } from 'vitest';
import { assembleGlsl, resolveConditionals } from '../../src/core/gpu/glsl.js';
import { SHADER_CHUNKS } from '../../src/core/gpu/shader-chunks.js';
import * as math from '../../src/math/index.js';

describe('GLSL assembly', () => {
  it('keeps only the active branch of conditionals', () => {
    const src = ['#ifdef A', 'a', '#elif defined(B)', 'b', '#else', 'c', '#endif', '#ifndef A', 'notA', '#endif'].join(
      '\n',
    );
    expect(resolveConditionals(src, { A: 1 }).split('\n')).toEqual(['a']);
    expect(resolveConditionals(src, { B: 1 }).split('\n')).toEqual(['b', 'notA']);
    expect(resolveConditionals(src, {}).split('\n')).toEqual(['c', 'notA']);
  });
  it('reads || and && of defined() as the C preprocessor does, and refuses other conditions', () => {
    const src = '#if defined(A) || defined(B) && !defined(C)\nyes\n#else\nno\n#endif';
    expect(resolveConditionals(src, { A: 1 })).toBe('yes');
    expect(resolveConditionals(src, { B: 1 })).toBe('yes');
    expect(resolveConditionals(src, { B: 1, C: 1 })).toBe('no');
    expect(resolveConditionals(src, {})).toBe('no');
    expect(() => resolveConditionals('#if X > 1\n#endif', {})).toThrow(/only 'defined/);
  });
  it('includes each chunk once and leaves a switched-off term out of the program', () => {
    const frag = SHADER_CHUNKS['fresnel-zones.frag.glsl'];
    const plain = assembleGlsl(frag, { defines: {} });
    const weighted = assembleGlsl(frag, {
      defines: { ZONE_BY_LH: 1, WEIGHTED: 1, NDF_GGX: 1, VIS_SMITH_GGX_CORRELATED: 1 },
    });
    expect(plain).not.toMatch(/ndfGGX|visibilitySmith|fresnelConductor/);
    expect(weighted).toMatch(/float ndfGGX/);
    expect(weighted.match(/float saturate\(float x\)/g)).toHaveLength(1);
    expect(() => assembleGlsl('#include "nope.glsl"')).toThrow(/unknown chunk/);
  });
  it('has a GLSL function of the same name for every JS shading function the shaders mirror', () => {
    const glsl = Object.values(SHADER_CHUNKS).join('\n');
    const mirrored = [
      'srgbToLinear',
      'linearToSrgb',
      'fresnelSchlick',
      'fresnelDielectric',
      'fresnelConductor',
      'ndfGGX',
      'visibilitySmithGGXCorrelated',
      'fresnelZone',
    ];
    for (const name of mirrored) {
      expect(typeof math[name]).toBe('function');
      expect(glsl).toMatch(new RegExp(`\\b(float|vec3) ${name}\\(`));
    }
  });
});
