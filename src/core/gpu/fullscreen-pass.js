// One full-screen pass: a quad that covers the target, drawn with whichever material is set, for the passes that
// shade every pixel of an image (the lab's sphere, prefiltering, the GPU sum, the parity grid, the media tracer).
import * as THREE from 'three';

/**
 * `render(renderer, material, target = null, layer = 0)` draws `material` over the whole `target` (the canvas
 * when null; of an array target, its `layer`) and puts the renderer's previous target back; `dispose()` frees the
 * quad (materials stay their owner's).
 */
export function createFullscreenPass() {
  const quad = new THREE.Mesh(new THREE.PlaneGeometry(2, 2));
  quad.frustumCulled = false; // the vertex shader places it, not the camera
  const scene = new THREE.Scene().add(quad);
  const camera = new THREE.Camera();
  return {
    render(renderer, material, target = null, layer = 0) {
      const previous = renderer.getRenderTarget();
      quad.material = material;
      renderer.setRenderTarget(target, layer);
      renderer.render(scene, camera);
      renderer.setRenderTarget(previous);
    },
    dispose() {
      quad.geometry.dispose();
    },
  };
}
