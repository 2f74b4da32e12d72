// The directional albedo ∫ f (n·l) dω of openPbrBRDF at view v, layer by layer (openPbrLayers), each by the
// quadrature that suits it: the microfacet lobes over their half vectors, the diffuse and fuzz lobes over
// directions. For the furnace and random-walk tests; isotropic materials only (the quadratures assume a lobe
// even about v's plane).
import { openPbrBaseRoughness, openPbrLayers, openPbrMaterial } from '../../src/math/openpbr.js';
import { albedoOverDirections, albedoOverHalfVector } from './openpbr-quadrature.js';

/** { specular, diffuse, metal, coat, fuzz, total }: each [r, g, b], at cos θv = mu (v in the xz plane). */
export function openPbrAlbedo(material, mu, n = 64) {
  const m = openPbrMaterial(material);
  const v = [Math.sqrt((1 - mu) * (1 + mu)), 0, mu];
  const part = (key) => (l) => openPbrLayers(l, v, m)[key];
  const rBase = openPbrBaseRoughness(m);
  const none = [0, 0, 0];
  const dielectric = m.base_metalness < 1;
  const out = {
    specular: dielectric ? albedoOverHalfVector(part('specular'), v, rBase * rBase, n) : none,
    metal: m.base_metalness > 0 ? albedoOverHalfVector(part('metal'), v, rBase * rBase, n) : none,
    coat: m.coat_weight > 0 ? albedoOverHalfVector(part('coat'), v, Math.max(m.coat_roughness ** 2, 1e-4), n) : none,
    diffuse: dielectric ? albedoOverDirections(part('diffuse'), n) : none,
    fuzz: m.fuzz_weight > 0 ? albedoOverDirections(part('fuzz'), n) : none,
  };
  out.total = [0, 1, 2].map((c) => out.specular[c] + out.metal[c] + out.coat[c] + out.diffuse[c] + out.fuzz[c]);
  return out;
}
