/**
 * The detail of the point on screen: the core's StepDetail (the point, the
 * step that produced it with its decision read and explained, the deviation,
 * the segment's note and the decision's picture), asked of the worker in one
 * request per point and handed to every view that shows it: the inspector
 * with its figure, and the 3D overlay.
 *
 * One request at a time, always for the latest wanted point, so fast
 * playback or scrubbing never queues stale work in the worker; a new path's
 * first detail is asked for after its first frame is drawn, so that the
 * replay never shares the CPU with that frame.
 */
import type { StepDetail } from '../core/types.js';
import { afterNextFrame } from '../main-thread.js';
import { CoreCrash } from '../worker/client.js';

/** What the details are read from: a trace the worker holds (RemoteTrace). */
export interface DetailedTrace {
  stepDetail(pointIndex: number): Promise<StepDetail>;
}

export class PointDetails {
  readonly #onDetail: (detail: StepDetail) => void;
  readonly #onError: (error: unknown) => void;
  #trace: DetailedTrace | undefined;
  /** The point the views should show; requests chase it one at a time. */
  #wantedPointIndex = 0;
  #latest: StepDetail | undefined;
  #fetching = false;
  /** Resolves once the current trace's first frame is drawn. */
  #drawn: Promise<void> = Promise.resolve();

  /** `onDetail` gets each detail of the current trace; `onError` a failure other than a crash (which the page's crash banner reports). */
  constructor(onDetail: (detail: StepDetail) => void, onError: (error: unknown) => void) {
    this.#onDetail = onDetail;
    this.#onError = onError;
  }

  /** Follows `trace` (undefined: none) from `pointIndex`, once its first frame is drawn. */
  setTrace(trace: DetailedTrace | undefined, pointIndex: number): void {
    this.#trace = trace;
    this.#latest = undefined;
    this.#drawn = afterNextFrame();
    this.show(pointIndex);
  }

  /** Asks for point index `pointIndex` of the current trace. */
  show(pointIndex: number): void {
    this.#wantedPointIndex = pointIndex;
    if (this.#trace && !this.#fetching) void this.#fetch();
  }

  async #fetch(): Promise<void> {
    this.#fetching = true;
    try {
      while (this.#trace && this.#latest?.pointIndex !== this.#wantedPointIndex) {
        // Read each time round: the trace may have changed while a request was out.
        await this.#drawn;
        const trace = this.#trace;
        if (!trace) break;
        const detail = await trace.stepDetail(this.#wantedPointIndex);
        if (trace !== this.#trace) continue;
        this.#latest = detail;
        this.#onDetail(detail);
      }
    } catch (error) {
      if (!(error instanceof CoreCrash)) this.#onError(error);
    } finally {
      this.#fetching = false;
    }
  }
}
