// The author page in Chromium: a set built with no JSON typed (a built-in exercise found by its chapter and kind,
// a number exercise and a widget-state exercise made with the form), the validator's messages beside the field
// each names as one types, the preview answered as a student would (graded against the closed form
// Lo = cdiff · c_light · cos θ), reordered, saved, opened again, shared as a link, and exported as a SCORM 1.2
// package whose bytes are unzipped with fflate: the manifest checked against the SCORM 1.2 structure, the set
// against the validator, the app's files byte-for-byte those of dist/.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { existsSync, mkdtempSync, readFileSync, readdirSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { strFromU8, unzipSync } from 'fflate';
import { WAIT_MS, allowDownloads, launchBrowser, open } from './helpers.js';
import { ROOT } from './harness.js';
import { readExerciseSet } from '../../src/exercises/load.js';
import { WIDGETS } from '../../src/widgets/registry.js';
import { DEG } from '../../src/math/angles.js';
import { createProgress, memoryStorage, progressFile } from '../../src/exercises/progress.js';

const schemaOf = async (name) => (Object.hasOwn(WIDGETS, name) ? (await WIDGETS[name].load()).widget.schema : null);
const field = (path) => `#author-form [data-field="${path}"]`;

let browser;
let downloads;
beforeAll(async () => {
  browser = await launchBrowser();
  downloads = mkdtempSync(join(tmpdir(), 'author-downloads-'));
});
afterAll(async () => {
  await browser?.close();
  rmSync(downloads, { recursive: true, force: true });
});

/** The messages shown beside the field `path` of the exercise form (or of the set's fields). */
const messages = (page, selector) =>
  page.$eval(selector, (box) => [...box.querySelectorAll(':scope > .author-errors li')].map((li) => li.textContent));

/** Replaces the text of a field's box, as typing does. */
async function fill(page, path, text) {
  const input = `${field(path)} > :is(input, textarea)`;
  await page.$eval(input, (el) => {
    el.value = '';
    el.focus();
  });
  await page.type(input, text);
}

/** A file the page downloads into `downloads`, once complete. */
async function downloaded(name) {
  const file = join(downloads, name);
  await expect.poll(() => existsSync(file) && !existsSync(`${file}.crdownload`), { timeout: WAIT_MS }).toBe(true);
  await expect.poll(() => statSync(file).size, { timeout: WAIT_MS }).toBeGreaterThan(0);
  return readFileSync(file);
}

const itemNames = (page) => page.$$eval('.author-items .author-pick', (bs) => bs.map((b) => b.textContent));

const filesUnder = (dir) =>
  readdirSync(dir, { recursive: true })
    .map(String)
    .filter((f) => statSync(join(dir, f)).isFile())
    .map((f) => f.split('\\').join('/'));

// one long story (each step needs the set the last one built); software WebGL on a loaded machine takes minutes
describe('the author page', { timeout: 600_000 }, () => {
  it('builds, previews, reorders, saves, opens, shares and exports a set with no JSON typed', async () => {
    const page = await open(browser, 'author.html', { width: 1280, height: 900 });
    // a preview frame sent elsewhere (another exercise picked, a newer version) aborts what it was still loading
    const aborted = new Set();
    page.on('requestfailed', (r) => {
      if (r.frame() !== page.mainFrame() && r.failure()?.errorText === 'net::ERR_ABORTED')
        aborted.add(`request failed: ${r.url()}`);
    });
    await allowDownloads(page, downloads);
    await page.waitForSelector('.author-library-list button');

    // a built-in exercise, found by chapter and kind
    await page.select('.author-filters [data-field="chapter"] select', 'fresnel');
    await page.select('.author-filters [data-field="kind"] select', 'number');
    const shown = await page.$$eval('.author-library-list li', (lis) => lis.map((li) => li.textContent));
    expect(shown).toHaveLength(2); // the two numbers of chapter 5: Schlick's worst angle, F82-tint's grazing gap
    expect(shown.every((t) => t.includes('chapter 5 · Type a number'))).toBe(true);
    const schlick = shown.findIndex((t) => t.includes('Where is Schlick worst?'));
    await page.click(`.author-library-list li:nth-child(${schlick + 1}) button`);
    await expect.poll(() => itemNames(page), { timeout: WAIT_MS }).toEqual(['Where is Schlick worst?']);

    // a number exercise made with the form: each message beside its field, gone once it is fixed
    await page.select('#author-new-kind', 'number');
    await page.click('#author-new');
    await page.select(`${field('grader')} select`, 'lambert-radiance');
    await expect
      .poll(() => messages(page, field('title')), { timeout: WAIT_MS })
      .toEqual(['title: missing (a non-empty string)']);
    await expect
      .poll(() => messages(page, field('params.thetaDeg')), { timeout: WAIT_MS })
      .toEqual(['params.thetaDeg: missing (required by grader "lambert-radiance")']);
    await fill(page, 'id', 'Wall Light');
    await fill(page, 'tolerance', '-1');
    await expect
      .poll(() => messages(page, field('id')), { timeout: WAIT_MS })
      .toEqual(['id: "Wall Light" is not a name of lower-case letters, digits and dashes']);
    await expect
      .poll(() => messages(page, field('tolerance')), { timeout: WAIT_MS })
      .toEqual(['tolerance: -1 is not a positive number']);
    expect(await messages(page, field('title'))).toEqual(['title: missing (a non-empty string)']);
    await fill(page, 'id', 'wall-light');
    await fill(page, 'title', 'A lit wall');
    await fill(page, 'prompt', 'What radiance $L_o$ leaves the wall?');
    await fill(page, 'params.cLight', '2');
    await fill(page, 'params.thetaDeg', '60');
    await fill(page, 'tolerance', '0,01');
    await fill(page, 'points', '2');
    await expect.poll(() => page.$$eval('#author-form .has-errors', (els) => els.length), { timeout: WAIT_MS }).toBe(0);

    // the preview is exercises.html: answered as a student would, graded against Lo = cdiff · c_light · cos θ
    const lo = 1 * 2 * Math.cos(60 * DEG);
    const frameHandle = await page.waitForSelector('.author-frame[src*="wall-light"]', { timeout: WAIT_MS });
    const frame = await frameHandle.contentFrame();
    await frame.waitForFunction(() => globalThis.__shadingLab?.exercise?.id === 'wall-light', { timeout: WAIT_MS });
    for (const [answer, ok] of [
      [String(lo * Math.PI), false],
      [String(lo), true],
    ]) {
      await frame.$eval('#exercise-answer', (el) => (el.value = ''));
      await frame.type('#exercise-answer', answer);
      await frame.click('.exercise-check');
      await frame.waitForFunction(
        (want) => document.querySelector(`.exercise-feedback.${want}`),
        {},
        ok ? 'ok' : 'wrong',
      );
    }
    expect(await frame.$eval('.exercise-prompt', (p) => p.textContent)).toContain('What radiance');

    // a widget-state exercise: the lock the grader needs is named beside the locks, ticked on the widget's list
    await page.select('#author-new-kind', 'state');
    await page.click('#author-new');
    await page.waitForSelector(`[data-field="locked"] input[value="material"]`, { timeout: WAIT_MS });
    await expect
      .poll(() => messages(page, '[data-field="locked"]'), { timeout: WAIT_MS })
      .toContain('locked: must include "material" (grader "fresnel-reflectance-angle" takes the question from it)');
    await page.click('[data-field="locked"] input[value="material"]');
    await fill(page, 'id', 'lake');
    await fill(page, 'title', 'A lake at 25%');
    await fill(page, 'prompt', 'Set the angle at which the lake reflects a quarter of the light.');
    await fill(page, 'params.target', '0.25');
    await expect
      .poll(() => page.$eval('#author-status', (s) => s.textContent), { timeout: WAIT_MS })
      .toContain('3 exercises, ready');

    // a shader exercise: a grid's messages beside that axis's field; then removed from the set
    await page.select('#author-new-kind', 'shader');
    await page.click('#author-new');
    await fill(page, 'domain.nh.steps', '500');
    await expect
      .poll(() => messages(page, field('domain.nh.steps')), { timeout: WAIT_MS })
      .toEqual(['domain.nh.steps: 500 is not a whole number within 2…101']);
    expect(await messages(page, field('sources'))).toEqual([
      'sources: missing (a list of sources, each its authors and year, e.g. "Schlick 1994")',
    ]);
    expect(await messages(page, field('domain.nh'))).toEqual([]);
    // the set's list is drawn again after each check: a button is pressed in one step, not found and then clicked
    await page.$eval('[aria-label="Remove “exercise-4”"]', (b) => b.click());

    // reorder with the arrows (the focus stays on the moved exercise's arrow), title and pass mark
    await page.$eval('[aria-label="Up: move “A lake at 25%” up"]', (b) => b.click());
    await expect
      .poll(() => itemNames(page), { timeout: WAIT_MS })
      .toEqual(['Where is Schlick worst?', 'A lake at 25%', 'A lit wall']);
    expect(await page.evaluate(() => document.activeElement.getAttribute('aria-label'))).toBe(
      'Up: move “A lake at 25%” up',
    );
    await page.type('[data-field="title"] input:not(#author-form *)', 'Week 3');
    await page.type('[data-field="passMark"] input', '60');
    await expect
      .poll(() => page.$eval('#author-status', (s) => s.textContent), { timeout: WAIT_MS })
      .toContain('3 exercises, ready');

    // saved as JSON: the validator passes it, in that order, with the points
    await page.click('#author-save');
    const saved = JSON.parse(String(await downloaded('week-3.json')));
    expect(saved).toMatchObject({ title: 'Week 3', passMark: 60 });
    const read = await readExerciseSet(saved, { source: 'week-3.json', schemaOf });
    expect(read.problems).toEqual([]);
    expect(read.exercises.map((e) => [e.id, e.points])).toEqual([
      ['schlick-worst', 1],
      ['lake', 1],
      ['wall-light', 2],
    ]);

    // shared as a link: exercises.html opens the same set from it
    await page.click('#author-share');
    const link = await page.waitForSelector('#author-link').then((h) => h.evaluate((el) => el.value));
    const shared = await open(browser, link.replace(/^.*?exercises\.html/, 'exercises.html'));
    await shared.waitForFunction(() => globalThis.__shadingLab?.exercise?.ready, { timeout: WAIT_MS });
    expect(await shared.$eval('.exercise-progress', (p) => p.textContent.trim())).toBe('0 of 3 solved');
    expect(shared.errors).toEqual([]);
    await shared.close();

    // exported as SCORM 1.2: the zip read back with fflate
    await page.click('#author-export');
    const zip = unzipSync(new Uint8Array(await downloaded('week-3-scorm.zip')));
    const made = await page.$eval('#author-output', (o) => o.textContent);
    console.log(`author export: ${made}`); // the package's size and the time it took, for the record
    const xml = strFromU8(zip['imsmanifest.xml']);
    expect(xml).toMatch(/<schema>ADL SCORM<\/schema>\s*<schemaversion>1\.2<\/schemaversion>/);
    expect(xml).toMatch(/<manifest identifier="shading-lab-[0-9a-z]+"/);
    expect(xml).toContain('<adlcp:masteryscore>60</adlcp:masteryscore>');
    expect(xml).toMatch(/adlcp:scormtype="sco" href="scorm-launch\.html"/);
    const listed = [...xml.matchAll(/<file href="([^"]+)"\/>/g)].map((m) => decodeURI(m[1]));
    expect(listed.sort()).toEqual(
      Object.keys(zip)
        .filter((f) => f !== 'imsmanifest.xml')
        .sort(),
    );
    expect(strFromU8(zip['scorm-launch.html'])).toContain('url=exercises.html?scorm=1&amp;src=set%2Fexercises.json');
    const set = JSON.parse(strFromU8(zip['set/exercises.json']));
    expect(set).toEqual({ ...saved, title: 'Week 3' });
    const dist = join(ROOT, 'dist');
    const app = filesUnder(dist);
    expect(
      Object.keys(zip)
        .filter((f) => !['imsmanifest.xml', 'scorm-launch.html', 'set/exercises.json'].includes(f))
        .sort(),
    ).toEqual(app.sort());
    for (const f of app) expect(Buffer.from(zip[f]).equals(readFileSync(join(dist, f))), f).toBe(true);

    // a student's progress file, as the exercises page saves it: 2 of 2 + 1 points solved, against the pass mark 60
    const student = join(downloads, 'ada.json');
    const done = createProgress(memoryStorage());
    done.record('lake', true, 'x');
    done.record('wall-light', false, 'y');
    const two = [
      { id: 'lake', title: 'A lake at 25%', points: 2 },
      { id: 'wall-light', title: 'A lit wall', points: 1 },
    ];
    writeFileSync(student, JSON.stringify(progressFile({ name: 'Ada', exercises: two, progress: done })));
    await (await page.$('#author-student-file')).uploadFile(student);
    await expect
      .poll(() => page.$eval('#author-student-view', (v) => v.textContent), { timeout: WAIT_MS })
      .toContain('Score 66.67% (1 of 2 solved; pass mark 60%): passed.');

    // opened again from the saved file: the same set, to edit
    await page.reload({ waitUntil: 'load' });
    await page.waitForSelector('.author-library-list button');
    const chooser = await page.$('#author-open-file');
    await chooser.uploadFile(join(downloads, 'week-3.json'));
    await expect
      .poll(() => itemNames(page), { timeout: WAIT_MS })
      .toEqual(['Where is Schlick worst?', 'A lake at 25%', 'A lit wall']);
    expect(await page.$eval('[data-field="passMark"] input', (i) => i.value)).toBe('60');
    expect(page.errors.filter((e) => !aborted.has(e))).toEqual([]);
    await page.close();
  });
});
