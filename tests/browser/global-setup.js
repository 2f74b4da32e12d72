// Builds the app once and serves it for every browser test file; checks that a Chromium exists. Each browser project
// runs this setup: the build is made once per run (shared through the main process) and each project has a server.
// It also keeps one Chromium per worker (the broker below): each file asks for its worker's one and works in an
// incognito context of its own (harness.js, launchBrowser), instead of starting a Chromium of its own.
import { createServer } from 'node:http';
import { CHROME_HINT, buildApp, findChrome, serveStatic, startChromium } from './harness.js';

/**
 * Serves GET /?worker=N: the DevTools WebSocket address of worker N's Chromium, started on the first ask and again
 * whenever the last one has crashed or been closed. Resolves to { url, close } (close ends every Chromium).
 */
function chromiumBroker() {
  const browsers = new Map(); // worker → Promise<Browser>
  const forWorker = async (worker) => {
    const known = await browsers.get(worker)?.catch(() => null);
    if (known?.connected) return known;
    const started = startChromium();
    browsers.set(worker, started);
    return started;
  };
  const server = createServer((req, res) => {
    const worker = new URL(req.url, 'http://x').searchParams.get('worker') ?? '0';
    forWorker(worker).then(
      (browser) => res.writeHead(200).end(browser.wsEndpoint()),
      (error) => res.writeHead(500).end(String(error?.message ?? error)),
    );
  });
  const close = async () => {
    server.close();
    const all = await Promise.all([...browsers.values()].map((b) => b.catch(() => null)));
    await Promise.all(all.map((b) => b?.close().catch(() => {})));
  };
  return new Promise((ok) => {
    server.listen(0, '127.0.0.1', () => ok({ url: `http://127.0.0.1:${server.address().port}/`, close }));
  });
}

export default async function setup(project) {
  if (!findChrome()) throw new Error(CHROME_HINT);
  const dir = await (globalThis.__shadingLabBuild ??= buildApp());
  const server = await serveStatic(dir);
  const broker = await chromiumBroker();
  project.provide('baseUrl', server.url);
  project.provide('chromiumBroker', broker.url);
  return async () => {
    server.close();
    await broker.close();
  };
}
