// The environment sampling tables against direct integration: the density integrates to 1 over the sphere,
// and drawing from the tables reproduces it (the share of samples in a bright patch matches its probability).
import { describe, expect, it } from 'vitest';
import { buildEnvSampling } from '../../src/lab/env-sampling.js';
import { skyPixels } from '../../src/lab/environments.js';

const W = 64;
const H = 32;
const sky = skyPixels(W, H, true);
const tables = buildEnvSampling(sky.data, W, H);

// a direction's density per steradian, as the shader computes it
const pdfAt = (u, v) => {
  const i = Math.min(Math.floor(u * W), W - 1);
  const j = Math.min(Math.floor(v * H), H - 1);
  return tables.pdf[j * W + i] / Math.cos((v - 0.5) * Math.PI);
};

describe('environment sampling tables', () => {
  it('give a density that integrates to 1 over the sphere (midpoint rule, 4 points per texel)', () => {
    let sum = 0;
    const n = 4;
    for (let j = 0; j < H * n; j++) {
      const v = (j + 0.5) / (H * n);
      const dOmega = (2 * Math.PI * Math.PI * Math.cos((v - 0.5) * Math.PI)) / (W * n * H * n);
      for (let i = 0; i < W * n; i++) sum += pdfAt((i + 0.5) / (W * n), v) * dOmega;
    }
    expect(sum).toBeCloseTo(1, 2);
  });
  it('are CDFs: increasing, ending at 1', () => {
    expect(tables.marginal[H - 1]).toBe(1);
    for (let j = 1; j < H; j++) expect(tables.marginal[j]).toBeGreaterThanOrEqual(tables.marginal[j - 1]);
    for (let j = 0; j < H; j++) expect(tables.conditional[j * W + W - 1]).toBeCloseTo(1, 6);
  });
  it('send samples to the sun in proportion to its share of the light', () => {
    let sunTexels = 0;
    let inSun = 0;
    const sunShare = [];
    for (let j = 0; j < H; j++)
      for (let i = 0; i < W; i++) if (sky.data[(j * W + i) * 4] > 100) sunShare.push(j * W + i);
    for (const t of sunShare) sunTexels += (tables.pdf[t] * 2 * Math.PI * Math.PI) / (W * H);
    const n = 20000;
    for (let s = 0; s < n; s++) {
      const u1 = (s + 0.5) / n;
      const j = tables.marginal.findIndex((c) => c >= u1);
      const u2 = (s * 0.618033988749895) % 1;
      let i = 0;
      while (tables.conditional[j * W + i] < u2) i++;
      if (sunShare.includes(j * W + i)) inSun++;
    }
    expect(sunShare.length).toBeGreaterThan(0);
    expect(inSun / n).toBeCloseTo(sunTexels, 2);
  });
  it('return null for a black map (nothing to sample)', () => {
    expect(buildEnvSampling(new Float32Array(4 * 8), 4, 2)).toBe(null);
  });
});
