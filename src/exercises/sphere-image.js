// An orthographically viewed unit sphere (view along +z) under a directional light, shaded by the JS math
// on an N×N grid: the picture a grader compares, and the one the exercises page draws next to the widget.
import { punctualRadiance } from '../math/brdf.js';
import { linearToSrgb } from '../math/color.js';
import { DEG } from '../math/angles.js';
import { termEntry } from '../math/catalogue/index.js';
import { microfacetInput, termAt } from '../math/catalogue/microfacet-input.js';
import { inTangentFrame, tangentFrameAlong } from '../math/tangent-frame.js';

/** The light lightThetaDeg from the view, in the x–z plane. */
const lightAt = (lightThetaDeg) => [Math.sin(lightThetaDeg * DEG), 0, Math.cos(lightThetaDeg * DEG)];

/** The grid over the disk, row-major from the top-left: radianceAt(n) at each pixel's normal, NaN off the disk. */
function overDisk(size, radianceAt) {
  const out = new Float64Array(size * size);
  for (let row = 0; row < size; row++) {
    for (let col = 0; col < size; col++) {
      const x = ((col + 0.5) / size) * 2 - 1;
      const y = 1 - ((row + 0.5) / size) * 2;
      const r2 = x * x + y * y;
      out[row * size + col] = r2 >= 1 ? NaN : radianceAt([x, y, Math.sqrt(1 - r2)]);
    }
  }
  return out;
}

/**
 * Radiance over the grid, row-major from the top-left; pixels off the disk are NaN.
 * f(cosines) is the BRDF from { nl, nv, nh, lh } (h = normalize(l + v), view v = (0, 0, 1)); the light,
 * of intensity cLight, lies lightThetaDeg from the view in the x–z plane.
 */
export function sphereRadiance(size, lightThetaDeg, f, cLight = 1) {
  const l = lightAt(lightThetaDeg);
  const hl = Math.hypot(l[0], l[1], l[2] + 1);
  const h = hl > 1e-12 ? [l[0] / hl, 0, (l[2] + 1) / hl] : [0, 0, 1];
  const lh = l[0] * h[0] + l[2] * h[2];
  return overDisk(size, (n) => {
    const nl = n[0] * l[0] + n[2] * l[2];
    const a = { nl, nv: n[2], nh: n[0] * h[0] + n[1] * h[1] + n[2] * h[2], lh };
    return nl > 0 ? punctualRadiance(f(a), nl, cLight) : 0;
  });
}

/** What a screen shows for radiance L at an exposure: clamped to [0, 1], sRGB-encoded. */
export const displayValue = (L, exposure = 1) => linearToSrgb(Math.min(Math.max(L * exposure, 0), 1));

/** RMS difference of the display values of two images over the pixels on the disk. */
export function displayRms(a, b, exposure = 1) {
  let sum = 0;
  let count = 0;
  for (let i = 0; i < a.length; i++) {
    if (Number.isNaN(a[i])) continue;
    const d = displayValue(a[i], exposure) - displayValue(b[i], exposure);
    sum += d * d;
    count++;
  }
  return Math.sqrt(sum / count);
}

/** Brightest radiance on the disk. */
export const peakOf = (img) => img.reduce((m, x) => (x > m ? x : m), 0);

/** Share of the disk's pixels at or above half the image's peak: the highlight's size. */
export function highlightArea(img) {
  const half = peakOf(img) / 2;
  let on = 0;
  let disk = 0;
  for (const x of img) {
    if (Number.isNaN(x)) continue;
    disk++;
    if (x >= half) on++;
  }
  return on / disk;
}

/**
 * The highlight of an anisotropic NDF (catalogue key `ndf`, e.g. 'ggxAniso') at the pair [αx, αy] on the sphere of
 * sphereRadiance, F = 1 and V = 1 so only D shows (radiance π·D/4·(n·l)), the tangent running left to right across
 * the picture as on the NDF explorer's spheres (tangentFrameAlong the view's x axis).
 */
export function anisotropicSphere(size, lightThetaDeg, pair, ndf = 'ggxAniso') {
  const entry = termEntry('ndf', ndf);
  const l = lightAt(lightThetaDeg);
  return overDisk(size, (n) => {
    const frame = tangentFrameAlong(n, [1, 0, 0]);
    const m = microfacetInput(inTangentFrame(l, n, frame), inTangentFrame([0, 0, 1], n, frame), pair);
    return m.nl > 0 && m.h ? punctualRadiance(termAt(entry, m, {}) / 4, m.nl, 1) : 0;
  });
}

/**
 * How far the highlight (pixels at or above half the peak) reaches left to right and bottom to top: the RMS
 * distance of its pixels from their centroid along each axis, in pixels, as [along x, along y].
 */
export function highlightSpread(img) {
  const size = Math.round(Math.sqrt(img.length));
  const half = peakOf(img) / 2;
  const on = [];
  img.forEach((L, i) => L >= half && on.push([i % size, Math.floor(i / size)]));
  return [0, 1].map((axis) => {
    const mean = on.reduce((s, p) => s + p[axis], 0) / on.length;
    return Math.sqrt(on.reduce((s, p) => s + (p[axis] - mean) ** 2, 0) / on.length);
  });
}
