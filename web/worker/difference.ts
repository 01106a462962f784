/**
 * Where two traces of the same move part, for compare mode: the first point
 * index where they differ (with the core's explain() of each side's step
 * there) and the cells only one of them visits.
 *
 * The cell sets are compared by sorting packed keys: each cell's coordinates,
 * offset to the union's smallest, packed into one 64-bit integer with as many
 * bits per axis as that axis's span needs. Sorting 1,000,000 keys takes a
 * fraction of a second here, in the worker.
 */
import type { Trace } from '../core/index.js';
import type { TraceDifference } from './protocol.js';

/** Bits per axis so that every coordinate of both paths, less `min`, fits; throws past 64 in all. */
function packing(a: Int32Array, b: Int32Array, dims: number): { min: number[]; bits: bigint[] } {
  const min = Array<number>(dims).fill(Infinity);
  const max = Array<number>(dims).fill(-Infinity);
  for (const points of [a, b]) {
    for (let o = 0; o < points.length; o += dims) {
      for (let d = 0; d < dims; d++) {
        const c = points[o + d]!;
        if (c < min[d]!) min[d] = c;
        if (c > max[d]!) max[d] = c;
      }
    }
  }
  const bits = min.map((lo, d) => BigInt(Math.max(1, Math.ceil(Math.log2(max[d]! - lo + 1)))));
  if (bits.reduce((s, b) => s + b, 0n) > 64n) throw new RangeError('the two paths span too far to compare cell by cell');
  return { min, bits };
}

function keys(points: Int32Array, dims: number, pack: { min: number[]; bits: bigint[] }): BigUint64Array {
  const out = new BigUint64Array(points.length / dims);
  for (let k = 0; k < out.length; k++) {
    let key = 0n;
    for (let d = 0; d < dims; d++) key = (key << pack.bits[d]!) | BigInt(points[k * dims + d]! - pack.min[d]!);
    out[k] = key;
  }
  return out;
}

/** Index of `key` in the sorted `sorted`, or -1. */
function find(sorted: BigUint64Array, key: bigint): number {
  let lo = 0;
  let hi = sorted.length - 1;
  while (lo <= hi) {
    const mid = (lo + hi) >> 1;
    const v = sorted[mid]!;
    if (v === key) return mid;
    if (v < key) lo = mid + 1;
    else hi = mid - 1;
  }
  return -1;
}

/** Cells of `points` (path order, each once) whose key is not among `other`'s. */
function cellsOnlyIn(points: Int32Array, own: BigUint64Array, other: BigUint64Array, dims: number): Int32Array {
  const sortedOther = other.slice().sort();
  const emitted = new Set<bigint>();
  const out: number[] = [];
  for (let k = 0; k < own.length; k++) {
    const key = own[k]!;
    if (emitted.has(key) || find(sortedOther, key) >= 0) continue;
    emitted.add(key);
    for (let d = 0; d < dims; d++) out.push(points[k * dims + d]!);
  }
  return Int32Array.from(out);
}

/** How traces a and b (same dims) differ; see TraceDifference. */
export function traceDifference(a: Trace, b: Trace): TraceDifference {
  if (a.dims !== b.dims) throw new RangeError(`cannot compare a ${a.dims}-axis path with a ${b.dims}-axis one`);
  const dims = a.dims;
  const pa = a.pointsInRange(0, a.steps + 1);
  const pb = b.pointsInRange(0, b.steps + 1);
  let first: number | null = null;
  const common = Math.min(a.steps, b.steps) + 1;
  for (let k = 0; k < common && first === null; k++) {
    for (let d = 0; d < dims; d++) {
      if (pa[k * dims + d] !== pb[k * dims + d]) {
        first = k;
        break;
      }
    }
  }
  if (first === null && a.steps !== b.steps) first = common;
  const why = (t: Trace) => (first !== null && first > 0 && first - 1 < t.steps ? t.explain(first - 1) : null);
  const pack = packing(pa, pb, dims);
  const ka = keys(pa, dims, pack);
  const kb = keys(pb, dims, pack);
  return {
    firstPointIndex: first,
    whyA: why(a),
    whyB: why(b),
    onlyInA: cellsOnlyIn(pa, ka, kb, dims),
    onlyInB: cellsOnlyIn(pb, kb, ka, dims),
  };
}
