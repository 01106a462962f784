/** Options of a call into the core, as the JSON text the core parses. */
export function encodeRequest(options: object): string {
  return JSON.stringify(options, (_key, value: unknown) => {
    // Typed arrays travel as plain lists; NaN and Infinity as text, so the
    // core reports them by name instead of JSON turning them into null.
    if (ArrayBuffer.isView(value)) return Array.from(value as unknown as ArrayLike<number>);
    if (typeof value === 'number' && !Number.isFinite(value)) return String(value);
    return value;
  });
}
