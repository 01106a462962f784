/**
 * G-code throughput: a generated 100,000-line program run through the
 * public API (runGcode: parse, interpret, step every move, build the trace),
 * once with each arc algorithm. Reports lines per second and steps per
 * second of the whole run, as a worker would see it (slices included).
 *
 * Runs from bench/run.ts with the other benches; alone (after npm run
 * build:lib), through Vite's SSR loader, which keeps the module graph open
 * for the core's dynamic import of node:fs:
 *   node -e "import('vite').then(async (v) => { const s = await v.createServer({ server: { middlewareMode: true, hmr: false, ws: false }, appType: 'custom', configFile: false, logLevel: 'error' }); try { console.table(await (await s.ssrLoadModule('/bench/gcode.bench.ts')).benchGcode()); } finally { await s.close(); } })"
 */
import { runGcode } from '../web/core/index.js';

/** Lines in the generated program. */
export const GCODE_BENCH_LINES = 100_000;

/**
 * A random walk of short G1 moves (up to 1 mm per axis in X and Y, 0.1 mm
 * in Z) with a clockwise quarter arc of r = 1 mm every tenth line: a pocket
 * clearing program's mix. Deterministic (a fixed linear congruential seed).
 */
export function generateProgram(lines: number): string {
  let seed = 12345;
  const random = () => {
    seed = (Math.imul(seed, 1103515245) + 12345) >>> 0;
    return seed / 2 ** 32;
  };
  const out = ['G21 G90 G17 F1200', 'G0 X25 Y25 Z0'];
  let [x, y, z] = [25, 25, 0];
  const mm = (v: number) => v.toFixed(3);
  while (out.length < lines) {
    if (out.length % 10 === 9) {
      // From angle 0 about (x - 1, y), clockwise to angle -90°.
      out.push(`G2 X${mm(x - 1)} Y${mm(y - 1)} I-1 J0`);
      [x, y] = [x - 1, y - 1];
    } else {
      // Stay within 5..45 mm: step back toward the middle at the edges.
      const step = (v: number, reach: number) => Math.min(45, Math.max(5, v + (random() * 2 - 1) * reach));
      [x, y, z] = [Number(mm(step(x, 1))), Number(mm(step(y, 1))), Number(mm(Math.min(0, step(z, 0.1))))];
      out.push(`G1 X${mm(x)} Y${mm(y)} Z${mm(z)}`);
    }
  }
  return out.join('\n') + '\n';
}

export interface GcodeBenchRow {
  name: string;
  lines: number;
  moves: number;
  steps: number;
  seconds: number;
  linesPerSecond: number;
  stepsPerSecond: number;
}

/** Runs the generated program with each arc algorithm; one row each. */
export async function benchGcode(): Promise<GcodeBenchRow[]> {
  const source = generateProgram(GCODE_BENCH_LINES);
  const rows: GcodeBenchRow[] = [];
  for (const arcAlgorithm of ['circle', 'arc-segments'] as const) {
    const started = performance.now();
    const program = await runGcode(source, { stepsPerMm: 80, arcAlgorithm });
    const seconds = (performance.now() - started) / 1000;
    if (program.errors.length > 0) throw new Error(`bench program failed: ${JSON.stringify(program.errors[0])}`);
    rows.push({
      name: `gcode ${GCODE_BENCH_LINES} lines, arcs: ${arcAlgorithm}`,
      lines: program.lines,
      moves: program.moves.length,
      steps: program.steps,
      seconds,
      linesPerSecond: program.lines / seconds,
      stepsPerSecond: program.steps / seconds,
    });
    program.free();
  }
  return rows;
}
