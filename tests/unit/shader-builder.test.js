// The one shader builder and the one program cache: every view that makes a three.js program goes through
// buildShader, keeps it in createProgramCache, and so builds one program per key however often it is drawn.
import { readFileSync, readdirSync } from 'node:fs';
import { join } from 'node:path';
import * as THREE from 'three';
import { describe, expect, it } from 'vitest';
import { assembleGlsl } from '../../src/core/gpu/glsl.js';
import { buildShader, fragmentSource, shadersBuilt } from '../../src/core/gpu/shader-builder.js';
import { SHADER_CHUNKS } from '../../src/core/gpu/shader-chunks.js';
import { createCustomPrograms } from '../../src/lab/custom-programs.js';
import { createZonesScene } from '../../src/widgets/fresnel-zones/scene-view.js';
import { defaultState } from '../../src/core/framework/state.js';
import { schema as zonesSchema } from '../../src/widgets/fresnel-zones/schema.js';

const built = (fragment) => shadersBuilt()[fragment] ?? 0;

/** Every .js file under `dir`. */
const sources = (dir) =>
  readdirSync(dir, { withFileTypes: true }).flatMap((e) =>
    e.isDirectory() ? sources(join(dir, e.name)) : e.name.endsWith('.js') ? [join(dir, e.name)] : [],
  );

describe('the shader builder', () => {
  it('builds a GLSL3 material over the named vertex program, its fragment assembled by glsl.js', () => {
    const m = buildShader('fresnel-zones.frag.glsl', { vertex: 'surface.vert.glsl', defines: { ZONE_BY_LH: 1 } });
    expect(m).toBeInstanceOf(THREE.ShaderMaterial);
    expect(m.glslVersion).toBe(THREE.GLSL3);
    expect(m.vertexShader).toBe(SHADER_CHUNKS['surface.vert.glsl']);
    expect(m.fragmentShader).toBe(
      assembleGlsl(SHADER_CHUNKS['fresnel-zones.frag.glsl'], { defines: { ZONE_BY_LH: 1 } }),
    );
    expect(buildShader('sum4x4.frag.glsl').vertexShader).toBe(SHADER_CHUNKS['fullscreen.vert.glsl']);
    expect(() => fragmentSource('no-such.frag.glsl')).toThrow(/no program "no-such.frag.glsl"/);
  });

  it('writes a switch one way: 1 (`#define NAME 1`); true, false and empty values are refused', () => {
    const text = fragmentSource('fresnel-zones.frag.glsl', { defines: { ZONE_BY_LH: 1 } });
    expect(text.split('\n')[0]).toBe('#define ZONE_BY_LH 1');
    for (const bad of [true, false, '', null])
      expect(() => fragmentSource('fresnel-zones.frag.glsl', { defines: { ZONE_BY_LH: bad } })).toThrow(
        /a switch is 1/,
      );
  });

  it('is the only place in src that makes a three.js ShaderMaterial (the parity harness too)', () => {
    const makers = sources('src')
      .filter((file) => /new THREE\.(Raw)?ShaderMaterial\(/.test(readFileSync(file, 'utf8')))
      .map((file) => file.replaceAll('\\', '/'));
    expect(makers).toEqual(['src/core/gpu/shader-builder.js']);
  });
});

describe('one program per key, in every view (cache hits counted at the builder)', () => {
  it('fresnel-zones: drawing A, B, A, B builds two programs, and its stats pass one more', () => {
    let state = defaultState(zonesSchema);
    const view = createZonesScene(() => state);
    const renderer = { render() {}, setRenderTarget() {}, setClearColor() {}, clear() {} };
    const before = built('fresnel-zones.frag.glsl');
    for (const mode of ['zones-nv', 'fresnel-nv', 'zones-nv', 'fresnel-nv']) {
      state = { ...state, mode };
      view.render(renderer);
    }
    expect(built('fresnel-zones.frag.glsl') - before).toBe(2);
    view.renderStats(renderer, null);
    view.renderStats(renderer, null);
    expect(built('fresnel-zones.frag.glsl') - before).toBe(3);
    expect(view.programInfo().variants).toBe(3);
    view.dispose();
  });

  it('the lab with a user BRDF: one program per key while the code stands; new code lets the old go', () => {
    const programs = createCustomPrograms({});
    const code = 'vec3 customBRDF(vec3 l, vec3 v) { return vec3(uK / 3.14159265); }';
    const defines = { MEASURED: 1, LIGHT_PUNCTUAL: 1 };
    const before = built('lab-shade.frag.glsl');
    const first = programs.get(defines, { code, params: { uK: 0.5 } });
    expect(programs.get({ LIGHT_PUNCTUAL: 1, MEASURED: 1 }, { code, params: { uK: 0.9 } })).toBe(first);
    expect(first.uniforms.uK.value).toBe(0.9); // the slider is a uniform: a new value is no new program
    expect(built('lab-shade.frag.glsl') - before).toBe(1);
    let disposed = 0;
    first.addEventListener('dispose', () => disposed++);
    const edited = code.replace('3.14159265', '3.1416');
    expect(programs.has(defines, { code: edited, params: { uK: 0.9 } })).toBe(false);
    expect(programs.get(defines, { code: edited, params: { uK: 0.9 } })).not.toBe(first);
    expect([disposed, programs.size, built('lab-shade.frag.glsl') - before]).toEqual([1, 1, 2]);
    programs.dispose();
  });
});
