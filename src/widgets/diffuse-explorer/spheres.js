// The diffuse explorer's spheres: one per chosen model with the diffuse term only, under the light of the pad;
// the probe reads f, f against Lambert and the radiance there.
import { createSphereGrid } from '../../core/ui/sphere-grid.js';
import { termDefines, termEntry } from '../../math/catalogue/index.js';
import { CUSTOM, cosPhiDiff, diffuseAt, paramsOf, radianceAt } from './model.js';

const VIEW = [0, 0, 1];

/** A diffuse model's sphere program: the diffuse term only. */
export const cellDefines = (key) => ({ SPECULAR_OFF: 1, ...termDefines({ diffuse: key }) });

const uniformsOf = (state, l) => ({
  uLightDir: l,
  uExposure: state.exposure,
  uDiffuse: state.cdiff,
  uF0: state.f0,
  uSigma: paramsOf(state).sigma,
});

/**
 * The sphere of the diffuse model `key` lit from l: { label, defines, uniforms, probe } for the sphere grid; the
 * user's (`own`: custom.js's { own, uniforms }) with its own program.
 */
export function sphereCell(key, state, l, own = null) {
  if (own)
    return {
      label: 'Yours',
      defines: cellDefines(key),
      own: own.own,
      uniforms: { ...own.uniforms, ...uniformsOf(state, l) },
    };
  const p = paramsOf(state);
  return {
    label: termEntry('diffuse', key).short,
    defines: cellDefines(key),
    uniforms: uniformsOf(state, l),
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
    /** One sphere per chosen model, lit from l; the user's (custom.js's cell) once its code compiled there. */
    draw: (state, l, own) =>
      grid.setCells(
        state.diffuse.filter((k) => k !== CUSTOM || own).map((k) => sphereCell(k, state, l, k === CUSTOM ? own : null)),
      ),
    get renderer() {
      return grid.renderer;
    },
    get canvas() {
      return grid.canvas;
    },
    dispose: () => grid.dispose(),
  };
}
