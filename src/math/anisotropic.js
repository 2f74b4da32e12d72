// Anisotropic microfacets: the distribution stretched along a tangent. Frame: x = t (tangent), y = b (bitangent),
// z = n; every direction a unit vector given by its components, so sin²θ and the azimuth come from x and y with
// no 1 - cos² to cancel. The forms are Heitz 2014 ("Understanding the Masking-Shadowing Function in
// Microfacet-Based BRDFs", JCGT 3(2)): D stretched in slope space by (alphaX, alphaY), and
// Smith's Λ with the roughness projected on the direction's azimuth, α(φ)² = cos²φ αx² + sin²φ αy².
// Twins in shaders/anisotropic.glsl (held to these by the parity rows in src/core/gpu/parity-cases/anisotropic.js).
import { ALPHA_MIN } from './ndf.js';
import { ALPHA_ANISO_MAX } from './catalogue/parameters.js';
import { erfc } from './special.js';

/**
 * Largest roughness per axis the anisotropic functions take: Burley's mapping reaches α/√0.1 ≈ 3.2 α and OpenPBR's
 * √2 α, and the isotropic clamp at 1 would change their models. alphaX and alphaY are clamped to [ALPHA_MIN, 4].
 */
export { ALPHA_ANISO_MAX };
const clampAxis = (a) => Math.min(Math.max(a, ALPHA_MIN), ALPHA_ANISO_MAX);

/** hx²/αx² + hy²/αy²: the squared slope of m in the stretched space, times hz² (tan² of the stretched normal). */
const stretchedSin2 = (hx, hy, ax, ay) => (hx / ax) ** 2 + (hy / ay) ** 2;

/** αx² wx² + αy² wy² = α(φ)² sin²θ: the projected roughness times sin²θ, from components. */
const projectedSin2 = (wx, wy, ax, ay) => (ax * wx) ** 2 + (ay * wy) ** 2;

/**
 * Anisotropic GGX (Heitz 2014): 1 / (π αx αy (hx²/αx² + hy²/αy² + hz²)²), 0 for hz <= 0. With αx = αy = α
 * it is ndfGGXFromSin2(hz, hx² + hy², α) exactly. No term cancels: every part of the sum is positive.
 */
export function ndfGGXAniso(hx, hy, hz, alphaX, alphaY) {
  if (!(hz > 0)) return 0;
  const [ax, ay] = [clampAxis(alphaX), clampAxis(alphaY)];
  const d = stretchedSin2(hx, hy, ax, ay) + hz * hz;
  return 1 / (Math.PI * ax * ay * d * d);
}

/**
 * Anisotropic Beckmann (Heitz 2014): exp(-(hx²/αx² + hy²/αy²)/hz²) / (π αx αy hz⁴), 0 for hz <= 0 and where
 * the exponential falls below e^-80 (compared before dividing, so hz⁴ never underflows into 0·Inf).
 */
export function ndfBeckmannAniso(hx, hy, hz, alphaX, alphaY) {
  if (!(hz > 0)) return 0;
  const [ax, ay] = [clampAxis(alphaX), clampAxis(alphaY)];
  const q = stretchedSin2(hx, hy, ax, ay);
  const c2 = hz * hz;
  if (q > 80 * c2) return 0;
  return Math.exp(-q / c2) / (Math.PI * ax * ay * c2 * c2);
}

/**
 * sqrt(wz² + αx² wx² + αy² wy²) = wz (1 + 2Λ(w)) for GGX: the root of every anisotropic Smith GGX form (the
 * isotropic ggxRoot of visibility.js with α² sin² from components).
 */
const ggxAnisoRoot = (wx, wy, wz, ax, ay) => Math.sqrt(wz * wz + projectedSin2(wx, wy, ax, ay));

/** Smith G1 for anisotropic GGX: 1/(1 + Λ) = 2 wz / (wz + sqrt(wz² + αx² wx² + αy² wy²)); 0 for wz <= 0. */
export function smithG1GGXAniso(wx, wy, wz, alphaX, alphaY) {
  if (!(wz > 0)) return 0;
  return (2 * wz) / (wz + ggxAnisoRoot(wx, wy, wz, clampAxis(alphaX), clampAxis(alphaY)));
}

/**
 * Smith G1 for anisotropic Beckmann: 1/(1 + Λ(a)), a = wz / sqrt(αx² wx² + αy² wy²) = cot θ / α(φ),
 * Λ(a) = (exp(-a²)/(a √π) - erfc(a)) / 2; 1 along n (a = ∞) and once Λ < 1e-290 (a > 26), 0 for wz <= 0.
 */
export function smithG1BeckmannAniso(wx, wy, wz, alphaX, alphaY) {
  if (!(wz > 0)) return 0;
  const p = Math.sqrt(projectedSin2(wx, wy, clampAxis(alphaX), clampAxis(alphaY)));
  if (!(wz < 26 * p)) return 1;
  const a = wz / p;
  return 1 / (1 + (Math.exp(-a * a) / (a * Math.sqrt(Math.PI)) - erfc(a)) / 2);
}

/**
 * Height-correlated Smith for anisotropic GGX (Heitz 2014, eq. 99, with the anisotropic Λ), in the app's
 * V = G2/((n·l)(n·v)):
 *   V = 2 / (vz sqrt(lz² + αx² lx² + αy² ly²) + lz sqrt(vz² + αx² vx² + αy² vy²)),
 * four times Filament's V_SmithGGXCorrelated_Anisotropic (which folds in the BRDF's 1/4). 0 below the horizon.
 */
export function visibilitySmithGGXCorrelatedAniso(lx, ly, lz, vx, vy, vz, alphaX, alphaY) {
  if (!(lz > 0 && vz > 0)) return 0;
  const [ax, ay] = [clampAxis(alphaX), clampAxis(alphaY)];
  return 2 / (vz * ggxAnisoRoot(lx, ly, lz, ax, ay) + lz * ggxAnisoRoot(vx, vy, vz, ax, ay));
}

const mix = (x, y, m) => x * (1 - m) + y * m;

/**
 * The three mappings from one roughness and an anisotropy a in [0, 1] (clamped) to [alphaX, alphaY], alpha being
 * the isotropic α = r² of each model. Every one stretches along the tangent (alphaX >= alphaY):
 *  - 'burley2012': Burley 2012 ("Physically-Based Shading at Disney", SIGGRAPH course notes), aspect = sqrt(1 - 0.9 a),
 *    [α / aspect, α aspect]: the geometric mean stays α;
 *  - 'gltf': KHR_materials_anisotropy (Khronos glTF extension, "Anisotropy"), [mix(α, 1, a²), α]: the tangent's
 *    α rises towards 1, the bitangent's stays the material's;
 *  - 'openpbr': OpenPBR Surface 1.1 (ASWF, v1.1.1, "Microfacet model"), αt = α sqrt(2 / (1 + (1 - a)²)),
 *    αb = (1 - a) αt: the mean of the squares stays α².
 * Returned as the models define them (no clamp: the functions above clamp to [ALPHA_MIN, ALPHA_ANISO_MAX]).
 */
export function anisotropicAlphas(alpha, anisotropy, convention) {
  const a = Math.min(Math.max(anisotropy, 0), 1);
  if (convention === 'burley2012') {
    const aspect = Math.sqrt(1 - 0.9 * a);
    return [alpha / aspect, alpha * aspect];
  }
  if (convention === 'gltf') return [mix(alpha, 1, a * a), alpha];
  if (convention === 'openpbr') {
    const at = alpha * Math.sqrt(2 / (1 + (1 - a) ** 2));
    return [at, (1 - a) * at];
  }
  throw new Error(`anisotropicAlphas: unknown convention "${convention}" (burley2012, gltf or openpbr)`);
}

/** The conventions anisotropicAlphas knows, in the order a page lists them. */
export const ANISOTROPY_CONVENTIONS = Object.freeze(['burley2012', 'gltf', 'openpbr']);

/**
 * A GGX normal drawn from the normals visible from v = (vx, vy, vz), density D_v(m) = G1(v) max(0, v·m) D(m) / vz
 * (Heitz 2018, "Sampling the GGX Distribution of Visible Normals", JCGT 7(4)), by Dupuy & Benyoub 2023 ("Sampling
 * Visible GGX Normals with Spherical Caps"): stretch v to α = 1 (v'), where the visible normals are normalize(c + v')
 * for c uniform on the unit sphere's cap c.z >= -v'.z; unstretch. u1 in [0, 1) sets the cap height, u2 the azimuth,
 * measured here from v''s own azimuth e (the listing measures it from t: the same density, rotated).
 * For float32 the sums are kept free of cancellation: 1 - w is never formed (w = v'.z rounds to 1 within 3e-4 rad
 * of n), ρ² = |v'.xy|² comes from the components, and with c.z = (1 - u1)(1 + w) - w,
 *   sin²θc = (1 - c.z)(1 + c.z) = u1 (ρ² + (1 - u1)(1 + w)²),  c.z + w = (1 - u1)(1 + w);
 * along e, where c + v' nearly vanishes near the rim (u1 -> 1, azimuth opposite e), with ψ = 2π u2,
 *   ρ + sin θc cos ψ = (ρ - sin θc) + 2 sin θc cos²(ψ/2),  ρ - sin θc = (1 - u1)(ρ² - u1 (1 + w)²) / (ρ + sin θc),
 * used where cos ψ < 0, so an error in cos(ψ/2) (a GPU's cos) enters squared where the terms would cancel; cos ψ
 * itself is (cos - sin)(cos + sin) of ψ/2. Only the rim's point c = -v'
 * gives m = 0: there n is returned.
 */
export function sampleVisibleNormalGGXAniso(vx, vy, vz, alphaX, alphaY, u1, u2) {
  const [ax, ay] = [clampAxis(alphaX), clampAxis(alphaY)];
  const len = Math.hypot(ax * vx, ay * vy, vz);
  const [x, y, w] = [(ax * vx) / len, (ay * vy) / len, vz / len];
  const rho2 = x * x + y * y;
  const rho = Math.sqrt(rho2);
  const [ex, ey] = rho > 0 ? [x / rho, y / rho] : [1, 0];
  const w1 = 1 + w;
  const sinC = Math.sqrt(u1 * (rho2 + (1 - u1) * w1 * w1));
  const rs = rho + sinC;
  const rhoMinusSin = rs > 0 ? ((1 - u1) * (rho2 - u1 * w1 * w1)) / rs : 0;
  // cos and sin of ψ/2 = π u2 as sines of arguments within π/2 of 0, where a float32 sine is relatively exact: c is
  // then exactly 0 at u2 = 1/2 (cos(π u2) would give float32 π's 4e-8, the rim's 0.33 at grazing v, αx = 4)
  const c = Math.sin(Math.PI * (0.5 - u2));
  const s = Math.sin(Math.PI * Math.min(u2, 1 - u2));
  const cosPsi = (c - s) * (c + s);
  // (c + v')·e: directly where nothing cancels (cos ψ >= 0), by the rim's form where it would
  const along = cosPsi >= 0 ? rho + sinC * cosPsi : rhoMinusSin + 2 * sinC * c * c;
  const across = 2 * sinC * s * c; // (c + v')·(e rotated by 90°)
  const hx = ax * (along * ex - across * ey);
  const hy = ay * (along * ey + across * ex);
  const hz = (1 - u1) * w1;
  const m = Math.hypot(hx, hy, hz);
  return m > 0 ? [hx / m, hy / m, hz / m] : [0, 0, 1];
}

/**
 * The density sampleVisibleNormalGGXAniso draws m with, per steradian of m: G1(v) max(0, v·m) D(m) / vz, written
 * 2 max(0, v·m) D(m) / (vz + sqrt(vz² + αx² vx² + αy² vy²)) so that grazing v divides by nothing small. 0 for
 * vz <= 0.
 */
export function visibleNormalPdfGGXAniso(vx, vy, vz, mx, my, mz, alphaX, alphaY) {
  if (!(vz > 0)) return 0;
  const vm = vx * mx + vy * my + vz * mz;
  if (!(vm > 0)) return 0;
  const root = ggxAnisoRoot(vx, vy, vz, clampAxis(alphaX), clampAxis(alphaY));
  return (2 * vm * ndfGGXAniso(mx, my, mz, alphaX, alphaY)) / (vz + root);
}

/**
 * Per steradian of l = reflect(v, m) for m from sampleVisibleNormalGGXAniso: D_v(m) / (4 v·m) = G1(v) D(m) / (4 vz),
 * i.e. D(m) / (2 (vz + sqrt(vz² + αx² vx² + αy² vy²))); 0 where v·m <= 0 (no such m is drawn).
 */
export function reflectedPdfGGXAniso(vx, vy, vz, mx, my, mz, alphaX, alphaY) {
  if (!(vz > 0) || !(vx * mx + vy * my + vz * mz > 0)) return 0;
  const root = ggxAnisoRoot(vx, vy, vz, clampAxis(alphaX), clampAxis(alphaY));
  return ndfGGXAniso(mx, my, mz, alphaX, alphaY) / (2 * (vz + root));
}

/**
 * The bent reflection vector of Filament's and three.js's anisotropic image-based lighting (Filament, "Lighting:
 * image based lights: anisotropy"; three.js's getIBLAnisotropyRadiance): a prefiltered map has no anisotropic form,
 * so the stretched highlight is drawn by moving the one direction it is read in. The grain (the brushing lines) is
 * b for a >= 0 (stretched along t, αx >= αy) and t for a < 0; v less its part along the grain is mixed into n with
 * weight (1 - |a| (1 - √α))⁴, three.js's weighting with √α its perceptual roughness, and v is mirrored about the
 * result. a is clamped to [-1, 1], α to [0, 1]; v along the grain (nothing left across it) gives the mirror about n.
 * Returns [rx, ry, rz] in the tangent frame (x = t, y = b, z = n). Twin in shaders/anisotropic.glsl.
 */
export function anisotropicBentReflection(vx, vy, vz, alpha, anisotropy) {
  const a = Math.min(Math.max(anisotropy, -1), 1);
  const [cx, cy] = a >= 0 ? [vx, 0] : [0, vy]; // v less its part along the grain
  const across2 = cx * cx + cy * cy + vz * vz;
  let [nx, ny, nz] = [0, 0, 1];
  if (!(across2 < 1e-12)) {
    const k = 1 - Math.abs(a) * (1 - Math.sqrt(Math.min(Math.max(alpha, 0), 1)));
    const toN = k * k * k * k;
    const s = (1 - toN) / Math.sqrt(across2);
    [nx, ny, nz] = [cx * s, cy * s, vz * s + toN];
    const len = Math.hypot(nx, ny, nz);
    [nx, ny, nz] = [nx / len, ny / len, nz / len];
  }
  const d = 2 * (nx * vx + ny * vy + nz * vz);
  return [d * nx - vx, d * ny - vy, d * nz - vz];
}
