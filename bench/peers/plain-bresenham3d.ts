/**
 * The 3D line a user would write in plain JavaScript instead of calling
 * voxpath: Bresenham's rule on every axis at once, all points written into
 * one Int32Array (stride 3, start and end included). The major axis's error
 * is always >= 0, so one loop serves every axis with no case per octant.
 */
export function plainBresenham3d(from: readonly number[], to: readonly number[]): Int32Array {
  let [x, y, z] = from as [number, number, number];
  const [dx, dy, dz] = [Math.abs(to[0]! - x), Math.abs(to[1]! - y), Math.abs(to[2]! - z)];
  const [sx, sy, sz] = [Math.sign(to[0]! - x), Math.sign(to[1]! - y), Math.sign(to[2]! - z)];
  const n = Math.max(dx, dy, dz);
  let [ex, ey, ez] = [2 * dx - n, 2 * dy - n, 2 * dz - n];
  const out = new Int32Array(3 * (n + 1));
  for (let i = 0; i < out.length; i += 3) {
    out[i] = x;
    out[i + 1] = y;
    out[i + 2] = z;
    if (ex >= 0) (x += sx), (ex -= 2 * n);
    if (ey >= 0) (y += sy), (ey -= 2 * n);
    if (ez >= 0) (z += sz), (ez -= 2 * n);
    (ex += 2 * dx), (ey += 2 * dy), (ez += 2 * dz);
  }
  return out;
}
