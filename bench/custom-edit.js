// The time from an edit of a user-written term to the redrawn widget: in brdf-lobe with a custom D, a one-digit
// change of a constant in the code, made with the keyboard as a user makes it, timed from that keystroke to the
// frame that shows it (the polar plot re-described with the new peak, the next animation frame drawn, the 3-D
// view's GPU work finished by a one-pixel read-back). Includes the editor's pause for typing (EDIT_DELAY_MS, the
// wait before an edit reaches the widget), then the static checks, the compile, the GPU table and the redraw.
// Run alone: `flock /tmp/browser.lock node bench/custom-edit.js` (prints and returns { medianMs, worstMs, … }).
import { pathToFileURL } from 'node:url';
import { EDIT_DELAY_MS } from '../src/core/custom/custom-panel-delay.js';
import { buildApp, launchBrowser, openPage, serveStatic, settle } from '../tests/browser/harness.js';

const EDITS = 20;
const CODE = `float customD(float nh, float alpha) {
float a2 = alpha * alpha;
float d = nh * nh * (a2 - 1.0) + 1.0;
return a2 / (PI * d * d) * 1.01;
}`;

/** In the page: from the next keydown in the editor to the frame that shows the edit (ms), or null after 10 s. */
function armTimer() {
  const canvas = document.querySelector('.polar-plot canvas');
  const before = canvas.getAttribute('aria-label');
  window.__editTime = new Promise((resolve) => {
    let t0 = 0;
    document.addEventListener('keydown', () => (t0 = performance.now()), { capture: true });
    const watch = new MutationObserver(() => {
      if (canvas.getAttribute('aria-label') === before) return;
      watch.disconnect();
      requestAnimationFrame(() => {
        const gl = document.querySelector('.lobe-3d canvas').getContext('webgl2');
        gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
        requestAnimationFrame(() => resolve(performance.now() - t0));
      });
    });
    watch.observe(canvas, { attributes: true, attributeFilter: ['aria-label'] });
    setTimeout(() => resolve(null), 10_000);
  });
}

const quantile = (xs, q) => [...xs].sort((a, b) => a - b)[Math.min(xs.length - 1, Math.floor(q * xs.length))];

/**
 * Median and worst time from an edit to the redrawn widget over `edits` one-digit edits. `url`: a served build
 * (else one is built and served here); `browser`: a launched Chromium (else one is launched here); `paste`: the
 * code put in as one input event instead of typed a key at a time (the bench's test: that setup is not timed, and
 * typed it took 4 to 11 s at a load average of 30 to 40); `pauseMs`: the pause after the code is in, before the edits.
 */
export async function measureCustomEdit({ url, browser, edits = EDITS, paste = false, pauseMs = 2000 } = {}) {
  const server = url ? null : await serveStatic(await buildApp());
  const chromium = browser ?? (await launchBrowser());
  try {
    const page = await openPage(chromium, url ?? server.url, 'embed.html?w=brdf-lobe&D=custom', {
      width: 1100,
      height: 1400,
    });
    await page.waitForSelector('.custom-panel .cm-content', { timeout: 60_000 });
    await page.click('.custom-panel .cm-content');
    await page.keyboard.down('Control');
    await page.keyboard.press('a');
    await page.keyboard.up('Control');
    await (paste ? page.keyboard.sendCharacter(CODE) : page.keyboard.type(CODE));
    for (const key of ['ArrowUp', 'End', 'ArrowLeft']) await page.keyboard.press(key); // after the last digit
    await settle(page, pauseMs);
    const ms = [];
    for (let i = 0; i < edits; i++) {
      await page.keyboard.press('Backspace');
      await page.evaluate(armTimer);
      await page.keyboard.type(String(1 + ((i + 1) % 9)));
      ms.push(await page.evaluate(() => window.__editTime));
      await settle(page, 100);
    }
    await page.close();
    const done = ms.filter((x) => x !== null);
    return {
      edits: done.length,
      missed: ms.length - done.length,
      medianMs: quantile(done, 0.5),
      worstMs: Math.max(...done),
      editDelayMs: EDIT_DELAY_MS,
    };
  } finally {
    if (!browser) await chromium.close();
    server?.close();
  }
}

if (import.meta.url === pathToFileURL(process.argv[1]).href) {
  const r = await measureCustomEdit();
  console.log(
    `Edit to redrawn widget (brdf-lobe, custom D, ${r.edits} edits${r.missed ? `, ${r.missed} missed` : ''}): ` +
      `median ${r.medianMs.toFixed(0)} ms, worst ${r.worstMs.toFixed(0)} ms ` +
      `(of which ${r.editDelayMs} ms the editor's pause for typing)`,
  );
}
