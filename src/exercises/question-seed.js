// A question with a hidden part (which NDF made the highlight) is drawn from a seed that the page keeps in its
// address (?seed=N) and shows: a reload or a shared link poses the same question, a new seed another one.
import { seededRandom } from '../math/microsurface.js';

export const MAX_SEED = 9999;

/**
 * The seed of `value` (the address's seed=, or null) when it is a whole number 1…MAX_SEED; otherwise a new one
 * drawn by `random`, with `problem` saying why when a value was given.
 */
export function readSeed(value, random = Math.random) {
  const n = Number(value);
  if (value !== null && value !== '' && Number.isInteger(n) && n >= 1 && n <= MAX_SEED)
    return { seed: n, problem: null };
  const seed = 1 + Math.floor(random() * MAX_SEED);
  const problem =
    value === null ? null : `seed=${value} is not a whole number from 1 to ${MAX_SEED}: question ${seed} is shown.`;
  return { seed, problem };
}

/** Whether the grader's hidden part comes from the draw (an exercise file may name it instead). */
export const drawsHidden = (grader, params) =>
  Boolean(grader.hide) && grader.hide(params, () => 0) !== grader.hide(params, () => 0.999999);

/** The hidden part of question `seed`. */
export const hiddenFor = (grader, params, seed) => grader.hide?.(params, seededRandom(seed));
