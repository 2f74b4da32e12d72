// Renders the material lab's sphere: once by the chosen approximations, once as a converging Monte Carlo
// reference (batches averaged in a float target), and their difference, summed on the GPU to an RMS error.
// A scene is { material, terms, lights, methods, maps } (see sceneDefines; maps: its environment-maps.js maps);
// `slots` approximations can be kept side by side. Images are res × res, linear radiance. The approximations read
// the DFG table and the prefiltered map of the chosen terms (lab-approximations.js says which): `dfg(terms)` gives
// the table's texture.
import * as THREE from 'three';
import { assembleGlsl } from '../core/gpu/glsl.js';
import { SHADER_CHUNKS } from '../core/gpu/shader-chunks.js';
import { createGpuSum, floatTarget } from '../core/gpu/gpu-sum.js';
import { createAlbedoTableTexture } from '../core/gpu/albedo-table-texture.js';
import { PREFILTER_LEVELS } from './environment-maps.js';
import { approximationInputs } from './lab-approximations.js';
import { termDefines } from '../math/catalogue/index.js';

export const EXTENT = 1.1; // the view's half width: the unit sphere fills 1/1.1 of it
export const REFERENCE_BATCH = 8; // samples per pixel and light in one reference batch

const DIFFUSE_DEFINES = {
  'fresnel-weighted': 'DIFFUSE_FRESNEL_WEIGHTED',
  'ashikhmin-shirley': 'DIFFUSE_ASHIKHMIN_SHIRLEY',
  'oren-nayar': 'DIFFUSE_OREN_NAYAR',
  'oren-nayar-qualitative': 'DIFFUSE_OREN_NAYAR_QUALITATIVE',
};
const COMPENSATION_DEFINES = { kullaConty: 'COMPENSATION_KULLA_CONTY', turquin: 'COMPENSATION_TURQUIN' };
const ENV_DEFINES = { mirror: 'ENV_MIRROR', importance: 'ENV_IMPORTANCE', 'split-sum': 'ENV_SPLIT_SUM' };

/**
 * The #defines of one program: only the terms, lights and methods in use are compiled. A measured table
 * (scene.measured: its name; scene.table: its 3-D texture) is the whole BRDF, no terms; of the approximations
 * only importance sampling and the sphere light's have a form for it (lab-approximations.js says so), so the
 * others leave the sphere unlit by their light.
 */
export function sceneDefines(scene, reference) {
  return scene.measured ? measuredDefines(scene, reference) : modelDefines(scene, reference);
}

function measuredDefines({ lights, methods }, reference) {
  // the table is the whole BRDF; the model's terms still compile (GGX's sampling, with the fit's uAlpha)
  const d = { MEASURED: 1, ...termDefines({ F: 'schlick', D: 'ggx', V: 'smithGGXCorrelated' }) };
  if (lights.punctual) d.LIGHT_PUNCTUAL = 1;
  if (lights.sphere) d.LIGHT_SPHERE = 1;
  if (reference) {
    return Object.assign(d, { REFERENCE: 1 }, lights.env && { LIGHT_ENV: 1 }, lights.ambient && { LIGHT_AMBIENT: 1 });
  }
  if (lights.env) d.LIGHT_ENV = 1; // the map behind the sphere
  if (lights.env && methods.env === 'importance') d.ENV_IMPORTANCE = 1;
  if (lights.sphere && methods.area === 'centre') d.AREA_CENTRE = 1;
  return d;
}

function modelDefines(scene, reference) {
  const d = {};
  const flag = (name) => name && (d[name] = 1);
  flag(DIFFUSE_DEFINES[scene.terms.diffuse]);
  Object.keys(termDefines({ F: scene.terms.F, D: scene.terms.D, V: scene.terms.V })).forEach(flag);
  if (scene.terms.compensation && scene.terms.compensation !== 'none') {
    flag(COMPENSATION_DEFINES[scene.terms.compensation]);
    flag('ALBEDO_TABLE_GGX');
  }
  if (scene.terms.layers === 'diffuse') flag('SPECULAR_OFF');
  if (scene.terms.layers === 'specular') flag('DIFFUSE_OFF');
  const { punctual, sphere, env, ambient } = scene.lights;
  if (punctual) flag('LIGHT_PUNCTUAL');
  if (sphere) flag('LIGHT_SPHERE');
  if (env) flag('LIGHT_ENV');
  if (ambient) flag('LIGHT_AMBIENT');
  if (reference) flag('REFERENCE');
  else {
    if (env) flag(ENV_DEFINES[scene.methods.env]);
    if (sphere && scene.methods.area === 'centre') flag('AREA_CENTRE');
  }
  return d;
}

export function createLabRenderer(renderer, { dfg, resolution, slots = 1 }) {
  const res = resolution;
  const approxTargets = Array.from(
    { length: slots },
    () =>
      new THREE.WebGLRenderTarget(res, res, {
        type: THREE.HalfFloatType,
        depthBuffer: false,
        magFilter: THREE.NearestFilter,
        minFilter: THREE.NearestFilter,
      }),
  );
  const ping = [floatTarget(res, res), floatTarget(res, res)];
  const errorTarget = floatTarget(res, res);
  const sum = createGpuSum(renderer);
  const quad = new THREE.Mesh(new THREE.PlaneGeometry(2, 2));
  quad.frustumCulled = false;
  const quadScene = new THREE.Scene().add(quad);
  const camera = new THREE.Camera();
  const programs = new Map();
  const uniforms = {
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
  const program = (defines) => {
    const key = JSON.stringify(defines);
    if (!programs.has(key)) {
      programs.set(
        key,
        new THREE.ShaderMaterial({
          glslVersion: THREE.GLSL3,
          uniforms,
          vertexShader: SHADER_CHUNKS['fullscreen.vert.glsl'],
          fragmentShader: assembleGlsl(SHADER_CHUNKS['lab-shade.frag.glsl'], { defines }),
          depthTest: false,
          depthWrite: false,
        }),
      );
    }
    return programs.get(key);
  };
  const errorPass = new THREE.ShaderMaterial({
    glslVersion: THREE.GLSL3,
    uniforms: { uImage: { value: null }, uOther: { value: null } },
    vertexShader: SHADER_CHUNKS['fullscreen.vert.glsl'],
    fragmentShader: assembleGlsl(SHADER_CHUNKS['lab-error.frag.glsl']),
    depthTest: false,
    depthWrite: false,
  });

  // three.js's own answer for the environment: MeshPhysicalMaterial with the PMREM, added onto the rest
  const pmremMaterial = new THREE.MeshPhysicalMaterial({
    metalness: 0,
    ior: 1.5,
    specularIntensity: 1,
    blending: THREE.AdditiveBlending,
    depthTest: false,
    depthWrite: false,
  });
  const pmremSphere = new THREE.Mesh(new THREE.SphereGeometry(1, 128, 64), pmremMaterial);
  const pmremScene = new THREE.Scene().add(pmremSphere);
  const orthoCamera = new THREE.OrthographicCamera(-EXTENT, EXTENT, EXTENT, -EXTENT, 0.1, 10);
  orthoCamera.position.z = 5;

  const setUniforms = (scene, reference) => {
    if (scene.terms.compensation !== 'none') uniforms.uAlbedoTableGGX.value ??= createAlbedoTableTexture();
    const { material, lights } = scene;
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
    uniforms.uEnvSampling.value = Boolean(lights.env) && m.sampling.usable;
    uniforms.uAmbient.value.set(...(lights.ambient ?? [0, 0, 0]));
  };
  const draw = (material, target) => {
    quad.material = material;
    renderer.setRenderTarget(target);
    renderer.render(quadScene, camera);
  };
  const pixel = new Float32Array(4);
  const halfPixel = new Uint16Array(4);
  const sync = (target) =>
    renderer.readRenderTargetPixels(
      target,
      0,
      0,
      1,
      1,
      target.texture.type === THREE.HalfFloatType ? halfPixel : pixel,
    );

  let batches = 0;
  let current = 0;

  return {
    resolution: res,
    approx: (slot = 0) => approxTargets[slot].texture,
    get reference() {
      return ping[current].texture;
    },
    get batches() {
      return batches;
    },
    /** Renders an approximation into `slot`; returns its GPU time in ms (the draw, waited for by a 1-texel read). */
    renderApprox(scene, slot = 0) {
      const approx = approxTargets[slot];
      setUniforms(scene, false);
      uniforms.uSamples.value = scene.methods.samples;
      const defines = sceneDefines(scene, false);
      const fresh = !programs.has(JSON.stringify(defines));
      if (fresh) draw(program(defines), approx); // compiles the program: not part of the cost of a frame
      sync(errorTarget); // finish earlier work so it is not counted
      const t0 = performance.now();
      draw(program(defines), approx);
      if (scene.lights.env && scene.methods.env === 'pmrem' && !scene.measured) {
        const { f0, diffuse, alpha } = scene.material;
        pmremMaterial.envMap = scene.maps.pmrem();
        pmremMaterial.envMapIntensity = scene.lights.env.intensity;
        const layers = scene.terms.layers;
        pmremMaterial.color.setRGB(...(layers === 'specular' ? [0, 0, 0] : diffuse), THREE.LinearSRGBColorSpace);
        pmremMaterial.specularColor.setRGB(...f0.map((x) => x / 0.04), THREE.LinearSRGBColorSpace); // F0 = 0.04 · specularColor at ior 1.5
        pmremMaterial.specularIntensity = layers === 'diffuse' ? 0 : 1;
        pmremMaterial.roughness = Math.sqrt(alpha);
        renderer.autoClear = false;
        renderer.render(pmremScene, orthoCamera);
        renderer.autoClear = true;
      }
      sync(approx);
      renderer.setRenderTarget(null);
      return performance.now() - t0;
    },
    resetReference() {
      batches = 0;
    },
    /** Adds one batch of REFERENCE_BATCH samples per pixel and light to the reference's running mean. */
    accumulate(scene) {
      setUniforms(scene, true);
      uniforms.uSamples.value = REFERENCE_BATCH;
      uniforms.uJitter.value.set(Math.random(), Math.random());
      uniforms.uPrevious.value = ping[current].texture;
      uniforms.uWeight.value = 1 / (batches + 1);
      draw(program(sceneDefines(scene, true)), ping[1 - current]);
      renderer.setRenderTarget(null);
      current = 1 - current;
      batches++;
    },
    /** RMS error of the approximation against the reference over the sphere, absolute and relative. */
    error(slot = 0) {
      errorPass.uniforms.uImage.value = approxTargets[slot].texture;
      errorPass.uniforms.uOther.value = ping[current].texture;
      draw(errorPass, errorTarget);
      const [sq, ref, count] = sum.sum(errorTarget);
      renderer.setRenderTarget(null);
      return { rms: Math.sqrt(sq / Math.max(count, 1)), relative: ref > 0 ? Math.sqrt(sq / ref) : 0, pixels: count };
    },
    /** Reads an image back (tests): 'approx' (of `slot`) or 'reference', RGBA float per pixel. */
    read(which, slot = 0) {
      const out = new Float32Array(res * res * 4);
      const target = which === 'approx' ? approxTargets[slot] : ping[current];
      if (which === 'approx') {
        const half = new Uint16Array(res * res * 4);
        renderer.readRenderTargetPixels(target, 0, 0, res, res, half);
        half.forEach((h, i) => (out[i] = THREE.DataUtils.fromHalfFloat(h)));
      } else renderer.readRenderTargetPixels(target, 0, 0, res, res, out);
      return out;
    },
    get variants() {
      return programs.size;
    },
    dispose() {
      [...approxTargets, ...ping, errorTarget, errorPass, pmremMaterial, pmremSphere.geometry, quad.geometry].forEach(
        (x) => x.dispose(),
      );
      programs.forEach((p) => p.dispose());
      uniforms.uAlbedoTableGGX.value?.dispose();
      sum.dispose();
    },
  };
}
