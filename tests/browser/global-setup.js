// Builds the app once and serves it for every browser test file; checks that a Chromium exists. Each browser project
// runs this setup: the build is made once per run (shared through the main process) and each project has a server.
import { CHROME_HINT, buildApp, findChrome, serveStatic } from './harness.js';

export default async function setup(project) {
  if (!findChrome()) throw new Error(CHROME_HINT);
  const dir = await (globalThis.__shadingLabBuild ??= buildApp());
  const server = await serveStatic(dir);
  project.provide('baseUrl', server.url);
  return () => server.close();
}
