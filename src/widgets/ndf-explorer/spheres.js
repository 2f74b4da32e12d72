// The NDF explorer's spheres: one per chosen NDF at the matched width, F = 1 and V = 1 so that only D differs,
// under one small light; the probe reads D and the radiance there. With anisotropy, GGX and Beckmann draw their
// anisotropic lobes (the catalogue's ggxAniso, beckmannAniso) at the pair (αx, αy), the tangent along the
// picture's x axis (the grid's uTangent): the highlight stretches left to right.
import { createSphereGrid } from '../../core/ui/sphere-grid.js';
import { lightDirFromAngles } from '../../math/angles.js';
import { NDF_TERMS, microfacetBRDFAt, punctualRadiance } from '../../math/brdf.js';
import { termDefines, termEntry } from '../../math/catalogue/index.js';
import { sharedUniforms, termUniforms } from '../../math/catalogue/uniforms.js';
import { DEG } from '../../math/angles.js';
import { ANGLES, drawsAnisotropic } from './model.js';
import { microfacetInput, termAt } from '../../math/catalogue/microfacet-input.js';
import { inTangentFrame, tangentFrameAlong } from '../../math/tangent-frame.js';

/** The view-space axis the spheres' tangent runs along (sphere-grid.js's uTangent default): across the picture. */
const TANGENT_AXIS = [1, 0, 0];

/** The terms of an NDF's sphere: only D differs. */
export const cellTerms = (key) => ({ F: 'one', D: key, V: 'implicit' });

/** The sphere of one NDF curve (model.js's ndfCurves): { label, defines, uniforms, probe } for the sphere grid. */
export function sphereCell(c, state) {
  if (c.cell) return customCell(c, state);
  if (drawsAnisotropic(c, state)) return anisotropicCell(c, state);
  const terms = cellTerms(c.key);
  const radiance = (a) => punctualRadiance(microfacetBRDFAt(a, { ...terms, ...c.p }), a.nl, 1);
  return {
    label: termEntry('ndf', c.key).short,
    defines: termDefines(terms),
    // each uniform from its parameter (the catalogue binds them; SGD's normaliser computed there too)
    uniforms: { ...lightUniforms(state), ...pairUniforms(c.p), ...termUniforms(terms, c.p) },
    probe: (a) => [
      ['D(n·h)', `${NDF_TERMS[c.key](a.nh, c.p).toPrecision(4)} /sr`],
      ['radiance π·D/4·(n·l)', radiance(a).toPrecision(4)],
    ],
  };
}

/** The microfacet input's α pair of an isotropic NDF: (α, α) where it has an α (Blinn–Phong and ABC have none). */
const pairUniforms = (p) => (p.alpha === undefined ? {} : sharedUniforms({ alphaPair: [p.alpha, p.alpha] }));

/** An NDF's anisotropic lobe on its sphere; the probe reads D at h in the sphere's tangent frame there. */
function anisotropicCell(c, state) {
  const { key, pair } = c.aniso;
  const terms = cellTerms(key);
  const light = lightUniforms(state);
  const entry = termEntry('ndf', key);
  const D = (n) => {
    const frame = tangentFrameAlong(n, TANGENT_AXIS);
    const m = microfacetInput(inTangentFrame(light.uLightDir, n, frame), inTangentFrame([0, 0, 1], n, frame), pair);
    return m.h ? termAt(entry, m, {}) : 0;
  };
  return {
    label: entry.short,
    defines: termDefines(terms),
    uniforms: { ...light, ...sharedUniforms({ alphaPair: pair }) },
    probe: (a, n) => [
      ['D(h), h in the tangent frame', `${D(n).toPrecision(4)} /sr`],
      ['radiance π·D/4·(n·l)', punctualRadiance(D(n) / 4, a.nl, 1).toPrecision(4)],
    ],
  };
}

const lightUniforms = (state) => ({ uLightDir: lightDirFromAngles(state.lightTheta, 135), uExposure: state.exposure });

/** The sphere of the user's D (custom.js's curve): its own program; the probe reads D off its curve. */
function customCell(c, state) {
  const D = (nh) => {
    const deg = Math.acos(Math.min(Math.max(nh, -1), 1)) / DEG;
    const i = ANGLES.findIndex((x) => x >= deg);
    if (i <= 0) return c.values[Math.max(i, 0)];
    const t = (deg - ANGLES[i - 1]) / (ANGLES[i] - ANGLES[i - 1]);
    return c.values[i - 1] + (c.values[i] - c.values[i - 1]) * t;
  };
  return {
    label: 'Yours',
    defines: termDefines(cellTerms(c.key)),
    own: c.cell.own,
    uniforms: { ...c.cell.uniforms, ...lightUniforms(state), ...pairUniforms(c.p) },
    probe: (a) => [
      ['D(n·h), your code', `${D(a.nh).toPrecision(4)} /sr`],
      ['radiance π·D/4·(n·l)', punctualRadiance(D(a.nh) / 4, a.nl, 1).toPrecision(4)],
    ],
  };
}

export function createNdfSpheres(container) {
  const grid = createSphereGrid(container, { label: 'NDF highlights on spheres' });
  return {
    /** One sphere per curve; the user's once its code compiled in the sphere's program. */
    draw: (curves, state) => grid.setCells(curves.filter((c) => c.cell !== null).map((c) => sphereCell(c, state))),
    get renderer() {
      return grid.renderer;
    },
    get canvas() {
      return grid.canvas;
    },
    dispose: () => grid.dispose(),
  };
}
