// The exercises page in Chromium: every shipped exercise solved through its controls (lil-gui, the answer
// box, the options) and graded right; a wrong answer graded wrong with feedback naming what is off; locked
// controls stay put; progress survives a reload and Reset clears it; bad files show their errors.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { WAIT_MS, getState, launchBrowser, open, setControl, untilIdle } from './helpers.js';
import { DEG } from '../../src/math/angles.js';

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

/**
 * Opens the exercises page in a small desktop window, just wide enough for the list beside the exercise (narrower,
 * exercise-list.css folds it away): what is read is the grading and the controls, not the size. Every
 * answer is typed or read from a control, none from a converged picture: the media's path tracer and the lab's
 * reference stop at one batch of 8 samples (sampleTarget in debug-hooks.js), so that waiting for idle does not
 * wait for them to converge.
 */
async function openExercises(path) {
  return open(browser, path, { width: 860, height: 640, maxSamples: 8 });
}

/** Opens an exercise from the list, as a reader would, and waits for its widget (if any). */
async function choose(page, id, { keyboard = false } = {}) {
  if (keyboard) {
    await page.focus(`#exercise-list a[href="#${id}"]`);
    await page.keyboard.press('Enter');
  } else await page.click(`#exercise-list a[href="#${id}"]`);
  await page.waitForFunction(
    (i) => globalThis.__shadingLab.exercise?.id === i && globalThis.__shadingLab.exercise.ready,
    { timeout: WAIT_MS }, // lake-mirror's surfaces widget took over 30 s to set up under a load average of 50
    id,
  );
  await untilIdle(page);
}

async function typeAnswer(page, text) {
  await page.$eval('#exercise-answer', (el) => {
    el.value = '';
  });
  await page.type('#exercise-answer', text);
}

/** Presses Check (or Enter in the answer box) and returns { ok, text } of the feedback. */
async function check(page, { enter = false } = {}) {
  if (enter) await page.keyboard.press('Enter');
  else await page.click('.exercise-check');
  await page.waitForSelector('.exercise-feedback.ok, .exercise-feedback.wrong');
  return page.$eval('.exercise-feedback', (el) => ({ ok: el.classList.contains('ok'), text: el.textContent }));
}

const control = (page, label, value) => setControl(page, label, value, '.exercise-widget');

describe('exercises', () => {
  it('solves each exercise through its controls, and grades a wrong answer wrong with what is off', async () => {
    const page = await openExercises('exercises.html');
    await page.waitForSelector('#exercise-list a');
    expect(await page.$$eval('#exercise-list a', (as) => as.length)).toBe(27); // public/exercises/index.json

    await choose(page, 'water-red-depth');
    await typeAnswer(page, '5');
    let r = await check(page, { enter: true });
    expect(r.ok).toBe(false);
    expect(r.text).toMatch(/5 m is too low by 9\.52 m/);
    await typeAnswer(page, '14.5');
    expect((await check(page)).ok).toBe(true);
    // a locked control: disabled, and a forced change is ignored
    expect(await page.$eval('.exercise-widget .lil-controller.locked select', (s) => s.disabled)).toBe(true);
    await page.$eval('.exercise-widget .lil-controller.locked select', (s) => {
      s.selectedIndex = 3;
      s.dispatchEvent(new Event('change'));
    });
    expect((await getState(page, 'exercise')).view).toBe('one');

    await choose(page, 'lake-mirror', { keyboard: true });
    // the heading takes the focus
    expect(await page.evaluate(() => document.activeElement.textContent)).toBe('When does a lake become a mirror?');
    r = await check(page);
    expect(r.ok).toBe(false);
    expect(r.text).toContain('points below the target 25%');
    expect(r.text).toContain('Raise the angle of incidence.');
    await control(page, 'Angle of incidence (°)', 77);
    expect((await check(page)).ok).toBe(true);

    await choose(page, 'match-sphere');
    await control(page, 'F0', 0.5);
    await control(page, 'A: roughness α', 0.1);
    r = await check(page);
    expect(r.ok).toBe(false);
    expect(r.text).toMatch(/RMS error 0\.\d+ \(display value 0–1\), needs < 0\.012/);
    expect(r.text).toContain('Roughness too low.');
    await control(page, 'A: roughness α', 0.2);
    expect((await check(page)).ok).toBe(true);

    await choose(page, 'masking-grazing');
    r = await check(page);
    expect(r.ok).toBe(false);
    expect(r.text).toContain('view the surface at a more grazing angle');
    await control(page, 'View angle θv (°)', 77);
    expect((await check(page)).ok).toBe(true);

    await choose(page, 'furnace-loss');
    await typeAnswer(page, '10');
    expect((await check(page)).text).toMatch(/10% is too low by 21\.\d%/);
    await typeAnswer(page, '31');
    expect((await check(page)).ok).toBe(true);

    // the random walk gives 24.4 points (node: randomWalkAlbedoGGX(1, 0.75, 0.71, 1e5, 1)); Kulla & Conty's 22.7, from
    // the furnace table's E = 0.4639 and E_avg = 0.5361, passes too
    await choose(page, 'rough-metal-gain');
    await typeAnswer(page, '5');
    expect((await check(page)).text).toMatch(/5 points is too low by 19\.\d points/);
    await typeAnswer(page, '22.7');
    expect((await check(page)).ok).toBe(true);

    await choose(page, 'red-zone');
    r = await check(page);
    expect(r.ok).toBe(false);
    expect(r.text).toContain('the object is green');
    await control(page, 'Light θ from view (°)', 160);
    expect((await check(page)).ok).toBe(true);

    await choose(page, 'schlick-worst');
    await typeAnswer(page, '45');
    expect((await check(page)).text).toMatch(/45° is too low by 40°/);
    await typeAnswer(page, '85');
    expect((await check(page)).ok).toBe(true);

    await choose(page, 'which-ndf');
    const hidden = await page.evaluate(() => globalThis.__shadingLab.exercise.hidden);
    const NAMES = {
      ggx: 'GGX',
      beckmann: 'Beckmann',
      blinnPhong: 'Blinn–Phong',
      abc: 'ABC',
      sgd: 'Shifted gamma (SGD)',
    };
    const wrongPick = ['beckmann', 'blinnPhong'].includes(hidden) ? 'ggx' : 'beckmann';
    await page.click(`input[name=answer][value=${wrongPick}]`);
    r = await check(page);
    expect(r.ok).toBe(false);
    expect(r.text).toContain(`${NAMES[wrongPick]}’s profile is`);
    await page.click(`input[name=answer][value=${hidden}]`);
    expect((await check(page)).ok).toBe(true);

    // beyond the talk (issue 28): αx = 0.4 > αy = 0.1 stretches the highlight along the tangent, left to right
    await choose(page, 'highlight-stretch');
    await page.click('input[name=answer][value=bitangent]');
    r = await check(page);
    expect(r.ok).toBe(false);
    expect(r.text).toMatch(/reaches [\d.]+ pixels left to right and [\d.]+ bottom to top/);
    await page.click('input[name=answer][value=tangent]');
    expect((await check(page)).ok).toBe(true);

    await choose(page, 'aniso-pair');
    const pair = await page.evaluate(() => globalThis.__shadingLab.exercise.hidden);
    const otherPair = pair === 'wideX' ? 'wideY' : 'wideX';
    await page.click(`input[name=answer][value=${otherPair}]`);
    r = await check(page);
    expect(r.ok).toBe(false);
    expect(r.text).toMatch(/draws a different highlight: RMS 0\.\d+, a match needs ≤ 0\.02/);
    await page.click(`input[name=answer][value=${pair}]`);
    expect((await check(page)).ok).toBe(true);

    await choose(page, 'separable-smith');
    const [c, a] = [Math.cos(80 * DEG), 0.5];
    const R = Math.sqrt(a * a + (1 - a * a) * c * c);
    await typeAnswer(page, '1');
    expect((await check(page)).text).toContain('1 is too high by');
    await typeAnswer(page, ((4 * c * R) / (c + R) ** 2).toFixed(2));
    expect((await check(page)).ok).toBe(true);

    await choose(page, 'lambert-brightness');
    await typeAnswer(page, (1.5 * Math.PI).toFixed(3));
    expect((await check(page)).text).toContain('π times too bright');
    await typeAnswer(page, '1.5');
    expect((await check(page)).ok).toBe(true);

    expect(await page.$eval('.exercise-progress', (el) => el.textContent.trim())).toBe('13 of 27 solved');
    expect(page.errors).toEqual([]);

    // progress survives a reload; Reset (confirmed) clears it
    await page.reload({ waitUntil: 'load' });
    await page.waitForSelector('#exercise-list a');
    expect(await page.$eval('.exercise-progress', (el) => el.textContent.trim())).toBe('13 of 27 solved');
    expect(await page.$eval('#exercise-list a[href="#lake-mirror"]', (a) => a.parentElement.textContent)).toContain(
      '✓ solved',
    );
    page.once('dialog', (d) => d.accept());
    await page.click('.exercise-reset');
    await expect
      .poll(() => page.$eval('.exercise-progress', (el) => el.textContent.trim()), { timeout: WAIT_MS })
      .toBe('0 of 27 solved');
    await page.reload({ waitUntil: 'load' });
    await page.waitForSelector('#exercise-list a');
    expect(await page.$eval('.exercise-progress', (el) => el.textContent.trim())).toBe('0 of 27 solved');
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it('one attempt per answer; the depth in metres; Next exercise by keyboard; the sliders beside Check', async () => {
    const page = await openExercises('exercises.html');
    await page.waitForSelector('#exercise-list a');
    await choose(page, 'water-red-depth');
    const status = () => page.$eval('.exercise-meta', (el) => el.textContent);
    await typeAnswer(page, '5');
    await check(page, { enter: true });
    await check(page); // the same answer again, by Check
    expect(await status()).toBe('Not solved yet: 1 attempt');
    await typeAnswer(page, '6');
    await check(page);
    expect(await status()).toBe('Not solved yet: 2 attempts');

    // the widget's slider is log₁₀ of the depth in metres: the line beside the answer says the depth in metres
    await control(page, 'Depth, log₁₀ metres', -1.3);
    await page.waitForFunction(() => document.querySelector('.exercise-readout').textContent.includes('0.0501 m'));
    expect(10 ** -1.3).toBeCloseTo(0.0501, 4);
    expect(await page.$eval('.exercise-readout', (el) => el.textContent)).toBe(
      'Depth on the widget: 0.0501 m (its slider shows log₁₀ of the depth in metres: −1.3). Answer in metres.',
    );

    // solved: the feedback offers the next exercise not yet solved, in the list's order; Tab from Check reaches it
    await typeAnswer(page, '14.5');
    expect((await check(page)).text).toContain('Next exercise: When does a lake become a mirror?');
    await page.focus('.exercise-check');
    await page.keyboard.press('Tab');
    expect(await page.evaluate(() => document.activeElement.textContent)).toBe(
      'Next exercise: When does a lake become a mirror?',
    );
    await page.keyboard.press('Enter');
    await page.waitForFunction(() => globalThis.__shadingLab.exercise?.id === 'lake-mirror');
    await page.waitForFunction(() => globalThis.__shadingLab.exercise.ready);
    await page.waitForSelector('#exercise-control-theta');

    // the answer's slider beside Check moves the widget, and the widget's own control moves it back
    await page.$eval('#exercise-control-theta', (input) => {
      input.value = '77';
      input.dispatchEvent(new Event('input', { bubbles: true }));
    });
    expect((await getState(page, 'exercise')).theta).toBe(77);
    await control(page, 'Angle of incidence (°)', 50);
    await page.waitForFunction(() => document.querySelector('#exercise-control-theta').value === '50');
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it('Which NDF: the question number is in the address and on the page, and a reload shows the same one', async () => {
    const page = await openExercises('exercises.html?seed=77#which-ndf');
    await page.waitForFunction(() => globalThis.__shadingLab?.exercise?.id === 'which-ndf');
    const hidden = await page.evaluate(() => globalThis.__shadingLab.exercise.hidden);
    expect(await page.$eval('.exercise-seed', (el) => el.textContent)).toMatch(/^Question 77 \(seed=77 /);
    await page.click('.exercise-again');
    await page.waitForFunction(() => !document.querySelector('.exercise-seed').textContent.startsWith('Question 77 '));
    const seed = new URL(page.url()).searchParams.get('seed');
    expect(seed).not.toBe('77');
    const drawn = await page.evaluate(() => globalThis.__shadingLab.exercise.hidden);
    await page.reload({ waitUntil: 'load' });
    await page.waitForFunction(() => globalThis.__shadingLab?.exercise?.id === 'which-ndf');
    expect(await page.evaluate(() => globalThis.__shadingLab.exercise.hidden)).toBe(drawn);
    expect(await page.$eval('.exercise-seed', (el) => el.textContent)).toContain(`Question ${seed} `);
    await page.goto(new URL('exercises.html?seed=77#which-ndf', page.url()).href, { waitUntil: 'load' });
    await page.waitForFunction(() => globalThis.__shadingLab?.exercise?.id === 'which-ndf');
    expect(await page.evaluate(() => globalThis.__shadingLab.exercise.hidden)).toBe(hidden);
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it('shows a bad set’s errors on the page and keeps its good exercises', async () => {
    const set = [
      {
        id: 'good',
        chapter: 'diffuse',
        title: 'Good',
        prompt: 'Lo?',
        grader: 'lambert-radiance',
        params: { cLight: 1, thetaDeg: 0 },
        tolerance: 0.1,
      },
      { id: 'bad', chapter: 'media', title: 'Bad', prompt: 'x', widget: 'media', state: { depth: 1 }, grader: 'guess' },
    ];
    const page = await openExercises(
      `exercises.html?src=${encodeURIComponent(`data:application/json,${JSON.stringify(set)}`)}`,
    );
    await page.waitForSelector('.notice-error');
    const text = await page.$eval('#exercise-problems', (el) => el.textContent);
    expect(text).toContain('data URL #2: 3 problems, not loaded');
    expect(text).toContain('tolerance: missing (a positive number)');
    expect(text).toContain('grader: unknown grader "guess"');
    expect(text).toContain('state.depth: unknown key for widget "media"');
    expect(await page.$$eval('#exercise-list a', (as) => as.map((a) => a.textContent))).toEqual(['Good']);
    await typeAnswer(page, '1');
    expect((await check(page)).ok).toBe(true);

    // a dropped (chosen) file that is not JSON
    const file = join(tmpdir(), 'not-json.json');
    writeFileSync(file, '{ "id": ');
    const input = await page.$('#exercise-file');
    await input.uploadFile(file);
    await page.waitForFunction(() =>
      document.querySelector('#exercise-problems').textContent.includes('not-json.json is not valid JSON'),
    );
    expect(await page.$eval('#exercise', (el) => el.textContent)).toBe('No exercises to show.');
    expect(page.errors).toEqual([]);
    await page.close();
  });
});
