// A machine setting is declared once, in Rust (the settings! rows of
// rust/src/gcode/program.rs), and everything else is made from the catalogue:
// for every setting the core lists, the CLI has a flag (documented in its
// help and accepted by `voxpath gcode`), the page's machine form has a field
// and the permalink has a key. A setting added in Rust is checked here
// without a line of this file changing.
import { beforeAll, describe, expect, it } from 'vitest';
import { flagOf, optionsFromFlags, parseFlags } from '../web/cli/flags.js';
import { gcodeHelp } from '../web/cli/gcode.js';
import { catalogue } from '../web/core/index.js';
import type { Catalogue, OptionSpec } from '../web/core/index.js';
import { machineSpecs } from '../web/state/app-state.js';
import { stateFromQuery, stateToQuery } from '../web/state/query.js';

let offered: Catalogue;

beforeAll(async () => {
  offered = await catalogue();
});

/** A value of the setting's kind, as a flag or a URL writes it. */
function sampleText(spec: OptionSpec): string {
  switch (spec.kind.type) {
    case 'choice':
      return spec.kind.values.at(-1)!;
    case 'perAxis':
      return spec.kind.notWhole !== undefined ? '4,8,16' : '1.5,2,4';
    case 'boolean':
      return 'true';
    case 'point':
      return '1,2,3';
    case 'number':
    case 'integer':
      return '7';
  }
}

describe('every G-code setting of the catalogue', () => {
  it('is a CLI flag that the help documents and gcode accepts', () => {
    const help = gcodeHelp(offered.gcodeSettings);
    for (const spec of offered.gcodeSettings) {
      const flag = flagOf(spec.name);
      expect(help, flag).toContain(`${flag} `);
      expect(help, flag).toContain(spec.doc);
      const flags = parseFlags([flag, sampleText(spec)]);
      expect(Object.keys(optionsFromFlags(flags, offered.gcodeSettings, 'gcode')), flag).toEqual([spec.name]);
    }
  });

  it("is a field of the page's machine form, except those the page sets itself", () => {
    const fields = machineSpecs(offered).map((s) => s.name);
    expect(fields.length).toBeGreaterThan(8);
    for (const spec of offered.gcodeSettings) if (spec.name !== 'maxSteps') expect(fields, spec.name).toContain(spec.name);
  });

  it('is a URL key of the G-code mode, read back as the value it wrote', () => {
    for (const spec of machineSpecs(offered)) {
      const state = stateFromQuery(`mode=gcode&${spec.name}=${sampleText(spec)}`, offered)!;
      const text = sampleText(spec);
      const expected = spec.kind.type === 'choice' ? text : text.includes(',') ? text.split(',').map(Number) : Number(text);
      expect(state.machine[spec.name], spec.name).toEqual(expected);
      expect(stateToQuery(state, { gcodeLimit: Infinity }), spec.name).toContain(`${spec.name}=${text}`);
    }
  });
});
