// The material lab's frame (createLabView's `frame`): the scene of the state, the approximation rendered again when
// it changed (its GPU time the median of `timingRuns` renders), the reference restarted when it changed and given
// one more batch until it has the samples asked for, and the error between them. The user's BRDF, when chosen, is
// asked for in each frame: the code that last ran well, with its sliders. OpenPBR's reference (the whole stack, a
// batch of samples of every light per pixel) costs many times its approximation: while a gesture is held on the
// widget (`held()`, a slider dragged) it waits, the last one kept and said to be, and starts over at the release.
import { REFERENCE_BATCH } from '../../lab/lab-renderer.js';
import { sceneOf } from './model.js';
import { sampleTarget } from '../../core/framework/debug-hooks.js';
import { tangentFieldOf } from '../../lab/lab-anisotropy.js';

/**
 * `state()` the widget's state, `measured()` the measured table in use or null, `custom(state)` the user's BRDF
 * ({ code, params }) to draw, `terms(state)` the user's anisotropic D and V to draw or null, `openpbr(state)` the
 * OpenPBR material of the panel, `file()` the dropped environment ({ key, pixels }), `held()` whether a gesture is
 * under way, `show(state, lights)` shows what the frame measured. frame(...) is the view's frame; stats the last
 * frame's; reset() renders everything again; remeasure(runs) times the approximation again, the median of `runs`
 * renders.
 */
export function createLabFrame({ state, measured, custom, terms, openpbr, file, held = () => false, show }) {
  let approxKey = '';
  let refKey = '';
  let stats = null;
  let ms = null;
  let centre = null; // the approximation's radiance at the sphere's centre
  let timingRuns = 1; // renders of the approximation whose median is its cost (the bench asks for more)

  const frame = ({ lab, environment, again }) => {
    const st = state();
    const table = st.brdfSource === 'measured' ? measured() : null;
    const fromFile = st.env && st.environment === 'file';
    const envKey = st.env ? (fromFile ? file().key : st.environment) : 'none';
    const ownBrdf = st.brdfSource === 'custom' ? custom(st) : null;
    const layered = st.brdfSource === 'openpbr' ? openpbr(st) : null;
    const { scene, lights, keys } = sceneOf(st, table, envKey, ownBrdf, layered, terms(st));
    scene.table = table?.texture;
    scene.maps = environment(st.env ? st.environment : 'furnace', fromFile ? file().pixels : null);
    if (keys.approx !== approxKey) {
      const times = Array.from({ length: timingRuns }, () => lab.renderApprox(scene)).sort((a, b) => a - b);
      ms = times[Math.floor(times.length / 2)];
      centre = lab.readCentre(); // once per new approximation, not per frame
      approxKey = keys.approx;
    }
    const waiting = keys.reference !== refKey && layered !== null && held();
    if (keys.reference !== refKey && !waiting) {
      lab.resetReference();
      refKey = keys.reference;
    }
    const target = sampleTarget(Number(st.refSamples));
    if (lab.batches < target / REFERENCE_BATCH && !waiting) {
      lab.accumulate(scene);
      again();
    }
    const { rms, relative, pixels } = waiting && stats ? stats : lab.error(); // the last error, while it waits
    stats = { rms, relative, pixels, ms, timingRuns, samples: lab.batches * REFERENCE_BATCH, target, waiting };
    Object.assign(stats, { samplesN: st.samples, method: st.envMethod, centre });
    const panels = show(st, lights, scene, stats);
    const tangents = st.showTangents ? tangentFieldOf(st) : null; // drawn over the two renders, not the error
    return tangents ? panels.map((p) => (p.image === 'error' ? p : { ...p, tangents })) : panels;
  };

  return {
    frame,
    get stats() {
      return stats;
    },
    reset: () => ([approxKey, refKey] = ['', '']),
    remeasure(runs) {
      timingRuns = runs;
      approxKey = '';
    },
  };
}
