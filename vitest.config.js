import { defineConfig } from 'vitest/config';

// The browser tests run two files at a time, each with its own Chromium: much of a browser test is waiting (idle
// windows, loads, convergence), so two share the 2 cores well (the suite in about 14 min, against about 17 min one
// at a time). The slide-deck tests run alone, after the rest: beside another file, a call into a cross-origin frame
// that reveal.js has just removed was seen to go unanswered.
const ALONE = ['tests/browser/slides.test.js'];
const browser = (test) => ({
  extends: true,
  test: {
    include: ['tests/browser/**/*.test.js'],
    globalSetup: ['tests/browser/global-setup.js'],
    testTimeout: 60_000,
    hookTimeout: 120_000,
    ...test,
  },
});

export default defineConfig({
  test: {
    projects: [
      // the unit and the parallel browser project take two workers each: vitest runs projects together only when
      // their worker counts agree
      {
        extends: true,
        test: { name: 'unit', include: ['tests/unit/**/*.test.js'], environment: 'node', maxWorkers: 2 },
      },
      browser({ name: 'browser', exclude: ['**/node_modules/**', ...ALONE], maxWorkers: 2 }),
      browser({ name: 'browser-alone', include: ALONE, maxWorkers: 1, sequence: { groupOrder: 1 } }),
    ],
  },
});
