// The tour's steps for the section "The BRDF and the reflectance equation" (src/tour/steps.js puts the
// sections together).
export const STEPS = [
  {
    id: 'brdf-radiance',
    widget: 'radiance',
    title: 'Light as a number: radiance',
    state: { distance: 4, lampRadius: 0.05, light: 'daylight', surface: 'grey' },
    text:
      'Shading measures light as radiance: power along a single ray, per area across it and per solid angle ' +
      'around it. Radiance does not fade with distance: the lamp, 4 m away here, is smaller than at 1 m but no ' +
      'dimmer. What fades is the irradiance a surface receives from the whole lamp, as $1/d^2$ (16 times less than ' +
      'at 1 m). Drag the distance and watch the two curves.',
  },
  {
    id: 'brdf-spectral',
    widget: 'radiance',
    title: 'Spectra become RGB',
    state: { distance: 1, light: 'sodium', surface: 'red' },
    text:
      'Light is a spectrum, but a renderer keeps three numbers and multiplies them channel by channel (the ⊗ ' +
      'of the reflectance equation). Under a sodium lamp, whose light sits almost all at 589 nm, that shortcut ' +
      'makes this red paint’s red channel 2.4 times too bright. Under the daylight-like white the two agree.',
  },
  {
    id: 'brdf-lobe',
    widget: 'brdf-lobe',
    title: 'The BRDF f(l, v)',
    state: { lightTheta: 30, viewTheta: 30, alpha: 0.2 },
    text:
      'With shading local, a surface point answers one question: of the light arriving from l, how much ' +
      'leaves towards v? That is the BRDF, defined only for l and v above the surface. Fix the light (here at ' +
      '30°, on a fairly smooth surface, α = 0.2) and sweep the view, and f traces a lobe around the mirror ' +
      'direction: 0.11 per steradian at its peak, at 31°, and 0.03 towards the horizon. Drag l or v on the ' +
      'polar plot.',
  },
  {
    id: 'brdf-intensity',
    widget: 'brdf-lobe',
    title: 'BRDF times the cosine',
    state: { lightTheta: 60, viewTheta: 60, cosine: true, alpha: 0.3 },
    text:
      'The BRDF is a density per steradian, and it can be large where little light goes. On this rougher ' +
      'surface (α = 0.3, light at 60°) f is largest at the horizon: 1.00 per steradian at θv = 89°, against 0.22 ' +
      'in the mirror direction (at α = 0.1 it would peak near the mirror direction). But seen from near the ' +
      'horizon the lit patch looks thin, so the light it sends per steradian towards v is f times the cosine of ' +
      'the view angle, n·v. That product is the lobe drawn here: it peaks near 70° and falls to nothing at the ' +
      'horizon. It is not the cosine of the reflectance equation, n·l, which weighs the light arriving from ' +
      'each direction l (the albedo plot adds that up).',
  },
  {
    id: 'brdf-factors',
    widget: 'brdf-lobe',
    title: 'Taking the BRDF apart',
    state: { lightTheta: 60, viewTheta: 60, useDenominator: false },
    text:
      'A microfacet BRDF is $\\frac{F\\,G\\,D}{4 \\nl\\nv}$. Here the denominator is switched off: the lobe stops ' +
      'growing at grazing angles. Turn factors off one at a time to see what each contributes.',
  },
  {
    id: 'brdf-compare',
    widget: 'brdf-lobe',
    title: 'Two BRDFs side by side',
    state: { compare: true, lightTheta: 30, viewTheta: 30 },
    text:
      'Overlay a second BRDF (dashed) at the same width: GGX against Beckmann. The images over the half and ' +
      'difference angles (θh, θd) show the same functions in the coordinates they really depend on.',
  },
];
