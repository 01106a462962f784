/**
 * The page's own words for a cap the core reports. The core's error names
 * the cap it met (its `limit`: the option, its value in force, what the
 * input needs at least, the most the option may be set to) and advises its
 * callers to raise it; the page sets maxSteps itself and has no control for
 * it, so it says what can be done here instead: shorten the move, or lower
 * the steps per mm, or take the work to the command line when a higher
 * maxSteps would be enough.
 */
import type { GcodeDiagnostic } from '../core/index.js';
import type { Limit } from '../core/types.js';
import { grouped } from '../format.js';

/** Where a command-line run could go past the page's cap, and when none could. */
function elsewhere(limit: Limit, command: string): string {
  return limit.atLeast <= limit.most
    ? ` The command line goes up to ${grouped(limit.most)} steps: ${command} --max-steps ${limit.atLeast}.`
    : ` No trace may have that many steps (${grouped(limit.most)} at most, anywhere).`;
}

/** What to do about a path (trace or compare mode) that needs more steps than the page draws. */
export function pathLimitAdvice(limit: Limit): string {
  return (
    `This path needs at least ${grouped(limit.atLeast)} steps; the page draws at most ${grouped(limit.value)} (its ${limit.option}, fixed). ` +
    'Shorten the move: bring its points closer together (drag a handle, or type smaller coordinates), or give an arc fewer turns.' +
    elsewhere(limit, 'voxpath trace')
  );
}

/** What to do about a program that needs more steps than the page runs. */
function programLimitAdvice(limit: Limit, line: number): string {
  return (
    `By line ${line} the program needs at least ${grouped(limit.atLeast)} steps; the page runs at most ${grouped(limit.value)} (its ${limit.option}, fixed). ` +
    'Lower stepsPerMm under Machine, or shorten the moves.' +
    elsewhere(limit, 'voxpath gcode')
  );
}

/** A program's diagnostic as the page words it: the core's message, or the page's advice for a cap. */
export function diagnosticText(diagnostic: GcodeDiagnostic): string {
  return diagnostic.limit ? programLimitAdvice(diagnostic.limit, diagnostic.line) : diagnostic.message;
}
