// The material lab as it opens and its readout of the sphere's centre, in Chromium: the punctual light on, and the
// centre's radiance read back from the approximation against the talk's L = π f c_light (n·l) (src/math/brdf.js's
// punctualRadiance with Lambert's f = c_diff/π from src/math/diffuse.js).
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { WAIT_MS, getState, launchBrowser, open, widget } from './helpers.js';
import { punctualRadiance } from '../../src/math/brdf.js';
import { diffuseLambert } from '../../src/math/diffuse.js';
import { WHITE_LAMBERT_HEAD_ON } from '../../src/widgets/material-lab/model.js';

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

const centreRow = (page) =>
  page.$$eval('.lab-readout tr', (rows) => rows.map((r) => r.textContent).find((t) => t.startsWith('Radiance at')));
const number = (text, before) => Number.parseFloat(text.split(before)[1]);

describe('material lab: opens lit, reads its centre', () => {
  it('opens with the punctual light on, the folders of the lights that are off closed', async () => {
    const page = await open(browser, 'embed.html?w=material-lab&refSamples=128', { width: 1280, height: 800 });
    await widget(page, 'material-lab');
    expect((await getState(page, 'material-lab')).punctual).toBe(true);
    const closed = await page.$$eval('.widget-material-lab .lil-gui.lil-closed > .lil-title', (els) =>
      els.map((e) => e.textContent),
    );
    // the anisotropic lobe's folder too: anisotropy starts at 0, the talk's isotropic lobe; and OpenPBR's, the BRDF
    // being the talk's model
    const openPbr = ['OpenPBR base', 'OpenPBR specular', 'OpenPBR coat', 'OpenPBR fuzz'];
    expect(closed).toEqual(['Anisotropy', ...openPbr, 'Sphere light', 'Ambient light', 'Reference and display']);
    const layout = await page.evaluate(() => {
      const bottom = (q) => document.querySelector(q).getBoundingClientRect().bottom;
      return {
        view: bottom('.widget-material-lab .widget-view'),
        panel: bottom('.widget-material-lab .widget-controls'),
      };
    });
    console.log(`material lab at 1280 px: view column ends at ${layout.view} px, panel at ${layout.panel} px`);
    expect(layout.panel - layout.view).toBeLessThan(200);
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it('one button lights a white Lambert sphere head-on: the centre reads L = c_light, f = 1/π, and L/π', async () => {
    const page = await open(browser, 'embed.html?w=material-lab&refSamples=128', { width: 1280, height: 800 });
    await widget(page, 'material-lab');
    await page.click('.lab-head-on');
    const state = await getState(page, 'material-lab');
    for (const [key, value] of Object.entries(WHITE_LAMBERT_HEAD_ON)) expect(state[key]).toBe(value);
    await expect.poll(() => centreRow(page), { timeout: WAIT_MS }).toMatch(/punctual light alone/);
    const expected = punctualRadiance(diffuseLambert(1), 1, 1); // 1: c_light itself
    let row = await centreRow(page);
    expect(Math.abs(number(row, 'L = ') - expected)).toBeLessThan(2e-3);
    expect(Math.abs(number(row, 'f = L / (π c_light (n·l)) = ') - diffuseLambert(1))).toBeLessThan(2e-3);
    expect(Math.abs(number(row, 'L / π = ') - expected / Math.PI)).toBeLessThan(2e-3);
    // 60° from the view, c_light 3: L = π (1/π) 3 cos 60° = 1.5
    await page.evaluate(() => globalThis.__shadingLab.widgets['material-lab'].update({ lightTheta: 60, cLight: 3 }));
    await expect
      .poll(async () => number(await centreRow(page), 'L = '), { timeout: WAIT_MS })
      .toBeCloseTo(punctualRadiance(diffuseLambert(1), Math.cos(Math.PI / 3), 3), 2);
    row = await centreRow(page);
    expect(row).toMatch(/c_light \(n·l\) = 3 × 0\.500 = 1\.500/);
    expect(page.errors).toEqual([]);
    await page.close();
  });
});
