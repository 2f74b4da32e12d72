import { defineConfig } from 'vitest/config';

export default defineConfig({
  test: {
    projects: [
      { extends: true, test: { name: 'unit', include: ['tests/unit/**/*.test.js'], environment: 'node' } },
      {
        extends: true,
        test: {
          name: 'browser',
          include: ['tests/browser/**/*.test.js'],
          globalSetup: ['tests/browser/global-setup.js'],
          testTimeout: 60_000,
          hookTimeout: 120_000,
          fileParallelism: false, // one Chromium at a time: software WebGL on 2 cores
        },
      },
    ],
  },
});
