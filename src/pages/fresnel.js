// The Fresnel chapter: curves, the zones demo and the F0 tables, each in its own section of the page.
// A material picked in the tables loads into the two other widgets in place. Each widget that fails says so in its
// own place; the others still mount, and a pick for a widget that is not up follows its link (the widget alone).
import '../styles.css';
import { mountOrExplain } from '../core/framework/widget-failure.js';
import { WIDGETS } from '../widgets/registry.js';

const slot = (name) => document.querySelector(`[data-slot="${name}"]`);
const mounted = {};
const mount = (name, prefix, options = {}) =>
  mountOrExplain(slot(name), name, { widgets: WIDGETS, prefix, options }, (instance) => (mounted[name] = instance));

await mount('fresnel-curves', 'curves');
await mount('fresnel-zones', 'zones');
await mount('f0-tables', 'tables', {
  onPick(key, target) {
    const { 'fresnel-curves': curves, 'fresnel-zones': zones } = mounted;
    if (target === 'fresnel-curves' && curves)
      curves.update({ materials: [...new Set([...curves.getState().materials, key])] });
    else if (target === 'fresnel-zones' && zones) zones.update({ material: key, mode: 'fresnel-nv' });
    else return false;
    slot(target).scrollIntoView({ behavior: 'smooth', block: 'start' });
    return true;
  },
});
await mount('metal-fresnel', 'metals');
