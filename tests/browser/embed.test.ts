// The page in a course author's material (issue 16, items 11 and 12), in
// headless Chromium: embedded, the view fills its frame with the current
// step's reason under the playback and a link to the same state in the full
// page; in the full page, the Embed button gives the <iframe> of the state
// on screen at the page's real address. The reason expected at step 5 of
// Wang et al.'s example (0,0,0)->(10,7,6) is eq. (8)'s M_5 = 0, a tie
// (region g), with N_5 = 10.
import type { PNG } from 'pngjs';
import { afterAll, describe, expect, it } from 'vitest';
import { canvasPng, closeAll, openPage, screenshot, siteUrl } from './harness.js';

afterAll(closeAll);

const EXAMPLE = 'algorithm=regions&from=0,0,0&to=10,7,6&step=5';

/** The box around the canvas pixels unlike its first (background) pixel. */
function inkBox(png: PNG): { left: number; top: number; right: number; bottom: number } {
  const bg = [png.data[0]!, png.data[1]!, png.data[2]!];
  const box = { left: png.width, top: png.height, right: -1, bottom: -1 };
  for (let y = 0; y < png.height; y++) {
    for (let x = 0; x < png.width; x++) {
      const i = (y * png.width + x) * 4;
      if (bg.every((v, c) => Math.abs(png.data[i + c]! - v) <= 24)) continue;
      box.left = Math.min(box.left, x);
      box.right = Math.max(box.right, x);
      box.top = Math.min(box.top, y);
      box.bottom = Math.max(box.bottom, y);
    }
  }
  return box;
}

describe('embedded', () => {
  it("shows the step's reason under the playback, links to the same state, and fills its frame", async () => {
    const p = await openPage(`?embed=1&${EXAMPLE}`);
    const { page } = p;
    await page.setViewportSize({ width: 640, height: 480 });
    await page.getByTestId('step-counter').filter({ hasText: 'Step 5 of 10' }).waitFor();
    const reason = page.getByTestId('step-reason');
    await reason.filter({ hasText: 'Step 5:' }).waitFor();
    expect(await reason.innerText()).toMatch(/^Step 5: x is the active axis; M = 0 and N = 10 > 0, so the line crosses segment g/);
    const timeline = (await page.locator('.timeline').boundingBox())!;
    const under = (await reason.boundingBox())!;
    expect(under.y).toBeGreaterThanOrEqual(timeline.y + timeline.height - 1);
    expect(under.y + under.height).toBeLessThanOrEqual(480);

    // The link: the full page, same state.
    const open = page.getByTestId('open-full');
    expect(await open.isVisible()).toBe(true);
    const link = new URL((await open.getAttribute('href'))!);
    const here = new URL(page.url());
    expect(link.origin + link.pathname).toBe(here.origin + here.pathname);
    expect(link.searchParams.has('embed')).toBe(false);
    expect(Object.fromEntries(['algorithm', 'from', 'to', 'step'].map((k) => [k, link.searchParams.get(k)]))).toEqual({ algorithm: 'regions', from: '0,0,0', to: '10,7,6', step: '5' });
    expect(await open.getAttribute('target')).toBe('_blank');
    await page.getByTestId('next').click();
    await expect.poll(async () => new URL((await open.getAttribute('href'))!).searchParams.get('step')).toBe('6');
    await reason.filter({ hasText: 'Step 6:' }).waitFor();

    // Framed to fill what the legend and the tools leave of the view.
    await page.getByTestId('reset-view').click();
    await page.waitForTimeout(300);
    const png = await canvasPng(page);
    const ink = inkBox(png);
    const scale = png.width / (await page.locator('#viewport').boundingBox())!.width;
    const overlays = await page.evaluate(() => Math.max(...[...document.querySelectorAll('#viewport > .legend, #viewport > .view-tools')].map((e) => e.getBoundingClientRect().bottom - document.querySelector('#viewport')!.getBoundingClientRect().top)));
    const freeTop = overlays * scale;
    expect(ink.top, 'the picture starts below the legend and the tools').toBeGreaterThanOrEqual(freeTop - 2);
    // The labels and handles are not in the canvas: the room kept for them is the rest.
    const fill = Math.max((ink.right - ink.left) / png.width, (ink.bottom - ink.top) / (png.height - freeTop));
    expect(fill, 'the picture fills the free part of the view across or down').toBeGreaterThan(0.7);
    expect(Math.abs((ink.left + ink.right) / 2 / png.width - 0.5), 'centered across').toBeLessThan(0.08);
    await screenshot(page, 'readme-embed');
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it("shows its link's move and the sample program, none of the reader's own saved points or program", async () => {
    // The reader's own visit: points checked in trace mode, a program of their own.
    const p = await openPage('?from=0,0,0&to=10,7,6');
    const { page, context } = p;
    await page.getByTestId('step-counter').filter({ hasText: /of 10$/ }).waitFor();
    await page.getByTestId('check-points').locator('summary').click();
    await page.getByTestId('learner-points').fill('0,0,0\n1,1,1\n');
    await page.getByTestId('check-verdict').waitFor();
    // The program of their own by a link of theirs, which the page keeps in storage as it runs it.
    await page.goto(`${siteUrl()}?mode=gcode&gcode=${encodeURIComponent('G21 G90\nG1 X1 Y0.5 F100\n')}`);
    await page.getByTestId('step-counter').filter({ hasText: /of 80$/ }).waitFor();
    await page.waitForTimeout(600);
    // Read as the page reads them: a part of which only the program or the points were written encodes them as URLSearchParams does ('+', %2C).
    const saved = await page.evaluate(() => JSON.parse(localStorage.getItem('voxpath.state') ?? '{}') as { trace?: string; gcode?: string });
    expect([new URLSearchParams(saved.gcode).get('gcode'), new URLSearchParams(saved.trace).get('points')]).toEqual(['G21 G90\nG1 X1 Y0.5 F100\n', '0,0,0\n1,1,1\n']);

    // A course page's frames, in the same browser: the circle alone, and the sample program.
    const frame = await context.newPage();
    await frame.goto(`${siteUrl()}?embed=1&algorithm=circle&from=5,0,0&to=0,5,0&center=0,0,0&dir=ccw&plane=xy&step=3`);
    await frame.getByTestId('step-counter').filter({ hasText: /^Step 3 of / }).waitFor();
    await frame.waitForTimeout(600);
    expect(await frame.getByTestId('check-verdict').count()).toBe(0);
    expect(new URL(frame.url()).searchParams.has('points')).toBe(false);
    expect(new URL((await frame.getByTestId('open-full').getAttribute('href'))!).searchParams.has('points')).toBe(false);
    await frame.goto(`${siteUrl()}?embed=1&mode=gcode`);
    await frame.getByTestId('step-counter').filter({ hasText: /of 6,400$/ }).waitFor();
    expect(new URL(frame.url()).searchParams.get('gcode') ?? '').not.toContain('G1 X1 Y0.5');

    // And the reader's own visit is still theirs.
    await page.reload();
    await page.getByTestId('step-counter').filter({ hasText: /of 80$/ }).waitFor();
    await frame.close();
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('an experiment shows its link to the full page, and opens a line there, in a new tab, staying the experiment', async () => {
    const p = await openPage('?embed=1&mode=experiment&algorithm=regions&count=20&seed=1');
    const { page, context } = p;
    await page.setViewportSize({ width: 640, height: 480 });
    await page.getByTestId('experiment-view').filter({ hasText: '20 random lines traced with regions' }).waitFor();
    // It stood in the hidden views: no size, not visible.
    const open = page.getByTestId('open-full');
    expect(await open.isVisible()).toBe(true);
    const box = (await open.boundingBox())!;
    expect(box.width * box.height).toBeGreaterThan(100);
    expect(box.y + box.height).toBeLessThanOrEqual(480);
    const full = new URL((await open.getAttribute('href'))!);
    expect([full.searchParams.get('mode'), full.searchParams.has('embed')]).toEqual(['experiment', false]);
    // A line opens in the full page; the frame stays on its table (it turned into Trace mode, no way back).
    const [tab] = await Promise.all([context.waitForEvent('page'), page.getByTestId('open-line-1').click()]);
    await tab.waitForLoadState();
    const line = new URL(tab.url());
    expect([line.searchParams.get('mode') ?? 'trace', line.searchParams.get('algorithm'), line.searchParams.has('embed')]).toEqual(['trace', 'regions', false]);
    expect(await page.evaluate(() => document.body.dataset.mode)).toBe('experiment');
    await screenshot(page, 'embed-experiment');
    await tab.close();
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('that could not trace says so, with no step counted and no empty reason box', async () => {
    const p = await openPage('?embed=1&algorithm=regions&from=0,0,0&to=10,7,1.5&step=3');
    const { page } = p;
    await page.getByTestId('embed-problem').filter({ hasText: /^Not traced: to: / }).waitFor();
    // It read "Step 3 of 0", over an empty box.
    expect(await page.getByTestId('step-counter').innerText()).toBe('No path');
    expect((await page.getByTestId('step-reason').boundingBox())?.height ?? 0).toBe(0);
    await p.close();
  });

  it('says over its view that it is tracing while a long comparison runs (it showed "No path" for seconds, without a word)', async () => {
    // Two lines of 1,400,000 steps, their metrics and the cells only one
    // visits: a second or so in the worker, said in steps too short to
    // poll for each ("Tracing…", "Measuring the path: ...", "Comparing the
    // paths ..."), so what it says is recorded as it changes, from the start.
    const p = await openPage('?embed=1&mode=compare&algorithm=regions&other=greedy&from=0,0,0&to=1400000,700,600', {
      waitUntil: 'commit',
      initScript: () => {
        const said: string[] = [];
        (window as unknown as { busySaid: string[] }).busySaid = said;
        document.addEventListener('DOMContentLoaded', () => {
          const busy = document.querySelector('[data-testid="embed-busy"]')!;
          new MutationObserver(() => {
            if ((busy as HTMLElement).checkVisibility() && busy.textContent) said.push(busy.textContent);
          }).observe(busy, { childList: true, characterData: true, subtree: true });
        });
      },
    });
    const { page } = p;
    const busy = page.getByTestId('embed-busy');
    await page.getByTestId('step-counter').filter({ hasText: 'of 1,401,300' }).waitFor({ timeout: 60_000 });
    await expect.poll(() => busy.isVisible()).toBe(false);
    const said = await page.evaluate(() => (window as unknown as { busySaid: string[] }).busySaid);
    expect(said[0]).toBe('Tracing…');
    expect(said).toContainEqual(expect.stringMatching(/^Comparing the paths \(cells sorted\): [\d,]+ of 2,801,302 points…$/));
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it("says what its link says that it cannot read, each left at its default (a frame showed another line without a word)", async () => {
    const p = await openPage('?embed=1&algorithm=regionz&from=5,abc,2&to=20,10,5&tie=sideways');
    const { page } = p;
    const note = page.getByTestId('link-note');
    await note.filter({ hasText: 'Not understood in this link' }).waitFor();
    expect(await note.innerText()).toBe('Not understood in this link, so left at their defaults: algorithm=regionz, from=5,abc,2, tie=sideways.');
    const box = (await note.boundingBox())!;
    expect(box.height).toBeGreaterThan(0);
    await screenshot(page, 'embed-link-note');
    await p.close();
    // A link the page wrote says nothing.
    const fine = await openPage(`?embed=1&${EXAMPLE}`);
    await fine.page.getByTestId('step-counter').filter({ hasText: 'Step 5 of 10' }).waitFor();
    expect(await fine.page.getByTestId('link-note').isVisible()).toBe(false);
    await fine.close();
  });

  it('says which value it read of a key its link gives twice, in the full page too (a "&to=9,9,9" added at the end was dropped without a word)', async () => {
    const link = 'algorithm=regions&from=0,0,0&to=5,5,5&tie=sideways&to=9,9,9';
    for (const query of [link, `embed=1&${link}`]) {
      const p = await openPage(query);
      const { page } = p;
      await page.getByTestId('step-counter').filter({ hasText: /of 5$/ }).waitFor();
      expect(await page.getByTestId('link-note').innerText(), query).toBe(
        'Not understood in this link, so left at their defaults: tie=sideways. Given more than once in this link, so read by its first value: to=5,5,5 (not 9,9,9).',
      );
      expect(p.problems()).toEqual([]);
      await p.close();
    }
  });

  it('says how it fitted a 2D link to a 3D algorithm, in the full page too (traced with z = 0 without a word)', async () => {
    const link = 'algorithm=regions&from=0,0&to=7,-3';
    const said = 'from and to had 2 coordinates; regions takes 3: z = 0 added.';
    for (const query of [link, `embed=1&${link}`]) {
      const p = await openPage(query);
      const { page } = p;
      await page.setViewportSize({ width: 640, height: 480 });
      await page.getByTestId('step-counter').filter({ hasText: /of 7$/ }).waitFor();
      const note = page.getByTestId('link-note');
      expect(await note.innerText(), query).toBe(said);
      const box = (await note.boundingBox())!;
      expect([box.height > 0, box.y >= 0, box.y + box.height <= 480], query).toEqual([true, true, true]);
      expect(p.problems()).toEqual([]);
      await p.close();
    }
  });

  it("says when its link's step is past the path's end, once traced, in the full page too (it opened at the end without a word)", async () => {
    const past = 'mode=trace&algorithm=bresenham3d&from=0,0,0&to=10,7,6&step=500';
    for (const [query, counter, said] of [
      [past, 'Step 10 of 10', "step 500 is past this path's last step, 10: shown at its end."],
      [`embed=1&${past}`, 'Step 10 of 10', "step 500 is past this path's last step, 10: shown at its end."],
      // After what the page could not read; the longer path's end; a program's.
      ['algorithm=regions&from=0,0,0&to=10,7,6&tie=sideways&step=11', 'Step 10 of 10', "Not understood in this link, so left at their defaults: tie=sideways. step 11 is past this path's last step, 10: shown at its end."],
      ['embed=1&mode=compare&algorithm=regions&other=greedy&from=0,0,0&to=10,7,6&step=30', 'Step 23 of 23', "step 30 is past the longer path's last step, 23: shown at its end."],
      ['embed=1&mode=gcode&step=10000', 'Step 6,400 of 6,400', "step 10,000 is past the program's last step, 6,400: shown at its end."],
    ] as const) {
      const p = await openPage(query);
      const { page } = p;
      await page.getByTestId('step-counter').filter({ hasText: counter }).waitFor();
      expect(await page.getByTestId('link-note').innerText(), query).toBe(said);
      expect(p.problems()).toEqual([]);
      await p.close();
    }
    // Its last step says nothing.
    const last = await openPage('?embed=1&mode=trace&algorithm=bresenham3d&from=0,0,0&to=10,7,6&step=10');
    await last.page.getByTestId('step-counter').filter({ hasText: 'Step 10 of 10' }).waitFor();
    expect(await last.page.getByTestId('link-note').isVisible()).toBe(false);
    await last.close();
  });

  it("keeps a 320 x 240 G-code frame's labels inside its view (x's hung 2 px below it)", async () => {
    const p = await openPage('?embed=1&mode=gcode');
    const { page } = p;
    await page.setViewportSize({ width: 320, height: 240 });
    await page.getByTestId('step-counter').filter({ hasText: /of 6,400$/ }).waitFor();
    await page.waitForTimeout(600);
    await screenshot(page, 'embed-gcode-320x240');
    // Each label shown, with its bottom against the view's: x's ticks hang below their points, at the picture's front edge.
    const { bottom, labels } = await page.evaluate(() => ({
      bottom: document.querySelector('#viewport')!.getBoundingClientRect().bottom,
      labels: [...document.querySelectorAll<HTMLElement>('#viewport .scene-label')]
        .filter((label) => label.checkVisibility())
        .map((label) => ({ text: label.textContent, bottom: label.getBoundingClientRect().bottom })),
    }));
    expect(labels.map((label) => label.text)).toContain('20 mm1600');
    expect(labels.filter((label) => label.bottom > bottom).map((label) => `${label.text}: ${(label.bottom - bottom).toFixed(1)} px below`)).toEqual([]);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('keeps at least half of a 320 x 180 or 400 x 225 frame for its view, the playback whole under it', async () => {
    // The playback, the reason and the clock took all but 18 to 115 px of it; a link's note all but 2.
    const side = 'mode=compare&layout=side&algorithm=regions&other=greedy&from=0,0,0&to=10,7,6&step=5';
    const note = 'algorithm=regionz&from=0,0&to=7,-3';
    for (const [width, height] of [
      [320, 180],
      [400, 225],
    ] as const) {
      for (const query of [EXAMPLE, 'mode=gcode&slowdown=1000', side, note]) {
        const p = await openPage(`?embed=1&${query}`);
        const { page } = p;
        await page.setViewportSize({ width, height });
        await page.getByTestId('step-counter').filter({ hasText: /of [1-9]/ }).waitFor();
        await page.waitForTimeout(300);
        const at = `${query} at ${width}x${height}`;
        const { views, controls, scrollHeight } = await page.evaluate(() => {
          const box = (e: Element) => e.getBoundingClientRect().toJSON() as { top: number; bottom: number; left: number; right: number; height: number };
          return {
            views: [...document.querySelectorAll('.viewport')].filter((v) => (v as HTMLElement).checkVisibility()).map(box),
            controls: [...document.querySelectorAll<HTMLElement>('.timeline input, .timeline button, .timeline select, .timeline output')].filter((e) => e.checkVisibility()).map((e) => ({ name: e.id, ...box(e) })),
            scrollHeight: document.documentElement.scrollHeight,
          };
        });
        expect(views.length, at).toBe(query === side ? 2 : 1);
        // With a link's note above it, a third.
        const least = query === note ? height / 3 : height / 2;
        for (const view of views) expect(view.height, `${at}: the view's height`).toBeGreaterThanOrEqual(least);
        expect(controls.map((c) => c.name), at).toEqual(expect.arrayContaining(['scrubber', 'step-counter', 'first', 'previous', 'play', 'next', 'last', 'speed']));
        const outside = controls.filter((c) => c.top < 0 || c.left < 0 || c.bottom > height + 0.5 || c.right > width + 0.5).map((c) => c.name);
        expect(outside, `${at}: controls outside the frame`).toEqual([]);
        expect(scrollHeight, `${at}: nothing runs off the frame`).toBeLessThanOrEqual(height);
        await screenshot(page, `embed-${width}x${height}-${query === side ? 'side' : query === note ? 'link-note' : query.includes('gcode') ? 'machine-time' : 'trace'}`);
        expect(p.problems()).toEqual([]);
        await p.close();
      }
    }
  });

  it('keeps its link to the full page off the views, one and two side by side, at 640 x 480', async () => {
    for (const query of [`?embed=1&${EXAMPLE}`, '?embed=1&mode=compare&algorithm=regions&other=bresenham3d&layout=side&from=0,0,0&to=10,7,6&step=5']) {
      const p = await openPage(query);
      const { page } = p;
      await page.setViewportSize({ width: 640, height: 480 });
      await page.getByTestId('step-counter').filter({ hasText: 'Step 5 of 10' }).waitFor();
      await page.waitForTimeout(300);
      // Over the last view it covered the x axis's name and its last tick.
      const boxes = await page.evaluate(() => {
        const box = (e: Element) => e.getBoundingClientRect().toJSON() as { left: number; right: number; top: number; bottom: number };
        return {
          link: box(document.querySelector('[data-testid=open-full]')!),
          views: [...document.querySelectorAll('.viewport')].filter((v) => (v as HTMLElement).checkVisibility()).map(box),
        };
      });
      expect(boxes.views.length).toBe(query.includes('layout=side') ? 2 : 1);
      for (const view of boxes.views) {
        const apart = boxes.link.top >= view.bottom || boxes.link.bottom <= view.top || boxes.link.left >= view.right || boxes.link.right <= view.left;
        expect(apart, `link ${JSON.stringify(boxes.link)}, view ${JSON.stringify(view)}`).toBe(true);
      }
      expect(boxes.link.bottom).toBeLessThanOrEqual(480);
      await p.close();
    }
  });

  it('leaves the reason out with explain=0', async () => {
    const p = await openPage(`?embed=1&explain=0&${EXAMPLE}`);
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: 'Step 5 of 10' }).waitFor();
    await page.waitForTimeout(300);
    expect(await page.getByTestId('step-reason').isVisible()).toBe(false);
    expect(new URL((await page.getByTestId('open-full').getAttribute('href'))!).searchParams.get('explain')).toBe('0');
    await p.close();
  });
});

describe('the Embed button', () => {
  it("gives the <iframe> of the state on screen at the page's own address, ready to copy", async () => {
    const p = await openPage(`?${EXAMPLE}`);
    const { page, context } = p;
    await context.grantPermissions(['clipboard-read', 'clipboard-write'], { origin: new URL(siteUrl()).origin });
    await page.getByTestId('step-counter').filter({ hasText: 'Step 5 of 10' }).waitFor();
    await page.getByTestId('embed-open').click();
    const dialog = page.getByTestId('embed-dialog');
    await dialog.waitFor();
    const snippet = await page.getByTestId('embed-snippet').inputValue();
    const frame = await page.evaluate((html) => {
      const iframe = new DOMParser().parseFromString(html, 'text/html').querySelector('iframe');
      return iframe && { src: iframe.src, title: iframe.title, width: iframe.width, height: iframe.height, count: new DOMParser().parseFromString(html, 'text/html').body.children.length };
    }, snippet);
    expect(frame).not.toBeNull();
    const src = new URL(frame!.src);
    // The real address the page is served from (the test server's sub-path), not a placeholder.
    expect(src.origin + src.pathname).toBe(siteUrl());
    expect(src.searchParams.get('embed')).toBe('1');
    expect(Object.fromEntries(['algorithm', 'from', 'to', 'step'].map((k) => [k, src.searchParams.get(k)]))).toEqual({ algorithm: 'regions', from: '0,0,0', to: '10,7,6', step: '5' });
    expect(frame!.title).toBe('Method of discriminate regions (3D line), (0, 0, 0) to (10, 7, 6), step by step (voxpath)');
    expect([frame!.width, frame!.height, frame!.count]).toEqual(['640', '480', 1]);

    await page.getByTestId('embed-copy').click();
    await page.getByTestId('embed-copied').filter({ hasText: 'Copied.' }).waitFor();
    expect(await page.evaluate(() => navigator.clipboard.readText())).toBe(snippet);
    await screenshot(page, 'embed-dialog');

    // What it embeds: this state, embedded.
    const embedded = await openPage(src.search);
    await embedded.page.getByTestId('step-counter').filter({ hasText: 'Step 5 of 10' }).waitFor();
    expect(await embedded.page.evaluate(() => document.body.classList.contains('embed'))).toBe(true);
    await embedded.close();
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('says when the inputs were not traced as they are (it gave their snippet without a word)', async () => {
    const p = await openPage(`?${EXAMPLE}`);
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: 'Step 5 of 10' }).waitFor();
    await page.getByTestId('embed-open').click();
    expect(await page.getByTestId('embed-note').isVisible()).toBe(false);
    await page.keyboard.press('Escape');
    await page.getByTestId('input-to-z').fill('1.5');
    await expect.poll(() => page.evaluate(() => document.body.dataset.stale)).toBe('rejected');
    await page.getByTestId('embed-open').click();
    await page.getByTestId('embed-note').filter({ hasText: 'The inputs were not traced as they are' }).waitFor();
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it("says when a learner's points are too long for the link it gives (they were left out silently)", async () => {
    const p = await openPage('?from=0,0,0&to=1000,0,0');
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: /of 1,000$/ }).waitFor();
    await page.getByTestId('check-points').locator('summary').click();
    const points = Array.from({ length: 1001 }, (_, x) => `${x},0,0`).join('\n');
    await page.getByTestId('learner-points').fill(points);
    await page.getByTestId('check-verdict').waitFor();
    await page.getByTestId('embed-open').click();
    await page.getByTestId('embed-note').filter({ hasText: 'Your points are longer than a link holds (2,000 characters)' }).waitFor();
    expect(await page.getByTestId('embed-snippet').inputValue()).not.toContain('points=');
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});
