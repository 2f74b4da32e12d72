// radiance, in words: the about text, how values are written, and the picture described for screen readers.
import { declareFormula, texNumber, texSignificant } from '../../core/framework/formula-registry.js';
import { LIGHTS, SURFACES, colours, lampView } from './model.js';

export const TITLE = 'Radiance';

export const ABOUT =
  'Radiance is light along a single ray: power per unit area across the ray and per unit solid angle around it. ' +
  'Move the lamp away: it covers fewer pixels, but each one it covers still receives the same radiance, so the ' +
  'lamp looks no dimmer, only smaller. What a surface facing it receives, the irradiance, adds up all those rays ' +
  'and so falls as 1/d². Below, light is a spectrum, yet a renderer keeps three numbers per colour and multiplies ' +
  'them channel by channel (the ⊗ of the reflectance equation). Under white light the shortcut is exact by ' +
  'construction; under a peaked spectrum, such as a sodium lamp, it can be far off.';

/** A value to three decimals, or in scientific notation when that would hide it. */
export const fmt = (x) => (Math.abs(x) >= 0.01 || x === 0 ? x.toFixed(3) : x.toExponential(2));
export const triple = (rgb) => rgb.map(fmt).join(', ');

/** The picture in words: the lamp's size and irradiance, and the two RGB answers for the reflected light. */
export function describeRadiance(s, view, c) {
  return (
    `A lamp ${s.distance} m away covers ${(2 * view.angularRadiusDeg).toFixed(2)}° and still shows ` +
    `radiance L; the irradiance it gives is ${fmt(view.irradiance)} L. ${LIGHTS[s.light].name} on ` +
    `${SURFACES[s.surface].name.toLowerCase()}: reflected light per wavelength is RGB ${triple(c.spectral)}, ` +
    `the RGB shortcut gives ${triple(c.product)}.`
  );
}

const rgb = (values) => `(${values.map((x) => texNumber(x, 3)).join(',\\ ')})`;
let memo = { key: '', value: null }; // the colours integrate spectra: once per light and surface
function coloursOf(state) {
  const key = `${state.light}|${state.surface}`;
  if (memo.key !== key) memo = { key, value: colours(state.light, state.surface) };
  return memo.value;
}

/** The lamp's solid angle and irradiance at the slider's distance, and the RGB product against the spectrum. */
export const FORMULA = declareFormula('radiance', (state) => {
  const view = lampView(state);
  const r = `\\sym{lampRadius}{${texNumber(state.lampRadius, 2)}}`;
  const s = `\\frac{${r}}{\\sym{distance}{${texNumber(state.distance, 2)}}}`;
  const lamp =
    `\\sin\\theta_s = \\frac{r}{d} = ${s},\\quad \\Omega = 2\\pi(1 - \\cos\\theta_s) = ` +
    `${texSignificant(view.solidAngle)}\\ \\mathrm{sr},\\quad E = \\pi L \\sin^2\\theta_s = ` +
    `${texSignificant(view.irradiance)}\\,L`;
  const c = coloursOf(state);
  const product =
    `\\sym{light}{${rgb(c.light)}} \\otimes \\sym{surface}{${rgb(c.surface)}} = ${rgb(c.product)}` +
    `\\ \\text{against}\\ ${rgb(c.spectral)}\\ \\text{per wavelength}`;
  return `\\begin{gathered}${lamp}\\\\ ${product}\\end{gathered}`;
});
