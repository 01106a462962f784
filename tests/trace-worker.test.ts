// The page's worker (web/worker/trace-worker.ts) answering in Node: its
// module is loaded with a stand-in for a worker's global scope (`self`),
// which hands it requests and keeps its replies with the buffers it
// transfers. The page's own worker runs in the browser tests.
import { beforeAll, describe, expect, it, vi } from 'vitest';
import { trace, type TraceOptions, traceToCsv } from '../web/core/index.js';
import type { LearnerCheck, PointsSent, ReplyMessage, RequestMessage, WorkerRequest } from '../web/worker/protocol.js';
import { inTaskOfItsOwn, pointsOf } from './helpers.js';

/** What readAndCheckPoints gave the worker, call by call: the core itself, only watched. */
const { checksRead } = vi.hoisted(() => ({ checksRead: [] as { points: Int32Array | null }[] }));
vi.mock('../web/core/index.js', async (importOriginal) => {
  const core = await importOriginal<typeof import('../web/core/index.js')>();
  return {
    ...core,
    readAndCheckPoints: async (...args: Parameters<typeof core.readAndCheckPoints>) => {
      const read = await core.readAndCheckPoints(...args);
      checksRead.push(read);
      return read;
    },
  };
});

type Listener = (event: { data: unknown }) => void;
let listener: Listener | undefined;
const posted: { message: ReplyMessage; transfer: Transferable[] }[] = [];

beforeAll(async () => {
  (globalThis as { self?: unknown }).self = {
    addEventListener: (_type: string, l: Listener) => (listener = l),
    postMessage: (message: ReplyMessage, options?: { transfer?: Transferable[] }) => posted.push({ message, transfer: options?.transfer ?? [] }),
  };
  await import('../web/worker/trace-worker.js');
});

let nextId = 1;

/** The worker's reply to `request`, and the buffers it handed over with it. */
async function ask(request: WorkerRequest): Promise<{ value: unknown; transfer: Transferable[] }> {
  const id = nextId++;
  listener!({ data: { id, request } });
  const reply = await replyTo(id);
  if (!('value' in reply.message)) throw new Error(`the worker failed: ${JSON.stringify(reply.message)}`);
  return { value: reply.message.value, transfer: reply.transfer };
}

/** The worker's reply to request `id`, once posted. */
async function replyTo(id: number): Promise<{ message: ReplyMessage; transfer: Transferable[] }> {
  for (;;) {
    const reply = posted.find((p) => p.message.id === id && 'ok' in p.message);
    if (reply) return reply;
    await new Promise((resolve) => setTimeout(resolve, 0));
  }
}

/** The rule's own points checked against it by the worker, which draws paths of fewer than `allBelow` cells whole. */
async function checkOwnPoints(rule: TraceOptions, allBelow: number): Promise<{ learner: LearnerCheck; transfer: Transferable[]; points: number[][] }> {
  const t = await trace(rule);
  const points = pointsOf(t);
  t.free();
  const pointsSent: PointsSent = { allBelow, sampled: 10 };
  const traceId = nextId++;
  await ask({ kind: 'trace', traceId, options: rule, pointsSent });
  const text = points.map((p) => p.join(',')).join('\n');
  const { value, transfer } = await ask({ kind: 'check', traceId, options: rule, text, pointsSent });
  await ask({ kind: 'free', traceId });
  return { learner: value as LearnerCheck, transfer, points };
}

describe("the worker's answer to a check", () => {
  it('carries the line through the cells for a path the view draws whole, with the points and their box', async () => {
    const { learner, transfer, points } = await checkOwnPoints({ algorithm: 'regions', from: [5, 5, 5], to: [25, 17, 9] }, 100);
    expect(learner.check.matches).toBe(true);
    expect(Array.from(learner.points!)).toEqual(points.flat());
    expect(learner.bounds).toEqual({ min: [5, 5, 5], max: [25, 17, 9] });
    expect(learner.centers!.xyz.length / 3).toBe(points.length);
    expect(learner.centers!.origin).toEqual([5, 5, 5]);
    expect(transfer).toEqual([learner.points!.buffer, learner.centers!.xyz.buffer]);
  });

  it("hands over the core's own Int32Array of the points, not a copy made of them", async () => {
    const { learner, transfer, points } = await checkOwnPoints({ algorithm: 'regions', from: [5, 5, 5], to: [205, 60, 9] }, 100);
    const read = checksRead.at(-1)!.points!;
    expect(read).toBeInstanceOf(Int32Array);
    expect(learner.points).toBe(read);
    expect(transfer).toEqual([read.buffer]);
    expect(Array.from(read)).toEqual(points.flat());
  });

  it('carries no line for a path too long to be drawn whole, only the points and their box', async () => {
    // 201 cells, from 100 on drawn the lighter way: the view makes the line near the current cell itself.
    const { learner, transfer, points } = await checkOwnPoints({ algorithm: 'regions', from: [5, 5, 5], to: [205, 60, 9] }, 100);
    expect(points.length).toBe(201);
    expect(learner.check.matches).toBe(true);
    expect(learner.centers).toBeNull();
    // The points' own box, not one taken from their first point (the line's).
    expect(learner.bounds).toEqual({ min: [5, 5, 5], max: [205, 60, 9] });
    expect(transfer).toEqual([learner.points!.buffer]);
  });

  it('carries no line for a path too wide to be drawn whole, however few its cells', async () => {
    // 401 cells of the 1,000 drawn whole, but 401 grid units wide: drawn the lighter way (LIGHT_DRAWING_SPAN).
    const { learner, transfer } = await checkOwnPoints({ algorithm: 'regions', from: [0, 0, 0], to: [400, 3, 1] }, 1000);
    expect(learner.centers).toBeNull();
    expect(learner.bounds).toEqual({ min: [0, 0, 0], max: [400, 3, 1] });
    expect(transfer).toEqual([learner.points!.buffer]);
  });
});

describe('a check cancelled as it starts', () => {
  it("stops before the check's first slice, the points' text not read", async () => {
    // A helix of 150,000 points, 2 MB of text. The text put into wasm
    // memory and the run made were one task before the check's first
    // slice (0.1 to 0.25 s in Chromium at the page's cap), which a Cancel
    // sent at the check's first report waited for: the first slice ran,
    // and reported, before the cancel was read.
    const rule: TraceOptions = { algorithm: 'helix', from: [250, 0, 0], to: [250, 0, 300], center: [0, 0, 0], plane: 'xy', turns: 106 };
    const t = await trace(rule);
    const text = traceToCsv(t);
    t.free();
    const pointsSent: PointsSent = { allBelow: 1000, sampled: 10 };
    const traceId = nextId++;
    await ask({ kind: 'trace', traceId, options: rule, pointsSent });
    const id = nextId++;
    listener!({ data: { id, request: { kind: 'check', traceId, options: rule, text, pointsSent } } });
    // As the page's Cancel reaches the worker: in a task of its own.
    inTaskOfItsOwn(() => listener!({ data: { id, cancel: true } satisfies RequestMessage }));
    const reply = await replyTo(id);
    expect(reply.message).toMatchObject({ ok: false, failure: 'cancelled' });
    // The worker's own first report, and none of the check's slices.
    const progress = posted.filter((p) => p.message.id === id && 'progress' in p.message).map((p) => (p.message as { progress: unknown }).progress);
    expect(progress).toEqual([{ stage: 'reading', done: false }]);
    // Checked when not cancelled.
    const again = nextId++;
    listener!({ data: { id: again, request: { kind: 'check', traceId, options: rule, text, pointsSent } } });
    expect((await replyTo(again)).message).toMatchObject({ ok: true, value: { check: { matches: true } } });
    await ask({ kind: 'free', traceId });
  });
});
