// The tour's steps for the section "Light in media" (src/tour/steps.js puts the sections together).
export const STEPS = [
  {
    id: 'media-straight-line',
    widget: 'media',
    title: 'Light in a clear medium',
    state: { medium: 'water', distance: 0 },
    text:
      'Where a medium is the same everywhere, light travels in straight lines. The glass here, the square inside ' +
      'a border of bare wall, holds a metre of clean water: the chequered wall shows through it sharp and ' +
      'undistorted, only tinted a little blue-green, since a metre of water lets 73% of red light through, 96% of ' +
      'green and 97% of blue. Five centimetres would leave the glass invisible: 98% of red gets across.',
  },
  {
    id: 'media-water-depth',
    widget: 'media',
    title: 'Absorption depends on distance',
    state: { medium: 'water', distance: 1.5 },
    text:
      'Water does absorb a little red. Over centimetres that is invisible, but Beer–Lambert makes the loss ' +
      'exponential in depth: after about thirty metres almost no red is left and the light is blue-green. ' +
      'The plot below follows each channel from a millimetre to a hundred metres.',
  },
  {
    id: 'media-red-absorber',
    widget: 'media',
    title: 'Absorption changes colour',
    state: { medium: 'red', distance: -1.3 },
    text:
      'A stronger absorber that takes far more blue and green than red (an illustrative one, wine-like) tints ' +
      'light within a centimetre: 1 cm leaves 97% of red, 55% of green and 41% of blue; the 5 cm shown leave 86%, ' +
      '5% and 1%. Absorption changes how much light there is and what colour it has, never its direction.',
  },
  {
    id: 'media-scattering',
    widget: 'media',
    title: 'Scattering makes a medium cloudy',
    state: { medium: 'cloudy', distance: -1.3 },
    text:
      'Particles whose index of refraction differs from their surroundings turn light aside. A few of them ' +
      'blur the wall behind the glass; the light is not lost, it leaves in other directions.',
  },
  {
    id: 'media-grid',
    widget: 'media',
    title: 'Absorption and scattering together',
    state: { view: 'grid', samples: '64' },
    text:
      'The talk’s grid of glasses: absorption grows upwards, scattering to the right. Strong scattering with ' +
      'little absorption (bottom right) sends light back out in every direction: the medium looks white and ' +
      'opaque, like milk.',
  },
];
