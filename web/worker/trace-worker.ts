/**
 * The trace worker: runs the wasm core off the main thread, so a long trace,
 * a G-code program or a replay of decisions never freezes the page. It holds
 * the Trace objects (and G-code programs) the page asked for, by the page's
 * trace id, until the page frees them.
 */
import {
  GcodeProgram,
  catalogue,
  pulseTrains,
  readAndCheckPoints,
  randomLines,
  runGcode,
  trace,
  traceCsvChunks,
  traceJsonChunks,
  VoxpathError,
} from '../core/index.js';
import type { Trace } from '../core/index.js';
import { grouped } from '../core/export.js';
import { yieldToEventLoop } from '../core/slices.js';
import { idealLineOf } from '../ideal-line.js';
import { drawnLight, pointBounds, widestCells } from '../scene/light-drawing.js';
import { pointsEvery } from './protocol.js';
import type { ExportFormat, LongRequestKind, PointsSent, ProgressValue, ReplyMessage, ReplyValue, RequestKind, RequestMessage, TracedPath, TraceFields, WorkerRequest } from './protocol.js';

const traces = new Map<number, Trace>();
const programs = new Map<number, GcodeProgram>();
/** Requests that can be cancelled while they run, by request id. */
const running = new Map<number, AbortController>();

function held(traceId: number): Trace {
  const t = traces.get(traceId);
  if (!t) throw new Error(`this worker holds no trace ${traceId}`);
  return t;
}

function heldProgram(traceId: number): GcodeProgram {
  const p = programs.get(traceId);
  if (!p) throw new Error(`this worker holds no G-code program ${traceId}`);
  return p;
}

interface Answer {
  value: ReplyValue[RequestKind];
  /** Buffers handed over to the page instead of copied; each is a fresh copy out of wasm memory. */
  transfer: Transferable[];
}

/** The arrays every view needs at once, freshly copied so they can be transferred; of the points, those `sent` asks for. */
function pathOf(t: Trace, sent: PointsSent): TracedPath<TraceFields> {
  // pointsInRange, not the cached `points` getter: a transferred buffer is
  // detached here, and the cache would then hand out an empty array.
  const every = pointsEvery(t.steps + 1, sent);
  const sampledPoints = t.pointsInRange(0, t.steps + 1, every);
  const idealLine = t.idealLine();
  // The summary's and the legend's fields, as the core declared them.
  return { summary: { ...t, ...t.legend }, sampledPoints, pointsEvery: every, idealLine, bounds: t.bounds };
}

/**
 * pathOf, with the metrics, which the page shows at once for a trace (its
 * status line): measured by the core a slice of points at a time, each
 * slice's progress posted, stopped by a cancel through `signal` (a helix's
 * 1,500,000 points took 1 to 2 s).
 */
async function tracedPath(id: number, t: Trace, sent: PointsSent, signal: AbortSignal): Promise<TracedPath> {
  const metrics = await t.metricsInSlices({ signal, onProgress: (progress) => report(id, progress) });
  const path = pathOf(t, sent);
  return { ...path, summary: { ...path.summary, metrics } };
}

/** Posts the progress of the long request `id`. */
function report(id: number, progress: ProgressValue[LongRequestKind]): void {
  self.postMessage({ id, progress } satisfies ReplyMessage);
}

/** Runs the long request `id`, which a cancel message naming it aborts through `signal`. */
async function cancellable(id: number, work: (signal: AbortSignal) => Promise<Answer>): Promise<Answer> {
  const controller = new AbortController();
  running.set(id, controller);
  try {
    return await work(controller.signal);
  } finally {
    running.delete(id);
  }
}

/**
 * Bytes of an export's parts gathered before they are put in its Blob: the
 * browser keeps a Blob's bytes outside the worker's heap (on disk when they
 * are many), where the parts themselves would all stay in it.
 */
const EXPORT_BLOB_BYTES = 16 * 1024 * 1024;

/**
 * An export's progress is posted at most this often, ms: its parts take a
 * millisecond or two each, and the page shows four reports a second at most
 * (run-progress.ts, PROGRESS_EVERY_MS).
 */
const EXPORT_REPORT_MS = 250;

/** The media type each export is saved as. */
const EXPORT_TYPES: Record<ExportFormat, string> = { csv: 'text/csv', json: 'application/json', vcd: 'text/plain' };

/**
 * The file trace `traceId` exports as `format`, made a part at a time from
 * the core's writers, with the event loop let run between parts (a cancel
 * through `signal`, the progress posted): a 50,000,000-step program's CSV
 * took a minute, and joined into one string it was past the longest a
 * browser holds.
 */
async function exportFile(id: number, traceId: number, format: ExportFormat, signal: AbortSignal): Promise<Blob> {
  const parts = format === 'vcd' ? heldProgram(traceId).vcdChunks() : format === 'csv' ? traceCsvChunks(held(traceId)) : traceJsonChunks(held(traceId));
  let file = new Blob([], { type: EXPORT_TYPES[format] });
  let gathered: (string | Uint8Array<ArrayBuffer>)[] = [];
  let gatheredBytes = 0;
  let bytes = 0;
  let reportedAt = -Infinity;
  for (const part of parts) {
    gathered.push(part as string | Uint8Array<ArrayBuffer>);
    // A string's length is its UTF-8 size but for the few non-ASCII names in a JSON export's notes.
    gatheredBytes += part.length;
    if (gatheredBytes >= EXPORT_BLOB_BYTES) {
      file = new Blob([file, ...gathered], { type: EXPORT_TYPES[format] });
      [gathered, gatheredBytes] = [[], 0];
    }
    bytes += part.length;
    if (performance.now() - reportedAt >= EXPORT_REPORT_MS) {
      reportedAt = performance.now();
      report(id, { bytes, done: false });
    }
    await yieldToEventLoop();
    signal.throwIfAborted();
  }
  file = new Blob([file, ...gathered], { type: EXPORT_TYPES[format] });
  // A Blob past what the browser can keep (a 50,000,000-step program's CSV,
  // 4 GB) is made all the same, and its download failed in the browser's
  // list, the page saying nothing: its end is read here, to say so.
  try {
    await file.slice(-1).arrayBuffer();
  } catch {
    const command = `voxpath ${programs.has(traceId) ? 'gcode' : 'trace'} --format ${format}`;
    throw new VoxpathError(`the browser could not keep its ${grouped(file.size)} bytes; the command line writes it as it goes (${command})`);
  }
  report(id, { bytes: file.size, done: true });
  return file;
}

async function answer(id: number, request: WorkerRequest): Promise<Answer> {
  switch (request.kind) {
    case 'catalogue':
      return { value: await catalogue(), transfer: [] };
    case 'trace':
      return cancellable(id, async (signal) => {
        const t = await trace(request.options);
        let path: TracedPath;
        try {
          path = await tracedPath(id, t, request.pointsSent, signal);
        } catch (error) {
          // Stopped: the page never holds this trace, to free it.
          t.free();
          throw error;
        }
        traces.set(request.traceId, t);
        return { value: path, transfer: [path.sampledPoints.buffer, path.idealLine.xyz.buffer] };
      });
    case 'gcode':
      return cancellable(id, async (signal) => {
        const program = await runGcode(request.source, request.settings, { signal, onProgress: (progress) => report(id, progress) });
        traces.set(request.traceId, program.trace);
        programs.set(request.traceId, program);
        const path = pathOf(program.trace, request.pointsSent);
        // The record's own fields, as the core declared them (the moves are asked for by range).
        const { trace: _trace, ...record } = program;
        return {
          value: { ...path, program: record },
          transfer: [path.sampledPoints.buffer, path.idealLine.xyz.buffer],
        };
      });
    case 'stepDetail':
      return { value: held(request.traceId).stepDetail(request.pointIndex), transfer: [] };
    case 'points': {
      const points = held(request.traceId).pointsInRange(request.fromPoint, request.toPoint);
      return { value: points, transfer: [points.buffer] };
    }
    case 'series':
      // Every point's deviation, a slice of points at a time: a helix's 1,500,000 took about a second.
      return cancellable(id, async (signal) => {
        const series = await held(request.traceId).chartSeriesInSlices(request.maxPoints, { signal, onProgress: (progress) => report(id, progress) });
        const arrays = [series.pointIndex, ...series.position, ...series.ideal, series.deviationMax, series.deviationMin];
        return { value: series, transfer: arrays.map((a) => a.buffer) };
      });
    case 'difference':
      return cancellable(id, async (signal) => {
        const [a, b] = [held(request.traceIdA), held(request.traceIdB)];
        const difference = await a.differenceWith(b, { signal, onProgress: (progress) => report(id, progress) });
        return { value: difference, transfer: [difference.onlyInA.buffer, difference.onlyInB.buffer] };
      });
    case 'pulses': {
      // A program's steps have instants on its planned profile; a trace's are ticks.
      const stepSeconds = programs.get(request.traceId)?.stepTimes(request.fromStep, request.toStep) ?? null;
      const trains = pulseTrains(held(request.traceId), request.fromStep, request.toStep, stepSeconds ?? undefined);
      const transfer = trains.flatMap((t) => [t.step.buffer, t.dir.buffer, ...(t.edgeSeconds ? [t.edgeSeconds.buffer, t.rateHz!.buffer] : [])]);
      return { value: { trains, stepSeconds }, transfer: stepSeconds ? [...transfer, stepSeconds.buffer] : transfer };
    }
    case 'stepClocks':
      return { value: held(request.traceId).stepClocks(request.maxRows), transfer: [] };
    case 'stepTimes': {
      const times = heldProgram(request.traceId).stepTimes(request.fromStep, request.toStep);
      return { value: times, transfer: [times.buffer] };
    }
    case 'pointAtSeconds':
      return { value: heldProgram(request.traceId).pointAtSeconds(request.seconds), transfer: [] };
    case 'dwellSeconds':
      return { value: heldProgram(request.traceId).dwellSeconds(request.fromSeconds, request.toSeconds), transfer: [] };
    case 'motionChart':
      return { value: heldProgram(request.traceId).motionChart(request.fromSeconds, request.toSeconds, request.buckets), transfer: [] };
    case 'moves': {
      const program = heldProgram(request.traceId);
      const to = Math.min(request.toMove, program.moveCount);
      return { value: program.movesInRange(Math.min(request.fromMove, to), to), transfer: [] };
    }
    case 'moveOfStep': {
      const program = heldProgram(request.traceId);
      const moveIndex = program.moveOfStep(request.stepIndex);
      return { value: { moveIndex, line: program.move(moveIndex).line }, transfer: [] };
    }
    case 'lineSteps': {
      const program = heldProgram(request.traceId);
      const move = program.moveAtLine(request.line);
      const pointBefore = program.pointBeforeLine(request.line);
      return { value: { firstStep: move?.firstStep ?? pointBefore, steps: move?.steps ?? 0, pointBefore }, transfer: [] };
    }
    case 'export':
      // A Blob crosses to the page as a handle on its bytes, not a copy.
      return cancellable(id, async (signal) => ({ value: await exportFile(id, request.traceId, request.format, signal), transfer: [] }));
    case 'randomLines':
      return cancellable(id, async (signal) => ({
        value: await randomLines(request.options, { signal, onProgress: (progress) => report(id, progress) }),
        transfer: [],
      }));
    case 'check':
      // The text is put into wasm memory and read once, each a slice at a
      // time (at the page's cap, 19 MB, one call of 70 to 200 ms and one of
      // 0.1 to 0.2 s before, which a Cancel waited for), giving its line
      // and column to any error, and then checked a slice at a time; the
      // points read, the core's Int32Array handed over as it is, are
      // drawn, and make their line for the view when it draws them whole.
      return cancellable(id, async (signal) => {
        const dims = held(request.traceId).dims;
        report(id, { stage: 'reading', done: false });
        const { check, points } = await readAndCheckPoints(request.options, request.text, { signal, onProgress: (progress) => report(id, progress) });
        const bounds = points && pointBounds(points, dims);
        const whole = bounds !== null && !drawnLight(points!.length / dims, widestCells(bounds), request.pointsSent.allBelow);
        const centers = whole ? idealLineOf(points!, dims) : null;
        const transfer = [points?.buffer, centers?.xyz.buffer].filter((b) => b !== undefined);
        return { value: { check, points, bounds, centers, dims }, transfer };
      });
    case 'free':
      // A program owns its trace: freeing the program frees both.
      (programs.get(request.traceId) ?? traces.get(request.traceId))?.free();
      programs.delete(request.traceId);
      traces.delete(request.traceId);
      return { value: null, transfer: [] };
  }
}

function failure(id: number, error: unknown): ReplyMessage {
  if (error instanceof VoxpathError) {
    // The detail, without the "field: " prefix: the page shows it beside that field. An error
    // in a text (a learner's points) is said with its line and column, in the text's own panel.
    if (error.line !== undefined) return { id, ok: false, failure: 'input', error: { message: error.message, limit: error.limit } };
    return { id, ok: false, failure: 'input', error: { field: error.field, message: error.field ? error.detail : error.message, limit: error.limit } };
  }
  const message = error instanceof Error ? `${error.name}: ${error.message}` : String(error);
  if (error instanceof DOMException && error.name === 'AbortError') return { id, ok: false, failure: 'cancelled', message };
  return { id, ok: false, failure: error instanceof WebAssembly.RuntimeError ? 'crash' : 'error', message };
}

self.addEventListener('message', (event: MessageEvent<RequestMessage>) => {
  const message = event.data;
  if ('cancel' in message) {
    running.get(message.id)?.abort();
    return;
  }
  const { id, request } = message;
  answer(id, request).then(
    ({ value, transfer }) => self.postMessage({ id, ok: true, value } satisfies ReplyMessage, { transfer }),
    (error: unknown) => self.postMessage(failure(id, error)),
  );
});
