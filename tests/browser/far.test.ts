// The view draws a path the same wherever it lies on the grid. WebGL's
// floats have 24 bits: a coordinate near 2^30 as one is a multiple of 64,
// and a path there was drawn as a smear or not at all (no cells, no grid,
// the ideal line missing its ends), within the page's own limit of ±2^30.
// So the same shape is drawn at the origin and moved near 2^30 (and near
// -2^30), and the two pictures are compared pixel by pixel: the view frames
// each from its own box, so they must match, labels aside.
import type { PNG } from 'pngjs';
import { afterAll, describe, expect, it } from 'vitest';
import { canvasPng, closeAll, openPage } from './harness.js';

afterAll(closeAll);

/**
 * The view's drawing of `algorithm` from `from` to `to`, seen by `camera`
 * (position x, y, z, target x, y, z, as the link writes it), all plus
 * `offset` on every axis, with more of the link (`more`). The camera is
 * given, not framed: the page frames a path with room for its tick labels,
 * which are longer far out.
 */
async function drawn(algorithm: string, from: readonly number[], to: readonly number[], camera: readonly number[], offset: number, more: string): Promise<PNG> {
  const at = (p: readonly number[]) => p.map((c) => c + offset).join(',');
  // A path in x and y lies at z = 0, and so does its camera's z.
  const moved = camera.map((c, i) => (i % 3 < from.length ? c + offset : c));
  const seen = `${moved.join(',')},1`;
  const p = await openPage(`?algorithm=${algorithm}&from=${at(from)}&to=${at(to)}&camera=${seen}${more}`);
  const { page } = p;
  await page.getByTestId('inspector-deviation').filter({ hasText: 'grid units' }).waitFor();
  // Two frames and a task: the overlay and the cells of the step are drawn.
  await page.evaluate(() => new Promise<void>((resolve) => requestAnimationFrame(() => requestAnimationFrame(() => setTimeout(resolve, 50)))));
  expect(p.problems()).toEqual([]);
  const png = await canvasPng(page);
  await p.close();
  return png;
}

/** Share of the pixels of `a` and `b` that differ by more than `tolerance` on some channel. */
function differingShare(a: PNG, b: PNG, tolerance = 16): number {
  expect([b.width, b.height]).toEqual([a.width, a.height]);
  let differing = 0;
  for (let i = 0; i < a.data.length; i += 4) {
    if ([0, 1, 2].some((c) => Math.abs(a.data[i + c]! - b.data[i + c]!) > tolerance)) differing += 1;
  }
  return differing / (a.width * a.height);
}

/** Share of the pixels that are not the most frequent colour (the background): how much was drawn. */
function drawnShare(png: PNG): number {
  const counts = new Map<number, number>();
  for (let i = 0; i < png.data.length; i += 4) {
    const rgb = png.data.readUInt32BE(i) >>> 8;
    counts.set(rgb, (counts.get(rgb) ?? 0) + 1);
  }
  return 1 - Math.max(...counts.values()) / (png.width * png.height);
}

describe('a path far from the origin', () => {
  it('is drawn at the far end of a long line as at the same end of a short one: the ideal line runs where its cells are', async () => {
    // Lines along (10, 7, 6): a short one's last cells are a long one's,
    // moved by a multiple of it, and so is the ideal line through them. The
    // long line's ideal line is taken from its start, 1,850,000 units away:
    // before, it was drawn 11 pixels (a tenth of a cell) off, across the
    // cells there, which are drawn from the point looked at. The step is 6
    // before the end and the camera looks at the last cells, which are
    // ahead of it and faint: no solid cell hides the line, whose dashes
    // behind cells are placed by its length, which differs.
    const end = (scale: number) => [10 * scale, 7 * scale, 6 * scale];
    const camera = (at: readonly number[]) => [at[0]! + 3.5, at[1]! - 5, at[2]! - 4.5, at[0]! - 1.5, at[1]! - 1.05, at[2]! - 0.9];
    const [long, short] = [end(140_000), end(20)];
    const near = await drawn('regions', [0, 0, 0], short, camera(short), 0, `&step=${short[0]! - 6}`);
    const far = await drawn('regions', [0, 0, 0], long, camera(long), 0, `&step=${long[0]! - 6}`);
    expect(drawnShare(near)).toBeGreaterThan(0.05);
    expect(differingShare(near, far)).toBeLessThan(0.002);
  });

  it("is drawn in a long line's middle as in a short one's, the ideal line through its cells", async () => {
    // The ideal line is one segment whose ends are 900,000 cells from the
    // middle, each off by up to a sixteenth of a cell as a float from
    // there: drawn between them, the line was as far off in the middle.
    // It is split there, so each half has an exact end near the camera.
    const point = (scale: number) => [10 * scale, 7 * scale, 6 * scale];
    const camera = (at: readonly number[]) => [at[0]! + 3.5, at[1]! - 5, at[2]! - 4.5, at[0]! - 1.5, at[1]! - 1.05, at[2]! - 0.9];
    const [long, short] = [140_000, 20];
    const near = await drawn('regions', [0, 0, 0], point(short), camera(point(short / 2)), 0, `&step=${5 * short - 6}`);
    const far = await drawn('regions', [0, 0, 0], point(long), camera(point(long / 2)), 0, `&step=${5 * long - 6}`);
    expect(drawnShare(near)).toBeGreaterThan(0.05);
    expect(differingShare(near, far)).toBeLessThan(0.002);
  });

  it('dashes the ideal line behind the cells at the far end of a long line as at the end of a short one', async () => {
    // At the path's end every cell is solid, and the line behind them is
    // dashed by its length from the start. Before, the long line's lengths
    // were 32-bit floats from its start, multiples of an eighth of a cell
    // at its end, and its dashes there, a fifth of a cell long, ran into a
    // speckled line (0.15% of pixels differed). 133,212 and 20 lengths of
    // (10, 7, 6) are the same number of dash periods (0.38 cell) to within
    // 1e-6 cell; the short line's dash ends still come a pixel apart from
    // the long one's here and there (0.03%).
    const end = (scale: number) => [10 * scale, 7 * scale, 6 * scale];
    const camera = (at: readonly number[]) => [at[0]! + 5, at[1]! - 6, at[2]! - 6, at[0]! - 2, at[1]! - 1.4, at[2]! - 1.2];
    const [long, short] = [end(133_212), end(20)];
    const near = await drawn('regions', [0, 0, 0], short, camera(short), 0, `&step=${short[0]}`);
    const far = await drawn('regions', [0, 0, 0], long, camera(long), 0, `&step=${long[0]}`);
    expect(drawnShare(near)).toBeGreaterThan(0.05);
    expect(differingShare(near, far)).toBeLessThan(0.0006);
  });

  it('is drawn near 2^30 as at the origin: cells, ideal line, grid and the exit face of Decision in 3D', async () => {
    const shape = ['regions', [0, 0, 0], [24, 10, 5], [30, -22, 20, 8, 4, 2]] as const;
    const near = await drawn(...shape, 0, '&step=5&decision3d=1');
    const far = await drawn(...shape, 1073741800, '&step=5&decision3d=1');
    expect(drawnShare(near)).toBeGreaterThan(0.05);
    // Before, the far picture had the current cube alone.
    expect(differingShare(near, far)).toBeLessThan(0.002);
  });

  it('is drawn near -2^30 in 2D as at the origin, and so is a circle there', async () => {
    const line = ['bresenham2d', [0, 0], [24, 5], [12, 2, 40, 12, 2, 0]] as const;
    const flat = '&step=4&view=2d';
    expect(differingShare(await drawn(...line, 0, flat), await drawn(...line, -1073741824, flat))).toBeLessThan(0.002);
    const circle = ['circle', [20, 0, 0], [0, 20, 0], [30, -20, 30, 10, 10, 0]] as const;
    const around = (c: number) => `&center=${c},${c},${c}&step=9&decision3d=1`;
    expect(differingShare(await drawn(...circle, 0, around(0)), await drawn(...circle, 1073741000, around(1073741000)))).toBeLessThan(0.002);
  });
});
