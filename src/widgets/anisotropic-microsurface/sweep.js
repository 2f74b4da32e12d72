// anisotropic-microsurface, the G1 measurement against the azimuth: one azimuth per task (each ~0.1-0.5 s), so the
// page never stalls; started once a drag pauses.
import { createSteppedTask } from '../../core/framework/stepped-task.js';
import { AZIMUTHS_MEASURED, measuredAt } from './model.js';

/**
 * Measures G1 at `thetaDeg` for each of AZIMUTHS_MEASURED once start() is called; `onStep()` follows each. `data`
 * fills in as it goes ({ azimuths, measured, away: null until done, complete }); `cancel()` stops it.
 */
export function createAzimuthSweep(surface, thetaDeg, onStep) {
  const azimuths = AZIMUTHS_MEASURED;
  const data = { azimuths, measured: azimuths.map(() => null), away: azimuths.map(() => null), complete: false };
  const task = createSteppedTask(
    azimuths.length,
    (i) => {
      const m = measuredAt(surface, thetaDeg, azimuths[i]);
      [data.measured[i], data.away[i]] = [m.g1, m.away];
      data.complete = i === azimuths.length - 1;
    },
    onStep,
  );
  return { data, start: task.start, cancel: task.cancel };
}
