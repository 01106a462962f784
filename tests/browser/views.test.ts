// How the page asks the worker, counted: every message the page posts to a
// Worker is recorded by wrapping Worker.prototype.postMessage before the
// page's scripts run (no hook in the page itself).
// - A view-only change (2D, Reset view, Decision in 3D, the camera) touches
//   the path views alone: no message to the worker, and the inspector's and
//   the charts' elements are not rebuilt.
// - A new point costs one request (stepDetail), which the inspector, its
//   figure and the 3D overlay all draw from, and so does the step's reason
//   under the timeline where it shows (a narrow window); compared, the
//   second path's reason is the one request more.
// - A trace the worker answers is held there until the page frees it: a
//   comparison whose other side the core refused frees the side it traced.
import type { Page } from 'playwright-core';
import { afterAll, describe, expect, it } from 'vitest';
import { closeAll, openPage } from './harness.js';

afterAll(closeAll);

declare global {
  interface Window {
    /** The kind of each request the page posted to a worker ('cancel' for a cancellation), in order. */
    workerRequests: string[];
    /** The ids of the traces a worker holds for the page: traced, and not yet freed. */
    tracesHeld: Set<number>;
  }
}

/** Installed before the page's scripts: records the kind of every message posted to a worker. */
function recordWorkerRequests(): void {
  window.workerRequests = [];
  const post = Worker.prototype.postMessage;
  Worker.prototype.postMessage = function (this: Worker, message: unknown, ...rest: [StructuredSerializeOptions?]) {
    const request = (message as { request?: { kind: string } }).request;
    window.workerRequests.push(request?.kind ?? 'cancel');
    return post.call(this, message, ...rest);
  } as Worker['postMessage'];
}

/**
 * Installed before the page's scripts: keeps window.tracesHeld, the traces a
 * worker answered (it holds those until the page frees them) less those the
 * page freed. A refused trace is held by no one.
 */
function recordTracesHeld(): void {
  window.tracesHeld = new Set();
  const traceIdOf = new Map<number, number>();
  const post = Worker.prototype.postMessage;
  Worker.prototype.postMessage = function (this: Worker, message: unknown, ...rest: [StructuredSerializeOptions?]) {
    const { id, request } = message as { id: number; request?: { kind: string; traceId?: number } };
    if (request?.kind === 'trace') traceIdOf.set(id, request.traceId!);
    if (request?.kind === 'free') window.tracesHeld.delete(request.traceId!);
    return post.call(this, message, ...rest);
  } as Worker['postMessage'];
  const PageWorker = window.Worker;
  window.Worker = class extends PageWorker {
    constructor(...args: ConstructorParameters<typeof Worker>) {
      super(...args);
      this.addEventListener('message', (event: MessageEvent<{ id: number; ok?: boolean }>) => {
        const traceId = traceIdOf.get(event.data.id);
        if (traceId !== undefined && event.data.ok) window.tracesHeld.add(traceId);
      });
    }
  };
}

/** The requests posted since the last call. */
function takeRequests(page: Page): Promise<string[]> {
  return page.evaluate(() => window.workerRequests.splice(0));
}

/** Resolves after two frames and a task: whatever a change set going has been asked for by then. */
function settled(page: Page): Promise<void> {
  return page.evaluate(() => new Promise<void>((resolve) => requestAnimationFrame(() => requestAnimationFrame(() => setTimeout(resolve, 50)))));
}

/** Marks the inspector's M cell and the first chart's canvas, to tell later whether they were replaced. */
function mark(page: Page): Promise<void> {
  return page.evaluate(() => {
    for (const selector of ['[data-testid=inspector-value-M]', '[data-testid=charts] canvas']) {
      (document.querySelector(selector) as HTMLElement).dataset.marked = 'yes';
    }
  });
}

function marked(page: Page): Promise<number> {
  return page.evaluate(() => document.querySelectorAll('[data-marked=yes]').length);
}

describe('the page and its worker', () => {
  it('changes the view (2D, Reset view, Decision in 3D, camera) without asking the worker or rebuilding the other panels', async () => {
    // A planar line (z = 0), so the 2D view applies; regions, so Decision in 3D has an exit face to draw.
    const p = await openPage('?algorithm=regions&from=0,0,0&to=10,7,0&step=3', { initScript: recordWorkerRequests });
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: /of 10$/ }).waitFor();
    await page.getByTestId('inspector-deviation').filter({ hasText: 'grid units' }).waitFor();
    await expect.poll(() => page.getByTestId('charts').locator('canvas').count()).toBe(2);
    await settled(page);
    expect(await takeRequests(page)).toContain('stepDetail');
    await mark(page);

    const canvas = page.getByTestId('scene-canvas');
    // Decision in 3D first: in 2D the exit face, seen edge on, is not drawn, and its toggle waits.
    await page.getByTestId('decision-3d').check();
    await page.waitForURL(/decision3d=1/);
    await page.getByTestId('view-2d').check();
    await expect.poll(() => canvas.getAttribute('data-projection')).toBe('2d');
    await settled(page);
    await page.getByTestId('reset-view').click();
    await canvas.focus();
    await page.keyboard.press('ArrowLeft');
    await page.keyboard.press('+');
    await page.waitForURL(/camera=/);
    await page.getByTestId('view-2d').uncheck();
    await expect.poll(() => canvas.getAttribute('data-projection')).toBe('3d');
    await page.getByTestId('decision-3d').uncheck();
    await page.waitForURL(/decision3d=0/);
    await settled(page);

    expect(await takeRequests(page)).toEqual([]);
    expect(await marked(page)).toBe(2);

    // One point, one request: the inspector, the figure and the overlay read the same answer.
    await page.getByTestId('decision-3d').check();
    await settled(page);
    await page.getByTestId('next').click();
    await page.getByTestId('step-counter').filter({ hasText: /^Step 4 of/ }).waitFor();
    await expect.poll(() => page.getByTestId('inspector-value-M').innerText()).toBe('6');
    await settled(page);
    expect(await takeRequests(page)).toEqual(['stepDetail']);
    expect(await marked(page)).toBe(2);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('explains the step under the timeline from the same request, in a narrow window; a compared second path costs one more', async () => {
    const p = await openPage('?algorithm=regions&from=0,0,0&to=10,7,6&step=3', { initScript: recordWorkerRequests });
    const { page } = p;
    await page.setViewportSize({ width: 700, height: 900 });
    const reason = page.getByTestId('step-reason');
    await expect.poll(() => reason.innerText()).toMatch(/^Step 3: /);
    await settled(page);
    await takeRequests(page);
    await page.getByTestId('next').click();
    await expect.poll(() => reason.innerText()).toMatch(/^Step 4: /);
    await settled(page);
    expect(await takeRequests(page)).toEqual(['stepDetail']);
    expect(await reason.innerText()).toBe(`Step 4: ${await page.getByTestId('inspector-explanation').textContent()}`);

    // Compare mode: its table tops the inspector, so the reason has its own place.
    await page.getByTestId('mode-compare').click();
    await page.getByTestId('step-counter').filter({ hasText: /of 23$/ }).waitFor();
    await page.getByTestId('jump-input').fill('3');
    await page.getByTestId('jump-go').click();
    await expect.poll(() => reason.innerText()).toMatch(/^regions, step 3: .*\ngreedy, step 3: /s);
    await settled(page);
    await takeRequests(page);
    await page.getByTestId('next').click();
    await expect.poll(() => reason.innerText()).toMatch(/^regions, step 4: .*\ngreedy, step 4: /s);
    await settled(page);
    expect((await takeRequests(page)).sort()).toEqual(['stepDetail', 'stepDetail']);
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it('frees the traced side of a comparison whose other side the core refused', async () => {
    // helix against circle on the helix's own move, which travels along z:
    // the circle refuses it. The helix's trace was kept in the worker for
    // good, one more at every change the circle refused.
    const p = await openPage('?mode=compare&algorithm=helix&other=circle&from=10,0,0&to=10,0,24&center=0,0,0', { initScript: recordTracesHeld });
    const { page } = p;
    await page.getByTestId('step-counter').filter({ hasText: 'No path' }).waitFor();
    await page.getByTestId('trace-status').filter({ hasText: /^Not traced/ }).waitFor();
    // A planar move both trace: the comparison shown is all the worker holds.
    await page.getByTestId('input-to-z').fill('0');
    await page.getByTestId('metrics-table').waitFor();
    await settled(page);
    expect(await page.evaluate(() => window.tracesHeld.size)).toBe(2);
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});
