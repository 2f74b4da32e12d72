// npm run chapter-pictures: one small picture per chapter for the landing page (public/chapters/KEY.webp), shot
// from the chapter's main widget in a telling state, cropped to 16:9 and encoded by Chromium as WebP.
import { mkdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { ROOT, buildApp, launchBrowser, openPage, serveStatic, settle } from './harness.js';
import { CHAPTER_PICTURE_SIZE as SIZE } from '../../src/pages/chapter-pictures.js';

const QUALITY = 0.78;
// chapter key → the page shot, the element pictured (default: the first canvas of the widget's view), and how it
// fits the 16:9 frame: 'cover' (cropped, centred) or 'contain' (whole, on the page's background)
const SHOTS = {
  media: ['embed.html?w=media&view=grid&samples=16'],
  surfaces: ['embed.html?w=surfaces&material=gold&alpha=0.3'],
  brdf: ['embed.html?w=brdf-lobe&lightTheta=50&alpha=0.3', '.lobe-3d canvas'],
  microfacets: ['embed.html?w=microfacets&lightTheta=60&rays=24'],
  fresnel: ['embed.html?w=fresnel-zones&mode=zones-lh&shape=torusknot&lightTheta=140'],
  ndf: ['embed.html?w=ndf-explorer&hwhm=12', '.sphere-grid canvas'],
  visibility: ['embed.html?w=visibility-explorer', '.widget-view canvas', 'contain'],
  diffuse: ['embed.html?w=diffuse-explorer'],
  rendering: ['embed.html?w=material-lab&material=gold&alpha=0.25', '.widget-view canvas', 'contain'],
  performance: ['performance.html', '.uplot', 'contain'],
};

const out = join(ROOT, 'public/chapters');
mkdirSync(out, { recursive: true });
const server = await serveStatic(await buildApp());
const browser = await launchBrowser();
for (const [key, [path, selector = '.widget-view canvas', fit = 'cover']] of Object.entries(SHOTS)) {
  const page = await openPage(browser, server.url, path, { width: 1100, height: 800 });
  const target = await page.waitForSelector(selector, { timeout: 30_000 });
  await target.scrollIntoView();
  await settle(page, 2500); // progressive views (the material lab's reference) get time to converge
  const png = await target.screenshot({ encoding: 'base64' });
  const webp = await page.evaluate(
    async (b64, { width, height }, quality, fit) => {
      const img = new Image();
      img.src = `data:image/png;base64,${b64}`;
      await img.decode();
      const scale = (fit === 'cover' ? Math.max : Math.min)(width / img.width, height / img.height);
      const c = Object.assign(document.createElement('canvas'), { width, height });
      const ctx = c.getContext('2d');
      ctx.fillStyle = getComputedStyle(document.body).backgroundColor;
      ctx.fillRect(0, 0, width, height);
      ctx.drawImage(
        img,
        (width - img.width * scale) / 2,
        (height - img.height * scale) / 2,
        img.width * scale,
        img.height * scale,
      );
      return c.toDataURL('image/webp', quality).split(',')[1];
    },
    png,
    SIZE,
    QUALITY,
    fit,
  );
  writeFileSync(join(out, `${key}.webp`), Buffer.from(webp, 'base64'));
  console.log(
    `${key}.webp ${Math.round((webp.length * 0.75) / 1024)} ` +
      `KiB${page.errors.length ? `  errors: ${page.errors.join(' | ')}` : ''}`,
  );
  await page.close();
}
await browser.close();
server.close();
