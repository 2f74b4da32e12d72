// Multisampling once a gesture ends (src/core/framework: settled-antialias.js, held-input.js), in fresnel-zones
// (its own shader) and the 3-D lobe of brdf-lobe (three.js's built-in materials, colour-managed by three.js): the
// tests drive input as a reader does (a pointer pressed, moved, released; a key held) and WebGL itself tells how each
// draw call was sampled (the SAMPLES of the framebuffer it draws into); each frame is read back in the task that
// drew it. No test reads the time between frames or sleeps to let one come: each waits for the frame count. The
// reference for the settled picture is the one before this mode: the same page with its WebGL context made
// multisampled (antialias: true), drawn straight to the canvas.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { WAIT_MS, baseUrl, launchBrowser } from './helpers.js';
import { openPage } from './harness.js';

const WIDGET = 'fresnel-zones';
const PAGE = `embed.html?w=${WIDGET}&shape=teapot&mode=zones-lh&camera=perspective`;
const DRAG = [0.2, 0.24, 0.28, 0.32, 0.36, 0.4, 0.44, 0.48]; // pointer positions: right of centre, by half-widths
const LOBE = 'brdf-lobe'; // its 3-D lobe view: a surface patch, two lobes and arrows

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

/**
 * In the page, before it loads: counts draw calls by the sample count of the framebuffer they draw into
 * (window.__draws: { plain, multisampled }); logs each frame of the render loop as it starts (window.__frameLog:
 * { multisampled so far }) and keeps it as read back right after it was drawn (window.__frame, RGBA); keeps
 * the last file saved (window.__saved). With `contextAntialias`, every WebGL2 context is made multisampled.
 */
function instrument(contextAntialias) {
  window.__draws = { plain: 0, multisampled: 0 };
  for (const fn of ['drawArrays', 'drawElements']) {
    const draw = WebGL2RenderingContext.prototype[fn];
    WebGL2RenderingContext.prototype[fn] = function sorted(...args) {
      window.__draws[this.getParameter(this.SAMPLES) > 0 ? 'multisampled' : 'plain']++;
      return draw.apply(this, args);
    };
  }
  const getContext = HTMLCanvasElement.prototype.getContext;
  HTMLCanvasElement.prototype.getContext = function made(type, attributes) {
    const forced = type === 'webgl2' && contextAntialias ? { ...attributes, antialias: true } : attributes;
    return getContext.call(this, type, forced);
  };
  const readFrame = () => {
    const gl = document.querySelector('.viewport canvas')?.getContext('webgl2');
    if (!gl) return;
    window.__frame = new Uint8Array(gl.drawingBufferWidth * gl.drawingBufferHeight * 4);
    gl.readPixels(0, 0, gl.drawingBufferWidth, gl.drawingBufferHeight, gl.RGBA, gl.UNSIGNED_BYTE, window.__frame);
  };
  window.__frameLog = [];
  const createObjectURL = URL.createObjectURL;
  URL.createObjectURL = (blob) => ((window.__saved = blob), createObjectURL(blob)); // the last file saved
  let frames = 0;
  // the render loop counts a frame right before drawing it: read it back once the draw is done (same task)
  globalThis.__shadingLab = {
    get frames() {
      return frames;
    },
    set frames(n) {
      frames = n;
      window.__frameLog.push({ multisampled: window.__draws.multisampled });
      queueMicrotask(readFrame);
    },
  };
}

/** In the page: the frames the render loops have drawn. */
const frames = (page) => page.evaluate(() => globalThis.__shadingLab.frames);

/** Waits until the render loops have drawn more than `n` frames. */
const untilFrameAfter = (page, n) =>
  page.waitForFunction((k) => globalThis.__shadingLab.frames > k, { timeout: WAIT_MS, polling: 'raf' }, n);

/**
 * Waits until no frame is pending: the frame count held over ten animation frames in a row (a frame asked for is
 * drawn at the next one; ten leave room for a resize or a late font). A test of "no more frames" rests on it.
 */
const untilQuiet = (page) =>
  page.evaluate(async () => {
    const lab = globalThis.__shadingLab;
    for (let still = 0, seen = lab.frames; still < 10;) {
      await new Promise((r) => requestAnimationFrame(r));
      [still, seen] = lab.frames === seen ? [still + 1, seen] : [0, lab.frames];
    }
  });

async function openWidget(widget, path, contextAntialias = false) {
  const page = await openPage(browser, baseUrl(), path, {
    timeout: WAIT_MS,
    beforeLoad: (p) => p.evaluateOnNewDocument(instrument, contextAntialias),
  });
  await page.waitForFunction((w) => globalThis.__shadingLab?.widgets?.[w], { timeout: WAIT_MS }, widget);
  await untilFrameAfter(page, 0);
  await untilQuiet(page);
  return page;
}
const openZones = (contextAntialias = false) => openWidget(WIDGET, PAGE, contextAntialias);

/** In the page: the state change, then the frame it causes. */
async function change(page, partial, widget = WIDGET) {
  const before = await frames(page);
  await page.evaluate((w, p) => globalThis.__shadingLab.widgets[w].update(p), widget, partial);
  await untilFrameAfter(page, before);
}

/** Frames and draw calls so far, the frame log; with `withFrame` the last frame (base64). */
const counts = (page, withFrame = false, kept = '__frame') =>
  page.evaluate(
    (all, name) => {
      let frame = '';
      for (let i = 0; all && i < window[name].length; i += 0x8000)
        frame += String.fromCharCode(...window[name].subarray(i, i + 0x8000));
      const { frames } = globalThis.__shadingLab;
      return { frames, ...window.__draws, frame: btoa(frame), log: window.__frameLog.slice() };
    },
    withFrame,
    kept,
  );

/** In the page: the last PNG saved, as RGBA rows bottom to top (as WebGL reads them back), base64. */
const savedPixels = (page) =>
  page.evaluate(async () => {
    const bitmap = await createImageBitmap(window.__saved);
    const ctx = new OffscreenCanvas(bitmap.width, bitmap.height).getContext('2d');
    ctx.drawImage(bitmap, 0, 0);
    const { data, width, height } = ctx.getImageData(0, 0, bitmap.width, bitmap.height);
    let text = '';
    for (let y = height - 1; y >= 0; y--)
      text += String.fromCharCode(...data.subarray(y * width * 4, (y + 1) * width * 4));
    return btoa(text);
  });

/**
 * A pointer pressed on the view's canvas at DRAG[0] and moved through the rest, each position waiting for its frame;
 * the pointer stays pressed. Returns the counts before the press and after the last move.
 */
async function pressAndDrag(page) {
  const box = await (await page.$('.viewport canvas')).boundingBox();
  const at = (f) => [box.x + box.width / 2 + (f * box.width) / 2, box.y + box.height / 2 - (f * box.height) / 8];
  await page.mouse.move(...at(DRAG[0]));
  await untilQuiet(page); // whatever the hover draws (the probe), before the press
  const start = await counts(page);
  await page.mouse.down();
  for (const f of DRAG.slice(1)) {
    const before = await frames(page);
    await page.mouse.move(...at(f));
    await untilFrameAfter(page, before);
  }
  return { start, held: await counts(page, true) };
}

/** Releases the pointer; returns the counts once the frame it asks for (if any) is drawn and nothing is pending. */
async function release(page) {
  await page.mouse.up();
  await untilQuiet(page);
  return counts(page, true);
}

/**
 * The reference: a page whose context multisamples, brought to `state` while a pointer is held on the widget (so
 * that its view draws straight to the canvas, as before this mode); its last frame.
 */
async function referenceFrame(widget, path, bringThere) {
  const reference = await openWidget(widget, path, true);
  await reference.$eval('.widget', (w) => w.dispatchEvent(new PointerEvent('pointerdown', { bubbles: true })));
  await bringThere(reference);
  const { frame } = await counts(reference, true);
  expect(reference.errors).toEqual([]);
  await reference.close();
  return frame;
}

describe("antialias: 'settled' (fresnel-zones)", () => {
  it('draws a pointer drag plainly, on release one multisampled frame = the context-multisampled one', async () => {
    const page = await openZones();
    const { start, held } = await pressAndDrag(page);
    expect(held.frames - start.frames, 'a frame per pointer position').toBeGreaterThanOrEqual(DRAG.length - 1);
    expect(held.multisampled - start.multisampled, 'no multisampled draw while the pointer is held').toBe(0);
    expect(held.plain).toBeGreaterThan(start.plain);
    const settled = await release(page);
    expect(settled.frames - held.frames, 'frames after the release').toBe(1);
    expect(settled.multisampled - held.multisampled, 'multisampled draws after the release: the mesh').toBe(1);
    expect(settled.frame, 'the settled frame differs from the last plain one').not.toBe(held.frame);

    const { lightTheta, lightPhi } = await page.evaluate((w) => globalThis.__shadingLab.widgets[w].getState(), WIDGET);
    const reference = await referenceFrame(WIDGET, PAGE, (p) => change(p, { lightTheta, lightPhi }));
    expect(settled.frame === reference, 'settled frame = context-multisampled frame, byte for byte').toBe(true);
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it('draws a lone change multisampled at once, and nothing more after it', async () => {
    const page = await openZones();
    const before = await counts(page);
    await change(page, { shape: 'torusknot' });
    const changed = await counts(page);
    expect(changed.frames - before.frames).toBe(1);
    expect(changed.multisampled - before.multisampled, 'the mesh, multisampled').toBe(1);
    await untilQuiet(page);
    const after = await counts(page);
    // (its zone shares are measured after it: plain draws into float images, no frame)
    expect([after.frames, after.multisampled]).toEqual([changed.frames, changed.multisampled]);
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it('draws a held key plainly from its first repeat, and multisampled on its release', async () => {
    const page = await openZones();
    await page.focus('.viewport canvas');
    const before = await counts(page);
    const press = async () => {
      const n = await frames(page);
      await page.keyboard.down('ArrowDown'); // the light 5° lower; pressed again: a repeat
      await untilFrameAfter(page, n);
      return counts(page);
    };
    const first = await press();
    expect(first.multisampled - before.multisampled, 'the first press: a lone change, multisampled').toBe(1);
    let repeated = first;
    for (let i = 0; i < 4; i++) repeated = await press();
    expect(repeated.frames - first.frames, 'a frame per repeat').toBe(4);
    expect(repeated.multisampled, 'no multisampled draw while the key repeats').toBe(first.multisampled);
    await page.keyboard.up('ArrowDown');
    await untilQuiet(page);
    const released = await counts(page);
    expect([released.frames - repeated.frames, released.multisampled - repeated.multisampled]).toEqual([1, 1]);
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it('saves the multisampled picture from the middle of a drag, its frame still plain', async () => {
    const page = await openZones();
    const { held } = await pressAndDrag(page);
    const atSave = await page.$eval('.widget-fresnel-zones .save-view', (button) => {
      const multisampled = window.__draws.multisampled;
      window.__plainAtSave = window.__frame.slice(); // the plain frame the canvas shows as the save is clicked
      button.click(); // the still is redrawn in the click's task
      return { frames: globalThis.__shadingLab.frames, multisampled: window.__draws.multisampled - multisampled };
    });
    expect(held.log.at(-1).multisampled, 'the frame at the save was plain').toBe(held.multisampled);
    expect(atSave.multisampled, 'the mesh drawn multisampled for the still').toBe(1);
    await page.waitForFunction(() => window.__saved, { timeout: WAIT_MS });
    const plain = await counts(page, true, '__plainAtSave');
    const settled = await release(page);
    expect(settled.frames, 'the release came after the save').toBe(atSave.frames + 1);
    const saved = await savedPixels(page);
    expect(saved === settled.frame, 'saved picture = settled frame, byte for byte').toBe(true);
    expect(saved).not.toBe(plain.frame);
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it('draws the same multisampled picture after its context is lost and restored', async () => {
    const page = await openZones();
    const before = await counts(page, true);
    await page.evaluate(() => {
      const gl = document.querySelector('.viewport canvas').getContext('webgl2');
      window.__lose = gl.getExtension('WEBGL_lose_context');
      window.__lose.loseContext();
    });
    await page.waitForFunction(() => document.querySelector('.viewport canvas').getContext('webgl2').isContextLost());
    await page.evaluate(() => window.__lose.restoreContext());
    await untilFrameAfter(page, before.frames);
    await untilQuiet(page);
    const after = await counts(page, true);
    expect(after.multisampled - before.multisampled, 'the mesh, multisampled').toBe(1);
    expect(after.frame === before.frame, 'the frame before the loss = the frame after, byte for byte').toBe(true);
    expect(page.errors).toEqual([]);
    await page.close();
  });
});

describe("antialias: 'settled' with three.js's own materials (the 3-D lobe of brdf-lobe)", () => {
  it('draws an orbit drag plainly, then a multisampled frame equal to that of a multisampled context', async () => {
    const path = `embed.html?w=${LOBE}`;
    const page = await openWidget(LOBE, path);
    const { start, held } = await pressAndDrag(page);
    expect(held.frames - start.frames, 'a frame per pointer move').toBeGreaterThanOrEqual(DRAG.length - 1);
    expect(held.multisampled - start.multisampled, 'no multisampled draw while the pointer is held').toBe(0);
    const settled = await release(page);
    expect(settled.frames - held.frames, 'frames after the release').toBe(1);
    expect(settled.multisampled, 'the frame after the release, multisampled').toBeGreaterThan(held.multisampled);
    // the same orbit (the same pointer path), its last frame drawn while the pointer is still down
    const reference = await referenceFrame(LOBE, path, pressAndDrag);
    expect(settled.frame === reference, 'settled frame = context-multisampled frame, byte for byte').toBe(true);
    expect(page.errors).toEqual([]);
    await page.close();
  });
});
