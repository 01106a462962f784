// Time in G-code mode (issue 14), in headless Chromium. The default program
// is a 20 mm square at F600 with Grbl's defaults (defaults.h: a = 10 mm/s²,
// max rate 500 mm/min, junction deviation 0.01 mm), so every side runs at
// 500/60 = 8.33 mm/s and each 90° corner at Grbl's junction speed
// √(a_j·δ·s/(1−s)), s = sin 45°, a_j = a·√2 along the corner's bisector.
import { readFileSync } from 'node:fs';
import { afterAll, describe, expect, it } from 'vitest';
import { closeAll, openPage, screenshot } from './harness.js';

afterAll(closeAll);

/** Seconds of a trapezoid over L mm from v0 to v1 at top speed vc, acceleration a (hand-worked: t = Δv/a per ramp, the rest at vc). */
function side(l: number, v0: number, v1: number, vc: number, a: number): number {
  const ramps = (vc * vc - v0 * v0) / (2 * a) + (vc * vc - v1 * v1) / (2 * a);
  return (vc - v0) / a + (vc - v1) / a + (l - ramps) / vc;
}

describe('G-code mode: time', () => {
  it('shows the total time, the timed STEP/DIR diagram, the speed and step-rate charts, and exports the VCD', async () => {
    const p = await openPage('?mode=gcode&stepsPerMm=80');
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: /of 6400$/ }).waitFor();
    const s = Math.SQRT1_2;
    const corner = Math.sqrt((10 * Math.SQRT2 * 0.01 * s) / (1 - s));
    const vc = 500 / 60;
    const total = side(20, 0, corner, vc, 10) + 2 * side(20, corner, corner, vc, 10) + side(20, corner, 0, vc, 10);
    await expect.poll(() => page.getByTestId('total-time').innerText()).toContain(`${total.toFixed(3)} s`);
    await page.getByTestId('timing').getByText(/planned instant \(ms\)/).waitFor();
    await page.getByTestId('motion').locator('canvas').nth(1).waitFor();
    const charts = await screenshot(page, 'gcode-time', '[data-testid=motion]');
    expect(charts.differingFraction).toBeGreaterThan(0.05);
    const timing = await screenshot(page, 'gcode-timing-seconds', '[data-testid=timing]');
    expect(timing.differingFraction).toBeGreaterThan(0.02);

    const [download] = await Promise.all([page.waitForEvent('download'), page.getByTestId('export-vcd').click()]);
    const vcd = readFileSync((await download.path())!, 'utf8');
    const id = /\$var wire 1 (\S+) x_step \$end/.exec(vcd)![1]!;
    // X moves 1600 steps out and 1600 back.
    expect(vcd.split('\n').filter((line) => line === `1${id}`).length).toBe(3200);
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});
