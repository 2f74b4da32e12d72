// The environments the app makes for itself (a sky with a sun, a white furnace) and the ones a user brings
// (.hdr, .exr), checked before they replace anything. Pixels are linear radiance, RGBA float32, rows from the
// bottom (v = 0) up, in the equirectangular layout of src/math/lighting.js.
import { HDRLoader } from 'three/examples/jsm/loaders/HDRLoader.js';
import { EXRLoader } from 'three/examples/jsm/loaders/EXRLoader.js';
import * as THREE from 'three';
import { equirectDirection } from '../../math/lighting.js';

export const ENVIRONMENTS = {
  studio: 'Studio (three.js RoomEnvironment)', sky: 'Sky with an enlarged sun (2°, the real one 0.27°)',
  furnace: 'White furnace (radiance 1)', file: 'Your file (drop .hdr / .exr)',
};

/**
 * The sky's sun: a disc of angular radius 2°, 35° up. The real sun's is 0.27° (7.5× smaller): enlarged so that the
 * 256 × 128 map (1.4° texels) resolves it and the reference's samples find it.
 */
export const SUN = { dir: unit([-0.45, Math.sin((35 * Math.PI) / 180), 0.65]), sin: Math.sin((2 * Math.PI) / 180), radiance: [900, 820, 700] };

function unit(d) {
  const n = Math.hypot(...d);
  return d.map((x) => x / n);
}

/** Radiance of the sky towards d: a blue gradient above a darker ground, plus the sun's disc if asked. */
export function skyRadiance(d, withSun = true) {
  const y = d[1];
  let c;
  if (y >= 0) {
    const t = Math.sqrt(y);
    c = [0.55 + (0.18 - 0.55) * t, 0.7 + (0.36 - 0.7) * t, 0.95 + (0.8 - 0.95) * t];
  } else {
    const t = Math.min(-y * 4, 1);
    c = [0.3 - 0.14 * t, 0.27 - 0.12 * t, 0.22 - 0.1 * t];
  }
  const cosSun = d[0] * SUN.dir[0] + d[1] * SUN.dir[1] + d[2] * SUN.dir[2];
  if (withSun && cosSun >= Math.sqrt(1 - SUN.sin * SUN.sin)) return SUN.radiance.slice();
  return c;
}

export function skyPixels(width, height, withSun = true) {
  const data = new Float32Array(width * height * 4);
  for (let j = 0; j < height; j++) {
    for (let i = 0; i < width; i++) {
      const c = skyRadiance(equirectDirection((i + 0.5) / width, (j + 0.5) / height), withSun);
      data.set([...c, 1], (j * width + i) * 4);
    }
  }
  return { data, width, height };
}

export const FURNACE = { data: new Float32Array(4 * 2 * 4).fill(1), width: 4, height: 2 };

export const MAX_FILE_BYTES = 64 * 1024 * 1024;
const MAX_WIDTH = 8192;

/**
 * Reads a dropped .hdr (Radiance RGBE) or .exr file into equirectangular pixels. Throws an Error whose message
 * says what is wrong in words a user can act on; the caller keeps the current environment.
 */
export function parseEnvironmentFile(name, buffer) {
  const ext = name.toLowerCase().split('.').pop();
  if (ext !== 'hdr' && ext !== 'exr') throw new Error(`“${name}” is not an .hdr or .exr file.`);
  if (buffer.byteLength > MAX_FILE_BYTES) throw new Error(`“${name}” is ${(buffer.byteLength / 2 ** 20).toFixed(0)} MB; the limit is ${MAX_FILE_BYTES / 2 ** 20} MB.`);
  let parsed;
  try {
    const loader = ext === 'hdr' ? new HDRLoader() : new EXRLoader();
    parsed = loader.setDataType(THREE.FloatType).parse(buffer);
  } catch (e) {
    throw new Error(`“${name}” could not be read as ${ext.toUpperCase()}: ${String(e?.message ?? e).replace(/^THREE\.\w+:\s*/, '')}`);
  }
  const { width, height, data, flipY } = parsed ?? {};
  if (!data || !(width > 0) || !(height > 0)) throw new Error(`“${name}” could not be read as ${ext.toUpperCase()}: no image in it.`);
  if (width > MAX_WIDTH || height > MAX_WIDTH / 2) throw new Error(`“${name}” is ${width}×${height}; the limit is ${MAX_WIDTH}×${MAX_WIDTH / 2}.`);
  if (Math.abs(width - 2 * height) > 2) throw new Error(`“${name}” is ${width}×${height}: an environment must be equirectangular, twice as wide as high.`);
  const channels = data.length / (width * height);
  const rgba = new Float32Array(width * height * 4);
  let bad = 0;
  for (let p = 0; p < width * height; p++) {
    // the app's maps run bottom up; the loaders say whether the file's rows run top down (flipY)
    const row = flipY ? height - 1 - Math.floor(p / width) : Math.floor(p / width);
    const q = (row * width + (p % width)) * 4;
    for (let c = 0; c < 3; c++) {
      const x = data[p * channels + Math.min(c, channels - 1)]; // a grey map repeats its one channel
      if (!Number.isFinite(x) || x < 0) bad++;
      rgba[q + c] = Number.isFinite(x) ? Math.max(x, 0) : 0;
    }
    rgba[q + 3] = 1;
  }
  if (bad > (width * height) / 100) throw new Error(`“${name}” has ${bad} negative, NaN or infinite values: not a usable radiance map.`);
  return { data: rgba, width, height };
}
