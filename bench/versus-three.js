// Our sphere shader with the terms of three.js's MeshStandardMaterial (GGX, height-correlated Smith,
// Schlick with F0 = 0.04, Lambert, one punctual light) against MeshStandardMaterial itself: same mesh,
// same resolution, same light; each frame drained with a 1-pixel readPixels, the median kept.
import * as THREE from 'three';
import { buildShader } from '../src/core/gpu/shader-builder.js';
import { termDefines } from '../src/math/catalogue/index.js';

const MESH_STANDARD_TERMS = termDefines({ F: 'schlick', D: 'ggx', V: 'smithGGXCorrelated', diffuse: 'lambert' });

export function compareWithMeshStandard({ size = 512, frames = 9 } = {}) {
  const canvas = document.createElement('canvas');
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: false });
  renderer.setPixelRatio(1);
  renderer.setSize(size, size, false);
  const gl = renderer.getContext();
  const geometry = new THREE.SphereGeometry(1, 128, 64);
  const camera = new THREE.PerspectiveCamera(30, 1, 0.1, 10);
  camera.position.z = 3.9; // the sphere fills most of the frame
  const lightDir = new THREE.Vector3(0.4, 0.5, 0.77).normalize(); // view space = world space here
  const alpha = 0.25;

  const ours = buildShader('brdf-sphere.frag.glsl', {
    vertex: 'surface.vert.glsl',
    defines: MESH_STANDARD_TERMS,
    uniforms: {
      uLightDir: { value: lightDir },
      uLightIntensity: { value: 1 },
      uExposure: { value: 1 },
      uAlphaPair: { value: new THREE.Vector2(alpha, alpha) },
      uF0: { value: 0.04 },
      uDiffuse: { value: 0.5 },
      uSigma: { value: 0 },
    },
  });
  // three's roughness r gives alpha = r²; F0 = 0.04 for metalness 0
  const theirs = new THREE.MeshStandardMaterial({
    color: new THREE.Color(0.5, 0.5, 0.5),
    roughness: Math.sqrt(alpha),
    metalness: 0,
  });
  const mesh = new THREE.Mesh(geometry);
  const light = new THREE.DirectionalLight(0xffffff, 1);
  light.position.copy(lightDir);
  const scene = new THREE.Scene().add(mesh, light);
  const pixel = new Uint8Array(4);

  const time = (material) => {
    mesh.material = material;
    const times = [];
    for (let i = 0; i < frames + 2; i++) {
      const t0 = performance.now();
      renderer.render(scene, camera);
      gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
      if (i >= 2) times.push(performance.now() - t0);
    }
    times.sort((a, b) => a - b);
    return times[Math.floor(times.length / 2)];
  };
  // interleave the two so that any drift of the machine falls on both alike
  const oursMs = [];
  const threeMs = [];
  for (let round = 0; round < 3; round++) {
    oursMs.push(time(ours));
    threeMs.push(time(theirs));
  }
  const median = (xs) => xs.sort((a, b) => a - b)[1];
  const result = { size, frames, oursMsPerFrame: median(oursMs), threeMsPerFrame: median(threeMs) };
  result.ratio = result.oursMsPerFrame / result.threeMsPerFrame;
  [ours, theirs, geometry].forEach((x) => x.dispose());
  renderer.dispose();
  return result;
}
