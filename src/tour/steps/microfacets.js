// The tour's steps for the section "Microfacet theory" (src/tour/steps.js puts the sections together).
export const STEPS = [
  {
    id: 'microfacets-half-vector',
    widget: 'microfacets',
    title: 'The half vector',
    state: { lightTheta: 35, viewTheta: -15, alpha: 0.5, bounces: false },
    text:
      'Each microfacet is a perfect mirror, so it reflects l into v only if its normal m lies halfway between ' +
      'them: $\\mathbf{m} = \\mathbf{h}$. The marked facets are the only ones that send this light to the eye; ' +
      '$D(\\mathbf{h})$ counts how many there are.',
  },
  {
    id: 'microfacets-shadowing',
    widget: 'microfacets',
    title: 'Shadowing and masking',
    state: { lightTheta: 75, viewTheta: -60, alpha: 0.6, bounces: false },
    text:
      'Not every facet facing along h contributes: some are hidden from the light (shadowed, solid black) ' +
      'and some from the eye (masked, hollow blue). Towards grazing angles more are lost; the plot compares the ' +
      'ray-traced share with Smith’s G1.',
  },
  {
    id: 'microfacets-anisotropic-shadowing',
    widget: 'anisotropic-microsurface',
    title: 'Shadowing on a brushed surface',
    state: { alphaX: 0.6, alphaY: 0.2, theta: 75, phi: 0, seed: 3 },
    text:
      'Beyond the talk: the same ray tracing on a 3-D surface whose bumps are stretched, rougher along the tangent ' +
      't (αx = 0.6) than along b (αy = 0.2). Light arriving along t (φ = 0°) crosses the steep slopes and is ' +
      'shadowed more than light running along the grooves (φ = 90°). Smith’s G1 follows this by using the ' +
      'roughness seen along the light’s azimuth, and the ray-traced points lie on its curve. The green points, ' +
      'facets tilted away from the light, lie below it: Smith ignores that which way a facet tilts changes how ' +
      'often it is shadowed.',
  },
  {
    id: 'microfacets-bounces',
    widget: 'microfacets',
    title: 'Light that bounces twice',
    state: { kind: 'ggx', alpha: 1, lightTheta: 60, viewTheta: -40, bounces: true },
    text:
      'Blocked light does not vanish: it bounces again (red) and some of it still reaches the eye. The ' +
      'microfacet BRDF drops it, so it assumes all blocked light is lost.',
  },
  {
    id: 'microfacets-furnace',
    widget: 'energy',
    title: 'The energy that is lost',
    state: {},
    look: '.sphere-grid',
    text:
      'How much does dropping the second bounces cost? In a uniform white environment a surface that loses ' +
      'nothing would vanish. In the row of spheres below the plots the smoothest nearly does; rougher ones stay ' +
      'grey, and at α = 1 most of the light arriving head-on is lost (the table has the figures).',
  },
  {
    id: 'microfacets-furnace-fixed',
    widget: 'energy',
    title: 'The lost energy, found',
    state: { compensation: 'kullaConty', metal: 'gold', metalAlpha: 0.8 },
    look: '.sphere-grid',
    text:
      'With an energy compensation switched on (here Kulla–Conty) the dropped light is put back, and the row of ' +
      'spheres below the plots looks empty: each sphere, at every roughness, is now as bright as the white around ' +
      'it (point at one: the probe’s compensated albedo reads 1.0000). It matters most on a metal (the plot and ' +
      'table under the spheres): rough gold (α = 0.8) seen head-on reflects 43% of red, 30% of green and 12% of ' +
      'blue light in one bounce; followed through every bounce (the random walk) it reflects 100%, 56% and 16%, ' +
      'brighter and more saturated (a channel that reflects more gets more of its lost light back). Kulla–Conty ' +
      'comes within 0.02 of the walk; Turquin overshoots green by 0.03.',
  },
  {
    id: 'microfacets-multiple-lobe',
    widget: 'brdf-lobe',
    title: 'Putting the lost light back',
    state: { multiple: true, alpha: 1, F: 'one', lightTheta: 30, viewTheta: 20 },
    text:
      'The talk stops at the loss; renderers since Kulla & Conty (2017) add it back as a second, nearly diffuse ' +
      'lobe (dotted), built so that the white furnace closes. The dots are the truth it approximates: light walked ' +
      'from facet to facet until it escapes (Heitz et al. 2016). At α = 1 with F = 1 the returned lobe is larger ' +
      'than the single-scattering one here: 0.24 against 0.09 per steradian at these angles.',
  },
];
