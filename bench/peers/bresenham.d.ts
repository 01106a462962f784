// npm `bresenham` 0.0.4 ships no types: its one export, as its index.js has it.
declare module 'bresenham' {
  /** Calls `fn` with every cell of the line from (x0, y0) to (x1, y1), both included; without `fn`, returns them. */
  function bresenham(x0: number, y0: number, x1: number, y1: number, fn: (x: number, y: number) => void): void;
  export default bresenham;
}
