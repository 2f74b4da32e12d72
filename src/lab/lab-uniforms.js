// The uniforms of the material lab's program (lab-shade.frag.glsl and its chunks), one set shared by every variant,
// and how a scene fills them.
import * as THREE from 'three';
import { createAlbedoTableTexture } from '../core/gpu/albedo-table-texture.js';
import { PREFILTER_LEVELS } from './environment-maps.js';
import { approximationInputs } from './lab-approximations.js';

export const EXTENT = 1.1; // the view's half width: the unit sphere fills 1/1.1 of it

/** Every uniform the lab's programs read, at rest: images `res` × `res`. */
export function createLabUniforms(res) {
  return {
    uSize: { value: new THREE.Vector2(res, res) },
    uExtent: { value: EXTENT },
    uF0: { value: new THREE.Vector3() },
    uDiffuseColor: { value: new THREE.Vector3() },
    uAlpha: { value: 0.3 },
    uSigma: { value: 0 },
    uExponent: { value: 40 },
    uA1: { value: 20 },
    uA2: { value: 2.5 },
    uSgdP: { value: 0.64 },
    uPunctualDir: { value: new THREE.Vector3(0, 0, 1) },
    uPunctualCLight: { value: new THREE.Vector3() },
    uSphereDir: { value: new THREE.Vector3(0, 0, 1) },
    uSphereSin: { value: 0.1 },
    uSphereRadiance: { value: new THREE.Vector3() },
    uEnv: { value: null },
    uEnvIntensity: { value: 1 },
    uAmbient: { value: new THREE.Vector3() },
    uPrefiltered: { value: null },
    uPrefilterLevels: { value: PREFILTER_LEVELS },
    uIrradiance: { value: null },
    uDfg: { value: null },
    uAlbedoTableGGX: { value: null }, // the albedo-loss table, made when a compensation is first chosen
    uMeasured: { value: null }, // a measured table's 3-D texture (scene.table), owned by the widget
    uEnvMarginal: { value: null },
    uEnvConditional: { value: null },
    uEnvPdf: { value: null },
    uEnvSampling: { value: false },
    uSamples: { value: 16 },
    uJitter: { value: new THREE.Vector2() },
    uPrevious: { value: null },
    uWeight: { value: 1 },
  };
}

/**
 * Fills `uniforms` from `scene` (lab-scene.js; scene.maps: its environment-maps.js maps, scene.table: a measured
 * table's texture). The approximations (not the `reference`) also read the DFG table `dfg(terms)` and the
 * prefiltered map of the chosen terms (lab-approximations.js says which).
 */
export function setSceneUniforms(uniforms, scene, { reference, dfg }) {
  if (scene.terms.compensation !== 'none') uniforms.uAlbedoTableGGX.value ??= createAlbedoTableTexture();
  setMaps(uniforms, scene, { reference, dfg });
  const { material, lights } = scene;
  uniforms.uF0.value.set(...material.f0);
  uniforms.uDiffuseColor.value.set(...material.diffuse);
  uniforms.uAlpha.value = material.alpha;
  uniforms.uSigma.value = material.sigma;
  uniforms.uExponent.value = material.exponent ?? 40;
  if (lights.punctual) {
    uniforms.uPunctualDir.value.set(...lights.punctual.dir);
    uniforms.uPunctualCLight.value.set(...lights.punctual.cLight);
  }
  if (lights.sphere) {
    uniforms.uSphereDir.value.set(...lights.sphere.dir);
    uniforms.uSphereSin.value = lights.sphere.sin;
    uniforms.uSphereRadiance.value.set(...lights.sphere.radiance);
  }
  uniforms.uEnvIntensity.value = lights.env?.intensity ?? 0;
  uniforms.uEnvSampling.value = Boolean(lights.env) && scene.maps.sampling.usable;
  uniforms.uAmbient.value.set(...(lights.ambient ?? [0, 0, 0]));
}

function setMaps(uniforms, scene, { reference, dfg }) {
  const m = scene.maps;
  uniforms.uEnv.value = m.env;
  uniforms.uMeasured.value = scene.table ?? null;
  if (!reference) {
    const inputs = approximationInputs(scene);
    if (inputs.dfg) uniforms.uDfg.value = dfg(inputs.dfg);
    if (inputs.prefilter) uniforms.uPrefiltered.value = m.prefiltered(inputs.prefilter);
  }
  uniforms.uIrradiance.value = m.irradiance;
  uniforms.uEnvMarginal.value = m.sampling.marginal;
  uniforms.uEnvConditional.value = m.sampling.conditional;
  uniforms.uEnvPdf.value = m.sampling.pdf;
}
