// radiance: the talk's "physics → math" step. A lamp seen from a distance the user sets: every pixel it covers
// shows the same radiance at any distance, while the irradiance it gives falls as 1/d². And a light spectrum
// and a surface's reflectance reduced to RGB: the per-wavelength product against the renderer's RGB ⊗ RGB.
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { createPlot } from '../../core/ui/plot.js';
import { sizeCanvas2d } from '../../core/ui/canvas2d.js';
import { rgbToHex } from '../../core/ui/palettes.js';
import { linearToSrgb } from '../../math/color.js';
import { LIGHTS, SURFACES, colours, lampView } from './model.js';

const names = (table) => Object.fromEntries(Object.entries(table).map(([k, v]) => [k, v.name]));

export const schema = {
  distance: { type: 'number', min: 0.1, max: 30, step: 0.1, default: 1, label: 'Distance to the lamp', unit: 'm' },
  lampRadius: { type: 'number', min: 0.01, max: 0.1, step: 0.01, default: 0.05, label: 'Lamp radius', unit: 'm' },
  light: { type: 'enum', options: names(LIGHTS), default: 'incandescent', label: 'Light spectrum' },
  surface: { type: 'enum', options: names(SURFACES), default: 'red', label: 'Surface reflectance' },
};

const ABOUT =
  'Radiance is light along a single ray: power per unit area across the ray and per unit solid angle around it. ' +
  'Move the lamp away: it covers fewer pixels, but each one it covers still receives the same radiance, so the ' +
  'lamp looks no dimmer, only smaller. What a surface facing it receives, the irradiance, adds up all those rays ' +
  'and so falls as 1/d². Below, light is a spectrum, yet a renderer keeps three numbers per colour and multiplies ' +
  'them channel by channel (the ⊗ of the reflectance equation). Under white light the shortcut is exact by ' +
  'construction; under a peaked spectrum, such as a sodium lamp, it can be far off.';

const TERMS_USED = []; // JS only (src/math/radiometry.js): nothing here runs on the GPU
const FIELD_DEG = 60; // the drawn eye's field of view: the lamp spans it at 0.1 m and about a pixel at 30 m
const DISTANCES = Float64Array.from({ length: 200 }, (_, i) => 0.1 * 300 ** (i / 199));
const WAVELENGTHS = Float64Array.from({ length: 401 }, (_, i) => 380 + i);
const fmt = (x) => (Math.abs(x) >= 0.01 || x === 0 ? x.toFixed(3) : x.toExponential(2));
const triple = (rgb) => rgb.map(fmt).join(', ');
const swatch = (rgb) => {
  const shown = rgb.map((c) => linearToSrgb(Math.min(Math.max(c, 0), 1)));
  return `<span class="swatch big" style="background:${rgbToHex(shown)}"></span>`;
};

function drawLamp(canvas, state, view) {
  const { ctx, w, h } = sizeCanvas2d(canvas);
  ctx.fillStyle = '#1b1e24';
  ctx.fillRect(0, 0, w, h);
  const pixel = 8; // one drawn "pixel" of an eye whose field is FIELD_DEG across
  const scale = w / FIELD_DEG;
  ctx.strokeStyle = '#ffffff14';
  for (let x = 0; x < w; x += pixel) ctx.strokeRect(x, 0, pixel, h);
  for (let y = 0; y < h; y += pixel) ctx.strokeRect(0, y, w, pixel);
  const r = Math.max(view.angularRadiusDeg * scale, 0.5);
  ctx.fillStyle = '#ffe9b0'; // the same value at every distance: radiance does not fall off
  ctx.beginPath();
  ctx.arc(w / 2, h / 2, r, 0, 2 * Math.PI);
  ctx.fill();
  ctx.fillStyle = '#e8e8e8';
  ctx.font = '12px system-ui, sans-serif';
  const span = `${(2 * view.angularRadiusDeg).toFixed(2)}°`;
  ctx.fillText(`the eye's view, ${FIELD_DEG}° across: the lamp at ${state.distance} m spans ${span}`, 8, h - 10);
}

function lampPlotSpec(state) {
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

function spectrumPlotSpec(state) {
  const { spectrum } = LIGHTS[state.light];
  const { reflectance } = SURFACES[state.surface];
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
    data: [WAVELENGTHS, ...[spectrum, reflectance, (l) => spectrum(l) * reflectance(l)].map((f) => WAVELENGTHS.map(f))],
    filename: `spectrum-${state.light}-${state.surface}`,
    height: 220,
  };
}

const row = (label, value) => `<tr><td>${label}</td><td>${value}</td></tr>`;
const table = (caption, rows) =>
  `<table class="data-table compact"><caption>${caption}</caption><tbody>${rows.join('')}</tbody></table>`;

function lampTableHtml(s, view) {
  return table(`A lamp of radiance L, radius ${s.lampRadius} m, at ${s.distance} m`, [
    row('radiance along each ray that meets it', `${fmt(view.radiance)} L, at any distance`),
    row('solid angle it covers', `${fmt(view.solidAngle)} sr`),
    row('irradiance on a surface facing it, π L (r/d)²', `${fmt(view.irradiance)} L`),
  ]);
}

function rgbTableHtml(c) {
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

export function createRadiance(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, {
    name: 'radiance',
    schema,
    initialState,
    locked,
    about: ABOUT,
    terms: TERMS_USED,
  });
  const canvas = document.createElement('canvas');
  canvas.className = 'radiance-lamp';
  const lampTable = document.createElement('div');
  const rgbTable = document.createElement('div');
  shell.view.append(canvas);
  const lampPlot = createPlot(shell.view, lampPlotSpec(shell.state));
  shell.view.append(lampTable);
  const spectrumPlot = createPlot(shell.view, spectrumPlotSpec(shell.state));
  shell.view.append(rgbTable);

  const render = (changed) => {
    const s = shell.state;
    const view = lampView(s);
    const touched = (...keys) => !changed || changed.some((k) => keys.includes(k));
    if (touched('distance', 'lampRadius')) lampPlot.setData(lampPlotSpec(s));
    if (touched('light', 'surface')) spectrumPlot.setData(spectrumPlotSpec(s));
    drawLamp(canvas, s, view);
    lampTable.innerHTML = lampTableHtml(s, view);
    const c = colours(s.light, s.surface);
    rgbTable.innerHTML = rgbTableHtml(c);
    shell.describe(
      `A lamp ${s.distance} m away covers ${(2 * view.angularRadiusDeg).toFixed(2)}° and still shows ` +
        `radiance L; the irradiance it gives is ${fmt(view.irradiance)} L. ${LIGHTS[s.light].name} on ` +
        `${SURFACES[s.surface].name.toLowerCase()}: reflected light per wavelength is RGB ${triple(c.spectral)}, ` +
        `the RGB shortcut gives ${triple(c.product)}.`,
      canvas,
    );
  };
  render(null);
  const resize = new ResizeObserver(() => drawLamp(canvas, shell.state, lampView(shell.state)));
  resize.observe(canvas);
  const update = shell.connect({ title: 'Radiance', onChanged: render, onStateChange });

  return {
    update,
    getState: () => shell.state,
    dispose() {
      resize.disconnect();
      lampPlot.dispose();
      spectrumPlot.dispose();
      shell.dispose();
    },
  };
}

export const widget = { name: 'radiance', schema, create: createRadiance, terms: TERMS_USED };
