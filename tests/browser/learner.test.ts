// The page as a learner meets it (issue 16), in headless Chromium: machine
// settings typed as on the command line, messages that say what to do on
// the page, and results that say when they are out of date. Expected values
// come from the inputs: regions takes one step per unit of the longest axis
// (Wang et al. 2020, section 2), so a G-code move of (dx, dy, dz) steps takes
// max(|dx|, |dy|, |dz|) of them.
import type { Page } from 'playwright-core';
import { afterAll, describe, expect, it } from 'vitest';
import { closeAll, openPage } from './harness.js';

afterAll(closeAll);

function text(page: Page, testId: string): Promise<string> {
  return page.getByTestId(testId).innerText();
}

/** Waits for the status line to contain `wanted`. */
async function status(page: Page, wanted: string | RegExp): Promise<string> {
  await page.getByTestId('trace-status').filter({ hasText: wanted }).waitFor();
  return text(page, 'trace-status');
}

describe('steps per mm per axis', () => {
  it('are typed and linked as the CLI takes them, 80,80,400', async () => {
    // (1, 1, 1) mm at 80, 80 and 400 steps/mm is (80, 80, 400) steps: 400 steps.
    const gcode = encodeURIComponent('G21 G90\nG1 X1 Y1 Z1 F600\n');
    const p = await openPage(`?mode=gcode&gcode=${gcode}&stepsPerMm=80,80,400`);
    const { page } = p;
    await status(page, '1 moves, 400 steps at 80 / 80 / 400 steps/mm');
    const field = page.getByTestId('input-machine-stepsPerMm');
    expect(await field.inputValue()).toBe('80,80,400');
    // The field's hint gives the syntax the field takes, the CLI's.
    expect(await page.locator('#machine-stepsPerMm-hint').innerText()).toContain('80,80,400');

    await field.fill('80,80,200');
    await status(page, '1 moves, 200 steps at 80 / 80 / 200 steps/mm');
    await expect.poll(() => new URL(page.url()).searchParams.get('stepsPerMm')).toBe('80,80,200');
    expect(await text(page, 'form-error')).toBe('');

    // Text that is not numbers is named at the field and never sent.
    await field.fill('80;80');
    expect(await text(page, 'error-machine-stepsPerMm')).toBe('give one number, or x,y,z');
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});

describe('messages about a cap', () => {
  it('say what to do on the page, not raise a maxSteps it has no control for', async () => {
    // A line to x = 2^30 takes 2^30 steps (regions: one per unit of the
    // longest axis): more than the page's 1,500,000 and than any maxSteps (10^9).
    const p = await openPage('?from=0,0,0&to=1073741824,0,0');
    const { page } = p;
    const formError = page.getByTestId('form-error');
    await formError.filter({ hasText: 'steps' }).waitFor();
    const far = await formError.innerText();
    expect(far).toMatch(/^This path needs at least 1,073,741,824 steps; the page draws at most 1,500,000 \(its maxSteps, fixed\)\. Shorten the move/);
    expect(far).toContain('No trace may have that many steps (1,000,000,000 at most, anywhere).');
    expect(far).not.toMatch(/raise/i);

    // 2,000,000 steps: the command line could, and the message says how.
    await page.getByTestId('input-to-x').fill('2000000');
    await formError.filter({ hasText: '2,000,000' }).waitFor();
    expect(await formError.innerText()).toContain('The command line goes up to 1,000,000,000 steps: voxpath trace --max-steps 2000000.');
    expect(p.problems()).toEqual([]);
    await p.close();
  });

  it("word a program's cap at its line, where the program is edited", async () => {
    // 700,000 mm at 80 steps/mm is 56,000,000 steps, past the 50,000,000 the page runs.
    const gcode = encodeURIComponent('G21 G90\nG1 X700000 F600\n');
    const p = await openPage(`?mode=gcode&gcode=${gcode}&stepsPerMm=80`);
    const { page } = p;
    const diagnostics = page.getByTestId('gcode-diagnostics');
    await diagnostics.filter({ hasText: 'line 2' }).waitFor();
    const message = await diagnostics.innerText();
    expect(message).toContain('By line 2 the program needs at least 56,000,000 steps; the page runs at most 50,000,000 (its maxSteps, fixed). Lower stepsPerMm under Machine, or shorten the moves.');
    expect(message).toContain('voxpath gcode --max-steps 56000000');
    expect(message).not.toMatch(/raise/i);
    expect(p.problems()).toEqual([]);
    await p.close();
  });
});
