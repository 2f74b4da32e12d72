// The albedo-loss table (src/math/albedo-table.js) as a float texture for multiple-scattering.glsl, which reads
// it with texelFetch (no filtering: the bilinear rule is the shader's, the same as the JS lookup's). The table
// is built once per page (~0.5 s), when first asked for; each caller owns and disposes its texture.
import * as THREE from 'three';
import { buildAlbedoTableGGX } from '../../math/albedo-table.js';

let table = null;
export const albedoTableOnce = () => (table ??= buildAlbedoTableGGX());

export function createAlbedoTableTexture() {
  const { size, data } = albedoTableOnce();
  const texture = new THREE.DataTexture(data, size, size, THREE.RGBAFormat, THREE.FloatType);
  texture.needsUpdate = true;
  return texture;
}
