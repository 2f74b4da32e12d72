// subsurface-scale's model, as pure functions: where the light of many 2-D random walks comes back out, and
// whether the shading sample holds enough of it for shading to stay local.
import { randomWalk2D } from '../../math/media.js';
import { seededRandom } from '../../math/microsurface.js';

export const STATS_WALKS = 20000;
export const MAX_EVENTS = 2000;
const LOCAL_SHARE = 0.9; // "local" when this share of the re-emerging light exits inside the sample

/**
 * STATS_WALKS walks from `seed` in a slab with σs = 1: each one that comes back out as [|x|, path length], by
 * distance, and how many are still inside after MAX_EVENTS events. A walk at another σs is this one scaled by
 * 1/σs (its steps are exponential with mean 1/σs, the same random numbers pick them, the slab has no far side),
 * so one set serves a whole drag of σs and of σa; only the seed asks for new walks.
 */
export function unitWalks(seed) {
  const rand = seededRandom(seed * 7919);
  const exits = [];
  let stuck = 0;
  for (let i = 0; i < STATS_WALKS; i++) {
    const w = randomWalk2D({ sigmaS: 1, rand, maxEvents: MAX_EVENTS });
    if (w.exit === 'lost') stuck++;
    else exits.push([Math.abs(w.x), w.path]);
  }
  exits.sort((a, b) => a[0] - b[0]);
  return { seed, exits, stuck };
}

/**
 * From the walks of state `s` (unitWalks of its seed, scaled to its σs): each exit's distance from the entry and
 * the light it carries ([d, weight], by distance), the share that comes back out, the share of that inside the
 * shading sample, the median and mean exit distance (weighted by light) and the share of walks still inside
 * after MAX_EVENTS events.
 */
export function statistics(s, walks = unitWalks(s.seed)) {
  const exits = walks.exits.map(([x, path]) => [x / s.sigmaS, Math.exp((-s.sigmaA * path) / s.sigmaS)]);
  const back = exits.reduce((t, [, w]) => t + w, 0); // light left after absorption along each path
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
    stuck: walks.stuck / STATS_WALKS,
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
