// Multisampling once a gesture ends: on software WebGL a multisampled frame of a large view costs about twice a
// plain one. A frame drawn while the reader holds a gesture on the widget (a pointer pressed on its view or its
// controls, a held key, a turning wheel: held-input.js) is drawn plainly on the canvas (its context made without
// multisampling), and once the gesture ends the same state is drawn once more into a multisampled framebuffer and
// resolved onto the canvas, as a multisampled context does with every frame. Any other frame (a click, a typed
// value, a parent's message) goes straight to the multisampled one. The input decides, not the time between frames:
// a slow machine spaces a drag's frames out but draws them plainly all the same.
//
// three.js draws into that framebuffer through a render target marked as its WebXR views' are (a framebuffer that
// stands for the display): its own colours (a scene's background, its built-in materials) are encoded and tone
// mapped there as on the canvas, not left in the working colour space as in a render target read as a texture.
import * as THREE from 'three';
import { watchHeldInput } from './held-input.js';

const SAMPLES = 4; // what a WebGL context's own multisampling gives (Chromium, SwiftShader included)

/**
 * A framebuffer of SAMPLES-sample colour and depth renderbuffers, sized by `fit(w, h)`; its colour has the canvas's
 * format (RGB8 without alpha), as a blit that resolves samples needs the same format on both sides.
 */
function createMultisampledFramebuffer(renderer) {
  const gl = renderer.getContext();
  const framebuffer = gl.createFramebuffer();
  const color = gl.createRenderbuffer();
  const depth = gl.createRenderbuffer();
  const colorFormat = gl.getContextAttributes()?.alpha ? gl.RGBA8 : gl.RGB8;
  let [width, height] = [0, 0];
  const store = (renderbuffer, format, attachment) => {
    gl.bindRenderbuffer(gl.RENDERBUFFER, renderbuffer);
    gl.renderbufferStorageMultisample(gl.RENDERBUFFER, SAMPLES, format, width, height);
    gl.framebufferRenderbuffer(gl.FRAMEBUFFER, attachment, gl.RENDERBUFFER, renderbuffer);
  };
  return {
    framebuffer,
    fit(w, h) {
      if (w === width && h === height) return;
      [width, height] = [w, h];
      renderer.state.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
      store(color, colorFormat, gl.COLOR_ATTACHMENT0);
      store(depth, gl.DEPTH_COMPONENT24, gl.DEPTH_ATTACHMENT);
      gl.bindRenderbuffer(gl.RENDERBUFFER, null);
      renderer.state.bindFramebuffer(gl.FRAMEBUFFER, null);
    },
    /** Resolves the samples onto the canvas. */
    resolve() {
      renderer.state.bindFramebuffer(gl.READ_FRAMEBUFFER, framebuffer);
      renderer.state.bindFramebuffer(gl.DRAW_FRAMEBUFFER, null);
      gl.blitFramebuffer(0, 0, width, height, 0, 0, width, height, gl.COLOR_BUFFER_BIT, gl.NEAREST);
      renderer.state.bindFramebuffer(gl.READ_FRAMEBUFFER, null);
    },
    dispose() {
      gl.deleteFramebuffer(framebuffer);
      gl.deleteRenderbuffer(color);
      gl.deleteRenderbuffer(depth);
    },
  };
}

/**
 * `draw(renderer)` draws a frame into the renderer's current target (the canvas, or the multisampled framebuffer);
 * `invalidate()` asks the render loop for a frame; the gestures that count are those on `element`'s widget.
 * Returns `frame()`, the render loop's draw, which picks plain or multisampled; `drawSettled()`, the multisampled
 * frame now (for a still read from the canvas); `drop()`, after a context loss; `dispose()`.
 */
export function createSettledAntialias(renderer, draw, invalidate, element) {
  const size = new THREE.Vector2();
  // three.js's handle on the framebuffer (its size, its viewport), in the canvas's colour space
  const target = new THREE.WebGLRenderTarget(1, 1, { colorSpace: renderer.outputColorSpace });
  target.isXRRenderTarget = true; // what three.js checks to treat a target's framebuffer as the display
  let multisampled = null; // made on first use, and again after a context loss
  let plainShown = false; // the canvas holds a plain frame: the gesture's end draws it multisampled
  const input = watchHeldInput(element, () => plainShown && invalidate());

  const drawSettled = () => {
    renderer.getDrawingBufferSize(size);
    multisampled ??= createMultisampledFramebuffer(renderer);
    multisampled.fit(size.x, size.y);
    target.setSize(size.x, size.y);
    renderer.setRenderTargetFramebuffer(target, multisampled.framebuffer); // again after a restore: three forgets
    const previous = renderer.getRenderTarget();
    renderer.setRenderTarget(target);
    draw(renderer);
    renderer.setRenderTarget(previous);
    multisampled.resolve();
  };

  return {
    frame() {
      plainShown = input.held;
      if (plainShown) draw(renderer);
      else drawSettled();
    },
    drawSettled,
    drop() {
      multisampled = null; // its objects died with the context
    },
    dispose() {
      input.dispose();
      multisampled?.dispose();
      target.dispose();
    },
  };
}
