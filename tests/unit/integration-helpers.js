// Independent numerical integrals for the tests (not the app's own integrate.js).

/**
 * ∫ D(m)(n·m) dω for D depending on c = n·m only: 2π ∫_0^1 D(c) c dc, by the midpoint rule in t with
 * c = 1 - t^4, which puts most samples near c = 1 where narrow lobes live.
 */
export function projectedNdfIntegral(D, n = 40000) {
  let sum = 0;
  for (let i = 0; i < n; i++) {
    const t = (i + 0.5) / n;
    const c = 1 - t ** 4;
    sum += D(c) * c * 4 * t ** 3;
  }
  return (2 * Math.PI * sum) / n;
}
