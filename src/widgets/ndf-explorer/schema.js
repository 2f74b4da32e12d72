// The NDF explorer's state: the matched half width, the shapes of ABC and SGD, which NDFs are drawn, the
// spheres' light and exposure, and the measured slice the measured-BRDF widget hands over.

/** The talk's five NDFs: their labels and the shader switch that picks each on the spheres. */
export const NDFS = {
  blinnPhong: { name: 'Blinn-Phong', define: 'NDF_BLINN_PHONG' },
  beckmann: { name: 'Beckmann', define: 'NDF_BECKMANN' },
  ggx: { name: 'GGX (Trowbridge-Reitz)', define: 'NDF_GGX' },
  abc: { name: 'ABC', define: 'NDF_ABC' },
  sgd: { name: 'Shifted gamma (SGD)', define: 'NDF_SGD' },
};

export const schema = {
  hwhm: { type: 'number', min: 1, max: 40, step: 0.5, default: 8, label: 'Matched half width', unit: '°' },
  abcA2: { type: 'number', min: 0.5, max: 10, step: 0.1, default: 2.5, label: 'ABC shape a2' },
  sgdP: { type: 'number', min: 0, max: 1.9, step: 0.01, default: 0.64, label: 'SGD shape p' },
  ndfs: {
    type: 'set',
    options: Object.fromEntries(Object.entries(NDFS).map(([k, v]) => [k, v.name])),
    default: Object.keys(NDFS),
    label: 'Distributions',
  },
  lightTheta: { type: 'number', min: 0, max: 80, step: 1, default: 35, label: 'Light from view', unit: '°' },
  exposure: { type: 'number', min: 0.05, max: 50, step: 0.05, default: 1, label: 'Exposure' },
  // the NDF a measurement implies, as the measured-BRDF widget hands it over: D/D(0) at the 90 θh nodes of a
  // MERL table (0: missing or below 1e-5), and the name of its file
  measured: { type: 'samples', length: 90, min: 0, max: 1, default: [], label: 'Measured NDF slice' },
  measuredName: { type: 'text', maxLength: 80, default: '', label: 'Measured file' },
};
