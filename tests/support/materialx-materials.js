// The OpenPBR Surface materials the MaterialX comparison renders (tests/browser/materialx.test.js), in OpenPBR's
// own input names; what a material leaves out takes the specification's default. Where a value is a fact it is
// computed here from its source: a metal's base_color and specular_color are F82-tint's f0 and tint fitted to the
// metal's measured (n, k) (f82TintFromConductor, src/math/fresnel.js; the constants in
// src/math/optical-constants.js).
import { measuredRgbNk, MEASURED_NK } from '../../src/math/optical-constants.js';
import { f82TintFromConductor } from '../../src/math/fresnel.js';
import { OPENPBR_PRESETS } from '../../src/lab/openpbr-presets.js';

/** base_color and specular_color of a metal of the table, from its (n, k) at 650, 550 and 450 nm. */
function metal(key) {
  const fits = measuredRgbNk(key).map(([n, k]) => f82TintFromConductor(n, k));
  return { base_color: fits.map((f) => f.f0), specular_color: fits.map((f) => Math.min(f.tint, 1)) };
}

/**
 * { name, source, inputs, layers }: `layers` lists the layers beyond the base (coat, fuzz) a material switches on,
 * so that a reference without them can leave it out.
 */
export const MATERIALX_MATERIALS = [
  { name: 'openpbr-default', source: 'OpenPBR Surface 1.1 defaults', inputs: {}, layers: [] },
  {
    name: 'polystyrene',
    source: 'n = 1.59, polystyrene at 589 nm (Sultanova et al. 2009)',
    inputs: { base_color: [0.6, 0.05, 0.04], specular_ior: 1.59, specular_roughness: 0.25 },
    layers: [],
  },
  {
    name: 'rough-dielectric',
    source: 'n = 1.5 (crown glass), a rough grey surface',
    inputs: { base_color: [0.5, 0.5, 0.5], specular_ior: 1.5, specular_roughness: 0.7 },
    layers: [],
  },
  {
    name: 'wet-dark',
    source: 'n = 1.333, water at 589 nm (Hale & Querry 1973), over a dark base, half the specular weight',
    inputs: { base_color: [0.05, 0.04, 0.03], specular_ior: 1.333, specular_roughness: 0.2, specular_weight: 0.5 },
    layers: [],
  },
  {
    name: 'gold',
    source: `gold's (n, k): ${MEASURED_NK.gold.source}`,
    inputs: { base_metalness: 1, ...metal('gold'), specular_roughness: 0.3 },
    layers: [],
  },
  {
    name: 'rough-aluminium',
    source: `aluminium's (n, k): ${MEASURED_NK.aluminum.source}`,
    inputs: { base_metalness: 1, ...metal('aluminum'), specular_roughness: 0.6 },
    layers: [],
  },
  {
    name: 'copper-half-metal',
    source: `copper's (n, k): ${MEASURED_NK.copper.source}; base_metalness 0.5 mixes it with a dielectric`,
    inputs: { base_metalness: 0.5, ...metal('copper'), specular_roughness: 0.4 },
    layers: [],
  },
  {
    name: 'coated',
    source: 'car paint: a red base under a clear coat of n = 1.5',
    inputs: {
      base_color: [0.5, 0.02, 0.02],
      specular_roughness: 0.4,
      coat_weight: 1,
      coat_ior: 1.5,
      coat_roughness: 0.1,
    },
    layers: ['coat'],
  },
  {
    name: 'fuzz',
    source: 'velvet: fuzz over a dark base (roughness 0.3)',
    inputs: { base_color: [0.1, 0.02, 0.05], fuzz_weight: 1, fuzz_color: [0.8, 0.3, 0.5], fuzz_roughness: 0.5 },
    layers: ['fuzz'],
  },
];

const presetMaterial = (key) => ({
  name: key,
  label: OPENPBR_PRESETS[key].label,
  source: OPENPBR_PRESETS[key].source,
  inputs: OPENPBR_PRESETS[key].material,
  layers: ['coat', 'fuzz'].filter((layer) => OPENPBR_PRESETS[key].material[`${layer}_weight`] > 0),
});
const coated = MATERIALX_MATERIALS.find((m) => m.name === 'coated');
const fuzzy = MATERIALX_MATERIALS.find((m) => m.name === 'fuzz');
const withoutCoat = Object.fromEntries(Object.entries(coated.inputs).filter(([k]) => !k.startsWith('coat_')));
const fuzzOf = Object.fromEntries(Object.entries(fuzzy.inputs).filter(([k]) => k.startsWith('fuzz_')));

/**
 * The bench's materials (bench/openpbr-materialx.js): the material lab's presets (src/lab/openpbr-presets.js), then
 * one material built up layer by layer: the test's car paint without its coat, with it, and with a fuzz on top; and
 * the velvet without its fuzz, which sets its base's difference apart from the fuzz's.
 */
export const MATERIALX_BENCH_MATERIALS = [
  ...Object.keys(OPENPBR_PRESETS).map(presetMaterial),
  {
    name: 'layers-base',
    label: 'Layer by layer: the base alone',
    source: 'a red dielectric base (0.5, 0.02, 0.02), specular_roughness 0.4, specular_ior 1.5',
    inputs: withoutCoat,
    layers: [],
  },
  {
    name: 'layers-coat',
    label: '+ coat',
    source: 'the same base under a clear coat (coat_ior 1.5, coat_roughness 0.1)',
    inputs: coated.inputs,
    layers: ['coat'],
  },
  {
    name: 'layers-fuzz',
    label: '+ fuzz',
    source: 'the coated base under a fuzz (fuzz_color (0.8, 0.3, 0.5), fuzz_roughness 0.5)',
    inputs: { ...coated.inputs, ...fuzzOf },
    layers: ['coat', 'fuzz'],
  },
  {
    name: 'velvet-base',
    label: 'Velvet without its fuzz',
    source: 'the velvet preset at fuzz_weight 0: what its base alone differs by, under the fuzz',
    inputs: { ...OPENPBR_PRESETS.velvet.material, fuzz_weight: 0 },
    layers: [],
  },
];
