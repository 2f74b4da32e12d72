// @ts-check
// The slots a user-written term fills, each with its fixed GLSL signature in the talk's conventions (Hoffman 2013,
// "Background: Physics and Math of Shading"): local frame n = (0, 0, 1), the BRDF in 1/sr, V = G / ((n·l)(n·v)),
// so the microfacet BRDF is F·D·V / 4. Pure data: loads in Node. Each starter is a correct term (the same as the
// reference the checks compare it with by default), written the way shaders/ writes it, float32 traps included.
// A custom chunk has common.glsl before it (PI, saturate, sin2FromCos), so the starters use PI. The calls of the
// slots that stand in a family's menu are the catalogue's (src/math/catalogue/custom-terms.js).
import { CUSTOM_TERMS } from '../../math/catalogue/index.js';
import { PARAMETERS } from '../../math/catalogue/parameters.js';
import { ALPHA_ANISO_MAX } from '../../math/anisotropic.js';

/**
 * One argument of a slot's GLSL function.
 * @typedef {object} SlotArg
 * @property {string} name as the signature spells it
 * @property {'float' | 'vec2' | 'vec3'} type
 * @property {number} min the documented domain (a direction's components: -1…1)
 * @property {number} max
 * @property {string} unit '' for a pure number
 * @property {string} label
 */

/**
 * @typedef {object} Slot
 * @property {'D' | 'DAniso' | 'V' | 'VAniso' | 'F' | 'diffuse' | 'brdf'} key
 * @property {string} fn the GLSL function the user writes
 * @property {string} signature its declaration
 * @property {'float' | 'vec3'} returns
 * @property {SlotArg[]} args
 * @property {'ndf' | 'visibility' | 'fresnel' | 'diffuse' | null} family the catalogue family whose menus it stands
 *   in as `custom` (null: none, for a whole BRDF and for the anisotropic D and V, which no family's menu offers:
 *   the material lab's own Stretched D and Stretched V do, src/widgets/material-lab/custom-aniso.js, as do the
 *   shader exercises; their references are the catalogue's anisotropic terms, src/core/custom/references.js)
 * @property {string} reference the catalogue key (of `family`, or of the diffuse family for 'brdf'; for 'DAniso' and
 *   'VAniso' of the ndf and visibility families' anisotropic terms) the checks compare with by default
 * @property {string} starter GLSL text, a correct term
 * @property {string} call the expression the widgets and the term dispatch use: for D and V over the fields of the
 *   microfacet input m (shaders/microfacet-input.glsl), the user's signature unchanged
 * @property {string[]} inputs what one evaluation input holds, in order (gpu-eval.js packs it into a.xyzw, b.xyzw)
 * @property {string} evalCall the call over a and b that evaluates the slot on those inputs
 * @property {1 | 3} outputs floats of the result (a float in .x, a vec3 in .xyz)
 */

const { alpha: ALPHA, f0: F0 } = PARAMETERS;
const ALPHA_ARG = /** @type {SlotArg} */ ({
  name: 'alpha',
  type: 'float',
  min: ALPHA.min,
  max: ALPHA.max,
  unit: '',
  label: 'α',
});
/** @param {string} name @param {string} label @returns {SlotArg} */
const cosArg = (name, label) => ({ name, type: 'float', min: 0, max: 1, unit: '', label });
/** @param {string} name @param {string} label @returns {SlotArg} */
const dirArg = (name, label) => ({ name, type: 'vec3', min: -1, max: 1, unit: '', label });

const STARTER_D = `// GGX (Trowbridge & Reitz 1975; Walter et al. 2007), in 1/sr:
// D(m) = α² / (π ((n·m)² α² + sin²θm)²), written with sin²θm = (1 - n·m)(1 + n·m):
// 1 - (n·m)² would cancel near n·m = 1, where the peak of a small α is.
float customD(float nh, float alpha) {
  if (!(nh > 0.0)) return 0.0;
  float c = min(nh, 1.0);
  float a = clamp(alpha, 1e-4, 1.0);
  float d = a * a * c * c + (1.0 - c) * (1.0 + c);
  float t = a / d; // a² / d² overflows float32 sooner
  return t * t / PI;
}
`;

const STARTER_D_ANISO = `// Anisotropic GGX (Heitz 2014), in 1/sr, h in the tangent frame (x = t, y = b, z = n):
// D(h) = 1 / (π αx αy (hx²/αx² + hy²/αy² + hz²)²). Every part of the sum is positive: nothing cancels,
// and sin²θ never comes from 1 - hz², so the peak of a small α stays sharp in float32.
float customDAniso(vec3 h, vec2 alpha) {
  if (!(h.z > 0.0)) return 0.0;
  vec2 a = clamp(alpha, 1e-4, 4.0);
  vec2 s = h.xy / a;
  float d = dot(s, s) + h.z * h.z;
  return 1.0 / (PI * a.x * a.y * d * d);
}
`;

const STARTER_V = `// Height-correlated Smith for GGX (Heitz 2014), as the talk's V = G / ((n·l)(n·v)):
// V = 2 / (n·l · r(n·v) + n·v · r(n·l)), r(x) = sqrt(x² + α² (1 - x²)) = x (1 + 2Λ(x)),
// Λ being Smith's Λ of that paper.
float customV(float nl, float nv, float alpha) {
  if (!(nl > 0.0 && nv > 0.0)) return 0.0;
  float l = min(nl, 1.0);
  float v = min(nv, 1.0);
  float a = clamp(alpha, 1e-4, 1.0);
  float a2 = a * a;
  float rootV = sqrt(v * v + a2 * (1.0 - v) * (1.0 + v));
  float rootL = sqrt(l * l + a2 * (1.0 - l) * (1.0 + l));
  return 2.0 / (l * rootV + v * rootL);
}
`;

const STARTER_V_ANISO = `// Height-correlated Smith for anisotropic GGX (Heitz 2014), as the talk's
// V = G / ((n·l)(n·v)), l and v in the tangent frame (x = t, y = b, z = n).
// Λ projects the roughness on each direction's azimuth φ:
// α(φ)² sin²θ = αx² wx² + αy² wy², so r(w) = sqrt(wz² + αx² wx² + αy² wy²) = wz (1 + 2Λ(w)).
float customVAniso(vec3 l, vec3 v, vec2 alpha) {
  if (!(l.z > 0.0 && v.z > 0.0)) return 0.0;
  vec2 a = clamp(alpha, 1e-4, 4.0);
  float rootL = length(vec3(a * l.xy, l.z));
  float rootV = length(vec3(a * v.xy, v.z));
  return 2.0 / (v.z * rootL + l.z * rootV);
}
`;

const STARTER_F = `// Schlick's approximation (Schlick 1994): F = F0 + (1 - F0) (1 - l·h)^5.
vec3 customF(vec3 f0, float lh) {
  float m = 1.0 - clamp(lh, 0.0, 1.0);
  float m2 = m * m;
  return f0 + (1.0 - f0) * (m2 * m2 * m);
}
`;

const STARTER_DIFFUSE = `// Lambert (Lambert 1760): c_diff / π, and 0 below the horizon. alpha is unused here.
vec3 customDiffuse(vec3 cdiff, vec3 l, vec3 v, float alpha) {
  if (!(l.z > 0.0 && v.z > 0.0)) return vec3(0.0);
  return clamp(cdiff, 0.0, 1.0) / PI;
}
`;

const STARTER_BRDF = `// A whole BRDF f(l, v) in 1/sr, n = (0, 0, 1): here Lambert with an albedo slider.
uniform float albedo; // slider 0 1 1 "Albedo"
vec3 customBRDF(vec3 l, vec3 v) {
  if (!(l.z > 0.0 && v.z > 0.0)) return vec3(0.0);
  return vec3(albedo / PI);
}
`;

/** The dispatch call of a family's custom term. @param {'ndf' | 'visibility' | 'fresnel'} family */
const catalogueCall = (family) => /** @type {string} */ (CUSTOM_TERMS[family]?.glslCall);

/** @type {Record<Slot['key'], Slot>} */
export const SLOTS = {
  D: {
    key: 'D',
    fn: 'customD',
    signature: 'float customD(float nh, float alpha)',
    returns: 'float',
    args: [cosArg('nh', 'n·h'), ALPHA_ARG],
    family: 'ndf',
    reference: 'ggx',
    starter: STARTER_D,
    call: catalogueCall('ndf'),
    inputs: ['nh', 'alpha'],
    evalCall: 'customD(a.x, a.y)',
    outputs: 1,
  },
  DAniso: {
    key: 'DAniso',
    fn: 'customDAniso',
    signature: 'float customDAniso(vec3 h, vec2 alpha)',
    returns: 'float',
    args: [
      dirArg('h', 'h'),
      { name: 'alpha', type: 'vec2', min: ALPHA.min, max: ALPHA_ANISO_MAX, unit: '', label: '(αx, αy)' },
    ],
    family: null, // in the material lab's Stretched D, no family's menu (see Slot.family)
    reference: 'ggxAniso',
    starter: STARTER_D_ANISO,
    call: 'customDAniso(m.h, m.alpha)',
    inputs: ['hx', 'hy', 'hz', 'alphaX', 'alphaY'],
    evalCall: 'customDAniso(a.xyz, vec2(a.w, b.x))',
    outputs: 1,
  },
  V: {
    key: 'V',
    fn: 'customV',
    signature: 'float customV(float nl, float nv, float alpha)',
    returns: 'float',
    args: [cosArg('nl', 'n·l'), cosArg('nv', 'n·v'), ALPHA_ARG],
    family: 'visibility',
    reference: 'smithGGXCorrelated',
    starter: STARTER_V,
    call: catalogueCall('visibility'),
    inputs: ['nl', 'nv', 'alpha'],
    evalCall: 'customV(a.x, a.y, a.z)',
    outputs: 1,
  },
  VAniso: {
    key: 'VAniso',
    fn: 'customVAniso',
    signature: 'float customVAniso(vec3 l, vec3 v, vec2 alpha)',
    returns: 'float',
    args: [
      dirArg('l', 'l'),
      dirArg('v', 'v'),
      { name: 'alpha', type: 'vec2', min: ALPHA.min, max: ALPHA_ANISO_MAX, unit: '', label: '(αx, αy)' },
    ],
    family: null,
    reference: 'smithGGXCorrelatedAniso',
    starter: STARTER_V_ANISO,
    call: 'customVAniso(m.l, m.v, m.alpha)',
    inputs: ['lx', 'ly', 'lz', 'vx', 'vy', 'vz', 'alphaX', 'alphaY'],
    evalCall: 'customVAniso(a.xyz, vec3(a.w, b.xy), b.zw)',
    outputs: 1,
  },
  F: {
    key: 'F',
    fn: 'customF',
    signature: 'vec3 customF(vec3 f0, float lh)',
    returns: 'vec3',
    args: [{ name: 'f0', type: 'vec3', min: F0.min, max: F0.max, unit: '', label: 'F0' }, cosArg('lh', 'l·h')],
    family: 'fresnel',
    reference: 'schlick',
    starter: STARTER_F,
    call: catalogueCall('fresnel'),
    inputs: ['f0r', 'f0g', 'f0b', 'lh'],
    evalCall: 'customF(a.xyz, a.w)',
    outputs: 3,
  },
  diffuse: {
    key: 'diffuse',
    fn: 'customDiffuse',
    signature: 'vec3 customDiffuse(vec3 cdiff, vec3 l, vec3 v, float alpha)',
    returns: 'vec3',
    args: [
      { name: 'cdiff', type: 'vec3', min: 0, max: 1, unit: '', label: 'c_diff' },
      dirArg('l', 'l'),
      dirArg('v', 'v'),
      ALPHA_ARG,
    ],
    family: 'diffuse',
    reference: 'lambert',
    starter: STARTER_DIFFUSE,
    call: 'customDiffuse(cdiff, l, v, alpha)',
    // a grey c_diff: one float, so that c_diff, l, v and α are eight floats, two texels of the harness
    inputs: ['cdiff', 'lx', 'ly', 'lz', 'vx', 'vy', 'vz', 'alpha'],
    evalCall: 'customDiffuse(vec3(a.x), a.yzw, b.xyz, b.w)',
    outputs: 3,
  },
  brdf: {
    key: 'brdf',
    fn: 'customBRDF',
    signature: 'vec3 customBRDF(vec3 l, vec3 v)',
    returns: 'vec3',
    args: [dirArg('l', 'l'), dirArg('v', 'v')],
    family: null,
    reference: 'lambert',
    starter: STARTER_BRDF,
    call: 'customBRDF(l, v)',
    inputs: ['lx', 'ly', 'lz', 'vx', 'vy', 'vz'],
    evalCall: 'customBRDF(a.xyz, vec3(a.w, b.xy))',
    outputs: 3,
  },
};

/**
 * The slot of a key; throws for a key that is no slot (a programmer's error: state and URLs go through the schema).
 * @param {string} key
 * @returns {Slot}
 */
export function slotOf(key) {
  if (!Object.hasOwn(SLOTS, key)) throw new Error(`custom: no slot '${key}' (${Object.keys(SLOTS).join(', ')})`);
  return SLOTS[/** @type {Slot['key']} */ (key)];
}
