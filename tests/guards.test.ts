// Issue 15 item 9: every argument of the JS API that JSON or wasm-bindgen
// would misread (a BigInt, a number for text, a string index, a freed
// handle, a stranger for a Trace) is refused with a VoxpathError naming it,
// before it reaches the core. Before these guards each of these was a
// TypeError, a RangeError with a garbled message ("step index 3..31"), a
// wasm "memory access out of bounds" or "null pointer passed to rust", or a
// silent misreading (stepTimes() returned nothing, dims '3' was read as 3).
import { runInNewContext } from 'node:vm';
import { describe, expect, it, vi } from 'vitest';
import {
  checkPoints,
  checkToTable,
  compare,
  comparisonToCsv,
  comparisonToTable,
  pulseTrains,
  randomLinesToCsv,
  randomLinesToTable,
  NO_VALUE,
  readDecision,
  readPoints,
  randomLines,
  runGcode,
  trace,
  traceCsvChunks,
  traceToCsv,
  traceToJson,
  traceToTable,
  VoxpathError,
} from '../web/core/index.js';
import type { Trace, TraceOptions } from '../web/core/index.js';
import { forOverwrite, readInRanges } from '../web/core/trace.js';
import { rejection, voxpath } from './helpers.js';

const LINE = { algorithm: 'regions', from: [0, 0, 0], to: [10, 7, 6] } satisfies TraceOptions;
const MACHINE = { stepsPerMm: 80 };

/** The VoxpathError `call` throws (failing the test if it returns or throws anything else). */
function thrown(call: () => unknown): VoxpathError {
  let error: unknown;
  try {
    call();
  } catch (e) {
    error = e;
  }
  expect(error).toBeInstanceOf(VoxpathError);
  return error as VoxpathError;
}

/** Calls that take nothing of the right type, for the type checker to let through. */
const any = (value: unknown) => value as never;

describe('the JS API refuses what the core would misread, naming the argument', () => {
  it('names a typed array with its article by sound: a Uint8Array, an Int32Array', async () => {
    const request = { algorithm: 'regions', from: [0, 0, 0], to: [1, 1, 1] } satisfies TraceOptions;
    expect((await rejection(checkPoints(request, { points: any(new Uint8Array(6)), dims: 3 }))).message).toBe(
      'points: expected { points: Int32Array or Float64Array, dims }, got points = a Uint8Array of length 6',
    );
    expect((await rejection(checkPoints(request, any(new Int32Array(6))))).message).toBe(
      'points: expected rows of coordinates, { points, dims } or text, got an Int32Array of length 6',
    );
  });

  it('says a hole, an undefined item and a number JSON cannot carry as what they are', async () => {
    // JSON makes a hole or undefined null, which the core called "got null".
    // eslint-disable-next-line no-sparse-arrays
    const hole = await rejection(trace({ ...LINE, from: any([0, , 0]) }));
    expect([hole.field, hole.message]).toEqual(['from', 'from: item 1 is a hole in a sparse array; give every item']);
    const undefinedItem = await rejection(trace({ ...LINE, to: any([1, undefined, 1]) }));
    expect(undefinedItem.message).toBe('to: item 1 is undefined; give a number');
    // NaN and Infinity are said as numbers, not as the text they travel as ("NaN").
    for (const [value, shown] of [[NaN, 'NaN'], [-Infinity, '-Infinity']] as const) {
      const e = await rejection(trace({ ...LINE, from: [0, 0, value] }));
      expect([e.field, e.axis, e.message]).toEqual(['from', 2, `from: z must be a number, got ${shown}`]);
    }
  });

  it('refuses BigInt and circular options by the option they are in', async () => {
    const bigFrom = await rejection(trace({ ...LINE, from: any([0n, 0, 0]) }));
    expect([bigFrom.field, bigFrom.message]).toEqual(['from', 'from: 0n is a BigInt; give a number (Number(0n))']);
    expect((await rejection(compare({ algorithms: ['regions', 'greedy'], from: [0, 0, 0], to: any([1n, 1, 1]) }))).field).toBe('to');
    expect((await rejection(runGcode('G1 X1 F100', { stepsPerMm: any(80n) }))).field).toBe('stepsPerMm');
    // NaN and Infinity cross as text: said as the numbers they were (as
    // trace() says them), not quoted as if a string had been given.
    for (const [settings, message] of [
      [{ stepsPerMm: Number.NaN }, 'stepsPerMm: expected a number, got NaN'],
      // In a per-axis list, the item's axis is named, as a point's is (README, Limits).
      [{ stepsPerMm: [80, 80, Number.POSITIVE_INFINITY] }, 'stepsPerMm: z must be a number, got Infinity'],
      [{ stepsPerMm: 80, acceleration: [10, Number.NaN, 10] }, 'acceleration: y must be a number, got NaN'],
      [{ stepsPerMm: 80, maxStepRate: [1000, 1000, '1000'] }, 'maxStepRate: z must be a number, got "1000"'],
      [{ stepAngle: [1.8, 1.8, 1.8], microsteps: [Number.NaN, 8, 8], pitch: 2 }, 'microsteps: x must be a number, got NaN'],
      [{ stepsPerMm: 80, junctionDeviation: Number.NaN }, 'junctionDeviation: expected a number, got NaN'],
    ] as const) {
      expect((await rejection(runGcode('G1 X1 F100', settings as never))).message).toBe(message);
    }
    expect((await rejection(randomLines({ algorithm: 'regions', count: any(5n) }))).field).toBe('count');
    // JSON leaves a function or a symbol out of an object: the option was
    // dropped and the core ran with its default (tie 'advance' for this one).
    for (const tie of [() => 'hold', Symbol('hold')]) {
      const e = await rejection(trace({ ...LINE, algorithm: 'bresenham3d', tie: any(tie) }));
      expect([e.field, e.message]).toEqual(['tie', `tie: is a ${typeof tie}; give a number, text, true or false, or a list`]);
    }
    // A getter that throws is named, not the option before it (it was 'to').
    const failing = await rejection(
      trace(
        any({
          ...LINE,
          get gcd(): boolean {
            throw new Error('boom');
          },
        }),
      ),
    );
    expect([failing.field, failing.message]).toEqual(['gcd', 'gcd: cannot be sent to the core as JSON: boom']);
    const failingToJson = await rejection(trace(any({ ...LINE, gcd: { toJSON: () => { throw new Error('bang'); } } })));
    expect([failingToJson.field, failingToJson.message]).toEqual(['gcd', 'gcd: cannot be sent to the core as JSON: bang']);
    const circular: Record<string, unknown> = { ...LINE };
    circular.self = circular;
    expect((await rejection(trace(any(circular)))).field).toBe('self');
    // No options at all: the core names the argument, as it does for null.
    for (const missing of [undefined, null, () => 1]) {
      expect((await rejection(trace(any(missing)))).field).toBe('request');
      expect((await rejection(randomLines(any(missing)))).field).toBe('request');
      expect((await rejection(runGcode('G1 X1 F100', any(missing)))).field).toBe('settings');
    }
  });

  it('refuses a G-code source that is neither a string nor UTF-8 bytes (12345 read wasm memory at address 12345)', async () => {
    for (const source of [12345, null, undefined, new Uint16Array(3), new DataView(new ArrayBuffer(2)), ['G1 X1']]) {
      const e = await rejection(runGcode(any(source), MACHINE));
      expect(e.field).toBe('source');
      expect(e.detail).toMatch(/^expected the program as a string or as UTF-8 bytes in a Uint8Array, got /);
    }
    expect((await rejection(runGcode(any(new Uint16Array(3)), MACHINE))).detail).toMatch(/Uint16Array of length 3 \(text of another encoding: decode it first/);
    // A DataView by its bytes ("of length undefined" before).
    expect((await rejection(runGcode(any(new DataView(new ArrayBuffer(4))), MACHINE))).detail).toMatch(/got a DataView of 4 bytes/);
    // UTF-8 bytes made in another realm are bytes too (instanceof fails across realms).
    const foreign = runInNewContext('new Uint8Array([71, 49, 32, 88, 49, 32, 70, 49, 48, 48])') as Uint8Array;
    expect(foreign instanceof Uint8Array).toBe(false);
    const program = await runGcode(foreign, MACHINE);
    expect([program.errors, program.moveCount]).toEqual([[], 1]);
    program.free();
  });

  it("refuses runGcode's options by name (a NaN sliceMs ran 0 lines a slice, forever)", async () => {
    const cases: [unknown, string][] = [
      [null, 'options'],
      [5, 'options'],
      [{ onProgress: 5 }, 'onProgress'],
      [{ signal: {} }, 'signal'],
      [{ sliceMs: Number.NaN }, 'sliceMs'],
      [{ sliceMs: 0 }, 'sliceMs'],
      [{ sliceMs: '20' }, 'sliceMs'],
      [{ sliceMs: Number.POSITIVE_INFINITY }, 'sliceMs'],
    ];
    for (const [options, field] of cases) expect((await rejection(runGcode('G1 X1 F100', MACHINE, any(options)))).field).toBe(field);
    // A key it does not know, as the core's options (a misspelt onprogress ran without a report).
    expect((await rejection(runGcode('G1 X1 F100', MACHINE, any({ onprogress: () => {} })))).message).toBe(
      'onprogress: runGcode does not take this option (did you mean onProgress?)',
    );
    expect((await rejection(runGcode('G1 X1 F100', MACHINE, any({ slices: 5 })))).message).toBe(
      'slices: runGcode does not take this option (it takes onProgress, signal, sliceMs)',
    );
  });

  it('takes step indices only as whole numbers inside the trace ("step index 3..31 is outside 0..10" before)', async () => {
    const t = await trace(LINE);
    const cases: [() => unknown, string, string][] = [
      [() => t.explain(any('3')), 'step', 'step index must be a whole number, got "3" (text)'],
      [() => t.explain(2.5), 'step', 'step index must be a whole number, got 2.5'],
      [() => t.explain(any(undefined)), 'step', 'step index must be a whole number, got nothing'],
      [() => t.explain(10), 'step', 'step index 10 is outside 0..9'],
      [() => t.explain(-1), 'step', 'step index -1 is outside 0..9'],
      [() => t.point(11), 'k', 'point index 11 is outside 0..10'],
      [() => t.point(any('1')), 'k', 'point index must be a whole number, got "1" (text)'],
      [() => t.pointsInRange(any('0'), 3), 'from', 'point index must be a whole number, got "0" (text)'],
      [() => t.pointsInRange(0, any(undefined)), 'to', 'point index must be a whole number, got nothing'],
      [() => t.pointsInRange(0, 2 ** 33), 'to', 'point index 8589934592 is outside 0..11'],
      [() => t.decisionsInRange(0, 1.5), 'to', 'step index must be a whole number, got 1.5'],
      [() => t.deviationInRange(2, 1), 'to', 'point index 1 is outside 2..11'],
      [() => t.axisErrorInRange(Number.NaN, 1), 'from', 'point index must be a whole number, got NaN'],
      [() => t.stepCodes(any(0n), any(1n)), 'from', 'step index must be a whole number, got 0n (a BigInt)'],
      [() => t.directionLevels(any(undefined), any(undefined)), 'from', 'step index must be a whole number, got nothing'],
      [() => pulseTrains(t, any('0'), 2), 'from', 'step index must be a whole number, got "0" (text)'],
      [() => pulseTrains(t, 0, 2, new Float64Array(3)), 'stepSeconds', 'expected the 2 instants of steps 0..2, got a Float64Array of length 3'],
      // Out of order, they gave a negative step rate; NaN, a rate of NaN.
      [() => pulseTrains(t, 3, 6, Float64Array.of(0.25, 0.5, 0.375)), 'stepSeconds', 'step 5 comes at 0.375 s, before step 4 at 0.5 s: instants go in step order'],
      [() => pulseTrains(t, 0, 2, Float64Array.of(0, Number.NaN)), 'stepSeconds', "step 1's instant is NaN, not a finite number of seconds"],
      [() => pulseTrains(t, 0, 1, Float64Array.of(Number.POSITIVE_INFINITY)), 'stepSeconds', "step 0's instant is Infinity, not a finite number of seconds"],
    ];
    for (const [call, field, detail] of cases) {
      const e = thrown(call);
      expect([e.field, e.detail, e.message]).toEqual([field, detail, `${field}: ${detail}`]);
    }
    // A trace of no steps has no step to explain.
    const still = await trace({ algorithm: 'regions', from: [1, 1, 1], to: [1, 1, 1] });
    expect(thrown(() => still.explain(0)).detail).toBe('step index 0: there is none (the range is empty)');
    expect(still.stepCodes(0, 0).length).toBe(0);
  });

  it('takes a Trace only where one is due (compareWith({}) threw "Cannot read private member")', async () => {
    const t = await trace(LINE);
    for (const other of [{}, null, undefined, { ...t }, 5]) {
      expect(thrown(() => t.compareWith(any(other))).field).toBe('other');
      expect(thrown(() => t.cellsOnlyIn(any(other))).field).toBe('other');
      expect(thrown(() => pulseTrains(any(other), 0, 1)).field).toBe('trace');
      for (const write of [traceToCsv, traceToJson, traceToTable]) expect(thrown(() => write(any(other))).field).toBe('trace');
      expect(thrown(() => traceCsvChunks(any(other)).next()).field).toBe('trace');
    }
    expect(thrown(() => t.compareWith(any({}))).detail).toBe('expected a Trace (from trace() or runGcode()), got an object');
  });

  it('refuses a freed trace or program by name ("null pointer passed to rust" before), and frees twice harmlessly', async () => {
    const kept = await trace(LINE);
    const freed = await trace(LINE);
    freed.free();
    const reads: ((t: Trace) => unknown)[] = [
      (t) => t.explain(0),
      (t) => t.points,
      (t) => t.decisions,
      (t) => t.pointsInRange(0, 1),
      (t) => t.stepCodes(0, 1),
      (t) => t.idealPolyline(),
      (t) => t.compareWith(kept),
      (t) => traceToCsv(t),
    ];
    for (const read of reads) {
      const e = thrown(() => read(freed));
      expect([e.field, e.detail]).toEqual(['trace', 'this trace was freed (free()); trace it again to read it']);
    }
    expect(thrown(() => kept.compareWith(freed)).field).toBe('other');
    expect(() => freed.free()).not.toThrow();
    // What a getter returned before the free, it keeps returning (it lives
    // in JavaScript), every getter alike; what was not read is refused.
    for (const read of [(t: Trace) => t.metrics, (t: Trace) => t.bounds, (t: Trace) => t.segments, (t: Trace) => t.deviation, (t: Trace) => t.axisError]) {
      expect(thrown(() => read(freed)).field).toBe('trace');
    }
    const cached = await trace(LINE);
    const before = [cached.points, cached.decisions, cached.deviation, cached.axisError, cached.metrics, cached.bounds, cached.segments];
    cached.free();
    expect([cached.points, cached.decisions, cached.deviation, cached.axisError, cached.metrics, cached.bounds, cached.segments]).toEqual(before);
    expect(cached.metrics).toBe(before[4]);

    const program = await runGcode('G1 X10 Y5 F600', MACHINE);
    program.free();
    for (const read of [() => program.stepTimes(0, 1), () => program.speedProfile(), () => program.vcd()]) {
      expect(thrown(read).field).toBe('program');
    }
    expect(thrown(() => program.trace.explain(0)).field).toBe('trace');
    expect(() => program.free()).not.toThrow();
    // The VCD reads the trace too: a trace freed on its own is named.
    const halfFreed = await runGcode('G1 X10 Y5 F600', MACHINE);
    halfFreed.trace.free();
    expect(thrown(() => halfFreed.vcd()).field).toBe('trace');
    halfFreed.free();
  });

  it("checks a program's step and line arguments (stepTimes() returned nothing, moveAtLine('1') nothing)", async () => {
    const p = await runGcode('G1 X10 Y5 F600', MACHINE);
    const cases: [() => unknown, string][] = [
      [() => p.stepTimes(any(undefined), any(undefined)), 'from'],
      [() => p.stepTimes(any('0'), 2), 'from'],
      [() => p.stepTimes(0.5, 2), 'from'],
      [() => p.stepTimes(0, p.steps + 1), 'to'],
      [() => p.moveOfStep(any('1')), 'k'],
      [() => p.lineOfStep(any(undefined)), 'k'],
      [() => p.lineByStepInRange(0, any(undefined)), 'to'],
      [() => p.moveAtLine(any('1')), 'line'],
      [() => p.pointBeforeLine(any('x')), 'line'],
      [() => p.pointBeforeLine(0), 'line'],
      // null and [] were read as 0 s, 5n threw a TypeError from the glue.
      [() => p.pointAtSeconds(any(null)), 'seconds'],
      [() => p.pointAtSeconds(any([])), 'seconds'],
      [() => p.pointAtSeconds(any(5n)), 'seconds'],
      [() => p.pointAtSeconds(Number.NaN), 'seconds'],
      [() => p.motionChart(any(null), 1, 10), 'fromSeconds'],
      [() => p.dwellSeconds(any(null), 1), 'fromSeconds'],
      [() => p.dwellSeconds(0, Number.NaN), 'toSeconds'],
      [() => p.motionChart(0, any('1'), 10), 'toSeconds'],
    ];
    for (const [call, field] of cases) expect(thrown(call).field).toBe(field);
    expect(p.stepTimes(0, 2).length).toBe(2);
    expect(p.pointAtSeconds(Number.POSITIVE_INFINITY)).toBe(p.steps);
    // A window's infinite end is the program's (it was refused naming a
    // 'window' no argument has), a reversed one names toSeconds, and one
    // past the end is empty at the end (it came back reversed).
    expect(p.motionChart(0, Number.POSITIVE_INFINITY, 10)).toEqual(p.motionChart(0, p.durationSeconds, 10));
    expect(thrown(() => p.motionChart(2, 1, 10)).field).toBe('toSeconds');
    const past = p.motionChart(5000, 6000, 10);
    expect([past.fromSeconds, past.toSeconds, past.seconds.length]).toEqual([p.durationSeconds, p.durationSeconds, 0]);
    p.free();
  });

  it("checks a learner's points before the core reads them ('0x10' would be 16, dims -1 was 4294967295)", async () => {
    const request = { algorithm: 'regions', from: [0, 0, 0], to: [1, 1, 1] } satisfies TraceOptions;
    const cases: [unknown, string, string][] = [
      [[[0n, 0n, 0n]], 'points', 'point 0: x must be a number, got 0n (a BigInt)'],
      [[['0', '0', '0x10']], 'points', 'point 0: x must be a number, got "0" (text)'],
      [[[0, 0, 0], null], 'points', 'point 1 is null; expected an array of coordinates'],
      [null, 'points', 'expected rows of coordinates, { points, dims } or text, got null'],
      [new Int32Array(6), 'points', 'expected rows of coordinates, { points, dims } or text, got an Int32Array of length 6'],
      [{ points: [0, 0, 0], dims: 3 }, 'points', 'expected { points: Int32Array or Float64Array, dims }, got points = an Array of length 3'],
      [{ points: new Int32Array(6), dims: '3' }, 'dims', 'coordinates per point must be a whole number, got "3" (text)'],
      [{ points: new Int32Array(6), dims: -1 }, 'dims', 'coordinates per point -1 is outside 1..4294967295'],
    ];
    for (const [points, field, detail] of cases) {
      const e = await rejection(checkPoints(request, any(points)));
      expect([e.field, e.detail]).toEqual([field, detail]);
    }
    for (const text of [null, 5, new Uint8Array(3)]) {
      const e = await rejection(readPoints(any(text), 3));
      expect(e.field).toBe('text');
      expect(e.detail).toMatch(/^expected the points as a string, got /);
    }
    expect((await rejection(readPoints('0 0 0', any('3')))).field).toBe('dims');
    // What the guards pass still reaches the core, which reads it as before.
    expect((await checkPoints(request, { points: new Int32Array([0, 0, 0, 1, 1, 1]), dims: 3 })).matches).toBe(true);
  });
});

describe("the writers of plain data refuse what is not that data, naming the argument (comparisonToCsv(null) threw 'Cannot read properties of null')", () => {
  it('refuses null, numbers, BigInt, text, arrays, a Trace (live or freed) and objects missing a field', async () => {
    const live = await trace(LINE);
    const freed = await trace(LINE);
    freed.free();
    const strangers: unknown[] = [null, undefined, 5, 5n, 'comparison', [], new Float64Array(2), () => 1, live, freed];
    const comparison = await compare({ algorithms: ['regions', 'greedy'], from: [0, 0, 0], to: [10, 7, 6] });
    const lines = await randomLines({ algorithm: 'regions', count: 3, seed: 1 });
    const check = await checkPoints(LINE, '0,0,0\n1,1,1\n');
    const writers: [(value: never) => string, string, unknown, string][] = [
      [comparisonToCsv, 'comparison', comparison, 'b'],
      [comparisonToTable, 'comparison', comparison, 'onlyInA'],
      [randomLinesToCsv, 'result', lines, 'lines'],
      [randomLinesToTable, 'result', lines, 'perpendicular'],
      [checkToTable, 'check', check, 'alsoMatches'],
    ];
    for (const [write, field, good, needed] of writers) {
      for (const stranger of strangers) expect(thrown(() => write(any(stranger))).field).toBe(field);
      // One field short of the real thing.
      const short = { ...(good as object) } as Record<string, unknown>;
      delete short[needed];
      expect(thrown(() => write(any(short))).detail).toMatch(new RegExp(`^expected .*, got an object without ${needed}$`));
      // A field set to undefined is as missing (it threw a TypeError from inside the writer).
      expect(thrown(() => write(any({ ...(good as object), [needed]: undefined }))).detail).toMatch(new RegExp(`^expected .*, got an object without ${needed}$`));
      // The real thing still writes.
      expect(write(any(good)).length).toBeGreaterThan(0);
    }
    expect(thrown(() => comparisonToCsv(any(null))).message).toBe('comparison: expected a Comparison (from compare() or compareWith()), got null');
    expect(thrown(() => checkToTable(any(live))).detail).toMatch(/^expected a Check \(from checkPoints\(\)\), got a Trace without /);
  });

  it("readDecision takes a column and a number (a null column threw 'reading kind'; text was returned as it was)", async () => {
    const region = (await trace(LINE)).columns.find((c) => c.name === 'region')!;
    for (const column of [null, undefined, 5, 'region', {}, [region]]) expect(thrown(() => readDecision(any(column), 1)).field).toBe('column');
    for (const value of [null, undefined, '1', 1n, [1]]) {
      const e = thrown(() => readDecision(region, any(value)));
      expect([e.field, e.detail]).toEqual(['value', `expected a decision value (a number), got ${value === null ? 'null' : value === undefined ? 'nothing' : value === '1' ? '"1" (text)' : value === 1n ? '1n (a BigInt)' : 'an Array of length 1'}`]);
    }
    expect(readDecision(region, Number.NaN)).toBeNull();
    expect(readDecision(region, NO_VALUE)).toBeNull();
    // A value no label has (99 came back as 99), and a flag's that is not 0 or 1.
    if (region.kind !== 'category') throw new Error('region is a category column');
    for (const value of [99, -1, 1.5, region.labels.length]) {
      expect(thrown(() => readDecision(region, value)).message).toBe(`value: ${value} is not a value of the category column region: 0 to ${region.labels.length - 1}, or NO_VALUE (255) where it does not apply`);
    }
    const tie = (await trace(LINE)).columns.find((c) => c.kind === 'flag')!;
    expect([readDecision(tie, 0), readDecision(tie, 1), readDecision(tie, NO_VALUE)]).toEqual([false, true, null]);
    expect(thrown(() => readDecision(tie, 2)).field).toBe('value');
  });

  it('pulseTrains takes step instants only as a Float64Array of the range (text of length 1 was read as one instant)', async () => {
    const t = await trace(LINE);
    for (const seconds of ['x', [0], null, new Float32Array(1)]) {
      const e = thrown(() => pulseTrains(t, 0, 1, any(seconds)));
      expect(e.field).toBe('stepSeconds');
    }
    expect(pulseTrains(t, 0, 1, new Float64Array(1)).length).toBe(3);
    // Instants in step order; two at one instant are an infinite rate, as a program may plan them.
    const [x] = pulseTrains(t, 0, 3, Float64Array.of(0.25, 0.5, 0.5));
    expect([Array.from(x!.edgeSeconds!), Array.from(x!.rateHz!)]).toEqual([
      [0.25, 0.5, 0.5],
      [Number.NaN, 4, Number.POSITIVE_INFINITY],
    ]);
  });
});

describe('a G-code run past what its outputs hold', () => {
  it('refuses a VCD of a program longer than its 1 ns ticks reach (every edge was pressed onto the last tick)', async () => {
    const p = await runGcode('G1 X10 Y5 F600\nG1 X0', { stepsPerMm: 80, acceleration: 1e-100 });
    expect(p.durationSeconds).toBeGreaterThan(1e50);
    const e = thrown(() => p.vcd());
    expect(e.field).toBe('program');
    expect(e.detail).toMatch(/^the program lasts 1\.255e51 s on its planned profile, past the 1\.845e10 s \(584 years\)/);
    p.free();
    // The CLI names the program, not a flag --program, and says it as the program's fault (status 1,
    // as a program's errors), not the command line's (status 2 and the usage).
    const r = voxpath(['gcode', '-', '--steps-per-mm', '80', '--acceleration', '1e-100', '--format', 'vcd'], 'G1 X10 Y5 F600\nG1 X0\n');
    expect([r.code, r.stdout]).toEqual([1, '']);
    expect(r.stderr).toMatch(/^voxpath: program: the program lasts 1\.255e51 s[^\n]*\n$/);
  });
});

describe('the arrays a trace hands out, past what one Node Buffer holds', () => {
  // A trace's points, deviations and axis errors are made for the core to
  // fill by forOverwrite. At the cap of 1,000,000,000 steps a 3D line's
  // points are 12 GB and its deviations 8 GB: Node's Buffer stops at 4 GiB,
  // and those reads were a RangeError on its "size", naming nothing given.
  // (A trace that long takes a minute and 2 GB to make, so the allocation
  // is tested on its own; a typed array past 4 GiB is only reserved, never
  // touched, here.)
  it('makes an array longer than 4 GiB as a plain typed array', () => {
    const length = 2 ** 30 + 1;
    const points = forOverwrite(Int32Array, length, readInRanges);
    expect([points.constructor, points.length, points.byteLength]).toEqual([Int32Array, length, 4 * length]);
  });

  it('names the argument when no array that long can be made here', () => {
    const e = thrown(() => forOverwrite(Float64Array, 2 ** 32 + 1, readInRanges));
    expect(e.field).toBe('to');
    expect(e.detail).toMatch(/^4294967297 values \(34359738376 bytes\) are more than one Float64Array can hold here \(.+\): read them a range at a time$/);
  });

  it("says an ideal line too long to make as the line's, naming no argument: idealLine() takes none", async () => {
    const made = await trace({ algorithm: 'regions', from: [0, 0, 0], to: [10, 7, 6] });
    // A runtime that cannot make the line's array (its 2 x 3 x 2 values
    // stand for the 700,000,000-vertex line that could not be made here).
    const Refusing = class Float32Array extends globalThis.Float32Array {
      constructor(length: number) {
        if (typeof length === 'number') throw new RangeError('Array buffer allocation failed');
        super(length);
      }
    };
    vi.stubGlobal('Float32Array', Refusing);
    try {
      const e = thrown(() => made.idealLine());
      expect([e.field, e.message]).toEqual([undefined, 'the ideal line of 2 vertices (x, y, z and what rounding left of each): 12 values (48 bytes) are more than one Float32Array can hold here (Array buffer allocation failed)']);
    } finally {
      vi.unstubAllGlobals();
      made.free();
    }
  });
});
