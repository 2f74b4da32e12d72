// The families of terms the benchmark compares: for each, a float64 reference, a documented input domain,
// and the variants (a JS function and the GLSL expression that computes the same thing on the GPU).
// Shared by the CPU/error benchmark (Node) and the GPU benchmark page (Chromium).
import * as M from '../src/math/index.js';
import { MULTIPLE_SCATTERING_FAMILY } from './multiple-scattering-family.js';

const range = (n, lo, hi) => Array.from({ length: n }, (_, i) => lo + ((hi - lo) * i) / (n - 1));
const COS = range(1001, 0, 1);
const DEG = Math.PI / 180;

const measuredChannels = M.METALS.flatMap((m) => M.measuredRgbNk(m.key).map(([n, k], ch) => ({ n, k, f0: M.f0FromIor(n, k), label: `${m.key} ${'RGB'[ch]}` })));

export const FAMILIES = [
  {
    key: 'fresnel-dielectric',
    title: 'Fresnel, dielectrics',
    domain: 'cos θ in [0, 1] (1001 points) × n in {1.33, 1.5, 1.76, 2.42}',
    errorOf: 'reflectance',
    inputs: COS.flatMap((c) => [1.33, 1.5, 1.76, 2.42].map((eta) => [c, eta, M.f0FromIor(eta)])),
    reference: (c, eta) => M.fresnelDielectric(c, eta),
    variants: [
      { key: 'exact', label: 'Exact (fresnelDielectric)', js: (c, eta) => M.fresnelDielectric(c, eta), glsl: 'fresnelDielectric(x, 1.0 + y)' },
      { key: 'schlick', label: 'Schlick', js: (c, eta, f0) => M.fresnelSchlick(f0, c), glsl: 'fresnelSchlick(0.04 * y, x)' },
      { key: 'schlick-sg', label: 'Schlick, spherical Gaussian (Karis 2013)', js: (c, eta, f0) => M.fresnelSchlickSG(f0, c), glsl: 'fresnelSchlickSG(0.04 * y, x)' },
    ],
  },
  {
    key: 'fresnel-conductor',
    title: 'Fresnel, metals',
    domain: 'cos θ in [0, 1] (1001 points) × the measured (n, k) of the five metals at 650/550/450 nm',
    errorOf: 'reflectance',
    inputs: COS.flatMap((c) => measuredChannels.map(({ n, k, f0 }) => [c, n, k, f0])),
    reference: (c, n, k) => M.fresnelConductor(c, n, k),
    variants: [
      { key: 'exact', label: 'Exact (fresnelConductor)', js: (c, n, k) => M.fresnelConductor(c, n, k), glsl: 'fresnelConductor(x, 0.2 + y, 3.0 + y)' },
      { key: 'schlick', label: 'Schlick', js: (c, n, k, f0) => M.fresnelSchlick(f0, c), glsl: 'fresnelSchlick(0.5 + 0.4 * y, x)' },
      { key: 'schlick-sg', label: 'Schlick, spherical Gaussian', js: (c, n, k, f0) => M.fresnelSchlickSG(f0, c), glsl: 'fresnelSchlickSG(0.5 + 0.4 * y, x)' },
    ],
  },
  {
    key: 'smith-g1-beckmann',
    title: 'Smith G1, Beckmann',
    domain: 'cos θ in [0.001, 1] (1000 points) × α in {0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1}',
    errorOf: 'G1',
    inputs: range(1000, 0.001, 1).flatMap((c) => [0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1].map((a) => [c, a])),
    reference: (c, a) => M.smithG1Beckmann(c, a),
    variants: [
      { key: 'exact', label: 'Exact, with erf', js: (c, a) => M.smithG1Beckmann(c, a), glsl: 'smithG1Beckmann(x, 0.05 + y)' },
      { key: 'walter', label: 'Rational fit (Walter 2007)', js: (c, a) => M.smithG1BeckmannWalter(c, a), glsl: 'smithG1BeckmannWalter(x, 0.05 + y)' },
    ],
  },
  {
    key: 'visibility',
    title: 'Visibility, against height-correlated Smith GGX',
    domain: 'l and v in one plane on opposite sides of n, θl, θv in [0°, 89°] (1° steps) × α in {0.05, 0.1, 0.3, 0.5, 0.8, 1}; error in G = V (n·l)(n·v)',
    errorOf: 'G',
    inputs: range(90, 0, 89).flatMap((tl) => range(90, 0, 89).flatMap((tv) => [0.05, 0.1, 0.3, 0.5, 0.8, 1].map((a) => {
      const l = [-Math.sin(tl * DEG), 0, Math.cos(tl * DEG)];
      const v = [Math.sin(tv * DEG), 0, Math.cos(tv * DEG)];
      const { nl, nv, nh, lh } = M.brdfAngles(l, v);
      return [nl, nv, nh, lh, a];
    }))),
    reference: (nl, nv, nh, lh, a) => M.visibilitySmithGGXCorrelated(nl, nv, a) * nl * nv,
    variants: [
      { key: 'correlated', label: 'Height-correlated Smith (Heitz 2014)', js: (nl, nv, nh, lh, a) => M.visibilitySmithGGXCorrelated(nl, nv, a) * nl * nv, glsl: 'visibilitySmithGGXCorrelated(x, y, 0.3)' },
      { key: 'separable', label: 'Separable Smith', js: (nl, nv, nh, lh, a) => M.visibilitySmithGGXSeparable(nl, nv, a) * nl * nv, glsl: 'visibilitySmithGGXSeparable(x, y, 0.3)' },
      { key: 'hammon', label: 'Hammon 2017', js: (nl, nv, nh, lh, a) => M.visibilitySmithGGXCorrelatedFast(nl, nv, a) * nl * nv, glsl: 'visibilitySmithGGXCorrelatedFast(x, y, 0.3)' },
      { key: 'schlick-ggx', label: 'Schlick-GGX (k = α/2)', js: (nl, nv, nh, lh, a) => M.visibilitySchlickGGX(nl, nv, a) * nl * nv, glsl: 'visibilitySchlickGGX(x, y, 0.3)' },
      { key: 'cook-torrance', label: 'Cook-Torrance', js: (nl, nv, nh, lh) => M.visibilityCookTorrance(nl, nv, nh, lh) * nl * nv, glsl: 'visibilityCookTorrance(x, y, 0.5 + 0.5 * x, 0.5 + 0.5 * y)' },
      { key: 'kelemen', label: 'Kelemen', js: (nl, nv, nh, lh) => (nl > 0 && nv > 0 ? M.visibilityKelemen(lh) * nl * nv : 0), glsl: 'visibilityKelemen(0.5 + 0.5 * y)' },
      { key: 'implicit', label: 'Implicit (V = 1)', js: (nl, nv) => M.visibilityImplicit(nl, nv) * nl * nv, glsl: 'visibilityImplicit(x, y)' },
    ],
  },
  {
    key: 'ndf',
    title: 'NDFs at one half width, against Beckmann',
    domain: 'θh in [0°, 90°) (0.25° steps) × half widths {2°, 5°, 10°, 20°}; error in D / D(0) of Beckmann',
    errorOf: 'D / D_Beckmann(0)',
    inputs: [2, 5, 10, 20].flatMap((hw) => {
      const m = M.matchNdfWidths(hw);
      const peak = M.ndfBeckmann(1, m.beckmann.alpha);
      return range(360, 0, 89.75).map((deg) => [Math.cos(deg * DEG), m, peak]);
    }),
    reference: (c, m, peak) => M.ndfBeckmann(c, m.beckmann.alpha) / peak,
    variants: [
      { key: 'beckmann', label: 'Beckmann', js: (c, m, peak) => M.ndfBeckmann(c, m.beckmann.alpha) / peak, glsl: 'ndfBeckmann(x, 0.05 + 0.5 * y)' },
      {
        key: 'blinn-phong',
        label: 'Blinn-Phong (Walter’s exponent)',
        js: (c, m, peak) => M.ndfBlinnPhong(c, M.blinnPhongExponentFromBeckmannAlpha(m.beckmann.alpha)) / peak,
        glsl: 'ndfBlinnPhong(x, 10.0 + 100.0 * y)',
      },
      { key: 'ggx', label: 'GGX', js: (c, m, peak) => M.ndfGGX(c, m.ggx.alpha) / peak, glsl: 'ndfGGX(x, 0.05 + 0.5 * y)' },
      { key: 'abc', label: 'ABC', js: (c, m, peak) => M.ndfABC(c, m.abc.a1, m.abc.a2) / peak, glsl: 'ndfABC(x, 1.0 + 100.0 * y, 2.5)' },
      { key: 'sgd', label: 'Shifted gamma', js: (c, m, peak) => M.ndfSGD(c, m.sgd.alpha, m.sgd.p) / peak, glsl: 'ndfSGD(x, 0.05 + 0.5 * y, 0.64)' },
    ],
  },
  {
    key: 'oren-nayar',
    title: 'Oren–Nayar, against the full model',
    domain: 'θl, θv in [0°, 85°] (5° steps) × cos φ in {−1, −0.5, 0, 0.5, 1} × σ in {0.1, 0.3, 0.6, 1} (radians), c_diff = 0.8; error in f (1/sr)',
    errorOf: 'f',
    inputs: range(18, 0, 85).flatMap((tl) => range(18, 0, 85).flatMap((tv) => [-1, -0.5, 0, 0.5, 1].flatMap((cp) => [0.1, 0.3, 0.6, 1].map((s) => [Math.cos(tl * DEG), Math.cos(tv * DEG), cp, s])))),
    reference: (nl, nv, cp, s) => M.diffuseOrenNayar(nl, nv, cp, s, 0.8),
    variants: [
      { key: 'full', label: 'Full model (with inter-reflection)', js: (nl, nv, cp, s) => M.diffuseOrenNayar(nl, nv, cp, s, 0.8), glsl: 'diffuseOrenNayar(x, y, 0.5, 0.5, 0.8)' },
      { key: 'qualitative', label: 'Qualitative (A + B form)', js: (nl, nv, cp, s) => M.diffuseOrenNayarQualitative(nl, nv, cp, s, 0.8), glsl: 'diffuseOrenNayarQualitative(x, y, 0.5, 0.5, 0.8)' },
      { key: 'lambert', label: 'Lambert', js: () => M.diffuseLambert(0.8), glsl: 'diffuseLambert(0.8 * x)' },
    ],
  },
  MULTIPLE_SCATTERING_FAMILY,
];

/** max |error| (and where), and RMS, of each variant against the family's reference over its domain. */
export function measureErrors(family) {
  const ref = family.inputs.map((args) => family.reference(...args));
  return family.variants.map((v) => {
    let maxAbs = 0;
    let maxAt = null;
    let sq = 0;
    family.inputs.forEach((args, i) => {
      const e = v.js(...args) - ref[i];
      sq += e * e;
      if (Math.abs(e) > maxAbs) [maxAbs, maxAt] = [Math.abs(e), args.filter((a) => typeof a === 'number')];
    });
    return { key: v.key, maxAbs, rms: Math.sqrt(sq / family.inputs.length), maxAt };
  });
}
