// Independent numerical integrals for the tests (not the app's own integrate.js).

/**
 * ∫ D(m)(n·m) dω for D depending on c = n·m only: 2π ∫_0^1 D(c) c dc, by the midpoint rule in t with
 * c = 1 - t^4, which puts most samples near c = 1 where narrow lobes live.
 */
export function projectedNdfIntegral(D, n = 40000) {
  let sum = 0;
  for (let i = 0; i < n; i++) {
    const t = (i + 0.5) / n;
    const c = 1 - t ** 4;
    sum += D(c) * c * 4 * t ** 3;
  }
  return (2 * Math.PI * sum) / n;
}

// The 10-point Gauss-Legendre rule on [-1, 1] (Abramowitz & Stegun, table 25.4), positive half.
const GL10_X = [0.1488743389816312, 0.4333953941292472, 0.6794095682990244, 0.8650633666889845, 0.9739065285171717];
const GL10_W = [0.2955242247147529, 0.2692667193099963, 0.219086362515982, 0.1494513491505806, 0.0666713443086881];

/** ∫ g over consecutive pieces [cuts[k], cuts[k + 1]], 10-point Gauss-Legendre on each. */
function piecewiseGauss(g, cuts) {
  let sum = 0;
  for (let k = 0; k + 1 < cuts.length; k++) {
    const mid = (cuts[k] + cuts[k + 1]) / 2;
    const half = (cuts[k + 1] - cuts[k]) / 2;
    for (let i = 0; i < 5; i++) sum += GL10_W[i] * half * (g(mid - half * GL10_X[i]) + g(mid + half * GL10_X[i]));
  }
  return sum;
}

/** Cuts of [lo, hi] that shrink geometrically (ratio 1.5, down to `finest`) toward `at`, none longer than `longest`. */
function gradedCuts(lo, hi, at, finest, longest) {
  const cuts = new Set([lo, at, hi]);
  for (let x = at, d = finest; x > lo; d = Math.min(d * 1.5, longest)) cuts.add(Math.max((x -= d), lo));
  for (let x = at, d = finest; x < hi; d = Math.min(d * 1.5, longest)) cuts.add(Math.min((x += d), hi));
  return [...cuts].sort((a, b) => a - b);
}

/**
 * Directional albedo ∫ f(l)(n·l) dω over the LIGHT direction l = (θ, φ), for a view at polar angle thetaV in the
 * x-z plane: 2 ∫_0^{π/2} cos θ sin θ ∫_0^π f dφ dθ (f even in φ), by Gauss-Legendre on pieces graded toward
 * the mirror direction (θv, π), the finest `width`/20 (width: the lobe's angular width), none longer than
 * `longest` (short pieces keep a kink of f, which no piece is aligned with, from costing accuracy).
 */
export function albedoOverLight(f, thetaV, width, longest = Math.PI / 8) {
  const finest = width / 20;
  return 2 * piecewiseGauss((theta) => {
    const st = Math.sin(theta);
    const ct = Math.cos(theta);
    const phiCuts = gradedCuts(0, Math.PI, Math.PI, Math.min(finest / Math.max(st, 1e-12), longest), longest);
    return st * ct * piecewiseGauss((phi) => f([st * Math.cos(phi), st * Math.sin(phi), ct]), phiCuts);
  }, gradedCuts(0, Math.PI / 2, thetaV, finest, longest));
}
