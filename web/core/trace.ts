/**
 * The headless API: `await trace(options)` runs an algorithm in the wasm core
 * and returns a Trace: the steps recorded, nothing else computed until it is
 * read. Points, deviations and axis errors are filled by the core into the
 * array returned; decision columns are copied out of wasm memory in chunks
 * of about CHUNK_BYTES.
 * Either way a long path never needs a second full-size copy inside wasm
 * (whose memory, once grown, is never given back).
 */
import type { Comparison, TraceDifference } from './compare.js';
import { callCore, VoxpathError } from './errors.js';
import { argumentError, describeValue, indexRange, wholeNumber } from './guard.js';
import type { StepClocks, TraceHandle } from './pkg/voxpath.js';
import { encodeRequest } from './request.js';
import { catalogue } from './catalogue.js';
import { advanceInSlices, checkSliceOptions, freeStopped, type SliceOptions, type SliceSizes, yieldToEventLoop } from './slices.js';
import type { AlgorithmInfo, ChartSeries, ColumnSpec, DecisionColumns, DeviationBound, FigureKind, IdealLine, Metrics, PointBounds, PointsProgress, SegmentInfo, StepDetail, TraceLegend, TraceOptions, TraceSummary } from './types.js';
import { loadCore } from './wasm.js';

/**
 * Bytes of decision columns copied out of wasm per call. Each call's array
 * is built in wasm memory before JS copies it, so this bounds what reading
 * adds to the core's memory: 256 KiB, against 2 bytes per step for the
 * trace itself.
 */
const CHUNK_BYTES = 1 << 18;

/** Steps per call for rows of `bytesPerRow` bytes. */
function chunkRows(bytesPerRow: number): number {
  return Math.max(1, Math.floor(CHUNK_BYTES / bytesPerRow));
}

type TypedArrayOf<T> = {
  new (length: number): T;
  new (buffer: ArrayBuffer, byteOffset: number, length: number): T;
  BYTES_PER_ELEMENT: number;
};

/**
 * Points the first slice of a pass over the points measures, and the
 * fewest any does (advanceInSlices): a helix's point took about 0.6 µs to
 * measure in a browser's worker, a line's 0.05 µs.
 */
const POINT_SLICES: SliceSizes = { first: 16_384, least: 1024 };

/** Options of the passes over a trace's points made in slices (metricsInSlices, chartSeriesInSlices): onProgress gets each slice's PointsProgress. */
export type PointsPassOptions = SliceOptions<PointsProgress>;

/** Arrays smaller than this are made as usual: zeroing them costs nothing measurable. */
const SMALLEST_UNZEROED_BYTES = 1 << 20;

/**
 * A typed array of `length` values that the caller overwrites whole before
 * anyone sees it, its memory not zeroed first where the runtime allows: in
 * Node, Buffer.allocUnsafeSlow (an ArrayBuffer of its own, outside Buffer's
 * shared pool) skips the allocator's zero fill, which for the 24 MB of a
 * 2,000,000-point 3D line cost as much as copying the points in (0.85 of
 * 1.7 ms, measured with the memory reused after a collection). In a
 * browser, for small arrays, and past Node's largest Buffer (4 GiB, which
 * a typed array may pass: the points of a 1,000,000,000-step line, 12 GB,
 * were a RangeError on the Buffer's "size"), a plain typed array. One
 * longer than the runtime makes (or has memory for) is the VoxpathError
 * `refused` makes of what was too long ("N values (B bytes) are more than
 * one Float64Array can hold here (...)"): it names what the array was for,
 * the argument that asked for it (readInRanges) or the whole it holds.
 */
export function forOverwrite<T extends Int32Array | Float32Array | Float64Array>(Kind: TypedArrayOf<T>, length: number, refused: (detail: string) => VoxpathError): T {
  const bytes = length * Kind.BYTES_PER_ELEMENT;
  const nodeBuffer = (globalThis as { Buffer?: { allocUnsafeSlow(size: number): Uint8Array } }).Buffer;
  if (nodeBuffer !== undefined && bytes >= SMALLEST_UNZEROED_BYTES) {
    try {
      const memory = nodeBuffer.allocUnsafeSlow(bytes);
      return new Kind(memory.buffer as ArrayBuffer, memory.byteOffset, length);
    } catch (error) {
      if (!(error instanceof RangeError)) throw error;
    }
  }
  try {
    return new Kind(length);
  } catch (error) {
    if (!(error instanceof RangeError)) throw error;
    throw refused(`${length} values (${bytes} bytes) are more than one ${Kind.name} can hold here (${error.message})`);
  }
}

/** forOverwrite's refusal of a range of a trace too long to read at once: `to` names its end. */
export function readInRanges(detail: string): VoxpathError {
  return argumentError('to', `${detail}: read them a range at a time`);
}

/**
 * The core's trace behind `trace`, `field` naming the argument it came in
 * as; a VoxpathError when it is not a Trace, or has been freed (the core
 * would read a null pointer). Set by Trace's static block, the one place
 * that may read a Trace's handle.
 */
let handleOf: (field: string, trace: unknown) => TraceHandle;

/** Throws a VoxpathError naming `field` unless `trace` is a Trace not yet freed (for functions that take one). */
export function requireTrace(field: string, trace: unknown): asserts trace is Trace {
  handleOf(field, trace);
}

/**
 * A finished trace: its summary's fields (the core's TraceSummary, declared
 * once in Rust), its legend's (TraceLegend: columns, figures,
 * deviationBound) and the per-step arrays, each read on demand. Point index
 * k runs 0..=steps, step index k runs 0..steps-1.
 */
// The class takes the summary's fields from the interface of the same name.
export interface Trace extends Readonly<TraceSummary> {}
export class Trace {
  /** The core's trace; undefined once freed. */
  #handle?: TraceHandle;
  #points?: Int32Array;
  #decisions?: DecisionColumns;
  #deviation?: Float64Array;
  #axisError?: Float64Array;
  #metrics?: Metrics;
  #legend?: TraceLegend;
  #bounds?: PointBounds;
  #segments?: SegmentInfo[];

  static {
    handleOf = (field, trace) => {
      if (typeof trace !== 'object' || trace === null || !(#handle in trace)) {
        throw argumentError(field, `expected a Trace (from trace() or runGcode()), got ${describeValue(trace)}`);
      }
      if (trace.#handle === undefined) throw argumentError(field, 'this trace was freed (free()); trace it again to read it');
      return trace.#handle;
    };
  }

  constructor(handle: TraceHandle) {
    this.#handle = handle;
    Object.assign(this, handle.summary());
  }

  /**
   * Whole-path statistics (deviation, per-axis error, ties, pulses),
   * computed by the core on first read: a pass over every point that
   * `trace()` does not make, so a caller that only wants points never pays
   * for it. Not one of the summary's fields: spreading a Trace leaves it out.
   */
  get metrics(): Metrics {
    if (this.#metrics === undefined) {
      const core = this.#core;
      this.#metrics = callCore(() => core.metrics());
    }
    return this.#metrics;
  }

  /**
   * The metrics, made by the core a slice of points at a time, the event
   * loop let run between slices: `onProgress` hears after each, and
   * `signal` stops the pass between them (a helix's 1,500,000 points took
   * 1 to 2 s in one call, which a worker could neither report nor stop).
   * The same values as `metrics`, to the bit. A pass stopped is taken up
   * where it stopped by the next call (or by `metrics`).
   */
  async metricsInSlices(runOptions: PointsPassOptions = {}): Promise<Metrics> {
    const sliceMs = checkSliceOptions('metricsInSlices', runOptions);
    await this.#inSlices((core, points) => core.advanceMetrics(points), runOptions, sliceMs);
    return this.metrics;
  }

  /**
   * Runs the core's pass `advance` to its end in slices (advanceInSlices),
   * the trace checked before each (a VoxpathError once freed); a cancel
   * sent while the last slice ran is still honoured.
   */
  async #inSlices(advance: (core: TraceHandle, points: number) => PointsProgress, runOptions: PointsPassOptions, sliceMs: number): Promise<void> {
    await advanceInSlices(
      (points) => {
        const core = this.#core;
        return callCore(() => advance(core, points));
      },
      runOptions,
      sliceMs,
      POINT_SLICES,
    );
    await yieldToEventLoop();
    runOptions.signal?.throwIfAborted();
  }

  /**
   * How to read the decisions (their columns, the pictures they can have)
   * and the bound the deviation keeps, fetched from the core on first read:
   * 2 to 3 KB of teaching text a trace, which a caller that reads points
   * alone need not wait for (it made a small `trace()` after a collection
   * 0.28 ms where it is 0.25 ms without).
   * Not one of the summary's fields: `{ ...trace, ...trace.legend }` has
   * them all.
   */
  get legend(): TraceLegend {
    if (this.#legend === undefined) {
      const core = this.#core;
      this.#legend = callCore(() => core.legend());
    }
    return this.#legend;
  }

  /** The decision columns, in the order the decisions hold them (the legend's). */
  get columns(): ColumnSpec[] {
    return this.legend.columns;
  }

  /** The pictures the steps' decisions can have (the legend's); a step's own is in its StepDetail. */
  get figures(): FigureKind[] {
    return this.legend.figures;
  }

  /** The bound every point's deviation keeps, null where the algorithm promises none (the legend's). */
  get deviationBound(): DeviationBound | null {
    return this.legend.deviationBound;
  }

  /**
   * The box every point lies in (min and max per axis, grid units), made by
   * the core on first read from the steps: a view framing the path reads it
   * rather than scanning the points itself. Not one of the summary's fields.
   */
  get bounds(): PointBounds {
    if (this.#bounds === undefined) {
      const core = this.#core;
      this.#bounds = callCore(() => core.bounds());
    }
    return this.#bounds;
  }

  /**
   * The stretches of the path, each by one stepper against one ideal path
   * (a line; a chord of an arc; a G-code move), with a note for a learner,
   * in step order; fetched from the core on first read (an arc in chords
   * or a G-code program has thousands). Not one of the summary's fields.
   */
  get segments(): SegmentInfo[] {
    if (this.#segments === undefined) {
      const core = this.#core;
      this.#segments = callCore(() => core.segments());
    }
    return this.#segments;
  }

  /** All points, flat with stride dims: point k is at [k * dims, (k + 1) * dims). */
  get points(): Int32Array {
    this.#points ??= this.pointsInRange(0, this.steps + 1);
    return this.#points;
  }

  /** This trace's handle in the core (a VoxpathError once freed). */
  get #core(): TraceHandle {
    return handleOf('trace', this);
  }

  /**
   * Points with point indices from..to, flat with stride dims: decoded by
   * the core a chunk at a time straight into the array returned (its wasm
   * memory grows by one chunk's buffer, not by the points). With `every`
   * above 1, every every-th of them only (point indices from, from + every,
   * ... below to): a view drawing a long path by a sample of its cells reads
   * those alone.
   */
  pointsInRange(from: number, to: number, every = 1): Int32Array {
    const core = this.#core;
    [from, to] = indexRange(from, to, this.steps + 1, 'point index');
    wholeNumber('every', every, 1, 2 ** 32 - 1, 'every (points apart)');
    const out = forOverwrite(Int32Array, Math.ceil((to - from) / every) * this.dims, readInRanges);
    callCore(() => core.points(from, to, every, out));
    return out;
  }

  /** Point index k as an array of coordinates. */
  point(k: number): number[] {
    wholeNumber('k', k, 0, this.steps, 'point index');
    return Array.from(this.pointsInRange(k, k + 1));
  }

  /**
   * Every decision column over all steps: decisions[name][k] produced
   * points[k + 1]. Computed on first use; for long traces prefer
   * decisionsInRange, which costs memory for the range only.
   */
  get decisions(): DecisionColumns {
    this.#decisions ??= this.decisionsInRange(0, this.steps);
    return this.#decisions;
  }

  /**
   * Decision columns for step indices from..to, recomputed exactly by the
   * core. Category and flag columns are Uint8Array (category values index the
   * column's labels; NO_VALUE where a column does not apply to a step);
   * numeric columns are Float64Array (NaN where it does not apply).
   * `readDecision` turns a value into what people read. A renamed column
   * still answers to its former name (`ColumnSpec.formerName`), deprecated:
   * see answerFormerName.
   */
  decisionsInRange(from: number, to: number): DecisionColumns {
    const core = this.#core;
    [from, to] = indexRange(from, to, this.steps, 'step index');
    const out: DecisionColumns = {};
    for (const c of this.columns) {
      out[c.name] = c.kind === 'category' || c.kind === 'flag' ? new Uint8Array(to - from) : new Float64Array(to - from);
    }
    const rows = chunkRows(Float64Array.BYTES_PER_ELEMENT * Math.max(1, this.columns.length));
    for (let k = from; k < to; k += rows) {
      const end = Math.min(to, k + rows);
      const flat = callCore(() => core.decisions(k, end));
      this.columns.forEach((c, i) => {
        out[c.name]!.set(flat.subarray(i * (end - k), (i + 1) * (end - k)), k - from);
      });
    }
    for (const c of this.columns) if (c.formerName !== undefined) answerFormerName(out, c.formerName, c.name);
    return out;
  }

  /** Distance of every point from the ideal path (grid units); deviation[k] belongs to points[k]. */
  get deviation(): Float64Array {
    this.#deviation ??= this.deviationInRange(0, this.steps + 1);
    return this.#deviation;
  }

  /**
   * The deviation of points from..to, written by the core straight into
   * the array returned (a buffer of wasm memory at a time, one copy).
   */
  deviationInRange(from: number, to: number): Float64Array {
    const core = this.#core;
    [from, to] = indexRange(from, to, this.steps + 1, 'point index');
    const out = forOverwrite(Float64Array, to - from, readInRanges);
    callCore(() => core.deviation(from, to, out));
    return out;
  }

  /** Per-axis error of every point (Wang eq. 11), flat with stride dims. */
  get axisError(): Float64Array {
    this.#axisError ??= this.axisErrorInRange(0, this.steps + 1);
    return this.#axisError;
  }

  /** The axis errors of points from..to, stride dims, made as deviationInRange makes its values. */
  axisErrorInRange(from: number, to: number): Float64Array {
    const core = this.#core;
    [from, to] = indexRange(from, to, this.steps + 1, 'point index');
    const out = forOverwrite(Float64Array, (to - from) * this.dims, readInRanges);
    callCore(() => core.axisError(from, to, out));
    return out;
  }

  /**
   * Packed steps of step indices from..to: bit a set when axis a moves, bit
   * 8 + a set when it moves in the negative direction (a step/direction pulse
   * pair per axis).
   */
  stepCodes(from: number, to: number): Uint16Array {
    const core = this.#core;
    [from, to] = indexRange(from, to, this.steps, 'step index');
    return callCore(() => core.stepCodes(from, to));
  }

  /**
   * DIR line levels of step indices from..to: bit a set while axis a's DIR is
   * at its negative level. An axis keeps its level between its moves and
   * starts positive; with stepCodes this is the step/direction signal pair.
   */
  directionLevels(from: number, to: number): Uint8Array {
    const core = this.#core;
    [from, to] = indexRange(from, to, this.steps, 'step index');
    return callCore(() => core.directionLevels(from, to));
  }

  /** One plain sentence: why step index k was taken. */
  explain(step: number): string {
    const core = this.#core;
    wholeNumber('step', step, 0, this.steps - 1, 'step index');
    return callCore(() => core.explain(step));
  }

  /**
   * Point index p and the step that produced it (step index p - 1; none
   * at p = 0): the point, its deviation, the decision with every value read,
   * the explanation, the segment and its note, and the picture of the
   * decision (StepDetail), from one replay of that step in the core.
   */
  stepDetail(pointIndex: number): StepDetail {
    const core = this.#core;
    wholeNumber('pointIndex', pointIndex, 0, this.steps, 'point index');
    return callCore(() => core.stepDetail(pointIndex));
  }

  /**
   * A chart's rows of point indices from..to (all points by default), at
   * most maxRows of them: every point, or buckets of consecutive points
   * (ChartSeries). One pass of the core over the range.
   */
  chartSeries(maxRows: number, from = 0, to = this.steps + 1): ChartSeries {
    const core = this.#core;
    [from, to] = indexRange(from, to, this.steps + 1, 'point index');
    wholeNumber('maxRows', maxRows, 1, 2 ** 32 - 1, 'maxRows');
    return this.#series(
      callCore(() => core.chartRows(from, to, maxRows)),
      from,
      to,
    );
  }

  /**
   * chartSeries over every point, made by the core a slice of points (of
   * whole buckets) at a time, as metricsInSlices makes the metrics: the
   * same rows, to the bit.
   */
  async chartSeriesInSlices(maxRows: number, runOptions: PointsPassOptions = {}): Promise<ChartSeries> {
    wholeNumber('maxRows', maxRows, 1, 2 ** 32 - 1, 'maxRows');
    const sliceMs = checkSliceOptions('chartSeriesInSlices', runOptions);
    const to = this.steps + 1;
    await this.#inSlices((core, points) => core.advanceChartRows(0, to, maxRows, points), runOptions, sliceMs);
    const core = this.#core;
    return this.#series(
      callCore(() => core.takeChartRows(0, to, maxRows)),
      0,
      to,
    );
  }

  /** The core's chart rows of points from..to as a ChartSeries. */
  #series(flat: Float64Array, from: number, to: number): ChartSeries {
    // Column-major: the point index, dims positions, dims ideal positions, largest and smallest deviation.
    const rows = flat.length / (3 + 2 * this.dims);
    const column = (c: number) => flat.slice(c * rows, (c + 1) * rows);
    const axes = Array.from({ length: this.dims }, (_, a) => a);
    return {
      pointIndex: column(0),
      position: axes.map((a) => column(1 + a)),
      ideal: axes.map((a) => column(1 + this.dims + a)),
      deviationMax: column(1 + 2 * this.dims),
      deviationMin: column(2 + 2 * this.dims),
      bucketed: rows < to - from,
    };
  }

  /**
   * This trace (a) against `other` (b), with the same number of axes: what
   * `compare()` returns for two algorithms, for traces already computed.
   */
  compareWith(other: Trace): Comparison {
    const core = this.#core;
    const theirs = handleOf('other', other);
    return callCore(() => core.compareWith(theirs));
  }

  /**
   * Every cell this trace visits and `other` never does, in this trace's
   * order, each once, flat with stride dims (`compareWith` lists only the
   * first 1000).
   */
  cellsOnlyIn(other: Trace): Int32Array {
    const core = this.#core;
    const theirs = handleOf('other', other);
    return callCore(() => core.cellsOnlyIn(theirs));
  }

  /**
   * Where this trace (a) and `other` (b), of one move, differ as a view
   * shows them: the first point where they part (compareWith's) and every
   * cell only one visits (cellsOnlyIn, both ways), each trace's cells
   * sorted once (those two calls sort each three times), one trace's at a
   * time, the event loop let run between them: `onProgress` hears the
   * points sorted, and `signal` stops it between the two.
   */
  async differenceWith(other: Trace, runOptions: PointsPassOptions = {}): Promise<TraceDifference> {
    const sliceMs = checkSliceOptions('differenceWith', runOptions);
    const both = (): [TraceHandle, TraceHandle] => [this.#core, handleOf('other', other)];
    const core = await loadCore();
    const run = callCore(() => new core.DifferenceRun(...both()));
    let difference: TraceDifference;
    try {
      // One trace's cells a slice, however many: a sort is not cut.
      await advanceInSlices(() => callCore(() => run.advance(...both())), runOptions, sliceMs, { first: 1, least: 1 });
      await yieldToEventLoop();
      runOptions.signal?.throwIfAborted();
      const [a, b] = both();
      difference = callCore(() => ({ firstDifference: run.firstDifference(a, b), onlyInA: run.cellsOnlyIn(0, a, b), onlyInB: run.cellsOnlyIn(1, a, b) }));
    } catch (error) {
      freeStopped(run);
      throw error;
    }
    run.free();
    return difference;
  }

  /**
   * The tool's speed per step under two clocks, as at most maxRows chart
   * rows: one tick per step (√m cells per tick for a step moving m axes)
   * and a constant feed of 1 cell per tick (a step takes √m ticks).
   */
  stepClocks(maxRows: number): StepClocks {
    const core = this.#core;
    wholeNumber('maxRows', maxRows, 1, 2 ** 32 - 1, 'maxRows');
    return callCore(() => core.stepClocks(maxRows));
  }

  /** The ideal path as a polyline for drawing, flat with stride dims. */
  idealPolyline(): Float64Array {
    return this.#core.idealPolyline();
  }

  /**
   * The ideal polyline as WebGL draws it: each vertex's x, y, z less the
   * path's start (its origin) rounded to a 32-bit float, with the box they
   * lie in and what the rounding left. Converted and boxed by the core in
   * the pass that makes the vertices, and copied out of it once, into an
   * array of their length.
   */
  idealLine(): IdealLine {
    const origin: [number, number, number] = [this.start[0] ?? 0, this.start[1] ?? 0, this.start[2] ?? 0];
    const line = this.#core.idealLine(...origin);
    try {
      // The core's layout (IdealLineHandle.copyInto): x, y, z of every
      // vertex, then as many rests.
      const values = 3 * line.vertices;
      // Not an argument's fault, and there is no range of it to read instead: said as the line's.
      const flat = forOverwrite(Float32Array, 2 * values, (detail) => new VoxpathError(`the ideal line of ${line.vertices} vertices (x, y, z and what rounding left of each): ${detail}`));
      callCore(() => line.copyInto(flat));
      const [minX, minY, minZ, maxX, maxY, maxZ] = line.bounds();
      return { xyz: flat.subarray(0, values), rest: flat.subarray(values), min: [minX!, minY!, minZ!], max: [maxX!, maxY!, maxZ!], origin };
    } finally {
      line.free();
    }
  }

  /**
   * Releases the core's memory now instead of at garbage collection. Reading
   * the trace afterwards is a VoxpathError, except for what its getters
   * (points, decisions, deviation, axisError, metrics, bounds, segments)
   * returned before, which they keep returning: those live in JavaScript.
   * Freeing it again does nothing.
   */
  free(): void {
    this.#handle?.free();
    this.#handle = undefined;
  }
}

/** Runs one trace; rejects with a VoxpathError naming the option at fault. */
export async function trace(options: TraceOptions): Promise<Trace> {
  const core = await loadCore();
  const request = encodeRequest(options);
  return new Trace(callCore(() => core.trace(request)));
}

/** Every algorithm voxpath runs, with citation, teaching text, columns and options. */
export async function algorithms(): Promise<AlgorithmInfo[]> {
  return (await catalogue()).algorithms;
}

/**
 * Lets `decisions[formerName]` read the column now called `name`: a column
 * renamed after 0.1.0 (face_u -> faceU, ...) answers to its old name through
 * the 0.2 releases; 0.3.0 drops these aliases (README, Conventions).
 * Deprecated.
 * Not enumerable, so Object.keys, JSON and the CSV and JSON writers show the
 * new name only.
 */
function answerFormerName(decisions: DecisionColumns, formerName: string, name: string): void {
  Object.defineProperty(decisions, formerName, { get: () => decisions[name], enumerable: false, configurable: true });
}
