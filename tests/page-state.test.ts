// The page's state <-> URL query (the permalink and localStorage format),
// against the real algorithm catalogue of the built wasm package.
import { beforeAll, describe, expect, it } from 'vitest';
import { algorithms } from '../web/core/index.js';
import type { AlgorithmInfo } from '../web/core/types.js';
import { type AppState, PAGE_OPTIONS, defaultAlgorithm, defaultState, traceOptions } from '../web/state/app-state.js';
import { stateFromQuery, stateToQuery } from '../web/state/query.js';

let catalogue: AlgorithmInfo[];
beforeAll(async () => {
  catalogue = await algorithms();
});

describe('page state in the URL query', () => {
  it('writes the default state as a readable link', () => {
    const state = defaultState(defaultAlgorithm(catalogue));
    expect(stateToQuery(state)).toBe('algorithm=regions&from=0,0,0&to=10,7,6&tie=advance&step=0&speed=2');
  });

  it('reads back every persisted key, and starts paused', () => {
    const state: AppState = {
      algorithm: 'regions',
      options: { from: [-3, 4, 2_000_000_000], to: [0, -7, 1], tie: 'hold' },
      pointIndex: 7,
      playing: true,
      speed: 16,
    };
    expect(stateFromQuery(stateToQuery(state), catalogue)).toEqual({ ...state, playing: false });
  });

  it('keeps out-of-range and fractional coordinates for the core to judge', () => {
    const state = stateFromQuery('from=0,0.5,0&to=2000000000,7,6', catalogue)!;
    expect(state.options).toEqual({ from: [0, 0.5, 0], to: [2_000_000_000, 7, 6], tie: 'advance' });
  });

  it('fills what a link leaves out with defaults, not with the last visit', () => {
    const state = stateFromQuery('?from=1,2,3', catalogue)!;
    expect(state).toEqual({ ...defaultState(defaultAlgorithm(catalogue)), options: { from: [1, 2, 3], to: [10, 7, 6], tie: 'advance' } });
  });

  it('replaces unusable values with defaults', () => {
    const state = stateFromQuery('from=a,b,c&to=1,,2&tie=sometimes&step=-1&speed=3', catalogue)!;
    expect(state).toEqual(defaultState(defaultAlgorithm(catalogue)));
  });

  it('is no state at all when the query has none of its keys', () => {
    expect(stateFromQuery('', catalogue)).toBeUndefined();
    expect(stateFromQuery('utm_source=mail', catalogue)).toBeUndefined();
  });

  it('leaves the options the page sets itself to the page', () => {
    const state = stateFromQuery('from=0,0,0&to=1,1,1&maxSteps=5', catalogue)!;
    expect(state.options).not.toHaveProperty('maxSteps');
    expect(traceOptions(state)).toEqual({ algorithm: 'regions', from: [0, 0, 0], to: [1, 1, 1], tie: 'advance', ...PAGE_OPTIONS });
  });
});
