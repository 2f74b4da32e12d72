// surfaces' spheres: metal of increasing roughness reflecting a room (three.js's standard material and
// RoomEnvironment, prefiltered once per context), each its own draw in a quarter of the canvas.
import * as THREE from 'three';
import { RoomEnvironment } from 'three/addons/environments/RoomEnvironment.js';
import { createViewport } from '../../core/gpu/viewport.js';

const SPHERE_ROUGHNESS = [0.05, 0.2, 0.4, 0.7];

/** Draws each material on the sphere in its own square, side by side. */
function drawSideBySide(renderer, { scene, camera, mesh, materials, size }) {
  const w = size.x / materials.length;
  renderer.setScissorTest(true);
  materials.forEach((m, i) => {
    mesh.material = m;
    const [x0, x1] = [Math.round(i * w), Math.round((i + 1) * w)];
    const side = Math.min(x1 - x0, size.y);
    renderer.setViewport(x0 + (x1 - x0 - side) / 2, (size.y - side) / 2, side, side);
    renderer.setScissor(x0, 0, x1 - x0, size.y);
    renderer.render(scene, camera);
  });
  renderer.setScissorTest(false);
}

const roughnessLabels = () => {
  const labels = Object.assign(document.createElement('div'), { className: 'sphere-labels' });
  labels.append(
    ...SPHERE_ROUGHNESS.map((r) => Object.assign(document.createElement('span'), { textContent: `roughness ${r}` })),
  );
  return labels;
};

export function createSpheresView(container) {
  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(24, 1, 0.1, 20);
  camera.position.set(0, 0, 5.2);
  const geometry = new THREE.SphereGeometry(1, 96, 48);
  const materials = SPHERE_ROUGHNESS.map(
    (r) => new THREE.MeshStandardMaterial({ color: '#b8bcc2', metalness: 1, roughness: r }),
  );
  const mesh = new THREE.Mesh(geometry);
  scene.add(mesh);
  let pmrem = null;
  const drawSize = new THREE.Vector2();
  const viewport = createViewport(container, {
    label: `Four metal spheres reflecting a room, roughness ${SPHERE_ROUGHNESS.join(', ')}`,
    onContextLost() {
      pmrem?.dispose(); // its texels were on the lost context: prefilter again on the next frame
      pmrem = null;
    },
    draw(renderer) {
      if (!pmrem) {
        const generator = new THREE.PMREMGenerator(renderer);
        pmrem = generator.fromScene(new RoomEnvironment(), 0.04);
        generator.dispose();
        scene.environment = pmrem.texture;
        scene.background = new THREE.Color('#2a2d33');
      }
      drawSideBySide(renderer, { scene, camera, mesh, materials, size: renderer.getSize(drawSize) });
    },
  });
  if (viewport) {
    viewport.holder.classList.add('sphere-grid');
    viewport.holder.style.aspectRatio = `${materials.length} / 1`;
    viewport.holder.append(roughnessLabels());
  }
  return {
    dispose() {
      materials.forEach((m) => m.dispose());
      geometry.dispose();
      pmrem?.dispose();
      viewport?.dispose();
    },
  };
}
