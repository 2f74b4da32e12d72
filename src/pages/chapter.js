// A chapter page: every element with data-slot="WIDGET" gets that widget, its URL keys under data-prefix.
import '../styles.css';
import { mountWidget } from '../core/framework/widget-host.js';
import { WIDGETS } from '../widgets/registry.js';
import { typesetFormulas } from '../core/ui/formulas.js';

typesetFormulas();

for (const slot of document.querySelectorAll('[data-slot]')) {
  await mountWidget(slot, slot.dataset.slot, { widgets: WIDGETS, prefix: slot.dataset.prefix });
}
