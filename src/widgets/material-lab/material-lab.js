// material-lab: the playground of the talk's last part. A sphere with a material from the F0 tables (or your
// own), the BRDF's terms to choose, and four kinds of light to switch on: punctual, a sphere (area) light, an
// environment, ambient. Each light is rendered by the approximation chosen for it; beside it the same view by
// a converging Monte Carlo reference, the error image, and the RMS error and GPU time of the approximation.
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { lightDirFromAngles } from '../../math/angles.js';
import { REFERENCE_BATCH } from '../../lab/lab-renderer.js';
import { ENVIRONMENTS, MAX_FILE_BYTES, parseEnvironmentFile } from '../../lab/environments.js';
import { MATERIAL_FIELDS, labScene, sphereLight } from '../../lab/lab-scene.js';
import { createLabView } from '../../lab/lab-view.js';
import { LAB_TERMS, createNotesList } from '../../lab/lab-approximations.js';
import { SIGMA_HINT } from '../../core/ui/sigma-range.js';
import { attachEnvironmentDrop } from './environment-drop.js';
import { createMeasuredMaterial } from './measured-material.js';
import { MERL_TEXTURE_BYTES } from '../measured-brdf/texture-size.js';

export const ENV_METHODS = {
  'split-sum': 'Split sum (prefiltered + DFG)',
  importance: 'Importance sampling, N samples',
  mirror: 'Mirror: F(v, n) × environment',
  pmrem: 'three.js PMREM (MeshPhysicalMaterial)',
};
export const AREA_METHODS = { representative: 'Representative point (Karis)', centre: 'Punctual at the centre' };

export const schema = {
  ...MATERIAL_FIELDS,
  layers: {
    group: 'BRDF terms',
    type: 'enum',
    options: { both: 'Specular + diffuse', specular: 'Specular only', diffuse: 'Diffuse only' },
    default: 'both',
    label: 'Layers',
  },
  fresnel: { group: 'BRDF terms', type: 'enum', options: LAB_TERMS.fresnel, default: 'schlick', label: 'F' },
  ndf: { group: 'BRDF terms', type: 'enum', options: LAB_TERMS.ndf, default: 'ggx', label: 'D' },
  visibility: {
    group: 'BRDF terms',
    type: 'enum',
    options: LAB_TERMS.visibility,
    default: 'smithGGXCorrelated',
    label: 'V',
  },
  compensation: {
    group: 'BRDF terms',
    type: 'enum',
    options: { none: 'None', kullaConty: 'Kulla–Conty 2017', turquin: 'Turquin 2019' },
    default: 'none',
    label: 'Multiple scattering',
  },
  diffuseModel: {
    group: 'BRDF terms',
    type: 'enum',
    options: LAB_TERMS.diffuse,
    default: 'lambert',
    label: 'Diffuse term',
  },
  sigma: {
    group: 'BRDF terms',
    type: 'number',
    min: 0,
    max: 60,
    step: 1,
    default: 20,
    label: 'Oren-Nayar σ',
    unit: '°',
    hint: SIGMA_HINT,
  },
  brdfSource: {
    group: 'BRDF terms',
    type: 'enum',
    default: 'model',
    label: 'BRDF',
    options: { model: 'The model (terms above)', measured: 'Measured (a dropped MERL file)' },
  },
  punctual: { group: 'Punctual light', type: 'bool', default: false, label: 'Punctual light' },
  lightTheta: {
    group: 'Punctual light',
    type: 'number',
    min: 0,
    max: 180,
    step: 1,
    default: 45,
    label: 'Punctual θ from view',
    unit: '°',
  },
  lightPhi: {
    group: 'Punctual light',
    type: 'number',
    min: -180,
    max: 180,
    step: 1,
    default: 45,
    label: 'Punctual φ',
    unit: '°',
  },
  cLight: {
    group: 'Punctual light',
    type: 'number',
    min: 0,
    max: 10,
    step: 0.05,
    default: 1,
    label: 'Punctual c_light',
  },
  area: { group: 'Sphere light', type: 'bool', default: false, label: 'Sphere light' },
  areaTheta: {
    group: 'Sphere light',
    type: 'number',
    min: 0,
    max: 180,
    step: 1,
    default: 40,
    label: 'Sphere light θ',
    unit: '°',
  },
  areaPhi: {
    group: 'Sphere light',
    type: 'number',
    min: -180,
    max: 180,
    step: 1,
    default: 135,
    label: 'Sphere light φ',
    unit: '°',
  },
  areaRadius: {
    group: 'Sphere light',
    type: 'number',
    min: 0.5,
    max: 30,
    step: 0.5,
    default: 8,
    label: 'Sphere light radius',
    unit: '°',
  },
  areaCLight: {
    group: 'Sphere light',
    type: 'number',
    min: 0,
    max: 10,
    step: 0.05,
    default: 1,
    label: 'Sphere light c_light',
  },
  areaMethod: {
    group: 'Sphere light',
    type: 'enum',
    options: AREA_METHODS,
    default: 'representative',
    label: 'Sphere light by',
  },
  env: { group: 'Environment', type: 'bool', default: true, label: 'Environment' },
  environment: {
    group: 'Environment',
    type: 'enum',
    options: ENVIRONMENTS,
    default: 'studio',
    label: 'Environment map',
  },
  envIntensity: {
    group: 'Environment',
    type: 'number',
    min: 0,
    max: 4,
    step: 0.05,
    default: 1,
    label: 'Environment intensity',
  },
  envMethod: {
    group: 'Environment',
    type: 'enum',
    options: ENV_METHODS,
    default: 'split-sum',
    label: 'Environment by',
  },
  samples: {
    group: 'Environment',
    type: 'number',
    min: 1,
    max: 256,
    step: 1,
    default: 16,
    label: 'Importance samples N',
  },
  ambient: { group: 'Ambient light', type: 'bool', default: false, label: 'Ambient light' },
  ambientLevel: {
    group: 'Ambient light',
    type: 'number',
    min: 0,
    max: 2,
    step: 0.05,
    default: 0.3,
    label: 'Ambient radiance',
  },
  refSamples: {
    group: 'Reference and display',
    type: 'enum',
    options: { 128: '128', 512: '512', 2048: '2048' },
    default: '512',
    label: 'Reference samples / pixel',
  },
  exposure: {
    group: 'Reference and display',
    type: 'number',
    min: 0.1,
    max: 8,
    step: 0.05,
    default: 1,
    label: 'Exposure',
  },
  errorScale: {
    group: 'Reference and display',
    type: 'number',
    min: 0.005,
    max: 1,
    step: 0.005,
    default: 0.05,
    label: 'Error image: full scale',
  },
};

const ABOUT =
  'A shading model becomes a picture only with an illumination model. The left sphere is rendered the way a ' +
  'real-time renderer would (the method chosen for each light); the middle one solves the reflectance equation ' +
  'by Monte Carlo, adding samples until it converges; the right image is their difference. The punctual light ' +
  'is exact in both (it is a single direction: L = π f c_light (n·l)). The sphere light, the environment and ' +
  'ambient light are integrals that the approximations shortcut: a representative point, a prefiltered map with ' +
  'a DFG table (the split sum), a few importance samples, or the mirror direction alone. Each one uses the F, D ' +
  'and V chosen above where it has a form for them (a DFG table and a prefiltered map made for the chosen D and ' +
  'V; F = 1 gives A + B); the lines under the images say what stands in where it has none. Multiple scattering ' +
  'puts back the light the microfacet model drops (Kulla & Conty 2017, or Turquin 2019), in both images, so the ' +
  'error image shows what each method does with it. Drop an .hdr or .exr panorama on the widget to light it with ' +
  'your own environment, or a MERL .binary file (Matusik et al. 2003) to render a measured BRDF: its table is ' +
  `a 3-D texture of ${(MERL_TEXTURE_BYTES / 1e6).toFixed(2)} MB on the GPU, and only the reference and importance ` +
  'sampling have a form for it.';

const TERMS_USED = [
  'microfacetBRDF',
  'dfgTableUv',
  'sampleGGXNormal',
  'sampleBeckmannNormal',
  'sampleCosine',
  'sampleCone',
  'sphereLightRepresentativeDir',
  'sphereLightNormalization',
  'equirectUv',
  'diffuseOrenNayar',
];

/** A lab scene with a measured table for its BRDF: no terms; the GGX fit's α (the state's until it is in) to
 * sample by. */
function measuredScene(scene, table) {
  const alpha = table.fit?.params.alpha ?? scene.material.alpha;
  return {
    ...scene,
    material: { ...scene.material, alpha: Math.max(alpha, 0.01) },
    terms: { ...scene.terms, D: 'ggx', compensation: 'none' },
    measured: table.name,
  };
}

export function lightsOf(state) {
  const c = (x) => [x, x, x];
  return {
    punctual: state.punctual
      ? { dir: lightDirFromAngles(state.lightTheta, state.lightPhi), cLight: c(state.cLight) }
      : null,
    sphere: state.area ? sphereLight(state.areaTheta, state.areaPhi, state.areaRadius, state.areaCLight) : null,
    env: state.env ? { intensity: state.envIntensity, map: state.environment } : null,
    ambient: state.ambient ? c(state.ambientLevel) : null,
  };
}

const fmt = (x, digits = 4) => (x === null || x === undefined ? '—' : x.toPrecision(digits));

/** The lights on and the method each is shaded by, in words (the approximation's caption). */
function methodText(st, lights) {
  const parts = [];
  if (lights.punctual) parts.push('punctual (exact)');
  if (lights.sphere) {
    parts.push(`sphere light by ${st.areaMethod === 'centre' ? 'its centre' : 'representative point'}`);
  }
  if (lights.env) {
    const samples = st.envMethod === 'importance' ? `${st.samples} importance samples` : st.envMethod;
    parts.push(`${ENVIRONMENTS[st.environment].split(' (')[0].toLowerCase()} by ${samples}`);
  }
  if (lights.ambient) parts.push('ambient');
  return parts.join(' + ') || 'no light on';
}

export function createMaterialLab(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, {
    name: 'material-lab',
    schema,
    initialState,
    locked,
    about: ABOUT,
    terms: TERMS_USED,
  });
  const readout = document.createElement('div');
  readout.className = 'lab-readout';
  readout.setAttribute('aria-live', 'polite');
  let filePixels = null;
  let fileKey = ''; // a new key for every file taken, so a second file of the same name is used too
  let approxKey = '';
  let refKey = '';
  let stats = null;
  let ms = null;
  let timingRuns = 1; // renders of the approximation whose median is its cost (the bench asks for more)

  const frame = ({ lab, environment, again }) => {
    const st = shell.state;
    const lights = lightsOf(st);
    const table = st.brdfSource === 'measured' ? measured.current : null;
    const scene = table ? measuredScene(labScene(st, lights), table) : labScene(st, lights);
    const envKey = st.env ? (st.environment === 'file' ? fileKey : st.environment) : 'none';
    const aKey = JSON.stringify([scene, envKey, table?.key]);
    const rKey = JSON.stringify([scene.material, scene.terms, scene.lights, envKey, table?.key]);
    scene.table = table?.texture;
    scene.maps = environment(
      st.env ? st.environment : 'furnace',
      st.env && st.environment === 'file' ? filePixels : null,
    );
    if (aKey !== approxKey) {
      const times = Array.from({ length: timingRuns }, () => lab.renderApprox(scene)).sort((a, b) => a - b);
      ms = times[Math.floor(times.length / 2)];
      approxKey = aKey;
    }
    if (rKey !== refKey) {
      lab.resetReference();
      refKey = rKey;
    }
    const target = Number(st.refSamples) / REFERENCE_BATCH;
    if (lab.batches < target) {
      lab.accumulate(scene);
      again();
    }
    stats = {
      ...lab.error(),
      ms,
      timingRuns,
      samples: lab.batches * REFERENCE_BATCH,
      target: Number(st.refSamples),
      samplesN: st.samples,
      method: st.envMethod,
    };
    showReadout(st, lights);
    notes.show(scene);
    return [
      { image: 'approx', caption: `Approximation: ${methodText(st, lights)}` },
      { image: 'reference', caption: `Reference: Monte Carlo, ${stats.samples} of ${stats.target} samples / pixel` },
      { image: 'error', caption: `Error |approx − reference|, 0 to ${st.errorScale}` },
    ];
  };

  const showReadout = (st, lights) => {
    const converging = stats.samples < stats.target;
    const anyLight = Object.values(lights).some(Boolean);
    readout.innerHTML = anyLight
      ? `<table class="data-table compact"><tbody>
        <tr><th scope="row">GPU time of the approximation</th><td>${fmt(stats.ms, 3)} ms for ${view.resolution}² pixels</td></tr>
        <tr><th scope="row">RMS error against the reference</th><td>${fmt(stats.rms)} (radiance), ${fmt(stats.relative * 100, 3)} % of the reference’s RMS${converging ? ' — reference still converging' : ''}</td></tr>
        </tbody></table>`
      : '<p class="lab-empty">Every light is off: switch one on in the controls.</p>';
    const errorWords = converging
      ? 'The reference is still converging.'
      : `RMS error ${fmt(stats.rms, 3)}, ${fmt(stats.relative * 100, 3)} % relative; ${fmt(stats.ms, 3)} ms.`;
    const table = st.brdfSource === 'measured' ? measured.current : null;
    const model = st.material === 'custom' ? `F0 ${st.f0}, diffuse ${st.diffuse}` : st.material;
    const what = table ? `the measured BRDF ${table.name}` : `${model}, roughness α ${st.alpha}`;
    shell.describe(
      `Material lab. A sphere (${what}) lit by ${methodText(st, lights)}; beside it the Monte Carlo reference (${stats.target} samples per pixel) and the error image. ${errorWords}`,
      view.canvas,
    );
  };

  // under the images: how each light's approximation treats the chosen terms (lab-approximations.js)
  const notes = createNotesList();

  const onReset = () => {
    [approxKey, refKey] = ['', ''];
    measured.reupload();
  };
  const measured = createMeasuredMaterial({
    onChange: () => (shell.state.brdfSource === 'measured' ? view.invalidate() : update({ brdfSource: 'measured' })),
    onError: (message) => shell.notices.show(message),
  });
  const view = createLabView(shell.view, { label: 'Material lab', resolution: 192, frame, onReset });
  view.setAspect(3);
  shell.view.append(readout, notes.element);

  const onChanged = (changed) => {
    if (changed.includes('brdfSource') && shell.state.brdfSource === 'measured' && !measured.current) {
      shell.notices.show('No MERL file has been dropped yet: drop a .binary file on the widget. Kept the model.');
      update({ brdfSource: 'model' });
      return;
    }
    if (changed.includes('environment') && shell.state.environment === 'file' && !filePixels) {
      shell.notices.show(
        'No environment file has been dropped yet: drop an .hdr or .exr panorama on the widget. Kept the studio.',
      );
      update({ environment: 'studio' });
      return;
    }
    view.setDisplay({ exposure: shell.state.exposure, errorScale: shell.state.errorScale });
  };
  const update = shell.connect({ title: 'Material lab', onChanged, onStateChange });
  onChanged(['environment', 'brdfSource']);

  const drop = attachEnvironmentDrop(shell.root, {
    maxBytes: MAX_FILE_BYTES,
    accept: '.hdr,.exr,.binary',
    text: 'Load an .hdr / .exr environment or a MERL .binary BRDF…',
    onFile: (name, buffer) => {
      if (/\.binary$/i.test(name)) {
        const mb = MAX_FILE_BYTES / 2 ** 20;
        if (!(buffer instanceof ArrayBuffer)) shell.notices.show(`${name}: larger than ${mb} MB. Kept the material.`);
        else measured.load(name, buffer);
        return buffer instanceof ArrayBuffer;
      }
      try {
        filePixels = parseEnvironmentFile(name, buffer);
      } catch (e) {
        shell.notices.show(`${e.message} Kept the current environment.`);
        return false;
      }
      fileKey = `file:${name}:${performance.now()}`;
      update({ env: true, environment: 'file' });
      view.invalidate();
      return true;
    },
  });

  return {
    update,
    getState: () => shell.state,
    getStats: () => stats,
    /** The measured table in use ({ name, fit }: fit null until the GGX fit is in), or null. */
    getMeasured: () => (measured.current ? { name: measured.current.name, fit: measured.current.fit } : null),
    getProgress: () => ({ frame: stats?.samples ?? 0, target: Number(shell.state.refSamples) }),
    /** Renders the approximation `runs` times and keeps the median time (stats.timingRuns says when it is done). */
    remeasure(runs) {
      timingRuns = runs;
      approxKey = '';
      view.invalidate();
    },
    read: (which) => view.lab?.read(which),
    get canvas() {
      return view.canvas;
    },
    get resolution() {
      return view.resolution;
    },
    dispose() {
      drop.dispose();
      measured.dispose();
      view.dispose();
      shell.dispose();
    },
  };
}

export const widget = { name: 'material-lab', schema, create: createMaterialLab, terms: TERMS_USED };
