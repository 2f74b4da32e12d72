// The inputs of MaterialX's open_pbr_surface node (its node definition ND_open_pbr_surface_surfaceshader,
// OpenPBR Surface 1.1.1, in MaterialX 1.39's libraries/bxdf/open_pbr_surface.mtlx): name, type, default and the hard
// range the definition gives (uimin/uimax; a soft limit is no limit). tests/unit/mtlx-materialx.test.js checks
// the table against that definition as MaterialX reads it. The four geometry vectors (normals and tangents) come
// from the geometry and are left out.

import { OPENPBR_DEFAULTS } from '../../math/openpbr.js';

const F = (value, min = 0, max = 1) => ({ type: 'float', value, min, max });
const C = (value) => ({ type: 'color3', value, min: 0, max: 1 });
const grey = (x) => [x, x, x];

/** Every input of open_pbr_surface but the geometry vectors, by name. */
export const OPENPBR_NODE_INPUTS = Object.freeze({
  base_weight: F(1),
  base_color: C(grey(0.8)),
  base_diffuse_roughness: F(0),
  base_metalness: F(0),
  specular_weight: F(1, 0, Infinity),
  specular_color: C(grey(1)),
  specular_roughness: F(0.3),
  specular_ior: F(1.5, 0, Infinity),
  specular_roughness_anisotropy: F(0),
  transmission_weight: F(0),
  transmission_color: C(grey(1)),
  transmission_depth: F(0, 0, Infinity),
  transmission_scatter: C(grey(0)),
  transmission_scatter_anisotropy: F(0, -1, 1),
  transmission_dispersion_scale: F(0),
  transmission_dispersion_abbe_number: F(20, 0, Infinity),
  subsurface_weight: F(0),
  subsurface_color: C(grey(0.8)),
  subsurface_radius: F(1, 0, Infinity),
  subsurface_radius_scale: C([1, 0.5, 0.25]),
  subsurface_scatter_anisotropy: F(0, -1, 1),
  fuzz_weight: F(0),
  fuzz_color: C(grey(1)),
  fuzz_roughness: F(0.5),
  coat_weight: F(0),
  coat_color: C(grey(1)),
  coat_roughness: F(0),
  coat_roughness_anisotropy: F(0),
  coat_ior: F(1.6, 0, Infinity),
  coat_darkening: F(1),
  thin_film_weight: F(0),
  thin_film_thickness: F(0.5, 0, Infinity),
  thin_film_ior: F(1.4, 0, Infinity),
  emission_luminance: F(0, 0, Infinity),
  emission_color: C(grey(1)),
  geometry_opacity: F(1),
  geometry_thin_walled: { type: 'boolean', value: false },
});

/** The geometry inputs: vectors the renderer supplies; a file that sets one is refused. */
export const OPENPBR_GEOMETRY_INPUTS = Object.freeze([
  'geometry_normal',
  'geometry_coat_normal',
  'geometry_tangent',
  'geometry_coat_tangent',
]);

/**
 * The inputs a material of the lab has (the subset src/math/openpbr.js evaluates: base, specular, coat and fuzz).
 * A file's other inputs are read, and reported when they differ from their defaults, but not kept.
 */
export const LAB_MATERIAL_KEYS = Object.freeze(Object.keys(OPENPBR_DEFAULTS));
