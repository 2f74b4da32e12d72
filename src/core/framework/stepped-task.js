// @ts-check
// Long measurements cut into steps, one per task, so that the page never stalls: step(0), step(1), … each in its own
// setTimeout once start() is called, onStep() after each; cancel() stops before the next. The microsurfaces' G1
// sweeps use it (one angle or azimuth a step).

/**
 * @param {number} count  steps to run
 * @param {(i: number) => void} step
 * @param {() => void} onStep  after each step (the last one's `complete` already true)
 */
export function createSteppedTask(count, step, onStep) {
  let [started, cancelled, complete] = [false, false, false];
  /** @param {number} i */
  const run = (i) => {
    if (cancelled) return;
    step(i);
    if (i + 1 < count) setTimeout(() => run(i + 1), 0);
    else complete = true;
    onStep();
  };
  return {
    /** Starts the steps (once; later calls do nothing). */
    start() {
      if (!started && count > 0) setTimeout(() => run(0), 0);
      started = true;
    },
    cancel() {
      cancelled = true;
    },
    get complete() {
      return complete;
    },
  };
}
