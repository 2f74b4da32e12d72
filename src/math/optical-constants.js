// Measured optical constants (n, k) of the talk's five metals, around the visible range, as published.
// Rows are [wavelength in micrometres, n, k], taken from the refractiveindex.info database (CC0), which
// transcribes the original papers named in `source`.

export const RGB_WAVELENGTHS_UM = [0.65, 0.55, 0.45]; // the red, green and blue samples used for RGB (n, k)

export const MEASURED_NK = {
  gold: {
    source: 'Johnson & Christy, Phys. Rev. B 6, 4370 (1972)',
    rows: [
      [0.4133, 1.46, 1.958],
      [0.4305, 1.45, 1.948],
      [0.4509, 1.38, 1.914],
      [0.4714, 1.31, 1.849],
      [0.4959, 1.04, 1.833],
      [0.5209, 0.62, 2.081],
      [0.5486, 0.43, 2.455],
      [0.5821, 0.29, 2.863],
      [0.6168, 0.21, 3.272],
      [0.6595, 0.14, 3.697],
      [0.7045, 0.13, 4.103],
    ],
  },
  silver: {
    source: 'Johnson & Christy, Phys. Rev. B 6, 4370 (1972)',
    rows: [
      [0.4133, 0.05, 2.275],
      [0.4305, 0.04, 2.462],
      [0.4509, 0.04, 2.657],
      [0.4714, 0.05, 2.869],
      [0.4959, 0.05, 3.093],
      [0.5209, 0.05, 3.324],
      [0.5486, 0.06, 3.586],
      [0.5821, 0.05, 3.858],
      [0.6168, 0.06, 4.152],
      [0.6595, 0.05, 4.483],
      [0.7045, 0.04, 4.838],
    ],
  },
  copper: {
    source: 'Johnson & Christy, Phys. Rev. B 6, 4370 (1972)',
    rows: [
      [0.4133, 1.28, 2.207],
      [0.4305, 1.25, 2.305],
      [0.4509, 1.24, 2.397],
      [0.4714, 1.25, 2.483],
      [0.4959, 1.22, 2.564],
      [0.5209, 1.18, 2.608],
      [0.5486, 1.02, 2.577],
      [0.5821, 0.7, 2.704],
      [0.6168, 0.3, 3.205],
      [0.6595, 0.22, 3.747],
      [0.7045, 0.21, 4.205],
    ],
  },
  iron: {
    source: 'Johnson & Christy, Phys. Rev. B 9, 5056 (1974)',
    rows: [
      [0.413, 2.35, 2.65],
      [0.431, 2.48, 2.71],
      [0.451, 2.59, 2.77],
      [0.471, 2.67, 2.82],
      [0.496, 2.74, 2.88],
      [0.521, 2.86, 2.91],
      [0.549, 2.95, 2.93],
      [0.582, 2.94, 2.99],
      [0.617, 2.88, 3.05],
      [0.659, 2.92, 3.1],
      [0.704, 2.86, 3.19],
    ],
  },
  aluminum: {
    source: 'Rakić, Appl. Opt. 34, 4755 (1995)',
    rows: [
      [0.41328, 0.52135, 5.0008],
      [0.4428, 0.6079, 5.3676],
      [0.47687, 0.7278, 5.7781],
      [0.5166, 0.8734, 6.2418],
      [0.56357, 1.0728, 6.7839],
      [0.61993, 1.366, 7.4052],
      [0.65225, 1.5724, 7.7354],
      [0.68881, 1.8301, 8.0601],
      [0.72932, 2.1606, 8.3565],
    ],
  },
};

/** (n, k) at a wavelength, linearly interpolated between the published rows (clamped at the ends). */
export function nkAtWavelength(rows, um) {
  if (um <= rows[0][0]) return [rows[0][1], rows[0][2]];
  for (let i = 1; i < rows.length; i++) {
    const [w1, n1, k1] = rows[i];
    if (um <= w1) {
      const [w0, n0, k0] = rows[i - 1];
      const t = (um - w0) / (w1 - w0);
      return [n0 + t * (n1 - n0), k0 + t * (k1 - k0)];
    }
  }
  const last = rows[rows.length - 1];
  return [last[1], last[2]];
}

/** Per-channel [[nR, kR], [nG, kG], [nB, kB]] of a measured metal. */
export function measuredRgbNk(metal) {
  return RGB_WAVELENGTHS_UM.map((um) => nkAtWavelength(MEASURED_NK[metal].rows, um));
}
