// The boundary is declared once, in Rust: every type that crosses
// rust/src/wasm.rs derives Tsify, which writes its TypeScript twin into the
// wasm package's .d.ts. This test holds that declaration to what the core
// really sends: values from the real built core, for every algorithm's
// example, a G-code program with arcs, warnings and an error, a comparison and
// an experiment, are checked field by field against the generated types
// (read with the TypeScript compiler). A field the core sends that the .d.ts
// does not declare (say a hand-written Serialize that drifted), a required
// field it declares and the core leaves out, a value of another kind than
// declared (a string for a number, null where null is not allowed) fails here.
import { fileURLToPath } from 'node:url';
import ts from 'typescript';
import { beforeAll, describe, expect, it } from 'vitest';
import { catalogue, compare, randomLines } from '../web/core/index.js';
import type { Catalogue } from '../web/core/index.js';
import { encodeRequest } from '../web/core/request.js';
import { loadCore, withTextBytes } from '../web/core/wasm.js';

const DECLARATIONS = fileURLToPath(new URL('../web/core/pkg/voxpath.d.ts', import.meta.url));

let checker: ts.TypeChecker;
let exported: Map<string, ts.Symbol>;

beforeAll(() => {
  const program = ts.createProgram([DECLARATIONS], { strict: true, noEmit: true, skipLibCheck: true });
  checker = program.getTypeChecker();
  const module = checker.getSymbolAtLocation(program.getSourceFile(DECLARATIONS)!)!;
  exported = new Map(checker.getExportsOfModule(module).map((s) => [s.name, s]));
});

function declared(name: string): ts.Type {
  const symbol = exported.get(name);
  if (!symbol) throw new Error(`the wasm package declares no type ${name}`);
  return checker.getDeclaredTypeOfSymbol(symbol);
}

/** The members of a union (the type itself when it is none), null and undefined left out. */
function members(type: ts.Type): ts.Type[] {
  const all = type.isUnion() ? type.types : [type];
  return all.filter((t) => !(t.flags & (ts.TypeFlags.Null | ts.TypeFlags.Undefined)));
}

function isArrayLike(type: ts.Type): boolean {
  return checker.isArrayType(type) || checker.isTupleType(type) || type.getSymbol()?.name === 'ArrayLike';
}

function elementOf(type: ts.Type): ts.Type {
  return checker.getIndexTypeOfType(type, ts.IndexKind.Number) ?? checker.getTypeArguments(type as ts.TypeReference)[0]!;
}

/** Where `value` does not fit `type` (empty when it does): a path and what is wrong there. */
function misfits(value: unknown, type: ts.Type, path: string): string[] {
  if (value === undefined) return [];
  const all = type.isUnion() ? type.types : [type];
  if (all.some((t) => t.flags & (ts.TypeFlags.Unknown | ts.TypeFlags.Any))) return [];
  // null only where the .d.ts allows it (serde_json also writes a NaN as null).
  if (value === null) return all.some((t) => t.flags & (ts.TypeFlags.Null | ts.TypeFlags.Undefined)) ? [] : [`${path}: null where the .d.ts has ${checker.typeToString(type)}`];
  const candidates = members(type);
  if (Array.isArray(value)) {
    const arrays = candidates.filter(isArrayLike);
    if (arrays.length === 0) return [`${path}: an array where the .d.ts has ${checker.typeToString(type)}`];
    return value.flatMap((item, i) => misfits(item, elementOf(arrays[0]!), `${path}[${i}]`));
  }
  if (typeof value !== 'object') {
    const kinds: Record<string, ts.TypeFlags> = { number: ts.TypeFlags.NumberLike, string: ts.TypeFlags.StringLike, boolean: ts.TypeFlags.BooleanLike, bigint: ts.TypeFlags.BigIntLike };
    const kind = kinds[typeof value] ?? 0;
    return candidates.some((t) => t.flags & kind) ? [] : [`${path}: a ${typeof value} where the .d.ts has ${checker.typeToString(type)}`];
  }
  const objects = candidates.filter((t) => t.flags & ts.TypeFlags.Object || t.isIntersection());
  if (objects.length === 0) return [`${path}: an object where the .d.ts has ${checker.typeToString(type)}`];
  // A tagged union: the member whose literal tags match the value's.
  const fitting = objects.map((t) => ({ t, problems: objectMisfits(value as Record<string, unknown>, t, path) }));
  return fitting.find((f) => f.problems.length === 0)?.problems ?? fitting.sort((a, b) => a.problems.length - b.problems.length)[0]!.problems;
}

function objectMisfits(value: Record<string, unknown>, type: ts.Type, path: string): string[] {
  const problems: string[] = [];
  const index = checker.getIndexTypeOfType(type, ts.IndexKind.String);
  for (const [key, field] of Object.entries(value)) {
    const property = checker.getPropertyOfType(type, key);
    if (!property) {
      if (!index) problems.push(`${path}.${key}: sent by the core, not declared in ${checker.typeToString(type)}`);
      continue;
    }
    const propertyType = checker.getTypeOfSymbol(property);
    const literals = members(propertyType).filter((t) => t.isStringLiteral());
    if (field !== null && literals.length > 0 && members(propertyType).every((t) => t.isStringLiteral()) && !literals.some((t) => (t as ts.StringLiteralType).value === field)) {
      problems.push(`${path}.${key}: '${String(field)}' is not one of ${checker.typeToString(propertyType)}`);
      continue;
    }
    problems.push(...misfits(field, propertyType, `${path}.${key}`));
  }
  for (const property of checker.getPropertiesOfType(type)) {
    if (!(property.flags & ts.SymbolFlags.Optional) && !(property.name in value)) {
      problems.push(`${path}.${property.name}: declared in the .d.ts, not sent by the core`);
    }
  }
  return problems;
}

function expectFits(value: unknown, typeName: string): void {
  expect(misfits(value, declared(typeName), typeName)).toEqual([]);
}

describe('the generated boundary types', () => {
  let offered: Catalogue;

  beforeAll(async () => {
    offered = await catalogue();
  });

  it('declare the catalogue: algorithms, experiments and G-code settings', () => {
    expectFits(offered, 'Catalogue');
    expect(offered.gcodeSettings.length).toBeGreaterThan(0);
  });

  it("declare every algorithm example's trace summary and its points' details, as the core hands them over", async () => {
    const core = await loadCore();
    const figures = new Set<string>();
    for (const info of offered.algorithms) {
      const handle = core.trace(encodeRequest({ ...info.example.options, algorithm: info.id }));
      try {
        const summary = handle.summary();
        expectFits(summary, 'TraceSummary');
        expectFits(handle.legend(), 'TraceLegend');
        for (const point of new Set([0, 1, Math.floor(summary.steps / 2), summary.steps])) {
          const detail = handle.stepDetail(point);
          expectFits(detail, 'StepDetail');
          if (detail.figure) figures.add(detail.figure.kind);
        }
        expectFits(handle.stepClocks(4), 'StepClocks');
        expectFits(handle.metrics(), 'Metrics');
        const segments = handle.segments();
        expect(segments.length).toBeGreaterThan(0);
        for (const segment of segments) expectFits(segment, 'SegmentSummary');
      } finally {
        handle.free();
      }
    }
    // Every kind of picture was among them.
    expect([...figures].sort()).toEqual(['arcCandidates', 'errorTerms', 'exitFace']);
  });

  it('declare a G-code program with arcs, a helix, warnings and an error, and its progress', async () => {
    const core = await loadCore();
    const source = 'G21 G90 G17\nG0 X0 Y0\nG1 X10 F600\nG2 X10 Y10 I0 J5\nG3 X0 Y10 Z2 R5\nM3\nG1 X\n';
    const run = withTextBytes(core, source, (bytes) => new core.GcodeRun(bytes, encodeRequest({ stepsPerMm: 10, maxStepRate: 10 })));
    expectFits(run.advance(3), 'Progress');
    expectFits(run.advance(100), 'Progress');
    const result = run.finish();
    try {
      const record = result.program();
      const moves = result.moves(0, record.moveCount);
      expect(moves.some((m) => m.arc !== null && m.kind === 'helix') && record.warnings.length > 0 && record.errors.length > 0).toBe(true);
      expectFits(record, 'ProgramInfo');
      for (const m of moves) expectFits(m, 'Move');
      const handle = result.takeTrace();
      try {
        const steps = handle.summary().steps;
        for (const point of [0, 1, Math.floor(steps / 2), steps]) expectFits(handle.stepDetail(point), 'StepDetail');
      } finally {
        handle.free();
      }
      expectFits(result.motionChart(0, record.durationSeconds, 3), 'MotionChart');
      expectFits(result.motionChart(0, record.durationSeconds, 10_000), 'MotionChart');
    } finally {
      result.free();
    }
  });

  it('declare a comparison with its first difference, and an experiment', async () => {
    const c = await compare({ algorithms: ['regions', 'greedy'], from: [0, 0, 0], to: [10, 7, 6] });
    expect(c.firstDifference).not.toBeNull();
    expectFits(c, 'Comparison');
    expectFits(await randomLines({ algorithm: 'regions', count: 3 }), 'RandomLines');
  });

  it('declare AlgorithmId as the union of the catalogue\'s ids, spelled from its list', () => {
    const ids = members(declared('AlgorithmId')).map((t) => (t.isStringLiteral() ? t.value : checker.typeToString(t)));
    expect(ids).toEqual(offered.algorithms.map((a) => a.id));
  });

  it('declare one GcodeSettings field per setting of the catalogue, and no other', () => {
    const fields = checker.getPropertiesOfType(declared('GcodeSettings')).map((p) => p.name);
    expect(fields.sort()).toEqual(offered.gcodeSettings.map((s) => s.name).sort());
  });

  it('find a field the core sends and the .d.ts lacks', () => {
    const summary = { algorithm: 'x', dims: 2, steps: 0, start: [0, 0], end: [0, 0], extra: 1 };
    expect(misfits(summary, declared('TraceSummary'), 'TraceSummary')).toContain('TraceSummary.extra: sent by the core, not declared in TraceSummary');
    const legend = { columns: [], figures: [], deviationBound: {} };
    expect(misfits(legend, declared('TraceLegend'), 'TraceLegend').some((p) => p.startsWith('TraceLegend.deviationBound.value: declared in the .d.ts'))).toBe(true);
  });
});
