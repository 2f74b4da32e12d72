// The app's chapters in the talk's order, and which page and widgets each has. Pure data, here beside the widget
// registry so that the rooms above the widgets (exercises, the tour, the pages) all read it.
export const CHAPTERS = [
  {
    key: 'media',
    title: 'Light in media',
    blurb: 'Absorption, scattering and the scale at which they show.',
    page: 'media.html',
    widgets: ['media'],
  },
  {
    key: 'surfaces',
    title: 'Surfaces and microgeometry',
    blurb: 'Optically flat vs rough; metals vs non-metals; when diffuse is local.',
    page: 'surfaces.html',
    widgets: ['surfaces', 'subsurface-scale'],
  },
  {
    key: 'brdf',
    title: 'The BRDF and the reflectance equation',
    blurb: 'Radiance and colour as numbers; lobes; the integral that sums them.',
    page: 'brdf.html',
    widgets: ['radiance', 'brdf-lobe'],
  },
  {
    key: 'microfacets',
    title: 'Microfacet theory',
    blurb: 'The half vector, shadowing and masking, the energy lost.',
    page: 'microfacets.html',
    widgets: ['microfacets', 'anisotropic-microsurface', 'energy'],
  },
  {
    key: 'fresnel',
    title: 'Fresnel reflectance',
    blurb: 'Exact vs Schlick, the F0 tables, and the Fresnel-zones demo.',
    page: 'fresnel.html',
    widgets: ['fresnel-curves', 'fresnel-zones', 'f0-tables'],
  },
  {
    key: 'ndf',
    title: 'Normal distribution functions',
    blurb: 'Five NDFs at matched widths: highlights and tails.',
    page: 'ndf.html',
    widgets: ['ndf-explorer'],
  },
  {
    key: 'visibility',
    title: 'Geometry and visibility terms',
    blurb: 'Implicit, Cook–Torrance, Kelemen, Smith.',
    page: 'visibility.html',
    widgets: ['visibility-explorer'],
  },
  {
    key: 'diffuse',
    title: 'Diffuse',
    blurb: 'Lambert, the diffuse–specular trade-off, Oren–Nayar.',
    page: 'diffuse.html',
    widgets: ['diffuse-explorer'],
  },
  {
    key: 'rendering',
    title: 'From math to rendering',
    blurb: 'Punctual, image-based, area and ambient light, each against a converged reference.',
    page: 'rendering.html',
    widgets: ['material-lab', 'lighting-models'],
  },
  {
    key: 'performance',
    title: 'Performance and accuracy',
    blurb: 'Run time against error for every approximation.',
    page: 'performance.html',
  },
];
