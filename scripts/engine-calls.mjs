#!/usr/bin/env node
// Counts, site by site, the wasm instructions that V8 runs as calls out of
// the compiled code: every `memory.copy` and `memory.fill` the compiler left
// (a copy or a clear of more than 64 bytes it could not keep in registers,
// about 7 ns a call on the bench's machine, measured apart). A loop that
// makes one a step or a segment pays it millions of times; this is how the
// "calls into the engine" in docs/benchmark-history.md were found.
//
//   node scripts/setup.mjs lib && node scripts/engine-calls.mjs [sites]
//
// The core that `setup lib` built is bound again with its function names
// kept (wasm-bindgen --keep-debug), disassembled (binaryen's wasm-dis), each
// such instruction replaced by a call to a function of its own that adds one
// to a counter (an exported global) and then does it, and assembled again
// (wasm-as). A copy of lib/ runs the end-to-end bench's requests and the
// G-code bench's program at 1 and 80 steps/mm through that core, each once
// to warm up and once counted, and prints the sites called most in the
// counted run, with the function each lies in. Counts, not times: they do
// not move with the machine's load.
import { spawnSync } from 'node:child_process';
import { cpSync, existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { homedir, tmpdir } from 'node:os';
import { delimiter, join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { openModuleRunner } from '../bench/module-runner.mjs';

const ROOT = fileURLToPath(new URL('..', import.meta.url));
const LIB = join(ROOT, 'lib');
const CORE_WASM = join(ROOT, 'rust', 'target', 'wasm32-unknown-unknown', 'release', 'voxpath.wasm');
const SITES_SHOWN = Number.parseInt(process.argv[2] ?? '6', 10);
/** The exported name of the glue's wasm exports, set on globalThis by the patched glue. */
const EXPORTS_NAME = '__voxpathEngineCalls';
/** The wasm features the core is built with (wasm-as refuses what it is not told of). */
const FEATURES = ['--enable-bulk-memory', '--enable-simd', '--enable-nontrapping-float-to-int', '--enable-sign-ext', '--enable-mutable-globals', '--enable-reference-types', '--enable-multivalue'];

process.env.PATH = [join(ROOT, 'node_modules', '.bin'), join(process.env.CARGO_HOME ?? join(homedir(), '.cargo'), 'bin'), process.env.PATH ?? ''].join(delimiter);

/** Runs a tool, its output shown only when it fails. @param {string} cmd @param {string[]} args */
function run(cmd, args) {
  const result = spawnSync(cmd, args, { encoding: 'utf8' });
  if (result.status !== 0) {
    console.error(`engine-calls: ${cmd} ${args.join(' ')} failed (${result.error?.message ?? `exit ${result.status}`})\n${result.stderr ?? ''}`);
    process.exit(2);
  }
}

/**
 * The module's text with every memory.copy and memory.fill a call to a
 * counting function of its own, and the sites: [kind, function] by index.
 * wasm-dis writes each instruction's opening on a line of its own, its
 * three operands after it, so the opening alone is replaced.
 * @param {string} text
 */
function instrument(text) {
  /** @type {[string, string][]} */
  const sites = [];
  let inFunction = '?';
  const lines = text.split('\n').map((/** @type {string} */ line) => {
    const opened = /^ \(func \$(\S+)/.exec(line);
    if (opened) inFunction = opened[1];
    const op = line.trim();
    if (op !== '(memory.copy' && op !== '(memory.fill') return line;
    sites.push([op.slice(1), inFunction]);
    return line.replace(op, `(call $__engine_call_${sites.length - 1}`);
  });
  const counters = sites.flatMap(([op], k) => [
    ` (global $__engine_calls_${k} (export "__engine_calls_${k}") (mut i32) (i32.const 0))`,
    ` (func $__engine_call_${k} (param i32 i32 i32) (global.set $__engine_calls_${k} (i32.add (global.get $__engine_calls_${k}) (i32.const 1))) (${op} (local.get 0) (local.get 1) (local.get 2)))`,
  ]);
  const body = lines.join('\n').trimEnd();
  // The module's closing parenthesis is the text's last character.
  return { text: `${body.slice(0, -1)}\n${counters.join('\n')}\n)\n`, sites };
}

if (!existsSync(join(LIB, 'core', 'index.js')) || !existsSync(CORE_WASM)) {
  console.error('engine-calls: the core is not built; run `node scripts/setup.mjs lib` first');
  process.exit(2);
}
const work = mkdtempSync(join(tmpdir(), 'voxpath-engine-calls-'));
try {
  const pkg = join(work, 'pkg');
  run('wasm-bindgen', ['--target', 'web', '--weak-refs', '--keep-debug', '--out-dir', pkg, '--out-name', 'voxpath', CORE_WASM]);
  run('wasm-dis', [join(pkg, 'voxpath_bg.wasm'), '-o', join(work, 'core.wat')]);
  const { text, sites } = instrument(readFileSync(join(work, 'core.wat'), 'utf8'));
  writeFileSync(join(work, 'counted.wat'), text);
  const lib = join(work, 'lib');
  cpSync(LIB, lib, { recursive: true });
  run('wasm-as', [...FEATURES, join(work, 'counted.wat'), '-o', join(lib, 'core', 'pkg', 'voxpath_bg.wasm')]);
  const glue = readFileSync(join(pkg, 'voxpath.js'), 'utf8');
  if (!glue.includes('wasm = instance.exports;')) throw new Error("wasm-bindgen's glue no longer sets `wasm = instance.exports;`");
  writeFileSync(join(lib, 'core', 'pkg', 'voxpath.js'), glue.replace('wasm = instance.exports;', `wasm = instance.exports; globalThis.${EXPORTS_NAME} = wasm;`));

  /** @type {typeof import('../web/core/index.js')} */
  const api = await import(pathToFileURL(join(lib, 'core', 'index.js')).href);
  // The end-to-end bench's requests and the G-code bench's program, from
  // their TypeScript (bench/module-runner.mjs).
  const modules = await openModuleRunner(ROOT);
  /** @type {typeof import('../bench/end-to-end.bench.ts')} */
  const { FROM_3D, TO_3D, CIRCLE, HELIX } = await modules.runner.import(join(ROOT, 'bench', 'end-to-end.bench.ts'));
  /** @type {typeof import('../bench/programs.ts')} */
  const { generateProgram } = await modules.runner.import(join(ROOT, 'bench', 'programs.ts'));
  await modules.close();
  /** Each site's calls so far, from the counted core's exports (on globalThis once the core is loaded). */
  const counts = () => {
    const exports = /** @type {Record<string, WebAssembly.Global>} */ (/** @type {Record<string, unknown>} */ (globalThis)[EXPORTS_NAME]);
    return sites.map((_, k) => /** @type {number} */ (exports[`__engine_calls_${k}`]?.value));
  };
  const line = { from: FROM_3D, to: TO_3D };
  /**
   * A case: its name, and one run of it returning what is to be freed.
   * @typedef {{ name: string, once: () => Promise<{ free(): void }> }} Case
   */
  /** A trace with its points read, as the end-to-end bench reads it. @returns {Case} */
  const traced = (/** @type {string} */ name, /** @type {import('../web/core/index.js').TraceOptions} */ request) => ({
    name: `${name}, trace and points`,
    once: async () => {
      const t = await api.trace(request);
      void t.points;
      return t;
    },
  });
  /** @type {Case[]} */
  const cases = [
    ...(/** @type {const} */ (['bresenham3d', 'regions', 'greedy', 'walk6'])).map((algorithm) => traced(`${algorithm}, the bench's 3D line`, { algorithm, ...line })),
    traced("the bench's circle", { algorithm: 'circle', ...CIRCLE }),
    traced("the bench's helix", { algorithm: 'helix', ...HELIX }),
    traced("arc-segments, the bench's circle", { algorithm: 'arc-segments', ...CIRCLE }),
  ];
  const source = generateProgram(100_000);
  for (const stepsPerMm of [1, 80]) {
    cases.push({ name: `the G-code bench's program at ${stepsPerMm} step${stepsPerMm === 1 ? '' : 's'}/mm`, once: () => api.runGcode(source, { stepsPerMm }) });
  }
  console.log(`${sites.length} memory.copy and memory.fill sites in the core; per case, the ${SITES_SHOWN} called most in one run:`);
  for (const { name, once } of cases) {
    (await once()).free();
    const before = counts();
    (await once()).free();
    const called = counts().map((n, k) => [n - before[k], k]).filter(([n]) => n > 0).sort((a, b) => b[0] - a[0]);
    console.log(`\n${name}: ${called.reduce((sum, [n]) => sum + n, 0).toLocaleString('en-US')} calls`);
    for (const [n, k] of called.slice(0, SITES_SHOWN)) console.log(`  ${n.toLocaleString('en-US').padStart(10)}  ${sites[k][0]}  in ${sites[k][1]}`);
  }
} finally {
  rmSync(work, { recursive: true, force: true });
}
