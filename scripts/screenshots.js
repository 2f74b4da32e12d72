// npm run screenshots: builds the app and writes a screenshot of every page to docs/screenshots/.
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';
import { ROOT, buildApp, launchBrowser, openPage, serveStatic, settle } from '../tests/browser/harness.js';

const SHOTS = [
  ['landing', 'index.html', { fullPage: true }],
  ['fresnel-page', 'fresnel.html', { fullPage: true }],
  ['fresnel-curves', 'embed.html?w=fresnel-curves&materials=gold,copper,aluminum,water,diamond'],
  ['fresnel-zones-nv', 'embed.html?w=fresnel-zones&mode=zones-nv'],
  ['fresnel-zones-lh', 'embed.html?w=fresnel-zones&mode=zones-lh&shape=torusknot&lightTheta=140'],
  ['fresnel-zones-weighted', 'embed.html?w=fresnel-zones&mode=zones-lh-weighted&shape=torusknot&lightTheta=140'],
  ['fresnel-zones-gold-teapot', 'embed.html?w=fresnel-zones&material=gold&shape=teapot&camera=perspective'],
  ['f0-tables', 'embed.html?w=f0-tables'],
  ['bad-url', 'embed.html?w=fresnel-zones&mode=banana&lightTheta=400&alpha=x'],
  ['parity', 'parity.html', { fullPage: true }],
  ['media-page', 'media.html?media.distance=1.3', { fullPage: true }],
  ['media-grid', 'embed.html?w=media&view=grid&samples=16'],
  ['surfaces-page', 'surfaces.html', { fullPage: true }],
  // tall: a 3-D view out of sight draws nothing; shot once the measured-BRDF widget's five fits are in, from
  // the viewport as it is (capturing beyond it re-lays the page out and the 3-D views come out blank)
  [
    'brdf-page',
    'brdf.html',
    {
      fullPage: true,
      height: 6000,
      captureBeyondViewport: false,
      ready: 'Object.keys(globalThis.__shadingLab.widgets.measured?.getFits() ?? {}).length === 5',
    },
  ],
  ['brdf-lobe-compare', 'embed.html?w=brdf-lobe&compare=1&cosine=1&lightTheta=60&viewTheta=20'],
  ['brdf-lobe-multiple', 'embed.html?w=brdf-lobe&multiple=1&alpha=1&F=one&lightTheta=30&viewTheta=20'],
  ['microfacets-page', 'microfacets.html', { fullPage: true }],
  ['energy-compensated', 'embed.html?w=energy&compensation=kullaConty', { fullPage: true }],
  ['ndf-page', 'ndf.html?ndf.exposure=8', { fullPage: true }],
  ['visibility-page', 'visibility.html', { fullPage: true }],
  ['diffuse-page', 'diffuse.html', { fullPage: true }],
  ['rendering-page', 'rendering.html', { fullPage: true }],
  ['performance-page', 'performance.html', { fullPage: true }],
  ['exercises-page', 'exercises.html#match-sphere', { fullPage: true }],
  ['author-page', 'author.html', { fullPage: true }],
  ['tour-fresnel-zones-lh', 'tour.html#fresnel-zones-lh'],
  ['tour-media-grid', 'tour.html#media-grid', { fullPage: true }],
  ['gallery-page', 'gallery.html', { fullPage: true }],
  ['wall-page', 'wall.html'], // not full page: that would put all twenty views in sight at once
];

const out = join(ROOT, 'docs/screenshots');
mkdirSync(out, { recursive: true });
const server = await serveStatic(await buildApp());
const browser = await launchBrowser();
for (const [name, path, { height, ready, ...opts } = {}] of SHOTS) {
  const page = await openPage(browser, server.url, path, height ? { height } : {});
  if (ready) await page.waitForFunction(ready, { timeout: 600_000, polling: 1000 });
  await settle(page, 800);
  // views out of sight draw nothing until they scroll into view: scroll through the page as a reader would
  for (let y = 0; y < (await page.evaluate(() => document.body.scrollHeight)); y += 600) {
    await page.evaluate((top) => window.scrollTo(0, top), y);
    await settle(page, 250);
  }
  await page.evaluate(() => window.scrollTo(0, 0));
  await page.evaluate(() => document.querySelector('.offline-status')?.remove()); // the first visit's "saved offline"
  await settle(page, 300);
  await page.screenshot({ path: join(out, `${name}.png`), ...opts });
  console.log(`${name}.png${page.errors.length ? `  errors: ${page.errors.join(' | ')}` : ''}`);
  await page.close();
}
await browser.close();
server.close();
