// Multisampling once the changes pause: on software WebGL a multisampled frame of a large view costs about twice a
// plain one. A frame that follows another within `quietMs` (a drag) is drawn plainly on the canvas (its context
// made without multisampling), and once the changes pause the same state is drawn once more, multisampled into a
// render target, resolved and copied to the canvas. A frame after a pause (a lone change: a click) goes straight
// to the multisampled one.
//
// In the render target three.js leaves its own colours (a scene's background, fog, its built-in materials) in the
// working colour space, where on the canvas it encodes them for the display: a view that opts in writes display
// values itself and gives such colours already encoded when `renderer.getRenderTarget()` is set.
import * as THREE from 'three';
import { createSettledTask } from './render-loop.js';
import { createFullscreenPass } from './fullscreen-pass.js';
import { SHADER_CHUNKS } from './shader-chunks.js';

const SAMPLES = 4; // what a WebGL context's own multisampling gives on this hardware and SwiftShader alike

/** Copies an image texel for pixel (no filtering, no colour conversion: the bytes as they are). */
function createCopyMaterial() {
  return new THREE.ShaderMaterial({
    glslVersion: THREE.GLSL3,
    uniforms: { uImage: { value: null } },
    vertexShader: SHADER_CHUNKS['fullscreen.vert.glsl'],
    fragmentShader:
      'uniform sampler2D uImage;\nout vec4 fragColor;\n' +
      'void main() { fragColor = texelFetch(uImage, ivec2(gl_FragCoord.xy), 0); }\n',
    depthTest: false,
    depthWrite: false,
  });
}

/**
 * `draw(renderer)` draws a frame into the renderer's current target (the canvas, or the multisampled target);
 * `invalidate()` asks the render loop for a frame. Returns `frame()`, the render loop's draw, which picks plain or
 * multisampled; `drawSettled()`, the multisampled frame now (for a still read from the canvas); `drop()`, after a
 * context loss; `dispose()`.
 */
export function createSettledAntialias(renderer, draw, invalidate, { quietMs = 130 } = {}) {
  const copy = createCopyMaterial();
  const pass = createFullscreenPass();
  const size = new THREE.Vector2();
  let target = null;
  let lastFrameAt = -Infinity;
  let due = false; // the pause came: the next frame is the multisampled one
  const settle = createSettledTask(
    () => {
      due = true;
      invalidate();
    },
    { quietMs, maxWaitMs: Infinity },
  );

  const drawSettled = () => {
    renderer.getDrawingBufferSize(size);
    if (!target) target = new THREE.WebGLRenderTarget(size.x, size.y, { samples: SAMPLES });
    else if (target.width !== size.x || target.height !== size.y) target.setSize(size.x, size.y);
    const previous = renderer.getRenderTarget();
    renderer.setRenderTarget(target);
    draw(renderer);
    renderer.setRenderTarget(previous); // each render() into the target ended by resolving it into target.texture
    copy.uniforms.uImage.value = target.texture;
    pass.render(renderer, copy);
  };

  return {
    frame() {
      const now = performance.now();
      if (due || now - lastFrameAt >= quietMs) {
        due = false;
        settle.cancel();
        drawSettled();
      } else {
        draw(renderer);
        settle.schedule();
      }
      lastFrameAt = now;
    },
    drawSettled,
    drop() {
      target?.dispose();
      target = null;
    },
    dispose() {
      settle.cancel();
      target?.dispose();
      copy.dispose();
      pass.dispose();
    },
  };
}
