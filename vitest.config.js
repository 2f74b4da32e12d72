import { defineConfig } from 'vitest/config';

// The browser tests run three files at a time, each with its own Chromium: much of a browser test is waiting (idle
// windows, loads, convergence), so three share the 2 cores (one file alone keeps them about 40 to 60 % busy; on a
// sample of ten files, two at a time took 133 s at 88 % busy, three 123 s at 94 %).

export default defineConfig({
  test: {
    projects: [
      // both projects take three workers: vitest runs projects together only when their worker counts agree
      {
        extends: true,
        test: { name: 'unit', include: ['tests/unit/**/*.test.js'], environment: 'node', maxWorkers: 3 },
      },
      {
        extends: true,
        test: {
          name: 'browser',
          include: ['tests/browser/**/*.test.js'],
          globalSetup: ['tests/browser/global-setup.js'],
          testTimeout: 60_000,
          hookTimeout: 120_000,
          maxWorkers: 3,
        },
      },
    ],
  },
});
