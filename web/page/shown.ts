/** What is on screen: the traces the worker holds for the current mode, and what the core said of them. */
import type { RandomLinesResult } from '../core/index.js';
import type { MeasuredTrace, RemoteProgram, RemoteTrace } from '../worker/client.js';
import type { LearnerCheck, TraceDifference } from '../worker/protocol.js';

export interface Shown {
  /** The trace (trace mode), or the first of two compared. */
  a?: MeasuredTrace;
  /** The second of two compared. */
  b?: MeasuredTrace;
  program?: RemoteProgram;
  difference?: TraceDifference;
  experiment?: RandomLinesResult;
  /** Trace mode: a learner's points checked against the trace's rule (Check points). */
  learner?: LearnerCheck;
}

/** The trace the inspector, the charts and the timeline follow: the program's, or the first one's. */
export function mainTrace(shown: Shown): RemoteTrace | undefined {
  return shown.program ?? shown.a;
}
