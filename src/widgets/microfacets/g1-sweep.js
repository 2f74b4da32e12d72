// microfacets, the G1 measurement: ray-tracing 18 angles takes up to ~2 s for GGX, so one angle per task and
// the page never stalls; started once a drag pauses, so that the surface's frames do not wait for it.
import { createSteppedTask } from '../../core/framework/stepped-task.js';
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
  const task = createSteppedTask(
    angles.length,
    (i) => {
      data.measured[i] = measuredG1(profile, angles[i] * DEG, G1_OPTIONS);
    },
    () => {
      data.complete = task.complete;
      onStep();
    },
  );
  return { data, start: task.start, cancel: task.cancel };
}
