// Every widget by name, loaded only when opened (each is its own chunk).
/** @type {import('../core/framework/types.js').WidgetRegistry} */
export const WIDGETS = {
  'fresnel-curves': {
    title: 'Fresnel curves',
    summary: 'Reflectance against angle, exact and Schlick, and the error of Schlick.',
    load: () => import('./fresnel-curves/fresnel-curves.js'),
  },
  'fresnel-zones': {
    title: 'Fresnel zones',
    summary: 'The talk’s live demo: Fresnel over a 3-D shape, zones of n·v and of l·h, weighted by the BRDF.',
    load: () => import('./fresnel-zones/fresnel-zones.js'),
  },
  'f0-tables': {
    title: 'F0 tables',
    summary: 'Normal-incidence reflectance of metals and non-metals, linear and sRGB, with swatches.',
    load: () => import('./f0-tables/f0-tables.js'),
  },
  'metal-fresnel': {
    title: 'Metals near grazing: F82-tint',
    summary: 'A metal’s exact Fresnel per channel beside Schlick, Gulbrandsen’s edge tint and F82-tint (OpenPBR).',
    load: () => import('./metal-fresnel/metal-fresnel.js'),
  },
  media: {
    title: 'Light in media',
    summary:
      'Absorption by Beer–Lambert over millimetres to 100 m, scattering from cloudy to opaque, the talk’s grid ' +
      'of glasses.',
    load: () => import('./media/media.js'),
  },
  surfaces: {
    title: 'Surfaces',
    summary:
      'A flat interface (reflection, refraction, metals vs non-metals), a rough one’s reflection cone, ' +
      'blurrier reflections.',
    load: () => import('./surfaces/surfaces.js'),
  },
  'subsurface-scale': {
    title: 'Subsurface scale',
    summary:
      'Random walks in a scattering slab: how far light travels before it re-emerges, against a pixel’s ' +
      'footprint radius.',
    load: () => import('./subsurface-scale/subsurface-scale.js'),
  },
  radiance: {
    title: 'Radiance and colour',
    summary:
      'Radiance along a ray stays put while a lamp’s irradiance falls as 1/d²; a spectrum reduced to RGB, and ' +
      'where RGB ⊗ RGB misleads.',
    load: () => import('./radiance/radiance.js'),
  },
  'brdf-lobe': {
    title: 'BRDF lobe',
    summary: 'The microfacet BRDF taken apart: polar and 3-D lobes, factors on and off, two BRDFs, (θh, θd), albedo.',
    load: () => import('./brdf-lobe/brdf-lobe.js'),
  },
  'measured-brdf': {
    title: 'Measured BRDF',
    summary:
      'Drop a MERL file (or keep a synthetic one): its lobe, spheres and NDF slice beside the five models ' +
      'fitted to it.',
    load: () => import('./measured-brdf/measured-brdf.js'),
  },
  'ndf-explorer': {
    title: 'NDF explorer',
    summary: 'The five NDFs of the talk at one matched width: linear and log plots, highlights, normalisation.',
    load: () => import('./ndf-explorer/ndf-explorer.js'),
  },
  'visibility-explorer': {
    title: 'Visibility explorer',
    summary: 'Implicit, Cook-Torrance, Kelemen and the Smith family against angle, their error, and on spheres.',
    load: () => import('./visibility-explorer/visibility-explorer.js'),
  },
  microfacets: {
    title: 'Microsurface',
    summary: 'A 2-D microsurface under a bundle of rays: facets along h, shadowing, masking, second bounces, vs Smith.',
    load: () => import('./microfacets/microfacets.js'),
  },
  'anisotropic-microsurface': {
    title: 'Anisotropic microsurface, ray-traced',
    summary: 'A 3-D Gaussian surface stretched along t, its shadows ray-traced, G1 against azimuth vs Smith’s.',
    load: () => import('./anisotropic-microsurface/anisotropic-microsurface.js'),
  },
  energy: {
    title: 'White furnace',
    summary: 'Directional albedo against angle for a sweep of roughness, the energy lost, and furnace spheres.',
    load: () => import('./energy/energy.js'),
  },
  'diffuse-explorer': {
    title: 'Diffuse explorer',
    summary:
      'Lambert, the diffuse–specular trade-off and Oren–Nayar on spheres and against angle; the rough “full ' +
      'moon” flattening.',
    load: () => import('./diffuse-explorer/diffuse-explorer.js'),
  },
  'material-lab': {
    title: 'Material lab',
    summary:
      'A material under punctual, sphere, environment and ambient light: each approximation beside a ' +
      'converging Monte Carlo reference, with its error and cost.',
    load: () => import('./material-lab/material-lab.js'),
  },
  'lighting-models': {
    title: 'Lighting models',
    summary:
      'One material under a sky with a sun: general lighting, image-based, area, punctual and ambient light, ' +
      'each with its cost and error.',
    load: () => import('./lighting-models/lighting-models.js'),
  },
};

export const isWidgetName = (name) => Object.hasOwn(WIDGETS, name);
