// The page in headless Chromium, on Wang et al.'s worked example
// (0,0,0)->(10,7,6). Expected values come from the paper's equations, not
// from the page: eq. (10) gives M_1 = 2*7 - 10 = 4 and N_1 = 2*6 - 10 = 2,
// and the recurrence eq. (8) then gives M = 4, -2, 12, 6, 0, ... and
// N = 2, -6, 6, -2, 10, ...; M_3 = 12 > 0 and N_3 = 6 > 0 put the line in
// region d, and the third step goes to D = (3, 2, 2) (as Liu's Table 1).
//
// The README screenshots are the readme* ones the browser tests save in
// tests/browser/__screenshots__/actual/ (this file's, and embed.test.ts's
// readme-embed); refresh them with
//   cp tests/browser/__screenshots__/actual/readme.png docs/screenshot.png
//   cp tests/browser/__screenshots__/actual/readme-gcode.png docs/gcode.png
//   cp tests/browser/__screenshots__/actual/readme-embed.png docs/embed.png
import type { BrowserContext, Page } from 'playwright-core';
import type { PNG } from 'pngjs';
import { afterAll, describe, expect, it } from 'vitest';
import { canvasPng, closeAll, openPage, screenshot, siteUrl } from './harness.js';
import { STORAGE_BLOCKED_NOTE } from '../../web/state/persist.js';

afterAll(closeAll);

const EXAMPLE = '?from=0,0,0&to=10,7,6';
/** The 3D view's clear colour (scene/palette.ts), RGB. */
const BACKGROUND = [0xf4, 0xf4, 0xf0];

function text(page: Page, testId: string): Promise<string> {
  return page.getByTestId(testId).innerText();
}

/** Waits until the trace of `steps` steps is on screen and the inspector has its replayed values. */
async function traced(page: Page, steps: number): Promise<void> {
  await page.getByTestId('step-counter').filter({ hasText: new RegExp(`of ${steps.toLocaleString('en-US')}$`) }).waitFor();
  await page.getByTestId('inspector-deviation').filter({ hasText: 'grid units' }).waitFor();
}

/**
 * How long a test waits for another tab's edit to show in a tab: the writer
 * waits 400 ms (the write delay) before it writes, and the reader follows
 * at the storage event; expect.poll's own second was too short for this
 * under CI's load (the caret test saw the program before the edit at 1 s).
 */
const TABS_POLL_MS = 10_000;

/**
 * Waits until G-code mode's status says `status` (the program and machine
 * run); if it never does, fails with what the page shows and what storage
 * holds, which say which tab's write was lost.
 */
async function gcodeStatus(page: Page, status: string | RegExp): Promise<void> {
  try {
    await page.getByTestId('trace-status').filter({ hasText: status }).waitFor({ timeout: 20_000 });
  } catch (error) {
    const shown = { status: await text(page, 'trace-status'), program: await page.getByTestId('gcode-text').inputValue(), url: page.url() };
    const stored = await page.evaluate(() => JSON.stringify({ local: { ...localStorage }, session: { ...sessionStorage }, navigation: (performance.getEntriesByType('navigation')[0] as PerformanceNavigationTiming).type }));
    throw new Error(`${String(error)}\nshown: ${JSON.stringify(shown)}\nstored: ${stored}`);
  }
}

/** The inspector's value cell for a decision column. */
async function decision(page: Page, column: string): Promise<string> {
  return text(page, `inspector-value-${column}`);
}

describe('the page', () => {
  it('steps forward three times and shows the decision of eq. (8) with a drawn view', async () => {
    const p = await openPage(EXAMPLE);
    const { page } = p;
    await traced(page, 10);
    expect(await text(page, 'step-counter')).toBe('Step 0 of 10');
    expect(await text(page, 'inspector-explanation')).toMatch(/no step has been decided yet/);

    for (let i = 0; i < 3; i++) await page.getByTestId('next').click();
    expect(await text(page, 'step-counter')).toBe('Step 3 of 10');
    await expect.poll(() => decision(page, 'M')).toBe('12');
    expect(await decision(page, 'N')).toBe('6');
    expect(await decision(page, 'region')).toBe('d');
    expect(await decision(page, 'corner')).toBe('D');
    expect(await text(page, 'inspector-point')).toBe('(3, 2, 2)');
    // Distance of (3,2,2) from the line, Liu's Table 1 as printed by Wang.
    expect(await text(page, 'inspector-deviation')).toBe('0.220564 grid units');
    expect(await text(page, 'inspector-explanation')).toMatch(/M = 12 > 0 and N = 6 > 0.*region d/);
    expect(await text(page, 'segment-note')).toMatch(/M_1 = [^.]*= 2·7 - 10 = 4\./);
    // The core's bound beside the largest distance (Wang Fig. 6b's √2/2).
    expect(await text(page, 'trace-status')).toMatch(/largest distance from the ideal path 0\.441 \(the rule keeps it within 0\.707: each of the 2 passive axes/);

    const stats = await screenshot(page, 'page-step-3', '[data-testid=scene-canvas]', { background: BACKGROUND, tolerance: 2 });
    expect(stats.width).toBeGreaterThan(400);
    expect(stats.differingFraction).toBeGreaterThan(0.05);
    expect(stats.distinctColors).toBeGreaterThan(50);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('is driven by the keyboard: arrows, Home, End and Space', async () => {
    const p = await openPage(EXAMPLE);
    const { page } = p;
    await traced(page, 10);
    await page.locator('body').click({ position: { x: 5, y: 5 } });
    await page.keyboard.press('ArrowRight');
    await page.keyboard.press('ArrowRight');
    expect(await text(page, 'step-counter')).toBe('Step 2 of 10');
    await page.keyboard.press('ArrowLeft');
    expect(await text(page, 'step-counter')).toBe('Step 1 of 10');
    await page.keyboard.press('End');
    expect(await text(page, 'step-counter')).toBe('Step 10 of 10');
    await page.keyboard.press('Home');
    expect(await text(page, 'step-counter')).toBe('Step 0 of 10');
    // Space plays from the start to the end at the chosen speed, then stops.
    await page.getByTestId('speed').selectOption('64');
    await page.locator('body').click({ position: { x: 5, y: 5 } });
    await page.keyboard.press('Space');
    await page.getByTestId('step-counter').filter({ hasText: 'Step 10 of 10' }).waitFor();
    expect(await page.getByTestId('play').innerText()).toBe('Play');
    // Arrow keys in a number field change the field, not the step.
    await page.getByTestId('input-to-z').focus();
    await page.keyboard.press('ArrowLeft');
    expect(await text(page, 'step-counter')).toBe('Step 10 of 10');
    // Space on a focused disclosure opens it, and does not start playback.
    const rule = page.locator('#algorithm-about details').first();
    await rule.locator('summary').focus();
    await page.keyboard.press('Space');
    await expect.poll(() => rule.evaluate((d: HTMLDetailsElement) => d.open)).toBe(true);
    expect(await page.getByTestId('play').innerText()).toBe('Play');
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it("plays with the inspector's point always the counter's, however late each point's detail arrives", async () => {
    // Along x, point k is (k, 0, 0). The inspector writes the point at once
    // and its detail (asked of the worker) follows: a detail of a point the
    // playback has already left must not write that older point.
    const p = await openPage('?algorithm=regions&from=0,0,0&to=400,0,0');
    const { page } = p;
    await traced(page, 400);
    await page.evaluate(() => {
      const seen: string[] = [];
      (window as unknown as { seenPoints: string[] }).seenPoints = seen;
      const point = document.querySelector('[data-testid=inspector-point]')!;
      const counter = document.querySelector('[data-testid=step-counter]')!;
      new MutationObserver(() => seen.push(`${counter.textContent} shows ${point.textContent}`)).observe(point, { childList: true, characterData: true, subtree: true });
    });
    await page.getByTestId('speed').selectOption('256');
    await page.locator('body').click({ position: { x: 5, y: 5 } });
    await page.keyboard.press('Space');
    await page.getByTestId('step-counter').filter({ hasText: 'Step 400 of 400' }).waitFor();
    const seen = await page.evaluate(() => (window as unknown as { seenPoints: string[] }).seenPoints);
    expect(seen.length).toBeGreaterThan(20);
    expect(seen.filter((s) => !/^Step (\d+) of 400 shows \(\1, 0, 0\)$/.test(s))).toEqual([]);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('shows a dash, not a number, where a decision column does not apply', async () => {
    // Wang's type ② line (section 2.2): all three axes active, so no
    // discriminant, region or corner decides step 1 (the core's NO_VALUE
    // and NaN), and no exit face is drawn.
    const p = await openPage('?from=0,0,0&to=3,3,3&step=1');
    const { page } = p;
    await traced(page, 3);
    expect(await text(page, 'step-counter')).toBe('Step 1 of 3');
    await expect.poll(() => decision(page, 'tie')).toBe('no');
    for (const column of ['M', 'N', 'region', 'corner']) expect(await decision(page, column), column).toBe('—');
    expect(await page.getByTestId('decision-figure').locator('svg').count()).toBe(0);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('shows why an input is refused beside its field, and stays usable', async () => {
    const p = await openPage(EXAMPLE);
    const { page } = p;
    await traced(page, 10);
    await page.getByTestId('input-to-x').fill('2000000000');
    const error = page.getByTestId('error-to');
    // Outside the range the catalogue declares: refused as typed, in the core's words.
    await error.filter({ hasText: 'must be' }).waitFor();
    expect(await error.innerText()).toBe('x must be -1073741824 to 1073741824, got 2000000000');
    expect(await page.getByTestId('input-to-x').getAttribute('aria-invalid')).toBe('true');
    expect(await text(page, 'error-from')).toBe('');
    // The last valid path stays on screen and keeps responding.
    await page.getByTestId('next').click();
    expect(await text(page, 'step-counter')).toBe('Step 1 of 10');
    await expect.poll(() => decision(page, 'M')).toBe('4');

    // A move longer than the page draws: the limit is the page's own, with no field: the message says so, beside the end point.
    await page.getByTestId('input-to-x').fill('2000000');
    const formError = page.getByTestId('error-to');
    await formError.filter({ hasText: 'maxSteps' }).waitFor();
    expect(await text(page, 'form-error')).toBe('');
    expect(await formError.innerText()).toMatch(/^This path needs at least 2,000,000 steps; the page draws at most 1,500,000 \(its maxSteps, fixed\)\./);

    await page.getByTestId('input-to-x').fill('12');
    await traced(page, 12);
    expect(await text(page, 'form-error')).toBe('');
    expect(await text(page, 'error-to')).toBe('');
    expect(await page.getByTestId('input-to-x').getAttribute('aria-invalid')).toBe('false');
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('exports the view as a PNG with its labels: axis names, ticks and handles (the canvas alone had none)', async () => {
    const p = await openPage('?from=0,0,0&to=10,7,6');
    const { page } = p;
    await page.setViewportSize({ width: 1280, height: 800 });
    await page.getByTestId('step-counter').filter({ hasText: /of 10$/ }).waitFor();
    const [png, drawing] = [await canvasPng(page, { labels: true }), await canvasPng(page)];
    const canvas = (await page.getByTestId('scene-canvas').boundingBox())!;
    const scale = png.width / canvas.width;
    /** Pixels darker than the page's grid lines inside the page box `box` (CSS pixels), in `png`. */
    const inkIn = (png: PNG, box: { x: number; y: number; width: number; height: number }) => {
      let ink = 0;
      for (let y = Math.floor((box.y - canvas.y) * scale); y < Math.ceil((box.y - canvas.y + box.height) * scale); y++) {
        for (let x = Math.floor((box.x - canvas.x) * scale); x < Math.ceil((box.x - canvas.x + box.width) * scale); x++) {
          const i = (png.width * y + x) * 4;
          if (png.data[i]! + png.data[i + 1]! + png.data[i + 2]! < 3 * 90) ink++;
        }
      }
      return ink;
    };
    // Ink where each label stands that the drawing alone has not there.
    for (const label of [page.locator('#viewport .axis-name').filter({ hasText: /^x$/ }), page.getByTestId('handle-to')]) {
      const box = (await label.boundingBox())!;
      expect(inkIn(png, box)).toBeGreaterThan(inkIn(drawing, box) + 3);
    }
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('keeps typed endpoints over a reload (URL) and a new visit (localStorage); a link wins', async () => {
    const p = await openPage(EXAMPLE);
    const { page } = p;
    await traced(page, 10);
    await page.getByTestId('input-to-y').fill('9');
    await page.getByTestId('next').click();
    await page.getByTestId('trace-status').filter({ hasText: 'to (10, 9, 6)' }).waitFor();
    await page.waitForURL(/to=10,9,6/);

    await page.reload();
    await traced(page, 10);
    expect(await page.getByTestId('input-to-y').inputValue()).toBe('9');
    expect(await text(page, 'step-counter')).toBe('Step 1 of 10');

    await page.goto(siteUrl());
    await traced(page, 10);
    expect(await page.getByTestId('input-to-y').inputValue()).toBe('9');

    await page.goto(`${siteUrl()}?from=1,1,1&to=4,2,3`);
    await traced(page, 3);
    expect(await page.getByTestId('input-to-y').inputValue()).toBe('2');
    expect(await page.getByTestId('input-from-x').inputValue()).toBe('1');

    // What the page itself refused survives a reload as typed, with its
    // message (the field showed the last valid value again): a coordinate
    // left empty, and a machine's steps per mm that are not numbers.
    await page.getByTestId('input-to-y').fill('');
    await page.getByTestId('error-to').filter({ hasText: 'y needs a number' }).waitFor();
    await page.reload();
    await traced(page, 3);
    expect(await page.getByTestId('input-to-y').inputValue()).toBe('');
    await page.getByTestId('error-to').filter({ hasText: 'y needs a number' }).waitFor();
    await page.getByTestId('input-to-y').fill('2');
    await expect.poll(() => text(page, 'error-to')).toBe('');
    await page.reload();
    await traced(page, 3);
    expect(await page.getByTestId('input-to-y').inputValue()).toBe('2');
    await page.getByTestId('mode-gcode').click();
    await page.waitForURL(/mode=gcode/);
    const stepsPerMm = page.getByTestId('input-machine-stepsPerMm');
    await stepsPerMm.fill('80,abc');
    await page.getByTestId('error-machine-stepsPerMm').filter({ hasText: 'give one number' }).waitFor();
    await page.reload();
    await expect.poll(() => stepsPerMm.inputValue()).toBe('80,abc');
    await page.getByTestId('error-machine-stepsPerMm').filter({ hasText: 'give one number' }).waitFor();
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('keeps the move typed when another algorithm that can trace it is picked, and opens the example of one that cannot', async () => {
    // The move went back to each algorithm's example, and the one typed was
    // lost. Found by a helper's hunt through the page.
    const p = await openPage(EXAMPLE);
    const { page } = p;
    await traced(page, 10);
    const to = () => Promise.all(['x', 'y', 'z'].map((a) => page.getByTestId(`input-to-${a}`).inputValue()));
    // Untouched, each opens its own example (bresenham3d's is the same move).
    await page.getByTestId('algorithm').selectOption('circle');
    await page.getByTestId('trace-status').filter({ hasText: 'circle' }).waitFor();
    expect(await to()).toEqual(['0', '5', '0']);
    await page.getByTestId('algorithm').selectOption('regions');
    await page.getByTestId('trace-status').filter({ hasText: 'regions' }).waitFor();
    await page.getByTestId('input-to-x').fill('20');
    await page.getByTestId('input-to-y').fill('3');
    await page.getByTestId('input-to-z').fill('9');
    await page.waitForURL(/to=20,3,9/);
    for (const id of ['bresenham3d', 'nd', 'regions']) {
      await page.getByTestId('algorithm').selectOption(id);
      await page.getByTestId('trace-status').filter({ hasText: `${id}: ` }).waitFor();
      expect(await to(), id).toEqual(['20', '3', '9']);
      expect(new URL(page.url()).searchParams.get('to'), id).toBe('20,3,9');
    }
    // An arc cannot trace a line: its own example.
    await page.getByTestId('algorithm').selectOption('circle');
    await page.getByTestId('trace-status').filter({ hasText: 'circle: ' }).waitFor();
    expect(await to()).toEqual(['0', '5', '0']);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('keeps out of the link a coordinate or count the core would refuse, and keeps it as typed over a reload', async () => {
    // Only an empty field was held back: 2.5, or 2^30 + 1, went into the
    // state and the link, and the core refused it after. Found by a helper's hunt.
    const p = await openPage(EXAMPLE);
    const { page } = p;
    await traced(page, 10);
    const x = page.getByTestId('input-to-x');
    for (const [typed, said] of [
      // In the core's words, as a link's 2.5 is told (the form had its own).
      ['2.5', 'x must be an integer number of grid units, got 2.5'],
      ['1073741825', 'x must be -1073741824 to 1073741824, got 1073741825'],
      ['99999999999999999999', 'x must be -1073741824 to 1073741824, got 1'],
    ] as const) {
      await x.fill(typed);
      await page.getByTestId('error-to').filter({ hasText: said }).waitFor();
      // A step taken is written to the link with the move.
      await page.getByTestId('next').click();
      await page.waitForURL(/step=1/);
      expect(new URL(page.url()).searchParams.get('to')).toBe('10,7,6');
      await page.getByTestId('previous').click();
      await page.waitForURL(/step=0/);
    }
    await page.reload();
    await traced(page, 10);
    expect(await x.inputValue()).toBe('99999999999999999999');
    await page.getByTestId('error-to').filter({ hasText: 'x must be -1073741824 to 1073741824' }).waitFor();
    await x.fill('12');
    await page.waitForURL(/to=12,7,6/);

    // A whole-number option of the catalogue's: the experiment's count.
    await page.getByTestId('mode-experiment').click();
    const count = page.getByTestId('input-experiment-count');
    await count.fill('2.5');
    await page.getByTestId('error-experiment-count').filter({ hasText: 'must be a whole number, got 2.5' }).waitFor();
    await count.fill('3');
    await page.waitForURL(/count=3(&|$)/);
    await count.fill('3.5');
    await page.getByTestId('error-experiment-count').filter({ hasText: 'got 3.5' }).waitFor();
    await page.reload();
    await page.waitForURL(/mode=experiment.*count=3(&|$)/);
    await expect.poll(() => count.inputValue()).toBe('3.5');
    await page.getByTestId('error-experiment-count').filter({ hasText: 'got 3.5' }).waitFor();

    // Real-number options and machine settings are held to their declared
    // ranges too (an acceleration of 0 went into the link, then the core
    // refused it), in the core's words (tests/settings.test.ts checks the
    // core says the same), one of several values naming its axis.
    await page.getByTestId('mode-gcode').click();
    await page.waitForURL(/mode=gcode/);
    for (const [name, typed, said, kept] of [
      ['acceleration', '10,0,10', 'y must be 1e-100 mm/s² or more, got 0', '20'],
      ['junctionDeviation', '-1', 'must be 0 mm or more, got -1', '0.02'],
      ['stepsPerMm', '2000000', 'must be 0.001 to 1000000 steps per mm, got 2000000', '40'],
      // The count first, as the core checks it: y's 0 was said, then, once mended, the count.
      ['maxRate', '10,0', 'expected one number or 3 (x, y, z), got 2', '600'],
    ] as const) {
      const field = page.getByTestId(`input-machine-${name}`);
      await field.fill(kept);
      await page.waitForURL(new RegExp(`${name}=${kept}(&|$)`));
      await field.fill(typed);
      await page.getByTestId(`error-machine-${name}`).filter({ hasText: said }).waitFor();
      // Not in the link: it still holds the value kept.
      await page.getByTestId('gcode-text').fill(`G1 X${name.length} F100`);
      await page.waitForURL(new RegExp(`X${name.length}`));
      expect(new URL(page.url()).searchParams.get(name), name).toBe(kept);
    }
    await page.reload();
    await expect.poll(() => page.getByTestId('input-machine-acceleration').inputValue()).toBe('10,0,10');
    await page.getByTestId('error-machine-acceleration').filter({ hasText: 'y must be 1e-100 mm/s² or more' }).waitFor();
    // A real number's field too is put back as typed, with its message (it
    // showed the last valid value, silent).
    await expect.poll(() => page.getByTestId('input-machine-junctionDeviation').inputValue()).toBe('-1');
    await page.getByTestId('error-machine-junctionDeviation').filter({ hasText: 'must be 0 mm or more, got -1' }).waitFor();
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it("keeps each mode's input over a reload in another mode (a permalink holds only its own mode's)", async () => {
    const p = await openPage(EXAMPLE);
    const { page } = p;
    await traced(page, 10);
    await page.getByTestId('input-to-y').fill('9');
    await page.getByTestId('trace-status').filter({ hasText: 'to (10, 9, 6)' }).waitFor();
    await page.getByTestId('mode-gcode').click();
    const program = 'G21 G90\nG1 X3 Y4 F600\nG1 X7\n';
    await page.getByTestId('gcode-text').fill(program);
    await page.getByTestId('trace-status').filter({ hasText: '3 lines, 2 moves' }).waitFor();
    // Reloaded in Trace mode, the program is still the one typed...
    await page.getByTestId('mode-trace').click();
    await page.waitForURL(/mode=trace/);
    await page.reload();
    await traced(page, 10);
    expect(await page.getByTestId('input-to-y').inputValue()).toBe('9');
    await page.getByTestId('mode-gcode').click();
    await expect.poll(() => page.getByTestId('gcode-text').inputValue()).toBe(program);
    await page.getByTestId('trace-status').filter({ hasText: '3 lines, 2 moves' }).waitFor();
    // ...and reloaded in G-code mode (and on a new visit), the move is.
    await page.waitForURL(/mode=gcode/);
    await page.reload();
    await page.getByTestId('trace-status').filter({ hasText: '3 lines, 2 moves' }).waitFor();
    await page.goto(siteUrl());
    await page.getByTestId('trace-status').filter({ hasText: '3 lines, 2 moves' }).waitFor();
    await page.getByTestId('mode-trace').click();
    await traced(page, 10);
    expect(await page.getByTestId('input-to-y').inputValue()).toBe('9');
    // A link describes its own mode; the reader's program stays theirs.
    await page.goto(`${siteUrl()}?mode=trace&from=1,1,1&to=4,2,3`);
    await traced(page, 3);
    await page.getByTestId('mode-gcode').click();
    await expect.poll(() => page.getByTestId('gcode-text').inputValue()).toBe(program);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('keeps a refused coordinate typed in one tab over a reload after another tab typed in the same field', async () => {
    const a = await openPage('?from=0,0,0&to=10,7,6');
    await traced(a.page, 10);
    const b = await a.context.newPage();
    await b.goto(`${siteUrl()}?from=0,0,0&to=10,7,6`);
    await traced(b, 10);
    await a.page.getByTestId('input-to-x').fill('2.5');
    await a.page.getByTestId('error-to').filter({ hasText: 'x ' }).waitFor();
    // B's own refused y, typed right: its draft dropped, A's went with it.
    await b.getByTestId('input-to-y').fill('2.5');
    await b.getByTestId('error-to').filter({ hasText: 'y ' }).waitFor();
    await b.getByTestId('input-to-y').fill('8');
    await traced(b, 10);
    await a.page.reload();
    await a.page.getByTestId('error-to').filter({ hasText: 'x ' }).waitFor();
    expect(await a.page.getByTestId('input-to-x').inputValue()).toBe('2.5');
    expect(a.problems()).toEqual([]);
    await a.close();
  });

  it('keeps a program typed in one tab over a reload after another tab changed its move, or its machine', async () => {
    const a = await openPage('?mode=gcode');
    await a.page.getByTestId('trace-status').filter({ hasText: 'moves' }).waitFor();
    const b = await a.context.newPage();
    await b.goto(`${siteUrl()}?mode=trace&from=0,0,0&to=10,7,6`);
    await traced(b, 10);
    const program = 'G21 G90\nG1 X3 Y4 F600\nG1 X7\n';
    await a.page.getByTestId('gcode-text').fill(program);
    await a.page.getByTestId('trace-status').filter({ hasText: '3 lines, 2 moves' }).waitFor();
    await a.page.getByTestId('mode-trace').click();
    await a.page.waitForURL(/mode=trace/);
    // Tab B, which never touched the program, changes its move: past the
    // write delay (400 ms) it wrote every mode's part as it held it, its
    // sample program too.
    await b.getByTestId('input-to-x').fill('12');
    await traced(b, 12);
    await b.waitForTimeout(1_000);
    await a.page.reload();
    await traced(a.page, 12);
    await a.page.getByTestId('mode-gcode').click();
    await gcodeStatus(a.page, '3 lines, 2 moves');
    expect(await a.page.getByTestId('gcode-text').inputValue()).toBe(program);
    // Nor does B's machine, typed beside its own (sample) program, replace
    // A's program: each input of a mode is written by the tab that typed it.
    await a.page.getByTestId('mode-trace').click();
    await a.page.waitForURL(/mode=trace/);
    await b.getByTestId('mode-gcode').click();
    await b.getByTestId('trace-status').filter({ hasText: 'moves' }).waitFor();
    await b.getByTestId('input-machine-stepsPerMm').fill('40');
    await b.getByTestId('trace-status').filter({ hasText: 'at 40 / 40 / 40 steps/mm' }).waitFor();
    await b.waitForTimeout(1_000);
    await a.page.reload();
    await traced(a.page, 12);
    await a.page.getByTestId('mode-gcode').click();
    await gcodeStatus(a.page, /^3 lines, 2 moves, [\d,]+ steps at 40 \/ 40 \/ 40 steps\/mm/);
    expect(await a.page.getByTestId('gcode-text').inputValue()).toBe(program);
    expect(a.problems()).toEqual([]);
    await a.close();
  });

  /**
   * A second tab of `context` at `query` that hears of another tab's write
   * only when it writes itself (its storage events stopped): it types
   * before another's write reaches it, as a tab does within that tab's
   * write delay (400 ms), or while busy.
   */
  async function unhearingTab(context: BrowserContext, query: string): Promise<Page> {
    const page = await context.newPage();
    await page.addInitScript(() => {
      window.addEventListener('storage', (event) => event.stopImmediatePropagation(), { capture: true });
    });
    await page.goto(`${siteUrl()}${query}`);
    return page;
  }

  it("offers back a program typed in one tab that another tab's, typed at the same time, replaced: in both tabs and over reloads", async () => {
    const a = await openPage('?mode=gcode');
    await a.page.getByTestId('trace-status').filter({ hasText: 'moves' }).waitFor();
    const b = await unhearingTab(a.context, '?mode=gcode');
    await b.getByTestId('trace-status').filter({ hasText: 'moves' }).waitFor();
    const programA = 'G21 G90\nG1 X3 Y4 F600\nG1 X7\n';
    const programB = 'G21 G90\nG1 X5 Y1 F600\nG1 Y6\nG1 X0\n';
    await a.page.getByTestId('gcode-text').fill(programA);
    await a.page.waitForURL(/X3/);
    await b.getByTestId('gcode-text').fill(programB);
    // B keeps its program, and A's, which it writes over, to bring back; A
    // follows B's write, and offers its own program back. Each says so from
    // its side (B said A's words: that its program was replaced).
    const offers = new Map([
      [a.page, "Your program (3 lines) was replaced by another tab's program, typed at the same time."],
      [b, "The other tab's program (3 lines), typed at the same time, was written over by this one."],
    ]);
    await b.getByTestId('gcode-replaced').filter({ hasText: offers.get(b) }).waitFor();
    expect(await b.getByTestId('tabs-note').innerText()).toBe(
      "Another tab changed the program at the same time as this one: what this tab has is kept, and is what a reload shows. The other tab's program is offered back beside the editor.",
    );
    await expect.poll(() => a.page.getByTestId('gcode-text').inputValue(), { timeout: TABS_POLL_MS }).toBe(programB);
    await a.page.getByTestId('gcode-replaced').filter({ hasText: offers.get(a.page) }).waitFor();
    for (const [page, offer] of offers) {
      await page.reload();
      await gcodeStatus(page, '4 lines, 3 moves');
      await page.getByTestId('gcode-replaced').filter({ hasText: offer }).waitFor();
    }
    await a.page.getByTestId('gcode-bring-back').click();
    await a.page.getByTestId('trace-status').filter({ hasText: '3 lines, 2 moves' }).waitFor();
    await a.page.reload();
    await gcodeStatus(a.page, '3 lines, 2 moves');
    expect(await a.page.getByTestId('gcode-text').inputValue()).toBe(programA);
    expect(await a.page.getByTestId('gcode-replaced').isHidden()).toBe(true);
    expect(a.problems()).toEqual([]);
    await a.close();
  });

  it("keeps both tabs' programs of a clash when a sample then replaces the one kept: both offered, and brought back, over reloads (the other tab's too long for a link)", async () => {
    const a = await openPage('?mode=gcode');
    await a.page.getByTestId('trace-status').filter({ hasText: 'moves' }).waitFor();
    const b = await unhearingTab(a.context, '?mode=gcode');
    await b.getByTestId('trace-status').filter({ hasText: 'moves' }).waitFor();
    // A's program, 151 lines (2,500 characters), is kept under storage's own keys, not in the part.
    const programA = `G21 G90\n${Array.from({ length: 150 }, (_, i) => `G1 X${i % 10} Y4 F600\n`).join('')}`;
    const programB = 'G21 G90\nG1 X5 Y1 F600\nG1 Y6\nG1 X0\n';
    await a.page.getByTestId('gcode-text').fill(programA);
    await a.page.waitForFunction(() => localStorage.getItem('voxpath.gcode') !== null);
    await b.getByTestId('gcode-text').fill(programB);
    await b.getByTestId('gcode-replaced').filter({ hasText: "The other tab's program (151 lines), typed at the same time, was written over by this one." }).waitFor();
    await expect.poll(() => a.page.getByTestId('gcode-text').inputValue(), { timeout: TABS_POLL_MS }).toBe(programB);
    // B, whose program was kept, picks a sample: its own program is offered
    // first, A's still (it held the offer) under it; A, following, says the same from its side.
    await b.getByTestId('sample').selectOption('helix.gcode');
    const offers = (page: Page) => Promise.all(['gcode-replaced', 'gcode-second-replaced'].map(async (id) => ((await page.getByTestId(id).isHidden()) ? '' : await page.getByTestId(id).innerText())));
    // The first offer waits for the sample programs' texts (one of them is not offered) and the page's run: longer than expect.poll's 1 s on a busy machine.
    const offered = (page: Page, expected: string[]) => expect.poll(() => offers(page), { timeout: 20_000 }).toEqual(expected);
    const bothOffered = [
      "Your program (4 lines) was replaced by the sample 'Helix'. Bring it back",
      "The other tab's program (151 lines), typed at the same time, was written over by yours. Bring it back",
    ];
    await offered(b, bothOffered);
    await offered(a.page, [
      "The other tab's program (4 lines) was replaced by the sample 'Helix'. Bring it back",
      "Your program (151 lines), typed at the same time, was written over by the other tab's. Bring it back",
    ]);
    // A link's program in B, then a reload: both still offered, the first named by the link.
    const linked = 'G21 G90\nG1 X9 F600\n';
    await b.goto(`${siteUrl()}?mode=gcode&gcode=${encodeURIComponent(linked)}`);
    await gcodeStatus(b, '2 lines, 1 move');
    const linkOffered = ["Your program (4 lines) was replaced by the link's program. Bring it back", bothOffered[1]];
    await offered(b, linkOffered);
    await b.reload();
    await gcodeStatus(b, '2 lines, 1 move');
    await offered(b, linkOffered);
    // A's brought back in B: B's own stays offered, as A's words after the clash were.
    await b.getByTestId('gcode-second-bring-back').click();
    await gcodeStatus(b, '151 lines, 150 moves');
    const bOffered = ["Your program (4 lines) was replaced by another tab's program, typed at the same time. Bring it back", ''];
    await offered(b, bOffered);
    await b.reload();
    await gcodeStatus(b, '151 lines, 150 moves');
    expect(await b.getByTestId('gcode-text').inputValue()).toBe(programA);
    await offered(b, bOffered);
    // And B's own brought back: the offer goes, B's program stays over a reload.
    await b.getByTestId('gcode-bring-back').click();
    await gcodeStatus(b, '4 lines, 3 moves');
    await b.reload();
    await gcodeStatus(b, '4 lines, 3 moves');
    expect(await b.getByTestId('gcode-text').inputValue()).toBe(programB);
    expect(await offers(b)).toEqual(['', '']);
    expect(a.problems()).toEqual([]);
    await a.close();
  });

  it("offers back points typed in one tab that another tab's, typed at the same time, replaced", async () => {
    const a = await openPage(EXAMPLE);
    await traced(a.page, 10);
    const b = await unhearingTab(a.context, EXAMPLE);
    await traced(b, 10);
    const [pointsA, pointsB] = ['0,0,0\n1,1,1\n2,1,1\n', '0,0,0\n1,0,0\n'];
    await a.page.getByTestId('check-points').locator('summary').click();
    await a.page.getByTestId('learner-points').fill(pointsA);
    await a.page.waitForURL(/points=/);
    await b.getByTestId('check-points').locator('summary').click();
    await b.getByTestId('learner-points').fill(pointsB);
    // Each tab says so from its side, after a reload too (B said A's words).
    const offer = "Your points (3 lines) were replaced by another tab's, typed at the same time.";
    const othersOffer = "The other tab's points (3 lines), typed at the same time, were written over by this tab's.";
    await b.getByTestId('learner-replaced').filter({ hasText: othersOffer }).waitFor();
    expect(await b.getByTestId('tabs-note').innerText()).toBe(
      "Another tab changed your points at the same time as this one: what this tab has is kept, and is what a reload shows. The other tab's points are offered back in Check points.",
    );
    await expect.poll(() => a.page.getByTestId('learner-points').inputValue(), { timeout: TABS_POLL_MS }).toBe(pointsB);
    await a.page.getByTestId('learner-replaced').filter({ hasText: offer }).waitFor();
    await b.reload();
    await b.getByTestId('learner-replaced').filter({ hasText: othersOffer }).waitFor();
    await a.page.reload();
    await a.page.getByTestId('learner-replaced').filter({ hasText: offer }).waitFor();
    await a.page.getByTestId('learner-bring-back').click();
    await a.page.getByTestId('check-verdict').waitFor();
    expect(await a.page.getByTestId('learner-points').inputValue()).toBe(pointsA);
    expect(await a.page.getByTestId('learner-replaced').isHidden()).toBe(true);
    await a.page.reload();
    await a.page.getByTestId('check-verdict').waitFor();
    expect(await a.page.getByTestId('learner-points').inputValue()).toBe(pointsA);
    expect(a.problems()).toEqual([]);
    await a.close();
  });

  it("keeps both tabs' points of a clash when a link's points then replace the ones kept: both offered, and brought back, over reloads (the other tab's too long for a link)", async () => {
    const a = await openPage(EXAMPLE);
    await traced(a.page, 10);
    const b = await unhearingTab(a.context, EXAMPLE);
    await traced(b, 10);
    // A's points, 401 lines (2,406 characters), are kept under storage's own keys, not in the part.
    const pointsA = `0,0,0\n${Array.from({ length: 400 }, (_, i) => `${i % 10},1,1`).join('\n')}\n`;
    const pointsB = '0,0,0\n1,0,0\n';
    await a.page.getByTestId('check-points').locator('summary').click();
    await a.page.getByTestId('learner-points').fill(pointsA);
    await a.page.waitForFunction(() => localStorage.getItem('voxpath.points') !== null);
    await b.getByTestId('check-points').locator('summary').click();
    await b.getByTestId('learner-points').fill(pointsB);
    await b.getByTestId('learner-replaced').filter({ hasText: "The other tab's points (401 lines), typed at the same time, were written over by this tab's." }).waitFor();
    const offers = (page: Page) => Promise.all(['learner-replaced', 'learner-second-replaced'].map(async (id) => ((await page.getByTestId(id).isHidden()) ? '' : await page.getByTestId(id).innerText())));
    const offered = (page: Page, expected: string[]) => expect.poll(() => offers(page), { timeout: 20_000 }).toEqual(expected);
    // B, whose points were kept, opens a link with points: its own are offered first, A's under them.
    const linked = '0,0,0\n0,1,0\n1,1,1\n';
    await b.goto(`${siteUrl()}${EXAMPLE}&points=${encodeURIComponent(linked)}`);
    await traced(b, 10);
    expect(await b.getByTestId('learner-points').inputValue()).toBe(linked);
    const bothOffered = [
      "Your points (2 lines) were replaced by the link's points. Bring them back",
      "The other tab's points (401 lines), typed at the same time, were written over by yours. Bring them back",
    ];
    await offered(b, bothOffered);
    await b.reload();
    await traced(b, 10);
    await offered(b, bothOffered);
    // A's brought back in B: B's own stay offered, as A's words after the clash were.
    await b.getByTestId('learner-second-bring-back').click();
    await expect.poll(() => b.getByTestId('learner-points').inputValue(), { timeout: TABS_POLL_MS }).toBe(pointsA);
    const bOffered = ["Your points (2 lines) were replaced by another tab's, typed at the same time. Bring them back", ''];
    await offered(b, bOffered);
    await b.reload();
    await traced(b, 10);
    await offered(b, bOffered);
    expect(await b.getByTestId('learner-points').inputValue()).toBe(pointsA);
    // And B's own brought back: the offers go, B's points stay over a reload.
    await b.getByTestId('learner-bring-back').click();
    await expect.poll(() => b.getByTestId('learner-points').inputValue(), { timeout: TABS_POLL_MS }).toBe(pointsB);
    await b.reload();
    await traced(b, 10);
    await expect.poll(() => b.getByTestId('learner-points').inputValue(), { timeout: TABS_POLL_MS }).toBe(pointsB);
    expect(await offers(b)).toEqual(['', '']);
    expect(a.problems()).toEqual([]);
    await a.close();
  });

  it('shows, as it is typed there, an input another tab changes that this tab left alone: the move and the points, without writing them back', async () => {
    const a = await openPage(EXAMPLE);
    await traced(a.page, 10);
    const b = await a.context.newPage();
    await b.goto(`${siteUrl()}${EXAMPLE}`);
    await traced(b, 10);
    await a.page.getByTestId('input-to-x').fill('12');
    await traced(a.page, 12);
    // B's form, view and address follow, with a word.
    await traced(b, 12);
    expect(await b.getByTestId('input-to-x').inputValue()).toBe('12');
    await b.waitForURL(/to=12,7,6/);
    expect(await b.getByTestId('tabs-note').innerText()).toBe('Another tab changed the move: shown here as there.');
    // The learner's points too: in the box, checked.
    await a.page.getByTestId('check-points').locator('summary').click();
    await a.page.getByTestId('learner-points').fill('0,0,0\n1,1,1\n');
    await b.getByTestId('check-verdict').filter({ hasText: /^Your points part from regions at point \d+/ }).waitFor();
    expect(await b.getByTestId('learner-points').inputValue()).toBe('0,0,0\n1,1,1\n');
    // B wrote none of them back: its writes since (a step) left A's as A wrote them.
    const edit = () => b.evaluate(() => (JSON.parse(localStorage.getItem('voxpath.state')!) as { edit: string }).edit);
    const before = await edit();
    await b.getByTestId('next').click();
    await b.waitForURL(/step=1/);
    expect(await edit()).toBe(before);
    expect(await a.page.evaluate(() => (JSON.parse(localStorage.getItem('voxpath.state')!) as { edit: string }).edit)).toBe(before);
    expect(a.problems()).toEqual([]);
    await a.close();
  });

  /** Where `box`'s selection is and which way it runs, and how far it is scrolled. */
  function caret(page: Page, testId: string) {
    return page.getByTestId(testId).evaluate((box: HTMLTextAreaElement) => ({
      start: box.selectionStart,
      end: box.selectionEnd,
      direction: box.selectionDirection,
      scrollTop: box.scrollTop,
      focused: document.activeElement === box,
    }));
  }

  /** The offset of `line` (from 1), `column` (from 0) in `text`. */
  function offsetIn(text: string, line: number, column: number): number {
    return text.split('\n').slice(0, line - 1).reduce((offset, l) => offset + l.length + 1, 0) + column;
  }

  /**
   * Two tabs of one browser context in G-code mode, each once its program
   * has run: `a` (with openPage's checks) and `b`, in which `bInit` runs
   * before the page's own scripts when given.
   */
  async function twoGcodeTabs(bInit?: () => void) {
    const a = await openPage('?mode=gcode');
    await a.page.getByTestId('trace-status').filter({ hasText: 'moves' }).waitFor();
    const b = await a.context.newPage();
    if (bInit) await b.addInitScript(bInit);
    await b.goto(`${siteUrl()}?mode=gcode`);
    await b.getByTestId('trace-status').filter({ hasText: 'moves' }).waitFor();
    return { a, b };
  }

  it("keeps the caret, the selection and the scroll of a text box in use where they were when another tab's program or points are followed into it", async () => {
    const { a, b } = await twoGcodeTabs();
    // Taller than the box: B reads it scrolled down, a selection on lines 40 and 41.
    const moves = Array.from({ length: 60 }, (_, i) => `G1 X${i} Y${i} F600`);
    const before = `G21 G90\n${moves.join('\n')}\n`;
    await a.page.getByTestId('gcode-text').fill(before);
    await expect.poll(() => b.getByTestId('gcode-text').inputValue(), { timeout: TABS_POLL_MS }).toBe(before);
    const box = b.getByTestId('gcode-text');
    await box.focus();
    await box.evaluate((text: HTMLTextAreaElement, [start, end]) => {
      text.setSelectionRange(start!, end!, 'backward');
      text.scrollTop = 500;
    }, [offsetIn(before, 40, 3), offsetIn(before, 41, 5)]);
    const read = await caret(b, 'gcode-text');
    expect(read.scrollTop).toBe(500);
    // A lengthens line 10: lines 40 and 41 stand further on in the text, at the same line and column.
    const after = before.replace('G1 X8 Y8 F600', 'G1 X8 Y8 Z2 F600 (over the clamp)');
    await a.page.getByTestId('gcode-text').fill(after);
    await expect.poll(() => box.inputValue(), { timeout: TABS_POLL_MS }).toBe(after);
    expect(await caret(b, 'gcode-text')).toEqual({ ...read, start: offsetIn(after, 40, 3), end: offsetIn(after, 41, 5) });
    // A shorter program: the selection's end, on line 40, clamped to the last line, its column to that line's end.
    await box.evaluate((text: HTMLTextAreaElement, [start, end]) => text.setSelectionRange(start!, end!), [offsetIn(after, 1, 5), offsetIn(after, 40, 12)]);
    const short = 'G21 G90\nG1 X3 Y4 F600\nG1 X7';
    await a.page.getByTestId('gcode-text').fill(short);
    await expect.poll(() => box.inputValue(), { timeout: TABS_POLL_MS }).toBe(short);
    expect(await caret(b, 'gcode-text')).toMatchObject({ start: offsetIn(short, 1, 5), end: offsetIn(short, 3, 5), direction: 'forward', focused: true });
    // The points in Check points, likewise.
    await Promise.all([a.page, b].map((page) => page.getByTestId('mode-trace').click()));
    await Promise.all([a.page, b].map((page) => page.getByTestId('check-points').locator('summary').click()));
    const points = Array.from({ length: 4 }, (_, i) => `${i},${i},0`).join('\n');
    await a.page.getByTestId('learner-points').fill(points);
    const pointsBox = b.getByTestId('learner-points');
    await expect.poll(() => pointsBox.inputValue(), { timeout: TABS_POLL_MS }).toBe(points);
    await pointsBox.focus();
    await pointsBox.evaluate((text: HTMLTextAreaElement, at) => text.setSelectionRange(at, at), offsetIn(points, 2, 2));
    const morePoints = `0,0,0\n${points}`;
    await a.page.getByTestId('learner-points').fill(morePoints);
    await expect.poll(() => pointsBox.inputValue(), { timeout: TABS_POLL_MS }).toBe(morePoints);
    expect(await caret(b, 'learner-points')).toMatchObject({ start: offsetIn(morePoints, 2, 2), end: offsetIn(morePoints, 2, 2), focused: true });
    expect(a.problems()).toEqual([]);
    await a.close();
  });

  it("keeps a tab's program, in both tabs and in storage, when another tab writes back storage as it read it before that program reached it (both then showed the older program)", async () => {
    const { a, b } = await twoGcodeTabs();
    const older = 'G21 G90\nG1 X3 Y4 F600\n';
    await a.page.getByTestId('gcode-text').fill(older);
    await expect.poll(() => b.getByTestId('gcode-text').inputValue(), { timeout: TABS_POLL_MS }).toBe(older);
    const storedThen = await b.evaluate(() => localStorage.getItem('voxpath.state')!);
    const newer = 'G21 G90\nG1 X3 Y4 F600\nG1 X7';
    await a.page.getByTestId('gcode-text').fill(newer);
    await expect.poll(() => b.getByTestId('gcode-text').inputValue(), { timeout: TABS_POLL_MS }).toBe(newer);
    // B's write of storage as it read it before A's reached it (each tab
    // reads its own copy of storage), landing after A's: as B's throttled
    // write after following a program, which changes no input, does when it
    // crosses A's next write (the caret test's failure in CI).
    await b.evaluate((text) => localStorage.setItem('voxpath.state', text), storedThen);
    const storedProgram = (page: Page) =>
      page.evaluate(() => new URLSearchParams((JSON.parse(localStorage.getItem('voxpath.state')!) as { gcode: string }).gcode).get('gcode'));
    // A writes its program again: storage holds it, and both tabs show it.
    for (const page of [a.page, b]) await expect.poll(() => storedProgram(page), { timeout: TABS_POLL_MS }).toBe(newer);
    for (const page of [a.page, b]) expect(await page.getByTestId('gcode-text').inputValue()).toBe(newer);
    expect(await a.page.getByTestId('tabs-note').evaluate((note: HTMLElement) => [note.hidden, note.textContent])).toEqual([true, '']);
    expect(a.problems()).toEqual([]);
    await a.close();
  });

  it("writes nothing to storage from a tab that followed another tab's program (it wrote back storage as it had read it, which, landing after the other tab's next write, took storage back to the older program)", async () => {
    // B counts its writes of its state to localStorage.
    const { a, b } = await twoGcodeTabs(() => {
      const setItem = Storage.prototype.setItem;
      const counted = window as unknown as { stateWrites: number };
      counted.stateWrites = 0;
      Storage.prototype.setItem = function (this: Storage, key: string, value: string) {
        if (this === window.localStorage && key === 'voxpath.state') counted.stateWrites++;
        setItem.call(this, key, value);
      };
    });
    // B's throttled write, if one is due, now (as when the page is hidden), and the count from there.
    const flushed = (page: Page) =>
      page.evaluate(() => {
        window.dispatchEvent(new PageTransitionEvent('pagehide'));
        return (window as unknown as { stateWrites: number }).stateWrites;
      });
    const writes = await flushed(b);
    const program = 'G21 G90\nG1 X3 Y4 F600\n';
    await a.page.getByTestId('gcode-text').fill(program);
    await expect.poll(() => b.getByTestId('gcode-text').inputValue(), { timeout: TABS_POLL_MS }).toBe(program);
    await b.getByTestId('trace-status').filter({ hasText: ', 1 move,' }).waitFor({ timeout: TABS_POLL_MS });
    expect(await flushed(b)).toBe(writes);
    // An edit of B's own is written.
    await b.getByTestId('gcode-text').fill(`${program}G1 X7\n`);
    await expect.poll(() => a.page.getByTestId('gcode-text').inputValue(), { timeout: TABS_POLL_MS }).toBe(`${program}G1 X7\n`);
    expect(await flushed(b)).toBeGreaterThan(writes);
    expect(a.problems()).toEqual([]);
    await a.close();
  });

  it("keeps a refused text over a visit to another mode, with its message (the last valid value came back)", async () => {
    const p = await openPage(EXAMPLE);
    const { page } = p;
    await traced(page, 10);
    await page.getByTestId('input-to-y').fill('');
    await page.getByTestId('error-to').filter({ hasText: 'y needs a number' }).waitFor();
    await page.getByTestId('mode-gcode').click();
    await page.getByTestId('trace-status').filter({ hasText: 'moves' }).waitFor();
    await page.getByTestId('mode-trace').click();
    await page.getByTestId('error-to').filter({ hasText: 'y needs a number' }).waitFor();
    expect(await page.getByTestId('input-to-y').inputValue()).toBe('');
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  /**
   * G-code mode with a 3-line program typed whose comment of 12 million
   * characters is past any browser's few MB of storage (quick to run), once
   * the storage note says so.
   */
  async function programTooLargeToStore() {
    const p = await openPage('?mode=gcode');
    const { page } = p;
    await page.getByTestId('trace-status').filter({ hasText: 'moves' }).waitFor();
    const note = page.getByTestId('storage-note');
    await page.evaluate(() => {
      const text = document.querySelector<HTMLTextAreaElement>('[data-testid=gcode-text]')!;
      text.value = `G21 G90\nG1 X3 Y4 F600\n(${'x'.repeat(12_000_000)})\n`;
      text.dispatchEvent(new Event('input', { bubbles: true }));
    });
    await note.filter({ hasText: "Too large for the browser's storage" }).waitFor();
    return { p, page, note };
  }

  it("says when a program is too large for the browser's storage, and keeps the rest (it was lost silently)", async () => {
    const { p, page, note } = await programTooLargeToStore();
    // The rest of the state is kept: steps/mm typed after it come back.
    await page.getByTestId('input-machine-stepsPerMm').fill('40');
    await page.waitForURL(/stepsPerMm=40/);
    await page.reload();
    await expect.poll(() => page.getByTestId('input-machine-stepsPerMm').inputValue()).toBe('40');
    // A program that fits: kept, and the note goes.
    await page.getByTestId('gcode-text').fill('G21 G90\nG1 X3 F600\n');
    await expect.poll(() => note.isHidden()).toBe(true);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it("says when a program a sample replaced, kept to bring back, is too large for the browser's storage", async () => {
    const { p, page, note } = await programTooLargeToStore();
    // The sample fits, but the program it replaced, offered back, does not: still said.
    await page.getByTestId('sample').selectOption('helix.gcode');
    await page.getByTestId('gcode-replaced').filter({ hasText: "Your program (3 lines) was replaced by the sample 'Helix'." }).waitFor();
    // Written: the address holds the sample.
    await page.waitForURL(/P3/);
    expect(await note.innerText()).toMatch(/the replaced program offered back will not come back after a reload/);
    // Brought back, the program itself is too large: said as before.
    await page.getByTestId('gcode-bring-back').click();
    await page.getByTestId('trace-status').filter({ hasText: '3 lines' }).waitFor();
    expect(await note.isVisible()).toBe(true);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it("says, once and under the status, that what is typed is not kept where the browser blocks storage, and what the address keeps (it was lost on reload with no word)", async () => {
    const blocked: [string, () => void][] = [
      // Blocked by the browser's settings: reaching either area throws.
      [
        'storage-blocked',
        () => {
          for (const name of ['localStorage', 'sessionStorage']) {
            Object.defineProperty(window, name, {
              get() {
                throw new DOMException('The operation is insecure.', 'SecurityError');
              },
            });
          }
        },
      ],
      // Damaged, as Firefox's: every read throws.
      [
        'storage-damaged',
        () => {
          Storage.prototype.getItem = () => {
            throw new DOMException('NS_ERROR_FILE_CORRUPTED', 'NS_ERROR_FILE_CORRUPTED');
          };
        },
      ],
    ];
    for (const [name, initScript] of blocked) {
      const p = await openPage(EXAMPLE, { initScript });
      const { page } = p;
      await traced(page, 10);
      const note = page.getByTestId('storage-blocked');
      expect(await note.innerText()).toBe(STORAGE_BLOCKED_NOTE);
      expect(STORAGE_BLOCKED_NOTE).toMatch(/^Your browser blocks this page's storage, .*: the inputs of the mode shown, with a program or points of up to 2,000 characters\. Bookmark or copy the address to keep them\.$/);
      // Under the status line, in the inputs' column.
      await note.scrollIntoViewIfNeeded();
      const [status, shown] = [(await page.getByTestId('trace-status').boundingBox())!, (await note.boundingBox())!];
      expect(shown.y).toBeGreaterThanOrEqual(status.y + status.height);
      await screenshot(page, name, { x: 0, y: Math.max(0, status.y - 60), width: 640, height: shown.y + shown.height + 20 - Math.max(0, status.y - 60) });
      // A narrow window's: within the page's width, no sideways scroll.
      await page.setViewportSize({ width: 320, height: 720 });
      await note.scrollIntoViewIfNeeded();
      const narrow = (await note.boundingBox())!;
      expect(narrow.x + narrow.width).toBeLessThanOrEqual(320);
      expect(await page.evaluate(() => document.documentElement.scrollWidth)).toBeLessThanOrEqual(320);
      await screenshot(page, `${name}-320`, { x: 0, y: Math.max(0, narrow.y - 80), width: 320, height: narrow.height + 100 });
      await page.setViewportSize({ width: 1280, height: 720 });
      // What the note says the address keeps comes back over a reload.
      await page.getByTestId('input-to-x').fill('12');
      await page.waitForURL(/to=12,7,6/);
      await page.reload();
      await traced(page, 12);
      expect(await note.innerText()).toBe(STORAGE_BLOCKED_NOTE);
      expect(p.problems()).toEqual([]);
      await p.close();
    }
    // Not said where storage keeps the inputs, nor in an embedded view, which keeps nothing in storage anyway.
    for (const [query, initScript] of [[EXAMPLE, undefined], [`${EXAMPLE}&embed=1`, blocked[0]![1]]] as const) {
      const p = await openPage(query, { initScript });
      await p.page.getByTestId('step-counter').filter({ hasText: /of 10$/ }).waitFor();
      expect(await p.page.getByTestId('storage-blocked').isHidden()).toBe(true);
      await p.close();
    }
  });

  it('keeps what was typed just before a reload (the address written after the request went)', async () => {
    const p = await openPage(EXAMPLE);
    const { page } = p;
    await traced(page, 10);
    // No wait for the throttled address: the reload requests the one before.
    await page.getByTestId('input-to-x').fill('13');
    await page.reload();
    await traced(page, 13);
    expect(await page.getByTestId('input-to-x').inputValue()).toBe('13');
    await page.waitForURL(/to=13,7,6/);
    // Once: a later visit to the old address is that address's state.
    await page.goto(`${siteUrl()}${EXAMPLE}`);
    await traced(page, 10);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('keeps what was typed over a reload that asks for the address from before the last write (as Chromium\'s does, 6 in 300, when it comes while the written address is on its way)', async () => {
    const p = await openPage(EXAMPLE);
    const { page } = p;
    await traced(page, 10);
    await page.getByTestId('input-to-x').fill('13');
    // Written: no write is pending at the reload.
    await page.waitForURL(/to=13,7,6/);
    // The reload asks for the address the page had before: redirected there.
    await page.route((url) => url.search.includes('to=13,7,6'), (route) => route.fulfill({ status: 302, headers: { location: `${siteUrl()}${EXAMPLE}` } }), { times: 1 });
    await page.reload();
    await traced(page, 13);
    expect(await page.getByTestId('input-to-x').inputValue()).toBe('13');
    await page.waitForURL(/to=13,7,6/);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it("saves the README screenshot of the G-code mode: the square sample at step 2000, line 5's", async () => {
    // 1600 steps a side (20 mm at 80 steps/mm): steps 1601..3200 are line 5's (Y20).
    const p = await openPage('?mode=gcode&stepsPerMm=80&step=2000');
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: 'Step 2,000 of 6,400' }).waitFor();
    await expect.poll(() => page.getByTestId('gcode-current-line').getAttribute('data-line')).toBe('5');
    await page.getByTestId('moves-table').waitFor();
    await page.getByTestId('inspector-deviation').filter({ hasText: 'grid units' }).waitFor();
    const stats = await screenshot(page, 'readme-gcode');
    expect(stats).toMatchObject({ width: 1280, height: 720 });
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('saves the README screenshot: the example line at its tie, step 5 of 10, its exit face drawn', async () => {
    // Close to the current cell, so that its exit face and the crossing read.
    const p = await openPage(`${EXAMPLE}&step=5&decision3d=1&camera=10.5,-1.5,7.5,5,3.5,3,1`);
    const { page } = p;
    await traced(page, 10);
    await expect.poll(() => decision(page, 'region')).toBe('g');
    const stats = await screenshot(page, 'readme');
    expect(stats).toMatchObject({ width: 1280, height: 720 });
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});
