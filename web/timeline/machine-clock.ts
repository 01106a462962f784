/**
 * Playback in machine time: a clock over a G-code program's planned
 * instants (Grbl's planner, in the core) that runs `slowdown` times slower
 * than real time, so a learner sees the machine slow down into a corner.
 * The step shown is the one the machine has reached at the clock's time:
 * the core's pointAtSeconds, asked of the worker. One question is in flight
 * at a time; frames while it is answered only advance the clock, so a slow
 * answer never piles up requests, and each step shown goes with the clock
 * time it was asked for.
 */

/** What machine-time playback needs of a program. */
export interface PlannedInstants {
  /** How long the program takes on its planned profile, seconds. */
  durationSeconds: number;
  /** The instant point index k is reached, seconds (0 for the start). */
  secondsAtPoint(pointIndex: number): Promise<number>;
  /** The point index reached at `seconds`: how many steps happen at or before it. */
  pointAtSeconds(seconds: number): Promise<number>;
}

export class MachineClock {
  readonly #instants: PlannedInstants;
  readonly #onReached: (pointIndex: number, seconds: number) => void;
  /** The clock, seconds of machine time; undefined until the starting point's instant is known. */
  #seconds: number | undefined;
  #asking = false;
  #stopped = false;

  /**
   * A clock starting at `startSeconds` of machine time (the instant a point
   * is reached, or where a paused clock stopped); `onReached` gets each
   * point reached and its clock time.
   */
  constructor(instants: PlannedInstants, startSeconds: Promise<number>, onReached: (pointIndex: number, seconds: number) => void) {
    this.#instants = instants;
    this.#onReached = onReached;
    void startSeconds.then(
      (seconds) => {
        this.#seconds ??= seconds;
      },
      () => this.stop(),
    );
  }

  /** Runs the clock on by `realSeconds` of real time slowed down `slowdown` times, and asks where the machine is then. */
  advance(realSeconds: number, slowdown: number): void {
    if (this.#seconds === undefined || this.#stopped) return;
    this.#seconds = Math.min(this.#seconds + realSeconds / slowdown, this.#instants.durationSeconds);
    if (this.#asking) return;
    this.#asking = true;
    const seconds = this.#seconds;
    this.#instants.pointAtSeconds(seconds).then(
      (pointIndex) => {
        this.#asking = false;
        if (!this.#stopped) this.#onReached(pointIndex, seconds);
      },
      // The program was replaced or its worker lost: this clock has nothing left to follow.
      () => this.stop(),
    );
  }

  /** Stops for good: an answer still on its way is dropped. */
  stop(): void {
    this.#stopped = true;
  }
}
