/**
 * Messages between the page (main thread) and the trace worker, which owns
 * every Trace (and G-code program) and is the page's only user of the wasm
 * core.
 *
 * Each request carries an id; the worker answers each with exactly one reply
 * carrying the same id, and a long request (a G-code run, the random-lines
 * experiment, an export, a trace's metrics, a chart's rows, a difference) may send
 * progress messages with that id before it. A `cancel` message stops the request it
 * names at its next slice. Bulk arrays cross as transferred buffers, not
 * copies:
 * - a G-code program's text: UTF-8 bytes, encoded by the page (in the
 *   worker, a 2.4 MB program took 7 to 12 ms to take as a string and encode
 *   into wasm memory, against 2.3 ms to encode on the page and a copy into
 *   wasm memory in the worker);
 * - points: Int32Array, stride dims: a path's whole, or every n-th point of
 *   a long one, which is all the page draws of it (PointsSent), the points
 *   near the one it shows asked for by range ('points');
 * - idealLine: the core's ideal polyline as the scene draws it (IdealLine:
 *   x, y, z as 32-bit floats, and its box; Trace.idealLine());
 * - bounds: the core's PointBounds of the points (min and max per axis);
 * - series: see ChartSeries; cells: Int32Array, stride dims;
 * - step instants: Float64Array, seconds, one per step index of the range;
 * - motion charts and step clocks: rows bounded by what the page asks for
 *   (about a chart's width in pixels), however long the program.
 * What the page shows of one point (the inspector, the decision's figure
 * and its 3D overlay) is one request, stepDetail, answered with the core's
 * StepDetail.
 */
import type { Check, CheckProgress, ExperimentProgress, GcodeMove, GcodeProgramInfo, GcodeProgress, GcodeSettings, MotionChart, PulseTrain, RandomLinesOptions, RandomLinesResult, TraceDifference } from '../core/index.js';
import type { Catalogue, ChartSeries, IdealLine, Limit, Metrics, PointBounds, PointsProgress, StepClocks, StepDetail, TraceLegend, TraceOptions, TraceSummary } from '../core/types.js';

/** What the worker can be asked. `traceId` is chosen by the page and names a trace the worker holds. */
export type WorkerRequest =
  | { kind: 'catalogue' }
  | { kind: 'trace'; traceId: number; options: TraceOptions; pointsSent: PointsSent }
  | { kind: 'gcode'; traceId: number; source: Uint8Array; settings: GcodeSettings; pointsSent: PointsSent }
  | { kind: 'points'; traceId: number; fromPoint: number; toPoint: number }
  | { kind: 'stepDetail'; traceId: number; pointIndex: number }
  | { kind: 'series'; traceId: number; maxPoints: number }
  | { kind: 'difference'; traceIdA: number; traceIdB: number }
  | { kind: 'pulses'; traceId: number; fromStep: number; toStep: number }
  | { kind: 'stepClocks'; traceId: number; maxRows: number }
  | { kind: 'stepTimes'; traceId: number; fromStep: number; toStep: number }
  | { kind: 'pointAtSeconds'; traceId: number; seconds: number }
  | { kind: 'dwellSeconds'; traceId: number; fromSeconds: number; toSeconds: number }
  | { kind: 'motionChart'; traceId: number; fromSeconds: number; toSeconds: number; buckets: number }
  | { kind: 'moves'; traceId: number; fromMove: number; toMove: number }
  | { kind: 'moveOfStep'; traceId: number; stepIndex: number }
  | { kind: 'lineSteps'; traceId: number; line: number }
  | { kind: 'export'; traceId: number; format: ExportFormat }
  | { kind: 'randomLines'; options: RandomLinesOptions }
  | { kind: 'check'; traceId: number; options: TraceOptions; text: string; pointsSent: PointsSent }
  | { kind: 'free'; traceId: number };

export type RequestKind = WorkerRequest['kind'];

/**
 * The trace id a successful reply to `request` leaves the worker holding (a
 * trace, or a program and its trace) until the page frees it; undefined
 * when the worker keeps nothing of it. A request kind that keeps something
 * must say so here: the client frees it when the page had cancelled the
 * request before its reply came.
 */
export function traceIdHeldAfter(request: WorkerRequest): number | undefined {
  return request.kind === 'trace' || request.kind === 'gcode' ? request.traceId : undefined;
}

/**
 * What the page receives of every trace besides its arrays: its summary and
 * its legend (the page shows the columns and the deviation's bound of each).
 */
export type TraceFields = TraceSummary & TraceLegend;

/**
 * The summary the page receives: the trace's fields, with its metrics. Not its
 * segments: a G-code program has a segment per move (100,000 for a program
 * of 100,000 lines), which the page would take a long task to receive; the
 * segment of the point it shows comes with that point's StepDetail instead.
 */
export type PathSummary = TraceFields & { metrics: Metrics };

/**
 * Which of a path's points come with it. A path of fewer than `allBelow`
 * points comes whole: the view draws every cell. A longer one comes as
 * every n-th point, n = ceil(points / sampled), at most `sampled` of them:
 * the view draws those as points, framed far out, and asks for the cells it
 * draws as cubes (those near the point shown) by range. At 80 steps/mm the
 * G-code bench's program has 5.5 million points, 66 MB the page would
 * receive, each byte of it in fresh memory, to draw 20,000 of them.
 * A check's points come whole (the page holds no trace of them to ask
 * ranges of); `allBelow` decides whether their line comes too (LearnerCheck).
 */
export interface PointsSent {
  allBelow: number;
  sampled: number;
}

/** Points apart of the points sent of a path of `points` points (1: all of them). */
export function pointsEvery(points: number, sent: PointsSent): number {
  return points < sent.allBelow ? 1 : Math.max(1, Math.ceil(points / sent.sampled));
}

/**
 * A finished trace as the page receives it: the summary (a trace's with its
 * metrics, by default) and the arrays every view needs at once.
 */
export interface TracedPath<Summary extends TraceFields = PathSummary> {
  summary: Summary;
  /** Point indices 0, pointsEvery, 2 · pointsEvery, ... (every point when pointsEvery is 1), flat with stride dims. */
  sampledPoints: Int32Array;
  pointsEvery: number;
  idealLine: IdealLine;
  /** The box every point lies in, as the core found it (the view frames the path with it). */
  bounds: PointBounds;
}

/** Where two traces of the same move part, as the core finds them (Trace.differenceWith). */
export type { TraceDifference };

/**
 * The program's record as the page receives it: the core's, which counts the
 * moves (the page asks for them by range).
 */
export type ProgramRecord = GcodeProgramInfo;

/**
 * A G-code run as the page receives it: the trace's summary and arrays and
 * the program's record. Not its metrics: for a program they make each of
 * its segments again (one per move) and replay it for its ties, several
 * times the run's own time, and no view of a program shows them.
 */
export interface RunProgram extends TracedPath<TraceFields> {
  program: ProgramRecord;
}

/** Step indices a source line produced (its move), and where the machine is when the line starts. */
export interface LineSteps {
  /** Step indices firstStep..firstStep + steps; steps is 0 for a line without a move. */
  firstStep: number;
  steps: number;
  /** The point index where the machine is when the line starts (GcodeProgram.pointBeforeLine). */
  pointBefore: number;
}


/** The signals of a window of steps for the timing diagram. */
export interface PulseWindow {
  /** The core's pulseTrains over the range, one per axis (with edgeSeconds and rateHz for a program). */
  trains: PulseTrain[];
  /** A program's step instants over the range, seconds, on its planned profile; null for a trace (one tick per step). */
  stepSeconds: Float64Array | null;
}

/** A learner's points checked against the rule of a trace (readAndCheckPoints: the text read once, as the check's first stage). */
export interface LearnerCheck {
  check: Check;
  /** The learner's points as read, flat with stride dims, to draw: readAndCheckPoints' own; null when a coordinate is past what the view draws (int32). */
  points: Int32Array | null;
  /** The box every point lies in (null with the points): the view frames and culls their cells by it, and decides with it how to draw them. */
  bounds: PointBounds | null;
  /**
   * The line through the points' cell centers, as the view draws it when it
   * draws every cell as a cube (drawnLight in web/scene/light-drawing.ts,
   * with the request's PointsSent.allBelow): made by the worker, since on
   * the main thread it took 18 to 39 ms of showing 200,000 points. Null with
   * the points, and for a path drawn the lighter way, whose line is drawn
   * through the cells near the current one only, made with their cubes
   * (PathStyle.centers in web/scene/voxel-path.ts): at the page's cap,
   * 1,498,841 points, this line was 36 MB made and sent for nothing.
   */
  centers: IdealLine | null;
  dims: number;
}

/** The value a successful reply carries, by request kind. */
export interface ReplyValue {
  catalogue: Catalogue;
  trace: TracedPath;
  gcode: RunProgram;
  stepDetail: StepDetail;
  /** Points fromPoint..toPoint, flat with stride dims. */
  points: Int32Array;
  series: ChartSeries;
  difference: TraceDifference;
  pulses: PulseWindow;
  stepClocks: StepClocks;
  /** A program's step instants over the range, seconds (GcodeProgram.stepTimes). */
  stepTimes: Float64Array;
  pointAtSeconds: number;
  /** Seconds of G4 dwell between two instants (GcodeProgram.dwellSeconds). */
  dwellSeconds: number;
  motionChart: MotionChart;
  moves: GcodeMove[];
  moveOfStep: { moveIndex: number; line: number };
  lineSteps: LineSteps;
  /** The file, made in the worker: it never passes through the page's thread as one string (a program's CSV is past the longest string a browser holds). */
  export: Blob;
  randomLines: RandomLinesResult;
  check: LearnerCheck;
  free: null;
}

/** An input the core rejected; `field` names the option at fault and `limit` the cap it ran into (as in VoxpathError). */
export interface InputError {
  field?: string;
  message: string;
  limit?: Limit;
}

export type RequestMessage = { id: number; request: WorkerRequest } | { id: number; cancel: true };

/**
 * A reply. Failures come in four kinds, because the page reacts differently:
 * - input: the core rejected the input; the form shows it next to the field;
 * - crash: the core trapped (a bug in the core); its memory can no longer be
 *   trusted, so the page replaces the worker;
 * - cancelled: the page cancelled the request;
 * - error: anything else (a bug in the page's request); the worker stays.
 * A progress message comes before the reply of a long request.
 */
export type ReplyMessage =
  | { id: number; ok: true; value: ReplyValue[RequestKind] }
  | { id: number; ok: false; failure: 'input'; error: InputError }
  | { id: number; ok: false; failure: 'crash' | 'error' | 'cancelled'; message: string }
  | { id: number; progress: ProgressValue[LongRequestKind] };

/**
 * A file the page saves: a trace's (or a program's) rows as the CLI writes
 * them (csv, json), or a program's STEP and DIR wires (vcd, GcodeProgram.vcdChunks).
 */
export type ExportFormat = 'csv' | 'json' | 'vcd';

/** How much of a file an export has written: its size is not known before its end. */
export interface ExportProgress {
  bytes: number;
  done: boolean;
}

/** What a long request reports after each slice of its work, by request kind. */
export interface ProgressValue {
  gcode: GcodeProgress;
  randomLines: ExperimentProgress;
  export: ExportProgress;
  /** The trace's metrics, measured a slice of points at a time (the trace itself is one call: a path the page takes, at most 1,500,000 steps, is traced in a fifth of a second). */
  trace: PointsProgress;
  /** The charts' rows, made a slice of points at a time. */
  series: PointsProgress;
  /** Where two paths differ: each path's cells sorted in turn (a sort of 1,500,000 cells took 0.2 to 0.3 s). */
  difference: PointsProgress;
  /** A learner's points checked (CheckRunProgress). */
  check: CheckRunProgress;
}

/**
 * How far a check of a learner's points has got: stage 'reading' with no
 * counts before the rule is traced; then the core's CheckProgress after
 * each slice (the text read, its bytes and points so far, then steps
 * compared, then the family's option combinations tried).
 */
export type CheckRunProgress = CheckProgress | { stage: 'reading'; done: false };

/** The requests that run in slices, report progress and can be cancelled. */
export type LongRequestKind = keyof ProgressValue;
