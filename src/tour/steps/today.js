// The tour's steps for the section "After the talk: the material of today" (src/tour/steps.js puts the sections
// together).
export const STEPS = [
  {
    id: 'today-openpbr-layers',
    widget: 'brdf-lobe',
    title: 'After the talk: a layered material',
    state: {
      brdf: 'openpbr',
      base_color: '#b22222',
      specular_roughness: 0.5,
      coat_weight: 1,
      coat_roughness: 0.3,
      lightTheta: 45,
      viewTheta: 0,
      openpbrLayer: 'coat',
    },
    look: '.openpbr-layers',
    text:
      'Today’s standard material, OpenPBR Surface (2024), stacks the talk’s terms in layers: a base (diffuse or ' +
      'metal), its specular lobe, a clear coat and a fuzz. Here a red car paint sits under a full coat. Each ' +
      'line is one layer’s part of the lobe. Seen from 0°, 88% of the light is the base’s diffuse lobe; in the ' +
      'mirror direction, 45°, the coat makes 98.7% of it. Each layer passes on only what it does not reflect, ' +
      '1 − E(n·v) of the light. Set coat_weight to 0 in the OpenPBR folder: the base’s own gloss comes back.',
  },
];
