// energy: the white furnace. With F = 1 a microfacet BRDF should send back all the light it receives, but
// the model drops every ray that a second microfacet blocks. Directional albedo E(mu) against angle for a
// sweep of roughness, the energy lost 1 - E, and spheres in a uniform white environment, each pixel reading
// E(n·v) from the split-sum table (the same float64 quadrature, bilinear on the GPU). A compensation switch puts
// the lost energy back (Kulla & Conty 2017, Turquin 2019), and a coloured metal's albedo is set beside the walk.
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { termLabel } from '../../math/catalogue/index.js';
import { schema } from './schema.js';
import { albedoSweep } from './model.js';
import { createAlbedoPlots } from './plots.js';
import { createFurnaceSpheres } from './spheres.js';
import { createAlbedoTable } from './table.js';
import { createMetalView } from './metal-view.js';
import { ABOUT, TERMS_USED, TITLE, describeFurnace } from './words.js';

export { schema };

export function createEnergy(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, {
    name: 'energy',
    schema,
    initialState,
    locked,
    about: ABOUT,
    terms: TERMS_USED,
  });
  // the spheres first: they are what the words speak of; the plots and the table give their figures
  const spheres = createFurnaceSpheres(shell.view);
  const plotHolder = document.createElement('div');
  shell.view.append(plotHolder);
  let sweep = albedoSweep(shell.state);
  const plots = createAlbedoPlots(plotHolder, sweep);
  const table = createAlbedoTable(shell.view);
  const compensationLabel = () => termLabel('compensation', shell.state.compensation);
  const metalNow = () => metalView.update(shell.state.metal, shell.state.metalAlpha);
  const describe = (metal) => {
    const compensated = shell.state.compensation === 'none' ? null : compensationLabel();
    shell.describe(describeFurnace(sweep, compensated, metal), spheres.canvas);
  };
  const metalView = createMetalView(shell.view, () => describe(metalNow())); // again when its walk arrives

  const render = () => {
    table.draw(sweep);
    spheres.draw(sweep, shell.state.compensation, compensationLabel());
    describe(metalNow());
  };
  const onChanged = (changed) => {
    if (changed.includes('alphas')) {
      sweep = albedoSweep(shell.state);
      plots.draw(sweep);
    }
    render();
  };
  render();
  const update = shell.connect({ title: TITLE, onChanged, onStateChange });

  return {
    update,
    getState: () => shell.state,
    getAlbedos: () => sweep.map((d) => ({ alpha: d.alpha, atNormal: d.atNormal, average: d.avg })),
    dispose() {
      plots.dispose();
      spheres.dispose();
      metalView.dispose();
      shell.dispose();
    },
  };
}

export const widget = { name: 'energy', schema, create: createEnergy, terms: TERMS_USED };
