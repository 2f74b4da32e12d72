// Special functions the shading terms need and JavaScript lacks. Float64, accurate to ~1e-15.

const TWO_OVER_SQRT_PI = 2 / Math.sqrt(Math.PI);

/** erfc(x) for x >= 0 by its continued fraction (Lentz-free backward evaluation), used for x >= 2.5. */
function erfcContinuedFraction(x) {
  let f = x;
  for (let n = 80; n >= 1; n--) f = x + n / 2 / f;
  return Math.exp(-x * x) / (Math.sqrt(Math.PI) * f);
}

/** The error function. Taylor series below 2.5 (alternating terms stay below e^6.25), continued fraction above. */
export function erf(x) {
  const ax = Math.abs(x);
  if (ax >= 2.5) return Math.sign(x) * (1 - erfcContinuedFraction(ax));
  let term = ax;
  let sum = ax;
  const x2 = ax * ax;
  for (let n = 1; n < 100; n++) {
    term *= -x2 / n;
    const add = term / (2 * n + 1);
    sum += add;
    if (Math.abs(add) < 1e-17 * Math.abs(sum)) break;
  }
  return Math.sign(x) * TWO_OVER_SQRT_PI * sum;
}

/** erfc(x) = 1 - erf(x), without cancellation for large x. */
export function erfc(x) {
  return x >= 2.5 ? erfcContinuedFraction(x) : 1 - erf(x);
}
