// Hostile environment files (the material lab's .hdr / .exr drop): empty, wrong magic, every truncation of a
// good file, a header that claims gigabytes. Each is read or refused in words, quickly, never hangs.
import { Worker } from 'node:worker_threads';
import { describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { EXRExporter } from 'three/examples/jsm/exporters/EXRExporter.js';

const W = 8;
const H = 4;
const enc = (s) => new TextEncoder().encode(s);
const cat = (...parts) => {
  const out = new Uint8Array(parts.reduce((n, p) => n + p.length, 0));
  parts.reduce((at, p) => (out.set(p, at), at + p.length), 0);
  return out;
};
const int32 = (...v) => new Uint8Array(new Int32Array(v).buffer);
// RGBE (128, 128, 128, 128) is 128 · 2^(128 − 128) / 255 ≈ 0.502 in three's HDRLoader (Ward's RGBE, /255)
const hdr = (w, h, pixels = w * h) =>
  cat(enc(`#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y ${h} +X ${w}\n`), new Uint8Array(pixels * 4).fill(128));
// a minimal EXR header: magic, version 2, a channel list, and the dataWindow (a box2i) that gives the size
const exrHeader = (w, h) =>
  cat(
    int32(20000630, 2),
    enc('channels\0chlist\0'),
    int32(1),
    new Uint8Array(1),
    enc('dataWindow\0box2i\0'),
    int32(16, 0, 0, w - 1, h - 1),
    new Uint8Array(1),
  );

async function goodExr() {
  const texture = new THREE.DataTexture(new Float32Array(W * H * 4).fill(0.5), W, H, THREE.RGBAFormat, THREE.FloatType);
  return new EXRExporter().parse(texture, { type: THREE.FloatType, compression: THREE.NO_COMPRESSION });
}

/** parseEnvironmentFile over `cases` in a worker; rejects if it takes longer than `ms` (a loader in a loop). */
function parseAll(cases, ms = 20_000) {
  const worker = new Worker(new URL('../support/env-file-worker.js', import.meta.url), { workerData: cases });
  return new Promise((resolve, reject) => {
    const timer = setTimeout(
      () => (worker.terminate(), reject(new Error(`still parsing after ${ms} ms: a loader hangs`))),
      ms,
    );
    worker.once('message', (r) => (clearTimeout(timer), worker.terminate(), resolve(r)));
    worker.once('error', (e) => (clearTimeout(timer), reject(e)));
  });
}

describe('environment files from a user', () => {
  it(
    'a good 8×4 .hdr and .exr read back as the 0.5 their writers put in ' + '(three’s EXRExporter; RGBE 128/255)',
    async () => {
      const [h, e] = await parseAll([
        { name: 'good.hdr', bytes: hdr(W, H) },
        { name: 'good.exr', bytes: await goodExr() },
      ]);
      expect(h).toMatchObject({ ok: true, width: W, height: H });
      expect(h.mean).toBeCloseTo(128 / 255, 6);
      expect(e).toMatchObject({ ok: true, width: W, height: H, mean: 0.5 });
    },
  );

  it(
    'every truncation of a good file, empty and wrong-magic files: read whole or refused in words, none hangs',
    { timeout: 30_000 },
    async () => {
      const exr = await goodExr();
      const full = { hdr: hdr(W, H), exr };
      const cases = [];
      for (const [ext, bytes] of Object.entries(full)) {
        for (let n = 0; n < bytes.length; n++) cases.push({ name: `cut-${n}.${ext}`, bytes: bytes.slice(0, n) });
        cases.push({ name: `magic.${ext}`, bytes: cat(enc('\x89PNG\r\n\x1a\n'), bytes) });
      }
      const results = await parseAll(cases);
      for (const r of results) {
        if (r.ok)
          expect(r, r.name).toMatchObject({ width: W, height: H }); // a cut in the last pixels' padding
        else
          expect(r.error, r.name).toMatch(
            new RegExp(`^“${r.name.replace('.', '\\.')}” (could not be read|ends early|has \\d+ negative)`),
          );
      }
      expect(results.filter((r) => r.name.startsWith('cut-0.')).every((r) => !r.ok)).toBe(true);
      expect(results.filter((r) => r.name.startsWith('magic.')).map((r) => r.ok)).toEqual([false, false]);
    },
  );

  it(
    'a header that claims 200000×100000 pixels (80 GB as float RGBA) is ' + 'refused from the header, before decoding',
    async () => {
      const started = performance.now();
      const results = await parseAll([
        { name: 'huge.hdr', bytes: hdr(200000, 100000, 4) },
        { name: 'huge.exr', bytes: cat(exrHeader(200000, 100000), new Uint8Array(64)) },
        { name: 'wide.hdr', bytes: hdr(16000, 8000, 4) }, // 2 GB: under the loader's own limits, over ours
      ]);
      for (const r of results) expect(r.error, r.name).toMatch(/claims to be \d+×\d+; the limit is 8192×4096/);
      expect(performance.now() - started).toBeLessThan(10_000); // generous: the point is no allocation of gigabytes
    },
  );
});
