// fresnel-zones, the measurement: the view's one-hot zone coverage rendered into a small float image and summed
// on the GPU; and the same averaged over light directions all around the object (the talk's claim, measured).
import * as THREE from 'three';
import { createGpuSum, floatTarget } from '../../core/gpu/gpu-sum.js';
import { lightDirFromAngles } from '../../math/angles.js';
import { AVERAGE_LIGHTS, changesAverage, changesShares, isWeighted, sharesOf, sphereLights } from './model.js';

const STATS_MAX = 512; // long side of the zone-statistics image, in pixels
const AVERAGE_MAX = 128; // smaller image for the average over light directions

/** What nothing has measured yet (and what a widget without WebGL shows). */
export const NOT_MEASURED = Object.freeze({ zoneShares: [0, 0, 0], averageShares: null });

/**
 * The zone shares of what `view` (scene-view.js) shows, measured with `renderer` when out of date: `measured`
 * holds the last ones ({ zoneShares, averageShares }, the average in the weighted mode only).
 */
export function createZoneStats(renderer, view) {
  const gpuSum = createGpuSum(renderer);
  const targets = {};
  const targetFor = (maxSide) => {
    const size = renderer.getDrawingBufferSize(new THREE.Vector2());
    const scale = Math.min(1, maxSide / Math.max(size.x, size.y));
    const [w, h] = [Math.max(1, Math.round(size.x * scale)), Math.max(1, Math.round(size.y * scale))];
    let target = targets[maxSide];
    if (!target || target.width !== w || target.height !== h) {
      target?.dispose();
      target = targets[maxSide] = floatTarget(w, h, true);
    }
    return target;
  };
  /** Renders the stats variant into an image of at most `maxSide` pixels and sums it: zone totals. */
  const zoneTotals = (maxSide) => {
    const target = targetFor(maxSide);
    view.renderStats(renderer, target);
    return gpuSum.sum(target).slice(0, 3);
  };
  const averageShares = () => {
    const totals = [0, 0, 0];
    for (const [theta, phi] of sphereLights(AVERAGE_LIGHTS)) {
      view.lightFrom(lightDirFromAngles(theta, phi));
      zoneTotals(AVERAGE_MAX).forEach((t, i) => (totals[i] += t));
    }
    view.applyState(); // the light back where the reader put it
    return sharesOf(totals);
  };
  const measured = { ...NOT_MEASURED };
  const dirty = { shares: true, average: true };
  return {
    measured,
    /** Marks out of date what a change of the keys `changed` moves; everything when none are given (a resize). */
    invalidate(changed) {
      dirty.shares ||= !changed || changesShares(changed);
      dirty.average ||= !changed || changesAverage(changed);
    },
    /** Measures what is out of date for `state` (the view's uniforms set from it); true when the shares moved. */
    measure(state) {
      if (isWeighted(state) && dirty.average) {
        measured.averageShares = averageShares();
        dirty.average = false;
        dirty.shares = true;
      }
      if (!dirty.shares) return false;
      measured.zoneShares = sharesOf(zoneTotals(STATS_MAX));
      dirty.shares = false;
      return true;
    },
    dispose() {
      gpuSum.dispose();
      Object.values(targets).forEach((t) => t.dispose());
    },
  };
}
