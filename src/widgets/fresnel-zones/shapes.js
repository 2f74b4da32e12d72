// The shapes the 3-D Fresnel views show (named in schema.js), each scaled to fit the unit sphere and centred.
import * as THREE from 'three';
import { TeapotGeometry } from 'three/addons/geometries/TeapotGeometry.js';

const make = {
  sphere: () => new THREE.SphereGeometry(1, 192, 96),
  torusknot: () => new THREE.TorusKnotGeometry(0.62, 0.22, 320, 40),
  teapot: () => new TeapotGeometry(1, 16),
};

// The cameras stay on the +z axis and the shape never turns, so the sphere's far half (z < 0) is only ever culled
// as back faces: it is made as its near half alone, the same vertices and triangles, at half the vertex work.
const nearHalf = { sphere: () => new THREE.SphereGeometry(1, 96, 96, 0, Math.PI) };

export function createShapeGeometry(name) {
  const whole = make[name]();
  whole.computeBoundingSphere();
  const { center, radius } = whole.boundingSphere; // the whole shape's fit, also for its near half
  const g = nearHalf[name]?.() ?? whole;
  if (g !== whole) whole.dispose();
  g.translate(-center.x, -center.y, -center.z);
  g.scale(1 / radius, 1 / radius, 1 / radius);
  g.computeBoundingSphere();
  return g;
}
