// The irradiance map of an equirectangular environment, summed texel by texel rather than sampled: each output
// texel, a normal n, holds (1/π) Σ L(t) max(n·d_t, 0) Ω_t, the radiance of a white Lambertian surface facing n.
// Exact for the map as it is (no noise from its small bright lamps, no bias from mip-mapping near the poles,
// where equirectangular texels shrink), and cheap at the sizes used: 32 × 16 normals × the map's texels.
import { equirectDirection } from '../math/lighting.js';

export function irradianceMap(rgba, width, height, outWidth, outHeight) {
  // each source texel as a direction and its radiance times its exact solid angle
  const n = width * height;
  const dirs = new Float64Array(3 * n);
  const power = new Float64Array(3 * n);
  for (let j = 0; j < height; j++) {
    const solidAngle =
      ((2 * Math.PI) / width) * (Math.sin(((j + 1) / height - 0.5) * Math.PI) - Math.sin((j / height - 0.5) * Math.PI));
    for (let i = 0; i < width; i++) {
      const t = j * width + i;
      dirs.set(equirectDirection((i + 0.5) / width, (j + 0.5) / height), 3 * t);
      for (let c = 0; c < 3; c++) power[3 * t + c] = rgba[4 * t + c] * solidAngle;
    }
  }
  const out = new Float32Array(outWidth * outHeight * 4);
  for (let q = 0; q < outHeight; q++) {
    for (let p = 0; p < outWidth; p++) {
      const [nx, ny, nz] = equirectDirection((p + 0.5) / outWidth, (q + 0.5) / outHeight);
      let r = 0;
      let g = 0;
      let b = 0;
      for (let t = 0; t < n; t++) {
        const c = nx * dirs[3 * t] + ny * dirs[3 * t + 1] + nz * dirs[3 * t + 2];
        if (c <= 0) continue;
        r += c * power[3 * t];
        g += c * power[3 * t + 1];
        b += c * power[3 * t + 2];
      }
      out.set([r / Math.PI, g / Math.PI, b / Math.PI, 1], (q * outWidth + p) * 4);
    }
  }
  return out;
}
