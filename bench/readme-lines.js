// The measured part of docs/performance.md as Markdown lines, from a bench report (bench/results/latest.json):
// pure, so that the tests can check what it says against the report (bench/readme-tables.js writes it).
import { iblCaseWords, iblMethodWords, iblStaleNote } from '../src/pages/ibl-note.js';
import { materialxLines } from './openpbr-materialx-lines.js';

const esc = (s) => s.replaceAll('|', '\\|');

/**
 * What the families' errors are measured against: exact forms, except a family whose reference is sampled (a
 * random walk: it has a referenceNote with its standard error), which is named with its note.
 */
function referenceWords(families) {
  const sampled = families
    .filter((f) => f.referenceNote)
    .map((f) => {
      const label = f.variants.find((v) => v.kind === 'reference').label;
      const reference = `${label.slice(0, 1).toLowerCase()}${label.slice(1)}`;
      const name = f.title.split(':')[0].replace(/^\w/, (c) => c.toLowerCase()); // OpenPBR keeps its capitals
      return `${name}, scored against a ${reference}, itself uncertain: ${f.referenceNote}`;
    });
  const exact = "the term families' errors and differences are against exact forms";
  return sampled.length ? `${exact}, except ${sampled.join('; ')}` : exact;
}

function headLines(report) {
  const { machine: m, gpuSetup: g } = report;
  const lines = [
    `Measured ${report.date.slice(0, 10)} on ${m.cpu} (${m.cores} cores), Node ${m.node}, ${m.chromium}, GPU: ` +
      `${m.gpuRenderer}. ` +
      `On this software renderer the GPU columns move by up to about 30% between runs (the empty pass alone is ` +
      `${g.baselineMsPerFrame.toFixed(1)} ms ` +
      `of every frame) and the CPU column by about 15%; ${referenceWords(report.families)}.`,
    '',
  ];
  if (report.familiesMeasured) {
    const { date, timedCpu } = report.familiesMeasured;
    const date0 = report.date.slice(0, 10);
    lines.push(
      `The term families' ${timedCpu ? 'errors and CPU costs' : 'errors'} below were measured again on ` +
        `${date.slice(0, 10)} (\`npm run bench -- --only families\`); their ` +
        `${timedCpu ? 'GPU columns are' : 'costs are'} ` +
        `from the full run${iblStaleNote(iblDate(report)) ? `, as are the image-based lighting rows (${date0})` : ''}.`,
      '',
    );
  }
  return lines;
}

const HEAD = (first, what) => [
  `| ${first} | ${what === 'error' ? 'error against' : 'difference from'} | max \\|${what}\\| | RMS | ` +
    'CPU ns/eval | GPU relative |',
  '|---|---|---|---|---|---|',
];
const row = (v, m) => {
  const reference = v.kind === 'reference';
  return (
    `| ${esc(v.label)} | ${reference ? 'reference' : esc(v.againstLabel)} | ` +
    `${reference ? '0' : m.maxAbs.toExponential(2)} | ` +
    // no CPU cost: a reference run once, offline, or a value looked up (OpenPBR's stacks: quadratures done once)
    `${m.rms.toExponential(2)} | ` +
    `${v.cpuNsPerEval === null ? (reference ? '— (run offline)' : '—') : v.cpuNsPerEval.toFixed(0)} | ` +
    `${v.gpuRelative === null ? '—' : `${v.gpuRelative.toFixed(2)}×`} |`
  );
};

function familyLines(f, measuredAlone) {
  const others = f.variants.filter((v) => v.kind === 'difference');
  const alone = measuredAlone && `measured alone on ${measuredAlone.slice(0, 10)}, \`--family ${f.key}\``;
  const notes = [f.referenceNote && esc(f.referenceNote), alone].filter(Boolean);
  const note = notes.length ? ` (${notes.join('; ')})` : '';
  const lines = [
    `**${f.title}** — ${esc(f.errorOf)} over ${esc(f.domain)}${note}`,
    '',
    ...HEAD('approximation', 'error'),
  ];
  for (const v of f.variants.filter((w) => w.kind !== 'difference')) lines.push(row(v, v.error));
  if (others.length) {
    const from = esc(others[0].againstLabel);
    lines.push('', `Other models, as a difference from ${from} (not an error: neither approximates the other):`, '');
    lines.push(...HEAD('model', 'difference'));
    for (const v of others) lines.push(row(v, v.difference));
  }
  lines.push('');
  return lines;
}

// the IBL rows' own date when they were measured alone (`--only ibl`), else the report's
const iblDate = (report) => report.ibl.date ?? report.date;
const percent = (x) => `${(x * 100).toFixed(2)} %`;

/** The reference's own noise per case, as bench/ibl.js measured it against a reference of fewer samples. */
const noiseLines = (ibl) =>
  (ibl.referenceChecks ?? []).map(
    (c) =>
      `- ${iblCaseWords(c)}: ${percent(c.noise)} (each method's estimate: ${c.each.map(percent).join(', ')}; ` +
      `against the ${c.checkSamples}-sample reference: ${c.relativeAtCheck.map(percent).join(', ')})`,
  );

function iblLines(report) {
  const { ibl } = report;
  const stale = iblStaleNote(iblDate(report));
  const noise = noiseLines(ibl);
  return [
    "**Image-based lighting against the reference.** The material lab's environment methods on a " +
      `${ibl.setup.resolution}² sphere against its Monte Carlo reference (${ibl.setup.referenceSamples} samples ` +
      `per pixel, multiple importance ` +
      `sampling of the BRDF and the map); GPU time of the method's pass, median of ${ibl.setup.timingRuns}; RMS ` +
      `error over the sphere, in radiance ` +
      `and relative to the reference's RMS.${stale ? ` ${stale}` : ''}` +
      (ibl.date ? ` Measured ${ibl.date.slice(0, 10)} (\`node bench/bench.js --only ibl\`).` : ''),
    '',
    '| environment, material | method | GPU ms | RMS | relative |',
    '|---|---|---|---|---|',
    ...ibl.rows.map(
      (r) =>
        `| ${iblCaseWords(r)} | ${iblMethodWords(r)} | ${r.ms.toFixed(1)} | ` +
        `${r.rms.toExponential(2)} | ${(r.relative * 100).toFixed(1)} % |`,
    ),
    '',
    ...(noise.length
      ? [
          "The reference's own noise, relative to its RMS: each method measured again against a reference of a " +
            'quarter of the samples, √((e²(N/4) − e²(N)) / 3) (the methods are deterministic):',
          '',
          ...noise,
          '',
        ]
      : []),
  ];
}

function restLines(report) {
  const { versusThree: vt } = report;
  return [
    ...iblLines(report),
    `**Against three.js.** A sphere at ${vt.size}² with the terms of MeshStandardMaterial (GGX, height-correlated ` +
      `Smith, Schlick with ` +
      `F0 = 0.04, Lambert, one punctual light): this app's shader ${vt.oursMsPerFrame.toFixed(1)} ms per frame, ` +
      `MeshStandardMaterial ` +
      `${vt.threeMsPerFrame.toFixed(1)} ms: a ratio of **${vt.ratio.toFixed(2)}**.`,
    '',
    '**Load only what is opened.** Each page is its own entry and each widget its own chunk, loaded when mounted; ' +
      'three.js is shared ' +
      'by the 3-D pages. What each page fetched, and when it drew its first frame:',
    '',
    '| page | JS (KiB, uncompressed) | load (ms) | first 3-D frame (ms) |',
    '|---|---|---|---|',
    ...report.pages.map(
      (p) =>
        `| \`${p.page}\` | ${p.jsKB.toFixed(0)} | ${p.loadMs.toFixed(0)} | ` +
        `${p.firstFrameMs === null ? '—' : p.firstFrameMs.toFixed(0)} |`,
    ),
  ];
}

/** The measured part of docs/performance.md, line by line. */
export const measuredLines = (report) => [
  ...headLines(report),
  ...report.families.flatMap((f) => familyLines(f, report.familyMeasured?.[f.key])),
  ...(report.materialx ? materialxLines(report.materialx) : []),
  ...restLines(report),
];
