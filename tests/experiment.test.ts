// The random-lines experiment (Wang et al. 2020, section 3.2, Figure 9)
// through the built wasm package and the CLI.
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { type ExperimentProgress, heapBytes, randomLines, type RandomLinesOptions, trace, VoxpathError } from '../web/core/index.js';

const BIN = fileURLToPath(new URL('../bin/voxpath.js', import.meta.url));

describe('randomLines', () => {
  it('is reproducible from its seed and summarises per-line statistics', async () => {
    const a = await randomLines({ algorithm: 'regions', count: 40, seed: 11 });
    const b = await randomLines({ algorithm: 'regions', count: 40, seed: 11 });
    expect(a).toEqual(b);
    expect(a.lines).toHaveLength(40);
    const maxima = a.lines.map((l) => l.perpendicular.max);
    expect(a.perpendicular.max.max).toBe(Math.max(...maxima));
    expect(a.perpendicular.max.min).toBe(Math.min(...maxima));
    // Section 3.2: every error is within sqrt(2)/2.
    expect(a.axisError.max.max).toBeLessThanOrEqual(Math.SQRT1_2 + 1e-12);
  });

  it('measures the same lines a trace does', async () => {
    const r = await randomLines({ algorithm: 'regions', count: 3, seed: 5 });
    for (const line of r.lines) {
      const t = await trace({ algorithm: 'regions', from: [0, 0, 0], to: line.to });
      expect(line.steps).toBe(t.steps);
      expect(line.perpendicular.max).toBe(t.metrics.maxDeviation);
      expect(line.perpendicular.mean).toBeCloseTo(t.metrics.meanDeviation, 12);
    }
  });

  it('passes algorithm options to every line and names bad ones', async () => {
    // Each line is measured as a trace of it with the same option measures
    // it, and the option changes the lines (liu-float rounds its float error
    // term to `decimals` places; a tie option would not show, a tie's two
    // cells being equally far off the line).
    const coarse = await randomLines({ algorithm: 'liu-float', count: 30, seed: 2, decimals: 0 });
    const fine = await randomLines({ algorithm: 'liu-float', count: 30, seed: 2, decimals: 6 });
    for (const [result, decimals] of [[coarse, 0], [fine, 6]] as const) {
      expect(result.lines).toHaveLength(30);
      for (const line of result.lines) {
        const t = await trace({ algorithm: 'liu-float', from: [0, 0, 0], to: line.to, decimals });
        expect(line.perpendicular.max, `${line.to} at ${decimals}`).toBe(t.metrics.maxDeviation);
        t.free();
      }
    }
    const changed = coarse.lines.filter((line, i) => line.perpendicular.max !== fine.lines[i]!.perpendicular.max);
    expect(changed.length).toBeGreaterThan(10);
    await expect(randomLines({ algorithm: 'regions', count: -1 })).rejects.toMatchObject({ field: 'count' });
    await expect(randomLines({ algorithm: 'regions', tie: 'never' })).rejects.toBeInstanceOf(VoxpathError);
    // The experiment draws each line's ends: a from given was overwritten, line after line.
    await expect(randomLines({ algorithm: 'regions', from: [5, 5, 5] } as never)).rejects.toMatchObject({ field: 'from' });
  });
});

describe('randomLines in slices', () => {
  const OPTIONS = { algorithm: 'bresenham3d', count: 300, seed: 4, maxCoordinate: 500 } satisfies RandomLinesOptions;

  it("reports its progress after every slice and gives the whole run's result", async () => {
    const whole = await randomLines(OPTIONS);
    const seen: ExperimentProgress[] = [];
    const sliced = await randomLines(OPTIONS, { onProgress: (q) => seen.push(q), sliceMs: 0.01 });
    expect(sliced).toEqual(whole);
    expect(seen.length).toBeGreaterThan(2);
    const done = seen.map((q) => q.linesDone);
    expect(done).toEqual([...done].sort((a, b) => a - b));
    for (const q of seen) {
      const steps = whole.lines.slice(0, q.linesDone).reduce((sum, l) => sum + l.steps, 0);
      expect(q).toEqual({ linesDone: q.linesDone, lines: 300, steps, done: q.linesDone === 300 });
    }
    expect(seen.at(-1)!.done).toBe(true);
    expect(seen.filter((q) => q.done)).toHaveLength(1);
  });

  it('stops when its signal is aborted, between slices or once its last slice has run, and frees the run', async () => {
    const heap = heapBytes();
    const early = new AbortController();
    const cancelled = randomLines(OPTIONS, { signal: early.signal, sliceMs: 0.01, onProgress: () => early.abort() });
    await expect(cancelled).rejects.toMatchObject({ name: 'AbortError' });
    const late = new AbortController();
    const finished = randomLines(OPTIONS, { signal: late.signal, onProgress: (q) => q.done && late.abort() });
    await expect(finished).rejects.toMatchObject({ name: 'AbortError' });
    expect(heapBytes()).toBe(heap);
    // Aborted before it starts: no line is traced.
    const seen: ExperimentProgress[] = [];
    await expect(randomLines(OPTIONS, { signal: AbortSignal.abort(), onProgress: (q) => seen.push(q) })).rejects.toMatchObject({ name: 'AbortError' });
    expect(seen).toEqual([]);
  });

  it('refuses an option of its own it does not know, naming it', async () => {
    await expect(randomLines(OPTIONS, { onprogress: () => {} } as never)).rejects.toMatchObject({
      message: 'onprogress: randomLines does not take this option (did you mean onProgress?)',
    });
    await expect(randomLines(OPTIONS, { sliceMs: 0 })).rejects.toMatchObject({ field: 'sliceMs' });
  });
});

describe('voxpath experiment random-lines', () => {
  const run = (...args: string[]) => spawnSync(process.execPath, [BIN, 'experiment', 'random-lines', ...args], { encoding: 'utf8' });

  it('prints JSON, CSV and a table beside Figure 9', () => {
    const json = JSON.parse(run('--count', '10', '--seed', '1').stdout);
    expect(json.lines).toHaveLength(10);
    expect(json.paperFigure9.mean.mean).toBe(0.3792);
    const csv = run('--count', '10', '--seed', '1', '--format', 'csv').stdout.trim().split('\n');
    expect(csv[0]).toBe('line,to_x,to_y,to_z,steps,perp_max,perp_mean,perp_std,eq11_max,eq11_mean,eq11_std');
    expect(csv).toHaveLength(11);
    const table = run('--count', '10', '--seed', '1', '--format', 'table').stdout;
    expect(table).toMatch(/^delta_Mean per line/m);
    expect(table).toContain('Figure 9 gives 0.7071 as both the largest and the smallest');
  });

  it('rejects unknown flags with exit 2', () => {
    const r = run('--count', '10', '--from', '1,1,1');
    expect(r.status).toBe(2);
    expect(r.stderr.split('\n')[0]).toBe(
      'voxpath: unknown flag --from for random-lines with regions (it takes --count, --seed, --max-coordinate, --dims, --tie, --gcd, --max-steps)',
    );
  });
});
