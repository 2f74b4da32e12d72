import { describe, expect, it } from 'vitest';
import { parseMerl, writeMerl } from '../../src/measured/merl.js';
import { modelBRDF } from '../../src/measured/fit.js';
import { ndfGGX, ndfABC } from '../../src/math/ndf.js';
import { ndfHalfWidthDeg } from '../../src/math/ndf-width.js';
import {
  EXAMPLES,
  THETA_H_DEG,
  fittedNdfSlice,
  lobe3dSpec,
  lobeStateForFit,
  measuredNdfSlice,
  ndfStateForFit,
} from '../../src/widgets/measured-brdf/model.js';

import { coerceState } from '../../src/core/framework/state.js';
import { schema as ndfSchema } from '../../src/widgets/ndf-explorer/ndf-explorer.js';
import { DEG } from '../../src/math/angles.js';

const asFit = (key) => ({ model: EXAMPLES[key].model, params: EXAMPLES[key].params, error: 0 });

/**
 * A MERL file of `f` at its θd = 0 nodes (there l = v, bit for bit) and 0 elsewhere: the slices read those nodes
 * only, and a file of zeros elsewhere is written in about a third of the time of `f` everywhere. A slice that read
 * any other node would read a zero and fail.
 */
const thetaD0File = (f) => parseMerl(writeMerl((l, v) => (l.every((x, i) => x === v[i]) ? f(l, v) : [0, 0, 0])));

describe('the measured-BRDF widget model', () => {
  it('the θd = 0 slice of a GGX file, less its diffuse and ÷ its V, is D(θh)/D(0) of GGX α 0.2 (closed form)', () => {
    const fit = asFit('ggx');
    const { table } = thetaD0File(modelBRDF('ggx', fit.params));
    const slice = measuredNdfSlice(table, fit);
    THETA_H_DEG.forEach((deg, i) => {
      const want = ndfGGX(Math.cos(deg * DEG), 0.2) / ndfGGX(1, 0.2);
      if (deg < 89) expect(Math.abs(slice[i] - want)).toBeLessThan(1e-12 + 1e-9 * want);
    });
    // without the fit, the diffuse floor stays in: the slice no longer falls like D
    expect(measuredNdfSlice(table)[80]).toBeGreaterThan(10 * slice[80]);
  });

  it('the 3-D lobe reads the green channel with l at -θ in the plane, and its scale is the largest value shown', () => {
    const f = modelBRDF('ggx', EXAMPLES.ggx.params);
    const dirs = [
      [0, 0, 1],
      [Math.sin(30 * DEG), 0, Math.cos(30 * DEG)],
      [0, Math.sin(60 * DEG), Math.cos(60 * DEG)],
    ];
    const spec = lobe3dSpec(f, null, 30, dirs);
    const l = [-Math.sin(30 * DEG), 0, Math.cos(30 * DEG)];
    dirs.forEach((v) => expect(spec.fA(v)).toBe(f(l, v)[1]));
    expect(spec.max).toBe(f(l, dirs[1])[1]); // the mirror direction is the brightest of the three
    expect(spec.fB).toBeNull();
    expect(spec.directions.mirror).toEqual([-l[0], 0, l[2]]);
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

  it(
    'ndf-explorer gets the fit’s half width (bisection on D), ' +
      'the fitted ABC and SGD shapes, and the measured slice',
    () => {
      const fits = {
        abc: asFit('abc'),
        sgd: { model: 'sgd', params: { alpha: 0.1, p: 1.2, f0: [0, 0, 0], cdiff: [0, 0, 0] }, error: 1 },
      };
      const measured = thetaD0File(modelBRDF('abc', fits.abc.params));
      const state = ndfStateForFit(fits.abc, fits, measured, 'my <b>copper</b>.binary');
      expect(state.hwhm).toBeCloseTo(
        ndfHalfWidthDeg((c) => ndfABC(c, 40, 2.5)),
        9,
      );
      expect(state).toMatchObject({ abcA2: 2.5, sgdP: 1.2, measuredName: 'my bcopperb.binary' });
      // the slice of the best fit (ABC, the truth) is ABC's D/D(0) (closed form) to the 3 digits the URL carries
      expect(state.measured).toHaveLength(90);
      state.measured.forEach((x, i) => {
        const want = ndfABC(Math.cos(THETA_H_DEG[i] * DEG), 40, 2.5) / ndfABC(1, 40, 2.5);
        if (THETA_H_DEG[i] < 89) expect(Math.abs(x - want)).toBeLessThanOrEqual(want > 1e-5 ? 5e-3 * want : 1e-5);
      });
      // and ndf-explorer's state takes it as it is (no notice)
      const { state: taken, notices } = coerceState(
        ndfSchema,
        Object.fromEntries(Object.entries(state).map(([k, v]) => [k, String(v)])),
      ); // as the URL carries it
      expect(notices).toEqual([]);
      expect(taken.measured).toEqual(state.measured);
    },
  );
});
