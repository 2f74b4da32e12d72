// The published bench report's MaterialX part (bench/openpbr-materialx.js, `node bench/bench.js --only materialx`):
// every material the bench compares is in it, with figures that hang together, and the figures keep the MaterialX
// test's tolerance (tests/browser/materialx.test.js: 4 %) where the app's composition is the one the test holds to it.
import { describe, expect, it } from 'vitest';
import report from '../../src/pages/data/bench-report.json';
import { MATERIALX_BENCH_MATERIALS } from '../support/materialx-materials.js';

const part = report.materialx;
const rows = part?.rows ?? [];
const TOLERANCE = 0.04; // materialx.test.js's MATERIALX_TOLERANCE
const comparisons = (r) => [r.glsl, r.float64, ...(r.withTurquin ? [r.withTurquin] : [])];

describe('the bench report: OpenPBR against MaterialX 1.39.5 (bench/openpbr-materialx.js)', () => {
  it('holds every material of the bench (the lab’s presets, base, + coat, + fuzz, velvet’s base), in order', () => {
    expect(part?.materialx).toBe('1.39.5');
    expect(rows.map((r) => r.name)).toEqual(MATERIALX_BENCH_MATERIALS.map((m) => m.name));
    expect(rows.map((r) => r.layers)).toEqual(MATERIALX_BENCH_MATERIALS.map((m) => m.layers));
  });

  it('per channel the largest difference is at least the mean, and the worst sample is the largest of them', () => {
    expect(rows.length).toBeGreaterThan(0);
    for (const c of rows.flatMap(comparisons)) {
      c.maxRelative.forEach((max, i) => expect(max).toBeGreaterThanOrEqual(c.meanRelative[i]));
      expect(Math.min(...c.meanRelative)).toBeGreaterThanOrEqual(0);
      expect(c.worst.relative).toBe(Math.max(...c.maxRelative));
      expect(c.maxRelative['rgb'.indexOf(c.worst.channel)]).toBe(c.worst.relative);
      expect(part.lightsDeg).toContain(c.worst.thetaL);
    }
  });

  it('the app’s GLSL is its float64 openPbrBRDF: their largest differences from MaterialX within 0.1 %', () => {
    expect(rows.length).toBeGreaterThan(0);
    for (const r of rows) expect(Math.abs(r.glsl.worst.relative - r.float64.worst.relative), r.name).toBeLessThan(1e-3);
  });

  it('within the MaterialX test’s 4 %: the coated materials, and the uncoated with Turquin’s compensation', () => {
    const coated = rows.filter((r) => r.layers.includes('coat'));
    expect(coated.map((r) => r.name)).toEqual(['carPaint', 'layers-coat', 'layers-fuzz']);
    for (const r of coated) expect(r.glsl.worst.relative, r.name).toBeLessThan(TOLERANCE);
    const compensated = rows.filter((r) => r.withTurquin);
    expect(compensated.map((r) => r.name)).toEqual(['plastic', 'gold', 'layers-base', 'velvet-base']);
    for (const r of compensated) expect(r.withTurquin.worst.relative, r.name).toBeLessThan(TOLERANCE);
  });
});
