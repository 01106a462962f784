/**
 * Checks of the arguments a JS caller hands the API, before any of them
 * reaches the core. wasm-bindgen converts what it is given without asking:
 * a number where text is due is read as a pointer into wasm memory, '3' + 1
 * is '31', 2.5 and undefined become 0 as a u32, a freed handle is a null
 * pointer. Every such argument is refused here with a VoxpathError naming
 * it, the way the core names a bad option. What the core checks itself (the
 * options inside a request, the text of a program) is left to the core.
 */
import { VoxpathError } from './errors.js';

/** A VoxpathError for the argument `field`: "field: detail". */
export function argumentError(field: string, detail: string): VoxpathError {
  return new VoxpathError(`${field}: ${detail}`, { field, detail });
}

/**
 * Text a user gave, as a message quotes it: a long one by its start and its
 * length, as the core's messages quote it (rust/src/text.rs), so that a
 * 100 KB flag is not said back whole.
 */
export function quoted(text: string): string {
  const chars = [...text];
  return chars.length <= 24 ? text : `${chars.slice(0, 16).join('')}... (${chars.length} characters)`;
}

/** A value as a message shows it: a number as itself, anything else with its kind. */
export function describeValue(value: unknown): string {
  if (value === undefined) return 'nothing';
  if (value === null) return 'null';
  if (typeof value === 'number') return String(value);
  if (typeof value === 'string') return `${JSON.stringify(value.length > 20 ? `${value.slice(0, 20)}…` : value)} (text)`;
  if (typeof value === 'bigint') return `${value}n (a BigInt)`;
  if (typeof value === 'function') return 'a function';
  const kind = typeof value === 'object' ? (value.constructor?.name ?? 'Object') : typeof value;
  // A DataView has no length, only bytes ("a DataView of length undefined").
  const length = value instanceof DataView ? ` of ${value.byteLength} bytes` : Array.isArray(value) || ArrayBuffer.isView(value) ? ` of length ${(value as ArrayLike<unknown>).length}` : '';
  // By sound: an Int32Array, an object, a Uint8Array.
  return `${/^[AEIO]/i.test(kind) ? 'an' : 'a'} ${kind === 'Object' ? 'object' : kind}${length}`;
}

/** A Promise, or any thenable: what a caller forgot to await. */
export function isPromiseLike(value: unknown): value is PromiseLike<unknown> {
  return (typeof value === 'object' || typeof value === 'function') && value !== null && typeof (value as { then?: unknown }).then === 'function';
}

/**
 * `value` as a whole number in min..max (both included), else a
 * VoxpathError naming `field`; `what` names the number ("step index").
 */
export function wholeNumber(field: string, value: unknown, min: number, max: number, what: string): number {
  if (typeof value !== 'number' || !Number.isInteger(value)) {
    throw argumentError(field, `${what} must be a whole number, got ${describeValue(value)}`);
  }
  if (value < min || value > max) {
    throw argumentError(field, max < min ? `${what} ${value}: there is none (the range is empty)` : `${what} ${value} is outside ${min}..${max}`);
  }
  return value;
}

/**
 * The half-open range of indices [from, to) inside 0..length, each end a
 * whole number named by its argument's name, from <= to. `what` names the
 * indices ("point index").
 */
export function indexRange(from: unknown, to: unknown, length: number, what: string): [number, number] {
  const start = wholeNumber('from', from, 0, length, what);
  return [start, wholeNumber('to', to, start, length, what)];
}

/**
 * `value` when it is a number other than NaN (an infinity allowed: "the
 * end"), else a VoxpathError naming `field`; `what` names the number
 * ("seconds"). wasm-bindgen reads null and [] as 0 for an f64 and throws a
 * TypeError on a BigInt.
 */
export function aNumber(field: string, value: unknown, what: string): number {
  if (typeof value !== 'number' || Number.isNaN(value)) {
    throw argumentError(field, `${what} must be a number, got ${describeValue(value)}`);
  }
  return value;
}

/** `value` as text, else a VoxpathError naming `field` (`what` says what text is expected). */
export function text(field: string, value: unknown, what: string): string {
  if (typeof value !== 'string') {
    const hint = ArrayBuffer.isView(value) ? '; decode the bytes first (new TextDecoder().decode(bytes))' : '';
    throw argumentError(field, `expected ${what} as a string, got ${describeValue(value)}${hint}`);
  }
  return value;
}

/**
 * Whether `value` is text: a string, or UTF-8 bytes in a Uint8Array (a Node
 * Buffer is one), which the core reads as they are and refuses if they are
 * not UTF-8.
 */
export function isTextOrUtf8(value: unknown): value is string | Uint8Array {
  // By its tag as well: a Uint8Array made in another realm (a vm context, a
  // frame) is not an instance of this one's.
  return typeof value === 'string' || value instanceof Uint8Array || Object.prototype.toString.call(value) === '[object Uint8Array]';
}

/**
 * `value` when it is text (isTextOrUtf8). Else a VoxpathError naming
 * `field` (`what` says what text is expected).
 */
export function textOrUtf8(field: string, value: unknown, what: string): string | Uint8Array {
  if (isTextOrUtf8(value)) return value;
  const hint = ArrayBuffer.isView(value) ? ' (text of another encoding: decode it first, with new TextDecoder(encoding).decode(bytes))' : '';
  throw argumentError(field, `expected ${what} as a string or as UTF-8 bytes in a Uint8Array, got ${describeValue(value)}${hint}`);
}

/**
 * `value` when it is an object (not an array) with each of `keys` defined: plain
 * data that an API function returned, handed back to be written out (a
 * Comparison to comparisonToCsv). Else a VoxpathError naming `field`, where
 * reading a field of null, a number or a Trace would throw a TypeError from
 * inside the writer; `what` names the data and its source ("a Comparison
 * (from compare())").
 */
export function plainData<T>(field: string, value: unknown, keys: readonly (keyof T & string)[], what: string): T {
  const isObject = typeof value === 'object' && value !== null && !Array.isArray(value) && !ArrayBuffer.isView(value);
  // A key set to undefined is as missing as one left out ({...c,
  // firstDifference: undefined}); a getter is not called (a freed Trace's throw).
  const absent = (key: string) => {
    if (!(key in (value as object))) return true;
    const own = Object.getOwnPropertyDescriptor(value, key);
    return own !== undefined && 'value' in own && own.value === undefined;
  };
  const missing = isObject ? keys.filter(absent) : [];
  if (!isObject || missing.length > 0) {
    const lacking = missing.length > 0 ? ` without ${missing.join(', ')}` : '';
    throw argumentError(field, `expected ${what}, got ${describeValue(value)}${lacking}`);
  }
  return value as T;
}

/** `value` when it is undefined or a function, else a VoxpathError naming `field`. */
export function optionalFunction<F extends (...args: never[]) => unknown>(field: string, value: unknown): F | undefined {
  if (value !== undefined && typeof value !== 'function') throw argumentError(field, `expected a function, got ${describeValue(value)}`);
  return value as F | undefined;
}

/** A decimal number as people write it: 12, -3.5, .5, 5., 1e6, +2. */
const DECIMAL = /^[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?$/;

/**
 * A number typed as text (a CLI flag, a URL key, a form field), blanks
 * around it ignored, or undefined when it is not a finite decimal number.
 * Number() alone reads '0x10' as 16, '0b11' as 3, '0o7' as 7, '' and ' ' as
 * 0, and 'Infinity' as a number; none of these is what a user of a grid
 * means, so each is refused rather than read.
 */
export function readDecimal(text: string): number | undefined {
  const trimmed = text.trim();
  if (!DECIMAL.test(trimmed)) return undefined;
  const value = Number(trimmed);
  return Number.isFinite(value) ? value : undefined;
}

/**
 * Whether text readDecimal reads writes a whole number: no digit but 0
 * after its point once its exponent has moved the point ('1.5e1' does,
 * '15e-1' does not). The number cannot tell: '0.99999999999999999' and
 * '1e-400' read as the whole numbers 1 and 0.
 */
function writesWholeNumber(text: string): boolean {
  const [mantissa = '', exponent = '0'] = text.trim().replace(/^[+-]/, '').split(/[eE]/);
  const [whole = '', fraction = ''] = mantissa.split('.');
  const point = whole.length + Number(exponent);
  return [...(whole + fraction)].every((digit, i) => i < point || digit === '0');
}

/**
 * Why `value`, read by readDecimal from `text` for a value of whole numbers
 * (a point, a count), is refused because the double does not say its text,
 * which the core, handed the double, cannot see: text that is not whole but
 * rounds to a whole number ('1e-400' reads as 0), or a whole number past
 * 2^53 - 1, where a double does not hold every whole number
 * (9007199254740993 reads as 9007199254740992). Quotes the text as typed.
 * Undefined when the double says the text, or is not whole (which the
 * option's range refuses in the core's words). The CLI refuses such a flag,
 * the page's link leaves such a key at its default.
 */
export function inexactWholeRefusal(text: string, value: number): string | undefined {
  if (!Number.isInteger(value)) return undefined;
  const typed = quoted(text.trim());
  if (!writesWholeNumber(text)) return `'${typed}' is not a whole number (as a double it rounds to ${value})`;
  if (!Number.isSafeInteger(value)) return `'${typed}' is past ±${Number.MAX_SAFE_INTEGER} (2^53 - 1), beyond which a double does not hold every whole number (it reads as ${value})`;
  return undefined;
}
