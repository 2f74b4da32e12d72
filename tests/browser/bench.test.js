// The benchmark is not a timed test: this only checks that it runs on a tiny budget and that its JSON has
// the documented shape (the page plots the committed results; their numbers are for people to read).
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { ROOT } from './harness.js';
import { FIT_MODELS } from '../../src/measured/fit.js';

const num = expect.any(Number);

function checkShape(report) {
  expect(report).toMatchObject({
    version: 1,
    date: expect.any(String),
    machine: { cpu: expect.any(String), cores: num, gpuRenderer: expect.any(String) },
  });
  expect(report.gpuSetup).toMatchObject({ size: num, loops: num, frames: num, baselineMsPerFrame: num });
  expect(report.families.map((f) => f.key)).toEqual([
    'fresnel-dielectric',
    'fresnel-conductor',
    'smith-g1-beckmann',
    'visibility',
    'ndf',
    'oren-nayar',
    'multiple-scattering',
    'anisotropy',
    'fresnel-metal-two-colours',
    'openpbr-layers',
  ]);
  for (const f of report.families) {
    expect(f).toMatchObject({ title: expect.any(String), domain: expect.any(String), errorOf: expect.any(String) });
    expect(f.variants.length).toBeGreaterThanOrEqual(2);
    for (const v of f.variants) {
      // an approximation has an error against its target; another model only a difference from it
      const measure = v.kind === 'difference' ? 'difference' : 'error';
      // a Monte Carlo reference run once offline (the random walk) has no cost columns, and says its own error
      const untimed = v.kind === 'reference' && v.cpuNsPerEval === null;
      const costs = untimed
        ? { cpuNsPerEval: null, gpuMsPerFrame: null, gpuRelative: null }
        : { cpuNsPerEval: f.cpuUntimed ? null : num, gpuMsPerFrame: num, gpuRelative: num }; // cpuUntimed: looked up
      if (untimed) expect(f.referenceNote).toEqual(expect.any(String));
      expect(v).toMatchObject({
        key: expect.any(String),
        label: expect.any(String),
        kind: expect.any(String),
        [measure]: { maxAbs: num, rms: num },
        ...costs,
      });
      expect(v).not.toHaveProperty(measure === 'error' ? 'difference' : 'error');
      if (v.kind !== 'reference') expect(f.variants.map((w) => w.key)).toContain(v.against);
      const numbers = [
        v[measure].maxAbs,
        v[measure].rms,
        ...(untimed ? [] : [v.cpuNsPerEval, v.gpuMsPerFrame, v.gpuRelative].filter((x) => x !== null)),
      ];
      for (const x of numbers) expect(Number.isFinite(x) && x >= 0).toBe(true);
    }
    expect(f.variants[0]).toMatchObject({ kind: 'reference', error: { maxAbs: 0 } }); // the reference against itself
    // GPU costs relative to the cheapest variant, or to the one the family names (OpenPBR's: the talk's model)
    const unit = f.relativeTo
      ? f.variants.find((v) => v.key === f.relativeTo).gpuRelative
      : Math.min(...f.variants.filter((v) => v.gpuRelative !== null).map((v) => v.gpuRelative));
    expect(unit).toBe(1);
  }
  expect(report.versusThree).toMatchObject({ size: num, oursMsPerFrame: num, threeMsPerFrame: num, ratio: num });
  expect(report.pages.map((p) => p.page)).toContain('fresnel.html');
  expect(report.ibl.setup).toMatchObject({ resolution: num, referenceSamples: num, timingRuns: num });
  expect(report.ibl.rows.length).toBeGreaterThanOrEqual(1);
  for (const r of report.ibl.rows) {
    expect(r).toMatchObject({
      environment: expect.any(String),
      material: expect.any(String),
      method: expect.any(String),
      ms: num,
      rms: num,
      relative: num,
    });
    for (const x of [r.ms, r.rms, r.relative]) expect(Number.isFinite(x) && x >= 0).toBe(true);
  }
  for (const p of report.pages) expect(p).toMatchObject({ jsKB: num, jsFiles: num, loadMs: num });
  expect(report.measured).toMatchObject({ writeMs: num, parseMs: num, fitSamples: { count: num, ms: num } });
  expect(report.measured.fits.map((f) => f.model)).toEqual(Object.keys(FIT_MODELS)); // each model, even quick
  for (const f of report.measured.fits) expect(f).toMatchObject({ ms: num, evaluations: num, error: num });
  expect(report.latency).toMatchObject({ steps: num, targetMs: 50 });
  expect(report.custom.edit).toMatchObject({ medianMs: num, worstMs: num, missed: 0 });
  expect(report.custom.grade.length).toBeGreaterThanOrEqual(report.quick ? 2 : 8); // every one in a full run
  for (const r of report.custom.grade) expect(r).toMatchObject({ id: expect.any(String), medianMs: num, passed: true });
  for (const r of report.latency.rows)
    expect(r).toMatchObject({ widget: expect.any(String), key: expect.any(String), medianMs: num, worstMs: num });
}

describe('npm run bench', () => {
  it('runs on a tiny budget and writes JSON of the documented shape', () => {
    const out = join(mkdtempSync(join(tmpdir(), 'bench-')), 'quick.json');
    const log = execFileSync('node', ['bench/bench.js', '--quick', '--out', out], {
      cwd: ROOT,
      encoding: 'utf8',
      timeout: 300_000,
      env: { ...process.env, BUILT_APP: join(ROOT, 'dist') }, // global-setup.js built it for this run
    });
    expect(log).toMatch(/Fresnel, dielectrics/);
    const report = JSON.parse(readFileSync(out, 'utf8'));
    expect(report.quick).toBe(true);
    checkShape(report);
  }, 300_000);
  it('the committed results the performance page plots have the same shape', () => {
    checkShape(JSON.parse(readFileSync(join(ROOT, 'bench/results/latest.json'), 'utf8')));
  });
});
