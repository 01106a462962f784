/**
 * Checking a learner's 1,000,000-point CSV (issue 17 item 6: "checking a
 * 1,000,000-point CSV takes no longer than tracing it plus parsing it").
 * The CSV is the regions path of a 3D line of 1,000,000 steps, so the check
 * compares every point and alsoMatches follows every rule that matches to
 * the end: the check's worst case. Against it: the trace of the rule alone,
 * and the core's reading of the CSV alone (readPoints, the reader the check
 * uses). Median of ROUNDS rounds each, after one untimed round.
 */
import { checkPoints, readPoints, trace } from '../web/core/index.js';
import type { BenchGroup } from './types.js';

const N = 1_000_000;
const REQUEST = { algorithm: 'regions', from: [0, 0, 0], to: [N, (7 * N) / 10 + 1, (6 * N) / 10 + 3] };
const ROUNDS = 5;

async function medianSeconds(run: () => unknown): Promise<number> {
  await run();
  const times: number[] = [];
  for (let i = 0; i < ROUNDS; i++) {
    const start = performance.now();
    await run();
    times.push((performance.now() - start) / 1000);
  }
  times.sort((a, b) => a - b);
  return times[Math.floor(ROUNDS / 2)]!;
}

export default async function check(): Promise<BenchGroup> {
  const rule = await trace(REQUEST);
  const points = rule.pointsInRange(0, rule.steps + 1);
  const rows: string[] = ['x,y,z'];
  for (let k = 0; k < points.length; k += 3) rows.push(`${points[k]},${points[k + 1]},${points[k + 2]}`);
  const csv = rows.join('\n') + '\n';
  const steps = rule.steps;
  rule.free();

  const traceSeconds = await medianSeconds(async () => (await trace(REQUEST)).free());
  const parseSeconds = await medianSeconds(() => readPoints(csv, 3));
  let matched = '';
  const checkSeconds = await medianSeconds(async () => {
    const c = await checkPoints(REQUEST, csv);
    matched = c.alsoMatches.map((m) => m.label).join('; ');
  });
  const ratio = checkSeconds / (traceSeconds + parseSeconds);
  const ms = (s: number) => `${(s * 1000).toFixed(0)} ms`;
  return {
    title: 'Checking a learner\'s 1,000,000-point CSV',
    notes: [
      `points/s of the ${steps + 1}-point CSV (${(csv.length / 1e6).toFixed(1)} MB), wasm, median of ${ROUNDS} rounds:`,
      `check ${ms(checkSeconds)}; trace ${ms(traceSeconds)} + parse ${ms(parseSeconds)} = ${ms(traceSeconds + parseSeconds)}; check / (trace + parse) = ${ratio.toFixed(2)} (goal: at most 1)`,
      `the points follow: ${matched}`,
    ],
    rows: [
      {
        name: 'regions path of a 3D line, as CSV text',
        steps,
        rates: { check: (steps + 1) / checkSeconds, trace: (steps + 1) / traceSeconds, parse: (steps + 1) / parseSeconds, 'trace + parse': (steps + 1) / (traceSeconds + parseSeconds) },
        ratios: { 'check / (trace + parse)': ratio },
      },
    ],
  };
}
