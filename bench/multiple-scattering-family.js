// The bench family for multiple scattering: the albedo of a GGX conductor (Schlick's F at every bounce) with
// no compensation, Kulla & Conty's and Turquin's, as a shader computes it (from the albedo table): three
// approximations of the random walk on the Smith microsurface (Heitz et al. 2016), the family's reference. The
// walks run once, when the reference is first asked for (in Node; the GPU page only compiles the expressions).
import * as M from '../src/math/index.js';

const MUS = [0.05, 0.1, 0.2, 0.35, 0.5, 0.7, 0.85, 1];
const ALPHAS = [0.05, 0.1, 0.2, 0.35, 0.5, 0.7, 0.85, 1];
const GOLD = M.METALS.find((m) => m.key === 'gold').linear;
const CHANNELS = [0.04, 0.5, 0.95, ...GOLD]; // the last three: gold's linear R, G, B (the talk's table)
export const WALK_SAMPLES = 200_000;
let walkSamples = WALK_SAMPLES;

let walks = null;
let table = null;
const tableOnce = () => (table ??= M.buildAlbedoTableGGX());

/** One walk per (mu, alpha), all six channels on the same paths, seeded by position in the grid. */
function walkAll() {
  const out = new Map();
  MUS.forEach((mu, i) =>
    ALPHAS.forEach((alpha, j) => {
      out.set(`${mu} ${alpha}`, M.randomWalkAlbedoGGX(mu, alpha, CHANNELS, walkSamples, 1 + i * ALPHAS.length + j));
    }),
  );
  return out;
}

const walkOnce = () => (walks ??= walkAll());

/** The largest standard error of the walk over the grid: the reference's own uncertainty. */
export function walkStandardError() {
  return Math.max(...[...walkOnce().values()].flatMap((w) => w.standardError));
}

const fromTable = (compensation) => (mu, alpha, f0) =>
  M.specularAlbedoFromTable(tableOnce(), mu, alpha, f0, compensation);

const MODEL = 'GGX conductor, all bounces'; // what every variant computes or approximates

export const MULTIPLE_SCATTERING_FAMILY = {
  key: 'multiple-scattering',
  title: 'Multiple scattering: energy compensation against the random walk',
  domain: `μ in {${MUS.join(', ')}} × α in {${ALPHAS.join(', ')}} × F0 in {0.04, 0.5, 0.95, gold's linear R, G, B}`,
  errorOf: 'Directional albedo (GGX, height-correlated Smith, Schlick F at every bounce)',
  inputs: MUS.flatMap((mu) => ALPHAS.flatMap((alpha) => CHANNELS.map((f0, channel) => [mu, alpha, f0, channel]))),
  referenceNote: () =>
    `${walkSamples / 1000}k paths per (μ, α); the walk's largest standard error is ` +
    `${walkStandardError().toExponential(1)}`,
  /** --quick (the test suite): 2000 paths per (μ, α) instead of 200k. */
  configure({ quick }) {
    walkSamples = quick ? 2000 : WALK_SAMPLES;
    walks = null;
  },
  // what the GPU pass needs besides the default chunks: the table, bound as a texture
  gpu: {
    chunk: 'multiple-scattering.glsl',
    defines: { ALBEDO_TABLE_GGX: 1 },
    tables: { uAlbedoTableGGX: tableOnce },
  },
  variants: [
    {
      key: 'walk',
      label: 'Random walk (Heitz et al. 2016)',
      kind: 'reference',
      model: MODEL,
      // run once for the whole grid (~25 s), not per evaluation and not on the GPU: no cost columns
      untimed: true,
      glsl: null,
      js: (mu, alpha, f0, channel) => walkOnce().get(`${mu} ${alpha}`).albedo[channel],
    },
    ...[
      ['none', 'Single scattering only', 'specularAlbedoGGX'],
      ['kullaConty', 'Kulla & Conty 2017', 'specularAlbedoKullaConty'],
      ['turquin', 'Turquin 2019', 'specularAlbedoTurquin'],
    ].map(([compensation, label, glsl]) => ({
      key: compensation === 'kullaConty' ? 'kulla-conty' : compensation,
      label,
      kind: 'approximation',
      against: 'walk',
      model: MODEL,
      js: fromTable(compensation),
      glsl: `${glsl}(x, 0.05 + 0.95 * y, 0.5)`,
    })),
  ],
};
