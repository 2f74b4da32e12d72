// subsurface-scale reuses one set of walks at σs = 1 for every σs and σa: checked against walks run at each σs.
import { describe, expect, it } from 'vitest';
import { randomWalk2D } from '../../src/math/media.js';
import { seededRandom } from '../../src/math/microsurface.js';
import { MAX_EVENTS, STATS_WALKS, statistics } from '../../src/widgets/subsurface-scale/model.js';

/** The reflectance and light-weighted mean exit distance of STATS_WALKS walks run at the state's own σs. */
function direct(s) {
  const rand = seededRandom(s.seed * 7919);
  let [back, moment] = [0, 0];
  for (let i = 0; i < STATS_WALKS; i++) {
    const w = randomWalk2D({ sigmaS: s.sigmaS, rand, maxEvents: MAX_EVENTS });
    if (w.exit === 'lost') continue;
    const weight = Math.exp(-s.sigmaA * w.path);
    back += weight;
    moment += weight * Math.abs(w.x);
  }
  return { reflectance: back / STATS_WALKS, mean: moment / back };
}

describe('subsurface-scale statistics from walks at σs = 1, scaled', () => {
  for (const s of [
    { sigmaS: 7.3, sigmaA: 0.5, pixel: 0.3, seed: 5 },
    { sigmaS: 0.2, sigmaA: 0.02, pixel: 20, seed: 999 },
  ]) {
    it(`match walks run at σs ${s.sigmaS}, σa ${s.sigmaA} (to 1e-12)`, () => {
      const scaled = statistics(s);
      const walked = direct(s);
      expect(scaled.reflectance).toBeCloseTo(walked.reflectance, 12);
      expect(Math.abs(scaled.mean / walked.mean - 1)).toBeLessThan(1e-12);
    });
  }
});
