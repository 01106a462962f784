// The page's layout in headless Chromium at the window sizes of issue 16:
// 1400x900 and 1024x768 (a laptop), 390x844 (a phone). The view, the
// timeline and the current step's reason must be on the first screen
// together, with nothing scrolled. The reason expected is the core's
// sentence for Wang et al.'s example (0,0,0)->(10,7,6) at step 3: M_3 = 12
// and N_3 = 6 (eq. 8) put the line in region d, so the step goes to D.
import type { Locator, Page } from 'playwright-core';
import { afterAll, describe, expect, it } from 'vitest';
import { closeAll, jumpTo, openPage, screenshot } from './harness.js';

afterAll(closeAll);

const REASON = 'M = 12 > 0 and N = 6 > 0';

/** True when the element is shown and wholly inside the window as it is (not scrolled). */
async function onFirstScreen(page: Page, locator: Locator): Promise<boolean> {
  if (!(await locator.isVisible())) return false;
  const box = (await locator.boundingBox())!;
  const { width, height } = page.viewportSize()!;
  return box.x >= 0 && box.y >= 0 && box.x + box.width <= width + 0.5 && box.y + box.height <= height + 0.5;
}

/** The elements showing the current step's reason that are on the first screen. */
async function reasonsInSight(page: Page, text: string): Promise<number> {
  const candidates = page.locator('[data-testid="inspector-explanation"], [data-testid="step-reason"]').filter({ hasText: text });
  let seen = 0;
  for (const candidate of await candidates.all()) if (await onFirstScreen(page, candidate)) seen++;
  return seen;
}

async function check(page: Page, name: string): Promise<void> {
  await page.getByTestId('inspector-explanation').filter({ hasText: REASON }).waitFor();
  await expect.poll(() => reasonsInSight(page, REASON), { message: `${name}: reason` }).toBeGreaterThan(0);
  expect(await onFirstScreen(page, page.locator('#viewport')), `${name}: view`).toBe(true);
  expect(await onFirstScreen(page, page.locator('.timeline')), `${name}: timeline`).toBe(true);
  expect(await page.evaluate(() => window.scrollY), `${name}: scrolled`).toBe(0);
  // The view is a real share of the window, not squeezed to make room.
  const view = (await page.locator('#viewport').boundingBox())!;
  const { width, height } = page.viewportSize()!;
  expect(view.width * view.height, `${name}: view area`).toBeGreaterThan(0.2 * width * height);
  // The legend clear of the view's tools (2D, Decision in 3D, Follow, Reset view), over the view or above it (compared in a narrow window).
  const overlaps = await page.evaluate(() => {
    const legend = document.querySelector('#legend')!.getBoundingClientRect();
    return [...document.querySelectorAll('#view-tools > *')]
      .map((e) => ({ text: (e as HTMLElement).innerText, box: e.getBoundingClientRect() }))
      .filter(({ box }) => box.left < legend.right && legend.left < box.right && box.top < legend.bottom && legend.top < box.bottom)
      .map(({ text }) => text);
  });
  expect(overlaps, `${name}: legend over the tools`).toEqual([]);
  await screenshot(page, `layout-${name}`);
}

describe('the view, the timeline and the reason, together', () => {
  for (const [width, height] of [
    [1400, 900],
    [1024, 768],
    [390, 844],
  ] as const) {
    it(`are on the first screen at ${width}x${height}, in trace and compare mode`, async () => {
      const p = await openPage('?algorithm=regions&from=0,0,0&to=10,7,6&step=3');
      const { page } = p;
      await page.setViewportSize({ width, height });
      await check(page, `trace-${width}x${height}`);
      // Compare mode: its table tops the inspector, so the reason has its own place.
      await page.getByTestId('mode-compare').click();
      await page.getByTestId('step-counter').filter({ hasText: /of 23$/ }).waitFor();
      await page.getByTestId('jump-input').fill('3');
      await page.getByTestId('jump-go').click();
      await check(page, `compare-${width}x${height}`);
      expect(await page.getByTestId('step-reason').innerText()).toMatch(/^regions, step 3: .*\ngreedy, step 3: /s);
      expect(p.problems()).toEqual([]);
      await p.close();
    });
  }
});

describe('the coordinate fields', () => {
  it('show ten digits whole: coordinates reach 2^30', async () => {
    const p = await openPage('?from=0,0,0&to=10,7,6');
    const { page } = p;
    await page.setViewportSize({ width: 1024, height: 768 });
    for (const [axis, value] of [
      ['x', '-1073741824'],
      ['y', '1073741824'],
      ['z', '-1073741823'],
    ] as const) {
      await page.getByTestId(`input-to-${axis}`).fill(value);
    }
    const clipped = await page.evaluate(() =>
      [...document.querySelectorAll<HTMLInputElement>('.axis input')].filter((i) => i.scrollWidth > i.clientWidth).map((i) => `${i.id} ${i.scrollWidth} > ${i.clientWidth}`),
    );
    expect(clipped).toEqual([]);
    // Each field still beside its axis name.
    for (const axis of ['x', 'y', 'z']) {
      const input = (await page.getByTestId(`input-to-${axis}`).boundingBox())!;
      const panel = (await page.locator('.inputs').boundingBox())!;
      expect(input.x + input.width).toBeLessThanOrEqual(panel.x + panel.width);
    }
    await p.close();
  });
});

describe('the decision cards', () => {
  it('stay where they are as their values change length', async () => {
    // (0,0,0)->(1000,7,6): eq. (10) gives M_1 = 2*7 - 1000 = -986, and M grows by 14 a step (eq. 8) to short values.
    const p = await openPage('?algorithm=regions&from=0,0,0&to=1000,7,6&step=1');
    const { page } = p;
    await page.getByTestId('inspector-value-M').filter({ hasText: '-986' }).waitFor();
    const cards = () => page.locator('[data-testid="inspector-decisions"] > div').evaluateAll((divs) => divs.map((d) => { const r = d.getBoundingClientRect(); return [Math.round(r.x), Math.round(r.y), Math.round(r.width)]; }));
    const before = await cards();
    await page.getByTestId('jump-input').fill('70');
    await page.getByTestId('jump-go').click();
    await page.locator('#decision-heading').filter({ hasText: 'step 70' }).waitFor();
    await expect.poll(() => page.getByTestId('inspector-value-M').innerText()).not.toBe('-986');
    expect((await page.getByTestId('inspector-value-M').innerText()).length).toBeLessThan(4);
    expect(await cards()).toEqual(before);
    await p.close();
  });

  it('hold a long value on one line and break a long name between its words', async () => {
    // arc-segments' fourth chord step: faceU = 1/6, written 0.166667 (it wrapped as 0.16666/7).
    const p = await openPage('?algorithm=arc-segments&from=20,0,0&to=-20,0,0&center=0,0,0&step=3');
    const { page } = p;
    await page.setViewportSize({ width: 1280, height: 800 });
    const faceU = page.getByTestId('inspector-value-faceU');
    await faceU.filter({ hasText: '0.166667' }).waitFor();
    const lines = (selector: string) =>
      page.locator(selector).evaluate((e) => Math.round(e.getBoundingClientRect().height / parseFloat(getComputedStyle(e).lineHeight)));
    expect(await lines('[data-testid=inspector-value-faceU]')).toBe(1);
    // circle's otherCandidate: "other" and "Candidate" on two lines (it broke as otherCandid/ate).
    await page.goto(page.url().replace(/\?.*/, '?algorithm=circle&from=5,0,0&to=0,5,0&center=0,0,0&step=2'));
    const title = page.locator('[data-testid=inspector-decisions] dt').filter({ hasText: 'otherCandidate' });
    await title.waitFor();
    expect(await title.evaluate((dt) => dt.querySelectorAll('wbr').length)).toBe(1);
    expect(await title.evaluate((dt) => (dt.lastChild as Text).data)).toBe('Candidate');
    // Each word whole: laid out in one box each.
    const boxes = await title.evaluate((dt) =>
      Array.from(dt.childNodes)
        .filter((n) => n.nodeType === Node.TEXT_NODE)
        .map((n) => {
          const range = document.createRange();
          range.selectNodeContents(n);
          return range.getClientRects().length;
        }),
    );
    expect(boxes).toEqual([1, 1]);

    // A bar's value and note whole inside its figure: the helix's step 3 keeps its
    // longest candidate, "9 (taken)", which ran past the figure's right edge.
    await page.goto(page.url().replace(/\?.*/, '?algorithm=helix&from=10,0,0&to=10,0,24&center=0,0,0&step=3'));
    const figure = page.getByTestId('decision-figure');
    await expect.poll(() => figure.locator('.bar-value').allTextContents()).toEqual(['9 (taken)', '-10']);
    const svgBox = (await figure.locator('svg.bars-figure').boundingBox())!;
    for (const value of await figure.locator('.bar-value').all()) {
      const box = (await value.boundingBox())!;
      expect(box.x + box.width).toBeLessThanOrEqual(svgBox.x + svgBox.width);
    }
    await p.close();
  });
});

describe('the algorithm picker', () => {
  it("shows the chosen algorithm's whole title, on more lines when it is long", async () => {
    const p = await openPage('?algorithm=regions&from=0,0,0&to=10,7,6');
    const { page } = p;
    const picker = page.getByTestId('algorithm');
    await page.getByTestId('step-counter').filter({ hasText: 'of 10' }).waitFor();
    await picker.selectOption('liu-float');
    await page.getByTestId('algorithm-title').filter({ hasText: "Liu's 3D Bresenham" }).waitFor();
    // "Liu's 3D Bresenham with a decimal discriminant kept to d places (liu-float)": three lines in a 270-pixel panel.
    const box = (await picker.boundingBox())!;
    const lineHeight = await picker.evaluate((e) => parseFloat(getComputedStyle(e).fontSize) * 1.25);
    expect(box.height).toBeGreaterThan(2.5 * lineHeight);
    const panel = (await page.locator('.inputs').boundingBox())!;
    expect(box.x + box.width).toBeLessThanOrEqual(panel.x + panel.width);
    await screenshot(page, 'picker-long-title', '.inputs');
    await p.close();
  });
});

/** Overlap of two boxes, as 'x y width height' of the shared part, or '' when they do not meet. */
function overlapOf(a: { x: number; y: number; width: number; height: number }, b: { x: number; y: number; width: number; height: number }): string {
  const [left, top] = [Math.max(a.x, b.x), Math.max(a.y, b.y)];
  const [right, bottom] = [Math.min(a.x + a.width, b.x + b.width), Math.min(a.y + a.height, b.y + b.height)];
  return right > left && bottom > top ? [left, top, right - left, bottom - top].map(Math.round).join(' ') : '';
}

/**
 * Where the legend, the axis names and handles of `view` (the first, or the
 * second side by side: '#viewport-b'), the view's tools and the embedded
 * page's Open in voxpath link stand (the link 0 x 0 where it is not shown).
 */
function viewBoxes(page: Page, view = '#viewport') {
  return page.evaluate((view) => {
    const box = (e: Element) => {
      const r = e.getBoundingClientRect();
      return { x: r.x, y: r.y, width: r.width, height: r.height };
    };
    return {
      legend: box(document.querySelector('#legend')!),
      names: [...document.querySelectorAll(`${view} .axis-name`)].map((e) => ({ name: e.textContent!, box: box(e) })),
      handles: [...document.querySelectorAll(`${view} .handle`)].map((e) => ({ name: `${e.textContent} handle`, box: box(e) })),
      tools: [...document.querySelectorAll('#view-tools > *')].map((e) => ({ name: (e as HTMLElement).innerText.trim(), box: box(e) })),
      link: box(document.querySelector('#open-full')!),
    };
  }, view);
}

/**
 * The axis names and handles of `view` (as viewBoxes names them) not whole inside its box: cut at its edge. Polled by
 * the tests: under load the view frames its path for a new window size a frame or more after the legend and tools
 * have moved (a CI run read x cut at 768 x 600 compared, then whole).
 */
async function cutAtViewEdge(page: Page, view = '#viewport'): Promise<string[]> {
  const { names, handles } = await viewBoxes(page, view);
  const box = (await page.locator(view).boundingBox())!;
  return [...names, ...handles].filter((label) => overlapOf(label.box, box) !== [label.box.x, label.box.y, label.box.width, label.box.height].map(Math.round).join(' ')).map(({ name }) => name);
}

/** The axis names and handles of `view` (as viewBoxes), the tools and the Open in voxpath link under the legend, a tool or the link: "z under the legend". */
async function coveredInView(page: Page, view = '#viewport'): Promise<string[]> {
  const { legend, names, handles, tools, link } = await viewBoxes(page, view);
  const openFull = { name: 'the Open in voxpath link', box: link };
  const covers = [{ name: 'the legend', box: legend }, ...tools, openFull];
  return [...names, ...handles, ...tools, openFull].flatMap((under) => covers.filter((over) => over !== under && overlapOf(over.box, under.box) !== '').map((over) => `${under.name} under ${over.name}`));
}

/**
 * A learner's points for the example line (0,0,0)->(10,7,6), in a link: they part from regions' path (at (2,1,1)),
 * so the legend shows both of their entries, the points and the first difference.
 */
const LEARNER_POINTS = encodeURIComponent('0,0,0\n1,1,1\n2,1,1\n3,2,2\n4,3,2\n5,3,3\n6,4,4\n7,5,4\n8,6,5\n9,6,5\n10,7,6\n');

/** Where the legend (and the tools after it) stands: 'viewport' over the view, 'views' above it. */
function legendPlace(page: Page): Promise<string> {
  return page.evaluate(() => document.querySelector('#legend')!.parentElement!.id);
}

describe('an embedded view in a small frame', () => {
  it('shows every playback control whole at 320x240, the buttons and the speed in one row under the scrubber', async () => {
    // The clock's longest choice (1000× slower) and the machine-time readout too.
    for (const query of ['algorithm=regions&from=0,0,0&to=10,7,6&step=5', 'mode=gcode', 'mode=gcode&slowdown=1000']) {
      const p = await openPage(`?embed=1&${query}`);
      const { page } = p;
      await page.setViewportSize({ width: 320, height: 240 });
      await page.getByTestId('step-counter').filter({ hasText: /of [1-9]/ }).waitFor();
      if (query.includes('slowdown')) await page.getByTestId('machine-time').filter({ hasText: 'the program takes' }).waitFor();
      const controls = await page.evaluate(() => {
        // A select shows its choice cut without a scrollbar (scrollWidth is its width): it
        // must be as wide as a select of the same type holding that choice alone
        // (to a pixel: that one's width is rounded up to whole pixels).
        const wholeWidth = (select: HTMLSelectElement) => {
          const probe = document.createElement('select');
          probe.append(new Option(select.selectedOptions[0]!.text));
          const style = getComputedStyle(select);
          for (const property of ['font', 'padding', 'border', 'letter-spacing', 'appearance', 'box-sizing']) probe.style.setProperty(property, style.getPropertyValue(property));
          probe.style.position = 'absolute';
          document.body.append(probe);
          const width = probe.getBoundingClientRect().width;
          probe.remove();
          return width;
        };
        return [...document.querySelectorAll<HTMLElement>('.timeline input, .timeline button, .timeline select, .timeline output')]
          .filter((e) => e.checkVisibility())
          .map((e) => {
            const box = e.getBoundingClientRect();
            return {
              name: e.id || e.dataset.testid || e.tagName,
              box: { x: box.x, y: box.y, width: box.width, height: box.height },
              cut: e.scrollWidth > e.clientWidth || (e instanceof HTMLSelectElement && box.width < wholeWidth(e) - 1),
            };
          });
      });
      expect(controls.map((c) => c.name), query).toEqual(expect.arrayContaining(['scrubber', 'step-counter', 'first', 'previous', 'play', 'next', 'last', 'speed']));
      for (const { name, box, cut } of controls) {
        const at = `${query}: ${name}`;
        expect(cut, `${at} cut`).toBe(false);
        expect([box.x >= 0, box.y >= 0, box.x + box.width <= 320.5, box.y + box.height <= 240.5], `${at} inside the frame`).toEqual([true, true, true, true]);
      }
      // Two rows: the scrubber's, then the buttons with the speed; G-code's clock
      // has a row of its own, and the machine-time readout one under it.
      const middles = controls.map(({ box }) => box.y + box.height / 2).sort((a, b) => a - b);
      const rows = middles.filter((y, i) => i === 0 || y - middles[i - 1]! > 8).length;
      expect(rows, `${query}: rows`).toBe(query.includes('slowdown') ? 4 : query.includes('gcode') ? 3 : 2);
      const middleOf = (name: string) => controls.filter((c) => c.name === name).map(({ box }) => box.y + box.height / 2)[0]!;
      expect(Math.abs(middleOf('speed') - middleOf('play')), `${query}: the speed beside the buttons`).toBeLessThan(4);
      // The view still a usable part of the frame, as keyboard.test.ts asks of it (52 px were left beside the machine-time readout).
      expect((await page.getByTestId('scene-canvas').boundingBox())!.height, `${query}: the view`).toBeGreaterThanOrEqual(70);
      await screenshot(page, `embed-320x240-${query.includes('slowdown') ? 'machine-time' : query.includes('gcode') ? 'gcode' : 'trace'}`);
      expect(p.problems()).toEqual([]);
      await p.close();
    }
  });

  it('shows both views side by side at 320x240 and in a short portrait frame, where the legend is left out', async () => {
    // The side-by-side grid kept a row for the legend above the views; with
    // the legend hidden (a frame under 300 px tall) the views took that row,
    // sized to their content, and stood 2 px tall: the frame showed no path.
    for (const size of [{ width: 320, height: 240 }, { width: 240, height: 290 }]) {
      const p = await openPage('?embed=1&mode=compare&layout=side&algorithm=regions&other=greedy&from=0,0,0&to=10,7,6&step=5');
      const { page } = p;
      await page.setViewportSize(size);
      await page.getByTestId('step-counter').filter({ hasText: 'Step 5 of 23' }).waitFor();
      await expect.poll(() => page.getByTestId('scene-canvas').count()).toBe(2);
      const views = await Promise.all(['#viewport', '#viewport-b'].map(async (v) => (await page.locator(v).boundingBox())!));
      for (const [i, view] of views.entries()) expect(view.height, `${size.width}x${size.height}: view ${i + 1}'s height`).toBeGreaterThan(40);
      await screenshot(page, `compare-side-embed-${size.width}x${size.height}`);
      expect(p.problems()).toEqual([]);
      await p.close();
    }
  });

  it('frames the picture above the Open in voxpath link in a frame under 400 px tall, the link over the view', async () => {
    // In the view's lower right corner (over the second view side by side) it covered the x axis's name in frames 320
    // to 480 px wide (560 in G-code mode, 720 side by side) and 240 to 399 tall; from 400 px tall it stands in a strip under the view.
    for (const [name, query, width, height, view] of [
      ['trace', 'algorithm=regions', 320, 240, '#viewport'],
      ['trace', 'algorithm=regions', 480, 360, '#viewport'],
      ['compare', 'mode=compare&algorithm=regions&other=greedy', 400, 399, '#viewport'],
      ['compare-side', 'mode=compare&layout=side&algorithm=regions&other=greedy', 640, 360, '#viewport-b'],
      ['gcode', 'mode=gcode', 480, 300, '#viewport'],
    ] as const) {
      const at = `${name}, ${width} x ${height}`;
      const p = await openPage(`?embed=1&${query}&from=0,0,0&to=10,7,6&step=5`);
      const { page } = p;
      await page.setViewportSize({ width, height });
      await page.getByTestId('step-counter').filter({ hasText: /^Step 5 of / }).waitFor();
      await expect.poll(() => page.locator(`${view} .axis-name`).count(), { message: `${at}: axes drawn`, timeout: 10_000 }).toBe(3);
      // Once the view has framed its path for the frame (a resize is followed a frame later).
      await expect.poll(() => coveredInView(page, view), { message: `${at}: covered`, timeout: 10_000 }).toEqual([]);
      // Still over the view: the frame gives it no strip of its own.
      const { link } = await viewBoxes(page, view);
      const viewBox = (await page.locator(view).boundingBox())!;
      expect(overlapOf(link, viewBox), `${at}: the link over the view`).not.toBe('');
      await screenshot(page, `open-full-${name}-${width}x${height}`);
      expect(p.problems()).toEqual([]);
      await p.close();
    }
  });

  it('keeps the compare legend off the first view side by side at 640x480, embedded and in the page', async () => {
    for (const query of ['?embed=1&', '?']) {
      const p = await openPage(`${query}mode=compare&layout=side&algorithm=regions&other=greedy&from=0,0,0&to=10,7,6&step=5`);
      const { page } = p;
      await page.setViewportSize({ width: 640, height: 480 });
      await page.getByTestId('step-counter').filter({ hasText: 'Step 5 of 23' }).waitFor();
      await expect.poll(() => page.getByTestId('scene-canvas').count()).toBe(2);
      const legend = page.locator('#legend');
      await legend.getByText('only greedy visits').waitFor();
      const [legendBox, left, right] = [(await legend.boundingBox())!, ...(await Promise.all((await page.getByTestId('scene-canvas').all()).map(async (c) => (await c.boundingBox())!)))];
      expect(overlapOf(legendBox, left!), `${query}: the legend over the first view`).toBe('');
      expect(overlapOf(legendBox, right!), `${query}: the legend over the second view`).toBe('');
      // Whole, inside the frame, and each of its entries in sight.
      expect([legendBox.x >= 0, legendBox.y >= 0, legendBox.x + legendBox.width <= 640.5, legendBox.y + legendBox.height <= 480.5], `${query}: legend inside`).toEqual([true, true, true, true]);
      for (const entry of await legend.locator('li:visible').all()) {
        const box = (await entry.boundingBox())!;
        expect(overlapOf(box, legendBox), `${query}: ${await entry.innerText()}`).toBe([box.x, box.y, box.width, box.height].map(Math.round).join(' '));
      }
      await screenshot(page, `compare-side-640x480${query.includes('embed') ? '-embed' : ''}`);
      if (!query.includes('embed')) {
        // Leaving side by side, the one view takes the whole stage at once,
        // before the new mode's paths are drawn (the legend moves back over
        // it only then): it stood at half the stage until then.
        const widths = await page.evaluate(() => {
          document.querySelector<HTMLButtonElement>('[data-testid=mode-trace]')!.click();
          const width = (selector: string) => Math.round(document.querySelector(selector)!.getBoundingClientRect().width);
          return { view: width('#viewport'), views: width('#views') };
        });
        expect(widths.view, 'the one view, leaving side by side').toBe(widths.views);
        await page.getByTestId('mode-compare').click();
        await expect.poll(() => page.getByTestId('scene-canvas').count()).toBe(2);
        // Overlaid, one view has both paths: the legend stands with it again, above it here (over it, it covered z), over it where it fits.
        await page.getByTestId('layout-overlay').check();
        await expect.poll(() => coveredInView(page), { timeout: 10_000 }).toEqual([]);
        await page.setViewportSize({ width: 1280, height: 800 });
        await expect.poll(() => legendPlace(page)).toBe('viewport');
      }
      expect(p.problems()).toEqual([]);
      await p.close();
    }
  });
});

describe("the inspector's point", () => {
  it('shows ten-digit coordinates whole inside the panel, broken only after a comma', async () => {
    // Step 3 of this move is (-999999997, -999999998, -999999998): held on one
    // line it ran about 100 px past the panel, its z unreadable.
    const p = await openPage('?algorithm=regions&from=-1000000000,-1000000000,-1000000000&to=-999999990,-999999993,-999999994&step=3');
    const { page } = p;
    const point = page.getByTestId('inspector-point');
    for (const [width, height] of [
      [1280, 720],
      [1920, 1080],
    ] as const) {
      await page.setViewportSize({ width, height });
      await point.filter({ hasText: '(-999999997, -999999998, -999999998)' }).waitFor();
      const laidOut = await point.evaluate((dd) => {
        const text = dd.firstChild as Text;
        const readout = dd.closest('.readout')!.getBoundingClientRect();
        const range = document.createRange();
        range.selectNodeContents(text);
        const outside = [...range.getClientRects()].filter((r) => r.left < readout.left - 0.5 || r.right > readout.right + 0.5).map((r) => `${r.left}-${r.right}`);
        // Each coordinate in one piece: a line break inside one would split its digits.
        const pieces = [...text.data.matchAll(/-?\d+/g)].map((m) => {
          range.setStart(text, m.index);
          range.setEnd(text, m.index + m[0].length);
          return range.getClientRects().length;
        });
        return { outside, pieces, readout: `${readout.left}-${readout.right}` };
      });
      expect(laidOut.outside, `${width}x${height}: lines past the readout's ${laidOut.readout}`).toEqual([]);
      expect(laidOut.pieces, `${width}x${height}: each coordinate whole`).toEqual([1, 1, 1]);
      await screenshot(page, `inspector-point-${width}x${height}`, '.inspector');
    }
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});

/** Texts drawn on a canvas, each by its inked box, and its dashed horizontal lines, in canvas pixels. */
interface Drawn {
  texts: { text: string; left: number; right: number; top: number; bottom: number }[];
  dashes: { y: number; left: number; right: number }[];
}

declare global {
  interface HTMLCanvasElement {
    drawn?: Drawn;
  }
}

/**
 * Installed before the page's scripts: each canvas keeps what was drawn on it
 * since it was last cleared whole (uPlot clears a chart so before each draw),
 * its texts' boxes as the context's transform puts them (the y axis's title
 * is drawn turned) and the heights of its dashed horizontal lines (a chart's
 * reference lines).
 */
function recordCanvasDrawing(): void {
  const proto = CanvasRenderingContext2D.prototype;
  const { clearRect, fillText, moveTo, lineTo } = proto;
  let from: DOMPoint | undefined;
  proto.clearRect = function (this: CanvasRenderingContext2D, x, y, w, h) {
    if (x <= 0 && y <= 0 && w >= this.canvas.width && h >= this.canvas.height) this.canvas.drawn = { texts: [], dashes: [] };
    clearRect.call(this, x, y, w, h);
  };
  proto.fillText = function (this: CanvasRenderingContext2D, text, x, y, maxWidth) {
    const m = this.measureText(text);
    const transform = this.getTransform();
    const corners = [
      [x - m.actualBoundingBoxLeft, y - m.actualBoundingBoxAscent],
      [x + m.actualBoundingBoxRight, y - m.actualBoundingBoxAscent],
      [x - m.actualBoundingBoxLeft, y + m.actualBoundingBoxDescent],
      [x + m.actualBoundingBoxRight, y + m.actualBoundingBoxDescent],
    ].map(([cx, cy]) => transform.transformPoint(new DOMPoint(cx, cy)));
    const xs = corners.map((c) => c.x);
    const ys = corners.map((c) => c.y);
    this.canvas.drawn?.texts.push({ text, left: Math.min(...xs), right: Math.max(...xs), top: Math.min(...ys), bottom: Math.max(...ys) });
    fillText.call(this, text, x, y, maxWidth);
  };
  proto.moveTo = function (this: CanvasRenderingContext2D, x, y) {
    from = this.getTransform().transformPoint(new DOMPoint(x, y));
    moveTo.call(this, x, y);
  };
  proto.lineTo = function (this: CanvasRenderingContext2D, x, y) {
    const to = this.getTransform().transformPoint(new DOMPoint(x, y));
    if (from && this.getLineDash().length > 0 && Math.abs(to.y - from.y) < 0.5) this.canvas.drawn?.dashes.push({ y: to.y, left: Math.min(from.x, to.x), right: Math.max(from.x, to.x) });
    from = to;
    lineTo.call(this, x, y);
  };
}

describe('the charts', () => {
  it("show every label whole, apart from the others and off the reference lines", async () => {
    // Each move showed one fault: "largest 0.6578" on the bound's dashed line,
    // the bound's label on the largest's, and the y axis's title against its
    // "1,000"; ticks of ten digits cut to "000,000,000" at the canvas's edge;
    // -5,000 to 6,000 labelled at 0 alone.
    for (const [name, move] of [
      ['near-bound', 'from=0,0,0&to=1000,7,6'],
      ['ten-digits', 'from=1000000000,-1000000000,5&to=1000000020,-999999990,12'],
      ['thousands', 'from=-5000,-5000,0&to=5000,2000,6000'],
    ] as const) {
      const p = await openPage(`?algorithm=regions&${move}`, { initScript: recordCanvasDrawing });
      const { page } = p;
      // Both charts drawn: they come once the worker sends their rows.
      await page.waitForFunction(() => {
        const canvases = [...document.querySelectorAll<HTMLCanvasElement>('#charts canvas')];
        return canvases.length === 2 && canvases.every((c) => (c.drawn?.texts.length ?? 0) > 0);
      });
      const charts = await page.locator('#charts canvas').evaluateAll((canvases) =>
        (canvases as HTMLCanvasElement[]).map((c) => ({ width: c.width, height: c.height, drawn: c.drawn! })),
      );
      for (const [i, { width, height, drawn }] of charts.entries()) {
        const at = `${name}, chart ${i + 1}`;
        const texts = drawn.texts.filter((t) => t.text.trim() !== '');
        const cut = texts.filter((t) => t.left < -0.5 || t.top < -0.5 || t.right > width + 0.5 || t.bottom > height + 0.5).map((t) => t.text);
        expect(cut, `${at}: cut at the canvas's edge`).toEqual([]);
        const meeting = texts.flatMap((a, j) =>
          texts.slice(j + 1).filter((b) => a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom).map((b) => `${a.text} / ${b.text}`),
        );
        expect(meeting, `${at}: labels on each other`).toEqual([]);
        // A reference line is 1.5 px wide.
        const crossed = texts.filter((t) => drawn.dashes.some((d) => d.y + 0.75 > t.top && d.y - 0.75 < t.bottom && d.left < t.right && t.left < d.right)).map((t) => t.text);
        expect(crossed, `${at}: labels on a reference line`).toEqual([]);
        // Two labelled ticks at least on the y axis: numbers above the x axis's row of them.
        const numbers = texts.filter((t) => /^-?[\d,.]+$/.test(t.text));
        const xRow = Math.max(...numbers.map((t) => t.top));
        expect(numbers.filter((t) => t.bottom < xRow).length, `${at}: y ticks labelled`).toBeGreaterThanOrEqual(2);
      }
      expect(charts[1]!.drawn.texts.map((t) => t.text)).toEqual(expect.arrayContaining([expect.stringMatching(/^largest /), expect.stringMatching(/^bound /)]));
      await screenshot(page, `charts-${name}`, '#charts');
      expect(p.problems()).toEqual([]);
      await p.close();
    }
  });
});

describe('the view tools side by side', () => {
  it("stand in one row above both views, off the ends' handles, with both reasons in sight", async () => {
    // Stacked in the first view's corner, they ran down it and Reset view stood
    // on the E handle; in the embedded frame the Embed dialog sizes (640 x 480)
    // the second algorithm's reason was below the fold of the reason box.
    for (const [query, width, height] of [
      ['&embed=1', 640, 480],
      ['', 1280, 720],
    ] as const) {
      const p = await openPage(`?mode=compare&algorithm=regions&other=bresenham3d&layout=side&from=0,0,0&to=10,7,6&step=5${query}`);
      const { page } = p;
      await page.setViewportSize({ width, height });
      const at = `${width}x${height}`;
      await page.getByTestId('step-counter').filter({ hasText: 'Step 5 of 10' }).waitFor();
      await expect.poll(() => page.getByTestId('scene-canvas').count()).toBe(2);
      await expect.poll(() => page.locator('.handle').count()).toBeGreaterThanOrEqual(2);
      const boxes = async (selector: string) =>
        Promise.all((await page.locator(selector).all()).map(async (e) => ({ text: await e.innerText(), box: (await e.boundingBox())! })));
      const tools = await boxes('.view-tools > *');
      expect(tools.map((t) => t.text.trim())).toEqual(['2D', 'Decision in 3D', 'Follow', 'Reset view']);
      const views = await boxes('#viewport, #viewport-b');
      const handles = await boxes('.handle');
      for (const tool of tools) {
        for (const handle of handles) expect(overlapOf(tool.box, handle.box), `${at}: ${tool.text} over the ${handle.text} handle`).toBe('');
        for (const [i, view] of views.entries()) expect(overlapOf(tool.box, view.box), `${at}: ${tool.text} over view ${i + 1}`).toBe('');
        const { x, y, width: w, height: h } = tool.box;
        expect([x >= 0, y >= 0, x + w <= width + 0.5, y + h <= height + 0.5], `${at}: ${tool.text} inside the window`).toEqual([true, true, true, true]);
      }
      const middles = tools.map(({ box }) => box.y + box.height / 2);
      expect(Math.max(...middles) - Math.min(...middles), `${at}: the tools in one row`).toBeLessThan(4);
      // Each algorithm's reason whole inside the reason box, not scrolled to.
      const reasonBox = page.getByTestId('step-reason');
      await reasonBox.filter({ hasText: 'bresenham3d, step 5' }).waitFor();
      const inner = await reasonBox.evaluate((e) => {
        const r = e.getBoundingClientRect();
        return { top: r.top + e.clientTop, bottom: r.top + e.clientTop + e.clientHeight };
      });
      for (const reason of await boxes('[data-testid=step-reason] .reason')) {
        expect([reason.box.y >= inner.top - 0.5, reason.box.y + reason.box.height <= inner.bottom + 0.5], `${at}: "${reason.text.slice(0, 20)}" in sight`).toEqual([true, true]);
      }
      await screenshot(page, `compare-side-tools-${at}${query ? '-embed' : ''}`);
      expect(p.problems()).toEqual([]);
      await p.close();
    }
  });
});

describe('the header', () => {
  it('keeps one row in every mode at 1280 px, showing the tagline whole or not at all', async () => {
    // G-code mode adds the VCD button: at 1280 px the header wrapped to two
    // rows (46 to 78 px) and pushed the page down; trace mode did from 1,181 to 1,250 px.
    const p = await openPage('?algorithm=regions&from=0,0,0&to=10,7,6');
    const { page } = p;
    for (const width of [1200, 1280, 1366]) {
      await page.setViewportSize({ width, height: 720 });
      for (const mode of ['trace', 'compare', 'gcode', 'experiment']) {
        await page.getByTestId(`mode-${mode}`).click();
        await expect.poll(() => page.evaluate(() => document.body.dataset.mode)).toBe(mode);
        const at = `${width} px, ${mode}`;
        const header = await page.evaluate(() => {
          const masthead = document.querySelector('.masthead')!;
          const items = [...masthead.querySelectorAll<HTMLElement>('h1, button')].filter((e) => e.checkVisibility());
          const middles = items.map((e) => {
            const box = e.getBoundingClientRect();
            return box.top + box.height / 2;
          });
          // The tagline's text, against the part of the tagline shown.
          const tagline = masthead.querySelector('.tagline')!.getBoundingClientRect();
          const range = document.createRange();
          range.selectNodeContents(masthead.querySelector('.tagline')!);
          const text = range.getBoundingClientRect();
          const inside = text.left >= tagline.left - 0.5 && text.right <= tagline.right + 0.5 && text.top >= tagline.top - 0.5 && text.bottom <= tagline.bottom + 0.5;
          const outside = text.top >= tagline.bottom - 0.5 || text.left >= tagline.right - 0.5;
          return {
            height: masthead.getBoundingClientRect().height,
            spread: Math.max(...middles) - Math.min(...middles),
            tagline: inside ? 'whole' : outside ? 'hidden' : 'cut',
          };
        });
        expect(header.spread, `${at}: the title and buttons in one row`).toBeLessThan(6);
        expect(header.height, `${at}: header height`).toBeLessThan(50);
        expect(header.tagline, `${at}: the tagline`).not.toBe('cut');
        if (width === 1366) expect(header.tagline, `${at}: the tagline, with room for it`).toBe('whole');
        if (width === 1280 && mode === 'gcode') await screenshot(page, 'header-1280-gcode', { x: 0, y: 0, width, height: 80 });
      }
    }
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});

/**
 * How wide the document is against the window, px, and what runs past the window's right edge (each as
 * 'id or tag.class right-edge'), leaving out what a box that scrolls or clips sideways keeps inside it.
 */
async function widthAndOverflow(page: Page): Promise<{ documentPx: number; windowPx: number; pastRightEdge: string[] }> {
  return page.evaluate(() => {
    const windowPx = document.documentElement.clientWidth;
    const clippedInside = (e: Element) => {
      for (let box = e.parentElement; box && box !== document.body; box = box.parentElement) {
        if (getComputedStyle(box).overflowX !== 'visible' && box.getBoundingClientRect().right <= windowPx + 0.5) return true;
      }
      return false;
    };
    const pastRightEdge = [...document.body.querySelectorAll('*')]
      .filter((e) => e.getBoundingClientRect().right > windowPx + 0.5 && e.checkVisibility() && !clippedInside(e))
      .map((e) => `${e.id || `${e.tagName.toLowerCase()}.${[...e.classList].join('.')}`} ${Math.round(e.getBoundingClientRect().right)}`);
    return { documentPx: document.documentElement.scrollWidth, windowPx, pastRightEdge };
  });
}

describe('a narrow window', () => {
  it("fits G-code mode's page at 240 to 360 px in machine time: the clock's choice on two lines, its readout wrapped, the moves' columns in sight", async () => {
    // The clock's select was as wide as its longest choice, 'machine time, 1000× slower' (251 px):
    // under 272 px the page scrolled sideways. So did the charts' 'Time shown' (237 px) and the moves'
    // table (230 px in a panel of 198 at 240 px), and the machine-time readout, held on one line
    // (350 px), up to 360 px.
    const program = encodeURIComponent('G21 G90\nG1 X1 F60\nG4 P2\n');
    const p = await openPage(`?mode=gcode&stepsPerMm=1&gcode=${program}`);
    const { page } = p;
    await page.setViewportSize({ width: 240, height: 700 });
    await page.getByTestId('step-counter').filter({ hasText: /of 1$/ }).waitFor();
    // Timed: machine time chosen, as a learner picks it, the readout giving the program's time.
    const clock = page.getByTestId('slowdown');
    await clock.selectOption({ label: 'machine time, 1000× slower' });
    await page.getByTestId('machine-time').filter({ hasText: 'the program takes 3.100 s' }).waitFor({ timeout: 10_000 });
    await page.getByTestId('moves-table').waitFor();
    for (const width of [240, 272, 320, 360]) {
      await page.setViewportSize({ width, height: 700 });
      const at = `${width} px`;
      await expect.poll(async () => (await widthAndOverflow(page)).pastRightEdge, { message: at, timeout: 10_000 }).toEqual([]);
      const { documentPx, windowPx } = await widthAndOverflow(page);
      expect(documentPx, `${at}: the document's width`).toBeLessThanOrEqual(windowPx);
      for (const testid of ['slowdown', 'machine-time', 'motion-window']) {
        const box = (await page.getByTestId(testid).boundingBox())!;
        expect([box.x >= 0, box.x + box.width <= width + 0.5], `${at}: ${testid} inside the window`).toEqual([true, true]);
      }
      // Usable: the clock shown, a real share of the playback's width.
      expect(await clock.isVisible(), at).toBe(true);
      expect((await clock.boundingBox())!.width, `${at}: the clock's width`).toBeGreaterThan(150);
      // The moves' six columns in the panel, not scrolled out of sight in their box.
      const moves = await page.getByTestId('moves-table').evaluate((table) => [table.parentElement!.scrollWidth, table.parentElement!.clientWidth]);
      expect(moves[0], `${at}: the moves' table`).toBeLessThanOrEqual(moves[1]!);
    }
    // At 240 px, where the browser lets a select be styled, the chosen clock in full on two lines, not cut to 'machine time, 100…'.
    await page.setViewportSize({ width: 240, height: 700 });
    if (await page.evaluate(() => CSS.supports('appearance', 'base-select'))) {
      const lineHeightPx = await clock.evaluate((e) => parseFloat(getComputedStyle(e).fontSize) * 1.25);
      await expect.poll(async () => (await clock.boundingBox())!.height).toBeGreaterThan(1.8 * lineHeightPx);
    }
    await page.locator('.timeline').scrollIntoViewIfNeeded();
    await screenshot(page, 'gcode-machine-time-240', '.timeline');
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it("keeps the legend and the view's tools off its axis names and handles at 240 to 360 px, compared or with a learner's points (over the view, squeezed beside the tools, the legend covered the z axis's name)", async () => {
    // Compared, its seven entries, in a column 85 px wide beside the stacked tools, stood 196 px tall over a view of
    // 364 at 240 px, and 125 to 161 px at 360: the view frames its picture below at most 30 % of its height.
    // A learner's points checked add two entries of three lines each to trace mode's four: 224 px at 240, 139 to 153 at 272 and 360.
    for (const [name, query] of [
      ['compare-legend-regions', 'mode=compare&algorithm=regions&other=greedy'],
      ['compare-legend-liu-float', 'mode=compare&algorithm=liu-float&other=bresenham3d'],
      ['trace-legend-points', `mode=trace&algorithm=regions&points=${LEARNER_POINTS}`],
    ]) {
      const p = await openPage(`?${query}&from=0,0,0&to=10,7,6&step=5`);
      const { page } = p;
      await page.setViewportSize({ width: 240, height: 700 });
      await page.getByTestId('step-counter').filter({ hasText: /^Step 5 of / }).waitFor();
      // Both entries of the points: they part from regions' path.
      if (name.startsWith('trace')) await page.locator('#legend-difference').waitFor({ timeout: 10_000 });
      for (const width of [240, 272, 320, 360]) {
        await page.setViewportSize({ width, height: 700 });
        const at = `${name}, ${width} px`;
        // Once the view has framed its path anew for the window's width (a resize is followed a frame later).
        await expect.poll(() => coveredInView(page), { message: `${at}: covered`, timeout: 10_000 }).toEqual([]);
        const { legend, names, handles } = await viewBoxes(page);
        expect(names.map(({ name }) => name).sort(), at).toEqual(['x', 'y', 'z']);
        expect(handles.map(({ name }) => name).sort(), at).toEqual(['E handle', 'S handle']);
        expect([legend.x >= 0, legend.x + legend.width <= width + 0.5], `${at}: the legend inside the window`).toEqual([true, true]);
        const { documentPx, windowPx } = await widthAndOverflow(page);
        expect(documentPx, `${at}: the document's width`).toBeLessThanOrEqual(windowPx);
        await page.locator('#views').scrollIntoViewIfNeeded();
        await screenshot(page, `${name}-${width}`, '#views');
      }
      // In a wide window it goes back over the view, where it takes no more of it than the picture is framed below.
      await page.setViewportSize({ width: 1280, height: 800 });
      await expect.poll(() => legendPlace(page)).toBe('viewport');
      if (name.startsWith('trace')) {
        // Without points, trace mode's four short entries stay over a view of 439 px even at 240 px wide (with the stacked tools, over 364 px they do not).
        await page.setViewportSize({ width: 240, height: 844 });
        await expect.poll(() => legendPlace(page)).toBe('views');
        await page.getByTestId('learner-points').fill('');
        await expect.poll(() => legendPlace(page), { timeout: 10_000 }).toBe('viewport');
      }
      expect(p.problems()).toEqual([]);
      await p.close();
    }
  });

  it("folds the legend to one line in a short window, where whole it covered the axes' names, and keeps it folded for a new visit", async () => {
    // Compared, whole, it covered z at 640 x 360 and y and z at 800 x 450 (a view of 148 px); trace mode's with a learner's points, z at both.
    for (const [width, height] of [
      [640, 360],
      [800, 450],
    ]) {
      for (const query of ['mode=compare&algorithm=liu-float&other=bresenham3d', `mode=trace&algorithm=regions&points=${LEARNER_POINTS}`]) {
        const mode = query.startsWith('mode=compare') ? 'compare' : 'trace';
        const at = `${mode}, ${width} x ${height}`;
        const p = await openPage(`?${query}&from=0,0,0&to=10,7,6&step=5`);
        const { page } = p;
        await page.setViewportSize({ width, height });
        await page.getByTestId('step-counter').filter({ hasText: /^Step 5 of / }).waitFor();
        const fold = page.getByTestId('legend-fold');
        expect([await fold.innerText(), await fold.getAttribute('aria-expanded')], at).toEqual(['▴', 'true']);
        await fold.click();
        await expect.poll(() => coveredInView(page), { message: `${at}: covered`, timeout: 10_000 }).toEqual([]);
        // One line: its button alone.
        const { legend } = await viewBoxes(page);
        expect(legend.height, `${at}: the folded legend's height`).toBeLessThan(40);
        await screenshot(page, `legend-folded-${mode}-${width}x${height}`, '#views');
        // Kept as the other view settings are: in the link, and for a visit without one (storage).
        await page.waitForURL(/legend=folded/, { timeout: 10_000 });
        const url = new URL(page.url());
        await page.goto(url.origin + url.pathname);
        await page.getByTestId('step-counter').filter({ hasText: /^Step 5 of / }).waitFor();
        expect([await fold.innerText(), await fold.getAttribute('aria-expanded')], at).toEqual(['Legend ▾', 'false']);
        await expect.poll(() => coveredInView(page), { message: `${at}: covered at the new visit`, timeout: 10_000 }).toEqual([]);
        // And shown whole again.
        await fold.click();
        await expect.poll(() => page.locator('#legend li:not(.legend-fold)').first().isVisible()).toBe(true);
        await page.waitForURL((url) => !url.searchParams.has('legend'), { timeout: 10_000 });
        expect(p.problems()).toEqual([]);
        await p.close();
      }
    }
  });

  it('gives the view a usable height in a short landscape window (a phone turned sideways), one column, the page scrolling', async () => {
    // Beside the panels the view shared the window's height with the header, the playback and (compared) the
    // two reasons: compared, it stood 110 px tall at 915 x 412, the tools over z and the E handle, 30 px at
    // 736 x 414 and 88 at 844 x 390, under the legend. The one-column layout gives it 260 px.
    for (const [width, height] of [
      [915, 412],
      [736, 414],
      [844, 390],
    ] as const) {
      for (const mode of ['trace', 'compare']) {
        const at = `${mode}, ${width} x ${height}`;
        const p = await openPage(`?mode=${mode}&algorithm=regions&other=greedy&from=0,0,0&to=10,7,6&step=5`);
        const { page } = p;
        await page.setViewportSize({ width, height });
        await page.getByTestId('step-counter').filter({ hasText: /^Step 5 of / }).waitFor();
        const view = (await page.locator('#viewport').boundingBox())!;
        expect(view.height, `${at}: the view's height`).toBeGreaterThanOrEqual(200);
        expect([view.x >= 0, view.y >= 0, view.x + view.width <= width + 0.5, view.y + view.height <= height + 0.5], `${at}: the view on the first screen`).toEqual([true, true, true, true]);
        // Once the view has framed its path for the window (a resize is followed a frame later).
        await expect.poll(() => coveredInView(page), { message: `${at}: covered`, timeout: 10_000 }).toEqual([]);
        const { names, handles } = await viewBoxes(page);
        expect(names.map(({ name }) => name).sort(), at).toEqual(['x', 'y', 'z']);
        expect(handles.map(({ name }) => name).sort(), at).toEqual(['E handle', 'S handle']);
        // The inspector is below, not beside the view: the step's reason is told under the playback, in trace mode too.
        const reason = (await page.getByTestId('step-reason').boundingBox())!;
        expect([reason.width, reason.height].map((px) => px > 20), `${at}: the step's reason shown`).toEqual([true, true]);
        const { documentPx, windowPx } = await widthAndOverflow(page);
        expect(documentPx, `${at}: the document's width`).toBeLessThanOrEqual(windowPx);
        await screenshot(page, `short-${mode}-${width}x${height}`);
        expect(p.problems()).toEqual([]);
        await p.close();
      }
    }
  });

  it("keeps a long path's step counter inside a window of 240 px, under the scrubber at every step", async () => {
    // 'Step 999,999 of 1,000,000', held on one line beside the scrubber, ran 17 px past the window.
    const long = await openPage('?algorithm=regions&from=0,0,0&to=1000000,3,2&step=999999');
    await long.page.setViewportSize({ width: 240, height: 700 });
    await long.page.getByTestId('step-counter').filter({ hasText: 'Step 999,999 of 1,000,000' }).waitFor({ timeout: 30_000 });
    await expect.poll(async () => (await widthAndOverflow(long.page)).pastRightEdge, { timeout: 10_000 }).toEqual([]);
    const { documentPx, windowPx } = await widthAndOverflow(long.page);
    expect(documentPx).toBeLessThanOrEqual(windowPx);
    await long.page.locator('.timeline').scrollIntoViewIfNeeded();
    await screenshot(long.page, 'step-counter-long-240', '.timeline');
    expect(long.problems()).toEqual([]);
    await long.close();

    // The default program's 'Step 6,400 of 6,400' left the scrubber beside it 18 px; the counter stands
    // under it from the first step ('Step 0 of 6,400' fits beside it), not moving there midway.
    const p = await openPage('?mode=gcode');
    const { page } = p;
    await page.setViewportSize({ width: 240, height: 700 });
    await page.getByTestId('step-counter').filter({ hasText: 'Step 0 of 6,400' }).waitFor();
    // Where the counter and the scrubber stand in the playback (the page may scroll).
    const placed = () =>
      page.evaluate(() => {
        const [playback, c, t] = ['.timeline', '#step-counter', '.scrub-track'].map((s) => document.querySelector(s)!.getBoundingClientRect());
        return { counterTop: Math.round(c!.top - playback!.top), scrubberTop: Math.round(t!.top - playback!.top), scrubberWidth: Math.round(t!.width) };
      });
    const first = await placed();
    expect(first.counterTop).toBeGreaterThan(first.scrubberTop);
    expect(first.scrubberWidth).toBeGreaterThan(150);
    await jumpTo(page, 6400);
    expect(await placed()).toEqual(first);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it("scrolls a program's moves sideways in their own box where their columns need more than the panel, not the page", async () => {
    // Coordinates of five and six characters: the table needs 233 px, the panel has 198 at 240 px.
    const program = encodeURIComponent('G21 G90\nG1 X123.456 Y-78.9 Z10 F600\nG1 X0 Y0 Z0\n');
    const p = await openPage(`?mode=gcode&stepsPerMm=10&gcode=${program}`);
    const { page } = p;
    await page.setViewportSize({ width: 240, height: 700 });
    await page.getByTestId('moves-table').waitFor({ timeout: 10_000 });
    await expect.poll(async () => (await widthAndOverflow(page)).pastRightEdge, { timeout: 10_000 }).toEqual([]);
    const { documentPx, windowPx } = await widthAndOverflow(page);
    expect(documentPx).toBeLessThanOrEqual(windowPx);
    // Its box scrolls: the last column can be brought into the window.
    const box = await page.getByTestId('moves-table').evaluate((table) => {
      const scroller = table.parentElement!;
      scroller.scrollLeft = scroller.scrollWidth;
      const last = table.querySelector('th:last-child')!.getBoundingClientRect();
      return { scrolls: scroller.scrollWidth > scroller.clientWidth, lastRight: last.right, windowPx: document.documentElement.clientWidth };
    });
    expect(box.scrolls).toBe(true);
    expect(box.lastRight).toBeLessThanOrEqual(box.windowPx);
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});

describe('two views side by side', () => {
  it('stand across the room they share where it is wide enough, one above the other where it is narrow, the legend saying where the second is', async () => {
    // They stood one above the other in any window taller than wide: at 480 x 541 two views of 462 x 94 px, z cut
    // off at their edge, in a room of about 470 x 190 px, where across it each is about 230 x 190.
    const p = await openPage('?mode=compare&layout=side&algorithm=regions&other=greedy&from=0,0,0&to=10,7,6&step=5');
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: 'Step 5 of 23' }).waitFor();
    await expect.poll(() => page.getByTestId('scene-canvas').count()).toBe(2);
    const second = page.locator('#legend-second-name');
    for (const [width, height, across] of [
      [480, 541, true],
      [540, 600, true],
      [1280, 720, true],
      [800, 900, false],
    ] as const) {
      const at = `${width} x ${height}`;
      await page.setViewportSize({ width, height });
      await expect.poll(() => second.innerText(), { message: `${at}: the second view named`, timeout: 10_000 }).toBe(across ? 'greedy (right view)' : 'greedy (lower view)');
      const [first, other] = await Promise.all(['#viewport', '#viewport-b'].map(async (v) => (await page.locator(v).boundingBox())!));
      if (across) {
        expect([other!.x >= first!.x + first!.width - 1, Math.abs(other!.y - first!.y) < 1], `${at}: the second view to the right`).toEqual([true, true]);
      } else {
        expect([other!.y >= first!.y + first!.height - 1, Math.abs(other!.x - first!.x) < 1], `${at}: the second view below`).toEqual([true, true]);
      }
      // Each view's axis names and handles whole inside it, clear of the legend and the tools.
      for (const view of ['#viewport', '#viewport-b']) {
        await expect.poll(() => coveredInView(page, view), { message: `${at}: ${view} covered`, timeout: 10_000 }).toEqual([]);
        const { names } = await viewBoxes(page, view);
        expect(names.map(({ name }) => name).sort(), `${at}: ${view}`).toEqual(['x', 'y', 'z']);
        await expect.poll(() => cutAtViewEdge(page, view), { message: `${at}: cut at ${view}'s edge`, timeout: 10_000 }).toEqual([]);
      }
      await screenshot(page, `compare-side-${width}x${height}`);
    }
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});

describe("the legend and the view's tools on a short view", () => {
  it('stand above the view where over it they would take more of it than the picture leaves them, and over it where they fit', async () => {
    // Over the view, the picture is framed below them in at most 70 % of its height: taller, they covered it. Compared,
    // beside the panels, the legend (85 to 125 px) covered y, z and the S and E handles at 721 x 541 (a view of 157 px), z
    // and E at 768 x 600 and z at 900 x 600 (216 and 298 px); trace mode's tools, stacked, put Reset view on the E handle at
    // 721 x 541; with a learner's points, the legend covered z in one column at 736 x 414.
    for (const [name, query, width, height] of [
      ['compare', 'mode=compare&algorithm=regions&other=greedy', 721, 541],
      ['compare', 'mode=compare&algorithm=regions&other=greedy', 768, 600],
      ['compare', 'mode=compare&algorithm=liu-float&other=bresenham3d', 900, 600],
      ['trace', 'mode=trace&algorithm=regions', 721, 541],
      ['trace-points', `mode=trace&algorithm=regions&points=${LEARNER_POINTS}`, 736, 414],
    ] as const) {
      const at = `${name}, ${width} x ${height}`;
      const p = await openPage(`?${query}&from=0,0,0&to=10,7,6&step=5`);
      const { page } = p;
      await page.setViewportSize({ width, height });
      await page.getByTestId('step-counter').filter({ hasText: /^Step 5 of / }).waitFor();
      if (name === 'trace-points') await page.locator('#legend-difference').waitFor({ timeout: 10_000 });
      // Once the view has framed its path for the window (a resize is followed a frame later).
      await expect.poll(() => coveredInView(page), { message: `${at}: covered`, timeout: 10_000 }).toEqual([]);
      expect(await legendPlace(page), at).toBe('views');
      // Each axis name and handle whole in the view: above it, the legend and the tools left the compared view at
      // 721 x 541 51 px, z and E cut off at its edge, until the reasons under the playback gave up lines for it.
      const { names, handles } = await viewBoxes(page);
      expect(names.map(({ name }) => name).sort(), at).toEqual(['x', 'y', 'z']);
      expect(handles.map(({ name }) => name).sort(), at).toEqual(['E handle', 'S handle']);
      await expect.poll(() => cutAtViewEdge(page), { message: `${at}: cut at the view's edge`, timeout: 10_000 }).toEqual([]);
      await screenshot(page, `short-view-${name}-${width}x${height}`);
      // Where the view has room for them, they stand over it again.
      await page.setViewportSize({ width: 1280, height: 800 });
      await expect.poll(() => legendPlace(page), { message: `${at}, then 1280 x 800`, timeout: 10_000 }).toBe('viewport');
      await expect.poll(() => coveredInView(page), { message: `${at}, then 1280 x 800: covered`, timeout: 10_000 }).toEqual([]);
      expect(p.problems()).toEqual([]);
      await p.close();
    }
  });
});
