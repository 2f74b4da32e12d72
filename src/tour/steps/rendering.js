// The tour's steps for the section "From math to rendering" (src/tour/steps.js puts the sections together).
export const STEPS = [
  {
    id: 'rendering-punctual',
    widget: 'material-lab',
    title: 'Punctual lights and c_light',
    state: {
      env: false,
      punctual: true,
      lightTheta: 0,
      cLight: 1,
      layers: 'diffuse',
      cdiff: '#ffffff',
      refSamples: '128',
    },
    text:
      'A punctual light is a direction and a colour. Its colour $\\mathbf{c}_{\\text{light}}$ is defined as the ' +
      'radiance of a white Lambertian surface that faces it: the centre of this white sphere shows exactly ' +
      '$\\mathbf{c}_{\\text{light}}$. The integral collapses to $L_o = \\pi f(\\mathbf{l}_c, \\mathbf{v}) \\otimes ' +
      '\\mathbf{c}_{\\text{light}} (\\mathbf{n} \\cdot \\mathbf{l}_c)$; the $\\pi$ is what turns a BRDF into that ' +
      'definition.',
  },
  {
    id: 'rendering-area',
    widget: 'material-lab',
    title: 'Area lights have a size',
    state: {
      env: false,
      punctual: false,
      area: true,
      areaRadius: 15,
      material: 'silver',
      alpha: 0.1,
      refSamples: '128',
      errorScale: 0.2,
    },
    text:
      'A real lamp has a size, and on a smooth surface its reflection shows it. The representative-point ' +
      'approximation bends the light direction towards the reflected ray to draw a highlight of the right shape; ' +
      'the reference integrates over the sphere light, and the error image shows what the shortcut misses.',
  },
  {
    id: 'rendering-mirror',
    widget: 'material-lab',
    title: 'Image-based lighting: a mirror',
    state: {
      material: 'silver',
      alpha: 0.01,
      punctual: false,
      envMethod: 'mirror',
      environment: 'studio',
      refSamples: '128',
    },
    text:
      'For an optically flat surface, image-based lighting is easy: the environment seen in the mirror ' +
      'direction, times Fresnel at the angle between view and normal. On this near-mirror the error is small.',
  },
  {
    id: 'rendering-split-sum',
    widget: 'material-lab',
    title: 'Glossy reflections by prefiltering',
    state: {
      material: 'gold',
      alpha: 0.3,
      punctual: false,
      envMethod: 'split-sum',
      environment: 'studio',
      refSamples: '128',
    },
    text:
      'A glossy surface needs the environment averaged over its lobe. Prefiltering does that once per ' +
      'roughness and splits off the rest of the BRDF into a small table (the split sum): cheap, and close to the ' +
      'reference except at grazing angles, where its assumption that the view looks straight at the surface fails.',
  },
  {
    id: 'rendering-importance',
    widget: 'material-lab',
    title: 'Glossy reflections by importance sampling',
    state: {
      material: 'gold',
      alpha: 0.3,
      punctual: false,
      envMethod: 'importance',
      samples: 16,
      environment: 'studio',
      refSamples: '128',
    },
    text:
      'Importance sampling takes a few directions where the BRDF is large and averages the environment ' +
      'there. With 16 samples the same pattern repeats on every pixel; more samples converge on the reference ' +
      'at a proportional cost. Raise N and watch the RMS error fall.',
  },
  {
    id: 'rendering-models',
    widget: 'lighting-models',
    title: 'From general lighting to ambient',
    state: { refSamples: '128' },
    text:
      'The illumination models side by side on one sky with an enlarged sun (2°; the real one is 0.27°): ' +
      'general lighting (the reference), ' +
      'image-based, area, punctual and ambient light. Each step down is cheaper and assumes more about where ' +
      'light comes from; the table says how much each costs and how far it falls from the reference.',
  },
];
