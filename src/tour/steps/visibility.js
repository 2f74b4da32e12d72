// The tour's steps for the section "Geometry and visibility terms" (src/tour/steps.js puts the sections together).
export const STEPS = [
  {
    id: 'visibility-terms',
    widget: 'visibility-explorer',
    title: 'The visibility term',
    state: { config: 'view-fixed', viewTheta: 60, alpha: 0.5 },
    text:
      'G gives the share of facets along h that are neither shadowed nor masked; the talk folds it with the ' +
      'denominator into $V = \\frac{G}{\\nl\\nv}$. The plots show G for every term against the light angle, and ' +
      'how far each is from height-correlated Smith.',
  },
  {
    id: 'visibility-implicit',
    widget: 'visibility-explorer',
    title: 'The implicit term ignores roughness',
    state: { config: 'view-fixed', viewTheta: 60, alpha: 0.1 },
    text:
      'The implicit term, $G = \\nl\\nv$, costs nothing but is the same at every roughness. At $\\alpha = 0.1$ the ' +
      'Smith terms stay near 1 until grazing angles, while the implicit one is at most $\\nv = 0.5$ here and falls ' +
      'with the light’s cosine.',
  },
  {
    id: 'visibility-mirror',
    widget: 'visibility-explorer',
    title: 'Cook-Torrance and Kelemen',
    state: { config: 'mirror', alpha: 0.5 },
    text:
      'With l and v mirrored about the normal, $\\mathbf{h} = \\mathbf{n}$: Cook-Torrance and Kelemen both give $G ' +
      '= 1$ whatever the angle, while the Smith terms darken towards grazing.',
  },
  {
    id: 'visibility-smith',
    widget: 'visibility-explorer',
    title: 'The Smith family',
    state: { alpha: 0.8, V: ['smithGGXSeparable', 'smithGGXCorrelated', 'smithGGXCorrelatedFast', 'schlickGGX'] },
    text:
      'Smith’s terms are derived from the NDF itself. The height-correlated form is the more accurate; the ' +
      'separable form shadows a little too much. The error plot shows how closely the cheaper approximations ' +
      'follow it, and where they part.',
  },
];
