// Time on the page (issue 14), in headless Chromium, with the screenshots
// checked for content. Expected values are worked from Grbl 1.1's planner
// (gnea/grbl planner.c, defaults.h), not read from the page: the default
// program is a 20 mm square at F500 with Grbl's defaults (a = 10 mm/s²,
// max rate 500 mm/min, junction deviation 0.01 mm), so every side runs
// at 500/60 = 8.33 mm/s and each 90° corner is taken at Grbl's junction
// speed √(a_j·δ·s/(1−s)), s = sin 45°, a_j = a·√2 (the acceleration limited
// along the corner's bisector, limit_value_by_axis_maximum).
import { readFileSync } from 'node:fs';
import type { Page } from 'playwright-core';
import { PNG } from 'pngjs';
import { afterAll, describe, expect, it } from 'vitest';
import { AXIS_COLOURS, PALETTE } from '../../web/scene/palette.js';
import { runGcode } from '../../web/core/index.js';
import { closeAll, jumpTo, openPage, pixelsOf, screenshot } from './harness.js';

afterAll(closeAll);

const A = 10;
const TOP = 500 / 60;
const S45 = Math.SQRT1_2;
const CORNER = Math.sqrt((A * Math.SQRT2 * 0.01 * S45) / (1 - S45));

/** Seconds of a trapezoid over l mm from v0 to v1, top speed vc, acceleration a: Δv/a per ramp, the rest at vc. */
function side(l: number, v0: number, v1: number, vc: number, a: number): number {
  const ramps = (vc * vc - v0 * v0) / (2 * a) + (vc * vc - v1 * v1) / (2 * a);
  return (vc - v0) / a + (vc - v1) / a + (l - ramps) / vc;
}

/**
 * Where the first side (from rest, accelerating to 8.33 mm/s in 0.833 s over
 * 3.47 mm, cruising until it slows for the corner at 2.4 s) is at t seconds,
 * mm: s = ½at², then s_a + v·(t − t_a).
 */
function firstSideMm(t: number): number {
  const ta = TOP / A;
  return t <= ta ? 0.5 * A * t * t : 0.5 * A * ta * ta + TOP * (t - ta);
}

function counterStep(text: string): number {
  return Number(/^Step ([\d,]+) of/.exec(text)![1]!.replaceAll(',', ''));
}

async function loaded(page: Page, steps: number): Promise<void> {
  await page.getByTestId('step-counter').filter({ hasText: new RegExp(`of ${steps.toLocaleString('en-US')}$`) }).waitFor();
}

/**
 * The X STEP and DIR edges drawn in the timing diagram's plot outside its
 * pause (columns where a vertical stroke of X's colour stands, a run of
 * columns each; the pause's label is as dark): how many, their span as a
 * share of the plot's width outside the pause, and the least distance from
 * one to the next, px.
 */
async function xEdges(page: Page, name: string, pause: { x: number; width: number }) {
  const over = page.getByTestId('timing').locator('.u-over');
  await over.scrollIntoViewIfNeeded();
  const plot = (await over.boundingBox())!;
  const shot = await screenshot(page, name, plot);
  const { width, height, data } = PNG.sync.read(readFileSync(shot.file));
  const rgb = [1, 3, 5].map((i) => parseInt(AXIS_COLOURS[0]!.slice(i, i + 2), 16));
  const stroke = (x: number) => {
    let n = 0;
    for (let y = 0; y < height; y++) {
      const i = 4 * (y * width + x);
      if (rgb.every((v, c) => Math.abs(data[i + c]! - v) <= 40)) n++;
    }
    // A vertical edge is a swing high (17 px); the lanes' levels a few px a column.
    return n >= 10;
  };
  const [pauseFrom, pauseTo] = [pause.x - plot.x, pause.x + pause.width - plot.x];
  const columns = Array.from({ length: width }, (_, x) => (x < pauseFrom - 1 || x > pauseTo + 1) && stroke(x));
  const starts = columns.flatMap((on, x) => (on && !columns[x - 1] ? [x] : []));
  const first = columns.indexOf(true);
  const last = columns.lastIndexOf(true);
  const nearestPx = Math.min(...starts.slice(1).map((x, i) => x - starts[i]!));
  return { runs: starts.length, spanShare: (last - first) / (width - pause.width), first: first / width, last: last / width, nearestPx };
}

/**
 * The narrowest gap between steps from..to - 1 at `instants` (the core's, seconds), px, drawn as the
 * timing diagram spans them (from the first to the last step and its last gap again, pulseEdges'
 * right edge) over the `stepsPx` they get.
 */
function narrowestGapPx(instants: Float64Array, from: number, to: number, stepsPx: number): number {
  const drawn = instants.subarray(from, to);
  const gaps = Array.from(drawn.subarray(1), (t, i) => t - drawn[i]!);
  const span = drawn[drawn.length - 1]! - drawn[0]! + gaps[gaps.length - 1]!;
  return (Math.min(...gaps) / span) * stepsPx;
}

/**
 * The lines of the timing diagram's pause labels as drawn, and those of them
 * not whole in their box: a line's text (its glyphs' boxes, the DOM's text
 * metrics of each line it wraps to) outside its box's inside, clipped by it.
 */
async function pauseLabelLines(page: Page): Promise<{ lines: string[][]; clipped: string[] }> {
  return page.evaluate(() => {
    const boxes = [...document.querySelectorAll<HTMLElement>('[data-testid=timing] .chart-break')];
    const clipped: string[] = [];
    const lines = boxes.map((box) => {
      const outer = box.getBoundingClientRect();
      const inside = { left: outer.left + box.clientLeft, right: outer.left + box.clientLeft + box.clientWidth, top: outer.top + box.clientTop, bottom: outer.top + box.clientTop + box.clientHeight };
      return [...box.querySelectorAll('span')].map((span) => {
        const range = document.createRange();
        range.selectNodeContents(span);
        for (const r of range.getClientRects()) {
          if (r.left < inside.left - 0.5 || r.right > inside.right + 0.5 || r.top < inside.top - 0.5 || r.bottom > inside.bottom + 0.5) {
            clipped.push(`'${span.textContent}': ${r.left.toFixed(1)}..${r.right.toFixed(1)} in a box ${inside.left.toFixed(1)}..${inside.right.toFixed(1)} wide`);
          }
        }
        // A line wrapped to its words (a value keeps its unit: no-break spaces) reads as one.
        return span.textContent!.replaceAll('\u00a0', ' ');
      });
    });
    return { lines, clipped };
  });
}

/**
 * Where the timing diagram's x axis title is drawn (on its canvas, in the
 * band under the tick labels): the columns of its ink from the canvas's
 * left side, and the canvas's width, CSS pixels, read from a screenshot
 * `name` of the band. The title is black; nothing else is drawn there.
 */
async function xTitleInk(page: Page, name: string): Promise<{ fromPx: number; toPx: number; canvasPx: number }> {
  const timing = page.getByTestId('timing');
  await timing.scrollIntoViewIfNeeded();
  const canvas = (await timing.locator('canvas').boundingBox())!;
  const plot = (await timing.locator('.u-over').boundingBox())!;
  // Under the plot, past the axis's ticks and their labels (its 36 px), to the canvas's bottom.
  const top = plot.y + plot.height + 36;
  const shot = await screenshot(page, name, { x: canvas.x, y: top, width: canvas.width, height: canvas.y + canvas.height - top });
  const { width, height, data } = PNG.sync.read(readFileSync(shot.file));
  const inked = Array.from({ length: width }, (_, x) =>
    Array.from({ length: height }, (_, y) => 4 * (y * width + x)).some((i) => data[i]! < 110 && data[i + 1]! < 110 && data[i + 2]! < 110),
  );
  return { fromPx: inked.indexOf(true), toPx: inked.lastIndexOf(true), canvasPx: width };
}

/**
 * How far the timing diagram's canvas runs past its panel's content box
 * (the panel's rect less its border and computed padding) at each side,
 * CSS pixels: none, 0 or less.
 */
async function timingPastPanelPx(page: Page): Promise<{ leftPx: number; rightPx: number }> {
  return page.getByTestId('timing').evaluate((timing) => {
    const panel = timing.closest<HTMLElement>('.panel')!;
    const { paddingLeft, paddingRight } = getComputedStyle(panel);
    const outer = panel.getBoundingClientRect();
    const content = { left: outer.left + panel.clientLeft + parseFloat(paddingLeft), right: outer.left + panel.clientLeft + panel.clientWidth - parseFloat(paddingRight) };
    const canvas = timing.querySelector('canvas')!.getBoundingClientRect();
    return { leftPx: content.left - canvas.left, rightPx: canvas.right - content.right };
  });
}

/**
 * The program of one step between two waits, G1 X1 F60 then G4 P2 at 1
 * step/mm, opened in G-code mode, with its timing diagram and the diagram's
 * pause boxes.
 */
async function oneStepProgram() {
  const program = encodeURIComponent('G21 G90\nG1 X1 F60\nG4 P2\n');
  const p = await openPage(`?mode=gcode&stepsPerMm=1&gcode=${program}`);
  const { page } = p;
  await loaded(page, 1);
  const timing = page.getByTestId('timing');
  return { p, page, timing, pauseBox: timing.locator('.chart-break') };
}

describe('G-code mode: time', () => {
  it("shows the total time worked from Grbl's formulas, the current step's instant, the charts, and exports the VCD", async () => {
    const p = await openPage('?mode=gcode&stepsPerMm=80');
    const { page } = p;
    await loaded(page, 6400);
    const total = side(20, 0, CORNER, TOP, A) + 2 * side(20, CORNER, CORNER, TOP, A) + side(20, CORNER, 0, TOP, A);
    await expect.poll(() => page.getByTestId('total-time').innerText()).toContain(`${total.toFixed(3)} s for 6,400 steps`);
    // The whole program in view: four trapezoids, drawn by their corners.
    const motion = page.getByTestId('motion');
    await expect.poll(() => motion.locator('canvas').count()).toBe(2);
    expect(await motion.locator('.u-title').first().innerText()).toMatch(/each block its trapezoid/);
    await page.getByTestId('timing').getByText(/planned instant, ms/).waitFor();

    // Step 800 of the first side: 10 mm in, cruising: t = t_a + (10 − s_a)/v.
    await jumpTo(page, 800);
    const at800 = TOP / A + (10 - (0.5 * TOP * TOP) / A) / TOP;
    await expect.poll(async () => Number(await page.getByTestId('step-instant').getAttribute('data-seconds'))).toBeCloseTo(at800, 9);
    const charts = await screenshot(page, 'gcode-time-charts', '[data-testid=motion]');
    expect(charts.differingFraction).toBeGreaterThan(0.05);
    // The planned speed's curve and the y step rate's are drawn, not only the axes and legends.
    expect(pixelsOf(charts.file, PALETTE.visited)).toBeGreaterThan(300);
    expect(pixelsOf(charts.file, AXIS_COLOURS[1])).toBeGreaterThan(300);

    // A window of 1 s with the step a third of the way in: inside the first side's trapezoid.
    await page.getByTestId('motion-window').selectOption({ label: '1 s around the current step' });
    await expect.poll(() => motion.locator('.u-title').first().innerText()).toContain(`${(at800 - 1 / 3).toFixed(3)} s to ${(at800 + 2 / 3).toFixed(3)} s (each block its trapezoid`);
    // 100 ms: in seconds too, as the time axis reads (the title said ms over an axis in s).
    await page.getByTestId('motion-window').selectOption({ label: '100 ms around the current step' });
    await expect.poll(() => motion.locator('.u-title').first().innerText()).toContain(`${(at800 - 0.1 / 3).toFixed(3)} s to ${(at800 + 0.2 / 3).toFixed(3)} s`);

    const [download] = await Promise.all([page.waitForEvent('download'), page.getByTestId('export-vcd').click()]);
    const vcd = readFileSync((await download.path())!, 'utf8');
    const id = /\$var wire 1 (\S+) x_step \$end/.exec(vcd)![1]!;
    // X moves 1600 steps out and 1600 back: a rising edge each.
    expect(vcd.split('\n').filter((line) => line === `1${id}`).length).toBe(3200);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('plays in machine time: the step shown is the one the machine has reached by the clock, at the planned instants', async () => {
    const p = await openPage('?mode=gcode&stepsPerMm=80&slowdown=1');
    const { page } = p;
    await loaded(page, 6400);
    expect(await page.getByTestId('slowdown').inputValue()).toBe('1');
    await page.getByTestId('machine-time').filter({ hasText: 'the program takes' }).waitFor();
    const started = Date.now();
    await page.getByTestId('play').click();
    // Step and clock read in one task, as the page sets them together.
    const read = () =>
      page.evaluate(() => ({
        counter: document.querySelector<HTMLOutputElement>('[data-testid=step-counter]')!.value,
        seconds: document.querySelector<HTMLOutputElement>('[data-testid=machine-time]')!.dataset.seconds,
      }));
    const samples: { step: number; seconds: number }[] = [];
    // Until the clock is 1.2 s in (the first side runs until 2.4 s before it slows for the corner).
    while (Date.now() - started < 15_000 && (samples.at(-1)?.seconds ?? 0) < 1.2) {
      const { counter, seconds } = await read();
      if (seconds !== undefined) samples.push({ step: counterStep(counter), seconds: Number(seconds) });
      await page.waitForTimeout(50);
    }
    await page.getByTestId('play').click();
    const elapsed = (Date.now() - started) / 1000;
    const last = samples.at(-1)!.seconds;
    expect(last).toBeGreaterThanOrEqual(1.2);
    expect(last).toBeLessThan(2.4);
    for (const { step, seconds } of samples) {
      // Step k (0-based) of the side at (k + 1)/80 mm: by t, ⌊80·s(t)⌋ steps.
      const expected = 80 * firstSideMm(seconds);
      expect(step, `at ${seconds} s`).toBeGreaterThanOrEqual(Math.floor(expected - 1e-6));
      expect(step, `at ${seconds} s`).toBeLessThanOrEqual(Math.floor(expected + 1e-6));
    }
    // Real time, never ahead of it: the clock ran at most as long as the playback did.
    expect(last).toBeLessThanOrEqual(elapsed);
    expect(new Set(samples.map((s) => s.step)).size).toBeGreaterThan(3);
    // Some while it accelerates, where steps come ever faster (s = ½at²), not one per tick.
    expect(samples.some((s) => s.seconds < TOP / A && s.step > 0)).toBe(true);
    // Paused, a step chosen shows its own instant (the clock stood still at
    // the pause whatever step was shown): the last step, the program's end.
    await page.keyboard.press('End');
    await page.getByTestId('machine-time').filter({ hasText: /^machine time (.+) of \1$/ }).waitFor();
    await page.keyboard.press('Home');
    await page.getByTestId('machine-time').filter({ hasText: 'the program takes' }).waitFor();
    // Ten times slower: the clock is kept in the link.
    await page.getByTestId('slowdown').selectOption('10');
    await page.waitForURL(/slowdown=10/);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it("reads the STEP/DIR diagram's time in the unit of the window it draws", async () => {
    // One step, 1/80 mm at 300 mm/min: the window runs from its instant to 1 ms after (pulseEdges),
    // so the axis is in ms; by the one step's spread of 0 it was µs, labelled 50,000 and up.
    const p = await openPage(`?mode=gcode&stepsPerMm=80&step=1&gcode=${encodeURIComponent('G1 X0.0125 F300\n')}`);
    const { page } = p;
    await loaded(page, 1);
    await page.getByTestId('timing').getByText(/planned instant, ms/).waitFor();
    // One step, said so ("for 1 steps" before).
    await expect.poll(() => page.getByTestId('total-time').innerText()).toMatch(/ for 1 step \(/);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('ends the STEP/DIR window at a dwell, labelled, so that the pulses beside it stay readable, and crosses it', async () => {
    // 2 mm at 600 mm/min (a triangle of 2·√0.2 = 0.894 s, a = 10 mm/s²),
    // G4 P2, 2 mm more: 160 X steps each side of a 2 s dwell; the first
    // step after it comes √(2·(1/80)/10) = 50 ms after the dwell, from rest.
    // A window of steps counted around the current one spanned the dwell:
    // 2.4 s, its 30-odd steps of 0.3 s pressed into bars at the edges.
    const gcode = 'G21 G90\nG1 X2 F600\nG4 P2\nG1 X4\n';
    const planned = await runGcode(gcode, { stepsPerMm: 80 });
    const instants = planned.stepTimes(0, planned.trace.steps);
    planned.free();
    const p = await openPage(`?mode=gcode&stepsPerMm=80&gcode=${encodeURIComponent(gcode)}`);
    const { page } = p;
    await loaded(page, 320);
    const timing = page.getByTestId('timing');
    const pauseBox = timing.locator('.chart-break');

    // Point 160, the last step before the dwell: the window ends there, the dwell at its right edge.
    await jumpTo(page, 160);
    await expect.poll(() => pauseBox.count()).toBe(1);
    await expect.poll(() => pauseBox.innerText()).toBe('dwell 2\u00a0s\nnext step\n+2.050\u00a0s');
    const plot = (await timing.locator('.u-over').boundingBox())!;
    const box = (await pauseBox.boundingBox())!;
    // At the right edge, the steps drawn up to the dwell (steps 0..159 the first move's).
    expect(box.x + box.width).toBeCloseTo(plot.x + plot.width, 0);
    expect(box.width / plot.width).toBeLessThanOrEqual(0.46);
    const drawn = async () => [Number(await timing.getAttribute('data-from-step')), Number(await timing.getAttribute('data-to-step'))];
    const [from, to] = await drawn();
    expect(to).toBe(160);
    // Slowing to rest, each gap longer than the one before: the most steps whose narrowest gap, by the
    // core's instants, is half a tick (7 px) of the plot left of the pause: 7 steps (the window chosen for
    // the whole plot, 12 steps, drew it 4.2 px; 11 after the dwell, where 15 drew it 5.1 px).
    expect(to - from).toBeGreaterThanOrEqual(6);
    expect(narrowestGapPx(instants, from, to, box.x - plot.x)).toBeGreaterThan(6.99);
    await screenshot(page, 'timing-dwell-before', '[data-testid=timing]');
    const before = await xEdges(page, 'timing-dwell-before-plot', box);
    // The pulses spread over the plot left of the pause, most of it,
    // each apart from the next (a rise and a fall a step; DIR has no edge:
    // X only goes +), where the window across the dwell drew a few bars.
    expect(before.spanShare, JSON.stringify(before)).toBeGreaterThan(0.75);
    expect(before.last).toBeLessThan(1 - box.width / plot.width + 0.01);
    expect(before.runs, JSON.stringify(before)).toBeGreaterThanOrEqual(to - from);

    // Point 161, across the dwell: the window starts there, the dwell at its left edge.
    await jumpTo(page, 161);
    await expect.poll(() => pauseBox.innerText()).toBe('dwell 2\u00a0s\nstep before\n−2.050\u00a0s');
    const left = (await pauseBox.boundingBox())!;
    expect(left.x).toBeCloseTo(plot.x, 0);
    const [fromAfter, toAfter] = await drawn();
    expect(fromAfter).toBe(160);
    expect(narrowestGapPx(instants, fromAfter!, toAfter!, plot.x + plot.width - (left.x + left.width))).toBeGreaterThan(6.99);
    await screenshot(page, 'timing-dwell-after', '[data-testid=timing]');
    const after = await xEdges(page, 'timing-dwell-after-plot', left);
    expect(after.spanShare, JSON.stringify(after)).toBeGreaterThan(0.75);
    expect(after.first).toBeGreaterThan(left.width / plot.width - 0.01);
    expect(after.runs, JSON.stringify(after)).toBeGreaterThanOrEqual(toAfter! - fromAfter!);
    // Its time in ms, from the steps' own span (not the dwell's 2 s); the pause has no tick in it.
    await timing.getByText(/planned instant, ms/).waitFor();

    // Clicking the pause goes to the point the machine waits at: the last before it.
    await page.mouse.click(left.x + left.width / 2, left.y + left.height / 2);
    await page.getByTestId('step-counter').filter({ hasText: /^Step 160 of/ }).waitFor();
    await expect.poll(() => pauseBox.innerText()).toBe('dwell 2\u00a0s\nnext step\n+2.050\u00a0s');
    // Far from the dwell, no pause: the window counted in steps.
    await jumpTo(page, 60);
    await expect.poll(() => pauseBox.count()).toBe(0);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it("ends the STEP/DIR window at a dwell after the program's last step, labelled with the program's end", async () => {
    // 2 mm at 600 mm/min (0.894 s), then G4 P2: the program ends 2 s after its 160th and last step.
    const program = encodeURIComponent('G21 G90\nG1 X2 F600\nG4 P2\n');
    const p = await openPage(`?mode=gcode&stepsPerMm=80&gcode=${program}`);
    const { page } = p;
    await loaded(page, 160);
    const timing = page.getByTestId('timing');
    await jumpTo(page, 160);
    const pauseBox = timing.locator('.chart-break');
    await expect.poll(() => pauseBox.innerText()).toBe('dwell 2\u00a0s\nprogram ends\n+2.000\u00a0s');
    expect(await pauseBox.getAttribute('title')).toBe("a pause with a G4 dwell of 2 s in it: the program ends 2.000 s after its last step (not to scale)");
    // At the right edge, after the last steps drawn, whose time reads in ms (not the dwell's 2 s).
    const plot = (await timing.locator('.u-over').boundingBox())!;
    const box = (await pauseBox.boundingBox())!;
    expect(box.x + box.width).toBeCloseTo(plot.x + plot.width, 0);
    expect(await timing.getAttribute('data-to-step')).toBe('160');
    await timing.getByText(/planned instant, ms/).waitFor();
    await screenshot(page, 'timing-closing-dwell', '[data-testid=timing]');
    // Far from the end, no pause.
    await jumpTo(page, 40);
    await expect.poll(() => pauseBox.count()).toBe(0);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('draws the waits of a program of one step as pauses, its closing dwell to the program\'s end', async () => {
    // G1 X1 F60 at 1 step/mm, then G4 P2: the one step at 1.1 s (1 mm/s, reached and left in 0.1 s at
    // 10 mm/s²), the program's end 2 s later. With no gap to space it the diagram drew the step alone,
    // 1 ms of it, neither the dwell after it (which a program of several steps draws) nor the wait before.
    const { p, page, timing, pauseBox } = await oneStepProgram();
    await expect.poll(() => pauseBox.allInnerTexts()).toEqual(['pause\nfirst step at\n1.100\u00a0s', 'dwell 2\u00a0s\nprogram ends\n+2.000\u00a0s']);
    // The wait from the start at the left edge, the dwell at the right, the step between them read in ms.
    const plot = (await timing.locator('.u-over').boundingBox())!;
    const [before, after] = [(await pauseBox.nth(0).boundingBox())!, (await pauseBox.nth(1).boundingBox())!];
    expect(before.x).toBeCloseTo(plot.x, 0);
    expect(after.x + after.width).toBeCloseTo(plot.x + plot.width, 0);
    await timing.getByText(/planned instant, ms/).waitFor();
    await screenshot(page, 'timing-one-step', '[data-testid=timing]');
    // Each label whole in its box (the panel's plot is 174 px; in boxes of 39 px they read 'st step',
    // 'rogram e'), here, in a one-column page 320 px wide and in the 260 px column of a 721 px window.
    const labels = [
      ['pause', 'first step at', '1.100 s'],
      ['dwell 2 s', 'program ends', '+2.000 s'],
    ];
    expect(await pauseLabelLines(page)).toEqual({ lines: labels, clipped: [] });
    for (const [width, height] of [
      [320, 700],
      [721, 700],
    ] as const) {
      await page.setViewportSize({ width, height });
      await jumpTo(page, 1);
      await expect.poll(async () => (await pauseLabelLines(page)).clipped, { message: `${width} x ${height}` }).toEqual([]);
      expect((await pauseLabelLines(page)).lines).toEqual(labels);
      await timing.scrollIntoViewIfNeeded();
      await screenshot(page, `timing-one-step-${width}`, '[data-testid=timing]');
    }
    // The same at point 0, before the step: the window is the step's.
    await jumpTo(page, 0);
    await expect.poll(() => pauseBox.count()).toBe(2);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it("keeps the pauses' labels whole in their boxes down to the narrowest page, shortened, the full ones under the chart", async () => {
    // The one-step program's two pauses, the most label the diagram draws beside the fewest steps. G-code
    // mode's page fits down to 240 px (layout.test.ts, 'a narrow window'), and a chart is 200 px wide at least where its panel has room, its plot 82 px (a page of 243 to 246 px; 79 px at 240). Below some 300 px the
    // two boxes needed more than the plot for their words, were drawn narrower, and cut their labels
    // ('rogram', '.100 s', 'st step'); resized, the diagram kept the boxes it had chosen for the wider plot.
    const { p, page, timing, pauseBox } = await oneStepProgram();
    await expect.poll(() => pauseBox.count()).toBe(2);
    const full = ['pause, first step at 1.100 s', 'dwell 2 s, program ends +2.000 s'];
    const descriptions = await pauseBox.evaluateAll((boxes) => boxes.map((b) => b.getAttribute('title')));
    for (const width of [300, 280, 240]) {
      await page.setViewportSize({ width, height: 700 });
      const at = `${width} px`;
      // Each label whole in its box, once the boxes are chosen for the plot's new width.
      await expect.poll(async () => (await pauseLabelLines(page)).clipped, { message: at, timeout: 5000 }).toEqual([]);
      const { lines } = await pauseLabelLines(page);
      const plot = (await timing.locator('.u-over').boundingBox())!;
      const [before, after] = [(await pauseBox.nth(0).boundingBox())!, (await pauseBox.nth(1).boundingBox())!];
      // At the plot's edges, apart, the step between them 30% of the plot or more.
      expect(before.x, at).toBeCloseTo(plot.x, 0);
      expect(after.x + after.width, at).toBeCloseTo(plot.x + plot.width, 0);
      expect(after.x - (before.x + before.width), at).toBeGreaterThanOrEqual(0.3 * plot.width - 1);
      // What a label leaves out of its box is said under the chart, in full; the tooltip says it all.
      const caption = ((await timing.locator('figcaption').count()) ? await timing.locator('figcaption').innerText() : '').replaceAll('\u00a0', ' ');
      lines.forEach((shown, i) => {
        const whole = shown.length === 3 && `${shown[0]}, ${shown.slice(1).join(' ')}` === full[i];
        expect(whole || caption.includes(full[i]!), `${at}: '${shown.join(' / ')}', under the chart '${caption}'`).toBe(true);
      });
      expect(await pauseBox.evaluateAll((boxes) => boxes.map((b) => b.getAttribute('title'))), at).toEqual(descriptions);
      await timing.scrollIntoViewIfNeeded();
      await screenshot(page, `timing-one-step-narrow-${width}`, '[data-testid=timing]');
    }
    // Wide again, the full labels in their boxes and none under the chart.
    await page.setViewportSize({ width: 1280, height: 720 });
    await expect.poll(async () => (await pauseLabelLines(page)).lines.map((shown) => `${shown[0]}, ${shown.slice(1).join(' ')}`)).toEqual(full);
    expect(await timing.locator('figcaption').count()).toBe(0);
    expect(p.problems()).toEqual([]);
    await p.close();

    // Across a dwell in a page of 280 px, where a new window is chosen at that width: its label whole too.
    const dwell = await openPage(`?mode=gcode&stepsPerMm=80&gcode=${encodeURIComponent('G21 G90\nG1 X2 F600\nG4 P2\nG1 X4\n')}`);
    await dwell.page.setViewportSize({ width: 280, height: 700 });
    await loaded(dwell.page, 320);
    await jumpTo(dwell.page, 161);
    const across = dwell.page.getByTestId('timing');
    await expect.poll(() => across.getAttribute('data-from-step')).toBe('160');
    await expect.poll(async () => (await pauseLabelLines(dwell.page)).clipped).toEqual([]);
    const shown = (await pauseLabelLines(dwell.page)).lines[0]!;
    const under = ((await across.locator('figcaption').count()) ? await across.locator('figcaption').innerText() : '').replaceAll('\u00a0', ' ');
    expect(shown.join(', ') === 'dwell 2 s, step before, −2.050 s' || under.includes('dwell 2 s, step before −2.050 s'), `'${shown.join(' / ')}', '${under}'`).toBe(true);
    await across.scrollIntoViewIfNeeded();
    await screenshot(dwell.page, 'timing-dwell-after-narrow-280', '[data-testid=timing]');
    expect(dwell.problems()).toEqual([]);
    await dwell.close();
  });

  it("keeps the diagram's axis title whole inside its chart down to a page of 240 px", async () => {
    // The axis's title, 'planned instant (ms)', was drawn by uPlot centred under the plot: in a page under
    // 272 px (the plot 82 px at 240, the lane names' axis at its left) it ran past the canvas's right side, cut.
    const { p, page, timing, pauseBox } = await oneStepProgram();
    await expect.poll(() => pauseBox.count()).toBe(2);
    // Beside a 1280 px view, centred under the plot and whole: its ink's width, read again at each width.
    const wide = await xTitleInk(page, 'timing-x-title-1280');
    const titleInkPx = wide.toPx - wide.fromPx;
    expect(titleInkPx).toBeGreaterThan(60);
    for (const width of [300, 272, 260, 240]) {
      await page.setViewportSize({ width, height: 700 });
      const at = `${width} px`;
      // The chart resized to its panel (200 px at least, but no wider than the panel), and its window chosen again for the new plot.
      const chartPx = () =>
        timing.evaluate((t) => [t.querySelector('canvas')!.getBoundingClientRect().width, Math.min(Math.floor(t.getBoundingClientRect().width), Math.max(200, t.clientWidth - 4))]);
      await expect.poll(async () => new Set(await chartPx()).size, { message: at, timeout: 10_000 }).toBe(1);
      await expect.poll(async () => (await pauseLabelLines(page)).clipped, { message: at, timeout: 10_000 }).toEqual([]);
      const ink = await xTitleInk(page, `timing-x-title-${width}`);
      // Whole, a column clear of the canvas's sides, and as wide as beside the wide view.
      expect(ink.fromPx, at).toBeGreaterThanOrEqual(1);
      expect(ink.toPx, at).toBeLessThanOrEqual(ink.canvasPx - 2);
      expect(Math.abs(ink.toPx - ink.fromPx - titleInkPx), at).toBeLessThanOrEqual(1);
      // The canvas and the chart's title in sight: inside the page's width, the title's text inside its box.
      const { canvas, title, viewportPx } = await timing.evaluate((t) => {
        const box = (e: Element) => e.getBoundingClientRect();
        const heading = t.querySelector<HTMLElement>('.u-title')!;
        return {
          canvas: box(t.querySelector('canvas')!),
          title: { ...box(heading).toJSON(), scrollPx: heading.scrollWidth, clientPx: heading.clientWidth },
          viewportPx: document.documentElement.clientWidth,
        };
      });
      expect(canvas.left, at).toBeGreaterThanOrEqual(0);
      expect(canvas.right, at).toBeLessThanOrEqual(viewportPx);
      expect(title.scrollPx, at).toBeLessThanOrEqual(title.clientPx);
      expect([title.left >= canvas.left - 0.5, title.right <= canvas.right + 0.5], at).toEqual([true, true]);
    }
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it("fits the diagram inside its panel's content box down to a page of 240 px, its labels whole", async () => {
    // A chart was 200 px wide at least, whatever its panel: in a page of 240 to 242 px, where the inspector's
    // content box is 197.5 to 199.5 px wide, the diagram's canvas ran past it into the panel's padding, 2.5 px
    // at 240, 1.5 px at 241.
    const { p, page, timing, pauseBox } = await oneStepProgram();
    await expect.poll(() => pauseBox.count()).toBe(2);
    for (const width of [241, 240]) {
      await page.setViewportSize({ width, height: 700 });
      const at = `${width} px`;
      // Once resized for the page (a canvas drawn for the last width is wider): the most it runs past a side.
      const pastPx = async () => Math.max(...Object.values(await timingPastPanelPx(page)));
      await expect.poll(pastPx, { message: at, timeout: 10_000 }).toBeLessThanOrEqual(0);
      // Still readable: the pauses' labels whole, the axis's title whole inside the canvas.
      await expect.poll(async () => (await pauseLabelLines(page)).clipped, { message: at, timeout: 10_000 }).toEqual([]);
      const ink = await xTitleInk(page, `timing-fits-x-title-${width}`);
      expect([ink.fromPx >= 1, ink.toPx <= ink.canvasPx - 2], at).toEqual([true, true]);
      await timing.scrollIntoViewIfNeeded();
      await screenshot(page, `timing-fits-panel-${width}`, '[data-testid=timing]');
    }
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it("sizes a pause's box for the pauses drawn beside it: drawn alone in a narrow page, its label whole", async () => {
    // Moves of 10 steps 0.1 s apart between dwells of 3 s (1 mm at F60, 10 steps/mm). At the middle move's
    // first step in a page of 240 px (the plot 79 px) a window can end at either dwell, but its steps leave
    // room for one box only: it is drawn with the dwell before it alone. Its box was sized as beside the other
    // dwell's too, the two more than 70% of the plot, and came out bare, its whole label under the chart.
    const program = encodeURIComponent('G21 G90\nG1 X1 F60\nG4 P3\nG1 X2\nG4 P3\nG1 X3\n');
    const p = await openPage(`?mode=gcode&stepsPerMm=10&gcode=${program}`);
    const { page } = p;
    await page.setViewportSize({ width: 240, height: 700 });
    await loaded(page, 30);
    await jumpTo(page, 11);
    const timing = page.getByTestId('timing');
    await expect.poll(() => timing.getAttribute('data-from-step'), { timeout: 10_000 }).toBe('10');
    const pauseBox = timing.locator('.chart-break');
    await expect.poll(() => pauseBox.count()).toBe(1);
    await expect.poll(async () => (await pauseLabelLines(page)).clipped, { timeout: 10_000 }).toEqual([]);
    // Its label in its box at the plot's left, what the pause is and its time, if not in full ('dwell 3 s,
    // step before −3.150 s', wrapped to its words, takes more than 70% of the plot) then said in full under the chart.
    const { lines } = await pauseLabelLines(page);
    expect(lines).toEqual([['dwell 3 s', '−3.2 s']]);
    expect((await timing.locator('figcaption').innerText()).replaceAll('\u00a0', ' ')).toBe('Hatched, not to scale: at the left, dwell 3 s, step before −3.150 s.');
    const plot = (await timing.locator('.u-over').boundingBox())!;
    const box = (await pauseBox.boundingBox())!;
    expect(box.x).toBeCloseTo(plot.x, 0);
    // The steps keep 30% of the plot.
    expect(plot.x + plot.width - (box.x + box.width)).toBeGreaterThanOrEqual(0.3 * plot.width - 1);
    await timing.scrollIntoViewIfNeeded();
    await screenshot(page, 'timing-lone-dwell-narrow-240', '[data-testid=timing]');
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('ends the STEP/DIR window where a much faster move starts, labelled, so that the pulses before it stay readable', async () => {
    // 1 mm at 60 mm/min, then 3 mm at 3000 mm/min with 1000 mm/s²: 80 X steps 12.5 ms apart, then the
    // fast move's, speeding up from 1 mm/s, the first 4.1 ms after the slow move's last, the fifth under
    // 1.25 ms after the one before. Around the slow move's last step the window's scale was the slow
    // steps': the fast ones in it were pressed into a bar at its right edge.
    const program = encodeURIComponent('G21 G90\nG1 X1 F60\nG1 X4 F3000\n');
    const p = await openPage(`?mode=gcode&stepsPerMm=80&acceleration=1000&maxRate=3000&gcode=${program}`);
    const { page } = p;
    await loaded(page, 320);
    // A narrow window, one column: the diagram the page's width, some 40 steps.
    await page.setViewportSize({ width: 700, height: 900 });
    const timing = page.getByTestId('timing');
    await jumpTo(page, 80);
    // The window ends at the slow move's last step, the edge marked as a pause's is, with the time to the next step.
    const pauseBox = timing.locator('.chart-break');
    await expect.poll(() => pauseBox.innerText()).toBe('faster steps\nnext step\n+4.099\u00a0ms');
    expect(await pauseBox.getAttribute('title')).toBe("a faster move, its steps at least 10 times as fast as the current step's: the next step comes 4.099 ms after the last one drawn (not to scale)");
    expect(await timing.getAttribute('data-to-step')).toBe('80');
    const plot = (await timing.locator('.u-over').boundingBox())!;
    const box = (await pauseBox.boundingBox())!;
    expect(box.x + box.width).toBeCloseTo(plot.x + plot.width, 0);
    await screenshot(page, 'timing-faster', '[data-testid=timing]');
    // The pulses over the plot left of the cut, each apart from the next, their edges some px apart.
    const drawn = await xEdges(page, 'timing-faster-plot', box);
    expect(drawn.spanShare, JSON.stringify(drawn)).toBeGreaterThan(0.75);
    expect(drawn.runs, JSON.stringify(drawn)).toBeGreaterThanOrEqual(80 - Number(await timing.getAttribute('data-from-step')));
    expect(drawn.nearestPx, JSON.stringify(drawn)).toBeGreaterThanOrEqual(4);
    expect(drawn.last).toBeLessThan(1 - box.width / plot.width + 0.01);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('draws a move nine times faster beside a slow one with each of their pulses apart', async () => {
    // 1 mm at 60 mm/min, then 1 mm at 540 mm/min, with 10,000 mm/s² (the speed changes within a step):
    // 80 X steps 12.5 ms apart, then 80 steps 1.39 ms apart, instants from the core's planner. Under ten
    // times, the window is not cut; counted in steps around the slow move's last step, it drew 13 slow
    // steps beside 28 fast ones 3.9 px apart, a rise and a fall 2 px apart, some merged (77 edges for 41 steps).
    const gcode = 'G21 G90\nG1 X1 F60\nG1 X2 F540\n';
    const machine = { stepsPerMm: 80, acceleration: 10000, maxRate: 6000 };
    const planned = await runGcode(gcode, machine);
    const instants = planned.stepTimes(0, planned.trace.steps);
    planned.free();
    expect(((instants[120]! - instants[119]!) * 9) / (instants[40]! - instants[39]!)).toBeCloseTo(1, 9);
    const p = await openPage(`?mode=gcode&stepsPerMm=80&acceleration=10000&maxRate=6000&gcode=${encodeURIComponent(gcode)}`);
    const { page } = p;
    await loaded(page, 160);
    await page.setViewportSize({ width: 700, height: 900 });
    const timing = page.getByTestId('timing');
    await jumpTo(page, 80);
    // Steps of both moves, no cut.
    await expect.poll(async () => Number(await timing.getAttribute('data-to-step'))).toBeGreaterThan(85);
    const [from, to] = [Number(await timing.getAttribute('data-from-step')), Number(await timing.getAttribute('data-to-step'))];
    // The current step, 79, an eighth of the window or more from either edge (windowHolds keeps it): 5 slow steps
    // and 33 fast of a plot of 536 px, 38 ticks.
    expect([79 - from, to - 1 - 79].every((n) => n >= Math.floor((to - from) / 8)), `${from}..${to}`).toBe(true);
    expect(from).toBeLessThan(80);
    expect(await timing.locator('.chart-break').count()).toBe(0);
    const plot = (await timing.locator('.u-over').boundingBox())!;
    // The narrowest gap drawn, by the core's instants: half a tick, 7 px, of the plot.
    expect(narrowestGapPx(instants, from, to, plot.width)).toBeGreaterThan(6.99);
    await screenshot(page, 'timing-nine-times', '[data-testid=timing]');
    // Drawn so: a STEP rise and fall a step (X only goes +, DIR has no edge), each apart from the next, but
    // the first step's rise, where the line starts high at the plot's edge, and the current one's, under the cursor.
    const edges = await xEdges(page, 'timing-nine-times-plot', { x: plot.x - 10, width: 0 });
    expect(edges.runs, JSON.stringify(edges)).toBeGreaterThanOrEqual(2 * (to - from) - 2);
    expect(edges.nearestPx, JSON.stringify(edges)).toBeGreaterThanOrEqual(3);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('plays a dwell after the last move in machine time, to the end of the program', async () => {
    // 1 mm at 300 mm/min (0.63 s), then 1 s at rest: playback stopped at the last step, the clock at 0.63 s.
    const program = encodeURIComponent('G1 X1 F300\nG4 P1\n');
    const p = await openPage(`?mode=gcode&stepsPerMm=80&slowdown=1&gcode=${program}`);
    const { page } = p;
    await loaded(page, 80);
    const clock = () => page.evaluate(() => Number(document.querySelector<HTMLOutputElement>('[data-testid=machine-time]')!.dataset.seconds ?? 0));
    await page.getByTestId('play').click();
    await expect.poll(() => page.getByTestId('play').getAttribute('data-playing'), { timeout: 10_000 }).toBe('false');
    expect(await clock()).toBeCloseTo(2 * Math.sqrt(0.1) + 1, 6);
    expect(await page.getByTestId('step-counter').innerText()).toBe('Step 80 of 80');
    // Paused in that dwell, Play resumes it there (it started the program over). Every instant the
    // clock shows is recorded as the page sets it: a poll could miss the restart's first 0.2 s on a
    // loaded machine (one read only the end, 1.63 s, each time it looked).
    await page.evaluate(() => {
      const shown = document.querySelector<HTMLOutputElement>('[data-testid=machine-time]')!;
      const seen: number[] = ((window as unknown as { clockSeen: number[] }).clockSeen = []);
      new MutationObserver(() => seen.push(Number(shown.dataset.seconds ?? 0))).observe(shown, { attributeFilter: ['data-seconds'] });
    });
    await page.getByTestId('play').click();
    const earliestSeen = () => page.evaluate(() => Math.min(...(window as unknown as { clockSeen: number[] }).clockSeen));
    await expect.poll(earliestSeen, { timeout: 10_000 }).toBeLessThan(0.2);
    await expect.poll(clock, { timeout: 10_000 }).toBeGreaterThan(0.9);
    await page.getByTestId('play').click();
    const paused = await clock();
    expect(paused).toBeLessThan(2 * Math.sqrt(0.1) + 1);
    await page.getByTestId('play').click();
    const seen: number[] = [];
    while ((await page.getByTestId('play').getAttribute('data-playing')) === 'true' && seen.length < 200) {
      seen.push(await clock());
      await page.waitForTimeout(20);
    }
    // Never back before the pause.
    expect(Math.min(...seen), `paused at ${paused}, then ${seen}`).toBeGreaterThanOrEqual(paused);
    await expect.poll(() => page.getByTestId('play').getAttribute('data-playing'), { timeout: 10_000 }).toBe('false');
    expect(await clock()).toBeCloseTo(2 * Math.sqrt(0.1) + 1, 6);
    expect(await page.getByTestId('step-counter').innerText()).toBe('Step 80 of 80');
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('resumes machine time where it was paused, in a dwell too, not at the instant of the step shown', async () => {
    // 1 mm at 300 mm/min: a triangle of 2·√0.1 = 0.63 s (a = 10 mm/s²), then 3 s at rest.
    const program = encodeURIComponent('G1 X1 F300\nG4 P3\nY1\n');
    const p = await openPage(`?mode=gcode&stepsPerMm=80&slowdown=1&gcode=${program}`);
    const { page } = p;
    await loaded(page, 160);
    const clock = () => page.evaluate(() => Number(document.querySelector<HTMLOutputElement>('[data-testid=machine-time]')!.dataset.seconds ?? 0));
    await page.getByTestId('play').click();
    // Into the dwell: the first move's 80 steps done, the clock past them.
    await expect.poll(clock, { timeout: 10_000 }).toBeGreaterThan(1.2);
    await page.getByTestId('play').click();
    const paused = await clock();
    expect(await page.getByTestId('step-counter').innerText()).toBe('Step 80 of 160');
    await page.getByTestId('play').click();
    // The clock goes on from the pause: it went back to the step's instant, 0.63 s.
    const seen: number[] = [];
    for (let i = 0; i < 6; i++) {
      seen.push(await clock());
      await page.waitForTimeout(50);
    }
    await page.getByTestId('play').click();
    expect(Math.min(...seen), `paused at ${paused}, then ${seen}`).toBeGreaterThanOrEqual(paused);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('shows the speed profile and the timed STEP/DIR diagram for every sample program', { timeout: 180_000 }, async () => {
    const samples = JSON.parse(readFileSync(new URL('../../public/samples/index.json', import.meta.url), 'utf8')) as { file: string }[];
    const p = await openPage('?mode=gcode&stepsPerMm=80');
    const { page } = p;
    await loaded(page, 6400);
    // The status line still names the program before until the sample, once
    // fetched, is run: its text is read once it has changed since the pick.
    await page.evaluate(() => {
      const line = document.querySelector('[data-testid=trace-status]')!;
      new MutationObserver(() => ((window as unknown as { statusChanged: boolean }).statusChanged = true)).observe(line, { childList: true, characterData: true, subtree: true });
    });
    for (const { file } of samples) {
      const text = readFileSync(new URL(`../../public/samples/${file}`, import.meta.url), 'utf8');
      // A sample that is the program shown already (the first, the default square) is not run again.
      const runs = (await page.getByTestId('gcode-text').inputValue()) !== text;
      await page.evaluate(() => ((window as unknown as { statusChanged: boolean }).statusChanged = false));
      await page.getByTestId('sample').selectOption(file);
      await expect.poll(() => page.getByTestId('gcode-text').inputValue()).toBe(text);
      await page.waitForFunction((runs) => {
        const status = document.querySelector('[data-testid=trace-status]')!.textContent ?? '';
        return (!runs || (window as unknown as { statusChanged: boolean }).statusChanged) && /moves, [\d,]+ steps/.test(status);
      }, runs);
      const status = page.getByTestId('trace-status');
      const steps = Number(/moves, ([\d,]+) steps/.exec(await status.innerText())![1]!.replaceAll(',', ''));
      expect(steps, file).toBeGreaterThan(0);
      await loaded(page, steps);
      const motion = page.getByTestId('motion');
      // The charts of this program, not the last sample's still on screen until it arrives.
      await motion.locator('.charts[data-drawn=true]').waitFor();
      await expect.poll(() => motion.locator('canvas').count(), { message: file }).toBe(2);
      expect(await page.getByTestId('total-time').innerText()).toMatch(/^Total time on the planned profile: \d+\.\d{3} s/);
      await page.getByTestId('timing').getByText(/planned instant, (ms|µs)/).waitFor();
      const name = file.replace('.gcode', '');
      // The box of the speed and step-rate charts, which stays while the
      // charts in it are redrawn for a new window (a chart itself could be
      // replaced while the screenshot waited for it: 'not attached to the DOM').
      // A window redrawn for the cursor (it follows the playback) can leave the
      // box empty for a frame: wait for its charts again and take it again.
      let speed: Awaited<ReturnType<typeof screenshot>> | undefined;
      for (let attempt = 0; !speed; attempt++) {
        await motion.locator('.charts[data-drawn=true] canvas').first().waitFor();
        speed = await screenshot(page, `time-${name}-speed`, '[data-testid=motion] > .charts').catch((error: unknown) => {
          if (attempt >= 4) throw error;
          return undefined;
        });
      }
      expect(speed.differingFraction, file).toBeGreaterThan(0.03);
      // The planned speed's curve, not only the axes and the legend.
      expect(pixelsOf(speed.file, PALETTE.visited), file).toBeGreaterThan(300);
      const timing = await screenshot(page, `time-${name}-timing`, '[data-testid=timing]');
      expect(timing.differingFraction, file).toBeGreaterThan(0.02);
    }
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});

describe('trace mode: the speed per step under two clocks', () => {
  it("charts a line's speed at one tick a step beside a constant feed, citing the 2009 blog, and none for a circle", async () => {
    // Bresenham from (0,0) to (8,3): 8 steps, 3 of them diagonal.
    const p = await openPage('?algorithm=bresenham2d&from=0,0&to=8,3');
    const { page } = p;
    await loaded(page, 8);
    const chart = page.getByTestId('step-clocks');
    await chart.locator('canvas').waitFor();
    expect(await chart.locator('figcaption').innerText()).toContain('“This means the speed would not be constant if I applied this algorithm directly.”');
    // 5 + 3√2 ticks at 1 cell a tick.
    expect(await chart.locator('.u-title').innerText()).toContain(`takes 8 ticks) or a constant feed (${(5 + 3 * Math.SQRT2).toFixed(2)} ticks)`);
    const shot = await screenshot(page, 'trace-step-clocks', '[data-testid=step-clocks]');
    expect(shot.differingFraction).toBeGreaterThan(0.05);
    // Both clocks' curves, not only the axes and the legend.
    expect(pixelsOf(shot.file, PALETTE.current)).toBeGreaterThan(250);
    expect(pixelsOf(shot.file, PALETTE.second)).toBeGreaterThan(150);
    await page.getByTestId('algorithm').selectOption('circle');
    await page.getByTestId('trace-status').filter({ hasText: 'circle' }).waitFor();
    await expect.poll(() => chart.isHidden()).toBe(true);
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});
