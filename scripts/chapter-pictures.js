// npm run chapter-pictures: one small picture per chapter for the landing page (public/chapters/KEY.webp), shot
// from the chapter's main widget in a telling state, cropped to 16:9 and encoded by Chromium as WebP.
import { mkdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { ROOT, buildApp, launchBrowser, openPage, serveStatic, settle } from '../tests/browser/harness.js';
import { CHAPTER_PICTURE_SIZE as SIZE } from '../src/pages/chapter-pictures.js';

const QUALITY = 0.78;
// chapter key → the page shot, the element pictured (default: the first canvas of the widget's view), how it fits
// the 16:9 frame ('cover': cropped, centred, for a picture with no words at its edges; 'contain': whole, on the
// page's background), and the width of the window it is shot in (narrow for a plot, so that its words come out
// near their size on the page, not shrunk). Rows of spheres show two or three, so that each sphere and its name
// are whole and large enough to read.
const SHOTS = {
  media: ['embed.html?w=media&view=grid&samples=16'],
  surfaces: ['embed.html?w=surfaces&material=gold&alpha=0.3'],
  brdf: ['embed.html?w=brdf-lobe&lightTheta=50&alpha=0.3', '.lobe-3d canvas'],
  microfacets: ['embed.html?w=microfacets&lightTheta=60&rays=24'],
  fresnel: ['embed.html?w=fresnel-zones&mode=zones-lh&shape=torusknot&lightTheta=140'],
  ndf: ['embed.html?w=ndf-explorer&hwhm=12&D=ggx,beckmann', '.sphere-grid canvas', 'contain', 420],
  visibility: [
    'embed.html?w=visibility-explorer&alpha=0.9&lightTheta=60&V=implicit,smithGGXCorrelated',
    '.sphere-grid canvas',
    'contain',
    420,
  ],
  diffuse: ['embed.html?w=diffuse-explorer&diffuse=lambert,orenNayar&sigma=60', '.sphere-grid canvas', 'contain', 420],
  rendering: ['embed.html?w=material-lab&material=gold&alpha=0.25', '.widget-view canvas', 'contain'],
  today: [
    'embed.html?w=brdf-lobe&brdf=openpbr&base_color=%23b22222&specular_roughness=0.5&coat_weight=1&coat_roughness=0.3' +
      '&lightTheta=45&viewTheta=20&cosine=true',
    '.polar-plot canvas',
    'contain',
    560,
  ],
  performance: ['performance.html', '.uplot .u-wrap', 'contain', 560],
};

const out = join(ROOT, 'public/chapters');
mkdirSync(out, { recursive: true });
const server = await serveStatic(await buildApp());
const browser = await launchBrowser();
// `npm run chapter-pictures -- ndf diffuse` shoots only those chapters' pictures
const only = process.argv.slice(2);
const shots = Object.entries(SHOTS).filter(([key]) => !only.length || only.includes(key));
for (const [key, [path, selector = '.widget-view canvas', fit = 'cover', width = 1100]] of shots) {
  const page = await openPage(browser, server.url, path, { width, height: 800 });
  const target = await page.waitForSelector(selector, { timeout: 120_000 });
  await page.addStyleTag({ content: '.save-view { display: none !important; }' }); // the view's own button
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
