import { defineConfig } from 'vitest/config';

// The browser tests run two files at a time, each with its own Chromium: much of a browser test is waiting (idle
// windows, loads, convergence), so two share the 2 cores (the suite in 13 to 14 min, against about 17 min one at a
// time). Three at a time was about 5 % faster, but a material-lab test failed under that load: not yet understood.
// A unit test gets 30 s, not vitest's 5 s: on a loaded machine (load average 26 on the 2 cores) the heaviest Node
// cases took 10 to 13 s (tests/unit/measured-model.test.js, 1 to 2 s idle, before it wrote less of its files); 30 s
// is twice the worst seen, and a test that hangs still fails within half a minute.

export default defineConfig({
  test: {
    projects: [
      // both projects take two workers: vitest runs projects together only when their worker counts agree
      {
        extends: true,
        test: {
          name: 'unit',
          include: ['tests/unit/**/*.test.js'],
          environment: 'node',
          testTimeout: 30_000,
          maxWorkers: 2,
        },
      },
      {
        extends: true,
        test: {
          name: 'browser',
          include: ['tests/browser/**/*.test.js'],
          globalSetup: ['tests/browser/global-setup.js'],
          testTimeout: 60_000,
          hookTimeout: 120_000,
          maxWorkers: 2,
        },
      },
    ],
  },
});
