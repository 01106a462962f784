/**
 * Plain TypeScript implementations of the core's algorithms, stepping only:
 * each returns the packed step codes of its path (the core's
 * Trace.stepCodes), with the core's default options. `npm run bench` times
 * them against the wasm core; tests/reference.test.ts checks that they give
 * exactly the core's steps, so the ratio compares like with like.
 */
import { arcSegments } from './arc-segments.js';
import { bresenham2d } from './bresenham2d.js';
import { bresenham3d } from './bresenham3d.js';
import { circle } from './circle.js';
import type { Reference } from './common.js';
import { dda } from './dda.js';
import { greedy } from './greedy.js';
import { helix } from './helix.js';
import { liuFloat } from './liu-float.js';
import { nd } from './nd.js';
import { regions } from './regions.js';
import { walk6 } from './walk6.js';

export type { Reference, ReferenceOptions } from './common.js';

/** The reference of each algorithm id (helix method segments is the chords' reference). */
export const REFERENCES: Record<string, Reference> = {
  regions,
  bresenham2d,
  bresenham3d,
  nd,
  'liu-float': liuFloat,
  greedy,
  walk6,
  dda,
  circle,
  'arc-segments': arcSegments,
  helix: (options) => (options.method === 'segments' ? arcSegments(options) : helix(options)),
};
