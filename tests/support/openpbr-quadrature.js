// Independent quadratures of a lobe's directional albedo ∫ g(l) (n·l) dω_l for the OpenPBR tests, v in the xz
// plane and g even in l's azimuth about it (every isotropic lobe here): over the half vector for a GGX-peaked
// lobe, over directions for the diffuse and fuzz lobes. Not the app's dfgSplitSum: written again here, plainer.
import { gaussLegendreVector } from '../../src/math/quadrature.js';
import { ndfGGX } from '../../src/math/ndf.js';

/** ∫ f(s) over [lo, hi] with x = lo + (hi − lo) s²(3 − 2s), n nodes: smooth across kinks at either end. */
function smoothed(f, lo, hi, n, dim) {
  if (!(hi > lo)) return new Float64Array(dim);
  return gaussLegendreVector(
    (s) => f(lo + (hi - lo) * s * s * (3 - 2 * s)).map((y) => y * 6 * s * (1 - s) * (hi - lo)),
    0,
    1,
    n,
    dim,
  );
}

/**
 * ∫ g(l)(n·l) dω_l with l = reflect(v, m) and m in the variables (r, φ) where GGX's D(m)(n·m) dω_m is
 * 2r dr dφ/2π (r = α / sqrt(α² + tan²θm)): E = ∫ 2r dr ∫ dφ/2π g(l) (n·l) 4(v·m)/(D(m)(n·m)). The r integral is
 * cut where l first and last meets the horizon; φ runs to φmax(r), its nodes crowded there. g returns `dim` values.
 */
export function albedoOverHalfVector(g, v, alpha, n = 64, dim = 3) {
  const [nv, sv] = [v[2], Math.hypot(v[0], v[1])];
  const a2 = alpha * alpha;
  const overPhi = (r) => {
    if (!(r > 0)) return new Array(dim).fill(0);
    const t2 = (a2 * (1 - r) * (1 + r)) / (r * r);
    const cm = 1 / Math.sqrt(1 + t2);
    const sm = Math.sqrt(t2) * cm;
    const c = (nv * (t2 - 1)) / (2 * sv * Math.sqrt(t2));
    const phiMax = !(sv > 0) || c <= -1 ? Math.PI : c >= 1 ? 0 : Math.acos(c);
    const d = ndfGGX(cm, alpha);
    const sum = gaussLegendreVector(
      (s) => {
        const q = 1 - s;
        const phi = phiMax - phiMax * q * q * q;
        const m = [sm * Math.cos(phi), sm * Math.sin(phi), cm];
        const vm = v[0] * m[0] + v[1] * m[1] + v[2] * m[2];
        const l = m.map((x, i) => 2 * vm * x - v[i]);
        if (!(l[2] > 0)) return new Array(dim).fill(0);
        const w = (3 * q * q * phiMax * l[2] * 4 * vm) / (d * cm);
        return [].concat(g(l)).map((y) => y * w);
      },
      0,
      1,
      n,
      dim,
    );
    return Array.from(sum, (y) => (2 * r * 2 * y) / (2 * Math.PI)); // φ over [0, φmax] is half of it
  };
  const rOf = (tan) => Math.sqrt(a2 / (a2 + tan * tan));
  const cuts = [...new Set([0, rOf((1 + sv) / nv), rOf(nv / (1 + sv)), 1])].sort((x, y) => x - y);
  const total = new Array(dim).fill(0);
  for (let k = 0; k + 1 < cuts.length; k++) {
    smoothed(overPhi, cuts[k], cuts[k + 1], n, dim).forEach((y, i) => (total[i] += y));
  }
  return total;
}

/** ∫ g(l)(n·l) dω_l over directions: μ = s², φ in [0, π] (doubled), n nodes each, cut at v's azimuth φ = 0. */
export function albedoOverDirections(g, n = 96, dim = 3) {
  return Array.from(
    gaussLegendreVector(
      (s) => {
        const mu = s * s;
        const st = Math.sqrt(1 - mu * mu);
        const row = gaussLegendreVector((phi) => g([st * Math.cos(phi), st * Math.sin(phi), mu]), 0, Math.PI, n, dim);
        return Array.from(row, (y) => 2 * y * mu * 2 * s);
      },
      0,
      1,
      n,
      dim,
    ),
  );
}
