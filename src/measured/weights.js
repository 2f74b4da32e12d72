// The linear part of a fit: for one channel, f = cdiff/pi + f0 · S (1 - s5) + S s5 with S = D V / 4 and
// s5 = (1 - l·h)^5 (Schlick), so f is linear in (cdiff, f0). They are found by minimising the cube-root
// error Σ w (f^(1/3) - m^(1/3))² (see fit.js) with Gauss-Newton, each step a least-squares problem solved
// exactly over the box cdiff ≥ 0, 0 ≤ f0 ≤ 1.

const TINY = 1e-12;
const ITERATIONS = 20;

/** argmin over the box x1 ≥ 0, 0 ≤ x2 ≤ 1 of q(x) = xᵀAx - 2gᵀx (A symmetric, positive semi-definite). */
export function boxQuadratic(a11, a12, a22, g1, g2) {
  const q = ([x1, x2]) => a11 * x1 * x1 + 2 * a12 * x1 * x2 + a22 * x2 * x2 - 2 * (g1 * x1 + g2 * x2);
  const det = a11 * a22 - a12 * a12;
  if (det > TINY * (a11 * a22 + TINY)) {
    const x = [(a22 * g1 - a12 * g2) / det, (a11 * g2 - a12 * g1) / det];
    if (x[0] >= 0 && x[1] >= 0 && x[1] <= 1) return x;
  }
  const ratio = (num, den) => (den > 0 ? num / den : 0);
  const candidates = [
    [0, Math.min(Math.max(ratio(g2, a22), 0), 1)],
    [Math.max(ratio(g1, a11), 0), 0],
    [Math.max(ratio(g1 - a12, a11), 0), 1],
  ];
  return candidates.reduce((best, x) => (q(x) < q(best) ? x : best));
}

/**
 * cdiff and f0 of channel c. samples: { count, w, s5, cbrtM: [r, g, b], relativeW: [r, g, b] } (typed
 * arrays; relativeW = w / (m + floor)^(4/3), the first fit's weights); S: D V / 4 per sample.
 * Returns { cdiff, f0, sumSq } with sumSq = Σ w (f^(1/3) - m^(1/3))².
 */
export function solveWeights(samples, S, c) {
  const { count, w, s5 } = samples;
  const [cm, rw] = [samples.cbrtM[c], samples.relativeW[c]];
  const a = 1 / Math.PI;
  // One pass at x: the error there and the normal equations of the next Gauss-Newton step (or, with
  // relative = true, of the least-squares fit Σ rw (f - m)², which starts the iteration).
  const pass = (x, relative) => {
    let [a11, a12, a22, g1, g2, e] = [0, 0, 0, 0, 0, 0];
    for (let s = 0; s < count; s++) {
      const b = S[s] * (1 - s5[s]);
      const k = S[s] * s5[s];
      let om;
      let y;
      if (relative) {
        om = rw[s];
        y = cm[s] * cm[s] * cm[s] - k;
      } else {
        const f = Math.max(a * x[0] + b * x[1] + k, TINY);
        const r = Math.cbrt(f);
        e += w[s] * (r - cm[s]) ** 2;
        const d = 1 / (3 * r * r); // f^(1/3) ≈ r + d (f' - f)
        om = w[s] * d * d;
        y = f - k - (r - cm[s]) / d;
      }
      a11 += om * a * a;
      a12 += om * a * b;
      a22 += om * b * b;
      g1 += om * a * y;
      g2 += om * b * y;
    }
    return { e, next: boxQuadratic(a11, a12, a22, g1, g2) };
  };
  let x = pass(null, true).next;
  let best = null;
  for (let it = 0; it < ITERATIONS; it++) {
    const { e, next } = pass(x, false);
    if (best && !(e < best.e)) {
      if (Math.abs(x[0] - best.x[0]) + Math.abs(x[1] - best.x[1]) < 1e-12) break;
      x = [(x[0] + best.x[0]) / 2, (x[1] + best.x[1]) / 2]; // overshot: damp towards the best point
      continue;
    }
    const converged = best && best.e - e <= 1e-13 * best.e;
    best = { x, e };
    if (converged) break;
    x = next;
  }
  return { cdiff: best.x[0], f0: best.x[1], sumSq: best.e };
}
