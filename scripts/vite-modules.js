// The app's modules in plain Node, through Vite's module runner: those that read files with import.meta.glob (the
// shader chunks) or import CSS (the widgets' schemas), which Node alone cannot load. Used by scripts/scorm.js and
// bench/openpbr-materialx.js.
import { resolve } from 'node:path';

const ROOT = resolve(import.meta.dirname, '..');

/** { import(path), close() }: `path` from the repository's root, as '/src/…'. */
export async function viteModules() {
  const { createServer, createServerModuleRunner } = await import('vite');
  const server = await createServer({
    root: ROOT,
    logLevel: 'warn',
    configFile: false,
    server: { middlewareMode: true, hmr: false, ws: false },
  });
  const runner = createServerModuleRunner(server.environments.ssr, { hmr: false });
  return { import: (path) => runner.import(path), close: async () => (await runner.close(), await server.close()) };
}
