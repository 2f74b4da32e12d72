// The lighting-models widget's model: the sky with its sun, and the illumination models of the talk's ladder, each
// with its lights and the map its sky is; the terms and methods the lab renders them with.
import { SUN, skyPixels } from '../../lab/environments.js';
import { sphereLightCLight } from '../../math/lighting.js';
import { FAILS } from './words.js';

const sunCLight = SUN.radiance.map((L) => sphereLightCLight(L, SUN.sin));

/** The mean radiance of the sky, sun included, over the whole sphere: the one number ambient light keeps. */
function skyMean() {
  const { data, width, height } = skyPixels(256, 128, true);
  const sum = [0, 0, 0];
  let weight = 0;
  for (let j = 0; j < height; j++) {
    const w = Math.cos(((j + 0.5) / height - 0.5) * Math.PI);
    for (let i = 0; i < width; i++) for (let c = 0; c < 3; c++) sum[c] += data[(j * width + i) * 4 + c] * w;
    weight += w * width;
  }
  return sum.map((x) => x / weight);
}

export const sky = { intensity: 1 };
export const sunSphere = { dir: SUN.dir, sin: SUN.sin, radiance: SUN.radiance };
// each model: its lights, which map its sky is (with the sun painted in, or without), and where it fails
export const MODELS = [
  {
    key: 'ibl',
    name: 'Image-based',
    lights: { env: sky },
    map: 'sky',
    fails: FAILS.ibl,
  },
  {
    key: 'area',
    name: 'Area light + IBL sky',
    lights: { env: sky, sphere: sunSphere },
    map: 'sky-no-sun',
    fails: FAILS.area,
  },
  {
    key: 'punctual',
    name: 'Punctual light + IBL sky',
    lights: { env: sky, punctual: { dir: SUN.dir, cLight: sunCLight } },
    map: 'sky-no-sun',
    fails: FAILS.punctual,
  },
  {
    key: 'ambient',
    name: 'Ambient only',
    lights: { ambient: skyMean() },
    map: 'furnace',
    fails: FAILS.ambient,
  },
];

export const TERMS = { F: 'schlick', D: 'ggx', V: 'smithGGXCorrelated', diffuse: 'lambert', layers: 'both' };
export const METHODS = { env: 'split-sum', area: 'representative', samples: 1 };
