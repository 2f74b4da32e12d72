// Builds the app once and serves it for every browser test file; checks that a Chromium exists.
import { CHROME_HINT, buildApp, findChrome, serveStatic } from './harness.js';

export default async function setup(project) {
  if (!findChrome()) throw new Error(CHROME_HINT);
  const dir = await buildApp();
  const server = await serveStatic(dir);
  project.provide('baseUrl', server.url);
  return () => server.close();
}
