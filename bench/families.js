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
import { ANISOTROPY_FAMILY } from './anisotropy-family.js';
import { F82_TINT_FAMILY } from './f82-tint-family.js';
import { OPENPBR_FAMILY } from './openpbr-family.js';
import { DEG } from '../src/math/angles.js';
import { CATALOGUE } from '../src/math/catalogue/index.js';

const range = (n, lo, hi) => Array.from({ length: n }, (_, i) => lo + ((hi - lo) * i) / (n - 1));
const COS = range(1001, 0, 1);

const measuredChannels = M.METALS.flatMap((m) =>
  M.measuredRgbNk(m.key).map(([n, k], ch) => ({ n, k, f0: M.f0FromIor(n, k), label: `${m.key} ${'RGB'[ch]}` })),
);

// The visibility and NDF families have one variant per catalogue term. What each is in the comparison (its key in
// the tables, kind, target, model, and the GLSL expression the GPU bench times) is said here for the terms it
// concerns; a term not named is another model, measured as its difference from the reference, with its own
// function on the GPU (angles x, y; its parameters from BENCH_GLSL or mid-range).
const BENCH_GLSL = {
  visibility: { alpha: '0.3' },
  ndf: {
    ...{ nh: 'x', sin2h: '(1.0 - x) * (1.0 + x)' }, // D over x = n·h (the microfacet input's nh, sin2h)
    ...{ alpha: '0.05 + 0.5 * y', exponent: '10.0 + 100.0 * y', a1: '1.0 + 100.0 * y', a2: '2.5', p: '0.64' },
  },
};
const glslFloat = (x) => (Number.isInteger(x) ? x.toFixed(1) : String(x));
const BENCH_ANGLE = {
  cos: 'x',
  sin2: '(1.0 - x) * (1.0 + x)',
  nl: 'x',
  nv: 'y',
  nh: '0.5 + 0.5 * x',
  lh: '0.5 + 0.5 * y',
};
const VISIBILITY_ROLES = {
  smithGGXCorrelated: { key: 'correlated', kind: 'reference' },
  smithGGXSeparable: { key: 'separable', model: 'smith-ggx-separable' },
  smithGGXCorrelatedFast: { key: 'hammon', kind: 'approximation', against: 'correlated' },
  schlickGGX: { key: 'schlick-ggx', kind: 'approximation', against: 'separable', model: 'smith-ggx-separable' },
};
// the visibility inputs are [nl, nv, nh, lh, alpha], compared in G = V (n·l)(n·v)
const visibilityOf = (term) => (nl, nv, nh, lh, alpha) => term.evaluate({ nl, nv, nh, lh }, { alpha }) * nl * nv;
const NDF_ROLES = {
  beckmann: { kind: 'reference' },
  blinnPhong: {
    key: 'blinn-phong',
    label: 'Blinn–Phong (Walter’s exponent)',
    kind: 'approximation',
    against: 'beckmann',
    model: 'beckmann',
    params: (m) => ({ exponent: M.blinnPhongExponentFromBeckmannAlpha(m.beckmann.alpha) }),
  },
};
// the NDF inputs are [cos θh, the matched parameters of every NDF, Beckmann's peak], compared in D / D_Beckmann(0)
const ndfOf = (term, params) => (c, m, peak) => term.evaluate(c, params ? params(m) : m[term.key]) / peak;
const FAMILY_OF = { visibility: visibilityOf, ndf: ndfOf };
const MODEL_OF = { smithGGXCorrelated: 'smith-ggx-correlated', smithGGXCorrelatedFast: 'smith-ggx-correlated' };
const kebab = (key) => key.replace(/[A-Z]+/g, (m) => `-${m.toLowerCase()}`);

/**
 * A term whose GLSL takes a normaliser computed once per draw (SGD's Γ(1 - p, α)) gets the one of its parameters'
 * midpoints: a uniform in the app, a constant here, the same cost per pixel.
 */
const normaliserOf = ({ normaliser, args, params }) =>
  normaliser ? [glslFloat(normaliser(...args.slice(1).map((a) => (params[a].min + params[a].max) / 2)))] : [];

/** One variant per term of a catalogue family, the reference first. */
function termVariants(family, roles) {
  // the terms with a curve over the bench's two cosines (not a lobe that reads the whole microfacet input)
  const variants = Object.values(CATALOGUE[family].terms)
    .filter((term) => term.evaluate)
    .map((term) => {
      const role = roles[term.key] ?? {};
      const model = role.model ?? MODEL_OF[term.key] ?? kebab(term.key);
      const reference = Object.keys(roles).find((k) => roles[k].kind === 'reference');
      const { params } = term;
      const glslOf = (arg) =>
        BENCH_GLSL[family][arg] ?? BENCH_ANGLE[arg] ?? glslFloat((params[arg].min + params[arg].max) / 2);
      return {
        key: role.key ?? kebab(term.key),
        label: role.label ?? term.label,
        kind: role.kind ?? 'difference',
        ...(role.kind === 'reference' ? {} : { against: role.against ?? roles[reference].key ?? kebab(reference) }),
        model,
        js: FAMILY_OF[family](term, role.params),
        glsl: role.glsl ?? `${term.glsl}(${[...term.args.map(glslOf), ...normaliserOf(term)].join(', ')})`,
      };
    });
  return [...variants.filter((v) => v.kind === 'reference'), ...variants.filter((v) => v.kind !== 'reference')];
}

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
      'l and v in one plane on opposite sides of n, θl, θv in [0°, 89°] (1° steps) × ' +
      'α in {0.05, 0.1, 0.3, 0.5, 0.8, 1}; compared in G = V (n·l)(n·v)',
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
    variants: termVariants('visibility', VISIBILITY_ROLES),
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
    variants: termVariants('ndf', NDF_ROLES),
  },
  {
    key: 'oren-nayar',
    title: 'Oren–Nayar: the qualitative form approximating the full model, and Lambert’s difference from it',
    domain:
      'θl, θv in [0°, 85°] (5° steps) × cos φ in {−1, −0.5, 0, 0.5, 1} × σ in {0.1, 0.3, 0.6, 1} (radians), ' +
      'c_diff = 0.8; compared in f (1/sr)',
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
  ANISOTROPY_FAMILY,
  F82_TINT_FAMILY,
  OPENPBR_FAMILY,
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
