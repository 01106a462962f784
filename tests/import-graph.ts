// File-level import graphs of rust/src and web/, and a cycle finder, for
// tests/imports.test.ts (the house rule: no file imports, directly or through
// others, a file that imports it).
//
// An edge A -> B means that file A names an item of file B:
// - Rust: a `use` (also `pub use`, a re-export) or an inline path
//   (`crate::a::b`, `super::x`, `self::x`, or `child::x` where `child` is a
//   module declared in A's module). A path resolves to the longest prefix of
//   its module path that is a file, a/b.rs or a/b/mod.rs (lib.rs for the crate
//   root). Declaring a module (`pub mod x;`) is not an edge: the parent owns
//   its children's place in the tree but does not depend on what they hold.
//   Test modules (`#[cfg(test)] mod tests { ... }`) count like any other code
//   of their file: they are compiled from it.
// - TypeScript: every `import` and `export ... from`, `import type` included,
//   and dynamic `import('...')`, read by the TypeScript compiler's own parser.
//   Only relative specifiers are edges; packages are outside the graph.
//
// A file's own module (`use super::*` in its test module) is not an edge.

import { readdirSync, readFileSync, statSync } from 'node:fs';
import { dirname, join, relative, resolve, sep } from 'node:path';
import ts from 'typescript';

/** File -> the files it imports, both as paths relative to the graph's root. */
export type ImportGraph = Map<string, Set<string>>;

/**
 * Every cycle class of the graph: each strongly connected component with more
 * than one file (Tarjan's algorithm), as one closed walk through it that
 * starts and ends at the same file, e.g. ['a.rs', 'b.rs', 'a.rs']. Empty when
 * no file reaches itself. A file importing itself (an edge A -> A) is a cycle
 * too; the builders below never record one.
 */
export function findCycles(graph: ImportGraph): string[][] {
  const nodes = new Set<string>(graph.keys());
  for (const targets of graph.values()) for (const t of targets) nodes.add(t);
  const index = new Map<string, number>();
  const low = new Map<string, number>();
  const onStack = new Set<string>();
  const stack: string[] = [];
  const components: string[][] = [];
  let counter = 0;

  // Iterative, so a long chain of files cannot overflow the call stack.
  for (const root of [...nodes].sort()) {
    if (index.has(root)) continue;
    const work: { node: string; next: Iterator<string> }[] = [];
    const enter = (node: string) => {
      index.set(node, counter);
      low.set(node, counter);
      counter++;
      stack.push(node);
      onStack.add(node);
      work.push({ node, next: [...(graph.get(node) ?? [])].sort()[Symbol.iterator]() });
    };
    enter(root);
    while (work.length > 0) {
      const frame = work[work.length - 1];
      const step = frame.next.next();
      if (!step.done) {
        const target = step.value;
        if (!index.has(target)) enter(target);
        else if (onStack.has(target)) low.set(frame.node, Math.min(low.get(frame.node)!, index.get(target)!));
        continue;
      }
      work.pop();
      if (work.length > 0) {
        const parent = work[work.length - 1].node;
        low.set(parent, Math.min(low.get(parent)!, low.get(frame.node)!));
      }
      if (low.get(frame.node) === index.get(frame.node)) {
        const component: string[] = [];
        let member: string;
        do {
          member = stack.pop()!;
          onStack.delete(member);
          component.push(member);
        } while (member !== frame.node);
        const selfLoop = graph.get(frame.node)?.has(frame.node) ?? false;
        if (component.length > 1 || selfLoop) components.push(component);
      }
    }
  }
  return components.map((component) => cycleThrough(graph, new Set(component)));
}

/**
 * A closed walk inside one strongly connected component: breadth-first from
 * its first file (by name) back to itself, so the cycle named is a shortest
 * one through that file.
 */
function cycleThrough(graph: ImportGraph, component: Set<string>): string[] {
  const start = [...component].sort()[0];
  const cameFrom = new Map<string, string>();
  const queue = [start];
  for (let i = 0; i < queue.length; i++) {
    const node = queue[i];
    for (const target of [...(graph.get(node) ?? [])].sort()) {
      if (!component.has(target)) continue;
      if (target === start) {
        // Back from the file that closes the loop to the start.
        const back: string[] = [];
        for (let at = node; at !== start; at = cameFrom.get(at)!) back.push(at);
        return [start, ...back.reverse(), start];
      }
      if (!cameFrom.has(target)) {
        cameFrom.set(target, node);
        queue.push(target);
      }
    }
  }
  throw new Error(`no cycle through ${start}: not a strongly connected component`);
}

/** Files under `dir` whose names end with `ext`, as paths relative to `root`. */
function filesUnder(root: string, dir: string, ext: string, skip: (path: string) => boolean): string[] {
  const out: string[] = [];
  for (const name of readdirSync(join(root, dir)).sort()) {
    const path = join(dir, name);
    if (skip(path)) continue;
    if (statSync(join(root, path)).isDirectory()) out.push(...filesUnder(root, path, ext, skip));
    else if (name.endsWith(ext)) out.push(path.split(sep).join('/'));
  }
  return out;
}

// ---- Rust ------------------------------------------------------------------

/** A token of Rust source with comments, strings and characters removed. */
type Token = string;

/**
 * Identifiers and punctuation of `source`, with comments (nested block
 * comments included), string, byte-string, raw-string and character literals
 * dropped, so that a doc link or a message such as "crate::x" is no import.
 * `::` is one token.
 */
export function rustTokens(source: string): Token[] {
  const tokens: Token[] = [];
  const s = source;
  let i = 0;
  const isIdentStart = (c: string) => /[A-Za-z_]/.test(c);
  const isIdent = (c: string) => /[A-Za-z0-9_]/.test(c);
  while (i < s.length) {
    const c = s[i];
    if (c === '/' && s[i + 1] === '/') {
      while (i < s.length && s[i] !== '\n') i++;
    } else if (c === '/' && s[i + 1] === '*') {
      let depth = 1;
      i += 2;
      while (i < s.length && depth > 0) {
        if (s[i] === '/' && s[i + 1] === '*') (depth++, (i += 2));
        else if (s[i] === '*' && s[i + 1] === '/') (depth--, (i += 2));
        else i++;
      }
    } else if (/\s/.test(c)) {
      i++;
    } else if ((c === 'r' || (c === 'b' && s[i + 1] === 'r')) && /^b?r#*"/.test(s.slice(i, i + 260))) {
      // Raw string: r"..." or r#"..."# (any number of #), also br.
      const open = /^b?r(#*)"/.exec(s.slice(i))!;
      const close = '"' + open[1];
      const end = s.indexOf(close, i + open[0].length);
      i = end < 0 ? s.length : end + close.length;
    } else if (c === '"' || (c === 'b' && s[i + 1] === '"')) {
      i += c === 'b' ? 2 : 1;
      while (i < s.length && s[i] !== '"') i += s[i] === '\\' ? 2 : 1;
      i++;
    } else if (c === "'" || (c === 'b' && s[i + 1] === "'")) {
      // A character literal ('x', '\n', '\u{1F600}', b'x'), or a lifetime
      // ('a), which is a quote followed by an identifier and no closing quote.
      const from = c === 'b' ? i + 1 : i;
      const literal = /^'(\\(u\{[0-9A-Fa-f]+\}|x[0-9A-Fa-f]{2}|.)|[^\\'])'/u.exec(s.slice(from, from + 16));
      if (literal) i = from + literal[0].length;
      else if (c === 'b') (tokens.push('b'), i++);
      else i++;
    } else if (isIdentStart(c)) {
      let j = i + 1;
      while (j < s.length && isIdent(s[j])) j++;
      tokens.push(s.slice(i, j));
      i = j;
    } else if (c === ':' && s[i + 1] === ':') {
      tokens.push('::');
      i += 2;
    } else {
      tokens.push(c);
      i++;
    }
  }
  return tokens;
}

/** A module path inside the crate, e.g. ['arc', 'curve'] ([] is the crate root). */
type ModulePath = string[];

/** The module a file of rust/src defines: lib.rs -> [], a/mod.rs and a.rs -> ['a']. */
function moduleOfFile(file: string): ModulePath {
  const parts = file.replace(/\.rs$/, '').split('/');
  if (parts.length === 1 && parts[0] === 'lib') return [];
  if (parts[parts.length - 1] === 'mod') parts.pop();
  return parts;
}

/**
 * The file-level import graph of a Rust crate whose sources are under
 * `root`/`srcDir` (lib.rs its root), with paths relative to `root`.
 */
export function rustImportGraph(root: string, srcDir: string): ImportGraph {
  const files = filesUnder(root, srcDir, '.rs', () => false);
  const fileOfModule = new Map<string, string>();
  for (const file of files) fileOfModule.set(moduleOfFile(relative(srcDir, file).split(sep).join('/')).join('::'), file);

  // The longest prefix of `path` that is a file of the crate.
  const fileOf = (path: ModulePath): string => {
    for (let n = path.length; n >= 0; n--) {
      const file = fileOfModule.get(path.slice(0, n).join('::'));
      if (file !== undefined) return file;
    }
    throw new Error(`no lib.rs under ${srcDir}`);
  };

  const graph: ImportGraph = new Map();
  for (const file of files) {
    const imports = new Set<string>();
    graph.set(file, imports);
    const fileModule = moduleOfFile(relative(srcDir, file).split(sep).join('/'));
    const tokens = rustTokens(readFileSync(join(root, file), 'utf8'));
    // Modules declared inline in this file ({ depth at which it opened, path }).
    const inline: { depth: number; path: ModulePath }[] = [];
    const declaredInline = new Set<string>();
    // Pass 1: the inline modules this file declares, so a bare `tests::x`
    // path from anywhere in the file can be told from an external crate's.
    for (let i = 0, depth = 0, open: { depth: number; path: ModulePath }[] = []; i < tokens.length; i++) {
      if (tokens[i] === '{') depth++;
      else if (tokens[i] === '}') {
        depth--;
        while (open.length > 0 && open[open.length - 1].depth > depth) open.pop();
      } else if (tokens[i] === 'mod' && /^[A-Za-z_]/.test(tokens[i + 1] ?? '') && tokens[i + 2] === '{') {
        const path = [...(open.at(-1)?.path ?? fileModule), tokens[i + 1]];
        declaredInline.add(path.join('::'));
        open.push({ depth: depth + 1, path });
      }
    }
    const isModule = (path: ModulePath) =>
      fileOfModule.has(path.join('::')) || declaredInline.has(path.join('::'));
    const current = () => inline.at(-1)?.path ?? fileModule;

    // The module path that `segments` (a path as written) names, or
    // undefined when it leaves the crate (std::, serde::, a local type).
    const absolute = (segments: string[]): ModulePath | undefined => {
      let [first, ...rest] = segments;
      let base: ModulePath;
      if (first === 'crate') base = [];
      else if (first === 'self') base = current();
      else if (first === 'super') {
        base = current().slice(0, -1);
        while (rest[0] === 'super') (base = base.slice(0, -1), rest.shift());
      } else if (isModule([...current(), first])) {
        base = [...current(), first];
      } else return undefined;
      return [...base, ...rest];
    };
    const addEdge = (segments: string[]) => {
      const path = absolute(segments);
      if (path === undefined) return;
      const target = fileOf(path);
      if (target !== file) imports.add(target);
    };

    let depth = 0;
    for (let i = 0; i < tokens.length; i++) {
      const t = tokens[i];
      if (t === '{') depth++;
      else if (t === '}') {
        depth--;
        while (inline.length > 0 && inline[inline.length - 1].depth > depth) inline.pop();
      } else if (t === 'mod' && /^[A-Za-z_]/.test(tokens[i + 1] ?? '')) {
        // `mod x;` declares a child file (no edge); `mod x {` opens an inline one.
        if (tokens[i + 2] === '{') {
          inline.push({ depth: depth + 1, path: [...current(), tokens[i + 1]] });
          depth++;
          i += 2;
        } else i += 1;
      } else if (t === 'use' && tokens[i - 1] !== '::') {
        let end = i + 1;
        while (end < tokens.length && tokens[end] !== ';') end++;
        for (const path of useTreePaths(tokens.slice(i + 1, end))) addEdge(path);
        i = end;
      } else if (/^[A-Za-z_]/.test(t) && tokens[i + 1] === '::' && tokens[i - 1] !== '::') {
        const segments = [t];
        let j = i + 1;
        while (tokens[j] === '::' && /^[A-Za-z_]/.test(tokens[j + 1] ?? '')) {
          segments.push(tokens[j + 1]);
          j += 2;
        }
        addEdge(segments);
        i = j - 1;
      }
    }
  }
  return graph;
}

/**
 * The paths a `use` tree names, as segment lists: `a::{b, c::{d, self}}` ->
 * [a, b], [a, c, d], [a, c]. `as` renames and globs end a path where they are.
 */
export function useTreePaths(tokens: Token[]): string[][] {
  let at = 0;
  const tree = (prefix: string[]): string[][] => {
    const path = [...prefix];
    if (tokens[at] === '::') at++; // a leading `::` (2015-style absolute path)
    for (;;) {
      const t = tokens[at];
      if (t === '{') {
        at++;
        const out: string[][] = [];
        while (tokens[at] !== '}' && at < tokens.length) {
          out.push(...tree(path));
          if (tokens[at] === ',') at++;
        }
        at++;
        return out;
      }
      if (t === '*') {
        at++;
        return [path];
      }
      if (t === 'self' && path.length > 0) {
        at++;
        return [path];
      }
      path.push(t);
      at++;
      if (tokens[at] === '::') {
        at++;
        continue;
      }
      if (tokens[at] === 'as') at += 2;
      return [path];
    }
  };
  return tree([]);
}

// ---- TypeScript --------------------------------------------------------------

/**
 * The file-level import graph of the .ts files under `root`/`dir`, leaving
 * out the folders `skip` accepts, with paths relative to `root`. A relative
 * specifier resolves as Node's nodenext resolution does for this project:
 * `./x.js` is the source file `./x.ts`.
 */
export function tsImportGraph(root: string, dir: string, skip: (path: string) => boolean): ImportGraph {
  const graph: ImportGraph = new Map();
  for (const file of filesUnder(root, dir, '.ts', skip)) {
    const imports = new Set<string>();
    graph.set(file, imports);
    for (const specifier of tsImportSpecifiers(readFileSync(join(root, file), 'utf8'), file)) {
      if (!specifier.startsWith('.')) continue;
      const target = resolve(root, dirname(file), specifier);
      const candidates = [target.replace(/\.js$/, '.ts'), target, `${target}.ts`, join(target, 'index.ts')];
      const found = candidates.find((c) => {
        try {
          return statSync(c).isFile();
        } catch {
          return false;
        }
      });
      if (found === undefined) throw new Error(`${file}: cannot resolve '${specifier}'`);
      imports.add(relative(root, found).split(sep).join('/'));
    }
  }
  return graph;
}

/**
 * Module specifiers `source` imports: import and export declarations (type-only
 * ones too), `import('x')` calls and `import('x').T` types.
 */
export function tsImportSpecifiers(source: string, fileName = 'file.ts'): string[] {
  const sourceFile = ts.createSourceFile(fileName, source, ts.ScriptTarget.Latest, false, ts.ScriptKind.TS);
  const out: string[] = [];
  const visit = (node: ts.Node) => {
    if ((ts.isImportDeclaration(node) || ts.isExportDeclaration(node)) && node.moduleSpecifier) {
      if (ts.isStringLiteral(node.moduleSpecifier)) out.push(node.moduleSpecifier.text);
    } else if (
      ts.isCallExpression(node) &&
      node.expression.kind === ts.SyntaxKind.ImportKeyword &&
      node.arguments.length > 0 &&
      ts.isStringLiteralLike(node.arguments[0])
    ) {
      out.push(node.arguments[0].text);
    } else if (
      ts.isImportTypeNode(node) &&
      ts.isLiteralTypeNode(node.argument) &&
      ts.isStringLiteral(node.argument.literal)
    ) {
      out.push(node.argument.literal.text);
    }
    ts.forEachChild(node, visit);
  };
  visit(sourceFile);
  return out;
}
