// surfaces' spheres: metal of increasing roughness reflecting a room (three.js's standard material and
// RoomEnvironment, prefiltered once per context), each its own draw in a quarter of the canvas.
// The prefilter is seconds of work on a software GPU (SwiftShader: 3 to 5 s idle, 25 s and more on a loaded
// machine), and a view's first frame comes when it is created, in sight or not: a view out of sight then (further
// down a chapter, on the wall of twenty widgets) leaves that frame, and the prefilter, until it first comes into
// sight. (A still drawn for print or download, once the view's place is known, prefilters at once.)
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
  let sight = null; // whether the view is in sight, once its observer has said; null until then
  let deferred = false; // the first frame was left while out of sight
  const sightNow = (el) => {
    const r = el.getBoundingClientRect();
    return r.bottom > 0 && r.right > 0 && r.top < innerHeight && r.left < innerWidth;
  };
  const viewport = createViewport(container, {
    label: `Four metal spheres reflecting a room, roughness ${SPHERE_ROUGHNESS.join(', ')}`,
    onContextLost() {
      pmrem?.dispose(); // its texels were on the lost context: prefilter again on the next frame
      pmrem = null;
    },
    draw(renderer) {
      if (!pmrem && sight === null && !sightNow(viewport.holder)) {
        deferred = true;
        return;
      }
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
  const watcher = new IntersectionObserver((entries) => {
    sight = entries[entries.length - 1].isIntersecting;
    if (sight && deferred) {
      deferred = false;
      viewport.invalidate();
    }
  });
  if (viewport) {
    watcher.observe(viewport.holder);
    viewport.holder.classList.add('sphere-grid');
    viewport.holder.style.aspectRatio = `${materials.length} / 1`;
    viewport.holder.append(roughnessLabels());
  }
  return {
    dispose() {
      materials.forEach((m) => m.dispose());
      geometry.dispose();
      pmrem?.dispose();
      watcher.disconnect();
      viewport?.dispose();
    },
  };
}
