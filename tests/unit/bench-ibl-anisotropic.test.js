// The bench's image-based lighting part (bench/ibl.js, `node bench/bench.js --only ibl`) as the performance page
// reads it (src/pages/data/bench-report.json): the brushed-metal case (issue 28) holds each method a renderer has for
// an anisotropic lobe under an environment (the split sum along the bent reflection vector of Filament and three.js,
// along the mirror direction, importance sampling), each scored against the lab's Monte Carlo reference, and the
// reference's own noise measured beside them.
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { PUBLISHED } from '../../bench/publish-report.js';
import { referenceNoise } from '../../bench/ibl.js';

const { ibl } = JSON.parse(readFileSync(PUBLISHED, 'utf8'));
const brushed = ibl.rows.filter((r) => r.anisotropy > 0);
const positive = (x) => Number.isFinite(x) && x > 0;

describe('the IBL part of the published bench report: brushed metal', () => {
  it('names its error: the relative RMS against the reference, of at least 2048 samples per pixel', () => {
    expect(ibl.errorOf).toMatch(/relative RMS .*reference/);
    expect(ibl.setup.referenceSamples).toBeGreaterThanOrEqual(2048);
    expect(ibl.date).toMatch(/^\d{4}-\d\d-\d\d/);
  });

  it('holds the bent reflection vector, the mirror direction and importance sampling, each timed and scored', () => {
    const methods = brushed.map((r) => [r.method, r.bent ?? null, r.samples]);
    expect(methods).toEqual([
      ['split-sum', true, null],
      ['split-sum', false, null],
      ['importance', null, 16],
      ['importance', null, 64],
      ['importance', null, 256],
    ]);
    for (const r of brushed) expect([r.ms, r.rms, r.relative].every(positive), JSON.stringify(r)).toBe(true);
    expect(new Set(brushed.map((r) => `${r.environment} ${r.material} ${r.alpha} ${r.anisotropy}`)).size).toBe(1);
  });

  it('measures the reference’s own noise: √((e²(N/4) − e²(N)) / 3) of each method, recomputed here', () => {
    const [check] = ibl.referenceChecks.filter((c) => c.anisotropy > 0);
    expect(check.checkSamples).toBe(ibl.setup.referenceSamples / 4);
    const each = brushed.map((r, i) => Math.sqrt(Math.max(0, check.relativeAtCheck[i] ** 2 - r.relative ** 2) / 3));
    for (const [i, x] of each.entries()) expect(check.each[i]).toBeCloseTo(x, 12);
    expect(check.noise).toBeCloseTo(each.reduce((a, b) => a + b) / each.length, 12);
    // a reference fit to score the split sums: its own noise well under either split sum's error
    for (const r of brushed.filter((b) => b.method === 'split-sum')) expect(check.noise).toBeLessThan(r.relative / 2);
  });
});

describe('referenceNoise (bench/ibl.js)', () => {
  it('recovers a noise put in by hand: e² = a² + s², and a quarter of the samples has 4 s² (closed form)', () => {
    const a = [0.5, 0.1, 0.03];
    const s = 0.02; // the full reference's relative noise
    const full = a.map((x) => Math.sqrt(x * x + s * s));
    const check = a.map((x) => Math.sqrt(x * x + 4 * s * s));
    const { each, mean } = referenceNoise(full, check);
    for (const x of each) expect(x).toBeCloseTo(s, 12);
    expect(mean).toBeCloseTo(s, 12);
  });
});
