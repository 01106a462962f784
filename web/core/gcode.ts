/**
 * G-code programs on a modelled machine:
 *
 *   const program = await runGcode('G1 X10 Y5 F600', { stepsPerMm: 80 }, { onProgress });
 *   program.trace;          // every step (a Trace: points, decisions, explain...)
 *   program.moveCount;      // how many moves ran
 *   program.move(0);        // a move: its source line, mm, steps, note, arc and timing
 *   program.movesInRange(0, 100); // moves 0..100, read from the core on demand
 *   program.lineOfStep(k);  // the line that produced step k
 *   program.errors;         // [{ line, column, message }]
 *   program.durationSeconds; // on the planned motion profile (Grbl 1.1's planner)
 *   program.stepTimes(0, 10); // Float64Array: when each step happens, seconds
 *   program.motionChart(0, 10, 800); // speed and step rates over 0..10 s, chart rows
 *
 * Machine positions are in steps (integers); moves also report mm. The core
 * runs the program a slice of lines at a time (./slices.ts), so a worker
 * stays responsive: it can post progress and take a cancel (an AbortSignal)
 * while a long program runs.
 */
import { callCore } from './errors.js';
import { aNumber, argumentError, indexRange, textOrUtf8, wholeNumber } from './guard.js';
import { encodeRequest } from './request.js';
import { advanceInSlices, checkSliceOptions, freeStopped, type SliceOptions, yieldToEventLoop } from './slices.js';
import { Trace, requireTrace } from './trace.js';
import { loadCore, withTextBytes } from './wasm.js';
import type { GcodeResult, GcodeSettings, GcodeVcd, MotionChart, Move, Progress as GcodeProgress, ProgramInfo } from './pkg/voxpath.js';

/**
 * The settings (GcodeSettings: one field per setting of the catalogue's
 * gcodeSettings, which documents each), the program's record and its parts
 * are the core's Rust types (rust/src/gcode/program.rs), re-exported under
 * the API's names.
 */
export type {
  ArcInfo as GcodeArc,
  Diagnostic as GcodeDiagnostic,
  GcodeSettings,
  MotionChart,
  Move as GcodeMove,
  ProgramInfo as GcodeProgramInfo,
  Progress as GcodeProgress,
  Timing as GcodeTiming,
} from './pkg/voxpath.js';

/** A program that has run: its record's fields (the core's ProgramInfo), its moves and its trace. */
export interface GcodeProgram extends Readonly<ProgramInfo> {}
export class GcodeProgram {
  /** Every step of every move, in order (dims 3: x, y, z in steps). */
  readonly trace: Trace;
  /** The core's record of the run; undefined once freed. */
  #result?: GcodeResult;
  readonly #openVcd: () => GcodeVcd;
  readonly #nextVcdPart: (writer: GcodeVcd) => Uint8Array | undefined;

  /**
   * `result` is the core's record of the run (its plan); `openVcd` starts the
   * run's VCD and `nextVcdPart` writes its next part (undefined at its end).
   */
  constructor(info: ProgramInfo, trace: Trace, result: GcodeResult, openVcd: () => GcodeVcd, nextVcdPart: (writer: GcodeVcd) => Uint8Array | undefined) {
    this.#result = result;
    this.#openVcd = openVcd;
    this.#nextVcdPart = nextVcdPart;
    Object.assign(this, info);
    this.trace = trace;
  }

  /** The core's record of the run (a VoxpathError once freed). */
  get #core(): GcodeResult {
    if (this.#result === undefined) throw argumentError('program', 'this program was freed (free()); run it again to read it');
    return this.#result;
  }

  /**
   * The moves of indices from..to, each with its source line, mm, steps,
   * note, arc and timing: the core keeps them compact and builds these
   * objects only when asked.
   */
  movesInRange(from: number, to: number): Move[] {
    const core = this.#core;
    [from, to] = indexRange(from, to, this.moveCount, 'move index');
    return callCore(() => core.moves(from, to));
  }

  /** The move of index i (0 ≤ i < moveCount). */
  move(i: number): Move {
    wholeNumber('i', i, 0, this.moveCount - 1, 'move index');
    return this.movesInRange(i, i + 1)[0]!;
  }

  /**
   * Every move at once (movesInRange(0, moveCount)), built on each read: a
   * long program's are better read by range.
   */
  get moves(): Move[] {
    return this.movesInRange(0, this.moveCount);
  }

  /** Index of the move that took step index k (moves are in step order). */
  moveOfStep(k: number): number {
    const core = this.#core;
    wholeNumber('k', k, 0, this.steps - 1, 'step index');
    return core.moveOfStep(k)!;
  }

  /** The 1-based source line that produced step index k. */
  lineOfStep(k: number): number {
    return this.move(this.moveOfStep(k)).line;
  }

  /** Source lines of step indices from..to: lineByStep[i] produced step from + i. */
  lineByStepInRange(from: number, to: number): Uint32Array {
    const core = this.#core;
    [from, to] = indexRange(from, to, this.steps, 'step index');
    return callCore(() => core.lineByStep(from, to));
  }

  /** The move programmed on a 1-based source line, if that line moved. */
  moveAtLine(line: number): Move | undefined {
    const core = this.#core;
    wholeNumber('line', line, 1, Number.MAX_SAFE_INTEGER, 'line number');
    const i = core.moveAtLine(Math.min(line, 2 ** 32 - 1));
    return i === undefined ? undefined : this.move(i);
  }

  /**
   * The point index where the machine is when `line` starts: every move of
   * an earlier line done. For an editor cursor on a line without a move.
   */
  pointBeforeLine(line: number): number {
    const core = this.#core;
    wholeNumber('line', line, 1, Number.MAX_SAFE_INTEGER, 'line number');
    return core.pointBeforeLine(Math.min(line, 2 ** 32 - 1));
  }

  /**
   * When each step index from..to happens, seconds from the program's start:
   * step k of a move of n steps when the planned position reaches (k + 1) / n
   * of the move's length. Computed in the core on demand, never stored.
   */
  stepTimes(from: number, to: number): Float64Array {
    const core = this.#core;
    [from, to] = indexRange(from, to, this.steps, 'step index');
    return callCore(() => core.stepTimes(from, to));
  }

  /**
   * Seconds the machine waits at rest for a G4 dwell between fromSeconds
   * and toSeconds (the dwells whose middle is in that span, summed): which
   * part of a pause between two steps (stepTimes) is a dwell, the rest
   * being the machine slowing to the stop and starting again.
   */
  dwellSeconds(fromSeconds: number, toSeconds: number): number {
    const core = this.#core;
    aNumber('fromSeconds', fromSeconds, 'seconds');
    aNumber('toSeconds', toSeconds, 'seconds');
    return callCore(() => core.dwellSeconds(fromSeconds, toSeconds));
  }

  /**
   * The planned speed over time: (seconds, mm/s) pairs, flat, four per
   * planner block (start, end of acceleration, start of deceleration, end);
   * an arc has one block per chord (Grbl's mc_arc).
   */
  speedProfile(): Float64Array {
    return this.#core.speedProfile();
  }

  /**
   * The planned motion over fromSeconds..toSeconds (clipped to the program,
   * an infinite end included; past its end, an empty window at the end)
   * as at most `buckets` chart rows: the tool's speed (mm/s) and each axis's
   * step rate (steps/s), least and greatest per row, and the planned speed
   * where each move starts after another (its corner's junction speed).
   * The rows are the trapezoids' corners when few blocks are in the window,
   * else equal buckets of time. Its cost is that of the blocks in the window.
   */
  motionChart(fromSeconds: number, toSeconds: number, buckets: number): MotionChart {
    const core = this.#core;
    aNumber('fromSeconds', fromSeconds, 'seconds');
    aNumber('toSeconds', toSeconds, 'seconds');
    wholeNumber('buckets', buckets, 1, 2 ** 32 - 1, 'buckets');
    return callCore(() => core.motionChart(fromSeconds, toSeconds, buckets));
  }

  /**
   * The point index the machine has reached `seconds` into the program: how
   * many steps happen at or before that instant (stepTimes, bisected).
   */
  pointAtSeconds(seconds: number): number {
    const core = this.#core;
    aNumber('seconds', seconds, 'seconds');
    return callCore(() => core.pointAtSeconds(seconds));
  }

  /**
   * The STEP and DIR wires of every axis as an IEEE 1364 Value Change Dump
   * (ASCII; timescale 1 ns): STEP rises at each step's instant and falls 10 µs
   * later (Grbl's default pulse), DIR is 1 while the axis runs negative. Opens
   * in PulseView, GTKWave or sigrok as a logic-analyser capture. The whole
   * file at once: for a long program (33 bytes a step on one axis: 1.6 GB
   * for 50,000,000 steps) prefer vcdChunks.
   */
  vcd(): Uint8Array {
    const parts = [...this.vcdChunks()];
    const whole = new Uint8Array(parts.reduce((length, part) => length + part.length, 0));
    let at = 0;
    for (const part of parts) {
      whole.set(part, at);
      at += part.length;
    }
    return whole;
  }

  /**
   * The VCD of vcd(), in parts: the header, then the lines of 65,536 steps
   * at a time, each written by the core when asked, so that only one part
   * is in memory (the CLI's --format vcd writes each as it comes). An error
   * of the program's (two steps too close for a pulse between them, or
   * instants past the VCD's 2^64 ns) is thrown before the first part: the
   * core checks every step's instant when the writer opens, so no part of a
   * VCD that cannot be written whole is handed out.
   */
  *vcdChunks(): Generator<Uint8Array> {
    // It reads both the plan and the trace: neither may have been freed, before any part or between two.
    const alive = () => {
      void this.#core;
      requireTrace('trace', this.trace);
    };
    alive();
    const writer = callCore(this.#openVcd);
    try {
      for (;;) {
        alive();
        const part = callCore(() => this.#nextVcdPart(writer));
        if (part === undefined) return;
        yield part;
      }
    } finally {
      writer.free();
    }
  }

  /**
   * Releases the core's memory of the trace and the plan now. Reading them
   * afterwards is a VoxpathError; freeing again does nothing.
   */
  free(): void {
    this.trace.free();
    this.#result?.free();
    this.#result = undefined;
  }
}

/** Options of runGcode: onProgress gets each slice's Progress (lines of the program). */
export type RunGcodeOptions = SliceOptions<GcodeProgress>;

/**
 * Parses and runs a G-code program: `source` is its text, as a string or as
 * UTF-8 bytes (a file read into a Buffer; bytes that are not UTF-8 reject
 * with a VoxpathError naming `source`). Bad settings reject with a
 * VoxpathError naming the setting; errors in the program do not reject:
 * they are in `errors`, and the trace holds the moves before the first of
 * them.
 */
export async function runGcode(source: string | Uint8Array, settings: GcodeSettings, options: RunGcodeOptions = {}): Promise<GcodeProgram> {
  textOrUtf8('source', source, 'the program');
  const settingsJson = encodeRequest(settings, 'settings');
  const sliceMs = checkSliceOptions('runGcode', options);
  const core = await loadCore();
  const run = callCore(() => trapsAsErrors(() => withTextBytes(core, source, (bytes) => new core.GcodeRun(bytes, settingsJson)), 0));
  let finished = false;
  let linesDone = 0;
  try {
    const advance = (lines: number) => {
      const progress = callCore(() => trapsAsErrors(() => run.advance(lines), linesDone));
      linesDone = progress.linesDone;
      return progress;
    };
    await advanceInSlices(advance, options, sliceMs, { first: 256, least: 16 });
    finished = true;
    const result = run.finish();
    // Every line is read and the motion planned: a cancel sent meanwhile
    // (the page's Cancel reaches its worker only between tasks, and the
    // finish is one) is still honoured, before the result is handed over.
    await yieldToEventLoop();
    if (options.signal?.aborted) {
      result.free();
      options.signal.throwIfAborted();
    }
    try {
      const info = result.program();
      const handle = callCore(() => result.takeTrace());
      return new GcodeProgram(
        info,
        new Trace(handle),
        result,
        () => new core.GcodeVcd(handle, result),
        (writer) => writer.next(handle, result),
      );
    } catch (error) {
      result.free();
      throw error;
    }
  } finally {
    // finish() consumes the run; free it only when it was not reached.
    if (!finished) freeStopped(run);
  }
}

/**
 * Runs `call`, turning a trap of the core (a WebAssembly.RuntimeError, such
 * as memory exhausted past the core's own check) into a VoxpathError that
 * says how far the run got: a caller sees no wasm trap.
 */
function trapsAsErrors<T>(call: () => T, linesDone: number): T {
  try {
    return call();
  } catch (error) {
    if (!(error instanceof WebAssembly.RuntimeError)) throw error;
    throw argumentError('program', `the core failed (${error.message}) after ${linesDone} lines; run the program in parts of fewer lines, or lower stepsPerMm`);
  }
}
