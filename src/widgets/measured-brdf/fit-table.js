// The measured-BRDF widget's fit table: a progress bar, one row per model with its shape, f0, c_diff and error,
// and "load this fit" buttons.
import { FIT_MODELS } from '../../measured/fit.js';
import { describeShape } from './model.js';

/** Three channels as text; one number when they agree to the digits shown (a grey material). */
const rgb = (x) => {
  const t = x.map((c) => c.toFixed(3));
  return t[0] === t[1] && t[1] === t[2] ? t[0] : t.join(' / ');
};

/** The fit table: a progress bar and one row per model; onLoad(model, target) from its buttons. */
export function createFitTable(container, onLoad) {
  const box = document.createElement('div');
  box.className = 'measured-fits';
  const progress = Object.assign(document.createElement('progress'), { max: 1, value: 0 });
  progress.setAttribute('aria-label', 'Fitting progress');
  const status = document.createElement('span');
  status.className = 'measured-fit-status';
  const table = document.createElement('table');
  table.className = 'data-table compact';
  box.append(progress, status, table);
  container.append(box);
  table.addEventListener('click', (e) => {
    const b = e.target.closest('button[data-model]');
    if (b) onLoad(b.dataset.model, b.dataset.target);
  });
  return {
    /** fits: { model: result }, running: model key or null, ms: { model: time } */
    draw(fits, { running = null, progressValue = 1, statusText = '' } = {}) {
      progress.value = progressValue;
      status.textContent = statusText;
      const best = Object.values(fits).reduce((a, f) => (!a || f.error < a.error ? f : a), null);
      const rows = Object.keys(FIT_MODELS).map((key) => {
        const f = fits[key];
        const name = `${FIT_MODELS[key].label}${best && f === best ? ' (best)' : ''}`;
        const status = running === key ? 'fitting…' : 'waiting';
        if (!f) return `<tr data-model="${key}"><td>${name}</td><td colspan="5">${status}</td></tr>`;
        const buttons = ['lobe', 'ndf']
          .map(
            (t) =>
              `<button type="button" data-model="${key}" data-target="${t}">` +
              `${t === 'lobe' ? 'BRDF lobe' : 'NDF explorer'}</button>`,
          )
          .join(' ');
        return (
          `<tr data-model="${key}"><td>${name}</td><td>${describeShape(f)}</td>` +
          `<td>${rgb(f.params.f0)}</td><td>${rgb(f.params.cdiff)}</td>` +
          `<td>${f.error.toExponential(2)}</td><td>${buttons}</td></tr>`
        );
      });
      table.innerHTML =
        '<caption>Fits: cdiff/π + F_Schlick(f0) D V / 4 per channel; error: Ngan et al. 2005’s cosine-weighted ' +
        'cube-root RMS, (1/sr)^⅓, θl, θv &lt; 80°</caption><thead><tr><th>model</th><th>shape</th>' +
        '<th>f0 (R / G / B)</th><th>c_diff (R / G / B)</th><th>error</th><th>load this fit into</th></tr></thead>' +
        `<tbody>${rows.join('')}</tbody>`;
    },
    dispose: () => box.remove(),
  };
}
