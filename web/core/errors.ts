import type { Limit } from './pkg/voxpath.js';

/** An input the core rejected, naming the option (or G-code line and column). */
export class VoxpathError extends Error {
  override readonly name = 'VoxpathError';
  /** The option at fault, e.g. 'from' or 'maxSteps'. */
  readonly field?: string;
  /** For a point option, the axis index (0 = x) at fault. */
  readonly axis?: number;
  /** 1-based line and column in a text input such as a G-code program. */
  readonly line?: number;
  readonly column?: number;
  /** The message without its location prefix. */
  readonly detail: string;
  /** The cap the input ran into (say maxSteps, with what the input needs), when that is what is wrong. */
  readonly limit?: Limit;

  constructor(message: string, where: { field?: string; axis?: number; line?: number; column?: number; detail?: string; limit?: Limit } = {}) {
    super(message);
    this.field = where.field;
    this.axis = where.axis;
    this.line = where.line;
    this.column = where.column;
    this.detail = where.detail ?? message;
    this.limit = where.limit;
  }
}

/**
 * Runs a call into the core, turning the errors it throws (JS Errors named
 * VoxpathError carrying field/line/column/limit) into VoxpathError instances.
 * Anything else, such as a trap from a bug in the core, is rethrown as is.
 */
export function callCore<T>(call: () => T): T {
  try {
    return call();
  } catch (error) {
    if (error instanceof Error && error.name === 'VoxpathError') {
      const e = error as Error & { field?: string; axis?: number; line?: number; column?: number; detail?: string; limit?: Limit };
      throw new VoxpathError(e.message, e);
    }
    throw error;
  }
}
