/**
 * Arcs as chords (the G-code interpreter blog, Grbl's chord count),
 * stepping only: rust/src/arc/arc_segments.rs in plain TypeScript with each
 * chord stepped by the regions reference (lineAlgorithm's default). Chords
 * by segmentLength, or by tolerance (default 0.5); vertices are the arc
 * points at i/n of the sweep rounded as Rust rounds (halves away from
 * zero, a computed coordinate within its error of a half and a height
 * exactly), the last one the end point. With a rise it is the helix's
 * method segments.
 */
import { readArc } from './arc.js';
import { onlyOptions, roundHalfAwayWithin, roundRatioHalfAway, type ReferenceOptions } from './common.js';
import { regions } from './regions.js';

/** atan2 moved into [0, 2π): the blog's atan3. */
function atan3(v: number, u: number): number {
  const a = Math.atan2(v, u);
  return a < 0 ? a + 2 * Math.PI : a;
}

export function arcSegments(options: ReferenceOptions): Uint16Array {
  const { from, to, segmentLength, tolerance, method, ...arcOptions } = options;
  if (method !== undefined && method !== 'segments') throw new RangeError('arc-segments: method is the helix reference\'s');
  onlyOptions({ from, to, ...arcOptions }, ['center', 'dir', 'plane', 'turns'], 'arc-segments');
  const arc = readArc(options);
  const [u, v, normal] = arc.axes;
  const [s, e] = [arc.start, arc.end];
  // rust/src/arc/mod.rs, local_sweep_rad: atan2 of the exact cross and dot.
  const cross = s[0] * e[1] - s[1] * e[0];
  const dot = s[0] * e[0] + s[1] * e[1];
  let localSweep = Math.atan2(cross, dot);
  if (cross < 0 || (cross === 0 && dot > 0)) localSweep += 2 * Math.PI;
  localSweep += 2 * Math.PI * arc.turns;
  const sweep = arc.sign * localSweep;
  const c = arc.center;
  const start = atan3(from[v]! - c[v]!, from[u]! - c[u]!);
  const r = Math.sqrt(arc.radiusSq);
  const arcLength = Math.abs(sweep) * r;
  let n: number;
  if (segmentLength !== undefined) {
    n = Math.floor(arcLength / (segmentLength as number));
  } else {
    const t = (tolerance as number | undefined) ?? 0.5;
    n = Math.floor((0.5 * arcLength) / Math.sqrt(t * (2 * r - t)));
  }
  n = Math.max(n, 1);
  // A vertex coordinate within 8 units in the last place of
  // |center| + r·(1 + |θ|) below a half is that half (arc_segments.rs,
  // VERTEX_HALF_ULPS).
  const error = (center: number, theta: number) => (Math.abs(center) + r * (1 + Math.abs(theta))) * 8 * Number.EPSILON;
  const chords: Uint16Array[] = [];
  let previous = [...from];
  for (let i = 1; i <= n; i++) {
    let point: number[];
    if (i === n) {
      point = [...to];
    } else {
      const fraction = i / n;
      const theta = start + sweep * fraction;
      point = [0, 0, 0];
      point[u] = roundHalfAwayWithin(c[u]! + r * Math.cos(theta), error(c[u]!, theta));
      point[v] = roundHalfAwayWithin(c[v]! + r * Math.sin(theta), error(c[v]!, theta));
      point[normal] = from[normal]! + roundRatioHalfAway(BigInt(arc.rise) * BigInt(i), BigInt(n));
    }
    if (point.some((p, a) => p !== previous[a])) {
      chords.push(regions({ from: previous, to: point }));
      previous = point;
    }
  }
  const out = new Uint16Array(chords.reduce((sum, chord) => sum + chord.length, 0));
  let at = 0;
  for (const chord of chords) {
    out.set(chord, at);
    at += chord.length;
  }
  return out;
}
