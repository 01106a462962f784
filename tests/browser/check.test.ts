// Trace mode's Check points panel (issue 17 item 4), on the issue's
// done-when case: the bresenham3d (tie = hold) path, computed by the core
// here, checked against regions from (0, 0, 0) to (10, 7, 6) on the page.
import type { Page } from 'playwright-core';
import { PNG } from 'pngjs';
import { afterAll, describe, expect, it } from 'vitest';
import { trace } from '../../web/core/index.js';
import { closeAll, openPage, screenshot } from './harness.js';
import { pointsOf } from '../helpers.js';

afterAll(closeAll);

/** `text` in the learner's points box as typed (Playwright's fill types a line break at a time, for minutes at the lengths here). */
async function typeInto(page: Page, text: string): Promise<void> {
  await page.getByTestId('learner-points').evaluate((box: HTMLTextAreaElement, value) => {
    box.value = value;
    box.dispatchEvent(new Event('input', { bubbles: true }));
  }, text);
}

/**
 * The points the page holds: past 10,000 lines they are listed read-only
 * (their note says how many lines), and "Edit as text" puts them in the
 * text box, where they are read.
 */
async function shownPoints(page: Page): Promise<string> {
  const box = page.getByTestId('learner-points');
  if (await page.getByTestId('learner-listing').isVisible()) {
    expect(await box.isHidden()).toBe(true);
    await page.getByTestId('learner-edit-anyway').click();
  }
  return box.inputValue();
}

const MOVE = { from: [0, 0, 0], to: [10, 7, 6] };

/**
 * Pixels of the learner's path, PALETTE.learner (#0072b2, Okabe-Ito blue)
 * lit: blue with hardly any red. The rule's visited cells (sky blue,
 * #56b4e9) keep a red of about 0.37 of their blue under the view's white
 * lights; nothing else in a line's view is blue.
 */
function learnerPixels(png: Buffer): number {
  const { data } = PNG.sync.read(png);
  let count = 0;
  for (let i = 0; i < data.length; i += 4) {
    const [r, g, b] = [data[i]!, data[i + 1]!, data[i + 2]!];
    if (b > 60 && r < 0.15 * b && g > 0.4 * b && g < 0.85 * b) count++;
  }
  return count;
}

async function canvasPng(page: Page): Promise<Buffer> {
  return page.getByTestId('scene-canvas').screenshot();
}

describe('Check points (trace mode)', () => {
  it("shows where bresenham3d (tie = hold) parts from regions, with regions' reason, the rules it follows, the path and a marker; kept over a reload", async () => {
    const hold = await trace({ algorithm: 'bresenham3d', ...MOVE, tie: 'hold' });
    const csv = 'x,y,z\n' + pointsOf(hold).map((r) => r.join(',')).join('\n') + '\n';
    hold.free();
    const regions = await trace({ algorithm: 'regions', ...MOVE });
    const why = regions.explain(4);
    regions.free();

    const p = await openPage('?mode=trace&algorithm=regions&from=0,0,0&to=10,7,6');
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: /of 10$/ }).waitFor();
    expect(await page.getByTestId('check-marker').isHidden()).toBe(true);
    const before = learnerPixels(await canvasPng(page));

    await page.getByTestId('check-points').locator('summary').click();
    await page.getByTestId('learner-points').fill(csv);
    const verdict = page.getByTestId('check-verdict');
    await verdict.waitFor();
    expect(await verdict.innerText()).toBe('Your points part from regions at point 5: at point 5 your path goes to (5, 3, 3); the rule goes to (5, 4, 3).');
    const reason = await page.getByTestId('check-why').innerText();
    // The core's own sentence for regions' step 4, and its decision values: segment g, a tie, advance.
    expect(reason).toContain(why);
    // Counted as the page counts steps: the decision that reaches point 5 is step 5 (the inspector's "Decision of step 5").
    expect(reason).toMatch(/^The rule at step 5: /);
    expect(reason).toMatch(/region = g/);
    expect(reason).toMatch(/tie = true/);
    expect(reason).toMatch(/advance/);
    expect(await page.getByTestId('check-follows').innerText()).toContain('bresenham3d with tie = hold');

    // The marker on the timeline at point 5, which goes there.
    const marker = page.getByTestId('check-marker');
    await marker.waitFor();
    expect(await marker.getAttribute('data-point-index')).toBe('5');
    // A small diamond above the scrubber's track: as a button it took the
    // buttons' least height and stood as a bar across half the scrubber.
    const markerBox = (await marker.boundingBox())!;
    expect(Math.abs(markerBox.width - markerBox.height)).toBeLessThan(2);
    expect(markerBox.height).toBeLessThan(20);
    await marker.click();
    expect(await page.getByTestId('step-counter').innerText()).toBe('Step 5 of 10');
    // Both cells at point 5 outlined, the learner's path drawn in its colour, with its legend entry.
    expect(await page.getByTestId('scene-canvas').getAttribute('data-highlighted')).toBe('2');
    expect(await page.getByTestId('legend-learner').isVisible()).toBe(true);
    // The legend grew by the learner's two entries: the path is framed below it again (the z axis's name stood under it).
    await expect
      .poll(async () => {
        const legend = (await page.locator('#legend').boundingBox())!;
        const z = (await page.locator('#viewport .axis-name').filter({ hasText: /^z$/ }).boundingBox())!;
        return z.y >= legend.y + legend.height;
      })
      .toBe(true);
    await page.getByTestId('last').click();
    const stats = await screenshot(page, 'check-points', '[data-testid=scene-canvas]');
    expect(stats.differingFraction).toBeGreaterThan(0.02);
    expect(learnerPixels(await canvasPng(page))).toBeGreaterThan(before + 200);
    await screenshot(page, 'check-points-page');

    // The points are in the link (short) and survive a reload.
    await page.waitForURL(/points=/);
    await page.reload();
    await page.getByTestId('check-verdict').filter({ hasText: 'at point 5' }).waitFor();
    expect(await page.getByTestId('learner-points').inputValue()).toBe(csv);
    expect(await page.getByTestId('check-marker').getAttribute('data-point-index')).toBe('5');
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('draws the checked points in one frame, framed below the legend their entries grow', async () => {
    // The learner's two legend entries grow the legend over the view's top,
    // below which the path is framed. Framed again only when the legend's
    // ResizeObserver reported it, after the layout of the frame that drew
    // the points, the view drew a second frame just to move the camera: at
    // the page's cap each is 100 to 210 ms of the main thread on a software
    // GPU (the compositor reads the canvas back). The frames are counted by
    // the view's clears, one a frame (three.js clears before it draws).
    const hold = await trace({ algorithm: 'bresenham3d', ...MOVE, tie: 'hold' });
    const csv = pointsOf(hold).map((r) => r.join(',')).join('\n') + '\n';
    hold.free();
    const p = await openPage('?mode=trace&algorithm=regions&from=0,0,0&to=10,7,6', {
      initScript: () => {
        const counted = window as unknown as { sceneFrames: number };
        counted.sceneFrames = 0;
        const clear = WebGL2RenderingContext.prototype.clear;
        WebGL2RenderingContext.prototype.clear = function (this: WebGL2RenderingContext, mask: number) {
          if ((this.canvas as HTMLCanvasElement).dataset.testid === 'scene-canvas') counted.sceneFrames++;
          clear.call(this, mask);
        };
      },
    });
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: /of 10$/ }).waitFor();
    await page.getByTestId('check-points').locator('summary').click();
    expect(await page.getByTestId('legend-learner').isHidden()).toBe(true);
    // From the task that shows the verdict (the worker's answer), the view's frames over the next ten animation frames.
    const framesAfterAnswer = page.evaluate(
      () =>
        new Promise<number>((resolve) => {
          const counted = window as unknown as { sceneFrames: number };
          const result = document.querySelector('[data-testid="check-result"]')!;
          const observer = new MutationObserver(() => {
            if (!result.querySelector('[data-testid="check-verdict"]')) return;
            observer.disconnect();
            const atAnswer = counted.sceneFrames;
            let left = 10;
            const tick = () => (--left > 0 ? requestAnimationFrame(tick) : resolve(counted.sceneFrames - atAnswer));
            requestAnimationFrame(tick);
          });
          observer.observe(result, { childList: true, subtree: true });
        }),
    );
    await page.getByTestId('learner-points').fill(csv);
    expect(await framesAfterAnswer).toBe(1);
    expect(await page.getByTestId('legend-learner').isVisible()).toBe(true);
    // That frame is framed below the grown legend: the z axis's name clear of it.
    const legend = (await page.locator('#legend').boundingBox())!;
    const z = (await page.locator('#viewport .axis-name').filter({ hasText: /^z$/ }).boundingBox())!;
    expect(z.y).toBeGreaterThanOrEqual(legend.y + legend.height);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it("draws a long path's points as the rule's are drawn, by their sample, with every cell near the current step", { timeout: 180_000 }, async () => {
    // The rule's 200,000-step line (drawn the lighter way on any WebGL: cells.ts), and its
    // points with one near the middle moved a cell: its z step taken a point later. Their line through the cells' centers was
    // drawn through all 200,001 of them: at the page's cap, 1,498,841 vertices that a software
    // GPU took 0.7 to 1.6 s to draw in every frame.
    const move = { from: [0, 0, 0], to: [200_000, 140_000, 120_000] };
    const rule = await trace({ algorithm: 'regions', ...move });
    const rows = pointsOf(rule);
    rule.free();
    const z = (k: number) => rows[k]![2]!;
    let moved = 100_000;
    while (z(moved) === z(moved - 1) || z(moved + 1) !== z(moved)) moved++;
    rows[moved]![2] = z(moved - 1);
    const [at, of] = [moved, rows.length - 1].map((n) => n.toLocaleString('en-US'));
    const p = await openPage(`?mode=trace&algorithm=regions&from=0,0,0&to=${move.to.join(',')}`);
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: /of 200,000$/ }).waitFor({ timeout: 60_000 });
    await page.getByTestId('check-points').locator('summary').click();
    await typeInto(page, rows.map((r) => r.join(',')).join('\n') + '\n');
    await page.getByTestId('check-verdict').filter({ hasText: new RegExp(`at point (${moved}|${at}):`) }).waitFor({ timeout: 120_000 });
    const canvas = page.getByTestId('scene-canvas');
    await page.getByTestId('go-check-difference').click();
    await page.getByTestId('step-counter').filter({ hasText: `Step ${at} of ${of}` }).waitFor();
    // The rule's cubes near the step come from the worker; the learner's points are held.
    interface Drawn {
      points: number;
      cubes: number;
      lineVertices: number;
    }
    const drawn = async (path: 'pathDrawn' | 'secondDrawn'): Promise<Drawn | undefined> => {
      const json = await canvas.evaluate((c, key) => (c as HTMLCanvasElement).dataset[key], path);
      return json ? (JSON.parse(json) as Drawn) : undefined;
    };
    await expect.poll(async () => (await drawn('pathDrawn'))?.cubes ?? 0).toBeGreaterThan(0);
    const ruleDrawn = (await drawn('pathDrawn'))!;
    const learnerDrawn = (await drawn('secondDrawn'))!;
    // The same sample of points as the rule's, the same cubes around the step, and the line through those cubes alone.
    expect(learnerDrawn.points).toBe(ruleDrawn.points);
    expect(learnerDrawn.cubes).toBe(ruleDrawn.cubes);
    expect(learnerDrawn.lineVertices).toBe(learnerDrawn.cubes);
    expect(learnerDrawn.points + learnerDrawn.cubes + learnerDrawn.lineVertices).toBeLessThan(rows.length / 5);
    // Brought close, the learner's cells and line at their difference are drawn, the two cells outlined.
    await page.waitForTimeout(300);
    expect(await canvas.getAttribute('data-highlighted')).toBe('2');
    expect(learnerPixels(await canvasPng(page))).toBeGreaterThan(500);
    await screenshot(page, 'check-points-long', '[data-testid=scene-canvas]');
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('goes to a difference past the end of the path at its last point', async () => {
    // Points that go on after the rule's path ends: the difference is at
    // point 11 of a 10-step path, and "Go to point 11" showed step 11 of 10.
    const regions = await trace({ algorithm: 'regions', ...MOVE });
    const csv = [...pointsOf(regions), [11, 7, 6], [12, 8, 7]].map((r) => r.join(',')).join('\n') + '\n';
    regions.free();
    const p = await openPage('?mode=trace&algorithm=regions&from=0,0,0&to=10,7,6');
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: /of 10$/ }).waitFor();
    await page.getByTestId('check-points').locator('summary').click();
    await page.getByTestId('learner-points').fill(csv);
    await page.getByRole('button', { name: 'Go to point 11' }).click();
    await page.getByTestId('step-counter').filter({ hasText: 'Step 10 of 10' }).waitFor();
    await page.waitForURL(/step=10&/);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it("names the line of a malformed point with the core's message, and keeps long points in storage", async () => {
    const p = await openPage('?mode=trace&algorithm=regions&from=0,0,0&to=10,7,6');
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: /of 10$/ }).waitFor();
    await page.getByTestId('check-points').locator('summary').click();
    await page.getByTestId('learner-points').fill('0,0,0\n1,1,1\n2,x,2\n');
    const error = page.getByTestId('check-error');
    await error.waitFor();
    expect(await error.innerText()).toBe("line 3, column 3: point 2: y = 'x' is not a number");
    expect(await page.getByTestId('check-marker').isHidden()).toBe(true);

    // Longer than a link keeps: in storage, whole, over a reload.
    const long = '# ' + 'a comment line\n# '.repeat(200) + '\n0,0,0\n1,1,1\n';
    await page.getByTestId('learner-points').fill(long);
    await page.getByTestId('check-verdict').filter({ hasText: 'point 2' }).waitFor();
    await page.waitForTimeout(600);
    expect(page.url()).not.toContain('points=');
    await page.reload();
    await page.getByTestId('check-verdict').filter({ hasText: 'your path stops at step 1 of 10' }).waitFor();
    expect(await page.getByTestId('learner-points').inputValue()).toBe(long);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('keeps long points whole over a reload right after each edit: longer, shorter, changed in the middle, short again', async () => {
    // 20,000 points, 240,000 characters: storage keeps them in several pieces, each rewritten only when it changes.
    const long = Array.from({ length: 20_000 }, (_, k) => `${k},${k + 1},${k + 2}`).join('\n') + '\n';
    const p = await openPage('?mode=trace&algorithm=regions&from=0,0,0&to=10,7,6');
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: /of 10$/ }).waitFor();
    await page.getByTestId('check-points').locator('summary').click();
    for (const text of [long, long.slice(0, 100_000), `${long.slice(0, 50_000)}# a note\n${long.slice(50_000, 100_000)}`, '0,0,0\n1,1,1\n']) {
      await typeInto(page, text);
      // No wait: the page writes what changed as it leaves.
      await page.reload();
      await page.getByTestId('step-counter').filter({ hasText: /of 10$/ }).waitFor();
      // 20,000 lines are listed; the others, 8,334 lines at most, are in the text box.
      expect(await page.getByTestId('learner-listing').isVisible()).toBe(text === long);
      expect(await shownPoints(page)).toBe(text);
    }
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('keeps the last-written tab\'s long points whole when two tabs edit them', async () => {
    const query = '?mode=trace&algorithm=regions&from=0,0,0&to=10,7,6';
    const long = (label: string) => Array.from({ length: 20_000 }, (_, k) => `${k},${k + 1},${k + 2} # ${label}`).join('\n') + '\n';
    const a = await openPage(query);
    const open = async () => {
      const page = await a.context.newPage();
      await page.goto(a.url);
      await page.getByTestId('step-counter').filter({ hasText: /of 10$/ }).waitFor();
      return page;
    };
    const type = async (page: Page, text: string) => {
      await typeInto(page, text);
      // Past the page's write delay (400 ms): written, and told to the other tab.
      await page.waitForTimeout(1_000);
    };
    const stored = async () => {
      const page = await open();
      const text = await shownPoints(page);
      await page.close();
      return text;
    };
    await a.page.getByTestId('step-counter').filter({ hasText: /of 10$/ }).waitFor();
    const first = long('a');
    await type(a.page, first);
    const b = await open();
    expect(await shownPoints(b)).toBe(first);
    // B shortens the points (its part holds them, their keys go); then A
    // steps, which changes none of its input: B's points, typed last, stay
    // whole (A's part, written again, said its points were in the keys B
    // had removed).
    await type(b, '0,0,0\n1,1,1\n');
    await a.page.getByTestId('next').click();
    await a.page.waitForTimeout(1_000);
    expect(await stored()).toBe('0,0,0\n1,1,1\n');
    // B changes the start of its points, A the end of its own: each rewrote
    // only the pieces it changed, and the keys held B's first piece with
    // A's others.
    await type(b, `# B's\n${first}`);
    await type(a.page, `${first}# A's\n`);
    expect(await stored()).toBe(`${first}# A's\n`);
    await b.close();
    expect(a.problems()).toEqual([]);
    await a.close();
  });
});
