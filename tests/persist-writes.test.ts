// When a tab writes its state to localStorage (web/state/persist.ts): only
// when it changed something it holds. Run in Node against a window, a
// document and storage areas made here, each test with persist.ts loaded
// afresh (its module keeps what the tab last wrote and read), and its
// throttled write flushed by the page's pagehide, never by waiting.
import { afterEach, beforeAll, beforeEach, describe, expect, it, vi } from 'vitest';
import { catalogue as coreCatalogue } from '../web/core/index.js';
import { type AppState, type Catalogue, DEFAULT_GCODE } from '../web/state/app-state.js';
import { Store } from '../web/state/store.js';

const STORAGE_KEY = 'voxpath.state';

/** A storage area that counts the writes of each key. */
class CountingStorage implements Storage {
  readonly #items = new Map<string, string>();
  readonly writes = new Map<string, number>();
  get length(): number {
    return this.#items.size;
  }
  key(index: number): string | null {
    return [...this.#items.keys()][index] ?? null;
  }
  getItem(key: string): string | null {
    return this.#items.get(key) ?? null;
  }
  setItem(key: string, value: string): void {
    this.writes.set(key, (this.writes.get(key) ?? 0) + 1);
    this.#items.set(key, value);
  }
  removeItem(key: string): void {
    this.#items.delete(key);
  }
  clear(): void {
    this.#items.clear();
  }
  /** Another tab's write: this tab's copy holds it, uncounted. */
  setByOtherTab(key: string, value: string): void {
    this.#items.set(key, value);
  }
}

/** A page's window and document, as much of them as persist.ts uses. */
function fakePage(local: CountingStorage) {
  const listeners = new Map<string, ((event: object) => void)[]>();
  const on = (type: string, listener: (event: object) => void) => listeners.set(type, [...(listeners.get(type) ?? []), listener]);
  const location = { pathname: '/', search: '', hash: '' };
  const window = {
    localStorage: local,
    sessionStorage: new CountingStorage(),
    location,
    history: {
      state: null,
      replaceState: (_state: unknown, _title: string, url: string) => {
        location.search = url.slice(url.indexOf('?'));
      },
    },
    addEventListener: on,
    get self() {
      return window;
    },
    get top() {
      return window;
    },
  };
  const document = { visibilityState: 'visible', addEventListener: on };
  const dispatch = (type: string, event: object = {}) => {
    for (const listener of listeners.get(type) ?? []) listener(event);
  };
  return { window, document, dispatch };
}

let catalogue: Catalogue;
let local: CountingStorage;
let page: ReturnType<typeof fakePage>;

beforeAll(async () => {
  catalogue = await coreCatalogue();
});

beforeEach(() => {
  vi.useFakeTimers();
  local = new CountingStorage();
  page = fakePage(local);
  vi.stubGlobal('window', page.window);
  vi.stubGlobal('document', page.document);
});

afterEach(() => {
  vi.useRealTimers();
  vi.unstubAllGlobals();
});

/** A tab loaded from the storage area and the address as they are now: persist.ts afresh, its store persisted. */
async function openTab() {
  vi.resetModules();
  const persist = await import('../web/state/persist.js');
  const store = new Store<AppState>(persist.loadState(catalogue));
  persist.persistState(store, catalogue, { onKept: () => {}, onOtherTab: () => {}, onBlocked: () => {} });
  return store;
}

/** How many times the tab wrote its state since `from` (the count then). */
const stateWrites = (from = 0) => (local.writes.get(STORAGE_KEY) ?? 0) - from;

/** The program storage holds (short enough for its part). */
const storedProgram = () => new URLSearchParams((JSON.parse(local.getItem(STORAGE_KEY)!) as { gcode: string }).gcode).get('gcode');

describe("a tab's writes of its state to storage (persist.ts)", () => {
  it('writes an edit, under a new edit stamp, at the throttled write or when the page is hidden', async () => {
    const store = await openTab();
    const [writes, stamp] = [stateWrites(), (JSON.parse(local.getItem(STORAGE_KEY)!) as { edit: string }).edit];
    store.update({ gcode: 'G21 G90\nG1 X3 Y4 F600\n' });
    page.dispatch('pagehide');
    expect(stateWrites(writes)).toBe(1);
    expect(storedProgram()).toBe('G21 G90\nG1 X3 Y4 F600\n');
    expect((JSON.parse(local.getItem(STORAGE_KEY)!) as { edit: string }).edit).not.toBe(stamp);
    // A step, not an input, is written too (a new visit comes back to it).
    store.update({ pointIndex: 2 });
    vi.runAllTimers();
    expect(stateWrites(writes)).toBe(2);
  });

  it('writes nothing after following another tab\'s write (it wrote back storage as this tab read it: landing after that tab\'s next write, it undid it)', async () => {
    const store = await openTab();
    const theirs = 'G21 G90\nG1 X3 Y4 F600\nG1 X7';
    const parts = JSON.parse(local.getItem(STORAGE_KEY)!) as Record<string, string>;
    const query = new URLSearchParams(parts.gcode);
    query.set('gcode', theirs);
    local.setByOtherTab(STORAGE_KEY, JSON.stringify({ ...parts, gcode: query.toString(), edit: 'other-tab.1' }));
    const writes = stateWrites();
    page.dispatch('storage', { key: STORAGE_KEY, storageArea: local });
    expect(store.state.gcode).toBe(theirs);
    page.dispatch('pagehide');
    vi.runAllTimers();
    expect(stateWrites(writes)).toBe(0);
  });

  it('writes nothing for an edit undone before its throttled write, of a program or of the move (an equal object)', async () => {
    const store = await openTab();
    const writes = stateWrites();
    const { gcode, options } = store.state;
    store.update({ gcode: `${gcode}G1 X9\n`, options: { ...options, to: [9, 7, 6] } });
    store.update({ gcode, options: { ...options } });
    page.dispatch('pagehide');
    expect(stateWrites(writes)).toBe(0);
  });

  it('writes nothing when loaded from storage as it is, and a link\'s program replacing the one typed (kept to bring back) when loaded from the link', async () => {
    const typed = 'G21 G90\nG1 X3 Y4 F600\n';
    (await openTab()).update({ mode: 'gcode', gcode: typed });
    page.dispatch('pagehide');
    page = fakePage(local);
    vi.stubGlobal('window', page.window);
    vi.stubGlobal('document', page.document);
    let writes = stateWrites();
    expect((await openTab()).state.gcode).toBe(typed);
    expect(stateWrites(writes)).toBe(0);
    page = fakePage(local);
    page.window.location.search = `?mode=gcode&gcode=${encodeURIComponent('G1 X1 F600\n')}`;
    vi.stubGlobal('window', page.window);
    vi.stubGlobal('document', page.document);
    writes = stateWrites();
    const linked = await openTab();
    expect([linked.state.gcode, linked.state.replacedProgram]).toEqual(['G1 X1 F600\n', typed]);
    expect(stateWrites(writes)).toBe(1);
    expect(storedProgram()).toBe('G1 X1 F600\n');
    expect(new URLSearchParams((JSON.parse(local.getItem(STORAGE_KEY)!) as { gcode: string }).gcode).get('replaced')).toBe(typed);
  });
});

describe('storage holding what this page never writes (persist.ts)', () => {
  it("reads a long text's piece count past the keys storage holds as no text kept, and writes over it (5e9 threw at load, leaving the page blank; 1e9 froze it reading absent pieces)", async () => {
    const typed = `G21 G90\n${'G1 X1 F600\nG1 X0\n'.repeat(200)}`;
    (await openTab()).update({ mode: 'gcode', gcode: typed });
    page.dispatch('pagehide');
    expect(local.getItem('voxpath.gcode')).toBe('1');
    // A removal of every piece the count names would run for minutes: stopped here, and the test fails.
    let removals = 0;
    const remove = local.removeItem.bind(local);
    local.removeItem = (key: string) => {
      removals += 1;
      if (removals > 10_000) throw new Error('removed more pieces than storage holds');
      remove(key);
    };
    for (const count of ['5000000000', '1e9', 'Infinity', '-1', '2.5']) {
      local.setByOtherTab('voxpath.gcode', count);
      page = fakePage(local);
      vi.stubGlobal('window', page.window);
      vi.stubGlobal('document', page.document);
      const store = await openTab();
      expect(store.state.gcode).toBe(DEFAULT_GCODE);
      const again = `${typed}G1 X2 ; ${count}\n`;
      store.update({ gcode: again });
      page.dispatch('pagehide');
      expect(local.getItem('voxpath.gcode')).toBe('1');
      expect(local.getItem('voxpath.gcode.0')).toBe(again);
    }
    expect(removals).toBeLessThan(100);
  });
});

describe('storage that cannot be read (storage-areas.ts)', () => {
  it("loads a link, and writes its address, where every read of storage throws, as Firefox's does from a damaged store (the page was left blank at load)", async () => {
    local.getItem = () => {
      throw new DOMException('NS_ERROR_FILE_CORRUPTED', 'NS_ERROR_FILE_CORRUPTED');
    };
    page.window.sessionStorage.getItem = local.getItem;
    page.window.location.search = '?mode=trace&algorithm=regions&from=0,0,0&to=4,3,2';
    const store = await openTab();
    expect(store.state.options.to).toEqual([4, 3, 2]);
    store.update({ pointIndex: 2 });
    page.dispatch('pagehide');
    expect(new URLSearchParams(page.window.location.search).get('step')).toBe('2');
  });
});

describe('storage probed (storage-areas.ts)', () => {
  it('once per page load, not at each throttled write (an empty key was read at every write to tell a store whose reads throw)', async () => {
    let probes = 0;
    const read = local.getItem.bind(local);
    local.getItem = (key: string) => {
      if (key === '') probes += 1;
      return read(key);
    };
    const store = await openTab();
    const writes = stateWrites();
    for (const to of [[1, 2, 3], [4, 5, 6], [7, 8, 9]]) {
      store.update({ options: { ...store.state.options, to } });
      vi.runAllTimers();
    }
    expect(stateWrites(writes)).toBe(3);
    expect(probes).toBe(1);
  });
});
