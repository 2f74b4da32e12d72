import { buildApp, launchBrowser, openPage, serveStatic } from './tests/browser/harness.js';
const out = '/tmp/shots/t28-micro3d';
const skip = process.argv.includes('--nobuild');
const dir = skip ? new URL('./dist', import.meta.url).pathname : await buildApp();
const server = await serveStatic(dir);
const browser = await launchBrowser([], { own: true });
const shots = [
  ['embed-1280', 'embed.html?w=anisotropic-microsurface', { width: 1280, height: 800 }],
  ['embed-390', 'embed.html?w=anisotropic-microsurface', { width: 390, height: 844, deviceScaleFactor: 2 }],
];
for (const [name, path, vp] of shots) {
  const page = await openPage(browser, server.url, path, vp);
  await page.setViewport(vp);
  await page.waitForFunction(() => globalThis.__shadingLab?.widgets?.['anisotropic-microsurface']?.getG1().complete, { timeout: 120000 });
  await new Promise((r) => setTimeout(r, 500));
  await page.screenshot({ path: `${out}/${name}.png`, fullPage: true });
  console.log(name, page.errors);
  const t0 = Date.now();
  await page.close();
}
await browser.close();
server.close();
