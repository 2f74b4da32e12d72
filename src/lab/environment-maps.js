// What image-based lighting needs on the GPU, made once per environment and kept: the environment as an
// equirectangular half-float map with mips, its irradiance (summed exactly in JS from the map read back), tables
// to sample it by brightness; made when first asked for: its prefiltered layers for the split sum, one set per NDF,
// and three.js's PMREM of it for comparison. Also the DFG table (dfg-table.js: src/math's dfgSplitSum, shipped
// precomputed), which does not depend on the environment.
import * as THREE from 'three';
import { RoomEnvironment } from 'three/examples/jsm/environments/RoomEnvironment.js';
import { createFullscreenPass } from '../core/gpu/fullscreen-pass.js';
import { createProgramCache } from '../core/gpu/program-cache.js';
import { DFG_TABLE_SIZE } from '../math/integrate.js';
import { dfgTableData } from './dfg-table.js';
import { buildEnvSampling } from './env-sampling.js';
import { irradianceMap } from './env-irradiance.js';
import { fullscreenMaterial } from './fullscreen-material.js';

// coarse enough that the reference converges on small bright lights, fine enough for a mirror
export const ENV_SIZE = [256, 128];
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

/**
 * The maps of one environment (see the top of this file), on `renderer`; load(source) replaces the environment,
 * dispose() frees everything.
 */
export function createEnvironmentMaps(renderer) {
  const mipmapped = { minFilter: THREE.LinearMipmapLinearFilter, generateMipmaps: true };
  const env = halfTarget(...ENV_SIZE, mipmapped);
  const weighted = halfTarget(...ENV_SIZE, mipmapped); // for the prefilter
  const pass = createFullscreenPass();
  const copies = createEnvCopies(renderer, pass, env, weighted);
  const prefiltered = createPrefilterCache(renderer, pass, weighted);
  const readback = createEnvReadback(renderer, env);
  const pmrem = createPmremOf(renderer, env);

  return {
    env: env.texture,
    /** The map prefiltered for the split sum with the lobe of `ndf` ('ggx' | 'beckmann'), made when first asked for. */
    prefiltered: prefiltered.get,
    irradiance: readback.irradiance,
    sampling: readback.sampling,
    /** Replaces the environment: 'studio', or pixels { data, width, height } (sky, furnace, a user's file). */
    load(source) {
      copies.load(source);
      prefiltered.stale();
      readback.update();
      pmrem.stale();
    },
    /** three.js's PMREM of the current environment, made when first asked for. */
    pmrem: pmrem.get,
    dispose() {
      [env, weighted, readback, copies, pass, prefiltered, pmrem].forEach((x) => x.dispose());
    },
  };
}

/**
 * Writes an environment into `env` (from pixels, or from three.js's room for 'studio') and its solid-angle
 * weighted copy into `weighted` (env-copy.frag.glsl).
 */
function createEnvCopies(renderer, pass, env, weighted) {
  const copy = (defines, source = null) =>
    fullscreenMaterial('env-copy.frag.glsl', {
      defines,
      uniforms: { uSource: { value: source }, uSize: { value: new THREE.Vector2(...ENV_SIZE) } },
    });
  const copyFlat = copy({});
  const copyWeighted = copy({ WEIGHTED: 1 }, env.texture);
  const copyCube = copy({ CUBE_SOURCE: 1 });
  return {
    load(source) {
      if (source === 'studio') {
        const cube = roomCube(renderer);
        copyCube.uniforms.uSource.value = cube.texture;
        pass.render(renderer, copyCube, env);
        cube.dispose();
      } else {
        const texture = halfTexture(source);
        copyFlat.uniforms.uSource.value = texture;
        pass.render(renderer, copyFlat, env);
        texture.dispose();
      }
      pass.render(renderer, copyWeighted, weighted);
    },
    dispose: () => [copyFlat, copyCube, copyWeighted].forEach((x) => x.dispose()),
  };
}

/** three.js's RoomEnvironment as a cube map (the studio). */
function roomCube(renderer) {
  const cubeTarget = new THREE.WebGLCubeRenderTarget(256, { type: THREE.HalfFloatType });
  const room = new RoomEnvironment();
  new THREE.CubeCamera(0.1, 100, cubeTarget).update(renderer, room);
  room.dispose();
  return cubeTarget;
}

/** three.js's PMREM of the map `env` (get()), made when first asked for after each change (stale()). */
function createPmremOf(renderer, env) {
  let generator = null;
  let pmrem = null;
  return {
    get() {
      generator ??= new THREE.PMREMGenerator(renderer);
      env.texture.mapping = THREE.EquirectangularReflectionMapping;
      pmrem ??= generator.fromEquirectangular(env.texture);
      return pmrem.texture;
    },
    stale() {
      pmrem?.dispose();
      pmrem = null;
    },
    dispose() {
      pmrem?.dispose();
      generator?.dispose();
    },
  };
}

/**
 * The map's prefiltered layers for the split sum, one set per NDF ('ggx' | 'beckmann'), each made when first asked
 * for and remade after the map changes (stale()): the solid-angle weighted map `weighted` filtered with the NDF's
 * lobe (env-prefilter.frag.glsl), layer k - 1 at alpha = (k / PREFILTER_LEVELS)².
 */
function createPrefilterCache(renderer, pass, weighted) {
  const filters = createProgramCache((defines) =>
    fullscreenMaterial('env-prefilter.frag.glsl', {
      defines,
      uniforms: {
        uEnv: { value: weighted.texture },
        uEnvSize: { value: new THREE.Vector2(...ENV_SIZE) },
        uSize: { value: new THREE.Vector2(...PREFILTER_SIZE) },
        uAlpha: { value: 0 },
        uSamples: { value: 64 },
      },
    }),
  );
  const byNdf = new Map(); // ndf -> { target, fresh }
  const entryOf = (ndf) => {
    if (!byNdf.has(ndf)) {
      const target = new THREE.WebGLArrayRenderTarget(...PREFILTER_SIZE, PREFILTER_LEVELS, {
        type: THREE.HalfFloatType,
        depthBuffer: false,
        magFilter: THREE.LinearFilter,
        minFilter: THREE.LinearFilter,
        wrapS: THREE.RepeatWrapping,
      });
      byNdf.set(ndf, { target, fresh: false });
    }
    return byNdf.get(ndf);
  };
  return {
    get(ndf) {
      const entry = entryOf(ndf);
      if (!entry.fresh) {
        const filter = filters.get(PREFILTER_DEFINES[ndf]);
        for (let k = 1; k <= PREFILTER_LEVELS; k++) {
          filter.uniforms.uAlpha.value = (k / PREFILTER_LEVELS) ** 2;
          pass.render(renderer, filter, entry.target, k - 1);
        }
        entry.fresh = true;
      }
      return entry.target.texture;
    },
    stale: () => byNdf.forEach((entry) => (entry.fresh = false)),
    dispose() {
      byNdf.forEach(({ target }) => target.dispose());
      filters.dispose();
    },
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
