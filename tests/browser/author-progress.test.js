// A student's progress file on exercises.html, for a course with no LMS: an answer checked, "Save my progress"
// downloads the file (read back with the app's own reader), Reset forgets the progress, and loading the file
// brings the solved exercise back; a file that is not one is refused in words, the progress unchanged.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { WAIT_MS, allowDownloads, launchBrowser, open } from './helpers.js';
import { readProgressFile } from '../../src/exercises/progress.js';

// Lo = π (cdiff/π) c_light cos θ = 2 · cos 60° = 1 (docs/exercises.md, lambert-radiance)
const SET = {
  title: 'One wall',
  exercises: [
    {
      id: 'wall',
      chapter: 'diffuse',
      title: 'A lit wall',
      prompt: 'What radiance leaves the wall?',
      grader: 'lambert-radiance',
      params: { cLight: 2, thetaDeg: 60 },
      tolerance: 0.01,
      points: 3,
    },
  ],
};

let browser;
let dir;
beforeAll(async () => {
  browser = await launchBrowser();
  dir = mkdtempSync(join(tmpdir(), 'progress-file-'));
});
afterAll(async () => {
  await browser?.close();
  rmSync(dir, { recursive: true, force: true });
});

describe('a progress file on the exercises page', () => {
  it('saves the progress to a file, and brings it back after a reset', async () => {
    const src = encodeURIComponent(`data:application/json,${JSON.stringify(SET)}`);
    const page = await open(browser, `exercises.html?src=${src}`, { width: 1280, height: 900 });
    await allowDownloads(page, dir);
    await page.waitForFunction(() => globalThis.__shadingLab?.exercise?.ready, { timeout: WAIT_MS });
    await page.type('#exercise-answer', '1');
    await page.click('.exercise-check');
    await page.waitForSelector('.exercise-feedback.ok');
    await page.type('#progress-name', 'Ada L.');
    await page.click('#progress-save');
    const file = join(dir, 'ada-l-shading-lab-progress.json');
    await expect.poll(() => existsSync(file), { timeout: WAIT_MS }).toBe(true);
    const got = readProgressFile(readFileSync(file, 'utf8'));
    expect(got.file).toMatchObject({ name: 'Ada L.', set: 'One wall' });
    expect(got.file.exercises).toEqual([{ id: 'wall', title: 'A lit wall', points: 3, solved: true, attempts: 1 }]);

    page.on('dialog', (d) => d.accept()); // Reset progress asks first
    await page.click('.exercise-reset');
    const solved = () => page.$eval('.exercise-progress', (p) => p.textContent.trim());
    await expect.poll(solved, { timeout: WAIT_MS }).toBe('0 of 1 solved');
    const bad = join(dir, 'notes.json');
    writeFileSync(bad, '{"solved": ["wall"]}');
    await (await page.$('#progress-load')).uploadFile(bad);
    await expect
      .poll(() => page.$eval('#progress-message', (m) => m.textContent), { timeout: WAIT_MS })
      .toBe(
        'notes.json is not a Shading Lab progress file (saved with “Save my progress”); your progress is unchanged.',
      );
    await (await page.$('#progress-load')).uploadFile(file);
    await expect.poll(solved, { timeout: WAIT_MS }).toBe('1 of 1 solved');
    expect(await page.$eval('#progress-message', (m) => m.textContent)).toBe('Loaded 1 exercise.');
    expect(page.errors).toEqual([]);
    await page.close();
  });
});
