import { defineConfig } from 'vitest/config';

// Two projects, both run by `vitest run`:
// - node: tests/*.test.ts, in Node against the real wasm package web/core/pkg
//   (scripts/setup.mjs builds it first; npm test runs setup).
// - browser: tests/browser/*.test.ts, which drive headless Chromium through
//   playwright-core (tests/browser/harness.ts) against a production build of
//   the site that global-setup.ts serves under a sub-path. This is not
//   vitest's own browser mode: the tests themselves run in Node.
export default defineConfig({
  test: {
    projects: [
      {
        test: {
          name: 'node',
          include: ['tests/*.test.ts'],
          environment: 'node',
        },
      },
      {
        test: {
          name: 'browser',
          include: ['tests/browser/*.test.ts'],
          environment: 'node',
          globalSetup: ['tests/browser/global-setup.ts'],
          // Chromium with software WebGL on a 2-core machine: one test file
          // at a time, and generous time for launches and page loads.
          fileParallelism: false,
          // After the node project, not beside it: its long traces (10,000,000
          // steps) would share the CPU with the page that scale.test.ts times.
          sequence: { groupOrder: 1 },
          testTimeout: 60_000,
          hookTimeout: 60_000,
        },
      },
    ],
  },
});
