/**
 * The G-code programs the benches run, made here so that a test can run
 * the same program (tests/scale.test.ts holds its memory per line to the
 * issue's bound) without loading a bench and its peers.
 */

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
