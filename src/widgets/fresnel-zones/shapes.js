// The shapes the 3-D Fresnel views show (named in schema.js), each scaled to fit the unit sphere and centred.
import * as THREE from 'three';
import { TeapotGeometry } from 'three/addons/geometries/TeapotGeometry.js';

const make = {
  sphere: () => new THREE.SphereGeometry(1, 192, 96),
  torusknot: () => new THREE.TorusKnotGeometry(0.62, 0.22, 320, 40),
  teapot: () => new TeapotGeometry(1, 16),
};

export function createShapeGeometry(name) {
  const g = make[name]();
  g.computeBoundingSphere();
  const { center, radius } = g.boundingSphere;
  g.translate(-center.x, -center.y, -center.z);
  g.scale(1 / radius, 1 / radius, 1 / radius);
  g.computeBoundingSphere();
  return g;
}
