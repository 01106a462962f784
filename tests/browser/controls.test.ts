// Controls of the view and the form found wrong by hand, in headless
// Chromium: the endpoint handles' letters, the + and - keys on the view, and
// the gcd option (Wang section 4), which must reach the core and the link.
//
// Expected values: on (0,0,0)->(10,8,6) regions' first discriminant is
// M_1 = 2·8 - 10 = 6 (Wang eq. 10); with gcd the deltas are divided by
// gcd(10, 8, 6) = 2, so M_1 = 2·4 - 5 = 3.
import type { Page } from 'playwright-core';
import { afterAll, describe, expect, it } from 'vitest';
import { PALETTE } from '../../web/scene/palette.js';
import { closeAll, onceShown, openPage, pixelsOf, screenshot } from './harness.js';

afterAll(closeAll);

/** The camera of the link once it has been written: distance from its target, and zoom. */
async function linkedCamera(page: Page, previous?: string): Promise<{ text: string; distance: number; zoom: number }> {
  const camera = () => new URL(page.url()).searchParams.get('camera');
  // A new camera: written (the link is written a little after a change) and not the previous one.
  await expect.poll(() => camera() !== null && camera() !== previous).toBe(true);
  const text = camera()!;
  const [px, py, pz, tx, ty, tz, zoom] = text.split(',').map(Number) as [number, number, number, number, number, number, number];
  return { text, distance: Math.hypot(px - tx, py - ty, pz - tz), zoom };
}

describe('view and form controls', () => {
  it('labels the handles S and E, and zooms in with + and out with - in 3D and 2D', async () => {
    const p = await openPage('?from=0,0,0&to=10,7,6');
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: /of 10$/ }).waitFor();
    expect(await page.getByTestId('handle-from').innerText()).toBe('S');
    expect(await page.getByTestId('handle-to').innerText()).toBe('E');

    await page.getByTestId('scene-canvas').focus();
    await page.keyboard.press('+');
    const closer = await linkedCamera(page);
    await page.keyboard.press('-');
    const back = await linkedCamera(page, closer.text);
    expect(back.distance).toBeGreaterThan(closer.distance);

    // 2D: the orthographic view zooms instead of moving.
    await page.getByTestId('algorithm').selectOption('greedy');
    await page.getByTestId('scene-canvas').filter({ has: page.locator('xpath=self::*[@data-projection="2d"]') }).waitFor();
    await page.getByTestId('scene-canvas').focus();
    await page.keyboard.press('+');
    const zoomed = await linkedCamera(page, back.text);
    expect(zoomed.zoom).toBeGreaterThan(1);
    await page.keyboard.press('-');
    expect((await linkedCamera(page, zoomed.text)).zoom).toBeLessThan(zoomed.zoom);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it("keeps the view's tools and legend over its handles and labels, so Reset view stays clickable after panning", async () => {
    // Panned down, the E handle was held at the view's top right, over Reset
    // view: a click there went to the handle, and the camera stayed (three.js
    // gives each label and handle a z-index of its own, up to one per label,
    // over the tools' 1). Found by a helper's hunt through the page.
    const p = await openPage('?from=0,0,0&to=10,7,6');
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: /of 10$/ }).waitFor();
    // The E handle and the z axis's name put over the middle of each tool
    // and of the legend, as a pan can leave them: the tool is what is there.
    const covered = await page.evaluate(() => {
      const hits: string[] = [];
      const view = document.getElementById('viewport')!.getBoundingClientRect();
      const movers = [document.querySelector<HTMLElement>('[data-testid=handle-to]')!, [...document.querySelectorAll<HTMLElement>('.scene-label.axis-name')].at(-1)!];
      for (const id of ['reset-view', 'follow', 'view-2d', 'legend']) {
        const target = document.getElementById(id)!;
        const box = target.getBoundingClientRect();
        const [x, y] = [box.left + box.width / 2, box.top + box.height / 2];
        for (const mover of movers) {
          mover.style.transform = `translate(-50%, -50%) translate(${x - view.left}px, ${y - view.top}px)`;
          const hit = document.elementFromPoint(x, y);
          if (!hit || !(hit === target || target.contains(hit) || hit.closest('label')?.contains(target))) hits.push(`${id} under ${mover.textContent}`);
        }
      }
      return hits;
    });
    expect(covered).toEqual([]);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('frames a path of no steps as a cell among others, with nothing to play', async () => {
    // One cell filled the view, its axis names off screen, and Play was
    // enabled at "Step 0 of 0". Found by a helper's hunt through the page.
    const p = await openPage('?from=3,3,3&to=3,3,3');
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: 'Step 0 of 0' }).waitFor();
    const play = page.getByTestId('play');
    await expect.poll(() => play.getAttribute('aria-disabled')).toBe('true');
    // Neither it nor Space starts playback.
    // Forced: aria-disabled is disabled to Playwright, which would wait.
    await play.click({ force: true });
    await page.keyboard.press('Space');
    await page.waitForTimeout(300);
    expect(await play.getAttribute('data-playing')).toBe('false');
    // The cell's lit top face, in the current cell's colour: a cell among a
    // few a side is a sliver of the view (it was 8% of it).
    const shot = await screenshot(page, 'no-steps', '#viewport');
    const view = (await page.locator('#viewport').boundingBox())!;
    const share = pixelsOf(shot.file, PALETTE.current, 24) / (view.width * view.height);
    expect(share).toBeGreaterThan(0);
    expect(share).toBeLessThan(0.02);
    // Every axis name in the view.
    for (const name of await page.locator('#viewport .scene-label.axis-name').all()) {
      const box = (await name.boundingBox())!;
      expect(box.x).toBeGreaterThanOrEqual(view.x);
      expect(box.x + box.width).toBeLessThanOrEqual(view.x + view.width);
      expect(box.y + box.height).toBeLessThanOrEqual(view.y + view.height);
    }
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('keeps a chart where it is on screen when a click on it shows the step, and its decision figure above it', async () => {
    // At step 0 the inspector has no figure: a click on a chart drew one
    // above the charts, which pushed the chart clicked 314 px down, out of
    // sight. Found by a helper's hunt through the page.
    const p = await openPage('?from=0,0,0&to=100,70,60');
    const { page } = p;
    await page.setViewportSize({ width: 1280, height: 800 });
    await page.getByTestId('step-counter').filter({ hasText: 'Step 0 of 100' }).waitFor();
    const chart = page.locator('#charts .u-wrap').first();
    await chart.waitFor();
    const before = (await chart.boundingBox())!;
    await page.mouse.click(before.x + 0.6 * before.width, before.y + 0.5 * before.height);
    await page.getByTestId('step-counter').filter({ hasText: /^Step [1-9]\d* of 100$/ }).waitFor();
    await page.getByTestId('decision-figure').locator('svg').waitFor();
    await page.waitForTimeout(300);
    const after = (await chart.boundingBox())!;
    expect(Math.abs(after.y - before.y)).toBeLessThan(2);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('frames the path again when the window changes shape, unless the user placed the camera', async () => {
    const p = await openPage('?from=0,0,0&to=10,7,6');
    const { page } = p;
    await page.setViewportSize({ width: 1280, height: 800 });
    await page.getByTestId('step-counter').filter({ hasText: /of 10$/ }).waitFor();
    // Both handles well inside the canvas, as a framed path leaves them.
    const inside = async () => {
      const canvas = (await page.getByTestId('scene-canvas').boundingBox())!;
      const handles = await Promise.all(['handle-from', 'handle-to'].map(async (id) => (await page.getByTestId(id).boundingBox())!));
      const margin = 20;
      return handles.every((h) => h.x >= canvas.x + margin && h.x + h.width <= canvas.x + canvas.width - margin && h.y >= canvas.y + margin && h.y + h.height <= canvas.y + canvas.height - margin);
    };
    await expect.poll(inside).toBe(true);
    // Narrower and taller: framed for 1280 x 800, the handles ended 11 px
    // from the canvas's sides, the end cell's cube cut by its edge.
    await page.setViewportSize({ width: 800, height: 900 });
    await expect.poll(inside).toBe(true);
    expect(new URL(page.url()).searchParams.get('camera')).toBeNull();
    // A camera the user placed stays where it is: with its vertical field of
    // view fixed, the picture only scales with the canvas's height (framed
    // again, it would be fitted to the new shape, margins and all).
    await page.getByTestId('scene-canvas').focus();
    await page.keyboard.press('+');
    const placed = await linkedCamera(page);
    const apart = async () => {
      const [from, to] = await Promise.all(['handle-from', 'handle-to'].map(async (id) => (await page.getByTestId(id).boundingBox())!));
      return Math.hypot(to!.x - from!.x, to!.y - from!.y);
    };
    const [before, heightBefore] = [await apart(), (await page.getByTestId('scene-canvas').boundingBox())!.height];
    await page.setViewportSize({ width: 1100, height: 700 });
    await page.waitForTimeout(300);
    const heightAfter = (await page.getByTestId('scene-canvas').boundingBox())!.height;
    expect(heightAfter).toBeLessThan(heightBefore - 50);
    expect((await apart()) / before).toBeCloseTo(heightAfter / heightBefore, 1);
    expect(new URL(page.url()).searchParams.get('camera')).toBe(placed.text);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('traces with the gcd reduction when its box is checked, and keeps it over a new visit', async () => {
    const p = await openPage('?algorithm=regions&from=0,0,0&to=10,8,6&step=1');
    const { page } = p;
    const m = page.getByTestId('inspector-value-M');
    await m.filter({ hasText: /^6$/ }).waitFor();
    const box = page.getByRole('checkbox', { name: 'gcd' });
    expect(await box.isChecked()).toBe(false);
    await box.check();
    await m.filter({ hasText: /^3$/ }).waitFor();
    await page.waitForURL(/gcd=true/);

    // A visit without a link comes back to the last state, box and trace.
    const url = new URL(page.url());
    await page.goto(url.origin + url.pathname);
    await m.filter({ hasText: /^3$/ }).waitFor();
    expect(await box.isChecked()).toBe(true);
    await box.uncheck();
    await m.filter({ hasText: /^6$/ }).waitFor();
    await page.waitForURL(/gcd=false/);
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});

describe('a Cancel in trace mode', () => {
  it("offers to trace the inputs again, as G-code's Run program does (a link's path cancelled while measured left a blank view until an input was changed)", { timeout: 120_000 }, async () => {
    const p = await openPage('?algorithm=helix&from=1000,0,0&to=1000,0,300&center=0,0,0&plane=xy&turns=264');
    const { page } = p;
    // Clicked from inside the page at the bar's first report: a click from the test may come once the measuring has ended.
    expect(await onceShown(page, 'trace-run', { click: 'trace-cancel' }, 'Measuring')).toMatch(/^Measuring: /);
    await page.getByTestId('trace-status').filter({ hasText: /^Cancelled\.$/ }).waitFor({ timeout: 10_000 });
    expect(await page.getByTestId('alert-message').innerText()).toBe('Cancelled: the inputs are not traced.');
    await page.getByRole('button', { name: 'Trace again' }).click();
    await page.getByTestId('step-counter').filter({ hasText: /of 1,498,840$/ }).waitFor({ timeout: 60_000 });
    expect(await page.getByTestId('alert-message').isHidden()).toBe(true);
    // A path kept on screen is said; a value then refused as typed withdraws the offer, which would trace the last valid one.
    await page.getByTestId('input-turns').fill('263');
    await page.getByTestId('step-counter').filter({ hasText: /of 1,493,184$/ }).waitFor({ timeout: 60_000 });
    const cancelled = onceShown(page, 'trace-run', { click: 'trace-cancel' }, 'Measuring');
    await page.getByTestId('input-turns').fill('264');
    await cancelled;
    await page.getByTestId('alert-message').filter({ hasText: 'Cancelled: the view shows the last paths traced, not the inputs.' }).waitFor({ timeout: 10_000 });
    await page.getByTestId('input-turns').fill('1e300');
    await expect.poll(() => page.getByTestId('alert-message').isHidden(), { timeout: 10_000 }).toBe(true);
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});

/** From now on, every text the status line says, in `window.statusSaid`; read with statusSaid. */
async function recordStatus(page: Page): Promise<void> {
  await page.evaluate(() => {
    const status = document.querySelector('[data-testid=trace-status]')!;
    const said: string[] = [];
    (window as unknown as { statusSaid: string[] }).statusSaid = said;
    new MutationObserver(() => said.push(status.textContent ?? '')).observe(status, { childList: true, characterData: true, subtree: true });
  });
}

function statusSaid(page: Page): Promise<string[]> {
  return page.evaluate(() => (window as unknown as { statusSaid: string[] }).statusSaid);
}

/**
 * Back in a mode whose run was cancelled: said so at once, and still so
 * once the page's wait before a run (250 ms) has long passed, with no run
 * started meanwhile ('Tracing…', 'Running: …').
 */
async function staysCancelled(page: Page): Promise<void> {
  await page.getByTestId('trace-status').filter({ hasText: /^Cancelled\.$/ }).waitFor({ timeout: 10_000 });
  // Not a bound on the page's time: only long enough for a run it started by itself to show.
  await page.waitForTimeout(1500);
  expect(await page.getByTestId('trace-status').innerText()).toBe('Cancelled.');
  expect((await statusSaid(page)).filter((text) => /^(Tracing|Running|Measuring)/.test(text))).toEqual([]);
}

describe('a run cancelled, then another mode and back', () => {
  it("stays cancelled in G-code mode until Run program (the mode's switch ran the program again by itself)", { timeout: 180_000 }, async () => {
    const p = await openPage('?mode=gcode&stepsPerMm=10');
    const { page } = p;
    const status = page.getByTestId('trace-status');
    await status.filter({ hasText: 'moves' }).waitFor({ timeout: 30_000 });
    // 5,000 moves of 100 steps (few enough lines to edit in the text box): many of the worker's slices, so that Cancel, clicked from inside the page at the bar's first report, comes before the end.
    const program = ['G21 G90', ...Array.from({ length: 5000 }, (_, i) => (i % 2 === 0 ? 'G1 X10 F6000' : 'G1 X0'))].join('\n');
    const cancelled = onceShown(page, 'gcode-progress', { click: 'gcode-cancel' });
    // Set as a paste sets it: Playwright's fill types a text of 1,000 lines in 6 s.
    await page.getByTestId('gcode-text').evaluate((box: HTMLTextAreaElement, text) => {
      box.value = text;
      box.dispatchEvent(new Event('input', { bubbles: true }));
    }, program);
    await cancelled;
    await status.filter({ hasText: 'Cancelled. The view still shows the last program that ran.' }).waitFor({ timeout: 30_000 });

    await page.getByTestId('mode-trace').click();
    await status.filter({ hasText: 'steps from' }).waitFor({ timeout: 30_000 });
    await recordStatus(page);
    await page.getByTestId('mode-gcode').click();
    await staysCancelled(page);
    // The trace mode's path is not shown as the program's.
    expect(await page.getByTestId('step-counter').innerText()).not.toMatch(/of [1-9]/);
    expect(await page.getByTestId('stale-note').innerText()).toBe('');
    expect(await page.getByTestId('gcode-run').isEnabled()).toBe(true);
    await page.getByTestId('gcode-run').click();
    await status.filter({ hasText: '5,000 moves, 500,000 steps' }).waitFor({ timeout: 120_000 });
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it.each([
    ['trace', '?algorithm=helix&from=1000,0,0&to=1000,0,300&center=0,0,0&plane=xy&turns=264', (page: Page) => page.getByTestId('step-counter').filter({ hasText: /of 1,498,840$/ })],
    ['compare', '?mode=compare&algorithm=regions&other=greedy&from=0,0,0&to=1400000,700,600', (page: Page) => page.getByTestId('trace-status').filter({ hasText: /^regions: .* greedy: / })],
  ] as const)('stays cancelled in %s mode until Trace again', { timeout: 180_000 }, async (mode, link, traced) => {
    const p = await openPage(link);
    const { page } = p;
    const status = page.getByTestId('trace-status');
    await onceShown(page, 'trace-run', { click: 'trace-cancel' }, 'Measuring');
    await status.filter({ hasText: /^Cancelled\.$/ }).waitFor({ timeout: 10_000 });
    await page.getByTestId('mode-gcode').click();
    await status.filter({ hasText: 'moves' }).waitFor({ timeout: 30_000 });
    // Not offered where it would run the program.
    expect(await page.getByTestId('alert-message').isHidden()).toBe(true);
    await recordStatus(page);
    await page.getByTestId(`mode-${mode}`).click();
    await staysCancelled(page);
    expect(await page.getByTestId('alert-message').innerText()).toBe('Cancelled: the inputs are not traced.');
    expect(await page.getByTestId('step-counter').innerText()).not.toMatch(/of [1-9]/);
    await page.getByRole('button', { name: 'Trace again' }).click();
    await traced(page).waitFor({ timeout: 60_000 });
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('stays cancelled in experiment mode until Run experiment', { timeout: 180_000 }, async () => {
    const p = await openPage('?mode=experiment&algorithm=bresenham3d&count=20&maxCoordinate=10000&seed=1');
    const { page } = p;
    const status = page.getByTestId('trace-status');
    await status.filter({ hasText: '20 lines traced with bresenham3d.' }).waitFor({ timeout: 30_000 });
    // 100,000 lines of up to 10,000 steps: about 25 s in the worker.
    const cancelled = onceShown(page, 'experiment-run', { click: 'experiment-cancel' }, 'Tracing');
    await page.getByTestId('input-experiment-count').fill('100000');
    await cancelled;
    await status.filter({ hasText: 'Cancelled. The tables still show the last experiment that ran.' }).waitFor({ timeout: 10_000 });
    await page.getByTestId('mode-trace').click();
    await status.filter({ hasText: 'steps from' }).waitFor({ timeout: 30_000 });
    await recordStatus(page);
    await page.getByTestId('mode-experiment').click();
    await staysCancelled(page);
    // The 20 lines' tables went with their result, which trace mode's path replaced (their CSV is no longer offered).
    expect(await page.getByTestId('lines-table').count()).toBe(0);
    await page.getByTestId('experiment-start').click();
    await status.filter({ hasText: /^Tracing: line [1-9]/ }).waitFor({ timeout: 30_000 });
    await page.getByTestId('experiment-cancel').click();
    await status.filter({ hasText: /^Cancelled\.$/ }).waitFor({ timeout: 10_000 });
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});

/** From now on, each time one of the bars `boxes` (test ids) shows, its id, in `window.barsShown`; read with barsShown. */
async function recordBars(page: Page, boxes: string[]): Promise<void> {
  await page.evaluate((boxes) => {
    const shown: string[] = [];
    (window as unknown as { barsShown: string[] }).barsShown = shown;
    for (const id of boxes) {
      const box = document.querySelector(`[data-testid="${id}"]`) as HTMLElement;
      new MutationObserver(() => {
        if (!box.hidden) shown.push(id);
      }).observe(box, { attributes: true, attributeFilter: ['hidden'] });
    }
  }, boxes);
}

function barsShown(page: Page): Promise<string[]> {
  return page.evaluate(() => (window as unknown as { barsShown: string[] }).barsShown);
}

describe("the charts or the check of a learner's points cancelled, then another mode and back", () => {
  // A helix of 264 turns, near the page's 1,500,000 steps: its charts' rows and a check against it take a while, with a bar and a Cancel.
  const helix = 'algorithm=helix&from=1000,0,0&to=1000,0,300&center=0,0,0&plane=xy';

  it('keeps the charts cancelled until Draw charts (the path traced again at the switch back drew them by itself)', { timeout: 180_000 }, async () => {
    const p = await openPage(`?${helix}&turns=1`);
    const { page } = p;
    const counter = page.getByTestId('step-counter');
    await counter.filter({ hasText: /of [1-9]/ }).waitFor({ timeout: 30_000 });
    // The first path's charts drawn, their bar gone: a CI run under load found it still shown when the path was, and
    // the Cancel below then stopped that path's charts, not the next one's, which the switch back drew.
    await expect.poll(() => page.getByTestId('charts').locator('.uplot').count(), { timeout: 30_000 }).toBe(2);
    await page.getByTestId('charts-run').waitFor({ state: 'hidden', timeout: 30_000 });
    // Clicked from inside the page at the bar's first report: a click from the test may come once the rows are made.
    const cancelled = onceShown(page, 'charts-run', { click: 'charts-cancel' });
    await page.getByTestId('input-turns').fill('264');
    await cancelled;
    await page.getByTestId('charts-cancelled').waitFor({ timeout: 10_000 });

    await page.getByTestId('mode-gcode').click();
    await page.getByTestId('trace-status').filter({ hasText: 'moves' }).waitFor({ timeout: 30_000 });
    // The program's charts are drawn: the Cancel was of the path's.
    await expect.poll(() => page.getByTestId('charts').locator('.uplot').count(), { timeout: 30_000 }).toBe(2);
    await recordBars(page, ['charts-run']);
    await page.getByTestId('mode-trace').click();
    // The path itself was not cancelled: it is traced again, to be shown.
    await counter.filter({ hasText: /of 1,498,840$/ }).waitFor({ timeout: 60_000 });
    // Said with the path or just after it (read at once, a CI run under load found it not yet shown); a Cancel that did
    // not stand would draw the charts instead, which the checks below catch.
    await page.getByTestId('charts-cancelled').waitFor({ timeout: 10_000 });
    // Not a bound on the page's time: only long enough for rows it asked for by itself to show their bar, or be drawn.
    await page.waitForTimeout(1500);
    expect(await barsShown(page)).toEqual([]);
    expect(await page.getByTestId('charts').locator('.uplot').count()).toBe(0);
    expect(await page.getByTestId('charts-cancelled').isVisible()).toBe(true);
    await page.getByTestId('charts-draw').click();
    await expect.poll(() => page.getByTestId('charts').locator('.uplot').count(), { timeout: 30_000 }).toBe(2);
    expect(await page.getByTestId('charts-cancelled').isHidden()).toBe(true);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('keeps the check cancelled until Check them (the path traced again at the switch back checked the points by itself)', { timeout: 180_000 }, async () => {
    // The helix's first points, and one off it: a verdict of a difference at point 2.
    const points = encodeURIComponent('1000,0,0\n1000,1,0\n1000,2,1\n');
    const p = await openPage(`?${helix}&turns=1&points=${points}`);
    const { page } = p;
    const counter = page.getByTestId('step-counter');
    const verdict = page.getByTestId('check-verdict');
    await verdict.waitFor({ timeout: 30_000 });
    const cancelled = onceShown(page, 'check-run', { click: 'check-cancel' });
    await page.getByTestId('input-turns').fill('264');
    await cancelled;
    await page.getByTestId('check-cancelled').waitFor({ timeout: 30_000 });

    await page.getByTestId('mode-gcode').click();
    await page.getByTestId('trace-status').filter({ hasText: 'moves' }).waitFor({ timeout: 30_000 });
    await recordBars(page, ['check-run']);
    await page.getByTestId('mode-trace').click();
    await counter.filter({ hasText: /of 1,498,840$/ }).waitFor({ timeout: 60_000 });
    // As above: said with the path or just after it.
    await page.getByTestId('check-cancelled').waitFor({ timeout: 10_000 });
    // As above: long enough for a check started by itself to show its bar, or its verdict.
    await page.waitForTimeout(1500);
    expect(await barsShown(page)).toEqual([]);
    expect(await verdict.count()).toBe(0);
    expect(await page.getByTestId('check-cancelled').isVisible()).toBe(true);
    await page.getByTestId('check-again').click();
    await verdict.waitFor({ timeout: 60_000 });
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});
