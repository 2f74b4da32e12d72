// A SCORM package from `npm run scorm` in a real SCORM 1.2 runtime: the unzipped package in an iframe of an
// LMS-like page whose window.API is scorm-again's Scorm12API (its browser build, from node_modules). A right and
// a wrong answer and a shader exercise's GLSL (worth 2 points) reach scorm-again as score (points solved of all),
// status and suspend data; a relaunch with that suspend data shows the progress; corrupt suspend data starts
// afresh; an API that refuses and throws is reported, answers still graded.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { copyFileSync, mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { unzipSync } from 'fflate';
import { ROOT, launchBrowser, openPage, serveStatic } from './harness.js';
import { WAIT_MS } from './helpers.js';
import { readExerciseSet } from '../../src/exercises/load.js';
import { WIDGETS } from '../../src/widgets/registry.js';
import { packageSet } from '../../scripts/scorm.js';
import { SHADER_SOLUTIONS } from './shader-solutions.js';

const EXERCISES = join(ROOT, 'public/exercises');
const schemaOf = async (name) => (Object.hasOwn(WIDGETS, name) ? (await WIDGETS[name].load()).widget.schema : null);

// The LMS page: scorm-again's API on window.API (or one that refuses every write and throws on commit), the
// suspend data of a previous visit loaded before LMSInitialize, and the package's launch file in a frame.
const LMS_JS = `
const params = new URLSearchParams(location.search);
const api = new Scorm12API({ autocommit: false, logLevel: 5 });
if (params.has('suspend')) api.loadFromJSON({ suspend_data: params.get('suspend') });
let last = '0';
const refusing = {
  ...Object.fromEntries(['LMSInitialize', 'LMSFinish', 'LMSGetErrorString'].map((n) => [n, (...a) => api[n](...a)])),
  LMSGetValue: (k) => ((last = '0'), api.LMSGetValue(k)),
  LMSSetValue: () => ((last = '405'), 'false'),
  LMSCommit: () => { throw new Error('the LMS is unreachable'); },
  LMSGetLastError: () => last,
};
window.scormAgain = api;
window.API = params.get('mode') === 'errors' ? refusing : api;
const frame = Object.assign(document.createElement('iframe'), { src: 'package/scorm-launch.html', title: 'Exercises' });
frame.style.cssText = 'width: 100%; height: 90vh; border: 0';
document.body.append(frame);
`;

let browser;
let server;
let dir;
beforeAll(async () => {
  dir = mkdtempSync(join(tmpdir(), 'scorm-lms-'));
  const setFile = join(dir, 'two.json');
  const three = ['schlick-worst.json', 'lambert-brightness.json', 'shader-schlick.json'].map((f) =>
    JSON.parse(readFileSync(join(EXERCISES, f))),
  );
  three[2].points = 2;
  writeFileSync(setFile, JSON.stringify({ title: 'Three exercises', exercises: three }));
  const got = await packageSet({
    setFile,
    outFile: join(dir, 'two.zip'),
    dist: join(ROOT, 'dist'), // built by the browser tests' global setup
    validate: { readExerciseSet, schemaOf },
  });
  expect(got.errors).toBeUndefined();
  for (const [name, bytes] of Object.entries(unzipSync(readFileSync(join(dir, 'two.zip'))))) {
    mkdirSync(join(dir, 'package', name, '..'), { recursive: true });
    writeFileSync(join(dir, 'package', name), bytes);
  }
  copyFileSync(join(ROOT, 'node_modules/scorm-again/dist/scorm12.js'), join(dir, 'scorm12.js'));
  writeFileSync(join(dir, 'lms.js'), LMS_JS);
  writeFileSync(
    join(dir, 'lms.html'),
    '<!doctype html><title>LMS</title><link rel="icon" href="data:,"><script src="scorm12.js"></script>' +
      '<body><script src="lms.js"></script></body>',
  );
  server = await serveStatic(dir);
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
  server?.close();
  if (dir) rmSync(dir, { recursive: true, force: true });
});

/** The LMS page and the exercises frame in it, once its first exercise is up. */
async function launch(query = '') {
  const page = await openPage(browser, server.url, `lms.html${query}`, {
    timeout: WAIT_MS,
    beforeLoad: (p) => {
      p.requests = [];
      p.on('request', (r) => r.frame() !== p.mainFrame() && p.requests.push(r.url())); // the package's
    },
  });
  let frame;
  await expect
    .poll(() => (frame = page.frames().find((f) => f.url().includes('exercises.html'))), { timeout: WAIT_MS })
    .toBeTruthy();
  await frame.waitForFunction(() => globalThis.__shadingLab?.exercise?.ready, { timeout: WAIT_MS });
  return { page, frame };
}

async function answer(frame, id, text) {
  await frame.click(`#exercise-list a[href="#${id}"]`);
  await frame.waitForFunction(
    (i) => globalThis.__shadingLab.exercise?.id === i && globalThis.__shadingLab.exercise.ready,
    {},
    id,
  );
  await frame.$eval('#exercise-answer', (el) => (el.value = ''));
  await frame.type('#exercise-answer', text);
  await frame.click('.exercise-check');
  await frame.waitForFunction(() => document.querySelector('.exercise-feedback')?.textContent);
  return frame.$eval('.exercise-feedback', (el) => el.className.includes('ok'));
}

/** Answers the shader exercise with its correct GLSL, typed into its editor as a student would. */
async function answerShader(page, frame, id) {
  await frame.click(`#exercise-list a[href="#${id}"]`);
  await frame.waitForFunction(
    (i) => globalThis.__shadingLab.exercise?.id === i && globalThis.__shadingLab.exercise.ready,
    { timeout: WAIT_MS },
    id,
  );
  await frame.click('.exercise-code .cm-content');
  await page.keyboard.down('Control');
  await page.keyboard.press('a');
  await page.keyboard.up('Control');
  await page.keyboard.press('Backspace');
  await page.keyboard.sendCharacter(SHADER_SOLUTIONS[id].correct);
  await frame.click('.exercise-check');
  await frame.waitForSelector('.exercise-feedback.ok, .exercise-feedback.wrong', { timeout: WAIT_MS });
  return frame.$eval('.exercise-feedback', (el) => el.className.includes('ok'));
}

// scorm-again's data model as it would send it to a server (its JSON export, which may read write-only elements)
const cmi = (page) =>
  page.evaluate(() => {
    const c = JSON.parse(JSON.stringify(window.scormAgain.cmi));
    const { score, lesson_status: status, session_time: time } = c.core;
    return {
      raw: score.raw,
      max: score.max,
      status,
      suspend: c.suspend_data,
      time,
      finished: window.scormAgain.isTerminated(),
    };
  });
const notice = (frame) => frame.$eval('.scorm-notice', (el) => el.textContent);
const solvedLine = (frame) => frame.$eval('.exercise-progress', (el) => el.textContent.trim());

describe('a SCORM package in scorm-again’s SCORM 1.2 runtime', () => {
  it('sends score, status and suspend data, finishes on leaving, and resumes from that suspend data', async () => {
    const first = await launch();
    expect(await notice(first.frame)).toContain('Connected to your course’s LMS');
    const where = (frame) => frame.$eval('#exercise-progress-where', (el) => el.textContent);
    expect(await where(first.frame)).toMatch(/^Your progress goes to your course’s learning management system/);
    expect(await answer(first.frame, 'schlick-worst', '85')).toBe(true);
    expect(await answer(first.frame, 'lambert-brightness', '4.712')).toBe(false);
    expect(await answerShader(first.page, first.frame, 'shader-schlick')).toBe(true);
    const sent = await cmi(first.page);
    // 1 + 2 of the 1 + 1 + 2 points solved: 75 of 100; not every exercise solved and no pass mark: incomplete
    expect(sent).toMatchObject({ raw: '75', max: '100', status: 'incomplete', finished: false });
    expect(sent.suspend).toMatch(/^SL1:[0-9a-z]+:s1\.u1\.s1$/);
    expect(sent.time).toMatch(/^\d{2,4}:\d\d:\d\d(\.\d\d)?$/);
    await first.page.$eval('iframe', (f) => (f.src = 'about:blank')); // leaving: pagehide → LMSFinish
    await expect.poll(async () => (await cmi(first.page)).finished, { timeout: WAIT_MS }).toBe(true);
    // offline: the package asks only for its own files (and data: URLs, a font lil-gui carries)
    const outside = first.page.requests.filter((u) => !/^(data:|about:blank$)/.test(u));
    expect(outside.filter((u) => !u.startsWith(`${server.url}package/`))).toEqual([]);
    expect(outside.length).toBeGreaterThan(5);
    expect(first.page.errors).toEqual([]);
    await first.page.close();

    const again = await launch(`?suspend=${encodeURIComponent(sent.suspend)}`);
    expect(await solvedLine(again.frame)).toBe('2 of 3 solved');
    expect(await again.frame.$eval('a[href="#lambert-brightness"]', (a) => a.parentElement.textContent)).toContain(
      '1 attempt',
    );
    expect(await answer(again.frame, 'lambert-brightness', '1.5')).toBe(true);
    expect(await cmi(again.page)).toMatchObject({ raw: '100', status: 'passed' });
    await again.page.close();
  });

  it('starts afresh from corrupt suspend data and says so', async () => {
    const { page, frame } = await launch('?suspend=%7B%22solved%22%3A%5B1%5D%7D');
    expect(await notice(frame)).toContain('could not be read, so you start afresh');
    expect(await solvedLine(frame)).toBe('0 of 3 solved');
    expect((await cmi(page)).suspend).toMatch(/^SL1:[0-9a-z]+:\.\.$/);
    await page.close();
  });

  it('reports an API that refuses writes (LMSGetLastError 405) and throws on commit; still grades', async () => {
    const { page, frame } = await launch('?mode=errors');
    expect(await answer(frame, 'schlick-worst', '85')).toBe(true);
    const text = await notice(frame);
    expect(text).toContain('The LMS refused LMSSetValue("cmi.core.score.min", "0"): error 405');
    expect(text).toContain('The LMS failed on LMSCommit(""): the LMS is unreachable.');
    expect(await solvedLine(frame)).toBe('1 of 3 solved');
    await page.close();
  });

  it('keeps a set the student loads out of the LMS: the package’s score and suspend data stay', async () => {
    const { page, frame } = await launch();
    expect(await answer(frame, 'schlick-worst', '85')).toBe(true);
    const before = await cmi(page);
    const own = join(dir, 'own.json');
    writeFileSync(own, readFileSync(join(EXERCISES, 'lake-mirror.json')));
    await (await frame.$('#exercise-file')).uploadFile(own);
    await frame.waitForFunction(() => globalThis.__shadingLab.exercise?.id === 'lake-mirror', {
      timeout: WAIT_MS, // the surfaces widget mounts in software WebGL on a loaded machine
      polling: 500,
    });
    expect(await notice(frame)).toContain('loaded yourself are checked here, but not sent to the LMS');
    expect(await cmi(page)).toMatchObject({ raw: '25', suspend: before.suspend });
    await page.close();
  });

  it('opened without an LMS, says grades are not being recorded', async () => {
    const page = await openPage(browser, server.url, 'package/scorm-launch.html', { timeout: WAIT_MS });
    await page.waitForFunction(() => globalThis.__shadingLab?.exercise?.ready, { timeout: WAIT_MS });
    expect(await page.$eval('.scorm-notice', (el) => el.textContent)).toContain('grades are not being recorded');
    expect(await page.$eval('.exercise-progress', (el) => el.textContent.trim())).toBe('0 of 3 solved');
    expect(await page.$eval('#exercise-progress-where', (el) => el.textContent)).toMatch(/stays in this browser/);
    expect(page.errors).toEqual([]);
    await page.close();
  });
});
