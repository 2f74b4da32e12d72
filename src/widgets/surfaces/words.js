// surfaces, in words: the about text and the pictures described for screen readers.
import { declareFormula, texNumber } from '../../core/framework/formula-registry.js';
import { DEG } from '../../math/angles.js';
import { fresnelParams } from '../../math/materials.js';
import { measuredRgbNk } from '../../math/optical-constants.js';
import { interfaceSpec } from './model.js';

export const TITLE = 'Surfaces';

export const ABOUT =
  'Top: an optically flat boundary. Change the material and the angle: the reflected share follows the exact ' +
  'Fresnel equations; a metal swallows the rest within nanometres, a non-metal scatters it and some finds its way ' +
  'back out. Middle: the same boundary with microgeometry (Beckmann slopes). Each tiny facet is still a mirror, ' +
  'but their normals vary, so reflected light spreads into a cone; the histogram of ray-traced reflections ' +
  'follows the microfacet prediction. Bottom: spheres of increasing roughness reflecting a room (rendered with ' +
  'three.js’s standard material): rougher is blurrier.';

/** The flat interface in cross-section (spec: model.js's interfaceSpec). */
export function describeInterface(spec) {
  const rest = spec.metal
    ? `absorbed by the metal within about ${spec.depthNm.toFixed(0)} nm`
    : 'refracted and scattered inside; some of it comes back out as diffuse light';
  return (
    `Optically flat ${spec.name} in cross-section: light at ${spec.theta.toFixed(0)}° incidence, ` +
    `${(spec.F * 100).toFixed(1)}% reflected; the other ${((1 - spec.F) * 100).toFixed(1)}% is ${rest}.`
  );
}

/** The widget's pictures in words: the interface, then the rough surface's cone. */
export const describeSurfaces = (state, spec) =>
  `${describeInterface(spec)} With microgeometry of roughness α ${state.alpha}, the reflection spreads into a ` +
  'cone around the mirror direction (plot below).';

/** The flat interface at the slider's angle (green, 550 nm, as the picture): Snell, exact Fresnel, metal depth. */
export const FORMULA = declareFormula('surfaces', (state) => {
  const spec = interfaceSpec(state);
  const ti = `\\sym{theta}{\\theta_i = ${texNumber(state.theta, 1)}^\\circ}`;
  const p = fresnelParams(state.material); // the green channel's n (and k), as the picture reads them
  const n = `\\sym{material}{${texNumber(p.eta[1], 2)}}`;
  const k = spec.metal ? `,\\ k = ${texNumber(p.k[1], 2)}` : '';
  const F = `F(\\theta_i) = ${texNumber(spec.F)}\\ (\\text{exact, } n = ${n}${k})`;
  const rough = `\\text{microsurface: Beckmann slopes, } \\sym{alpha}{\\alpha = ${texNumber(state.alpha, 2)}}`;
  if (spec.metal) {
    const k550 = texNumber(measuredRgbNk(state.material)[1][1], 2);
    const depth =
      `\\delta = \\frac{\\lambda}{4\\pi k_{\\text{measured}}} = \\frac{550\\ \\text{nm}}{4\\pi \\cdot ${k550}} = ` +
      `${texNumber(spec.depthNm, 1)}\\ \\text{nm}`;
    return `\\begin{gathered}${ti}:\\ ${F}\\\\ ${depth}\\\\ ${rough}\\end{gathered}`;
  }
  const st = Math.sin(state.theta * DEG) / spec.etaRefr;
  const sinI = `\\sin ${texNumber(state.theta, 1)}^\\circ`;
  const snell =
    `\\sin\\theta_t = \\frac{\\sin\\theta_i}{n} = \\frac{${sinI}}{${n}} = ${texNumber(st)}` +
    `,\\ \\theta_t = ${texNumber(Math.asin(st) / DEG, 1)}^\\circ`;
  return `\\begin{gathered}${ti}:\\ ${F}\\\\ ${snell}\\\\ ${rough}\\end{gathered}`;
});
