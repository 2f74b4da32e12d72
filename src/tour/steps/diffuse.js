// The tour's steps for the section "Diffuse" (src/tour/steps.js puts the sections together).
export const STEPS = [
  {
    id: 'diffuse-lambert',
    widget: 'diffuse-explorer',
    title: 'Lambert: the same from every direction',
    state: { diffuse: ['lambert'], lightTheta: 50, lightPhi: 30 },
    text:
      'Light that enters a non-metal, scatters inside and comes out again close to where it went in is seen from ' +
      'afar as diffuse reflection. Lambert’s model makes it a constant, ' +
      '$\\frac{\\mathbf{c}_{\\text{diff}}}{\\pi}$: the sphere’s brightness follows $\\nl$ alone and does not ' +
      'depend on where you look from.',
  },
  {
    id: 'diffuse-tradeoff',
    widget: 'diffuse-explorer',
    title: 'The diffuse–specular trade-off',
    state: { diffuse: ['lambert', 'fresnelWeighted', 'ashikhminShirley'], lightTheta: 70, lightPhi: 0 },
    text:
      'Light reflected at the surface never enters it, so it cannot come back out as diffuse. Where Fresnel ' +
      'reflects more, at grazing angles, there must be less diffuse. Plain Lambert ignores this; the ' +
      'Fresnel-weighted and Ashikhmin–Shirley terms dim towards the rim to keep the budget at most 1.',
  },
  {
    id: 'diffuse-full-moon',
    widget: 'diffuse-explorer',
    title: 'Rough diffuse: the full moon',
    state: { diffuse: ['lambert', 'orenNayar', 'orenNayarQualitative'], sigma: 40, lightTheta: 0, lightPhi: 0 },
    text:
      'When the surface is rough on a scale larger than the distance light travels inside it, the bumps ' +
      'themselves shade each other. Lit from behind the viewer, a rough sphere looks flatter, towards the look ' +
      'of the full moon: near the rim, 95% of the radius out, Oren–Nayar at σ = 40° is still 0.71 as bright as ' +
      'the centre (its qualitative form 0.80), where Lambert, following n·l, has fallen to 0.31.',
  },
];
