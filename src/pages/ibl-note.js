// Said under the image-based lighting figures (performance page and docs/performance.md) while they predate the
// split sum's current DFG tables: the float64 quadrature, one table per (D, V) pair (issue 11), in place of a 32²
// Monte Carlo one.
export const DFG_QUADRATURE_SINCE = '2026-11-30';

/** The sentence for IBL rows measured on `date` (ISO), or '' once they were measured with the current tables. */
export function iblStaleNote(date) {
  const day = date.slice(0, 10);
  if (day >= DFG_QUADRATURE_SINCE) return '';
  return (
    `Measured ${day}, before the split sum's DFG table became the float64 quadrature (one table per D and V, ` +
    '72², shipped precomputed; it was a 32² Monte Carlo table): the split-sum rows may differ now. Rerun ' +
    '`npm run bench` to update.'
  );
}

/** An IBL row's method, with the direction an anisotropic case's split sum reads the light in. */
export const iblMethod = (r) =>
  r.bent === undefined ? r.method : `${r.method}, ${r.bent ? 'bent reflection' : 'mirror direction'}`;

/** An IBL row's method in words: importance sampling's N, else iblMethod. */
export const iblMethodWords = (r) => (r.samples ? `importance, N = ${r.samples}` : iblMethod(r));

/** An IBL row's case in words: environment, material, α and any anisotropy. */
export const iblCaseWords = (r) =>
  `${r.environment}, ${r.material} α ${r.alpha}${r.anisotropy ? `, anisotropy ${r.anisotropy}` : ''}`;
