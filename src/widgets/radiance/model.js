// The radiance widget's model, pure: what the eye gets from a lamp at a distance, and the RGB a renderer keeps
// for a light and a surface against the RGB of the light the surface really reflects.
import {
  planckRadiance,
  spectrumToXyz,
  sphereLightIrradiance,
  sphereSolidAngle,
  xyzToLinearSrgb,
} from '../../math/radiometry.js';

export const LAMP_RADIANCE = 1; // W sr⁻¹ m⁻²: the units cancel in every ratio the widget shows

/** The lamp at `distance` (m): its radiance, solid angle, angular radius and the irradiance it gives. */
export function lampView({ distance, lampRadius }) {
  return {
    radiance: LAMP_RADIANCE,
    solidAngle: sphereSolidAngle(lampRadius, distance),
    angularRadiusDeg: (Math.asin(Math.min(lampRadius / distance, 1)) * 180) / Math.PI,
    irradiance: sphereLightIrradiance(LAMP_RADIANCE, lampRadius, distance),
  };
}

const gauss = (l, mu, sigma) => Math.exp(-0.5 * ((l - mu) / sigma) ** 2);
/** A black body's spectrum at `kelvin`, relative power against wavelength (nm), 1 at its peak. */
export const blackBody = (kelvin) => {
  const peak = planckRadiance(2.897771955e6 / kelvin, kelvin); // Wien: scaled to 1 at its peak
  return (l) => planckRadiance(l, kelvin) / peak;
};

/** Light spectra, relative power against wavelength (nm). */
export const LIGHTS = {
  daylight: { name: 'Black body at 6504 K (daylight-like white)', spectrum: blackBody(6504) },
  incandescent: { name: 'Black body at 2856 K (a tungsten bulb, CIE illuminant A)', spectrum: blackBody(2856) },
  sodium: { name: 'Low-pressure sodium lamp (the 589 nm doublet, as one line)', spectrum: (l) => gauss(l, 589.3, 1.5) },
};

/** Surface reflectance spectra: illustrative smooth curves, not measurements. */
export const SURFACES = {
  red: { name: 'Red paint (illustrative)', reflectance: (l) => 0.05 + 0.8 / (1 + Math.exp(-(l - 600) / 12)) },
  green: {
    name: 'Leaf green (illustrative)',
    reflectance: (l) => 0.04 + 0.4 * gauss(l, 550, 30) + 0.5 / (1 + Math.exp(-(l - 710) / 10)),
  },
  grey: { name: 'Grey (50% at every wavelength)', reflectance: () => 0.5 },
};

/** The white that RGB (1, 1, 1) stands for here: the 6504 K black body. */
const WHITE = LIGHTS.daylight.spectrum;
const rgbOf = (spectrum) => xyzToLinearSrgb(spectrumToXyz(spectrum));
const WHITE_RGB = rgbOf(WHITE);
const WHITE_Y = spectrumToXyz(WHITE)[1];
const relative = (rgb) => rgb.map((c, i) => c / WHITE_RGB[i]);

/**
 * Linear RGB, white = (1, 1, 1): the light (scaled to the white's luminance), the surface's colour under white
 * light, the RGB of the light the surface reflects computed per wavelength, and the renderer's shortcut: the
 * component-wise product (⊗) of the two RGB triples. `spectrum` and `reflectance` are functions of λ (nm).
 */
export function coloursOf(spectrum, reflectance) {
  const k = WHITE_Y / spectrumToXyz(spectrum)[1];
  const light = relative(rgbOf((l) => k * spectrum(l)));
  const surface = relative(rgbOf((l) => reflectance(l) * WHITE(l)));
  const spectral = relative(rgbOf((l) => k * spectrum(l) * reflectance(l)));
  const product = light.map((c, i) => c * surface[i]);
  return { light, surface, spectral, product };
}

/** coloursOf for one of the widget's lights and surfaces. */
export const colours = (lightKey, surfaceKey) => coloursOf(LIGHTS[lightKey].spectrum, SURFACES[surfaceKey].reflectance);
