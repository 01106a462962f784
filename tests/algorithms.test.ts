// Every line algorithm of the catalogue, through the public API against the
// real wasm core. The list of algorithms comes from `algorithms()`; what
// each one promises (README, "Algorithms": connectivity, step count,
// reversal, deviation) is stated once in PROMISES, and a test fails for a
// catalogued line algorithm missing there. Golden cases name the document,
// section and equation or table their expected values come from.
import { describe, expect, it } from 'vitest';
import { algorithms, NO_VALUE, trace, traceToJson } from '../web/core/index.js';
import type { AlgorithmInfo, Trace } from '../web/core/index.js';
import { distanceToLine, everyDirection, expectEnds, expectUnitSteps, labelsOf, pointsOf } from './helpers.js';

interface Promises {
  /** 'any': one unit on any number of axes per step (26-connected); 'one': one axis per step (6-connected). */
  axesPerStep: 'any' | 'one';
  /** Steps of a line: the largest |Δ| or the sum of |Δ|. */
  steps: 'longest' | 'sum';
  /** README: the same cells backwards when the move is reversed and the tie rule flipped. */
  reverses: boolean | 'not stated';
  /**
   * Largest |point - ideal point at the same fraction k / steps| on any axis
   * (each passive axis within 1/2 of the line), or null where the algorithm
   * states no such bound.
   */
  axisBound: number | null;
  /** Amanatides & Woo: every cell visited is one the segment passes through. */
  cellsOnSegment?: true;
  /** Options that make the rule exact enough for its bound (liu-float's decimals). */
  exact?: Record<string, unknown>;
}

const PROMISES: Record<string, Promises> = {
  regions: { axesPerStep: 'any', steps: 'longest', reverses: true, axisBound: 0.5 },
  bresenham2d: { axesPerStep: 'any', steps: 'longest', reverses: 'not stated', axisBound: 0.5 },
  bresenham3d: { axesPerStep: 'any', steps: 'longest', reverses: true, axisBound: 0.5 },
  nd: { axesPerStep: 'any', steps: 'longest', reverses: true, axisBound: 0.5 },
  // Wang section 4: "will not deviate ... when more than two decimals are reserved".
  'liu-float': { axesPerStep: 'any', steps: 'longest', reverses: 'not stated', axisBound: 0.5, exact: { decimals: 6 } },
  greedy: { axesPerStep: 'one', steps: 'sum', reverses: false, axisBound: null },
  walk6: { axesPerStep: 'one', steps: 'sum', reverses: true, axisBound: null, cellsOnSegment: true },
  // Rounding to nearest: within 1/2, up to the float error of the accumulators.
  dda: { axesPerStep: 'any', steps: 'longest', reverses: 'not stated', axisBound: 0.5 + 1e-9 },
};

const LINES: AlgorithmInfo[] = (await algorithms()).filter((a) => a.family === 'line');
const takes = (a: AlgorithmInfo, option: string) => a.options.some((o) => o.name === option);
const promises = (a: AlgorithmInfo) => PROMISES[a.id]!;

/** Axes of the moves below: 3, or 2 for a 2D-only algorithm. */
const dimsOf = (a: AlgorithmInfo) => Math.min(Math.max(3, a.minDims), a.maxDims);

/** The options of a move by `a` between 3-axis points, cut to its axes. */
function move(a: AlgorithmInfo, from: number[], to: number[]) {
  return { algorithm: a.id, from: from.slice(0, dimsOf(a)), to: to.slice(0, dimsOf(a)), ...promises(a).exact };
}

/**
 * Whether the cell [c - 1/2, c + 1/2]^n meets the segment from -> to: the
 * t-ranges (0 <= t <= 1) of its slabs along each axis overlap.
 */
function meetsSegment(cell: number[], from: number[], to: number[]): boolean {
  let [lo, hi] = [0, 1];
  cell.forEach((c, a) => {
    const d = to[a]! - from[a]!;
    if (d === 0) {
      if (Math.abs(c - from[a]!) > 0.5) hi = -1;
      return;
    }
    const [t0, t1] = [(c - 0.5 - from[a]!) / d, (c + 0.5 - from[a]!) / d].sort((p, q) => p - q);
    [lo, hi] = [Math.max(lo, t0!), Math.min(hi, t1!)];
  });
  return lo <= hi;
}

/** Checks what every trace of `a` promises: ends, step count, connectivity, distance from the line. */
function expectPromises(a: AlgorithmInfo, t: Trace, from: number[], to: number[]): void {
  const p = promises(a);
  const what = `${a.id} ${JSON.stringify(from)} -> ${JSON.stringify(to)}`;
  expectEnds(t, from, to);
  const magnitudes = from.map((v, i) => Math.abs(to[i]! - v));
  expect(t.steps, what).toBe(p.steps === 'longest' ? Math.max(...magnitudes) : magnitudes.reduce((s, m) => s + m, 0));
  const points = pointsOf(t);
  expectUnitSteps(points, p.axesPerStep, what);
  if (p.axisBound !== null) {
    // Relative to `from`, so that coordinates near 2^30 lose no precision here.
    let worst = 0;
    points.forEach((q, k) => q.forEach((c, i) => (worst = Math.max(worst, Math.abs(c - from[i]! - ((to[i]! - from[i]!) * k) / t.steps)))));
    expect(worst, what).toBeLessThanOrEqual(p.axisBound);
  }
  if (p.cellsOnSegment) for (const cell of points) expect(meetsSegment(cell, from, to), `${what}: ${JSON.stringify(cell)}`).toBe(true);
  for (let k = 0; k <= t.steps; k += Math.max(1, Math.floor(t.steps / 50))) {
    expect(t.deviation[k], what).toBeCloseTo(distanceToLine(points[k]!, from, to), 6);
  }
}

describe('the catalogue', () => {
  it('states the promises of exactly its line algorithms', () => {
    expect(LINES.map((a) => a.id).sort()).toEqual(Object.keys(PROMISES).sort());
  });
});

describe.each(LINES.map((a) => [a.id, a] as const))('%s', (_, a) => {
  it('keeps its promises in every direction (every octant)', async () => {
    const dims = dimsOf(a);
    // Each axis the major one in turn, and every sign pattern of each.
    const shapes = [[7, 3, 2], [3, 7, 2], [2, 3, 7], [5, 5, 1]].map((m) => m.slice(0, dims));
    for (const magnitudes of shapes) {
      const from = [4, -6, 1].slice(0, dims);
      for (const to of everyDirection(from, magnitudes)) expectPromises(a, await trace({ algorithm: a.id, from, to, ...promises(a).exact }), from, to);
    }
  });

  it('keeps them on a longer line in all its axes', async () => {
    for (let dims = a.minDims; dims <= a.maxDims; dims++) {
      const from = [-40, 17, 3, -2, 9, 0].slice(0, dims);
      const to = [131, -60, 92, 45, -11, 77].slice(0, dims);
      expectPromises(a, await trace({ algorithm: a.id, from, to, ...promises(a).exact }), from, to);
    }
  });

  it('treats a zero-length line as an empty trace', async () => {
    const m = move(a, [3, -4, 5], [3, -4, 5]);
    const t = await trace(m);
    expect(t.steps).toBe(0);
    expect(pointsOf(t)).toEqual([m.from]);
    for (const c of t.columns) expect(t.decisions[c.name]).toHaveLength(0);
    expect(t.metrics.maxDeviation).toBe(0);
  });

  it('steps exactly near ±2^30 without overflow', async () => {
    const big = 2 ** 30;
    const m = move(a, [big - 40, -big + 3, big], [big, -big + 29, big - 17]);
    const t = await trace(m);
    expectPromises(a, t, m.from, m.to);
    // The same move at the other end of x (shifted by -2^31 + 80) takes the same path, shifted.
    const shift = (p: number[], by: number) => p.map((c, i) => (i === 0 ? c + by : c));
    const other = await trace({ ...m, from: shift(m.from, 80 - 2 * big), to: shift(m.to, 80 - 2 * big) });
    expect(pointsOf(other).map((p) => shift(p, 2 * big - 80))).toEqual(pointsOf(t));
    // Every axis count it takes, each axis at ±2^30 (alternating) and moving toward 0.
    for (let dims = a.minDims; dims <= a.maxDims; dims++) {
      const from = Array.from({ length: dims }, (_, i) => (i % 2 ? -big : big));
      const to = from.map((c, i) => c - Math.sign(c) * (30 - 4 * i));
      expectPromises(a, await trace({ algorithm: a.id, from, to, ...promises(a).exact }), from, to);
    }
  });

  it('marks each category or flag cell as a label, 0 or 1, or NO_VALUE', async () => {
    const t = await trace(move(a, [0, 0, 0], [10, 7, 6]));
    for (const c of t.columns.filter((c) => c.kind === 'category' || c.kind === 'flag')) {
      const valid = (v: number) => v === NO_VALUE || (c.kind === 'flag' ? v <= 1 : v < labelsOf(c).length);
      expect(Array.from(t.decisions[c.name]!).every(valid), c.name).toBe(true);
    }
  });

  if (takes(a, 'tie')) {
    it('switches ties between advance and hold, marking them', async () => {
      // (10, 7, 6) (Wang's line; for 2D Saleem's (10, 3)) has a discriminant
      // or error term of exactly 0 at step index 4 (SEED-NOTES; 2D: worked below).
      const m = a.maxDims === 2 ? { algorithm: a.id, from: [0, 0], to: [10, 3] } : move(a, [0, 0, 0], [10, 7, 6]);
      const [advance, hold] = await Promise.all([trace({ ...m, tie: 'advance' }), trace({ ...m, tie: 'hold' })]);
      expect(pointsOf(advance)).not.toEqual(pointsOf(hold));
      for (const t of [advance, hold]) {
        expect(t.decisions.tie![4]).toBe(1);
        expect(t.metrics.ties).toBeGreaterThanOrEqual(1);
        expect(Array.from(t.decisions.tie!).filter((v) => v === 1)).toHaveLength(t.metrics.ties);
      }
      // The paths part at the tied step; without the option the catalogue's default decides.
      const [pa, ph] = [pointsOf(advance), pointsOf(hold)];
      expect(pa.slice(0, 5)).toEqual(ph.slice(0, 5));
      expect(pa[5]).not.toEqual(ph[5]);
      expect(pointsOf(await trace(m))).toEqual(a.defaultTie === 'advance' ? pa : ph);
    });
  }

  if (takes(a, 'tieAxis')) {
    it('orders tied axes lower or higher first, marking the tie', async () => {
      // (0,0) -> (3,1): walk6's segment meets the corner (1.5, 0.5) at t = 1/2,
      // where x's second face (t = 3/6) and y's first (t = 1/2) coincide;
      // greedy at (2,0) leaves 0² + 1² = 1 by x and 1² + 0² = 1 by y.
      const [lower, higher] = await Promise.all([
        trace({ algorithm: a.id, from: [0, 0], to: [3, 1], tieAxis: 'lower' }),
        trace({ algorithm: a.id, from: [0, 0], to: [3, 1], tieAxis: 'higher' }),
      ]);
      expect(pointsOf(lower)).not.toEqual(pointsOf(higher));
      for (const t of [lower, higher]) {
        expect(t.metrics.ties).toBe(1);
        expect(Array.from(t.decisions.tie!).filter((v) => v === 1)).toHaveLength(1);
      }
      const tied = Array.from(lower.decisions.tie!).indexOf(1);
      const axis = lower.columns.find((c) => c.name === 'axis' || c.name === 'crosses')!;
      expect(labelsOf(axis)[lower.decisions[axis.name]![tied]!]).toBe('x');
      expect(labelsOf(axis)[higher.decisions[axis.name]![tied]!]).toBe('y');
    });
  }

  if (!takes(a, 'tie') && !takes(a, 'tieAxis')) {
    it('has no tie rule, and marks no step a tie', async () => {
      const t = await trace(move(a, [0, 0, 0], [10, 7, 6]));
      expect(a.defaultTie).toBeNull();
      expect(t.metrics.ties).toBe(0);
    });
  }

  if (takes(a, 'gcd')) {
    it('gives the same path with GCD reduction (Wang section 4), its discriminants divided by the GCD', async () => {
      // |Δ| = (30, 21, 18) = 3 · (10, 7, 6).
      const m = move(a, [2, -5, 1], [-28, 16, 19]);
      const [plain, reduced] = await Promise.all([trace({ ...m, gcd: false }), trace({ ...m, gcd: true })]);
      expect(pointsOf(reduced)).toEqual(pointsOf(plain));
      const integer = plain.columns.filter((c) => c.kind === 'int').map((c) => c.name);
      expect(integer.length).toBeGreaterThan(0);
      for (const name of integer) {
        const scaled = Array.from(reduced.decisions[name]!, (v) => v * 3);
        expect(scaled, name).toEqual(Array.from(plain.decisions[name]!));
      }
    });
  }

  if (promises(a).reverses !== 'not stated') {
    it(`${promises(a).reverses ? 'visits the same cells backwards' : 'does not retrace itself'} when reversed with the tie rule flipped`, async () => {
      const flip = takes(a, 'tie') ? (['tie', 'advance', 'hold'] as const) : (['tieAxis', 'lower', 'higher'] as const);
      const retraced: boolean[] = [];
      for (const [from, to] of [
        [[0, 0, 0], [10, 7, 6]],
        [[5, -3, 8], [-14, 6, 1]],
      ]) {
        const m = move(a, from!, to!);
        const forward = await trace({ ...m, [flip[0]]: flip[1] });
        const backward = await trace({ ...m, from: m.to, to: m.from, [flip[0]]: flip[2] });
        retraced.push(JSON.stringify(pointsOf(backward).reverse()) === JSON.stringify(pointsOf(forward)));
      }
      // Promised: every move retraces; not promised (greedy): some move does not.
      expect(promises(a).reverses ? retraced.every(Boolean) : !retraced.every(Boolean)).toBe(true);
    });
  }
});

describe('golden cases from the documents', () => {
  it('regions: M and N at every step equal Wang eq. (6) in closed form, on a mirrored line', async () => {
    // Eq. (6) with x active: M_i = 2|Δy|·x_i - 2|Δx|·y_i + 2|Δy| - |Δx|, in
    // units travelled toward the end (SEED-NOTES, "closed form").
    const from = [3, -2, 7];
    const to = [-9, 3, -1];
    const t = await trace({ algorithm: 'regions', from, to });
    const d = from.map((v, i) => Math.abs(to[i]! - v));
    const sign = from.map((v, i) => Math.sign(to[i]! - v));
    const points = pointsOf(t);
    const done = (k: number, axis: number) => (points[k]![axis]! - from[axis]!) * sign[axis]!;
    for (let k = 0; k < t.steps; k++) {
      expect(t.decisions.M![k]).toBe(2 * d[1]! * done(k, 0) - 2 * d[0]! * done(k, 1) + 2 * d[1]! - d[0]!);
      expect(t.decisions.N![k]).toBe(2 * d[2]! * done(k, 0) - 2 * d[0]! * done(k, 2) + 2 * d[2]! - d[0]!);
    }
  });

  it('regions: a type ② line has no region or corner (NO_VALUE; null in JSON)', async () => {
    // Wang section 2.2: |Δx| = |Δy| = |Δz|, every axis active, no face decides.
    const t = await trace({ algorithm: 'regions', from: [0, 0, 0], to: [-3, 3, 3] });
    expect(Array.from(t.decisions.region!)).toEqual([NO_VALUE, NO_VALUE, NO_VALUE]);
    expect(Array.from(t.decisions.corner!)).toEqual([NO_VALUE, NO_VALUE, NO_VALUE]);
    expect(labelsOf(t.columns.find((c) => c.name === 'region')!)).not.toContain('-');
    expect(traceToJson(t).decisions).toMatchObject({ M: [null, null, null], region: [null, null, null], corner: [null, null, null], tie: [false, false, false] });
  });

  it('bresenham2d: Saleem section 2, eq. (4)-(5), on (0,0) -> (10,3)', async () => {
    // Eq. (4): the error 2Δx·ε adds 2Δy = 6 each step; eq. (5): y steps when
    // it exceeds Δx = 10, and then drops by 2Δx = 20 (the erratum: the
    // text's Δx). By hand: 6, 12 (step, -8), -2, 4, 10 (= Δx: a tie, held
    // by Saleem's strict >), 16 (step, -4), 2, 8, 14 (step, -6), 0.
    const t = await trace({ algorithm: 'bresenham2d', from: [0, 0], to: [10, 3] });
    expect(Array.from(t.decisions.error!)).toEqual([6, 12, -2, 4, 10, 16, 2, 8, 14, 0]);
    expect(Array.from(t.decisions.threshold!)).toEqual(Array(10).fill(10));
    expect(pointsOf(t).map((p) => p[1])).toEqual([0, 0, 1, 1, 1, 1, 2, 2, 2, 3, 3]);
    const octant = t.columns.find((c) => c.name === 'octant')!;
    expect(labelsOf(octant)[t.decisions.octant![0]!]).toBe('1');
    // Octant k of Saleem Fig. 1 is the half-open 45° range [45°(k-1), 45°k) from +x.
    for (const [to, k] of [[[3, 10], '2'], [[-3, 10], '3'], [[-10, 3], '4'], [[-10, -3], '5'], [[-3, -10], '6'], [[3, -10], '7'], [[10, -3], '8']] as const) {
      const o = await trace({ algorithm: 'bresenham2d', from: [0, 0], to: [...to] });
      expect(labelsOf(octant)[o.decisions.octant![0]!], JSON.stringify(to)).toBe(k);
    }
  });

  it('bresenham3d: Saleem section 3 (hold) and Liu via Wang Table 1 (advance) on (0,0,0) -> (10,7,6)', async () => {
    // x major, threshold Δx = 10; errorY adds 2·7 = 14, errorZ 2·6 = 12,
    // dropping by 20 after a step (SEED-NOTES). errorY by hand: 14 (step,
    // -6), 8, 22 (-> 2), 16 (-> -4), 10 (tie: holds), 24 (-> 4), 18 (-> -2),
    // 12 (-> -8), 6, 20; errorZ: 12, 4, 16, 8, 20, 12, 4, 16, 8, 20.
    const hold = await trace({ algorithm: 'bresenham3d', from: [0, 0, 0], to: [10, 7, 6] });
    expect(Array.from(hold.decisions.errorY!)).toEqual([14, 8, 22, 16, 10, 24, 18, 12, 6, 20]);
    expect(Array.from(hold.decisions.errorZ!)).toEqual([12, 4, 16, 8, 20, 12, 4, 16, 8, 20]);
    expect(Array.from(hold.decisions.errorX!).every(Number.isNaN)).toBe(true);
    expect(hold.point(5)).toEqual([5, 3, 3]);
    // Liu's Table 1 (Wang), which steps on a tie: the points of eq. (8).
    const advance = await trace({ algorithm: 'bresenham3d', from: [0, 0, 0], to: [10, 7, 6], tie: 'advance' });
    expect(pointsOf(advance)).toEqual(pointsOf(await trace({ algorithm: 'regions', from: [0, 0, 0], to: [10, 7, 6] })));
  });

  it('nd: one discriminant per passive axis, Wang section 3.4 eq. (16)-(17), in five axes', async () => {
    // Eq. (16)-(17) extend eq. (6): D_a = 2|Δa|·x_i - 2|Δx|·a_i + 2|Δa| - |Δx|
    // for each passive axis a, from the point alone; x (|Δx| = 10) is active.
    const from = [0, 0, 0, 0, 0];
    const to = [10, 7, -6, 5, 3];
    const t = await trace({ algorithm: 'nd', from, to });
    const points = pointsOf(t);
    const names = ['discriminantX', 'discriminantY', 'discriminantZ', 'discriminantA', 'discriminantB'];
    for (let k = 0; k < t.steps; k++) {
      const x = points[k]![0]!;
      for (let axis = 1; axis < 5; axis++) {
        const d = Math.abs(to[axis]!);
        const done = Math.abs(points[k]![axis]!);
        expect(t.decisions[names[axis]!]![k]).toBe(2 * d * x - 2 * 10 * done + 2 * d - 10);
      }
      expect(t.decisions.discriminantX![k]).toBeNaN();
    }
    // In three axes it is Wang's 3D rule.
    expect(pointsOf(await trace({ algorithm: 'nd', from: [0, 0, 0], to: [10, 7, 6] }))).toEqual(
      pointsOf(await trace({ algorithm: 'regions', from: [0, 0, 0], to: [10, 7, 6] })),
    );
  });

  it("liu-float: Liu's ε of Wang eq. (14)-(15) and Table 1, and Fig. 10's drift at one decimal", async () => {
    // Eq. (14)-(15): ε(y_1) = k_yx - 0.5 = 0.2, ε(z_1) = k_zx - 0.5 = 0.1;
    // then ε += k, and -1 after the axis steps (it steps on ε >= 0). With
    // k = 0.7 and 0.6 every ε is a whole tenth, so one decimal is exact
    // here. Table 1 prints these, except ε(z) at i = 8 (0.1 for -0.1, an
    // erratum in SEED-NOTES).
    const t = await trace({ algorithm: 'liu-float', from: [0, 0, 0], to: [10, 7, 6], decimals: 1 });
    // In tenths, so the recurrence is exact: ε·10 starts at 10k - 5.
    const liu = (kTenths: number) => {
      const out: number[] = [];
      let e = kTenths - 5;
      for (let i = 0; i < 10; i++) {
        out.push(e / 10);
        e += (e >= 0 ? -10 : 0) + kTenths;
      }
      return out;
    };
    expect(Array.from(t.decisions.epsY!, (v) => Math.round(v * 10) / 10)).toEqual(liu(7));
    expect(Array.from(t.decisions.epsZ!, (v) => Math.round(v * 10) / 10)).toEqual(liu(6));
    expect(liu(7)).toEqual([0.2, -0.1, 0.6, 0.3, 0, -0.3, 0.4, 0.1, -0.2, 0.5]);
    expect(liu(6)[8]).toBe(-0.1);
    expect(pointsOf(t)).toEqual(pointsOf(await trace({ algorithm: 'regions', from: [0, 0, 0], to: [10, 7, 6] })));
    // Table 1's Error column: the distance of each point from the line
    // (0.225064 at i = 7 is an erratum for 0.220564).
    const table1 = [0, 0.374887, 0.336918, 0.220564, 0.441129, 0.4287, 0.441129, 0.220564, 0.336918, 0.374887, 0];
    table1.forEach((e, k) => expect(t.deviation[k]).toBeCloseTo(e, 6));
    // Fig. 10 / section 4: with one decimal k = 1/7 is kept as 0.1 and the
    // path strays past the bound sqrt(2)/2; with four it does not.
    const one = await trace({ algorithm: 'liu-float', from: [0, 0, 0], to: [7, 1, 1], decimals: 1 });
    const four = await trace({ algorithm: 'liu-float', from: [0, 0, 0], to: [7, 1, 1], decimals: 4 });
    expect(one.metrics.maxDeviation).toBeGreaterThan(Math.SQRT1_2);
    expect(four.metrics.maxDeviation).toBeLessThanOrEqual(Math.SQRT1_2);
    expect(one.point(7)).toEqual([7, 1, 1]);
  });

  it('greedy: the 2009 blog on (0,0) -> (8,3), squared distances to the goal (SEED-NOTES)', async () => {
    // The move that leaves the smaller squared distance to the goal wins,
    // ties to x: from (0,0), x leaves 7² + 3² = 58, y 8² + 2² = 68. It runs
    // along x until the remaining distances are equal, then alternates.
    const t = await trace({ algorithm: 'greedy', from: [0, 0], to: [8, 3] });
    expect(pointsOf(t)).toEqual([[0, 0], [1, 0], [2, 0], [3, 0], [4, 0], [5, 0], [6, 0], [6, 1], [7, 1], [7, 2], [8, 2], [8, 3]]);
    const points = pointsOf(t);
    for (let k = 0; k < t.steps; k++) {
      const [x, y] = points[k]!;
      expect(t.decisions.distSqX![k]).toBe(x! < 8 ? (8 - x! - 1) ** 2 + (3 - y!) ** 2 : NaN);
      expect(t.decisions.distSqY![k]).toBe(y! < 3 ? (8 - x!) ** 2 + (3 - y! - 1) ** 2 : NaN);
    }
    // It strays with length: further from the line on a longer move of the same slope.
    const long = await trace({ algorithm: 'greedy', from: [0, 0], to: [800, 300] });
    expect(long.metrics.maxDeviation).toBeGreaterThan(10 * t.metrics.maxDeviation);
  });

  it('walk6: Amanatides & Woo, the cell faces in order of crossing on (0,0) -> (8,3)', async () => {
    // The segment crosses x's k-th face at t = (2k+1)/(2·8), y's at
    // (2k+1)/(2·3); the path steps the axes in the order of those t.
    const t = await trace({ algorithm: 'walk6', from: [0, 0], to: [8, 3] });
    const crossings = [
      ...Array.from({ length: 8 }, (_, k) => ({ axis: 0, t: (2 * k + 1) / 16 })),
      ...Array.from({ length: 3 }, (_, k) => ({ axis: 1, t: (2 * k + 1) / 6 })),
    ].sort((p, q) => p.t - q.t);
    const expected = [[0, 0]];
    for (const c of crossings) expected.push(expected.at(-1)!.map((v, a) => (a === c.axis ? v + 1 : v)));
    expect(pointsOf(t)).toEqual(expected);
    expect(Array.from(t.decisions.crosses!)).toEqual(crossings.map((c) => c.axis));
    expect(t.decisions.tX![0]).toBeCloseTo(1 / 16, 15);
    expect(t.decisions.tY![0]).toBeCloseTo(1 / 6, 15);
  });

  it('dda: the textbook float DDA on (0,0) -> (14,1), whose seven additions of 1/14 miss 0.5', async () => {
    // y's accumulator adds 1/14 per step in f64 and rounds to nearest; the
    // same additions here give 0.4999999999999999 after 7 steps, so y
    // steps at step 8, not at the true half way of step 7.
    const t = await trace({ algorithm: 'dda', from: [0, 0], to: [14, 1] });
    let acc = 0;
    const accs = Array.from({ length: 14 }, () => (acc += 1 / 14));
    expect(Array.from(t.decisions.accY!)).toEqual(accs);
    expect(accs[6]).toBeLessThan(0.5);
    expect(pointsOf(t).map((p) => p[1])).toEqual(accs.reduce((ys, a) => [...ys, Math.floor(a + 0.5)], [0]));
    expect(t.point(7)).toEqual([7, 0]);
    expect(t.point(8)).toEqual([8, 1]);
  });
});
