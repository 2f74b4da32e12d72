// The energy widget's random walk off the main thread (8 angles × 20,000 paths × 3 channels take about a
// second). Message in: { id, alpha, f0 } (f0 linear [r, g, b]); out: { id, walk } as walkPoints returns it.
import { walkPoints } from './compensation.js';

self.onmessage = ({ data: { id, alpha, f0 } }) => self.postMessage({ id, walk: walkPoints(alpha, f0) });
