/**
 * Text as UTF-8 bytes, encoded natively (`encodeInto`) into room the caller
 * gives: the core's TextBytes in wasm memory, or an array the page hands to
 * its worker. No imports: the page's main bundle takes it without the core.
 */

const utf8 = new TextEncoder();

/**
 * Encodes `text` into room asked of `room`: first one byte a character,
 * enough for ASCII (G-code, numbers), else three, the most UTF-8 takes for
 * one UTF-16 unit (asked again only when the first fell short). Returns how
 * many bytes went into the last room given.
 */
export function encodeUtf8Into(text: string, room: (bytes: number) => Uint8Array): number {
  let written = utf8.encodeInto(text, room(text.length));
  if (written.read < text.length) written = utf8.encodeInto(text, room(3 * text.length));
  return written.written;
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
