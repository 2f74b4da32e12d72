// The fits the measured-BRDF widget ships for its synthetic examples (example-fits.data.js, made by
// scripts/example-fits.js) against the fitter itself, on the same table with the same default samples: GGX fitted
// again gives the shipped GGX fit; every shipped fit is the metric's evaluation at its shape and a minimum of it;
// and the example's own family comes back with the parameters the table was written from.
import { beforeAll, describe, expect, it } from 'vitest';
import { FIT_MODELS, evaluateShape, fitMeasured, fitSamples } from '../../src/measured/fit.js';
import { EXAMPLES } from '../../src/widgets/measured-brdf/model.js';
import { exampleTable } from '../../src/widgets/measured-brdf/example-table.js';
import { EXAMPLE_FITS } from '../../src/widgets/measured-brdf/example-fits.data.js';

const shapeOf = (model, params) => Object.fromEntries(FIT_MODELS[model].shape.map((s) => [s.key, params[s.key]]));
// a step in the optimiser's coordinates: ln x for a log-scaled parameter, x itself for a linear one (SGD's p)
const STEP = 1e-3;

/** The shape moved by ±STEP along each parameter and, for two, along both diagonals; kept within range. */
function neighbours(model, shape) {
  const params = FIT_MODELS[model].shape;
  const moves = params.flatMap((_, i) => [-1, 1].map((sign) => params.map((__, j) => (i === j ? sign : 0))));
  if (params.length === 2) moves.push([1, 1], [1, -1], [-1, 1], [-1, -1]);
  return moves
    .map((move) =>
      Object.fromEntries(
        params.map((s, i) => {
          const x = s.log ? shape[s.key] * Math.exp(move[i] * STEP) : shape[s.key] + move[i] * STEP;
          return [s.key, Math.min(Math.max(x, s.min), s.max)];
        }),
      ),
    )
    .filter((n) => params.some((s) => n[s.key] !== shape[s.key]));
}

for (const [key, example] of Object.entries(EXAMPLES)) {
  describe(`the shipped fits of the ${key} example`, () => {
    let measured;
    let samples;
    beforeAll(() => {
      measured = exampleTable(key);
      samples = fitSamples(measured);
    }, 60_000);

    it('there is one for each of the five models', () => {
      expect(Object.keys(EXAMPLE_FITS[key]).sort()).toEqual(Object.keys(FIT_MODELS).sort());
      for (const [model, fit] of Object.entries(EXAMPLE_FITS[key])) {
        expect(fit.model).toBe(model);
        expect(fit.evaluations).toBeGreaterThan(0);
        expect(fit.evaluations).toBeLessThanOrEqual(400); // the fitter's default budget
      }
    });

    it('GGX fitted again by the fitter is the shipped GGX fit', () => {
      const again = fitMeasured(measured, 'ggx', { samples });
      const shipped = EXAMPLE_FITS[key].ggx;
      expect(again.evaluations).toBe(shipped.evaluations);
      expect(again.params.alpha / shipped.params.alpha).toBeCloseTo(1, 12);
      for (const k of ['f0', 'cdiff'])
        again.params[k].forEach((x, c) => expect(x).toBeCloseTo(shipped.params[k][c], 12));
    }, 60_000);

    for (const model of Object.keys(FIT_MODELS)) {
      it(`${model}: its error and weights are the metric's at its shape, and no neighbouring shape does better`, () => {
        const fit = EXAMPLE_FITS[key][model];
        const shape = shapeOf(model, fit.params);
        const at = evaluateShape(samples, model, shape);
        // relative 1e-9; for the example's own family, whose error is ~1e-14, this is bit for bit: a change in the
        // order of a sum in the fitter can fail it, and then the data is made again (npm run example-fits)
        expect(Math.abs(at.error - fit.error)).toBeLessThanOrEqual(1e-9 * fit.error + 1e-15);
        for (const k of ['f0', 'cdiff']) at[k].forEach((x, c) => expect(x).toBeCloseTo(fit.params[k][c], 9));
        const around = neighbours(model, shape).map((n) => evaluateShape(samples, model, n).error);
        expect(around.length).toBe(FIT_MODELS[model].shape.length === 2 ? 8 : 2);
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
