// The tour's steps for the section "Fresnel reflectance" (src/tour/steps.js puts the sections together).
export const STEPS = [
  {
    id: 'fresnel-curves',
    widget: 'fresnel-curves',
    title: 'Fresnel reflectance against angle',
    state: { materials: ['copper', 'aluminum', 'glass-low', 'diamond'], schlick: false, zones: true },
    text:
      'The share of light reflected by an optically flat surface depends on the material and on the angle. ' +
      'Up to about 45° it barely changes, to 75° it changes somewhat, and at grazing angles it rises quickly to ' +
      '100% for every material. Metals get one curve per colour channel.',
  },
  {
    id: 'fresnel-nv-glass',
    widget: 'fresnel-zones',
    title: 'Fresnel of n·v on a shape',
    state: { mode: 'fresnel-nv', material: 'glass-low', shape: 'sphere' },
    text:
      'Under even, directionless light the angle that matters is the one between the view and the normal. ' +
      'Glass on a sphere: about 3% reflected where it faces us, brightening to white at the silhouette.',
  },
  {
    id: 'fresnel-zones-nv',
    widget: 'fresnel-zones',
    title: 'Zones of n·v',
    state: { mode: 'zones-nv', shape: 'sphere' },
    text:
      'Colour the same angles by zone. Most of the picture lies where reflectance barely changes: for an ' +
      'orthographic sphere exactly $\\sin^2 45^\\circ = 50\\%$, then 43.3% where it changes somewhat, and only ' +
      '6.7% in the rapidly rising zone at the rim. The widget measures the shares on the GPU beside the analytic ' +
      'values.',
  },
  {
    id: 'fresnel-zones-lh',
    widget: 'fresnel-zones',
    title: 'Zones of l·h',
    state: { mode: 'zones-lh', shape: 'torusknot', lightTheta: 140 },
    text:
      'In a microfacet BRDF the facets that reflect are those facing along h, so Fresnel takes the angle ' +
      'between l and h. With the light behind the object the whole shape turns yellow or red. Move the light ' +
      'around (drag, or the arrow keys on the picture).',
  },
  {
    id: 'fresnel-zones-lh-weighted',
    widget: 'fresnel-zones',
    title: 'Weighted by the rest of the BRDF',
    state: { mode: 'zones-lh-weighted', shape: 'torusknot', lightTheta: 140, alpha: 0.3 },
    text:
      'Now weight each pixel by the light the rest of the BRDF actually sends to the eye. From behind, ' +
      'little light reaches the eye: only thin grazing edges stay bright. Averaged over light directions all ' +
      'around the object, at this roughness (GGX α = 0.3) about two thirds of the reflected light is green and ' +
      'under 1% red (see the legend); a smoother surface (α = 0.1) sends about 2% red.',
  },
  {
    id: 'fresnel-f0-tables',
    widget: 'f0-tables',
    title: 'F(0°) is the specular colour',
    state: { selected: 'gold' },
    text:
      'Since reflectance hardly moves over most angles, its value at normal incidence, F(0°), serves as the ' +
      'surface’s specular colour. Metals are bright and often coloured; non-metals are dark and grey, a few ' +
      'percent. Mind linear against sRGB values.',
  },
  {
    id: 'fresnel-gold',
    widget: 'fresnel-zones',
    title: 'A metal’s colour is its reflection',
    state: { mode: 'fresnel-nv', material: 'gold', shape: 'teapot', camera: 'perspective' },
    text:
      'A metal has no diffuse term: everything refracted is absorbed, so its Fresnel reflectance is all the ' +
      'colour it has. Gold keeps its yellow over most of the teapot and whitens only at grazing angles.',
  },
  {
    id: 'fresnel-schlick',
    widget: 'fresnel-curves',
    title: 'Schlick’s approximation',
    state: { materials: ['gold', 'copper', 'glass-low', 'diamond'], schlick: true, zones: true },
    text:
      'Schlick’s approximation needs only $F(0^\\circ)$: $F(0^\\circ) + (1 - F(0^\\circ))(1 - \\cos \\theta)^5$. ' +
      'The dashed curves follow the exact ones closely; the error plot shows it is largest towards grazing angles, ' +
      'where little of the picture lies.',
  },
];
