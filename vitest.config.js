import { configDefaults, defineConfig } from 'vitest/config';

// The browser tests run two files at a time (one Chromium a worker, a browser context a file: harness.js
// launchBrowser, kept by tests/browser/global-setup.js): much of a browser test is waiting (idle
// windows, loads, convergence), so two share the 2 cores (the suite of 2026-11-30 in 13 to 14 min, against about
// 17 min one at a time). Three at a time was about 5 % faster, but a material-lab test failed under that load: not
// yet understood.
// A unit test gets 30 s, not vitest's 5 s: on this 2-core machine shared with other work (load average 20 to 28)
// the heaviest Node cases (tests/unit/measured-model.test.js) took 10 and 13 s; after they wrote less of their MERL
// files, 4 and 2 s, but 16 and 12 s with two CPU hogs and a browser test beside them. 30 s is about twice the
// worst seen, and a test that hangs still fails within half a minute. A hook gets the same (a beforeAll that imports
// the app with a module mocked took over vitest's 10 s at a load average of about 40).
// The unit files share their worker's modules (isolate: false): isolated, each of the 96 files imported the app's
// modules afresh (three.js and every widget, for the files that load the registry), 366 s of import in a run at a
// load average of about 30; eight of those files took 91 s isolated and 39 s shared, back to back. The files that
// mock modules or stub globals keep a worker's modules to themselves (ISOLATED_UNIT, the project unit-isolated).

/**
 * The unit files that mock modules (vi.mock, vi.doMock: three.js made unloadable, a term added to the catalogue)
 * or stub globals and timers: each gets modules of its own, as before.
 */
const ISOLATED_UNIT = [
  'add-a-term',
  'add-an-anisotropic-term',
  'debug-hooks',
  'fresnel-widgets-pure',
  'gl-budget',
  'hostile-exercises',
  'pure-rooms-media-surfaces-measured',
  'settled-task',
  'term-widget-rooms',
].map((name) => `tests/unit/${name}.test.js`);

/**
 * The quick run (npm run test:quick, SHADING_LAB_QUICK=1): every unit file but the heavy numerical ones (each 5 s
 * or more in Node: integrals, fits, tables recomputed), and of the browser files these four.
 */
export const HEAVY_UNIT = [
  'measured-fit',
  'multiple-scattering',
  'albedo-table',
  'quoted-figures',
  'dfg-table',
  'lab-programs',
  'saved-links',
  'example-fits',
  'openpbr-walk',
  'albedo-quadrature',
  'openpbr',
  'brdf-integrate',
  'measured-merl',
].map((name) => `tests/unit/${name}.test.js`);
export const QUICK_BROWSER = ['pages-load', 'parity', 'csp', 'harness'].map((name) => `tests/browser/${name}.test.js`);
const quick = process.env.SHADING_LAB_QUICK === '1';

export default defineConfig({
  test: {
    projects: [
      // every project takes two workers: vitest runs projects together only when their worker counts agree
      {
        extends: true,
        test: {
          name: 'unit',
          include: ['tests/unit/**/*.test.js'],
          exclude: [...configDefaults.exclude, ...ISOLATED_UNIT, ...(quick ? HEAVY_UNIT : [])],
          environment: 'node',
          isolate: false,
          testTimeout: 30_000,
          hookTimeout: 30_000,
          maxWorkers: 2,
        },
      },
      {
        extends: true,
        test: {
          name: 'unit-isolated',
          include: ISOLATED_UNIT,
          environment: 'node',
          testTimeout: 30_000,
          hookTimeout: 30_000,
          maxWorkers: 2,
        },
      },
      {
        extends: true,
        test: {
          name: 'browser',
          include: quick ? QUICK_BROWSER : ['tests/browser/**/*.test.js'],
          globalSetup: ['tests/browser/global-setup.js'],
          // a test's budget (helpers.js TEST_BUDGET_MS): a browser test waits on conditions, each wait bounded by
          // WAIT_MS (180 s), so a loaded machine (two CPU hogs beside the suite: up to ~3 times as long) fails none
          testTimeout: 240_000,
          hookTimeout: 240_000,
          // expect.poll's own default is 1 s: a condition a loaded machine takes longer to reach (a lil-gui folder's
          // opening transition, in CI) failed there; a poll with no timeout of its own gets WAIT_MS (helpers.js)
          expect: { poll: { timeout: 180_000 } },
          maxWorkers: 2,
        },
      },
    ],
  },
});
