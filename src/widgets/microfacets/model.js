// microfacets, its model as pure functions: the profile's window on screen, what each facet sees, where the
// bundle of light rays lands and bounces, and Smith's G1 for the same roughness.
import { DEG } from '../../math/angles.js';
import { reflect } from '../../math/integrate.js';
import { castUp, generateProfile, heightBounds, intersectProfile, segmentNormal } from '../../math/microsurface.js';
import { smithG1Beckmann, smithG1GGX } from '../../math/visibility.js';

export const PROFILE = 80000; // long enough that GGX's heavy-tailed slopes measure within ~0.03 of Smith
export const WINDOW = 44; // facets shown
const H_TOLERANCE_DEG = 3; // a facet within this of h is marked as reflecting to the eye
const PIECES = 6; // each facet is judged in pieces: a shadow's edge can fall inside one
export const G1_ANGLES_DEG = Array.from({ length: 18 }, (_, i) => i * 5);
export const G1_OPTIONS = { perSegment: 2, margin: 0.25 };

/** A unit direction in the plane of the cut, `deg` from the mean normal: [x, y]. */
export const dirOf = (deg) => [Math.sin(deg * DEG), Math.cos(deg * DEG)];

/** Smith's G1 of the state's distribution and roughness at the cosine `c`. */
export const smithG1 = (state, c) => (state.kind === 'ggx' ? smithG1GGX : smithG1Beckmann)(c, state.alpha);

/** The angle of a direction [x, y] from the mean normal, in degrees. */
const angleOf = (x, y) => Math.atan2(x, y) / DEG;
/** The half vector's angle from the mean normal, in degrees, for the directions `l` and `v` ([x, y]). */
export const halfAngleDeg = (l, v) => angleOf(l[0] + v[0], l[1] + v[1]);

/** The state's random surface: its heights and their bounds. */
export function createSurface(state) {
  const profile = generateProfile(PROFILE, state.kind, state.alpha, state.seed);
  return { profile, bounds: heightBounds(profile) };
}

/** The facets on screen, [x0, x0 + WINDOW] in the middle of the profile, and their mean height. */
export function surfaceWindow(profile) {
  const x0 = Math.floor(PROFILE / 2 - WINDOW / 2);
  let mean = 0;
  for (let i = x0; i <= x0 + WINDOW; i++) mean += profile[i] / (WINDOW + 1);
  return { x0, x1: x0 + WINDOW, mean };
}

/**
 * Each facet on screen: its pieces ({ from, to } points of the profile, `lit` when the light reaches it,
 * `seen` when the eye does), and `normal` ({ x, y, nx, ny } at its middle) when it faces along h.
 */
export function facetsSeen({ profile, bounds }, { x0, x1 }, l, v) {
  const hAngle = halfAngleDeg(l, v);
  const facets = [];
  for (let i = x0; i < x1; i++) {
    const rise = profile[i + 1] - profile[i];
    const [nx, ny] = segmentNormal(profile, i);
    const pieces = Array.from({ length: PIECES }, (_, k) => {
      const [ta, tb] = [k / PIECES, (k + 1) / PIECES];
      const xm = i + (ta + tb) / 2;
      const ym = profile[i] + ((ta + tb) / 2) * rise + 1e-9;
      return {
        from: [i + ta, profile[i] + ta * rise],
        to: [i + tb, profile[i] + tb * rise],
        lit: nx * l[0] + ny * l[1] > 0 && castUp(profile, bounds, xm, ym, l[0], l[1]) === null,
        seen: nx * v[0] + ny * v[1] > 0 && castUp(profile, bounds, xm, ym, v[0], v[1]) === null,
      };
    });
    const alongH = Math.abs(angleOf(nx, ny) - hAngle) < H_TOLERANCE_DEG;
    facets.push({ pieces, normal: alongH ? { x: i + 0.5, y: profile[i] + rise / 2, nx, ny } : null });
  }
  return facets;
}

/**
 * `count` parallel rays from the light, spread across the window, starting at height `top`: where each first
 * meets the surface (`hit`), where its reflection ends (`end`, on the surface when it hits it `second`), and
 * the direction the second bounce leaves in (`out2`). Rays that miss the window are left out.
 */
export function traceRays({ profile }, { x0, x1 }, l, count, top) {
  const rays = [];
  for (let r = 0; r < count; r++) {
    const xs = x0 + ((r + 0.5) / count) * WINDOW;
    const along = (top - profile[Math.round(xs)]) / l[1];
    const start = [xs + l[0] * along, profile[Math.round(xs)] + l[1] * along];
    const hit = intersectProfile(profile, start[0], start[1], -l[0], -l[1], x0, x1, 0);
    if (!hit) continue;
    const m = segmentNormal(profile, hit.segment);
    const out = reflect([l[0], l[1], 0], [m[0], m[1], 0]);
    const second = intersectProfile(profile, hit.x, hit.y, out[0], out[1], x0 - 20, x1 + 20);
    const end = second ?? { x: hit.x + out[0] * 4, y: hit.y + out[1] * 4 };
    const m2 = second && segmentNormal(profile, second.segment);
    const out2 = second && reflect([-out[0], -out[1], 0], [m2[0], m2[1], 0]);
    rays.push({ start, hit, end, second, out2 });
  }
  return rays;
}

/** Smith's G1 against the light's angle, 0° to 89°, for the plot. */
export function smithCurve(state) {
  const xs = Float64Array.from({ length: 90 }, (_, i) => i);
  return { xs, ys: xs.map((d) => smithG1(state, Math.cos(d * DEG))) };
}
