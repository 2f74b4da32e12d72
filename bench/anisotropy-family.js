// The bench family for anisotropic visibility: the exact height-correlated Smith V of anisotropic GGX (Heitz 2014;
// the form Filament ships as V_SmithGGXCorrelated_Anisotropic and three.js r187 as V_GGX_SmithCorrelated_Anisotropic)
// against the cheaper forms renderers use in its place, compared in G2 = V (n·l)(n·v) as the visibility family is:
//   - the glTF extension's sample code (KHR_materials_anisotropy, "Implementation", and earlier three.js releases)
//     returns clamp(0.5 / (…), 0, 1): the app's V capped at 4, which bites at grazing pairs of a smooth axis;
//   - the other branch of Filament's visibilityAnisotropic (SPECULAR_V_SMITH_GGX, shaders/src/brdf.fs):
//     the isotropic V at Filament's roughness, the mean of αt = α(1 + a) and αb = α(1 − a);
//   - the isotropic V at OpenPBR 1.1's roughness α, √((αt² + αb²)/2): what its specification designs a renderer
//     without anisotropy to fall back on;
//   - Hammon 2017's fast isotropic form (Filament's V_SmithGGXCorrelated_Fast) at the mean: the cheapest of all.
import * as M from '../src/math/index.js';
import { DEG } from '../src/math/angles.js';

const THETAS = Array.from({ length: 18 }, (_, i) => 5 * i * DEG); // 0° to 85°
const PHIS = Array.from({ length: 12 }, (_, i) => 30 * i * DEG); // 0° to 330°, from the tangent
const DIRECTIONS = THETAS.flatMap((t) =>
  PHIS.map((p) => [Math.sin(t) * Math.cos(p), Math.sin(t) * Math.sin(p), Math.cos(t)]),
);
// glTF's mapping at roughness 0.3 and 0.6 (α = r²), strength 0.5 and 1: (αt, αb) = (mix(α, 1, s²), α)
const PAIRS = [0.3, 0.6].flatMap((r) => [0.5, 1].map((s) => M.anisotropicAlphas(r * r, s, 'gltf')));

const MODEL = 'smith-ggx-correlated-anisotropic';
const exact = (lx, ly, lz, vx, vy, vz, ax, ay) => M.visibilitySmithGGXCorrelatedAniso(lx, ly, lz, vx, vy, vz, ax, ay);
const mean = (ax, ay) => (ax + ay) / 2;
const rms = (ax, ay) => Math.sqrt((ax * ax + ay * ay) / 2);
// G2 = V (n·l)(n·v), the quantity compared
const inG = (V) => (lx, ly, lz, vx, vy, vz, ax, ay) => V(lx, ly, lz, vx, vy, vz, ax, ay) * lz * vz;

// GPU: the pass's x and y as n·l and n·v, the other components from them (a cost, not a value, is measured)
const L = 'vec3(0.8 * y, 0.6 * y, x)';
const V = 'vec3(-0.6 * x, 0.8 * x, y)';
const ALPHA = 'vec2(0.05 + 0.9 * y, 0.05)';

export const ANISOTROPY_FAMILY = {
  key: 'anisotropy',
  title: 'Anisotropic visibility: exact Smith GGX against the cheaper forms renderers ship',
  domain:
    'θl, θv in [0°, 85°] (5° steps) × φl, φv in [0°, 330°] from the tangent (30° steps) × (αx, αy) from ' +
    'KHR_materials_anisotropy at roughness 0.3, 0.6 and strength 0.5, 1; compared in G = V (n·l)(n·v)',
  errorOf: 'G',
  inputs: DIRECTIONS.flatMap((l) => DIRECTIONS.flatMap((v) => PAIRS.map(([ax, ay]) => [...l, ...v, ax, ay]))),
  gpu: { chunk: 'anisotropic.glsl' },
  variants: [
    {
      key: 'exact',
      label: 'Exact (Heitz 2014; Filament, three.js)',
      kind: 'reference',
      model: MODEL,
      js: inG(exact),
      glsl: `visibilitySmithGGXCorrelatedAniso(${L}, ${V}, ${ALPHA})`,
    },
    {
      key: 'gltf-clamped',
      label: 'Exact, clamped as glTF’s sample code',
      kind: 'approximation',
      against: 'exact',
      model: MODEL,
      js: inG((...a) => Math.min(exact(...a), 4)),
      glsl: `min(visibilitySmithGGXCorrelatedAniso(${L}, ${V}, ${ALPHA}), 4.0)`,
    },
    {
      key: 'isotropic-mean',
      label: 'Isotropic at the mean α (Filament’s option)',
      kind: 'approximation',
      against: 'exact',
      model: MODEL,
      js: inG((lx, ly, lz, vx, vy, vz, ax, ay) => M.visibilitySmithGGXCorrelated(lz, vz, mean(ax, ay))),
      glsl: 'visibilitySmithGGXCorrelated(x, y, 0.5 * (0.1 + 0.9 * y))',
    },
    {
      key: 'isotropic-rms',
      label: 'Isotropic at OpenPBR’s α, √((αx² + αy²)/2)',
      kind: 'approximation',
      against: 'exact',
      model: MODEL,
      js: inG((lx, ly, lz, vx, vy, vz, ax, ay) => M.visibilitySmithGGXCorrelated(lz, vz, rms(ax, ay))),
      glsl: 'visibilitySmithGGXCorrelated(x, y, sqrt(0.5 * ((0.05 + 0.9 * y) * (0.05 + 0.9 * y) + 0.0025)))',
    },
    {
      key: 'hammon-mean',
      label: 'Hammon 2017 at the mean α',
      kind: 'approximation',
      against: 'exact',
      model: MODEL,
      js: inG((lx, ly, lz, vx, vy, vz, ax, ay) => M.visibilitySmithGGXCorrelatedFast(lz, vz, mean(ax, ay))),
      glsl: 'visibilitySmithGGXCorrelatedFast(x, y, 0.5 * (0.1 + 0.9 * y))',
    },
  ],
};
