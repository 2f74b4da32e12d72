// The directional albedo OpenPBR Surface's albedo scaling needs for its rough dielectric interfaces (the base's
// gloss over the diffuse lobe, the coat over the base): E(μ, α, η) = ∫ f (n·l) dω of the single-scattering GGX
// lobe with height-correlated Smith and the exact unpolarised dielectric Fresnel at relative index η ≥ 1, untinted
// (specular_color tints only the light the interface reflects, not what it lets through: the specification's
// "Dielectric base"). Computed in float64 by the split sum's quadrature (dfgSplitSum with that Fresnel), tabulated
// by `npm run openpbr-albedo` (scripts/openpbr-albedo.js) into openpbr-albedo.data.js, and read by one trilinear
// rule in JS and in GLSL (openPbrDielectricAlbedo in shaders/openpbr-albedo.glsl) so the two agree node for node.
import { dfgSplitSum } from './integrate.js';
import { fresnelDielectric } from './fresnel.js';
import { gaussLegendre } from './quadrature.js';
import { OPENPBR_ALBEDO_BASE64 } from './openpbr-albedo.data.js';

/**
 * Nodes per axis: x = cbrt(μ) (32), y = cbrt(α) (32), z = sqrt(r) with r = (η − 1)/(η + 1) (32; η = 1.5 is
 * z = 0.447, η = 3 is 0.707): F0 = r² goes as z⁴ and the grazing rise of F near η = 1 as z, and the square root
 * gave 1/30 of r's error there. Packed in one 64 × 128 RGBA float texture: slice k of z is channel k mod 4 of the
 * 32 × 32 block floor(k/4), the blocks two to a row.
 */
export const OPENPBR_ALBEDO_DIMS = Object.freeze({ mu: 32, alpha: 32, r: 32 });
export const OPENPBR_ALBEDO_SIZE = Object.freeze({ width: 64, height: 128 });
/** Gauss–Legendre nodes per piece of the quadrature the table is built with (1e-6 of the adaptive one). */
export const OPENPBR_ALBEDO_NODES = 16;
const ETA_AT_R1 = 1e6; // r = 1 is η = ∞ (F = 1); the quadrature takes a large finite η

/** z = sqrt(r), r = (η − 1)/(η + 1), for η ≥ 1 (below 1 is taken as 1), and its inverse. */
export const albedoAxisR = (eta) => Math.sqrt((Math.max(eta, 1) - 1) / (Math.max(eta, 1) + 1));
const etaOfR = (z) => (z < 1 ? (1 + z * z) / (1 - z * z) : ETA_AT_R1);

/** E(μ, α, η) by quadrature: adaptive to ~1e-7 (nodes = 0) or `nodes` Gauss–Legendre nodes per piece. */
export function dielectricAlbedoQuadrature(mu, alpha, eta, nodes = 0) {
  const fresnel = (c) => fresnelDielectric(c, eta);
  return dfgSplitSum(mu, alpha, {}, { nodes, fresnel })[0];
}

/** Texel offset (of 4 floats) and channel of node (i, j, k). */
function nodeIndex(i, j, k) {
  const { mu } = OPENPBR_ALBEDO_DIMS;
  const block = k >> 2;
  const x = i + mu * (block & 1);
  const y = j + mu * (block >> 1);
  return 4 * (y * OPENPBR_ALBEDO_SIZE.width + x) + (k & 3);
}

/** The table's node values, computed (the script's work: ~10 s). `albedo` may be replaced by a test. */
const tableQuadrature = (mu, a, eta) => dielectricAlbedoQuadrature(mu, a, eta, OPENPBR_ALBEDO_NODES);
export function buildOpenPbrAlbedoTable(albedo = tableQuadrature) {
  const { mu: nm, alpha: na, r: nr } = OPENPBR_ALBEDO_DIMS;
  const { width, height } = OPENPBR_ALBEDO_SIZE;
  const data = new Float32Array(width * height * 4);
  for (let k = 0; k < nr; k++) {
    const eta = etaOfR(k / (nr - 1));
    for (let j = 0; j < na; j++) {
      const alpha = (j / (na - 1)) ** 3;
      for (let i = 0; i < nm; i++) data[nodeIndex(i, j, k)] = albedo((i / (nm - 1)) ** 3, alpha, eta);
    }
  }
  return { width, height, data };
}

/** The shipped table, decoded once: { width, height, data } (little-endian float32, openpbr-albedo.data.js). */
let shipped = null;
export function openPbrAlbedoTable() {
  if (shipped) return shipped;
  const bytes = Uint8Array.from(atob(OPENPBR_ALBEDO_BASE64), (ch) => ch.charCodeAt(0));
  shipped = { ...OPENPBR_ALBEDO_SIZE, data: new Float32Array(bytes.buffer) };
  return shipped;
}

/**
 * The hemispherical average of the exact dielectric Fresnel, F̄(η) = 2∫F(μ, η) μ dμ = 4∫F(s², η) s³ ds, by the
 * 16-point Gauss–Legendre rule in s that the GLSL twin uses (its closed form cancels in float32 near η = 1; the
 * rule is within 2e-10 of it for η in (1, 10], 4e-9 at 100, tested).
 */
export function fresnelDielectricAverage(eta) {
  const { x, w } = gaussLegendre(16);
  let sum = 0;
  for (let i = 0; i < x.length; i++) {
    const s = 0.5 * (1 + x[i]);
    sum += 2 * w[i] * fresnelDielectric(s * s, eta) * s * s * s;
  }
  return sum;
}

/** Cell index and fraction of t in [0, 1] on n nodes. */
function cell(t, n) {
  const x = Math.min(Math.max(t, 0), 1) * (n - 1);
  const i = Math.min(Math.floor(x), n - 2);
  return [i, x - i];
}

/**
 * E(μ, α, η) from the table, trilinear in (cbrt μ, cbrt α, r), clamped to the table (η ≥ 1, α ≤ 1). For an
 * anisotropic lobe pass the α of the same mean square (OpenPBR's αt² + αb² = 2α²: α = roughness²).
 */
export function openPbrDielectricAlbedo(mu, alpha, eta, table = openPbrAlbedoTable()) {
  const { mu: nm, alpha: na, r: nr } = OPENPBR_ALBEDO_DIMS;
  const [i, fx] = cell(Math.cbrt(Math.max(mu, 0)), nm);
  const [j, fy] = cell(Math.cbrt(Math.max(alpha, 0)), na);
  const [k, fz] = cell(albedoAxisR(eta), nr);
  const at = (di, dj, dk) => table.data[nodeIndex(i + di, j + dj, k + dk)];
  const bilinear = (dk) => {
    const lo = at(0, 0, dk) + (at(1, 0, dk) - at(0, 0, dk)) * fx;
    const hi = at(0, 1, dk) + (at(1, 1, dk) - at(0, 1, dk)) * fx;
    return lo + (hi - lo) * fy;
  };
  const e0 = bilinear(0);
  return e0 + (bilinear(1) - e0) * fz;
}
