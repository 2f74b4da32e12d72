// subsurface-scale's model, as pure functions: where the light of many 2-D random walks comes back out, and
// whether the shading sample holds enough of it for shading to stay local.
import { randomWalk2D } from '../../math/media.js';
import { seededRandom } from '../../math/microsurface.js';

export const STATS_WALKS = 20000;
export const MAX_EVENTS = 2000;
const LOCAL_SHARE = 0.9; // "local" when this share of the re-emerging light exits inside the sample

/**
 * From STATS_WALKS walks: each exit's distance from the entry and the light it carries ([d, weight], by
 * distance), the share that comes back out, the share of that inside the shading sample, the median and mean
 * exit distance (weighted by light) and the share of walks still inside after MAX_EVENTS events.
 */
export function statistics(s) {
  const rand = seededRandom(s.seed * 7919);
  const exits = [];
  let back = 0;
  let stuck = 0;
  for (let i = 0; i < STATS_WALKS; i++) {
    const w = randomWalk2D({ sigmaS: s.sigmaS, rand, maxEvents: MAX_EVENTS });
    if (w.exit === 'lost') stuck++;
    else {
      const weight = Math.exp(-s.sigmaA * w.path); // light left after absorption along the path
      exits.push([Math.abs(w.x), weight]);
      back += weight;
    }
  }
  exits.sort((a, b) => a[0] - b[0]);
  const inside = exits.filter(([d]) => d <= s.pixel).reduce((t, [, w]) => t + w, 0);
  let acc = 0;
  const median = exits.find(([, w]) => (acc += w) >= back / 2)?.[0] ?? 0;
  const mean = back > 0 ? exits.reduce((t, [d, w]) => t + d * w, 0) / back : 0;
  return {
    exits,
    reflectance: back / STATS_WALKS,
    insideShare: back > 0 ? inside / back : 0,
    median,
    mean,
    stuck: stuck / STATS_WALKS,
  };
}

/** Whether shading may stay local: enough of the light that comes back out leaves inside the sample. */
export const isLocal = (stats) => stats.insideShare >= LOCAL_SHARE;

/** Light per mm leaving at each distance up to maxDist, in 60 bins: { xs (bin centres), ys }. */
export function histogram(stats, maxDist) {
  const bins = 60;
  const width = maxDist / bins;
  const xs = Float64Array.from({ length: bins }, (_, i) => (i + 0.5) * width);
  const ys = new Float64Array(bins);
  for (const [d, w] of stats.exits) if (d < maxDist) ys[Math.floor(d / width)] += w / STATS_WALKS / width;
  return { xs, ys };
}

/** The histogram's range in mm: past the shading sample and the bulk of the exits. */
export const histogramRange = (state, stats) => Math.max(state.pixel * 1.5, stats.median * 6, 1);

/** The walks picture's width in mm: the whole shading sample and most paths. */
export const pictureSpan = (state, stats) => Math.max(state.pixel * 2.6, stats.median * 8, 2);
