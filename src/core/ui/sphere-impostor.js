// The unit sphere as one quad under an orthographic camera that frames it in a square cell: its fragment program
// (with sphere-impostor.glsl) ray-traces the sphere under each pixel and blends its silhouette over the background
// by the part of the pixel it covers, so its view draws without multisampling (createViewport's antialias: false).
import * as THREE from 'three';

/** The camera's half extent in the sphere's units: the unit sphere fills 1/1.08 of its cell. */
export const HALF_SIZE = 1.08;

/**
 * A scene that clears a cell to `background` and covers it with the quad, whose material a draw sets; and the
 * background as the uBackground its programs read (linear RGB).
 * @param {THREE.ColorRepresentation} background
 */
export function createImpostorView(background) {
  const geometry = new THREE.PlaneGeometry(2 * HALF_SIZE, 2 * HALF_SIZE);
  const mesh = new THREE.Mesh(geometry);
  const scene = new THREE.Scene().add(mesh);
  scene.background = new THREE.Color(background);
  const camera = new THREE.OrthographicCamera(-HALF_SIZE, HALF_SIZE, HALF_SIZE, -HALF_SIZE, 0.1, 10);
  camera.position.z = 5;
  const { r, g, b } = scene.background; // three.js keeps colours in linear sRGB
  return { mesh, scene, camera, background: [r, g, b], dispose: () => geometry.dispose() };
}
