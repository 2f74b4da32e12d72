// The lecturer's host for the slides tests and screenshots: the repo's examples, reveal.js from node_modules
// and the built modules (dist/), served on `localhost` while the app is on 127.0.0.1 (another origin).
import { readFileSync } from 'node:fs';
import { createServer } from 'node:http';
import { extname, join, normalize } from 'node:path';
import { ROOT } from './harness.js';

const TYPES = { '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript', '.css': 'text/css' };
const SERVED = ['/examples/', '/node_modules/reveal.js/dist/', '/dist/'];

/**
 * The lecturer's host: the repo's examples, reveal.js and the built modules, on `localhost` (the app is on 127.0.0.1).
 */
export function serveDecks(pages) {
  const server = createServer((req, res) => {
    const path = decodeURIComponent(new URL(req.url, 'http://x').pathname);
    if (path === '/favicon.ico') return void res.writeHead(204).end();
    if (pages[path]) return void res.writeHead(200, { 'content-type': 'text/html' }).end(pages[path]);
    const file = normalize(join(ROOT, path));
    if (!SERVED.some((p) => path.startsWith(p)) || !file.startsWith(ROOT)) return void res.writeHead(404).end();
    try {
      res
        .writeHead(200, { 'content-type': TYPES[extname(file)] ?? 'application/octet-stream' })
        .end(readFileSync(file));
    } catch {
      res.writeHead(404).end();
    }
  });
  return new Promise((ok) =>
    server.listen(0, '127.0.0.1', () =>
      ok({ url: `http://localhost:${server.address().port}`, close: () => server.close() }),
    ),
  );
}

/** A deck of `n` slides, each with a 3-D widget; fragments on every third (cheap modes: no 64-light average). */
export function longDeck(n) {
  const slides = Array.from({ length: n }, (_, i) => {
    const frag = i % 3 === 0 ? '<p class="fragment" data-shading-lab-set="mode=zones-nv">zones of n·v</p>' : '';
    return (
      `<section data-shading-lab="fresnel-zones?mode=zones-lh&amp;lightTheta=${40 + 3 * i}"><h3>Slide ` +
      `${i + 1}</h3>${frag}</section>`
    );
  });
  return `<!doctype html><html><head><meta charset="utf-8"><title>Long deck</title>
<link rel="stylesheet" href="/node_modules/reveal.js/dist/reveal.css"></head>
<body><div class="reveal"><div class="slides">${slides.join('')}</div></div>
<script type="module" src="/examples/deck/deck.js"></script></body></html>`;
}
