/**
 * voxpath's headless API, for Node (ESM) and browsers:
 *
 *   import { trace } from 'voxpath';
 *   const t = await trace({ algorithm: 'regions', from: [0, 0, 0], to: [10, 7, 6] });
 *   t.points;          // Int32Array, stride t.dims
 *   t.decisions.M;     // Float64Array, one value per step
 *   t.deviation;       // Float64Array, one value per point
 *   t.metrics;         // { steps, maxDeviation, meanDeviation, ... }, computed when first read
 *
 *   const c = await compare({ algorithms: ['regions', 'greedy'], from: [0, 0, 0], to: [10, 7, 6] });
 *   c.firstDifference; // { pointIndex, a, b, aWhy: { explanation, decisions }, bWhy }
 *
 *   const k = await checkPoints({ algorithm: 'regions', from: [0, 0, 0], to: [10, 7, 6] }, studentPoints);
 *   k.firstDifference; // { pointIndex, expected, got, message, why, decisions, around }
 *   k.alsoMatches;     // [{ label: 'bresenham3d with tie = hold', ... }]
 *
 *   import { runGcode } from 'voxpath';
 *   const p = await runGcode('G1 X10 Y5 F600', { stepsPerMm: 80 });
 *   p.move(0);         // a move: its source line, mm and steps (p.moveCount of them, read on demand)
 *   p.trace;           // a Trace of every step
 */
export { trace, algorithms, Trace } from './trace.js';
export type { PointsPassOptions } from './trace.js';
export { catalogue } from './catalogue.js';
export { AXIS_NAMES } from './axes.js';
export { VoxpathError } from './errors.js';
export { heapBytes, memoryBytes } from './wasm.js';
export { compare } from './compare.js';
export type { Cells, CompareOptions, Comparison, FirstDifference, StepWhy, TraceDifference, TraceDigest } from './compare.js';
export { checkPoints, readAndCheckPoints, readPoints } from './check.js';
export type { AlsoMatch, AroundRow, Check, CheckDifference, CheckOptions, CheckProgress, CheckStage, DifferenceKind, LearnerPoints } from './check.js';
export { GcodeProgram, runGcode } from './gcode.js';
export type { GcodeArc, GcodeDiagnostic, GcodeMove, GcodeProgramInfo, GcodeProgress, GcodeSettings, GcodeTiming, MotionChart, RunGcodeOptions } from './gcode.js';
export { pulseTrains } from './pulses.js';
export type { PulseTrain } from './pulses.js';
export { experiments, randomLines } from './experiment.js';
export type { ErrorStats, ExperimentInfo, ExperimentProgress, LineResult, MeasureSummary, RandomLines, RandomLinesOptions, RandomLinesResult, RandomLinesRunOptions, Spread } from './experiment.js';
export {
  checkToTable,
  comparisonToCsv,
  comparisonToTable,
  randomLinesToCsv,
  randomLinesToTable,
  readDecision,
  traceCsvChunks,
  traceJsonChunks,
  traceTableChunks,
  traceToCsv,
  traceToJson,
  traceToTable,
  EXPORT_CHUNK_ROWS,
} from './export.js';
export type { TraceJson } from './export.js';
export { NO_VALUE } from './types.js';
export type * from './types.js';
