// The fits the measured-BRDF widget ships for its synthetic examples (example-fits.data.js, made by
// scripts/example-fits.js) against the fitter itself, on the same table with the same default samples: each is
// the metric's evaluation at its shape and a minimum of it, and the example's own family comes back with the
// parameters the table was written from.
import { beforeAll, describe, expect, it } from 'vitest';
import { FIT_MODELS, evaluateShape, fitSamples } from '../../src/measured/fit.js';
import { EXAMPLES } from '../../src/widgets/measured-brdf/model.js';
import { exampleTable } from '../../src/widgets/measured-brdf/example-table.js';
import { EXAMPLE_FITS } from '../../src/widgets/measured-brdf/example-fits.data.js';

const shapeOf = (model, params) => Object.fromEntries(FIT_MODELS[model].shape.map((s) => [s.key, params[s.key]]));
const STEP = 1e-3; // in the optimiser's coordinates: ln x for a log-scaled parameter, x / range otherwise

/** The shape moved by ±STEP along each parameter, within its range. */
function neighbours(model, shape) {
  return FIT_MODELS[model].shape.flatMap((s) =>
    [-1, 1]
      .map((sign) => {
        const x = s.log ? shape[s.key] * Math.exp(sign * STEP) : shape[s.key] + sign * STEP * (s.max - s.min);
        return { ...shape, [s.key]: Math.min(Math.max(x, s.min), s.max) };
      })
      .filter((n) => n[s.key] !== shape[s.key]),
  );
}

for (const [key, example] of Object.entries(EXAMPLES)) {
  describe(`the shipped fits of the ${key} example`, () => {
    let samples;
    beforeAll(() => {
      samples = fitSamples(exampleTable(key));
    }, 60_000);

    it('there is one for each of the five models', () => {
      expect(Object.keys(EXAMPLE_FITS[key]).sort()).toEqual(Object.keys(FIT_MODELS).sort());
    });

    for (const model of Object.keys(FIT_MODELS)) {
      it(`${model}: its error and weights are the metric's at its shape, and no neighbouring shape does better`, () => {
        const fit = EXAMPLE_FITS[key][model];
        const shape = shapeOf(model, fit.params);
        const at = evaluateShape(samples, model, shape);
        expect(Math.abs(at.error - fit.error)).toBeLessThanOrEqual(1e-9 * fit.error + 1e-15);
        for (const k of ['f0', 'cdiff']) at[k].forEach((x, c) => expect(x).toBeCloseTo(fit.params[k][c], 9));
        const around = neighbours(model, shape).map((n) => evaluateShape(samples, model, n).error);
        expect(around.length).toBeGreaterThan(0);
        for (const e of around) expect(e).toBeGreaterThan(fit.error);
      });
    }

    it(`the ${example.model} fit has the parameters the table was written from (to 1e-6)`, () => {
      const { params } = EXAMPLE_FITS[key][example.model];
      for (const [k, want] of Object.entries(example.params)) {
        [want].flat().forEach((w, c) => expect([params[k]].flat()[c]).toBeCloseTo(w, 6));
      }
    });
  });
}
