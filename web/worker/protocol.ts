/**
 * Messages between the page (main thread) and the trace worker, which owns
 * every Trace and is the page's only user of the wasm core.
 *
 * Each request carries an id; the worker answers each with exactly one reply
 * carrying the same id. Bulk arrays cross as transferred buffers, not copies:
 * - points: Int32Array, stride dims, one row per point index 0..=steps;
 * - idealPolyline: Float64Array, stride dims, grid units;
 * - decisions: one typed array per column, one entry per step index of the range;
 * - deviation: Float64Array, one entry per point index of the range.
 */
import type { AlgorithmInfo, DecisionColumns, TraceOptions, TraceSummary } from '../core/types.js';

/** What the worker can be asked. `traceId` is chosen by the page and names a trace the worker holds. */
export type WorkerRequest =
  | { kind: 'catalogue' }
  | { kind: 'trace'; traceId: number; options: TraceOptions }
  | { kind: 'decisions'; traceId: number; fromStep: number; toStep: number }
  | { kind: 'deviation'; traceId: number; fromPoint: number; toPoint: number }
  | { kind: 'explain'; traceId: number; stepIndex: number }
  | { kind: 'free'; traceId: number };

export type RequestKind = WorkerRequest['kind'];

/** A finished trace as the page receives it: the summary and the arrays every view needs at once. */
export interface TracedPath {
  summary: TraceSummary;
  points: Int32Array;
  idealPolyline: Float64Array;
}

/** The value a successful reply carries, by request kind. */
export interface ReplyValue {
  catalogue: AlgorithmInfo[];
  trace: TracedPath;
  decisions: DecisionColumns;
  deviation: Float64Array;
  explain: string;
  free: null;
}

/** An input the core rejected; `field` names the option at fault (as in VoxpathError). */
export interface InputError {
  field?: string;
  message: string;
}

export interface RequestMessage {
  id: number;
  request: WorkerRequest;
}

/**
 * A reply. Failures come in three kinds, because the page reacts differently:
 * - input: the core rejected the input; the form shows it next to the field;
 * - crash: the core trapped (a bug in the core); its memory can no longer be
 *   trusted, so the page replaces the worker;
 * - error: anything else (a bug in the page's request); the worker stays.
 */
export type ReplyMessage =
  | { id: number; ok: true; value: ReplyValue[RequestKind] }
  | { id: number; ok: false; failure: 'input'; error: InputError }
  | { id: number; ok: false; failure: 'crash' | 'error'; message: string };
