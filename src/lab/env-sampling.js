// Tables for drawing directions from an equirectangular environment in proportion to its brightness:
// texel (i, j) is chosen with probability lum·cos(elevation) / Σ (its share of the sphere's light), and a
// point uniformly inside it. The reference uses them so small bright lights (the studio's lamps, the sun)
// are found by a few samples instead of by luck.
const luminance = (r, g, b) => 0.2126 * r + 0.7152 * g + 0.0722 * b;

/**
 * The map is read with bilinear filtering, so a texel next to a lamp shows some of the lamp: each texel is
 * weighted by the brightest of its 3 × 3 neighbours, so no direction is much brighter than its density allows.
 * rgba: width × height texels, rows bottom up (v = (j + 0.5)/height). Returns Float32Arrays:
 * marginal[j] = P(row ≤ j); conditional[j·width + i] = P(column ≤ i | row j); pdf[j·width + i] = P(texel)·W·H / 2π²,
 * which divided by cos(elevation) of a direction in the texel is the density per steradian there (uniform in
 * (u, v) inside a texel is not uniform in solid angle: dω = 2π² cos(el) du dv).
 */
export function buildEnvSampling(rgba, width, height) {
  const lum = new Float64Array(width * height);
  for (let t = 0; t < width * height; t++)
    lum[t] = Math.max(luminance(rgba[4 * t], rgba[4 * t + 1], rgba[4 * t + 2]), 0);
  const brightestAround = (i, j) => {
    let m = 0;
    for (let dj = -1; dj <= 1; dj++) {
      const jj = Math.min(Math.max(j + dj, 0), height - 1);
      for (let di = -1; di <= 1; di++) m = Math.max(m, lum[jj * width + ((i + di + width) % width)]);
    }
    return m;
  };
  const weight = new Float64Array(width * height);
  const rowSum = new Float64Array(height);
  let total = 0;
  for (let j = 0; j < height; j++) {
    const cosEl = Math.cos(((j + 0.5) / height - 0.5) * Math.PI);
    for (let i = 0; i < width; i++) {
      const w = brightestAround(i, j) * cosEl;
      weight[j * width + i] = w;
      rowSum[j] += w;
    }
    total += rowSum[j];
  }
  const marginal = new Float32Array(height);
  const conditional = new Float32Array(width * height);
  const pdf = new Float32Array(width * height);
  if (!(total > 0)) return null; // a black environment: nothing to sample
  let acc = 0;
  for (let j = 0; j < height; j++) {
    acc += rowSum[j];
    marginal[j] = acc / total;
    let row = 0;
    for (let i = 0; i < width; i++) {
      row += weight[j * width + i];
      conditional[j * width + i] = rowSum[j] > 0 ? row / rowSum[j] : (i + 1) / width;
      pdf[j * width + i] = (weight[j * width + i] * width * height) / (2 * Math.PI * Math.PI * total);
    }
  }
  marginal[height - 1] = 1;
  return { marginal, conditional, pdf, width, height };
}
