// The diffuse explorer's words: what it shows, the functions it names, and its spheres described for screen readers.
import { sigmaText } from '../../core/ui/sigma-range.js';
import { termLabel } from '../../math/catalogue/index.js';

export const TITLE = 'Diffuse explorer';

export const ABOUT =
  'Every sphere has a diffuse term only, lit by one punctual light (L = π f c_light (n·l), c_light = 1). ' +
  'Lambert’s f is a constant, so its brightness is just the cosine: bright where the surface faces the light, ' +
  'dark towards the terminator. The two trade-off models give the specular term first claim on the light, so ' +
  'they darken near the silhouette, where Fresnel reflection takes nearly everything; F0 sets how much they ' +
  'give up. Oren–Nayar models a surface of V-shaped grooves whose slopes spread by σ: grooves facing the viewer ' +
  'are also the lit ones when the light is behind the viewer, so the rim stays bright and the disc looks flat, ' +
  'like the full moon. Put the light at the centre of the pad, raise σ and compare the profiles; at σ = 0 both ' +
  'Oren–Nayar forms are exactly Lambert. σ is the spread of the facet tilt angle: beyond about 45° a Gaussian ' +
  'that wide would tilt over 4.6% of the facets past 90°, so the slider’s upper half (to 90°) extrapolates the ' +
  'model, and the plots say so. The last plot adds a smooth specular F(θv) to each diffuse albedo: above 1, the ' +
  'pair reflects more light than arrives. Fresnel-weighted Lambert is not normalised: head-on it returns ' +
  '(1 − F0)²·20/21 of c_diff (0.878 at F0 = 0.04).';

/** The functions behind the pictures, linked to their rows on the parity page. */
export const TERMS_USED = [
  'diffuseLambert',
  'diffuseFresnelWeighted',
  'diffuseAshikhminShirley',
  'diffuseOrenNayar',
  'diffuseOrenNayarQualitative',
  'fresnelSchlick',
];

/** The spheres in words: the parameters, the light and the models shown. */
export const describeSpheres = (state) =>
  `Spheres with a diffuse term only (c_diff ${state.cdiff}, F0 ${state.f0}, ${sigmaText(state.sigma)}), light ` +
  `${state.lightTheta}° from the view: ${state.models.map((k) => termLabel('diffuse', k)).join(', ')}.`;
