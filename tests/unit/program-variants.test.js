// Every variant of every program assembles: each set of #defines its hosts can produce is read by the program and
// picks a term in every chain, and, where the host's uniform names are known, every uniform the assembled source
// declares is one the host feeds (a shared chunk declaring a uniform its host does not feed shows up here).
import { describe, expect, it } from 'vitest';
import { assembleGlsl } from '../../src/core/gpu/glsl.js';
import { SHADER_CHUNKS } from '../../src/core/gpu/shader-chunks.js';
import { PARITY_CASES } from '../../src/core/gpu/parity-cases.js';
import { SPHERE_UNIFORMS, sphereFragment } from '../../src/core/ui/sphere-grid.js';
import { CATALOGUE, termDefines } from '../../src/math/catalogue/index.js';
import { sceneDefines } from '../../src/lab/lab-defines.js';
import { LAB_TERMS } from '../../src/lab/lab-approximations.js';

const keys = (family) => Object.keys(CATALOGUE[family].terms);
const product = (...lists) => lists.reduce((acc, list) => acc.flatMap((a) => list.map((x) => [...a, x])), [[]]);
const declaredUniforms = (source) => [...source.matchAll(/^\s*uniform\s+\w+\s+(\w+)\s*;/gm)].map((m) => m[1]);

/** brdf-sphere's variants: the sphere grid's cells (every specular choice, every diffuse term alone or added) and
 * the white furnace of the energy widget. */
function sphereVariants() {
  const specular = product(
    keys('fresnel').filter((F) => CATALOGUE.fresnel.terms[F].define),
    keys('ndf'),
    keys('visibility'),
  ).map(([F, D, V]) => termDefines({ F, D, V }));
  const diffuse = keys('diffuse').map((d) => termDefines({ diffuse: d }));
  return [
    ...specular,
    ...diffuse.map((d) => ({ SPECULAR_OFF: 1, ...d })),
    ...diffuse.map((d) => ({ ...termDefines({ F: 'schlick', D: 'ggx', V: 'smithGGXCorrelated' }), ...d })),
    { FURNACE: 1 },
    { FURNACE: 1, COMPENSATION_KULLA_CONTY: 1, ALBEDO_TABLE_GGX: 1 },
    { FURNACE: 1, COMPENSATION_TURQUIN: 1, ALBEDO_TABLE_GGX: 1 },
  ];
}

const COMPENSATIONS = ['none', 'kullaConty', 'turquin'];
const LAYERS = ['both', 'specular', 'diffuse'];

/** The material lab's scenes: every choice of terms under every light, and every light and method alone. */
function labScenes() {
  const lights = (on) => Object.fromEntries(['punctual', 'sphere', 'env', 'ambient'].map((k) => [k, on.includes(k)]));
  const all = lights(['punctual', 'sphere', 'env', 'ambient']);
  const methods = { env: 'split-sum', area: 'representative' };
  // every F, D, V and diffuse term together; the compensations and layers in turn (they switch code of their own)
  const terms = product(
    Object.keys(LAB_TERMS.fresnel),
    Object.keys(LAB_TERMS.ndf),
    Object.keys(LAB_TERMS.visibility),
    Object.keys(LAB_TERMS.diffuse),
  ).map(([F, D, V, diffuse], i) => ({
    terms: { F, D, V, diffuse, compensation: COMPENSATIONS[i % 3], layers: LAYERS[Math.floor(i / 3) % 3] },
    lights: all,
    methods,
  }));
  const base = terms[0].terms;
  const lighting = product(
    product([[]], ...['punctual', 'sphere', 'env', 'ambient'].map((k) => [[], [k]])).map((sets) => sets.flat()),
    ['split-sum', 'importance', 'mirror', 'pmrem'],
    ['representative', 'centre'],
  ).map(([on, env, area]) => ({ terms: base, lights: lights(on), methods: { env, area } }));
  const measured = lighting.map((scene) => ({ ...scene, measured: 'a table' }));
  return [...terms, ...lighting, ...measured];
}

describe('every variant of every program assembles, and declares only the uniforms its host feeds', () => {
  it('brdf-sphere.frag.glsl: every sphere-grid and furnace variant; uniforms ⊆ the sphere grid’s', () => {
    const variants = sphereVariants();
    // 2 F × 7 D (5 isotropic, 2 anisotropic) × 9 V (8 and 1), the diffuse terms alone and added, the furnaces
    expect(variants.length).toBe(2 * 7 * 9 + 5 + 5 + 3);
    for (const defines of variants) {
      const source = sphereFragment(defines); // as the grid assembles it: the impostor's
      for (const u of declaredUniforms(source)) expect(SPHERE_UNIFORMS, JSON.stringify(defines)).toContain(u);
    }
  });
  it('parity.frag.glsl: every parity row; uniforms ⊆ uArgs, the row’s tables and its uniforms', () => {
    for (const c of PARITY_CASES) {
      const wrap = `vec4(${c.glsl}${', 0.0'.repeat(4 - c.outputs)})`;
      const source = assembleGlsl(`#include "${c.chunk}"\n${SHADER_CHUNKS['parity.frag.glsl']}`, {
        defines: { ...c.defines, CALL: wrap },
      });
      const fed = ['uArgs', ...Object.keys(c.tables ?? {}), ...Object.keys(c.uniforms ?? {})];
      for (const u of declaredUniforms(source)) expect(fed, c.name).toContain(u);
    }
  });
  it('lab-shade.frag.glsl: every scene the lab’s terms, lights and methods make, approximation and reference', () => {
    const scenes = labScenes();
    expect(scenes.length).toBe(2 * 2 * 6 * 5 + 2 * 16 * 4 * 2);
    for (const scene of scenes)
      for (const reference of [false, true])
        expect(
          () => assembleGlsl(SHADER_CHUNKS['lab-shade.frag.glsl'], { defines: sceneDefines(scene, reference) }),
          JSON.stringify(scene),
        ).not.toThrow();
  }, 60_000);
  it('every shader program in shaders/ is one of the programs checked here or named as checked by its host', () => {
    const programs = Object.keys(SHADER_CHUNKS).filter((name) => name.endsWith('.frag.glsl'));
    const here = ['brdf-sphere.frag.glsl', 'parity.frag.glsl', 'lab-shade.frag.glsl'];
    // programs whose hosts pass no term defines: they assemble with the defines their hosts give (none or sizes)
    const plain = {
      'env-copy.frag.glsl': [{}],
      'env-prefilter.frag.glsl': [termDefines({ D: 'ggx' }), termDefines({ D: 'beckmann' })],
      'fresnel-zones.frag.glsl': [
        {},
        { ZONE_BY_LH: 1, WEIGHTED: 1, ...termDefines({ D: 'ggx', V: 'smithGGXCorrelated' }) },
      ],
      'lab-error.frag.glsl': [{}],
      'lab-view.frag.glsl': [{}],
      'measured-sphere.frag.glsl': [{}],
      'media-display.frag.glsl': [{}],
      'media-tracer.frag.glsl': [{ CELLS: 4, CELLS_X: 2, CELLS_Y: 2 }],
      'sum4x4.frag.glsl': [{}],
    };
    expect([...here, ...Object.keys(plain)].sort()).toEqual(programs.sort());
    for (const [name, variants] of Object.entries(plain))
      for (const defines of variants) expect(() => assembleGlsl(SHADER_CHUNKS[name], { defines }), name).not.toThrow();
  });
});
