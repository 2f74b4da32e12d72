// @ts-check
// From a lab widget's state to the renderer's scene: the material (from the talk's F0 tables or set by hand), the
// terms, the lights that are on (directions in view space: z towards the viewer, y up) and the methods.
import { METALS, NON_METALS, materialByKey, isMetal } from '../math/materials.js';
import { srgbToLinear } from '../math/color.js';
import { lightDirFromAngles } from '../math/angles.js';
import { hexToRgb } from '../core/ui/palettes.js';
import { DEG } from '../math/angles.js';
import { anisotropyOf } from './lab-anisotropy.js';

/**
 * @typedef {object} LabMaterialState  the material fields (MATERIAL_FIELDS) of a lab widget's state
 * @property {string} material  'manual' or a key of the talk's F0 tables
 * @property {number} f0  F0 set by hand
 * @property {string} cdiff  the diffuse colour set by hand, sRGB '#rrggbb'
 * @property {number} alpha  roughness α
 * @property {number} [sigma]  Oren–Nayar σ in degrees, where the widget has it
 */

/**
 * @typedef {LabMaterialState & {
 *   F: string, D: string, V: string, diffuse: string, layers: string,
 *   compensation?: string, envMethod: string, areaMethod: string, samples: number
 * }} LabState  what labScene reads of the material lab's state (the catalogue's choice: names and keys)
 */

/**
 * @typedef {object} LabMaterial
 * @property {number[]} f0  linear RGB
 * @property {number[]} diffuse  linear RGB; black for a metal
 * @property {number} alpha
 * @property {number} sigma  Oren–Nayar σ in radians
 */

/**
 * @typedef {object} SphereLight
 * @property {number[]} dir  unit direction to its centre, view space
 * @property {number} sin  sine of its angular radius
 * @property {number[]} radiance  RGB
 */

/**
 * @typedef {object} LabLights  the lights that are on (null: off); directions in view space
 * @property {{ dir: number[], cLight: number[] } | null} punctual
 * @property {SphereLight | null} sphere
 * @property {{ intensity: number, map: string } | null} env  the environment's key and its scale
 * @property {number[] | null} ambient  uniform radiance, RGB
 */

/**
 * @typedef {object} LabScene  what the lab renderer draws
 * @property {LabMaterial} material
 * @property {{ F: string, D: string, V: string, diffuse: string, layers: string, compensation: string }} terms
 * @property {LabLights} lights
 * @property {{ env: string, area: string, samples: number }} methods
 * @property {string} [measured]  the measured table's name, when a MERL file stands in for the model
 * @property {import('./lab-anisotropy.js').LabAnisotropy | null} [anisotropy]  the lobe's stretch, when set
 */

export const MATERIAL_OPTIONS = {
  manual: 'Custom (F0 and diffuse below)',
  ...Object.fromEntries(
    [...METALS, ...NON_METALS].map((m) => [m.key, `${m.name} (${isMetal(m.key) ? 'metal' : 'non-metal'})`]),
  ),
};

/** The material fields every lab widget's schema shares. */
export const MATERIAL_FIELDS = {
  // `manual`, not `custom`, which names the user's own GLSL; old links' `custom` reads as `manual`
  material: {
    type: 'enum',
    options: MATERIAL_OPTIONS,
    aliases: { custom: 'manual' },
    default: 'manual',
    label: 'Material',
  },
  f0: { type: 'number', min: 0, max: 1, step: 0.01, default: 0.04, label: 'Custom F0' },
  // c_diff, as the diffuse explorer names it; `diffuse` now names the diffuse term
  cdiff: { type: 'color', formerly: ['diffuse'], default: '#b5532e', label: 'Diffuse colour' },
  alpha: { type: 'number', min: 0, max: 1, step: 0.005, default: 0.25, label: 'Roughness α' },
};

/**
 * F0 and diffuse colour (linear) of the chosen material: metals have no diffuse term (the talk).
 * @param {LabMaterialState} state
 * @returns {LabMaterial}
 */
export function materialOf(state) {
  const table = state.material !== 'manual' ? materialByKey(state.material) : null;
  const f0 = table ? table.linear : [state.f0, state.f0, state.f0];
  const diffuse = table && isMetal(state.material) ? [0, 0, 0] : hexToRgb(state.cdiff).map(srgbToLinear);
  return { f0, diffuse, alpha: state.alpha, sigma: (state.sigma ?? 0) * DEG };
}

/**
 * @param {LabState} state
 * @param {LabLights} lights
 * @returns {LabScene}
 */
export function labScene(state, lights) {
  return {
    material: materialOf(state),
    terms: {
      F: state.F,
      D: state.D,
      V: state.V,
      diffuse: state.diffuse,
      layers: state.layers,
      compensation: state.compensation ?? 'none',
    },
    lights,
    methods: { env: state.envMethod, area: state.areaMethod, samples: state.samples },
    anisotropy: anisotropyOf(state),
  };
}

/**
 * The sphere light: c_light is kept as the radius changes (radiance = c_light / sin²θs), so only the shape of its
 * highlight changes.
 * @param {number} thetaDeg
 * @param {number} phiDeg
 * @param {number} radiusDeg  its angular radius
 * @param {number} cLight
 * @returns {SphereLight}
 */
export function sphereLight(thetaDeg, phiDeg, radiusDeg, cLight) {
  const sin = Math.sin(radiusDeg * DEG);
  return { dir: lightDirFromAngles(thetaDeg, phiDeg), sin, radiance: [1, 1, 1].map(() => cLight / (sin * sin)) };
}
