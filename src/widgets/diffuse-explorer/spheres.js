// The diffuse explorer's spheres: one per chosen model with the diffuse term only, under the light of the pad;
// the probe reads f, f against Lambert and the radiance there.
import { createSphereGrid } from '../../core/ui/sphere-grid.js';
import { termDefines, termEntry } from '../../math/catalogue/index.js';
import { cosPhiDiff, diffuseAt, paramsOf, radianceAt } from './model.js';

const VIEW = [0, 0, 1];

/** The sphere of the diffuse model `key` lit from l: { label, defines, uniforms, probe } for the sphere grid. */
export function sphereCell(key, state, l) {
  const p = paramsOf(state);
  return {
    label: termEntry('diffuse', key).short,
    defines: { SPECULAR_OFF: true, ...termDefines({ diffuse: key }) },
    uniforms: { uLightDir: l, uExposure: state.exposure, uDiffuse: state.cdiff, uF0: state.f0, uSigma: p.sigma },
    probe: (a, n) => {
      const value = diffuseAt(key, a.nl, a.nv, cosPhiDiff(n, l, VIEW), p);
      return [
        ['f (1/sr)', value.toFixed(5)],
        ['f / Lambert', state.cdiff > 0 ? (value / (state.cdiff / Math.PI)).toFixed(4) : '—'],
        ['Lo / c_light', radianceAt(key, n, l, VIEW, p).toFixed(4)],
      ];
    },
  };
}

export function createDiffuseSpheres(container) {
  const grid = createSphereGrid(container, { label: 'Diffuse models on spheres' });
  return {
    /** One sphere per chosen model, lit from l. */
    draw: (state, l) => grid.setCells(state.models.map((k) => sphereCell(k, state, l))),
    get canvas() {
      return grid.canvas;
    },
    dispose: () => grid.dispose(),
  };
}
