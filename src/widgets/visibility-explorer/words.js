// The visibility explorer's words: what it shows, the functions it names, and its pictures described for
// screen readers.

export const TITLE = 'Visibility explorer';

export const ABOUT =
  'The plots show G = V·(n·l)(n·v), the share of microfacets that are neither shadowed nor masked, so that ' +
  'all terms share one scale. The implicit term is G = (n·l)(n·v): it falls too soon and is the same at every ' +
  'roughness. Change α and watch which curves move. The error plot measures each term against ' +
  'height-correlated Smith. With l and v mirrored about n, h = n and both Cook-Torrance and Kelemen give G = 1 ' +
  'exactly. On the spheres (GGX D, F = 1) the differences show at the silhouettes, where the ' +
  'angles are grazing.';

/** The functions behind the pictures, linked to their rows on the parity page. */
export const TERMS_USED = [
  'visibilityImplicit',
  'visibilityCookTorrance',
  'visibilityKelemen',
  'visibilitySmithGGXSeparable',
  'visibilitySmithGGXCorrelated',
  'visibilitySmithGGXCorrelatedFast',
  'visibilitySchlickGGX',
  'visibilitySmithBeckmannSeparable',
  'microfacetBRDF',
];

/** The x axis of both plots, by how l and v move. */
export const angleAxisLabel = (state) =>
  state.config === 'mirror'
    ? 'Angle of l and of v from n (degrees)'
    : `Light angle θl, view fixed at ${state.viewTheta}° (degrees)`;

/** The spheres in words: the light, and each term's largest difference from height-correlated Smith. */
export function describeSpheres(curves, state) {
  const where = state.config === 'mirror' ? 'l and v mirrored' : `view at ${state.viewTheta}°`;
  const worst = curves.map((c) => `${c.label} ${c.worst.toFixed(1)}%`).join(', ') || 'no term chosen';
  return (
    `Spheres with GGX D at α ${state.alpha} and F = 1, light ${state.lightTheta}° from the view, ` +
    `exposure ${state.exposure}, one per visibility term. ` +
    `Largest difference from height-correlated Smith up to 80° (${where}): ${worst}.`
  );
}
