// microfacets, the G1 measurement: ray-tracing 18 angles takes up to ~2 s for GGX, so one angle per task and
// the page never stalls; started once a drag pauses, so that the surface's frames do not wait for it.
import { DEG } from '../../math/angles.js';
import { measuredG1 } from '../../math/microsurface.js';
import { G1_ANGLES_DEG, G1_OPTIONS } from './model.js';

/**
 * Measures G1 of `profile` at each of G1_ANGLES_DEG once start() is called; `onStep()` follows each angle. `data`
 * fills in as it goes ({ angles, measured (null until done), complete }); `cancel()` stops it.
 */
export function createG1Sweep(profile, onStep) {
  const angles = G1_ANGLES_DEG;
  const data = { angles, measured: angles.map(() => null), complete: false };
  let [started, cancelled] = [false, false];
  const step = (i) => {
    if (cancelled) return;
    data.measured[i] = measuredG1(profile, angles[i] * DEG, G1_OPTIONS);
    onStep();
    if (i + 1 < angles.length) setTimeout(() => step(i + 1), 0);
    else data.complete = true;
  };
  return {
    data,
    /** Starts the measurement (once; later calls do nothing). */
    start() {
      if (!started) setTimeout(() => step(0), 0);
      started = true;
    },
    cancel() {
      cancelled = true;
    },
  };
}
