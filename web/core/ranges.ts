/**
 * A number held to the range its option declares in the catalogue
 * (IntegerRangeInfo, NumberRangeInfo, PerAxisInfo), in the words the core
 * says it with: the page's form checks each field as it is typed, and the
 * CLI each flag as it reads it, so that either can say what was typed
 * rather than the double the core would be handed (9007199254740993 reads
 * as 9007199254740992; 1e20 would be said back as 100000000000000000000).
 */
import { AXIS_NAMES } from './axes.js';
import type { IntegerRangeInfo, NumberRangeInfo, PerAxisInfo } from './pkg/voxpath.js';

/**
 * Why `value` is refused by its declaration, ending ", got " and `shown`
 * (the value as the user wrote it; the number by default): outside the
 * range, or not finite, in the words the core says it with (`mustBe`),
 * checked first as the core does (1e20 is told its range); else not whole
 * where the range takes whole values only (`notWhole`). Undefined when it
 * is neither.
 */
export function rangeRefusal(range: IntegerRangeInfo | NumberRangeInfo, value: number, shown = String(value)): string | undefined {
  const { min, max, mustBe, notWhole } = range;
  const exclusive = 'minExclusive' in range && range.minExclusive;
  const below = min !== undefined && (value < min || (exclusive && value === min));
  const above = max !== undefined && value > max;
  if (below || above || !Number.isFinite(value)) return `${mustBe ?? 'must be a finite number'}, got ${shown}`;
  return notWhole === undefined || Number.isInteger(value) ? undefined : `${notWhole}, got ${shown}`;
}

/**
 * rangeRefusal for a value of several axes, each named (as the core names
 * them): `values[a]` is axis a's, `shown[a]` as it was written. Undefined
 * when every value is taken.
 */
export function axesRefusal(range: IntegerRangeInfo | NumberRangeInfo, values: readonly number[], shown: readonly string[] = values.map(String)): string | undefined {
  for (const [a, value] of values.entries()) {
    const refused = rangeRefusal(range, value, shown[a]);
    if (refused !== undefined) return `${AXIS_NAMES[a] ?? 'a value'} ${refused}`;
  }
  return undefined;
}

/**
 * Why a per-axis setting as read (one number, or one per axis) is refused
 * by its declaration, in the order the core checks: a list of another
 * length than its axes (`10,0` was told y's range, then, once y was mended,
 * the count), then one number as rangeRefusal, one of several naming its
 * axis. `shown` as rangeRefusal's, one per value. Undefined when every
 * value is taken.
 */
export function perAxisRefusal(range: PerAxisInfo, read: number | readonly number[], shown?: readonly string[]): string | undefined {
  if (!Array.isArray(read)) return rangeRefusal(range, read as number, shown?.[0]);
  const values = read as readonly number[];
  if (values.length !== range.axes) return `${range.wrongCount}, got ${values.length}`;
  return axesRefusal(range, values, shown);
}
