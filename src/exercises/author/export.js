// The set out of the author page: as a JSON file (the format exercises.html?src= reads), as a link that carries it
// (a data: URL, under the loader's size limit), and as a SCORM 1.2 package made in the browser from the app's own
// built files, the ones its service worker precaches (vite-plugin-pwa lists them at build), plus that worker.
import { MAX_SET_BYTES } from '../load.js';
import { buildPackage } from '../scorm/package.js';

/** The set file: { title, passMark, exercises } with the empty fields left out. */
export function setJson({ title, passMark, exercises }) {
  return { ...(title ? { title } : {}), ...(passMark === undefined ? {} : { passMark }), exercises };
}

/** The link that opens the set in exercises.html, or { error } past the size limit a set has. */
export function shareLink(set, base = location.href) {
  const text = JSON.stringify(set);
  const bytes = new TextEncoder().encode(text).length;
  const most = MAX_SET_BYTES.toLocaleString('en');
  if (bytes > MAX_SET_BYTES)
    return { error: `The set is ${bytes.toLocaleString('en')} bytes; a link carries ${most}.` };
  const url = new URL('exercises.html', base);
  url.search = `src=${encodeURIComponent(`data:application/json,${text}`)}`;
  return { url: url.href, bytes };
}

/** The paths of the built app: the service worker's precache list, the worker and its Workbox runtime. */
export async function appFiles(base = location.href) {
  const res = await fetch(new URL('sw.js', base)).catch(() => null);
  const type = res?.headers.get('content-type') ?? '';
  if (!res?.ok || !/javascript/.test(type))
    throw new Error('this page is not the built app (npm run build), whose service worker lists its files');
  const worker = await res.text();
  // minified or not: {url:"a.html",revision:"…"} or { "url": "a.html", "revision": "…" }
  const urls = [...worker.matchAll(/\{\s*"?url"?:\s*"([^"]+)",\s*"?revision"?:/g)].map((m) => m[1]);
  const runtime = [...worker.matchAll(/["']\.\/(workbox-[\w-]+)["']/g)].map((m) => `${m[1]}.js`);
  if (!urls.length) throw new Error('the service worker lists no files');
  return [...new Set([...urls, 'sw.js', ...runtime])].sort();
}

/** Fetches `paths` a few at a time: { path: bytes }. */
async function fetchAll(paths, base, onProgress) {
  const out = {};
  let done = 0;
  const queue = [...paths];
  const worker = async () => {
    for (let path = queue.shift(); path; path = queue.shift()) {
      const res = await fetch(new URL(path, base));
      if (!res.ok) throw new Error(`${path} could not be fetched (HTTP ${res.status})`);
      out[path] = new Uint8Array(await res.arrayBuffer());
      onProgress(++done, paths.length);
    }
  };
  await Promise.all(Array.from({ length: 6 }, worker));
  return out;
}

/** The package of a checked set: { zip, files, ms }. exercises: checked; raw: as saved; title; passMark. */
export async function scormPackage(
  { exercises, raw, title, passMark },
  { base = location.href, onProgress = () => {} } = {},
) {
  const started = performance.now();
  const app = await fetchAll(await appFiles(base), base, onProgress);
  const { zip, files } = buildPackage({ app, exercises, raw, title, passMark });
  return { zip, files, ms: performance.now() - started };
}
