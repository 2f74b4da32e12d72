// Pictures some graders show next to the prompt, drawn from the same JS math they grade with: the target
// sphere beside the student's (sphere-match), the hidden NDF's highlight and profile (ndf-profile), and the
// widget's depth in metres, the answer's unit, beside its log₁₀ slider (transmittance-depth).
import { createPlot } from '../core/ui/plot.js';
import { displayValue, peakOf } from './sphere-image.js';
import { fmt, highlightSphere, materialSphere } from './graders.js';
import { pairSphere } from './graders/aniso-pair.js';
import { ANGLES, logAxes, ndfCurves } from '../widgets/ndf-explorer/model.js';
import { NDF_KEYS } from '../widgets/ndf-explorer/schema.js';

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

/** The hidden NDF's plot: its D(θh) among the explorer's five curves at this width, on its log plot's axes. */
export function hiddenNdfPlot(params, hidden) {
  // isotropic, as the talk's NDFs are (at anisotropy 0 every convention gives αx = αy = α)
  const { hwhm, abcA2, sgdP } = params;
  const curves = ndfCurves({ hwhm, abcA2, sgdP, D: NDF_KEYS, anisotropy: 0, convention: 'burley2012' });
  const { clip, ...axes } = logAxes(curves);
  return {
    ...axes,
    title: 'The highlight’s NDF: D(θh), log scale, on the axes of the explorer’s log plot',
    series: [{ label: 'hidden NDF', stroke: '#d55e00' }],
    data: [ANGLES, clip(curves.find((c) => c.key === hidden).values)],
    height: 260,
    legend: false,
    filename: 'highlight-profile',
  };
}

/** The media widget's depth slider is in log₁₀ metres, the answer in metres: the line says both. */
function depthLine(parent) {
  const line = document.createElement('p');
  line.className = 'exercise-readout';
  parent.append(line);
  return {
    update(state) {
      if (!Number.isFinite(state.distance)) return void (line.textContent = '');
      line.textContent =
        `Depth on the widget: ${fmt(10 ** state.distance)} m (its slider shows log₁₀ of the depth in metres: ` +
        `${fmt(state.distance).replace(/^-/, '−')}). Answer in metres.`;
    },
  };
}

const PREVIEWS = {
  'transmittance-depth': (parent) => depthLine(parent),

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
    const holder = document.createElement('div');
    holder.className = 'exercise-profile';
    parent.append(holder);
    const plot = createPlot(holder, hiddenNdfPlot(params, hidden));
    return { update() {}, dispose: () => plot.dispose() };
  },

  'aniso-pair'(parent, { params, hidden }) {
    const image = pairSphere(hidden, params);
    sphereFigure(parent, 'The highlight (tangent left to right)').draw(image, 1 / peakOf(image));
    return { update() {} };
  },
};

/** The grader's pictures in `parent`, or null when it has none. */
export function createPreview(parent, exercise, hidden) {
  const make = PREVIEWS[exercise.grader];
  return make ? make(parent, { params: exercise.params, hidden }) : null;
}
