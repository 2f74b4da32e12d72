// fresnel-zones, what the reader handles on the view: the light control (drag or arrow keys; hidden in the modes
// of n·v, where the light plays no part), the probe, and the button that saves the zone shares (the picture has the
// save every view has).
import { attachLightControl } from '../../core/ui/light-control.js';
import { attachProbe } from '../../core/ui/probe.js';
import { createToolbar, downloadCsv } from '../../core/ui/export.js';
import { ZONE_LABELS } from '../../core/ui/palettes.js';
import { probeRows } from './probe-readout.js';
import { lightMatters } from './model.js';

/**
 * Attaches the tools to `viewport` inside `column`. `getState`, `update(partial)`, `view` (scene-view.js) and
 * `getZoneShares()` connect them to the widget.
 */
export function attachViewTools(viewport, column, { getState, update, view, getZoneShares }) {
  const lightControl = attachLightControl(viewport.canvas, viewport.holder, {
    get: getState,
    set: update,
    active: () => lightMatters(getState()),
  });
  const probe = attachProbe(viewport.canvas, column, {
    getMesh: () => view.mesh,
    getCamera: view.camera,
    describe: (n, v) => probeRows(getState(), n, v),
    isBusy: () => lightControl.dragging,
  });
  const file = (ext) => `fresnel-zones-${getState().mode}.${ext}`;
  const saveCsv = () =>
    downloadCsv(
      [
        { name: 'zone', values: ZONE_LABELS },
        { name: 'share', values: getZoneShares() },
      ],
      file('csv'),
    );
  createToolbar(column, [{ label: 'Save CSV', onClick: saveCsv }]);
  return {
    drawLight: () => lightControl.draw(),
    refreshProbe: () => probe.refresh(),
    dispose() {
      probe.dispose();
      lightControl.dispose();
    },
  };
}
