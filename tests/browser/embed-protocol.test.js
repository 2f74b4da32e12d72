// Embedding, the postMessage protocol between a parent page and embed.html: ready, get, set through validation,
// bad messages ignored, other origins refused unless listed, the content's height told to allowed origins only.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import {
  WAIT_MS,
  afterFrames,
  baseUrl,
  frameShowing,
  launchBrowser,
  open,
  openForeignParent,
  otherOrigin,
  setControl,
  untilIdle,
} from './helpers.js';

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

const originOf = (url) => new URL(url).origin;

/**
 * Turns the page into a parent that embeds `src` in an iframe and records every message it receives
 * (window.__inbox: { origin, data }). Returns the iframe's frame once its widget is registered.
 */
async function embedIn(page, src) {
  await page.evaluate((src) => {
    window.__inbox = [];
    window.addEventListener('message', (e) => window.__inbox.push({ origin: e.origin, data: e.data }));
    const frame = Object.assign(document.createElement('iframe'), { src, id: 'embedded' });
    frame.style.cssText = 'width: 1000px; height: 700px; border: 0';
    document.body.replaceChildren(frame);
  }, src);
  const frame = await frameShowing(page, '#embedded');
  await frame.waitForFunction(() => Object.keys(globalThis.__shadingLab?.widgets ?? {}).length === 1, {
    timeout: WAIT_MS,
  });
  return frame;
}

/** Posts `message` to the iframe from the parent, with the given target origin. */
const post = (page, message, targetOrigin) =>
  page.evaluate((m, t) => document.getElementById('embedded').contentWindow.postMessage(m, t), message, targetOrigin);

const inbox = (page) => page.evaluate(() => window.__inbox);
const waitForMessage = (page, test) =>
  page
    .waitForFunction(`window.__inbox.map((m) => m.data).find(${test})`, { timeout: WAIT_MS })
    .then((h) => h.jsonValue());
const widgetState = (frame) => frame.evaluate(() => Object.values(globalThis.__shadingLab.widgets)[0].getState());

describe('postMessage protocol of embed.html', () => {
  it(
    'announces itself, answers get, applies a set through validation, ' + 'reports bad values, and follows the user',
    async () => {
      const page = await open(browser, 'index.html');
      const frame = await embedIn(page, new URL('embed.html?w=fresnel-zones', baseUrl()).href);
      const own = originOf(baseUrl());

      const ready = await waitForMessage(page, (d) => d.type === 'shading-lab:ready');
      expect(ready.widget).toBe('fresnel-zones');
      expect(ready.state).toEqual(await widgetState(frame));
      expect(ready.query).toBe('');
      expect((await inbox(page)).every((m) => m.origin === own)).toBe(true);
      // and its height: the content's, measured in the frame (main's box, rounded up), which the 700 px frame cuts
      const height = () => frame.$eval('#embed', (m) => Math.ceil(m.getBoundingClientRect().height));
      const lastResize = async () => (await inbox(page)).findLast((m) => m.data.type === 'shading-lab:resize')?.data;
      await expect
        .poll(async () => [await lastResize(), await height()], { timeout: WAIT_MS })
        .toSatisfy(([m, h]) => m?.height === h);
      expect(await lastResize()).toEqual({
        type: 'shading-lab:resize',
        widget: 'fresnel-zones',
        height: await height(),
      });
      expect(await height()).toBeGreaterThan(700);

      await post(page, { type: 'shading-lab:get', id: 'g1' }, own);
      const got = await waitForMessage(page, (d) => d.type === 'shading-lab:state' && d.id === 'g1');
      expect(got.state).toEqual(ready.state);

      // good values are applied, a number out of range is clamped, a bad enum keeps the last good value
      await post(
        page,
        {
          type: 'shading-lab:set',
          id: 's1',
          state: { mode: 'zones-lh', alpha: 0.5, lightTheta: 400, shape: 'banana', colour: 'red' },
        },
        own,
      );
      const reply = await waitForMessage(page, (d) => d.type === 'shading-lab:state' && d.id === 's1');
      const error = await waitForMessage(page, (d) => d.type === 'shading-lab:error' && d.id === 's1');
      expect(reply.state).toMatchObject({ mode: 'zones-lh', alpha: 0.5, lightTheta: 180, shape: 'sphere' });
      expect(reply.state).not.toHaveProperty('colour');
      expect(reply.query).toBe(new URLSearchParams({ mode: 'zones-lh', alpha: '0.5', lightTheta: '180' }).toString());
      expect(error.errors.join(' ')).toMatch(/400 is outside 0…180; clamped to 180/);
      expect(error.errors.join(' ')).toMatch(/"banana" is not one of/);
      expect(error.errors.join(' ')).toMatch(/“colour” is not a setting/);
      expect(await widgetState(frame)).toEqual(reply.state);
      // reported on the page too, and the iframe's own URL carries the new state
      const noticeText = await frame.$eval('body', (b) =>
        [...b.querySelectorAll('.notice')].map((n) => n.textContent).join(' '),
      );
      expect(noticeText).toMatch(/banana/);
      expect(noticeText).toMatch(/colour/);
      const frameParam = (f, key) => new URL(f.url()).searchParams.get(key); // the URL is written back after a pause
      await expect.poll(() => frameParam(frame, 'mode'), { timeout: WAIT_MS }).toBe('zones-lh');
      // a change the parent made is not echoed back as a user change
      expect((await inbox(page)).some((m) => m.data.type === 'shading-lab:changed')).toBe(false);

      // the user edits the widget: one debounced `changed`, with the new state
      await setControl(frame, 'Mode', 'Zones of n·v');
      const changed = await waitForMessage(page, (d) => d.type === 'shading-lab:changed');
      expect(changed.state.mode).toBe('zones-nv');
      expect(changed.state).toEqual(await widgetState(frame));
      expect(changed.query).toContain('mode=zones-nv');
      expect(page.errors).toEqual([]);
      await page.close();
    },
  );

  it('coerces a set once, where the widget does: a locked key is kept as it is and brings no error', async () => {
    const page = await open(browser, 'index.html');
    const src = new URL('embed.html?w=fresnel-zones&locked=alpha,lightTheta&alpha=0.2', baseUrl()).href;
    const frame = await embedIn(page, src);
    const own = originOf(baseUrl());
    await waitForMessage(page, (d) => d.type === 'shading-lab:ready');
    // alpha 7 and lightTheta 400 would be clamped (an error) were they free; locked, they are left alone, silently
    await post(
      page,
      { type: 'shading-lab:set', id: 'l1', state: { alpha: 7, lightTheta: 400, mode: 'zones-lh' } },
      own,
    );
    const reply = await waitForMessage(page, (d) => d.type === 'shading-lab:state' && d.id === 'l1');
    expect(reply.state).toMatchObject({ alpha: 0.2, mode: 'zones-lh' });
    expect(reply.state.lightTheta).toBe((await widgetState(frame)).lightTheta);
    // a real error of the same set path still comes back: the free key's bad value
    await post(page, { type: 'shading-lab:set', id: 'l2', state: { alpha: 0.9, shape: 'banana' } }, own);
    const error = await waitForMessage(page, (d) => d.type === 'shading-lab:error' && d.id === 'l2');
    expect(error.errors).toHaveLength(1);
    expect(error.errors[0]).toMatch(/"banana" is not one of/);
    expect((await inbox(page)).some((m) => m.data.type === 'shading-lab:error' && m.data.id === 'l1')).toBe(false);
    expect(await widgetState(frame)).toMatchObject({ alpha: 0.2, mode: 'zones-lh', shape: 'sphere' });
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it('ignores messages of the wrong shape without a reply, a change or an error', async () => {
    const page = await open(browser, 'index.html');
    const frame = await embedIn(page, new URL('embed.html?w=ndf-explorer', baseUrl()).href);
    const own = originOf(baseUrl());
    await waitForMessage(page, (d) => d.type === 'shading-lab:ready');
    const before = await widgetState(frame);
    const bad = [
      'shading-lab:get',
      null,
      42,
      [1, 2],
      { type: 'shading-lab:set', state: 'hwhm=20' },
      { type: 'shading-lab:set', state: [20] },
      { type: 'shading-lab:set', id: { x: 1 }, state: { hwhm: 20 } },
      { type: 'shading-lab:sett', state: { hwhm: 20 } },
      { type: 'shading-lab:state', state: { hwhm: 20 } },
      { state: { hwhm: 20 } },
    ];
    for (const m of bad) await post(page, m, own);
    await post(page, { type: 'shading-lab:get', id: 'last' }, own);
    await waitForMessage(page, (d) => d.id === 'last');
    // a window for replies that must not come, in frames of the widget once it is idle: it cannot fail a widget that
    // keeps silent
    await untilIdle(frame);
    await afterFrames(frame, 20);
    const unasked = new Set(['shading-lab:ready', 'shading-lab:resize']);
    const replies = (await inbox(page)).filter((m) => !unasked.has(m.data?.type));
    expect(replies.map((m) => m.data.id)).toEqual(['last']);
    expect(await widgetState(frame)).toEqual(before);
    expect(await frame.$$eval('.notice', (n) => n.length)).toBe(0);
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it('ignores a parent on an origin it was not given, and talks to one listed in origins=', async () => {
    const page = await openForeignParent(browser);
    const parentOrigin = originOf(otherOrigin());
    const widgetOrigin = originOf(baseUrl());
    expect(parentOrigin).not.toBe(widgetOrigin);

    const frame = await embedIn(page, new URL('embed.html?w=fresnel-zones', baseUrl()).href);
    const before = await widgetState(frame);
    await post(page, { type: 'shading-lab:set', id: 's', state: { mode: 'zones-lh' } }, widgetOrigin);
    await post(page, { type: 'shading-lab:get', id: 'g' }, '*');
    await untilIdle(frame); // a window for what must not come, as above
    await afterFrames(frame, 30);
    expect(await inbox(page)).toEqual([]); // not even `ready` or `resize`: nothing goes to an origin not allowed
    expect(await widgetState(frame)).toEqual(before);

    const allowed = await embedIn(
      page,
      new URL(`embed.html?w=fresnel-zones&origins=${encodeURIComponent(parentOrigin)}`, baseUrl()).href,
    );
    const ready = await waitForMessage(page, (d) => d.type === 'shading-lab:ready');
    expect(ready.widget).toBe('fresnel-zones');
    await waitForMessage(page, (d) => d.type === 'shading-lab:resize'); // told its height, as the origin is allowed
    await post(page, { type: 'shading-lab:set', id: 's2', state: { mode: 'zones-lh' } }, widgetOrigin);
    await waitForMessage(page, (d) => d.type === 'shading-lab:state' && d.id === 's2');
    expect((await widgetState(allowed)).mode).toBe('zones-lh');
    expect((await inbox(page)).every((m) => m.origin === widgetOrigin)).toBe(true);
    // kept when the state is written back (after a pause)
    await expect.poll(() => new URL(allowed.url()).searchParams.get('mode'), { timeout: WAIT_MS }).toBe('zones-lh');
    expect(new URL(allowed.url()).searchParams.get('origins')).toBe(parentOrigin);
    expect(page.errors).toEqual([]);
    await page.close();
  });
});
