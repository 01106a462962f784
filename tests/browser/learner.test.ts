// The page as a learner meets it (issue 16), in headless Chromium: machine
// settings typed as on the command line, messages that say what to do on
// the page, and results that say when they are out of date. Expected values
// come from the inputs: regions takes one step per unit of the longest axis
// (Wang et al. 2020, section 2), so a G-code move of (dx, dy, dz) steps takes
// max(|dx|, |dy|, |dz|) of them.
import type { Page } from 'playwright-core';
import { PNG } from 'pngjs';
import { afterAll, describe, expect, it } from 'vitest';
import { catalogue, trace } from '../../web/core/index.js';
import { PALETTE } from '../../web/scene/palette.js';
import { canvasPng, closeAll, jumpTo, openPage, screenshot } from './harness.js';

afterAll(closeAll);

function text(page: Page, testId: string): Promise<string> {
  return page.getByTestId(testId).innerText();
}

/** Waits for the status line to contain `wanted`. */
async function status(page: Page, wanted: string | RegExp): Promise<string> {
  await page.getByTestId('trace-status').filter({ hasText: wanted }).waitFor();
  return text(page, 'trace-status');
}

/** The box around the pixels within `tolerance` per channel of the colour `hex`, or undefined when there are none. */
function colourBox(png: PNG, hex: string, tolerance: number): { left: number; top: number; right: number; bottom: number; count: number } | undefined {
  const rgb = [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16));
  let box: { left: number; top: number; right: number; bottom: number; count: number } | undefined;
  for (let y = 0; y < png.height; y++) {
    for (let x = 0; x < png.width; x++) {
      const i = (y * png.width + x) * 4;
      if (rgb.some((v, c) => Math.abs(png.data[i + c]! - v) > tolerance)) continue;
      box ??= { left: x, top: y, right: x, bottom: y, count: 0 };
      box.left = Math.min(box.left, x);
      box.right = Math.max(box.right, x);
      box.top = Math.min(box.top, y);
      box.bottom = Math.max(box.bottom, y);
      box.count++;
    }
  }
  return box;
}

/** Pairs of the view's tick and axis labels whose boxes overlap, by their text. */
async function overlappingLabels(page: Page): Promise<string[]> {
  return page.evaluate(() => {
    const labels = [...document.querySelectorAll<HTMLElement>('#viewport .scene-label.tick, #viewport .scene-label.axis-name')].filter((e) => e.offsetParent !== null);
    const boxes = labels.map((e) => ({ text: e.textContent ?? '', box: e.getBoundingClientRect() }));
    const overlaps: string[] = [];
    boxes.forEach((a, i) => {
      for (const b of boxes.slice(i + 1)) {
        // A pixel of slack: glyph boxes touch where the text does not.
        if (a.box.left + 1 < b.box.right && b.box.left + 1 < a.box.right && a.box.top + 1 < b.box.bottom && b.box.top + 1 < a.box.bottom) overlaps.push(`${a.text} / ${b.text}`);
      }
    });
    return overlaps;
  });
}

/** The view's tick and axis labels that reach past its edges, with how far, by their text. */
async function labelsPastTheView(page: Page): Promise<string[]> {
  return page.evaluate(() => {
    const view = document.querySelector('#viewport')!.getBoundingClientRect();
    return [...document.querySelectorAll<HTMLElement>('#viewport .scene-label.tick, #viewport .scene-label.axis-name')]
      .filter((e) => e.offsetParent !== null)
      .map((e) => ({ text: e.textContent ?? '', box: e.getBoundingClientRect() }))
      .map(({ text, box }) => ({ text, past: Math.max(view.left - box.left, box.right - view.right, view.top - box.top, box.bottom - view.bottom) }))
      .filter(({ past }) => past > 0)
      .map(({ text, past }) => `${text}: ${past.toFixed(1)} px`);
  });
}

/** Whether the view's canvas is drawn at the size of the box it fills (its renderer resized to it). */
function canvasFitsItsBox(page: Page): Promise<boolean> {
  return page.evaluate(() => {
    const canvas = document.querySelector<HTMLCanvasElement>('[data-testid="scene-canvas"]')!;
    const box = canvas.parentElement!;
    return canvas.clientWidth === box.clientWidth && canvas.clientHeight === box.clientHeight;
  });
}

describe('G-code mode', () => {
  it('opens on a visible path: over a grid that reaches past it, framed, its axes in mm with steps beside', async () => {
    // The square sample: 20 mm sides at 80 steps/mm, 1600 steps each.
    const p = await openPage('?mode=gcode');
    const { page } = p;
    await status(page, '6,400 steps at 80 / 80 / 80 steps/mm');
    await page.getByTestId('step-counter').filter({ hasText: 'of 6,400' }).waitFor();
    const ticks = await page.locator('#viewport .scene-label.tick').allInnerTexts();
    expect(ticks).toContain('20 mm1600');
    expect(ticks).toContain('10 mm800');
    expect(await overlappingLabels(page)).toEqual([]);

    // Whole inside the view: '20 mm1600' at the right reached 1 to 2 px past
    // its edge, at 1280 px and on a phone alike, its last digit cut.
    for (const size of [{ width: 390, height: 844 }, { width: 1280, height: 720 }]) {
      await page.setViewportSize(size);
      // The view resized to its box first: until its ResizeObserver has run, the labels of the
      // narrower frame lie inside the wider one, and the PNG below was drawn at the old size (the
      // square 392 pixels of ideal line where it has over 500, once in CI).
      await expect.poll(() => canvasFitsItsBox(page), { message: `${size.width} px` }).toBe(true);
      await expect.poll(() => labelsPastTheView(page), { message: `${size.width} px` }).toEqual([]);
    }
    await page.setViewportSize({ width: 1280, height: 720 });

    const png = await canvasPng(page);
    // The ideal path is the square; the grid must show around it on every side, not end on it.
    const path = colourBox(png, PALETTE.ideal, 16)!;
    const grid = colourBox(png, PALETTE.grid, 3)!;
    expect(path.count).toBeGreaterThan(500);
    for (const [side, beyond] of [
      ['left', path.left - grid.left],
      ['top', path.top - grid.top],
      ['right', grid.right - path.right],
      ['bottom', grid.bottom - path.bottom],
    ] as const) {
      expect(beyond, `grid past the path on the ${side}`).toBeGreaterThan(4);
    }
    // Framed: the square spans most of the view's width.
    expect((path.right - path.left) / png.width).toBeGreaterThan(0.55);
    await screenshot(page, 'gcode-opens');
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});

describe('the view of a long path', () => {
  it('keeps its axis names clear of the last ticks', async () => {
    const p = await openPage('?from=0,0,0&to=300,170,90');
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: 'of 300' }).waitFor();
    await expect.poll(() => page.locator('#viewport .scene-label.tick').count()).toBeGreaterThan(10);
    expect(await overlappingLabels(page)).toEqual([]);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('labels an axis far shorter than the longest no closer than its labels fit', async () => {
    // z runs to 8 beside x's 300: labelled every 2 as its own length asks,
    // its four labels stood within some 10 px, one blot over the x axis's 0.
    const p = await openPage('?from=0,0,0&to=300,40,8');
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: 'of 300' }).waitFor();
    const ticks = page.locator('#viewport .scene-label.tick').filter({ visible: true });
    await expect.poll(() => ticks.allInnerTexts()).toContain('300');
    expect(await overlappingLabels(page)).toEqual([]);
    // The end of each short axis is still read.
    expect(await ticks.allInnerTexts()).toEqual(expect.arrayContaining(['40', '8']));
    // A program 5 mm wide and 120 mm long: its x axis in mm is as short.
    const lines = Array.from({ length: 24 }, (_, i) => `X${(i % 2) * 5} Y${(i + 1) * 5}`);
    const gcode = encodeURIComponent(`G21 G90\nG1 F600\n${lines.join('\n')}\n`);
    await page.goto(`${p.url.replace(/\?.*$/, '')}?mode=gcode&gcode=${gcode}&stepsPerMm=80`);
    await page.getByTestId('step-counter').filter({ hasText: /of [\d,]+$/ }).waitFor();
    await expect.poll(() => ticks.allInnerTexts()).toContain('100 mm8000');
    expect(await overlappingLabels(page)).toEqual([]);
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});

describe('steps per mm per axis', () => {
  it('are typed and linked as the CLI takes them, 80,80,400', async () => {
    // (1, 1, 1) mm at 80, 80 and 400 steps/mm is (80, 80, 400) steps: 400 steps.
    const gcode = encodeURIComponent('G21 G90\nG1 X1 Y1 Z1 F600\n');
    const p = await openPage(`?mode=gcode&gcode=${gcode}&stepsPerMm=80,80,400`);
    const { page } = p;
    await status(page, '1 move, 400 steps at 80 / 80 / 400 steps/mm');
    const field = page.getByTestId('input-machine-stepsPerMm');
    expect(await field.inputValue()).toBe('80,80,400');
    // The field's hint gives the syntax the field takes, the CLI's.
    expect(await page.locator('#machine-stepsPerMm-hint').innerText()).toContain('80,80,400');

    await field.fill('80,80,200');
    await status(page, '1 move, 200 steps at 80 / 80 / 200 steps/mm');
    await expect.poll(() => new URL(page.url()).searchParams.get('stepsPerMm')).toBe('80,80,200');
    expect(await text(page, 'form-error')).toBe('');

    // Text that is not numbers is named at the field and never sent.
    await field.fill('80;80');
    expect(await text(page, 'error-machine-stepsPerMm')).toBe('give one number, or x,y,z');
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});

describe('messages about a cap', () => {
  it('say what to do on the page, not raise a maxSteps it has no control for', async () => {
    // A line to x = 2^30 takes 2^30 steps (regions: one per unit of the
    // longest axis): more than the page's 1,500,000 and than any maxSteps (10^9).
    const p = await openPage('?from=0,0,0&to=1073741824,0,0');
    const { page } = p;
    // Beside the end point, where the move is shortened; nothing under the form.
    const formError = page.getByTestId('error-to');
    await formError.filter({ hasText: 'steps' }).waitFor();
    expect(await text(page, 'form-error')).toBe('');
    const far = await formError.innerText();
    expect(far).toMatch(/^This path needs at least 1,073,741,824 steps; the page draws at most 1,500,000 \(its maxSteps, fixed\)\. Shorten the move/);
    expect(far).toContain('No trace may have that many steps (1,000,000,000 at most, anywhere).');
    expect(far).not.toMatch(/raise/i);

    // 2,000,000 steps: the command line could, and the message says how.
    await page.getByTestId('input-to-x').fill('2000000');
    await formError.filter({ hasText: '2,000,000' }).waitFor();
    expect(await formError.innerText()).toContain('The command line goes up to 1,000,000,000 steps: voxpath trace --max-steps 2000000.');
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it("word a program's cap at its line, where the program is edited", async () => {
    // 700,000 mm at 80 steps/mm is 56,000,000 steps, past the 50,000,000 the page runs.
    const gcode = encodeURIComponent('G21 G90\nG1 X700000 F600\n');
    const p = await openPage(`?mode=gcode&gcode=${gcode}&stepsPerMm=80`);
    const { page } = p;
    const diagnostics = page.getByTestId('gcode-diagnostics');
    await diagnostics.filter({ hasText: 'line 2' }).waitFor();
    const message = await diagnostics.innerText();
    expect(message).toContain('By line 2 the program needs at least 56,000,000 steps; the page runs at most 50,000,000 (its maxSteps, fixed). Lower stepsPerMm under Machine, or shorten the moves.');
    expect(message).toContain('voxpath gcode --max-steps 56000000');
    expect(message).not.toMatch(/raise/i);
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});

/** Hue (degrees), saturation and value (0..1) of an RGB colour. */
function hsv(r: number, g: number, b: number): [number, number, number] {
  const max = Math.max(r, g, b);
  const min = Math.min(r, g, b);
  const d = max - min;
  const h = d === 0 ? 0 : max === r ? ((g - b) / d + 6) % 6 : max === g ? (b - r) / d + 2 : (r - g) / d + 4;
  return [h * 60, max === 0 ? 0 : d / max, max / 255];
}

/**
 * Pixels of `png` drawn in `rgb` as the view shades it: a cell's faces are
 * the colour times a light factor (0.62 to 1), which keeps its hue and
 * saturation and lowers its value; an outline is the colour itself.
 */
function pixelsShadedAs(png: PNG, rgb: readonly number[]): number {
  let count = 0;
  for (let i = 0; i < png.data.length; i += 4) if (shadedAs(png.data[i]!, png.data[i + 1]!, png.data[i + 2]!, rgb)) count++;
  return count;
}

/** True when the pixel (r, g, b) is the colour `rgb` as the view shades it (see pixelsShadedAs). */
function shadedAs(r: number, g: number, b: number, rgb: readonly number[]): boolean {
  const [h0, s0, v0] = hsv(rgb[0]!, rgb[1]!, rgb[2]!);
  const [h, s, v] = hsv(r, g, b);
  const dh = Math.min(Math.abs(h - h0), 360 - Math.abs(h - h0));
  return dh < 10 && Math.abs(s - s0) < 0.25 && v <= v0 + 0.06 && v >= 0.45 * v0;
}

/** The colour of a legend swatch as drawn: its middle pixel, or its border's (a highlight's swatch is outlined in its colour). */
async function swatchColour(page: Page, selector: string, where: 'middle' | 'border'): Promise<number[]> {
  const png = PNG.sync.read(await page.locator(`${selector}:visible`).screenshot());
  const x = where === 'middle' ? png.width >> 1 : 0;
  const i = ((png.height >> 1) * png.width + x) * 4;
  return [png.data[i]!, png.data[i + 1]!, png.data[i + 2]!];
}

describe('compare mode', () => {
  it("draws each path and each path's own cells in its legend colour, overlaid and side by side", async () => {
    // regions and greedy on (0,0,0)->(10,7,6) share only a few cells: 8 are
    // regions' alone and 21 greedy's (greedy's 23 steps wander from the line).
    const p = await openPage('?mode=compare&algorithm=regions&other=greedy&layout=overlay&from=0,0,0&to=10,7,6&step=23');
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: 'Step 23 of 23' }).waitFor();
    await page.getByTestId('first-difference').waitFor();
    const legend = {
      first: await swatchColour(page, '.swatch-visited', 'middle'),
      second: await swatchColour(page, '.swatch-second', 'middle'),
      onlyFirst: await swatchColour(page, '.swatch-only-first', 'border'),
      onlySecond: await swatchColour(page, '.swatch-only-second', 'border'),
    };
    const overlay = await canvasPng(page);
    for (const [name, colour] of Object.entries(legend)) {
      expect(pixelsShadedAs(overlay, colour), `overlaid: ${name} ${colour.join(',')}`).toBeGreaterThan(150);
    }

    await page.getByTestId('layout-side').check();
    await expect.poll(() => page.locator('#viewport-b canvas').isVisible()).toBe(true);
    await page.waitForTimeout(500);
    const left = await canvasPng(page);
    const right = PNG.sync.read(await page.locator('#viewport-b canvas').screenshot());
    expect(pixelsShadedAs(left, legend.first), 'left: first').toBeGreaterThan(150);
    expect(pixelsShadedAs(left, legend.onlyFirst), 'left: only first').toBeGreaterThan(150);
    expect(pixelsShadedAs(right, legend.second), 'right: second').toBeGreaterThan(150);
    expect(pixelsShadedAs(right, legend.onlySecond), 'right: only second').toBeGreaterThan(150);
    // The right view is the second path's: none of the first's colour.
    expect(pixelsShadedAs(right, legend.first), 'right: first').toBeLessThan(20);
    await screenshot(page, 'compare-side-colours');
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('overlaid, steps the longer second path on past the end of the first', async () => {
    // regions takes 10 steps, greedy 23: overlaid, greedy stood at its point 10 from step 10 on.
    const p = await openPage('?mode=compare&algorithm=regions&other=greedy&layout=overlay&from=0,0,0&to=10,7,6&step=10');
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: 'Step 10 of 23' }).waitFor();
    await page.waitForTimeout(300);
    const second = await swatchColour(page, '.swatch-second', 'middle');
    const atTen = pixelsShadedAs(await canvasPng(page), second);
    await page.getByTestId('last').click();
    await page.getByTestId('step-counter').filter({ hasText: 'Step 23 of 23' }).waitFor();
    await page.waitForTimeout(300);
    const atEnd = pixelsShadedAs(await canvasPng(page), second);
    // Thirteen more of greedy's cells visited, in its colour.
    expect(atEnd).toBeGreaterThan(atTen * 1.3);
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});

describe("a G-code program's errors", () => {
  it('are marked in the gutter, on their line and above the editor, which goes to the line', async () => {
    // Line 2 moves with no feed rate yet (a warning: Grbl's error 22); line 3's X1.2.3 is no number.
    const gcode = encodeURIComponent('G21 G90\nG1 X1 Y1\nG1 X1.2.3 F500\nG1 X5\n');
    const p = await openPage(`?mode=gcode&gcode=${gcode}&stepsPerMm=10`);
    const { page } = p;
    await status(page, 'stopped at line 3');
    const problems = page.getByTestId('gcode-problems');
    await problems.waitFor();
    expect(await text(page, 'gcode-error')).toMatch(/^Line 3:\d+: malformed number/);
    expect(await problems.innerText()).toMatch(/1 warning, listed under Moves; the first: line 2:\d+: /);
    expect(await page.getByTestId('gutter-error').allInnerTexts()).toEqual(['3']);
    expect(await page.getByTestId('gutter-warning').allInnerTexts()).toEqual(['2']);
    expect(await page.getByTestId('gcode-error-line').getAttribute('data-line')).toBe('3');
    expect(await page.getByTestId('gcode-text').getAttribute('aria-invalid')).toBe('true');
    await screenshot(page, 'gcode-error-marked', '.inputs');

    // The error's link puts the cursor on its line.
    await page.getByTestId('gcode-error').getByRole('button').click();
    await expect.poll(() => page.getByTestId('gcode-picked-line').getAttribute('data-line')).toBe('3');
    expect(await page.getByTestId('gcode-text').evaluate((e: HTMLTextAreaElement) => e.value.slice(0, e.selectionStart).split('\n').length)).toBe(3);

    // Fixed, the marks go.
    await page.getByTestId('gcode-text').fill('G21 G90\nG1 X1 Y1 F500\nG1 X1.2 F500\nG1 X5\n');
    await status(page, '3 moves');
    expect(await problems.isHidden()).toBe(true);
    expect(await page.getByTestId('gutter-error').count()).toBe(0);
    expect(await page.getByTestId('gcode-text').getAttribute('aria-invalid')).toBe('false');
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});

describe('results of a rejected input', () => {
  it('are marked out of date until a valid input is traced, in trace and experiment mode, the rejected handle kept in sight', async () => {
    const p = await openPage('?from=0,0,0&to=10,7,6');
    const { page } = p;
    const note = page.getByTestId('stale-note');
    const opacity = (selector: string) => page.locator(selector).first().evaluate((e) => getComputedStyle(e).opacity);
    await page.getByTestId('step-counter').filter({ hasText: 'of 10' }).waitFor();
    expect(await note.isVisible()).toBe(false);
    expect(await opacity('#viewport')).toBe('1');

    // Past the steps the page draws: rejected by the core, the last path stays, marked.
    await page.getByTestId('input-to-x').fill('1000000000');
    await note.filter({ hasText: 'Out of date' }).waitFor();
    expect(await opacity('#viewport')).toBe('0.5');
    expect(await opacity('.inspector > *')).toBe('0.5');
    // The rejected point's handle stays in the view, at its edge, to be dragged back.
    const handle = page.getByTestId('handle-to');
    await expect.poll(() => handle.getAttribute('class')).toContain('pinned');
    const view = (await page.locator('#viewport').boundingBox())!;
    const box = (await handle.boundingBox())!;
    expect(box.x >= view.x && box.x + box.width <= view.x + view.width && box.y >= view.y && box.y + box.height <= view.y + view.height).toBe(true);
    await page.getByTestId('input-to-x').fill('12');
    await page.getByTestId('step-counter').filter({ hasText: 'of 12' }).waitFor();
    await expect.poll(() => note.isVisible()).toBe(false);
    expect(await opacity('#viewport')).toBe('1');

    // Refused by the page before the core sees it (an empty coordinate): marked the same way, and unmarked once it is typed again.
    await page.getByTestId('input-to-x').fill('');
    await page.getByTestId('error-to').filter({ hasText: 'x needs a number' }).waitFor();
    await note.filter({ hasText: 'Out of date' }).waitFor();
    expect(await opacity('#viewport')).toBe('0.5');
    await page.getByTestId('input-to-x').fill('12');
    await expect.poll(() => note.isVisible()).toBe(false);
    expect(await opacity('#viewport')).toBe('1');
    // Left refused, then an algorithm picked that opens its own example (an
    // arc: the line typed is not its move): its form is built anew and its
    // trace shown, no longer out of date (the old form's refusal stayed).
    // One that keeps the move keeps the text refused with it, out of date.
    await page.getByTestId('input-to-x').fill('');
    await note.filter({ hasText: 'Out of date' }).waitFor();
    await page.getByTestId('algorithm').selectOption('bresenham3d');
    await expect.poll(() => page.getByTestId('input-to-x').inputValue()).toBe('');
    expect(await note.isVisible()).toBe(true);
    await page.getByTestId('algorithm').selectOption('circle');
    await page.getByTestId('trace-status').filter({ hasText: 'circle' }).waitFor();
    await expect.poll(() => note.isVisible()).toBe(false);
    expect(await opacity('#viewport')).toBe('1');

    // The experiment's table, after a count it cannot take.
    await page.getByTestId('mode-experiment').click();
    await page.getByTestId('lines-table').waitFor();
    await page.getByTestId('input-experiment-count').fill('0');
    await note.filter({ hasText: 'Out of date' }).waitFor();
    expect(await opacity('#experiment-view > *')).toBe('0.5');
    await page.getByTestId('input-experiment-count').fill('20');
    await page.getByTestId('experiment-view').filter({ hasText: '20 random lines' }).waitFor();
    await expect.poll(() => note.isVisible()).toBe(false);
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});

describe('the experiment', () => {
  it('opens a line in Trace mode from its row, and says when two algorithms gave the same statistics', async () => {
    const p = await openPage('?mode=experiment&algorithm=regions&count=20&seed=1&maxCoordinate=100');
    const { page } = p;
    const view = page.getByTestId('experiment-view');
    await view.filter({ hasText: '20 random lines traced with regions' }).waitFor();
    expect(await page.getByTestId('same-statistics').count()).toBe(0);

    // bresenham3d steps as regions does except at ties: the same numbers.
    await page.getByTestId('algorithm').selectOption('bresenham3d');
    await view.filter({ hasText: 'traced with bresenham3d' }).waitFor();
    const regionsRows = await page.getByTestId('lines-table').locator('tbody tr').allInnerTexts();
    expect(await text(page, 'same-statistics')).toMatch(/^Every statistic here is the one regions gave on these 20 lines, line for line/);
    // greedy strays from the line: no such note.
    await page.getByTestId('algorithm').selectOption('greedy');
    await view.filter({ hasText: 'traced with greedy' }).waitFor();
    expect(await page.getByTestId('same-statistics').count()).toBe(0);
    await page.getByTestId('algorithm').selectOption('bresenham3d');
    await view.filter({ hasText: 'traced with bresenham3d' }).waitFor();

    // Row 3: its point and step count, in Trace mode.
    const [, to, steps] = regionsRows[2]!.split('\t');
    const [x, y, z] = to!.replace(/[()]/g, '').split(', ');
    await page.getByTestId('lines-table').locator('tbody tr').nth(2).locator('td').nth(3).click();
    await page.getByTestId('step-counter').filter({ hasText: new RegExp(`^Step 0 of ${Number(steps!.replaceAll(',', '')).toLocaleString('en-US')}$`) }).waitFor();
    expect(await page.getByTestId('mode-trace').getAttribute('aria-pressed')).toBe('true');
    expect(await page.getByTestId('algorithm').inputValue()).toBe('bresenham3d');
    expect([await page.getByTestId('input-to-x').inputValue(), await page.getByTestId('input-to-y').inputValue(), await page.getByTestId('input-to-z').inputValue()]).toEqual([x, y, z]);
    expect(await page.getByTestId('input-from-x').inputValue()).toBe('0');
    // Back returns to the table it was opened from (it left the site), and Forward to the line.
    await page.waitForURL(/mode=trace/);
    await page.goBack();
    await expect.poll(() => page.getByTestId('mode-experiment').getAttribute('aria-pressed')).toBe('true');
    await view.filter({ hasText: 'traced with bresenham3d' }).waitFor();
    await page.goForward();
    await page.getByTestId('step-counter').filter({ hasText: new RegExp(`^Step 0 of ${Number(steps!.replaceAll(',', '')).toLocaleString('en-US')}$`) }).waitFor();
    expect(await page.getByTestId('mode-trace').getAttribute('aria-pressed')).toBe('true');

    // And from the keyboard: the row's button.
    await page.getByTestId('mode-experiment').click();
    await page.getByTestId('open-line-5').focus();
    await page.keyboard.press('Enter');
    await expect.poll(() => page.getByTestId('mode-trace').getAttribute('aria-pressed')).toBe('true');
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});

describe("the experiment's form", () => {
  it('says of every field out of its declared range that it is, at once, as it is typed', async () => {
    const p = await openPage('?mode=experiment&algorithm=regions&count=20&seed=1');
    const { page } = p;
    await page.getByTestId('experiment-view').filter({ hasText: '20 random lines traced with regions' }).waitFor();
    await page.getByTestId('input-experiment-count').fill('0');
    await page.getByTestId('input-experiment-maxCoordinate').fill('10001');
    await page.getByTestId('input-experiment-seed').fill('-1');
    // The core's words for each, from the catalogue (its mustBe for the ranges experiment.rs declares).
    expect(await text(page, 'error-experiment-count')).toBe('must be 1 to 100000, got 0');
    expect(await text(page, 'error-experiment-maxCoordinate')).toBe('must be 1 to 10000, got 10001');
    expect(await text(page, 'error-experiment-seed')).toBe('must be 0 to 8999999999999999, got -1');
    expect(await page.getByTestId('input-experiment-count').getAttribute('aria-invalid')).toBe('true');
    // Nothing refused reaches the core: the tables shown are marked out of date.
    await expect.poll(() => text(page, 'stale-note')).toMatch(/^Out of date: the inputs were not traced/);
    // Put right, one at a time: the others still say so; all right, it traces.
    await page.getByTestId('input-experiment-count').fill('30');
    expect(await text(page, 'error-experiment-count')).toBe('');
    expect(await text(page, 'error-experiment-seed')).toBe('must be 0 to 8999999999999999, got -1');
    await page.getByTestId('input-experiment-maxCoordinate').fill('50');
    await page.getByTestId('input-experiment-seed').fill('2');
    await page.getByTestId('experiment-view').filter({ hasText: '30 random lines traced with regions' }).waitFor();
    expect(await text(page, 'stale-note')).toBe('');
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});

/** Pixels of the colour `hex` as the view shades it (pixelsShadedAs), and their mean position as a share of the image's width and height. */
function colourSpot(png: PNG, hex: string): { count: number; x: number; y: number } {
  const rgb = [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16));
  let [count, sx, sy] = [0, 0, 0];
  for (let y = 0; y < png.height; y++) {
    for (let x = 0; x < png.width; x++) {
      const i = (y * png.width + x) * 4;
      if (!shadedAs(png.data[i]!, png.data[i + 1]!, png.data[i + 2]!, rgb)) continue;
      count++;
      sx += x;
      sy += y;
    }
  }
  return { count, x: sx / count / png.width, y: sy / count / png.height };
}

/**
 * The current cell as a view that follows it shows it: some 40 pixels
 * across (600 pixels, and 5 times its size `framedCount` in the whole
 * path's framing), in the middle of the view.
 */
async function expectCurrentCellClose(page: Page, framedCount: number): Promise<void> {
  const spot = colourSpot(await canvasPng(page), PALETTE.current);
  expect(spot.count).toBeGreaterThan(Math.max(600, 5 * framedCount));
  expect(Math.abs(spot.x - 0.5)).toBeLessThan(0.1);
  expect(Math.abs(spot.y - 0.5)).toBeLessThan(0.1);
}

describe('following the current cell', () => {
  it('keeps it in the middle of the view at a readable size as it steps, toggled with F', async () => {
    // 300 steps: framed whole, a cell is a few pixels and the exit face a speck.
    const p = await openPage('?from=0,0,0&to=300,170,90&step=150&decision3d=1');
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: 'Step 150 of 300' }).waitFor();
    await page.getByTestId('inspector-deviation').filter({ hasText: 'grid units' }).waitFor();
    const framedPng = await canvasPng(page);
    const framed = colourSpot(framedPng, PALETTE.current);
    expect(framed.count).toBeLessThan(200);

    await page.keyboard.press('f');
    await expect.poll(() => page.getByTestId('scene-canvas').first().getAttribute('data-follow')).toBe('true');
    expect(await page.getByTestId('follow').isChecked()).toBe(true);
    await expect.poll(() => new URL(page.url()).searchParams.get('follow')).toBe('1');
    // Framed, a marker of a few pixels; followed, the cell itself, some 40 pixels across.
    await expectCurrentCellClose(page, framed.count);
    // The exit face's crossing dot grows with it.
    expect(colourSpot(await canvasPng(page), PALETTE.crossing).count).toBeGreaterThan(3 * Math.max(1, colourSpot(framedPng, PALETTE.crossing).count));

    // Twenty steps on, still there.
    for (let i = 0; i < 20; i++) await page.keyboard.press('ArrowRight');
    await page.getByTestId('step-counter').filter({ hasText: 'Step 170 of 300' }).waitFor();
    await page.waitForTimeout(300);
    await expectCurrentCellClose(page, framed.count);

    await page.keyboard.press('f');
    await expect.poll(() => page.getByTestId('scene-canvas').first().getAttribute('data-follow')).toBe('false');
    await screenshot(page, 'follow-off');
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});

describe("a check's first difference", () => {
  it('is brought close by "Go to point" (outlined too small to see in the whole path\'s framing)', async () => {
    // The rule's 300-step path with point 150 moved one cell: the first difference.
    const t = await trace({ algorithm: 'regions', from: [0, 0, 0], to: [300, 170, 90] });
    const flat = t.points;
    t.free();
    const rows = Array.from({ length: flat.length / 3 }, (_, k) => [flat[3 * k]!, flat[3 * k + 1]!, flat[3 * k + 2]!]);
    rows[150]![2]! += rows[150]![2]! === rows[149]![2]! ? 1 : -1;
    const p = await openPage('?from=0,0,0&to=300,170,90');
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: 'of 300' }).waitFor();
    await page.getByTestId('check-points').locator('summary').click();
    await page.getByTestId('learner-points').fill(rows.map((r) => r.join(',')).join('\n'));
    await page.getByTestId('go-check-difference').filter({ hasText: 'Go to point 150' }).waitFor();
    await page.waitForTimeout(300);
    const framed = colourSpot(await canvasPng(page), PALETTE.current);
    await page.getByTestId('go-check-difference').click();
    await page.getByTestId('step-counter').filter({ hasText: 'Step 150 of 300' }).waitFor();
    await page.waitForTimeout(300);
    // As Follow comes close: the current cell some 40 pixels across, in the middle.
    await expectCurrentCellClose(page, framed.count);
    // Once: Follow stays off, and the camera stays where it is as the path steps on.
    expect(await page.getByTestId('follow').isChecked()).toBe(false);
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});

describe("a G-code step's decision", () => {
  it("shows the columns of the step's own algorithm: regions' on a line, the circle's on an arc", async () => {
    // At 4 steps/mm, G1 to (4, 2) is steps 1-4 (regions), the G2 steps 5-10 (Saleem's circle).
    const gcode = encodeURIComponent('G21 G90\nG1 X1 Y0.5\nG2 X1 Y-0.5 I0 J-0.5\n');
    const p = await openPage(`?mode=gcode&gcode=${gcode}&stepsPerMm=4&step=2`);
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: 'of 10' }).waitFor();
    await page.getByTestId('inspector-deviation').filter({ hasText: 'grid units' }).waitFor();
    const shown = () => page.locator('[data-testid="inspector-decisions"] > div:visible dt').allInnerTexts();
    // The columns each algorithm declares in the core's catalogue.
    const { algorithms } = await catalogue();
    const columnsOf = (id: string) => algorithms.find((a) => a.id === id)!.columns.map((c) => c.name);
    await expect.poll(shown).toEqual(columnsOf('regions'));
    await jumpTo(page, 6);
    await expect.poll(shown).toEqual(columnsOf('circle'));
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});

describe('switching modes', () => {
  it('comes back to a mode at the step it was left at, unless its inputs changed meanwhile', async () => {
    const p = await openPage('?from=0,0,0&to=10,7,6&step=5');
    const { page } = p;
    const counter = page.getByTestId('step-counter');
    await counter.filter({ hasText: 'Step 5 of 10' }).waitFor();
    await page.getByTestId('mode-gcode').click();
    await counter.filter({ hasText: /^Step 0 of [1-9]/ }).waitFor();
    await page.getByTestId('scrubber').focus();
    await page.keyboard.press('End');
    await page.getByTestId('mode-trace').click();
    await status(page, 'to (10, 7, 6)');
    await counter.filter({ hasText: 'Step 5 of 10' }).waitFor();
    // G-code again: its program has not changed, so it comes back at its last step.
    await page.getByTestId('mode-gcode').click();
    await counter.filter({ hasText: /^Step ([\d,]+) of \1$/ }).waitFor();
    // Compare changes the algorithm: Trace's move is traced by another rule, from step 0.
    await page.getByTestId('mode-compare').click();
    await counter.filter({ hasText: /^Step 0 of / }).waitFor();
    await page.getByTestId('algorithm').selectOption('bresenham3d');
    await status(page, 'bresenham3d');
    await page.getByTestId('mode-trace').click();
    await status(page, 'to (10, 7, 6)');
    await counter.filter({ hasText: 'Step 0 of 10' }).waitFor();
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});
