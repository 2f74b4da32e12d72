// Sums every texel of a float render target on the GPU (4x4 blocks per pass, log4 passes) and reads back
// one texel: a whole image's statistics for the price of a 1x1 readPixels.
import * as THREE from 'three';
import { buildShader } from './shader-builder.js';
import { createFullscreenPass } from './fullscreen-pass.js';

export function floatTarget(width, height, depthBuffer = false) {
  return new THREE.WebGLRenderTarget(width, height, {
    type: THREE.FloatType,
    format: THREE.RGBAFormat,
    minFilter: THREE.NearestFilter,
    magFilter: THREE.NearestFilter,
    depthBuffer,
    generateMipmaps: false,
  });
}

export function createGpuSum(renderer) {
  const material = buildShader('sum4x4.frag.glsl', {
    uniforms: { uSrc: { value: null }, uSrcSize: { value: new THREE.Vector2() } },
    depthTest: false,
    depthWrite: false,
  });
  const pass = createFullscreenPass();
  const targets = new Map();
  const targetOf = (w, h) => {
    const key = `${w}x${h}`;
    if (!targets.has(key)) targets.set(key, floatTarget(w, h));
    return targets.get(key);
  };
  const out = new Float32Array(4);

  return {
    /** Sum of all texels of `source` (a float WebGLRenderTarget) as [r, g, b, a]. */
    sum(source) {
      let src = source;
      let [w, h] = [source.width, source.height];
      while (w > 1 || h > 1) {
        const [tw, th] = [Math.ceil(w / 4), Math.ceil(h / 4)];
        const dst = targetOf(tw, th);
        material.uniforms.uSrc.value = src.texture;
        material.uniforms.uSrcSize.value.set(w, h);
        pass.render(renderer, material, dst);
        [src, w, h] = [dst, tw, th];
      }
      renderer.readRenderTargetPixels(src, 0, 0, 1, 1, out);
      return Array.from(out);
    },
    dispose() {
      targets.forEach((t) => t.dispose());
      material.dispose();
      pass.dispose();
    },
  };
}
