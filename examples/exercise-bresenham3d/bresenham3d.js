// A student's 3D Bresenham line, as handed in for the exercise "implement
// 3D Bresenham (Saleem & Saleem 2004, section 3), tie = advance". It has a
// deliberate bug for the exercise to find, marked below.

/**
 * The cells of the line from `from` to `to` (integer [x, y, z] each), one
 * per step: the axis that moves farthest steps every time; each other axis
 * keeps an error term scaled by 2·Δmajor and steps when the line is half a
 * cell or more away.
 * @param {number[]} from @param {number[]} to @returns {number[][]}
 */
export function bresenham3d(from, to) {
  const delta = to.map((t, a) => Math.abs(t - from[a]));
  const sign = to.map((t, a) => Math.sign(t - from[a]));
  const major = delta.indexOf(Math.max(...delta));
  const error = delta.map((d) => 2 * d - delta[major]);
  const point = [...from];
  const points = [[...point]];
  for (let i = 0; i < delta[major]; i++) {
    point[major] += sign[major];
    for (let a = 0; a < 3; a++) {
      if (a === major) continue;
      // DELIBERATE BUG (the exercise): the rule steps when the line is
      // exactly half way (error >= 0, tie = advance); '>' holds there.
      if (error[a] > 0) {
        point[a] += sign[a];
        error[a] -= 2 * delta[major];
      }
      error[a] += 2 * delta[a];
    }
    points.push([...point]);
  }
  return points;
}
