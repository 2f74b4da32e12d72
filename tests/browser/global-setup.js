// Builds the app once (not at all when dist/ is the build of the present sources: build-cache.js) and serves it for
// every browser test file; checks that a Chromium exists. Each browser project runs this setup: the build is made
// once per run (shared through the main process) and each project has a server.
// It also keeps one Chromium per worker (the broker below): each file asks for its worker's one and works in an
// incognito context of its own (harness.js, launchBrowser), instead of starting a Chromium of its own.
import { createServer } from 'node:http';
import { CHROME_HINT, findChrome, serveStatic, startChromium } from './harness.js';
import { buildOnce } from './build-cache.js';

/** Closes every incognito context of `browser` (what a file that ended without closing its own left behind). */
async function disposeContexts(browser) {
  const session = await browser.target().createCDPSession();
  try {
    const { browserContextIds } = await session.send('Target.getBrowserContexts');
    await Promise.all(
      browserContextIds.map((id) =>
        session.send('Target.disposeBrowserContext', { browserContextId: id }).catch(() => {}),
      ),
    );
  } finally {
    await session.detach();
  }
}

/**
 * Serves GET /?worker=N&pid=P: the DevTools WebSocket address of worker N's Chromium, started on the first ask and
 * again whenever the last one has crashed or been closed. Each test file runs in a process of its own (P): asked by
 * a new one, the broker first closes whatever contexts the worker's last file left open (a file stopped by a timeout
 * in its hooks, say), so that no page of it goes on drawing beside the next file. Resolves to { url, close }.
 */
function chromiumBroker() {
  const browsers = new Map(); // worker → Promise<Browser>
  const served = new Map(); // worker → the process it last served
  const forWorker = async (worker, pid) => {
    let browser = await browsers.get(worker)?.catch(() => null);
    if (!browser?.connected) {
      const started = startChromium();
      browsers.set(worker, started);
      browser = await started;
    } else if (served.get(worker) !== pid) await disposeContexts(browser);
    served.set(worker, pid);
    return browser;
  };
  const server = createServer((req, res) => {
    const query = new URL(req.url, 'http://x').searchParams;
    forWorker(query.get('worker') ?? '0', query.get('pid')).then(
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
  const dir = await (globalThis.__shadingLabBuild ??= buildOnce());
  const server = await serveStatic(dir);
  const broker = await chromiumBroker();
  project.provide('baseUrl', server.url);
  project.provide('chromiumBroker', broker.url);
  return async () => {
    server.close();
    await broker.close();
  };
}
