// The families of terms the benchmark compares: for each, a documented input domain and the variants (a JS
// function and the GLSL expression that computes the same thing on the GPU), the first the float64 reference.
// Shared by the CPU/error benchmark (Node) and the GPU benchmark page (Chromium).
//
// Every variant says what it is (`kind`) and what it is measured against (`against`, another variant's key):
//   'reference'      the family's exact float64 form (first variant, against nothing);
//   'approximation'  a cheaper form of the same model as `against` (same `model`): its distance is an error;
//   'difference'     another model altogether: its distance from `against` is a difference, not an error.
// `model` names the model a variant computes or approximates; tests/unit/bench-families.test.js holds the
// kinds consistent with it.
import * as M from '../src/math/index.js';
import { MULTIPLE_SCATTERING_FAMILY } from './multiple-scattering-family.js';
import { DEG } from '../src/math/angles.js';

const range = (n, lo, hi) => Array.from({ length: n }, (_, i) => lo + ((hi - lo) * i) / (n - 1));
const COS = range(1001, 0, 1);

/** G = V (n·l)(n·v) of a visibility term V(n·l, n·v, α), over the visibility family's inputs. */
const asG = (V) => (nl, nv, nh, lh, a) => V(nl, nv, a) * nl * nv;

const measuredChannels = M.METALS.flatMap((m) =>
  M.measuredRgbNk(m.key).map(([n, k], ch) => ({ n, k, f0: M.f0FromIor(n, k), label: `${m.key} ${'RGB'[ch]}` })),
);

export const FAMILIES = [
  {
    key: 'fresnel-dielectric',
    title: 'Fresnel, dielectrics',
    domain: 'cos θ in [0, 1] (1001 points) × n in {1.33, 1.5, 1.76, 2.42}',
    errorOf: 'reflectance',
    inputs: COS.flatMap((c) => [1.33, 1.5, 1.76, 2.42].map((eta) => [c, eta, M.f0FromIor(eta)])),
    variants: [
      {
        key: 'exact',
        label: 'Exact (fresnelDielectric)',
        kind: 'reference',
        model: 'fresnel',
        js: (c, eta) => M.fresnelDielectric(c, eta),
        glsl: 'fresnelDielectric(x, 1.0 + y)',
      },
      {
        key: 'schlick',
        label: 'Schlick',
        kind: 'approximation',
        against: 'exact',
        model: 'fresnel',
        js: (c, eta, f0) => M.fresnelSchlick(f0, c),
        glsl: 'fresnelSchlick(0.04 * y, x)',
      },
      {
        key: 'schlick-sg',
        label: 'Schlick, spherical Gaussian (Karis 2013)',
        kind: 'approximation',
        against: 'exact',
        model: 'fresnel',
        js: (c, eta, f0) => M.fresnelSchlickSG(f0, c),
        glsl: 'fresnelSchlickSG(0.04 * y, x)',
      },
    ],
  },
  {
    key: 'fresnel-conductor',
    title: 'Fresnel, metals',
    domain: 'cos θ in [0, 1] (1001 points) × the measured (n, k) of the five metals at 650/550/450 nm',
    errorOf: 'reflectance',
    inputs: COS.flatMap((c) => measuredChannels.map(({ n, k, f0 }) => [c, n, k, f0])),
    variants: [
      {
        key: 'exact',
        label: 'Exact (fresnelConductor)',
        kind: 'reference',
        model: 'fresnel',
        js: (c, n, k) => M.fresnelConductor(c, n, k),
        glsl: 'fresnelConductor(x, 0.2 + y, 3.0 + y)',
      },
      {
        key: 'schlick',
        label: 'Schlick',
        kind: 'approximation',
        against: 'exact',
        model: 'fresnel',
        js: (c, n, k, f0) => M.fresnelSchlick(f0, c),
        glsl: 'fresnelSchlick(0.5 + 0.4 * y, x)',
      },
      {
        key: 'schlick-sg',
        label: 'Schlick, spherical Gaussian',
        kind: 'approximation',
        against: 'exact',
        model: 'fresnel',
        js: (c, n, k, f0) => M.fresnelSchlickSG(f0, c),
        glsl: 'fresnelSchlickSG(0.5 + 0.4 * y, x)',
      },
    ],
  },
  {
    key: 'smith-g1-beckmann',
    title: 'Smith G1, Beckmann',
    domain: 'cos θ in [0.001, 1] (1000 points) × α in {0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1}',
    errorOf: 'G1',
    inputs: range(1000, 0.001, 1).flatMap((c) => [0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1].map((a) => [c, a])),
    variants: [
      {
        key: 'exact',
        label: 'Exact, with erf',
        kind: 'reference',
        model: 'smith-g1-beckmann',
        js: (c, a) => M.smithG1Beckmann(c, a),
        glsl: 'smithG1Beckmann(x, 0.05 + y)',
      },
      {
        key: 'walter',
        label: 'Rational fit (Walter 2007)',
        kind: 'approximation',
        against: 'exact',
        model: 'smith-g1-beckmann',
        js: (c, a) => M.smithG1BeckmannWalter(c, a),
        glsl: 'smithG1BeckmannWalter(x, 0.05 + y)',
      },
    ],
  },
  {
    key: 'visibility',
    title: 'Visibility: approximations of Smith GGX, and other models’ difference from it',
    domain:
      'l and v in one plane on opposite sides of n, θl, θv in [0°, 89°] (1° steps) × α in {0.05, 0.1, 0.3, 0.5, 0.8, 1}; compared in G = V (n·l)(n·v)',
    errorOf: 'G',
    // Schlick-GGX is Karis 2013's fit to Smith GGX's G1, used as the separable product G1(l) G1(v): it is
    // scored against the separable form it approximates, which is itself a different model (uncorrelated
    // heights) from the height-correlated reference (Heitz 2014).
    inputs: range(90, 0, 89).flatMap((tl) =>
      range(90, 0, 89).flatMap((tv) =>
        [0.05, 0.1, 0.3, 0.5, 0.8, 1].map((a) => {
          const l = [-Math.sin(tl * DEG), 0, Math.cos(tl * DEG)];
          const v = [Math.sin(tv * DEG), 0, Math.cos(tv * DEG)];
          const { nl, nv, nh, lh } = M.brdfAngles(l, v);
          return [nl, nv, nh, lh, a];
        }),
      ),
    ),
    variants: [
      {
        key: 'correlated',
        label: 'Height-correlated Smith (Heitz 2014)',
        kind: 'reference',
        model: 'smith-ggx-correlated',
        js: asG(M.visibilitySmithGGXCorrelated),
        glsl: 'visibilitySmithGGXCorrelated(x, y, 0.3)',
      },
      {
        key: 'separable',
        label: 'Separable Smith',
        kind: 'difference',
        against: 'correlated',
        model: 'smith-ggx-separable',
        js: asG(M.visibilitySmithGGXSeparable),
        glsl: 'visibilitySmithGGXSeparable(x, y, 0.3)',
      },
      {
        key: 'hammon',
        label: 'Hammon 2017',
        kind: 'approximation',
        against: 'correlated',
        model: 'smith-ggx-correlated',
        js: asG(M.visibilitySmithGGXCorrelatedFast),
        glsl: 'visibilitySmithGGXCorrelatedFast(x, y, 0.3)',
      },
      {
        key: 'schlick-ggx',
        label: 'Schlick-GGX (k = α/2, Karis 2013)',
        kind: 'approximation',
        against: 'separable',
        model: 'smith-ggx-separable',
        js: asG(M.visibilitySchlickGGX),
        glsl: 'visibilitySchlickGGX(x, y, 0.3)',
      },
      {
        key: 'cook-torrance',
        label: 'Cook-Torrance',
        kind: 'difference',
        against: 'correlated',
        model: 'cook-torrance',
        js: (nl, nv, nh, lh) => M.visibilityCookTorrance(nl, nv, nh, lh) * nl * nv,
        glsl: 'visibilityCookTorrance(x, y, 0.5 + 0.5 * x, 0.5 + 0.5 * y)',
      },
      {
        key: 'kelemen',
        label: 'Kelemen',
        kind: 'difference',
        against: 'correlated',
        model: 'kelemen',
        js: (nl, nv, nh, lh) => (nl > 0 && nv > 0 ? M.visibilityKelemen(lh) * nl * nv : 0),
        glsl: 'visibilityKelemen(0.5 + 0.5 * y)',
      },
      {
        key: 'implicit',
        label: 'Implicit (V = 1)',
        kind: 'difference',
        against: 'correlated',
        model: 'implicit',
        js: (nl, nv) => M.visibilityImplicit(nl, nv) * nl * nv,
        glsl: 'visibilityImplicit(x, y)',
      },
    ],
  },
  {
    key: 'ndf',
    title: 'NDFs at one half width: Blinn-Phong approximating Beckmann, and the other shapes’ difference from it',
    domain: 'θh in [0°, 90°) (0.25° steps) × half widths {2°, 5°, 10°, 20°}; compared in D / D(0) of Beckmann',
    errorOf: 'D / D_Beckmann(0)',
    inputs: [2, 5, 10, 20].flatMap((hw) => {
      const m = M.matchNdfWidths(hw);
      const peak = M.ndfBeckmann(1, m.beckmann.alpha);
      return range(360, 0, 89.75).map((deg) => [Math.cos(deg * DEG), m, peak]);
    }),
    variants: [
      {
        key: 'beckmann',
        label: 'Beckmann',
        kind: 'reference',
        model: 'beckmann',
        js: (c, m, peak) => M.ndfBeckmann(c, m.beckmann.alpha) / peak,
        glsl: 'ndfBeckmann(x, 0.05 + 0.5 * y)',
      },
      {
        key: 'blinn-phong',
        label: 'Blinn-Phong (Walter’s exponent)',
        kind: 'approximation',
        against: 'beckmann',
        model: 'beckmann',
        js: (c, m, peak) => M.ndfBlinnPhong(c, M.blinnPhongExponentFromBeckmannAlpha(m.beckmann.alpha)) / peak,
        glsl: 'ndfBlinnPhong(x, 10.0 + 100.0 * y)',
      },
      {
        key: 'ggx',
        label: 'GGX',
        kind: 'difference',
        against: 'beckmann',
        model: 'ggx',
        js: (c, m, peak) => M.ndfGGX(c, m.ggx.alpha) / peak,
        glsl: 'ndfGGX(x, 0.05 + 0.5 * y)',
      },
      {
        key: 'abc',
        label: 'ABC',
        kind: 'difference',
        against: 'beckmann',
        model: 'abc',
        js: (c, m, peak) => M.ndfABC(c, m.abc.a1, m.abc.a2) / peak,
        glsl: 'ndfABC(x, 1.0 + 100.0 * y, 2.5)',
      },
      {
        key: 'sgd',
        label: 'Shifted gamma',
        kind: 'difference',
        against: 'beckmann',
        model: 'sgd',
        js: (c, m, peak) => M.ndfSGD(c, m.sgd.alpha, m.sgd.p) / peak,
        glsl: 'ndfSGD(x, 0.05 + 0.5 * y, 0.64)',
      },
    ],
  },
  {
    key: 'oren-nayar',
    title: 'Oren–Nayar: the qualitative form approximating the full model, and Lambert’s difference from it',
    domain:
      'θl, θv in [0°, 85°] (5° steps) × cos φ in {−1, −0.5, 0, 0.5, 1} × σ in {0.1, 0.3, 0.6, 1} (radians), c_diff = 0.8; compared in f (1/sr)',
    errorOf: 'f',
    inputs: range(18, 0, 85).flatMap((tl) =>
      range(18, 0, 85).flatMap((tv) =>
        [-1, -0.5, 0, 0.5, 1].flatMap((cp) =>
          [0.1, 0.3, 0.6, 1].map((s) => [Math.cos(tl * DEG), Math.cos(tv * DEG), cp, s]),
        ),
      ),
    ),
    variants: [
      {
        key: 'full',
        label: 'Full model (with inter-reflection)',
        kind: 'reference',
        model: 'oren-nayar',
        js: (nl, nv, cp, s) => M.diffuseOrenNayar(nl, nv, cp, s, 0.8),
        glsl: 'diffuseOrenNayar(x, y, 0.5, 0.5, 0.8)',
      },
      {
        key: 'qualitative',
        label: 'Qualitative (A + B form)',
        kind: 'approximation',
        against: 'full',
        model: 'oren-nayar',
        js: (nl, nv, cp, s) => M.diffuseOrenNayarQualitative(nl, nv, cp, s, 0.8),
        glsl: 'diffuseOrenNayarQualitative(x, y, 0.5, 0.5, 0.8)',
      },
      {
        key: 'lambert',
        label: 'Lambert',
        kind: 'difference',
        against: 'full',
        model: 'lambert',
        js: () => M.diffuseLambert(0.8),
        glsl: 'diffuseLambert(0.8 * x)',
      },
    ],
  },
  MULTIPLE_SCATTERING_FAMILY,
];

/**
 * max |distance| (and where), and RMS, of each variant from what it is measured against (`against`; the
 * reference measures 0 against itself) over the family's domain: an error for an approximation, a
 * difference for another model.
 */
export function measureErrors(family) {
  const values = new Map(family.variants.map((v) => [v.key, family.inputs.map((args) => v.js(...args))]));
  return family.variants.map((v) => {
    const ref = values.get(v.against ?? v.key);
    let maxAbs = 0;
    let maxAt = null;
    let sq = 0;
    family.inputs.forEach((args, i) => {
      const e = values.get(v.key)[i] - ref[i];
      sq += e * e;
      if (Math.abs(e) > maxAbs) [maxAbs, maxAt] = [Math.abs(e), args.filter((a) => typeof a === 'number')];
    });
    return { key: v.key, maxAbs, rms: Math.sqrt(sq / family.inputs.length), maxAt };
  });
}
