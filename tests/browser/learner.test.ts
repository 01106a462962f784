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
