// Pictures some graders show next to the prompt, drawn from the same JS math they grade with: the target
// sphere beside the student's (sphere-match), and the hidden NDF's highlight and profile (ndf-profile).
import { createPlot } from '../core/ui/plot.js';
import { displayValue, peakOf } from './sphere-image.js';
import { highlightSphere, materialSphere, ndfProfiles } from './graders.js';

/** A figure with a canvas showing a grey radiance image at an exposure, one canvas pixel per grid cell. */
function sphereFigure(parent, caption) {
  const figure = document.createElement('figure');
  figure.className = 'exercise-sphere';
  const canvas = document.createElement('canvas');
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-label', caption);
  const text = document.createElement('figcaption');
  text.textContent = caption;
  figure.append(canvas, text);
  parent.append(figure);
  return {
    draw(image, exposure) {
      const size = Math.round(Math.sqrt(image.length));
      canvas.width = size;
      canvas.height = size;
      const ctx = canvas.getContext('2d');
      const pixels = ctx.createImageData(size, size);
      image.forEach((L, i) => {
        const v = Number.isNaN(L) ? 0.12 : displayValue(L, exposure);
        pixels.data.set([v * 255, v * 255, v * 255, 255], i * 4);
      });
      ctx.putImageData(pixels, 0, 0);
    },
  };
}

const PREVIEWS = {
  'sphere-match'(parent, { params }) {
    const target = sphereFigure(parent, 'Target');
    const yours = sphereFigure(parent, 'Yours (F0 and α from the controls)');
    target.draw(materialSphere(params, params), params.exposure);
    return { update: (state) => yours.draw(materialSphere(state, params), params.exposure) };
  },

  'ndf-profile'(parent, { params, hidden }) {
    const image = highlightSphere(hidden, params);
    const peak = peakOf(image);
    sphereFigure(parent, 'The highlight').draw(image, 1 / peak);
    sphereFigure(parent, 'Its tail (30× brighter)').draw(image, 30 / peak);
    const xs = Float64Array.from({ length: 360 }, (_, i) => i * 0.25);
    const profile = ndfProfiles(params.hwhm, params)[hidden].map((v) => Math.max(v, 1e-6));
    const holder = document.createElement('div');
    holder.className = 'exercise-profile';
    parent.append(holder);
    const plot = createPlot(holder, {
      title: 'The highlight’s profile: D(θh) / D(0)',
      xLabel: 'θh (degrees)',
      yLabel: 'D / D(0)',
      x: { min: 0, max: Math.min(90, 8 * params.hwhm) },
      y: { log: true, min: 1e-4, max: 1 },
      series: [{ label: 'hidden NDF', stroke: '#d55e00' }],
      data: [xs, profile],
      height: 220,
      legend: false,
      filename: 'highlight-profile',
    });
    return { update() {}, dispose: () => plot.dispose() };
  },
};

/** The grader's pictures in `parent`, or null when it has none. */
export function createPreview(parent, exercise, hidden) {
  const make = PREVIEWS[exercise.grader];
  return make ? make(parent, { params: exercise.params, hidden }) : null;
}
