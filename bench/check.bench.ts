/**
 * Checking a learner's 1,000,000-point CSV (issue 17 item 6: "checking a
 * 1,000,000-point CSV takes no longer than tracing it plus parsing it").
 * The CSV is the regions path of a 3D line of 1,000,000 steps, so the check
 * compares every point and alsoMatches follows every rule that matches to
 * the end: the check's worst case.
 *
 * Against it: the trace of the rule alone, and "parsing it" as a learner's
 * own code would, in plain JavaScript: one pass over the text's characters
 * into an Int32Array (header skipped, no checks), the least any reading of
 * the text can do. voxpath's own reader (readPoints, the reader the check
 * uses, with its checks and its copy out as a Float64Array) is timed beside
 * it for reference. Each round times all four, one after another, and the
 * ratio is taken within the round; the figures are medians of ROUNDS rounds,
 * after one untimed round.
 */
import { checkPoints, readPoints, trace } from '../web/core/index.js';
import type { TraceOptions } from '../web/core/index.js';
import type { BenchGroup } from './types.js';

const N = 1_000_000;
const REQUEST = { algorithm: 'regions', from: [0, 0, 0], to: [N, (7 * N) / 10 + 1, (6 * N) / 10 + 3] } satisfies TraceOptions;
const ROUNDS = 7;

/** The CSV's numbers in plain JavaScript: the first line (the header) skipped, then each run of digits, with its minus sign, one value. */
function plainParse(csv: string): Int32Array {
  // At least two characters per value (a digit and a separator): room for all.
  const values = new Int32Array(csv.length >> 1);
  let count = 0;
  let value = 0;
  let negative = false;
  let inNumber = false;
  for (let i = csv.indexOf('\n') + 1; i < csv.length; i++) {
    const c = csv.charCodeAt(i);
    if (c >= 48 && c <= 57) {
      value = value * 10 + (c - 48);
      inNumber = true;
    } else if (c === 45) {
      negative = true;
    } else {
      if (inNumber) values[count++] = negative ? -value : value;
      value = 0;
      negative = false;
      inNumber = false;
    }
  }
  if (inNumber) values[count++] = negative ? -value : value;
  return values.subarray(0, count);
}

async function seconds(run: () => unknown): Promise<number> {
  const start = performance.now();
  await run();
  return (performance.now() - start) / 1000;
}

function median(values: number[]): number {
  const sorted = [...values].sort((a, b) => a - b);
  return sorted[Math.floor(sorted.length / 2)]!;
}

export default async function check(): Promise<BenchGroup> {
  const rule = await trace(REQUEST);
  const points = rule.pointsInRange(0, rule.steps + 1);
  const rows: string[] = ['x,y,z'];
  for (let k = 0; k < points.length; k += 3) rows.push(`${points[k]},${points[k + 1]},${points[k + 2]}`);
  const csv = rows.join('\n') + '\n';
  const steps = rule.steps;
  rule.free();
  if (plainParse(csv).length !== points.length) throw new Error('the plain parse misread the CSV');

  const times = { trace: [] as number[], parse: [] as number[], read: [] as number[], check: [] as number[] };
  const ratios: number[] = [];
  const ratiosToReader: number[] = [];
  let matched = '';
  for (let round = 0; round <= ROUNDS; round++) {
    const traceSeconds = await seconds(async () => (await trace(REQUEST)).free());
    const parseSeconds = await seconds(() => plainParse(csv));
    const readSeconds = await seconds(() => readPoints(csv, 3));
    const checkSeconds = await seconds(async () => {
      const c = await checkPoints(REQUEST, csv);
      matched = c.alsoMatches.map((m) => m.label).join('; ');
    });
    if (round === 0) continue; // untimed: compiles, warms up, grows wasm memory
    times.trace.push(traceSeconds);
    times.parse.push(parseSeconds);
    times.read.push(readSeconds);
    times.check.push(checkSeconds);
    ratios.push(checkSeconds / (traceSeconds + parseSeconds));
    ratiosToReader.push(checkSeconds / (traceSeconds + readSeconds));
  }
  const [traceSeconds, parseSeconds, readSeconds, checkSeconds] = [times.trace, times.parse, times.read, times.check].map(median) as [number, number, number, number];
  const ratio = median(ratios);
  const ms = (s: number) => `${(s * 1000).toFixed(0)} ms`;
  return {
    title: 'Checking a learner\'s 1,000,000-point CSV',
    notes: [
      `points/s of the ${steps + 1}-point CSV (${(csv.length / 1e6).toFixed(1)} MB), wasm, medians of ${ROUNDS} rounds, ratios taken within each round:`,
      `check ${ms(checkSeconds)}; trace ${ms(traceSeconds)} + plain JS parse ${ms(parseSeconds)} = ${ms(traceSeconds + parseSeconds)}; check / (trace + parse) = ${ratio.toFixed(2)} (goal: at most 1)`,
      `voxpath's reader alone (readPoints) ${ms(readSeconds)}; check / (trace + readPoints) = ${median(ratiosToReader).toFixed(2)}`,
      `the points follow: ${matched}`,
    ],
    rows: [
      {
        name: 'regions path of a 3D line, as CSV text',
        steps,
        rates: {
          check: (steps + 1) / checkSeconds,
          trace: (steps + 1) / traceSeconds,
          parse: (steps + 1) / parseSeconds,
          'trace + parse': (steps + 1) / (traceSeconds + parseSeconds),
          readPoints: (steps + 1) / readSeconds,
        },
        ratios: { 'check / (trace + parse)': ratio },
      },
    ],
  };
}
