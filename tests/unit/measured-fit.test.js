import { beforeAll, describe, expect, it } from 'vitest';
import { parseMerl, writeMerl } from '../../src/measured/merl.js';
import { FIT_MODELS, fitMeasured, fitSamples, modelBRDF } from '../../src/measured/fit.js';
import { nelderMead } from '../../src/measured/nelder-mead.js';
import { boxQuadratic } from '../../src/measured/weights.js';

describe('the optimiser', () => {
  it('Nelder-Mead finds the Rosenbrock minimum (1, 1) (closed form)', () => {
    const f = ([x, y]) => (1 - x) ** 2 + 100 * (y - x * x) ** 2;
    const r = nelderMead(f, [-1.2, 1], { step: 0.5, maxEvaluations: 2000, xTolerance: 1e-10 });
    expect(r.x[0]).toBeCloseTo(1, 5);
    expect(r.x[1]).toBeCloseTo(1, 5);
  });

  it('boxQuadratic: the minimum over cdiff ≥ 0, 0 ≤ f0 ≤ 1 agrees with a brute-force grid search', () => {
    const cases = [
      [2, 0.5, 1, 1, 0.3],
      [1, 0.9, 1, -1, 2],
      [1, -0.2, 3, 0.5, 5],
      [4, 1, 1, -3, -1],
    ];
    for (const [a11, a12, a22, g1, g2] of cases) {
      const q = (x1, x2) => a11 * x1 * x1 + 2 * a12 * x1 * x2 + a22 * x2 * x2 - 2 * (g1 * x1 + g2 * x2);
      let best = [0, 0];
      for (let i = 0; i <= 400; i++)
        for (let j = 0; j <= 400; j++) if (q(i / 100, j / 400) < q(...best)) best = [i / 100, j / 400];
      const x = boxQuadratic(a11, a12, a22, g1, g2);
      expect(q(...x)).toBeLessThanOrEqual(q(...best) + 1e-12);
      expect(x[0]).toBeCloseTo(best[0], 1);
      expect(x[1]).toBeCloseTo(best[1], 2);
    }
  });
});

// Synthetic files written by writeMerl from the models themselves: the parameters they were made with are
// the truth. Coarse strides keep the unit test quick; the page and the bench use the defaults.
const OPTIONS = { strideD: 6, strideP: 12 };
const SYNTHETIC = {
  ggx: { alpha: 0.2, f0: [0.04, 0.04, 0.04], cdiff: [0.3, 0.3, 0.3] },
  abc: { a1: 40, a2: 2.5, f0: [0.9, 0.6, 0.3], cdiff: [0.05, 0.1, 0.2] },
};

for (const [family, truth] of Object.entries(SYNTHETIC)) {
  describe(`fitting a file written from ${family} (truth: the parameters it was written with)`, () => {
    let fits;
    beforeAll(() => {
      const measured = parseMerl(writeMerl(modelBRDF(family, truth)));
      const samples = fitSamples(measured, OPTIONS);
      fits = Object.fromEntries(Object.keys(FIT_MODELS).map((m) => [m, fitMeasured(measured, m, { samples })]));
    }, 600_000);

    it('recovers every parameter within 2 %', () => {
      const p = fits[family].params;
      for (const key of Object.keys(truth)) {
        [truth[key]].flat().forEach((want, c) => expect(Math.abs([p[key]].flat()[c] / want - 1)).toBeLessThan(0.02));
      }
    });

    it(`the ${family} fit has the smallest error of the five families`, () => {
      const ranked = Object.values(fits).sort((a, b) => a.error - b.error);
      expect(ranked[0].model).toBe(family);
      expect(ranked[0].error).toBeLessThan(ranked[1].error / 100);
    });
  });
}

it('an unknown model is refused by name', () => {
  expect(() => fitMeasured({ table: new Float64Array(0) }, 'phong')).toThrow(/Unknown model "phong"/);
});
