/**
 * The page against Node on the G-code bench's program: the same 100,000
 * lines run by the page (pasted into its G-code mode, run in its worker,
 * the result sent to the page and drawn) and by runGcode in Node, at 1 and
 * at 80 steps/mm. Issue 13 asks that the page run the program in about the
 * time Node takes plus drawing; this prints both times and their ratio.
 *
 * The site is built as `npm run build` builds it (vite.config.ts), served
 * under a sub-path, and opened in the system's Chromium (the browser tests'
 * launch, scripts/chromium.mjs). A page round starts when the page is asked
 * to run (the Run button, clicked in the page, after the first round's
 * paste) and ends two animation frames after the status line reports the
 * finished program: the run, the result's transfer and the frame that draws
 * it. The status line names the program's lines, moves and steps, which
 * must be Node's, so both sides are checked to run the same program. Each
 * timed run, page or Node, starts on a page left quiet ({@link settle}).
 */
import { mkdtemp, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import type { Page } from 'playwright-core';
import { build } from 'vite';
import { CHROMIUM_ARGS, CHROMIUM_HINT, findChromium } from '../scripts/chromium.mjs';
import { serveStatic } from '../scripts/static-server.mjs';
import { countOf } from '../web/core/export.js';
import { runGcode } from '../web/core/index.js';
import { GCODE_BENCH_LINES } from './gcode.bench.js';
import { collectGarbage } from './measure.js';
import { generateProgram } from './programs.js';
import type { BenchGroup, BenchRow } from './types.js';

/** Timed rounds per row, after the untimed first (the paste); the median counts. */
const ROUNDS = 5;

const ROOT = fileURLToPath(new URL('..', import.meta.url));

/** What the page's observer keeps (on window, read back by the bench). */
interface Observed {
  /** When the bench asked the page to run, page clock (ms). */
  started: number;
  /** When the status line first reported the finished program after that. */
  reported: number;
  /** Two animation frames after `reported`: the frame that drew it is done. */
  drawn: number;
}

/**
 * Quiet time before each timed run, page or Node. When the status line
 * reports a program the page goes on asking its worker for what the views
 * show after the first frame (the charts' series, the step clocks) and
 * Chromium's GPU process draws in software: at 80 steps/mm that work ran
 * about 330 ms past the status line, so a round started at once was timed
 * beside the round before's (the page's side to its status line 1.5 to 2
 * times as long as from a page left idle, and Node's side beside it too).
 */
const SETTLE_MS = 1500;

/** Waits until the page has had SETTLE_MS to finish what it does after a round, and its main thread is idle. */
async function settle(page: Page): Promise<void> {
  await page.waitForTimeout(SETTLE_MS);
  await page.evaluate(() => new Promise<void>((resolve) => requestIdleCallback(() => resolve(), { timeout: 10_000 })));
}

const median = (values: number[]) => [...values].sort((a, b) => a - b)[values.length >> 1]!;

/** Seconds of one runGcode of `source` in Node, its steps, and what it reports as the page's status line starts. */
async function nodeRun(source: string, stepsPerMm: number): Promise<{ seconds: number; steps: number; status: string }> {
  await collectGarbage();
  const started = performance.now();
  const program = await runGcode(source, { stepsPerMm });
  const seconds = (performance.now() - started) / 1000;
  const { steps } = program;
  // The page's own wording (web/page/status.ts), counts grouped.
  const status = `${countOf(program.lines, 'line')}, ${countOf(program.moveCount, 'move')}, ${countOf(steps, 'step')} at `;
  program.free();
  return { seconds, steps, status };
}

export default async function benchPageGcode(): Promise<BenchGroup> {
  const executablePath = findChromium();
  if (!executablePath) throw new Error(CHROMIUM_HINT);
  const outDir = await mkdtemp(join(tmpdir(), 'voxpath-bench-site-'));
  const prefix = '/voxpath/';
  await build({ configFile: join(ROOT, 'vite.config.ts'), build: { outDir, emptyOutDir: true }, logLevel: 'warn' });
  const server = await serveStatic({ dir: outDir, prefix });
  const browser = await chromium.launch({ executablePath, args: CHROMIUM_ARGS });
  const source = generateProgram(GCODE_BENCH_LINES);
  const rows: BenchRow[] = [];
  try {
    for (const stepsPerMm of [1, 80]) {
      const context = await browser.newContext({ viewport: { width: 1280, height: 720 } });
      await context.grantPermissions(['clipboard-read', 'clipboard-write']);
      const page = await context.newPage();
      await page.goto(`${server.url}?mode=gcode&stepsPerMm=${stepsPerMm}`);
      await page.getByTestId('trace-status').filter({ hasText: 'moves' }).waitFor();
      const { status, steps } = await nodeRun(source, stepsPerMm);
      // Every change of the status line after a start is timed in the page.
      await page.evaluate((finished) => {
        const observed: Observed = { started: Infinity, reported: 0, drawn: 0 };
        (window as unknown as { benchObserved: Observed }).benchObserved = observed;
        const line = document.querySelector('[data-testid=trace-status]')!;
        new MutationObserver(() => {
          const now = performance.now();
          if (now < observed.started || observed.reported > observed.started) return;
          if (!(line.textContent ?? '').startsWith(finished)) return;
          observed.reported = now;
          requestAnimationFrame(() => requestAnimationFrame(() => (observed.drawn = performance.now())));
        }).observe(line, { childList: true, characterData: true, subtree: true });
      }, status);
      const pageRun = async (start: 'paste' | 'run'): Promise<Observed> => {
        if (start === 'paste') {
          await page.evaluate((text) => navigator.clipboard.writeText(text), source);
          await page.getByTestId('gcode-text').focus();
          await page.keyboard.press('ControlOrMeta+A');
          await page.evaluate(() => ((window as unknown as { benchObserved: Observed }).benchObserved.started = performance.now()));
          await page.keyboard.press('ControlOrMeta+V');
        } else {
          await page.evaluate(() => {
            (window as unknown as { benchObserved: Observed }).benchObserved.started = performance.now();
            document.querySelector<HTMLButtonElement>('[data-testid=gcode-run]')!.click();
          });
        }
        await page.waitForFunction(
          () => {
            const o = (window as unknown as { benchObserved: Observed }).benchObserved;
            return o.drawn > o.started;
          },
          undefined,
          { timeout: 120_000, polling: 50 },
        );
        return page.evaluate(() => ({ ...(window as unknown as { benchObserved: Observed }).benchObserved }));
      };
      await pageRun('paste');
      const [pageSeconds, reportedSeconds, nodeSeconds]: number[][] = [[], [], []];
      for (let round = 0; round < ROUNDS; round++) {
        // Each side first in every other round, each after the page has
        // finished what the round before left it doing.
        await settle(page);
        const node = round % 2 === 0 ? await nodeRun(source, stepsPerMm) : undefined;
        if (node) await settle(page);
        const observed = await pageRun('run');
        pageSeconds.push((observed.drawn - observed.started) / 1000);
        reportedSeconds.push((observed.reported - observed.started) / 1000);
        if (!node) await settle(page);
        nodeSeconds.push((node ?? (await nodeRun(source, stepsPerMm))).seconds);
      }
      await context.close();
      rows.push({
        name: `${GCODE_BENCH_LINES.toLocaleString('en-US')} lines at ${stepsPerMm} step${stepsPerMm === 1 ? '' : 's'}/mm: the page (worker, result, frame drawn) vs runGcode in Node`,
        steps,
        rates: {
          'page lines/s': GCODE_BENCH_LINES / median(pageSeconds),
          'page lines/s to its status': GCODE_BENCH_LINES / median(reportedSeconds),
          'Node lines/s': GCODE_BENCH_LINES / median(nodeSeconds),
        },
        ratios: {
          'page / Node time': median(pageSeconds) / median(nodeSeconds),
          'to its status / Node': median(reportedSeconds) / median(nodeSeconds),
        },
      });
    }
  } finally {
    await browser.close();
    await server.close();
    await rm(outDir, { recursive: true, force: true });
  }
  return {
    title: 'G-code on the page: the same program in the worker, drawn, against Node',
    notes: [
      `The G-code bench's ${GCODE_BENCH_LINES.toLocaleString('en-US')}-line program pasted into the built page's G-code mode (headless Chromium, WebGL on SwiftShader, software), then run again by its Run button ${ROUNDS} times, each time with runGcode in Node in turn, each side's run ${SETTLE_MS / 1000} s after the page's last one and once its main thread is idle (the page goes on reading what its views show after the status line); medians.`,
      "page lines/s: from the click to two animation frames after the status line reports the finished program (the worker's run, the result sent to the page, the frame that draws it); 'to its status': to the report alone.",
      'Node lines/s: runGcode of the same text in this process (wall time, as the G-code table times it); the status line must name its lines, moves and steps.',
    ],
    rows,
  };
}
