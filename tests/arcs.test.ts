// Every arc algorithm of the catalogue (circle, arc-segments, helix) through
// the public API against the real wasm core: quarter, half and full circles
// in each plane and direction, centers in negative quadrants, radii 1, 2 and
// 2^20, the radial error each states, and bad input.
//
// Conventions checked (README, "Algorithms"; SEED-NOTES on the G-code blog):
// G17/G18/G19 put the plane's axes (u, v) as (x, y), (z, x), (y, z); G03
// (ccw) increases the angle atan2(v, u) about the center, G02 (cw)
// decreases it: counter-clockwise / clockwise seen from the positive end of
// the plane's normal axis, right-handed in all three planes.
import { describe, expect, it } from 'vitest';
import { algorithms, NO_VALUE, readDecision, trace } from '../web/core/index.js';
import type { AlgorithmInfo, Trace } from '../web/core/index.js';
import { expectEnds, inPlane, labelsOf, PLANE_AXES, PLANES, rejection } from './helpers.js';
import type { Plane } from './helpers.js';

const ARCS: AlgorithmInfo[] = (await algorithms()).filter((a) => a.family === 'arc');

/**
 * The largest distance of a point from the circle (in its plane) each
 * algorithm states: Saleem's circle picks, of two candidates, the one with
 * the smaller |u² + v² - r²|, which keeps every point within 1/2 of the
 * circle (a helix steps the same circle); chords add their sagitta
 * r(1 - cos(θ/2)) to the line algorithm's sqrt(2)/2 and the vertices'
 * rounding, sqrt(2)/2.
 */
const RADIAL_BOUND: Record<string, (t: Trace, r: number, sweep: number) => number> = {
  circle: () => 0.5,
  helix: () => 0.5,
  'arc-segments': (t, r, sweep) => r * (1 - Math.cos(Math.abs(sweep) / t.segments.length / 2)) + Math.SQRT2,
};

/** `to` raised by `rise` along the plane's normal axis (a helix's end). */
const raised = (plane: Plane, to: number[], rise: number) => to.map((c, i) => (i === PLANE_AXES[plane][2] ? c + rise : c));

/** The options of an arc by `a`, a helix rising `rise`; arc-segments in chords of 3 units unless `chords` says otherwise. */
function arcOptions(a: AlgorithmInfo, plane: Plane, from: number[], to: number[], center: number[], dir: 'cw' | 'ccw', rise = 0, chords: Record<string, number> = { segmentLength: 3 }) {
  return { algorithm: a.id, from, to: a.id === 'helix' ? raised(plane, to, rise) : to, center, plane, dir, ...(a.id === 'arc-segments' ? chords : {}) };
}

/**
 * Checks a traced arc about `center` of radius r: one unit per axis per
 * step (8-connected in the plane; the normal axis moves only in a helix,
 * at most one unit, `rise` in all), the swept angle (signed, radians) and
 * the radial error bound. Returns the in-plane octants visited (0-7,
 * counter-clockwise from +u). Reads the flat points in one loop: a quarter
 * of radius 2^20 has 1.5 million.
 */
function expectArc(a: AlgorithmInfo, t: Trace, plane: Plane, center: number[], r: number, sweep: number, rise = 0): Set<number> {
  const [ua, va, na] = PLANE_AXES[plane];
  const p = t.points;
  const octants = new Set<number>();
  let [turned, worst] = [0, 0];
  let badStep: number | undefined;
  for (let k = 0; k <= t.steps; k++) {
    const [u, v] = [p[3 * k + ua]! - center[ua]!, p[3 * k + va]! - center[va]!];
    worst = Math.max(worst, Math.abs(Math.hypot(u, v) - r));
    octants.add(Math.floor((((Math.atan2(v, u) + 2 * Math.PI) % (2 * Math.PI)) / (Math.PI / 4)) + 1e-12) % 8);
    if (k === 0) continue;
    const moved = [0, 1, 2].map((i) => Math.abs(p[3 * k + i]! - p[3 * (k - 1) + i]!));
    if (Math.max(...moved) !== 1 || (a.id !== 'helix' && moved[na] !== 0)) badStep ??= k - 1;
    const [pu, pv] = [p[3 * (k - 1) + ua]! - center[ua]!, p[3 * (k - 1) + va]! - center[va]!];
    turned += Math.atan2(pu * v - pv * u, pu * u + pv * v);
  }
  expect(badStep, 'first step that is not one unit per axis in the plane').toBeUndefined();
  expect(turned).toBeCloseTo(sweep, 9);
  expect(worst).toBeLessThanOrEqual(RADIAL_BOUND[a.id]!(t, r, sweep));
  expect(t.end[na]! - t.start[na]!).toBe(rise);
  return octants;
}

describe('the catalogue', () => {
  it('states a radial bound for exactly its arc algorithms', () => {
    expect(ARCS.map((a) => a.id).sort()).toEqual(Object.keys(RADIAL_BOUND).sort());
  });
});

describe.each(ARCS.map((a) => [a.id, a] as const))('%s', (_, a) => {
  // r = 5 about a center in the negative quadrant (u, v) = (-7, -3), at height -4.
  const [cu, cv, height, r] = [-7, -3, -4, 5];
  const center = (plane: Plane) => inPlane(plane, [cu, cv, 9]); // the normal coordinate of a center is ignored
  const at = (plane: Plane, angle: number) => inPlane(plane, [cu + Math.round(r * Math.cos(angle)), cv + Math.round(r * Math.sin(angle)), height]);

  it.each(PLANES.flatMap((plane) => (['ccw', 'cw'] as const).map((dir) => [plane, dir] as const)))(
    'runs quarter, half and full circles in %s, %s',
    async (plane, dir) => {
      const sign = dir === 'ccw' ? 1 : -1;
      const from = at(plane, 0);
      for (const turn of [0.25, 0.5, 1]) {
        const to = at(plane, sign * turn * 2 * Math.PI);
        const rise = a.id === 'helix' ? 6 : 0;
        const t = await trace(arcOptions(a, plane, from, to, center(plane), dir, rise));
        expectEnds(t, from, a.id === 'helix' ? raised(plane, to, rise) : to);
        const octants = expectArc(a, t, plane, center(plane), r, sign * turn * 2 * Math.PI, rise);
        if (turn === 1) {
          expect(t.point(t.steps).filter((_, i) => i !== PLANE_AXES[plane][2])).toEqual(from.filter((_, i) => i !== PLANE_AXES[plane][2]));
          expect([...octants].sort()).toEqual([0, 1, 2, 3, 4, 5, 6, 7]);
          // Saleem's octant column (circle, helix; NO_VALUE on a helix's steps of the linear axis alone) names all eight too.
          const column = t.columns.find((c) => c.name === 'octant');
          if (column) expect(new Set(Array.from(t.decisions.octant!).filter((v) => v !== NO_VALUE).map((v) => labelsOf(column)[v]))).toEqual(new Set(labelsOf(column)));
        }
      }
    },
  );

  it('steps full circles of radius 1 and 2 in every plane and direction', async () => {
    // Chords of 1 unit: the blog's floor(2πr / 3) would give r = 1 two
    // chords, a diameter there and back (the rule, not an arc).
    for (const radius of [1, 2]) {
      for (const plane of PLANES) {
        for (const dir of ['ccw', 'cw'] as const) {
          const from = inPlane(plane, [-3 + radius, -8, 2]);
          const c = inPlane(plane, [-3, -8, 0]);
          const t = await trace(arcOptions(a, plane, from, from, c, dir, a.id === 'helix' ? 1 : 0, { segmentLength: 1 }));
          expectEnds(t, from, a.id === 'helix' ? raised(plane, from, 1) : from);
          const octants = expectArc(a, t, plane, c, radius, (dir === 'ccw' ? 2 : -2) * Math.PI, a.id === 'helix' ? 1 : 0);
          expect(octants.size, `r = ${radius} ${plane} ${dir}`).toBeGreaterThanOrEqual(4);
        }
      }
    }
  });

  it('ends exactly on a quarter of radius 2^20, 8-connected and within its radial bound', { timeout: 60_000 }, async () => {
    const big = 2 ** 20;
    const c = [-big, -3, 5];
    const rise = a.id === 'helix' ? 100 : 0;
    // Chords by Grbl's tolerance: 3-unit chords would make 550,000 of them.
    const t = await trace(arcOptions(a, 'xy', [0, -3, 5], [-big, big - 3, 5], c, 'ccw', rise, { tolerance: 0.5 }));
    expectEnds(t, [0, -3, 5], [-big, big - 3, 5 + rise]);
    expectArc(a, t, 'xy', c, big, Math.PI / 2, rise);
  });

  it('names the field at fault', async () => {
    const c = [0, 0, 0];
    const base = arcOptions(a, 'xy', [5, 0, 0], [0, 5, 0], c, 'ccw');
    // The radii differ by more than 1 grid unit: 5 against 7.
    expect((await rejection(trace({ ...base, to: [0, 7, base.to[2]!] }))).field).toBe('to');
    // r = 0: the center is the start point.
    expect((await rejection(trace({ ...base, from: c, to: c }))).field).toBe('center');
    expect((await rejection(trace({ ...base, center: ['a', 0, 0] }))).field).toBe('center');
    expect((await rejection(trace({ ...base, from: [5, Number.NaN, 0] }))).field).toBe('from');
    expect((await rejection(trace({ ...base, dir: 'left' }))).field).toBe('dir');
    expect((await rejection(trace({ ...base, plane: 'xz' }))).field).toBe('plane');
    if (a.id !== 'helix') {
      // A move off the plane: from and to differ along the normal axis (a helix's job),
      // or the plane yz does not contain a move in x and y.
      expect((await rejection(trace({ ...base, to: [0, 5, 3] }))).field).toBe('to');
      expect((await rejection(trace({ ...base, plane: 'yz' }))).field).toBe('to');
    }
  });
});

describe("the circle's correction", () => {
  it('says how many steps close the gap to an end off the circle, and none for an end on it', async () => {
    // r = 5 from (5, 0); the end (0, 6) has 0² + 6² - 5² = 11 (Saleem eq. 6):
    // the circle stops at (0, 5) and one step closes the gap.
    const one = await trace({ algorithm: 'circle', from: [5, 0, 0], to: [0, 6, 0], center: [0, 0, 0] });
    expect(one.segments[0]!.note).toMatch(/u² \+ v² - r² = 11 .*so 1 correction step closes the gap\.$/);
    // The end (0, 5) is on the circle: no correction at all.
    const none = await trace({ algorithm: 'circle', from: [5, 0, 0], to: [0, 5, 0], center: [0, 0, 0] });
    expect(none.segments[0]!.note).toMatch(/to \(0, 5, 0\), which is the end point\.$/);
  });
});

describe('a circle given in x and y', () => {
  it("is the xy plane's circle at z = 0, its points, ideal path and candidates in 2 axes", async () => {
    // A pixel circle: from, to and center with 2 coordinates each.
    const [flat, spatial] = await Promise.all([
      trace({ algorithm: 'circle', from: [7, -3], to: [-2, 6], center: [-1, -2], dir: 'cw', turns: 1 }),
      trace({ algorithm: 'circle', from: [7, -3, 0], to: [-2, 6, 0], center: [-1, -2, 0], dir: 'cw', turns: 1 }),
    ]);
    expect([flat.dims, flat.steps]).toEqual([2, spatial.steps]);
    const xy = (values: ArrayLike<number>) => Array.from(values).filter((_, i) => i % 3 !== 2);
    expect(Array.from(flat.points)).toEqual(xy(spatial.points));
    expect(Array.from(flat.idealPolyline())).toEqual(xy(spatial.idealPolyline()));
    expect(flat.segments[0]!.ideal).toMatchObject({ kind: 'arc', center: [-1, -2], plane: 'xy' });
    expect(flat.segments[0]!.note).toMatch(/to \(-2, 6\), which is the end point\.$/);
    expect(flat.metrics.maxDeviation).toBe(spatial.metrics.maxDeviation);
    const candidates = (t: Trace) => (t.stepDetail(5).figure as { candidates: { cell: number[] }[] }).candidates.map((c) => c.cell);
    expect(candidates(flat)).toEqual(candidates(spatial).map((cell) => cell.slice(0, 2)));
  });

  it('takes only the xy plane, and center in as many axes as from', async () => {
    const flat = { algorithm: 'circle', from: [5, 0], to: [0, 5], center: [0, 0] } as const;
    const zx = await rejection(trace({ ...flat, plane: 'zx' }));
    expect([zx.field, zx.message]).toEqual(['plane', 'plane: from, to and center have 2 coordinates (x, y), so the arc is in the xy plane (G17), not zx (G18); give 3 coordinates for that plane']);
    expect((await rejection(trace({ ...flat, center: [0, 0, 0] }))).message).toBe('center: expected 2 coordinates, as from has, got 3');
    expect((await rejection(trace({ ...flat, algorithm: 'helix' }))).message).toBe('from: helix takes 3 coordinates, got 2');
  });
});

describe('arc-segments chord counts', () => {
  it('refuses more than 65,536 chords, naming the option and the count in a readable form', async () => {
    // Grbl's rule on a full circle of r = 10^6 with a tolerance of 1e-300:
    // floor(0.5·2π·10^6 / sqrt(1e-300·(2·10^6 - 1e-300))) ≈ 2.2e153 chords.
    const e = await rejection(trace({ algorithm: 'arc-segments', from: [1e6, 0, 0], to: [1e6, 0, 0], center: [0, 0, 0], tolerance: 1e-300 }));
    expect(e.field).toBe('tolerance');
    expect(e.message).toMatch(/splits this arc into 2\.221e153 chords, more than 65536/);
  });
});

/**
 * Saleem's two candidates (section 4, eq. 6-7) as the core hands them to the
 * page: at each arc step, the point reached and the cell `otherCandidate`
 * names from it. Checked here against u² + v² - r² worked out from the
 * points alone: the residual columns are those two cells' residuals, the
 * reached one is nearer 0, and the two differ by one in-plane step.
 */
describe("the circle's candidates", () => {
  const DECIDING = ARCS.filter((a) => a.columns.some((c) => c.name === 'otherCandidate'));

  it('are given by circle and helix; arc-segments steps chords, which have none', () => {
    expect(DECIDING.map((a) => a.id).sort()).toEqual(['circle', 'helix']);
  });

  it('match the hand-worked quarter of radius 5 (Saleem eq. 6-7)', async () => {
    // The same quarter as the Rust golden (circle_saleem.rs): (stay, move)
    // residuals per step, and the cell not taken from the one reached.
    const t = await trace({ algorithm: 'circle', from: [5, 0, 0], to: [0, 5, 0], center: [0, 0, 0] });
    expect(Array.from(t.decisions.residualStay!)).toEqual([1, 4, 9, 7, -5, 1, 0]);
    expect(Array.from(t.decisions.residualMove!)).toEqual([-8, -5, 0, 0, 4, 12, 11]);
    const other = t.columns.find((c) => c.name === 'otherCandidate')!;
    expect(Array.from(t.decisions.otherCandidate!, (v) => readDecision(other, v))).toEqual(['-x', '-x', '+x', '+x', '-y', '+y', '+y']);
  });

  it.each(DECIDING.flatMap((a) => PLANES.flatMap((plane) => (['ccw', 'cw'] as const).map((dir) => [a.id, plane, dir, a] as const))))(
    '%s in %s, %s: the step takes the candidate nearer the circle',
    async (_, plane, dir, a) => {
      // r² = 7² + 4² = 65 about a center off the origin: 210° counter-clockwise, 270° clockwise.
      const [ua, va] = PLANE_AXES[plane];
      const c = inPlane(plane, [-20, 11, 3]);
      const from = inPlane(plane, [-13, 15, 3]);
      const to = inPlane(plane, dir === 'ccw' ? [-24, 4, 3] : [-24, 18, 3]);
      const t = await trace(arcOptions(a, plane, from, to, c, dir, 5));
      const other = t.columns.find((col) => col.name === 'otherCandidate')!;
      const residual = (p: number[]) => (p[ua]! - c[ua]!) ** 2 + (p[va]! - c[va]!) ** 2 - 65;
      let decided = 0;
      for (let k = 0; k < t.steps; k++) {
        const label = readDecision(other, t.decisions.otherCandidate![k]!);
        if (label === null) {
          expect(t.decisions.residualStay![k]).toBeNaN();
          continue;
        }
        decided++;
        const reached = Array.from(t.point(k + 1));
        const axis = 'xyz'.indexOf(String(label)[1]!);
        expect([ua, va]).toContain(axis);
        const cell = reached.map((v, i) => (i === axis ? v + (String(label)[0] === '-' ? -1 : 1) : v));
        const moved = t.decisions.slowSteps![k] === 1;
        expect([t.decisions.residualStay![k], t.decisions.residualMove![k]]).toEqual(moved ? [residual(cell), residual(reached)] : [residual(reached), residual(cell)]);
        expect(Math.abs(residual(reached))).toBeLessThan(Math.abs(residual(cell)));
      }
      expect(decided).toBeGreaterThan(10);
    },
  );
});
