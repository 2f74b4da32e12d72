// Square cells side by side across one canvas, each its own draw: the spheres of the sphere grid, of the
// measured-BRDF widget and of surfaces.
import * as THREE from 'three';

const size = new THREE.Vector2();

/**
 * Draws `count` cells across the renderer's canvas: cell i is scissored to its column (whole pixels: no seams
 * between cells) with its viewport the largest square centred in it, then `drawCell(i)` draws it.
 * @param {THREE.WebGLRenderer} renderer
 * @param {number} count
 * @param {(i: number) => void} drawCell
 */
export function drawSideBySide(renderer, count, drawCell) {
  renderer.getSize(size);
  const w = size.x / Math.max(count, 1);
  renderer.setScissorTest(true);
  for (let i = 0; i < count; i++) {
    const [x0, x1] = [Math.round(i * w), Math.round((i + 1) * w)];
    const side = Math.min(x1 - x0, size.y);
    renderer.setViewport(x0 + (x1 - x0 - side) / 2, (size.y - side) / 2, side, side);
    renderer.setScissor(x0, 0, x1 - x0, size.y);
    drawCell(i);
  }
  renderer.setScissorTest(false);
}
