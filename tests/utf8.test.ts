// Text as UTF-8 into room the caller gives (web/core/utf8.ts): the page
// encodes a G-code program before sending it to its worker, and the core's
// withTextBytes encodes into wasm memory, both through it.
import { describe, expect, it } from 'vitest';
import { encodeUtf8Into, utf8Bytes } from '../web/core/utf8.js';

const TEXTS = {
  ascii: 'G21 G90\nG1 X1.5 Y-2 F1200\n',
  empty: '',
  'two- and three-byte characters': 'Ø 3 mm — 45°',
  'a four-byte character (a surrogate pair)': 'π/2 ≈ 𝜋/2',
  'a lone surrogate (encoded as U+FFFD)': 'x\uD800y',
};

describe('utf8Bytes', () => {
  for (const [name, text] of Object.entries(TEXTS)) {
    it(`gives TextEncoder's bytes for ${name}, in a buffer of their length`, () => {
      const bytes = utf8Bytes(text);
      expect(Array.from(bytes)).toEqual(Array.from(new TextEncoder().encode(text)));
      expect(bytes.buffer.byteLength).toBe(bytes.length);
    });
  }
});

describe('encodeUtf8Into', () => {
  it('asks for one byte a character, and for three only when that falls short', () => {
    const asked: number[] = [];
    const room = (bytes: number) => {
      asked.push(bytes);
      return new Uint8Array(bytes);
    };
    expect(encodeUtf8Into(TEXTS.ascii, room)).toBe(TEXTS.ascii.length);
    expect(asked).toEqual([TEXTS.ascii.length]);
    asked.length = 0;
    const wide = TEXTS['two- and three-byte characters'];
    expect(encodeUtf8Into(wide, room)).toBe(new TextEncoder().encode(wide).length);
    expect(asked).toEqual([wide.length, 3 * wide.length]);
  });
});
