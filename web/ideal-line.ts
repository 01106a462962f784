/**
 * A path's cell centers (or any flat polyline) as the scene draws an ideal
 * line: the form the core's Trace.idealLine() gives (IdealLine), for lines
 * voxpath makes itself, such as through a learner's points (in the worker).
 */
import type { IdealLine } from './core/types.js';

/**
 * `polyline`: flat, stride `dims`, grid units. Its vertices are taken from
 * its first one rounded to the grid (the origin), as the core's are from a
 * trace's start (IdealLine).
 */
export function idealLineOf(polyline: Float64Array | Int32Array, dims: number): IdealLine {
  const count = polyline.length / dims;
  const axes = Math.min(dims, 3);
  const origin: [number, number, number] = [0, 0, 0];
  if (count > 0) for (let a = 0; a < axes; a++) origin[a] = Math.round(polyline[a]!);
  // One buffer for both, which the worker hands over whole.
  const values = new Float32Array(count * 6);
  const xyz = values.subarray(0, count * 3);
  const rest = values.subarray(count * 3);
  for (let k = 0; k < count; k++) {
    for (let a = 0; a < axes; a++) {
      const exact = polyline[k * dims + a]! - origin[a]!;
      xyz[k * 3 + a] = exact;
      rest[k * 3 + a] = exact - xyz[k * 3 + a]!;
    }
  }
  if (count === 0) return { xyz, rest, min: [0, 0, 0], max: [0, 0, 0], origin };
  let [minX, minY, minZ] = [xyz[0]!, xyz[1]!, xyz[2]!];
  let [maxX, maxY, maxZ] = [minX, minY, minZ];
  for (let i = 3; i < xyz.length; i += 3) {
    const [x, y, z] = [xyz[i]!, xyz[i + 1]!, xyz[i + 2]!];
    if (x < minX) minX = x;
    else if (x > maxX) maxX = x;
    if (y < minY) minY = y;
    else if (y > maxY) maxY = y;
    if (z < minZ) minZ = z;
    else if (z > maxZ) maxZ = z;
  }
  return { xyz, rest, min: [minX, minY, minZ], max: [maxX, maxY, maxZ], origin };
}

