// radiance, in words: the about text, how values are written, and the picture described for screen readers.
import { LIGHTS, SURFACES } from './model.js';

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
