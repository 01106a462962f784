// The exercise's own vitest set-up, so that `npx vitest run` in this folder
// runs its test: the repository's vitest.config.ts has projects for tests/
// only, and `npx vitest run examples/exercise-bresenham3d` from the root
// found no test files. Copied into a course's own project, this file is
// optional (vitest's default include takes *.test.js).
import { defineConfig } from 'vitest/config';

export default defineConfig({ test: { include: ['*.test.js'] } });
