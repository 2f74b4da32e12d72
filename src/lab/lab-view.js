// One canvas for the lab: panels (approximations, reference, errors), each a res × res image from the lab
// renderer, drawn with the exposure (or on the error scale), in as many columns as fit (one row on a wide screen,
// a grid on a phone), each with its HTML caption in a strip above it, never over the picture. Also owns the GPU side:
// the lab renderer, each environment's maps and each DFG table, made when first asked for and kept for switching
// back.
import * as THREE from 'three';
import { createViewport } from '../core/framework/viewport.js';
import { createFullscreenPass } from '../core/gpu/fullscreen-pass.js';
import { createDfgTexture, createEnvironmentMaps } from './environment-maps.js';
import { fullscreenMaterial } from './fullscreen-material.js';
import { createLabRenderer } from './lab-renderer.js';
import { EXTENT } from './lab-uniforms.js';
import { FURNACE, skyPixels } from './environments.js';

const viewMaterial = (defines) =>
  fullscreenMaterial('lab-view.frag.glsl', {
    defines,
    uniforms: {
      uImage: { value: null },
      uOther: { value: null },
      uRect: { value: new THREE.Vector4() },
      uExposure: { value: 1 },
      uErrorScale: { value: 0.1 },
      uExtent: { value: EXTENT },
      uTangentAxis: { value: [0, 0, 1] },
      uTangentRotation: { value: 0 },
    },
  });

const BUILT_IN = {
  studio: () => 'studio',
  furnace: () => FURNACE,
  sky: () => skyPixels(512, 256, true),
  'sky-no-sun': () => skyPixels(512, 256, false),
};

/**
 * frame({ lab, environment, again }) runs in each drawn frame and returns the panels to show: [{ image:
 * 'approx' | 'reference' | 'error', slot, caption, tangents }] (tangents: a tangent field, lab-anisotropy.js, whose
 * brushing lines are drawn over the image). environment(key, pixels?) gives the maps of a built-in
 * environment or of pixels (a file) under `key`; again() asks for another frame (a converging reference).
 * onReset(): the GPU content is gone (the context was given up): the widget must render everything again.
 */
export function createLabView(container, { label, resolution, slots = 1, frame, onReset }) {
  const captions = document.createElement('div');
  captions.className = 'lab-captions';
  let lab = null;
  const resources = createLabResources();
  const layout = createLayout(captions);
  const panels = createPanels(layout);
  let again = false;

  const draw = (renderer) => {
    lab ??= createLabRenderer(renderer, { dfg: resources.dfg, resolution, slots });
    again = false;
    const shown = frame({ lab, environment: resources.environment(renderer), again: () => (again = true) });
    panels.draw(renderer, lab, shown);
    captions.replaceChildren(
      ...shown.map((p) => Object.assign(document.createElement('span'), { textContent: p.caption })),
    );
    if (layout.fitLines()) {
      layout.fit(viewport.holder, viewport.holder.clientWidth); // the pictures drawn again under the new strip
      again = true;
    }
    if (again) viewport.invalidate();
  };

  // everything on the GPU went with the context: rebuilt by the next draw, from the state
  const onContextLost = () => {
    lab?.dispose();
    lab = null;
    resources.dispose();
    onReset?.();
  };
  const onResize = (width) => viewport && layout.fit(viewport.holder, width);
  const viewport = createViewport(container, { draw, label, onContextLost, onResize });
  if (viewport) {
    viewport.holder.classList.add('lab-view');
    viewport.holder.append(captions);
  }
  return {
    viewport,
    get canvas() {
      return viewport?.canvas;
    },
    get lab() {
      return lab;
    },
    resolution,
    setDisplay(next) {
      panels.setDisplay(next);
      viewport?.invalidate();
    },
    /** How many panels the frame shows: the grid (columns, rows, the holder's height) follows. */
    setPanels(count) {
      layout.count = count;
      if (viewport) layout.fit(viewport.holder, viewport.holder.clientWidth);
    },
    invalidate: () => viewport?.invalidate(),
    dispose() {
      panels.dispose();
      resources.dispose();
      lab?.dispose();
      viewport?.dispose();
    },
  };
}

// CSS px above each picture: as many lines of the captions' 0.78rem text (15 px) as the longest one takes at the
// columns' width, two at least (four lights and their methods take five lines in a phone's column)
const CAPTION_LINE = 15;
const captionStrip = (lines) => 8 + CAPTION_LINE * lines;

/** The lines the longest caption's text takes (its own box is the strip's height, so its text is measured). */
function captionLines(captions) {
  const range = document.createRange();
  const heights = [...captions.children].map((span) => {
    range.selectNodeContents(span);
    return range.getBoundingClientRect().height;
  });
  return Math.max(2, ...heights.map((h) => Math.round(h / CAPTION_LINE)));
}
const MIN_PANEL = 140; // CSS px: narrower pictures go on more rows instead

/**
 * The panels' grid: as many columns as fit pictures at least MIN_PANEL wide (the last row may be short).
 * fit(holder, width) sets the holder's aspect to rows of (square + caption strip) and lays the captions out on the
 * same grid; cell(i, width, height) is panel i's square in CSS px, y from the top.
 */
function createLayout(captions) {
  const grid = { count: 1, cols: 1, rows: 1, lines: 2, strip: captionStrip(2) };
  const columnsFor = (width) => Math.min(Math.max(Math.floor(width / MIN_PANEL), 1), grid.count);
  return {
    set count(n) {
      grid.count = n;
    },
    /** Sets the strip's lines to what the captions take; true when they changed (the holder must be fitted again). */
    fitLines() {
      const lines = captionLines(captions);
      if (lines === grid.lines) return false;
      [grid.lines, grid.strip] = [lines, captionStrip(lines)];
      return true;
    },
    fit(holder, width) {
      if (width <= 0) return;
      grid.cols = columnsFor(width);
      grid.rows = Math.ceil(grid.count / grid.cols);
      const cellHeight = width / grid.cols + grid.strip;
      holder.style.aspectRatio = `${width} / ${Math.round(grid.rows * cellHeight)}`;
      captions.style.gridTemplateColumns = `repeat(${grid.cols}, minmax(0, 1fr))`;
      captions.style.gridAutoRows = `${cellHeight}px`;
      captions.style.setProperty('--caption-strip', `${grid.strip}px`);
    },
    cell(i, width, height) {
      const [w, h] = [width / grid.cols, height / grid.rows];
      const side = Math.max(Math.min(w, h - grid.strip), 1);
      const [col, row] = [i % grid.cols, Math.floor(i / grid.cols)];
      return { x: col * w + (w - side) / 2, y: row * h + grid.strip, side };
    },
  };
}

/**
 * The panels on the canvas: draw(renderer, lab, panels) shows each image of `lab` in its square of the layout,
 * with the exposure (or on the error scale) of setDisplay({ exposure, errorScale }).
 */
function createPanels(layout) {
  const tone = viewMaterial({});
  const error = viewMaterial({ ERROR_VIEW: 1 });
  const overlays = {
    around: viewMaterial({ TANGENT_OVERLAY: 1 }),
    along: viewMaterial({ TANGENT_OVERLAY: 1, TANGENT_ALONG: 1 }),
  };
  const materialOf = (panel) => {
    if (panel.image === 'error') return error;
    if (!panel.tangents) return tone;
    const m = overlays[panel.tangents.mode];
    m.uniforms.uTangentAxis.value = panel.tangents.axis;
    m.uniforms.uTangentRotation.value = panel.tangents.rotation;
    return m;
  };
  const pass = createFullscreenPass();
  const size = new THREE.Vector2();
  let settings = { exposure: 1, errorScale: 0.1 };
  return {
    draw(renderer, lab, panels) {
      const pr = renderer.getPixelRatio();
      renderer.getSize(size);
      renderer.setScissorTest(true);
      panels.forEach((panel, i) => {
        const { x: left, y: top, side } = layout.cell(i, size.x, size.y);
        const rect = [left, size.y - top - side, side, side]; // GL counts y from the bottom
        const m = materialOf(panel);
        m.uniforms.uImage.value = panel.image === 'reference' ? lab.reference : lab.approx(panel.slot ?? 0);
        m.uniforms.uOther.value = lab.reference;
        m.uniforms.uRect.value.set(...rect.map((x) => x * pr));
        m.uniforms.uExposure.value = settings.exposure;
        m.uniforms.uErrorScale.value = settings.errorScale;
        renderer.setViewport(...rect);
        renderer.setScissor(...rect);
        pass.render(renderer, m, null);
      });
      renderer.setScissorTest(false);
    },
    setDisplay(next) {
      settings = { ...settings, ...next };
    },
    dispose() {
      [tone, error, overlays.around, overlays.along, pass].forEach((x) => x.dispose());
    },
  };
}

/**
 * What the lab keeps on the GPU between frames: each environment's maps (environment(renderer)(key, pixels?))
 * and each DFG table as a texture (dfg(terms)), made when first asked for; dispose() lets all go.
 */
function createLabResources() {
  const dfgTextures = new Map(); // "ndf/visibility" -> the DFG table of those terms
  const environments = new Map(); // key -> { maps, pixels }
  return {
    environment:
      (renderer) =>
      (key, pixels = null) => {
        let entry = environments.get(key);
        if (!entry) environments.set(key, (entry = { maps: createEnvironmentMaps(renderer), pixels: undefined }));
        if (entry.pixels !== pixels) {
          entry.maps.load(pixels ?? BUILT_IN[key]());
          entry.pixels = pixels;
        }
        return entry.maps;
      },
    dfg(terms) {
      const key = `${terms.ndf}/${terms.visibility}`;
      if (!dfgTextures.has(key)) dfgTextures.set(key, createDfgTexture(terms));
      return dfgTextures.get(key);
    },
    dispose() {
      dfgTextures.forEach((t) => t.dispose());
      dfgTextures.clear();
      environments.forEach((e) => e.maps.dispose());
      environments.clear();
    },
  };
}
