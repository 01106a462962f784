#!/usr/bin/env node
// The voxpath CLI. Runs the compiled TypeScript in lib/cli (built by
// `npm run build:lib`, `npm run setup`, `npm run build` or `npm test`; not by
// `npm start`, which builds only what the page needs).
import { existsSync } from 'node:fs';

const entry = new URL('../lib/cli/main.js', import.meta.url);
if (!existsSync(entry)) {
  process.stderr.write('voxpath: the CLI is not built yet; run `npm run setup` in the voxpath folder first\n');
  process.exit(1);
}
const { main } = await import(entry.href);
process.exitCode = await main(process.argv.slice(2));
