// microfacets, in words: the about text, the legend of the cut's colours, and the picture described for screen
// readers.
import { schema } from './schema.js';

export const TITLE = 'Microsurface';

export const ABOUT =
  'A cut through a rough surface, magnified: every facet is a tiny mirror. Yellow rays come from the light; ' +
  'a facet sends light to the eye only if its normal is the half vector h (marked in magenta). Black stretches ' +
  'are shadowed (the light cannot reach them), blue ones masked (the eye cannot see them). Some reflected rays ' +
  'hit the surface again (red): the microfacet BRDF drops that light. The plot ray-traces a profile of ' +
  '80 000 facets and compares the share of lit facets with Smith’s G1 for the same roughness.';

const key = (color, mark, text) => `<span style="color:${color}">${mark}</span> ${text}`;
export const LEGEND_HTML = [
  key('#e6a700', '━', 'light rays'),
  key('#d62728', '━', 'second bounce'),
  key('#cc79a7', '▮', 'facet normal = h'),
  key('#111', '▬', 'shadowed (solid)'),
  key('#0072b2', '▭', 'masked (hollow)'),
].join(' &nbsp; ');

/** The shadowed share, 1 − G1, as a percentage. */
export const shadowedShare = (g1, digits) => `${((1 - g1) * 100).toFixed(digits)}%`;

/** The picture in words; `hDeg` is the half vector's angle from the mean normal. */
export function describeCut(state, { measured, smith, twice, hDeg }) {
  const s = state;
  return (
    `Magnified cross-section of a rough surface, ${schema.kind.options[s.kind]}, α ${s.alpha}: ` +
    `${s.rays} rays from the light at ${s.lightTheta}°, eye at ${s.viewTheta}°, so the half vector h is ` +
    `${hDeg.toFixed(1)}° from the mean normal; facets along h are marked. Shadowed share of the facets facing ` +
    `the light: ${shadowedShare(measured, 1)} ray-traced, ${shadowedShare(smith, 1)} by Smith. ` +
    `${twice} of ${s.rays} rays hit the surface a second time${s.bounces ? ' (drawn in red)' : ''}.`
  );
}
