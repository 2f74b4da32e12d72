// What `npm run stress` feeds every exported function of src/math, and the range each result must lie in.
// Every export is listed: a new function without an entry fails the stress test until it is classified.
import { CATALOGUE } from '../../src/math/catalogue/index.js';
import { argGroups, argParam, paramStress, termInputs } from '../../src/math/catalogue/grids.js';
import { ANISOTROPIC_STRESS_DOMAINS } from './stress-domains-anisotropic.js';

const COS = [-1, -0.5, 0, 1e-7, 1e-4, 0.5, 1 - 1e-7, 1, 1 + 1e-7, 1.5];
const ALPHA = [0, 1e-5, 1e-4, 1e-2, 0.3, 1, 2];
const ETA = [1e-3, 1 - 1e-6, 1, 1 + 1e-6, 1.5, 100];
const K = [0, 1e-3, 1, 10];
const F0 = [0, 0.04, 0.5, 1];
const SRGB = [-1, 0, 1e-4, 0.5, 1, 2];
const EXPONENT = [0, 1, 1e3, 1e6, 1e7, 2e8, 1e300, Number.MAX_VALUE, Infinity];
const ABC = [0, 0.01, 1, 1e4, 1e5];
const SGD_P = [-1, 0, 0.64, 1, 1.9, 3];
const ANGLE = [0, 1e-7, 0.7, Math.PI / 2, Math.PI];

const unit = (x, y, z) => {
  const n = Math.hypot(x, y, z);
  return [x / n, y / n, z / n];
};
// direction pairs with the degenerate cases: l = v, l = -v, mirror, grazing, below the horizon
const DIRS = [
  [0, 0, 1],
  [1, 0, 0],
  unit(1, 0, 1e-7),
  unit(0.6, 0, 0.8),
  unit(-0.6, 0, 0.8),
  unit(0, 0.6, 0.8),
  [0, 0, -1],
  unit(1, 0, -1),
];
const PAIRS = DIRS.flatMap((l) => [...DIRS.map((v) => [l, v]), [l, l.map((x) => -x)]]);

// the terms microfacetBRDF of src/math evaluates from the cosines (a term that reads the whole microfacet input,
// an anisotropic lobe, is swept alone, through termStress)
const cosineTerms = (family) =>
  Object.values(family.terms)
    .filter((t) => t.evaluate)
    .map((t) => t.key);
const D_KINDS = cosineTerms(CATALOGUE.ndf);
const V_KINDS = cosineTerms(CATALOGUE.visibility);
const BRDF_PARAMS = D_KINDS.flatMap((D) =>
  V_KINDS.flatMap((V) =>
    [0, 1e-4, 0.3, 1].map((alpha) => ({ F: 'schlick', D, V, alpha, f0: 0.04, exponent: 1e4, a1: 1e4, a2: 3, p: 1.9 })),
  ),
);

const ZERO_TO_ONE = [0, 1];
const SPLIT_SUM_TERMS = [
  {},
  { ndf: 'beckmann', visibility: 'cookTorrance' },
  { visibility: 'kelemen' },
  { visibility: 'smithBeckmannSeparable' },
];
const NON_NEGATIVE = [0, Infinity];
const FINITE = [-Infinity, Infinity]; // only NaN and ±Inf are failures

const TERM_ANGLES = {
  cos: COS,
  sin2h: [0, 1e-12, 0.5, 1],
  nl: COS,
  nv: COS,
  nh: COS,
  lh: COS,
  cosPhi: [-1.5, -1, 0, 1, 1.5],
};
const TERM_RANGE = { fresnel: ZERO_TO_ONE, ndf: NON_NEGATIVE, visibility: NON_NEGATIVE, diffuse: NON_NEGATIVE };

/**
 * A term's stress inputs: each argument over its list, or, for a term that reads directions of the microfacet
 * input (an anisotropic lobe's hx … vz), the tuples of the directions above (DIRS, unit) and its other arguments.
 * @param {import('../../src/math/catalogue/types.js').TermEntry} term
 */
function termStress(term) {
  const values = (arg) => {
    const param = argParam(term, arg);
    return param ? paramStress(param) : TERM_ANGLES[arg];
  };
  if (!argGroups(term.args).some((g) => g.kind.startsWith('dir:'))) return { args: term.args.map(values) };
  return { tuples: termInputs(term, (kind) => (kind.startsWith('dir:') ? DIRS : values(kind))) };
}

/**
 * The function of every catalogue term (fn, by its name), its angles over the lists above and its parameters over
 * their stress values (src/math/catalogue/grids.js). An entry below with the same name replaces it where the
 * function takes values past the catalogue's stress (float64 extremes: Blinn–Phong's p up to Infinity, …).
 */
const termDomains = () =>
  Object.fromEntries(
    Object.values(CATALOGUE).flatMap((family) =>
      Object.values(family.terms)
        .filter((term) => term.js)
        .map((term) => [term.glsl, { fn: term.js, ...termStress(term), range: TERM_RANGE[family.family] }]),
    ),
  );

/**
 * name -> { fn?: the function if not M[name], args: [list per argument] } | { tuples: [argument lists] } |
 * { pairs: [[l, v]], params } with range [lo, hi]; pick: the result fields to check; allowInfinity: Inf is a
 * documented result (meanFreePath in a vacuum). Functions in `skipped` say why they are not swept.
 */
export const STRESS_DOMAINS = {
  ...termDomains(),
  ...ANISOTROPIC_STRESS_DOMAINS,
  srgbToLinear: { args: [SRGB], range: ZERO_TO_ONE },
  linearToSrgb: { args: [SRGB], range: ZERO_TO_ONE },
  fresnelSchlickSG: { args: [F0, COS], range: ZERO_TO_ONE },
  fresnelConductor: { args: [COS, ETA, K], range: ZERO_TO_ONE },
  f0FromIor: { args: [ETA, K], range: ZERO_TO_ONE },
  iorFromF0: { args: [[-1, 0, 0.04, 0.999, 1, 2]], range: [1, Infinity] },
  conductorIorFromF0EdgeTint: {
    args: [
      [-1, 0, 0.5, 0.999, 1, 2],
      [-1, 0, 0.5, 1, 2],
    ],
    range: NON_NEGATIVE,
  },
  edgeTintFromConductorIor: { args: [[0.01, 0.5, 1, 3, 100], K], range: FINITE },
  f82TintFromConductor: { args: [ETA, K], range: [0, 2.2], pick: ['f0', 'tint'] }, // tint ≤ 1 / (6/7)⁵ ≈ 2.16
  fresnelZone: { args: [COS], range: [0, 2] },
  sphereZoneFractions: { args: [], range: ZERO_TO_ONE },
  clampAlpha: { args: [ALPHA], range: [1e-4, 1] },
  clampAbc: { args: [ABC, ABC], range: [0.01, 1e4] },
  clampSgd: { args: [ALPHA, SGD_P], range: [0, 2] },
  ndfGGX: { args: [COS, ALPHA], range: NON_NEGATIVE },
  ndfBeckmann: { args: [COS, ALPHA], range: NON_NEGATIVE },
  ndfBlinnPhong: { args: [COS, EXPONENT], range: NON_NEGATIVE },
  ndfBlinnPhongFromSin2: { args: [COS, [0, 1e-300, 1e-12, 0.5, 1], EXPONENT], range: NON_NEGATIVE },
  ndfABC: { args: [COS, ABC, ABC], range: NON_NEGATIVE },
  abcNormalization: {
    args: [
      [0.01, 0.5, 1, 1e4],
      [0.05, 1, 2, 20],
    ],
    range: [0, 1],
  },
  ndfSGD: { args: [COS, ALPHA, SGD_P], range: NON_NEGATIVE },
  sgdNormalization: {
    args: [
      [0.01, 0.3, 2],
      [0, 0.64, 1, 1.9],
    ],
    range: NON_NEGATIVE,
  },
  blinnPhongExponentFromBeckmannAlpha: { args: [ALPHA], range: NON_NEGATIVE },
  beckmannAlphaFromBlinnPhongExponent: { args: [EXPONENT], range: [1e-4, 1] },
  ndfParamsMatchingGGX: { args: [D_KINDS, [1e-3, 0.05, 0.5, 1]], range: NON_NEGATIVE },
  matchNdfWidths: { args: [[1, 10, 40]], range: NON_NEGATIVE },
  erf: { args: [[-30, -2.5, -1e-9, 0, 1e-9, 2.5, 30]], range: [-1, 1] },
  erfc: { args: [[0, 1e-9, 2.4999, 2.5, 10, 30]], range: [0, 2] },
  smithG1GGX: { args: [COS, ALPHA], range: ZERO_TO_ONE },
  smithG1Beckmann: { args: [COS, ALPHA], range: ZERO_TO_ONE },
  smithG1BeckmannWalter: { args: [COS, ALPHA], range: ZERO_TO_ONE },
  halfVector: { pairs: PAIRS, range: [-1, 1], nullable: true },
  brdfAngles: { pairs: PAIRS, range: [-1, 1] },
  halfDiffAngles: { pairs: PAIRS.filter(([l, v]) => l.some((x, i) => x !== -v[i])), range: [0, Math.PI] },
  halfDiffFromDirections: {
    pairs: PAIRS.filter(([l, v]) => l.some((x, i) => x !== -v[i])),
    range: [-Math.PI, Math.PI],
  },
  reflect: { pairs: PAIRS, range: [-1, 1] },
  microfacetBRDF: { pairs: PAIRS, params: BRDF_PARAMS, range: NON_NEGATIVE },
  microfacetTerms: { pairs: PAIRS, params: BRDF_PARAMS, pick: ['F', 'D', 'V', 'G'], range: NON_NEGATIVE },
  microfacetTermsAt: {
    tuples: COS.flatMap((c) => BRDF_PARAMS.slice(0, 40).map((p) => [{ nl: c, nv: c, nh: c, lh: c }, p])),
    pick: ['F', 'D', 'V', 'G'],
    range: NON_NEGATIVE,
  },
  microfacetBRDFAt: {
    tuples: COS.flatMap((c) => BRDF_PARAMS.map((p) => [{ nl: c, nv: 1 - c / 3, nh: c, lh: c }, p])),
    range: NON_NEGATIVE,
  },
  microfacetFactors: {
    pairs: PAIRS,
    params: BRDF_PARAMS,
    use: { F: true, D: true, G: true, denominator: true },
    range: NON_NEGATIVE,
  },
  brdf: { pairs: PAIRS, params: BRDF_PARAMS, range: NON_NEGATIVE },
  diffuseLambert: { args: [SRGB], range: [0, 1 / Math.PI] },
  diffuseFresnelWeighted: { args: [COS, COS, F0, SRGB], range: [0, 1 / Math.PI] },
  diffuseAshikhminShirley: { args: [COS, COS, F0, SRGB], range: [0, 28 / (23 * Math.PI)] },
  diffuseOrenNayar: { args: [COS, COS, [-1.5, -1, 0, 1, 1.5], [0, 0.3, 1, 3], SRGB], range: NON_NEGATIVE },
  diffuseOrenNayarQualitative: { args: [COS, COS, [-1.5, -1, 0, 1, 1.5], [0, 0.3, 1, 3], SRGB], range: NON_NEGATIVE },
  punctualRadiance: { args: [[0, 1, 1e8], COS, [0, 1]], range: NON_NEGATIVE },
  brdfFromPunctualRadiance: { args: [[0, 1, 1e8], COS, [0, 1e-8, 1]], range: NON_NEGATIVE, nullable: true },
  directionFromCos: { args: [COS], range: [-1, 1] },
  directionsFromHalfDiff: { args: [ANGLE, ANGLE, ANGLE], range: [-1, 1] },
  sampleGGXNormal: { args: [[0, 0.5, 1 - 1e-12], [0, 0.5, 1], ALPHA], range: [-1, 1] },
  sampleBeckmannNormal: { args: [[0, 0.5, 1 - 1e-12], [0, 0.5, 1], ALPHA], range: [-1, 1] },
  hammersley: {
    tuples: [
      [0, 1],
      [0, 256],
      [255, 256],
      [2 ** 31, 2 ** 32],
      [2 ** 32 - 1, 2 ** 32],
    ],
    range: ZERO_TO_ONE,
  },
  albedoGGX: { args: [COS, ALPHA], range: ZERO_TO_ONE },
  // a mismatched pair (GGX's D with Beckmann's Smith) sends back up to ~1.6 at grazing
  dfgSplitSum: { args: [COS, ALPHA, SPLIT_SUM_TERMS], range: [0, 2] },
  dfgTableUv: { args: [COS, ALPHA], range: ZERO_TO_ONE },
  sampleCosine: {
    args: [
      [0, 0.5, 1 - 1e-12, 1],
      [0, 0.5, 1],
    ],
    range: [-1, 1],
  },
  sampleCone: {
    args: [
      [0, 0.5, 1],
      [0, 0.5, 1],
      [-1, 0, 0.9999, 1],
    ],
    range: [-1, 1],
  },
  sphereLightCLight: {
    args: [
      [0, 1, 1e4],
      [0, 1e-4, 0.05, 1],
    ],
    range: NON_NEGATIVE,
  },
  sphereLightRepresentativeDir: {
    tuples: PAIRS.flatMap(([r, d]) => [0, 1e-4, 0.05, 1].map((s) => [r, d, s])),
    range: [-1, 1],
  },
  equirectUv: { tuples: DIRS.map((d) => [d]), range: ZERO_TO_ONE },
  equirectDirection: {
    args: [
      [0, 0.25, 1],
      [0, 0.5, 1],
    ],
    range: [-1, 1],
  },
  sphereLightNormalization: { args: [ALPHA, [0, 1e-4, 0.05, 1]], range: ZERO_TO_ONE },
  transmittance: {
    args: [
      [-1, 0, 1e-9, 0.3, 1e3],
      [-1, 0, 1, 1e6],
    ],
    range: ZERO_TO_ONE,
  },
  opticalDepth: {
    args: [
      [-1, 0, 0.3, 1e3],
      [-1, 0, 1, 1e6],
    ],
    range: NON_NEGATIVE,
  },
  scatteringAlbedo: {
    args: [
      [-1, 0, 1, 1e6],
      [-1, 0, 1, 1e6],
    ],
    range: ZERO_TO_ONE,
  },
  meanFreePath: { args: [[-1, 0, 1e-9, 1, 1e6]], range: [0, Infinity], allowInfinity: true },
  absorptionFromK: {
    args: [
      [0, 1e-9, 1],
      [0.4, 0.7],
    ],
    range: NON_NEGATIVE,
  },
  waterAbsorptionRgb: { args: [], range: NON_NEGATIVE },
  lambertianEntryAngle2D: { args: [[() => 0, () => 0.5, () => 1 - 1e-12]], range: [-Math.PI / 2, Math.PI / 2] },
  slopeDensity: {
    args: [
      ['beckmann', 'ggx'],
      [0.01, 0.3, 1],
      [-1e6, -1, 0, 1, 1e6],
    ],
    range: NON_NEGATIVE,
  },
  reflectedAngleDensity: {
    args: [[-Math.PI, -1, 0, 1, Math.PI], [0, 0.7, 1.5], ['beckmann', 'ggx'], [0.05, 0.5], [(c, a) => c ** a]],
    range: NON_NEGATIVE,
  },
  segmentNormal: {
    tuples: [
      [[0, 1, -5, 1e6], 0],
      [[0, 1, -5, 1e6], 1],
      [[0, 1, -5, 1e6], 2],
    ],
    range: [-1, 1],
  },
  heightBounds: { tuples: [[[0, 3, -2, 7]], [[5]]], range: FINITE },
  averageAlbedoGGX: { args: [ALPHA], range: ZERO_TO_ONE },
  multipleScatteringFromLoss: {
    args: [
      [-0.5, 0, 1e-7, 0.3, 1, 1.5],
      [-0.5, 0, 1e-7, 0.3, 1, 1.5],
      [-0.5, 0, 1e-7, 0.59, 1, 1.5],
    ],
    range: NON_NEGATIVE,
  },
  multipleScatteringKullaConty: { args: [COS, COS, ALPHA], range: NON_NEGATIVE },
  fresnelAverage: { args: [F0], range: ZERO_TO_ONE },
  fresnelMultipleScatteringKullaConty: { args: [F0, [0, 1e-7, 0.4, 1]], range: ZERO_TO_ONE },
  energyCompensationTurquin: { args: [F0, [-1, 0, 1e-7, 0.3, 1, 1.5]], range: [1, 1e4] },
  compensatedAlbedoGGX: { args: [COS, ALPHA, F0, ['none', 'kullaConty', 'turquin']], range: ZERO_TO_ONE },
  sampleVisibleNormalGGX: {
    tuples: DIRS.flatMap((d) =>
      ALPHA.flatMap((a) =>
        [
          [0, 0],
          [0.5, 0.3],
          [1 - 1e-12, 1],
        ].map(([u, w]) => [d, a, u, w]),
      ),
    ),
    range: [-1, 1],
  },
  randomWalkAlbedoGGX: {
    tuples: COS.flatMap((mu) => ALPHA.flatMap((a) => [0, 1, [1, 0.71, 0.29]].map((f0) => [mu, a, f0, 100, 1]))),
    pick: ['albedo', 'single', 'standardError', 'singleStandardError', 'dropped'],
    range: ZERO_TO_ONE,
  },
  buildAlbedoTableGGX: { tuples: [[2], [3]], pick: ['data'], range: ZERO_TO_ONE },
  tableSplitSum: { args: [COS, ALPHA], range: ZERO_TO_ONE },
  albedoLossTableGGX: {
    tuples: [-1, 0, 1e-7, 0.5, 1, 1.5].flatMap((mu) =>
      ALPHA.map((a) => [
        { size: 2, data: new Float32Array([0.1, 0.2, 0, 1, 0.3, 0.2, 0.1, 1, 0, 0, 0, 1, 0.05, 0, 0.2, 1]) },
        mu,
        a,
      ]),
    ),
    range: ZERO_TO_ONE,
  },
  specularAlbedoFromTable: {
    tuples: [0, 1e-7, 0.5, 1].flatMap((mu) =>
      F0.flatMap((f0) =>
        ['none', 'kullaConty', 'turquin'].map((c) => [
          { size: 2, data: new Float32Array([0.1, 0.2, 0, 1, 0.3, 0.2, 0.1, 1, 0, 0, 0, 1, 0.05, 0, 0.2, 1]) },
          mu,
          0.5,
          f0,
          c,
        ]),
      ),
    ),
    range: ZERO_TO_ONE,
  },
  randomWalkBRDFGGX: {
    tuples: PAIRS.flatMap(([l, v]) => [0, 1e-4, 0.3, 1].map((a) => [l, v, a, 0.5, 20, 1])),
    range: NON_NEGATIVE,
  },
  sphereSolidAngle: {
    args: [
      [-1, 0, 1e-9, 1, 1e6],
      [-1, 0, 1e-9, 1, 1e6],
    ],
    range: [0, 2 * Math.PI],
  },
  sphereLightIrradiance: {
    args: [
      [-1, 0, 1, 1e6],
      [-1, 0, 1e-9, 1, 1e6],
      [-1, 0, 1e-9, 1, 1e6],
    ],
    range: NON_NEGATIVE,
  },
  planckRadiance: {
    args: [
      [-1, 0, 1e-3, 380, 780, 1e6],
      [-1, 0, 1, 1000, 6500, 1e6],
    ],
    range: NON_NEGATIVE,
  },
  cieXyzFit: { args: [[-1e6, 0, 380, 555, 780, 1e6]], range: [0, 2] },
  spectrumToXyz: { args: [[() => 0, () => 1, (l) => l / 780]], range: NON_NEGATIVE },
  xyzToLinearSrgb: { tuples: [[[0, 0, 0]], [[0.95047, 1, 1.08883]], [[1e6, 0, 0]]], range: FINITE },
  luminanceRec709: { tuples: [[[0, 0, 0]], [[1, 1, 1]], [[1e-30, 0, 0]], [[1e6, 1e6, 1e6]]], range: NON_NEGATIVE },
  skipped: {
    seededRandom: 'returns a generator; unit-tested through the samplers',
    sampleSlope: 'Monte Carlo; its moments are unit-tested',
    generateProfile: 'Monte Carlo; its statistics are unit-tested',
    castUp: 'ray casting; tested through measuredG1 and reflectedAngles against Smith',
    intersectProfile: 'ray casting for drawing; exercised by the microfacets widget test',
    measuredG1: 'Monte Carlo; unit-tested against Smith G1',
    reflectedAngles: 'Monte Carlo; unit-tested against reflectedAngleDensity',
    randomWalk2D: 'a Monte Carlo walk; its statistics are unit-tested against published results',
    hemisphereIntegral: 'takes an integrand; exercised by the unit tests with BRDFs',
    reflectanceImportanceGGX: 'takes a BRDF; exercised by the unit tests',
    averageAlbedo: 'takes E(mu); exercised by the unit tests',
    ndfHalfWidthDeg: 'takes an NDF; exercised through matchNdfWidths',
    ndfProjectedIntegral: 'takes an NDF; exercised by the normalisation tests',
    channelIor: 'data lookup; swept over every table material below',
    fresnelParams: 'data lookup; swept over every table material below',
    materialByKey: 'data lookup',
    isMetal: 'data lookup',
    measuredRgbNk: 'data lookup; swept through channelIor',
    measuredSource: 'data lookup',
    nkAtWavelength: 'interpolation of published rows; unit-tested',
  },
};
