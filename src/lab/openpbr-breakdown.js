// What each layer of an OpenPBR material adds, for the material lab's bars: under the punctual light, the mean
// radiance of each part of openPbrLayers over the lab's sphere (π f c_light (n·l), view along -z); and in the white
// furnace, each part's directional albedo E = ∫ f (n·l) dω (GGX-sampled over the half vector for the microfacet
// lobes, the midpoint rule over directions for the diffuse and fuzz lobes, as src/math/integrate.js does them).
import { openPbrBaseRoughness, openPbrLayers, openPbrMaterial } from '../math/openpbr.js';
import { hammersley, hemisphereIntegral, reflect, sampleGGXNormal } from '../math/integrate.js';
import { ndfGGX } from '../math/ndf.js';

export const PARTS = Object.freeze(['diffuse', 'specular', 'metal', 'coat', 'fuzz']);
const zero = () => Object.fromEntries(PARTS.map((p) => [p, [0, 0, 0]]));
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

/** n and two tangents about it (any: the bars are of isotropic materials' means; a stretched lobe turns with it). */
function frame(n) {
  const up = Math.abs(n[2]) < 0.999 ? [0, 0, 1] : [1, 0, 0];
  const t = [up[1] * n[2] - up[2] * n[1], up[2] * n[0] - up[0] * n[2], up[0] * n[1] - up[1] * n[0]];
  const lt = Math.hypot(...t);
  const x = t.map((c) => c / lt);
  const y = [n[1] * x[2] - n[2] * x[1], n[2] * x[0] - n[0] * x[2], n[0] * x[1] - n[1] * x[0]];
  return (w) => [dot(w, x), dot(w, y), dot(w, n)];
}

/**
 * The mean over the sphere's disc (a `grid` × `grid` lattice of its view) of each part's radiance under the punctual
 * light from view-space direction `dir` with c_light `cLight` ([r, g, b]): { diffuse, specular, metal, coat, fuzz }.
 */
export function openPbrLightBreakdown(material, dir, cLight, grid = 24) {
  const m = openPbrMaterial(material);
  const out = zero();
  let count = 0;
  for (let j = 0; j < grid; j++) {
    for (let i = 0; i < grid; i++) {
      const [x, y] = [(2 * (i + 0.5)) / grid - 1, (2 * (j + 0.5)) / grid - 1];
      const r2 = x * x + y * y;
      if (r2 >= 1) continue;
      count++;
      const toLocal = frame([x, y, Math.sqrt(1 - r2)]);
      const l = toLocal(dir);
      const parts = openPbrLayers(l, toLocal([0, 0, 1]), m);
      for (const p of PARTS) for (let c = 0; c < 3; c++) out[p][c] += Math.PI * parts[p][c] * cLight[c] * l[2];
    }
  }
  for (const p of PARTS) out[p] = out[p].map((s) => s / count);
  return out;
}

/** ∫ (the parts `keys` of openPbrLayers) (n·l) dω by GGX-sampled half vectors of α `alpha`, `n` Hammersley points. */
function overHalfVector(m, v, alpha, keys, n, out) {
  for (let i = 0; i < n; i++) {
    const h = sampleGGXNormal(...hammersley(i, n), alpha);
    const vh = dot(v, h);
    const l = vh > 0 ? reflect(v, h) : null;
    if (!l || l[2] <= 0) continue;
    const w = (4 * vh * l[2]) / (ndfGGX(h[2], alpha) * h[2] * n);
    const parts = openPbrLayers(l, v, m);
    for (const k of keys) for (let c = 0; c < 3; c++) out[k][c] += parts[k][c] * w;
  }
}

/**
 * Each part's directional albedo at cos θv = mu ({ diffuse, specular, metal, coat, fuzz, total }, [r, g, b]), for an
 * isotropic material (a stretched lobe is taken at the α of the same mean square). `samples`: per microfacet lobe.
 */
export function openPbrFurnace(material, mu, samples = 1024) {
  const m = openPbrMaterial(material);
  const v = [Math.sqrt((1 - mu) * (1 + mu)), 0, mu];
  const out = zero();
  const rBase = openPbrBaseRoughness(m);
  overHalfVector(m, v, Math.max(rBase * rBase, 1e-4), ['specular', 'metal'], samples, out);
  if (m.coat_weight > 0) overHalfVector(m, v, Math.max(m.coat_roughness ** 2, 1e-4), ['coat'], samples, out);
  for (const k of ['diffuse', 'fuzz']) {
    for (let c = 0; c < 3; c++) out[k][c] = hemisphereIntegral((l) => openPbrLayers(l, v, m)[k][c], 12);
  }
  const total = [0, 1, 2].map((c) => PARTS.reduce((s, p) => s + out[p][c], 0));
  return { ...out, total };
}

/** The material with every colour white: its furnace shows what the stack itself loses (1 − E). */
export const whiteStack = (material) => ({
  ...material,
  base_color: [1, 1, 1],
  specular_color: [1, 1, 1],
  coat_color: [1, 1, 1],
  fuzz_color: [1, 1, 1],
});
