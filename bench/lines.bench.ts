/**
 * Every line algorithm on one long move: a 3D line of 2,000,000 steps for
 * the algorithms that step the longest axis every time (greedy and walk6
 * take one axis per step: 4,600,004), the same line in 2D for bresenham2d.
 * Plus the regions stepper alone, natively: what stepping costs before
 * anything is recorded.
 */
import { COLUMN_NOTES, COLUMNS, measureRow, native } from './measure.js';
import type { BenchGroup, BenchRow } from './types.js';

const N = 2_000_000;
const TO_3D = [N, (7 * N) / 10 + 1, (6 * N) / 10 + 3];

const LINES = [
  ['regions', 3],
  ['bresenham3d', 3],
  ['nd', 3],
  ['liu-float', 3],
  ['dda', 3],
  ['greedy', 3],
  ['walk6', 3],
  ['bresenham2d', 2],
] as const;

export default async function lines(): Promise<BenchGroup> {
  const requests = LINES.map(([algorithm, dims]) => ({ algorithm, from: new Array<number>(dims).fill(0), to: TO_3D.slice(0, dims) }));
  const natives = native(requests);
  const rows: BenchRow[] = [];
  for (const [i, request] of requests.entries()) {
    rows.push(await measureRow(`${request.algorithm}, ${request.to.length}D line to (${request.to.join(', ')})`, request, natives[i]!));
  }
  const regions = natives[0]!;
  rows.push({
    name: 'regions stepper alone (RegionsWang::next_step, nothing recorded)',
    steps: regions.steps,
    rates: { [COLUMNS.nativeSteps]: regions.steps / regions.stepperSeconds! },
  });
  return { title: 'Lines', notes: COLUMN_NOTES, rows };
}
