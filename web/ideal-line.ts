/**
 * The ideal path in the form the scene hands to WebGL: x, y, z of each
 * vertex as 32-bit floats (a 2-axis path at z = 0; axes past the third are
 * not drawn), with the box the vertices lie in.
 *
 * The worker makes it beside the polyline, so the page's main thread gets a
 * buffer WebGL takes as it is: converting and boxing a 100,000-line
 * program's 250,000 vertices there took 5.7 ms, and the 6 MB of doubles it
 * received brought on a major garbage collection. The box saves three.js two
 * more passes over the vertices to cull the line in its first frame.
 */
export interface IdealLine {
  /** Stride 3, grid units. */
  xyz: Float32Array;
  /** Smallest and largest x, y, z over the vertices (zeros when there are none). */
  min: [number, number, number];
  max: [number, number, number];
}

/** `polyline`: flat, stride `dims`, grid units (Trace.idealPolyline(), or a path's cell centers). */
export function idealLineOf(polyline: Float64Array | Int32Array, dims: number): IdealLine {
  const count = polyline.length / dims;
  let xyz: Float32Array;
  if (dims === 3) {
    xyz = new Float32Array(polyline);
  } else {
    xyz = new Float32Array(count * 3);
    const axes = Math.min(dims, 3);
    for (let k = 0; k < count; k++) for (let a = 0; a < axes; a++) xyz[k * 3 + a] = polyline[k * dims + a]!;
  }
  if (count === 0) return { xyz, min: [0, 0, 0], max: [0, 0, 0] };
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
  return { xyz, min: [minX, minY, minZ], max: [maxX, maxY, maxZ] };
}
