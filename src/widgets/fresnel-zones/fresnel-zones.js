// fresnel-zones: the talk's live demo. A shape under a light the user drags; the glass Fresnel of n·v,
// the zones of n·v, the zones of l·h, and the l·h zones weighted by the rest of the BRDF, with the share
// of covered pixels (or of reflected light) in each zone summed on the GPU.
import * as THREE from 'three';
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { createViewport } from '../../core/gpu/viewport.js';
import { createGpuSum, floatTarget } from '../../core/gpu/gpu-sum.js';
import { assembleGlsl } from '../../core/gpu/glsl.js';
import { SHADER_CHUNKS } from '../../core/gpu/shader-chunks.js';
import { attachLightControl } from '../../core/ui/light-control.js';
import { lightDirFromAngles } from '../../math/angles.js';
import { attachProbe, angleText, probeAngles } from '../../core/ui/probe.js';
import { createToolbar, canvasToPng, downloadCsv } from '../../core/ui/export.js';
import {
  ZONE_LABELS,
  ZONE_PALETTES,
  ZONE_PALETTE_FIELD,
  hexToRgb,
  paletteColourNames,
} from '../../core/ui/palettes.js';
import { CONDUCTOR_MODELS, METALS, NON_METALS, fresnelParams, materialByKey } from '../../math/materials.js';
import { fresnelConductor, fresnelDielectric, fresnelSchlick } from '../../math/fresnel.js';
import { ndfGGX } from '../../math/ndf.js';
import { visibilitySmithGGXCorrelated } from '../../math/visibility.js';
import { microfacetBRDFAt, punctualRadiance } from '../../math/brdf.js';
import { fresnelZone, sphereZoneFractions } from '../../math/zones.js';
import { srgbToLinear } from '../../math/color.js';
import { SHAPES, createShapeGeometry } from './shapes.js';

const MODES = {
  'fresnel-nv': 'Fresnel reflectance of n·v',
  'zones-nv': 'Zones of n·v',
  'zones-lh': 'Zones of l·h',
  'zones-lh-weighted': 'Zones of l·h × rest of BRDF',
};

export const schema = {
  mode: { type: 'enum', options: MODES, default: 'fresnel-nv', label: 'Mode' },
  shape: { type: 'enum', options: SHAPES, default: 'sphere', label: 'Shape' },
  camera: {
    type: 'enum',
    options: { orthographic: 'Orthographic', perspective: 'Perspective' },
    default: 'orthographic',
    label: 'Camera',
  },
  material: {
    type: 'enum',
    options: Object.fromEntries([...NON_METALS, ...METALS].map((m) => [m.key, m.name])),
    default: 'glass-low',
    label: 'Material',
  },
  conductor: { type: 'enum', options: CONDUCTOR_MODELS, default: 'f0-tint', label: 'Metal n, k' },
  fresnel: { type: 'enum', options: { exact: 'Exact', schlick: 'Schlick' }, default: 'exact', label: 'Fresnel' },
  alpha: { type: 'number', min: 0.01, max: 1, step: 0.01, default: 0.3, label: 'GGX α (roughness)' },
  exposure: { type: 'number', min: 0.1, max: 10, step: 0.1, default: 1, label: 'Exposure' },
  lightTheta: { type: 'number', min: 0, max: 180, step: 0.1, default: 60, label: 'Light θ from view', unit: '°' },
  lightPhi: { type: 'number', min: -180, max: 180, step: 0.1, default: 35, label: 'Light φ around view', unit: '°' },
  palette: ZONE_PALETTE_FIELD,
};

const ABOUT =
  'Drag on the picture (or focus it and use the arrow keys) to move the light; the ring marks light at 90° ' +
  'from the view. Start with the glass Fresnel of n·v: dark centre, bright rim. Then compare the zones of n·v ' +
  'with the zones of l·h: by l·h the whole object can turn yellow or red, yet once weighted by the rest of the ' +
  'BRDF the light that actually reaches the eye is mostly green. Hover the surface to probe it.';

const STATS_MAX = 512; // long side of the zone-statistics image, in pixels
const AVERAGE_MAX = 128; // smaller image for the average over light directions
const AVERAGE_LIGHTS = 64; // light directions, uniform over the sphere (Fibonacci lattice)

/** Light directions (theta, phi in degrees, view space) spread uniformly over the whole sphere. */
function sphereLights(n) {
  const golden = Math.PI * (3 - Math.sqrt(5));
  return Array.from({ length: n }, (_, i) => {
    const z = 1 - (2 * (i + 0.5)) / n;
    return [(Math.acos(z) * 180) / Math.PI, ((i * golden * 180) / Math.PI) % 360];
  });
}

function defines(state, stats) {
  const d = {};
  if (state.mode === 'fresnel-nv') d.SHOW_FRESNEL = true;
  if (state.mode.startsWith('zones-lh')) d.ZONE_BY_LH = true;
  if (state.mode === 'zones-lh-weighted') d.WEIGHTED = true;
  if (d.SHOW_FRESNEL && state.fresnel === 'schlick') d.FRESNEL_SCHLICK = true;
  if (d.SHOW_FRESNEL && fresnelParams(state.material).metal) d.METAL = true;
  if (stats) {
    d.STATS_PASS = true;
    delete d.SHOW_FRESNEL; // stats need only the zones
    delete d.FRESNEL_SCHLICK;
    delete d.METAL;
  }
  return d;
}

const TERMS_USED = [
  'fresnelZone',
  'fresnelDielectric',
  'fresnelConductor',
  'fresnelSchlick',
  'ndfGGX',
  'visibilitySmithGGXCorrelated',
  'linearToSrgb',
];

export function createFresnelZones(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, {
    name: 'fresnel-zones',
    schema,
    initialState,
    locked,
    about: ABOUT,
    terms: TERMS_USED,
  });
  const viewCol = document.createElement('div');
  viewCol.className = 'view-column';
  shell.view.append(viewCol);

  const uniforms = {
    uLightDir: { value: new THREE.Vector3() },
    uEta: { value: new THREE.Vector3() },
    uK: { value: new THREE.Vector3() },
    uF0: { value: new THREE.Vector3() },
    uAlpha: { value: 0.3 },
    uExposure: { value: 1 },
    uZoneColors: { value: [new THREE.Color(), new THREE.Color(), new THREE.Color()] },
  };
  const materials = new Map(); // program variants, kept for reuse
  const materialFor = (d) => {
    const key = JSON.stringify(d);
    if (!materials.has(key)) {
      materials.set(
        key,
        new THREE.ShaderMaterial({
          glslVersion: THREE.GLSL3,
          uniforms,
          vertexShader: SHADER_CHUNKS['surface.vert.glsl'],
          fragmentShader: assembleGlsl(SHADER_CHUNKS['fresnel-zones.frag.glsl'], { defines: d }),
        }),
      );
    }
    return materials.get(key);
  };

  const scene = new THREE.Scene();
  scene.background = new THREE.Color('#22252b');
  const mesh = new THREE.Mesh(createShapeGeometry(shell.state.shape), undefined);
  scene.add(mesh);
  const cameras = {
    orthographic: new THREE.OrthographicCamera(),
    perspective: new THREE.PerspectiveCamera(30, 1, 0.1, 20),
  };
  cameras.perspective.position.set(0, 0, 1.1 / Math.sin((15 * Math.PI) / 180));
  cameras.orthographic.position.set(0, 0, 5);
  const fit = (w, h) => {
    const aspect = w / h;
    const half = 1.1;
    const o = cameras.orthographic;
    [o.left, o.right, o.top, o.bottom] =
      aspect >= 1 ? [-half * aspect, half * aspect, half, -half] : [-half, half, half / aspect, -half / aspect];
    o.near = 0.1;
    o.far = 10;
    o.updateProjectionMatrix();
    cameras.perspective.aspect = aspect;
    cameras.perspective.fov =
      aspect >= 1 ? 30 : (2 * Math.atan(Math.tan((15 * Math.PI) / 180) / aspect) * 180) / Math.PI;
    cameras.perspective.updateProjectionMatrix();
  };
  const camera = () => cameras[shell.state.camera];

  let gpuSum = null;
  let zoneShares = [0, 0, 0];
  let averageShares = null; // weighted mode only
  let lightControl = null;

  const legend = document.createElement('div');
  legend.className = 'zone-legend';

  const targets = {};
  /** Renders the stats variant into a float image of at most `maxSide` pixels and sums it: zone totals. */
  const zoneTotals = (renderer, maxSide) => {
    const size = renderer.getDrawingBufferSize(new THREE.Vector2());
    const scale = Math.min(1, maxSide / Math.max(size.x, size.y));
    const [w, h] = [Math.max(1, Math.round(size.x * scale)), Math.max(1, Math.round(size.y * scale))];
    let target = targets[maxSide];
    if (!target || target.width !== w || target.height !== h) {
      target?.dispose();
      target = targets[maxSide] = floatTarget(w, h, true);
    }
    mesh.material = materialFor(defines(shell.state, true));
    const background = scene.background;
    scene.background = null;
    renderer.setRenderTarget(target);
    renderer.setClearColor(0x000000, 0);
    renderer.clear();
    renderer.render(scene, camera());
    renderer.setRenderTarget(null);
    scene.background = background;
    return gpuSum.sum(target).slice(0, 3);
  };
  const shares = (totals) => {
    const sum = totals[0] + totals[1] + totals[2];
    return sum > 0 ? totals.map((t) => t / sum) : [0, 0, 0];
  };
  const computeStats = (renderer) => {
    zoneShares = shares(zoneTotals(renderer, STATS_MAX));
  };
  // The talk's claim, measured: over every light direction, where does the reflected light fall?
  const computeAverage = (renderer) => {
    const totals = [0, 0, 0];
    for (const [theta, phi] of sphereLights(AVERAGE_LIGHTS)) {
      uniforms.uLightDir.value.set(...lightDirFromAngles(theta, phi));
      zoneTotals(renderer, AVERAGE_MAX).forEach((t, i) => (totals[i] += t));
    }
    averageShares = shares(totals);
    updateUniforms();
  };

  const updateUniforms = () => {
    const s = shell.state;
    uniforms.uLightDir.value.set(...lightDirFromAngles(s.lightTheta, s.lightPhi));
    const p = fresnelParams(s.material, s.conductor);
    uniforms.uEta.value.set(...p.eta);
    uniforms.uK.value.set(...p.k);
    uniforms.uF0.value.set(...p.f0);
    uniforms.uAlpha.value = s.alpha;
    uniforms.uExposure.value = s.exposure;
    ZONE_PALETTES[s.palette].colors.forEach((hex, i) => {
      uniforms.uZoneColors.value[i].setRGB(...hexToRgb(hex).map(srgbToLinear)); // the shader works in linear
    });
  };

  let statsDirty = true;
  let averageDirty = true;
  const draw = (renderer) => {
    updateUniforms();
    if (shell.state.mode === 'zones-lh-weighted' && averageDirty) {
      computeAverage(renderer);
      averageDirty = false;
      statsDirty = true;
    }
    if (statsDirty) {
      computeStats(renderer);
      statsDirty = false;
      renderLegend();
    }
    mesh.material = materialFor(defines(shell.state, false));
    renderer.render(scene, camera());
    lightControl?.draw();
  };

  const viewport = createViewport(viewCol, {
    draw,
    onResize: (w, h) => {
      fit(w, h);
      statsDirty = true;
      averageDirty = true;
    },
    label: 'Fresnel zones view',
  });

  const describe = (n, v) => {
    const s = shell.state;
    const l = lightDirFromAngles(s.lightTheta, s.lightPhi);
    const a = probeAngles(n, l, v);
    const p = fresnelParams(s.material, s.conductor);
    const exact = p.eta.map((eta, i) => (p.metal ? fresnelConductor(a.nv, eta, p.k[i]) : fresnelDielectric(a.nv, eta)));
    const schlick = p.f0.map((f0) => fresnelSchlick(f0, a.nv));
    const rgb = (xs) => (p.metal ? xs.map((x) => x.toFixed(4)).join(', ') : xs[0].toFixed(4));
    const zoneOf = (c) => ZONE_LABELS[fresnelZone(c)].split(' (')[0];
    return [
      ['n·v', angleText(a.nv)],
      ['n·l', angleText(a.nl)],
      ['n·h', angleText(a.nh)],
      ['l·h', angleText(a.lh)],
      ['F(n·v) exact', rgb(exact)],
      ['F(n·v) Schlick', rgb(schlick)],
      ['zone of n·v / l·h', `${zoneOf(a.nv)} / ${zoneOf(a.lh)}`],
      ['D GGX(n·h)', ndfGGX(a.nh, s.alpha).toPrecision(4)],
      ['V Smith corr.', visibilitySmithGGXCorrelated(a.nl, a.nv, s.alpha).toPrecision(4)],
      [
        'π·D·V/4·(n·l)',
        punctualRadiance(
          microfacetBRDFAt(a, { F: 'one', D: 'ggx', V: 'smithGGXCorrelated', alpha: s.alpha }),
          a.nl,
          1,
        ).toPrecision(4),
      ],
    ];
  };

  let probe = null;
  if (viewport) {
    gpuSum = createGpuSum(viewport.renderer);
    lightControl = attachLightControl(viewport.canvas, viewport.holder, {
      get: () => shell.state,
      set: (partial) => update(partial),
    });
    probe = attachProbe(viewport.canvas, viewCol, {
      getMesh: () => mesh,
      getCamera: camera,
      describe,
      isBusy: () => lightControl.dragging,
    });
    createToolbar(viewCol, [
      {
        label: 'Save PNG',
        onClick: () => {
          draw(viewport.renderer);
          canvasToPng(viewport.canvas, `fresnel-zones-${shell.state.mode}.png`);
        },
      },
      {
        label: 'Save CSV',
        onClick: () =>
          downloadCsv(
            [
              { name: 'zone', values: ZONE_LABELS },
              { name: 'share', values: zoneShares },
            ],
            `fresnel-zones-${shell.state.mode}.csv`,
          ),
      },
    ]);
  }
  viewCol.append(legend);

  function renderLegend() {
    const s = shell.state;
    const weighted = s.mode === 'zones-lh-weighted';
    const analytic =
      s.shape === 'sphere' && s.camera === 'orthographic' && !s.mode.startsWith('zones-lh')
        ? sphereZoneFractions()
        : null;
    const what = weighted ? 'share of reflected light' : 'share of covered pixels';
    legend.replaceChildren();
    const head = document.createElement('div');
    head.className = 'zone-legend-head';
    head.textContent = `Zones of ${s.mode.startsWith('zones-lh') ? 'l·h' : 'n·v'} — ${what}${analytic ? ' (analytic for this sphere)' : ''}`;
    legend.append(head);
    ZONE_PALETTES[s.palette].colors.forEach((color, i) => {
      const row = document.createElement('div');
      row.className = 'zone-row';
      row.dataset.zone = i;
      const sw = document.createElement('span');
      sw.className = 'swatch';
      sw.style.background = color;
      const label = document.createElement('span');
      label.textContent = ZONE_LABELS[i];
      const pct = document.createElement('span');
      pct.className = 'pct';
      pct.textContent = `${(zoneShares[i] * 100).toFixed(1)}%${analytic ? ` (${(analytic[i] * 100).toFixed(1)}%)` : ''}`;
      row.append(sw, label, pct);
      legend.append(row);
    });
    if (weighted && averageShares) {
      const avg = document.createElement('div');
      avg.className = 'zone-average';
      avg.textContent =
        `Averaged over ${AVERAGE_LIGHTS} light directions all around the object (GGX α ${s.alpha}): ` +
        averageShares.map((z, i) => `${ZONE_LABELS[i].split(' (')[0]} ${(z * 100).toFixed(1)}%`).join(', ') +
        '.';
      legend.append(avg);
    }
    shell.describe(describeView(), viewport?.canvas);
  }

  /** The picture in words: the shape, what colours it, where the light is, and the measured zone shares. */
  function describeView() {
    const s = shell.state;
    const lh = s.mode.startsWith('zones-lh');
    const pct = (x) => `${(x * 100).toFixed(1)}%`;
    const zones = (xs) => xs.map((z, i) => `${ZONE_LABELS[i].split(' (')[0]} ${pct(z)}`).join(', ');
    const f0 = fresnelParams(s.material, s.conductor).f0;
    const picture =
      s.mode === 'fresnel-nv'
        ? `${s.fresnel} Fresnel reflectance of n·v: ${f0.map(pct).join(' / ')} where the surface faces the viewer, rising to 100% at the silhouette`
        : `${MODES[s.mode]}${s.mode === 'zones-lh-weighted' ? ` (GGX α ${s.alpha})` : ''}, zones coloured ${paletteColourNames(s.palette)}`;
    const shareOf = s.mode === 'zones-lh-weighted' ? 'reflected light' : 'covered pixels';
    return (
      `${SHAPES[s.shape]} (${s.camera}), ${materialByKey(s.material).name}: ${picture}. ` +
      `Light ${s.lightTheta.toFixed(0)}° from the view direction, ${s.lightPhi.toFixed(0)}° around it${s.lightTheta > 90 ? ' (behind the object)' : ''}. ` +
      `Share of ${shareOf} by zone of ${lh ? 'l·h' : 'n·v'}: ${zones(zoneShares)}.` +
      (averageShares && s.mode === 'zones-lh-weighted'
        ? ` Averaged over ${AVERAGE_LIGHTS} light directions: ${zones(averageShares)}.`
        : '')
    );
  }
  if (!viewport) renderLegend();

  const DISPLAY_ONLY = ['palette', 'exposure', 'fresnel', 'conductor']; // change the picture, not the zone shares
  const onChanged = (changed) => {
    if (changed.includes('shape')) {
      mesh.geometry.dispose();
      mesh.geometry = createShapeGeometry(shell.state.shape);
    }
    statsDirty ||= !changed.every((k) => DISPLAY_ONLY.includes(k));
    averageDirty ||= changed.some((k) => ['shape', 'camera', 'alpha'].includes(k));
    if (changed.includes('palette')) renderLegend();
    viewport?.invalidate();
  };
  const update = shell.connect({ title: 'Fresnel zones', onChanged, onStateChange });

  return {
    update,
    getState: () => shell.state,
    /** Zone shares last measured on the GPU (for tests and exercises). */
    getZoneShares: () => [...zoneShares],
    /** In the weighted mode: the shares averaged over light directions uniform on the sphere. */
    getAverageShares: () => averageShares && [...averageShares],
    /** Number of distinct shader programs compiled so far, and the source of the one in use. */
    getProgramInfo: () => ({ variants: materials.size, fragmentShader: mesh.material?.fragmentShader ?? '' }),
    dispose() {
      probe?.dispose();
      lightControl?.dispose();
      gpuSum?.dispose();
      Object.values(targets).forEach((t) => t.dispose());
      materials.forEach((m) => m.dispose());
      mesh.geometry.dispose();
      viewport?.dispose();
      shell.dispose();
    },
  };
}

export const widget = { name: 'fresnel-zones', schema, create: createFresnelZones, terms: TERMS_USED };
