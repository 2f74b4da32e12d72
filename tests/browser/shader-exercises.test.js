// Shader exercises in Chromium, code typed into the editor and graded on the GPU: every shipped exercise passes
// its correct code and fails each typical mistake with the message naming the input where the mistake shows
// (tests/browser/shader-solutions.js works each out from the mistake); compile errors and static-check problems
// land on the student's line; progress is kept; a parent page on another origin hears the result only when
// `origins=` allows it.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { WAIT_MS, baseUrl, frameShowing, launchBrowser, open, openForeignParent, otherOrigin } from './helpers.js';
import { SHADER_SOLUTIONS } from './shader-solutions.js';

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

const DIR = join(import.meta.dirname, '../../public/exercises');
const exerciseFile = (id) => JSON.parse(readFileSync(join(DIR, `${id}.json`), 'utf8'));

/** Opens exercise `id` in `target` (a page or a frame) by its anchor and waits for its editor. */
async function choose(target, id) {
  await target.evaluate((i) => {
    location.hash = i;
  }, id);
  await target.waitForFunction(
    (i) => globalThis.__shadingLab?.exercise?.id === i && globalThis.__shadingLab.exercise.ready,
    { timeout: WAIT_MS },
    id,
  );
  await target.waitForSelector('.exercise-code .cm-content', { timeout: WAIT_MS });
}

/**
 * Replaces the editor's text as a user would: click into it, select all, then type (one insertText), and checks it
 * arrived. The keys go where the focus is, so the click is repeated until the editor holds it: in a frame that is
 * still laying out on a loaded machine, the first click can land before the editor is where it was measured.
 */
async function setCode(page, target, code) {
  const focused = () => target.evaluate(() => Boolean(document.activeElement?.closest('.exercise-code')));
  // a click the editor may miss while it is laid out: clicked again every 5 s, for up to WAIT_MS in all
  for (const end = Date.now() + WAIT_MS; Date.now() < end && !(await focused());) {
    await target.click('.exercise-code .cm-content');
    await target
      .waitForFunction(() => document.activeElement?.closest('.exercise-code'), { timeout: 5_000 })
      .catch(() => {});
  }
  await page.keyboard.down('Control');
  await page.keyboard.press('a');
  await page.keyboard.up('Control');
  await page.keyboard.press('Backspace');
  await page.keyboard.sendCharacter(code);
  const text = () => target.$$eval('.exercise-code .cm-line', (lines) => lines.map((l) => l.textContent).join('\n'));
  await expect.poll(text, { timeout: WAIT_MS }).toBe(code); // a final newline is an empty last line
}

/** Presses Check and returns the feedback: { ok, summary, details }. */
async function check(target) {
  await target.click('.exercise-check');
  await target.waitForSelector('.exercise-feedback.ok, .exercise-feedback.wrong', { timeout: WAIT_MS });
  return target.$eval('.exercise-feedback', (el) => ({
    ok: el.classList.contains('ok'),
    summary: el.querySelector('p').textContent,
    details: [...el.querySelectorAll('li')].map((li) => li.textContent),
  }));
}

describe('shader exercises', () => {
  let page;
  beforeAll(async () => {
    // a small desktop window, just wide enough for the list beside the exercise (exercise-list.css folds it away
    // below 820 px): the grading runs on the GPU at its own size, whatever the window
    page = await open(browser, 'exercises.html', { width: 860, height: 640 });
    await page.waitForSelector('#exercise-list a');
  });
  afterAll(async () => {
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it.each(Object.entries(SHADER_SOLUTIONS))(
    '%s: the correct code passes on the GPU against the float64 catalogue term; each mistake fails where it shows',
    async (id, { correct, mistakes }) => {
      await choose(page, id);
      for (const m of mistakes) {
        await setCode(page, page, m.starter ? exerciseFile(id).starter : m.code);
        const r = await check(page);
        expect(r.ok, m.name).toBe(false);
        expect(r.summary, m.name).toMatch(m.summary);
        if (m.detail) expect(r.details.join('\n'), m.name).toMatch(m.detail);
      }
      await setCode(page, page, correct);
      const r = await check(page);
      expect(r.summary).toMatch(/^Right: your .* matches .* at all [\d,]+ inputs/);
      expect(r.ok).toBe(true);
      expect(await page.$eval(`#exercise-list a[href="#${id}"]`, (a) => a.parentElement.textContent)).toContain(
        '✓ solved',
      );
    },
  );

  it('compile errors and static-check problems show at the student’s line, in feedback and editor', async () => {
    await choose(page, 'shader-schlick');
    await setCode(page, page, 'vec3 customF(vec3 f0, float lh) {\n  float m = 1.0 - lh;\n  return f0 + m5;\n}\n');
    let r = await check(page);
    expect(r.summary).toBe('Your code does not compile:');
    expect(r.details[0]).toMatch(/^Line 3: .*m5/);
    const marked = () =>
      page.$$eval('.exercise-code .cm-line', (lines) =>
        lines.map((l, i) => (l.querySelector('.cm-lintRange-error') ? i + 1 : 0)).filter(Boolean),
      );
    expect(await marked()).toEqual([3]);

    await setCode(
      page,
      page,
      'vec3 customF(vec3 f0, float lh) {\n  float m = 1.0;\n  while (m > 0.5) m *= 0.9;\n  return f0 * m;\n}\n',
    );
    r = await check(page);
    expect(r.summary).toBe('Your code did not pass the static check:');
    expect(r.details[0]).toMatch(/^Line 3: /);
    expect(await marked()).toEqual([3]);
  });

  it('the three common mistakes get plain words after the parser’s or the compiler’s message', async () => {
    await choose(page, 'shader-schlick');
    const F = (...body) => ['vec3 customF(vec3 f0, float lh) {', ...body, '}', ''].join('\n');
    const cases = [
      [
        F('  float m = 1.0 - lh', '  return f0 + (1.0 - f0) * pow(m, 5.0);'),
        /^Line 3: does not parse: .*\. In plain words: line 2 ends without “;”\./,
      ],
      [
        F('  return f0 + (1.0 - f0) * pow(1.0 - lh, 5);'),
        /^Line 2: 'pow' : no matching overloaded function found\. In plain words: .* write 5\.0 for 5\.$/,
      ],
      [F('  float m = 1.0 - lh;', '  return f0 + m5;'), /^Line 3: .*m5.*In plain words: “m5” is not declared/],
    ];
    for (const [code, detail] of cases) {
      await setCode(page, page, code);
      const r = await check(page);
      expect(r.ok).toBe(false);
      expect(r.details[0]).toMatch(detail);
    }
  });
});

describe('the graded message to a parent page', () => {
  /** A parent on another origin embedding the exercises page; window.__inbox records what it hears. */
  async function parentWith(query) {
    const page = await openForeignParent(browser);
    const src = new URL(`exercises.html${query}#shader-schlick`, baseUrl()).href;
    await page.evaluate((src) => {
      window.__inbox = [];
      window.addEventListener('message', (e) => window.__inbox.push({ origin: e.origin, data: e.data }));
      const frame = Object.assign(document.createElement('iframe'), { src, id: 'exercises' });
      frame.style.cssText = 'width: 1200px; height: 900px; border: 0';
      document.body.replaceChildren(frame);
    }, src);
    const frame = await frameShowing(page, '#exercises');
    await choose(frame, 'shader-schlick');
    return { page, frame };
  }

  it('reaches a parent on an origin listed in origins=, from the app’s origin, after each Check', async () => {
    const parentOrigin = new URL(otherOrigin()).origin;
    const { page, frame } = await parentWith(`?origins=${encodeURIComponent(parentOrigin)}`);
    await setCode(page, frame, SHADER_SOLUTIONS['shader-schlick'].mistakes[0].code);
    expect((await check(frame)).ok).toBe(false);
    await setCode(page, frame, SHADER_SOLUTIONS['shader-schlick'].correct);
    expect((await check(frame)).ok).toBe(true);
    await page.waitForFunction(() => window.__inbox.filter((m) => m.data?.type === 'shading-lab:graded').length === 2, {
      timeout: WAIT_MS,
    });
    const graded = (await page.evaluate(() => window.__inbox)).filter((m) => m.data?.type === 'shading-lab:graded');
    expect(graded.map((m) => m.origin)).toEqual([new URL(baseUrl()).origin, new URL(baseUrl()).origin]);
    expect(graded[0].data).toMatchObject({ id: 'shader-schlick', passed: false });
    expect(graded[0].data.score).toBeGreaterThan(0);
    expect(graded[0].data.score).toBeLessThan(1);
    expect(graded[1].data).toEqual({ type: 'shading-lab:graded', id: 'shader-schlick', passed: true, score: 1 });
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it('stays silent to a parent whose origin is not listed', async () => {
    const { page, frame } = await parentWith('?origins=https://course.example.org');
    await setCode(page, frame, SHADER_SOLUTIONS['shader-schlick'].correct);
    expect((await check(frame)).ok).toBe(true);
    // the page posts a Check's result in the task that shows it (shader-view.js): a message the frame posts after
    // that comes after it, since postMessage keeps the order of one window's messages to another
    await frame.evaluate(() => window.parent.postMessage({ type: 'after-the-check' }, '*'));
    await page.waitForFunction(() => window.__inbox.some((m) => m.data?.type === 'after-the-check'), {
      timeout: WAIT_MS,
    });
    const messages = await page.evaluate(() => window.__inbox);
    expect(messages.filter((m) => m.data?.type === 'shading-lab:graded')).toEqual([]);
    expect(page.errors).toEqual([]);
    await page.close();
  });
});
