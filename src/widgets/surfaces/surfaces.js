// surfaces: a flat interface splitting light into reflection and refraction (exact Fresnel), what a metal
// and a non-metal do with the refracted light, the reflection cone of a rough surface against the microfacet
// prediction, and environment reflections blurring as roughness grows.
import * as THREE from 'three';
import { RoomEnvironment } from 'three/addons/environments/RoomEnvironment.js';
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { createPlot } from '../../core/ui/plot.js';
import { createViewport } from '../../core/gpu/viewport.js';
import { METALS, NON_METALS, fresnelParams, isMetal, materialByKey } from '../../math/materials.js';
import { fresnelConductor, fresnelDielectric } from '../../math/fresnel.js';
import { measuredRgbNk } from '../../math/optical-constants.js';
import { generateProfile, reflectedAngleDensity, reflectedAngles, seededRandom } from '../../math/microsurface.js';
import { smithG1Beckmann } from '../../math/visibility.js';
import { describeInterface, drawInterface } from './interface-view.js';
import { DEG } from '../../math/angles.js';

export const schema = {
  material: {
    type: 'enum',
    options: Object.fromEntries([...NON_METALS, ...METALS].map((m) => [m.key, m.name])),
    default: 'glass-high',
    label: 'Material',
  },
  theta: { type: 'number', min: 0, max: 89, step: 1, default: 40, label: 'Angle of incidence', unit: '°' },
  alpha: { type: 'number', min: 0.02, max: 0.8, step: 0.01, default: 0.2, label: 'Microsurface roughness α' },
};

const ABOUT =
  'Top: an optically flat boundary. Change the material and the angle: the reflected share follows the exact ' +
  'Fresnel equations; a metal swallows the rest within nanometres, a non-metal scatters it and some finds its way ' +
  'back out. Middle: the same boundary with microgeometry (Beckmann slopes). Each tiny facet is still a mirror, ' +
  'but their normals vary, so reflected light spreads into a cone; the histogram of ray-traced reflections ' +
  'follows the microfacet prediction. Bottom: spheres of increasing roughness reflecting a room (rendered with ' +
  'three.js’s standard material): rougher is blurrier.';

const TERMS_USED = ['fresnelDielectric', 'fresnelConductor', 'smithG1Beckmann'];
const PROFILE = 60000;
const RAYS = 30000;
const SPHERE_ROUGHNESS = [0.05, 0.2, 0.4, 0.7];

function interfaceSpec(s) {
  const p = fresnelParams(s.material);
  const c = Math.cos(s.theta * DEG);
  const metal = isMetal(s.material);
  const green = 1; // the 550 nm channel stands for the picture
  const F = metal ? fresnelConductor(c, p.eta[green], p.k[green]) : fresnelDielectric(c, p.eta[green]);
  const k550 = metal ? measuredRgbNk(s.material)[green][1] : 0;
  return {
    theta: s.theta,
    F,
    etaRefr: metal ? Math.max(p.eta[green], 1) : p.eta[green],
    metal,
    depthNm: metal ? 550 / (4 * Math.PI * k550) : 0,
    name: materialByKey(s.material).name,
  };
}

function coneSpec(s, profile) {
  const ti = s.theta * DEG;
  const bins = 90;
  const width = Math.PI / bins; // outgoing angles -90°..90°
  const counts = new Float64Array(bins);
  for (const t of reflectedAngles(profile, ti, RAYS, seededRandom(11))) {
    const b = Math.floor((t + Math.PI / 2) / width);
    if (b >= 0 && b < bins) counts[b] += 1 / RAYS / width / (180 / Math.PI);
  }
  const xs = Float64Array.from({ length: bins }, (_, b) => ((b + 0.5) * width - Math.PI / 2) / DEG);
  const predicted = xs.map(
    (deg) => reflectedAngleDensity(deg * DEG, ti, 'beckmann', s.alpha, smithG1Beckmann) / (180 / Math.PI),
  );
  return {
    title: `Where light from ${s.theta}° goes after one reflection (rough surface, α = ${s.alpha})`,
    xLabel: 'Outgoing angle (degrees; the mirror direction is −θ)',
    yLabel: 'share per degree',
    x: { min: -90, max: 90 },
    y: null,
    series: [
      { label: 'ray-traced microsurface', stroke: '#d55e00' },
      { label: 'microfacet prediction', stroke: '#0072b2', dash: [6, 4] },
    ],
    data: [xs, counts, predicted],
    bands: [],
    xValues: (u, t) => t.map((v) => `${v}°`),
    filename: 'reflection-cone',
    height: 230,
  };
}

export function createSurfaces(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, {
    name: 'surfaces',
    schema,
    initialState,
    locked,
    about: ABOUT,
    terms: TERMS_USED,
  });
  const flat = document.createElement('canvas');
  flat.className = 'interface';
  shell.view.append(flat);
  let profile = generateProfile(PROFILE, 'beckmann', shell.state.alpha, 2);
  const cone = createPlot(shell.view, coneSpec(shell.state, profile));

  // spheres under a room environment, each its own draw in a quarter of the canvas
  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(24, 1, 0.1, 20);
  camera.position.set(0, 0, 5.2);
  const geometry = new THREE.SphereGeometry(1, 96, 48);
  const materials = SPHERE_ROUGHNESS.map(
    (r) => new THREE.MeshStandardMaterial({ color: '#b8bcc2', metalness: 1, roughness: r }),
  );
  const mesh = new THREE.Mesh(geometry);
  scene.add(mesh);
  let pmrem = null;
  const drawSize = new THREE.Vector2();
  const viewport = createViewport(shell.view, {
    label: `Four metal spheres reflecting a room, roughness ${SPHERE_ROUGHNESS.join(', ')}`,
    onContextLost() {
      pmrem?.dispose(); // its texels were on the lost context: prefilter again on the next frame
      pmrem = null;
    },
    draw(renderer) {
      if (!pmrem) {
        const generator = new THREE.PMREMGenerator(renderer);
        pmrem = generator.fromScene(new RoomEnvironment(), 0.04);
        generator.dispose();
        scene.environment = pmrem.texture;
        scene.background = new THREE.Color('#2a2d33');
      }
      const size = renderer.getSize(drawSize);
      const w = size.x / materials.length;
      renderer.setScissorTest(true);
      materials.forEach((m, i) => {
        mesh.material = m;
        const [x0, x1] = [Math.round(i * w), Math.round((i + 1) * w)];
        const side = Math.min(x1 - x0, size.y);
        renderer.setViewport(x0 + (x1 - x0 - side) / 2, (size.y - side) / 2, side, side);
        renderer.setScissor(x0, 0, x1 - x0, size.y);
        renderer.render(scene, camera);
      });
      renderer.setScissorTest(false);
    },
  });
  if (viewport) {
    viewport.holder.classList.add('sphere-grid');
    viewport.holder.style.aspectRatio = `${materials.length} / 1`;
    const labels = document.createElement('div');
    labels.className = 'sphere-labels';
    labels.append(
      ...SPHERE_ROUGHNESS.map((r) => Object.assign(document.createElement('span'), { textContent: `roughness ${r}` })),
    );
    viewport.holder.append(labels);
  }

  const render = (changed) => {
    const spec = interfaceSpec(shell.state);
    drawInterface(flat, spec);
    shell.describe(
      `${describeInterface(spec)} With microgeometry of roughness α ${shell.state.alpha}, the reflection spreads into a cone around the mirror direction (plot below).`,
      flat,
    );
    if (changed?.includes('alpha')) profile = generateProfile(PROFILE, 'beckmann', shell.state.alpha, 2);
    if (!changed || changed.some((k) => k === 'alpha' || k === 'theta')) cone.setData(coneSpec(shell.state, profile));
  };
  render(null);
  const resize = new ResizeObserver(() => drawInterface(flat, interfaceSpec(shell.state)));
  resize.observe(flat);
  const update = shell.connect({ title: 'Surfaces', onChanged: render, onStateChange });

  return {
    update,
    getState: () => shell.state,
    getReflected: () => interfaceSpec(shell.state).F,
    dispose() {
      resize.disconnect();
      cone.dispose();
      materials.forEach((m) => m.dispose());
      geometry.dispose();
      pmrem?.dispose();
      viewport?.dispose();
      shell.dispose();
    },
  };
}

export const widget = { name: 'surfaces', schema, create: createSurfaces, terms: TERMS_USED };
