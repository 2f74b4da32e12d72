// Multisampling once the changes pause (src/core/gpu/settled-antialias.js), in fresnel-zones (its own shader) and
// the 3-D lobe of brdf-lobe (three.js's built-in materials, colour-managed by three.js): WebGL itself tells
// how each draw call was sampled (the SAMPLES of the framebuffer it draws into), and each frame is read back in the
// task that drew it. The reference for the settled picture is the one before this mode: the same page with its
// WebGL context made multisampled (antialias: true), drawn straight to the canvas.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { baseUrl, launchBrowser, settle } from './helpers.js';
import { openPage } from './harness.js';

const WIDGET = 'fresnel-zones';
const PAGE = `embed.html?w=${WIDGET}&shape=teapot&mode=zones-nv&camera=perspective`;
const DRAG = [30, 34, 38, 42, 46, 50, 54, 58]; // light θ, one change per frame
const LOBE = 'brdf-lobe'; // its 3-D lobe view: a surface patch, two lobes and arrows
const QUIET_MS = 130; // the pause after which a frame is multisampled (settled-antialias.js)

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
 * { at, multisampled so far }) and keeps it as read back right after it was drawn (window.__frame, RGBA); keeps
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
      window.__frameLog.push({ at: performance.now(), multisampled: window.__draws.multisampled });
      queueMicrotask(readFrame);
    },
  };
}

async function openWidget(widget, path, contextAntialias = false) {
  const page = await openPage(browser, baseUrl(), path, {
    beforeLoad: (p) => p.evaluateOnNewDocument(instrument, contextAntialias),
  });
  await page.waitForFunction((w) => globalThis.__shadingLab?.widgets?.[w], { timeout: 30_000 }, widget);
  await settle(page, 1000);
  return page;
}
const openZones = (contextAntialias = false) => openWidget(WIDGET, PAGE, contextAntialias);

/** In the page: the state change, then the frame it causes (or none within a second). */
const change = (page, partial, widget = WIDGET) =>
  page.evaluate(
    (w, p) => {
      const lab = globalThis.__shadingLab;
      const before = lab.frames;
      lab.widgets[w].update(p);
      return new Promise((resolve) => {
        const t0 = performance.now();
        const wait = () =>
          lab.frames > before || performance.now() - t0 > 1000 ? resolve() : requestAnimationFrame(wait);
        requestAnimationFrame(wait);
      });
    },
    widget,
    partial,
  );

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

/** A drag of the light, one change per frame; and the state once it has paused. */
async function drag(page, widget = WIDGET) {
  const start = await counts(page);
  for (const lightTheta of DRAG) await change(page, { lightTheta }, widget);
  const dragged = await counts(page, true);
  await settle(page, 800);
  return { start, dragged, settled: await counts(page, true) };
}

/** Whether the last frame drawn had no multisampled draw. */
const lastFramePlain = ({ log, multisampled }) => log.at(-1).multisampled === multisampled;

/** Each frame of a drag (after its first): the time since the frame before it (ms), its multisampled draws. */
function dragFrames({ start, dragged }) {
  const log = [...dragged.log.slice(start.frames), { multisampled: dragged.multisampled }];
  return log
    .slice(1, -1)
    .map((f, i) => ({ gap: f.at - log[i].at, multisampled: log[i + 2].multisampled - f.multisampled }));
}

describe("antialias: 'settled' (fresnel-zones)", () => {
  it('draws a drag plainly, then one multisampled frame equal to the context-multisampled one', async () => {
    const page = await openZones();
    const run = await drag(page);
    const { start, dragged, settled } = run;
    expect(dragged.frames - start.frames, 'a frame per change').toBe(DRAG.length);
    // a frame that follows the one before within the pause is plain, one after a longer gap multisampled (this
    // machine may be slow enough for a gap that long)
    const frames = dragFrames(run);
    const quick = frames.filter((f) => f.gap < QUIET_MS);
    expect(quick.length, `frames ${JSON.stringify(frames)}`).toBeGreaterThanOrEqual(frames.length / 2);
    expect(quick.map((f) => f.multisampled)).toEqual(quick.map(() => 0));
    expect(frames.filter((f) => f.gap > QUIET_MS + 1).every((f) => f.multisampled === 1)).toBe(true);
    // one multisampled frame after the pause, unless the drag's last frame was one already (a slow gap before it)
    const after = lastFramePlain(dragged) ? 1 : 0;
    expect(settled.frames - dragged.frames, 'frames after the pause').toBe(after);
    expect(settled.multisampled - dragged.multisampled, 'multisampled draws after the pause: the mesh').toBe(after);
    if (after) expect(settled.frame, 'the settled frame differs from the last plain one').not.toBe(dragged.frame);

    const reference = await openZones(true); // the picture before this mode: every frame multisampled by the context
    const { dragged: referenceLast } = await drag(reference);
    expect(settled.frame === referenceLast.frame, 'settled frame = context-multisampled frame, byte for byte').toBe(
      true,
    );
    expect([...page.errors, ...reference.errors]).toEqual([]);
    await Promise.all([page.close(), reference.close()]);
  });

  it('draws a lone change multisampled at once, and nothing more after it', async () => {
    const page = await openZones();
    const before = await counts(page);
    await change(page, { shape: 'torusknot' });
    const changed = await counts(page);
    expect(changed.frames - before.frames).toBe(1);
    expect(changed.multisampled - before.multisampled, 'the mesh, multisampled').toBe(1);
    await settle(page, 800);
    const after = await counts(page);
    // (its zone shares are measured after it: plain draws into float images, no frame)
    expect([after.frames, after.multisampled]).toEqual([changed.frames, changed.multisampled]);
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it('saves the multisampled picture from the middle of a drag, its frame still plain', async () => {
    const page = await openZones();
    // a loaded machine may space a drag's frames past the pause (then the canvas already holds the multisampled
    // frame): the drag is made again until its last frame is plain, and the save is clicked in the same task
    let atSave = null;
    for (let attempt = 0; attempt < 5 && !atSave; attempt++) {
      for (const lightTheta of DRAG) await change(page, { lightTheta: lightTheta + attempt });
      atSave = await page.$eval('.widget-fresnel-zones .save-view', (button) => {
        const multisampled = window.__draws.multisampled;
        if (window.__frameLog.at(-1).multisampled !== multisampled) return null; // the last frame multisampled
        window.__plainAtSave = window.__frame.slice(); // the plain frame the canvas shows as the save is clicked
        button.click(); // the still is redrawn in the click's task
        return { frames: globalThis.__shadingLab.frames, multisampled: window.__draws.multisampled - multisampled };
      });
    }
    expect(atSave, 'a drag whose last frame is plain, in five tries').not.toBeNull();
    expect(atSave.multisampled, 'the mesh drawn multisampled for the still').toBe(1);
    await page.waitForFunction(() => window.__saved, { timeout: 10_000 });
    const plain = await counts(page, true, '__plainAtSave');
    await settle(page, 800);
    const settled = await counts(page, true);
    expect(settled.frames, 'the pause came after the save').toBe(atSave.frames + 1);
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
      const lose = document.querySelector('.viewport canvas').getContext('webgl2').getExtension('WEBGL_lose_context');
      lose.loseContext();
      setTimeout(() => lose.restoreContext(), 300);
    });
    await settle(page, 1500);
    const after = await counts(page, true);
    expect(after.frames).toBeGreaterThan(before.frames);
    expect(after.multisampled - before.multisampled, 'the mesh, multisampled').toBe(1);
    expect(after.frame === before.frame, 'the frame before the loss = the frame after, byte for byte').toBe(true);
    expect(page.errors).toEqual([]);
    await page.close();
  });
});

describe("antialias: 'settled' with three.js's own materials (the 3-D lobe of brdf-lobe)", () => {
  it('draws a drag plainly, then a multisampled frame equal to that of a multisampled context', async () => {
    const page = await openWidget(LOBE, `embed.html?w=${LOBE}`);
    const { start, dragged, settled } = await drag(page, LOBE);
    expect(dragged.frames - start.frames, 'a frame per change').toBe(DRAG.length);
    expect(dragged.plain, 'the drag drew plain frames').toBeGreaterThan(start.plain);
    if (lastFramePlain(dragged)) {
      expect(settled.frames - dragged.frames, 'frames after the pause').toBe(1);
      expect(settled.multisampled, 'the frame after the pause, multisampled').toBeGreaterThan(dragged.multisampled);
    } else expect(settled.frames, 'the last frame was multisampled: none after it').toBe(dragged.frames);
    const reference = await openWidget(LOBE, `embed.html?w=${LOBE}`, true);
    const { dragged: referenceLast } = await drag(reference, LOBE);
    expect(settled.frame === referenceLast.frame, 'settled frame = context-multisampled frame, byte for byte').toBe(
      true,
    );
    expect([...page.errors, ...reference.errors]).toEqual([]);
    await Promise.all([page.close(), reference.close()]);
  });
});
