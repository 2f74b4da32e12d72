// The visibility explorer's state: the roughness, how l and v move for the plots, which terms are drawn, and
// the spheres' light and exposure.

/** The geometry/visibility terms of the talk (and the cheaper ones in use): labels and shader switches. */
export const TERMS = {
  implicit: { name: 'Implicit (V = 1)', define: 'VIS_IMPLICIT' },
  cookTorrance: { name: 'Cook-Torrance', define: 'VIS_COOK_TORRANCE' },
  kelemen: { name: 'Kelemen 1/(l·h)²', define: 'VIS_KELEMEN' },
  smithGGXSeparable: { name: 'Smith GGX, separable', define: 'VIS_SMITH_GGX_SEPARABLE' },
  smithGGXCorrelated: { name: 'Smith GGX, height-correlated', define: 'VIS_SMITH_GGX_CORRELATED' },
  smithGGXCorrelatedFast: { name: 'Hammon 2017 approx.', define: 'VIS_SMITH_GGX_CORRELATED_FAST' },
  schlickGGX: { name: 'Schlick-GGX (k = α/2)', define: 'VIS_SCHLICK_GGX' },
  smithBeckmannSeparable: { name: 'Smith Beckmann, separable', define: 'VIS_SMITH_BECKMANN_SEPARABLE' },
};

export const schema = {
  alpha: { type: 'number', min: 0.01, max: 1, step: 0.01, default: 0.5, label: 'Roughness α' },
  config: {
    type: 'enum',
    options: { mirror: 'l, v mirrored about n (h = n)', 'view-fixed': 'View fixed, light sweeps' },
    default: 'view-fixed',
    label: 'Directions',
  },
  viewTheta: { type: 'number', min: 0, max: 85, step: 1, default: 60, label: 'View angle (view fixed)', unit: '°' },
  terms: {
    type: 'set',
    options: Object.fromEntries(Object.entries(TERMS).map(([k, v]) => [k, v.name])),
    default: [
      'implicit',
      'cookTorrance',
      'kelemen',
      'smithGGXSeparable',
      'smithGGXCorrelated',
      'smithGGXCorrelatedFast',
      'schlickGGX',
    ],
    label: 'Terms',
  },
  lightTheta: { type: 'number', min: 0, max: 85, step: 1, default: 30, label: 'Sphere light from view', unit: '°' },
  exposure: { type: 'number', min: 0.1, max: 20, step: 0.1, default: 1.5, label: 'Sphere exposure' },
};
