// The grader 'ndf-profile': Which NDF made the highlight.
// Its fields follow the grader contract in src/exercises/graders.js.
import { NDF_TERMS, microfacetBRDFAt } from '../../math/brdf.js';
import { matchNdfWidths } from '../../math/ndf-width.js';
import { DEG } from '../../math/angles.js';
import { termOptions } from '../../math/catalogue/index.js';
import { sphereRadiance } from '../sphere-image.js';
import { fmt, pct, times } from './feedback.js';

/** The terms' one labels (src/math/catalogue), as graders' choices and in their feedback. */
export const NDF_NAMES = termOptions('ndf');

/** D(θh) / D(0) over θh = 0°, 0.25°, … 89.75° for each NDF at a matched half width. */
export function ndfProfiles(hwhm, shapes) {
  const params = matchNdfWidths(hwhm, shapes);
  const out = {};
  for (const kind of Object.keys(NDF_NAMES)) {
    const D = (deg) => NDF_TERMS[kind](Math.cos(deg * DEG), params[kind]);
    const peak = D(0);
    out[kind] = Float64Array.from({ length: 360 }, (_, i) => D(i * 0.25) / peak);
  }
  return out;
}

/**
 * The largest factor between two profiles (max of a/b and b/a) where `ref` is at least `floor` of its peak —
 * the part of a highlight a picture shows at 1/floor exposure — and where it is (θh in degrees).
 */
export function profileFactor(a, ref, floor) {
  let worst = { factor: 1, deg: 0 };
  ref.forEach((r, i) => {
    if (r < floor) return;
    const f = Math.max(a[i] / r, r / a[i]);
    if (f > worst.factor) worst = { factor: f, deg: i * 0.25 };
  });
  return worst;
}

/** The highlight an NDF makes on the sphere (the exercise's preview): F = 1, implicit visibility: its shape is D's. */
export function highlightSphere(kind, { hwhm, abcA2, sgdP, lightTheta }, size = 96) {
  const p = { F: 'one', D: kind, V: 'implicit', ...matchNdfWidths(hwhm, { abcA2, sgdP })[kind] };
  return sphereRadiance(size, lightTheta, (a) => microfacetBRDFAt(a, p));
}

export const grader = {
  title: 'Which NDF made the highlight',
  summary:
    'The page shows a highlight made by a hidden NDF (`hidden`, or a random one) at half width `hwhm`; a ' +
    'choice is right when its profile D(θh)/D(0) at that width matches the highlight’s wherever the highlight ' +
    'is at least `floor` of its peak.',
  answer: { kind: 'choice', choices: () => NDF_NAMES },
  widget: null,
  params: {
    hidden: { type: 'enum', options: { random: 'random', ...NDF_NAMES }, default: 'random', label: 'hidden NDF' },
    hwhm: { type: 'number', min: 1, max: 40, default: 5, label: 'half width (°)' },
    floor: { type: 'number', min: 1e-4, max: 0.5, default: 0.01, label: 'floor' },
    abcA2: { type: 'number', min: 0.5, max: 10, default: 2.5, label: 'ABC a2' },
    sgdP: { type: 'number', min: 0, max: 1.9, default: 0.64, label: 'SGD p' },
    lightTheta: { type: 'number', min: 0, max: 80, default: 30, label: 'light angle from the view (°)' },
  },
  tolerance: 'largest factor (≥ 1) allowed between the two profiles where the highlight is above the floor',
  /** Well posed: whichever NDF is hidden, no other is within the tolerance of it (one right answer). */
  check(params, tolerance) {
    const profiles = ndfProfiles(params.hwhm, params);
    const hidden = params.hidden === 'random' ? Object.keys(NDF_NAMES) : [params.hidden];
    const problems = [];
    for (const h of hidden) {
      for (const k of Object.keys(NDF_NAMES)) {
        const f = k === h ? Infinity : profileFactor(profiles[k], profiles[h], params.floor).factor;
        if (f <= tolerance) {
          problems.push(
            `at a half width of ${params.hwhm}° ${NDF_NAMES[k]} is within ${fmt(f, 3)}× of ${NDF_NAMES[h]}, ` +
              `inside the tolerance ${fmt(tolerance, 3)}: two answers would be right`,
          );
        }
      }
    }
    return problems;
  },
  /** The hidden NDF: the one named, or one drawn by `random` (the page seeds it: the same seed, the same NDF). */
  hide(params, random = Math.random) {
    if (params.hidden !== 'random') return params.hidden;
    const kinds = Object.keys(NDF_NAMES);
    return kinds[Math.floor(random() * kinds.length)];
  },
  grade({ answer, params, tolerance, hidden }) {
    const profiles = ndfProfiles(params.hwhm, params);
    const mine = profileFactor(profiles[answer], profiles[hidden], params.floor);
    const where = `wherever the highlight is above ${pct(params.floor)} of its peak`;
    const verdict =
      mine.factor - 1 < 1e-9
        ? `${NDF_NAMES[answer]} made it: its profile is the highlight’s`
        : `${NDF_NAMES[answer]}’s profile is within ${pct(mine.factor - 1)} of the highlight’s ${where}`;
    if (mine.factor <= tolerance)
      return {
        ok: true,
        summary: `Right: ${verdict} (profiles within ${pct(tolerance - 1)} of each other ${where} count).`,
        details: [],
      };
    const side =
      profiles[answer][Math.round(mine.deg / 0.25)] > profiles[hidden][Math.round(mine.deg / 0.25)]
        ? 'brighter'
        : 'darker';
    return {
      ok: false,
      summary:
        `${NDF_NAMES[answer]}’s profile is ${times(mine.factor)} ${side} than the highlight’s at θh = ` +
        `${fmt(mine.deg)}°; a match needs ≤ ${fmt(tolerance, 3)}×.`,
      details: [
        side === 'brighter'
          ? 'The highlight’s tail falls off faster than your choice’s.'
          : 'The highlight’s tail reaches further than your choice’s.',
      ],
    };
  },
};
