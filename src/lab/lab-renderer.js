// Renders the material lab's sphere: once by the chosen approximations, once as a converging Monte Carlo
// reference (batches averaged in a float target), and their difference, summed on the GPU to an RMS error.
// A scene is { material, terms, lights, methods, maps } (see lab-defines.js; maps: its environment-maps.js maps;
// custom: { code, params } when the BRDF is the user's whole BRDF, custom-programs.js; ownTerms: { code: { DAniso?,
// VAniso? }, params } when its stretched lobe reads the user's anisotropic D or V);
// `slots` approximations can be kept side by side. Images are res × res, linear radiance. The approximations read
// the DFG table and the prefiltered map of the chosen terms (lab-approximations.js says which): `dfg(terms)` gives
// the table's texture.
import * as THREE from 'three';
import { createFullscreenPass } from '../core/gpu/fullscreen-pass.js';
import { createGpuSum, floatTarget } from '../core/gpu/gpu-sum.js';
import { createProgramCache } from '../core/gpu/program-cache.js';
import { fullscreenMaterial } from './fullscreen-material.js';
import { sceneDefines } from './lab-defines.js';
import { createLabUniforms, setSceneUniforms } from './lab-uniforms.js';
import { createPmremOverlay } from './pmrem-overlay.js';
import { createCustomPrograms, customTermChunks } from './custom-programs.js';

export const REFERENCE_BATCH = 8; // samples per pixel and light in one reference batch

const halfTarget = (res) =>
  new THREE.WebGLRenderTarget(res, res, {
    type: THREE.HalfFloatType,
    depthBuffer: false,
    magFilter: THREE.NearestFilter,
    minFilter: THREE.NearestFilter,
  });

/** three.js's PMREM stands in for the lab's program under the environment (not for a measured table). */
const byPmrem = (scene) =>
  scene.lights.env && scene.methods.env === 'pmrem' && !scene.measured && !scene.custom && !scene.openpbr;

export function createLabRenderer(renderer, { dfg, resolution, slots = 1 }) {
  const res = resolution;
  const approxTargets = Array.from({ length: slots }, () => halfTarget(res));
  const uniforms = createLabUniforms(res);
  const modelPrograms = createProgramCache((defines) =>
    fullscreenMaterial('lab-shade.frag.glsl', { uniforms, defines }),
  );
  const customPrograms = createCustomPrograms(uniforms);
  const termPrograms = createCustomPrograms(uniforms, customTermChunks); // the user's anisotropic D and V
  /** The program of `scene` for `defines`: the model's, the one with the user's BRDF or with the user's terms. */
  const programs = {
    get: (scene, defines) => {
      if (scene.custom) return customPrograms.get(defines, scene.custom);
      return scene.ownTerms ? termPrograms.get(defines, scene.ownTerms) : modelPrograms.get(defines);
    },
    has: (scene, defines) => {
      if (scene.custom) return customPrograms.has(defines, scene.custom);
      return scene.ownTerms ? termPrograms.has(defines, scene.ownTerms) : modelPrograms.has(defines);
    },
  };
  const pass = createFullscreenPass();
  const pmrem = createPmremOverlay();
  const reference = createReference(renderer, { res, uniforms, pass });
  const errors = createErrorSum(renderer, { res, pass });
  const sync = createSync(renderer);

  return {
    resolution: res,
    approx: (slot = 0) => approxTargets[slot].texture,
    get reference() {
      return reference.texture;
    },
    get batches() {
      return reference.batches;
    },
    /** Renders an approximation into `slot`; returns its GPU time in ms (the draw, waited for by a 1-texel read). */
    renderApprox(scene, slot = 0) {
      const target = approxTargets[slot];
      setSceneUniforms(uniforms, scene, { reference: false, dfg });
      uniforms.uSamples.value = scene.methods.samples;
      const defines = sceneDefines(scene, false);
      const fresh = !programs.has(scene, defines);
      const program = programs.get(scene, defines);
      if (fresh) compileInto(renderer, pass, program, target); // the compile is not the cost
      sync(errors.target); // finish earlier work so it is not counted
      const t0 = performance.now();
      pass.render(renderer, program, target);
      if (byPmrem(scene)) pmrem.render(renderer, scene, target);
      sync(target);
      return performance.now() - t0;
    },
    resetReference: () => reference.reset(),
    /** Adds one batch of REFERENCE_BATCH samples per pixel and light to the reference's running mean. */
    accumulate(scene) {
      setSceneUniforms(uniforms, scene, { reference: true, dfg });
      reference.add(programs.get(scene, sceneDefines(scene, true)));
    },
    /** RMS error of the approximation against the reference over the sphere, absolute and relative. */
    error: (slot = 0) => errors.measure(approxTargets[slot].texture, reference.texture),
    /** The approximation's radiance at the sphere's centre (n = v): the mean RGB of its four middle texels. */
    readCentre(slot = 0) {
      const target = approxTargets[slot];
      const half = target.texture.type === THREE.HalfFloatType;
      const texels = half ? new Uint16Array(16) : new Float32Array(16);
      renderer.readRenderTargetPixels(target, res / 2 - 1, res / 2 - 1, 2, 2, texels);
      const value = (i) => (half ? THREE.DataUtils.fromHalfFloat(texels[i]) : texels[i]);
      return [0, 1, 2].map((c) => (value(c) + value(4 + c) + value(8 + c) + value(12 + c)) / 4);
    },
    /** Reads an image back (tests): 'approx' (of `slot`) or 'reference', RGBA float per pixel. */
    read: (which, slot = 0) => readImage(renderer, which === 'approx' ? approxTargets[slot] : reference.target),
    get variants() {
      return modelPrograms.size + customPrograms.size + termPrograms.size;
    },
    dispose() {
      approxTargets.forEach((t) => t.dispose());
      [modelPrograms, customPrograms, termPrograms, pass, pmrem, reference, errors].forEach((x) => x.dispose());
      uniforms.uAlbedoTableGGX.value?.dispose();
      uniforms.uOpenPbrAlbedo.value?.dispose();
    },
  };
}

/** The reference: batches of Monte Carlo samples averaged into one of two float targets (ping-pong). */
function createReference(renderer, { res, uniforms, pass }) {
  const ping = [floatTarget(res, res), floatTarget(res, res)];
  let batches = 0;
  let current = 0;
  return {
    get texture() {
      return ping[current].texture;
    },
    get target() {
      return ping[current];
    },
    get batches() {
      return batches;
    },
    reset: () => (batches = 0),
    /** One batch by `program` (its uniforms set for the scene), averaged in. */
    add(program) {
      uniforms.uSamples.value = REFERENCE_BATCH;
      uniforms.uJitter.value.set(Math.random(), Math.random());
      uniforms.uPrevious.value = ping[current].texture;
      uniforms.uWeight.value = 1 / (batches + 1);
      pass.render(renderer, program, ping[1 - current]);
      current = 1 - current;
      batches++;
    },
    dispose: () => ping.forEach((t) => t.dispose()),
  };
}

/** The RMS error of an image against the reference over the sphere: per-pixel squares summed on the GPU. */
function createErrorSum(renderer, { res, pass }) {
  const target = floatTarget(res, res);
  const sum = createGpuSum(renderer);
  const material = fullscreenMaterial('lab-error.frag.glsl', {
    uniforms: { uImage: { value: null }, uOther: { value: null } },
  });
  return {
    target,
    measure(image, reference) {
      material.uniforms.uImage.value = image;
      material.uniforms.uOther.value = reference;
      pass.render(renderer, material, target);
      const [sq, ref, count] = sum.sum(target);
      renderer.setRenderTarget(null);
      return { rms: Math.sqrt(sq / Math.max(count, 1)), relative: ref > 0 ? Math.sqrt(sq / ref) : 0, pixels: count };
    },
    dispose() {
      [target, material, sum].forEach((x) => x.dispose());
    },
  };
}

/**
 * Draws `program` into one texel of `target`: compiled and linked without shading the whole image, which the timed
 * render then does (on software WebGL a 256-sample image was drawn twice for a new program).
 */
function compileInto(renderer, pass, program, target) {
  target.scissor.set(0, 0, 1, 1);
  target.scissorTest = true;
  pass.render(renderer, program, target);
  target.scissorTest = false;
  target.scissor.set(0, 0, target.width, target.height);
}

/** Waits for the GPU to finish the work drawn into `target` so far (a 1-texel read). */
function createSync(renderer) {
  const pixel = new Float32Array(4);
  const halfPixel = new Uint16Array(4);
  return (target) =>
    renderer.readRenderTargetPixels(
      target,
      0,
      0,
      1,
      1,
      target.texture.type === THREE.HalfFloatType ? halfPixel : pixel,
    );
}

/** The whole of `target` read back as RGBA float32 (a half-float target converted). */
function readImage(renderer, target) {
  const { width, height } = target;
  const out = new Float32Array(width * height * 4);
  if (target.texture.type === THREE.HalfFloatType) {
    const half = new Uint16Array(width * height * 4);
    renderer.readRenderTargetPixels(target, 0, 0, width, height, half);
    half.forEach((h, i) => (out[i] = THREE.DataUtils.fromHalfFloat(h)));
  } else renderer.readRenderTargetPixels(target, 0, 0, width, height, out);
  return out;
}
