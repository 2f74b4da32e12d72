// The tour's steps for the section "Normal distribution functions" (src/tour/steps.js puts the sections together).
export const STEPS = [
  {
    id: 'ndf-matched',
    widget: 'ndf-explorer',
    title: 'Five NDFs at one width',
    state: { hwhm: 8 },
    text:
      'The normal distribution function D(h) is the density of facets facing along h: it sets the size and ' +
      'shape of the highlight. Given the same half width, the five distributions of the talk share a core and ' +
      'differ in shape.',
  },
  {
    id: 'ndf-tails',
    widget: 'ndf-explorer',
    title: 'Long tails, soft halos',
    state: { hwhm: 8, exposure: 8 },
    text:
      'On the log plot the tails part ways: GGX, ABC and the shifted gamma keep many more facets far from the ' +
      'peak than Beckmann or Blinn-Phong. Raised exposure shows what that does: a glow around the highlight.',
  },
  {
    id: 'ndf-rough',
    widget: 'ndf-explorer',
    title: 'Roughness is width',
    state: { hwhm: 25 },
    text:
      'Widen the distribution and the highlight grows and dims. D is normalised, so the projected area of ' +
      'the facets always integrates to one, as the table measures.',
  },
  {
    // numbers from src/widgets/ndf-explorer/model.js's ndfCurves at this state (Burley's convention, the default)
    id: 'ndf-anisotropic',
    widget: 'ndf-explorer',
    title: 'Beyond the talk: stretched highlights',
    state: { hwhm: 8, D: ['ggx', 'beckmann'], anisotropy: 0.8 },
    look: '.slope-maps',
    text:
      'This goes beyond the talk, whose NDFs are the same in every direction around n. Brushed metal is not: ' +
      'Heitz (2014) gives GGX and Beckmann one roughness along a tangent and another across it, and Burley (2012) ' +
      'maps one roughness and an anisotropy to the pair. At anisotropy 0.8, GGX’s α = 0.21 becomes ' +
      '(αx, αy) = (0.40, 0.11): the highlight stretches along the tangent, left to right, to a half width of 16° ' +
      'against 4° across it, and the slope maps below draw the lobe as an ellipse.',
  },
];
