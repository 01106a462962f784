// Time on the planned motion profile (Grbl 1.1's planner, rust/src/planner.rs)
// through the headless API and the CLI, against the real wasm. The issue's
// example, worked by hand: G1 X200 F6000 at a = 100 mm/s² from rest reaches
// 100 mm/s in v/a = 1 s over v²/2a = 50 mm, cruises 100 mm in 1 s and stops
// in 1 s: 3.0 s. At 80 steps/mm the 400th step is at 5 mm, where s = ½at²
// gives t = √(2·5/100) s.
import { describe, expect, it } from 'vitest';
import { pulseTrains, runGcode, trace } from '../web/core/index.js';
import { voxpath } from './helpers.js';

const EXAMPLE = 'G1 X200 F6000\n';
const MACHINE = { stepsPerMm: 80, acceleration: 100, maxRate: 6000 };
const FLAGS = ['--steps-per-mm', '80', '--acceleration', '100', '--max-rate', '6000'];

/** Rising and falling edge times (ns) of a VCD wire, read from the dump's text. */
function vcdEdges(text: string, wire: string): { rising: number[]; falling: number[] } {
  const id = new RegExp(`\\$var wire 1 (\\S+) ${wire} \\$end`).exec(text)?.[1];
  if (id === undefined) throw new Error(`no wire ${wire}`);
  const rising: number[] = [];
  const falling: number[] = [];
  let now = 0;
  let body = false;
  for (const line of text.split('\n')) {
    if (line.startsWith('$enddefinitions')) body = true;
    if (!body) continue;
    if (line.startsWith('#')) now = Number(line.slice(1));
    else if (line === `1${id}`) rising.push(now);
    else if (line === `0${id}` && now > 0) falling.push(now);
  }
  return { rising, falling };
}

describe('the planned motion profile', () => {
  it("keeps the speed profile's times in order across a long arc's chords (they went back by up to 7e-12 s)", async () => {
    const p = await runGcode('G0 X1\nG2 X1 I-1 P20 F1000\n', { stepsPerMm: 100 });
    const profile = p.speedProfile();
    let backwards = 0;
    for (let k = 2; k < profile.length; k += 2) if (profile[k]! < profile[k - 2]!) backwards++;
    expect([profile.length / 2 > 3000, backwards]).toEqual([true, 0]);
    p.free();
  });

  it('times the issue example: 3.0 s, the 400th step at √(2·5/100) s', async () => {
    const p = await runGcode(EXAMPLE, MACHINE);
    expect(p.durationSeconds).toBeCloseTo(3.0, 12);
    const t = p.moves[0]!.timing;
    expect([t.startSeconds, t.entrySpeed, t.exitSpeed]).toEqual([0, 0, 0]);
    expect(t.cruiseSpeed).toBeCloseTo(100, 9);
    expect(t.endSeconds).toBeCloseTo(3.0, 12);
    const times = p.stepTimes(0, p.steps);
    expect(times).toBeInstanceOf(Float64Array);
    expect(times.length).toBe(16_000);
    expect(times[399]).toBeCloseTo(Math.sqrt((2 * 5) / 100), 12);
    expect(p.stepTimes(399, 400)[0]).toBe(times[399]);
    // Cruising at 100 mm/s: 8000 steps/s on X.
    const [x] = pulseTrains(p.trace, 7000, 7100, p.stepTimes(7000, 7100));
    expect(x!.edgeSeconds!.length).toBe(100);
    expect(x!.rateHz![1]).toBeCloseTo(8000, 6);
    expect(Number.isNaN(x!.rateHz![0])).toBe(true);
    expect(() => p.stepTimes(0, 16_001)).toThrow(/outside 0..16000/);
    p.free();
  });

  it("uses Grbl's defaults when no limits are given, and warns where Grbl would refuse", async () => {
    // defaults.h: max rate 500 mm/min and 10 mm/s² on every axis. G1 X10 has
    // no F, so it is timed at the max rate, v = 500/60 mm/s, from rest; it
    // ends at the next move's feed, which Grbl's max entry speed takes as the
    // lower nominal speed of the two: up v/a seconds, down (v − v1)/a, the
    // rest of the 10 mm cruising at v. That move is in inverse time: F2 on
    // 10 mm is 20 mm/min (planner.c: programmed_rate = feed_rate * millimeters).
    const p = await runGcode('G1 X10\nG93 G1 X20 F2\n', { stepsPerMm: 80 });
    const [a, v, v1] = [10, 500 / 60, 20 / 60];
    const cruiseMm = 10 - (v * v) / (2 * a) - (v * v - v1 * v1) / (2 * a);
    expect(p.moves[0]!.timing.cruiseSpeed).toBeCloseTo(v, 9);
    expect(p.moves[0]!.timing.exitSpeed).toBeCloseTo(v1, 9);
    expect(p.moves[0]!.timing.endSeconds).toBeCloseTo(v / a + (v - v1) / a + cruiseMm / v, 9);
    expect(p.moves[1]!.feedMmPerMin).toBeCloseTo(20, 9);
    expect(p.warnings.map((w) => [w.line, w.message.match(/error 22|G93/)?.[0]])).toEqual([[1, 'error 22']]);
    p.free();
    const bad = runGcode('G1 X1 F1', { stepsPerMm: 80, acceleration: -1 });
    await expect(bad).rejects.toMatchObject({ field: 'acceleration' });
  });
});

describe('inverse time (G93)', () => {
  it('runs a line in 1/F minutes at F times its length (planner.c: programmed_rate = feed_rate * millimeters)', async () => {
    // F6 on 10 mm: 60 mm/min, v = 1 mm/s; at a = 10 mm/s² the trapezoid is
    // up v/a, down v/a, and the rest of the 10 mm at v.
    const p = await runGcode('G93 G1 X10 F6\n', { stepsPerMm: 80, acceleration: 10, maxRate: 6000 });
    const [a, v] = [10, 1];
    expect(p.moves[0]!.feedMmPerMin).toBeCloseTo(60, 9);
    expect(p.durationSeconds).toBeCloseTo((2 * v) / a + (10 - (v * v) / a) / v, 9);
    expect(p.warnings).toEqual([]);
    p.free();
  });

  it("warns where Grbl's feed limits change the time G93 asks for: its max rate and its least feed", async () => {
    // 0.1 mm at F2: 0.2 mm/min, which Grbl raises to its MINIMUM_FEED_RATE,
    // 1 mm/min (planner.c): 6 s, not 30; the same below 1 mm/min in G94.
    const slow = await runGcode('G93 G1 X0.1 F2\nG94 G1 X0 F0.5\n', { stepsPerMm: 80, acceleration: 10, maxRate: 6000 });
    expect(slow.warnings.map((w) => [w.line, w.message])).toEqual([
      [1, "G93 F2 (0.2 mm/min along this move, to run it in 1/2 min) is below Grbl's least feed, 1 mm/min (planner.c, MINIMUM_FEED_RATE): it runs at 1 mm/min, as Grbl runs it"],
      [2, "F0.5 mm/min is below Grbl's least feed, 1 mm/min (planner.c, MINIMUM_FEED_RATE): it runs at 1 mm/min, as Grbl runs it"],
    ]);
    expect(slow.moves[0]!.timing.cruiseSpeed).toBeCloseTo(1 / 60, 12);
    slow.free();
    // 1000 mm at F10000000: 10^10 mm/min, said and run as such where the
    // max rate allows it (it was held to 10^9 without a word).
    const far = await runGcode('G93 G1 X1000 F10000000\n', { stepsPerMm: 1, maxRate: 1e12, acceleration: 1e16 });
    expect(far.moves[0]!.feedMmPerMin).toBeCloseTo(1e10, 0);
    expect(far.moves[0]!.timing.cruiseSpeed).toBeCloseTo(1e10 / 60, 0);
    expect(far.warnings).toEqual([]);
    far.free();
    // A G93 feed and a G94 F of the same mm/min are told apart: each warned of.
    const both = await runGcode('G93 G1 X10 F0.05\nG94 G1 X20 F0.5\n', { stepsPerMm: 80 });
    expect(both.warnings.map((w) => w.line)).toEqual([1, 2]);
    both.free();
    // 10 mm at F100: 1000 mm/min, twice Grbl's default max rate.
    const fast = await runGcode('G93 G1 X10 F100\n', { stepsPerMm: 80 });
    expect(fast.warnings.map((w) => w.message)).toEqual([
      "G93 F100 (1000 mm/min along this move, to run it in 1/100 min) is above the max rate along this move (500 mm/min, from maxRate, Grbl's $110-$112): it runs at 500 mm/min, as Grbl caps it; raise maxRate to run it in 1/100 min",
    ]);
    fast.free();
  });

  it('runs an arc in 1/F minutes along all its chords, as mc_arc means to and RS274/NGC says', async () => {
    // A half circle of r = 10 mm at F2: 30 s along its chords. The
    // acceleration is high enough (10^6 mm/s²) that its ramps and corners
    // take microseconds; its feed is F times the chords' summed length,
    // below the arc's 10π mm. Grbl 1.1 would run its 78 chords
    // (floor(5π / √(0.002 · 19.998)), arc tolerance 0.002 mm) at F·78 =
    // 156 mm/min, about 12 s: it clears the inverse-time flag after scaling F.
    const settings = { stepsPerMm: 100, acceleration: 1e6, maxRate: 1e5, junctionDeviation: 1 };
    const p = await runGcode('G93 G2 X20 Y0 I10 J0 F2\n', settings);
    const feed = p.moves[0]!.feedMmPerMin!;
    expect(feed / 2).toBeGreaterThan(10 * Math.PI * 0.999);
    expect(feed / 2).toBeLessThan(10 * Math.PI);
    expect(p.durationSeconds).toBeCloseTo(30, 3);
    // The next line's F is its own: F1 runs the same half circle back in 60 s.
    const back = await runGcode('G93 G2 X20 Y0 I10 J0 F2\nG3 X0 Y0 I-10 J0 F1\n', settings);
    expect(back.moves[1]!.timing.endSeconds - back.moves[1]!.timing.startSeconds).toBeCloseTo(60, 3);
    p.free();
    back.free();
  });
});

describe('chart rows and the step reached at an instant, for the page', () => {
  it("charts the example's trapezoid by its corners, and a window of a long program in buckets", async () => {
    const p = await runGcode(EXAMPLE, MACHINE);
    // One block: 0 -> 100 mm/s by 1 s, cruise to 2 s, 0 at 3 s; X steps 80 per mm.
    const c = p.motionChart(0, 10, 1000);
    expect(c.exact).toBe(true);
    expect([c.fromSeconds, c.toSeconds]).toEqual([0, 3]);
    expect(c.seconds.map((t) => Number(t.toFixed(9)))).toEqual([0, 1, 2, 3]);
    expect(c.speedMax.map((v) => Number(v!.toFixed(9)))).toEqual([0, 100, 100, 0]);
    expect(c.stepRateMax[0]!.map((v) => Number(v!.toFixed(6)))).toEqual([0, 8000, 8000, 0]);
    expect(c.junctionSpeed).toEqual([null, null, null, null]);
    // Inside the acceleration, by t the machine has taken ⌊80·½at²⌋ steps (the 400th at √(2·5/100) s).
    expect(p.pointAtSeconds(Math.sqrt(0.1))).toBe(400);
    expect(p.pointAtSeconds(0.2501)).toBe(250);
    expect(p.pointAtSeconds(-1)).toBe(0);
    expect(p.pointAtSeconds(99)).toBe(16_000);
    expect(() => p.pointAtSeconds(Number.NaN)).toThrow(/seconds/);
    expect(() => p.motionChart(2, 1, 10)).toThrow(/^toSeconds: must be greater than fromSeconds; got 2..1$/);
    p.free();
    // 2,000 moves out and back along X, each reversal a stop: 500 buckets, each with its least and greatest.
    const long = await runGcode(Array.from({ length: 2000 }, (_, i) => `G1 X${i % 2 === 0 ? 1 : 0} F600`).join('\n'), { stepsPerMm: 80 });
    const b = long.motionChart(0, long.durationSeconds, 500);
    expect(b.exact).toBe(false);
    expect(b.seconds.length).toBe(500);
    expect(b.speedMin.every((v) => v === 0)).toBe(true);
    // 1 mm from rest to rest at 10 mm/s²: a triangle peaking at √(a·L) = √10 mm/s, under the 8.33 mm/s cap.
    expect(Math.max(...b.speedMax.map((v) => v!))).toBeCloseTo(Math.sqrt(10), 9);
    // Every reversal is a stop, and the buckets mark them: with four moves a bucket, nearly every bucket has a move start in it.
    const marked = b.junctionSpeed.filter((v) => v !== null);
    expect(marked.length).toBeGreaterThan(400);
    expect(marked.every((v) => v === 0)).toBe(true);
    long.free();
  });

  it('tells the dwell in the pause between two steps, for the timing diagram', async () => {
    // Grbl's defaults (10 mm/s²): 2 mm at 600 mm/min is a triangle of
    // 2·√(2·1/10) s, then G4 P2; the next move's first step 1/80 mm from rest, √(2/800) s later.
    const p = await runGcode('G21 G90\nG1 X2 F600\nG4 P2\nG1 X4\n', { stepsPerMm: 80 });
    const [before, after] = p.stepTimes(159, 161);
    expect(before).toBeCloseTo(2 * Math.sqrt(0.2), 9);
    expect(after! - before!).toBeCloseTo(2 + Math.sqrt(2 / 800), 9);
    expect(p.dwellSeconds(before!, after!)).toBeCloseTo(2, 12);
    expect(p.dwellSeconds(0, before!)).toBe(0);
    expect(p.dwellSeconds(after!, Number.POSITIVE_INFINITY)).toBe(0);
    p.free();
  });

  it("gives a trace's speed per step at one tick a step and at a constant feed", async () => {
    // Bresenham (0,0) -> (8,3): 5 axis steps and 3 diagonal ones.
    const t = await trace({ algorithm: 'bresenham2d', from: [0, 0], to: [8, 3] });
    const c = t.stepClocks(100);
    expect(c.rowEdges).toEqual([0, 1, 2, 3, 4, 5, 6, 7, 8]);
    expect([...c.equalTickMax].sort()).toEqual([1, 1, 1, 1, 1, Math.SQRT2, Math.SQRT2, Math.SQRT2]);
    expect(c.equalTickTotalTicks).toBe(8);
    expect(c.feedTotalTicks).toBeCloseTo(5 + 3 * Math.SQRT2, 12);
    expect(c.feedCellsPerTick).toBe(1);
    expect(t.stepClocks(1).equalTickMin).toEqual([1]);
    t.free();
  });
});

describe('voxpath gcode timing', () => {
  it('reports the duration, the step times and a VCD of 16,000 X STEP pulses', () => {
    const json = voxpath(['gcode', '-', ...FLAGS, '--step-times'], EXAMPLE);
    expect(json.code).toBe(0);
    const out = JSON.parse(json.stdout) as { durationSeconds: number; stepTimes: number[] };
    expect(out.durationSeconds).toBeCloseTo(3.0, 12);
    expect(out.stepTimes[399]).toBeCloseTo(Math.sqrt(0.1), 12);

    const vcd = voxpath(['gcode', '-', ...FLAGS, '--format', 'vcd'], EXAMPLE);
    expect(vcd.code).toBe(0);
    expect(vcd.stdout).toMatch(/\$timescale\s+1\s*ns\s+\$end/);
    const x = vcdEdges(vcd.stdout, 'x_step');
    // One rising edge per step; each pulse falls 10 µs later (Grbl's default).
    expect(x.rising.length).toBe(16_000);
    expect(x.falling.length).toBe(16_000);
    expect(x.rising[399]).toBe(Math.round(Math.sqrt(0.1) * 1e9));
    expect(x.rising[15_999]).toBe(3e9);
    expect(x.falling[7000]! - x.rising[7000]!).toBe(10_000);
    expect(vcdEdges(vcd.stdout, 'y_step').rising.length).toBe(0);

    const table = voxpath(['gcode', '-', ...FLAGS, '--format', 'table'], EXAMPLE);
    expect(table.stdout).toMatch(/duration on the planned profile: 3 s/);
    const misuse = voxpath(['gcode', '-', ...FLAGS, '--step-times', '--format', 'csv'], EXAMPLE);
    expect(misuse.code).toBe(2);
    // Four CLI processes, each loading the wasm: seconds on a loaded 2-core machine.
  }, 30_000);
});
