/**
 * The page's side of the trace worker: typed requests with ids, answered by
 * promises, and RemoteTrace, the main thread's view of a trace the worker holds
 * (the same shape as the core's Trace, with the replayed parts asynchronous).
 *
 * If the core crashes (a trap in wasm is a bug in the core) or the worker dies,
 * every pending request is rejected with CoreCrash, the listener is told, and
 * the next request starts a fresh worker: the page stays usable.
 */
import type { ExperimentProgress, GcodeMove, GcodeProgress, GcodeSettings, MotionChart, RandomLinesOptions, RandomLinesResult } from '../core/index.js';
import type { ChartSeries, IdealLine, PointBounds, PointsProgress, StepClocks, StepDetail, TraceOptions } from '../core/types.js';
import { utf8Bytes } from '../core/utf8.js';
import { traceIdHeldAfter } from './protocol.js';
import type {
  ExportFormat,
  ExportProgress,
  InputError,
  LearnerCheck,
  LineSteps,
  LongRequestKind,
  PathSummary,
  PointsSent,
  ProgramRecord,
  ProgressValue,
  PulseWindow,
  ReplyMessage,
  ReplyValue,
  RequestKind,
  RequestMessage,
  RunProgram,
  TraceDifference,
  TraceFields,
  TracedPath,
  WorkerRequest,
} from './protocol.js';

/** The core rejected an input; `field` names the option at fault. */
export class InputRejected extends Error implements InputError {
  override readonly name = 'InputRejected';
  readonly field?: string;
  readonly limit?: InputError['limit'];

  constructor(error: InputError) {
    super(error.message);
    this.field = error.field;
    this.limit = error.limit;
  }
}

/** The core or its worker died; the request may be retried on the fresh worker. */
export class CoreCrash extends Error {
  override readonly name = 'CoreCrash';
}

/** The page cancelled the request. */
export class Cancelled extends Error {
  override readonly name = 'Cancelled';
}

/** The part of a Worker the client uses, so tests can drive it with a fake. */
export interface WorkerPort {
  postMessage(message: RequestMessage, transfer?: Transferable[]): void;
  terminate(): void;
  onmessage: ((event: MessageEvent<ReplyMessage>) => void) | null;
  onerror: ((event: ErrorEvent) => void) | null;
}

interface Pending {
  resolve(value: ReplyValue[RequestKind]): void;
  reject(error: Error): void;
  onProgress?: (progress: ProgressValue[LongRequestKind]) => void;
  /** The trace the worker holds once it has answered (traceIdHeldAfter): freed when the answer comes after a cancel. */
  holds: number | undefined;
  /** The page cancelled it: its progress is dropped, and whatever the worker answers, it rejects with Cancelled. */
  cancelled: boolean;
}

/** A request under way that can be stopped. */
export interface Running<T> {
  result: Promise<T>;
  /**
   * Asks the worker to stop. Unless `result` had already settled, it then
   * rejects with Cancelled when the worker answers, even with a result made
   * before the cancel reached it (whose trace, if it holds one, is freed),
   * and no more progress is reported; a crash of the worker meanwhile still
   * rejects it with CoreCrash, as it does every request.
   */
  cancel(): void;
}

export class TraceClient {
  readonly #createWorker: () => WorkerPort;
  readonly #onCrash: (message: string) => void;
  readonly #pointsSent: () => PointsSent;
  #worker?: WorkerPort;
  /** Counts workers started, so a RemoteTrace can tell that its worker is gone. */
  #generation = 0;
  #nextId = 1;
  #nextTraceId = 1;
  readonly #pending = new Map<number, Pending>();
  /**
   * The program text last sent and its UTF-8 bytes: a program is often run
   * again as it is, at other machine settings, and a copy of its bytes
   * (0.3 ms for the G-code bench's 2.4 MB) costs less than encoding it again
   * (2 to 6 ms on the page's thread).
   */
  #lastProgram?: { text: string; bytes: Uint8Array };

  /** `pointsSent`: which of a path's points come with it (the rest are asked for by range), asked when a path or a check is: it depends on the page's WebGL, found once the view is made. */
  constructor(createWorker: () => WorkerPort, onCrash: (message: string) => void, pointsSent: () => PointsSent) {
    this.#pointsSent = pointsSent;
    this.#createWorker = createWorker;
    this.#onCrash = onCrash;
  }

  /** Worker incarnation; bumped on every crash. */
  get generation(): number {
    return this.#generation;
  }

  /**
   * The worker, started on first use. Started lazily rather than right after a
   * crash, so that a worker which cannot even load (say its script is missing)
   * fails once per user action instead of in a restart loop.
   */
  #port(): WorkerPort {
    if (!this.#worker) {
      const worker = this.#createWorker();
      worker.onmessage = (event) => this.#receive(worker, event.data);
      worker.onerror = (event) => {
        event.preventDefault?.();
        this.#crash(worker, `the trace worker failed: ${event.message || 'it could not start'}`);
      };
      this.#worker = worker;
    }
    return this.#worker;
  }

  #receive(worker: WorkerPort, reply: ReplyMessage): void {
    if (worker !== this.#worker) return;
    const pending = this.#pending.get(reply.id);
    if (!pending) return;
    if ('progress' in reply) {
      // After a cancel the page has taken the run as stopped: a report would show its bar again.
      if (!pending.cancelled) pending.onProgress?.(reply.progress);
      return;
    }
    this.#pending.delete(reply.id);
    if (pending.cancelled && (reply.ok || reply.failure === 'input' || reply.failure === 'error')) {
      // The worker had ended before the cancel reached it (its answer on
      // its way, or not yet handled by a busy main thread): the user pressed
      // Cancel, and is not shown it. Nothing else will hold what it left in
      // the worker.
      if (reply.ok && pending.holds !== undefined) this.freeTrace(pending.holds);
      pending.reject(new Cancelled('cancelled after the worker had answered'));
      return;
    }
    if (reply.ok) pending.resolve(reply.value);
    else if (reply.failure === 'input') pending.reject(new InputRejected(reply.error));
    else if (reply.failure === 'error') pending.reject(new Error(reply.message));
    else if (reply.failure === 'cancelled') pending.reject(new Cancelled(reply.message));
    else {
      pending.reject(new CoreCrash(reply.message));
      this.#crash(worker, reply.message);
    }
  }

  #crash(worker: WorkerPort, message: string): void {
    if (worker !== this.#worker) return;
    worker.terminate();
    this.#worker = undefined;
    this.#generation += 1;
    const pending = [...this.#pending.values()];
    this.#pending.clear();
    for (const p of pending) p.reject(new CoreCrash(message));
    this.#onCrash(message);
  }

  request<K extends RequestKind>(request: Extract<WorkerRequest, { kind: K }>): Promise<ReplyValue[K]> {
    return this.start(request).result;
  }

  /** Sends `request`, handing over the buffers in `transfer`; progress messages (of a long request) go to `onProgress`. */
  start<K extends RequestKind>(
    request: Extract<WorkerRequest, { kind: K }>,
    onProgress?: (progress: K extends LongRequestKind ? ProgressValue[K] : never) => void,
    transfer: Transferable[] = [],
  ): Running<ReplyValue[K]> {
    const id = this.#nextId++;
    const worker = this.#port();
    const result = new Promise<ReplyValue[K]>((resolve, reject) => {
      this.#pending.set(id, { resolve: resolve as Pending['resolve'], reject, onProgress: onProgress as Pending['onProgress'], holds: traceIdHeldAfter(request), cancelled: false });
      worker.postMessage({ id, request }, transfer);
    });
    return {
      result,
      cancel: () => {
        const pending = this.#pending.get(id);
        // Ids are never reused: a request lost with a crashed worker is no longer pending.
        if (!pending || pending.cancelled) return;
        pending.cancelled = true;
        worker.postMessage({ id, cancel: true });
      },
    };
  }

  /** Releases the worker's trace (or program) `traceId`: a RemoteTrace's (free), or one whose answer came after a cancel. */
  freeTrace(traceId: number): void {
    // A crash while this is on its way takes the trace with it: nothing to report.
    this.request({ kind: 'free', traceId }).catch(() => undefined);
  }

  /** Every algorithm and experiment the core runs. */
  catalogue(): Promise<ReplyValue['catalogue']> {
    return this.request({ kind: 'catalogue' });
  }

  /**
   * Runs a trace in the worker, with its metrics, measured a slice of
   * points at a time (reported to `onProgress`); cancellable. Rejects with
   * InputRejected naming the option at fault. `distinction`: the value it
   * is told apart by from the other side of an algorithm compared with
   * itself (its `name` says it).
   */
  trace(options: TraceOptions, onProgress?: (progress: PointsProgress) => void, distinction?: string): Running<MeasuredTrace> {
    const traceId = this.#nextTraceId++;
    const generation = this.#generation;
    const running = this.start({ kind: 'trace', traceId, options, pointsSent: this.#pointsSent() }, onProgress);
    return { result: running.result.then((path) => new MeasuredTrace(this, traceId, generation, path, distinction)), cancel: running.cancel };
  }

  /** Runs a G-code program in the worker, reporting progress after every slice of lines; cancellable. */
  runGcode(text: string, settings: GcodeSettings, onProgress: (progress: GcodeProgress) => void): Running<RemoteProgram> {
    const traceId = this.#nextTraceId++;
    const generation = this.#generation;
    if (this.#lastProgram?.text !== text) this.#lastProgram = { text, bytes: utf8Bytes(text) };
    // A copy is handed over: the one kept stays whole.
    const source = this.#lastProgram.bytes.slice();
    const running = this.start({ kind: 'gcode', traceId, source, settings, pointsSent: this.#pointsSent() }, onProgress, [source.buffer]);
    return { result: running.result.then((run) => new RemoteProgram(this, traceId, generation, run, text)), cancel: running.cancel };
  }

  /** Where two traces of the same move part (both held by the current worker), each one's cells sorted in turn (reported to `onProgress`); cancellable. */
  difference(a: RemoteTrace, b: RemoteTrace, onProgress?: (progress: PointsProgress) => void): Running<TraceDifference> {
    if (!a.alive || !b.alive) return { result: Promise.reject(new CoreCrash('a trace was lost with a crashed worker; trace again')), cancel: () => {} };
    return this.start({ kind: 'difference', traceIdA: a.traceId, traceIdB: b.traceId }, onProgress);
  }

  /**
   * A learner's points (text, as pasted) checked against the rule `options`
   * traces, whose trace `rule` the worker holds, a slice at a time (each
   * slice's progress to `onProgress`); cancellable.
   */
  check(rule: RemoteTrace, options: TraceOptions, text: string, onProgress?: (progress: ProgressValue['check']) => void): Running<LearnerCheck> {
    if (!rule.alive) return { result: Promise.reject(new CoreCrash('the trace was lost with a crashed worker; trace again')), cancel: () => {} };
    return this.start({ kind: 'check', traceId: rule.traceId, options, text, pointsSent: this.#pointsSent() }, onProgress);
  }

  /** Wang's random-lines experiment (section 3.2, Figure 9), reporting progress after every slice of lines; cancellable. */
  randomLines(options: RandomLinesOptions, onProgress: (progress: ExperimentProgress) => void): Running<RandomLinesResult> {
    return this.start({ kind: 'randomLines', options }, onProgress);
  }
}

/**
 * A trace held by the worker: its summary's fields (the core's, less the
 * segments) and the arrays every view needs. Point index k runs 0..=steps,
 * step index k runs 0..steps-1 (step k moves point k to point k + 1), as in
 * the core's Trace.
 */
export interface RemoteTrace extends Readonly<TraceFields> {}
export class RemoteTrace {
  /**
   * Point indices 0, pointsEvery, 2 · pointsEvery, ... flat with stride
   * dims: every point of a short path (pointsEvery 1), every n-th of a long
   * one (PointsSent), whose other points are asked for by range.
   */
  readonly sampledPoints: Int32Array;
  readonly pointsEvery: number;
  /** The ideal path as the core draws it, in the form the scene takes. */
  readonly idealLine: IdealLine;
  /** The box every point lies in (min and max per axis, grid units), as the core found it. */
  readonly bounds: PointBounds;
  /** Compared with its own algorithm: the value of the compared option it ran ('segments'), else undefined. */
  readonly distinction: string | undefined;
  readonly #client: TraceClient;
  /** The id the worker holds this trace by. */
  readonly traceId: number;
  readonly #generation: number;

  constructor(client: TraceClient, traceId: number, generation: number, path: TracedPath<TraceFields>, distinction?: string) {
    this.#client = client;
    this.traceId = traceId;
    this.#generation = generation;
    this.distinction = distinction;
    Object.assign(this, path.summary);
    this.sampledPoints = path.sampledPoints;
    this.pointsEvery = path.pointsEvery;
    this.idealLine = path.idealLine;
    this.bounds = path.bounds;
  }

  /** What the page calls it: its algorithm, told apart from the other side (traceName). */
  get name(): string {
    return traceName(this.algorithm, this.distinction);
  }

  /** Point index k as its coordinates (a view into `sampledPoints`) when the page holds it, else undefined (ask pointsInRange). */
  point(pointIndex: number): Int32Array | undefined {
    if (pointIndex % this.pointsEvery !== 0) return undefined;
    const row = pointIndex / this.pointsEvery;
    return this.sampledPoints.subarray(row * this.dims, (row + 1) * this.dims);
  }

  /** Points fromPoint..toPoint, flat with stride dims: from those held when every point is, else asked of the worker. */
  pointsInRange(fromPoint: number, toPoint: number): Promise<Int32Array> {
    if (this.pointsEvery === 1) return Promise.resolve(this.sampledPoints.slice(fromPoint * this.dims, toPoint * this.dims));
    return this.ask({ kind: 'points', traceId: this.traceId, fromPoint, toPoint });
  }

  /** False once the worker holding this trace has crashed: replayed data is then out of reach. */
  get alive(): boolean {
    return this.#generation === this.#client.generation;
  }

  protected ask<K extends RequestKind>(request: Extract<WorkerRequest, { kind: K }>): Promise<ReplyValue[K]> {
    if (!this.alive) return Promise.reject(new CoreCrash('this trace was lost with a crashed worker; trace again'));
    return this.#client.request(request);
  }

  /** Starts the long request `request` (cancellable, reporting to `onProgress`); a CoreCrash, with no message sent, once this trace's worker is gone. */
  protected startLong<K extends LongRequestKind>(request: Extract<WorkerRequest, { kind: K }>, onProgress?: (progress: ProgressValue[K]) => void): Running<ReplyValue[K]> {
    if (!this.alive) return { result: Promise.reject(new CoreCrash('this trace was lost with a crashed worker; trace again')), cancel: () => {} };
    return this.#client.start(request, onProgress as (progress: K extends LongRequestKind ? ProgressValue[K] : never) => void);
  }

  /**
   * Point index p and the step that produced it (step index p - 1), as the
   * core replays it once: decision read, explanation, deviation, segment and
   * note, and the decision's picture.
   */
  stepDetail(pointIndex: number): Promise<StepDetail> {
    return this.ask({ kind: 'stepDetail', traceId: this.traceId, pointIndex });
  }

  /**
   * The charts' rows: every point, or buckets when there are more than
   * maxPoints; made a slice of points at a time (reported to
   * `onProgress`), cancellable.
   */
  series(maxPoints: number, onProgress?: (progress: PointsProgress) => void): Running<ChartSeries> {
    return this.startLong({ kind: 'series', traceId: this.traceId, maxPoints }, onProgress);
  }

  /** Each axis's STEP and DIR signals over step indices fromStep..toStep (the core's pulseTrains), for the timing diagram; a program's with its steps' instants. */
  pulseTrains(fromStep: number, toStep: number): Promise<PulseWindow> {
    return this.ask({ kind: 'pulses', traceId: this.traceId, fromStep, toStep });
  }

  /** The tool's speed per step at one tick a step and at a constant feed, in at most maxRows rows (Trace.stepClocks). */
  stepClocks(maxRows: number): Promise<StepClocks> {
    return this.ask({ kind: 'stepClocks', traceId: this.traceId, maxRows });
  }

  /**
   * The whole trace as the CLI writes it, made in the worker a part at a
   * time: CSV (one row per point) or JSON, and a program's VCD; cancellable,
   * reporting the bytes written so far.
   */
  exportAs(format: ExportFormat, onProgress: (progress: ExportProgress) => void): Running<Blob> {
    return this.startLong({ kind: 'export', traceId: this.traceId, format }, onProgress);
  }

  /** Releases the worker's copy; a trace lost in a crash has nothing left to free. */
  free(): void {
    if (this.alive) this.#client.freeTrace(this.traceId);
  }
}

/**
 * What the page calls a trace of `algorithm`: its id, with the value that
 * tells it apart from the other side of an algorithm compared with itself
 * ("helix (segments)").
 */
export function traceName(algorithm: string, distinction: string | undefined): string {
  return distinction === undefined ? algorithm : `${algorithm} (${distinction})`;
}

/** A trace the worker ran for the page (trace and compare modes), with its metrics, which the status line shows at once. */
export interface MeasuredTrace extends Readonly<PathSummary> {}
export class MeasuredTrace extends RemoteTrace {
  constructor(client: TraceClient, traceId: number, generation: number, path: TracedPath, distinction?: string) {
    super(client, traceId, generation, path, distinction);
  }
}

/** A G-code program the worker ran and holds: its trace, plus the program's record and line <-> step lookups. */
export class RemoteProgram extends RemoteTrace {
  /** The program's record as the core reports it (lines, warnings, errors, duration...), less its moves. */
  readonly program: ProgramRecord;

  /** The text the program ran from: its lines are this text's. */
  readonly source: string;

  constructor(client: TraceClient, traceId: number, generation: number, run: RunProgram, source: string) {
    super(client, traceId, generation, run);
    this.program = run.program;
    this.source = source;
  }

  /** The machine's steps per mm on each axis, which the view labels its axes with. */
  get stepsPerMm(): number[] {
    return this.program.stepsPerMm;
  }

  /** Moves fromMove..toMove of the program, in step order. */
  moves(fromMove: number, toMove: number): Promise<GcodeMove[]> {
    return this.ask({ kind: 'moves', traceId: this.traceId, fromMove, toMove });
  }

  /** The move that took step index k, and its 1-based source line. */
  moveOfStep(stepIndex: number): Promise<{ moveIndex: number; line: number }> {
    return this.ask({ kind: 'moveOfStep', traceId: this.traceId, stepIndex });
  }

  /** The steps a 1-based source line produced, and where the machine is when it starts. */
  lineSteps(line: number): Promise<LineSteps> {
    return this.ask({ kind: 'lineSteps', traceId: this.traceId, line });
  }

  /** The instants of step indices fromStep..toStep on the planned profile, seconds. */
  stepTimes(fromStep: number, toStep: number): Promise<Float64Array> {
    return this.ask({ kind: 'stepTimes', traceId: this.traceId, fromStep, toStep });
  }

  /** The instant point index k is reached: that of step k - 1 (0 for the start), seconds. */
  async secondsAtPoint(pointIndex: number): Promise<number> {
    return pointIndex === 0 ? 0 : (await this.stepTimes(pointIndex - 1, pointIndex))[0]!;
  }

  /** The point index reached `seconds` into the program (GcodeProgram.pointAtSeconds). */
  pointAtSeconds(seconds: number): Promise<number> {
    return this.ask({ kind: 'pointAtSeconds', traceId: this.traceId, seconds });
  }

  /** Seconds of G4 dwell between two instants (GcodeProgram.dwellSeconds): which part of a pause between two steps is a dwell. */
  dwellSeconds(fromSeconds: number, toSeconds: number): Promise<number> {
    return this.ask({ kind: 'dwellSeconds', traceId: this.traceId, fromSeconds, toSeconds });
  }

  /** The planned speed and step rates over a window of time, in at most `buckets` rows (GcodeProgram.motionChart). */
  motionChart(fromSeconds: number, toSeconds: number, buckets: number): Promise<MotionChart> {
    return this.ask({ kind: 'motionChart', traceId: this.traceId, fromSeconds, toSeconds, buckets });
  }
}
