//! The recording loop shared by the integer line rules whose passive axes
//! each keep one discriminant: Saleem's error terms (bresenham3d) and Wang's
//! n-axis discriminants (nd). Both rules have the same shape per passive
//! axis and step:
//!
//! ```text
//! the axis steps when  value > steps_above;   then  value += increment - (decrement if it stepped)
//! ```
//!
//! so one loop, with no branch on the values, records either. The steppers'
//! own `next_step` (which builds the decision a learner reads) stays the
//! reference; `tests` below and the property tests check that both give the
//! same steps.

use crate::grid::Step;
use crate::trace::TiePolicy;

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

impl Term {
    /// `steps_above` for a rule that steps past `threshold` and decides
    /// `value == threshold` by `tie`.
    pub fn steps_above(threshold: i64, tie: TiePolicy) -> i64 {
        match tie {
            TiePolicy::Hold => threshold,
            TiePolicy::Advance => threshold - 1,
        }
    }
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

impl<const N: usize> Terms<N> {
    /// Records `out.len()` steps.
    ///
    /// The mask is all ones when the term exceeds `steps_above` (their
    /// difference is negative), else 0: built by a subtraction and a shift,
    /// it keeps a term's step bits and decrement when its axis steps. The
    /// callers keep |value| and |steps_above| below 2^62, so the difference
    /// cannot overflow.
    #[inline(always)]
    pub fn fill(&mut self, out: &mut [Step]) {
        for slot in out {
            let mut bits = self.always.0;
            for term in &mut self.terms {
                let mask = (term.steps_above - term.value) >> 63;
                bits |= term.step.0 & mask as u16;
                term.value += term.increment - (term.decrement & mask);
            }
            *slot = Step(bits);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
            let mut out = [Step::NONE; 4];
            terms.fill(&mut out);
            out.map(|s| s.0)
        };
        // Hold: 10 = 10 holds; 20 > 10 steps (-> 10); 10 holds; 20 steps.
        assert_eq!(run(TiePolicy::Hold), [0b1, 0b101, 0b1, 0b101]);
        // Advance: 10 = 10 steps (-> 0); 0 < 10 holds (-> 10); 10 steps;
        // 0 holds.
        assert_eq!(run(TiePolicy::Advance), [0b101, 0b1, 0b101, 0b1]);
    }
}
