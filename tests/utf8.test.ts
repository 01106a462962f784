// Text as UTF-8 into room the caller gives (web/core/utf8.ts): the page
// encodes a G-code program before sending it to its worker, and the core's
// withTextBytes encodes into wasm memory, both through it, and
// withTextBytesInSlices a part at a time (Utf8Encoding).
import { describe, expect, it } from 'vitest';
import { encodeUtf8Into, Utf8Encoding, utf8Bytes } from '../web/core/utf8.js';
import { loadCore, withTextBytes, withTextBytesInSlices } from '../web/core/wasm.js';
import { inTaskOfItsOwn } from './helpers.js';

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

describe('Utf8Encoding', () => {
  for (const [name, text] of Object.entries(TEXTS)) {
    it(`gives TextEncoder's bytes for ${name}, a unit or a few at a time, in one room of each size`, () => {
      for (const units of [1, 2, 3]) {
        const rooms = new Map<number, Uint8Array>();
        const asked: number[] = [];
        const encoding = new Utf8Encoding(text, (bytes) => {
          asked.push(bytes);
          if (!rooms.has(bytes)) rooms.set(bytes, new Uint8Array(bytes));
          return rooms.get(bytes)!;
        });
        let parts = 1;
        while (!encoding.advance(units)) parts++;
        const expected = new TextEncoder().encode(text);
        // A surrogate pair is encoded whole, never as two U+FFFD.
        expect(Array.from(rooms.get(asked.at(-1)!)!.subarray(0, encoding.written)), `${units} a part`).toEqual(Array.from(expected));
        expect(encoding.read).toBe(text.length);
        // The room asked before each part, one byte a unit until a part falls short.
        expect(asked).toHaveLength(parts);
        expect(new Set(asked)).toEqual(new Set(expected.length === text.length ? [text.length] : [text.length, 3 * text.length]));
      }
    });
  }
});

describe('withTextBytesInSlices', () => {
  // Parts of 262,144 units: a surrogate pair across the first one's end,
  // and a character of two bytes at the text's end, where the room of a
  // byte a unit falls short and the encoding starts over in room of three.
  const long = `${'1,2,3\n'.repeat(43_690)}1,2𝜋${'4,5,6\n'.repeat(50_000)}Ø\n`;

  it('puts a string into wasm memory as withTextBytes does, a slice at a time', async () => {
    expect(long.codePointAt(262_143)).toBe(0x1d70b);
    const core = await loadCore();
    for (const text of [...Object.values(TEXTS), long]) {
      const whole = withTextBytes(core, text, (bytes) => bytes.view().slice());
      const sliced = await withTextBytesInSlices(core, text, (bytes) => bytes.view().slice(), undefined, 0.05);
      expect(Array.from(sliced)).toEqual(Array.from(whole));
      expect(Array.from(sliced)).toEqual(Array.from(new TextEncoder().encode(text)));
    }
  });

  it('stops when its signal is aborted while it writes, before the bytes are used', async () => {
    const core = await loadCore();
    const cancel = new AbortController();
    let used = false;
    const writing = withTextBytesInSlices(core, long, () => (used = true), cancel.signal, 0.05);
    inTaskOfItsOwn(() => cancel.abort());
    await expect(writing).rejects.toMatchObject({ name: 'AbortError' });
    expect(used).toBe(false);
  });
});
