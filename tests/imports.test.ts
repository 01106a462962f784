// No import loops between files, Rust or TypeScript: no file imports,
// directly or through others, a file that imports it. The graphs and the
// rules that make them are in tests/import-graph.ts.

import { mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { afterAll, describe, expect, test } from 'vitest';
import {
  type ImportGraph,
  findCycles,
  rustImportGraph,
  rustTokens,
  tsImportGraph,
  tsImportSpecifiers,
  useTreePaths,
} from './import-graph.js';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');

/** The cycles of a graph as the failure message names them. */
const named = (graph: ImportGraph) =>
  findCycles(graph)
    .map((cycle) => cycle.join(' -> '))
    .sort();

const graphOf = (edges: Record<string, string[]>): ImportGraph =>
  new Map(Object.entries(edges).map(([from, to]) => [from, new Set(to)]));

describe('the cycle finder', () => {
  test('names a loop through three files, and not the file that only enters it', () => {
    const graph = graphOf({ a: ['b'], b: ['c'], c: ['a'], d: ['a'], e: [] });
    expect(named(graph)).toEqual(['a -> b -> c -> a']);
  });

  test('names a shortest loop through the first file of each loop', () => {
    // Two separate loops; in the first, a -> c -> a is shorter than a -> b -> c -> a.
    const graph = graphOf({ a: ['b', 'c'], b: ['c'], c: ['a'], x: ['y'], y: ['x'] });
    expect(named(graph)).toEqual(['a -> c -> a', 'x -> y -> x']);
  });

  test('a file importing itself is a loop; a diamond is not', () => {
    expect(named(graphOf({ a: ['a'] }))).toEqual(['a -> a']);
    expect(named(graphOf({ top: ['left', 'right'], left: ['base'], right: ['base'], base: [] }))).toEqual([]);
  });
});

describe('reading Rust', () => {
  test('comments, strings and characters are no paths', () => {
    const tokens = rustTokens(
      [
        '/// See [`crate::a::B`].',
        '/* nested /* crate::x */ still comment */',
        'let s = "crate::y"; let r = r#"crate::z "quoted""#; let c = \'"\'; let b = b"crate::w";',
        "fn f<'a>(x: &'a str) -> char { '\\'' }",
        'use crate::real::Thing;',
      ].join('\n'),
    );
    expect(tokens.join(' ')).toBe(
      "let s = ; let r = ; let c = ; let b = ; fn f < a > ( x : & a str ) - > char { } use crate :: real :: Thing ;",
    );
  });

  test('a use tree expands into one path per name', () => {
    const tree = rustTokens('crate::a::{b, c::{d, self}, e as f, g::*}');
    expect(useTreePaths(tree)).toEqual([
      ['crate', 'a', 'b'],
      ['crate', 'a', 'c', 'd'],
      ['crate', 'a', 'c'],
      ['crate', 'a', 'e'],
      ['crate', 'a', 'g'],
    ]);
  });

  describe('a small crate', () => {
    const dir = mkdtempSync(join(tmpdir(), 'voxpath-imports-'));
    afterAll(() => rmSync(dir, { recursive: true, force: true }));
    const write = (path: string, text: string) => {
      mkdirSync(dirname(join(dir, path)), { recursive: true });
      writeFileSync(join(dir, path), text);
    };
    write('src/lib.rs', 'pub mod shape;\npub mod table;\npub use table::Table;\n');
    // A parent that declares its children and uses one item of one of them.
    write('src/shape/mod.rs', 'pub mod circle;\npub mod info;\nuse info::Info;\n');
    write('src/shape/info.rs', 'pub struct Info;\n');
    // circle reaches the table through a path in an expression, and its test
    // module reaches its own file through super.
    write(
      'src/shape/circle.rs',
      'use super::info::Info;\nfn f() { crate::table::row(); }\n#[cfg(test)]\nmod tests {\n    use super::*;\n}\n',
    );
    // table uses circle, which reaches table: a loop.
    write('src/table.rs', 'use crate::shape::circle;\npub fn row() {}\npub struct Table;\n');
    const graph = rustImportGraph(dir, 'src');

    test('edges: uses and paths resolve to the longest prefix that is a file; declaring a module is none', () => {
      const edges = Object.fromEntries([...graph].map(([file, to]) => [file, [...to].sort()]));
      expect(edges).toEqual({
        'src/lib.rs': ['src/table.rs'],
        'src/shape/mod.rs': ['src/shape/info.rs'],
        'src/shape/info.rs': [],
        'src/shape/circle.rs': ['src/shape/info.rs', 'src/table.rs'],
        'src/table.rs': ['src/shape/circle.rs'],
      });
    });

    test('and the loop between two files of it is named', () => {
      expect(named(graph)).toEqual(['src/shape/circle.rs -> src/table.rs -> src/shape/circle.rs']);
    });
  });
});

describe('reading TypeScript', () => {
  test('imports, type imports, re-exports and import() are all edges', () => {
    const specifiers = tsImportSpecifiers(
      [
        "import { a } from './a.js';",
        "import type { B } from './b.js';",
        "export { c } from './c.js';",
        "export type * from './d.js';",
        "const e = await import('./e.js');",
        "let f: import('./f.js').F;",
        "// import { g } from './g.js';",
        "const h = './h.js';",
      ].join('\n'),
    );
    expect(specifiers).toEqual(['./a.js', './b.js', './c.js', './d.js', './e.js', './f.js']);
  });

  test('a loop made of type imports alone is named', () => {
    const dir = mkdtempSync(join(tmpdir(), 'voxpath-imports-'));
    try {
      writeFileSync(join(dir, 'a.ts'), "import type { B } from './b.js';\nexport type A = B[];\n");
      writeFileSync(join(dir, 'b.ts'), "import type { A } from './a.js';\nexport type B = { a: A };\n");
      writeFileSync(join(dir, 'c.ts'), "import type { A } from './a.js';\n");
      expect(named(tsImportGraph(dir, '.', () => false))).toEqual(['a.ts -> b.ts -> a.ts']);
    } finally {
      rmSync(dir, { recursive: true, force: true });
    }
  });
});

describe('the project', () => {
  test('no file of rust/src imports, directly or through others, a file that imports it', () => {
    const graph = rustImportGraph(root, 'rust/src');
    // The graph is read, not empty: a few edges the code is known to have.
    expect(graph.get('rust/src/trace.rs')).toContain('rust/src/ideal/mod.rs');
    expect(graph.get('rust/src/ideal/mod.rs')).toContain('rust/src/ideal/curve.rs');
    expect(graph.get('rust/src/ideal/curve.rs')).toContain('rust/src/ideal/info.rs');
    expect(graph.get('rust/src/algorithms.rs')).toContain('rust/src/line/regions_wang.rs');
    expect(named(graph)).toEqual([]);
  });

  test('no file of web/ imports, directly or through others, a file that imports it', () => {
    // web/core/pkg is wasm-pack's output, which imports nothing of web/.
    const graph = tsImportGraph(root, 'web', (path) => path === join('web', 'core', 'pkg'));
    expect(graph.get('web/cli/gcode.ts')).toContain('web/cli/flags.ts');
    expect(named(graph)).toEqual([]);
  });
});
