// The sphere grid's impostor spheres (sphere-impostor.glsl), read back from the canvas in Chromium: a Lambert sphere
// against its closed form L = c_diff (n·l) at the exact normal under every pixel centre, and its silhouette against
// the box-filtered picture (each rim pixel's light integrated over the pixel, the exact circle parting sphere from
// background): an edge antialiased without multisampling, neither stepped nor haloed.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { launchBrowser, open, shot, untilSteady, widget, withPixels } from './helpers.js';
import { lightDirFromAngles } from '../../src/math/angles.js';
import { linearToSrgb, srgbToLinear } from '../../src/math/color.js';

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

const HALF_SIZE = 1.08; // the camera's half extent in the sphere's units (sphere-impostor.js)
const CDIFF = 0.8;
const LIGHT = lightDirFromAngles(60, 30);
const BACKGROUND = srgbToLinear(0x16 / 255); // the red of the grid's background #16181d, as light

/** Lambert's radiance at a point (x, y) of the unit sphere seen from +z: c_diff max(n·l, 0), c_light = 1. */
const lambert = (x, y) => {
  const n = [x, y, Math.sqrt(Math.max(1 - x * x - y * y, 0))];
  return CDIFF * Math.max(n[0] * LIGHT[0] + n[1] * LIGHT[1] + n[2] * LIGHT[2], 0);
};

/**
 * The part of pixel (px, py) inside the sphere's silhouette and the sphere's light over it (as a fraction of the
 * pixel): in 256 columns, each column's chord of the circle exactly, the light along it at 32 midpoints.
 */
function pixelIntegral(toSphere, px, py) {
  const [COLUMNS, ROWS] = [256, 32];
  const [top, bottom] = [toSphere(px, py)[1], toSphere(px, py + 1)[1]];
  let covered = 0;
  let light = 0;
  for (let i = 0; i < COLUMNS; i++) {
    const x = toSphere(px + (i + 0.5) / COLUMNS, py)[0];
    const half = Math.sqrt(Math.max(1 - x * x, 0));
    const [y0, y1] = [Math.max(bottom, -half), Math.min(top, half)];
    if (y1 <= y0) continue;
    const part = (y1 - y0) / (top - bottom);
    covered += part / COLUMNS;
    for (let j = 0; j < ROWS; j++)
      light += (part * Math.min(lambert(x, y0 + ((j + 0.5) / ROWS) * (y1 - y0)), 1)) / (COLUMNS * ROWS);
  }
  return { covered, light };
}

/** The red channel of the canvas's screenshot, and the geometry of its one square cell. */
async function readSphere() {
  const page = await open(
    browser,
    `embed.html?w=diffuse-explorer&diffuse=lambert&cdiff=${CDIFF}&lightTheta=60&lightPhi=30&exposure=1`,
    { width: 900, height: 900 },
  );
  await widget(page, 'diffuse-explorer');
  await page.addStyleTag({ content: '.sphere-labels, .viewport button { display: none !important; }' });
  await untilSteady(page, 'drawCalls'); // the spheres drawn, nothing more to come
  const size = await page.$eval('.sphere-grid canvas', (c) => [c.width, c.height]);
  const image = await withPixels(page, await shot(page, '.sphere-grid canvas'), (img) => ({
    width: img.width,
    height: img.height,
    red: Array.from({ length: img.width * img.height }, (_, i) => img.data[i * 4]),
  }));
  expect([image.width, image.height]).toEqual(size); // one screenshot pixel per drawn pixel
  expect(page.errors).toEqual([]);
  await page.close();
  const radius = Math.min(image.width, image.height) / 2 / HALF_SIZE; // in pixels
  /** Pixel-space (px, py) as sphere coordinates: x right, y up, the unit sphere's centre at the cell's. */
  const toSphere = (px, py) => [(px - image.width / 2) / radius, -(py - image.height / 2) / radius];
  return { ...image, radius, toSphere };
}

describe('sphere impostor: a Lambert sphere in the sphere grid', () => {
  let sphere;
  beforeAll(async () => {
    sphere = await readSphere();
  });

  it('inside the silhouette each pixel is c_diff (n·l) at the exact normal under its centre, within 1 level', () => {
    const { width, height, red, radius, toSphere } = sphere;
    let worst = { diff: 0 };
    let count = 0;
    for (let py = 0; py < height; py++)
      for (let px = 0; px < width; px++) {
        const [x, y] = toSphere(px + 0.5, py + 0.5);
        if (Math.hypot(x, y) > 1 - 1 / radius) continue; // a full pixel inside
        const expected = linearToSrgb(lambert(x, y)) * 255;
        const diff = Math.abs(red[py * width + px] - expected);
        if (diff > worst.diff) worst = { diff, px, py, got: red[py * width + px], expected };
        count++;
      }
    console.log(`Lambert sphere, radius ${radius.toFixed(1)} px: ${count} pixels, worst ${JSON.stringify(worst)}`);
    expect(count).toBeGreaterThan(0.9 * Math.PI * radius * radius);
    expect(worst.diff).toBeLessThanOrEqual(1);
  });

  it('each rim pixel is the box-filtered picture: sphere and background light integrated over the pixel', () => {
    const { width, height, red, radius, toSphere } = sphere;
    let worst = { diff: 0 };
    let halfCovered = 0;
    for (let py = 0; py < height; py++)
      for (let px = 0; px < width; px++) {
        const [cx, cy] = toSphere(px + 0.5, py + 0.5);
        if (Math.abs(Math.hypot(cx, cy) - 1) * radius > 1) continue; // within a pixel of the silhouette
        const { covered, light } = pixelIntegral(toSphere, px, py);
        // compared as light: in 8-bit levels near black a thousandth of white is several levels
        const expected = light + (1 - covered) * BACKGROUND;
        const got = srgbToLinear(red[py * width + px] / 255);
        const diff = Math.abs(got - expected);
        if (diff > worst.diff) worst = { diff, px, py, got, expected, covered };
        if (covered > 0.3 && covered < 0.7) halfCovered++;
      }
    console.log(`rim against the box filter: worst ${JSON.stringify(worst)}; ${halfCovered} about half covered`);
    expect(worst.diff).toBeLessThanOrEqual(0.01);
    expect(halfCovered).toBeGreaterThan(radius); // the edge was crossed all round
  });
});
