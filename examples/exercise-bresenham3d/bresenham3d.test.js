// The exercise's test: the student's line must follow voxpath's rule. Run
// with `npx vitest run` in this folder (its vitest.config.js; in this
// repository, after `npm run build:lib`, which makes voxpath/vitest). With
// the deliberate bug in bresenham3d.js it fails at point 5, with voxpath's
// reason.
import { expect, test } from 'vitest';
import { voxpathMatchers } from 'voxpath/vitest';
import { bresenham3d } from './bresenham3d.js';

expect.extend(voxpathMatchers);

export const MOVE = { from: [0, 0, 0], to: [10, 7, 6] };

test('my 3D Bresenham follows Wang\'s discriminate regions (tie = advance)', async () => {
  await expect(bresenham3d(MOVE.from, MOVE.to)).toFollowRule({ algorithm: 'regions', ...MOVE });
});
