// surfaces: a flat interface splitting light into reflection and refraction (exact Fresnel), what a metal
// and a non-metal do with the refracted light, the reflection cone of a rough surface against the microfacet
// prediction, and environment reflections blurring as roughness grows.
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { schema, TERMS_USED } from './schema.js';
import { interfaceSpec, roughProfile } from './model.js';
import { ABOUT, TITLE, describeSurfaces } from './words.js';
import { drawInterface } from './interface-view.js';
import { createConePlot } from './cone-plot.js';
import { createSpheresView } from './spheres-view.js';

export { schema };

export function create(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, {
    name: 'surfaces',
    schema,
    initialState,
    locked,
    about: ABOUT,
    terms: TERMS_USED,
  });
  const flat = Object.assign(document.createElement('canvas'), { className: 'interface' });
  shell.view.append(flat);
  let profile = roughProfile(shell.state.alpha);
  const cone = createConePlot(shell.view, shell.state, profile);
  const spheres = createSpheresView(shell.view);

  const drawFlat = () => {
    const spec = interfaceSpec(shell.state);
    drawInterface(flat, spec);
    return spec;
  };
  const showFlat = () => shell.describe(describeSurfaces(shell.state, drawFlat()), flat);
  const onChanged = (changed) => {
    showFlat();
    if (changed.includes('alpha')) profile = roughProfile(shell.state.alpha);
    if (changed.some((k) => k === 'alpha' || k === 'theta')) cone.show(shell.state, profile);
  };
  showFlat();
  const resize = new ResizeObserver(drawFlat);
  resize.observe(flat);
  const update = shell.connect({ title: TITLE, onChanged, onStateChange });

  return {
    update,
    getState: () => shell.state,
    getReflected: () => interfaceSpec(shell.state).F,
    dispose() {
      resize.disconnect();
      cone.dispose();
      spheres.dispose();
      shell.dispose();
    },
  };
}

export const widget = { name: 'surfaces', schema, create, terms: TERMS_USED };
