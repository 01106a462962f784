/**
 * Arcs and helices: a full circle of r = 100,000 stepped directly and in
 * chords (Grbl's tolerance 0.5, each chord by regions), and a helix of nine
 * turns of r = 20,000 rising 9000, by Saleem's method and in chords.
 */
import { COLUMN_NOTES, measureRow, native } from './measure.js';
import type { BenchGroup, BenchRow } from './types.js';

const CIRCLE = { from: [100_000, 0, 0], to: [100_000, 0, 0], center: [0, 0, 0] };
const HELIX = { from: [20_000, 0, 0], to: [20_000, 0, 9000], center: [0, 0, 0], turns: 8 };

const CASES = [
  ['circle, full turn of r = 100000', { algorithm: 'circle', ...CIRCLE }],
  ['arc-segments, the same circle in chords', { algorithm: 'arc-segments', ...CIRCLE }],
  ['helix (saleem), 9 turns of r = 20000 rising 9000', { algorithm: 'helix', ...HELIX }],
  ['helix (segments), the same helix in chords', { algorithm: 'helix', method: 'segments', ...HELIX }],
] as const;

export default async function arcs(): Promise<BenchGroup> {
  const natives = native(CASES.map(([, request]) => request));
  const rows: BenchRow[] = [];
  for (const [i, [name, request]] of CASES.entries()) rows.push(await measureRow(name, request, natives[i]!));
  return { title: 'Arcs and helices', notes: COLUMN_NOTES, rows };
}
