#!/usr/bin/env node
// Brings a checkout to the point where `vite`, `vite build` or the tests can
// run: npm packages, the Rust wasm toolchain, the wasm package web/core/pkg,
// the library lib/ and (for tests) Chromium.
//
//   node scripts/setup.mjs [start|build|lib|test]     (default: build)
//
// Every step is skipped when its result is already there, so a second run
// takes well under a second and prints nothing. Build steps are keyed on a
// hash of their inputs, stored in .setup-stamps/; delete that folder to force
// everything to be checked and rebuilt. Plain Node with no npm dependencies,
// because it runs before `npm install`.
import { spawnSync } from 'node:child_process';
import { createHash } from 'node:crypto';
import { cpSync, existsSync, mkdirSync, readFileSync, readdirSync, rmSync, writeFileSync } from 'node:fs';
import { homedir } from 'node:os';
import { basename, delimiter, dirname, join, relative } from 'node:path';
import { fileURLToPath } from 'node:url';
import { CHROMIUM_HINT, findChromium } from './chromium.mjs';

const ROOT = dirname(dirname(fileURLToPath(import.meta.url)));
const STAMPS = join(ROOT, '.setup-stamps');
const CRATE = join(ROOT, 'rust');
const PKG = join(ROOT, 'web', 'core', 'pkg');
const WASM_TARGET = 'wasm32-unknown-unknown';
// Pinned so that CI installs the wasm-pack the build was tried with.
const WASM_PACK_VERSION = '0.15.1';
// --weak-refs: wasm-bindgen frees Rust objects whose JS wrappers were garbage
// collected (FinalizationRegistry), so a forgotten .free() does not leak.
const WASM_PACK_ARGS = [
  'build', 'rust', '--release', '--target', 'web', '--weak-refs',
  '--out-dir', '../web/core/pkg', '--out-name', 'voxpath',
];

class SetupError extends Error {}

/** @param {string} message @returns {never} */
function fail(message) {
  throw new SetupError(message);
}

/**
 * One line per step that actually does something, on stderr as all of this
 * script's output: it runs as the package's prepack, and `npm pack --json`
 * hands its caller stdout, which must stay JSON (a build of lib/ by prepack
 * put "setup: tsc ..." before it).
 * @param {string} message
 */
function step(message) {
  console.error(`setup: ${message}`);
}

// Children find the tools this script installs: node_modules/.bin first, so
// wasm-pack picks binaryen's wasm-opt (its own download cannot work offline),
// then cargo's bin folder, where `cargo install` puts wasm-bindgen and wasm-pack.
const cargoBin = join(process.env.CARGO_HOME ?? join(homedir(), '.cargo'), 'bin');
process.env.PATH = [join(ROOT, 'node_modules', '.bin'), cargoBin, process.env.PATH ?? ''].join(delimiter);

/**
 * Runs a command with output shown to the user, its stdout on this script's
 * stderr (see step); fails setup when it fails.
 * @param {string} cmd @param {string[]} args @param {string} [cwd]
 */
function run(cmd, args, cwd = ROOT) {
  const result = spawnSync(cmd, args, { cwd, stdio: ['inherit', 2, 'inherit'] });
  if (result.error) fail(`cannot run ${cmd}: ${result.error.message}`);
  if (result.status !== 0) fail(`\`${[cmd, ...args].join(' ')}\` failed (exit ${result.status ?? result.signal})`);
}

/**
 * Output of a quick query command, or null when it is missing or fails.
 * @param {string} cmd @param {string[]} args @param {string} [cwd]
 */
function query(cmd, args, cwd = ROOT) {
  const result = spawnSync(cmd, args, { cwd, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
  return result.status === 0 ? result.stdout.trim() : null;
}

/** All files under a folder (none when it is missing), in a stable order. @param {string} dir @returns {string[]} */
function listFiles(dir) {
  if (!existsSync(dir)) return [];
  return readdirSync(dir, { withFileTypes: true, recursive: true })
    .filter((entry) => entry.isFile())
    .map((entry) => join(entry.parentPath, entry.name))
    .sort();
}

/** Hash of file names and contents (missing files count as absent), plus extra strings. @param {string[]} files @param {string[]} [extra] */
function hashInputs(files, extra = []) {
  const hash = createHash('sha256');
  for (const file of files) {
    if (!existsSync(file)) continue;
    hash.update(`${relative(ROOT, file)}\0`).update(readFileSync(file)).update('\0');
  }
  for (const text of extra) hash.update(`${text}\0`);
  return hash.digest('hex');
}

/** @param {string} name */
function readStamp(name) {
  const file = join(STAMPS, name);
  return existsSync(file) ? readFileSync(file, 'utf8') : null;
}

/** @param {string} name @param {string} value */
function writeStamp(name, value) {
  mkdirSync(STAMPS, { recursive: true });
  writeFileSync(join(STAMPS, name), value);
}

/** npm packages, installed again whenever the dependency lists or the lockfile change. */
function npmPackages() {
  const lockfile = join(ROOT, 'package-lock.json');
  const key = () => {
    const manifest = JSON.parse(readFileSync(join(ROOT, 'package.json'), 'utf8'));
    // Only the dependency fields: editing "scripts" must not reinstall.
    const deps = ['dependencies', 'devDependencies', 'optionalDependencies', 'peerDependencies', 'overrides']
      .map((field) => JSON.stringify(manifest[field] ?? null));
    return hashInputs([lockfile], deps);
  };
  if (existsSync(join(ROOT, 'node_modules')) && readStamp('npm') === key()) return;
  const command = existsSync(lockfile) ? 'ci' : 'install';
  step(`npm ${command}`);
  run('npm', [command, '--no-audit', '--no-fund']);
  writeStamp('npm', key());
}

/** The wasm32 target of the Rust toolchain that rust/ uses. */
function rustTarget() {
  const installed = query('rustup', ['target', 'list', '--installed'], CRATE);
  if (installed === null) fail('rustup not found (or failing): install Rust with rustup, then run this again');
  if (installed.split(/\s+/).includes(WASM_TARGET)) return;
  step(`rustup target add ${WASM_TARGET}`);
  run('rustup', ['target', 'add', WASM_TARGET], CRATE);
}

/** The wasm-bindgen version pinned with "=X.Y.Z" in rust/Cargo.toml, the one place it is written. */
function pinnedWasmBindgen() {
  const manifest = join(CRATE, 'Cargo.toml');
  if (!existsSync(manifest)) fail('rust/Cargo.toml not found');
  const line = readFileSync(manifest, 'utf8')
    .match(/^\s*wasm-bindgen\s*=\s*(?:"([^"]*)"|\{[^}\n]*\bversion\s*=\s*"([^"]*)")/m);
  const exact = (line?.[1] ?? line?.[2])?.match(/^=\s*(\d+\.\d+\.\d+)$/);
  if (!exact) fail('rust/Cargo.toml must pin wasm-bindgen exactly (wasm-bindgen = "=X.Y.Z"): its CLI has to be the same version');
  return exact[1];
}

/** The wasm-bindgen CLI at exactly the crate's version, and wasm-pack. */
function wasmTools() {
  const version = pinnedWasmBindgen();
  const expected = `wasm-bindgen ${version}`;
  if (query('wasm-bindgen', ['--version']) !== expected) {
    step(`cargo install wasm-bindgen-cli ${version} (takes a few minutes)`);
    // --force: replaces another version, even one cargo did not install.
    run('cargo', ['install', 'wasm-bindgen-cli', '--version', version, '--locked', '--force']);
    const found = query('wasm-bindgen', ['--version']);
    if (found !== expected) fail(`wasm-bindgen on PATH is "${found}", not "${expected}": remove the other one`);
  }
  if (query('wasm-pack', ['--version']) === null) {
    step(`cargo install wasm-pack ${WASM_PACK_VERSION} (takes a few minutes)`);
    run('cargo', ['install', 'wasm-pack', '--version', WASM_PACK_VERSION, '--locked']);
  }
}

/** web/core/pkg, rebuilt when the crate's sources, manifest or lockfile change. */
function wasmPackage() {
  const key = () => hashInputs(
    [join(CRATE, 'Cargo.toml'), join(CRATE, 'Cargo.lock'), join(CRATE, 'build.rs'), join(CRATE, '.cargo', 'config.toml'), ...listFiles(join(CRATE, 'src'))],
    [...WASM_PACK_ARGS, pinnedWasmBindgen()],
  );
  const built = existsSync(join(PKG, 'voxpath.js')) && existsSync(join(PKG, 'voxpath_bg.wasm'));
  if (built && readStamp('wasm') === key()) return;
  step('wasm-pack build → web/core/pkg');
  run('wasm-pack', WASM_PACK_ARGS);
  // Hashed after the build: the first build writes rust/Cargo.lock.
  writeStamp('wasm', key());
}

/** lib/ (tsc output of web/core and web/cli, plus a copy of the wasm package), rebuilt when they change. */
function library() {
  const lib = join(ROOT, 'lib');
  const key = () => hashInputs([
    fileURLToPath(import.meta.url), // declareLoaderWithoutDom, declareDisposable
    join(ROOT, 'tsconfig.lib.json'),
    ...listFiles(join(ROOT, 'web', 'core')), // includes web/core/pkg
    ...listFiles(join(ROOT, 'web', 'cli')),
  ]);
  if (existsSync(join(lib, 'core')) && readStamp('lib') === key()) return;
  step('tsc -p tsconfig.lib.json → lib/');
  // Start clean so a deleted source leaves no stale .js behind.
  rmSync(join(lib, 'core'), { recursive: true, force: true });
  rmSync(join(lib, 'cli'), { recursive: true, force: true });
  run('tsc', ['-p', 'tsconfig.lib.json']);
  // wasm-pack's own package.json and its .gitignore ("*") stay behind: the
  // .gitignore would make `npm pack` leave lib/core/pkg out of the tarball.
  cpSync(PKG, join(lib, 'core', 'pkg'), {
    recursive: true,
    filter: (source) => !['.gitignore', 'package.json'].includes(basename(source)),
  });
  declareLoaderWithoutDom(join(lib, 'core', 'pkg', 'voxpath.d.ts'));
  declareDisposable(join(lib, 'core', 'pkg', 'voxpath.d.ts'));
  writeStamp('lib', key());
}

/**
 * wasm-bindgen types its loader (`init`, `initSync`, their input and
 * output), which only web/core/wasm.ts calls, with the DOM library's names
 * (RequestInfo, Response, BufferSource, WebAssembly.Memory, ...). A Node
 * project that checks its dependencies' declarations (no skipLibCheck) and
 * does not load the DOM library failed on them. The library's copy types
 * them as `unknown`, which no caller of the library meets.
 * @param {string} file
 */
function declareLoaderWithoutDom(file) {
  const text = readFileSync(file, 'utf8');
  const loader = text.indexOf('export type InitInput');
  if (loader < 0) fail(`${file}: no wasm-bindgen loader (export type InitInput) to retype; has wasm-bindgen's output changed?`);
  const retyped = text
    .slice(loader)
    .split('\n')
    .map((line) => (/^\s*(\/\*|\*|\/\/)/.test(line) ? line : line.replace(/\b(?:RequestInfo|URL|Response|BufferSource)\b|\bWebAssembly\.\w+/g, 'unknown').replace(/unknown(?: \| unknown)+/g, 'unknown')))
    .join('\n');
  writeFileSync(file, text.slice(0, loader) + retyped);
}

/**
 * wasm-bindgen declares each class it exports disposable
 * (`[Symbol.dispose](): void`), a name of TypeScript's esnext.disposable
 * library, which neither es2022 nor the DOM library holds: a project that
 * checks its dependencies' declarations (no skipLibCheck) and does not load
 * @types/node (which loads that library) failed on each of them ("Property
 * 'dispose' does not exist on type 'SymbolConstructor'"). The library's
 * copy loads it itself, as @types/node does.
 * @param {string} file
 */
function declareDisposable(file) {
  const reference = '/// <reference lib="esnext.disposable" />\n';
  const text = readFileSync(file, 'utf8');
  if (!text.includes('[Symbol.dispose]')) fail(`${file}: no [Symbol.dispose] left to declare; has wasm-bindgen's output changed?`);
  writeFileSync(file, reference + text);
}

/** Chromium for the browser tests: found, or installed with apt-get when running as root. */
function chromium() {
  /** @returns {string | null} */
  const find = () => {
    try {
      return findChromium();
    } catch (error) {
      return fail(error instanceof Error ? error.message : String(error));
    }
  };
  if (find()) return;
  const canApt = process.getuid?.() === 0 && query('apt-get', ['--version']) !== null;
  if (!canApt) fail(CHROMIUM_HINT);
  step('apt-get install -y chromium');
  process.env.DEBIAN_FRONTEND = 'noninteractive';
  const installed = spawnSync('apt-get', ['install', '-y', 'chromium'], { stdio: 'inherit' }).status === 0;
  if (!installed) {
    // A fresh machine has no package lists yet.
    step('apt-get update, then install chromium again');
    run('apt-get', ['update']);
    run('apt-get', ['install', '-y', 'chromium']);
  }
  if (!find()) fail(CHROMIUM_HINT);
}

const PLANS = {
  start: [npmPackages, rustTarget, wasmTools, wasmPackage],
  build: [npmPackages, rustTarget, wasmTools, wasmPackage, library],
  lib: [npmPackages, rustTarget, wasmTools, wasmPackage, library],
  // Chromium first: a missing browser should fail before minutes of compiling.
  test: [npmPackages, chromium, rustTarget, wasmTools, wasmPackage, library],
};

const target = process.argv[2] ?? 'build';
if (!Object.hasOwn(PLANS, target)) {
  console.error(`usage: node scripts/setup.mjs [${Object.keys(PLANS).join('|')}]`);
  process.exit(2);
}
try {
  for (const task of PLANS[/** @type {keyof PLANS} */ (target)]) task();
} catch (error) {
  if (!(error instanceof SetupError)) throw error;
  console.error(`setup: ${error.message}`);
  process.exit(1);
}
