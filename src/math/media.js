// Light in homogeneous media: absorption by Beer-Lambert, the quantities that describe a scattering medium,
// and a random walk through a scattering slab in flatland (2-D), for the subsurface-scale chapter.
import { RGB_WAVELENGTHS_UM, nkAtWavelength } from './optical-constants.js';

/** Fraction of light left after `distance` in a medium with extinction coefficient sigma (same length units). */
export function transmittance(sigma, distance) {
  return Math.exp(-Math.max(sigma, 0) * Math.max(distance, 0));
}

/** Optical depth tau = sigma · distance: transmittance is exp(-tau). */
export const opticalDepth = (sigma, distance) => Math.max(sigma, 0) * Math.max(distance, 0);

/** Single-scattering albedo: the chance that an interaction scatters rather than absorbs. */
export function scatteringAlbedo(sigmaS, sigmaA) {
  const t = Math.max(sigmaS, 0) + Math.max(sigmaA, 0);
  return t > 0 ? Math.max(sigmaS, 0) / t : 0;
}

/** Mean free path between interactions, 1/sigma_t (Infinity in a vacuum). */
export const meanFreePath = (sigmaT) => (sigmaT > 0 ? 1 / sigmaT : Infinity);

/** Absorption coefficient (1/m) from the imaginary part k of the refractive index at wavelength um: 4 pi k / lambda. */
export const absorptionFromK = (k, um) => (4 * Math.PI * k) / (um * 1e-6);

/** Pure liquid water at 25 °C, Hale & Querry, Appl. Opt. 12, 555 (1973), via refractiveindex.info (CC0). */
export const WATER_K = {
  source: 'Hale & Querry, Appl. Opt. 12, 555 (1973)',
  rows: [
    [0.4, 1.339, 1.86e-9],
    [0.425, 1.338, 1.3e-9],
    [0.45, 1.337, 1.02e-9],
    [0.475, 1.336, 9.35e-10],
    [0.5, 1.335, 1e-9],
    [0.525, 1.334, 1.32e-9],
    [0.55, 1.333, 1.96e-9],
    [0.575, 1.333, 3.6e-9],
    [0.6, 1.332, 1.09e-8],
    [0.625, 1.332, 1.39e-8],
    [0.65, 1.331, 1.64e-8],
    [0.675, 1.331, 2.23e-8],
    [0.7, 1.331, 3.35e-8],
  ],
};

/** Water's absorption coefficients at the app's red, green and blue wavelengths, in 1/m. */
export function waterAbsorptionRgb() {
  return RGB_WAVELENGTHS_UM.map((um) => absorptionFromK(nkAtWavelength(WATER_K.rows, um)[1], um));
}

/**
 * One random walk in flatland through a slab 0 < y < thickness (light enters at y = 0, going up), with
 * exponential free paths (mean 1/sigmaT) and isotropic scattering. Absorption is tracked as a weight
 * exp(-sigmaA · path) (exact for a homogeneous medium), so one walk serves every absorption.
 * Returns { exit: 'back' | 'through' | 'lost', x (where it left), path (length inside), events, points }.
 */
export function randomWalk2D({
  sigmaS,
  thickness = Infinity,
  entryAngle = 0,
  rand,
  maxEvents = 10000,
  keepPoints = false,
}) {
  let [x, y] = [0, 0];
  let [dx, dy] = [Math.sin(entryAngle), Math.cos(entryAngle)];
  let path = 0;
  const points = keepPoints ? [[0, 0]] : null;
  for (let events = 0; events < maxEvents; events++) {
    const step = -Math.log(1 - rand()) / sigmaS;
    // where would the step leave the slab?
    const toBack = dy < 0 ? -y / dy : Infinity;
    const toFar = dy > 0 ? (thickness - y) / dy : Infinity;
    const exit = Math.min(toBack, toFar);
    if (exit <= step) {
      path += exit;
      [x, y] = [x + dx * exit, y + dy * exit];
      points?.push([x, y]);
      return { exit: toBack <= toFar ? 'back' : 'through', x, path, events, points };
    }
    path += step;
    [x, y] = [x + dx * step, y + dy * step];
    points?.push([x, y]);
    const phi = 2 * Math.PI * rand();
    [dx, dy] = [Math.cos(phi), Math.sin(phi)];
  }
  return { exit: 'lost', x, path, events: maxEvents, points };
}

/** An entry angle for light falling evenly on a 2-D surface from all directions: density cos(theta)/2. */
export const lambertianEntryAngle2D = (rand) => Math.asin(2 * rand() - 1);

/**
 * Whole milk, Jensen, Marschner, Levoy & Hanrahan, "A Practical Model for Subsurface Light Transport",
 * SIGGRAPH 2001 (Table 2): absorption and the REDUCED scattering coefficient σ′s = (1 − g) σs per RGB
 * channel, converted to 1/m. σ′s is what the similarity relation keeps when a forward-scattering medium
 * (mean cosine g) is replaced by an isotropic one that diffuses light alike; the paper gives no g, so σs
 * itself (≥ σ′s) is unknown here.
 */
export const WHOLE_MILK = {
  source: 'Jensen et al., SIGGRAPH 2001 (whole milk, reduced scattering)',
  sigmaSReduced: [2550, 3210, 3770],
  sigmaA: [1.1, 2.4, 14],
};
