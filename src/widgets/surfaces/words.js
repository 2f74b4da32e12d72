// surfaces, in words: the about text and the pictures described for screen readers.

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
