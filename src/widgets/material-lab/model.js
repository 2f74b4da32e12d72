// The material lab's model, pure: from the widget's state to the lab renderer's scene (lab-scene.js), and the keys
// that say when the approximation must be rendered again and when the reference must start over.
import { lightDirFromAngles } from '../../math/angles.js';
import { labScene, sphereLight } from '../../lab/lab-scene.js';

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

/** A lab scene with a measured table for its BRDF: no terms; the GGX fit's α (the state's until it is in) to
 * sample by. */
function measuredScene(scene, table) {
  const alpha = table.fit?.params.alpha ?? scene.material.alpha;
  return {
    ...scene,
    material: { ...scene.material, alpha: Math.max(alpha, 0.01) },
    terms: { ...scene.terms, D: 'ggx', compensation: 'none' },
    measured: table.name,
  };
}

/**
 * The scene of `state` (`table`: the measured table in use, or null; `envKey`: which map is lit by, a new one for
 * every file taken) and its keys: `approx` changes when the approximation must be rendered again, `reference` when
 * the reference must start over.
 */
export function sceneOf(state, table, envKey) {
  const lights = lightsOf(state);
  const scene = table ? measuredScene(labScene(state, lights), table) : labScene(state, lights);
  return {
    scene,
    lights,
    keys: {
      approx: JSON.stringify([scene, envKey, table?.key]),
      reference: JSON.stringify([scene.material, scene.terms, scene.lights, envKey, table?.key]),
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
