// media's picture: glasses of a medium in front of a chequered wall, path traced on the GPU (media-tracer.frag)
// one sample per pixel a frame into a running sum that the display pass shows, until the samples asked for.
import * as THREE from 'three';
import { createViewport } from '../../core/framework/viewport.js';
import { createFullscreenPass } from '../../core/gpu/fullscreen-pass.js';
import { createProgramCache } from '../../core/gpu/program-cache.js';
import { floatTarget } from '../../core/gpu/gpu-sum.js';
import { buildShader } from '../../core/gpu/shader-builder.js';
import { cellLayout, cellsFor } from './model.js';
import { sampleTarget } from '../../core/framework/debug-hooks.js';

const TRACE_MAX_WIDTH = 480; // pixels across that are path traced; the display scales them up

/** The tracer for CELLS_X × CELLS_Y glasses, one σa and σs uniform per glass. */
const makeTracer = (defines) =>
  buildShader('media-tracer.frag.glsl', {
    defines,
    uniforms: {
      uPrev: { value: null },
      uSize: { value: new THREE.Vector2() },
      uFrame: { value: 0 },
      uSigmaA: { value: Array.from({ length: defines.CELLS }, () => new THREE.Vector3()) },
      uSigmaS: { value: Array.from({ length: defines.CELLS }, () => new THREE.Vector3()) },
    },
  });

const makeDisplay = () =>
  buildShader('media-display.frag.glsl', {
    uniforms: { uSum: { value: null }, uSize: { value: new THREE.Vector2() } },
  });

/** The running sum's two targets (read one, write the other), at the traced size, filtered when scaled up. */
function makeTargets(size) {
  const targets = [floatTarget(size.x, size.y), floatTarget(size.x, size.y)];
  targets.forEach((t) => {
    t.texture.minFilter = t.texture.magFilter = THREE.LinearFilter;
  });
  return targets;
}

/** The traced size for a canvas: at most TRACE_MAX_WIDTH across (long walks, as in milk, are costly). */
function traceSizeOf(canvasSize, out) {
  const scale = Math.min(1, TRACE_MAX_WIDTH / canvasSize.x);
  return out.set(Math.max(1, Math.round(canvasSize.x * scale)), Math.max(1, Math.round(canvasSize.y * scale)));
}

/** A tracer with this state's glasses in its uniforms. */
function tracerFor(tracers, state) {
  const [cx, cy] = cellLayout(state);
  const tracer = tracers.get({ CELLS: cx * cy, CELLS_X: cx, CELLS_Y: cy });
  cellsFor(state).forEach((c, i) => {
    tracer.uniforms.uSigmaA.value[i].set(...c.sigmaA);
    tracer.uniforms.uSigmaS.value[i].set(...c.sigmaS);
  });
  return tracer;
}

const clearTargets = (renderer, targets) => {
  for (const t of targets) {
    renderer.setRenderTarget(t);
    renderer.setClearColor(0x000000, 0);
    renderer.clear();
  }
  renderer.setRenderTarget(null);
};

/**
 * The picture of `getState()`'s glasses. `restart()` starts the sum over (after a change); `frames()` is the
 * samples per pixel summed so far; `canvas` is null without WebGL.
 */
export function createGlassesView(container, getState) {
  let frame = 0;
  let targets = null;
  const pass = createFullscreenPass();
  const tracers = createProgramCache(makeTracer);
  const display = makeDisplay();
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
  const draw = (renderer) => {
    const canvasSize = renderer.getDrawingBufferSize(bufferSize);
    const size = traceSizeOf(canvasSize, traceSize);
    targets ??= makeTargets(size);
    if (frame === 0) clearTargets(renderer, targets);
    const tracer = tracerFor(tracers, getState());
    tracer.uniforms.uPrev.value = targets[0].texture;
    tracer.uniforms.uSize.value.set(size.x, size.y);
    tracer.uniforms.uFrame.value = frame;
    pass.render(renderer, tracer, targets[1]);
    targets.reverse();
    display.uniforms.uSum.value = targets[0].texture;
    display.uniforms.uSize.value.copy(canvasSize);
    pass.render(renderer, display, null);
    frame++;
    // a running animation: refine until done, then idle
    if (frame < sampleTarget(Number(getState().samples))) viewport.invalidate();
  };
  const viewport = createViewport(container, {
    label: 'Glasses of a medium in front of a chequered wall',
    onResize: dropTargets,
    onContextLost: dropTargets, // the running sum is gone with the context: start the accumulation over
    draw,
  });
  if (viewport) viewport.holder.classList.add('media-view');

  return {
    canvas: viewport?.canvas,
    restart,
    frames: () => frame,
    dispose() {
      targets?.forEach((t) => t.dispose());
      tracers.dispose();
      display.dispose();
      pass.dispose();
      viewport?.dispose();
    },
  };
}
