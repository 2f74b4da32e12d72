// Hands a fit to another widget: in place when it is on this page (brdf-lobe on the BRDF page), else a new tab
// (ndf-explorer gets the measured NDF slice and the source's name in its URL too).
import { lobeStateForFit, ndfStateForFit } from './model.js';
import { mountedWidget } from '../../core/framework/debug-hooks.js';

export function loadFitInto(fit, { fits, measured, sourceName }, target) {
  const lobe = mountedWidget('lobe');
  if (target === 'lobe' && lobe) {
    lobe.update(lobeStateForFit(fit));
    document.querySelector('[data-widget="brdf-lobe"]')?.scrollIntoView({ behavior: 'smooth' });
    return;
  }
  const [page, prefix, state] =
    target === 'lobe'
      ? ['brdf.html', 'lobe', lobeStateForFit(fit)]
      : ['ndf.html', 'ndf', ndfStateForFit(fit, fits, measured, sourceName)];
  const params = new URLSearchParams(
    Object.entries(state).map(([k, v]) => [`${prefix}.${k}`, typeof v === 'number' ? +v.toPrecision(4) : String(v)]),
  );
  window.open(`${page}?${params}`, '_blank', 'noopener');
}
