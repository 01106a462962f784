/**
 * The npm packages a user would pick instead of voxpath, each writing the
 * cells it visits into one Int32Array (stride 2) through its callback: the
 * cheapest way to keep what a callback API hands out.
 */
import bresenham from 'bresenham';
import * as zingl from 'bresenham-zingl';

// bresenham-zingl 0.2.8's index.d.ts re-exports its files by extensionless
// paths, which Node's module resolution (tsconfig's nodenext) does not
// follow: its circle as its dist/types/circle.d.ts declares it.
const { circle } = zingl as unknown as {
  circle: (xm: number, ym: number, r: number, setPixel: (x: number, y: number) => void) => void;
};

/** npm `bresenham` (the 2D line, start and end included). */
export function npmBresenham(from: readonly number[], to: readonly number[]): Int32Array {
  const [x0, y0, x1, y1] = [from[0]!, from[1]!, to[0]!, to[1]!];
  const out = new Int32Array(2 * (Math.max(Math.abs(x1 - x0), Math.abs(y1 - y0)) + 1));
  let i = 0;
  bresenham(x0, y0, x1, y1, (x, y) => {
    out[i++] = x;
    out[i++] = y;
  });
  return out;
}

/**
 * npm `bresenham-zingl`'s circle about (0, 0): Zingl's midpoint circle,
 * which hands out each quadrant's cells in turn, 8-connected like voxpath's:
 * about 4 sqrt(2) r of them, fewer than the array's 6 r + 8.
 */
export function zinglCircle(radius: number): Int32Array {
  const out = new Int32Array(2 * (6 * radius + 8));
  let i = 0;
  circle(0, 0, radius, (x, y) => {
    out[i++] = x;
    out[i++] = y;
  });
  return out.subarray(0, i);
}
