/**
 * Standard output of the CLI: written a piece at a time, each piece once the
 * last has been handed to the system, so that memory holds one piece
 * whatever the length of the output.
 */

/**
 * Standard output refused a write (ENOSPC on a full disk, EIO, ...): main
 * says so in one line and exits with OUTPUT_FAILED.
 */
export class OutputError extends Error {}

/** The exit status when the output cannot be written (check and gcode already give 1 a meaning of their own). */
export const OUTPUT_FAILED = 3;

/** "ENOSPC: no space left on device", without the system call Node appends (", write"). */
function outputFailure(e: NodeJS.ErrnoException): OutputError {
  const message = e.syscall !== undefined ? e.message.replace(new RegExp(`, ${e.syscall}$`), '') : e.message;
  return new OutputError(`cannot write the output: ${message}`);
}

/**
 * Writes to stdout; resolves to false when the reader is gone. A reader that
 * stops early (`voxpath ... | head`) closes the pipe: EPIPE then means it has
 * all it wanted, not that voxpath failed. Any other error rejects with an
 * OutputError.
 */
export async function write(piece: string | Uint8Array): Promise<boolean> {
  return new Promise<boolean>((resolve, reject) =>
    process.stdout.write(piece, (e?: NodeJS.ErrnoException | null) => (e && e.code !== 'EPIPE' ? reject(outputFailure(e)) : resolve(!e))),
  );
}

/** Writes pieces one after another (see write); stops when the reader is gone. */
export async function writeAll(pieces: Iterable<string | Uint8Array>): Promise<void> {
  for (const piece of pieces) if (!(await write(piece))) return;
}

/**
 * The stream also reports a failed write as an 'error' event, after the
 * write's callback, which has already rejected with it; unheard, the event
 * would end the process with a stack trace outside main's catch.
 */
function writeErrorReportedByCallback(): void {}

/**
 * A message that cannot be written to stderr (`2>/dev/full`) has nowhere
 * else to go: unheard, its 'error' event ended the process with status 1,
 * where the exit status is the one thing left to say what happened (a usage
 * error's 2).
 */
function stderrUnwritable(): void {}

/** Installs the listeners above once, however often main runs in one process. */
export function listenForWriteErrors(): void {
  if (!process.stdout.listeners('error').includes(writeErrorReportedByCallback)) process.stdout.on('error', writeErrorReportedByCallback);
  if (!process.stderr.listeners('error').includes(stderrUnwritable)) process.stderr.on('error', stderrUnwritable);
}
