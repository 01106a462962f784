/**
 * What the plain TypeScript references share: the packed step code of the
 * core (rust/src/grid.rs: bit a when axis a moves, bit 8 + a when it moves
 * in the negative direction), moves seen along their direction of travel,
 * the finish rule of the algorithms that can drift, and Rust's rounding.
 *
 * The references keep integers in JS numbers, exact below 2^53. With every
 * |Δ| (and radius) below 2^25 the largest product one forms, walk6's
 * (2|Δ| + 1) · 2|Δ|, stays below 2^53; a reference refuses larger moves.
 */

/** Options a reference takes: the core's, for the defaults each reference says it supports. */
export interface ReferenceOptions {
  from: readonly number[];
  to: readonly number[];
  [option: string]: unknown;
}

/** A plain TypeScript implementation of one algorithm: the packed steps of its path. */
export type Reference = (options: ReferenceOptions) => Uint16Array;

/** |Δ| (and radius) below this, so that every product stays exact in a double. */
export const MAGNITUDE_LIMIT = 2 ** 25;

/** The step code moving `axis` by `direction` (-1, 0 or +1). */
export function stepCode(axis: number, direction: number): number {
  if (direction === 0) return 0;
  return direction > 0 ? 1 << axis : (1 << axis) | (1 << (8 + axis));
}

/** A move along its direction of travel: per axis the sign (+1 for an axis that stays) and |Δ|. */
export interface Mirror {
  dims: number;
  sign: number[];
  magnitude: number[];
  /** Step code of one unit toward the end on each axis. */
  unit: number[];
  longest: number;
}

export function mirror(from: readonly number[], to: readonly number[]): Mirror {
  if (from.length !== to.length) throw new RangeError('from and to differ in axes');
  const sign = from.map((f, a) => (to[a]! < f ? -1 : 1));
  const magnitude = from.map((f, a) => Math.abs(to[a]! - f));
  if (magnitude.some((m) => m >= MAGNITUDE_LIMIT)) throw new RangeError('the references take |Δ| below 2^25');
  return {
    dims: from.length,
    sign,
    magnitude,
    unit: sign.map((s, a) => stepCode(a, s)),
    longest: Math.max(...magnitude),
  };
}

/** The lowest-index axis with the largest |Δ| (rust/src/line/mod.rs, Mirror::major). */
export function major(m: Mirror): number {
  return m.magnitude.indexOf(m.longest);
}

/**
 * The finish rule (rust/src/line/mod.rs, Guard::apply): a passive axis never
 * passes its end coordinate and never falls so far behind that it cannot
 * reach it in the steps left. Returns whether the axis steps.
 */
export function guard(wants: boolean, unitsLeft: number, stepsLeft: number): boolean {
  if (wants && unitsLeft === 0) return false;
  if (!wants && unitsLeft >= stepsLeft && unitsLeft > 0) return true;
  return wants;
}

/** Rust's f64::round: halves away from zero (Math.round takes halves up). */
export function roundHalfAway(x: number): number {
  return x < 0 ? -Math.round(-x) : Math.round(x);
}

/**
 * rust/src/grid.rs, round_half_away_within: halves away from zero, x
 * within `error` below a half taken as that half (a computed value whose
 * exact one may be the half).
 */
export function roundHalfAwayWithin(x: number, error: number): number {
  const whole = Math.trunc(x);
  return Math.abs(x - whole) >= 0.5 - error ? whole + Math.sign(x) : whole;
}

/** rust/src/grid.rs, round_ratio_half_away: numerator / denominator (> 0) rounded, halves away from zero, exactly. */
export function roundRatioHalfAway(numerator: bigint, denominator: bigint): number {
  const size = numerator < 0n ? -numerator : numerator;
  const rounded = (2n * size + denominator) / (2n * denominator);
  return Number(numerator < 0n ? -rounded : rounded);
}

/** Refuses options a reference does not implement, so a test cannot pass on the wrong path. */
export function onlyOptions(options: ReferenceOptions, allowed: readonly string[], name: string): void {
  for (const key of Object.keys(options)) {
    if (!['from', 'to', ...allowed].includes(key)) throw new RangeError(`the ${name} reference does not take ${key}`);
  }
}
