/**
 * G-code throughput: a generated 100,000-line program run through the
 * public API (runGcode: parse, interpret, step every move, build the trace).
 * At 1 step/mm against cncjs's gcode-toolpath in the same run (lines per
 * second, median of rounds, both figures and the ratio); at 80 steps/mm
 * with each arc algorithm (steps per second). Rates are of the whole run,
 * as a worker would see it (slices included).
 *
 * `npm run bench` (bench/run.mjs) runs it with the other benches and prints
 * its group (bench/types.ts).
 */
import Toolpath from 'gcode-toolpath';
import { runGcode } from '../web/core/index.js';
import type { GcodeProgram, GcodeSettings } from '../web/core/index.js';
import { collectGarbage } from './measure.js';
import { generateProgram } from './programs.js';
import type { BenchGroup, BenchRow } from './types.js';

/** Lines in the generated program. */
export const GCODE_BENCH_LINES = 100_000;

/** Column names: rates of the whole run, slices included; the plan's share. */
const COLUMNS = {
  lines: 'lines/s',
  steps: 'steps/s',
  peerLines: 'gcode-toolpath lines/s',
  finishMoves: 'finish moves/s',
  stepTimes: 'stepTimes steps/s',
} as const;

/** Rounds of each measurement; the median is reported. */
const ROUNDS = 6;

const median = (values: number[]) => [...values].sort((a, b) => a - b)[values.length >> 1]!;

/**
 * cncjs's gcode-toolpath 3.0.0 (what a JavaScript user would pick to read a
 * program: parse, modal state, one callback per line or arc segment) on the
 * same text, the moves kept by counting them. Seconds.
 */
function peerSeconds(source: string): number {
  let segments = 0;
  const started = performance.now();
  new Toolpath({ addLine: () => void segments++, addArcCurve: () => void segments++ }).loadFromStringSync(source);
  const seconds = (performance.now() - started) / 1000;
  if (segments === 0) throw new Error('gcode-toolpath read no moves');
  return seconds;
}

/** One run through runGcode: seconds of the whole run and of its finish (after the last line ran). */
async function runSeconds(source: string, settings: GcodeSettings) {
  const started = performance.now();
  // The last progress report comes when every line has run; what follows
  // is the run's finish: the planner's passes over every block, each
  // move's timing, the program's record and the trace handed over.
  let linesDoneAt = started;
  const program = await runGcode(source, settings, { onProgress: () => (linesDoneAt = performance.now()) });
  const finished = performance.now();
  if (program.errors.length > 0) throw new Error(`bench program failed: ${JSON.stringify(program.errors[0])}`);
  return { program, seconds: (finished - started) / 1000, finishSeconds: (finished - linesDoneAt) / 1000 };
}

/**
 * The generated program at 1 step/mm against gcode-toolpath (rounds
 * alternate, so both see the same machine), then at 80 steps/mm with each
 * arc algorithm.
 */
export default async function benchGcode(): Promise<BenchGroup> {
  const source = generateProgram(GCODE_BENCH_LINES);
  const rows: BenchRow[] = [];
  const [ours, peer, finish]: number[][] = [[], [], []];
  let moves = 0;
  let steps = 0;
  for (let round = 0; round <= ROUNDS; round++) {
    // The two sides in turn, each first in every other round and each
    // after an untimed collection of the garbage before it (as the
    // end-to-end table measures): the side that runs second, in the
    // other's garbage, was seen to run slower.
    let peerRun = 0;
    if (round % 2 === 1) {
      await collectGarbage();
      peerRun = peerSeconds(source);
    }
    await collectGarbage();
    const run = await runSeconds(source, { stepsPerMm: 1 });
    if (round % 2 === 0) {
      await collectGarbage();
      peerRun = peerSeconds(source);
    }
    [moves, steps] = [run.program.moveCount, run.program.steps];
    run.program.free();
    // The first round warms both up (V8 compiles JavaScript and wasm in tiers).
    if (round === 0) continue;
    ours.push(run.seconds);
    peer.push(peerRun);
    finish.push(run.finishSeconds);
  }
  rows.push({
    name: `${GCODE_BENCH_LINES.toLocaleString('en-US')} lines, ${moves.toLocaleString('en-US')} moves, 1 step/mm, arcs: circle`,
    steps,
    rates: {
      [COLUMNS.lines]: GCODE_BENCH_LINES / median(ours),
      [COLUMNS.steps]: steps / median(ours),
      [COLUMNS.peerLines]: GCODE_BENCH_LINES / median(peer),
      [COLUMNS.finishMoves]: moves / median(finish),
    },
    ratios: { 'voxpath / gcode-toolpath': median(peer) / median(ours) },
  });
  for (const arcAlgorithm of ['circle', 'arc-segments'] as const) {
    const [seconds, finishSeconds, stepTimeSeconds]: number[][] = [[], [], []];
    let program: GcodeProgram | undefined;
    for (let round = 0; round < ROUNDS; round++) {
      program?.free();
      await collectGarbage();
      const run = await runSeconds(source, { stepsPerMm: 80, arcAlgorithm });
      program = run.program;
      seconds.push(run.seconds);
      finishSeconds.push(run.finishSeconds);
      const t0 = performance.now();
      program.stepTimes(0, program.steps);
      stepTimeSeconds.push((performance.now() - t0) / 1000);
    }
    const p = program!;
    rows.push({
      name: `${p.lines.toLocaleString('en-US')} lines, ${p.moveCount.toLocaleString('en-US')} moves, 80 steps/mm, arcs: ${arcAlgorithm}`,
      steps: p.steps,
      rates: {
        [COLUMNS.lines]: p.lines / median(seconds),
        [COLUMNS.steps]: p.steps / median(seconds),
        [COLUMNS.finishMoves]: p.moveCount / median(finishSeconds),
        [COLUMNS.stepTimes]: p.steps / median(stepTimeSeconds),
      },
      ratios: { 'finish / run': median(finishSeconds) / median(seconds) },
    });
    p.free();
  }
  return {
    title: 'G-code',
    notes: [
      `A generated ${GCODE_BENCH_LINES.toLocaleString('en-US')}-line program through runGcode (wasm): parse, interpret, step every move (lines by regions), build the trace; the moves stay in the core, read on demand.`,
      `${COLUMNS.lines} and ${COLUMNS.steps}: source lines and steps over the seconds of the whole run, as a worker sees it (median of ${ROUNDS} rounds).`,
      `${COLUMNS.peerLines}: cncjs's gcode-toolpath 3.0.0 (parse, modal state, one callback per line or arc) on the same text, in turn with runGcode, each first in every other round, each after an untimed young-generation collection; 'voxpath / gcode-toolpath' is its time over runGcode's (issue 13's goal: 5x).`,
      `${COLUMNS.finishMoves}: moves over the seconds of the run's finish (after the last line ran): Grbl 1.1-style look-ahead planning of every block, the step-rate checks, the record, the trace. The planner's cost per move, so measured: ${rows.map((r) => `${(1e6 / r.rates[COLUMNS.finishMoves]!).toFixed(2)} µs`).join(', ')} (rows in order); 'finish / run' is its share of the whole run.`,
      `${COLUMNS.stepTimes}: program.stepTimes(0, steps), every step's instant from the plan in closed form (median of ${ROUNDS} rounds).`,
    ],
    rows,
  };
}
