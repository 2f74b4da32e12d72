// Independent numerical integrals for the tests (not the app's own integrate.js).
import { gaussLegendre } from '../../src/math/quadrature.js';

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
  return (
    2 *
    piecewiseGauss(
      (theta) => {
        const st = Math.sin(theta);
        const ct = Math.cos(theta);
        const phiCuts = gradedCuts(0, Math.PI, Math.PI, Math.min(finest / Math.max(st, 1e-12), longest), longest);
        return st * ct * piecewiseGauss((phi) => f([st * Math.cos(phi), st * Math.sin(phi), ct]), phiCuts);
      },
      gradedCuts(0, Math.PI / 2, thetaV, finest, longest),
    )
  );
}

/** ∫_a^b g(x) dx by a Gauss–Legendre rule ({ x, w } of quadrature.js). */
export function integrateGL(g, a, b, rule) {
  const h = (b - a) / 2;
  return h * rule.x.reduce((sum, x, i) => sum + rule.w[i] * g(a + h * (x + 1)), 0);
}

/** ∫_a^b g by Gauss–Legendre on panels no wider than `width`. */
function panels(g, a, b, rule, width) {
  const k = Math.max(1, Math.ceil((b - a) / width));
  let sum = 0;
  for (let i = 0; i < k; i++) sum += integrateGL(g, a + ((b - a) * i) / k, a + ((b - a) * (i + 1)) / k, rule);
  return sum;
}

/** ∫_a^b g with panels shrinking geometrically towards b (for a sharp feature at b). */
function gradedTowards(g, a, b, rule, ratio = 0.25, levels = 14) {
  let sum = 0;
  let hi = b - (b - a);
  for (let k = 1; k <= levels; k++) {
    const next = b - (b - a) * ratio ** k;
    sum += integrateGL(g, hi, next, rule);
    hi = next;
  }
  return sum + integrateGL(g, hi, b, rule);
}

/** Largest x in [lo, hi] with f(x) <= target, for f increasing (bisection). */
function bisect(f, target, lo, hi) {
  for (let i = 0; i < 200; i++) {
    const mid = (lo + hi) / 2;
    if (f(mid) <= target) lo = mid;
    else hi = mid;
  }
  return lo;
}

/**
 * Directional albedo of GGX with height-correlated Smith and F = 1, deterministically and independently of
 * integrate.js: nested Gauss–Legendre over the microfacet normal m. The polar variable is y = ln(tan θm / alpha),
 * in which D(m)(n·m) dω_m = 2 r/(1 + r)² dy dφ/2π with r = e^{2y} (smooth at every roughness). The reflected
 * direction stays above the horizon for cos φ > c*(y) = cos θv (1 - 2 cos²θm)/(2 cos θm sin θv sin θm), so φ
 * runs over [0, acos c*], on panels graded towards the cut-off (where n·l → 0 and, at grazing v, V(n·l) n·l
 * turns sharply); the y range is split where the cut-off appears (c* = -1: a square-root kink, smoothed by
 * y = y1 + L s²) and where nothing is left (c* = 1). Integrand: V (n·l)(v·m)/(n·m), from
 * f (n·l) dω_l = D V (n·l)(v·m) dω_m; times Schlick's F(v·m) at f0 when f0 < 1.
 */
export function albedoGGXQuadrature(mu, alpha, n = 24, f0 = 1) {
  const cv = Math.min(Math.max(mu, 1e-6), 1);
  const sv = Math.sqrt((1 - cv) * (1 + cv));
  const a = Math.min(Math.max(alpha, 1e-4), 1);
  const a2 = a * a;
  const rule = gaussLegendre(n);
  const normal = (y) => {
    const t2 = a2 * Math.exp(2 * y);
    const cm = 1 / Math.sqrt(1 + t2);
    return [cm, Math.sqrt(t2) * cm];
  };
  const cutoff = (y) => {
    const [cm, sm] = normal(y);
    const num = cv * (1 - 2 * cm * cm);
    const den = 2 * cm * sv * sm;
    return den > 0 ? num / den : num > 0 ? Infinity : -Infinity;
  };
  const V = (nl) => 2 / (nl * Math.sqrt(cv * cv + a2 * sv * sv) + cv * Math.sqrt(nl * nl + a2 * (1 - nl * nl)));
  const inner = (y) => {
    const [cm, sm] = normal(y);
    const c = cutoff(y);
    if (c >= 1) return 0;
    const g = (phi) => {
      const vm = sv * sm * Math.cos(phi) + cv * cm;
      const nl = 2 * vm * cm - cv;
      return nl > 0 && vm > 0 ? (V(nl) * nl * vm * (f0 + (1 - f0) * (1 - vm) ** 5)) / cm : 0;
    };
    const r = Math.exp(2 * y);
    const weight = (2 * r) / ((1 + r) * (1 + r)) / Math.PI;
    return weight * (c <= -1 ? integrateGL(g, 0, Math.PI, rule) : gradedTowards(g, 0, Math.acos(c), rule));
  };
  const [lo, hi] = [-25, 25]; // r(1 + r)^-2 < 2e-22 beyond
  const y1 = bisect(cutoff, -1, lo, hi);
  const y2 = bisect(cutoff, 1, y1, hi);
  const L = Math.min(1, y2 - y1);
  const kink = integrateGL((s) => inner(y1 + L * s * s) * 2 * L * s, 0, 1, rule);
  return panels(inner, lo, y1, rule, 1) + kink + panels(inner, y1 + L, y2, rule, 1);
}
