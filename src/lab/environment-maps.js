// What image-based lighting needs on the GPU, made once per environment and kept: the environment as an
// equirectangular half-float map with mips, its irradiance (summed exactly in JS from the map read back), tables
// to sample it by brightness; made when first asked for: its prefiltered layers for the split sum, one set per NDF,
// and three.js's PMREM of it for comparison. Also the DFG table (dfg-table.js: src/math's dfgSplitSum, shipped
// precomputed), which does not depend on the environment.
import * as THREE from 'three';
import { RoomEnvironment } from 'three/examples/jsm/environments/RoomEnvironment.js';
import { assembleGlsl } from '../core/gpu/glsl.js';
import { SHADER_CHUNKS } from '../core/gpu/shader-chunks.js';
import { DFG_TABLE_SIZE } from '../math/integrate.js';
import { dfgTableData } from './dfg-table.js';
import { buildEnvSampling } from './env-sampling.js';
import { irradianceMap } from './env-irradiance.js';

export const ENV_SIZE = [256, 128]; // coarse enough that the reference converges on small bright lights, fine enough for a mirror
export const PREFILTER_SIZE = [128, 64];
export const PREFILTER_LEVELS = 8; // layer k at perceptual roughness k/8, alpha = (k/8)²; level 0 is the map itself
const IRRADIANCE_SIZE = [32, 16];
const PREFILTER_DEFINES = { ggx: { NDF_GGX: 1 }, beckmann: { NDF_BECKMANN: 1 } };

export { dfgTableData }; // decoded in dfg-table.js (plain JS, no GPU)

/** The DFG table for terms { ndf, visibility } as a filtered texture (half float): sample it at dfgTableUv. */
export function createDfgTexture(terms = {}) {
  const dfg = halfTexture({ data: dfgTableData(terms).data, width: DFG_TABLE_SIZE, height: DFG_TABLE_SIZE });
  dfg.wrapS = THREE.ClampToEdgeWrapping;
  return dfg;
}

const toHalf = (data, out = new Uint16Array(data.length)) => {
  for (let i = 0; i < data.length; i++) out[i] = THREE.DataUtils.toHalfFloat(Math.min(data[i], 65000));
  return out;
};

function halfTexture({ data, width, height }) {
  const t = new THREE.DataTexture(toHalf(data), width, height, THREE.RGBAFormat, THREE.HalfFloatType);
  t.minFilter = THREE.LinearFilter;
  t.magFilter = THREE.LinearFilter;
  t.wrapS = THREE.RepeatWrapping;
  t.needsUpdate = true;
  return t;
}

const halfTarget = (w, h, options = {}) =>
  new THREE.WebGLRenderTarget(w, h, {
    type: THREE.HalfFloatType,
    format: THREE.RGBAFormat,
    depthBuffer: false,
    magFilter: THREE.LinearFilter,
    minFilter: THREE.LinearFilter,
    wrapS: THREE.RepeatWrapping,
    ...options,
  });

export function createEnvironmentMaps(renderer) {
  const env = halfTarget(...ENV_SIZE, { minFilter: THREE.LinearMipmapLinearFilter, generateMipmaps: true });
  const weighted = halfTarget(...ENV_SIZE, { minFilter: THREE.LinearMipmapLinearFilter, generateMipmaps: true }); // for the prefilter

  const quad = new THREE.Mesh(new THREE.PlaneGeometry(2, 2));
  quad.frustumCulled = false;
  const scene = new THREE.Scene().add(quad);
  const camera = new THREE.Camera();
  const pass = (fragment, defines, uniforms) =>
    new THREE.ShaderMaterial({
      glslVersion: THREE.GLSL3,
      uniforms,
      vertexShader: SHADER_CHUNKS['fullscreen.vert.glsl'],
      fragmentShader: assembleGlsl(SHADER_CHUNKS[fragment], { defines }),
      depthTest: false,
      depthWrite: false,
    });
  const copyFlat = pass(
    'env-copy.frag.glsl',
    {},
    { uSource: { value: null }, uSize: { value: new THREE.Vector2(...ENV_SIZE) } },
  );
  const copyWeighted = pass(
    'env-copy.frag.glsl',
    { WEIGHTED: 1 },
    { uSource: { value: env.texture }, uSize: { value: new THREE.Vector2(...ENV_SIZE) } },
  );
  const copyCube = pass(
    'env-copy.frag.glsl',
    { CUBE_SOURCE: 1 },
    { uSource: { value: null }, uSize: { value: new THREE.Vector2(...ENV_SIZE) } },
  );
  const filterUniforms = () => ({
    uEnv: { value: weighted.texture },
    uEnvSize: { value: new THREE.Vector2(...ENV_SIZE) },
    uSize: { value: new THREE.Vector2() },
    uAlpha: { value: 0 },
    uSamples: { value: 64 },
  });
  const run = (material, target, layer = 0) => {
    quad.material = material;
    renderer.setRenderTarget(target, layer);
    renderer.render(scene, camera);
  };
  const prefilterPass = (defines) => pass('env-prefilter.frag.glsl', defines, filterUniforms());
  const prefiltered = createPrefilterCache(renderer, run, prefilterPass);

  const readback = createEnvReadback(renderer, env);
  let pmremGenerator = null;
  let pmrem = null;

  const roomCube = () => {
    const cubeTarget = new THREE.WebGLCubeRenderTarget(256, { type: THREE.HalfFloatType });
    const room = new RoomEnvironment();
    new THREE.CubeCamera(0.1, 100, cubeTarget).update(renderer, room);
    room.dispose();
    return cubeTarget;
  };

  return {
    env: env.texture,
    /** The map prefiltered for the split sum with the lobe of `ndf` ('ggx' | 'beckmann'), made when first asked for. */
    prefiltered: prefiltered.get,
    irradiance: readback.irradiance,
    sampling: readback.sampling,
    /** Replaces the environment: 'studio', or pixels { data, width, height } (sky, furnace, a user's file). */
    load(source) {
      const previous = renderer.getRenderTarget();
      if (source === 'studio') {
        const cube = roomCube();
        copyCube.uniforms.uSource.value = cube.texture;
        run(copyCube, env);
        cube.dispose();
      } else {
        const texture = halfTexture(source);
        copyFlat.uniforms.uSource.value = texture;
        run(copyFlat, env);
        texture.dispose();
      }
      run(copyWeighted, weighted);
      prefiltered.stale();
      readback.update();
      renderer.setRenderTarget(previous);
      pmrem?.dispose();
      pmrem = null;
    },
    /** three.js's PMREM of the current environment, made when first asked for. */
    pmrem() {
      pmremGenerator ??= new THREE.PMREMGenerator(renderer);
      env.texture.mapping = THREE.EquirectangularReflectionMapping;
      pmrem ??= pmremGenerator.fromEquirectangular(env.texture);
      return pmrem.texture;
    },
    dispose() {
      [env, weighted].forEach((x) => x.dispose());
      readback.dispose();
      [copyFlat, copyCube, copyWeighted, quad.geometry].forEach((x) => x.dispose());
      prefiltered.dispose();
      pmrem?.dispose();
      pmremGenerator?.dispose();
    },
  };
}

/**
 * The map's prefiltered layers for the split sum, one set per NDF ('ggx' | 'beckmann'), each made when first asked
 * for and remade after the map changes (stale()). `makeFilter(defines)` gives the prefilter pass for an NDF.
 */
function createPrefilterCache(renderer, run, makeFilter) {
  const byNdf = new Map(); // ndf -> { target, filter, fresh }
  const entryOf = (ndf) => {
    if (!byNdf.has(ndf)) {
      const target = new THREE.WebGLArrayRenderTarget(...PREFILTER_SIZE, PREFILTER_LEVELS, {
        type: THREE.HalfFloatType,
        depthBuffer: false,
        magFilter: THREE.LinearFilter,
        minFilter: THREE.LinearFilter,
        wrapS: THREE.RepeatWrapping,
      });
      const filter = makeFilter(PREFILTER_DEFINES[ndf]);
      filter.uniforms.uSize.value.set(...PREFILTER_SIZE);
      byNdf.set(ndf, { target, filter, fresh: false });
    }
    return byNdf.get(ndf);
  };
  return {
    get(ndf) {
      const entry = entryOf(ndf);
      if (!entry.fresh) {
        const previous = renderer.getRenderTarget();
        for (let k = 1; k <= PREFILTER_LEVELS; k++) {
          entry.filter.uniforms.uAlpha.value = (k / PREFILTER_LEVELS) ** 2;
          run(entry.filter, entry.target, k - 1);
        }
        renderer.setRenderTarget(previous);
        entry.fresh = true;
      }
      return entry.target.texture;
    },
    stale: () => byNdf.forEach((entry) => (entry.fresh = false)),
    dispose: () => byNdf.forEach(({ target, filter }) => [target, filter].forEach((x) => x.dispose())),
  };
}

/** From the map `env` as it is on the GPU (update() reads it back): its irradiance, and tables to sample it by
 * brightness. */
function createEnvReadback(renderer, env) {
  const [iw, ih] = IRRADIANCE_SIZE;
  const irradiance = halfTexture({ data: new Float32Array(iw * ih * 4), width: iw, height: ih });
  const table = (w, h) => {
    const t = new THREE.DataTexture(new Float32Array(w * h), w, h, THREE.RedFormat, THREE.FloatType);
    t.minFilter = t.magFilter = THREE.NearestFilter;
    return t;
  };
  const sampling = {
    marginal: table(ENV_SIZE[1], 1),
    conditional: table(...ENV_SIZE),
    pdf: table(...ENV_SIZE),
    usable: false,
  };
  const update = () => {
    const half = new Uint16Array(ENV_SIZE[0] * ENV_SIZE[1] * 4);
    renderer.readRenderTargetPixels(env, 0, 0, ...ENV_SIZE, half);
    const pixels = Float32Array.from(half, THREE.DataUtils.fromHalfFloat);
    toHalf(irradianceMap(pixels, ...ENV_SIZE, ...IRRADIANCE_SIZE), irradiance.image.data);
    irradiance.needsUpdate = true;
    const tables = buildEnvSampling(pixels, ...ENV_SIZE);
    sampling.usable = Boolean(tables);
    if (!tables) return;
    for (const key of ['marginal', 'conditional', 'pdf']) {
      sampling[key].image.data.set(tables[key]);
      sampling[key].needsUpdate = true;
    }
  };
  const dispose = () => [irradiance, sampling.marginal, sampling.conditional, sampling.pdf].forEach((x) => x.dispose());
  return { irradiance, sampling, update, dispose };
}
