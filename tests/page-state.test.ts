// The page's state <-> URL query (the permalink and localStorage format),
// against the real algorithm catalogue of the built wasm package.
import { readFileSync } from 'node:fs';
import { beforeAll, describe, expect, it } from 'vitest';
import { catalogue as coreCatalogue, compare, trace } from '../web/core/index.js';
import { rejection } from './helpers.js';
import {
  ANOTHER_TABS_POINTS,
  ANOTHER_TABS_PROGRAM,
  type AppState,
  type Catalogue,
  PAGE_OPTIONS,
  axisChoices,
  axisCount,
  comparableWith,
  comparedRequests,
  comparedValues,
  defaultAlgorithm,
  defaultOther,
  defaultState,
  experimentAlgorithm,
  machineSpecs,
  offeredAlgorithms,
  pointsBroughtBack,
  pointsReplaced,
  programBroughtBack,
  programReplaced,
  sharedOptionSpecs,
  traceOptions,
  OptionSetter,
  type OptionValue,
  withAxes,
  withOption,
} from '../web/state/app-state.js';
import { GCODE_URL_LIMIT, type LinkNotes, STATE_KEYS, roundCamera, stateFromQuery, stateToQuery } from '../web/state/query.js';
import { carriedOptions } from '../web/form/algorithm-inputs.js';
import { OfferSide } from '../web/state/offer-side.js';
import { readPerAxis } from '../web/form/options-form.js';
import { otherTabEdits, otherTabNote } from '../web/state/persist.js';

let catalogue: Catalogue;
const url = { gcodeLimit: GCODE_URL_LIMIT };
const info = (id: string) => catalogue.algorithms.find((a) => a.id === id)!;
const first = () => defaultState(defaultAlgorithm(catalogue.algorithms), catalogue.algorithms);

beforeAll(async () => {
  catalogue = await coreCatalogue();
});

describe('page state in the URL query', () => {
  it('writes the default state as a readable link', () => {
    expect(stateToQuery(first(), url)).toBe('mode=trace&algorithm=regions&from=0,0,0&to=10,7,6&step=0&speed=2&view=3d&decision3d=0');
  });

  it('names what a link says that it cannot read, each left at its default (they were taken without a word)', () => {
    const notes: LinkNotes = { unread: [], fitted: [] };
    const state = stateFromQuery(`mode=tracee&algorithm=regionz&from=5,abc,2&to=${'9'.repeat(3000)},1,1&tie=sideways&view=4d&step=-1&camera=1,2`, catalogue, notes)!;
    expect(notes.fitted).toEqual([]);
    expect(notes.unread).toEqual(['mode=tracee', 'algorithm=regionz', 'from=5,abc,2', 'to=9999999999999999... (3004 characters)', 'tie=sideways', 'step=-1', 'view=4d', 'camera=1,2']);
    expect([state.mode, state.algorithm, state.options.from, state.options.tie]).toEqual(['trace', 'regions', [0, 0, 0], first().options.tie]);
    // A step it reads is kept for the note, which says once traced whether it is past the path's end.
    expect(notes.step).toBeUndefined();
    const read: LinkNotes = { unread: [], fitted: [] };
    stateFromQuery('from=0,0,0&to=10,7,6&step=500', catalogue, read);
    expect(read).toEqual({ unread: [], fitted: [], step: 500 });
    // Every link the page writes is read whole.
    for (const written of [first(), { ...first(), mode: 'compare' as const, other: 'bresenham3d', layout: 'side' as const }, { ...first(), mode: 'gcode' as const }, { ...first(), mode: 'experiment' as const }]) {
      const none: LinkNotes = { unread: [], fitted: [] };
      stateFromQuery(stateToQuery(written, url), catalogue, none);
      expect([none.unread, none.fitted, none.repeated]).toEqual([[], [], undefined]);
    }
  });

  it('leaves at its default, named in the note as typed, a whole-number key whose text a double does not hold (to=9007199254740993 was read as 9007199254740992, step=1e-400 as 0)', () => {
    const notes: LinkNotes = { unread: [], fitted: [] };
    const state = stateFromQuery('from=1e-400,0,0&to=9007199254740993,1,1&step=1e-400', catalogue, notes)!;
    expect(notes.unread).toEqual(['from=1e-400,0,0', 'to=9007199254740993,1,1', 'step=1e-400']);
    expect([state.options.from, state.options.to, state.pointIndex]).toEqual([first().options.from, first().options.to, 0]);
    // The machine's whole numbers (microsteps) and the experiment's (count) too; a real number (stepsPerMm) is as the double reads it.
    const machine: LinkNotes = { unread: [], fitted: [] };
    const gcode = stateFromQuery('mode=gcode&stepsPerMm=9007199254740993&microsteps=9007199254740993,1,1&count=0.99999999999999999', catalogue, machine)!;
    expect(machine.unread).toEqual(['microsteps=9007199254740993,1,1', 'count=0.99999999999999999']);
    expect(gcode.machine.stepsPerMm).toBe(9007199254740992);
    // Whole numbers as written, up to 2^53 - 1, and fractions (the core judges them), are read.
    const read: LinkNotes = { unread: [], fitted: [] };
    const kept = stateFromQuery('from=1.5e1,-9007199254740991,0&to=2.5,0,0&step=3e0', catalogue, read)!;
    expect(read.unread).toEqual([]);
    expect([kept.options.from, kept.options.to, kept.pointIndex]).toEqual([[15, -9007199254740991, 0], [2.5, 0, 0], 3]);
  });

  it('says which value it read of a key given more than once with another value: the first (a later "&to=9,9,9" added by hand was dropped without a word)', () => {
    const notes: LinkNotes = { unread: [], fitted: [] };
    const state = stateFromQuery(`from=0,0,0&to=5,5,5&tie=hold&to=9,9,9&to=${'8'.repeat(40)},1,1&to=9,9,9&tie=hold&stepsPerMm=80&stepsPerMm=10`, catalogue, notes)!;
    expect(state.options.to).toEqual([5, 5, 5]);
    expect(state.options.tie).toBe('hold');
    expect(notes.repeated).toEqual(['to=5,5,5 (not 9,9,9, 8888888888888888... (44 characters))', 'stepsPerMm=80 (not 10)']);
    expect(notes.unread).toEqual([]);
    // Keys the page does not read are not its to judge.
    const unknown: LinkNotes = { unread: [], fitted: [] };
    stateFromQuery('to=5,5,5&utm_source=a&utm_source=b', catalogue, unknown);
    expect(unknown.repeated).toBeUndefined();
  });

  it('reads back every persisted key of each mode, and starts paused', () => {
    const camera = { position: [12.5, -30, 20] as [number, number, number], target: [5, 3.5, 3] as [number, number, number], zoom: 1.25 };
    const states: AppState[] = [
      { ...first(), options: { from: [-3, 4, 2_000_000_000], to: [0, -7, 1], tie: 'hold', gcd: true }, pointIndex: 7, playing: true, speed: 16, camera, decision3d: true },
      { ...first(), algorithm: 'helix', options: { from: [10, 0, 0], to: [10, 0, 24], center: [0, 0, 0], dir: 'ccw', plane: 'xy', method: 'segments', tolerance: 0.25 } },
      { ...first(), mode: 'compare', other: 'bresenham3d', layout: 'side', options: { from: [0, 0, 0], to: [10, 7, 6], tie: 'hold' }, projection: '2d', legendFolded: true, embed: true },
      { ...first(), mode: 'gcode', gcode: 'G1 X10 Y5 F600\nG2 X20 Y5 I5 J0\n', machine: { stepAngle: 1.8, microsteps: 8, pitch: 2, lineAlgorithm: 'bresenham3d', arcAlgorithm: 'arc-segments' }, pointIndex: 3, slowdown: 100 },
      { ...first(), mode: 'experiment', experiment: { count: 20, seed: 7, maxCoordinate: 50 } },
    ];
    for (const state of states) {
      const back = stateFromQuery(stateToQuery(state, url), catalogue)!;
      const mode = state.mode;
      expect(back.mode).toBe(mode);
      if (mode === 'trace' || mode === 'compare') expect(back.options).toEqual(state.options);
      if (mode === 'compare') expect([back.other, back.layout]).toEqual([state.other, state.layout]);
      if (mode === 'gcode') expect([back.gcode, back.machine, back.slowdown]).toEqual([state.gcode, { ...state.machine }, state.slowdown]);
      if (mode === 'experiment') expect(back.experiment).toEqual(state.experiment);
      if (mode !== 'experiment') expect([back.pointIndex, back.speed, back.projection, back.decision3d, back.camera, back.legendFolded]).toEqual([state.pointIndex, state.speed, state.projection, state.decision3d, state.camera, state.legendFolded]);
      expect(back.embed).toBe(state.embed);
      expect(back.playing).toBe(false);
    }
  });

  it("names every parameter a link can hold in the README's table of them", () => {
    // The rows' first cells: `mode`, `from`, `to`, `center`, ...
    const readme = readFileSync(new URL('../README.md', import.meta.url), 'utf8');
    const table = readme.slice(readme.indexOf('The parameters the page reads:'), readme.indexOf('A link starts paused'));
    const documented = new Set(table.split('\n').flatMap((row) => [...(row.match(/^\| ([^|]*)\|/)?.[1] ?? '').matchAll(/`(\w+)`/g)].map((m) => m[1]!)));
    const states: AppState[] = [
      { ...first(), options: { from: [0, 0, 0], to: [10, 7, 6], tie: 'hold', gcd: true }, learnerPoints: '0,0,0', follow: true, camera: { position: [1, 2, 3], target: [0, 0, 0], zoom: 1 }, embed: true, explain: false },
      { ...first(), mode: 'compare', other: 'bresenham3d', layout: 'side' },
      { ...first(), mode: 'gcode', gcode: 'G1 X1 F600', machine: { stepsPerMm: 80, acceleration: 50, maxRate: 3000, junctionDeviation: 0.02, maxStepRate: 30000 }, slowdown: 10 },
      { ...first(), mode: 'gcode', machine: { stepAngle: 1.8, microsteps: 8, pitch: 2, lineAlgorithm: 'bresenham3d', arcAlgorithm: 'arc-segments' } },
      { ...first(), mode: 'experiment', experiment: { count: 20, seed: 7, maxCoordinate: 50, dims: 3 } },
    ];
    const written = new Set(states.flatMap((state) => [...new URLSearchParams(stateToQuery(state, url)).keys()]));
    const settings = [...catalogue.algorithms.flatMap((a) => a.options), ...machineSpecs(catalogue)].map((o) => o.name).filter((name) => !(name in PAGE_OPTIONS));
    expect([...new Set([...written, ...settings])].filter((name) => !documented.has(name))).toEqual([]);
  });

  it("never names an algorithm's option as one of the page's own keys, which would shadow it", () => {
    const names = catalogue.algorithms.flatMap((a) => a.options.map((o) => o.name));
    expect(names.filter((name) => STATE_KEYS.includes(name))).toEqual([]);
  });

  it('keeps a long program out of the URL, and reads it from a query that holds it (as stored states did before long texts had keys of their own)', () => {
    const gcode = 'G1 X1\n'.repeat(GCODE_URL_LIMIT);
    const state = { ...first(), mode: 'gcode' as const, gcode };
    expect(stateToQuery(state, url)).not.toContain('gcode=');
    expect(stateFromQuery(stateToQuery(state, { gcodeLimit: Infinity }), catalogue)!.gcode).toBe(gcode);
  });

  it('rounds a camera to what the link writes, and ignores a malformed one', () => {
    const camera = roundCamera({ position: [1.234567, 2, 3], target: [0, 0, 0.00004], zoom: 1 });
    expect(camera).toEqual({ position: [1.2346, 2, 3], target: [0, 0, 0], zoom: 1 });
    expect(stateFromQuery('camera=1,2,3', catalogue)!.camera).toBeNull();
    expect(stateFromQuery('camera=1,2,3,4,5,6,0', catalogue)!.camera).toBeNull();
    // Out of reach (a view drawn blank), or looking at itself: framed by the page instead.
    for (const camera of ['1e308,1e308,1e308,0,0,0,1', '1,2,3,0,0,0,1e7', '1,2,3,1,2,3,1']) {
      expect(stateFromQuery(`camera=${camera}`, catalogue)!.camera, camera).toBeNull();
    }
    expect(stateFromQuery('camera=1e9,2,3,0,0,0,1e6', catalogue)!.camera).toEqual({ position: [1e9, 2, 3], target: [0, 0, 0], zoom: 1e6 });
  });

  it("declares every integer option's range, where it has one, within what the core reads exactly: the form refuses what the core does, and keeps it out of the link (a seed of 1e20 went into the link, and the core refused it)", () => {
    const specs = [...catalogue.algorithms.flatMap((a) => a.options), ...catalogue.experiments.flatMap((e) => e.options)];
    const ranged = specs.flatMap((spec) => (spec.kind.type === 'integer' && (spec.kind.min !== undefined || spec.kind.max !== undefined) ? [{ name: spec.name, ...spec.kind }] : []));
    expect(ranged.map((r) => r.name)).toContain('seed');
    for (const { name, min, max } of ranged) {
      expect([name, min !== undefined && Math.abs(min) < 9e15, max !== undefined && Math.abs(max) < 9e15]).toEqual([name, true, true]);
    }
  });

  it('keeps out-of-range and fractional coordinates for the core to judge', () => {
    const state = stateFromQuery('from=0,0.5,0&to=2000000000,7,6', catalogue)!;
    expect(state.options).toEqual({ from: [0, 0.5, 0], to: [2_000_000_000, 7, 6] });
  });

  it('fills what a link leaves out with defaults, not with the last visit', () => {
    const state = stateFromQuery('?from=1,2,3', catalogue)!;
    expect(state).toEqual({ ...first(), options: { from: [1, 2, 3], to: [10, 7, 6] } });
  });

  it('replaces unusable values with defaults', () => {
    const state = stateFromQuery('from=a,b,c&to=1,,2&tie=sometimes&step=-1&speed=3&slowdown=7&mode=dance&view=4d&decision3d=yes', catalogue)!;
    expect(state).toEqual(first());
    // An unreadable steps/mm keeps the default machine (it left none: "stepsPerMm: missing").
    expect(stateFromQuery('mode=gcode&stepsPerMm=80,abc', catalogue)!.machine).toEqual(first().machine);
    expect(stateFromQuery('mode=gcode&stepAngle=1.8&microsteps=8&pitch=2', catalogue)!.machine).not.toHaveProperty('stepsPerMm');
  });

  it('reads decimal numbers only: 0x10, 0b11, 0o7, Infinity and blanks are unusable, not 16, 3, 7', () => {
    expect(stateFromQuery('from=0x10,0b11,0o7&to=Infinity,%20,6&step=0x2', catalogue)).toEqual(first());
    expect(stateFromQuery('from=1e1,-.5,+2&to=%2010%20,7,6', catalogue)!.options).toEqual({ from: [10, -0.5, 2], to: [10, 7, 6] });
  });

  it("reads the machine form's per-axis fields the same way", () => {
    expect([readPerAxis('0x50'), readPerAxis('80,0b1,400'), readPerAxis('80,,400'), readPerAxis('Infinity')]).toEqual([null, null, null, null]);
    expect([readPerAxis(' 80 '), readPerAxis('80, 80, 4e2'), readPerAxis('  ')]).toEqual([80, [80, 80, 400], undefined]);
  });

  it('is no state at all when the query has none of its keys', () => {
    expect(stateFromQuery('', catalogue)).toBeUndefined();
    expect(stateFromQuery('utm_source=mail', catalogue)).toBeUndefined();
  });

  it('compares only algorithms that can be compared, and runs the experiment with a line algorithm', () => {
    // A link (or an old visit) pairing a circle with a line algorithm gets the circle's partner.
    expect(stateFromQuery('mode=compare&algorithm=circle&other=greedy', catalogue)!.other).toBe('arc-segments');
    expect(stateFromQuery('mode=compare&algorithm=regions&other=walk6', catalogue)!.other).toBe('walk6');
    // One naming the first algorithm again gets its partner too, as the picker gives.
    expect(stateFromQuery('mode=compare&algorithm=regions&other=regions', catalogue)!.other).toBe('greedy');
    expect(stateFromQuery('mode=compare&algorithm=circle&other=circle', catalogue)!.other).toBe('arc-segments');
    // random-lines traces lines: with an arc algorithm the experiment runs
    // the default one, and the arc stays the state's, for Trace to come back to.
    const arcLink = stateFromQuery('mode=experiment&algorithm=circle', catalogue)!;
    expect([arcLink.algorithm, experimentAlgorithm(arcLink, catalogue).id]).toEqual(['circle', 'regions']);
    expect(experimentAlgorithm(stateFromQuery('mode=experiment&algorithm=dda', catalogue)!, catalogue).id).toBe('dda');
    expect(offeredAlgorithms('experiment', catalogue).map((a) => a.family)).not.toContain('arc');
    expect(offeredAlgorithms('trace', catalogue)).toEqual(catalogue.algorithms);
    // Every algorithm's default partner is one it can be compared with, and
    // another algorithm; none is comparable with itself but the helix, by its
    // method, whose partner it is (no other algorithm takes a move that rises).
    for (const a of catalogue.algorithms) {
      const other = defaultOther(a, catalogue.algorithms);
      expect(comparableWith(a, catalogue.algorithms), a.id).toContain(other);
      if (a.id === 'helix') {
        expect(other, a.id).toBe(a);
        continue;
      }
      expect(comparableWith(a, catalogue.algorithms), a.id).not.toContain(a);
      expect(other.id, a.id).not.toBe(a.id);
    }
  });

  it.each([
    ['helix against itself, chords first', 'helix', 'method=segments&segmentLength=6'],
    ['helix against itself, saleem first, a chord option typed', 'helix', 'tolerance=0.2'],
    ['helix (saleem) against arc-segments, a chord option typed', 'arc-segments', 'segmentLength=6'],
    ['helix (saleem) against the circle, tie typed', 'circle', 'tie=advance'],
  ])('sends the two sides what the core\'s compare() gives them: %s', async (_, other, typed) => {
    const query = `mode=compare&algorithm=helix&other=${other}&from=20,0,0&to=0,20,0&center=0,0,0&${typed}`;
    const state = stateFromQuery(query, catalogue)!;
    const sides = comparedRequests(state, catalogue.algorithms);
    const traces = await Promise.all(sides.map((side) => trace(side.options)));
    const shared: Record<string, unknown> = { ...state.options };
    const c = await compare({ ...shared, algorithms: ['helix', other as 'helix'] });
    expect(traces.map((t) => t.steps)).toEqual([c.a.steps, c.b.steps]);
    expect(sides.map((side) => side.distinction ?? null)).toEqual([c.a.comparedValue, c.b.comparedValue]);
    for (const t of traces) t.free();
  });

  it('leaves a chord option neither side takes to the core, which refuses it by name, as compare() does', async () => {
    const state = stateFromQuery('mode=compare&algorithm=helix&other=circle&from=20,0,0&to=0,20,0&center=0,0,0&segmentLength=6', catalogue)!;
    const [helixSide] = comparedRequests(state, catalogue.algorithms);
    expect(helixSide.options.segmentLength).toBe(6);
    expect((await rejection(trace(helixSide.options))).message).toBe('segmentLength: applies to method segments only');
    const shared: Record<string, unknown> = { ...state.options };
    expect((await rejection(compare({ ...shared, algorithms: ['helix', 'circle'] }))).message).toBe('segmentLength: helix: applies to method segments only');
  });

  it('runs the helix against itself by the method the first side does not run', async () => {
    const state = stateFromQuery('mode=compare&algorithm=helix&other=helix&method=segments&segmentLength=2', catalogue)!;
    const helix = catalogue.algorithms.find((a) => a.id === 'helix')!;
    expect(state.other).toBe('helix');
    const compared = comparedValues(state, catalogue.algorithms)!;
    expect(compared).toEqual({ option: 'method', values: ['segments', 'saleem'] });
    const sides = comparedRequests(state, catalogue.algorithms);
    expect(sides.map((side) => [side.options.method, side.distinction])).toEqual([
      ['segments', 'segments'],
      ['saleem', 'saleem'],
    ]);
    // The chord options typed go to the side that runs chords only: the core
    // declares them as applying with method segments (OptionSpec.appliesWith)
    // and refuses them with saleem, so the page leaves them out of that side.
    expect(sides.map((side) => side.options.segmentLength)).toEqual([2, undefined]);
    const [chords, saleem] = await Promise.all(sides.map((side) => trace(side.options)));
    // Both sides trace (the Saleem side had refused segmentLength): chords, against the one segment of Saleem's rule.
    expect(chords!.segments.length).toBeGreaterThan(1);
    expect(saleem!.segments.length).toBe(1);
    chords!.free();
    saleem!.free();
    // Out of compare mode a chord option typed beside method saleem is sent
    // as typed, and the core's refusal names it (shown on its field).
    const alone = traceOptions({ ...state, mode: 'trace', options: { ...state.options, method: 'saleem' } }, helix);
    expect(alone.segmentLength).toBe(2);
    expect((await rejection(trace(alone))).message).toBe('segmentLength: applies to method segments only');
    // Left at its default, the first runs saleem and the second segments.
    expect(comparedValues(stateFromQuery('mode=compare&algorithm=helix', catalogue)!, catalogue.algorithms)?.values).toEqual(['saleem', 'segments']);
    // Out of compare mode, or against another algorithm, nothing tells the sides apart.
    expect(comparedValues({ ...state, mode: 'trace' }, catalogue.algorithms)).toBeUndefined();
    expect(comparedValues({ ...state, other: 'circle' }, catalogue.algorithms)).toBeUndefined();
  });

  it("fits a link's points to the axes the page shows (nd in 4D was traced in 4D behind 3 fields)", () => {
    expect(stateFromQuery('mode=trace&algorithm=nd&from=0,0,0,0&to=10,7,6,3', catalogue)!.options).toMatchObject({ from: [0, 0, 0], to: [10, 7, 6] });
    // Points of two counts: the count of from, where the page shows it.
    expect(stateFromQuery('algorithm=nd&from=1,2&to=10,7,6,3', catalogue)!.options).toMatchObject({ from: [1, 2], to: [10, 7] });
    // Points the page shows are left alone.
    expect(stateFromQuery('algorithm=greedy&from=1,2&to=8,3', catalogue)!.options).toMatchObject({ from: [1, 2], to: [8, 3] });
  });

  it("says how it fitted a link's points to the axes the page shows (regions' from=0,0 was traced with z = 0 without a word)", () => {
    const fitted = (query: string) => {
      const notes: LinkNotes = { unread: [], fitted: [] };
      const options = stateFromQuery(query, catalogue, notes)!.options;
      return { options, notes };
    };
    expect(fitted('algorithm=regions&from=0,0&to=7,-3')).toEqual({
      options: { from: [0, 0, 0], to: [7, -3, 0] },
      notes: { unread: [], fitted: ['from and to had 2 coordinates; regions takes 3: z = 0 added'] },
    });
    expect(fitted('algorithm=circle&from=5&to=0,5,0&center=0,0,0,9').notes.fitted).toEqual([
      'from had 1 coordinate; the page shows 3: y = 0 and z = 0 added',
      'center had 4 coordinates; the page shows 3: a dropped',
    ]);
    expect(fitted('mode=compare&algorithm=regions&other=greedy&from=0,0&to=7,-3,1').notes.fitted).toEqual(['from had 2 coordinates; regions and greedy take 3: z = 0 added']);
    // Where the algorithm takes more than one count: from's, else the page's.
    expect(fitted('algorithm=nd&from=1,2&to=10,7,6,3').notes.fitted).toEqual(['to had 4 coordinates; from has 2: z and a dropped']);
    expect(fitted('algorithm=nd&from=0,0,0,0,0,0,0&to=10,7,6').notes.fitted).toEqual(['from had 7 coordinates; the page shows 3: a, b, c and coordinate 7 dropped']);
    // A point left at its default (unreadable) is not fitted, only unread; points the page shows say nothing.
    expect(fitted('algorithm=regions&from=0,x&to=10,7,6').notes).toEqual({ unread: ['from=0,x'], fitted: [] });
    expect(fitted('algorithm=greedy&from=1,2&to=8,3').notes).toEqual({ unread: [], fitted: [] });
    // Points the link does not give are fitted without a word: nd's default
    // to beside from=1,2, greedy's 2D defaults beside a 3D from.
    expect(fitted('algorithm=nd&from=1,2')).toMatchObject({ options: { from: [1, 2] }, notes: { unread: [], fitted: [] } });
    expect(fitted('algorithm=greedy&from=0,0,0').notes.fitted).toEqual([]);
  });

  it("traces a link's tolerance by tolerance, without the example's segmentLength (the two were refused together)", () => {
    const query = 'algorithm=arc-segments&from=20,0,0&to=0,20,0&center=0,0,0';
    expect(stateFromQuery(query, catalogue)!.options).toMatchObject({ segmentLength: 8 });
    const byTolerance = stateFromQuery(`${query}&tolerance=0.25`, catalogue)!.options;
    expect(byTolerance).toMatchObject({ tolerance: 0.25 });
    expect(byTolerance).not.toHaveProperty('segmentLength');
    expect(stateFromQuery(`${query}&segmentLength=4`, catalogue)!.options).not.toHaveProperty('tolerance');
  });

  it('clears the alternative of a value typed, so that no form holds, nor link carries, a pair the core refuses together', async () => {
    // tolerance typed beside the example's segmentLength went into the link,
    // which opened to an empty view ("give segmentLength or tolerance, not both").
    const query = 'algorithm=arc-segments&from=20,0,0&to=-20,0,0&center=0,0,0';
    const state = stateFromQuery(query, catalogue)!;
    state.options = withOption(state.options, 'tolerance', 0.5);
    expect(state.options).toMatchObject({ tolerance: 0.5 });
    expect(state.options).not.toHaveProperty('segmentLength');
    const link = stateToQuery(state, { gcodeLimit: GCODE_URL_LIMIT });
    expect(link).toContain('tolerance=0.5');
    expect(link).not.toContain('segmentLength');
    (await trace(traceOptions(stateFromQuery(link, catalogue)!, info('arc-segments')))).free();
    expect(withOption({ tolerance: 0.5 }, 'segmentLength', 4)).toEqual({ segmentLength: 4 });
    // Clearing one leaves the other as it is.
    expect(withOption({ tolerance: 0.5, segmentLength: 4 }, 'tolerance', undefined)).toEqual({ segmentLength: 4 });
    // Steps per mm, or the motor's three.
    const machine = { stepsPerMm: 80, acceleration: 10 };
    expect(withOption(machine, 'stepAngle', 1.8)).toEqual({ stepAngle: 1.8, acceleration: 10 });
    expect(withOption({ stepAngle: 1.8, microsteps: 8, pitch: 2 }, 'stepsPerMm', 40)).toEqual({ stepsPerMm: 40 });
    expect(withOption({ stepAngle: 1.8, microsteps: 8 }, 'pitch', 2)).toEqual({ stepAngle: 1.8, microsteps: 8, pitch: 2 });
  });

  it("puts back what a value typed cleared once it is cleared in turn (a form's OptionSetter)", () => {
    // One keystroke in stepAngle lost a stepsPerMm of 80,80,400 for good.
    const setter = new OptionSetter();
    let machine: Record<string, OptionValue> = { stepsPerMm: [80, 80, 400], acceleration: 10 };
    machine = setter.set(machine, 'stepAngle', 1.8);
    expect(machine).toEqual({ stepAngle: 1.8, acceleration: 10 });
    machine = setter.set(machine, 'microsteps', 8);
    machine = setter.set(machine, 'stepAngle', undefined);
    // microsteps is still there: steps per mm would stand beside it, refused.
    expect(machine).toEqual({ microsteps: 8, acceleration: 10 });
    machine = setter.set(machine, 'microsteps', undefined);
    expect(machine).toEqual({ stepsPerMm: [80, 80, 400], acceleration: 10 });
    // A value typed for the option set aside supersedes it.
    const chords = new OptionSetter();
    let options: Record<string, OptionValue> = { segmentLength: 8 };
    options = chords.set(options, 'tolerance', 0.5);
    options = chords.set(options, 'segmentLength', 4);
    expect(options).toEqual({ segmentLength: 4 });
    options = chords.set(options, 'segmentLength', undefined);
    expect(options).toEqual({ tolerance: 0.5 });
    // One set aside that came back by other means (Back, a link) is not put back over itself when cleared.
    const back = new OptionSetter();
    let state: Record<string, OptionValue> = back.set({ stepsPerMm: 80 }, 'stepAngle', 1.8);
    state = { stepsPerMm: 100 };
    expect(back.set(state, 'stepsPerMm', undefined)).toEqual({});
  });

  it('leaves the options the page sets itself to the page', () => {
    const state = stateFromQuery('from=0,0,0&to=1,1,1&maxSteps=5', catalogue)!;
    expect(state.options).not.toHaveProperty('maxSteps');
    expect(traceOptions(state, info('regions'))).toEqual({ algorithm: 'regions', from: [0, 0, 0], to: [1, 1, 1], ...PAGE_OPTIONS });
  });
});

describe('axes and options of one or two algorithms', () => {
  it('opens greedy, walk6 and dda in 2D, as their examples are, and lets them have 3 axes', () => {
    for (const id of ['greedy', 'walk6', 'dda']) {
      expect(axisChoices([info(id)])).toEqual([2, 3]);
      expect(axisCount([info(id)], {})).toBe(2);
      const state = stateFromQuery(`algorithm=${id}`, catalogue)!;
      expect(state.options.from).toEqual([0, 0]);
      expect(state.projection).toBe('2d');
    }
    expect(axisCount([info('greedy')], { from: [0, 0, 0] })).toBe(3);
    expect(axisChoices([info('regions')])).toEqual([3]);
    expect(axisChoices([info('nd')])).toEqual([2, 3]);
    expect(axisChoices([info('regions'), info('bresenham2d')])).toEqual([]);
  });

  it('fits points to a new axis count and keeps other options', () => {
    expect(withAxes({ from: [1, 2], to: [3, 4, 5], tie: 'hold' }, 3)).toEqual({ from: [1, 2, 0], to: [3, 4, 5], tie: 'hold' });
    expect(withAxes({ from: [1, 2, 9] }, 2)).toEqual({ from: [1, 2] });
  });

  it("gives each compared algorithm the shared options it declares, as the core's compare() does", () => {
    const state: AppState = { ...first(), mode: 'compare', other: 'greedy', options: { from: [0, 0, 0], to: [10, 7, 6], tie: 'hold', tieAxis: 'higher' } };
    expect(traceOptions(state, info('regions'))).toEqual({ algorithm: 'regions', from: [0, 0, 0], to: [10, 7, 6], tie: 'hold', ...PAGE_OPTIONS });
    expect(traceOptions(state, info('greedy'))).toEqual({ algorithm: 'greedy', from: [0, 0, 0], to: [10, 7, 6], tieAxis: 'higher', ...PAGE_OPTIONS });
    expect(sharedOptionSpecs([info('circle'), info('arc-segments')]).map((s) => s.name)).toEqual([
      'from', 'to', 'center', 'dir', 'plane', 'turns', 'segmentLength', 'tolerance', 'lineAlgorithm', 'tie',
    ]);
  });

  it("offers each algorithm's own default where the two differ (the field showed regions' tie while bresenham3d ran with hold)", () => {
    const tie = (infos: string[]) => sharedOptionSpecs(infos.map(info)).find((s) => s.name === 'tie')!;
    expect(info('regions').options.find((s) => s.name === 'tie')!.default).toBe('advance');
    expect(info('bresenham3d').options.find((s) => s.name === 'tie')!.default).toBe('hold');
    for (const pair of [['regions', 'bresenham3d'], ['bresenham3d', 'regions']]) {
      const merged = tie(pair);
      expect(merged.default).toBeNull();
      expect(merged.doc).toContain(`each algorithm runs with its own (${pair[0]}: ${pair[0] === 'regions' ? 'advance' : 'hold'}, ${pair[1]}: ${pair[1] === 'regions' ? 'advance' : 'hold'})`);
    }
    // Where they agree, or for one algorithm, the field keeps its default.
    expect(tie(['regions', 'regions']).default).toBe('advance');
    expect(tie(['regions']).default).toBe('advance');
  });

  it('carries the typed move to a newly compared algorithm, fitted to the axes both take', () => {
    const options = carriedOptions([info('regions'), info('greedy')], { from: [1, 2, 3], to: [9, 8, 7], tie: 'hold' }, true);
    expect(options).toEqual({ from: [1, 2, 3], to: [9, 8, 7], tie: 'hold' });
    expect(carriedOptions([info('greedy')], { from: [1, 2, 3] }, false)).toEqual({ from: [0, 0], to: [8, 3] });
  });
});

describe("another tab's write (persist.ts)", () => {
  /** Every mode's input as storage's parts keep it, read back as a reload reads it. */
  const stored = (state: AppState): AppState => {
    const read = (mode: AppState['mode']) => stateFromQuery(stateToQuery({ ...state, mode }, url), catalogue)!;
    return { ...read('trace'), other: read('compare').other, layout: read('compare').layout, replacedPoints: state.replacedPoints, gcode: state.gcode, replacedProgram: state.replacedProgram, replacedBy: state.replacedBy, machine: read('gcode').machine, slowdown: read('gcode').slowdown, experiment: read('experiment').experiment };
  };
  const typed = 'G21 G90\nG1 X3 Y4 F600\n';

  it('follows what only the other tab changed, and nothing it wrote again unchanged (read anew, each object is another)', () => {
    const written = first();
    const seen = stored(written);
    const theirs = stored({ ...written, options: { ...written.options, to: [12, 7, 6] }, gcode: typed, machine: { ...written.machine, stepsPerMm: 40 } });
    const edits = otherTabEdits(seen, theirs, written, written);
    expect(edits.followed).toEqual({ options: theirs.options, gcode: typed, machine: theirs.machine });
    expect(edits.followed.options).toBe(theirs.options);
    expect([edits.both, edits.kept]).toEqual([[], {}]);
    expect(otherTabNote(edits)).toBe('Another tab changed the move, the program and the machine: shown here as there.');
    // Storage read again as written, each value another object: nothing is followed, nothing said.
    const again = otherTabEdits(seen, stored(written), written, written);
    expect(again).toEqual({ followed: {}, both: [], kept: {}, rewritten: [] });
    expect(otherTabNote(again)).toBe('');
  });

  it("keeps this tab's edit of an input the other tab changed too, and the other's program and points, written over, to bring back", () => {
    const written = first();
    const seen = stored(written);
    const mine = { ...written, gcode: 'G21\nG1 X1 F600\n', learnerPoints: '0,0,0\n1,1,1', options: { ...written.options, to: [9, 7, 6] } };
    const theirs = stored({ ...written, gcode: typed, learnerPoints: '0,0,0\n1,0,0', options: { ...written.options, to: [12, 7, 6] }, layout: 'side' });
    const edits = otherTabEdits(seen, theirs, written, mine);
    expect(edits.followed).toEqual({ layout: 'side' });
    expect(edits.both).toEqual(['options', 'learnerPoints', 'gcode']);
    expect(edits.kept).toEqual({ replacedProgram: typed, replacedBy: "another tab's program, typed at the same time", replacedPoints: '0,0,0\n1,0,0', replacedPointsBy: "another tab's, typed at the same time" });
    expect(otherTabNote(edits)).toBe(
      "Another tab changed the layout: shown here as there. Another tab changed the move, your points and the program at the same time as this one: what this tab has is kept, and is what a reload shows. The other tab's program is offered back beside the editor. The other tab's points are offered back in Check points.",
    );
    // The same text typed in both is no clash; the default program, or no points, put back there, are not kept.
    expect(otherTabEdits(seen, stored({ ...written, gcode: mine.gcode }), written, mine).followed).toEqual({ gcode: mine.gcode });
    const reset = otherTabEdits(stored({ ...written, gcode: typed, learnerPoints: '0,0,0' }), stored(written), { ...written, gcode: typed, learnerPoints: '0,0,0' }, mine);
    expect([reset.both, reset.kept]).toEqual([['learnerPoints', 'gcode'], {}]);
  });

  it('keeps a move with a text refused here (a draft: the state holds the last valid move) rather than follow the other tab', () => {
    const written = first();
    const theirs = stored({ ...written, options: { ...written.options, to: [10, 8, 6] } });
    expect(otherTabEdits(stored(written), theirs, written, written, new Set(['options'])).both).toEqual(['options']);
    expect(otherTabEdits(stored(written), theirs, written, written, new Set(['machine'])).followed).toEqual({ options: theirs.options });
  });

  it("follows nothing of storage gone back to a write older than this tab's, and writes again what differs: a tab wrote back storage as it read it before this tab's write reached it (this tab's program was lost in both tabs)", () => {
    const older = { ...first(), gcode: typed, options: { ...first().options, to: [12, 7, 6] } };
    // This tab wrote a shorter program over it, and followed another tab's move.
    const mine = { ...older, gcode: 'G21 G90\nG1 X3 Y4 F600\nG1 X7', options: { ...older.options, to: [9, 7, 6] } };
    const edits = otherTabEdits(stored(mine), stored(older), mine, mine, new Set(), true);
    expect(edits).toEqual({ followed: {}, both: [], kept: {}, rewritten: ['options', 'gcode'] });
    expect(otherTabNote(edits)).toBe('');
    // Nothing differs: nothing to write again.
    expect(otherTabEdits(stored(mine), stored(mine), mine, mine, new Set(), true).rewritten).toEqual([]);
  });
});

describe('the programs kept to bring back (programReplaced, programBroughtBack, OfferSide)', () => {
  const [mine, theirs, sample] = ['G21 G90\nG1 X3 Y4 F600\nG1 X7\n', 'G21 G90\nG1 X5 Y1 F600\nG1 Y6\nG1 X0\n', 'G21\nG1 X1 F600\n'];
  const none = { replacedProgram: '', replacedBy: '', secondReplacedProgram: '' };
  /** After a clash: this tab's program kept, the other's written over and offered (otherTabEdits). */
  const clashed = { gcode: mine, replacedProgram: theirs, replacedBy: ANOTHER_TABS_PROGRAM, secondReplacedProgram: '' };

  it('keeps a typed program a sample replaces, and with an offer standing keeps that one (the program shown replaced it)', () => {
    expect(programReplaced({ gcode: mine, ...none }, sample, "the sample 'Helix'", true)).toEqual({ gcode: sample, replacedProgram: mine, replacedBy: "the sample 'Helix'", secondReplacedProgram: '' });
    expect(programReplaced({ gcode: sample, ...none }, mine, "the link's program", false)).toEqual({ gcode: mine, ...none });
    const offered = { gcode: sample, replacedProgram: mine, replacedBy: "the sample 'Helix'", secondReplacedProgram: '' };
    expect(programReplaced(offered, theirs, "the link's program", true)).toEqual({ ...offered, gcode: theirs, replacedBy: "the link's program" });
  });

  it("keeps both programs of a clash when the one kept is replaced: it first, the other tab's second; and both again after another sample", () => {
    const replaced = programReplaced(clashed, sample, "the sample 'Helix'", true);
    expect(replaced).toEqual({ gcode: sample, replacedProgram: mine, replacedBy: "the sample 'Helix'", secondReplacedProgram: theirs });
    expect(programReplaced(replaced, 'G1 X2\n', "the sample 'Star'", false)).toEqual({ ...replaced, gcode: 'G1 X2\n', replacedBy: "the sample 'Star'" });
    // A sample shown at the clash (picked here while the other tab typed) is not kept.
    expect(programReplaced({ ...clashed, gcode: sample }, 'G1 X2\n', "the sample 'Star'", false)).toEqual({ ...clashed, gcode: 'G1 X2\n', replacedBy: "the sample 'Star'" });
  });

  it('brings back either of two programs kept, the other offered as after the clash; one alone, the offer withdrawn', () => {
    const replaced = programReplaced(clashed, sample, "the sample 'Helix'", true);
    expect(programBroughtBack(replaced, 'replacedProgram')).toEqual(clashed);
    expect(programBroughtBack(replaced, 'secondReplacedProgram')).toEqual({ gcode: theirs, replacedProgram: mine, replacedBy: ANOTHER_TABS_PROGRAM, secondReplacedProgram: '' });
    expect(programBroughtBack(clashed, 'replacedProgram')).toEqual({ gcode: theirs, ...none });
  });

  it("keeps points a link's replace, and both tabs' points of a clash when a link's replace the ones kept", () => {
    const [ours, others, linked] = ['0,0,0\n1,1,1\n2,1,1', '0,0,0\n1,0,0', '0,0,0\n0,1,0'];
    const noPoints = { replacedPoints: '', replacedPointsBy: '', secondReplacedPoints: '' };
    expect(pointsReplaced({ learnerPoints: ours, ...noPoints }, linked, "the link's points")).toEqual({ learnerPoints: linked, replacedPoints: ours, replacedPointsBy: "the link's points", secondReplacedPoints: '' });
    expect(pointsReplaced({ learnerPoints: '', ...noPoints }, linked, "the link's points")).toEqual({ learnerPoints: linked, ...noPoints });
    const clash = { learnerPoints: ours, replacedPoints: others, replacedPointsBy: ANOTHER_TABS_POINTS, secondReplacedPoints: '' };
    const replaced = pointsReplaced(clash, linked, "the link's points");
    expect(replaced).toEqual({ learnerPoints: linked, replacedPoints: ours, replacedPointsBy: "the link's points", secondReplacedPoints: others });
    expect(pointsBroughtBack(replaced, 'replacedPoints')).toEqual(clash);
    expect(pointsBroughtBack(replaced, 'secondReplacedPoints')).toEqual({ learnerPoints: others, replacedPoints: ours, replacedPointsBy: ANOTHER_TABS_POINTS, secondReplacedPoints: '' });
    expect(pointsBroughtBack(clash, 'replacedPoints')).toEqual({ learnerPoints: others, ...noPoints });
  });

  it('says, in the tab whose program was kept and in the one whose program was written over, whose each kept program is as they move', () => {
    // In node there is no sessionStorage: each tab judges by what it saw.
    const kept = new OfferSide('kept');
    const writtenOver = new OfferSide('writtenOver');
    kept.othersText(mine, '');
    writtenOver.othersText(theirs, '');
    // The clash: the tab that kept its program sees the offer come beside it; the other sees its program replaced.
    expect(kept.othersText(mine, theirs)).toBe(true);
    expect(writtenOver.othersText(mine, theirs)).toBe(false);
    // A sample replaces the program kept: the two change places (the second is the other of the two).
    const replaced = programReplaced(clashed, sample, "the sample 'Helix'", true);
    const judged = (side: OfferSide, state: typeof replaced) => side.othersText(state.gcode, state.replacedProgram, state.secondReplacedProgram);
    expect(judged(kept, replaced)).toBe(false);
    expect(judged(writtenOver, replaced)).toBe(true);
    // Brought back, the first: as after the clash; or the second: the first stays whose it was.
    expect(judged(kept, programBroughtBack(replaced, 'replacedProgram'))).toBe(true);
    expect(judged(writtenOver, programBroughtBack(replaced, 'replacedProgram'))).toBe(false);
    for (const side of [kept, writtenOver]) judged(side, replaced);
    expect(judged(kept, programBroughtBack(replaced, 'secondReplacedProgram'))).toBe(false);
  });
});
