/**
 * G-code programs on a modelled machine:
 *
 *   const program = await runGcode('G1 X10 Y5 F600', { stepsPerMm: 80 }, { onProgress });
 *   program.trace;          // every step (a Trace: points, decisions, explain...)
 *   program.moves;          // each with its source line and its steps
 *   program.lineOfStep(k);  // the line that produced step k
 *   program.errors;         // [{ line, column, message }]
 *   program.durationSeconds; // on the planned motion profile (Grbl 1.1's planner)
 *   program.stepTimes(0, 10); // Float64Array: when each step happens, seconds
 *
 * Machine positions are in steps (integers); moves also report mm. The core
 * runs the program a slice of lines at a time and this module yields to the
 * event loop between slices, so a worker stays responsive: it can post
 * progress and take a cancel (an AbortSignal) while a long program runs.
 */
import { callCore } from './errors.js';
import { encodeRequest } from './request.js';
import { Trace } from './trace.js';
import { loadCore } from './wasm.js';
import type { GcodeResult } from './pkg/voxpath.js';

/** How the program is run. Give stepsPerMm, or stepAngle, microsteps and pitch. */
export interface GcodeSettings {
  /** Steps per mm: one number for every axis or [x, y, z]. */
  stepsPerMm?: number | number[];
  /** Motor step angle θ in degrees (one or [x, y, z]); steps/mm = (360 / θ · microsteps) / pitch (Wang 3.3). */
  stepAngle?: number | number[];
  /** Microsteps per full step (one or [x, y, z]). */
  microsteps?: number | number[];
  /** Lead-screw pitch, mm per turn (one or [x, y, z]). */
  pitch?: number | number[];
  /** A 3-axis line algorithm id (default 'regions'); also steps the chords of arc-segments. */
  lineAlgorithm?: string;
  /** 'circle' (Saleem, default) or 'arc-segments' (chords); helical arcs use helix by the matching method. */
  arcAlgorithm?: 'circle' | 'arc-segments';
  /** Refuse programs longer than this many steps (default 50,000,000). */
  maxSteps?: number;
  /** Acceleration, mm/s²: one number or [x, y, z] (Grbl $120-$122; default 10). */
  acceleration?: number | number[];
  /** Top rate, mm/min: one number or [x, y, z]; also G0's rate (Grbl $110-$112; default 500). */
  maxRate?: number | number[];
  /** Junction deviation δ, mm (Grbl $11; default 0.01): corner speed² = a·δ·s/(1−s), s = sin(θ/2). */
  junctionDeviation?: number;
  /** Fastest step rate the drivers take, steps/s (one or [x, y, z]): a move needing more is a warning. */
  maxStepRate?: number | number[];
}

/** A warning or an error at a 1-based line and column of the program. */
export interface GcodeDiagnostic {
  line: number;
  column: number;
  message: string;
}

/** An arc as programmed (mm) and as stepped (steps). */
export interface GcodeArc {
  plane: 'xy' | 'zx' | 'yz';
  /** cw = G2, ccw = G3, seen from the positive end of the plane's normal axis. */
  direction: 'cw' | 'ccw';
  /** How the centre was given: I J K, or R. */
  format: 'ijk' | 'r';
  centerMm: number[];
  radiusMm: number;
  /** Signed (< 0 clockwise), extra turns included. */
  sweepDeg: number;
  /** Full turns added by P (P - 1). */
  extraTurns: number;
  /** The grid centre the arc was stepped around; null when it was stepped as a straight line. */
  centerSteps: number[] | null;
}

/** One move of the program. Step indices index program.trace. */
export interface GcodeMove {
  /** 1-based source line and column of its motion code (or first axis word). */
  line: number;
  column: number;
  code: 'G0' | 'G1' | 'G2' | 'G3';
  kind: 'rapid' | 'line' | 'arc' | 'helix';
  /** Machine coordinates (G92 applied), mm. */
  fromMm: number[];
  toMm: number[];
  /** The same in steps: toSteps is round(toMm × steps/mm), halves away from zero. */
  fromSteps: number[];
  toSteps: number[];
  /** The feed in force, mm/min (kept, not used for timing); null for rapids or when unset. */
  feedMmPerMin: number | null;
  /** Step index of the move's first step and its number of steps. */
  firstStep: number;
  steps: number;
  /** Its segments among trace.segments (one per chord for arc-segments). */
  firstSegment: number;
  segments: number;
  /** The catalogue algorithm that stepped it. */
  algorithm: string;
  arc: GcodeArc | null;
  /** What the move is, in a sentence (its segments' notes start with it). */
  note: string;
  /** When it runs on the planned profile; speeds in mm/s (cruiseSpeed: the highest planned in the move). */
  timing: GcodeTiming;
}

/** A move's place in time, seconds from the program's start, speeds in mm/s. */
export interface GcodeTiming {
  startSeconds: number;
  endSeconds: number;
  entrySpeed: number;
  cruiseSpeed: number;
  exitSpeed: number;
}

/** How far a run has got; passed to onProgress after every slice. */
export interface GcodeProgress {
  linesDone: number;
  lines: number;
  moves: number;
  steps: number;
  done: boolean;
}

/** The program's record, as the core reports it. */
export interface GcodeProgramInfo {
  lines: number;
  steps: number;
  stepsPerMm: number[];
  lineAlgorithm: string;
  arcAlgorithm: string;
  moves: GcodeMove[];
  /** How long the program takes on the planned profile, seconds. */
  durationSeconds: number;
  /** Pulses per axis (x, y, z) over the whole program. */
  pulses: number[];
  warnings: GcodeDiagnostic[];
  /** Warnings past the first 1000, counted only. */
  warningsOmitted: number;
  /** Execution stops at the first error; later lines are still checked for syntax. */
  errors: GcodeDiagnostic[];
  /** The line of the first error (every line before it ran), or null. */
  stoppedAtLine: number | null;
}

/** A program that has run: its moves and its trace. */
export class GcodeProgram implements GcodeProgramInfo {
  readonly lines: number;
  readonly steps: number;
  readonly stepsPerMm: number[];
  readonly lineAlgorithm: string;
  readonly arcAlgorithm: string;
  readonly moves: GcodeMove[];
  readonly durationSeconds: number;
  readonly pulses: number[];
  readonly warnings: GcodeDiagnostic[];
  readonly warningsOmitted: number;
  readonly errors: GcodeDiagnostic[];
  readonly stoppedAtLine: number | null;
  /** Every step of every move, in order (dims 3: x, y, z in steps). */
  readonly trace: Trace;
  #moveByLine?: Map<number, number>;
  readonly #result: GcodeResult;
  readonly #vcd: () => Uint8Array;

  /** `result` is the core's record of the run (its plan); `vcd` writes the run's VCD. */
  constructor(info: GcodeProgramInfo, trace: Trace, result: GcodeResult, vcd: () => Uint8Array) {
    this.#result = result;
    this.#vcd = vcd;
    this.lines = info.lines;
    this.steps = info.steps;
    this.stepsPerMm = info.stepsPerMm;
    this.lineAlgorithm = info.lineAlgorithm;
    this.arcAlgorithm = info.arcAlgorithm;
    this.moves = info.moves;
    this.durationSeconds = info.durationSeconds;
    this.pulses = info.pulses;
    this.warnings = info.warnings;
    this.warningsOmitted = info.warningsOmitted;
    this.errors = info.errors;
    this.stoppedAtLine = info.stoppedAtLine;
    this.trace = trace;
  }

  /** Index of the move that took step index k (moves are in step order; a binary search). */
  moveOfStep(k: number): number {
    if (!Number.isInteger(k) || k < 0 || k >= this.steps) throw new RangeError(`step index ${k} is outside 0..${this.steps}`);
    let lo = 0;
    let hi = this.moves.length - 1;
    // The first move whose end (firstStep + steps) is past k.
    while (lo < hi) {
      const mid = (lo + hi) >> 1;
      const m = this.moves[mid]!;
      if (m.firstStep + m.steps <= k) lo = mid + 1;
      else hi = mid;
    }
    return lo;
  }

  /** The 1-based source line that produced step index k. */
  lineOfStep(k: number): number {
    return this.moves[this.moveOfStep(k)]!.line;
  }

  /** Source lines of step indices from..to: lineByStep[i] produced step from + i. */
  lineByStepInRange(from: number, to: number): Uint32Array {
    if (!Number.isInteger(from) || !Number.isInteger(to) || from < 0 || to < from || to > this.steps) {
      throw new RangeError(`step indices ${from}..${to} are outside 0..${this.steps}`);
    }
    const out = new Uint32Array(to - from);
    if (from === to) return out;
    for (let i = this.moveOfStep(from), k = from; k < to; i++) {
      const m = this.moves[i]!;
      const end = Math.min(to, m.firstStep + m.steps);
      out.fill(m.line, k - from, end - from);
      k = Math.max(k, end);
    }
    return out;
  }

  /** The move programmed on a 1-based source line, if that line moved. */
  moveAtLine(line: number): GcodeMove | undefined {
    this.#moveByLine ??= new Map(this.moves.map((m, i) => [m.line, i]));
    const i = this.#moveByLine.get(line);
    return i === undefined ? undefined : this.moves[i];
  }

  /**
   * The point index where the machine is when `line` starts: every move of
   * an earlier line done. For an editor cursor on a line without a move.
   */
  pointBeforeLine(line: number): number {
    const next = this.moves.find((m) => m.line >= line);
    return next === undefined ? this.steps : next.firstStep;
  }

  /**
   * When each step index from..to happens, seconds from the program's start:
   * step k of a move of n steps when the planned position reaches (k + 1) / n
   * of the move's length. Computed in the core on demand, never stored.
   */
  stepTimes(from: number, to: number): Float64Array {
    return callCore(() => this.#result.stepTimes(from, to));
  }

  /**
   * The planned speed over time: (seconds, mm/s) pairs, flat, four per
   * planner block (start, end of acceleration, start of deceleration, end);
   * an arc has one block per chord (Grbl's mc_arc).
   */
  speedProfile(): Float64Array {
    return this.#result.speedProfile();
  }

  /**
   * The STEP and DIR wires of every axis as an IEEE 1364 Value Change Dump
   * (ASCII; timescale 1 ns): STEP rises at each step's instant and falls 10 µs
   * later (Grbl's default pulse), DIR is 1 while the axis runs negative. Opens
   * in PulseView, GTKWave or sigrok as a logic-analyser capture.
   */
  vcd(): Uint8Array {
    return callCore(this.#vcd);
  }

  /** Releases the core's memory of the trace and the plan now. */
  free(): void {
    this.trace.free();
    this.#result.free();
  }
}

/** Options of runGcode. */
export interface RunGcodeOptions {
  /** Called after every slice, and once at the end with done = true. */
  onProgress?: (progress: GcodeProgress) => void;
  /** Stops the run between slices; runGcode then rejects with the signal's reason. */
  signal?: AbortSignal;
  /** Time one slice aims at, ms (default 20): the core adapts the lines per slice to it. */
  sliceMs?: number;
}

const yieldToEventLoop = () => new Promise<void>((resolve) => setTimeout(resolve, 0));

/**
 * Parses and runs a G-code program. Bad settings reject with a VoxpathError
 * naming the setting; errors in the program do not reject: they are in
 * `errors`, and the trace holds the moves before the first of them.
 */
export async function runGcode(source: string, settings: GcodeSettings, options: RunGcodeOptions = {}): Promise<GcodeProgram> {
  const core = await loadCore();
  const run = callCore(() => new core.GcodeRun(source, encodeRequest(settings)));
  const sliceMs = options.sliceMs ?? 20;
  let finished = false;
  try {
    let lines = 256;
    for (;;) {
      options.signal?.throwIfAborted();
      const started = performance.now();
      const progress = JSON.parse(run.advance(lines)) as GcodeProgress;
      const elapsed = performance.now() - started;
      options.onProgress?.(progress);
      if (progress.done) break;
      // Aim the next slice at sliceMs, growing at most 4 times per slice.
      lines = Math.max(16, Math.min(lines * 4, Math.round((lines * sliceMs) / Math.max(elapsed, 0.5))));
      await yieldToEventLoop();
    }
    finished = true;
    const result = run.finish();
    try {
      const info = JSON.parse(result.programJson()) as GcodeProgramInfo;
      const handle = callCore(() => result.takeTrace());
      return new GcodeProgram(info, new Trace(handle), result, () => core.gcodeVcd(handle, result));
    } catch (error) {
      result.free();
      throw error;
    }
  } finally {
    // finish() consumes the run; free it only when it was not reached.
    if (!finished) run.free();
  }
}
