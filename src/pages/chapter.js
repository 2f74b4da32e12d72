// A chapter page: every element with data-slot="WIDGET" gets that widget, its URL keys under data-prefix. A widget
// that fails says so in its own place; the others still mount.
import '../styles.css';
import { mountOrExplain } from '../core/framework/widget-failure.js';
import { WIDGETS } from '../widgets/registry.js';
import { typesetFormulas } from '../core/framework/formulas.js';

typesetFormulas();

// a slot's data-initial (JSON) is the state it starts from, under what the URL says
for (const slot of document.querySelectorAll('[data-slot]')) {
  const initialState = slot.dataset.initial ? JSON.parse(slot.dataset.initial) : {};
  await mountOrExplain(slot, slot.dataset.slot, { widgets: WIDGETS, prefix: slot.dataset.prefix, initialState });
}
