// The measured-BRDF widget's views, top to bottom: the drop zone; the lobe plot beside the spheres and the 3-D
// lobe; the (θh, θd) image beside the NDF plot; the fit table; a residual image per model.
import { FIT_MODELS } from '../../measured/fit.js';
import { describeCanvas } from '../../core/framework/describe.js';
import { createHalfDiffImage } from '../brdf-lobe/half-diff-image.js';
import { createLobeView } from '../brdf-lobe/lobe-view.js';
import { createDropZone } from './drop-zone.js';
import { createFitTable } from './fit-table.js';
import { createLobePlot } from './lobe-plot.js';
import { createNdfPlot } from './ndf-plot.js';
import { createMeasuredSpheres } from './spheres.js';
import { IMAGE_TITLE, LOBE_3D_EMPTY, residualTitle } from './words.js';

const div = (className) => Object.assign(document.createElement('div'), { className });

/** The views in `shell.view`; `all` lists every one for dispose. */
export function createViews(shell, state, { onFile, onLoadFit }) {
  const drop = createDropZone(shell.view, onFile);
  const rows = ['lobe-row', 'lobe-row', 'half-diff-row measured-residuals'].map(div);
  const lobePlot = createLobePlot(rows[0], state.lightTheta);
  const sphereHolder = div('measured-spheres');
  rows[0].append(sphereHolder);
  const spheres = createMeasuredSpheres(sphereHolder, {
    label: 'Spheres: the measured BRDF (left) and the overlaid fit (right)',
  });
  const lobeHolder = div('lobe-3d');
  sphereHolder.append(lobeHolder);
  const lobe3d = createLobeView(lobeHolder);
  describeCanvas(lobe3d.canvas, LOBE_3D_EMPTY);
  const imageHolder = div('half-diff-row');
  rows[1].append(imageHolder);
  const image = createHalfDiffImage(imageHolder, IMAGE_TITLE);
  const ndfPlot = createNdfPlot(rows[1], state.overlay);
  shell.view.append(rows[0], rows[1]);
  const table = createFitTable(shell.view, onLoadFit);
  shell.view.append(rows[2]);
  const residuals = Object.keys(FIT_MODELS).map((k) => createHalfDiffImage(rows[2], residualTitle(k)));
  return {
    drop,
    lobePlot,
    lobe3d,
    spheres,
    image,
    ndfPlot,
    table,
    residuals,
    all: [lobePlot, lobe3d, ndfPlot, image, ...residuals, spheres, table, drop],
  };
}
