// What each approximation of the material lab does with the chosen BRDF terms, decided in one place: the DFG
// table and the prefiltered map it reads (built for the chosen NDF and visibility term), and, where a method has
// no form for a term, what stands in for it. The sentences the lab shows under its images come from here, so
// the error image is read as the method's error and not as a difference between two models.
import { SIGMA_MODELLED_DEG, sigmaExtrapolated, sigmaText } from '../core/ui/sigma-range.js';
import { CATALOGUE, CUSTOM_KEY, termEntry, termLabel, termOptions } from '../math/catalogue/index.js';
import { ANISOTROPY_MODELS, SAMPLED_LOBE, stretchesLobe } from './lab-anisotropy.js';

/**
 * The keys of a family's terms that the catalogue says have the capability (src/math/catalogue/types.js), in
 * menu order.
 * @param {'ndf' | 'visibility'} family
 * @param {'sampler' | 'dfgTable' | 'measuredFit'} capability
 */
export const termsWith = (family, capability) =>
  Object.values(CATALOGUE[family].terms)
    .filter((term) => term.capabilities?.[capability])
    .map((term) => term.key);

/**
 * The terms the lab offers, by family, with the catalogue's labels: the D and V its approximations have tables
 * for (their DFG tables; the NDFs also an importance sampler, for the prefilters) and that its program draws.
 */
export const LAB_TERMS = {
  fresnel: termOptions('fresnel', ['schlick', 'one']),
  ndf: termOptions(
    'ndf',
    termsWith('ndf', 'dfgTable').filter((key) => termsWith('ndf', 'sampler').includes(key)),
  ),
  visibility: termOptions('visibility', termsWith('visibility', 'dfgTable')),
  diffuse: termOptions('diffuse', [
    'lambert',
    'fresnelWeighted',
    'ashikhminShirley',
    'orenNayar',
    'orenNayarQualitative',
  ]),
  compensation: termOptions('compensation', ['none', 'kullaConty', 'turquin']),
};

const has = (terms) => ({ specular: terms.layers !== 'diffuse', diffuse: terms.layers !== 'specular' });

/**
 * What the approximation of `scene` ({ terms, lights, methods }, see lab-scene.js) reads: `dfg` the terms of its
 * DFG table ({ ndf, visibility }) or null, `prefilter` the NDF its prefiltered map is filtered with or null.
 */
export function approximationInputs({ terms, lights, methods, measured, custom, openpbr }) {
  if (measured || custom || openpbr) return { dfg: null, prefilter: null };
  const splitSum = Boolean(lights.env) && methods.env === 'split-sum';
  return {
    dfg: splitSum || lights.ambient ? { ndf: terms.D, visibility: terms.V } : null,
    prefilter: splitSum ? terms.D : null,
  };
}

const specularWords = (terms) => `${LAB_TERMS.ndf[terms.D]} with ${LAB_TERMS.visibility[terms.V]}`;
const fresnelWords = (terms) => (terms.F === 'one' ? 'A + B, as F = 1' : 'F0·A + B, Schlick’s F');

/** The specular part of each light's method, in words: what it follows of the chosen terms. */
function specularNotes({ terms, lights, methods }) {
  const notes = [];
  const ndf = LAB_TERMS.ndf[terms.D];
  const env = lights.env ? methods.env : null;
  if (env === 'split-sum') {
    notes.push(
      `Split sum: the map prefiltered with the ${ndf} lobe (n = v = r) times the DFG table of ` +
        `${specularWords(terms)} (${fresnelWords(terms)}).`,
    );
  }
  if (env === 'mirror') {
    notes.push(
      `Mirror: ${terms.F === 'one' ? 'F = 1' : 'Schlick’s F at n·v'} times the map in the reflected ` +
        'direction; the roughness is ignored, which is the method’s error.',
    );
  }
  if (env === 'importance') {
    notes.push(
      `Importance sampling: N normals drawn from ${ndf}, every term evaluated at each sample; the diffuse ` +
        'term by N cosine-distributed directions.',
    );
  }
  if (lights.ambient) {
    notes.push(
      `Ambient: the directional albedo from the DFG table of ${specularWords(terms)} ` + `(${fresnelWords(terms)}).`,
    );
  }
  if (lights.sphere && methods.area !== 'centre' && terms.D !== 'ggx') {
    notes.push(
      `Sphere light: the representative point’s energy factor (α/α′)² is Karis’s (2013) for GGX, ` + `kept for ${ndf}.`,
    );
  }
  return notes;
}

/**
 * The diffuse term under the environment and ambient light. Irradiance × Lambert (c_diff/π) is the only diffuse
 * form the mirror and split-sum paths and ambient light have; with another diffuse term chosen it stands in for it.
 */
export function diffuseUnderSurround({ terms, lights, methods }) {
  const byIrradiance = [];
  if (lights.env && (methods.env === 'split-sum' || methods.env === 'mirror')) {
    byIrradiance.push(`the environment (${methods.env === 'mirror' ? 'mirror' : 'split sum'})`);
  }
  if (lights.ambient) byIrradiance.push('ambient light');
  if (!byIrradiance.length) return null;
  const where = byIrradiance.join(' and ');
  const diffuse = termEntry('diffuse', terms.diffuse); // an old spelling of the key read as the key
  if (diffuse.key === 'lambert') return `Diffuse under ${where}: irradiance × c_diff/π, Lambert’s exact answer.`;
  const name = diffuse.label;
  const none = byIrradiance.length > 1 ? 'neither has a form' : 'it has no form';
  return (
    `Diffuse under ${where}: ${none} for ${name}, so ${name} is approximated by Lambert ` +
    `(irradiance × c_diff/π) while the reference uses ${name}: that substitution is part of the error image.`
  );
}

/** How each method treats the chosen energy compensation (its tables are GGX with height-correlated Smith). */
export function compensationNote({ terms, lights, methods }) {
  if (!terms.compensation || terms.compensation === 'none') return null;
  const name = terms.compensation === 'turquin' ? 'Turquin’s factor' : 'Kulla & Conty’s lobe';
  const tables =
    terms.D === 'ggx' && terms.V === 'smithGGXCorrelated'
      ? ''
      : ` Its tables are for GGX with height-correlated Smith; here they stand in for ${LAB_TERMS.ndf[terms.D]}.`;
  const env = lights.env && methods.env === 'mirror' ? ' The mirror method has no form for it and leaves it out.' : '';
  const split =
    lights.env && methods.env === 'split-sum' && terms.compensation === 'kullaConty'
      ? ' Under the split sum the lobe’s albedo F_ms (1 − E) multiplies the irradiance (Fdez-Agüera 2019).'
      : '';
  const where = 'in the reference and every method that evaluates the BRDF';
  return `Multiple scattering: ${name} ${where}.${split}${env}${tables}`;
}

const PMREM_NOTE =
  'three.js PMREM: MeshPhysicalMaterial shades with three.js’s own model whatever terms are chosen (GGX, ' +
  'height-correlated Smith, Schlick’s F, Lambert, plus its multiple-scattering term and a diffuse reduced by the ' +
  'specular), so its error includes those differences of model.';

const ENV_WORDS = { 'split-sum': 'The split sum', mirror: 'The mirror method', pmrem: 'three.js’s PMREM' };

/** What each method does with a measured table: the methods built on a model's terms have no form for it. */
export function measuredNotes({ lights, methods, measured, material }) {
  const notes = [
    `Measured BRDF (${measured}): the reference integrates the table itself (a 3-D texture, ` +
      `trilinear between its nodes), drawing directions from the GGX fit’s lobe (α ${material.alpha.toFixed(3)}), ` +
      'by cosine and from the map; the fit only steers the samples, it is not what is rendered. The material ' +
      'and terms chosen above are not used.',
  ];
  if (lights.env && methods.env === 'importance') {
    notes.push(
      'Importance sampling: N directions from the fitted GGX lobe and N by cosine, each weighted by the ' +
        'balance heuristic, the table evaluated at every one (it has no separate diffuse part to sample alone).',
    );
  } else if (lights.env) {
    notes.push(
      `${ENV_WORDS[methods.env]} has no form for a table (it needs a model’s D, V and F), so the ` +
        'environment is left out of the approximation: choose importance sampling.',
    );
  }
  if (lights.ambient) {
    notes.push('Ambient: the DFG table of a model has no form for a measured table; left out of the approximation.');
  }
  if (lights.sphere && methods.area !== 'centre') {
    notes.push(
      'Sphere light: the table at the representative point, with Karis’s (2013) GGX energy factor at the ' +
        'fitted α.',
    );
  }
  return notes;
}

/**
 * What each method does with the user's whole BRDF: as with a table, only the reference, importance sampling and
 * the sphere light evaluate it. Its samples follow GGX at the state's α and the cosine, by the balance heuristic:
 * the cosine's density is above 0 wherever n·l is, so the estimate converges to the integral whatever the BRDF
 * (a bounded f gives a bounded weight, at most π f), and a lobe near the mirror direction is sampled by GGX.
 */
export function customNotes({ lights, methods, material }) {
  const alpha = material.alpha.toFixed(3);
  const notes = [
    `Your BRDF: the reference integrates customBRDF itself, with directions drawn from a GGX lobe of α ${alpha} ` +
      '(the roughness slider: set it near your lobe’s width), by cosine and from the map, weighted by the ' +
      'balance heuristic. The lobe only steers the samples: a poor α makes the reference noisier, not wrong. ' +
      'The material and terms chosen above are not used.',
  ];
  if (lights.env && methods.env === 'importance') {
    notes.push('Importance sampling: N directions from that GGX lobe and N by cosine, your BRDF at every one.');
  } else if (lights.env) {
    notes.push(
      `${ENV_WORDS[methods.env]} has no form for a BRDF it does not know (it needs a model’s D, V and F), so ` +
        'the environment is left out of the approximation: choose importance sampling.',
    );
  }
  if (lights.ambient) notes.push('Ambient: the DFG table of a model has no form for your BRDF; left out.');
  if (lights.sphere && methods.area !== 'centre') {
    notes.push('Sphere light: your BRDF at the representative point, with Karis’s (2013) GGX energy factor at α.');
  }
  return notes;
}

/** Where an approximation reads the light for an anisotropic lobe: the bent reflection vector, or the mirror. */
const readAlong = (a) =>
  a.bent
    ? 'the bent reflection vector of Filament and three.js (n bent towards v less its part along the brushing), ' +
      'which moves the highlight but cannot stretch it'
    : 'the mirror direction, as if the lobe were isotropic (the bent reflection vector is off)';

/** The isotropic terms of a family that the catalogue has an anisotropic form of, in words ('GGX and Beckmann'). */
const stretchable = (family) =>
  Object.values(CATALOGUE[family].terms)
    .filter((term) => term.isotropic)
    .map((term) => termEntry(family, term.isotropic).short)
    .join(' and ');

/** A stretched term in words: the catalogue's label, or the user's function. */
const stretchedWords = (family, key) =>
  key === CUSTOM_KEY ? `your ${family === 'ndf' ? 'customDAniso' : 'customVAniso'}` : termLabel(family, key);

/** How the reference and importance sampling draw the stretched lobe of D `key`. */
const samplingWords = (key) =>
  'The reference and importance sampling draw the visible normals of ' +
  (key === SAMPLED_LOBE
    ? 'the stretched lobe (Dupuy & Benyoub 2023).'
    : `${termLabel('ndf', SAMPLED_LOBE)} at the same pair (Dupuy & Benyoub 2023), the one anisotropic sampler ` +
      'the lab has; each sample is divided by its density, so the estimate converges to this D’s lobe too.');

/** What each method does with an anisotropic lobe (lab-anisotropy.js): the forms that have none, and what stands in. */
export function anisotropyNotes(scene) {
  const { anisotropy: a, terms, lights, methods } = scene;
  if (!a || terms.layers === 'diffuse') return [];
  if (!stretchesLobe(scene)) {
    return [
      `Anisotropy: the catalogue has an anisotropic form of ${stretchable('ndf')} only; ` +
        `${LAB_TERMS.ndf[terms.D]} stays isotropic at α.`,
    ];
  }
  const [ax, ay] = a.alpha.map((x) => x.toFixed(3));
  const projected = ', each direction’s roughness projected on its azimuth (Heitz 2014)';
  const v = a.V
    ? `${stretchedWords('visibility', a.V)}${a.V === CUSTOM_KEY ? '' : projected}`
    : `${LAB_TERMS.visibility[terms.V]}, which has no anisotropic form here, at α`;
  const notes = [
    `Anisotropy a = ${a.strength} by ${ANISOTROPY_MODELS[a.model].split(':')[0]}: αx = ${ax} across the brushing ` +
      `(along t), αy = ${ay} along it (b); D ${stretchedWords('ndf', a.D)} at the pair, V ${v}. ` +
      samplingWords(a.D),
  ];
  const env = lights.env ? methods.env : null;
  if (env === 'split-sum') {
    notes.push(
      `Split sum, anisotropic: the prefiltered map and the DFG table are the isotropic lobe’s at α = ` +
        `${scene.material.alpha}, read along ${readAlong(a)}: the error image shows what that costs.`,
    );
  }
  if (lights.sphere && methods.area !== 'centre') {
    notes.push(
      `Sphere light, anisotropic: the representative point is the disc’s point nearest ${readAlong(a)}, with ` +
        'Karis’s energy factor at α; the stretched lobe is evaluated at that one point.',
    );
  }
  if (lights.ambient) notes.push('Ambient, anisotropic: the DFG table’s albedo is the isotropic lobe’s at α.');
  if (env === 'pmrem') notes.push('three.js PMREM: its material here is isotropic.');
  if (terms.compensation && terms.compensation !== 'none') {
    notes.push('Multiple scattering, anisotropic: its tables are the isotropic lobe’s, read at α.');
  }
  return notes;
}

/**
 * What each method does with OpenPBR Surface (src/math/openpbr.js, whole: its layers are not apart into the lab's
 * specular and diffuse terms): as with your BRDF, only the reference, importance sampling and the sphere light
 * evaluate it, sampled by GGX at its sharpest lobe's α and by cosine.
 */
export function openPbrNotes({ lights, methods, material }) {
  const notes = [
    'OpenPBR Surface (the panel’s base, specular, coat and fuzz): the reference integrates it whole, with ' +
      `directions drawn from a GGX lobe of α ${material.alpha.toFixed(3)} (its sharpest layer’s) and by cosine. ` +
      'The material and terms chosen above are not used; the layers share the sphere’s one normal.',
  ];
  if (lights.env && methods.env !== 'importance') {
    notes.push(
      `${ENV_WORDS[methods.env]} has no form for a layered material (it needs one lobe’s D, V and F), so the ` +
        'environment is left out of the approximation: choose importance sampling.',
    );
  }
  if (lights.ambient) notes.push('Ambient: the DFG table of one lobe has no form for the stack; left out.');
  return notes;
}

/** The sentences under the lab's images: for each light on, how its approximation treats the chosen terms. */
export function approximationNotes(scene) {
  const whole = scene.anisotropy ? ['Anisotropy: not applied here; the whole BRDF is drawn as it is.'] : [];
  if (scene.measured) return [...measuredNotes(scene), ...whole];
  if (scene.custom) return [...customNotes(scene), ...whole];
  if (scene.openpbr) return openPbrNotes(scene);
  const { specular, diffuse } = has(scene.terms);
  const notes = specular ? [...specularNotes(scene), ...anisotropyNotes(scene)] : [];
  const surround = diffuse ? diffuseUnderSurround(scene) : null;
  if (surround) notes.push(surround);
  if (scene.lights.env && scene.methods.env === 'pmrem') notes.push(PMREM_NOTE);
  const sigmaDeg = Math.round(((scene.material?.sigma ?? 0) * 180) / Math.PI);
  const orenNayar = termEntry('diffuse', scene.terms.diffuse).key.startsWith('orenNayar');
  if (diffuse && orenNayar && sigmaExtrapolated(sigmaDeg)) {
    notes.push(
      `Oren-Nayar at ${sigmaText(sigmaDeg)}: past ${SIGMA_MODELLED_DEG}° a Gaussian of facet tilts puts ` +
        'over 4.6% of them beyond 90°, which no V-groove can have (the diffuse chapter).',
    );
  }
  const compensation = specular ? compensationNote(scene) : null;
  if (compensation) notes.push(compensation);
  return notes;
}

/** The notes as a list under the lab's images, redrawn only when they change. */
export function createNotesList() {
  const element = document.createElement('ul');
  element.className = 'lab-notes';
  let shown = '';
  const show = (scene) => {
    const lines = approximationNotes(scene);
    if (lines.join('\n') === shown) return;
    shown = lines.join('\n');
    element.replaceChildren(...lines.map((line) => Object.assign(document.createElement('li'), { textContent: line })));
  };
  return { element, show };
}
