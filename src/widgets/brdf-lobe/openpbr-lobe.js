// BRDF A as OpenPBR Surface (issue 29): the layered material of src/math/openpbr.js, drawn as one lobe (the
// luminance of its RGB value) with each layer's part beside it (openPbrLayers, already weighted so that the parts
// add up to the whole). The widget's state holds a few of the specification's parameters under its own names.
import { openPbrBaseRoughness, openPbrLayers, openPbrMaterial } from '../../math/openpbr.js';
import { luminanceRec709, srgbToLinear } from '../../math/color.js';
import { directionFromCos, hemisphereIntegral, reflectanceImportanceGGX } from '../../math/integrate.js';
import { DEG } from '../../math/angles.js';
import { planeAzimuth, turnAboutN } from './azimuths.js';

/** The layers' parts as openPbrLayers names them, with the words and colours the views give them. */
export const OPENPBR_LAYERS = {
  specular: { short: 'specular', label: 'specular (dielectric gloss)', color: '#0072b2', dash: [] },
  diffuse: { short: 'diffuse', label: 'diffuse (EON, under the gloss)', color: '#996b00', dash: [6, 3] },
  metal: { short: 'metal', label: 'metal (F82-tint)', color: '#cc79a7', dash: [2, 3] },
  coat: { short: 'coat', label: 'coat', color: '#009e73', dash: [8, 3, 2, 3] },
  fuzz: { short: 'fuzz', label: 'fuzz (Zeltner et al. 2022)', color: '#56b4e9', dash: [1, 2] },
};
export const LAYER_KEYS = Object.keys(OPENPBR_LAYERS);

/** The state's keys that are OpenPBR parameters (the specification's names); colours are sRGB '#rrggbb'. */
export const OPENPBR_KEYS = [
  'base_color',
  'base_metalness',
  'specular_color',
  'specular_roughness',
  'coat_weight',
  'coat_roughness',
  'fuzz_weight',
  'fuzz_roughness',
];

const linearOf = (hex) => [1, 3, 5].map((i) => srgbToLinear(parseInt(hex.slice(i, i + 2), 16) / 255));

/**
 * The OpenPBR material of the state: its parameters, colours from sRGB to linear, the anisotropy slider as
 * specular_roughness_anisotropy (OpenPBR's own mapping of it to (αt, αb)); every other key takes its default.
 */
export function openPbrMaterialOf(state) {
  const m = Object.fromEntries(OPENPBR_KEYS.map((k) => [k, state[k]]));
  for (const k of ['base_color', 'specular_color']) m[k] = linearOf(state[k]);
  return openPbrMaterial({ ...m, specular_roughness_anisotropy: state.anisotropy });
}

/** Every layer's part at (l, v) in the plane's frame (turned into the tangent's), [r, g, b] in 1/sr each. */
export const layersAt = (l, v, p) => openPbrLayers(turnAboutN(l, p.phi), turnAboutN(v, p.phi), p.openpbr);

/** The luminance (Rec. 709 Y) of each layer's part at (l, v), and of the whole (`all`), in 1/sr. */
export function layerLuminances(l, v, p) {
  const parts = layersAt(l, v, p);
  const out = { all: 0 };
  for (const k of LAYER_KEYS) out.all += out[k] = luminanceRec709(parts[k]);
  return out;
}

/** The lobe's value: the luminance of one layer's part, or of the whole when `layer` is absent. */
export const openPbrValue = (l, v, p, layer = 'all') => layerLuminances(l, v, p)[layer];

/** A's spec in OpenPBR mode: the material, the plane's azimuth, and no factors to switch. */
export function openPbrSpec(state) {
  return { openpbr: openPbrMaterialOf(state), phi: planeAzimuth(state), custom: {}, aniso: null, label: 'A: OpenPBR' };
}

const GLOSS_SAMPLES = 256; // per angle, for each of the two GGX lobes (the base's, the coat's)
const SMOOTH_CELLS = 16; // the midpoint rule's n: 16 × 32 cells for the diffuse and fuzz lobes

/**
 * E(θv) of the whole stack at each angle: each layer integrated as suits its lobe, the gloss and metal by
 * importance sampling GGX at the base's α, the coat at its own (GLOSS_SAMPLES each), the diffuse and fuzz lobes
 * by the midpoint rule over (n·l, φ); the view turned off the plane by `turn` (radians).
 */
export function openPbrAlbedo(p, angles, turn = 0) {
  const m = p.openpbr;
  const alphaBase = Math.max(openPbrBaseRoughness(m) ** 2, 1e-3);
  const alphaCoat = Math.max(m.coat_roughness ** 2, 1e-3);
  const sum = (keys) => (l, v) => {
    const y = layerLuminances(l, v, p);
    return keys.reduce((s, k) => s + y[k], 0);
  };
  return Array.from(angles, (deg) => {
    const v = turnAboutN(directionFromCos(Math.cos(deg * DEG)), turn);
    const glossy = reflectanceImportanceGGX(sum(['specular', 'metal']), v, alphaBase, GLOSS_SAMPLES);
    const coat = m.coat_weight > 0 ? reflectanceImportanceGGX(sum(['coat']), v, alphaCoat, GLOSS_SAMPLES) : 0;
    const smooth = hemisphereIntegral((l) => sum(['diffuse', 'fuzz'])(l, v), SMOOTH_CELLS);
    return glossy + coat + smooth;
  });
}
