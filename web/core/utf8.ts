/**
 * Text as UTF-8 bytes, encoded natively (`encodeInto`) into room the caller
 * gives: the core's TextBytes in wasm memory, or an array the page hands to
 * its worker. No imports: the page's main bundle takes it without the core.
 */

const utf8 = new TextEncoder();

/**
 * A text encoded as UTF-8 a part at a time (`advance`), for a long text
 * whose encoding in one call would be one long task: in a Chromium worker,
 * `encodeInto` took 70 to 200 ms for the page's 19 MB of points, which a
 * Cancel waited for. The room is asked of `room` before each part: first
 * one byte a character, enough for ASCII (G-code, numbers), else three,
 * the most UTF-8 takes for one UTF-16 unit (asked only when the first falls
 * short, and the encoding then starts over in it). The same size asked
 * again is the same room, as a view made anew (a view into wasm memory is
 * detached when the memory grows, which another call may do between parts).
 */
export class Utf8Encoding {
  /** UTF-16 units of the text encoded so far, and the bytes they took. */
  read = 0;
  written = 0;
  readonly #text: string;
  readonly #room: (bytes: number) => Uint8Array;
  #roomBytes: number;

  constructor(text: string, room: (bytes: number) => Uint8Array) {
    this.#text = text;
    this.#room = room;
    this.#roomBytes = text.length;
  }

  /** Encodes up to `units` more UTF-16 units (one more rather than split a surrogate pair); whether the whole text is encoded now. */
  advance(units: number): boolean {
    const text = this.#text;
    let end = Math.min(text.length, this.read + Math.max(1, units));
    // The two halves of a pair encoded apart would each be written as U+FFFD.
    if (isHighSurrogate(text.charCodeAt(end - 1)) && isLowSurrogate(text.charCodeAt(end))) end += 1;
    const part = this.read === 0 && end === text.length ? text : text.slice(this.read, end);
    const { read, written } = utf8.encodeInto(part, this.#room(this.#roomBytes).subarray(this.written));
    if (read < part.length) {
      [this.#roomBytes, this.read, this.written] = [3 * text.length, 0, 0];
      return false;
    }
    this.read = end;
    this.written += written;
    return end === text.length;
  }
}

function isHighSurrogate(unit: number): boolean {
  return unit >= 0xd800 && unit <= 0xdbff;
}

function isLowSurrogate(unit: number): boolean {
  return unit >= 0xdc00 && unit <= 0xdfff;
}

/**
 * Encodes `text` into room asked of `room` (as Utf8Encoding asks it, the
 * whole text a part: a new room each time it is asked). Returns how many
 * bytes went into the last room given.
 */
export function encodeUtf8Into(text: string, room: (bytes: number) => Uint8Array): number {
  const encoding = new Utf8Encoding(text, room);
  while (!encoding.advance(Infinity));
  return encoding.written;
}

/**
 * `text` as UTF-8 in an array of its own, as long as its bytes. `encodeInto`
 * into a new array, not `encode`: in Chromium `encode` took 8.1 ms for the
 * G-code bench's 2.4 MB program, `encodeInto` 2.3 ms. Text that is not all
 * ASCII is copied out of the room of three bytes a character it was encoded
 * into, which would otherwise be held (and sent) with it.
 */
export function utf8Bytes(text: string): Uint8Array {
  let out = new Uint8Array(0);
  const written = encodeUtf8Into(text, (bytes) => (out = new Uint8Array(bytes)));
  return written === out.length ? out : out.slice(0, written);
}
