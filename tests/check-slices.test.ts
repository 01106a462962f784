// A learner's points checked by the core a slice at a time (checkPoints
// with onProgress, signal or sliceMs), as the page's worker checks them to
// report progress and take a Cancel: the check of the one call, to the bit,
// whatever the slices and wherever the points part from the rule; a signal
// stops it between slices.
import { describe, expect, it } from 'vitest';
import { type Check, type CheckProgress, checkPoints, readAndCheckPoints, readPoints, trace, type TraceOptions, traceToCsv } from '../web/core/index.js';
import { loadCore, withTextBytes } from '../web/core/wasm.js';
import { checkBar } from '../web/form/run-progress.js';
import { inTaskOfItsOwn } from './helpers.js';

/** Moves of each family, each long enough to take several slices. */
const RULES: Record<string, TraceOptions> = {
  'a line': { algorithm: 'regions', from: [0, 0, 0], to: [30001, 17003, 9999] },
  'an arc': { algorithm: 'circle', from: [300, 0, 0], to: [0, 300, 0], center: [0, 0, 0], plane: 'xy', turns: 3 },
  'a helix': { algorithm: 'helix', from: [200, 0, 0], to: [200, 0, 300], center: [0, 0, 0], plane: 'xy', turns: 6 },
  'a helix in chords': { algorithm: 'helix', method: 'segments', from: [200, 0, 0], to: [200, 0, 300], center: [0, 0, 0], plane: 'xy', turns: 6 },
};

/** The step from point k - 1 to point k of flat points, stride 3. */
function stepAt(points: Int32Array, k: number): number[] {
  return [0, 1, 2].map((a) => points[k * 3 + a]! - points[(k - 1) * 3 + a]!);
}

/**
 * The rule's own points, and points that part from them at various places:
 * started elsewhere, two unequal steps swapped (point k alone moves) near
 * the start, the middle and the end, cut short, and gone on past the end.
 */
function deviations(points: Int32Array): [string, Int32Array][] {
  const n = points.length / 3;
  const out: [string, Int32Array][] = [['the path', points]];
  out.push(['started elsewhere', points.map((c, i) => (i % 3 === 0 ? c + 1 : c))]);
  for (const near of [1, Math.floor(n / 2), n - 2]) {
    let k = Math.max(1, near);
    while (k < n - 1 && stepAt(points, k).join() === stepAt(points, k + 1).join()) k++;
    if (k >= n - 1) continue;
    const swapped = points.slice();
    const next = stepAt(points, k + 1);
    for (let a = 0; a < 3; a++) swapped[k * 3 + a] = points[(k - 1) * 3 + a]! + next[a]!;
    out.push([`a step swapped at point ${k}`, swapped]);
  }
  out.push(['cut short', points.slice(0, Math.floor(n / 2) * 3)]);
  const longer = new Int32Array(points.length + 3);
  longer.set(points);
  longer.set([points[points.length - 3]! + 1, points[points.length - 2]!, points[points.length - 1]!], points.length);
  out.push(['gone on', longer]);
  return out;
}

describe('a check made in slices', () => {
  it.each(Object.entries(RULES))('is the one call check, for %s, wherever the points part', async (_, rule) => {
    const t = await trace(rule);
    const path = t.pointsInRange(0, t.steps + 1);
    t.free();
    for (const [how, points] of deviations(path)) {
      const whole: Check = await checkPoints(rule, { points, dims: 3 });
      expect(whole.matches, how).toBe(how === 'the path');
      // Slices of 1 ns hold one core call each (a call takes microseconds),
      // so how many slices the variants take does not hang on the clock:
      // slices of 0.05 ms held as many calls as ran in that time, and a
      // fast run made the variants in 2 slices where a slow one took more.
      for (const sliceMs of [1e-6, 0.5, 5]) {
        const progress: CheckProgress[] = [];
        const sliced = await checkPoints(rule, { points, dims: 3 }, { sliceMs, onProgress: (p) => progress.push(p) });
        // Bit for bit: JSON writes every double so that it reads back the same.
        expect(JSON.stringify(sliced), `${how}, slices of ${sliceMs} ms`).toBe(JSON.stringify(whole));
        expect(sliced).toEqual(whole);
        const last = progress.at(-1)!;
        expect(last).toMatchObject({ stage: 'done', done: true });
        expect(last.variantsTried).toBe(last.variants);
        expect(last.stepsCompared).toBe(last.stepsShared);
        // The stages in order, each count growing.
        const order = ['comparing', 'variants', 'done'];
        for (let i = 1; i < progress.length; i++) {
          const [before, now] = [progress[i - 1]!, progress[i]!];
          expect(order.indexOf(now.stage)).toBeGreaterThanOrEqual(order.indexOf(before.stage));
          expect(now.stepsCompared).toBeGreaterThanOrEqual(before.stepsCompared);
          expect(now.variantsTried).toBeGreaterThanOrEqual(before.variantsTried);
        }
        if (sliceMs === 1e-6) expect(progress.filter((p) => p.stage === 'variants').length, how).toBeGreaterThan(2);
      }
    }
  });

  it('reads text as the one call does, a slice at a time', { timeout: 120_000 }, async () => {
    const rule = RULES['a helix']!;
    const t = await trace(rule);
    const path = t.pointsInRange(0, t.steps + 1);
    t.free();
    const rows = (points: Int32Array, bracketed: boolean) => {
      const out: string[] = [];
      for (let k = 0; k < points.length; k += 3) out.push(bracketed ? `(${points[k]}, ${points[k + 1]}, ${points[k + 2]})` : `${points[k]},${points[k + 1]},${points[k + 2]}`);
      return bracketed ? `[${out.join(',\n')}]\n` : `x,y,z\n${out.join('\n')}\n`;
    };
    const core = await loadCore();
    for (const [how, points] of deviations(path)) {
      for (const bracketed of [false, true]) {
        const text = rows(points, bracketed);
        const whole = await checkPoints(rule, text);
        const json = JSON.stringify(whole);
        expect(whole.matches, how).toBe(how === 'the path');
        // The core's run at 1, 7 and 65,536 units a call: the reading is
        // its first stage, its bytes and points growing to the text's.
        for (const units of [1, 7, 65_536]) {
          const run = withTextBytes(core, text, (bytes) => core.CheckRun.fromText(JSON.stringify(rule), bytes));
          const seen: CheckProgress[] = [];
          for (let p = run.advance(units); ; p = run.advance(units)) {
            seen.push(p);
            if (p.done) break;
          }
          expect(JSON.stringify(run.result()), `${how}, ${units} units a call`).toBe(json);
          // The same values readPoints gives, as an Int32Array.
          expect(run.readPoints()).toEqual(Int32Array.from(await readPoints(text, 3)));
          run.free();
          const reading = seen.filter((p) => p.stage === 'reading');
          // 65,536 rows read the helix's text in one call, which goes on to check them.
          if (units < 65_536) expect(reading.length, how).toBeGreaterThan(units === 1 ? 100 : 0);
          for (let i = 1; i < reading.length; i++) {
            expect(reading[i]!.pointsRead).toBeGreaterThanOrEqual(reading[i - 1]!.pointsRead);
            expect(reading[i]!.bytes).toBe(reading[0]!.bytes);
          }
          // As the page's bar says them: the points read and the part of the text.
          for (const p of reading.filter((p) => p.bytes > 0)) {
            const { bar, verb } = checkBar(p);
            expect(verb).toBe('Reading your points');
            expect(bar.said).toBe(`${p.pointsRead.toLocaleString('en-US')} point${p.pointsRead === 1 ? '' : 's'}, ${Math.floor((100 * p.bytesRead) / p.bytes)}% of the text`);
          }
          const last = seen.at(-1)!;
          expect(last.bytes).toBeGreaterThanOrEqual(text.length);
          expect(last).toMatchObject({ bytesRead: last.bytes, pointsRead: points.length / 3 });
        }
        for (const sliceMs of [0.05, 1, 5]) {
          const progress: CheckProgress[] = [];
          const sliced = await checkPoints(rule, text, { sliceMs, onProgress: (p) => progress.push(p) });
          expect(JSON.stringify(sliced), `${how}, slices of ${sliceMs} ms`).toBe(json);
          expect(progress.at(-1)!.done).toBe(true);
          const both = await readAndCheckPoints(rule, text, { sliceMs });
          expect(JSON.stringify(both.check)).toBe(json);
          expect(both.points).toEqual(points);
        }
      }
    }
    // An error in the text, found by the slice that reads it: its line and column, as the one call gives them.
    const bad = `${rows(path, false)}1,2,x\n`;
    const error = await checkPoints(rule, bad).catch((e: unknown) => e);
    const slicedError = await checkPoints(rule, bad, { sliceMs: 0.05 }).catch((e: unknown) => e);
    expect(slicedError).toMatchObject({ message: (error as Error).message, line: path.length / 3 + 2 });
  });

  it('stops while it reads text when its signal is aborted', async () => {
    // A helix of 150,000 points: its text takes three slices to read.
    const rule: TraceOptions = { algorithm: 'helix', from: [250, 0, 0], to: [250, 0, 300], center: [0, 0, 0], plane: 'xy', turns: 106 };
    const t = await trace(rule);
    const text = traceToCsv(t);
    t.free();
    const cancel = new AbortController();
    const seen: CheckProgress[] = [];
    const stopped = checkPoints(rule, text, {
      signal: cancel.signal,
      sliceMs: 0.05,
      onProgress: (p) => {
        seen.push(p);
        cancel.abort();
      },
    });
    await expect(stopped).rejects.toMatchObject({ name: 'AbortError' });
    expect(seen).toHaveLength(1);
    expect(seen[0]!.stage).toBe('reading');
    expect(seen[0]!.bytesRead).toBeLessThan(seen[0]!.bytes);
  });

  it('stops before its first slice when its signal is aborted as it starts', async () => {
    // The text put into wasm memory and the run made were one task before
    // the first slice (0.1 to 0.25 s in Chromium at the page's cap), which
    // an abort sent as the check started waited for: the first slice ran.
    const rule: TraceOptions = { algorithm: 'helix', from: [250, 0, 0], to: [250, 0, 300], center: [0, 0, 0], plane: 'xy', turns: 106 };
    const t = await trace(rule);
    const text = traceToCsv(t);
    t.free();
    for (const check of [checkPoints, readAndCheckPoints]) {
      const cancel = new AbortController();
      const seen: CheckProgress[] = [];
      const stopped = check(rule, text, { signal: cancel.signal, onProgress: (p) => seen.push(p) });
      inTaskOfItsOwn(() => cancel.abort());
      await expect(stopped).rejects.toMatchObject({ name: 'AbortError' });
      expect(seen).toEqual([]);
    }
  });

  it('stops between slices when its signal is aborted', async () => {
    const rule = RULES['a helix']!;
    const t = await trace(rule);
    const points = t.pointsInRange(0, t.steps + 1);
    t.free();
    // Aborted at the first report, then at the third.
    for (const reports of [1, 3]) {
      const cancel = new AbortController();
      const seen: CheckProgress[] = [];
      const stopped = checkPoints(rule, { points, dims: 3 }, {
        signal: cancel.signal,
        sliceMs: 0.05,
        onProgress: (p) => {
          seen.push(p);
          if (seen.length === reports) cancel.abort();
        },
      });
      await expect(stopped).rejects.toMatchObject({ name: 'AbortError' });
      // The slice that heard the abort was the last one made, before the end.
      expect(seen).toHaveLength(reports);
      expect(seen.at(-1)!.done).toBe(false);
      expect(seen.at(-1)!.variantsTried).toBeLessThan(seen.at(-1)!.variants);
    }
  });

  it('refuses a slice option it does not know, naming it', async () => {
    await expect(checkPoints(RULES['a line']!, [[0, 0, 0]], { onprogress: () => {} } as object)).rejects.toThrow(/onprogress.*did you mean onProgress/);
  });
});
