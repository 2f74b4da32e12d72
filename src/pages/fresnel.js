// The Fresnel chapter: curves, the zones demo and the F0 tables, each in its own section of the page.
// A material picked in the tables loads into the two other widgets in place.
import '../styles.css';
import { mountWidget } from '../core/framework/widget-host.js';
import { WIDGETS } from '../widgets/registry.js';

const slot = (name) => document.querySelector(`[data-slot="${name}"]`);

const curves = await mountWidget(slot('fresnel-curves'), 'fresnel-curves', { widgets: WIDGETS, prefix: 'curves' });
const zones = await mountWidget(slot('fresnel-zones'), 'fresnel-zones', { widgets: WIDGETS, prefix: 'zones' });
await mountWidget(slot('f0-tables'), 'f0-tables', {
  widgets: WIDGETS,
  prefix: 'tables',
  options: {
    onPick(key, target) {
      if (target === 'fresnel-curves')
        curves.update({ materials: [...new Set([...curves.getState().materials, key])] });
      else zones.update({ material: key, mode: 'fresnel-nv' });
      slot(target).scrollIntoView({ behavior: 'smooth', block: 'start' });
      return true;
    },
  },
});
