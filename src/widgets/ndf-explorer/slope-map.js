// The NDF explorer's slope maps: D of GGX and of Beckmann over the hemisphere of h, drawn in slope space (the
// microfacet's slopes hx/hz across, hy/hz up), log-scaled viridis colours from the peak down four decades. An
// anisotropic lobe is an ellipse stretched along the tangent's axis.
import { viridis } from '../../core/ui/palettes.js';
import { describeCanvas } from '../../core/framework/describe.js';
import { squareImageAxes } from '../../core/ui/canvas2d.js';
import { slopeExtent, slopeMapValues } from './model.js';

const N = 96;
const DECADES = 4;
const [X0, Y0, SIZE] = [44, 8, 168]; // the image's place in its canvas, CSS pixels

/** The image of `values` (N × N, row 0 at the bottom) into a canvas of N × N pixels. */
function paint(cell, values, peak) {
  const img = cell.getContext('2d').createImageData(N, N);
  values.forEach((v, k) => {
    const t = v > 0 ? 1 + Math.log10(v / peak) / DECADES : 0;
    const [r, g, b] = v > 0 && t > 0 ? viridis(t) : [30, 30, 30];
    img.data.set([r, g, b, 255], ((N - 1 - Math.floor(k / N)) * N + (k % N)) * 4);
  });
  cell.getContext('2d').putImageData(img, 0, 0);
}

/** The axes: ticks at -extent, 0 and extent on both, and their names. */
const axes = (ctx, extent) =>
  squareImageAxes(ctx, {
    x0: X0,
    y0: Y0,
    size: SIZE,
    ticks: [-extent, 0, extent].map((x, i) => [i / 2, `${Number(x.toPrecision(3))}`]),
    xLabel: 'slope along the tangent, hx/hz',
    yLabel: 'slope along the bitangent, hy/hz',
  });

/** One map in a figure of its own; draw(lobe) paints it and describes it. */
function createMap(container) {
  const figure = document.createElement('figure');
  figure.className = 'half-diff slope-map';
  const caption = document.createElement('figcaption');
  const canvas = Object.assign(document.createElement('canvas'), { width: 224, height: 214 });
  canvas.setAttribute('role', 'img');
  figure.append(caption, canvas);
  container.append(figure);
  const cell = Object.assign(document.createElement('canvas'), { width: N, height: N });
  return {
    draw(lobe) {
      const extent = slopeExtent(lobe.pair);
      const values = slopeMapValues(lobe, N, extent);
      const peak = lobe.D(0, 0, 1, ...lobe.pair);
      paint(cell, values, peak);
      const ctx = canvas.getContext('2d');
      ctx.clearRect(0, 0, canvas.width, canvas.height);
      ctx.imageSmoothingEnabled = false;
      ctx.drawImage(cell, X0, Y0, SIZE, SIZE);
      axes(ctx, extent);
      caption.textContent = `${lobe.label}: D in slope space`;
      const [ax, ay] = lobe.pair.map((a) => a.toPrecision(3));
      describeCanvas(
        canvas,
        `${caption.textContent}, αx = ${ax}, αy = ${ay}, slopes from ${-extent} to ${extent} on both axes; ` +
          `viridis colours on a log scale, brightest (yellow) at the peak D = ${peak.toPrecision(3)} /sr, ` +
          `darkest ${DECADES} decades below.`,
      );
    },
    dispose: () => figure.remove(),
  };
}

/** The maps of the chosen NDFs that have an anisotropic form, and the note on conventions under them. */
export function createSlopeMaps(container) {
  const row = document.createElement('div');
  row.className = 'half-diff-row slope-maps';
  const note = document.createElement('p');
  note.className = 'anisotropy-note';
  container.append(row, note);
  let maps = [];
  return {
    /** lobes: model.js's anisotropicLobe of each chosen NDF that has one; text: the note. */
    draw(lobes, text) {
      if (maps.length !== lobes.length) {
        maps.forEach((m) => m.dispose());
        maps = lobes.map(() => createMap(row));
      }
      lobes.forEach((lobe, i) => maps[i].draw(lobe));
      note.textContent = text;
    },
    dispose() {
      maps.forEach((m) => m.dispose());
      row.remove();
      note.remove();
    },
  };
}
