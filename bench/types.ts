/**
 * The shape every bench/*.bench.ts file follows: it default-exports one
 * async function that measures and returns a group of rows; bench/run.mjs
 * finds the files, runs them in name order and prints each group.
 */

/** One line of a group's table. */
export interface BenchRow {
  /** What was traced, e.g. 'regions, 3D line'. */
  name: string;
  /** Steps in the path. */
  steps: number;
  /** Rates per second by column name (steps, or what the group notes say, e.g. lines); a column a row lacks prints as '-'. */
  rates: Record<string, number>;
  /** Ratios by column name (for example wasm over TypeScript). */
  ratios?: Record<string, number>;
}

export interface BenchGroup {
  title: string;
  /** What each column measures, printed above the table. */
  notes: string[];
  rows: BenchRow[];
}

/** What a bench file default-exports. */
export type Bench = () => Promise<BenchGroup>;
