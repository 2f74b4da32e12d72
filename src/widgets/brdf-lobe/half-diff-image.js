// A BRDF as an image over the half/difference angles: theta_h across, theta_d up, at one phi_d, with
// log-scaled viridis colours. Specular peaks lie along theta_h = 0; Fresnel brightens towards theta_d = 90°.
import { viridis } from '../../core/ui/palettes.js';
import { describeCanvas } from '../../core/framework/describe.js';
import { squareImageAxes } from '../../core/ui/canvas2d.js';

const N = 90;
const DECADES = 4; // colour range: the top of the scale down to 1e-4 of it
const TOP_PERCENTILE = 0.99; // grazing angles blow up; scale to the 99th percentile, not the maximum

export function createHalfDiffImage(container, title) {
  const figure = document.createElement('figure');
  figure.className = 'half-diff';
  const caption = document.createElement('figcaption');
  caption.textContent = title;
  const canvas = document.createElement('canvas');
  canvas.width = 232;
  canvas.height = 226;
  canvas.setAttribute('role', 'img');
  figure.append(caption, canvas);
  container.append(figure);
  const cell = document.createElement('canvas');
  cell.width = N;
  cell.height = N;

  return {
    /**
     * value(thetaH, thetaD) in radians, and what it is in words; returns the top of the colour scale. With
     * { max }, images drawn side by side share one scale instead of each taking its own 99th percentile.
     */
    draw(value, description, { max: sharedMax } = {}) {
      const vals = new Float64Array(N * N);
      for (let j = 0; j < N; j++) {
        for (let i = 0; i < N; i++)
          vals[j * N + i] = value(((i + 0.5) * Math.PI) / 2 / N, ((j + 0.5) * Math.PI) / 2 / N);
      }
      const sorted = Float64Array.from(vals).sort();
      const max = sharedMax ?? sorted[Math.floor(TOP_PERCENTILE * (sorted.length - 1))];
      const img = cell.getContext('2d').createImageData(N, N);
      vals.forEach((v, k) => {
        const i = k % N;
        const j = Math.floor(k / N);
        const t = v > 0 && max > 0 ? 1 + Math.log10(v / max) / DECADES : 0;
        const [r, g, b] = v > 0 ? viridis(t) : [30, 30, 30];
        const o = ((N - 1 - j) * N + i) * 4; // theta_d grows upwards
        img.data.set([r, g, b, 255], o);
      });
      cell.getContext('2d').putImageData(img, 0, 0);
      const ctx = canvas.getContext('2d');
      ctx.clearRect(0, 0, canvas.width, canvas.height);
      const [x0, y0, size] = [40, 8, 180];
      ctx.imageSmoothingEnabled = false;
      ctx.drawImage(cell, x0, y0, size, size);
      squareImageAxes(ctx, {
        x0,
        y0,
        size,
        ticks: [0, 30, 60, 90].map((deg) => [deg / 90, `${deg}°`]),
        xLabel: 'θh (half vector from n)',
        yLabel: 'θd (l from h)',
      });
      const top = `${max.toPrecision(3)}${sharedMax ? '' : ' per steradian (99th percentile)'}`;
      describeCanvas(
        canvas,
        `${title}: ${description}; viridis colours on a log scale, brightest (yellow) at ${top}, darkest ` +
          `${DECADES} decades below.`,
      );
      return max;
    },
    dispose() {
      figure.remove();
    },
  };
}
