// The material lab's OpenPBR presets: each value a fact with its source beside it, or said to be a choice.
// Car paint, brushed aluminium and velvet are MaterialX's own example materials for open_pbr_surface
// (resources/Materials/Examples/OpenPbr/ in the MaterialX repository, Academy Software Foundation, 1.39; inputs
// the file leaves out take the specification's defaults). Gold and plastic come from the talk's F0 table (Hoffman
// 2013, after Real-Time Rendering 3rd ed.), gold's grazing tint from its measured refractive index by
// f82TintFromConductor (Hoffman 2019's F82-tint, fitted to the exact conductor Fresnel at cos θ = 1/7).
import { channelIor, materialByKey, measuredSource } from '../math/materials.js';
import { f82TintFromConductor, iorFromF0 } from '../math/fresnel.js';

const grey = (x) => [x, x, x];
const GOLD = materialByKey('gold');
const PLASTIC = materialByKey('plastic-high');

/** { key: { label, source, material } }: material in OpenPBR's names, only what differs from the defaults. */
export const OPENPBR_PRESETS = Object.freeze({
  carPaint: {
    label: 'Car paint',
    source:
      'MaterialX example open_pbr_carpaint.mtlx: blue base, specular_ior 1.6, a clear coat (ior 1.6, roughness 0.02)',
    material: {
      base_color: [0.1, 0.6, 0.9],
      specular_ior: 1.6,
      specular_roughness: 0.3,
      coat_weight: 1,
      coat_roughness: 0.02,
      coat_ior: 1.6,
    },
  },
  brushedAluminium: {
    label: 'Brushed aluminium',
    source:
      'MaterialX example open_pbr_aluminum_brushed.mtlx: metal, F0 0.912–0.920, edge tint 0.970–0.988, ' +
      'roughness 0.2, anisotropy 0.9',
    material: {
      base_color: [0.912, 0.914, 0.92],
      base_metalness: 1,
      specular_color: [0.97, 0.979, 0.988],
      specular_roughness: 0.2,
      specular_roughness_anisotropy: 0.9,
    },
  },
  velvet: {
    label: 'Velvet',
    source: 'MaterialX example open_pbr_velvet.mtlx: near-black base (0.02), roughness 0.8, grey fuzz 0.4 at 0.5',
    material: {
      base_color: grey(0.02),
      specular_roughness: 0.8,
      fuzz_weight: 1,
      fuzz_color: grey(0.4),
      fuzz_roughness: 0.5,
    },
  },
  plastic: {
    label: 'Plastic',
    source:
      `The talk's F0 table: plastic (high) F0 ${PLASTIC.linear[0]}, so specular_ior ` +
      `${iorFromF0(PLASTIC.linear[0]).toFixed(3)}; the red base colour (0.6, 0.05, 0.05) and the specification's ` +
      'default roughness 0.3 are choices',
    material: { base_color: [0.6, 0.05, 0.05], specular_ior: iorFromF0(PLASTIC.linear[0]), specular_roughness: 0.3 },
  },
  gold: {
    label: 'Gold',
    source:
      `The talk's F0 table: gold F0 (${GOLD.linear.join(', ')}) as base_color; specular_color the F82 tint of ` +
      `gold's measured index (${measuredSource('gold')}) by f82TintFromConductor; roughness 0.25 is a choice`,
    material: {
      base_color: [...GOLD.linear],
      base_metalness: 1,
      specular_color: channelIor('gold', 'measured').map(([n, k]) => Math.min(f82TintFromConductor(n, k).tint, 1)),
      specular_roughness: 0.25,
    },
  },
});
