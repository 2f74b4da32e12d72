// The performance page's image-based lighting section, from the bench's IBL part (bench/ibl.js; `node bench/bench.js
// --only ibl` measures it alone): each of the material lab's environment methods against the lab's Monte Carlo
// reference, relative RMS error against the GPU time of its pass, a chart per case and one table; the brushed-metal
// case (issue 28) in a part of its own that says what each of its methods does, and how converged the reference was.
import {
  iblCaseWords as named,
  iblMethod as methodOf,
  iblMethodWords as methodWords,
  iblStaleNote,
} from './ibl-note.js';
import { anisotropicAlphas } from '../math/anisotropic.js';
import { createPlot } from '../core/ui/plot.js';
import { SERIES_COLORS } from '../core/ui/palettes.js';

/** A table row of `cells` (HTML), each in a <td>, or in a <th> for a head row. */
export const row = (cells, tag = 'td') => `<tr>${cells.map((c) => `<${tag}>${c}</${tag}>`).join('')}</tr>`;

// a case is a material under an environment, anisotropic ones apart
const caseOf = (r) => `${r.environment}|${r.material}|${r.alpha}|${r.anisotropy ?? 0}`;
const percent = (x, digits = 2) => `${(x * 100).toFixed(digits)} %`;

/** One case's chart: relative RMS error against GPU time, a point per method, importance sampling one curve. */
function casePlot(section, rows) {
  const methods = [...new Set(rows.map(methodOf))];
  const xs = [...new Set(rows.map((r) => r.ms))].sort((a, b) => a - b);
  const { environment, material } = rows[0];
  return createPlot(section, {
    title: `${named(rows[0])}: relative RMS error against GPU time (lower left is better)`,
    xLabel: 'GPU time of the pass (ms)',
    yLabel: 'relative RMS error',
    x: { min: xs[0] * 0.8, max: xs[xs.length - 1] * 1.2, log: true },
    y: { min: 0.005, max: 10 ** Math.ceil(Math.log10(Math.max(...rows.map((r) => r.relative)) * 1.5)), log: true },
    series: methods.map((m, i) => ({
      label: m,
      stroke: SERIES_COLORS[i % SERIES_COLORS.length],
      width: m === 'importance' ? 1.5 : 0,
      points: true,
      spanGaps: true,
    })),
    data: [
      xs,
      ...methods.map((m) => xs.map((x) => rows.find((r) => methodOf(r) === m && r.ms === x)?.relative ?? null)),
    ],
    filename: `ibl-${environment}-${material}${rows[0].anisotropy ? '-anisotropic' : ''}`,
    height: 220,
  });
}

/** What a method of the anisotropic case does, and whose it is. */
function anisotropicWords(r) {
  if (r.samples)
    return (
      'Importance sampling: N directions per pixel drawn from the visible normals of the stretched GGX lobe itself ' +
      '(Dupuy & Benyoub 2023), the same Hammersley pattern on every pixel; no prefiltered map, and the cost grows ' +
      'with N.'
    );
  if (r.bent)
    return (
      'Split sum, bent reflection vector: the round-lobe map read along the view with its part along the brushing ' +
      'removed, mixed into the normal, the view mirrored about the result. Filament’s documentation takes it from ' +
      'McAuley 2015 (Far Cry 4), after Revie 2012, and calls it a rough approximation whose alternative is ' +
      'importance sampling; three.js does the same, with the weight (1 − a(1 − √α))⁴ on the normal.'
    );
  return 'Split sum, mirror direction: the round-lobe map read along the plain mirror direction, as if unbrushed.';
}

/** The reference's own noise, as the bench measured it (bench/ibl.js, referenceNoise), beside the least error. */
function noiseWords(c, samples, least) {
  const size =
    c.noise < least
      ? `under the smallest error in the table (${percent(least)})`
      : `as large as the smallest errors (${percent(least)}), which are then partly the reference’s own`;
  return (
    `How converged the reference is: every method measured again against a ${c.checkSamples}-sample reference ` +
    `puts the ${samples}-sample one’s own noise at ${percent(c.noise)} of its RMS (each method’s estimate: ` +
    `${c.each.map((x) => percent(x)).join(', ')}), ${size}.`
  );
}

/** The anisotropic cases in `part` (in the page): what each method does, a chart, a table, the reference's noise. */
function anisotropicPart(part, ibl, plots) {
  const rows = ibl.rows.filter((r) => r.anisotropy);
  const checks = (ibl.referenceChecks ?? []).filter((c) => c.anisotropy);
  const kinds = [rows.find((r) => r.bent), rows.find((r) => r.bent === false), rows.find((r) => r.samples)];
  const [ax, ay] = anisotropicAlphas(rows[0].alpha, rows[0].anisotropy, 'burley2012');
  part.innerHTML =
    '<h3>Brushed metal: no prefiltered map for a stretched lobe</h3>' +
    `<p class="domain">${named(rows[0])}: by Burley 2012’s mapping (the lab’s default) a pair of roughnesses, ` +
    `α<sub>x</sub> = ${ax.toFixed(2)} across the brushing and α<sub>y</sub> = ${ay.toFixed(2)} along it. ` +
    'The split sum (Karis 2013) prefilters the map with a round lobe, so a renderer that uses it for brushed ' +
    'metal can only change the direction it reads the map in. Each method is scored against the lab’s ' +
    'reference, which samples the stretched lobe and the map. This goes beyond the talk, whose distributions ' +
    'are round.</p>' +
    `<ul>${kinds
      .filter(Boolean)
      .map((r) => `<li>${anisotropicWords(r)}</li>`)
      .join('')}</ul>`;
  plots.push(casePlot(part, rows));
  const table = document.createElement('table');
  table.className = 'data-table compact';
  table.innerHTML =
    '<caption>Brushed metal: GPU time of each method’s pass on a ' +
    `${ibl.setup.resolution}² sphere (ms, median of ${ibl.setup.timingRuns}), RMS error (radiance) and relative ` +
    `RMS error against the ${ibl.setup.referenceSamples}-sample reference.</caption>` +
    `<thead>${row(['Method', 'GPU ms', 'RMS error', 'relative'], 'th')}</thead><tbody>` +
    rows.map((r) => row([methodWords(r), r.ms.toFixed(1), r.rms.toExponential(2), percent(r.relative, 1)])).join('') +
    '</tbody>';
  part.append(table);
  const least = Math.min(...rows.map((r) => r.relative));
  for (const c of checks) {
    const note = Object.assign(document.createElement('p'), { className: 'source' });
    note.textContent = noiseWords(c, ibl.setup.referenceSamples, least);
    part.append(note);
  }
}

/** Rows measured alone, on their own day: their GPU times compare with each other's, not with other days' costs. */
function aloneWords({ date, loadAverage: load }) {
  const beside = load
    ? `, at a load average of ${load.before.toFixed(0)} before and ${load.after.toFixed(0)} after`
    : '';
  return (
    `Measured alone on ${date.slice(0, 10)} (node bench/bench.js --only ibl${beside}): its GPU times compare with ` +
    'each other, not with the costs above, which were measured in other runs, under other loads.'
  );
}

/** The section before `anchor`; its charts are pushed on `plots`. `reportDate` dates rows that carry no date. */
export function renderIbl(ibl, { anchor, plots, reportDate }) {
  const section = document.createElement('section');
  section.id = 'ibl';
  const stale = iblStaleNote(ibl.date ?? reportDate);
  section.innerHTML =
    '<h2>Image-based lighting against the reference</h2>' +
    `<p class="domain">The material lab's environment methods on a ${ibl.setup.resolution}² sphere, each ` +
    `against the lab's Monte Carlo reference (${ibl.setup.referenceSamples} samples per pixel): ` +
    'relative RMS error over the sphere against the GPU time ' +
    `of the method's pass (median of ${ibl.setup.timingRuns}). Importance sampling is one curve, N = 4 to 256 ` +
    `samples.${ibl.date ? ` ${aloneWords(ibl)}` : ''}` +
    `${stale ? ` ${stale.replace(/`/g, '')}` : ''}</p>`;
  anchor.before(section);
  const round = ibl.rows.filter((r) => !r.anisotropy);
  for (const c of new Set(round.map(caseOf)))
    plots.push(
      casePlot(
        section,
        round.filter((r) => caseOf(r) === c),
      ),
    );
  const table = document.createElement('table');
  table.className = 'data-table compact';
  table.innerHTML =
    `<thead>${row(['Environment, material', 'Method', 'GPU ms', 'RMS error', 'relative'], 'th')}</thead><tbody>` +
    round
      .map((r) => row([named(r), methodWords(r), r.ms.toFixed(2), r.rms.toExponential(2), percent(r.relative)]))
      .join('') +
    '</tbody>';
  section.append(table);
  const checks = (ibl.referenceChecks ?? []).filter((c) => !c.anisotropy);
  if (checks.length) {
    const note = Object.assign(document.createElement('p'), { className: 'source' });
    note.textContent =
      `How converged the reference is: every method measured again against a ${checks[0].checkSamples}-sample ` +
      `reference puts the ${ibl.setup.referenceSamples}-sample one’s own noise, relative to its RMS, at ` +
      `${checks.map((c) => `${percent(c.noise)} (${named(c)})`).join(', ')}; an error near its case’s figure is ` +
      'partly the reference’s own.';
    section.append(note);
  }
  if (!ibl.rows.some((r) => r.anisotropy)) return;
  const part = Object.assign(document.createElement('div'), { id: 'ibl-anisotropic' });
  section.append(part);
  anisotropicPart(part, ibl, plots);
}
