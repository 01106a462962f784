/** Axis names by axis index (0 = x), as the core names them in its messages. */
export const AXIS_NAMES = ['x', 'y', 'z', 'a', 'b', 'c'] as const;
