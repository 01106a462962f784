// Checks shared by the Node test files: running the CLI, catching a
// rejection, reading a trace's points, and the properties every path
// promises (unit steps, exact ends, distance from its ideal line).
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { expect } from 'vitest';
import { VoxpathError } from '../web/core/index.js';
import type { ColumnSpec, Trace } from '../web/core/index.js';

/** The CLI's entry point. */
export const BIN = fileURLToPath(new URL('../bin/voxpath.js', import.meta.url));

/** Runs `node bin/voxpath.js ...args` (the compiled CLI, built by setup), with `input` on stdin. */
export function voxpath(args: string[], input?: string): { code: number | null; stdout: string; stderr: string } {
  const r = spawnSync(process.execPath, [BIN, ...args], { encoding: 'utf8', input, maxBuffer: 1 << 30 });
  return { code: r.status, stdout: r.stdout, stderr: r.stderr };
}

/**
 * Runs the CLI with its stdout piped into `reader` (a shell command such as
 * `head -n 2`): the CLI's exit status and what it wrote to stderr.
 */
export function voxpathPipedInto(args: string[], reader: string): { code: number; stderr: string } {
  const quoted = [process.execPath, BIN, ...args].map((a) => `'${a}'`).join(' ');
  const r = spawnSync('bash', ['-c', `${quoted} 2>&3 | ${reader} > /dev/null; echo "\${PIPESTATUS[0]}"`], {
    encoding: 'utf8',
    stdio: ['ignore', 'pipe', 'pipe', 'pipe'],
  });
  return { code: Number(r.stdout.trim()), stderr: (r.output[3] as string | null) ?? '' };
}

/**
 * Runs `act` in a task of its own, after the one that calls this: as a
 * worker receives a message (a cancel), and as the core's slices yield
 * (yieldToEventLoop, a message on a channel too, not a timer).
 */
export function inTaskOfItsOwn(act: () => void): void {
  const { port1, port2 } = new MessageChannel();
  port1.onmessage = () => {
    port1.close();
    act();
  };
  port2.postMessage(null);
}

/** The VoxpathError `promise` rejects with (failing the test if it resolves or rejects with anything else). */
export async function rejection(promise: Promise<unknown>): Promise<VoxpathError> {
  const error = await promise.then(
    () => undefined,
    (e: unknown) => e,
  );
  expect(error).toBeInstanceOf(VoxpathError);
  return error as VoxpathError;
}

/** Every point of a trace, point index 0..steps, as coordinate arrays (grid units). */
export function pointsOf(t: Trace): number[][] {
  const out: number[][] = [];
  for (let k = 0; k <= t.steps; k++) out.push(Array.from(t.points.subarray(k * t.dims, (k + 1) * t.dims)));
  return out;
}

/**
 * Every step moves each axis by at most one unit and at least one axis:
 * `any` axes at once (8-connected in 2D, 26-connected in 3D) or exactly
 * `one` (4- / 6-connected).
 */
export function expectUnitSteps(points: number[][], axesPerStep: 'any' | 'one', what = ''): void {
  for (let k = 1; k < points.length; k++) {
    const moved = points[k]!.map((c, a) => Math.abs(c - points[k - 1]![a]!));
    const ok = moved.every((m) => m <= 1) && (axesPerStep === 'one' ? moved.filter((m) => m === 1).length === 1 : moved.some((m) => m === 1));
    if (!ok) expect.fail(`${what} step ${k - 1}: ${JSON.stringify(points[k - 1])} -> ${JSON.stringify(points[k])}`);
  }
}

/** The trace starts exactly at `from`, ends exactly at `to`, and its summary says so. */
export function expectEnds(t: Trace, from: number[], to: number[]): void {
  expect(t.point(0)).toEqual(from);
  expect(t.point(t.steps)).toEqual(to);
  expect([t.start, t.end]).toEqual([from, to]);
}

/** Perpendicular distance from p to the line through a and b, straight from the definition. */
export function distanceToLine(p: number[], a: number[], b: number[]): number {
  const d = b.map((v, i) => v - a[i]!);
  const r = p.map((v, i) => v - a[i]!);
  const dd = d.reduce((s, v) => s + v * v, 0);
  const rd = r.reduce((s, v, i) => s + v * d[i]!, 0);
  const rr = r.reduce((s, v) => s + v * v, 0);
  return Math.sqrt(Math.max(0, rr - (rd * rd) / dd));
}

/** Every sign pattern of |Δ| = `magnitudes` from `from`: one end point per pattern. */
export function everyDirection(from: number[], magnitudes: number[]): number[][] {
  const ends: number[][] = [];
  for (let bits = 0; bits < 1 << magnitudes.length; bits++) ends.push(magnitudes.map((m, a) => from[a]! + ((bits >> a) & 1 ? -m : m)));
  return ends;
}

/** The planes of G17, G18, G19. */
export type Plane = 'xy' | 'zx' | 'yz';
export const PLANES: Plane[] = ['xy', 'zx', 'yz'];

/** Grid axes of a plane's (u, v, normal): G17 (x, y; z), G18 (z, x; y), G19 (y, z; x). */
export const PLANE_AXES: Record<Plane, [number, number, number]> = { xy: [0, 1, 2], zx: [2, 0, 1], yz: [1, 2, 0] };

/** Grid coordinates of plane coordinates (u, v) at height n on the plane's normal axis. */
export function inPlane(plane: Plane, [u, v, n]: number[]): number[] {
  const p = [0, 0, 0];
  const [a, b, c] = PLANE_AXES[plane];
  [p[a], p[b], p[c]] = [u!, v!, n!];
  return p;
}

/** The labels of a category column (none for other kinds). */
export function labelsOf(column: ColumnSpec): string[] {
  return column.kind === 'category' ? column.labels : [];
}

/**
 * `count` lines of `dims` axes drawn from a fixed seed (mulberry32): each
 * axis's delta up to `longest` either way, from a start anywhere within
 * +-2^30 that keeps the end within it. Long enough for the core's recording
 * loops to run their eight-step passes in 32-bit lanes (from 32 steps a
 * line) and their two 64-bit chains (nd's 5 and 6 axes, from 256 steps) in
 * the wasm build's vector code, with the large coordinates a machine's field
 * can have.
 */
export function randomLines(seed: number, count: number, dims: number, longest: number): { from: number[]; to: number[] }[] {
  let state = seed >>> 0;
  const next = (): number => {
    state = (state + 0x6d2b79f5) >>> 0;
    let t = state;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 2 ** 32;
  };
  const limit = 2 ** 30 - longest;
  return Array.from({ length: count }, () => {
    const from = Array.from({ length: dims }, () => Math.round((2 * next() - 1) * limit));
    return { from, to: from.map((c) => c + Math.round((2 * next() - 1) * longest)) };
  });
}
