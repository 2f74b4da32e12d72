import { describe, expect, it } from 'vitest';
import { parseMerl, writeMerl } from '../../src/measured/merl.js';
import { modelBRDF } from '../../src/measured/fit.js';
import { ndfGGX, ndfABC } from '../../src/math/ndf.js';
import { ndfHalfWidthDeg } from '../../src/math/ndf-width.js';
import {
  EXAMPLES,
  THETA_H_DEG,
  fittedNdfSlice,
  lobeStateForFit,
  measuredNdfSlice,
  ndfStateForFit,
} from '../../src/widgets/measured-brdf/model.js';

const DEG = Math.PI / 180;
const asFit = (key) => ({ model: EXAMPLES[key].model, params: EXAMPLES[key].params, error: 0 });

describe('the measured-BRDF widget model', () => {
  it('the θd = 0 slice of a GGX file, less its diffuse and ÷ its V, is D(θh)/D(0) of GGX α 0.2 (closed form)', () => {
    const fit = asFit('ggx');
    const table = parseMerl(writeMerl(modelBRDF('ggx', fit.params))).table;
    const slice = measuredNdfSlice(table, fit);
    THETA_H_DEG.forEach((deg, i) => {
      const want = ndfGGX(Math.cos(deg * DEG), 0.2) / ndfGGX(1, 0.2);
      if (deg < 89) expect(Math.abs(slice[i] - want)).toBeLessThan(1e-12 + 1e-9 * want);
    });
    // without the fit, the diffuse floor stays in: the slice no longer falls like D
    expect(measuredNdfSlice(table)[80]).toBeGreaterThan(10 * slice[80]);
  });

  it('a fit’s own slice is its normalised NDF (ABC, closed form)', () => {
    const fit = asFit('abc');
    fittedNdfSlice(fit).forEach((x, i) =>
      expect(x).toBeCloseTo(ndfABC(Math.cos(THETA_H_DEG[i] * DEG), 40, 2.5) / ndfABC(1, 40, 2.5), 12),
    );
  });

  it('loading a GGX fit into brdf-lobe keeps its α (same width) and takes the mean f0', () => {
    const state = lobeStateForFit({ model: 'ggx', params: { alpha: 0.2, f0: [0.9, 0.6, 0.3], cdiff: [0, 0, 0] } });
    expect(state).toMatchObject({ D: 'ggx', V: 'smithGGXCorrelated', F: 'schlick' });
    expect(state.alpha).toBeCloseTo(0.2, 4);
    expect(state.f0).toBeCloseTo(0.6, 12);
  });

  it('ndf-explorer gets the fit’s half width (bisection on D) and the fitted ABC and SGD shapes', () => {
    const fits = {
      abc: asFit('abc'),
      sgd: { model: 'sgd', params: { alpha: 0.1, p: 1.2, f0: [0, 0, 0], cdiff: [0, 0, 0] } },
    };
    const state = ndfStateForFit(fits.abc, fits);
    expect(state.hwhm).toBeCloseTo(
      ndfHalfWidthDeg((c) => ndfABC(c, 40, 2.5)),
      9,
    );
    expect(state).toMatchObject({ abcA2: 2.5, sgdP: 1.2 });
  });
});
