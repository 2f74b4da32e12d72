// Every program the material lab can make assembles (no #error of a term chain, no define that no chunk reads),
// and every uniform it declares is one the lab renderer feeds (createLabUniforms).
import { describe, expect, it } from 'vitest';
import { assembleGlsl } from '../../src/core/gpu/glsl.js';
import { SHADER_CHUNKS } from '../../src/core/gpu/shader-chunks.js';
import { sceneDefines } from '../../src/lab/lab-defines.js';
import { createLabUniforms } from '../../src/lab/lab-uniforms.js';
import { CATALOGUE } from '../../src/math/catalogue/index.js';
import { LAB_TERMS } from '../../src/lab/lab-approximations.js';
import { anisotropyOf, ownSlots } from '../../src/lab/lab-anisotropy.js';
import { customTermChunks } from '../../src/lab/custom-programs.js';
import { SLOTS } from '../../src/core/custom/slots.js';

const LIGHTS = ['punctual', 'sphere', 'env', 'ambient'];
const subsets = (keys) => Array.from({ length: 2 ** keys.length }, (_, m) => keys.filter((_, i) => m & (1 << i)));
const lightsOf = (on) => Object.fromEntries(LIGHTS.map((k) => [k, on.includes(k) ? {} : null]));

/** Every scene of the lab's menus: each term once against the defaults, each light set with each method. */
function* scenes() {
  const terms = { F: 'schlick', D: 'ggx', V: 'smithGGXCorrelated', diffuse: 'lambert', layers: 'both' };
  const slots = { F: 'fresnel', D: 'ndf', V: 'visibility', diffuse: 'diffuse' };
  const termSets = [{ ...terms, compensation: 'none' }];
  for (const [slot, family] of Object.entries(slots)) {
    for (const key of Object.keys(LAB_TERMS[family])) termSets.push({ ...terms, [slot]: key, compensation: 'none' });
  }
  for (const compensation of ['kullaConty', 'turquin']) termSets.push({ ...terms, compensation });
  for (const layers of ['specular', 'diffuse']) termSets.push({ ...terms, layers, compensation: 'none' });
  for (const on of subsets(LIGHTS)) {
    for (const env of ['split-sum', 'importance', 'mirror', 'pmrem']) {
      for (const area of ['representative', 'centre']) {
        const methods = { env, area, samples: 4 };
        for (const t of termSets) yield { terms: t, lights: lightsOf(on), methods };
        // the anisotropic lobe (lab-anisotropy.js) of each D with each visibility term, with the user's D and V, and
        // along an axis (the tangent field is a switch of its own)
        const stretched = [
          ...Object.keys(LAB_TERMS.ndf).flatMap((D) => Object.keys(LAB_TERMS.visibility).map((V) => ({ D, V }))),
          { anisoD: 'custom' },
          { anisoV: 'custom' },
          { anisoD: 'custom', anisoV: 'custom' },
          { tangentField: 'along' },
        ];
        for (const choice of stretched) {
          const t = { ...termSets[0], ...choice };
          yield { terms: t, lights: lightsOf(on), methods, anisotropy: anisotropic(t) };
        }
        yield { terms: termSets[0], lights: lightsOf(on), methods, measured: 'a MERL table' };
      }
    }
  }
}

const anisotropic = (state) => anisotropyOf({ alpha: 0.25, anisotropy: 0.5, ...state });
/** The chunks of a program: with the user's anisotropic D and V (their starters) where it reads them. */
const chunksOf = (scene) =>
  customTermChunks(Object.fromEntries(ownSlots(scene.anisotropy).map((slot) => [slot, SLOTS[slot].starter])));

const UNIFORM = /^\s*uniform\s+(?:highp\s+|mediump\s+|lowp\s+)?\w+\s+(\w+)/gm;

describe('material lab programs', () => {
  it('the lab offers only terms of the catalogue', () => {
    for (const family of ['fresnel', 'ndf', 'visibility', 'diffuse']) {
      for (const key of Object.keys(LAB_TERMS[family])) expect(CATALOGUE[family].terms[key]?.key).toBe(key);
    }
  });
  it('every variant assembles and declares only uniforms that createLabUniforms feeds', () => {
    const fed = new Set(Object.keys(createLabUniforms(8)));
    const seen = new Map();
    for (const scene of scenes()) {
      for (const reference of [false, true]) {
        const defines = sceneDefines(scene, reference);
        const key = JSON.stringify(Object.entries(defines).sort()); // a value too: the stretched D's call
        if (seen.has(key)) continue;
        let text;
        try {
          text = assembleGlsl(SHADER_CHUNKS['lab-shade.frag.glsl'], { defines, chunks: chunksOf(scene) });
        } catch (e) {
          throw new Error(`${key}: ${e.message}`, { cause: e });
        }
        const declared = [...text.matchAll(UNIFORM)].map((m) => m[1]);
        expect(
          declared.filter((u) => !fed.has(u)),
          key,
        ).toEqual([]);
        seen.set(key, declared);
      }
    }
    expect(seen.size).toBeGreaterThan(100);
    const stretched = [...seen.keys()].filter((key) => key.includes('"ANISOTROPIC"'));
    expect(stretched.some((key) => key.includes('TANGENT_ALONG'))).toBe(true);
    expect(stretched.some((key) => key.includes('REFERENCE'))).toBe(true);
    expect(stretched.some((key) => key.includes('CUSTOM_DANISO') && key.includes('CUSTOM_VANISO'))).toBe(true);
  }, 60_000);
});
