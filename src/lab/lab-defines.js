// The #defines of one material-lab program (lab-shade.frag.glsl): only the terms, lights and methods in use are
// compiled. Pure: loads in Node, so the uniform and variant tests can list every program the lab makes.
import { termDefines } from '../math/catalogue/index.js';
import { anisotropicDefines, stretchesLobe } from './lab-anisotropy.js';

const ENV_DEFINES = { mirror: 'ENV_MIRROR', importance: 'ENV_IMPORTANCE', 'split-sum': 'ENV_SPLIT_SUM' };

/**
 * The #defines of the program that renders `scene` ({ terms, lights, methods, measured? }, see lab-scene.js) by
 * its approximations, or with `reference` by Monte Carlo. A measured table (scene.measured: its name) is the
 * whole BRDF, no terms, and so is the user's (scene.custom: custom-programs.js puts it where the table would be
 * read), and so is OpenPBR Surface's (scene.openpbr: its material, lab-openpbr.glsl); of the approximations only
 * importance sampling and the sphere light's have a form for a whole BRDF (lab-approximations.js says so), so the
 * others leave the sphere unlit by their light.
 * @returns {Record<string, 1>}
 */
export function sceneDefines(scene, reference) {
  if (scene.openpbr) {
    // lab-openpbr.glsl, whole; shaded in the tangent field's frame (lab-anisotropy.glsl), where its anisotropy lies
    const along = scene.tangentField?.mode === 'along' && { TANGENT_ALONG: 1 };
    return { ...measuredDefines(scene, reference), OPENPBR: 1, TANGENT_FIELD: 1, ...along };
  }
  return scene.measured || scene.custom ? measuredDefines(scene, reference) : modelDefines(scene, reference);
}

// a measured table is sampled by the lobe of its GGX fit (ndf-sampling.glsl)
const sampledByGgx = { NDF_GGX: 1 };

function measuredDefines({ lights, methods }, reference) {
  const d = { MEASURED: 1 };
  if (lights.punctual) d.LIGHT_PUNCTUAL = 1;
  if (lights.sphere) d.LIGHT_SPHERE = 1;
  if (reference) {
    const surround = Object.assign({}, lights.env && { LIGHT_ENV: 1 }, lights.ambient && { LIGHT_AMBIENT: 1 });
    return Object.assign(d, { REFERENCE: 1 }, sampledByGgx, surround);
  }
  if (lights.env) d.LIGHT_ENV = 1; // the map behind the sphere
  if (lights.env && methods.env === 'importance') Object.assign(d, { ENV_IMPORTANCE: 1 }, sampledByGgx);
  if (lights.sphere && methods.area === 'centre') d.AREA_CENTRE = 1;
  return d;
}

function modelDefines(scene, reference) {
  const d = {};
  const flag = (name) => name && (d[name] = 1);
  const { F, D, V, diffuse, compensation = 'none' } = scene.terms;
  Object.keys(termDefines({ F, D, V, diffuse, compensation })).forEach(flag);
  if (compensation !== 'none') flag('ALBEDO_TABLE_GGX'); // the compensations' tables
  if (scene.terms.layers === 'diffuse') flag('SPECULAR_OFF');
  if (stretchesLobe(scene)) Object.assign(d, anisotropicDefines(scene, reference)); // lab-anisotropy.glsl
  if (scene.terms.layers === 'specular') flag('DIFFUSE_OFF');
  const { punctual, sphere, env, ambient } = scene.lights;
  if (punctual) flag('LIGHT_PUNCTUAL');
  if (sphere) flag('LIGHT_SPHERE');
  if (env) flag('LIGHT_ENV');
  if (ambient) flag('LIGHT_AMBIENT');
  if (reference) flag('REFERENCE');
  else {
    if (env) flag(ENV_DEFINES[scene.methods.env]);
    if (sphere && scene.methods.area === 'centre') flag('AREA_CENTRE');
  }
  return d;
}
