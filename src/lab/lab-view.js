// One canvas for the lab: a row of panels (approximations, reference, errors), each a res × res image from the
// lab renderer, drawn with the exposure (or on the error scale), with HTML captions. Also owns the GPU side:
// the lab renderer, each environment's maps and each DFG table, made when first asked for and kept for switching
// back.
import * as THREE from 'three';
import { createViewport } from '../core/gpu/viewport.js';
import { createFullscreenPass } from '../core/gpu/fullscreen-pass.js';
import { createDfgTexture, createEnvironmentMaps } from './environment-maps.js';
import { fullscreenMaterial } from './fullscreen-material.js';
import { createLabRenderer } from './lab-renderer.js';
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
 * 'approx' | 'reference' | 'error', slot, caption }]. environment(key, pixels?) gives the maps of a built-in
 * environment or of pixels (a file) under `key`; again() asks for another frame (a converging reference).
 * onReset(): the GPU content is gone (the context was given up): the widget must render everything again.
 */
export function createLabView(container, { label, resolution, slots = 1, frame, onReset }) {
  const captions = document.createElement('div');
  captions.className = 'lab-captions';
  let lab = null;
  const resources = createLabResources();
  const panels = createPanels();
  let again = false;

  const draw = (renderer) => {
    lab ??= createLabRenderer(renderer, { dfg: resources.dfg, resolution, slots });
    again = false;
    const shown = frame({ lab, environment: resources.environment(renderer), again: () => (again = true) });
    panels.draw(renderer, lab, shown);
    captions.replaceChildren(
      ...shown.map((p) => Object.assign(document.createElement('span'), { textContent: p.caption })),
    );
    if (again) viewport.invalidate();
  };

  // everything on the GPU went with the context: rebuilt by the next draw, from the state
  const onContextLost = () => {
    lab?.dispose();
    lab = null;
    resources.dispose();
    onReset?.();
  };
  const viewport = createViewport(container, { draw, label, onContextLost });
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
    setAspect(panels) {
      if (viewport) viewport.holder.style.aspectRatio = `${panels} / 1`;
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

/**
 * The row of panels on the canvas: draw(renderer, lab, panels) shows each image of `lab` in its square, with the
 * exposure (or on the error scale) of setDisplay({ exposure, errorScale }).
 */
function createPanels() {
  const tone = viewMaterial({});
  const error = viewMaterial({ ERROR_VIEW: 1 });
  const pass = createFullscreenPass();
  const size = new THREE.Vector2();
  let settings = { exposure: 1, errorScale: 0.1 };
  return {
    draw(renderer, lab, panels) {
      const pr = renderer.getPixelRatio();
      renderer.getSize(size);
      const w = size.x / panels.length;
      renderer.setScissorTest(true);
      panels.forEach((panel, i) => {
        const side = Math.min(w, size.y);
        const rect = [i * w + (w - side) / 2, (size.y - side) / 2, side, side];
        const m = panel.image === 'error' ? error : tone;
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
      [tone, error, pass].forEach((x) => x.dispose());
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
