// surfaces' spheres: metal of increasing roughness reflecting a room (three.js's standard material and
// RoomEnvironment, prefiltered once per context), each its own draw in a quarter of the canvas.
import * as THREE from 'three';
import { RoomEnvironment } from 'three/addons/environments/RoomEnvironment.js';
import { createViewport } from '../../core/framework/viewport.js';
import { drawSideBySide } from '../../core/ui/side-by-side.js';

const SPHERE_ROUGHNESS = [0.05, 0.2, 0.4, 0.7];

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
      drawSideBySide(renderer, materials.length, (i) => {
        mesh.material = materials[i];
        renderer.render(scene, camera);
      });
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
