import { argumentError } from './guard.js';

/**
 * Options of a call into the core, as the JSON text the core parses; `field`
 * names the argument (the core names it too, e.g. 'request' or 'settings').
 * Whatever JSON cannot carry is refused here, naming the option it is in: a
 * BigInt, a function or a symbol (which JSON would leave out of an object,
 * so the core would run with its default instead: `tie: () => 'hold'` ran
 * with tie 'advance'), or options that contain themselves. An option set to
 * undefined is an option not given, as JSON leaves it out.
 */
export function encodeRequest(options: unknown, field = 'request'): string {
  let option = field;
  const named = typeof options === 'object' && options !== null && !Array.isArray(options);
  let json: string | undefined;
  try {
    json = JSON.stringify(options, function (this: unknown, key: string, value: unknown) {
      // The holder of a top-level option is the options object itself.
      if (named && this === options) option = key;
      if (typeof value === 'bigint') throw argumentError(option, `${value}n is a BigInt; give a number (Number(${value}n))`);
      if (typeof value === 'function' || typeof value === 'symbol') throw argumentError(option, `is a ${typeof value}; give a number, text, true or false, or a list`);
      // JSON writes a list's missing item as null, which the core would call null.
      if (value === undefined && Array.isArray(this)) {
        throw argumentError(option, Object.hasOwn(this, key) ? `item ${key} is undefined; give a number` : `item ${key} is a hole in a sparse array; give every item`);
      }
      // Typed arrays travel as plain lists; NaN and Infinity as text, so the
      // core reports them by name instead of JSON turning them into null.
      if (ArrayBuffer.isView(value)) return Array.from(value as unknown as ArrayLike<number>);
      if (typeof value === 'number' && !Number.isFinite(value)) return String(value);
      return value;
    });
  } catch (error) {
    if (error instanceof Error && error.name === 'VoxpathError') throw error;
    // A circular structure, or a getter or toJSON that throws. Either throws
    // before the replacer sees its key, so `option` would still name the
    // option before it: the one that fails is looked for.
    if (named) option = Object.keys(options).find((key) => failsToEncode(options, key)) ?? option;
    throw argumentError(option, `cannot be sent to the core as JSON: ${error instanceof Error ? error.message.split('\n')[0] : String(error)}`);
  }
  return json ?? 'null';
}

/** Whether reading `key` of `holder` or writing its value as JSON throws (a getter or a toJSON that fails, a cycle). */
function failsToEncode(holder: object, key: string): boolean {
  try {
    JSON.stringify((holder as Record<string, unknown>)[key]);
    return false;
  } catch {
    return true;
  }
}
