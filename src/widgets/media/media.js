// media: light through a homogeneous medium. Absorption per RGB channel by Beer-Lambert over a distance set
// on a log scale, scattering that clouds the medium and then makes it opaque, and the talk's grid of glasses
// from low to high absorption and scattering. Rendered on the GPU by a progressive Monte Carlo volume path
// tracer (unscattered light transmitted exactly), with the transmitted colour plotted against distance.
import * as THREE from 'three';
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { createPlot } from '../../core/ui/plot.js';
import { createViewport } from '../../core/gpu/viewport.js';
import { floatTarget } from '../../core/gpu/gpu-sum.js';
import { assembleGlsl } from '../../core/gpu/glsl.js';
import { SHADER_CHUNKS } from '../../core/gpu/shader-chunks.js';
import { SERIES_DASHES, rgbToHex } from '../../core/ui/palettes.js';
import { linearToSrgb } from '../../math/color.js';
import { WATER_K, WHOLE_MILK, transmittance, waterAbsorptionRgb } from '../../math/media.js';

export const MEDIA = {
  water: { name: 'Clean water', sigmaA: waterAbsorptionRgb(), sigmaS: [0, 0, 0], source: WATER_K.source },
  red: {
    name: 'Red absorber (wine-like, illustrative)',
    sigmaA: [3, 60, 90],
    sigmaS: [0, 0, 0],
    source: 'illustrative values',
  },
  cloudy: {
    name: 'Cloudy water (illustrative)',
    sigmaA: waterAbsorptionRgb(),
    sigmaS: [25, 25, 25],
    source: 'water plus illustrative scattering',
  },
  // milk's σ′s stands in for σs with isotropic scattering (the similarity relation): the picture diffuses light as
  // milk does, but the straight-through light it implies is only an upper bound on milk's
  milk: {
    name: 'Whole milk (reduced scattering σ′s)',
    sigmaA: WHOLE_MILK.sigmaA,
    sigmaS: WHOLE_MILK.sigmaSReduced,
    source: WHOLE_MILK.source,
    reduced: true,
  },
};

export const schema = {
  view: {
    type: 'enum',
    options: { one: 'One glass', grid: 'The talk’s grid of glasses' },
    default: 'one',
    label: 'View',
  },
  medium: {
    type: 'enum',
    options: Object.fromEntries(Object.entries(MEDIA).map(([k, m]) => [k, m.name])),
    default: 'water',
    label: 'Medium',
  },
  distance: { type: 'number', min: -3, max: 2, step: 0.05, default: -1.3, label: 'Depth, log₁₀ metres' },
  samples: {
    type: 'enum',
    options: { 16: '16', 64: '64', 256: '256', 1024: '1024' },
    default: '64',
    label: 'Samples per pixel',
  },
};

const ABOUT =
  'The depth slider runs from a millimetre to a hundred metres (log scale). Clean water stays clear over a few ' +
  'centimetres but its small absorption of red adds up: over tens of metres only blue-green is left. A strong ' +
  'absorber (the illustrative wine-like one) colours light within a centimetre. Scattering does something else: it turns light aside, so the glass first ' +
  'looks cloudy and then, when scattering is strong and absorption weak (milk), opaque and white. The grid sets ' +
  'absorption (upwards) against scattering (across), as in the talk, milk at the lower right. The picture is path traced on the GPU and ' +
  'refines for a moment after each change.';

const TERMS_USED = ['transmittance'];
const MILK_CAVEAT =
  'would pass unscattered if milk scattered evenly in all directions with its reduced ' +
  'coefficient σ′s (the similarity relation, which the picture uses). Milk’s fat globules, about a wavelength ' +
  'across or more, scatter mostly forwards (g > 0 by Lorenz–Mie theory, which Frisvad, Christensen & Jensen 2007 ' +
  'apply to milk; Jensen et al. 2001 give σ′s only), so its true σs = σ′s/(1 − g) is larger and the light that ' +
  'really passes unscattered is less.';
// the talk's grid: absorption (more in blue: a red look) grows upwards, scattering to the right, so the
// milk-like glass (high scattering, low absorption) sits at the lower right as on the talk's slide
const GRID_ABSORB = [0, 1.5, 6].map((k) => [0.15 * k, 0.8 * k, 1.4 * k]);
const GRID_SCATTER = [0, 3, 40];
const TRACE_MAX_WIDTH = 480; // pixels across that are path traced; the display scales them up
const DISTANCES = Float64Array.from({ length: 241 }, (_, i) => 10 ** (-3 + i * (5 / 240)));

function cellsFor(s) {
  if (s.view === 'grid') {
    return GRID_ABSORB.flatMap((a) => GRID_SCATTER.map((sc) => ({ sigmaA: a, sigmaS: [sc, sc, sc] }))); // cell 0 at the bottom left
  }
  const m = MEDIA[s.medium];
  const d = 10 ** s.distance;
  return [{ sigmaA: m.sigmaA.map((x) => x * d), sigmaS: m.sigmaS.map((x) => x * d) }]; // per unit depth of the drawn cube
}

export function createMedia(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, {
    name: 'media',
    schema,
    initialState,
    locked,
    about: ABOUT,
    terms: TERMS_USED,
  });
  const readout = document.createElement('p');
  readout.className = 'media-readout';

  let frame = 0;
  let targets = null;
  const quad = new THREE.Mesh(new THREE.PlaneGeometry(2, 2));
  quad.frustumCulled = false;
  const scene = new THREE.Scene().add(quad);
  const camera = new THREE.Camera();
  const programs = new Map(); // by cell layout
  const tracerFor = (cx, cy) => {
    const key = `${cx}x${cy}`;
    if (!programs.has(key)) {
      const n = cx * cy;
      programs.set(
        key,
        new THREE.ShaderMaterial({
          glslVersion: THREE.GLSL3,
          uniforms: {
            uPrev: { value: null },
            uSize: { value: new THREE.Vector2() },
            uFrame: { value: 0 },
            uSigmaA: { value: Array.from({ length: n }, () => new THREE.Vector3()) },
            uSigmaS: { value: Array.from({ length: n }, () => new THREE.Vector3()) },
          },
          vertexShader: SHADER_CHUNKS['fullscreen.vert.glsl'],
          fragmentShader: assembleGlsl(SHADER_CHUNKS['media-tracer.frag.glsl'], {
            defines: { CELLS: n, CELLS_X: cx, CELLS_Y: cy },
          }),
        }),
      );
    }
    return programs.get(key);
  };
  const display = new THREE.ShaderMaterial({
    glslVersion: THREE.GLSL3,
    uniforms: { uSum: { value: null }, uSize: { value: new THREE.Vector2() } },
    vertexShader: SHADER_CHUNKS['fullscreen.vert.glsl'],
    fragmentShader: assembleGlsl(SHADER_CHUNKS['media-display.frag.glsl']),
  });

  const bufferSize = new THREE.Vector2(); // reused by every progressive frame
  const traceSize = new THREE.Vector2();
  const restart = () => {
    frame = 0;
    viewport?.invalidate();
  };

  const dropTargets = () => {
    targets?.forEach((t) => t.dispose());
    targets = null;
    restart();
  };
  const viewport = createViewport(shell.view, {
    label: 'Glasses of a medium in front of a chequered wall',
    onResize: dropTargets,
    onContextLost: dropTargets, // the running sum is gone with the context: start the accumulation over
    draw(renderer) {
      const canvasSize = renderer.getDrawingBufferSize(bufferSize);
      const scale = Math.min(1, TRACE_MAX_WIDTH / canvasSize.x); // long walks (milk) are costly: trace fewer pixels
      const size = traceSize.set(
        Math.max(1, Math.round(canvasSize.x * scale)),
        Math.max(1, Math.round(canvasSize.y * scale)),
      );
      if (!targets) {
        targets = [floatTarget(size.x, size.y), floatTarget(size.x, size.y)];
        targets.forEach((t) => {
          t.texture.minFilter = t.texture.magFilter = THREE.LinearFilter;
        });
      }
      const s = shell.state;
      const [cx, cy] = s.view === 'grid' ? [3, 3] : [1, 1];
      const tracer = tracerFor(cx, cy);
      cellsFor(s).forEach((c, i) => {
        tracer.uniforms.uSigmaA.value[i].set(...c.sigmaA);
        tracer.uniforms.uSigmaS.value[i].set(...c.sigmaS);
      });
      if (frame === 0) {
        for (const t of targets) {
          renderer.setRenderTarget(t);
          renderer.setClearColor(0x000000, 0);
          renderer.clear();
        }
      }
      tracer.uniforms.uPrev.value = targets[0].texture;
      tracer.uniforms.uSize.value.set(size.x, size.y);
      tracer.uniforms.uFrame.value = frame;
      quad.material = tracer;
      renderer.setRenderTarget(targets[1]);
      renderer.render(scene, camera);
      targets.reverse();
      display.uniforms.uSum.value = targets[0].texture;
      display.uniforms.uSize.value.copy(canvasSize);
      quad.material = display;
      renderer.setRenderTarget(null);
      renderer.render(scene, camera);
      frame++;
      if (frame < Number(s.samples)) viewport.invalidate(); // a running animation: refine until done, then idle
    },
  });
  if (viewport) viewport.holder.classList.add('media-view');
  shell.view.append(readout);

  const plotSpec = () => {
    const m = MEDIA[shell.state.medium];
    const st = m.sigmaA.map((a, i) => a + m.sigmaS[i]);
    const d = 10 ** shell.state.distance;
    return {
      title: m.reduced
        ? `${m.name}: e^(−(σa + σ′s) d), an upper bound on the light left unscattered (Beer–Lambert, ${m.source})`
        : `${m.name}: light left unscattered and unabsorbed after a depth d (Beer–Lambert, ${m.source})`,
      xLabel: 'Depth d (m, log scale)',
      yLabel: 'transmittance',
      x: { min: 1e-3, max: 100, log: true },
      y: { min: 0, max: 1.02 },
      xValues: (u, t) =>
        t.map((v) => (v == null ? '' : v >= 1 ? `${v} m` : v >= 0.01 ? `${v * 100} cm` : `${v * 1000} mm`)),
      series: ['red (650 nm)', 'green (550 nm)', 'blue (450 nm)'].map((label, i) => ({
        label,
        stroke: ['#d55e00', '#009e73', '#0072b2'][i],
        dash: SERIES_DASHES[i],
      })),
      data: [DISTANCES, ...st.map((sig) => DISTANCES.map((x) => transmittance(sig, x)))],
      bands: [{ from: d / 1.06, to: d * 1.06, color: '#0000002a', label: '' }],
      filename: `transmittance-${shell.state.medium}`,
      height: 240,
    };
  };
  const plot = createPlot(shell.view, plotSpec());

  const describe = () => {
    const s = shell.state;
    if (s.view === 'grid') {
      readout.textContent =
        'Across: no, some and strong scattering. Upwards: no, some and strong absorption (strongest in blue). Bottom right: high scattering, no absorption, white like milk.';
      shell.describe(
        'Nine glasses in front of a chequered wall: absorption grows upwards, scattering to the right; the top-left is clear dark red, the bottom-right white and opaque like milk.',
        viewport?.canvas,
      );
      return;
    }
    const m = MEDIA[s.medium];
    const d = 10 ** s.distance;
    const T = m.sigmaA.map((a, i) => transmittance(a + m.sigmaS[i], d));
    const hex = rgbToHex(T.map(linearToSrgb));
    const depth =
      d >= 1
        ? `${d.toPrecision(3)} m`
        : d >= 0.01
          ? `${(d * 100).toPrecision(3)} cm`
          : `${(d * 1000).toPrecision(3)} mm`;
    readout.innerHTML =
      `<span class="swatch big" style="background:${hex}"></span> <span>White light after <strong>${depth}</strong> of ${m.name.toLowerCase()}: ` +
      `R ${(T[0] * 100).toFixed(1)}%, G ${(T[1] * 100).toFixed(1)}%, B ${(T[2] * 100).toFixed(1)}% ${m.reduced ? MILK_CAVEAT : 'passes without being absorbed or scattered.'}</span>`;
    shell.describe(
      `A glass of ${m.name.toLowerCase()} ${depth} deep in front of a chequered wall; ${readout.textContent.trim()}`,
      viewport?.canvas,
    );
  };
  describe();

  const onChanged = (changed) => {
    if (changed.some((k) => k === 'medium' || k === 'distance' || k === 'view')) plot.setData(plotSpec());
    describe();
    restart();
  };
  const update = shell.connect({ title: 'Media', onChanged, onStateChange });

  return {
    update,
    getState: () => shell.state,
    getProgress: () => ({ frame, target: Number(shell.state.samples) }),
    dispose() {
      plot.dispose();
      targets?.forEach((t) => t.dispose());
      programs.forEach((p) => p.dispose());
      display.dispose();
      quad.geometry.dispose();
      viewport?.dispose();
      shell.dispose();
    },
  };
}

export const widget = { name: 'media', schema, create: createMedia, terms: TERMS_USED };
