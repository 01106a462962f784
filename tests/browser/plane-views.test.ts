// The 2D view of a plane looks from the positive end of its normal, as the
// page's cw and ccw are meant (and G2, G3 in G17, G18, G19): an arc the
// page calls counterclockwise turns counterclockwise on screen. The zx
// plane was seen from -y, and every arc in it turned the other way round
// from its label. Read on screen: the start and end handles, and the
// current cell (its colour's pixels) part way round.
import type { Page } from 'playwright-core';
import { PNG } from 'pngjs';
import { afterAll, describe, expect, it } from 'vitest';
import { closeAll, openPage } from './harness.js';

afterAll(closeAll);

/** The current cell's colour (PALETTE.current). */
const CURRENT = [0xd5, 0x5e, 0x00];

/** Center of the element `testId`, page pixels, y down. */
async function centerOf(page: Page, testId: string): Promise<[number, number]> {
  const box = (await page.getByTestId(testId).boundingBox())!;
  return [box.x + box.width / 2, box.y + box.height / 2];
}

/** Center of the current cell's pixels in the view, page pixels, y down. */
async function currentCell(page: Page): Promise<[number, number]> {
  const canvas = page.locator('canvas').first();
  const box = (await canvas.boundingBox())!;
  const png = PNG.sync.read(await canvas.screenshot());
  const scale = png.width / box.width;
  let [sx, sy, n] = [0, 0, 0];
  for (let y = 0; y < png.height; y++) {
    for (let x = 0; x < png.width; x++) {
      const i = (y * png.width + x) * 4;
      if (CURRENT.every((v, c) => Math.abs(png.data[i + c]! - v) <= 12)) [sx, sy, n] = [sx + x, sy + y, n + 1];
    }
  }
  expect(n, 'pixels of the current cell').toBeGreaterThan(20);
  return [box.x + sx / n / scale, box.y + sy / n / scale];
}

/** +1 when a, b, c turn counterclockwise as seen (page y is down), -1 clockwise. */
function turn(a: [number, number], b: [number, number], c: [number, number]): number {
  const cross = (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]);
  return -Math.sign(cross);
}

describe('the 2D view of the zx plane', () => {
  it("stands x's tick labels left of its axis, which runs up the screen, and z's below theirs", async () => {
    const p = await openPage('?algorithm=circle&from=0,0,40&to=40,0,0&center=0,0,0&plane=zx&dir=ccw&view=2d');
    const { page } = p;
    await page.getByTestId('inspector-deviation').filter({ hasText: 'grid units' }).waitFor();
    await page.evaluate(() => new Promise<void>((resolve) => requestAnimationFrame(() => requestAnimationFrame(() => setTimeout(resolve, 50)))));
    const { axisX, x, z } = await page.evaluate(() => {
      const shown = (axis: string) =>
        [...document.querySelectorAll<HTMLElement>(`.scene-label.tick[data-axis=${axis}]`)].filter((e) => e.checkVisibility()).map((e) => e.getBoundingClientRect().toJSON() as DOMRect);
      const name = [...document.querySelectorAll<HTMLElement>('.scene-label.axis-name')].find((e) => e.textContent === 'x')!.getBoundingClientRect();
      return { axisX: name.left + name.width / 2, x: shown('x'), z: shown('z') };
    });
    expect(x.length).toBeGreaterThan(1);
    expect(z.length).toBeGreaterThan(1);
    // x's labels wholly left of its axis line (they were centred on it) and one above another; z's in one row.
    for (const label of x) expect(label.right, JSON.stringify(label)).toBeLessThanOrEqual(axisX);
    expect(new Set(x.map((l) => Math.round(l.left + l.width / 2))).size).toBeLessThanOrEqual(2);
    expect(new Set(z.map((l) => Math.round(l.top))).size).toBe(1);
    await p.close();
  });
});

describe('the 2D view of each plane', () => {
  it.each([
    ['xy', '5,0,0', '0,5,0'],
    ['yz', '0,5,0', '0,0,5'],
    ['zx', '0,0,5', '5,0,0'],
  ])('shows a counterclockwise arc in %s turning counterclockwise, and a clockwise one clockwise', async (plane, from, to) => {
    for (const [dir, sense] of [
      ['ccw', 1],
      ['cw', -1],
    ] as const) {
      // A quarter turn ccw, three quarters cw: a third of the way along, the
      // current cell is off the chord from the start to the end.
      const p = await openPage(`?algorithm=circle&from=${from}&to=${to}&center=0,0,0&plane=${plane}&dir=${dir}&view=2d&step=${dir === 'ccw' ? 3 : 8}`);
      const { page } = p;
      await page.getByTestId('inspector-deviation').filter({ hasText: 'grid units' }).waitFor();
      await page.evaluate(() => new Promise<void>((resolve) => requestAnimationFrame(() => requestAnimationFrame(() => setTimeout(resolve, 50)))));
      const [start, now, end] = [await centerOf(page, 'handle-from'), await currentCell(page), await centerOf(page, 'handle-to')];
      expect(turn(start, now, end), `${plane} ${dir}: start ${start}, a third along ${now}, end ${end}`).toBe(sense);
      expect(p.problems()).toEqual([]);
      await p.close();
    }
  });
});
