/**
 * voxpath's headless API, for Node (ESM) and browsers:
 *
 *   import { trace } from 'voxpath';
 *   const t = await trace({ algorithm: 'regions', from: [0, 0, 0], to: [10, 7, 6] });
 *   t.points;          // Int32Array, stride t.dims
 *   t.decisions.M;     // Float64Array, one value per step
 *   t.deviation;       // Float64Array, one value per point
 *   t.metrics;         // { steps, maxDeviation, meanDeviation, ... }
 */
export { trace, algorithms, Trace } from './trace.js';
export { VoxpathError } from './errors.js';
export { memoryBytes } from './wasm.js';
export { experiments, randomLines } from './experiment.js';
export type { ErrorStats, ExperimentInfo, MeasureSummary, RandomLinesOptions, RandomLinesResult, Spread } from './experiment.js';
export { randomLinesToCsv, randomLinesToTable, traceToCsv, traceToJson, traceToTable } from './export.js';
export type { TraceJson } from './export.js';
export type * from './types.js';
