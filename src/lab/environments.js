// The environments the app makes for itself (a sky with a sun, a white furnace) and the ones a user brings
// (.hdr, .exr), checked before they replace anything. Pixels are linear radiance, RGBA float32, rows from the
// bottom (v = 0) up, in the equirectangular layout of src/math/lighting.js.
import { HDRLoader } from 'three/examples/jsm/loaders/HDRLoader.js';
import { EXRLoader } from 'three/examples/jsm/loaders/EXRLoader.js';
import * as THREE from 'three';
import { equirectDirection } from '../math/lighting.js';

export const ENVIRONMENTS = {
  studio: 'Studio (three.js RoomEnvironment)',
  sky: 'Sky with an enlarged sun (2°, the real one 0.27°)',
  furnace: 'White furnace (radiance 1)',
  file: 'Your file (drop .hdr / .exr)',
};

/**
 * The sky's sun: a disc of angular radius 2°, 35° up. The real sun's is 0.27° (7.5× smaller): enlarged so that the
 * 256 × 128 map (1.4° texels) resolves it and the reference's samples find it.
 */
export const SUN = {
  dir: unit([-0.45, Math.sin((35 * Math.PI) / 180), 0.65]),
  sin: Math.sin((2 * Math.PI) / 180),
  radiance: [900, 820, 700],
};

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

const EXR_MAGIC = 20000630;
const LATIN1 = new TextDecoder('latin1');

/**
 * The EXR header's dataWindow as { width, height }. The header must end (an empty attribute name) within the
 * bytes given: three's EXRLoader reads past the end of a truncated header without stopping.
 */
function exrHeaderSize(view) {
  const bytes = new Uint8Array(view.buffer, view.byteOffset, view.byteLength);
  let at = 8; // magic and version
  let size = null;
  const text = () => {
    const end = bytes.indexOf(0, at);
    if (end < 0) return null;
    const s = LATIN1.decode(bytes.subarray(at, end));
    at = end + 1;
    return s;
  };
  for (;;) {
    const name = text();
    if (name === '') return size ?? { problem: 'its header has no dataWindow' };
    const type = name === null ? null : text();
    if (type === null || at + 4 > bytes.length) return { problem: 'its header ends early' };
    const length = view.getInt32(at, true);
    at += 4;
    if (length < 0 || at + length > bytes.length) return { problem: 'its header ends early' };
    if (name === 'dataWindow' && type === 'box2i' && length === 16) {
      const [x0, y0, x1, y1] = [0, 4, 8, 12].map((o) => view.getInt32(at + o, true));
      size = { width: x1 - x0 + 1, height: y1 - y0 + 1 };
    }
    at += length;
  }
}

/**
 * The size a file's header claims, read before any pixel is decoded (a header may claim gigabytes of pixels in
 * a file of a few bytes): { width, height }, { problem } when the header is broken, or null when the loader
 * is left to say what is wrong.
 */
export function claimedSize(ext, buffer) {
  if (ext === 'exr') {
    const view = new DataView(buffer);
    return view.byteLength >= 4 && view.getUint32(0, true) === EXR_MAGIC ? exrHeaderSize(view) : null;
  }
  const head = LATIN1.decode(new Uint8Array(buffer, 0, Math.min(buffer.byteLength, 1 << 16)));
  const m = /\n\s*[-+]Y\s+(\d+)\s+[-+]X\s+(\d+)\s*\n/.exec(head); // the resolution line, e.g. "-Y 512 +X 1024"
  return m ? { width: Number(m[2]), height: Number(m[1]) } : null;
}

/** Why a width × height map cannot be an environment, or null. */
function sizeProblem(name, width, height, claims = 'is') {
  const size = `“${name}” ${claims} ${width}×${height}`;
  if (width > MAX_WIDTH || height > MAX_WIDTH / 2) return `${size}; the limit is ${MAX_WIDTH}×${MAX_WIDTH / 2}.`;
  if (Math.abs(width - 2 * height) > 2)
    return `${size}: an environment must be equirectangular, twice as wide as high.`;
  return null;
}

/**
 * Reads a dropped .hdr (Radiance RGBE) or .exr file into equirectangular pixels. Throws an Error whose message
 * says what is wrong in words a user can act on; the caller keeps the current environment.
 */
export function parseEnvironmentFile(name, buffer) {
  const ext = name.toLowerCase().split('.').pop();
  if (ext !== 'hdr' && ext !== 'exr') throw new Error(`“${name}” is not an .hdr or .exr file.`);
  if (buffer.byteLength > MAX_FILE_BYTES) {
    const limit = `${MAX_FILE_BYTES.toLocaleString('en')} bytes (${MAX_FILE_BYTES / 2 ** 20} MB)`;
    throw new Error(`“${name}” is ${buffer.byteLength.toLocaleString('en')} bytes; the limit is ${limit}.`);
  }
  const claimed = claimedSize(ext, buffer);
  if (claimed?.problem) throw new Error(`“${name}” could not be read as EXR: ${claimed.problem}.`);
  const refused = claimed && sizeProblem(name, claimed.width, claimed.height, 'claims to be');
  if (refused) throw new Error(refused);
  let parsed;
  try {
    const loader = ext === 'hdr' ? new HDRLoader() : new EXRLoader();
    parsed = loader.setDataType(THREE.FloatType).parse(buffer);
  } catch (e) {
    throw new Error(
      `“${name}” could not be read as ${ext.toUpperCase()}: ${String(e?.message ?? e).replace(/^THREE\.\w+:\s*/, '')}`,
    );
  }
  const { width, height, data, flipY } = parsed ?? {};
  if (!data || !(width > 0) || !(height > 0))
    throw new Error(`“${name}” could not be read as ${ext.toUpperCase()}: no image in it.`);
  const problem = sizeProblem(name, width, height);
  if (problem) throw new Error(problem);
  const channels = data.length / (width * height);
  if (![1, 3, 4].includes(channels)) {
    throw new Error(`“${name}” ends early: ${width}×${height} pixels need more data than it holds.`);
  }
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
  if (bad > (width * height) / 100)
    throw new Error(`“${name}” has ${bad} negative, NaN or infinite values: not a usable radiance map.`);
  return { data: rgba, width, height };
}
