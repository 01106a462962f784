// The page by keyboard and through assistive technology, in headless
// Chromium: which keys the page's shortcuts give way to (an open list, the
// view, a modal dialog), where the focus goes when a line of the experiment
// opens and on the way back, what a screen reader hears as the step changes,
// the legend in forced colours, the view's focus ring, the charts' cursor
// of a link's step, and a small embedded frame. Found by a tester who used
// the page with the keyboard only.
import { readFileSync } from 'node:fs';
import type { Page } from 'playwright-core';
import { PNG } from 'pngjs';
import { afterAll, describe, expect, it } from 'vitest';
import { closeAll, openPage, screenshot } from './harness.js';

afterAll(closeAll);

async function counter(page: Page): Promise<string> {
  return page.getByTestId('step-counter').innerText();
}

describe('the keys the page gives way to', () => {
  it('leaves the keys of an open algorithm list to the list', async () => {
    const p = await openPage('?from=0,0,0&to=10,7,6&step=3');
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: 'Step 3 of 10' }).waitFor();
    await page.getByTestId('algorithm').focus();
    await page.keyboard.press('Enter');
    // The list is open (a styled select focuses its option): End, Home and
    // the arrows move in it, not along the path.
    for (const key of ['End', 'Home', 'ArrowDown', 'ArrowRight']) await page.keyboard.press(key);
    expect(await page.evaluate(() => document.activeElement?.closest('select')?.id)).toBe('algorithm');
    expect(await counter(page)).toBe('Step 3 of 10');
    expect(await page.locator('#play-label').innerText()).toBe('Play');
    await page.keyboard.press('Escape');
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('takes only the keys the view and a handle use there: Space, Home, End, ? and F still work', async () => {
    const p = await openPage('?from=0,0,0&to=10,7,6&step=3');
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: 'Step 3 of 10' }).waitFor();
    await page.getByTestId('scene-canvas').focus();
    // The arrows pan the view: the step stays.
    await page.keyboard.press('ArrowRight');
    expect(await counter(page)).toBe('Step 3 of 10');
    await page.keyboard.press('End');
    await page.getByTestId('step-counter').filter({ hasText: 'Step 10 of 10' }).waitFor();
    await page.keyboard.press('Home');
    await page.getByTestId('step-counter').filter({ hasText: 'Step 0 of 10' }).waitFor();
    await page.keyboard.press('f');
    expect(await page.getByTestId('follow').isChecked()).toBe(true);
    await page.keyboard.press('f');
    expect(await page.getByTestId('follow').isChecked()).toBe(false);
    await page.keyboard.press('?');
    await page.getByTestId('help').waitFor();
    await page.keyboard.press('Escape');
    // A handle: Page Up moves it (the move's end changes); End still goes to the last step.
    await page.getByTestId('handle-to').focus();
    await page.keyboard.press('End');
    await page.getByTestId('step-counter').filter({ hasText: 'Step 10 of 10' }).waitFor();
    await page.keyboard.press('?');
    await page.getByTestId('help').waitFor();
    await page.keyboard.press('Escape');
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('plays and pauses with Space on a handle, whose arrows still move it', async () => {
    // A handle is a button, and Space on a button was left to the button,
    // whose press does nothing: Space did nothing there. Found by a helper's hunt.
    const p = await openPage('?from=0,0,0&to=10,7,6&speed=8');
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: 'Step 0 of 10' }).waitFor();
    const handle = page.getByTestId('handle-from');
    await handle.focus();
    await page.keyboard.press(' ');
    await page.locator('#play-label').filter({ hasText: 'Pause' }).waitFor();
    await page.getByTestId('step-counter').filter({ hasText: /^Step [1-9]/ }).waitFor();
    await page.keyboard.press(' ');
    await page.locator('#play-label').filter({ hasText: 'Play' }).waitFor();
    await page.keyboard.press('ArrowRight');
    await expect.poll(() => handle.getAttribute('title')).toBe('from (1, 0, 0)');
    expect(await page.evaluate(() => (document.activeElement as HTMLElement | null)?.dataset.testid)).toBe('handle-from');
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('keeps every key from the page behind a modal dialog', async () => {
    const p = await openPage('?from=0,0,0&to=10,7,6&step=3');
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: 'Step 3 of 10' }).waitFor();
    await page.getByTestId('help-open').click();
    await page.getByTestId('help').waitFor();
    for (const key of ['End', 'ArrowRight', 'Home', 'f']) await page.keyboard.press(key);
    expect(await counter(page)).toBe('Step 3 of 10');
    expect(await page.getByTestId('follow').isChecked()).toBe(false);
    await page.keyboard.press('Escape');
    await page.keyboard.press('End');
    await page.getByTestId('step-counter').filter({ hasText: 'Step 10 of 10' }).waitFor();
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});

describe('focus and what a screen reader hears', () => {
  it('moves the focus to the view when a line of the experiment opens, and back to its button after Back', async () => {
    const p = await openPage('?mode=experiment&algorithm=regions&count=5&seed=1');
    const { page } = p;
    await page.getByTestId('open-line-3').focus();
    await page.keyboard.press('Enter');
    await page.getByTestId('trace-status').filter({ hasText: 'regions' }).waitFor();
    expect(await page.evaluate(() => document.activeElement?.id)).toBe('viewport');
    // There the arrows step the path.
    await page.getByTestId('step-counter').filter({ hasText: /of [1-9]/ }).waitFor();
    await page.keyboard.press('ArrowRight');
    await page.getByTestId('step-counter').filter({ hasText: /^Step 1 of/ }).waitFor();
    await page.goBack();
    await page.getByTestId('lines-table').waitFor();
    await expect.poll(() => page.evaluate(() => (document.activeElement as HTMLElement | null)?.dataset.testid)).toBe('open-line-3');
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it("says the step's reason in a live region in a wide window too, where it is out of sight beside the inspector", async () => {
    const p = await openPage('?from=0,0,0&to=10,7,6');
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: 'Step 0 of 10' }).waitFor();
    const reason = page.getByTestId('step-reason');
    expect(await reason.getAttribute('aria-live')).toBe('polite');
    await page.getByTestId('scrubber').focus();
    await page.keyboard.press('ArrowRight');
    // Wang eq. (10) at the first step of (0,0,0)->(10,7,6): region d, all three axes step.
    await expect.poll(() => reason.textContent()).toMatch(/^Step 1: /);
    expect(await page.getByTestId('inspector-explanation').textContent()).toBe((await reason.textContent())!.replace(/^Step 1: /, ''));
    // In the accessibility tree, not on screen: the inspector shows the same words.
    const box = (await reason.boundingBox())!;
    expect(box.width * box.height).toBeLessThanOrEqual(1);
    expect(await page.evaluate(() => document.querySelector('[data-testid=step-reason]')!.checkVisibility())).toBe(true);
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});

describe('what is drawn for the keyboard and in forced colours', () => {
  it("draws the view's focus ring inside the view, which clips what overflows it", async () => {
    const p = await openPage('?from=0,0,0&to=10,7,6');
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: 'Step 0 of 10' }).waitFor();
    const region = (await page.locator('#viewport').boundingBox())!;
    const unfocused = await screenshot(page, 'view-unfocused', region);
    await page.getByTestId('reset-view').focus();
    await page.keyboard.press('Tab');
    expect(await page.evaluate(() => (document.activeElement as HTMLElement).dataset.testid)).toBe('scene-canvas');
    const focused = await screenshot(page, 'view-focused', region);
    // The ring: the canvas's edge in the accent colour, which the unfocused view does not have.
    const edge = (file: string) => {
      const { data, width } = PNG.sync.read(readFileSync(file));
      let accent = 0;
      for (let x = 4; x < width - 4; x++) {
        const i = (2 * width + x) * 4;
        if (data[i]! < 60 && data[i + 1]! > 90 && data[i + 1]! < 140 && data[i + 2]! > 150) accent++;
      }
      return accent / (width - 8);
    };
    expect(edge(unfocused.file)).toBeLessThan(0.1);
    expect(edge(focused.file)).toBeGreaterThan(0.9);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('keeps the legend swatches in the colours the view draws in, in forced colours', async () => {
    const p = await openPage('?mode=compare&algorithm=regions&other=greedy&from=0,0,0&to=10,7,6');
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: /of [\d,]+$/ }).waitFor();
    const colours = () =>
      page.evaluate(() => ['visited', 'current', 'second', 'only-first', 'only-second'].map((name) => getComputedStyle(document.querySelector(`.swatch-${name}`)!).backgroundColor));
    const normal = await colours();
    await page.emulateMedia({ forcedColors: 'active' });
    expect(await page.evaluate(() => matchMedia('(forced-colors: active)').matches)).toBe(true);
    const forced = await colours();
    expect(forced).toEqual(normal);
    // And each is its own: forced colours made them one colour.
    expect(new Set(forced).size).toBe(forced.length);
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});

describe("a link's step", () => {
  it("puts the charts' cursor at the step the link gives, as stepping there does", async () => {
    const p = await openPage('?from=0,0,0&to=10,7,6&step=7');
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: 'Step 7 of 10' }).waitFor();
    const chart = page.locator('.chart').first();
    await chart.waitFor();
    /** The column of the chart's cursor: the one with the most pixels of its colour (#d55e00). */
    const cursorColumn = async () => {
      const png = PNG.sync.read(await chart.screenshot());
      let best = -1;
      let most = 0;
      for (let x = 0; x < png.width; x++) {
        let n = 0;
        for (let y = 0; y < png.height; y++) {
          const i = (y * png.width + x) * 4;
          if (Math.abs(png.data[i]! - 0xd5) < 20 && Math.abs(png.data[i + 1]! - 0x5e) < 20 && png.data[i + 2]! < 30) n++;
        }
        if (n > most) [best, most] = [x, n];
      }
      return best;
    };
    // Let the charts arrive and draw.
    await expect.poll(() => cursorColumn()).toBeGreaterThan(0);
    const fromLink = await cursorColumn();
    await page.getByTestId('scrubber').focus();
    await page.keyboard.press('Home');
    await page.getByTestId('step-counter').filter({ hasText: 'Step 0 of 10' }).waitFor();
    await expect.poll(() => cursorColumn()).not.toBe(fromLink);
    for (let i = 0; i < 7; i++) await page.keyboard.press('ArrowRight');
    await page.getByTestId('step-counter').filter({ hasText: 'Step 7 of 10' }).waitFor();
    await expect.poll(() => cursorColumn()).toBe(fromLink);
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});

describe('a small embedded frame', () => {
  it('keeps the view a usable part of the frame, with its link inside it', async () => {
    // What the picture can use: the view below the legend and the tools where they stand over it. At 480 x 360 the
    // tools stood stacked over 125 px of a view of 266 (141 px left under them); above it, they leave it 197 to 207 px.
    const usableHeight = (page: Page) =>
      page.evaluate(() => {
        const view = document.querySelector('[data-testid=scene-canvas]')!.getBoundingClientRect();
        const over = [...document.querySelectorAll('#viewport > .legend, #viewport > .view-tools')].map((e) => e.getBoundingClientRect()).filter((box) => box.height > 0);
        return view.bottom - Math.max(view.top, ...over.map((box) => box.bottom));
      });
    for (const [width, height, least] of [
      [320, 240, 70],
      [480, 360, 190],
    ] as const) {
      for (const query of ['?embed=1&from=0,0,0&to=10,7,6', '?embed=1&mode=gcode']) {
        const p = await openPage(query);
        const { page } = p;
        await page.setViewportSize({ width, height });
        await page.getByTestId('step-counter').filter({ hasText: /of [1-9]/ }).waitFor();
        const at = `${query} at ${width}x${height}`;
        await expect.poll(() => usableHeight(page), { message: at }).toBeGreaterThanOrEqual(least);
        const link = (await page.getByTestId('open-full').boundingBox())!;
        expect(link.y, at).toBeGreaterThanOrEqual(0);
        expect(link.y + link.height, at).toBeLessThanOrEqual(height);
        // Nothing runs off the frame: the playback fits without a scroll.
        expect(await page.evaluate(() => document.documentElement.scrollHeight), at).toBeLessThanOrEqual(height);
        expect(p.problems()).toEqual([]);
        await p.close();
      }
    }
  });
});
