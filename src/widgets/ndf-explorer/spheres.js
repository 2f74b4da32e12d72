// The NDF explorer's spheres: one per chosen NDF at the matched width, F = 1 and V = 1 so that only D differs,
// under one small light; the probe reads D and the radiance there.
import { createSphereGrid } from '../../core/ui/sphere-grid.js';
import { lightDirFromAngles } from '../../math/angles.js';
import { NDF_TERMS, microfacetBRDFAt, punctualRadiance } from '../../math/brdf.js';
import { termDefines, termEntry } from '../../math/catalogue/index.js';

/** The sphere of one NDF curve (model.js's ndfCurves): { label, defines, uniforms, probe } for the sphere grid. */
export function sphereCell(c, state) {
  const terms = { F: 'one', D: c.key, V: 'implicit' }; // only D differs
  const radiance = (a) => punctualRadiance(microfacetBRDFAt(a, { ...terms, ...c.p }), a.nl, 1);
  return {
    label: termEntry('ndf', c.key).short,
    defines: termDefines(terms),
    uniforms: {
      uLightDir: lightDirFromAngles(state.lightTheta, 135),
      uExposure: state.exposure,
      uAlpha: c.p.alpha ?? 0.3,
      uExponent: c.p.exponent ?? 1,
      uA1: c.p.a1 ?? 1,
      uA2: c.p.a2 ?? 1,
      uSgdP: c.p.p ?? 0,
    },
    probe: (a) => [
      ['D(n·h)', `${NDF_TERMS[c.key](a.nh, c.p).toPrecision(4)} /sr`],
      ['radiance π·D/4·(n·l)', radiance(a).toPrecision(4)],
    ],
  };
}

export function createNdfSpheres(container) {
  const grid = createSphereGrid(container, { label: 'NDF highlights on spheres' });
  return {
    draw: (curves, state) => grid.setCells(curves.map((c) => sphereCell(c, state))),
    get canvas() {
      return grid.canvas;
    },
    dispose: () => grid.dispose(),
  };
}
