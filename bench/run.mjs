#!/usr/bin/env node
// `npm run bench`: runs every bench/*.bench.ts in name order and prints one
// table per file; `npm run bench -- end-to-end lines` runs only the files
// whose names contain one of the words given. A bench file default-exports an async function returning
// { title, notes, rows } (bench/types.ts), so a new one needs no change
// here. Node 20 does not run TypeScript, so the files go through vite's
// module runner (bench/module-runner.mjs).
//
// Timings are not asserted anywhere: they depend on the machine and on
// what else runs on it. Run `node scripts/setup.mjs build` first (the npm
// script does).
import { execFileSync } from 'node:child_process';
import { readdirSync } from 'node:fs';
import { cpus, totalmem } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { openModuleRunner } from './module-runner.mjs';

const BENCH = dirname(fileURLToPath(import.meta.url));
const ROOT = dirname(BENCH);

/** @typedef {{ name: string; steps: number; rates: Record<string, number>; ratios?: Record<string, number> }} BenchRow */
/** @typedef {{ title: string; notes: string[]; rows: BenchRow[] }} BenchGroup */

/** "12.3 M/s". @param {number} rate */
function rateText(rate) {
  return rate >= 1e6 ? `${(rate / 1e6).toFixed(1)} M/s` : `${(rate / 1e3).toFixed(0)} k/s`;
}

/** The columns of a group, in the order they first appear. @param {BenchRow[]} rows @param {'rates' | 'ratios'} field */
function columnsOf(rows, field) {
  const names = new Set(/** @type {string[]} */ ([]));
  for (const row of rows) for (const name of Object.keys(row[field] ?? {})) names.add(name);
  return [...names];
}

/** One group as an aligned table, with its notes above. @param {BenchGroup} group */
function render(group) {
  const rateColumns = columnsOf(group.rows, 'rates');
  const ratioColumns = columnsOf(group.rows, 'ratios');
  const header = ['', 'steps', ...rateColumns, ...ratioColumns];
  const body = group.rows.map((row) => [
    row.name,
    row.steps.toLocaleString('en-US'),
    ...rateColumns.map((c) => (row.rates[c] === undefined ? '-' : rateText(row.rates[c]))),
    ...ratioColumns.map((c) => (row.ratios?.[c] === undefined ? '-' : `${row.ratios[c].toFixed(2)}x`)),
  ]);
  const widths = header.map((h, i) => Math.max(h.length, ...body.map((r) => r[i].length)));
  const line = (/** @type {string[]} */ r) => r.map((cell, i) => (i === 0 ? cell.padEnd(widths[i]) : cell.padStart(widths[i]))).join('  ');
  return [`## ${group.title}`, ...group.notes.map((n) => `- ${n}`), '', line(header), ...body.map(line), ''].join('\n');
}

/** The Rust compiler's version, or a note that it is missing. */
function rustc() {
  try {
    return execFileSync('rustc', ['--version'], { encoding: 'utf8' }).trim();
  } catch {
    return 'rustc not found';
  }
}

const only = process.argv.slice(2);
const files = readdirSync(BENCH)
  .filter((f) => f.endsWith('.bench.ts') && (only.length === 0 || only.some((word) => f.includes(word))))
  .sort();
const cpu = cpus();
console.log(
  [
    `voxpath bench, ${new Date().toISOString().slice(0, 10)}: ${cpu.length} x ${cpu[0]?.model ?? 'unknown CPU'}, ` +
      `${(totalmem() / 2 ** 30).toFixed(0)} GiB, Node ${process.version}, ${rustc()}.`,
    'Numbers move with whatever else runs on the machine: compare rows of one run, not runs.',
    '',
  ].join('\n'),
);

const { runner, close } = await openModuleRunner(ROOT);
try {
  for (const file of files) {
    const module = await runner.import(join(BENCH, file));
    const group = /** @type {BenchGroup} */ (await module.default());
    console.log(render(group));
  }
} finally {
  await close();
}
