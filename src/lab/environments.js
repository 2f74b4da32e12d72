// The environments the lab offers and the ones the app makes for itself (a sky with a sun, a white furnace); the
// ones a user brings are read by environment-files.js. Pixels are linear radiance, RGBA float32, rows from the
// bottom (v = 0) up, in the equirectangular layout of src/math/lighting.js. Pure: no three.js.
import { equirectDirection } from '../math/lighting.js';

export const ENVIRONMENTS = {
  studio: 'Studio (three.js RoomEnvironment)',
  sky: 'Sky with an enlarged sun (2°, the real one 0.27°)',
  furnace: 'White furnace (radiance 1)',
  file: 'Your file (drop .hdr / .exr)',
};

/**
 * The sky's sun: a disc of angular radius 2°, 35° up. The real sun's is 0.27° (7.5× smaller): enlarged so that the
 * 256 × 128 map (1.4° texels) resolves it and the reference's samples find it.
 */
export const SUN = {
  dir: unit([-0.45, Math.sin((35 * Math.PI) / 180), 0.65]),
  sin: Math.sin((2 * Math.PI) / 180),
  radiance: [900, 820, 700],
};

function unit(d) {
  const n = Math.hypot(...d);
  return d.map((x) => x / n);
}

/** Radiance of the sky towards d: a blue gradient above a darker ground, plus the sun's disc if asked. */
export function skyRadiance(d, withSun = true) {
  const y = d[1];
  let c;
  if (y >= 0) {
    const t = Math.sqrt(y);
    c = [0.55 + (0.18 - 0.55) * t, 0.7 + (0.36 - 0.7) * t, 0.95 + (0.8 - 0.95) * t];
  } else {
    const t = Math.min(-y * 4, 1);
    c = [0.3 - 0.14 * t, 0.27 - 0.12 * t, 0.22 - 0.1 * t];
  }
  const cosSun = d[0] * SUN.dir[0] + d[1] * SUN.dir[1] + d[2] * SUN.dir[2];
  if (withSun && cosSun >= Math.sqrt(1 - SUN.sin * SUN.sin)) return SUN.radiance.slice();
  return c;
}

export function skyPixels(width, height, withSun = true) {
  const data = new Float32Array(width * height * 4);
  for (let j = 0; j < height; j++) {
    for (let i = 0; i < width; i++) {
      const c = skyRadiance(equirectDirection((i + 0.5) / width, (j + 0.5) / height), withSun);
      data.set([...c, 1], (j * width + i) * 4);
    }
  }
  return { data, width, height };
}

export const FURNACE = { data: new Float32Array(4 * 2 * 4).fill(1), width: 4, height: 2 };
