// @ts-check
// Which catalogue term stretches which: an anisotropic D or V entry names, as `isotropic`, the term of its family it
// equals at αx = αy (ggxAniso → ggx). The hosts that stretch a chosen term (the material lab, the BRDF lobe, the
// NDF explorer) look its anisotropic form up here, so a new anisotropic entry is offered with no edit of theirs.
import { CATALOGUE } from './index.js';

/**
 * The anisotropic entry of `family` that stretches the term `key`, or null when the catalogue has none.
 * @param {'ndf' | 'visibility'} family
 * @param {string} key
 * @returns {import('./types.js').TermEntry | null}
 */
export const anisotropicForm = (family, key) =>
  Object.values(CATALOGUE[family].terms).find((term) => term.isotropic === key) ?? null;
