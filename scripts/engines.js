// npm run engines: every top-level page and the parity page in other engines than the suite's SwiftShader Chromium,
// on Mesa's llvmpipe under Xvfb: Chromium with --use-angle=gl, Firefox ESR (puppeteer-core over WebDriver BiDi) and
// WebKitGTK (WebKitWebDriver), with LANG=C.UTF-8. Per engine: no page error, no widget slot left empty, no blank
// canvas once scrolled into view, parity within tolerance. Prints a table (engine, GL renderer, functions beyond
// tolerance, pages at fault) and exits non-zero if any engine fails a check. Started without a display, it runs
// itself under xvfb-run. Options: --engines chromium,firefox,webkit (default all three), --pages a.html,b.html
// (default every top-level page), --report DIR (each engine's parity report written there).
import { spawn } from 'node:child_process';
import { mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { ROOT, buildApp, serveStatic } from '../tests/browser/harness.js';
import { ENGINES } from './engines/drivers.js';
import { PROBE, checkPage, checkParity } from './engines/checks.js';

const option = (name) => {
  const i = process.argv.indexOf(`--${name}`);
  return i > 0 ? process.argv[i + 1] : undefined;
};

const PAGES = option('pages')?.split(',') ?? readdirSync(ROOT).filter((f) => f.endsWith('.html'));
const engines = option('engines')?.split(',') ?? Object.keys(ENGINES);
const reportDir = option('report');

/** A build in a temporary directory, with the error probe put first in every page's <head>. */
async function probedBuild() {
  const dir = await buildApp(mkdtempSync(join(tmpdir(), 'shading-lab-engines-')));
  writeFileSync(join(dir, 'engine-probe.js'), PROBE);
  for (const page of readdirSync(dir).filter((f) => f.endsWith('.html'))) {
    const html = readFileSync(join(dir, page), 'utf8');
    writeFileSync(join(dir, page), html.replace('<head>', '<head>\n    <script src="./engine-probe.js"></script>'));
  }
  return dir;
}

let current = null; // the open driver, closed on an interrupt

async function runEngine(name, baseUrl) {
  const t0 = performance.now();
  const driver = (current = await ENGINES[name]());
  try {
    const parity = await checkParity(driver, new URL('parity.html', baseUrl).href);
    const pages = [];
    for (const page of PAGES) {
      const result = await checkPage(driver, new URL(page, baseUrl).href).catch((e) => ({ errors: [String(e)] }));
      pages.push({ page, empty: [], blank: [], ...result });
      const blank = result.blank ? `${result.blank.length} of ${result.canvases} canvases blank` : 'not checked';
      const empty = result.empty?.length ? `, widgets that never mounted: ${result.empty.join(', ')}` : '';
      console.log(`  ${name} ${page}: ${result.errors.length} errors, ${blank}${empty}`);
      for (const e of result.errors) console.log(`    ${e.slice(0, 300)}`);
    }
    return { name, parity, pages, seconds: (performance.now() - t0) / 1000 };
  } finally {
    await driver.close();
  }
}

const faults = (p) => p.errors.length + p.blank.length + p.empty.length;

function printTable(rows) {
  const line = (cells) => cells.map((c, i) => String(c).padEnd([10, 66, 18, 0][i])).join(' ');
  console.log(`\n${line(['engine', 'GL renderer', 'beyond tolerance', 'pages with errors, blanks or empty slots'])}`);
  for (const r of rows) {
    const bad = r.pages?.filter(faults) ?? [];
    const parity = r.parity?.error ?? `${r.parity?.failed.length} of ${r.parity?.total}`;
    const pages = r.error ?? `${bad.length} of ${r.pages.length}`;
    console.log(line([r.name, r.parity?.renderer ?? '?', parity, `${pages} (${r.seconds?.toFixed(0) ?? '?'} s)`]));
    for (const f of r.parity?.failed ?? []) console.log(`${' '.repeat(11)}beyond tolerance: ${f}`);
    for (const p of bad)
      console.log(
        `${' '.repeat(11)}${p.page}: ${p.errors.length} errors; blank: ${p.blank.join(', ') || 'none'}; ` +
          `never mounted: ${p.empty.join(', ') || 'none'}`,
      );
  }
}

async function main() {
  process.env.LANG = 'C.UTF-8';
  for (const signal of ['SIGINT', 'SIGTERM'])
    process.on(signal, async () => {
      await current?.close().catch(() => {});
      process.exit(130);
    });
  const dir = await probedBuild();
  const server = await serveStatic(dir);
  const rows = [];
  for (const name of engines) {
    console.log(`${name}…`);
    const row = await runEngine(name, server.url).catch((e) => ({ name, error: String(e).split('\n')[0] }));
    if (reportDir && row.parity?.report) {
      mkdirSync(reportDir, { recursive: true });
      writeFileSync(join(reportDir, `parity-${name}.txt`), row.parity.report);
    }
    rows.push(row);
  }
  server.close();
  rmSync(dir, { recursive: true, force: true });
  printTable(rows);
  const failed = rows.filter((r) => r.error || r.parity?.error || r.parity?.failed.length || r.pages.some(faults));
  process.exit(failed.length ? 1 : 0);
}

// without a display: the same command under xvfb-run (signals passed on, its exit code kept)
if (!process.env.DISPLAY) {
  const args = ['-a', '-s', '-screen 0 1280x1024x24', process.execPath, ...process.argv.slice(1)];
  const env = { ...process.env, LANG: 'C.UTF-8' };
  const child = spawn('xvfb-run', args, { stdio: 'inherit', env, detached: true }); // its own group, for the kill
  child.on('error', (e) => console.error(`no display and no xvfb-run (Debian: apt-get install xvfb): ${e}`));
  child.on('exit', (code) => process.exit(code ?? 1));
  for (const signal of ['SIGINT', 'SIGTERM']) process.on(signal, () => process.kill(-child.pid, signal));
} else {
  await main();
}
