// The downhill simplex method of Nelder and Mead (1965), with the usual coefficients (reflection 1,
// expansion 2, contraction 1/2, shrink 1/2). Small, derivative-free, enough for one or two shape parameters.

/**
 * Minimises f over R^n from x0. options: { step (initial simplex edge, per coordinate), maxEvaluations,
 * xTolerance (stop when every vertex is this close to the best), fTolerance (and f differs by less) }.
 * Returns { x, f, evaluations }.
 */
export function nelderMead(f, x0, { step = 0.5, maxEvaluations = 400, xTolerance = 1e-8, fTolerance = 1e-14 } = {}) {
  const n = x0.length;
  let evaluations = 0;
  const at = (x) => {
    evaluations++;
    return { x, f: f(x) };
  };
  let simplex = [at([...x0]), ...x0.map((_, i) => at(x0.map((x, j) => (i === j ? x + step : x))))];
  const along = (a, b, t) => a.map((ai, i) => ai + t * (b[i] - ai)); // a + t (b - a)
  while (evaluations < maxEvaluations) {
    simplex.sort((a, b) => a.f - b.f);
    const [best, worst] = [simplex[0], simplex[n]];
    const spread = Math.max(...simplex.map((p) => Math.max(...p.x.map((x, i) => Math.abs(x - best.x[i])))));
    if (spread < xTolerance && worst.f - best.f <= fTolerance * (1 + Math.abs(best.f))) break;
    const centroid = x0.map((_, i) => simplex.slice(0, n).reduce((s, p) => s + p.x[i], 0) / n);
    const reflected = at(along(centroid, worst.x, -1));
    if (reflected.f < best.f) {
      const expanded = at(along(centroid, worst.x, -2));
      simplex[n] = expanded.f < reflected.f ? expanded : reflected;
    } else if (reflected.f < simplex[n - 1].f) {
      simplex[n] = reflected;
    } else {
      const outside = reflected.f < worst.f;
      const contracted = at(along(centroid, outside ? reflected.x : worst.x, 0.5));
      if (contracted.f < Math.min(worst.f, reflected.f)) simplex[n] = contracted;
      else simplex = [best, ...simplex.slice(1).map((p) => at(along(best.x, p.x, 0.5)))];
    }
  }
  simplex.sort((a, b) => a.f - b.f);
  return { x: simplex[0].x, f: simplex[0].f, evaluations };
}
