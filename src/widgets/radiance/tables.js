// radiance, the two tables under the plots: the lamp's radiance, solid angle and irradiance; the colours of the
// light, the surface and the reflected light, per wavelength and by the renderer's shortcut.
import { rgbToHex } from '../../core/ui/palettes.js';
import { linearToSrgb } from '../../math/color.js';
import { fmt, triple } from './words.js';

const swatch = (rgb) => {
  const shown = rgb.map((c) => linearToSrgb(Math.min(Math.max(c, 0), 1)));
  return `<span class="swatch big" style="background:${rgbToHex(shown)}"></span>`;
};
const row = (label, value) => `<tr><td>${label}</td><td>${value}</td></tr>`;
const table = (caption, rows) =>
  `<table class="data-table compact"><caption>${caption}</caption><tbody>${rows.join('')}</tbody></table>`;

/** The lamp's table: radiance, solid angle and irradiance (model.js's lampView) at the state's distance. */
export function lampTableHtml(s, view) {
  return table(`A lamp of radiance L, radius ${s.lampRadius} m, at ${s.distance} m`, [
    row('radiance along each ray that meets it', `${fmt(view.radiance)} L, at any distance`),
    row('solid angle it covers', `${fmt(view.solidAngle)} sr`),
    row('irradiance on a surface facing it, π L (r/d)²', `${fmt(view.irradiance)} L`),
  ]);
}

/** The colours' table (model.js's colours): each as a swatch and a triple, and the shortcut's error. */
export function rgbTableHtml(c) {
  const ratio = c.product.map((p, i) => (Math.abs(c.spectral[i]) > 1e-6 ? `${(p / c.spectral[i]).toFixed(2)}×` : '—'));
  const shown = (rgb) => `${swatch(rgb)} ${triple(rgb)}`;
  const caption =
    'Linear RGB, white (the 6504 K black body) = (1, 1, 1); values outside 0…1 are outside the sRGB ' +
    'gamut (swatches clip them)';
  return table(caption, [
    row('the light', shown(c.light)),
    row('the surface under white light (its stored colour)', shown(c.surface)),
    row('reflected light, wavelength by wavelength', shown(c.spectral)),
    row('the renderer’s shortcut: light ⊗ surface', shown(c.product)),
    row('shortcut ÷ wavelength by wavelength, per channel', ratio.join(', ')),
  ]);
}
