// The page's worker client: replies matched by id, the core's input errors
// kept apart from crashes, a crashed worker replaced so the page goes on,
// and a Cancel honoured even when the worker had already answered.
// A scripted fake stands in for the Worker; the real worker runs in the
// browser tests.
import { describe, expect, it } from 'vitest';
import { Cancelled, CoreCrash, InputRejected, TraceClient, type WorkerPort } from '../web/worker/client.js';
import { pointsEvery } from '../web/worker/protocol.js';
import type { ProgramRecord, ReplyMessage, RequestMessage, TracedPath, WorkerRequest } from '../web/worker/protocol.js';

class FakeWorker implements WorkerPort {
  onmessage: ((event: MessageEvent<ReplyMessage>) => void) | null = null;
  onerror: ((event: ErrorEvent) => void) | null = null;
  readonly received: RequestMessage[] = [];
  /** The buffers handed over with each message, in step with `received`. */
  readonly transferred: Transferable[][] = [];
  terminated = false;

  postMessage(message: RequestMessage, transfer: Transferable[] = []): void {
    this.received.push(message);
    this.transferred.push(transfer);
  }

  terminate(): void {
    this.terminated = true;
  }

  reply(message: ReplyMessage): void {
    this.onmessage?.({ data: message } as MessageEvent<ReplyMessage>);
  }
}

/** Which points the tests' client asks to be sent with a path: all of fewer than 100, else at most 10. */
const POINTS_SENT = { allBelow: 100, sampled: 10 };

function setUp() {
  const workers: FakeWorker[] = [];
  const crashes: string[] = [];
  const client = new TraceClient(
    () => {
      const worker = new FakeWorker();
      workers.push(worker);
      return worker;
    },
    (message) => crashes.push(message),
    () => POINTS_SENT,
  );
  return { client, workers, crashes };
}

const PATH: TracedPath = {
  summary: {
    algorithm: 'regions',
    dims: 3,
    steps: 1,
    start: [0, 0, 0],
    end: [1, 1, 0],
    columns: [],
    figures: [],
    metrics: { steps: 1, stepsMovingAxes: [0, 1, 0], pulsesByAxis: [1, 1, 0], maxDeviation: 0, meanDeviation: 0, stdDeviation: 0, maxAxisError: [0, 0, 0], ties: 0 },
    deviationBound: null,
  },
  sampledPoints: new Int32Array([0, 0, 0, 1, 1, 0]),
  pointsEvery: 1,
  idealLine: { xyz: new Float32Array([0, 0, 0, 1, 1, 0]), rest: new Float32Array(6), min: [0, 0, 0], max: [1, 1, 0], origin: [0, 0, 0] },
  bounds: { min: [0, 0, 0], max: [1, 1, 0] },
};

describe('TraceClient', () => {
  it('starts no worker until asked, and matches replies to requests by id', async () => {
    const { client, workers } = setUp();
    expect(workers).toHaveLength(0);
    const first = client.request({ kind: 'pointAtSeconds', traceId: 1, seconds: 1 });
    const second = client.request({ kind: 'pointAtSeconds', traceId: 1, seconds: 2 });
    const [a, b] = workers[0]!.received;
    workers[0]!.reply({ id: b!.id, ok: true, value: 20 });
    workers[0]!.reply({ id: a!.id, ok: true, value: 10 });
    expect(await first).toBe(10);
    expect(await second).toBe(20);
    expect(workers).toHaveLength(1);
  });

  it("turns the core's input errors into InputRejected naming the field", async () => {
    const { client, workers, crashes } = setUp();
    const traced = client.trace({ algorithm: 'regions', from: [0, 0, 0], to: [2e9, 0, 0] }).result;
    const { id } = workers[0]!.received[0]!;
    workers[0]!.reply({ id, ok: false, failure: 'input', error: { field: 'to', message: 'x = 2000000000 is outside ±2^30' } });
    const error = await traced.catch((e: unknown) => e);
    expect(error).toBeInstanceOf(InputRejected);
    expect(error).toMatchObject({ field: 'to', message: 'x = 2000000000 is outside ±2^30' });
    expect(crashes).toEqual([]);
    expect(workers[0]!.terminated).toBe(false);
  });

  it('on a crash rejects everything pending, reports it once and starts a fresh worker on the next request', async () => {
    const { client, workers, crashes } = setUp();
    const traced = client.trace({ algorithm: 'regions', from: [0, 0, 0], to: [1, 1, 0] }).result;
    workers[0]!.reply({ id: workers[0]!.received[0]!.id, ok: true, value: PATH });
    const trace = await traced;
    expect(trace.alive).toBe(true);
    expect(Array.from(trace.point(1)!)).toEqual([1, 1, 0]);

    const start = trace.stepDetail(0);
    const end = trace.stepDetail(1);
    const [, startRequest] = workers[0]!.received;
    workers[0]!.reply({ id: startRequest!.id, ok: false, failure: 'crash', message: 'RuntimeError: unreachable' });
    await expect(start).rejects.toBeInstanceOf(CoreCrash);
    await expect(end).rejects.toThrow('RuntimeError: unreachable');
    expect(crashes).toEqual(['RuntimeError: unreachable']);
    expect(workers[0]!.terminated).toBe(true);

    // The old trace died with its worker: asking it again fails without a message sent.
    expect(trace.alive).toBe(false);
    await expect(trace.stepDetail(0)).rejects.toBeInstanceOf(CoreCrash);
    trace.free();
    expect(workers).toHaveLength(1);

    const catalogue = client.catalogue();
    expect(workers).toHaveLength(2);
    workers[1]!.reply({ id: workers[1]!.received[0]!.id, ok: true, value: [] });
    expect(await catalogue).toEqual([]);
  });

  it('treats a worker that fails to run like a crash', async () => {
    const { client, workers, crashes } = setUp();
    const pending = client.catalogue();
    workers[0]!.onerror?.({ message: 'Uncaught SyntaxError', preventDefault() {} } as ErrorEvent);
    await expect(pending).rejects.toBeInstanceOf(CoreCrash);
    expect(crashes).toEqual(['the trace worker failed: Uncaught SyntaxError']);
    // A late reply from the dead worker is ignored.
    workers[0]!.reply({ id: workers[0]!.received[0]!.id, ok: true, value: [] });
    expect(crashes).toHaveLength(1);
  });

  it('keeps the worker after a bad request from the page', async () => {
    const { client, workers, crashes } = setUp();
    const pending = client.request({ kind: 'stepDetail', traceId: 9, pointIndex: 0 });
    workers[0]!.reply({ id: workers[0]!.received[0]!.id, ok: false, failure: 'error', message: 'Error: this worker holds no trace 9' });
    const error = await pending.catch((e: unknown) => e);
    expect(error).toBeInstanceOf(Error);
    expect(error).not.toBeInstanceOf(CoreCrash);
    expect(error).toMatchObject({ message: 'Error: this worker holds no trace 9' });
    expect(workers[0]!.terminated).toBe(false);
    expect(crashes).toEqual([]);
  });

  it('asks for the points a path is sent with, and for the others by range when it holds a sample', async () => {
    const { client, workers } = setUp();
    // A path of 1000 steps, 1001 points: past allBelow, so every 101st point (at most 10 asked: ceil(1001 / 10) apart, so 10 of them).
    expect(pointsEvery(1001, POINTS_SENT)).toBe(101);
    expect(pointsEvery(99, POINTS_SENT)).toBe(1);
    expect(pointsEvery(100, POINTS_SENT)).toBe(10);
    const traced = client.trace({ algorithm: 'regions', from: [0, 0, 0], to: [1000, 0, 0] }).result;
    const request = workers[0]!.received[0]!;
    expect(request).toMatchObject({ request: { kind: 'trace', pointsSent: POINTS_SENT } });
    const sampledPoints = Int32Array.from({ length: 10 * 3 }, (_, i) => (i % 3 === 0 ? (i / 3) * 101 : 0));
    workers[0]!.reply({ id: request.id, ok: true, value: { ...PATH, summary: { ...PATH.summary, steps: 1000, end: [1000, 0, 0] }, sampledPoints, pointsEvery: 101 } });
    const trace = await traced;
    expect(Array.from(trace.point(202)!)).toEqual([202, 0, 0]);
    expect(trace.point(203)).toBeUndefined();
    const range = trace.pointsInRange(200, 203);
    const asked = workers[0]!.received[1]!;
    expect(asked).toMatchObject({ request: { kind: 'points', traceId: trace.traceId, fromPoint: 200, toPoint: 203 } });
    workers[0]!.reply({ id: asked.id, ok: true, value: new Int32Array([200, 0, 0, 201, 0, 0, 202, 0, 0]) });
    expect(Array.from(await range)).toEqual([200, 0, 0, 201, 0, 0, 202, 0, 0]);

    // A short path is held whole: its ranges are read without asking.
    const short = client.trace({ algorithm: 'regions', from: [0, 0, 0], to: [1, 1, 0] }).result;
    workers[0]!.reply({ id: workers[0]!.received[2]!.id, ok: true, value: PATH });
    expect(Array.from(await (await short).pointsInRange(1, 2))).toEqual([1, 1, 0]);
    expect(workers[0]!.received).toHaveLength(3);
  });

  it("sends a G-code program as its UTF-8 bytes, handing their buffer over rather than copying it", () => {
    const { client, workers } = setUp();
    const text = 'G1 X1 (Ø 3 mm, 𝜋/2)\n';
    client.runGcode(text, { stepsPerMm: 80 }, () => undefined);
    const message = workers[0]!.received[0]!;
    expect(message).toMatchObject({ request: { kind: 'gcode', settings: { stepsPerMm: 80 } } });
    const { source } = (message as { request: { source: Uint8Array } }).request;
    expect(new TextDecoder().decode(source)).toBe(text);
    expect(Array.from(source)).toEqual(Array.from(new TextEncoder().encode(text)));
    expect(workers[0]!.transferred[0]).toEqual([source.buffer]);

    // Run again as it is (another machine setting), then edited: the same bytes in a buffer of their own, then the new text's.
    client.runGcode(text, { stepsPerMm: 100 }, () => undefined);
    client.runGcode(`${text}G0 X0\n`, { stepsPerMm: 100 }, () => undefined);
    const [again, edited] = workers[0]!.received.slice(1).map((m) => (m as { request: { source: Uint8Array } }).request.source);
    expect(new TextDecoder().decode(again)).toBe(text);
    expect(again!.buffer).not.toBe(source.buffer);
    expect(workers[0]!.transferred[1]).toEqual([again!.buffer]);
    expect(new TextDecoder().decode(edited)).toBe(`${text}G0 X0\n`);
  });

  describe('a Cancel', () => {
    /** The request the worker received as message `index`, with its id. */
    function requestAt(worker: FakeWorker, index: number): { id: number; request: WorkerRequest } {
      const message = worker.received[index]!;
      if (!('request' in message)) throw new Error(`message ${index} is a cancel, not a request`);
      return message;
    }

    it("made before the worker's answer was handled rejects with Cancelled, and frees the trace or program that answer left in the worker", async () => {
      // The worker had ended before the cancel reached it: its answer was on
      // its way (or queued behind the main thread's drawing), and the path
      // was shown though Cancel had been pressed.
      const { client, workers } = setUp();
      const traced = client.trace({ algorithm: 'regions', from: [0, 0, 0], to: [1, 1, 0] });
      const run = client.runGcode('G1 X1\n', { stepsPerMm: 80 }, () => undefined);
      const worker = workers[0]!;
      const [traceRequest, programRequest] = [requestAt(worker, 0), requestAt(worker, 1)];
      traced.cancel();
      run.cancel();
      expect(worker.received.slice(2)).toEqual([
        { id: traceRequest.id, cancel: true },
        { id: programRequest.id, cancel: true },
      ]);
      worker.reply({ id: traceRequest.id, ok: true, value: PATH });
      worker.reply({ id: programRequest.id, ok: true, value: { ...PATH, program: {} as ProgramRecord } });
      await expect(traced.result).rejects.toBeInstanceOf(Cancelled);
      await expect(run.result).rejects.toBeInstanceOf(Cancelled);
      // Nothing on the page holds them to free them later.
      const frees = worker.received.slice(4).map((m) => ('request' in m ? m.request : m));
      expect(frees).toEqual([
        { kind: 'free', traceId: (traceRequest.request as { traceId: number }).traceId },
        { kind: 'free', traceId: (programRequest.request as { traceId: number }).traceId },
      ]);
    });

    it('rejects with Cancelled whatever the worker answers, and frees nothing that the answer did not leave in the worker', async () => {
      const { client, workers } = setUp();
      const traced = client.trace({ algorithm: 'regions', from: [0, 0, 0], to: [1, 1, 0] }).result;
      const worker = workers[0]!;
      worker.reply({ id: requestAt(worker, 0).id, ok: true, value: PATH });
      const rule = await traced;
      const rows = rule.series(2000);
      const exported = rule.exportAs('csv', () => undefined);
      const stopped = rule.exportAs('json', () => undefined);
      for (const running of [rows, exported, stopped]) running.cancel();
      const [rowsId, exportId, stoppedId] = [1, 2, 3].map((index) => requestAt(worker, index).id);
      worker.reply({ id: rowsId!, ok: false, failure: 'error', message: 'Error: this worker holds no trace 1' });
      worker.reply({ id: exportId!, ok: true, value: new Blob(['x,y,z\n']) });
      worker.reply({ id: stoppedId!, ok: false, failure: 'cancelled', message: 'AbortError: aborted' });
      for (const running of [rows, exported, stopped]) await expect(running.result).rejects.toBeInstanceOf(Cancelled);
      // The three requests and their three cancels: no free.
      expect(worker.received).toHaveLength(1 + 3 + 3);
    });

    it('made after the answer was handled changes nothing', async () => {
      const { client, workers } = setUp();
      const traced = client.trace({ algorithm: 'regions', from: [0, 0, 0], to: [1, 1, 0] });
      const worker = workers[0]!;
      worker.reply({ id: requestAt(worker, 0).id, ok: true, value: PATH });
      const trace = await traced.result;
      traced.cancel();
      expect(await traced.result).toBe(trace);
      expect(trace.alive).toBe(true);
      // No cancel, and no free of the trace the page now holds.
      expect(worker.received).toHaveLength(1);
    });

    it('stops the progress reported: a report that comes after it is not passed on', async () => {
      const { client, workers } = setUp();
      const reports: number[] = [];
      const traced = client.trace({ algorithm: 'regions', from: [0, 0, 0], to: [1, 1, 0] }, (progress) => reports.push(progress.pointsDone));
      const worker = workers[0]!;
      const { id } = requestAt(worker, 0);
      worker.reply({ id, progress: { pointsDone: 1, points: 2, done: false } });
      traced.cancel();
      worker.reply({ id, progress: { pointsDone: 2, points: 2, done: true } });
      worker.reply({ id, ok: false, failure: 'cancelled', message: 'AbortError: aborted' });
      await expect(traced.result).rejects.toBeInstanceOf(Cancelled);
      expect(reports).toEqual([1]);
    });

    it('still lets a crash of the worker say so', async () => {
      // The page restarts the worker and says why; a Cancelled would read as the user's own doing.
      const { client, workers, crashes } = setUp();
      const traced = client.trace({ algorithm: 'regions', from: [0, 0, 0], to: [1, 1, 0] });
      traced.cancel();
      workers[0]!.reply({ id: requestAt(workers[0]!, 0).id, ok: false, failure: 'crash', message: 'RuntimeError: unreachable' });
      await expect(traced.result).rejects.toBeInstanceOf(CoreCrash);
      expect(crashes).toEqual(['RuntimeError: unreachable']);
    });
  });
});
