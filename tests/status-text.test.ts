// The status line's sentence for a program: its size, where it stopped and
// its warnings, as one sentence however the core's message ends.
import { describe, expect, it } from 'vitest';
import { runGcode } from '../web/core/index.js';
import { programStatus } from '../web/page/status.js';

describe("a program's status line", () => {
  it('ends one sentence once, though the stopping message ends with a full stop ("--max-steps 60000000..")', async () => {
    // 60 mm at 1000 steps/mm: past maxSteps, whose advice ends with a full stop.
    const p = await runGcode('G21 G90\nG1 X60000 F1000\n', { stepsPerMm: 1000 });
    const info = { ...p };
    p.free();
    expect(info.errors).toHaveLength(1);
    const status = programStatus(info);
    expect(status).not.toMatch(/\.\.|\.;/);
    expect(status).toMatch(/^2 lines, 0 moves, 0 steps at 1000 \/ 1000 \/ 1000 steps\/mm; stopped at line 2: .+[^.]\.$/);
  });
});
