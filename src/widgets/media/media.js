// media: light through a homogeneous medium. Absorption per RGB channel by Beer-Lambert over a distance set
// on a log scale, scattering that clouds the medium and then makes it opaque, and the talk's grid of glasses
// from low to high absorption and scattering. Rendered on the GPU by a progressive Monte Carlo volume path
// tracer (unscattered light transmitted exactly), with the transmitted colour plotted against distance.
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { schema, TERMS_USED } from './schema.js';
import { ABOUT, TITLE, describeMedia } from './words.js';
import { createGlassesView } from './glasses-view.js';
import { createTransmittancePlot } from './transmittance-plot.js';
import { sampleTarget } from '../../core/framework/debug-hooks.js';

export { schema };

export function create(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, {
    name: 'media',
    schema,
    initialState,
    locked,
    about: ABOUT,
    terms: TERMS_USED,
  });
  const glasses = createGlassesView(shell.view, () => shell.state);
  const readout = Object.assign(document.createElement('p'), { className: 'media-readout' });
  shell.view.append(readout);
  const plot = createTransmittancePlot(shell.view, shell.state);

  const describe = () => {
    const words = describeMedia(shell.state);
    readout.innerHTML = words.readout;
    shell.describe(words.description, glasses.canvas);
  };
  describe();

  const onChanged = (changed) => {
    if (changed.some((k) => k === 'medium' || k === 'distance' || k === 'view')) plot.show(shell.state);
    describe();
    glasses.restart();
  };
  const update = shell.connect({ title: TITLE, onChanged, onStateChange });

  return {
    update,
    getState: () => shell.state,
    getProgress: () => ({ frame: glasses.frames(), target: sampleTarget(Number(shell.state.samples)) }),
    dispose() {
      plot.dispose();
      glasses.dispose();
      shell.dispose();
    },
  };
}

export const widget = { name: 'media', schema, create, terms: TERMS_USED };
