/**
 * G-code throughput: a generated 100,000-line program run through the
 * public API (runGcode: parse, interpret, step every move, build the trace),
 * once with each arc algorithm. Reports lines per second and steps per
 * second of the whole run, as a worker would see it (slices included).
 *
 * `npm run bench` (bench/run.mjs) runs it with the other benches and prints
 * its group (bench/types.ts).
 */
import { runGcode } from '../web/core/index.js';
import type { BenchGroup, BenchRow } from './types.js';

/** Lines in the generated program. */
export const GCODE_BENCH_LINES = 100_000;

/**
 * A random walk of short G1 moves (up to 1 mm per axis in X and Y, 0.1 mm
 * in Z) with a clockwise quarter arc of r = 1 mm every tenth line: a pocket
 * clearing program's mix. Deterministic (a fixed linear congruential seed).
 */
export function generateProgram(lines: number): string {
  let seed = 12345;
  const random = () => {
    seed = (Math.imul(seed, 1103515245) + 12345) >>> 0;
    return seed / 2 ** 32;
  };
  const out = ['G21 G90 G17 F1200', 'G0 X25 Y25 Z0'];
  let [x, y, z] = [25, 25, 0];
  const mm = (v: number) => v.toFixed(3);
  while (out.length < lines) {
    if (out.length % 10 === 9) {
      // From angle 0 about (x - 1, y), clockwise to angle -90°.
      out.push(`G2 X${mm(x - 1)} Y${mm(y - 1)} I-1 J0`);
      [x, y] = [x - 1, y - 1];
    } else {
      // Stay within 5..45 mm: step back toward the middle at the edges.
      const step = (v: number, reach: number) => Math.min(45, Math.max(5, v + (random() * 2 - 1) * reach));
      [x, y, z] = [Number(mm(step(x, 1))), Number(mm(step(y, 1))), Number(mm(Math.min(0, step(z, 0.1))))];
      out.push(`G1 X${mm(x)} Y${mm(y)} Z${mm(z)}`);
    }
  }
  return out.join('\n') + '\n';
}

/** Column names: rates of the whole run, slices included; the plan's share. */
const COLUMNS = {
  lines: 'lines/s',
  steps: 'steps/s',
  finishPerMove: 'finish µs/move',
  stepTimes: 'stepTimes steps/s',
} as const;

/** Rounds of stepTimes over the whole program; the median is reported. */
const STEP_TIME_ROUNDS = 5;

const median = (values: number[]) => [...values].sort((a, b) => a - b)[values.length >> 1]!;

/** Runs the generated program with each arc algorithm; one row each. */
export default async function benchGcode(): Promise<BenchGroup> {
  const source = generateProgram(GCODE_BENCH_LINES);
  const rows: BenchRow[] = [];
  for (const arcAlgorithm of ['circle', 'arc-segments'] as const) {
    // One run each, not the best of several: a run is seconds long, so the
    // compilers' warm-up is a small part of it, and the bench stays short.
    const started = performance.now();
    // The last progress report comes when every line has run; what follows
    // is the run's finish: the planner's passes over every block, each
    // move's timing, the program's JSON record and the trace handed over.
    let linesDoneAt = started;
    const program = await runGcode(source, { stepsPerMm: 80, arcAlgorithm }, { onProgress: () => (linesDoneAt = performance.now()) });
    const finished = performance.now();
    const seconds = (finished - started) / 1000;
    if (program.errors.length > 0) throw new Error(`bench program failed: ${JSON.stringify(program.errors[0])}`);
    const stepTimeSeconds: number[] = [];
    for (let round = 0; round < STEP_TIME_ROUNDS; round++) {
      const t0 = performance.now();
      program.stepTimes(0, program.steps);
      stepTimeSeconds.push((performance.now() - t0) / 1000);
    }
    rows.push({
      name: `${program.lines.toLocaleString('en-US')} lines, ${program.moves.length.toLocaleString('en-US')} moves, arcs: ${arcAlgorithm}`,
      steps: program.steps,
      rates: {
        [COLUMNS.lines]: program.lines / seconds,
        [COLUMNS.steps]: program.steps / seconds,
        [COLUMNS.finishPerMove]: ((finished - linesDoneAt) * 1000) / program.moves.length,
        [COLUMNS.stepTimes]: program.steps / median(stepTimeSeconds),
      },
      ratios: { 'finish / run': (finished - linesDoneAt) / (finished - started) },
    });
    program.free();
  }
  return {
    title: 'G-code',
    notes: [
      `A generated ${GCODE_BENCH_LINES.toLocaleString('en-US')}-line program at 80 steps/mm through runGcode (wasm): parse, interpret, step every move (lines by regions), build the trace.`,
      `${COLUMNS.lines} and ${COLUMNS.steps}: source lines and steps over the seconds of the whole run, as a worker sees it.`,
      `${COLUMNS.finishPerMove}: the run's finish (after the last line ran: Grbl-style look-ahead planning of every block, each move's timing, the JSON record, the trace), per move; 'finish / run' is its share of the whole run.`,
      `${COLUMNS.stepTimes}: program.stepTimes(0, steps), every step's instant from the plan in closed form (median of ${STEP_TIME_ROUNDS} rounds).`,
    ],
    rows,
  };
}
