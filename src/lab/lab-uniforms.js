// The uniforms of the material lab's program (lab-shade.frag.glsl and its chunks), one set shared by every variant,
// and how a scene fills them. The material's parameters (α and the pair (αx, αy), the anisotropy, F0, c_diff, σ)
// and the chosen terms' own (Blinn–Phong's exponent, …) go by the catalogue's binding of each uniform to its
// parameter (src/math/catalogue/uniforms.js), not by names written here.
import * as THREE from 'three';
import { createAlbedoTableTexture } from '../core/gpu/albedo-table-texture.js';
import { sharedUniforms, termUniformDefaults, termUniforms } from '../math/catalogue/uniforms.js';
import { PREFILTER_LEVELS } from './environment-maps.js';
import { approximationInputs } from './lab-approximations.js';
import { OPENPBR_DEFAULTS } from '../math/openpbr.js';
import { openPbrAlbedoTable } from '../math/openpbr-albedo.js';

export const EXTENT = 1.1; // the view's half width: the unit sphere fills 1/1.1 of it

/** Every uniform the lab's programs read, at rest: images `res` × `res`. */
export function createLabUniforms(res) {
  return {
    uSize: { value: new THREE.Vector2(res, res) },
    uExtent: { value: EXTENT },
    ...asUniforms(sharedUniforms(materialParams(REST))),
    ...asUniforms(termUniformDefaults({ alpha: REST.alpha })),
    uTangentAxis: { value: [0, 0, 1] },
    uTangentRotation: { value: 0 },
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
    uOpenPbr: { value: openPbrStruct(OPENPBR_DEFAULTS) }, // lab-openpbr.glsl's material, by the struct's names
    uOpenPbrAlbedo: { value: null }, // its albedo table, made when OpenPBR is first chosen
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
  if (scene.openpbr) {
    uniforms.uOpenPbrAlbedo.value ??= openPbrAlbedoTexture();
    uniforms.uOpenPbr.value = openPbrStruct(scene.openpbr);
  }
  setMaps(uniforms, scene, { reference, dfg });
  const { material, lights } = scene;
  const params = materialParams({ ...material, anisotropy: scene.anisotropy });
  const { F, D, V, diffuse } = scene.terms;
  setValues(uniforms, { ...sharedUniforms(params), ...termUniforms({ F, D, V, diffuse }, params) });
  const field = scene.anisotropy?.field ?? scene.tangentField;
  if (field) setValues(uniforms, { uTangentAxis: field.axis, uTangentRotation: field.rotation });
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

/** An OpenPBR material (every key of OPENPBR_DEFAULTS, colours [r, g, b]) as the struct uniform's value. */
const openPbrStruct = (m) =>
  Object.fromEntries(Object.keys(OPENPBR_DEFAULTS).map((k) => [k, Array.isArray(m[k]) ? [...m[k]] : m[k]]));

/** The OpenPBR albedo table (64 × 128 RGBA float, read by texelFetch in openpbr-albedo.glsl). */
function openPbrAlbedoTexture() {
  const { width, height, data } = openPbrAlbedoTable();
  const texture = new THREE.DataTexture(data, width, height, THREE.RGBAFormat, THREE.FloatType);
  texture.needsUpdate = true;
  return texture;
}

/** A material at rest, for the uniforms' first values. */
const REST = { f0: [0, 0, 0], diffuse: [0, 0, 0], alpha: 0.3, sigma: 0, anisotropy: null };

/**
 * A lab material's values by parameter name (parameters.js): α, the pair (αx, αy) (equal to α when the lobe is
 * isotropic), the anisotropy a, F0, c_diff and σ. A term's own parameters (Blinn–Phong's exponent, …) are not the
 * material's: termUniforms gives them their entries' defaults.
 * @param {{ f0: number[], diffuse: number[], alpha: number, sigma: number,
 *   anisotropy?: import('./lab-anisotropy.js').LabAnisotropy | null }} material
 */
function materialParams({ f0, diffuse, alpha, sigma, anisotropy }) {
  const [alphaX, alphaY] = anisotropy?.alpha ?? [alpha, alpha];
  return { alpha, alphaPair: [alphaX, alphaY], anisotropy: anisotropy?.strength ?? 0, f0, cdiff: diffuse, sigma };
}

/** `{ name: value }` as three.js uniforms (arrays copied: a uniform's value is its own). */
const asUniforms = (values) =>
  Object.fromEntries(Object.entries(values).map(([name, v]) => [name, { value: Array.isArray(v) ? [...v] : v }]));

/** Sets the values of the uniforms named, each one the lab declares. */
function setValues(uniforms, values) {
  for (const [name, v] of Object.entries(values)) uniforms[name].value = Array.isArray(v) ? [...v] : v;
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
