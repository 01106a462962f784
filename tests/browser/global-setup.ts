// Global setup of the `browser` test project: a production build of the site
// (vite.config.ts, as `npm run build` makes it) into a temporary folder, served
// under a sub-path on a free port. Tests read the address with
// `inject('siteUrl')` (or siteUrl() from harness.ts).
import { existsSync } from 'node:fs';
import { mkdtemp, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { build } from 'vite';
import type { TestProject } from 'vitest/node';
import { serveStatic } from '../../scripts/static-server.mjs';

/** Not the root, so a URL that only works at the root fails the tests. */
export const SITE_PREFIX = '/sub/voxpath/';

declare module 'vitest' {
  export interface ProvidedContext {
    /** Address of the built site's index page; ends with SITE_PREFIX. */
    siteUrl: string;
  }
}

export default async function setup(project: TestProject): Promise<() => Promise<void>> {
  const root = project.config.root;
  if (!existsSync(join(root, 'web', 'index.html'))) {
    throw new Error('web/index.html is missing: the browser tests test the page, so there must be one');
  }
  if (!existsSync(join(root, 'web', 'core', 'pkg', 'voxpath_bg.wasm'))) {
    throw new Error('web/core/pkg is not built: run `node scripts/setup.mjs test` first (npm test does)');
  }
  const outDir = await mkdtemp(join(tmpdir(), 'voxpath-site-'));
  await build({
    configFile: join(root, 'vite.config.ts'),
    build: { outDir, emptyOutDir: true },
    logLevel: 'warn',
  });
  const server = await serveStatic({ dir: outDir, prefix: SITE_PREFIX });
  project.provide('siteUrl', server.url);
  return async () => {
    await server.close();
    await rm(outDir, { recursive: true, force: true });
  };
}
