// The tour's steps for the section "Surfaces and microgeometry" (src/tour/steps.js puts the sections together).
export const STEPS = [
  {
    id: 'surfaces-flat',
    widget: 'surfaces',
    title: 'An optically flat surface',
    state: { material: 'glass-high', theta: 40, alpha: 0.02 },
    text:
      'A surface is a sudden change of refractive index. When its bumps are smaller than a wavelength it is ' +
      'optically flat and splits light into exactly two directions, reflected and refracted; the Fresnel ' +
      'equations give the split (here 8.7% and 91.3%, drawn at the top). The plot under that picture is set to ' +
      'the smoothest microsurface the widget has, α = 0.02, nearly flat: the reflected light leaves in one narrow ' +
      'spike at the mirror direction, −40°.',
  },
  {
    id: 'surfaces-metal',
    widget: 'surfaces',
    title: 'Metals and non-metals',
    state: { material: 'copper', theta: 40 },
    text:
      'What happens to the refracted light depends on the material. A metal absorbs it within nanometres, so ' +
      'all we see is the reflection; a non-metal (switch the material back to glass) scatters it inside, and some ' +
      'comes back out elsewhere.',
  },
  {
    id: 'surfaces-rough',
    widget: 'surfaces',
    title: 'Rougher means blurrier',
    state: { material: 'glass-high', theta: 30, alpha: 0.5 },
    text:
      'Most surfaces have microgeometry: facets too small to see but larger than a wavelength. Each one is a ' +
      'mirror, but they face different ways, so the reflection spreads into a cone, and the ray-traced histogram ' +
      'follows the microfacet prediction. The spheres below show the result: rougher, blurrier reflections.',
  },
  {
    id: 'subsurface-local',
    widget: 'subsurface-scale',
    title: 'When diffuse is local',
    state: { pixel: 4 },
    text:
      'Light refracted into a non-metal wanders and re-emerges some distance from where it entered. If a pixel’s ' +
      'footprint on the surface is much wider than that distance, we may pretend it comes out where it went in: ' +
      'shading stays local, and this re-emerging light is the diffuse term.',
  },
  {
    id: 'subsurface-needed',
    widget: 'subsurface-scale',
    title: 'When subsurface scattering is needed',
    state: { pixel: 0.3 },
    text:
      'Shrink the shading sample below the typical exit distance (a close-up of skin, say) and most of the ' +
      'light leaves outside it. The physics is the same as diffuse; only the scale has changed, and now ' +
      'subsurface scattering has to be rendered.',
  },
];
