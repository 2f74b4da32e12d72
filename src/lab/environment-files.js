// The environments a user brings (.hdr, .exr), checked before they replace anything: read into the pixels of
// environments.js (linear radiance, RGBA float32, rows from the bottom up), or refused in words a user can act on.
import { HDRLoader } from 'three/examples/jsm/loaders/HDRLoader.js';
import { EXRLoader } from 'three/examples/jsm/loaders/EXRLoader.js';
import * as THREE from 'three';

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
    const why = String(e?.message ?? e).replace(/^THREE\.\w+:\s*/, '');
    throw new Error(`“${name}” could not be read as ${ext.toUpperCase()}: ${why}`, { cause: e });
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
