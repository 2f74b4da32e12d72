// The bench family of a metal's Fresnel from two colours (two numbers per channel): Schlick (F0 alone, the talk's),
// Gulbrandsen 2014's edge tint (F0 and g, mapped to (n, k) once per material, then the exact equations per pixel) and
// F82-tint (F0 and the tint at cos θ = 1/7: Hoffman 2023, OpenPBR's metal), each fitted to the measured (n, k) of the
// talk's five metals and scored against the exact conductor Fresnel equations with those (n, k).
import * as M from '../src/math/index.js';

const COS = Array.from({ length: 1001 }, (_, i) => i / 1000);
const CHANNELS = M.METALS.flatMap((m) =>
  M.measuredRgbNk(m.key).map(([n, k]) => {
    const { f0, tint } = M.f82TintFromConductor(n, k);
    return [n, k, f0, tint, M.edgeTintFromConductorIor(n, k)];
  }),
);
// the GPU times one pixel's work: (n, k) from (F0, g) is per material, a uniform in a shader, so Gulbrandsen's
// pixel is fresnelConductor's
const CONDUCTOR_GLSL = 'fresnelConductor(x, 0.2 + y, 3.0 + y)';

export const F82_TINT_FAMILY = {
  key: 'fresnel-metal-two-colours',
  title: 'Fresnel, metals from two colours: Schlick, Gulbrandsen’s edge tint, F82-tint',
  domain:
    'cos θ in [0, 1] (1001 points) × the measured (n, k) of the five metals at 650/550/450 nm; each model ' +
    'fitted to them (F0 exact; F82-tint exact at cos θ = 1/7; g from n, k)',
  errorOf: 'reflectance',
  inputs: COS.flatMap((c) => CHANNELS.map((channel) => [c, ...channel])),
  variants: [
    {
      key: 'exact',
      label: 'Exact (fresnelConductor)',
      kind: 'reference',
      model: 'fresnel',
      js: (c, n, k) => M.fresnelConductor(c, n, k),
      glsl: CONDUCTOR_GLSL,
    },
    {
      key: 'schlick',
      label: 'Schlick (F0)',
      kind: 'approximation',
      against: 'exact',
      model: 'fresnel',
      js: (c, n, k, f0) => M.fresnelSchlick(f0, c),
      glsl: 'fresnelSchlick(0.5 + 0.4 * y, x)',
    },
    {
      key: 'gulbrandsen',
      label: 'Gulbrandsen 2014 (F0, edge tint g)',
      kind: 'approximation',
      against: 'exact',
      model: 'fresnel',
      js: (c, n, k, f0, tint, g) => M.fresnelConductor(c, ...M.conductorIorFromF0EdgeTint(f0, g)),
      glsl: CONDUCTOR_GLSL,
    },
    {
      key: 'f82-tint',
      label: 'F82-tint (F0, tint at 81.8°)',
      kind: 'approximation',
      against: 'exact',
      model: 'fresnel',
      js: (c, n, k, f0, tint) => M.fresnelF82Tint(f0, tint, c),
      glsl: 'fresnelF82Tint(0.5 + 0.4 * y, 0.8 + 0.1 * y, x)',
    },
  ],
};
