// fresnel-zones, what the reader handles on the view: the light control (drag or arrow keys), the probe, and
// the buttons that save the picture and the zone shares.
import { attachLightControl } from '../../core/ui/light-control.js';
import { attachProbe } from '../../core/ui/probe.js';
import { canvasToPng, createToolbar, downloadCsv } from '../../core/ui/export.js';
import { ZONE_LABELS } from '../../core/ui/palettes.js';
import { probeRows } from './probe-readout.js';

/**
 * Attaches the tools to `viewport` inside `column`. `getState`, `update(partial)`, `view` (scene-view.js),
 * `redraw()` (draws now, for the PNG) and `getZoneShares()` connect them to the widget.
 */
export function attachViewTools(viewport, column, { getState, update, view, redraw, getZoneShares }) {
  const lightControl = attachLightControl(viewport.canvas, viewport.holder, { get: getState, set: update });
  const probe = attachProbe(viewport.canvas, column, {
    getMesh: () => view.mesh,
    getCamera: view.camera,
    describe: (n, v) => probeRows(getState(), n, v),
    isBusy: () => lightControl.dragging,
  });
  const file = (ext) => `fresnel-zones-${getState().mode}.${ext}`;
  const savePng = () => {
    redraw();
    canvasToPng(viewport.canvas, file('png'));
  };
  const saveCsv = () =>
    downloadCsv(
      [
        { name: 'zone', values: ZONE_LABELS },
        { name: 'share', values: getZoneShares() },
      ],
      file('csv'),
    );
  createToolbar(column, [
    { label: 'Save PNG', onClick: savePng },
    { label: 'Save CSV', onClick: saveCsv },
  ]);
  return {
    drawLight: () => lightControl.draw(),
    dispose() {
      probe.dispose();
      lightControl.dispose();
    },
  };
}
