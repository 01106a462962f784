//! The step grid: points, axes and single steps.
//!
//! Coordinates are integer grid units (one unit = one motor step or one pixel).
//! Inputs are limited to |coordinate| <= 2^30 so that every difference fits in
//! 32 bits and every product of two differences fits in i64 (2^31 * 2^31 = 2^62).

use crate::error::{Error, number_text};
use crate::range::IntegerRange;
use std::fmt;
use std::mem::MaybeUninit;

/// Most axes a path may have: X Y Z A B C.
pub const MAX_AXES: usize = 6;

/// Calls `$recv.$method::<DIMS>(args)` with the number of axes `$dims` as
/// the const `DIMS`, so that a stepper's per-axis loops unroll for each
/// count; 1 axis, or 6, takes [`MAX_AXES`] (the loops stop at the path's own
/// axis count either way). One dispatch for every `fill_axes` of the line
/// steppers, not a `match` written out in each.
macro_rules! by_axis_count {
    ($dims:expr, $recv:ident . $method:ident ( $($arg:expr),* )) => {
        match $dims {
            2 => $recv.$method::<2>($($arg),*),
            3 => $recv.$method::<3>($($arg),*),
            4 => $recv.$method::<4>($($arg),*),
            5 => $recv.$method::<5>($($arg),*),
            _ => $recv.$method::<{ $crate::grid::MAX_AXES }>($($arg),*),
        }
    };
}
pub(crate) use by_axis_count;

/// Axis names in index order.
pub const AXIS_NAMES: [&str; MAX_AXES] = ["x", "y", "z", "a", "b", "c"];

/// Octants 1-8 of a plane (Saleem Fig. 1, counter-clockwise from the first
/// axis): the labels of an octant column, which stores octant k as index k - 1.
pub const OCTANT_LABELS: [&str; 8] = ["1", "2", "3", "4", "5", "6", "7", "8"];

/// A grid axis and a way along it, as a category column's labels: index
/// 2 axis is toward +axis, 2 axis + 1 toward -axis (see [`signed_axis`]).
/// Columns that place something in the 3D view relative to a point use it
/// (regions' exit-face axes, the circle's other candidate), so the page reads
/// a direction instead of working one out.
pub const SIGNED_AXIS_LABELS: &[&str] = &["+x", "-x", "+y", "-y", "+z", "-z"];

/// The [`SIGNED_AXIS_LABELS`] index of grid axis `axis` (0-2) taken in the
/// direction of the sign of `dir` (0 counts as +).
pub fn signed_axis(axis: usize, dir: i64) -> u8 {
    debug_assert!(axis < 3, "signed-axis labels cover x, y and z");
    2 * axis as u8 + (dir < 0) as u8
}

/// Largest accepted |coordinate| of an input point, in grid units.
pub const COORD_LIMIT: i64 = 1 << 30;

/// The range of each coordinate of an input point, as the catalogue
/// declares it for every point option (the page's form checks each
/// coordinate against it as it is typed, in the words [`Point::parse`]
/// refuses it with).
pub const COORD_RANGE: IntegerRange = IntegerRange {
    min: Some(-COORD_LIMIT),
    max: Some(COORD_LIMIT),
    whole: COORDINATE_UNITS,
};

/// What a coordinate must be when it is not whole.
pub const COORDINATE_UNITS: &str = "an integer number of grid units";

/// Largest magnitude (exclusive) of the integers whose products the fast
/// paths form in i64: two factors below 2^31 multiply to below 2^62, so a
/// sum or difference of two such products stays below 2^63. Inputs within
/// +-2^30 differ by at most 2^31, so only a move spanning the whole range on
/// an axis (or a point outside the input box) reaches the i128 fallback.
pub const I64_PRODUCT_BOUND: u64 = 1 << 31;

/// True when every value is below [`I64_PRODUCT_BOUND`] in magnitude (an OR
/// of the magnitudes has the highest bit of the largest: one test, no branch
/// per value).
pub fn within_i64_product_bound(values: &[i64]) -> bool {
    values.iter().fold(0, |bits, v| bits | v.unsigned_abs()) < I64_PRODUCT_BOUND
}

/// A grid point with 1 to [`MAX_AXES`] integer coordinates.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub struct Point {
    coords: [i64; MAX_AXES],
    dims: u8,
}

impl Point {
    /// The point with the given coordinates; panics on more than [`MAX_AXES`]
    /// (callers validate user input with [`Point::parse`] first).
    pub fn new(coords: &[i64]) -> Point {
        assert!(
            (1..=MAX_AXES).contains(&coords.len()),
            "a point has 1 to {MAX_AXES} axes"
        );
        let mut c = [0; MAX_AXES];
        c[..coords.len()].copy_from_slice(coords);
        Point {
            coords: c,
            dims: coords.len() as u8,
        }
    }

    /// This point in `dims` axes: the axes it gains are at 0, and those it
    /// loses must be (a circle given in x and y runs at z = 0).
    pub fn with_dims(&self, dims: usize) -> Point {
        debug_assert!(
            self.coords()
                .get(dims..)
                .is_none_or(|lost| lost.iter().all(|&c| c == 0)),
            "{self} loses a coordinate that is not 0"
        );
        let mut c = [0; MAX_AXES];
        let kept = dims.min(self.dims());
        c[..kept].copy_from_slice(&self.coords[..kept]);
        Point {
            coords: c,
            dims: dims as u8,
        }
    }

    /// The origin with `dims` axes.
    pub fn origin(dims: usize) -> Point {
        Point::new(&[0; MAX_AXES][..dims])
    }

    /// Validates user input: 2..=MAX_AXES integers within [`COORD_RANGE`].
    /// `field` names the input in the error (for example "from").
    pub fn parse(field: &str, values: &[f64]) -> Result<Point, Error> {
        if !(2..=MAX_AXES).contains(&values.len()) {
            return Err(Error::field(
                field,
                format!("expected 2 to {MAX_AXES} coordinates, got {}", values.len()),
            ));
        }
        let mut coords = [0i64; MAX_AXES];
        for (axis, &v) in values.iter().enumerate() {
            let name = AXIS_NAMES[axis];
            if !v.is_finite() || v.fract() != 0.0 {
                return Err(Error::field(
                    field,
                    format!("{name} {}, got {}", COORD_RANGE.not_whole(), number_text(v)),
                )
                .on_axis(axis));
            }
            if let Some(words) = COORD_RANGE.must_be_if_outside(v) {
                return Err(
                    Error::field(field, format!("{name} {words}, got {}", number_text(v)))
                        .on_axis(axis),
                );
            }
            coords[axis] = v as i64;
        }
        Ok(Point::new(&coords[..values.len()]))
    }

    pub fn dims(&self) -> usize {
        self.dims as usize
    }

    pub fn coords(&self) -> &[i64] {
        &self.coords[..self.dims as usize]
    }

    pub fn coords_mut(&mut self) -> &mut [i64] {
        &mut self.coords[..self.dims as usize]
    }

    /// Coordinate on `axis` (0 = x).
    pub fn get(&self, axis: usize) -> i64 {
        self.coords()[axis]
    }

    /// `to - self` per axis; exact because inputs are within +-2^30.
    #[inline]
    pub fn delta_to(&self, to: &Point) -> [i64; MAX_AXES] {
        let mut d = [0; MAX_AXES];
        for axis in 0..self.dims() {
            d[axis] = to.coords[axis] - self.coords[axis];
        }
        d
    }

    /// The most units any axis moves from here to `to`: the fewest steps
    /// that reach it moving each axis at most a unit a step.
    pub fn chebyshev_to(&self, to: &Point) -> u64 {
        (0..self.dims())
            .map(|axis| (to.coords[axis] - self.coords[axis]).unsigned_abs())
            .max()
            .unwrap_or(0)
    }

    /// Moves this point by `delta` per axis (from [`displacement`]).
    pub fn displace(&mut self, delta: &[i64; MAX_AXES]) {
        for axis in 0..self.dims() {
            self.coords[axis] += delta[axis];
        }
    }

    /// Applies one step in place.
    #[inline]
    pub fn apply(&mut self, step: Step) {
        for axis in 0..self.dims() {
            self.coords[axis] += step.delta(axis);
        }
    }
}

impl fmt::Debug for Point {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{self}")
    }
}

impl fmt::Display for Point {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "(")?;
        for (i, c) in self.coords().iter().enumerate() {
            if i > 0 {
                write!(f, ", ")?;
            }
            write!(f, "{c}")?;
        }
        write!(f, ")")
    }
}

/// One step: each axis moves by -1, 0 or +1.
///
/// Packed in 16 bits so that a 10,000,000-step path costs 20 MB:
/// bit `axis` is set when the axis moves, bit `8 + axis` when it moves in the
/// negative direction. This is also a step/direction pulse pair per axis.
/// Transparent: a run of steps is a run of u16, which the line loop stores
/// eight at a time (`line::terms`).
#[derive(Clone, Copy, PartialEq, Eq, Hash, Default)]
#[repr(transparent)]
pub struct Step(pub u16);

impl Step {
    /// No axis moves.
    pub const NONE: Step = Step(0);

    /// The step that moves `axis` by `direction` (-1, 0 or +1).
    pub fn along(axis: usize, direction: i64) -> Step {
        Step::NONE.with(axis, direction)
    }

    /// This step with `axis` also moved by `direction` (-1, 0 or +1).
    ///
    /// The two bits are formed arithmetically rather than by a match, so a
    /// stepper that calls this once per axis per step has no data-dependent
    /// branch here (the range check is never taken by a correct stepper).
    #[inline]
    pub fn with(self, axis: usize, direction: i64) -> Step {
        assert!(
            (-1..=1).contains(&direction),
            "a step moves an axis by -1, 0 or +1, not {direction}"
        );
        let moves = (direction != 0) as u16;
        let negative = (direction < 0) as u16;
        Step(self.0 | moves << axis | negative << (8 + axis))
    }

    /// The step from point `before` to point `now`, coordinates of points
    /// at most one cell apart on each axis ([`jumps`] is false).
    pub fn between(before: &[i64], now: &[i64]) -> Step {
        (0..before.len()).fold(Step::NONE, |step, axis| {
            step.with(axis, now[axis] - before[axis])
        })
    }

    /// Movement of `axis`: -1, 0 or +1, as moved - 2 * (moved and negative):
    /// no branch, so applying a run of steps to a point is a straight loop.
    #[inline]
    pub fn delta(self, axis: usize) -> i64 {
        let moved = (self.0 >> axis & 1) as i64;
        let negative = (self.0 >> (8 + axis) & 1) as i64;
        moved - 2 * (moved & negative)
    }

    /// Adds `times` this step's move to `delta`, visiting only the axes
    /// it moves: a line's fill sums its displacement from its active axes'
    /// step and a step per passive axis, each moving an axis or two, where
    /// a sum over all six axes of each (a call of its own in wasm) took 3%
    /// of the trace of an arc in 1,720 chords.
    #[inline]
    pub fn add_times(self, times: i64, delta: &mut [i64; MAX_AXES]) {
        let mut axes = self.moving_axes();
        while axes != 0 {
            let axis = axes.trailing_zeros() as usize;
            delta[axis] += self.delta(axis) * times;
            axes &= axes - 1;
        }
    }

    /// Bit mask of the axes that move (bit 0 = x).
    pub fn moving_axes(self) -> u8 {
        self.0 as u8
    }

    /// How many axes move in this step.
    pub fn axis_count(self) -> u32 {
        self.moving_axes().count_ones()
    }
}

impl fmt::Debug for Step {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Step(")?;
        let mut first = true;
        for (axis, name) in AXIS_NAMES.iter().enumerate() {
            let d = self.delta(axis);
            if d != 0 {
                if !first {
                    write!(f, " ")?;
                }
                write!(f, "{name}{}", if d > 0 { "+" } else { "-" })?;
                first = false;
            }
        }
        write!(f, ")")
    }
}

/// Bits apart of the per-axis counters in [`displacement`].
const LANE_BITS: u32 = 10;
/// One multiplication spreads 6 step bits into counters LANE_BITS apart:
/// bit a of x times 2^(9a') lands at a + 9a', which is 10a only for a' = a,
/// and no two (bit, copy) pairs share a position (their bits differ by less
/// than 9), so nothing carries into a counter.
const SPREAD_MULTIPLIER: u64 = 1 | 1 << 9 | 1 << 18 | 1 << 27 | 1 << 36 | 1 << 45;
/// The counters' positions: bit 10a for axis a.
const SPREAD_MASK: u64 = 1 | 1 << 10 | 1 << 20 | 1 << 30 | 1 << 40 | 1 << 50;
/// Steps summed before the 10-bit counters are emptied.
const LANE_CAPACITY: usize = (1 << LANE_BITS) - 1;

/// Whether `now` is more than one cell from `before` on some axis, so
/// that no step leads from one to the other.
pub fn jumps(before: &[i64], now: &[i64]) -> bool {
    before.iter().zip(now).any(|(a, b)| (a - b).abs() > 1)
}

/// Slots of steps every one of which has been written, as those steps:
/// what a recording loop reads back of the room it writes into
/// ([`crate::trace::Stepper::fill`]). The standard library's
/// `assume_init_ref` on slices is newer than this crate's rust-version.
///
/// # Safety
/// Every slot of `slots` has been written.
#[inline(always)]
pub unsafe fn written_steps(slots: &[MaybeUninit<Step>]) -> &[Step] {
    // SAFETY: MaybeUninit<Step> has Step's layout, and every slot holds a
    // step (the caller's promise).
    unsafe { &*(slots as *const [MaybeUninit<Step>] as *const [Step]) }
}

/// [`written_steps`], mutable.
///
/// # Safety
/// Every slot of `slots` has been written.
#[inline(always)]
pub unsafe fn written_steps_mut(slots: &mut [MaybeUninit<Step>]) -> &mut [Step] {
    // SAFETY: as in written_steps.
    unsafe { &mut *(slots as *mut [MaybeUninit<Step>] as *mut [Step]) }
}

/// Where a run of steps moves, per axis. Applying each step to a point
/// costs several operations per axis; here each step's six moving bits and
/// six negative bits are spread into one counter per axis with one
/// multiplication each ([`SPREAD_MULTIPLIER`]) and summed, a few operations
/// per step whatever the number of axes. The trace builder finds the
/// position after every chunk of steps this way.
pub fn displacement(steps: &[Step]) -> [i64; MAX_AXES] {
    let spread = |bits: u16| (bits as u64 & 0x3f).wrapping_mul(SPREAD_MULTIPLIER) & SPREAD_MASK;
    let mut delta = [0; MAX_AXES];
    for run in steps.chunks(LANE_CAPACITY) {
        let (mut moved, mut negative) = (0u64, 0u64);
        for step in run {
            moved += spread(step.0);
            negative += spread(step.0 >> 8);
        }
        for (axis, d) in delta.iter_mut().enumerate() {
            let lane = |counters: u64| {
                (counters >> (LANE_BITS * axis as u32) & LANE_CAPACITY as u64) as i64
            };
            // A negative move is counted in both: +1 - 2 = -1.
            *d += lane(moved) - 2 * lane(negative);
        }
    }
    delta
}

/// `x` rounded to the nearest whole number, halves away from zero, where x
/// was computed within `error` of a value that may be exactly a half: x
/// within `error` below a half is taken as that half (cos 60° in f64 is
/// 0.5000000000000001, and r = 3 times the sine of 30° 1.4999999999999998).
/// Wasm has only round-half-to-even, so f64::round is a libm call there;
/// trunc and signum are wasm instructions. x - trunc(x) is exact (Sterbenz:
/// for |x| >= 1, trunc(x) is within a factor 2 of x; below 1 it is 0); NaN
/// and the infinities come out as they go in.
pub fn round_half_away_within(x: f64, error: f64) -> f64 {
    let whole = x.trunc();
    if (x - whole).abs() >= 0.5 - error {
        whole + x.signum()
    } else {
        whole
    }
}

/// `numerator / denominator` (denominator > 0) rounded to the nearest whole
/// number, halves away from zero, exactly: the quotient's half is a half,
/// where the product of a float fraction may fall either side of it. In
/// i64, not i128 (in wasm a call into software a multiplication and a
/// division): its caller, a helix's chord heights, passes a rise of at most
/// 2^31 times a chord index of at most 2^16, so 2 |numerator| + denominator
/// stays under 2^49.
pub fn round_ratio_half_away(numerator: i64, denominator: i64) -> i64 {
    debug_assert!(denominator > 0);
    numerator.signum() * ((2 * numerator.abs() + denominator) / (2 * denominator))
}

/// Greatest common divisor of non-negative integers (gcd(0, 0) = 0).
/// Stein's binary algorithm: shifts and subtractions, no division, which
/// in wasm (i64.rem_u) costs tens of cycles a step; a G-code program finds
/// the divisor of every move it steps by regions, nd or bresenham3d.
pub fn gcd(a: u64, b: u64) -> u64 {
    if a == 0 || b == 0 {
        return a | b;
    }
    let shift = (a | b).trailing_zeros();
    let (mut a, mut b) = (a >> a.trailing_zeros(), b);
    loop {
        // a is odd here; b loses its factors of 2 (none of them common).
        b >>= b.trailing_zeros();
        if a > b {
            (a, b) = (b, a);
        }
        b -= a;
        if b == 0 {
            return a << shift;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every one of the 3^6 steps: each axis by -1, 0 or +1.
    fn every_step() -> impl Iterator<Item = Step> {
        (0..729).map(|code| {
            let mut step = Step::NONE;
            let mut rest = code;
            for axis in 0..MAX_AXES {
                step = step.with(axis, rest % 3 - 1);
                rest /= 3;
            }
            step
        })
    }

    #[test]
    fn chebyshev_to_is_the_longest_move_of_any_axis() {
        let from = Point::new(&[3, -4, 5]);
        assert_eq!(from.chebyshev_to(&Point::new(&[-7, 2, 5])), 10);
        assert_eq!(from.chebyshev_to(&Point::new(&[3, -4, 5])), 0);
        assert_eq!(Point::new(&[0, 0]).chebyshev_to(&Point::new(&[2, -9])), 9);
        // Across the whole coordinate range, as a chord's may be.
        let edge = (1i64 << 30) - 1;
        assert_eq!(
            Point::new(&[-edge, 0, 0]).chebyshev_to(&Point::new(&[edge, 1, 0])),
            2 * edge as u64
        );
    }

    #[test]
    fn step_packs_direction_per_axis() {
        let s = Step::along(0, 1).with(2, -1).with(5, 1);
        assert_eq!(
            (s.delta(0), s.delta(1), s.delta(2), s.delta(5)),
            (1, 0, -1, 1)
        );
        assert_eq!(s.axis_count(), 3);
    }

    #[test]
    fn arithmetic_step_bits_match_every_axis_and_direction() {
        // Every axis and direction, alone and on top of every other axis
        // already moving either way: the bits and the deltas agree.
        for axis in 0..MAX_AXES {
            for direction in -1..=1 {
                let alone = Step::along(axis, direction);
                assert_eq!(alone.delta(axis), direction);
                assert_eq!(alone.axis_count(), (direction != 0) as u32);
                for other in (0..MAX_AXES).filter(|&o| o != axis) {
                    for other_direction in [-1, 1] {
                        let s = Step::along(other, other_direction).with(axis, direction);
                        assert_eq!(
                            (s.delta(axis), s.delta(other)),
                            (direction, other_direction)
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn add_times_adds_the_step_s_move_on_every_axis_it_moves() {
        // Every one of the 3^6 steps, times a count of either sign, onto
        // a displacement that already has some.
        let start = [5, -3, 0, 7, 1, -2];
        for step in every_step() {
            for times in [0, 1, -4, 1 << 40] {
                let mut sum = start;
                step.add_times(times, &mut sum);
                let expected: Vec<i64> = (0..MAX_AXES)
                    .map(|axis| start[axis] + step.delta(axis) * times)
                    .collect();
                assert_eq!(sum[..], expected[..], "{step:?} times {times}");
            }
        }
    }

    #[test]
    fn displacement_sums_the_steps_per_axis() {
        // Every one of the 3^6 steps, repeated past a counter's capacity
        // (1023), in an order that mixes directions.
        let steps: Vec<Step> = every_step().collect();
        let many: Vec<Step> = (0..5000).map(|k| steps[k * 7 % steps.len()]).collect();
        for run in [&steps[..], &many[..], &many[..1023], &many[..1024], &[][..]] {
            let mut expected = [0; MAX_AXES];
            for step in run {
                for (axis, e) in expected.iter_mut().enumerate() {
                    *e += step.delta(axis);
                }
            }
            assert_eq!(displacement(run), expected, "{} steps", run.len());
        }
        // All on one axis, one way: a counter filled to capacity and more.
        assert_eq!(displacement(&[Step::along(5, -1); 3000])[5], -3000);
    }

    #[test]
    #[should_panic(expected = "a step moves an axis by -1, 0 or +1, not 2")]
    fn a_step_of_two_units_is_a_bug() {
        Step::along(0, 2);
    }

    #[test]
    fn parse_names_the_field_and_axis() {
        let e = Point::parse("to", &[1.0, 2.5, 0.0]).unwrap_err();
        assert_eq!(e.axis, Some(1));
        assert_eq!(
            e.to_string(),
            "to: y must be an integer number of grid units, got 2.5"
        );
        let e = Point::parse("from", &[0.0, 2f64.powi(31)]).unwrap_err();
        assert_eq!(
            e.to_string(),
            "from: y must be -1073741824 to 1073741824, got 2147483648"
        );
        let e = Point::parse("from", &[1.0]).unwrap_err();
        assert_eq!(e.to_string(), "from: expected 2 to 6 coordinates, got 1");
        // A huge number is said in e-notation, not as its 301 digits.
        let huge = Point::parse("to", &[1e300, 0.0]).unwrap_err();
        assert_eq!(
            huge.to_string(),
            "to: x must be -1073741824 to 1073741824, got 1e300"
        );
        let tiny = Point::parse("to", &[0.0, 1e-300]).unwrap_err();
        assert_eq!(
            tiny.to_string(),
            "to: y must be an integer number of grid units, got 1e-300"
        );
        assert_eq!(
            Point::parse("from", &[-3.0, 4.0]).unwrap(),
            Point::new(&[-3, 4])
        );
    }

    /// Exact at the largest inputs its caller passes (a rise of ±2^31 at
    /// chord i of 2^16), against the quotient rounded in i128.
    #[test]
    fn ratio_rounds_halves_away_at_the_largest_heights() {
        let n = 1i64 << 16;
        for rise in [(1i64 << 31), -(1i64 << 31), (1 << 31) - 1, 3, -3, 0] {
            for i in [1, 2, n / 2, n - 1, n] {
                let exact = (rise as i128 * i as i128 * 2 + (n as i128) * (rise as i128).signum())
                    / (2 * n as i128);
                assert_eq!(
                    round_ratio_half_away(rise * i, n) as i128,
                    exact,
                    "{rise} {i}"
                );
            }
        }
        assert_eq!(round_ratio_half_away(5, 2), 3);
        assert_eq!(round_ratio_half_away(-5, 2), -3);
        assert_eq!(round_ratio_half_away(7, 3), 2);
    }

    #[test]
    fn gcd_of_deltas() {
        assert_eq!(gcd(8000, 6000), 2000);
        assert_eq!(gcd(gcd(8000, 6000), 5000), 1000);
        assert_eq!(gcd(0, 7), 7);
        assert_eq!(gcd(0, 0), 0);
        assert_eq!(gcd(7, 0), 7);
        assert_eq!(gcd(1 << 30, 3 << 20), 1 << 20);
    }

    proptest::proptest! {
        /// The binary GCD against Euclid's, on magnitudes up to 2^31 with
        /// common factors of 2 (which the binary one takes out first).
        #[test]
        fn binary_gcd_equals_euclid(a in 0u64..1 << 31, b in 0u64..1 << 31, twos in 0u32..8) {
            let euclid = |mut a: u64, mut b: u64| {
                while b != 0 {
                    (a, b) = (b, a % b);
                }
                a
            };
            proptest::prop_assert_eq!(gcd(a, b), euclid(a, b));
            proptest::prop_assert_eq!(gcd(a << twos, b << twos), euclid(a << twos, b << twos));
        }
    }
}
