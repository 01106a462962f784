// Drives headless Chromium (the system's, found by scripts/chromium.mjs)
// through playwright-core against the built site that global-setup.ts serves.
//
//   afterAll(closeAll);
//   const p = await openPage('?algo=regions');
//   ... p.page is a Playwright Page ...
//   expect(p.problems()).toEqual([]);
//   const stats = await screenshot(p.page, 'regions-canvas', 'canvas');
//   expect(stats.differingFraction).toBeGreaterThan(0.01);
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { type Browser, type BrowserContext, chromium, type Page } from 'playwright-core';
import { PNG } from 'pngjs';
import { inject } from 'vitest';
import { CHROMIUM_ARGS, CHROMIUM_HINT, findChromium } from '../../scripts/chromium.mjs';

const VIEWPORT = { width: 1280, height: 720 };

/** Where screenshot() writes its PNGs (gitignored). */
const SCREENSHOT_DIR = join(dirname(fileURLToPath(import.meta.url)), '__screenshots__', 'actual');

/** One HTTP response the page received. */
export interface ResponseRecord {
  url: string;
  status: number;
  /** The Content-Type header without parameters ('' when absent). */
  contentType: string;
}

/** A page of the built site in its own browser context. */
export interface OpenedPage {
  page: Page;
  context: BrowserContext;
  /** The URL opened: the site's index plus the query. */
  url: string;
  /** HTTP status of the index document. */
  status: number;
  /** Every console message of type 'error', with its source URL (but see the favicon note below). */
  consoleErrors: string[];
  /** Uncaught exceptions and unhandled rejections of the page. */
  pageErrors: string[];
  /** Every response, in the order received. */
  responses: ResponseRecord[];
  /** Requests that got no response at all, as 'URL: reason'. */
  failedRequests: string[];
  /** The first response (already received or still to come) that `match` accepts. */
  waitForResponse(match: (response: ResponseRecord) => boolean, timeoutMs?: number): Promise<ResponseRecord>;
  /** Console errors, page errors, failed requests and HTTP errors (status >= 400), one line each. */
  problems(): string[];
  close(): Promise<void>;
}

/** Address of the built site's index, served under a sub-path (ends with '/'). */
export function siteUrl(): string {
  return inject('siteUrl');
}

let browser: Promise<Browser> | undefined;
const opened = new Set<OpenedPage>();

async function launch(): Promise<Browser> {
  const executablePath = findChromium();
  if (!executablePath) throw new Error(CHROMIUM_HINT);
  // A plain launch: playwright gives each launch a fresh temporary profile.
  return chromium.launch({ executablePath, args: CHROMIUM_ARGS });
}

export interface OpenOptions {
  /** Runs in the page before any of its own scripts (Playwright's addInitScript), say to observe it from the start. */
  initScript?: () => void;
  /** Return once the document has arrived ('commit'), to act while it loads; default: at its load event. */
  waitUntil?: 'load' | 'commit';
}

/**
 * Opens the site's index page (plus `query`, with or without its leading '?')
 * in a fresh browser context of a browser shared by the test file, and waits
 * for the page's load event (see OpenOptions). Diagnostics are collected from the start.
 */
export async function openPage(query = '', options: OpenOptions = {}): Promise<OpenedPage> {
  browser ??= launch();
  const context = await (await browser).newContext({ viewport: VIEWPORT });
  const page = await context.newPage();
  if (options.initScript) await page.addInitScript(options.initScript);
  const consoleErrors: string[] = [];
  const pageErrors: string[] = [];
  const responses: ResponseRecord[] = [];
  const failedRequests: string[] = [];
  const waiters = new Set<(response: ResponseRecord) => void>();
  page.on('console', (message) => {
    if (message.type() !== 'error') return;
    const source = message.location().url;
    // A page that declares no icon makes Chromium ask for /favicon.ico at the
    // origin's root, which under a sub-path is outside the site: its 404 is
    // not the site's error. An icon the page does declare is still checked.
    if (source && new URL(source).pathname === '/favicon.ico') return;
    consoleErrors.push(source ? `${message.text()} (${source})` : message.text());
  });
  page.on('pageerror', (error) => pageErrors.push(error.stack ?? error.message));
  page.on('requestfailed', (request) => failedRequests.push(`${request.url()}: ${request.failure()?.errorText}`));
  page.on('response', (response) => {
    const record = {
      url: response.url(),
      status: response.status(),
      contentType: (response.headers()['content-type'] ?? '').split(';')[0].trim(),
    };
    responses.push(record);
    for (const waiter of waiters) waiter(record);
  });

  const url = siteUrl() + (query && !query.startsWith('?') ? `?${query}` : query);
  const result: OpenedPage = {
    page,
    context,
    url,
    status: 0,
    consoleErrors,
    pageErrors,
    responses,
    failedRequests,
    waitForResponse(match, timeoutMs = 15_000) {
      const seen = responses.find(match);
      if (seen) return Promise.resolve(seen);
      return new Promise((resolve, reject) => {
        const timer = setTimeout(() => {
          waiters.delete(waiter);
          reject(new Error(`no matching response within ${timeoutMs} ms; got:\n${responses.map((r) => `${r.status} ${r.url}`).join('\n')}`));
        }, timeoutMs);
        const waiter = (response: ResponseRecord) => {
          if (!match(response)) return;
          clearTimeout(timer);
          waiters.delete(waiter);
          resolve(response);
        };
        waiters.add(waiter);
      });
    },
    problems: () => [
      ...consoleErrors.map((text) => `console error: ${text}`),
      ...pageErrors.map((text) => `page error: ${text}`),
      ...failedRequests.map((text) => `request failed: ${text}`),
      ...responses.filter((r) => r.status >= 400).map((r) => `HTTP ${r.status}: ${r.url}`),
    ],
    close: async () => {
      opened.delete(result);
      await context.close();
    },
  };
  opened.add(result);
  const response = await page.goto(url, { waitUntil: options.waitUntil ?? 'load' });
  result.status = response?.status() ?? 0;
  return result;
}

/** Goes to step `step` by the playback's jump field, as a learner types it, once the step counter says so. */
export async function jumpTo(page: Page, step: number): Promise<void> {
  await page.getByTestId('jump-input').fill(String(step));
  await page.getByTestId('jump-input').press('Enter');
  await page.getByTestId('step-counter').filter({ hasText: new RegExp(`^Step ${step.toLocaleString('en-US')} of`) }).waitFor();
}

/**
 * Once the element of test id `box` shows (a run's bar: its first report),
 * and its text starts with `saying`, clicks the element of test id
 * `click`, or types `value` into the field of test id `field` (`act` null:
 * neither), from inside the page, at once: a click from the test comes tens of ms later, after a
 * run shorter than that (a chart's rows in Chromium's worker) had ended.
 * Resolves with the box's text then.
 */
export function onceShown(page: Page, box: string, act: { click: string } | { field: string; value: string } | null, saying = ''): Promise<string> {
  return page.evaluate(
    ([box, act, saying]) =>
      new Promise<string>((resolve) => {
        const target = document.querySelector(`[data-testid="${box}"]`) as HTMLElement;
        const run = () => {
          const text = target.textContent?.trim() ?? '';
          if (target.hidden || !text.startsWith(saying)) return;
          observer.disconnect();
          if (act === null) {
            // Only its text, seen.
          } else if ('click' in act) (document.querySelector(`[data-testid="${act.click}"]`) as HTMLButtonElement).click();
          else {
            const field = document.querySelector(`[data-testid="${act.field}"]`) as HTMLInputElement;
            field.value = act.value;
            field.dispatchEvent(new Event('input', { bubbles: true }));
          }
          resolve(text);
        };
        const observer = new MutationObserver(run);
        observer.observe(target, { attributes: true, attributeFilter: ['hidden'], childList: true, subtree: true, characterData: true });
        run();
      }),
    [box, act, saying] as const,
  );
}

/** Closes every page still open and the browser; use as `afterAll(closeAll)`. */
export async function closeAll(): Promise<void> {
  await Promise.all([...opened].map((p) => p.close()));
  const running = browser;
  browser = undefined;
  // A launch that failed has already failed the test that asked for it.
  await (await running?.catch(() => undefined))?.close();
}

/** A rectangle in CSS pixels of the viewport. */
export interface Region {
  x: number;
  y: number;
  width: number;
  height: number;
}

/** Content statistics of an image, enough to tell a drawn canvas from a blank one. */
export interface ImageStats {
  width: number;
  height: number;
  /** RGBA of the background: the given colour, else the most frequent one. */
  background: [number, number, number, number];
  /** Fraction (0..1) of pixels differing from the background by more than the tolerance in some channel. */
  differingFraction: number;
  /** Number of distinct RGBA values. */
  distinctColors: number;
}

export interface StatsOptions {
  /** Background colour, RGB or RGBA (alpha 255 when omitted); default: the most frequent colour. */
  background?: readonly number[];
  /** Largest per-channel difference still counted as background; default 0. */
  tolerance?: number;
}

/** Statistics of a PNG image (see ImageStats). */
function imageStats(png: Buffer, options: StatsOptions = {}): ImageStats {
  const { width, height, data } = PNG.sync.read(png);
  const pixelCount = width * height;
  // Each pixel as one RGBA number, counted per distinct value.
  const counts = new Map<number, number>();
  for (let i = 0; i < pixelCount * 4; i += 4) {
    const rgba = data.readUInt32BE(i);
    counts.set(rgba, (counts.get(rgba) ?? 0) + 1);
  }
  let background: [number, number, number, number];
  if (options.background) {
    const [r, g, b, a = 255] = options.background;
    background = [r, g, b, a];
  } else {
    let mode = 0;
    let modeCount = 0;
    for (const [rgba, count] of counts) if (count > modeCount) [mode, modeCount] = [rgba, count];
    background = [mode >>> 24, (mode >>> 16) & 255, (mode >>> 8) & 255, mode & 255];
  }
  const tolerance = options.tolerance ?? 0;
  let differing = 0;
  for (let i = 0; i < pixelCount * 4; i += 4) {
    if (background.some((value, channel) => Math.abs(data[i + channel] - value) > tolerance)) differing += 1;
  }
  return {
    width,
    height,
    background,
    differingFraction: pixelCount ? differing / pixelCount : 0,
    distinctColors: counts.size,
  };
}

/**
 * Pixels of the PNG file `file` within `tolerance` of `colour` ('#rrggbb') on
 * every channel: how much a chart drew of a series stroked in that colour
 * (its legend swatch alone is a few dozen pixels).
 */
export function pixelsOf(file: string, colour: string, tolerance = 24): number {
  const { data } = PNG.sync.read(readFileSync(file));
  const rgb = [1, 3, 5].map((i) => parseInt(colour.slice(i, i + 2), 16));
  let count = 0;
  for (let i = 0; i < data.length; i += 4) {
    if (rgb.every((value, channel) => Math.abs(data[i + channel]! - value) <= tolerance)) count += 1;
  }
  return count;
}

/**
 * Saves a PNG of the page (the viewport, a region of it, or the first element
 * matching a selector) as SCREENSHOT_DIR/NAME.png and returns its statistics.
 */
export async function screenshot(
  page: Page,
  name: string,
  target?: Region | string,
  options?: StatsOptions,
): Promise<ImageStats & { file: string }> {
  if (!/^[\w.-]+$/.test(name)) throw new Error(`screenshot name "${name}" must be letters, digits, '_', '-' or '.'`);
  const png =
    typeof target === 'string'
      ? await page.locator(target).first().screenshot()
      : await page.screenshot(target ? { clip: target } : {});
  mkdirSync(SCREENSHOT_DIR, { recursive: true });
  const file = join(SCREENSHOT_DIR, `${name}.png`);
  writeFileSync(file, png);
  return { ...imageStats(png, options), file };
}

/**
 * The page's PNG export of the (first) view: drawn and encoded in one task,
 * since the canvas keeps no drawing buffer to read later. In an embedded
 * page, which has no export button, the export is asked for through the
 * same click. The export draws the labels shown over the view (axis names,
 * ticks, handles); unless `labels`, they are hidden while it is made, so
 * that colours counted in it are the drawing's (label text is as dark as
 * the ideal path, and the exit face's letters stand on its crossing dot).
 */
export async function canvasPng(page: Page, { labels = false } = {}): Promise<PNG> {
  const hidden = labels ? undefined : await page.addStyleTag({ content: '.scene-labels { display: none !important; }' });
  try {
    const downloading = page.waitForEvent('download');
    await page.evaluate(() => document.querySelector<HTMLButtonElement>('[data-testid="export-png"]')!.click());
    const download = await downloading;
    const chunks: Buffer[] = [];
    for await (const chunk of await download.createReadStream()) chunks.push(chunk as Buffer);
    return PNG.sync.read(Buffer.concat(chunks));
  } finally {
    await hidden?.evaluate((style) => (style as Element).remove());
  }
}
