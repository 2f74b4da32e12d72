// The material lab's model, pure: from the widget's state to the lab renderer's scene (lab-scene.js), and the keys
// that say when the approximation must be rendered again and when the reference must start over.
import { lightDirFromAngles } from '../../math/angles.js';
import { labScene, sphereLight } from '../../lab/lab-scene.js';
import { tangentFieldOf } from '../../lab/lab-anisotropy.js';

/** The lights that are on, in view space (lab-scene.js), from the state. */
export function lightsOf(state) {
  const c = (x) => [x, x, x];
  return {
    punctual: state.punctual
      ? { dir: lightDirFromAngles(state.lightTheta, state.lightPhi), cLight: c(state.cLight) }
      : null,
    sphere: state.area ? sphereLight(state.areaTheta, state.areaPhi, state.areaRadius, state.areaCLight) : null,
    env: state.env ? { intensity: state.envIntensity, map: state.environment } : null,
    ambient: state.ambient ? c(state.ambientLevel) : null,
  };
}

/**
 * A lab scene whose BRDF is whole (`whole`: { measured: a table's name } or { custom: { code, params } }, the
 * user's): no terms; a GGX lobe of α (at least 0.01) to sample by.
 */
const wholeBrdfScene = (scene, alpha, whole) => ({
  ...scene,
  material: { ...scene.material, alpha: Math.max(alpha, 0.01) },
  terms: { ...scene.terms, D: 'ggx', compensation: 'none' },
  ...whole,
});

/** The α an OpenPBR material is sampled by: its sharpest lobe's, the base's or, where coated, the coat's. */
const openPbrAlpha = (m) => Math.min(m.specular_roughness ** 2, m.coat_weight > 0 ? m.coat_roughness ** 2 : 1);

/** The scene of `state` with its BRDF: the model, a measured table (sampled by its GGX fit's α, the state's until
 * it is in), the user's (`custom`, sampled at the state's α) or OpenPBR Surface (`openpbr`, its material). */
function sceneWithBrdf(state, lights, { table, custom, openpbr, ownTerms }) {
  const scene = labScene(state, lights);
  if (table) return wholeBrdfScene(scene, table.fit?.params.alpha ?? scene.material.alpha, { measured: table.name });
  if (custom) return wholeBrdfScene(scene, scene.material.alpha, { custom });
  // OpenPBR's specular_anisotropy lies along the lab's tangent field, as the model's anisotropic GGX does
  if (openpbr) {
    return wholeBrdfScene(scene, openPbrAlpha(openpbr), {
      openpbr,
      anisotropy: null,
      tangentField: tangentFieldOf(state),
    });
  }
  return ownTerms ? { ...scene, ownTerms } : scene; // the user's anisotropic D, V (custom-aniso.js)
}

/**
 * The scene of `state` (`table`: the measured table in use, or null; `envKey`: which map is lit by, a new one for
 * every file taken; `custom`: the user's BRDF { code, params } when the state asks for it, or null; `openpbr`: the
 * OpenPBR material when the state asks for it, or null; `ownTerms`: the user's anisotropic D and V, { code, params },
 * or null) and its keys: `approx` changes when the approximation must
 * be rendered again, `reference` when the reference must start over.
 */
export function sceneOf(state, table, envKey, custom = null, openpbr = null, ownTerms = null) {
  const lights = lightsOf(state);
  const scene = sceneWithBrdf(state, lights, { table, custom, openpbr, ownTerms });
  return {
    scene,
    lights,
    keys: {
      approx: JSON.stringify([scene, envKey, table?.key]),
      reference: JSON.stringify([
        scene.material,
        scene.terms,
        scene.lights,
        envKey,
        table?.key,
        scene.custom,
        scene.openpbr,
        scene.anisotropy,
        scene.ownTerms,
      ]),
    },
  };
}

/**
 * A change of `state` (the keys `changed`) that asks for a file not dropped yet (`has`: { measured, file }): the
 * notice to show (a key of words.js's NOTICES) and the state to keep `instead`; or null.
 */
export function missingFile(changed, state, has) {
  if (changed.includes('brdfSource') && state.brdfSource === 'measured' && !has.measured) {
    return { notice: 'noMeasured', instead: { brdfSource: 'model' } };
  }
  if (changed.includes('environment') && state.environment === 'file' && !has.file) {
    return { notice: 'noFile', instead: { environment: 'studio' } };
  }
  return null;
}

/** One click to the talk's check of the π: a white Lambert sphere under the punctual light alone, head-on. */
export const WHITE_LAMBERT_HEAD_ON = {
  material: 'manual',
  cdiff: '#ffffff',
  layers: 'diffuse',
  diffuse: 'lambert',
  brdfSource: 'model',
  punctual: true,
  lightTheta: 0,
  cLight: 1,
  area: false,
  env: false,
  ambient: false,
};

/**
 * A starting point for anisotropy: aluminium (the talk's F0 table) brushed in circles around a pole tilted 50°
 * up, as a turned disc is, Burley's mapping at a = 0.8 (αx = 0.472, αy = 0.132 from α = 0.25), the lines drawn.
 */
export const BRUSHED_ALUMINIUM = {
  material: 'aluminum',
  alpha: 0.25,
  layers: 'both',
  D: 'ggx',
  V: 'smithGGXCorrelated',
  compensation: 'none',
  brdfSource: 'model',
  anisotropy: 0.8,
  anisotropyModel: 'burley2012',
  tangentField: 'around',
  tangentTheta: 50,
  tangentPhi: 90,
  tangentRotation: 0,
  showTangents: true,
};

/** Whether the punctual light is the only light on (then the centre's radiance is π f c_light (n·l) alone). */
export const punctualAlone = (lights) => Boolean(lights.punctual && !lights.sphere && !lights.env && !lights.ambient);
