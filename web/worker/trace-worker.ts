/**
 * The trace worker: runs the wasm core off the main thread, so a long trace or
 * a replay of decisions never freezes the page. It holds the Trace objects the
 * page asked for, by the page's trace id, until the page frees them.
 */
import { algorithms, trace, VoxpathError } from '../core/index.js';
import type { Trace } from '../core/index.js';
import type { ReplyMessage, ReplyValue, RequestKind, RequestMessage, WorkerRequest } from './protocol.js';

const traces = new Map<number, Trace>();

function held(traceId: number): Trace {
  const t = traces.get(traceId);
  if (!t) throw new Error(`this worker holds no trace ${traceId}`);
  return t;
}

interface Answer {
  value: ReplyValue[RequestKind];
  /** Buffers handed over to the page instead of copied; each is a fresh copy out of wasm memory. */
  transfer: Transferable[];
}

async function answer(request: WorkerRequest): Promise<Answer> {
  switch (request.kind) {
    case 'catalogue':
      return { value: await algorithms(), transfer: [] };
    case 'trace': {
      const t = await trace(request.options);
      traces.set(request.traceId, t);
      // pointsInRange, not the cached `points` getter: a transferred buffer is
      // detached here, and the cache would then hand out an empty array.
      const points = t.pointsInRange(0, t.steps + 1);
      const idealPolyline = t.idealPolyline();
      const { algorithm, dims, steps, start, end, columns, metrics, segments } = t;
      return {
        value: { summary: { algorithm, dims, steps, start, end, columns, metrics, segments }, points, idealPolyline },
        transfer: [points.buffer, idealPolyline.buffer],
      };
    }
    case 'decisions': {
      const columns = held(request.traceId).decisionsInRange(request.fromStep, request.toStep);
      return { value: columns, transfer: Object.values(columns).map((c) => c.buffer) };
    }
    case 'deviation': {
      const deviation = held(request.traceId).deviationInRange(request.fromPoint, request.toPoint);
      return { value: deviation, transfer: [deviation.buffer] };
    }
    case 'explain':
      return { value: held(request.traceId).explain(request.stepIndex), transfer: [] };
    case 'free':
      traces.get(request.traceId)?.free();
      traces.delete(request.traceId);
      return { value: null, transfer: [] };
  }
}

function failure(id: number, error: unknown): ReplyMessage {
  if (error instanceof VoxpathError) {
    // The detail, without the "field: " prefix: the page shows it beside that field.
    return { id, ok: false, failure: 'input', error: { field: error.field, message: error.field ? error.detail : error.message } };
  }
  const message = error instanceof Error ? `${error.name}: ${error.message}` : String(error);
  return { id, ok: false, failure: error instanceof WebAssembly.RuntimeError ? 'crash' : 'error', message };
}

self.addEventListener('message', (event: MessageEvent<RequestMessage>) => {
  const { id, request } = event.data;
  answer(request).then(
    ({ value, transfer }) => self.postMessage({ id, ok: true, value } satisfies ReplyMessage, { transfer }),
    (error: unknown) => self.postMessage(failure(id, error)),
  );
});
