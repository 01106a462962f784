//! The stepping rule shared by the integer line rules whose passive axes
//! each keep one discriminant: Saleem's error terms (bresenham2d and 3d)
//! and Wang's discriminants (regions, nd). Both rules have the same shape per passive
//! axis and step:
//!
//! ```text
//! the axis steps when  value > steps_above;   then  value += increment - (decrement if it stepped)
//! ```
//!
//! so one loop, with no branch on the values, records any of them. Regions
//! also takes its single steps here; the others' `next_step` (which builds
//! the decision a learner reads) keeps the rule in the paper's words, and
//! the property tests check that both give the same steps.

use crate::grid::{MAX_AXES, Step, displacement, written_steps};
use crate::lanes::Quad;
use crate::request::TiePolicy;
use std::mem::MaybeUninit;

/// One passive axis's discriminant, in the form [`Terms`] steps.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Term {
    /// The value compared at the next step.
    pub value: i64,
    /// Added every step.
    pub increment: i64,
    /// Subtracted when the axis steps.
    pub decrement: i64,
    /// The axis steps when `value` exceeds this: the rule's threshold, less
    /// one when a tie (value == threshold) advances.
    pub steps_above: i64,
    /// The step bits of this axis toward the end point.
    pub step: Step,
}

/// A jump to the next step of a term's axis ([`Term::or_steps_into`]): from
/// the state after one of its steps (`at`, the index past it, and the
/// term's value), the state after the next.
#[derive(Clone, Copy, Debug)]
struct Jump {
    /// The value at or below which the jump takes short_count + 1 steps.
    long_below: i64,
    /// Q = decrement / increment: the fewer steps a jump may take.
    short_count: i64,
    /// What the value moves by in a jump of Q steps (Q·increment -
    /// decrement) and in one of Q + 1.
    short_move: i64,
    long_move: i64,
}

impl Jump {
    /// The jump for a term's increment, decrement and steps_above (each
    /// below 2^62 in magnitude, as [`Term::advance_mask`] asks).
    fn new(increment: i64, decrement: i64, steps_above: i64) -> Self {
        Self::over(1, increment, decrement, steps_above).expect("one step of the axis fits")
    }

    /// The jump over `count` steps of the axis at once, None where its
    /// constants would pass i64. After every step of the axis the value
    /// lies in the window (low, low + increment], low = steps_above +
    /// increment - decrement; `count` steps of the axis on it is
    /// v + J·increment - count·decrement, back in the window, for the one
    /// J that puts it there: Q = count·decrement / increment or Q + 1, the
    /// latter exactly when v <= low + count·decrement - Q·increment. For
    /// count 1 that is [`Jump::new`]'s bound.
    ///
    /// Only count·decrement can pass i64: the division's rest is below an
    /// increment, and low plus it is at most steps_above.
    fn over(count: i64, increment: i64, decrement: i64, steps_above: i64) -> Option<Self> {
        let decrements = decrement.checked_mul(count)?;
        let short_count = decrements / increment;
        let rest = decrements - short_count * increment;
        let low = steps_above + increment - decrement;
        Some(Jump {
            long_below: low + rest,
            short_count,
            short_move: -rest,
            long_move: increment - rest,
        })
    }

    /// This jump for four chains at once in the i32 lanes of a [`Quad`],
    /// None where a value they take might not fit them: the chains' places
    /// run up to `steps` plus a jump's steps, their values stay in the
    /// window (low, low + increment] of [`Jump::over`] (increment =
    /// long_move - short_move), and every value and constant must stay
    /// below 2^30 in size, as [`Quad`] asks.
    fn in_lanes(&self, steps: i64) -> Option<LaneJump> {
        const FITS: i64 = 1 << 29;
        let long_count = self.short_count + 1;
        let low = self.long_below + self.short_move;
        let increment = self.long_move - self.short_move;
        let fits = [
            steps + long_count,
            self.long_below.abs() + 1,
            low.abs() + increment,
        ]
        .iter()
        .all(|&x| x < FITS);
        fits.then(|| LaneJump {
            long_from: Quad::splat(self.long_below + 1),
            short_count: Quad::splat(self.short_count),
            short_move: Quad::splat(self.short_move),
            long_more: Quad::splat(increment),
        })
    }

    /// The state one step of the axis on from (`at`, `value`).
    #[inline(always)]
    fn from(&self, at: i64, value: i64) -> (i64, i64) {
        let long = value <= self.long_below;
        (
            at + self.short_count + long as i64,
            value
                + if long {
                    self.long_move
                } else {
                    self.short_move
                },
        )
    }
}

/// A [`Jump`] for four chains at once ([`Jump::in_lanes`]): per lane, a
/// compare, two adds and a subtraction for the place, an and and two adds
/// for the value, where each scalar jump took a compare, two selects and
/// three adds.
#[derive(Clone, Copy)]
struct LaneJump {
    /// long_below + 1: a value below it jumps short_count + 1 steps.
    long_from: Quad,
    short_count: Quad,
    short_move: Quad,
    /// long_move - short_move: the term's increment.
    long_more: Quad,
}

impl LaneJump {
    /// [`Jump::from`] in each lane.
    #[inline(always)]
    fn from(&self, ats: Quad, values: Quad) -> (Quad, Quad) {
        // All ones (-1) in the lanes whose jump is long.
        let long = self.long_from.above(values);
        (
            ats.add(self.short_count).sub(long),
            values.add(self.short_move).add(long.and(self.long_more)),
        )
    }
}

/// `steps`·`by`, None where it passes i64. Where both are below 2^31 in
/// size (a chord's, a G-code move's, most lines') the product is below
/// 2^62 and taken as it is: `checked_mul` on i64 is a call to a 128-bit
/// multiplication in wasm, which has no overflow flag, and a fill asks for
/// one or two products per term.
#[inline(always)]
fn steps_times(steps: u64, by: i64) -> Option<i64> {
    if steps < 1 << 31 && by.unsigned_abs() < 1 << 31 {
        Some(steps as i64 * by)
    } else {
        (steps as i64).checked_mul(by)
    }
}

impl Term {
    /// `steps_above` for a rule that steps past `threshold` and decides
    /// `value == threshold` by `tie`.
    pub fn steps_above(threshold: i64, tie: TiePolicy) -> i64 {
        match tie {
            TiePolicy::Hold => threshold,
            TiePolicy::Advance => threshold - 1,
        }
    }

    /// Whether this term can be stepped in 32-bit lanes: its constants are
    /// below [`NARROW_BOUND`] (2^28) in size. Every value lies in the
    /// window (steps_above - decrement + increment, steps_above +
    /// increment] (see [`Term::jumped`]), so below 2^29 in size; a value
    /// plus up to a decrement, and each bound the loop compares with, below
    /// 2^30: no 32-bit sum or comparison of the loop can overflow. `start`,
    /// the value the fill starts from, is checked to be in the window in
    /// debug builds.
    fn fits_i32(&self, start: i64) -> bool {
        debug_assert!(
            start > self.steps_above - self.decrement + self.increment
                && start <= self.steps_above + self.increment,
            "a value {start} outside its window: {self:?}"
        );
        [self.steps_above, self.increment, self.decrement]
            .iter()
            .all(|v| v.unsigned_abs() < NARROW_BOUND as u64)
    }

    /// One step: the step bits it adds (this axis's or none), and `value`
    /// moved on to the next step. The value is passed apart from the term's
    /// constants so that several chains of values can share one set of
    /// constants (in registers).
    #[inline(always)]
    fn advance(&self, value: &mut i64) -> u16 {
        self.step.0 & self.advance_mask(value) as u16
    }

    /// One step, as [`Term::advance`] takes it, returning the mask itself
    /// (for a caller whose term decides more than step bits: Saleem's helix,
    /// where the minor "axis" may be the arc).
    ///
    /// The mask is all ones when the value exceeds `steps_above` (their
    /// difference is negative), else 0: built by a subtraction and a shift,
    /// it keeps the step bits and the decrement when the axis steps. The
    /// callers keep |value| and |steps_above| below 2^62, so the difference
    /// cannot overflow.
    #[inline(always)]
    pub fn advance_mask(&self, value: &mut i64) -> i64 {
        let mask = (self.steps_above - *value) >> 63;
        *value += self.increment - (self.decrement & mask);
        mask
    }

    /// ORs `bits` into the steps of `out` at which this term steps its
    /// axis, `value` being the one the first of them compares (moved on
    /// past them all): the steps [`Term::advance_mask`] marks, found by
    /// jumping from one to the next rather than testing every step, for
    /// an axis that steps seldom (a helix's linear axis beside a wide arc;
    /// one that steps more than every other step is tested step by step).
    ///
    /// From value v the axis next steps j steps on, the least j with
    /// v + j·increment > steps_above: a division, once. Then the value is
    /// v + (j + 1)·increment - decrement, which lies above
    /// steps_above + increment - decrement and at most at
    /// steps_above + 2·increment - decrement (it stepped at most an
    /// increment above steps_above), so the next j is Q - 1 or Q, with
    /// Q = decrement / increment: a comparison or two per step of the axis.
    pub fn or_steps_into(&self, value: &mut i64, out: &mut [Step], bits: u16) {
        let (increment, decrement) = (self.increment, self.decrement);
        if increment == 0 {
            // The value stays in its window (steps_above - decrement,
            // steps_above] and never passes steps_above: the axis never
            // steps (a helix that does not rise). Tested step by step, it
            // made such a helix four times as slow as the circle it is.
            debug_assert!(
                *value <= self.steps_above,
                "a value {value} outside its window: {self:?}"
            );
            return;
        }
        if 2 * increment > decrement {
            for slot in out.iter_mut() {
                slot.0 |= bits & self.advance_mask(value) as u16;
            }
            return;
        }
        // Written through a pointer, not `out[index]`: the bounds check
        // on each of the r = 300,000 helix's 100,000 linear steps was 3 to
        // 4% of its trace in Node (0.947 -> 0.915 ms, medians of 38
        // alternating the two builds).
        let (base, len) = (out.as_mut_ptr(), out.len());
        self.each_step_seldom(value, len, |index| {
            debug_assert!(index < len, "a mark within the steps");
            // SAFETY: each_step_seldom marks only indices below the count
            // of steps it is given, `out`'s length (each of its loops
            // stops before a place past them), and `out` is borrowed
            // mutably for the call.
            unsafe { (*base.add(index)).0 |= bits }
        });
    }

    /// Whether this term's axis steps at most every other step, and at all:
    /// what [`Term::each_step_seldom`] asks.
    pub fn steps_seldom(&self) -> bool {
        self.increment > 0 && 2 * self.increment <= self.decrement
    }

    /// Calls `mark` with the index of each of the next `steps` steps at
    /// which this term steps its axis (each below `steps`: the caller may
    /// rely on it to write unchecked), in order, `value` being the one the
    /// first of them compares (moved on past them all), for a term that
    /// [`Term::steps_seldom`]: found by jumping as [`Term::or_steps_into`]
    /// says.
    #[inline(always)]
    pub fn each_step_seldom(&self, value: &mut i64, steps: usize, mut mark: impl FnMut(usize)) {
        debug_assert!(
            self.steps_seldom(),
            "jumps need an axis that steps seldom: {self:?}"
        );
        let (increment, decrement, above) = (self.increment, self.decrement, self.steps_above);
        let steps = steps as i64;
        let mut v = *value;
        let first = if v > above {
            0
        } else {
            (above - v) / increment + 1
        };
        if first >= steps {
            *value = v + steps * increment;
            return;
        }
        mark(first as usize);
        v += (first + 1) * increment - decrement;
        // The state after a step of the axis: `at`, the index past it, and
        // v. After every step v lies in the window (low, low + increment],
        // low = steps_above + increment - decrement (it stepped at most an
        // increment above steps_above). A step of the axis on, it is
        // v + J·increment - decrement, J the steps taken: the one J that
        // puts it back in the window, Q = decrement / increment or Q + 1,
        // the latter exactly when v <= low - Q·increment + decrement. So
        // `at` moves by one of two counts and v by one of two constants: a
        // compare and two selects a jump, with no multiplication on the
        // value's chain (in wasm the helix's linear axis took 3 ns a step
        // when it had one). Past the first few steps, four such chains,
        // each jumping four steps of the axis ([`Jump::over`]), one step
        // apart: the r = 300,000 helix's 100,000 linear steps took about
        // 0.19 ms of its trace in Node with one chain, 0.14 ms so (its
        // trace 0.900/0.856 -> 0.843/0.817 ms, medians of 94 alternating
        // with the build before). Two chains had made nothing measurable
        // in wasm (natively 0.115 -> 0.10 ms).
        let mut at = first + 1;
        let one = Jump::new(increment, decrement, above);
        if let Some(four) = Jump::over(4, increment, decrement, above) {
            // Four chains, each jumping four steps of the axis, one step of
            // the axis apart (the three steps after this one start them):
            // their jumps do not wait on one another.
            let mut chains = [(at, v); 4];
            let mut seeded = true;
            for chain in chains.iter_mut().skip(1) {
                let (next, after) = one.from(at, v);
                if next > steps {
                    seeded = false;
                    break;
                }
                mark((next - 1) as usize);
                (at, v) = (next, after);
                *chain = (at, v);
            }
            if let (true, Some(lanes)) = (seeded, four.in_lanes(steps)) {
                // The four chains in the lanes of one vector each for the
                // steps' places and the values.
                let mut ats = Quad::new(chains.map(|(at, _)| at));
                let mut values = Quad::new(chains.map(|(_, v)| v));
                loop {
                    let (next_ats, next_values) = lanes.from(ats, values);
                    let places = next_ats.lanes();
                    if places[3] > steps {
                        break;
                    }
                    for at in places {
                        mark((at - 1) as usize);
                    }
                    (ats, values) = (next_ats, next_values);
                }
                (at, v) = (ats.lanes()[3], values.lanes()[3]);
            } else if seeded {
                loop {
                    let next = chains.map(|(at, v)| four.from(at, v));
                    if next[3].0 > steps {
                        break;
                    }
                    for (at, _) in next {
                        mark((at - 1) as usize);
                    }
                    chains = next;
                }
                (at, v) = chains[3];
            }
        }
        loop {
            let (next, after) = one.from(at, v);
            debug_assert!(
                v + (next - at - 1) * increment > above && v + (next - at - 2) * increment <= above
            );
            if next > steps {
                break;
            }
            mark((next - 1) as usize);
            (at, v) = (next, after);
        }
        *value = v + (steps - at) * increment;
    }

    /// How many of `steps` steps, taken from this term, stepped its axis,
    /// given the value they left: value_after = value + steps·increment -
    /// moves·decrement, so the value says it without a pass over the steps.
    pub fn moves(&self, steps: u64, value_after: i64) -> i64 {
        if steps == 0 || self.increment == 0 {
            // No step (and a zero-length line's decrement is 0), or a term
            // whose axis never steps ([`Terms::fill_interleaved_moving`]):
            // a planar line's idle axis, one division a fill saved.
            return 0;
        }
        // In i64 where it fits (a chord's or a short line's terms: an i128
        // division is a library call in wasm, and a trace makes one per
        // chunk), else in i128: steps·increment reaches 2^63 on the longest
        // lines.
        if let Some(gone) = steps_times(steps, self.increment)
            .and_then(|total| total.checked_add(self.value))
            .and_then(|total| total.checked_sub(value_after))
        {
            return gone / self.decrement;
        }
        ((self.value as i128 + steps as i128 * self.increment as i128 - value_after as i128)
            / self.decrement as i128) as i64
    }

    /// How many of the values the next `steps` steps compare, this one
    /// first, equal `target`, without taking the steps: the ties among
    /// them where `target` is the rule's threshold (Saleem's helix, the
    /// Bresenham lines).
    pub fn values_equal(&self, target: i64, steps: u64) -> u64 {
        Equal::of(self, target).count_below(steps)
    }

    /// How many of the next `steps` steps of terms run side by side (the
    /// passive axes of a line in 3 or more axes) compare a value equal to
    /// `target` in at least one of them, without taking the steps: by
    /// inclusion and exclusion, the steps where each subset of the terms
    /// all do ([`Equal::both`]) added for a subset of odd size and taken
    /// off for one of even size (31 subsets for the most terms, five).
    pub fn values_equal_in_any(terms: &[Term], target: i64, steps: u64) -> u64 {
        assert!(terms.len() < MAX_AXES, "at most one term a passive axis");
        let mut equal = [Equal::None; MAX_AXES];
        for (e, term) in equal.iter_mut().zip(terms) {
            *e = Equal::of(term, target);
        }
        let mut in_any = 0i128;
        for subset in 1..1u32 << terms.len() {
            let all = (0..terms.len())
                .filter(|&i| subset >> i & 1 == 1)
                .map(|i| equal[i])
                .reduce(Equal::both)
                .expect("a subset of at least one term");
            let count = all.count_below(steps) as i128;
            in_any += if subset.count_ones() % 2 == 1 {
                count
            } else {
                -count
            };
        }
        in_any as u64
    }

    /// This term `steps` steps later, without taking them.
    ///
    /// Every rule here keeps its value in the window (steps_above -
    /// decrement + increment, steps_above + increment]: it starts there,
    /// and a step adds the increment and, when the value was above
    /// steps_above, takes the decrement off (increment <= decrement: a
    /// passive axis moves no farther than the active one). After `steps`
    /// steps, of which n stepped the axis, the value is value + steps·
    /// increment - n·decrement, and only one n puts that in the window.
    fn jumped(&self, steps: u64) -> Term {
        if steps == 0 {
            return *self;
        }
        // In i64 where it fits, as in `moves`, else in i128: steps·increment
        // reaches 2^63 on the longest lines.
        let total =
            steps_times(steps, self.increment).and_then(|gained| gained.checked_add(self.value));
        let excess = total.and_then(|t| {
            t.checked_sub(self.steps_above)
                .and_then(|e| e.checked_sub(self.increment))
        });
        if let (Some(total), Some(less)) = (total, excess.and_then(i64::checked_neg)) {
            // n = ceil(excess / decrement), decrement > 0 on any line with
            // steps; n·decrement is at most the excess plus a decrement.
            let n = -less.div_euclid(self.decrement);
            if let Some(value) = n
                .checked_mul(self.decrement)
                .and_then(|d| total.checked_sub(d))
            {
                return Term { value, ..*self };
            }
        }
        let (inc, dec) = (self.increment as i128, self.decrement as i128);
        let excess = self.value as i128 + steps as i128 * inc - self.steps_above as i128 - inc;
        let n = -(-excess).div_euclid(dec);
        Term {
            value: (self.value as i128 + steps as i128 * inc - n * dec) as i64,
            ..*self
        }
    }
}

/// The steps, counted from a term's present state (step 0 the next), at
/// which it compares a value equal to a target: every `period`-th step
/// from `first`, or none.
/// A period no path reaches the second step of: every path is shorter than
/// 2^32 steps (maxSteps is at most 10^9). Two periods below it multiply
/// within i128, as [`Equal::both`] and [`least_solution`] multiply them.
const ONCE: i128 = 1 << 63;

#[derive(Clone, Copy, Debug, PartialEq)]
enum Equal {
    None,
    Every { first: i128, period: i128 },
}

impl Equal {
    /// Where `term` compares `target`. Step j compares value + j·increment
    /// less n·decrement (n the steps of the axis before it), and every
    /// value lies in the window (steps_above - decrement + increment,
    /// steps_above + increment] ([`Term::jumped`]), which holds one number
    /// of each class modulo the decrement. So a target in the window is
    /// compared exactly at the j with j·increment ≡ target - value (mod
    /// decrement): every period-th j from the least one.
    fn of(term: &Term, target: i64) -> Equal {
        if term.decrement == 0 {
            // No step of the axis, nor an increment (at most the
            // decrement): the value stays.
            return if term.value == target {
                Equal::Every {
                    first: 0,
                    period: 1,
                }
            } else {
                Equal::None
            };
        }
        let (increment, decrement) = (term.increment as i128, term.decrement as i128);
        let target = target as i128;
        let above = term.steps_above as i128;
        if target <= above - decrement + increment || target > above + increment {
            return Equal::None;
        }
        match least_solution(increment, target - term.value as i128, decrement) {
            Some((first, period)) => Equal::Every { first, period },
            None => Equal::None,
        }
    }

    /// The steps in both: j = first_a + t·period_a also ≡ first_b (mod
    /// period_b), so t·period_a ≡ first_b - first_a (mod period_b), whose
    /// least solution t0 (< period_b / g, g = gcd of the periods) gives
    /// the least such j, first_a + t0·period_a, and they recur every
    /// lcm = period_a·period_b / g steps (the Chinese remainder theorem).
    /// Each first is below its period, so a j >= 0 of both classes is past
    /// both firsts: every one of them is a step of both. A period of
    /// [`ONCE`] or more holds its first step alone within any path, and
    /// stands for every longer one, so that the products stay in i128 over
    /// the five terms of a 6-axis line.
    fn both(self, other: Equal) -> Equal {
        let (
            Equal::Every {
                first: first_a,
                period: period_a,
            },
            Equal::Every {
                first: first_b,
                period: period_b,
            },
        ) = (self, other)
        else {
            return Equal::None;
        };
        if period_a >= ONCE {
            return if other.holds(first_a) {
                self
            } else {
                Equal::None
            };
        }
        if period_b >= ONCE {
            return if self.holds(first_b) {
                other
            } else {
                Equal::None
            };
        }
        match least_solution(period_a, first_b - first_a, period_b) {
            Some((t, t_period)) => Equal::Every {
                first: first_a + t * period_a,
                period: (t_period * period_a).min(ONCE),
            },
            None => Equal::None,
        }
    }

    /// Whether step `j` is one of these.
    fn holds(self, j: i128) -> bool {
        match self {
            Equal::Every { first, period } => j >= first && (j - first) % period == 0,
            Equal::None => false,
        }
    }

    /// How many of these steps come before step `steps`.
    fn count_below(self, steps: u64) -> u64 {
        let steps = steps as i128;
        match self {
            Equal::Every { first, period } if first < steps => {
                ((steps - 1 - first) / period + 1) as u64
            }
            _ => 0,
        }
    }
}

/// The least j >= 0 with a·j ≡ c (mod d), d > 0, and the period of the
/// solutions, d / gcd(a, d); None where there is none. By Euclid's
/// algorithm extended: each remainder r is s·a modulo d, so the last one
/// that is not 0, gcd(a, d), is s·a with the s kept beside it, and
/// (c / gcd)·s solves the congruence where gcd divides c.
fn least_solution(a: i128, c: i128, d: i128) -> Option<(i128, i128)> {
    let (mut r, mut next_r) = (d, a.rem_euclid(d));
    let (mut s, mut next_s) = (0i128, 1i128);
    while next_r != 0 {
        let q = r / next_r;
        (r, next_r) = (next_r, r - q * next_r);
        (s, next_s) = (next_s, s - q * next_s);
    }
    if c.rem_euclid(r) != 0 {
        return None;
    }
    let period = d / r;
    let first = (c / r).rem_euclid(period) * s.rem_euclid(period) % period;
    Some((first, period))
}

/// `N` passive terms and the axes that step every time. `N` is a constant
/// so that the loop over the terms unrolls; callers with a varying number of
/// passive axes pick `N` with a match.
#[derive(Clone, Copy, Debug)]
pub struct Terms<const N: usize> {
    /// Step bits of the active axes, which move every step.
    pub always: Step,
    pub terms: [Term; N],
}

/// How many stretches [`Terms::fill`] steps at once when a term's values
/// need 64 bits. Two: the chains share the terms' constants, but with four
/// their values and the constants no longer fit the registers a wasm engine
/// gives the loop (measured: 660 million steps per second with four, 810
/// with two, 570 with four chains each holding its own constants); natively
/// two are as fast as four. With the wasm vector path, four chains (two
/// vectors per term) took the bench's 3D line's trace from 3.0 to 3.7 ms.
const LANES: usize = 2;

/// How many consecutive steps [`Terms::fill_interleaved`] takes at once
/// when every term fits 32 bits ([`Term::fits_i32`]): eight chains, two
/// 128-bit vectors of four i32 lanes per term, step k in lane k mod 8.
const NARROW_LANES: usize = 8;

/// From this many steps on, [`Terms::fill`] takes them eight at a time
/// ([`Terms::fill_interleaved`]), when the terms fit 32 bits: it needs no
/// jump, so only the splat of its constants is paid per call.
const MIN_INTERLEAVED_STEPS: usize = 32;

/// Up to this many passive terms take the 32-bit chains: with more, their
/// constants and values no longer fit the vector registers (nd's lines of
/// 5 and 6 axes keep the 64-bit chains).
const MAX_NARROW_TERMS: usize = 3;

/// A term whose constants and values are all smaller than this in size
/// runs in 32 bits ([`Term::fits_i32`]).
const NARROW_BOUND: i64 = 1 << 28;

/// Below this many steps per lane, one stretch: the jumps (an i64 division
/// each) would cost more than they save. Measured on the G-code bench at
/// 80 steps/mm, whose moves take tens to a few hundred steps, in wasm: 32
/// took 1.04x to 1.05x the time of 128, and 512 1.03x to 1.08x.
const MIN_LANE_STEPS: usize = 128;

/// Up to this many steps, [`Terms::fill`] sums the displacement from the
/// steps it wrote ([`displacement`]: a few operations a step) rather than
/// from its terms (a division per term and a sum per axis and term): the
/// moves of a G-code program at 1 step/mm take a handful of steps each.
const MAX_STEPS_SUMMED: usize = 16;

impl<const N: usize> Terms<N> {
    /// One step of every term, each value of `values` with the constants of
    /// the term at its index.
    #[inline(always)]
    fn advance(always: u16, terms: &[Term; N], values: &mut [i64; N]) -> Step {
        let mut bits = always;
        for (term, value) in terms.iter().zip(values) {
            bits |= term.advance(value);
        }
        Step(bits)
    }

    /// The [`LANES`] chains side by side: chain j records the j-th of
    /// [`LANES`] equal stretches of `body` from the values `lanes[j]`, a
    /// step of each in turn.
    ///
    /// Each term's values are one [`Pair`] (lane j chain j's), a 128-bit
    /// vector where the target has one: a step of both chains is, per
    /// term, one mask ([`Term::advance_mask`]'s, all ones where the value
    /// exceeds steps_above), an add, two ands, a subtraction and an or,
    /// where scalar code takes each of them twice; the codes are then the
    /// low 16 bits of each lane. In wasm this made the bench's 3D line's
    /// trace 2.7 times faster.
    #[inline(always)]
    fn fill_chains(
        always: u16,
        terms: &[Term; N],
        lanes: &mut [[i64; N]; LANES],
        body: &mut [MaybeUninit<Step>],
    ) {
        let splat = |f: fn(&Term) -> i64| -> [Pair; N] {
            std::array::from_fn(|i| Pair::splat(f(&terms[i])))
        };
        let above = splat(|t| t.steps_above);
        let increment = splat(|t| t.increment);
        let decrement = splat(|t| t.decrement);
        let bits = splat(|t| t.step.0 as i64);
        let always = Pair::splat(always as i64);
        let mut values: [Pair; N] = std::array::from_fn(|i| Pair::new([lanes[0][i], lanes[1][i]]));
        let (first, second) = body.split_at_mut(body.len() / LANES);
        assert_eq!(first.len(), second.len(), "two stretches of equal length");
        for (s0, s1) in first.iter_mut().zip(second) {
            let mut code = always;
            for i in 0..N {
                let mask = values[i].above(above[i]);
                code = code.or(mask.and(bits[i]));
                values[i] = values[i].add(increment[i]).sub(mask.and(decrement[i]));
            }
            let [c0, c1] = code.low_u16s();
            s0.write(Step(c0));
            s1.write(Step(c1));
        }
        for (i, value) in values.iter().enumerate() {
            [lanes[0][i], lanes[1][i]] = value.lanes();
        }
    }

    /// Records `out` (a multiple of [`NARROW_LANES`] steps) eight steps at
    /// a time, the terms' values starting at `values` and moved on past
    /// them, every term fitting 32 bits ([`Term::fits_i32`]).
    ///
    /// Lane k of a term's two vectors holds its value at step i + k, so one
    /// pass decides eight consecutive steps, and their codes leave in one
    /// 16-byte store (the low halves of the lanes, packed: a code is below
    /// 2^14). Chains each recording their own stretch, as
    /// [`Self::fill_chains`] runs them, store each code apart, and those
    /// stores were the loop's limit; two vectors rather than one give the
    /// processor two chains of dependent instructions to run side by side
    /// (the 3D line's run 0.88 -> 0.66 ms natively, its trace in Node
    /// 1.34 -> 1.05 ms).
    ///
    /// A lane then moves eight steps on at once. A value lives in the window
    /// (steps_above - decrement + increment, steps_above + increment], one
    /// decrement wide, and a step adds the increment and takes the
    /// decrement off when it leaves the window ([`Term::jumped`]), so eight
    /// steps on, the value is the one in the window that is congruent to
    /// value + 8·increment modulo the decrement: value + r, less the
    /// decrement when that passes the window's top, with r = 8·increment
    /// mod decrement. The mask of that comparison is found from the value
    /// itself (value > top - r), beside the step's own, so the chain from
    /// one pass to the next is a comparison, an and and a subtraction, as
    /// in [`Term::advance_mask`].
    #[inline(always)]
    fn fill_interleaved(
        always: u16,
        terms: &[Term; N],
        values: &mut [i64; N],
        out: &mut [MaybeUninit<Step>],
    ) {
        const L: usize = NARROW_LANES;
        assert_eq!(out.len() % L, 0, "whole groups of {L} steps");
        let splat = |f: &dyn Fn(&Term) -> i64| -> [Quad; N] {
            std::array::from_fn(|i| Quad::splat(f(&terms[i])))
        };
        // r = 8·increment mod decrement (0 for a line of no steps, whose
        // decrement is 0).
        let skip = |t: &Term| {
            (L as i64 * t.increment)
                .checked_rem(t.decrement)
                .unwrap_or(0)
        };
        let above = splat(&|t| t.steps_above);
        let bits = splat(&|t| t.step.0 as i64);
        let skips = splat(&skip);
        let wraps_above = splat(&|t| t.steps_above + t.increment - skip(t));
        let decrement = splat(&|t| t.decrement);
        let always = Quad::splat(always as i64);
        // Each term's values at the first eight steps, four per vector.
        let mut lanes: [[Quad; 2]; N] = std::array::from_fn(|i| {
            let mut value = values[i];
            let mut next = || {
                let at = value;
                terms[i].advance_mask(&mut value);
                at
            };
            let lo = Quad::new(std::array::from_fn(|_| next()));
            let hi = Quad::new(std::array::from_fn(|_| next()));
            [lo, hi]
        });
        for group in out.chunks_exact_mut(L) {
            let mut codes = [always; 2];
            for i in 0..N {
                for (value, code) in lanes[i].iter_mut().zip(&mut codes) {
                    let steps = value.above(above[i]);
                    *code = code.or(steps.and(bits[i]));
                    let wraps = value.above(wraps_above[i]);
                    *value = value.add(skips[i]).sub(wraps.and(decrement[i]));
                }
            }
            Quad::store_codes(codes, group);
        }
        // Lane 0 now holds the value at step out.len().
        for (value, lane) in values.iter_mut().zip(&lanes) {
            *value = lane[0].lanes()[0];
        }
    }

    /// [`Self::fill_interleaved`], with a term whose axis never steps left
    /// out of the loop when there are two: a line in a plane of the grid
    /// (a circle's chords, most G-code moves) has a passive axis that does
    /// not move, and its term would take half the loop's work for nothing.
    /// A term of no increment never steps: its value lies in the window
    /// (steps_above - decrement, steps_above] ([`Term::jumped`]), so it never
    /// exceeds steps_above, and stays where it is.
    #[inline(always)]
    fn fill_interleaved_moving(
        always: u16,
        terms: &[Term; N],
        values: &mut [i64; N],
        out: &mut [MaybeUninit<Step>],
    ) {
        if N == 2 {
            if let Some(moving) = [1, 0].into_iter().find(|&i| terms[1 - i].increment == 0) {
                let mut value = [values[moving]];
                Terms::<1>::fill_interleaved(always, &[terms[moving]], &mut value, out);
                values[moving] = value[0];
                return;
            }
        }
        Self::fill_interleaved(always, terms, values, out);
    }

    /// One step, for a stepper that builds its decision around it.
    #[inline(always)]
    pub fn step(&mut self) -> Step {
        let mut values = self.terms.map(|t| t.value);
        let step = Self::advance(self.always.0, &self.terms, &mut values);
        self.set_values(values);
        step
    }

    fn set_values(&mut self, values: [i64; N]) {
        for (term, value) in self.terms.iter_mut().zip(values) {
            term.value = value;
        }
    }

    /// Records `out.len()` steps, every slot of `out` written, and returns
    /// where they moved per axis.
    ///
    /// Each step's value depends on the one before, so stepping is a chain
    /// of dependent instructions and the processor waits on it. Split into
    /// chains that run side by side: when the terms fit 32 bits
    /// ([`Term::fits_i32`]: any line of fewer than 2^27 steps), eight
    /// consecutive steps at a time ([`Self::fill_interleaved`]); else
    /// [`LANES`] stretches in 64-bit lanes, each started where
    /// [`Term::jumped`] says the rule will be ([`Self::fill_chains`]). What
    /// is left over steps on from where they ended.
    ///
    /// The displacement needs no pass over the steps: the active axes moved
    /// every step, and a term's value says how often its axis did (value_end
    /// = value_start + steps·increment - moves·decrement); a few steps are
    /// summed instead ([`MAX_STEPS_SUMMED`]).
    #[inline(always)]
    pub fn fill(&mut self, out: &mut [MaybeUninit<Step>]) -> [i64; MAX_AXES] {
        // Read in place, not copied: in wasm a copy of the terms (80 bytes
        // for two) was a memory.copy, which V8 runs as a call into the
        // engine, once per fill (a G-code move or an arc's chord).
        let terms = &self.terms;
        let always = self.always.0;
        let mut values: [i64; N] = std::array::from_fn(|i| terms[i].value);
        let mut filled = 0;
        if N <= MAX_NARROW_TERMS
            && out.len() >= MIN_INTERLEAVED_STEPS
            && (0..N).all(|i| terms[i].fits_i32(values[i]))
        {
            filled = out.len() / NARROW_LANES * NARROW_LANES;
            Self::fill_interleaved_moving(always, terms, &mut values, &mut out[..filled]);
        }
        if filled == 0 && out.len() >= LANES * MIN_LANE_STEPS {
            let lane_steps = out.len() / LANES;
            filled = lane_steps * LANES;
            let mut lanes: [[i64; N]; LANES] = std::array::from_fn(|lane| {
                std::array::from_fn(|i| terms[i].jumped((lane * lane_steps) as u64).value)
            });
            Self::fill_chains(always, terms, &mut lanes, &mut out[..filled]);
            values = lanes[LANES - 1];
        }
        let tail = &mut out[filled..];
        for slot in tail {
            slot.write(Self::advance(always, terms, &mut values));
        }
        let steps = out.len();
        let moved = if steps <= MAX_STEPS_SUMMED {
            // SAFETY: the loops above wrote every slot.
            displacement(unsafe { written_steps(out) })
        } else {
            // From the values before the fill (the terms') and after it.
            let mut moved = [0; MAX_AXES];
            self.always.add_times(steps as i64, &mut moved);
            for (term, value) in terms.iter().zip(values) {
                term.step
                    .add_times(term.moves(steps as u64, value), &mut moved);
            }
            moved
        };
        self.set_values(values);
        moved
    }
}

/// One term's values of the two chains of [`Terms::fill_chains`], in one
/// 128-bit vector where the target has one: wasm with SIMD, where the
/// engine turns the 64-bit compare into one instruction on x86-64 (SSE4.2)
/// and Arm64 alike, and x86-64, whose every processor has SSE2 (the mask is
/// then a subtraction, as [`Term::advance_mask`] builds it, and a shuffle
/// and a shift to spread each lane's sign). Elsewhere, two scalars.
///
/// Every value and steps_above the callers keep is below 2^62 in size, so
/// a difference of two cannot overflow.
#[derive(Clone, Copy)]
struct Pair(
    #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))] core::arch::wasm32::v128,
    #[cfg(target_arch = "x86_64")] core::arch::x86_64::__m128i,
    #[cfg(not(any(
        all(target_arch = "wasm32", target_feature = "simd128"),
        target_arch = "x86_64"
    )))]
    [i64; 2],
);

#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
impl Pair {
    #[inline(always)]
    fn new([a, b]: [i64; 2]) -> Pair {
        Pair(core::arch::wasm32::i64x2(a, b))
    }
    #[inline(always)]
    fn splat(x: i64) -> Pair {
        Pair(core::arch::wasm32::i64x2_splat(x))
    }
    /// All ones in each lane whose value is above `limit`'s, else 0.
    #[inline(always)]
    fn above(self, limit: Pair) -> Pair {
        Pair(core::arch::wasm32::i64x2_gt(self.0, limit.0))
    }
    #[inline(always)]
    fn add(self, other: Pair) -> Pair {
        Pair(core::arch::wasm32::i64x2_add(self.0, other.0))
    }
    #[inline(always)]
    fn sub(self, other: Pair) -> Pair {
        Pair(core::arch::wasm32::i64x2_sub(self.0, other.0))
    }
    #[inline(always)]
    fn and(self, other: Pair) -> Pair {
        Pair(core::arch::wasm32::v128_and(self.0, other.0))
    }
    #[inline(always)]
    fn or(self, other: Pair) -> Pair {
        Pair(core::arch::wasm32::v128_or(self.0, other.0))
    }
    #[inline(always)]
    fn low_u16s(self) -> [u16; 2] {
        use core::arch::wasm32::u16x8_extract_lane;
        [
            u16x8_extract_lane::<0>(self.0),
            u16x8_extract_lane::<4>(self.0),
        ]
    }
    #[inline(always)]
    fn lanes(self) -> [i64; 2] {
        use core::arch::wasm32::i64x2_extract_lane;
        [
            i64x2_extract_lane::<0>(self.0),
            i64x2_extract_lane::<1>(self.0),
        ]
    }
}

// SAFETY (every intrinsic below): SSE2 is part of x86-64 itself, so these
// instructions exist on every processor the target runs on.
#[cfg(target_arch = "x86_64")]
impl Pair {
    #[inline(always)]
    fn new([a, b]: [i64; 2]) -> Pair {
        Pair(unsafe { core::arch::x86_64::_mm_set_epi64x(b, a) })
    }
    #[inline(always)]
    fn splat(x: i64) -> Pair {
        Pair(unsafe { core::arch::x86_64::_mm_set1_epi64x(x) })
    }
    /// All ones in each lane whose value is above `limit`'s, else 0: the
    /// sign of limit - value (SSE2 has no 64-bit compare), its high half
    /// copied to both halves of the lane and shifted arithmetically.
    #[inline(always)]
    fn above(self, limit: Pair) -> Pair {
        use core::arch::x86_64::{_mm_shuffle_epi32, _mm_srai_epi32, _mm_sub_epi64};
        Pair(unsafe {
            _mm_srai_epi32::<31>(_mm_shuffle_epi32::<0b11_11_01_01>(_mm_sub_epi64(
                limit.0, self.0,
            )))
        })
    }
    #[inline(always)]
    fn add(self, other: Pair) -> Pair {
        Pair(unsafe { core::arch::x86_64::_mm_add_epi64(self.0, other.0) })
    }
    #[inline(always)]
    fn sub(self, other: Pair) -> Pair {
        Pair(unsafe { core::arch::x86_64::_mm_sub_epi64(self.0, other.0) })
    }
    #[inline(always)]
    fn and(self, other: Pair) -> Pair {
        Pair(unsafe { core::arch::x86_64::_mm_and_si128(self.0, other.0) })
    }
    #[inline(always)]
    fn or(self, other: Pair) -> Pair {
        Pair(unsafe { core::arch::x86_64::_mm_or_si128(self.0, other.0) })
    }
    #[inline(always)]
    fn low_u16s(self) -> [u16; 2] {
        use core::arch::x86_64::_mm_extract_epi16;
        unsafe {
            [
                _mm_extract_epi16::<0>(self.0) as u16,
                _mm_extract_epi16::<4>(self.0) as u16,
            ]
        }
    }
    #[inline(always)]
    fn lanes(self) -> [i64; 2] {
        // SAFETY: __m128i and [i64; 2] are both 16 plain bytes.
        unsafe { std::mem::transmute::<core::arch::x86_64::__m128i, [i64; 2]>(self.0) }
    }
}

#[cfg(not(any(
    all(target_arch = "wasm32", target_feature = "simd128"),
    target_arch = "x86_64"
)))]
impl Pair {
    fn new(values: [i64; 2]) -> Pair {
        Pair(values)
    }
    fn splat(x: i64) -> Pair {
        Pair([x; 2])
    }
    /// All ones in each lane whose value is above `limit`'s, else 0
    /// ([`Term::advance_mask`]'s subtraction and shift).
    fn above(self, limit: Pair) -> Pair {
        Pair([0, 1].map(|i| (limit.0[i] - self.0[i]) >> 63))
    }
    fn add(self, other: Pair) -> Pair {
        Pair([0, 1].map(|i| self.0[i] + other.0[i]))
    }
    fn sub(self, other: Pair) -> Pair {
        Pair([0, 1].map(|i| self.0[i] - other.0[i]))
    }
    fn and(self, other: Pair) -> Pair {
        Pair([0, 1].map(|i| self.0[i] & other.0[i]))
    }
    fn or(self, other: Pair) -> Pair {
        Pair([0, 1].map(|i| self.0[i] | other.0[i]))
    }
    fn low_u16s(self) -> [u16; 2] {
        self.0.map(|x| x as u16)
    }
    fn lanes(self) -> [i64; 2] {
        self.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::displacement;

    /// `len` steps of `terms` ([`Terms::fill`]) in a vector, and where
    /// they moved.
    fn filled<const N: usize>(terms: &mut Terms<N>, len: usize) -> (Vec<Step>, [i64; MAX_AXES]) {
        let mut out = Vec::with_capacity(len);
        let moved = terms.fill(&mut out.spare_capacity_mut()[..len]);
        // SAFETY: Terms::fill writes every slot it is given.
        unsafe { out.set_len(len) };
        (out, moved)
    }

    /// A term of decrement `period`·`factor` (up to 2^33, a line's of
    /// 2^32 units or more) and increment `factor`·`units`, whose window holds
    /// `target`, comparing `target` at step `at` when `meets`, else at a
    /// value of its window picked by `seed`.
    fn term_around(
        target: i64,
        period: i64,
        factor: i64,
        units: i64,
        at: usize,
        meets: bool,
        seed: i64,
    ) -> Term {
        let (decrement, increment) = (period * factor, units * factor);
        let steps_above = target - increment + seed.rem_euclid(decrement);
        let mut term = Term {
            value: 0,
            increment,
            decrement,
            steps_above,
            step: Step::NONE,
        };
        term.value = steps_above + increment - seed.rotate_left(17).rem_euclid(decrement);
        if meets {
            // Back from `target` at step `at`: of the two values a step can
            // come from, v - increment and v - increment + decrement, the
            // one in the window.
            let mut v = target;
            for _ in 0..at {
                v -= increment;
                if v <= steps_above - decrement + increment {
                    v += decrement;
                }
            }
            term.value = v;
        }
        term
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(2000))]
        /// `values_equal_in_any` counts the steps where any of 1 to 5 terms
        /// compares the target, as their steps, taken one by one, compare
        /// it: terms of periods from 1 to past 2^31 (whose products pass
        /// 2^63, where the count caps them) and decrements up to 2^33, most
        /// of them meeting the target at one shared step, so that the
        /// Chinese remainder theorem's intersections are seldom empty. The
        /// lines' own tests meet only the periods of short directions.
        #[test]
        fn values_equal_in_any_counts_what_the_steps_compare(
            specs in proptest::collection::vec(
                (0u8..4, 1i64..=1 << 22, proptest::num::i64::ANY, proptest::num::i64::ANY, 0u8..4),
                1..=5,
            ),
            target in -(1i64 << 30)..=(1 << 30),
            at in 0usize..50,
            stretch in 0usize..4000,
        ) {
            let terms: Vec<Term> = specs.iter().map(|&(kind, raw, seed, factor_seed, meets)| {
                let period = match kind {
                    0 => 1 + raw % 60,
                    1 => 60 + raw % 1940,
                    2 => (1 << 20) + raw,
                    // Two of these alone pass 2^63 together.
                    _ => (1 << 31) + raw * 1024,
                };
                let factor = 1 + factor_seed.rem_euclid((1i64 << 33) / period);
                let units = seed.rotate_left(29).rem_euclid(period + 1);
                term_around(target, period, factor, units, at, meets > 0, seed)
            }).collect();
            let steps = at + stretch;
            let mut values: Vec<i64> = terms.iter().map(|t| t.value).collect();
            let mut expected = 0u64;
            for _ in 0..steps {
                expected += u64::from(values.contains(&target));
                for (t, v) in terms.iter().zip(values.iter_mut()) {
                    t.advance_mask(v);
                }
            }
            proptest::prop_assert_eq!(Term::values_equal_in_any(&terms, target, steps as u64), expected, "{:?}", terms);
        }
    }

    /// The values a term compares equal a target where its steps, taken
    /// one by one, find it: every small term of either tie policy, from
    /// every value of its window, for every target in and around it.
    #[test]
    fn values_equal_counts_what_the_steps_compare() {
        for decrement in 0..=12i64 {
            for increment in 0..=decrement {
                for threshold in -3..=decrement + 3 {
                    for tie in [TiePolicy::Hold, TiePolicy::Advance] {
                        let steps_above = Term::steps_above(threshold, tie);
                        let window =
                            steps_above - decrement + increment + 1..=steps_above + increment;
                        for value in window.clone() {
                            let term = Term {
                                value,
                                increment,
                                decrement,
                                steps_above,
                                step: Step::NONE,
                            };
                            let mut compared = Vec::new();
                            let mut v = value;
                            for _ in 0..60 {
                                compared.push(v);
                                term.advance_mask(&mut v);
                            }
                            for target in window.start() - 2..=window.end() + 2 {
                                for steps in [0, 1, 2, 5, 13, 60] {
                                    let expected =
                                        compared[..steps].iter().filter(|&&v| v == target).count()
                                            as u64;
                                    assert_eq!(
                                        term.values_equal(target, steps as u64),
                                        expected,
                                        "{term:?}, target {target}, {steps} steps"
                                    );
                                }
                            }
                        }
                    }
                }
            }
        }
    }

    /// The product without checks where both factors are small, with them
    /// past that: the same as i128 says, on both sides of 2^31.
    #[test]
    fn steps_times_is_the_product_where_it_fits_i64() {
        let near = |n: i64| [n - 1, n, n + 1];
        let sizes = [0, 1, 7]
            .into_iter()
            .chain(near(1 << 31))
            .chain(near(1 << 32))
            .chain(near(1 << 62))
            .chain([i64::MAX]);
        let sizes: Vec<i64> = sizes.collect();
        for &steps in &sizes {
            for &size in &sizes {
                for by in [size, -size] {
                    let exact = steps as i128 * by as i128;
                    let want = i64::try_from(exact).ok();
                    assert_eq!(steps_times(steps as u64, by), want, "{steps} x {by}");
                }
            }
        }
    }

    #[test]
    fn a_term_steps_past_its_threshold_and_on_it_by_the_tie_policy() {
        // Saleem's 2D rule (section 2, eq. 4-5) for Δ = (10, 5) as a term:
        // the error after adding 2·Δy = 10 is compared with Δx = 10, and a
        // minor step takes 2·Δx = 20 off. Worked by hand: the tested errors
        // are 10 (a tie), then 20 (held) or 0 (advanced), then 10 again.
        let run = |tie| {
            let mut terms = Terms {
                always: Step(0b1),
                terms: [Term {
                    value: 10,
                    increment: 10,
                    decrement: 20,
                    steps_above: Term::steps_above(10, tie),
                    step: Step(0b100),
                }],
            };
            filled(&mut terms, 4)
                .0
                .iter()
                .map(|s| s.0)
                .collect::<Vec<_>>()
        };
        // Hold: 10 = 10 holds; 20 > 10 steps (-> 10); 10 holds; 20 steps.
        assert_eq!(run(TiePolicy::Hold), [0b1, 0b101, 0b1, 0b101]);
        // Advance: 10 = 10 steps (-> 0); 0 < 10 holds (-> 10); 10 steps;
        // 0 holds.
        assert_eq!(run(TiePolicy::Advance), [0b101, 0b1, 0b101, 0b1]);
    }

    /// Wang's discriminant for a passive axis of |Δ| = `passive` against an
    /// active |Δ| = `active` (eq. 10 start, eq. 8 steps), as a term.
    fn wang(passive: i64, active: i64, tie: TiePolicy) -> Term {
        Term {
            value: 2 * passive - active,
            increment: 2 * passive,
            decrement: 2 * active,
            steps_above: Term::steps_above(0, tie),
            step: Step(0b100),
        }
    }

    #[test]
    fn a_jump_lands_where_the_steps_do() {
        for (passive, active) in [(0, 5), (1, 7), (3, 6), (7, 10), (10, 10), (999, 1000)] {
            for tie in [TiePolicy::Hold, TiePolicy::Advance] {
                let mut stepped = wang(passive, active, tie);
                for steps in 0..=3 * active as u64 {
                    assert_eq!(
                        wang(passive, active, tie).jumped(steps),
                        stepped,
                        "{passive}/{active} after {steps}"
                    );
                    let mut value = stepped.value;
                    stepped.advance(&mut value);
                    stepped.value = value;
                }
            }
        }
    }

    proptest::proptest! {
        #[test]
        fn jumping_to_an_axis_s_steps_marks_the_steps_it_takes(
            // n_z = 0 (a helix that does not rise) in a case of four.
            minor in proptest::prop_oneof![proptest::strategy::Just(0i64), 0i64..2000, 0i64..2000, 0i64..2000],
            extra in 0i64..50_000,
            start in 0u64..100_000,
            len in 0usize..3000,
            advance in proptest::bool::ANY,
            // Past what the four chains' i32 lanes take (Jump::in_lanes),
            // in one case of four: the same term's i64 chains.
            scale in proptest::prop_oneof![proptest::strategy::Just(1i64 << 30), proptest::strategy::Just(1i64), proptest::strategy::Just(1i64), proptest::strategy::Just(1i64)],
        ) {
            // Saleem's helix term for n_z = minor against n_c = minor + extra
            // (sparse and dense minor axes, ties both ways), taken `start`
            // steps in, over `len` steps: the same marks and value as a
            // step-by-step pass.
            let (minor, extra) = (minor * scale, extra * scale);
            let major = minor + extra;
            let tie = if advance { TiePolicy::Advance } else { TiePolicy::Hold };
            let term = Term {
                value: 2 * minor,
                increment: 2 * minor,
                decrement: 2 * major,
                steps_above: Term::steps_above(major, tie),
                step: Step::NONE,
            }
            .jumped(start);
            let mut by_step = vec![Step(1); len];
            let mut value = term.value;
            for slot in by_step.iter_mut() {
                slot.0 |= 4 & term.advance_mask(&mut value) as u16;
            }
            let mut by_jumps = vec![Step(1); len];
            let mut jumped_value = term.value;
            term.or_steps_into(&mut jumped_value, &mut by_jumps, 4);
            proptest::prop_assert_eq!(by_jumps, by_step);
            proptest::prop_assert_eq!(jumped_value, value);
        }
    }

    #[test]
    fn a_jump_over_four_steps_of_the_axis_is_four_jumps() {
        // From values of the window after a step of the axis (see
        // Jump::over; every one for the narrow windows, some 50 and both
        // sides of the bound between short and long jumps for the wide
        // ones), sparse and dense axes, both ties: the same index and value
        // as four single jumps. Past i64 there is no such jump.
        for (minor, major) in [
            (1, 2),
            (1, 17),
            (3, 7),
            (5, 16),
            (7, 1000),
            (999, 1000),
            (100_000, 1_697_056),
        ] {
            for tie in [TiePolicy::Hold, TiePolicy::Advance] {
                let (increment, decrement) = (2 * minor, 2 * major);
                let above = Term::steps_above(major, tie);
                let (one, four) = (
                    Jump::new(increment, decrement, above),
                    Jump::over(4, increment, decrement, above).unwrap(),
                );
                let low = above + increment - decrement;
                let sampled = (low + 1..=low + increment).step_by((increment as usize / 50).max(1));
                let bound = [four.long_below, four.long_below + 1];
                for v in sampled.chain(
                    bound
                        .into_iter()
                        .filter(|v| (low + 1..=low + increment).contains(v)),
                ) {
                    let mut by_one = (10, v);
                    for _ in 0..4 {
                        by_one = one.from(by_one.0, by_one.1);
                    }
                    assert_eq!(four.from(10, v), by_one, "{minor}/{major} {tie:?} from {v}");
                }
            }
        }
        assert!(Jump::over(4, 3, 1 << 62, 0).is_none());
    }

    #[test]
    fn jumps_on_the_longest_lines_stay_exact() {
        // |Δ| = 2^31: a jump over the whole line equals two jumps over its
        // halves, and lands back on the start value (eq. 8 summed over a
        // line: 2|Δp|·|Δa| - |Δp|·2|Δa| = 0), with no overflow on the way.
        let active = 1i64 << 31;
        for passive in [1, active / 3, active - 1] {
            let term = wang(passive, active, TiePolicy::Advance);
            let whole = term.jumped(active as u64);
            assert_eq!(
                whole,
                term.jumped(active as u64 / 2 + 7)
                    .jumped(active as u64 / 2 - 7)
            );
            assert_eq!(whole.value, term.value);
        }
    }

    /// `start` filled `len` steps at once, against the same terms stepped
    /// one step at a time: the same steps, displacement and state after.
    fn fills_as_one_chain<const N: usize>(start: Terms<N>, len: usize) {
        let mut lanes = start;
        let (out, moved) = filled(&mut lanes, len);
        assert_eq!(moved, displacement(&out), "{len} steps");
        let mut chain = start;
        let expected: Vec<Step> = (0..len).map(|_| chain.step()).collect();
        assert_eq!(out, expected, "{len} steps");
        assert_eq!(lanes.terms, chain.terms, "the state after {len} steps");
    }

    #[test]
    fn lanes_take_the_steps_of_one_chain() {
        // Either side of the summed displacement's bound and of each lane
        // count's threshold, and long enough for odd and even lanes.
        let lanes_from = LANES * MIN_LANE_STEPS;
        let interleaved_from = MIN_INTERLEAVED_STEPS;
        for len in [
            0,
            1,
            MAX_STEPS_SUMMED,
            MAX_STEPS_SUMMED + 1,
            lanes_from - 1,
            lanes_from,
            lanes_from + 1,
            interleaved_from - 1,
            interleaved_from,
            interleaved_from + 1,
            interleaved_from + 3,
            interleaved_from + 7,
            4096,
            4099,
        ] {
            fills_as_one_chain(
                Terms {
                    always: Step(1),
                    terms: [
                        wang(7, 10, TiePolicy::Hold),
                        Term {
                            step: Step(0b1000),
                            ..wang(3, 10, TiePolicy::Advance)
                        },
                    ],
                },
                len,
            );
        }
    }

    #[test]
    fn a_term_whose_axis_never_steps_is_left_out_exactly() {
        // Wang's term of a passive axis with |Δ| = 0 (value -|Δa|, no
        // increment: a line in a plane of the grid) beside a moving one,
        // either first, both ties, starting anywhere in the window; then
        // both idle (a line along one axis).
        for tie in [TiePolicy::Hold, TiePolicy::Advance] {
            let idle = Term {
                step: Step(0b10),
                ..wang(0, 300, tie)
            };
            let moving = wang(97, 300, tie);
            let idle_at_top = Term {
                value: idle.steps_above,
                ..idle
            };
            for terms in [
                [idle, moving],
                [moving, idle],
                [
                    idle,
                    Term {
                        step: Step(0b100),
                        ..idle
                    },
                ],
                [idle_at_top, moving],
                [moving, idle_at_top],
            ] {
                for len in [MIN_INTERLEAVED_STEPS, MIN_INTERLEAVED_STEPS + 5, 300, 4099] {
                    fills_as_one_chain(
                        Terms {
                            always: Step(1),
                            terms,
                        },
                        len,
                    );
                }
            }
        }
    }

    #[test]
    fn saleem_terms_near_the_bound_take_the_32_bit_lanes_exactly() {
        // Saleem's terms (bresenham2d and 3d) compare with |Δmajor| rather
        // than 0: their values reach |Δmajor| + 2|Δminor|, one and a half
        // decrements, where Wang's stay within one. The largest major whose
        // terms still take the 32-bit lanes, minors across its range, both
        // ties, starts along the line, one and three terms. (With the
        // bound raised to 2^31 these lines wrap; Wang's do not.)
        let major = NARROW_BOUND / 2 - 1;
        let minors = [
            major,
            major - 1,
            major * 7 / 8,
            major / 2 + 1,
            major / 3,
            1,
            0,
        ];
        for tie in [TiePolicy::Hold, TiePolicy::Advance] {
            let term = |minor: i64, axis: usize| Term {
                value: 2 * minor,
                increment: 2 * minor,
                decrement: 2 * major,
                steps_above: Term::steps_above(major, tie),
                step: Step(1 << axis),
            };
            for minor in minors {
                for start in [0, 1, 2, 3, 7, 1000, major as u64 / 3] {
                    let t = term(minor, 1).jumped(start);
                    assert!(t.fits_i32(t.value), "minor {minor} at step {start}");
                    for len in [MIN_INTERLEAVED_STEPS, 4099] {
                        fills_as_one_chain(
                            Terms {
                                always: Step(1),
                                terms: [t],
                            },
                            len,
                        );
                    }
                }
            }
            for three in [[0, 1, 2], [3, 4, 5], [0, 2, 4]] {
                let terms: [Term; 3] = std::array::from_fn(|i| term(minors[three[i]], i + 1));
                assert!(terms.iter().all(|t| t.fits_i32(t.value)));
                fills_as_one_chain(
                    Terms {
                        always: Step(1),
                        terms,
                    },
                    4099,
                );
            }
        }
    }

    #[test]
    fn terms_past_32_bits_take_the_64_bit_lanes() {
        // Lines whose terms reach 2^28 and beyond, up to |Δ| = 2^30 (its
        // terms' 2^31 would wrap in 32-bit lanes: the 64-bit ones take
        // them), with one, two and three passive axes, and on each side
        // of the bound.
        let bound = NARROW_BOUND / 2;
        for active in [bound - 1, bound, bound + 1, 1 << 29, (1 << 30) - 1, 1 << 30] {
            // Each term on an axis of its own (1 to 3), so that every lane's steps show.
            let term = |axis: usize, passive: i64, tie| Term {
                step: Step(1 << axis),
                ..wang(passive, active, tie)
            };
            let (hold, advance) = (TiePolicy::Hold, TiePolicy::Advance);
            for len in [MIN_INTERLEAVED_STEPS, LANES * MIN_LANE_STEPS, 4099] {
                let always = Step(1);
                let one = [term(1, active - 3, hold)];
                fills_as_one_chain(Terms { always, terms: one }, len);
                let two = [term(1, active / 3, hold), term(2, active - 1, advance)];
                fills_as_one_chain(Terms { always, terms: two }, len);
                let three = [
                    term(1, active / 7, advance),
                    term(2, active / 2, hold),
                    term(3, active - 2, advance),
                ];
                fills_as_one_chain(
                    Terms {
                        always,
                        terms: three,
                    },
                    len,
                );
            }
        }
    }
}
