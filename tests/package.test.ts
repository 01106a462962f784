// The package as `npm pack` makes it (its prepack builds lib/ first: a clean
// checkout packed only LICENSE, the README, package.json and the bin): the
// library with its .wasm and the CLI, every module they import (no package
// but Node's own), and no runtime dependency (three.js and uPlot are the
// page's, not the library's).
import { execFileSync, spawnSync } from 'node:child_process';
import { mkdtempSync, mkdirSync, readFileSync, rmSync, symlinkSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';

const ROOT = fileURLToPath(new URL('..', import.meta.url));

describe('the npm package', () => {
  it('holds the library, its .wasm and the CLI, every module they import, and nothing else', { timeout: 120_000 }, () => {
    const [packed] = JSON.parse(execFileSync('npm', ['pack', '--dry-run', '--json'], { cwd: ROOT, encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'] })) as [{ files: { path: string }[] }];
    const files = new Set(packed.files.map((f) => f.path));
    for (const needed of ['bin/voxpath.js', 'lib/core/index.js', 'lib/core/index.d.ts', 'lib/core/vitest.js', 'lib/core/pkg/voxpath_bg.wasm', 'lib/core/pkg/voxpath.js', 'lib/cli/main.js']) {
      expect(files, needed).toContain(needed);
    }
    expect([...files].filter((f) => !/^(bin|lib)\//.test(f)).sort()).toEqual(['LICENSE', 'README.md', 'package.json']);
    // Every relative import of every packed module is packed too.
    let imports = 0;
    for (const file of [...files].filter((f) => f.endsWith('.js'))) {
      const text = readFileSync(new URL(file, `file://${ROOT}/`), 'utf8');
      // Statements, not the examples in comments (which import 'voxpath' as a user does).
      const statement = /^(?:import|export)\s+(?:\{[^}]*\}|\*(?:\s+as\s+\w+)?|\w+(?:\s*,\s*\{[^}]*\})?)\s+from\s*'([^']+)'|^import\s*'([^']+)'|\bimport\(\s*'([^']+)'\s*\)/gm;
      for (const match of text.matchAll(statement)) {
        const target = match[1] ?? match[2] ?? match[3];
        if (target === undefined) continue;
        if (!target.startsWith('.')) {
          // No package but Node's own: a runtime dependency would be one the package does not declare.
          expect(target, `${file} imports ${target}`).toMatch(/^node:/);
          continue;
        }
        const resolved = new URL(target, new URL(file, 'file:///')).pathname.slice(1);
        expect(files, `${file} imports ${target}`).toContain(resolved);
        imports++;
      }
    }
    expect(imports).toBeGreaterThan(40);
    const manifest = JSON.parse(readFileSync(new URL('package.json', `file://${ROOT}/`), 'utf8')) as { dependencies?: object; scripts: Record<string, string> };
    expect(manifest.dependencies ?? {}).toEqual({});
    expect(manifest.scripts.prepack).toBe('node scripts/setup.mjs lib');
  });

  /**
   * The output of tsc checking `use.ts`, a user's module of the package,
   * in a project of its own whose tsconfig has `compilerOptions`: '' when
   * it type-checks.
   */
  function typeCheckUser(compilerOptions: Record<string, unknown>): { output: string; status: number | null } {
    const project = mkdtempSync(join(tmpdir(), 'voxpath-types-'));
    try {
      writeFileSync(join(project, 'package.json'), JSON.stringify({ type: 'module' }));
      mkdirSync(join(project, 'node_modules'));
      symlinkSync(ROOT, join(project, 'node_modules', 'voxpath'), 'dir');
      writeFileSync(join(project, 'tsconfig.json'), JSON.stringify({ compilerOptions: { module: 'nodenext', strict: true, noEmit: true, skipLibCheck: false, ...compilerOptions }, files: ['use.ts'] }));
      writeFileSync(
        join(project, 'use.ts'),
        [
          "import { runGcode, trace } from 'voxpath';",
          "import type { Trace, TraceOptions } from 'voxpath';",
          "const options: TraceOptions = { algorithm: 'regions', from: [0, 0, 0], to: [5, 3, 1] };",
          "// @ts-expect-error: an id the catalogue does not list ('bresenham' is npm's; voxpath's are bresenham2d and bresenham3d).",
          "const misspelt: TraceOptions = { algorithm: 'bresenham', from: [0, 0], to: [5, 3] };",
          'const t: Trace = await trace(options);',
          "const program = await runGcode('G1 X1 F100', { stepsPerMm: 1 });",
          'console.log(t.points.length, program.steps, misspelt);',
        ].join('\n'),
      );
      const tsc = spawnSync(process.execPath, [join(ROOT, 'node_modules', 'typescript', 'bin', 'tsc'), '-p', project], { encoding: 'utf8' });
      return { output: tsc.stdout + tsc.stderr, status: tsc.status };
    } finally {
      rmSync(project, { recursive: true, force: true });
    }
  }

  // The declarations a TypeScript user's project checks when it does not
  // skip its libraries' (skipLibCheck off): a Node project loads no DOM
  // library, and wasm-bindgen's loader was typed with its names
  // (RequestInfo, BufferSource, WebAssembly.Module).
  it('type-checks in a Node project without the DOM library and without skipLibCheck', { timeout: 120_000 }, () => {
    const checked = typeCheckUser({ target: 'es2022', lib: ['es2022'], types: ['node'], typeRoots: [join(ROOT, 'node_modules', '@types')] });
    expect(checked).toEqual({ output: '', status: 0 });
  });

  // A browser project's plain tsconfig (es2022 and the DOM library, its
  // default) without @types/node: wasm-bindgen declares its classes
  // disposable ([Symbol.dispose]), a name of the esnext.disposable library
  // that only @types/node had loaded, and each was an error.
  it('type-checks in a project of es2022 without @types/node and without skipLibCheck', { timeout: 120_000 }, () => {
    const checked = typeCheckUser({ target: 'es2022', types: [] });
    expect(checked).toEqual({ output: '', status: 0 });
  });
});
