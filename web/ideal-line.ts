/**
 * A path's cell centers (or any flat polyline) as the scene draws an ideal
 * line: the form the core's Trace.idealLine() gives (IdealLine), for lines
 * voxpath makes itself, such as through a learner's points (in the worker);
 * and any ideal line's vertices taken from a point near where the view
 * looks, as the scene draws them (verticesFrom).
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

/**
 * How far (grid units, on any axis) the point the view looks at may move
 * from the grid point an ideal line's drawn vertices are taken from before
 * they are taken again from a point there (IdealPath.drawNear).
 */
export const REBASE_CELLS = 2 ** 12;

/** How far (grid units) the point looked at is from the drawn vertices' origin, at most: REBASE_CELLS on each axis. */
const LOOKED_AT_REACH = REBASE_CELLS * Math.sqrt(3);

/**
 * A 32-bit float's rounding, relative: WebGL rounds a vertex, and the
 * view's product with it, to about this share of its distance from the
 * drawn vertices' origin.
 */
const FLOAT_ROUNDING = 2 ** -24;

/**
 * Grid units from the origin within which a drawn vertex is off by under
 * 2^-10 of a cell (FLOAT_ROUNDING of it): a segment reaching no farther is
 * drawn exactly enough wherever the learner looks.
 */
const EXACT_REACH = 2 ** 14;

/**
 * Radians a segment may be drawn off as seen from the point looked at,
 * where it passes farther from it than LOOKED_AT_REACH: a quarter of a
 * pixel at the view's thousand-odd pixels of focal length.
 */
const ANGLE_TOLERANCE = 2 ** -12;

/** A segment split where it passes nearest the drawn vertices' origin (verticesFrom). */
export interface Split {
  /** Segment index k: from vertex k to vertex k + 1 of the ideal line. */
  segment: number;
  /** The point it is split at, grid units from the origin, exact (doubles). */
  point: [number, number, number];
}

/** An ideal line's vertices as drawn from an origin (verticesFrom). */
export interface DrawnVertices {
  /** Stride 3, grid units from the origin, 32-bit floats: the line's vertices with each split point after its segment's first. */
  xyz: Float32Array;
  /** The segments split, in order. */
  splits: readonly Split[];
}

/**
 * The vertices of `ideal` taken from the grid point `origin` (x, y, z) as
 * 32-bit floats, each from its exact value (xyz + rest from ideal.origin),
 * to draw from a group placed at `origin` while the point the view looks
 * at stays within REBASE_CELLS of it on every axis (IdealPath).
 *
 * Why: WebGL takes the vertices, and the view's translation to the group,
 * as 32-bit floats, rounded to FLOAT_ROUNDING of their size. From the
 * path's start, the far end of a path of a million cells was drawn a tenth
 * of a cell off the cells there, which are drawn from the point looked at
 * (cells.ts). From a point near where the learner looks, each vertex is
 * off by that share of its distance from there, which the eye sees as the
 * same tiny angle near and far. But a segment is drawn between its two
 * ends: one that passes near the origin between ends far from it (a long
 * line's middle) is off there as much as its ends. Such a segment is split
 * at its point nearest the origin, so each half has an end near where the
 * learner looks: one vertex more per such segment, not one per stretch of
 * a long line, whatever its length. A segment is split when it is off
 * there (its ends' errors, interpolated) by more than EXACT_REACH allows
 * near the point looked at, or farther out by more than ANGLE_TOLERANCE of
 * its distance from there.
 *
 * Taken again only when the point looked at moves REBASE_CELLS, not every
 * frame: between times a frame draws the same vertices. Its xyz is
 * `ideal.xyz` itself when `origin` is ideal.origin and nothing is split.
 */
export function verticesFrom(ideal: IdealLine, origin: readonly [number, number, number]): DrawnVertices {
  const { xyz, rest } = ideal;
  const count = xyz.length / 3;
  // ideal.origin - origin: whole numbers, exact in doubles.
  const [sx, sy, sz] = [0, 1, 2].map((a) => ideal.origin[a]! - origin[a]!) as [number, number, number];
  const moved = sx !== 0 || sy !== 0 || sz !== 0;
  // The box's farthest corner bounds every vertex's distance: when no
  // vertex can be off by more than EXACT_REACH allows, no segment is looked at.
  const corner = (a: number, shift: number) => Math.max(Math.abs(ideal.min[a]! + shift), Math.abs(ideal.max[a]! + shift));
  const seek = corner(0, sx) ** 2 + corner(1, sy) ** 2 + corner(2, sz) ** 2 > EXACT_REACH ** 2;
  if (!moved && !seek) return { xyz, splits: [] };
  const taken = moved ? new Float32Array(count * 3) : xyz;
  const splits: Split[] = [];
  // One pass, written out (no Math.hypot, no arrays per vertex): it runs
  // over a program's quarter of a million vertices in the frame that takes
  // them from a new origin, mostly before V8 has optimised it. A vertex
  // from `origin` is exact: a float and its rest add exactly in doubles.
  let ax = 0;
  let ay = 0;
  let az = 0;
  let a2 = 0;
  for (let i = 0; i < count * 3; i += 3) {
    const cx = sx + xyz[i]! + rest[i]!;
    const cy = sy + xyz[i + 1]! + rest[i + 1]!;
    const cz = sz + xyz[i + 2]! + rest[i + 2]!;
    if (moved) {
      taken[i] = cx;
      taken[i + 1] = cy;
      taken[i + 2] = cz;
    }
    const c2 = cx * cx + cy * cy + cz * cz;
    // Only a segment with a vertex past EXACT_REACH can be off by more than it allows.
    if (seek && i > 0 && Math.max(a2, c2) > EXACT_REACH ** 2) {
      const dx = cx - ax;
      const dy = cy - ay;
      const dz = cz - az;
      // Nearest the origin at a fraction t of the way along: an end (t at
      // or outside 0..1) is a vertex already, exact as drawn from here.
      const t = -(ax * dx + ay * dy + az * dz) / (dx * dx + dy * dy + dz * dz);
      if (t > 0 && t < 1) {
        const point: [number, number, number] = [ax + t * dx, ay + t * dy, az + t * dz];
        const beyondLookedAt = Math.max(0, Math.sqrt(point[0] ** 2 + point[1] ** 2 + point[2] ** 2) - LOOKED_AT_REACH);
        const off = ((1 - t) * Math.sqrt(a2) + t * Math.sqrt(c2)) * FLOAT_ROUNDING;
        if (off > EXACT_REACH * FLOAT_ROUNDING + ANGLE_TOLERANCE * beyondLookedAt) splits.push({ segment: i / 3 - 1, point });
      }
    }
    ax = cx;
    ay = cy;
    az = cz;
    a2 = c2;
  }
  if (splits.length === 0) return { xyz: taken, splits };
  // Each split point after its segment's first vertex, the runs between copied whole.
  const out = new Float32Array((count + splits.length) * 3);
  let from = 0;
  splits.forEach(({ segment, point }, n) => {
    const to = (segment + 1) * 3;
    out.set(taken.subarray(from, to), from + n * 3);
    out.set(point, to + n * 3);
    from = to;
  });
  out.set(taken.subarray(from), from + splits.length * 3);
  return { xyz: out, splits };
}

/**
 * Where a wide line's dashes fall on each drawn segment of `ideal` from
 * `origin` (its vertices and `splits` as verticesFrom gave them): its
 * distance along the path at its start and at its end, two per segment,
 * as LineMaterial reads them (instanceDistanceStart, instanceDistanceEnd),
 * dashes repeating every `periodCells`.
 *
 * Why: three.js's computeLineDistances adds up distances from the path's
 * start as 32-bit floats, which at a million cells along are multiples of
 * an eighth of a cell: the dashes there, a fifth of a cell long, ran
 * together. Here the distances are added up exactly (doubles) and each
 * segment's are given from its end nearer the origin (near where the
 * learner looks), as that distance less whole periods (small, so exact as
 * a float), and its other end that plus or minus its length: the pattern
 * is the path's own, continuous from segment to segment, and exact where
 * the learner looks; only far out is it rounded.
 */
export function dashDistances(ideal: IdealLine, origin: readonly [number, number, number], splits: readonly Split[], periodCells: number): Float32Array {
  const { xyz, rest } = ideal;
  // The drawn vertices, exact: each of the line's, and each split point after its segment's first.
  const exact: number[] = [];
  let next = 0;
  for (let k = 0; k < xyz.length / 3; k++) {
    for (let a = 0; a < 3; a++) exact.push(ideal.origin[a]! - origin[a]! + xyz[k * 3 + a]! + rest[k * 3 + a]!);
    if (splits[next]?.segment === k) exact.push(...splits[next++]!.point);
  }
  const segments = Math.max(0, exact.length / 3 - 1);
  const out = new Float32Array(segments * 2);
  /** Distance along the path from its start to drawn vertex j, cells. */
  let along = 0;
  for (let j = 0; j < segments; j++) {
    const [ax, ay, az, cx, cy, cz] = exact.slice(j * 3, j * 3 + 6) as [number, number, number, number, number, number];
    const length = Math.hypot(cx - ax, cy - ay, cz - az);
    const startNearer = Math.hypot(ax, ay, az) <= Math.hypot(cx, cy, cz);
    const anchor = (startNearer ? along : along + length) % periodCells;
    out[j * 2] = startNearer ? anchor : anchor - length;
    out[j * 2 + 1] = startNearer ? anchor + length : anchor;
    along += length;
  }
  return out;
}
