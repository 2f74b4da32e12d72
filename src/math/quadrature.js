// Adaptive Gauss-Kronrod quadrature (the 7-point Gauss rule inside the 15-point Kronrod rule, as in QUADPACK's
// QK15): deterministic, exact for polynomials of degree 22 on each piece, and it halves only the pieces whose
// Gauss and Kronrod estimates disagree, so kinks and endpoint singularities cost a few levels of bisection.

// Kronrod abscissae (positive half; the last is 0) and weights, and the Gauss weights of x[1], x[3], x[5], x[7],
// QUADPACK's 33-digit values rounded to the 17 significant digits a double holds (each the nearest double)
const X = [
  0.99145537112081261, 0.94910791234275849, 0.8648644233597691, 0.74153118559939446, 0.58608723546769115,
  0.40584515137739718, 0.20778495500789848, 0,
];
const WK = [
  0.022935322010529224, 0.063092092629978558, 0.10479001032225019, 0.14065325971552592, 0.16900472663926791,
  0.19035057806478542, 0.20443294007529889, 0.20948214108472782,
];
const WG = [0.1294849661688697, 0.27970539148927664, 0.38183005050511892, 0.4179591836734694];

const MAX_PANELS = 500;

/**
 * One 15-point Kronrod estimate of ∫_a^b f for an f returning `dim` values, and its error estimate: QUADPACK's
 * |K - G| scaled by (200 |K - G| / I|f - mean|)^1.5, which tracks the true error of K closely on smooth pieces
 * (|K - G| alone is the error of the 7-point G, orders larger).
 */
function kronrod(f, a, b, dim) {
  const half = (b - a) / 2;
  const mid = (a + b) / 2;
  const k = new Float64Array(dim);
  const g = new Float64Array(dim);
  const ys = new Float64Array(15 * dim); // f's values, copied (f may hand back the same array each call)
  for (let n = 0; n < 15; n++) {
    const i = n >> 1; // nodes 2i and 2i + 1 are ∓X[i]; node 14 is the midpoint
    const y = f(n === 14 ? mid : mid + (n % 2 ? half : -half) * X[i]);
    for (let d = 0; d < dim; d++) {
      ys[n * dim + d] = y[d];
      k[d] += WK[i] * y[d];
      if (i % 2) g[d] += WG[(i - 1) / 2] * y[d];
    }
  }
  let err = 0;
  for (let d = 0; d < dim; d++) {
    const mean = k[d] / 2;
    let asc = 0; // ∫ |f - mean| by the Kronrod rule
    for (let n = 0; n < 15; n++) asc += WK[n >> 1] * Math.abs(ys[n * dim + d] - mean);
    const diff = Math.abs((k[d] - g[d]) * half);
    asc *= Math.abs(half);
    err = Math.max(err, asc > 0 && diff > 0 ? asc * Math.min(1, ((200 * diff) / asc) ** 1.5) : diff);
    k[d] *= half;
  }
  return { value: k, err };
}

/**
 * ∫_a^b f(x) dx for a vector-valued f (returning an array of `dim` numbers), to an absolute tolerance `tol`
 * on each component: globally adaptive (QUADPACK's QAG), it bisects the piece with the largest error estimate
 * until the estimates add up to less than tol (or MAX_PANELS pieces). f is evaluated only inside (a, b), never
 * at the ends, so an integrable singularity there is allowed.
 */
export function integrateVector(f, a, b, tol, dim) {
  if (!(b > a)) return new Float64Array(dim);
  const panels = [{ a, b, ...kronrod(f, a, b, dim) }];
  let error = panels[0].err;
  while (error > tol && panels.length < MAX_PANELS) {
    let worst = 0;
    for (let i = 1; i < panels.length; i++) if (panels[i].err > panels[worst].err) worst = i;
    const p = panels[worst];
    const m = (p.a + p.b) / 2;
    if (!(m > p.a && m < p.b)) break; // the piece cannot be halved in float64
    const left = { a: p.a, b: m, ...kronrod(f, p.a, m, dim) };
    const right = { a: m, b: p.b, ...kronrod(f, m, p.b, dim) };
    panels[worst] = left;
    panels.push(right);
    error += left.err + right.err - p.err;
  }
  const sum = new Float64Array(dim);
  for (const p of panels) for (let d = 0; d < dim; d++) sum[d] += p.value[d];
  return sum;
}

/** ∫_a^b f(x) dx for a scalar f, to the absolute tolerance `tol` (see integrateVector). */
export function integrate(f, a, b, tol = 1e-10) {
  return integrateVector((x) => [f(x)], a, b, tol, 1)[0];
}

const legendreCache = new Map();
/** Nodes and weights of the n-point Gauss-Legendre rule on [-1, 1] (Newton's method on P_n; exact to ~1e-15). */
export function gaussLegendre(n) {
  if (legendreCache.has(n)) return legendreCache.get(n);
  const x = new Float64Array(n);
  const w = new Float64Array(n);
  for (let i = 0; i < n; i++) {
    let z = Math.cos((Math.PI * (i + 0.75)) / (n + 0.5));
    let dp = 1;
    for (let it = 0; it < 100; it++) {
      let p0 = 1;
      let p1 = z;
      for (let k = 2; k <= n; k++) [p0, p1] = [p1, ((2 * k - 1) * z * p1 - (k - 1) * p0) / k];
      dp = (n * (z * p1 - p0)) / (z * z - 1);
      const dz = p1 / dp;
      z -= dz;
      if (Math.abs(dz) < 1e-16) break;
    }
    x[i] = z;
    w[i] = 2 / ((1 - z * z) * dp * dp);
  }
  const rule = { x, w };
  legendreCache.set(n, rule);
  return rule;
}

/** ∫_a^b f by the fixed n-point Gauss-Legendre rule, for an f returning `dim` values. */
export function gaussLegendreVector(f, a, b, n, dim) {
  const sum = new Float64Array(dim);
  if (!(b > a)) return sum;
  const { x, w } = gaussLegendre(n);
  const half = (b - a) / 2;
  for (let i = 0; i < n; i++) {
    const y = f(a + half * (1 + x[i]));
    for (let d = 0; d < dim; d++) sum[d] += w[i] * half * y[d];
  }
  return sum;
}
