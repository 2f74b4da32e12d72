// three.js's own answer for the environment, for comparison in the material lab: a MeshPhysicalMaterial sphere
// lit by the map's PMREM, added onto what the lab's program drew (the other lights).
import * as THREE from 'three';
import { EXTENT } from './lab-uniforms.js';

export function createPmremOverlay() {
  const material = new THREE.MeshPhysicalMaterial({
    metalness: 0,
    ior: 1.5,
    specularIntensity: 1,
    blending: THREE.AdditiveBlending,
    depthTest: false,
    depthWrite: false,
  });
  const sphere = new THREE.Mesh(new THREE.SphereGeometry(1, 128, 64), material);
  const scene = new THREE.Scene().add(sphere);
  const camera = new THREE.OrthographicCamera(-EXTENT, EXTENT, EXTENT, -EXTENT, 0.1, 10);
  camera.position.z = 5;

  return {
    /** Adds the sphere of the lab scene `lab` (its material, layers and environment) into `target`. */
    render(renderer, lab, target) {
      const { f0, diffuse, alpha } = lab.material;
      const layers = lab.terms.layers;
      material.envMap = lab.maps.pmrem();
      material.envMapIntensity = lab.lights.env.intensity;
      material.color.setRGB(...(layers === 'specular' ? [0, 0, 0] : diffuse), THREE.LinearSRGBColorSpace);
      // F0 = 0.04 · specularColor at ior 1.5
      material.specularColor.setRGB(...f0.map((x) => x / 0.04), THREE.LinearSRGBColorSpace);
      material.specularIntensity = layers === 'diffuse' ? 0 : 1;
      material.roughness = Math.sqrt(alpha);
      const previous = renderer.getRenderTarget();
      renderer.setRenderTarget(target);
      renderer.autoClear = false;
      renderer.render(scene, camera);
      renderer.autoClear = true;
      renderer.setRenderTarget(previous);
    },
    dispose() {
      material.dispose();
      sphere.geometry.dispose();
    },
  };
}
