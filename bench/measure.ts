/**
 * Measuring helpers the bench files share: the best of several runs (the
 * one least disturbed by other work on the machine), the native numbers
 * from the Rust example, the core's raw trace, and trace() as users call
 * it (which computes no metrics: they wait until first read).
 */
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { setFlagsFromString } from 'node:v8';
import { runInNewContext } from 'node:vm';
import { trace } from '../web/core/index.js';
import type { TraceOptions } from '../web/core/index.js';
import { encodeRequest } from '../web/core/request.js';
import { loadCore } from '../web/core/wasm.js';
import { REFERENCES } from './reference/index.js';
import type { ReferenceOptions } from './reference/index.js';
import type { BenchRow } from './types.js';

// V8's collector, callable: a context made after --expose-gc is set has
// gc() as a global (bench/run.mjs is started without the flag).
setFlagsFromString('--expose-gc');
const gc = runInNewContext('gc') as (options: { type: 'minor' | 'major' }) => void;

/**
 * A young-generation collection, untimed, before a timed run: it frees the
 * arrays the runs before left behind (an ArrayBuffer dies young), then
 * waits SETTLE_MS for the collector's threads to finish giving that memory
 * back before the clock starts. Not a full collection: in two whole runs of
 * the end-to-end table with one, the peers that write through a callback
 * (a new closure each run) ran 3 to 4 times slower than with none, as if
 * their optimised code were thrown away with the closures that died.
 */
export async function collectGarbage(): Promise<void> {
  gc({ type: 'minor' });
  await new Promise((resolve) => setTimeout(resolve, SETTLE_MS));
}

/** Milliseconds to wait after collecting garbage before a timed run. */
const SETTLE_MS = 20;

/** Timed runs of each measurement, after one untimed run; the fastest counts. */
const REPEAT = 5;

/**
 * Seconds of the fastest of `repeat` runs of `run`, after one run that is
 * not timed: V8 compiles both JavaScript and wasm in tiers, optimising what
 * runs hot, so a first run measures the compiler as much as the code.
 */
async function bestSeconds(run: () => unknown, repeat = REPEAT): Promise<number> {
  await run();
  let best = Infinity;
  for (let i = 0; i < repeat; i++) {
    const start = performance.now();
    await run();
    best = Math.min(best, (performance.now() - start) / 1000);
  }
  return best;
}

/** What rust/examples/bench.rs reports for one request (seconds, best of its runs). */
export interface NativeResult {
  steps: number;
  recordSeconds: number;
  metricsSeconds: number;
  /** regions only: the stepper alone, nothing recorded. */
  stepperSeconds: number | null;
}

const MANIFEST = fileURLToPath(new URL('../rust/Cargo.toml', import.meta.url));

/** Runs the native example (a release build: cargo builds it on first use) on `requests`. */
export function native(requests: TraceOptions[], repeat = REPEAT): NativeResult[] {
  const cases = requests.map((request) => ({ request, repeat }));
  const run = spawnSync('cargo', ['run', '--quiet', '--release', '--manifest-path', MANIFEST, '--example', 'bench'], {
    input: JSON.stringify(cases),
    encoding: 'utf8',
    stdio: ['pipe', 'pipe', 'inherit'],
    maxBuffer: 1 << 20,
  });
  if (run.status !== 0) throw new Error(`cargo run --example bench failed (exit ${run.status ?? run.signal})`);
  return JSON.parse(run.stdout) as NativeResult[];
}

/**
 * Seconds of the core's trace in wasm with its steps recorded. The raw
 * binding, as the public trace(), plans a line or an arc (its start, end
 * and length, nothing stepped: its points, read first, come from the plan;
 * the end-to-end table times them) and records its steps when something
 * first reads one, so each run reads the first step's code. The binding
 * timed alone, as it was until plans came in, then timed the plan: 10^5 to
 * 10^6 M steps/s in both wasm columns, and wasm/TS ratios in the thousands.
 * A circle's or helix's plan counts its steps by Saleem's dry run, and the
 * recording runs it again (each run pays for it twice; the native example
 * records without a plan, once).
 */
async function wasmStepsSeconds(request: TraceOptions): Promise<number> {
  const core = await loadCore();
  const json = encodeRequest(request);
  // The raw binding: the public trace() also asks for the summary and
  // makes the Trace object around it.
  return bestSeconds(() => {
    const handle = core.trace(json);
    handle.stepCodes(0, 1);
    handle.free();
  });
}

/** Seconds of trace() as users call it, with its steps recorded by a read of the first step's code (no metrics: they are computed when first read). */
async function wasmFullSeconds(request: TraceOptions): Promise<number> {
  return bestSeconds(async () => {
    const t = await trace(request);
    t.stepCodes(0, 1);
    t.free();
  });
}

/** Seconds of the plain TypeScript reference of `request.algorithm`. */
async function typescriptSeconds(request: TraceOptions): Promise<number> {
  const { algorithm, ...options } = request;
  const reference = REFERENCES[algorithm];
  if (!reference) throw new Error(`no TypeScript reference for ${algorithm}`);
  return bestSeconds(() => reference(options as ReferenceOptions));
}

/** Column names shared by the bench files, so their tables line up. */
export const COLUMNS = {
  nativeSteps: 'native steps',
  nativeFull: 'native full',
  wasmSteps: 'wasm steps',
  wasmFull: 'wasm full',
  typescriptSteps: 'TS steps',
  ratio: 'wasm/TS steps',
} as const;

/** What the shared columns measure. */
export const COLUMN_NOTES = [
  `${COLUMNS.nativeSteps} / ${COLUMNS.wasmSteps}: stepping and recording, as the core's trace does when a step is first read (2 bytes per step, a position and a stepper state every 4096 steps; circles and helices include Saleem's dry run). In wasm, the raw binding's plan (trace() plans a line or an arc and records it when a step is read; its points alone come from the plan, timed in the end-to-end table) and the read of the first step's code that records it.`,
  `${COLUMNS.nativeFull}: the same plus the metrics pass (deviation and per-axis error of every point). ${COLUMNS.wasmFull}: trace() as users call it, the summary and the Trace object included, and the first step's code read; no metrics, which the core computes only when they are first read.`,
  `${COLUMNS.typescriptSteps}: the plain TypeScript reference (bench/reference) filling a Uint16Array with the same step codes (tests/reference.test.ts checks they are the core's), dry runs included.`,
  `${COLUMNS.ratio}: wasm steps over TS steps, like with like. Rates are steps per second, the best of ${REPEAT} runs after one untimed run.`,
];

/** One row: every measurement of one request, with its native result. */
export async function measureRow(name: string, request: TraceOptions, nativeResult: NativeResult): Promise<BenchRow> {
  const steps = nativeResult.steps;
  const [wasmSteps, wasmFull, typescript] = [
    await wasmStepsSeconds(request),
    await wasmFullSeconds(request),
    await typescriptSeconds(request),
  ];
  return {
    name,
    steps,
    rates: {
      [COLUMNS.nativeSteps]: steps / nativeResult.recordSeconds,
      [COLUMNS.nativeFull]: steps / (nativeResult.recordSeconds + nativeResult.metricsSeconds),
      [COLUMNS.wasmSteps]: steps / wasmSteps,
      [COLUMNS.wasmFull]: steps / wasmFull,
      [COLUMNS.typescriptSteps]: steps / typescript,
    },
    ratios: { [COLUMNS.ratio]: typescript / wasmSteps },
  };
}
