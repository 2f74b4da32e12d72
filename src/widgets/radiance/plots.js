// radiance, the two plots: radiance and irradiance against distance, and the light, the surface and the
// reflected light against wavelength.
import { LIGHTS, SURFACES, lampView } from './model.js';

const DISTANCES = Float64Array.from({ length: 200 }, (_, i) => 0.1 * 300 ** (i / 199));
const WAVELENGTHS = Float64Array.from({ length: 401 }, (_, i) => 380 + i);

/** Radiance stays, irradiance falls as 1/d²: both against distance, the state's distance marked. */
export function lampPlotSpec(state) {
  const views = [...DISTANCES].map((d) => lampView({ ...state, distance: d }));
  return {
    title: 'Radiance along a ray to the lamp, and irradiance from the whole lamp, against distance',
    xLabel: 'distance d (m, log scale)',
    yLabel: 'value / L',
    x: { min: 0.1, max: 30, log: true },
    y: { min: 1e-6, max: 10, log: true },
    series: [
      { label: 'radiance of a ray that meets the lamp (W sr⁻¹ m⁻², /L)', stroke: '#d55e00' },
      { label: 'irradiance on a facing surface (W m⁻², /L)', stroke: '#0072b2', dash: [9, 4] },
    ],
    data: [DISTANCES, views.map((v) => v.radiance), views.map((v) => v.irradiance)],
    bands: [{ from: state.distance / 1.04, to: state.distance * 1.04, color: '#0000002a', label: '' }],
    filename: 'radiance-irradiance',
    height: 220,
  };
}

/** The state's light, surface and their product against wavelength. */
export function spectrumPlotSpec(state) {
  const { spectrum } = LIGHTS[state.light];
  const { reflectance } = SURFACES[state.surface];
  const curves = [spectrum, reflectance, (l) => spectrum(l) * reflectance(l)];
  return {
    title: `${LIGHTS[state.light].name} on ${SURFACES[state.surface].name.toLowerCase()}, per wavelength`,
    xLabel: 'wavelength (nm)',
    yLabel: 'relative power / reflectance',
    x: { min: 380, max: 780 },
    y: { min: 0, max: 1.05 },
    series: [
      { label: 'light (relative power)', stroke: '#e69f00' },
      { label: 'surface reflectance', stroke: '#009e73', dash: [9, 4] },
      { label: 'reflected light = light × reflectance', stroke: '#000000', dash: [2, 3] },
    ],
    data: [WAVELENGTHS, ...curves.map((f) => WAVELENGTHS.map(f))],
    filename: `spectrum-${state.light}-${state.surface}`,
    height: 220,
  };
}
