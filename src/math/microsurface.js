// A 2-D (flatland) microsurface for looking at microfacet theory directly: a height profile with unit
// spacing whose slopes are independent draws from the 1-D slope distribution of Beckmann or GGX (the
// marginal of the 2-D slope density, i.e. what a cut through an isotropic surface sees), and exact ray
// casting against it. Smith's G1 is a prediction about such surfaces; this measures it.

/** A small, seeded PRNG (mulberry32), so that a profile is reproducible from its seed. */
export function seededRandom(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 2 ** 32;
  };
}

/**
 * One slope draw. Beckmann: Gaussian with standard deviation alpha/sqrt(2) (Box-Muller).
 * GGX: the marginal density 1/(2 alpha (1 + q²/alpha²)^(3/2)) has CDF 1/2 + q/(2 sqrt(alpha² + q²)),
 * inverted: q = alpha t / sqrt(1 - t²) with t = 2u - 1.
 */
export function sampleSlope(kind, alpha, rand) {
  if (kind === 'ggx') {
    const t = Math.min(Math.max(2 * rand() - 1, -1 + 1e-12), 1 - 1e-12);
    return (alpha * t) / Math.sqrt((1 - t) * (1 + t));
  }
  const u1 = Math.max(rand(), 1e-300);
  return (alpha / Math.SQRT2) * Math.sqrt(-2 * Math.log(u1)) * Math.cos(2 * Math.PI * rand());
}

/** Heights h[0..n] of a profile with n segments of unit width. */
export function generateProfile(n, kind, alpha, seed = 1) {
  const rand = seededRandom(seed);
  const h = new Float64Array(n + 1);
  for (let i = 1; i <= n; i++) h[i] = h[i - 1] + sampleSlope(kind, alpha, rand);
  return h;
}

/** Suffix and prefix maxima of the heights, so that rays can stop as soon as nothing further can block them. */
export function heightBounds(h) {
  const n = h.length;
  const right = new Float64Array(n);
  const left = new Float64Array(n);
  right[n - 1] = h[n - 1];
  for (let i = n - 2; i >= 0; i--) right[i] = Math.max(h[i], right[i + 1]);
  left[0] = h[0];
  for (let i = 1; i < n; i++) left[i] = Math.max(h[i], left[i - 1]);
  return { right, left };
}

/**
 * Is the ray from (x0, y0) towards the direction (dx, dy) (dy > 0, upwards) blocked by the profile?
 * A straight ray passes above a linear segment if it passes above both its ends, so the vertices suffice.
 * Returns null when it escapes, else the x where it first meets the profile.
 */
export function castUp(h, bounds, x0, y0, dx, dy) {
  const n = h.length - 1;
  const slope = dy / Math.abs(dx || 1e-300);
  const step = dx >= 0 ? 1 : -1;
  let i = dx >= 0 ? Math.floor(x0) + 1 : Math.ceil(x0) - 1;
  while (i >= 0 && i <= n) {
    const y = y0 + Math.abs(i - x0) * slope;
    if ((step > 0 ? bounds.right[i] : bounds.left[i]) < y) return null;
    if (h[i] > y) {
      // the ray crossed the segment between i - step and i: find where
      const j = i - step;
      const yj = y0 + Math.abs(j - x0) * slope;
      const t = (yj - h[j]) / (yj - h[j] - (y - h[i]));
      return j + step * Math.min(Math.max(t, 0), 1);
    }
    i += step;
  }
  return null;
}

/**
 * Measured G1 for the direction at angle theta (radians) from the mean normal, positive towards +x:
 * the projected length of front-facing microfacets that the direction sees unblocked, over all of it.
 * Each segment is sampled at `perSegment` points; segments near the ends are skipped (`margin`).
 */
export function measuredG1(h, theta, { perSegment = 4, margin = 0.25 } = {}) {
  const bounds = heightBounds(h);
  const n = h.length - 1;
  const [dx, dy] = [Math.sin(theta), Math.cos(theta)];
  let seen = 0;
  let total = 0;
  for (let i = Math.floor(n * margin); i < Math.floor(n * (1 - margin)); i++) {
    const rise = h[i + 1] - h[i];
    const len = Math.hypot(1, rise);
    const proj = (dx * -rise + dy) / len; // direction · facet normal (normal of (1, rise) is (-rise, 1)/len)
    if (proj <= 0) continue;
    const w = (proj * len) / perSegment;
    for (let k = 0; k < perSegment; k++) {
      const t = (k + 0.5) / perSegment;
      total += w;
      if (castUp(h, bounds, i + t, h[i] + t * rise + 1e-9, dx, dy) === null) seen += w;
    }
  }
  return total > 0 ? seen / total : 1;
}

/**
 * First point where the ray from (x0, y0) along (dx, dy) meets the profile between x = lo and x = hi
 * (any direction, for drawing rays that bounce). Returns { x, y, segment } or null.
 */
export function intersectProfile(h, x0, y0, dx, dy, lo, hi, skip = 1e-6) {
  let best = null;
  for (let i = Math.max(Math.floor(lo), 0); i < Math.min(Math.ceil(hi), h.length - 1); i++) {
    // segment from (i, h[i]) to (i + 1, h[i + 1]); solve (x0, y0) + s (dx, dy) = (i + t, h[i] + t rise)
    const rise = h[i + 1] - h[i];
    const det = dx * rise - dy;
    if (Math.abs(det) < 1e-15) continue;
    const ex = i - x0;
    const ey = h[i] - y0;
    const s = (ex * rise - ey) / det;
    const t = (dx * ey - dy * ex) / -det;
    if (s > skip && t >= 0 && t <= 1 && (!best || s < best.s)) best = { s, x: i + t, y: h[i] + t * rise, segment: i };
  }
  return best;
}

/** Unit normal of segment i, pointing up out of the surface. */
export function segmentNormal(h, i) {
  const rise = h[i + 1] - h[i];
  const len = Math.hypot(1, rise);
  return [-rise / len, 1 / len];
}

/** The 1-D slope density of the profile: Beckmann exp(-q²/a²)/(a sqrt(pi)), GGX 1/(2a (1 + q²/a²)^(3/2)). */
export function slopeDensity(kind, alpha, q) {
  if (kind === 'ggx') return 1 / (2 * alpha * (1 + (q * q) / (alpha * alpha)) ** 1.5);
  return Math.exp(-(q * q) / (alpha * alpha)) / (alpha * Math.sqrt(Math.PI));
}

/**
 * Microfacet prediction, in flatland, of where light from angle thetaI (radians from the mean normal) goes
 * after its first reflection: the density over the outgoing angle thetaO. Facet normals at angle θm have
 * (length-weighted) density D(θm) = P(tan θm)/cos³θm; the light sees them in proportion to cos(θi − θm) and
 * Smith's G1(θi) (G1 of the same slope distribution); a mirror facet sends it to θo = 2θm − θi.
 */
export function reflectedAngleDensity(thetaO, thetaI, kind, alpha, G1) {
  const thetaM = (thetaO + thetaI) / 2;
  if (Math.abs(thetaM) >= Math.PI / 2) return 0;
  const seen = Math.cos(thetaI - thetaM);
  if (seen <= 0) return 0;
  const D = slopeDensity(kind, alpha, Math.tan(thetaM)) / Math.cos(thetaM) ** 3;
  return (G1(Math.cos(thetaI), alpha) * seen * D) / Math.cos(thetaI) / 2;
}

/**
 * The same, ray-traced: first hits of parallel rays from thetaI on the profile h, found by picking facets
 * in proportion to their projected length towards the light and keeping those the light reaches.
 * Returns the outgoing angles of `n` first reflections.
 */
export function reflectedAngles(h, thetaI, n, rand) {
  const bounds = heightBounds(h);
  const [lx, ly] = [Math.sin(thetaI), Math.cos(thetaI)];
  const segments = h.length - 1;
  const lo = Math.floor(segments * 0.25);
  const span = Math.floor(segments * 0.5);
  // rejection sampling by projected length: a facet's weight is (l · m) len = ly - lx rise, at most ly + |lx| maxRise
  let maxWeight = 0;
  for (let i = lo; i < lo + span; i++) maxWeight = Math.max(maxWeight, ly - lx * (h[i + 1] - h[i]));
  const out = [];
  while (out.length < n) {
    const i = lo + Math.floor(rand() * span);
    const rise = h[i + 1] - h[i];
    const w = ly - lx * rise;
    if (w <= 0 || rand() * maxWeight > w) continue;
    const t = rand();
    if (castUp(h, bounds, i + t, h[i] + t * rise + 1e-9, lx, ly) !== null) continue; // in shadow
    const thetaM = -Math.atan(rise);
    out.push(2 * thetaM - thetaI);
  }
  return out;
}
