/**
 * Giving the main thread back. A browser measures responsiveness per task:
 * work split across tasks lets key presses, clicks and frames in between.
 */

/** Resolves in a task of its own, after whatever is queued now (input included). */
export function nextTask(): Promise<void> {
  return new Promise((resolve) => setTimeout(resolve, 0));
}

/**
 * Resolves once the next frame has been drawn: a task queued from that
 * frame's animation callback runs after the frame is committed. Work that
 * can wait for it (asking the worker for explanations of a new path) then no
 * longer shares the CPU with the frame, which a software GPU draws on the
 * same cores.
 */
export function afterNextFrame(): Promise<void> {
  return new Promise((resolve) => requestAnimationFrame(() => setTimeout(resolve, 0)));
}
