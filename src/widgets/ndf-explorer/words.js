// The NDF explorer's words: what it shows, the functions it names, and its pictures described for screen readers.

export const TITLE = 'NDF explorer';

export const ABOUT =
  'Each NDF is given the same half width at half maximum (the angle where D drops to half its peak), so the ' +
  'cores of the lobes match and only their shapes differ. The log plot shows the tails: GGX, ABC and SGD keep ' +
  'far more microfacets at large angles than Beckmann or Blinn-Phong, which is the halo around their highlights. ' +
  'Raise the exposure to see it. The spheres use F = 1 and V = 1 so that only D differs. The table integrates ' +
  'each D·(n·m) over the hemisphere: a density must give 1. Opened from the measured-BRDF widget (BRDF page), ' +
  'the log plot adds the NDF a measurement implies (black) and puts every curve over its own peak, so the ' +
  'measured tail is read against the five shapes at the fitted width.';

/** The functions behind the pictures, linked to their rows on the parity page. */
export const TERMS_USED = ['ndfBlinnPhong', 'ndfBeckmann', 'ndfGGX', 'ndfABC', 'ndfSGD', 'microfacetBRDF'];

/** An NDF's matched parameters in words: "exponent 41.2", "a1 …, a2 …", "α …, p …" or "α …". */
export const describeParams = (key, p) =>
  key === 'blinnPhong'
    ? `exponent ${p.exponent.toFixed(1)}`
    : key === 'abc'
      ? `a1 ${p.a1.toFixed(2)}, a2 ${p.a2.toFixed(2)}`
      : key === 'sgd'
        ? `α ${p.alpha.toFixed(4)}, p ${p.p.toFixed(2)}`
        : `α ${p.alpha.toFixed(4)}`;

/** The spheres in words: the light, and each NDF with its parameters and peak. */
export function describeSpheres(curves, state) {
  const each = curves.map(
    (c) => `${c.label} (${describeParams(c.key, c.p)}, peak D ${c.values[0].toPrecision(3)} /sr)`,
  );
  return (
    `Spheres lit by one small light ${state.lightTheta}° from the view, exposure ${state.exposure}, F = 1 and ` +
    `V = 1, one per NDF at a half width of ${state.hwhm}°: ${each.join(', ') || 'none chosen'}.`
  );
}
