/**
 * What the arc references share: the arc options read as the core reads
 * them (rust/src/arc/mod.rs, planes.rs), and Saleem's circle stepper
 * (rust/src/arc/circle_saleem.rs) in plain TypeScript, in the local
 * counter-clockwise frame: (a, b) = (u - u_c, s (v - v_c)) with s = -1 for
 * clockwise arcs, the mirror image.
 */
import { MAGNITUDE_LIMIT, stepCode, type ReferenceOptions } from './common.js';

const PLANE_AXES: Record<string, [number, number, number]> = { xy: [0, 1, 2], zx: [2, 0, 1], yz: [1, 2, 0] };

/** An arc request: the plane's axes (u, v, normal), the mirror sign, the center, local start and end, r². */
export interface Arc {
  axes: [number, number, number];
  /** +1 for G03 (ccw), -1 for G02 (cw). */
  sign: number;
  /** The center with the start's height on the normal axis. */
  center: number[];
  start: [number, number];
  end: [number, number];
  radiusSq: number;
  turns: number;
  /** to - from along the normal axis. */
  rise: number;
  /** Step code of a local move by d (-1, 0, +1) on local axis 0 or 1: `unit[axis][d + 1]`. */
  unit: [number[], number[]];
}

export function readArc(options: ReferenceOptions): Arc {
  const { from, to } = options;
  const axes = PLANE_AXES[(options.plane as string | undefined) ?? 'xy']!;
  const sign = options.dir === 'cw' ? -1 : 1;
  const [u, v, n] = axes;
  const given = options.center as readonly number[];
  const center = [0, 0, 0];
  center[u] = given[u]!;
  center[v] = given[v]!;
  center[n] = from[n]!;
  const local = (p: readonly number[]): [number, number] => [p[u]! - center[u]!, sign * (p[v]! - center[v]!)];
  const start = local(from);
  const radiusSq = start[0] * start[0] + start[1] * start[1];
  if (radiusSq >= MAGNITUDE_LIMIT ** 2) throw new RangeError('the references take radii below 2^25');
  const unitOn = (axis: number, s: number) => [-1, 0, 1].map((d) => stepCode(axis, s * d));
  return {
    axes,
    sign,
    center,
    start,
    end: local(to),
    radiusSq,
    turns: (options.turns as number | undefined) ?? 0,
    rise: to[n]! - from[n]!,
    unit: [unitOn(u, 1), unitOn(v, sign)],
  };
}

/** Per octant 1-8 (rust/src/arc/planes.rs, OCTANTS): fast axis and direction, slow axis and direction. */
const OCTANTS: readonly (readonly [number, number, number, number])[] = [
  [1, 1, 0, -1],
  [0, -1, 1, 1],
  [0, -1, 1, -1],
  [1, -1, 0, -1],
  [1, -1, 0, 1],
  [0, 1, 1, -1],
  [0, 1, 1, 1],
  [1, 1, 0, 1],
];

/** The octant ahead of local point (a, b): boundaries belong to the octant travel enters. */
function octantAhead(a: number, b: number): number {
  if (b >= 0 && a > b) return 1;
  if (a > 0 && b >= a) return 2;
  if (a <= 0 && b > -a) return 3;
  if (b > 0 && -a >= b) return 4;
  if (b <= 0 && a < b) return 5;
  if (a < 0 && b <= a) return 6;
  if (a >= 0 && -b > a) return 7;
  if (b < 0 && a >= -b) return 8;
  throw new RangeError('the circle never passes through its center');
}

const CIRCLE = 0;
const CORRECTION = 1;
const DONE = 2;

/**
 * Saleem's circle: in each octant the fast axis steps and the slow one
 * steps too when that leaves the smaller |a² + b² - r²| (eq. 7); the path
 * stops at the circle point nearest the end and steps straight to the end.
 */
export class Circle {
  a: number;
  b: number;
  readonly endA: number;
  readonly endB: number;
  readonly radiusSq: number;
  crossingsLeft: number;
  phase = CIRCLE;

  constructor(arc: Arc) {
    [this.a, this.b] = arc.start;
    [this.endA, this.endB] = arc.end;
    this.radiusSq = arc.radiusSq;
    this.crossingsLeft = arc.turns + 1;
  }

  copy(): Circle {
    return Object.assign(Object.create(Circle.prototype) as Circle, this);
  }

  /** The next local move as (da + 1) * 3 + (db + 1), or -1 at the end. */
  next(): number {
    if (this.phase === DONE) return -1;
    if (this.phase === CORRECTION) {
      if (this.a === this.endA && this.b === this.endB) {
        this.phase = DONE;
        return -1;
      }
      return this.correction();
    }
    const [fast, fastDir, slow, slowDir] = OCTANTS[octantAhead(this.a, this.b) - 1]!;
    const stayA = this.a + (fast === 0 ? fastDir : 0);
    const stayB = this.b + (fast === 1 ? fastDir : 0);
    const movedA = stayA + (slow === 0 ? slowDir : 0);
    const movedB = stayB + (slow === 1 ? slowDir : 0);
    const stay = stayA * stayA + stayB * stayB - this.radiusSq;
    const moved = movedA * movedA + movedB * movedB - this.radiusSq;
    const slowSteps = Math.abs(moved) < Math.abs(stay);
    const nextA = slowSteps ? movedA : stayA;
    const nextB = slowSteps ? movedB : stayB;
    // The ray from the center through the end: end × point turns from < 0 to >= 0.
    const crossNow = this.endA * this.b - this.endB * this.a;
    const crossNext = this.endA * nextB - this.endB * nextA;
    if (crossNow < 0 && crossNext >= 0) {
      this.crossingsLeft--;
      if (this.crossingsLeft === 0) {
        this.phase = CORRECTION;
        const distance = (p: number, q: number) => (this.endA - p) ** 2 + (this.endB - q) ** 2;
        if (distance(nextA, nextB) >= distance(this.a, this.b)) return this.correction();
      }
    }
    const move = (nextA - this.a + 1) * 3 + (nextB - this.b + 1);
    this.a = nextA;
    this.b = nextB;
    return move;
  }

  /** One step straight toward the end, each axis by its sign. */
  private correction(): number {
    const da = Math.sign(this.endA - this.a);
    const db = Math.sign(this.endB - this.b);
    this.a += da;
    this.b += db;
    return (da + 1) * 3 + (db + 1);
  }

  /** Steps left, by a dry run of a copy (Saleem's dummy procedure). */
  count(): number {
    const dry = this.copy();
    let n = 0;
    while (dry.next() >= 0) n++;
    return n;
  }
}

/** Step codes of the nine local moves, indexed by Circle.next()'s value. */
export function moveCodes(arc: Arc): number[] {
  const codes: number[] = [];
  for (let da = 0; da < 3; da++) for (let db = 0; db < 3; db++) codes.push(arc.unit[0][da]! | arc.unit[1][db]!);
  return codes;
}
