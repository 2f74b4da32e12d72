// The bench family of OpenPBR Surface's layers (src/math/openpbr.js, shaders/openpbr.glsl): the stack built up
// layer by layer (the base's diffuse alone; + the specular lobe, which is the talk's model: GGX, height-correlated
// Smith, Fresnel, the diffuse term; + the coat; + the fuzz, the whole material the lab renders), each stack's GPU
// cost with the layers above it compiled out (OPENPBR_NO_SPECULAR, _NO_COAT, _NO_FUZZ) against the talk's model's,
// and its directional albedo against light followed through the layers themselves (layeredWalkAlbedo, Guo, Hašan &
// Zhao 2018's position-free Monte Carlo), the family's reference: what each layer adds, and what OpenPBR's albedo
// scaling misses. Each stack's albedo is its openPbrBRDF's (every layer it leaves out at weight 0) integrated over
// the hemisphere (openPbrFurnace: GGX-sampled lobes, the midpoint rule for the diffuse); the walk runs once, when the
// reference is first asked for (in Node; the GPU page only compiles the expressions). The walk has no fuzz layer:
// every case has fuzz_weight 0, so the last stack's figures are the coat's and only its cost is the fuzz's.
import { layeredWalkAlbedo } from '../src/math/openpbr-walk.js';
import { openPbrFurnace } from '../src/lab/openpbr-breakdown.js';
import { openPbrAlbedoTable } from '../src/math/openpbr-albedo.js';

export const MUS = [0.1, 0.3, 0.5, 0.7, 0.9, 1];
export const WALK_SAMPLES = 100_000; // per (case, μ): standard error ≤ 1.6e-3
let walkSamples = WALK_SAMPLES;
// per microfacet lobe: within 1.1e-3 of a Gauss quadrature (the lab’s bars take 1024)
export const FURNACE_SAMPLES = 16384;
// --quick (the bench's test reads only the report's shape): 64 per lobe (the family's errors: 15 s → 1.5 s)
const QUICK_FURNACE_SAMPLES = 64;
let furnaceSamples = FURNACE_SAMPLES;

/**
 * The cases: an OpenPBR material and the same layers for the walk (α = roughness², OpenPBR's mapping; the coat's
 * absorption 0, coat_color white; the walk's Lambertian base is EON at base_diffuse_roughness 0). Gold: the walk
 * test's (tests/unit/openpbr-walk.test.js); the walk's metal keeps its own roughness, which the specification
 * widens under a coat (openPbrBaseRoughness): one of the things its albedo scaling changes.
 */
export const CASES = [
  {
    label: 'gloss over diffuse (plastic)',
    material: { base_color: 0.8, specular_roughness: 0.3, specular_ior: 1.5 },
    stack: { coat: { alpha: 0.09, eta: 1.5, sigma: [0, 0, 0] }, base: { kind: 'lambert', albedo: [0.8, 0.8, 0.8] } },
  },
  {
    label: 'rough coat over diffuse',
    material: { base_color: 0.8, specular_weight: 0, coat_weight: 1, coat_roughness: 0.3 },
    stack: { coat: { alpha: 0.09, eta: 1.6, sigma: [0, 0, 0] }, base: { kind: 'lambert', albedo: [0.8, 0.8, 0.8] } },
  },
  {
    label: 'rough coat over gold',
    material: {
      base_metalness: 1,
      base_color: [1, 0.78, 0.34],
      specular_color: [0.95, 0.9, 0.8],
      coat_weight: 1,
      coat_roughness: 0.3,
    },
    stack: {
      coat: { alpha: 0.09, eta: 1.6, sigma: [0, 0, 0] },
      base: { kind: 'conductor', alpha: 0.09, f0: [1, 0.78, 0.34], tint: [0.95, 0.9, 0.8] },
    },
  },
];

/** The stacks, bottom up: each leaves out the layers above it (their weights 0; in GLSL, compiled out). */
export const STACKS = [
  { key: 'base', label: 'Base: its diffuse alone', off: { specular_weight: 0, coat_weight: 0, fuzz_weight: 0 } },
  { key: 'talk', label: '+ specular: the talk’s model', off: { coat_weight: 0, fuzz_weight: 0 } },
  { key: 'coat', label: '+ coat', off: { fuzz_weight: 0 } },
  { key: 'fuzz', label: '+ fuzz: the whole subset, the lab’s shader', off: {} },
];
const DEFINES = {
  base: { OPENPBR_NO_SPECULAR: 1, OPENPBR_NO_COAT: 1, OPENPBR_NO_FUZZ: 1 },
  talk: { OPENPBR_NO_COAT: 1, OPENPBR_NO_FUZZ: 1 },
  coat: { OPENPBR_NO_FUZZ: 1 },
  fuzz: {},
};

let walks = null;
/** The seed of case i's walk at MUS[j]: each its own. */
export const walkSeed = (i, j) => 1 + i * 16 + j;
const walkOnce = () =>
  (walks ??= CASES.map((c, i) => MUS.map((mu, j) => layeredWalkAlbedo(mu, c.stack, walkSamples, walkSeed(i, j)))));
/** The walk's largest standard error over the cases and angles: the reference's own uncertainty. */
export const walkStandardError = () => Math.max(...walkOnce().flatMap((row) => row.flatMap((w) => w.standardError)));

const albedos = new Map();
/** A stack's directional albedo, [r, g, b], of case `i` at cos θv = mu (computed once). */
export function stackAlbedo(stack, i, mu) {
  const key = `${stack.key} ${i} ${mu}`;
  if (!albedos.has(key))
    albedos.set(key, openPbrFurnace({ ...CASES[i].material, ...stack.off }, mu, furnaceSamples).total);
  return albedos.get(key);
}

// GPU: the pass's x and y as the directions and the material's varying parts, so nothing folds to a constant (a
// cost, not a value, is measured); every layer weighted, as the lab's uniform may be
const L = 'normalize(vec3(0.8 * y, 0.6 * y, x + 0.05))';
const V = 'normalize(vec3(-0.6 * x, 0.8 * x, y + 0.05))';
const MATERIAL =
  'OpenPbrMaterial(1.0, vec3(0.8, 0.6 * y, 0.3), 0.5 * y, 0.3 * y, 1.0, vec3(1.0), 0.2 + 0.5 * y, 0.0, 1.5, y, ' +
  'vec3(0.9), 0.1 + 0.3 * x, 0.0, 1.6, 1.0, x, vec3(1.0), 0.5)';
const MODEL = 'OpenPBR Surface layered through its layers'; // what every variant computes or approximates

export const OPENPBR_FAMILY = {
  key: 'openpbr-layers',
  title: 'The layers of OpenPBR Surface: each stack’s cost, and its albedo against a random walk through the layers',
  domain:
    `cos θv in {${MUS.join(', ')}} × ${CASES.map((c) => c.label).join('; ')} (fuzz_weight 0: the walk has no ` +
    'fuzz) × R, G, B; the GPU cost of each stack, the layers above it compiled out, relative to the talk’s model’s',
  errorOf: 'Directional albedo E(μ)',
  inputs: CASES.flatMap((c, i) => MUS.flatMap((mu) => [0, 1, 2].map((channel) => [mu, i, channel]))),
  referenceNote: () =>
    `${walkSamples / 1000}k paths per (case, μ); the walk's largest standard error is ` +
    `${walkStandardError().toExponential(1)}`,
  /** The GPU cost of each stack relative to the talk's model's (not to the cheapest). */
  relativeTo: 'talk',
  /**
   * --quick (the test suite): 2000 paths per (case, μ) instead of 100k, and QUICK_FURNACE_SAMPLES per lobe unless
   * `furnaceSamples` is given (the family's unit test: the full run's quadrature beside the quick walk).
   */
  configure({ quick, furnaceSamples: samples = quick ? QUICK_FURNACE_SAMPLES : FURNACE_SAMPLES }) {
    walkSamples = quick ? 2000 : WALK_SAMPLES;
    walks = null;
    if (samples !== furnaceSamples) albedos.clear();
    furnaceSamples = samples;
  },
  gpu: { chunk: 'openpbr.glsl', tables: { uOpenPbrAlbedo: openPbrAlbedoTable } },
  // a stack's albedo is a quadrature, computed once per (case, μ) and looked up after: no CPU cost per evaluation
  cpuUntimed: true,
  variants: [
    {
      key: 'walk',
      label: 'Random walk through the layers (Guo et al. 2018)',
      kind: 'reference',
      model: MODEL,
      untimed: true, // run once for the whole domain, not per evaluation and not on the GPU: no cost columns
      glsl: null,
      js: (mu, i, channel) => walkOnce()[i][MUS.indexOf(mu)].albedo[channel],
    },
    ...STACKS.map((stack) => ({
      key: stack.key,
      label: stack.label,
      kind: 'approximation',
      against: 'walk',
      model: MODEL,
      js: (mu, i, channel) => stackAlbedo(stack, i, mu)[channel],
      glsl: `openPbrBRDF(${L}, ${V}, ${MATERIAL}).g`,
      defines: DEFINES[stack.key],
    })),
  ],
};
