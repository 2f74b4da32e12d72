// Parity rows of OpenPBR Surface (shaders/openpbr*.glsl against src/math/openpbr*.js), in the row format of
// parity-cases.js. The stress inputs: views and lights along n, within 1e-7 of the horizon, on the mirror direction
// of a near-mirror lobe (α clamped at 1e-4, D ~ 3e7), below the horizon; materials at every range end and beyond it
// (weights 0 and 5, colours −0.5 and 1.5, indices 0.5, 1 and 3, anisotropy 1, a coat darker than black), the
// coat's index above and below the base's (the total-internal-reflection fix), and the albedo table's ends.
import { OPENPBR_DEFAULTS, openPbrBRDF } from '../../../math/openpbr.js';
import { diffuseEON, albedoFujiiOrenNayar } from '../../../math/openpbr-diffuse.js';
import { albedoFuzzZeltner, fuzzZeltner } from '../../../math/openpbr-fuzz.js';
import { fresnelDielectricAverage, openPbrAlbedoTable, openPbrDielectricAlbedo } from '../../../math/openpbr-albedo.js';

const cartesian = (...lists) => lists.reduce((acc, list) => acc.flatMap((a) => list.map((x) => [...a, x])), [[]]);
const unit = (x, y, z) => [x, y, z].map((c) => Math.fround(c / Math.hypot(x, y, z)));
const TABLES = { uOpenPbrAlbedo: openPbrAlbedoTable };
const sine = (c) => Math.sqrt(Math.max(1 - Math.min(Math.abs(c), 1) ** 2, 0));

const VIEWS = [[0, 0, 1], unit(1, 0, 1e-7), unit(0.6, 0.8, 1e-4), unit(0.5, 0, 0.866), unit(-0.3, 0.9, 0.3)];
const LIGHTS = [
  ...VIEWS,
  unit(-0.5, 0, 0.866), // the mirror of the oblique view: the peak of a near-mirror coat
  unit(0.2, -0.7, 0.69),
  [0.6, 0, -0.8], // below the horizon
];
const KEYS = Object.keys(OPENPBR_DEFAULTS);
const flat = (m) =>
  KEYS.flatMap((k) => {
    const x = m[k] ?? OPENPBR_DEFAULTS[k];
    return Array.isArray(OPENPBR_DEFAULTS[k]) && !Array.isArray(x) ? [x, x, x] : [].concat(x);
  });
const MATERIALS = [
  {},
  { coat_weight: 1, coat_roughness: 0.2, fuzz_weight: 1, base_diffuse_roughness: 0.5 },
  { base_metalness: 1, base_color: [1, 0.78, 0.34], specular_color: [0.95, 0.9, 0.8], specular_roughness: 0.4 },
  { base_metalness: 0.5, specular_roughness_anisotropy: 1, coat_weight: 0.5, coat_roughness_anisotropy: 1 },
  { coat_weight: 1, coat_color: [0.9, 0.5, -0.5], coat_ior: 1.3, specular_ior: 2.4, coat_darkening: 0.3 },
  { coat_weight: 1, coat_ior: 3, specular_ior: 1, specular_roughness: 0, coat_roughness: 1 },
  { specular_weight: 5, specular_ior: 0.5, base_color: [1.5, -0.5, 0.5], base_weight: 1.5 },
  { specular_weight: 0, base_diffuse_roughness: 1, fuzz_weight: 0.7, fuzz_roughness: 0, fuzz_color: [1, 0.2, 0] },
  { specular_roughness: 1, fuzz_weight: 1, fuzz_roughness: 1, coat_weight: 1, coat_roughness: 0 },
  {
    base_weight: 0,
    base_metalness: 1,
    specular_weight: 0.3,
    coat_weight: 0.7,
    coat_color: 0,
    coat_ior: 1.001,
    fuzz_weight: 0.2,
  },
];

/** The GLSL struct from the row's floats (arg(6) on), clamped as openPbrMaterial clamps. */
function materialGlsl() {
  let i = 6;
  const parts = KEYS.map((k) => {
    if (!Array.isArray(OPENPBR_DEFAULTS[k])) return `arg(${i++})`;
    i += 3;
    return `vec3(arg(${i - 3}), arg(${i - 2}), arg(${i - 1}))`;
  });
  return `openPbrClamp(OpenPbrMaterial(${parts.join(', ')}))`;
}

/** The JS material from the same floats. */
function materialOf(xs) {
  let i = 0;
  return Object.fromEntries(
    KEYS.map((k) => [k, Array.isArray(OPENPBR_DEFAULTS[k]) ? [xs[i++], xs[i++], xs[i++]] : xs[i++]]),
  );
}

const MU = [-0.5, 0, 1e-7, 1e-4, 0.01, 0.1, 0.3, 0.5, 0.7071, 0.9, 0.999, 1, 1 + 1e-6];
const ROUGH = [-0.5, 0, 1e-4, 0.01, 0.1, 0.3, 0.5, 0.9, 1, 1.5];

/** openPbrBRDF's row; with `defines` (OPENPBR_NO_*: the bench's stacks, bench/openpbr-family.js), the weights those
 * compile out set to 0 in JS. */
const brdfRow = (name = 'openPbrBRDF', defines = {}, zeroed = []) => ({
  name,
  chunk: 'openpbr.glsl',
  defines,
  glsl: `openPbrBRDF(vec3(a.x, a.y, a.z), vec3(a.w, b.x, b.y), ${materialGlsl()})`,
  outputs: 3,
  js: (...xs) =>
    openPbrBRDF(xs.slice(0, 3), xs.slice(3, 6), {
      ...materialOf(xs.slice(6)),
      ...Object.fromEntries(zeroed.map((k) => [k, 0])),
    }),
  range: [0, Infinity],
  tables: TABLES,
  args: cartesian(LIGHTS, VIEWS, MATERIALS).map(([l, v, m]) => [...l, ...v, ...flat(m)]),
});
const [SPECULAR, COAT, FUZZ] = ['OPENPBR_NO_SPECULAR', 'OPENPBR_NO_COAT', 'OPENPBR_NO_FUZZ'];

export const OPENPBR_PARITY_CASES = [
  brdfRow(),
  brdfRow('openPbrBRDF (fuzz compiled out)', { [FUZZ]: 1 }, ['fuzz_weight']),
  brdfRow('openPbrBRDF (coat and fuzz compiled out)', { [COAT]: 1, [FUZZ]: 1 }, ['coat_weight', 'fuzz_weight']),
  brdfRow('openPbrBRDF (specular, coat and fuzz compiled out)', { [SPECULAR]: 1, [COAT]: 1, [FUZZ]: 1 }, [
    'specular_weight',
    'coat_weight',
    'fuzz_weight',
  ]),
  {
    name: 'openPbrDielectricAlbedo',
    chunk: 'openpbr-albedo.glsl',
    glsl: 'openPbrDielectricAlbedo(a.x, a.y, a.z)',
    outputs: 1,
    js: (mu, alpha, eta) => openPbrDielectricAlbedo(mu, alpha, eta),
    range: [0, 1],
    tables: TABLES,
    args: cartesian(
      MU,
      [-1, 0, 1e-4, 0.001, 0.01, 0.09, 0.3, 0.7, 1, 2],
      [0.5, 1, 1.001, 1.1, 1.5, 1.6, 2.4, 3, 10, 1e6],
    ),
  },
  {
    name: 'fresnelDielectricAverage',
    chunk: 'openpbr-albedo.glsl',
    glsl: 'fresnelDielectricAverage(a.x)',
    outputs: 1,
    js: fresnelDielectricAverage,
    range: [0, 1],
    tables: TABLES,
    args: [0.5, 1, 1.0005, 1.002, 1.01, 1.05, 1.1, 1.33, 1.5, 1.6, 2, 2.4, 3, 4, 10, 100].map((x) => [x]),
  },
  {
    name: 'diffuseEON',
    chunk: 'openpbr-diffuse.glsl',
    glsl: 'diffuseEON(a.x, a.y, a.z, a.w, b.x)',
    outputs: 1,
    js: diffuseEON,
    range: [0, Infinity],
    // l·v from (n·l, n·v) and the azimuth between them, cos φ in {−1, 0, 0.5, 1}, so that the three agree
    args: cartesian(MU, MU, [-1, 0, 0.5, 1], [-0.5, 0, 0.01, 0.3, 1, 1.5], [-0.5, 0, 0.5, 1, 1.5]).map(
      ([nl, nv, cosPhi, r, rho]) => [nl, nv, nl * nv + sine(nl) * sine(nv) * cosPhi, r, rho],
    ),
  },
  {
    name: 'albedoFujiiOrenNayar',
    chunk: 'openpbr-diffuse.glsl',
    glsl: 'albedoFujiiOrenNayar(a.x, a.y)',
    outputs: 1,
    js: albedoFujiiOrenNayar,
    range: [0, 1],
    args: cartesian(MU, ROUGH),
  },
  {
    name: 'albedoFuzzZeltner',
    chunk: 'openpbr-fuzz.glsl',
    glsl: 'albedoFuzzZeltner(a.x, a.y)',
    outputs: 1,
    js: albedoFuzzZeltner,
    range: [0, 1],
    args: cartesian(MU, ROUGH),
  },
  {
    name: 'fuzzZeltner',
    chunk: 'openpbr-fuzz.glsl',
    glsl: 'fuzzZeltner(a.xyz, vec3(a.w, b.x, b.y), b.z)',
    outputs: 1,
    js: (lx, ly, lz, vx, vy, vz, r) => fuzzZeltner([lx, ly, lz], [vx, vy, vz], r),
    range: [0, Infinity],
    args: cartesian(LIGHTS, VIEWS, ROUGH).map(([l, v, r]) => [...l, ...v, r]),
  },
];
