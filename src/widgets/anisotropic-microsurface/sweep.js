// anisotropic-microsurface, the G1 measurement against the azimuth: one azimuth per task (each ~0.1-0.5 s), so the page
// never stalls; started once a drag pauses.
import { AZIMUTHS_MEASURED, measuredAt } from './model.js';

/**
 * Measures G1 at the state's θ for each of AZIMUTHS_MEASURED once start() is called; `onStep()` follows each.
 * `data` fills in as it goes ({ azimuths, measured, away: null until done, complete }); `cancel()` stops it.
 */
export function createAzimuthSweep(surface, thetaDeg, onStep) {
  const azimuths = AZIMUTHS_MEASURED;
  const data = { azimuths, measured: azimuths.map(() => null), away: azimuths.map(() => null), complete: false };
  let [started, cancelled] = [false, false];
  const step = (i) => {
    if (cancelled) return;
    const m = measuredAt(surface, thetaDeg, azimuths[i]);
    [data.measured[i], data.away[i]] = [m.g1, m.away];
    if (i + 1 < azimuths.length) setTimeout(() => step(i + 1), 0);
    else data.complete = true;
    onStep();
  };
  return {
    data,
    start() {
      if (!started) setTimeout(() => step(0), 0);
      started = true;
    },
    cancel() {
      cancelled = true;
    },
  };
}
