// The landing page's picture of each chapter (by chapter key): public/chapters/KEY.webp, shot from the chapter's
// main widget by `npm run chapter-pictures`, and its alt text, which says what the picture shows.
export const CHAPTER_PICTURES = {
  media: 'Glasses of water, a red absorber, cloudy water and milk at growing depths',
  surfaces: 'Light meeting a flat boundary: the reflected and refracted shares',
  brdf: 'A microfacet BRDF lobe in 3-D, with the light, view and half vectors',
  microfacets: 'Rays on a rough 2-D microsurface, some shadowed or masked',
  fresnel: 'A torus knot coloured by the Fresnel zones of l·h, lit from behind',
  ndf: 'Two spheres under one light, GGX and Beckmann at the same width: GGX’s highlight fades out further',
  visibility: 'Two rough spheres (α = 0.9) lit from 60°: the implicit visibility term (V = 1) and Smith’s',
  diffuse: 'Two spheres lit head on: Lambert darkens towards the rim, Oren–Nayar (σ = 60°) looks flat',
  rendering: 'A gold sphere lit by an environment: approximation, reference and their error',
  today: 'A coated red paint’s OpenPBR lobe in the plane of incidence, each layer’s part a line of its own',
  performance: 'Error against GPU cost for the Fresnel approximations',
};

export const chapterPictureUrl = (key) => `chapters/${key}.webp`;
export const CHAPTER_PICTURE_SIZE = { width: 480, height: 270 };
