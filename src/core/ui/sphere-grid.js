// A row of spheres in one canvas, each shaded by its own BRDF variant (brdf-sphere.frag.glsl) under the
// same punctual light, or in the white furnace, each a ray-traced impostor (sphere-impostor.js). Cells: [{ label,
// defines, uniforms, probe, own? }]; each cell is one draw in its own viewport. Variants are compiled once and
// reused. A cell with a user-written term brings its chunks (`own`: { key, chunks }, key naming the code): its
// program is kept while a cell draws it. Hovering a sphere probes it: the angles there, and the rows the cell's
// probe(angles, n) returns ([[label, text], ...]; n in view space).
import * as THREE from 'three';
import { createViewport } from '../framework/viewport.js';
import { buildShader, fragmentSource } from '../gpu/shader-builder.js';
import { SHADER_CHUNKS } from '../gpu/shader-chunks.js';
import { createProgramCache, definesKey, programKey } from '../gpu/program-cache.js';
import { angleText, probeAngles, showProbeRows } from './probe.js';
import { drawSideBySide } from './side-by-side.js';
import { HALF_SIZE, createImpostorView } from './sphere-impostor.js';
import { termUniformDefaults } from '../../math/catalogue/uniforms.js';

const ALPHA_DEFAULT = 0.3;

/**
 * Every uniform a cell's program may read, with its value when the cell gives none (brdf-sphere.frag.glsl): the
 * terms' from the catalogue (each bound to its parameter; a cell gives its own with termUniforms).
 */
const UNIFORM_DEFAULTS = {
  uLightDir: [0, 0, 1],
  uLightIntensity: 1,
  uExposure: 1,
  uAlphaPair: [ALPHA_DEFAULT, ALPHA_DEFAULT], // the microfacet input's (αx, αy): a cell gives it by sharedUniforms
  uTangent: [1, 0, 0], // the view-space axis the tangent runs along: across the picture
  ...termUniformDefaults({ alpha: ALPHA_DEFAULT }),
  uF0: 1,
  uDiffuse: 0.5,
  uSigma: 0,
  uDfg: null, // the split-sum table, for the furnace
  uAlbedoTableGGX: null, // the albedo-loss table, for the compensated furnace
  uBackground: [0, 0, 0], // the grid's background (linear RGB), for the antialiased silhouette
};

/** The names of the uniforms the sphere grid feeds brdf-sphere.frag.glsl (the program-variants test checks them). */
export const SPHERE_UNIFORMS = Object.keys(UNIFORM_DEFAULTS);

const withImpostor = (defines) => ({ ...defines, SPHERE_IMPOSTOR: 1 });

/** The sphere's fragment program for `defines`, with `chunks` (the app's, or those with a user's term). */
export const sphereFragment = (defines, chunks = SHADER_CHUNKS) =>
  fragmentSource('brdf-sphere.frag.glsl', { defines: withImpostor(defines), chunks });

/**
 * The program of one set of #define switches, its uniforms set to the defaults; a cell with a term of the user's
 * brings its chunks and its sliders (`own`: { key, chunks, uniforms }).
 */
const sphereMaterial = (defines, own) =>
  buildShader('brdf-sphere.frag.glsl', {
    vertex: 'sphere-impostor.vert.glsl',
    defines: withImpostor(defines),
    chunks: own?.chunks,
    uniforms: Object.fromEntries(
      Object.entries({ ...own?.uniforms, ...UNIFORM_DEFAULTS }).map(([k, v]) => [
        k,
        { value: Array.isArray(v) ? new (v.length === 2 ? THREE.Vector2 : THREE.Vector3)(...v) : v },
      ]),
    ),
  });

const sameValue = (a, b) => a === b || (Array.isArray(a) && Array.isArray(b) && a.every((x, i) => x === b[i]));

/** Whether two lists of cells draw the same picture: labels, programs and uniform values (textures by identity). */
function sameDrawing(cells, next) {
  const same = (a, b) =>
    a.label === b.label &&
    definesKey(a.defines) === definesKey(b.defines) &&
    a.own?.key === b.own?.key &&
    Object.keys({ ...a.uniforms, ...b.uniforms }).every((k) => sameValue(a.uniforms[k], b.uniforms[k]));
  return cells.length === next.length && cells.every((c, i) => same(c, next[i]));
}

/** Draws each cell in its own square viewport, side by side across the canvas, with its program and uniforms. */
function drawCells(renderer, cells, programs, view) {
  drawSideBySide(renderer, cells.length, (i) => {
    const cell = cells[i];
    const material = programs.get(cell.defines, cell.own && { ...cell.own, uniforms: cell.uniforms });
    const uniforms = { ...UNIFORM_DEFAULTS, uBackground: view.background, ...cell.uniforms };
    for (const [k, v] of Object.entries(uniforms)) {
      if (Array.isArray(v)) material.uniforms[k].value.set(...v);
      else material.uniforms[k].value = v;
    }
    view.mesh.material = material;
    renderer.render(view.scene, view.camera);
  });
}

/**
 * Hovering a sphere, or the arrow keys on the focused canvas, probes it: the angles there and the rows of its
 * cell's probe(angles, n). Returns the panel's dispose.
 */
function attachProbe(container, viewport, cellsNow) {
  const probePanel = document.createElement('div');
  probePanel.className = 'probe';
  const idle =
    'Probe: point at a sphere (or focus the picture and use the arrow keys) to read the angles and terms there.';
  probePanel.textContent = idle;
  container.append(probePanel);
  const marker = document.createElement('span'); // where the keyboard probe is
  marker.className = 'probe-marker';
  marker.hidden = true;
  viewport?.holder.append(marker);

  /** Cell i's layout in CSS pixels: its width, the side of its sphere's square, the canvas height. */
  const layout = () => {
    const rect = viewport.canvas.getBoundingClientRect();
    const w = rect.width / Math.max(cellsNow().length, 1);
    return { rect, w, side: Math.min(w, rect.height) };
  };
  /** Shows the probe at (x, y) on sphere i (sphere coordinates, x² + y² < 1). */
  const probeAt = (i, x, y) => {
    const cell = cellsNow()[i];
    if (!cell || x * x + y * y >= 1) {
      probePanel.textContent = idle;
      return;
    }
    const n = [x, y, Math.sqrt(1 - x * x - y * y)];
    const l = cell.uniforms.uLightDir ?? UNIFORM_DEFAULTS.uLightDir;
    const a = probeAngles(n, l, [0, 0, 1]);
    showProbeRows(probePanel, [
      ['sphere', cell.label],
      ['n·v', angleText(a.nv)],
      ['n·l', angleText(a.nl)],
      ['n·h', angleText(a.nh)],
      ['l·h', angleText(a.lh)],
      ...(cell.probe?.(a, n) ?? []),
    ]);
  };
  const onMove = (e) => {
    const { rect, w, side } = layout();
    const i = Math.floor((e.clientX - rect.left) / w);
    marker.hidden = true;
    probeAt(
      i,
      ((e.clientX - rect.left - i * w - w / 2) / (side / 2)) * HALF_SIZE,
      -((e.clientY - rect.top - rect.height / 2) / (side / 2)) * HALF_SIZE,
    );
  };
  // the keyboard probe: arrows move it over a sphere (Shift: finer); across a sphere's edge it goes on to the next
  let keyProbe = { i: 0, x: 0, y: 0 };
  const onKey = (e) => {
    const d = e.shiftKey ? 0.02 : 0.1;
    const move = { ArrowLeft: [-d, 0], ArrowRight: [d, 0], ArrowUp: [0, d], ArrowDown: [0, -d] }[e.key];
    if (!move || !cellsNow().length) return;
    e.preventDefault();
    let { i, x, y } = keyProbe;
    [x, y] = [x + move[0], y + move[1]];
    if (x * x + y * y >= 1 && move[0] && cellsNow()[i + Math.sign(move[0])])
      [i, x] = [i + Math.sign(move[0]), -Math.sign(move[0]) * 0.9];
    const r = Math.hypot(x, y);
    if (r > 0.98) [x, y] = [(x / r) * 0.98, (y / r) * 0.98];
    keyProbe = { i: Math.min(i, cellsNow().length - 1), x, y };
    const { rect, w, side } = layout();
    marker.style.left = `${keyProbe.i * w + w / 2 + (x / HALF_SIZE) * (side / 2)}px`;
    marker.style.top = `${rect.height / 2 - (y / HALF_SIZE) * (side / 2)}px`;
    marker.hidden = false;
    probeAt(keyProbe.i, x, y);
  };
  viewport?.canvas.addEventListener('pointermove', onMove);
  viewport?.canvas.addEventListener('pointerleave', () => (probePanel.textContent = idle));
  viewport?.canvas.addEventListener('keydown', onKey);
  viewport?.canvas.addEventListener('blur', () => (marker.hidden = true));
  return () => probePanel.remove();
}

export function createSphereGrid(container, { label = 'Spheres', aspectPerCell = 1, background = '#16181d' } = {}) {
  let cells = [];
  let drawnOnce = false;
  const programs = createProgramCache(sphereMaterial);
  const view = createImpostorView(background);
  const labels = document.createElement('div');
  labels.className = 'sphere-labels';
  const viewport = createViewport(container, {
    draw: (renderer) => drawCells(renderer, cells, programs, view),
    label,
    antialias: false, // the spheres smooth their own silhouettes
  });
  if (viewport) {
    viewport.holder.classList.add('sphere-grid');
    viewport.holder.classList.toggle('light-background', new THREE.Color(background).getHSL({}).l > 0.6);
    viewport.holder.append(labels);
  }
  const removeProbe = attachProbe(container, viewport, () => cells);
  const setAspect = () =>
    viewport && (viewport.holder.style.aspectRatio = `${Math.max(cells.length, 1) * aspectPerCell} / 1`);

  return {
    /** Replaces the cells; redraws when what they draw differs (a probe alone may change). */
    setCells(next) {
      const redraw = !drawnOnce || !sameDrawing(cells, next);
      [cells, drawnOnce] = [next, true];
      const drawn = new Set(cells.filter((c) => c.own).map((c) => programKey(c.defines, c.own)));
      programs.keepOnly((key) => drawn.has(key)); // a user's programs of code no cell draws go
      labels.replaceChildren(
        ...cells.map((c) => Object.assign(document.createElement('span'), { textContent: c.label })),
      );
      setAspect();
      if (redraw) viewport?.invalidate();
    },
    get canvas() {
      return viewport?.canvas;
    },
    /** The renderer the spheres are drawn with (null without WebGL2): a user's term is evaluated on it too. */
    get renderer() {
      return viewport?.renderer ?? null;
    },
    get variants() {
      return programs.size;
    },
    dispose() {
      removeProbe();
      programs.dispose();
      view.dispose();
      viewport?.dispose();
    },
  };
}
