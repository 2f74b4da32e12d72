// node bench/openpbr-latency.js: the material lab's latency for an OpenPBR parameter change, timed as
// `npm run bench:latency` times a widget (bench/latency.js's measure: a slider's drag held on the widget, each
// change to its finished frame), the lab opened on the car paint preset (a blue base under a clear coat:
// src/lab/openpbr-presets.js) with the lab's lights as they open (the studio environment and the punctual light)
// and with the punctual light alone. Prints the rows (and the load average beside them: the machine may be
// shared); writes nothing.
import { loadavg, tmpdir } from 'node:os';
import { mkdtempSync } from 'node:fs';
import { join } from 'node:path';
import { buildApp, launchBrowser, serveStatic } from '../tests/browser/harness.js';
import { TARGET_MS, measure } from './latency.js';
import { stateOfOpenPbr } from '../src/lab/openpbr-lab.js';
import { OPENPBR_PRESETS } from '../src/lab/openpbr-presets.js';

const STEPS = 24;
const KEY = 'specular_roughness';
const preset = new URLSearchParams({
  ...stateOfOpenPbr(OPENPBR_PRESETS.carPaint.material).patch,
  brdfSource: 'openpbr',
});
const ROWS = [
  ['car paint, studio + punctual light', '&refSamples=128'],
  ['car paint, punctual light alone', '&refSamples=128&env=0'],
];
/** specular_roughness swept from 0.2 to 0.6 (the preset's is 0.3), as DRAGS sweeps a widget's main control. */
const drag = async (steps) => ({
  key: KEY,
  values: Array.from({ length: steps }, (_, i) => 0.2 + (0.4 * i) / (steps - 1)),
  step: 0.005,
});

const server = await serveStatic(await buildApp(mkdtempSync(join(tmpdir(), 'shading-lab-openpbr-latency-'))));
const browser = await launchBrowser();
try {
  for (const [label, lights] of ROWS) {
    const row = await measure(browser, server.url, 'material-lab', null, STEPS, { query: `&${preset}${lights}`, drag });
    console.log(
      `  ${label.padEnd(38)}${KEY}: median ${row.medianMs.toFixed(1).padStart(7)} ms, worst ` +
        `${row.worstMs.toFixed(1).padStart(7)} ms over ${row.steps} steps (target ${TARGET_MS} ms; load average ` +
        `${loadavg()[0].toFixed(1)})`,
    );
  }
} finally {
  await browser.close();
  server.close();
}
