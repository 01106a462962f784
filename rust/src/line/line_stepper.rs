//! A line algorithm's stepper made from typed endpoints: for callers that
//! run many lines into one trace (a G-code program's straight moves, an
//! arc's chords), each straight into it, with no request to read per line
//! and no trace of its own to copy.

use super::bresenham3d::Bresenham3d;
use super::dda::Dda;
use super::greedy::Greedy;
use super::nd::Nd;
use super::regions_wang::RegionsWang;
use super::walk6::Walk6;
use super::{TieAxis, gcd_option};
use crate::algorithm_info::AlgorithmInfo;
use crate::error::Error;
use crate::figure::FigureKind;
use crate::grid::Point;
use crate::ideal::IdealPath;
use crate::plan::PointsSink;
use crate::request::{Request, TiePolicy};
use crate::trace::{Column, Decision, MadeSegment, Stepper};

/// A line algorithm with its options read once.
#[derive(Clone, Copy, Debug)]
pub enum LineStepper {
    Regions(TiePolicy, bool),
    Bresenham3d(TiePolicy, bool),
    Nd(TiePolicy, bool),
    Greedy(TieAxis),
    Walk6(TieAxis),
    Dda,
    /// Stepped through the catalogue's request, a trace of its own per
    /// line (liu-float, whose options have no public reader).
    ByRequest,
}

impl LineStepper {
    /// `info`'s algorithm with the options `request` gives (its tie, its
    /// GCD reduction, its tie axis), each at the algorithm's default when
    /// absent, read by the algorithm's own readers as the catalogue path
    /// reads them. [`LineStepper::ByRequest`] for an algorithm without
    /// public readers, or options they refuse (the catalogue path then
    /// says why).
    pub fn for_request(info: &AlgorithmInfo, request: &Request) -> LineStepper {
        let read = || -> Result<LineStepper, Error> {
            let tie = || request.tie(info.default_tie.unwrap_or(TiePolicy::Advance));
            Ok(match info.id {
                "regions" => LineStepper::Regions(tie()?, gcd_option(request)?),
                "bresenham3d" => LineStepper::Bresenham3d(tie()?, gcd_option(request)?),
                "nd" => LineStepper::Nd(tie()?, gcd_option(request)?),
                "greedy" => LineStepper::Greedy(TieAxis::from_request(request)?),
                "walk6" => LineStepper::Walk6(TieAxis::from_request(request)?),
                "dda" => LineStepper::Dda,
                _ => LineStepper::ByRequest,
            })
        };
        read().unwrap_or(LineStepper::ByRequest)
    }

    /// `visitor` given this algorithm's stepper from `from` to `to`, or
    /// None for [`LineStepper::ByRequest`]: the one place such a line's
    /// stepper is made, when it is run and when its segment is made again
    /// to be read.
    pub fn with_stepper<V: StepperVisitor>(
        self,
        from: Point,
        to: Point,
        visitor: V,
    ) -> Option<V::Out> {
        Some(match self {
            LineStepper::Regions(tie, gcd) => {
                visitor.visit(RegionsWang::with_gcd(from, to, tie, gcd))
            }
            LineStepper::Bresenham3d(tie, gcd) => {
                visitor.visit(Bresenham3d::new(from, to, tie, gcd))
            }
            LineStepper::Nd(tie, gcd) => visitor.visit(Nd::new(from, to, tie, gcd)),
            LineStepper::Greedy(order) => visitor.visit(Greedy::new(from, to, order)),
            LineStepper::Walk6(order) => visitor.visit(Walk6::new(from, to, order)),
            LineStepper::Dda => visitor.visit(Dda::new(from, to)),
            LineStepper::ByRequest => return None,
        })
    }

    /// Steps this rule takes from `from` to `to`, where known without
    /// stepping: the largest |Δ| for the Bresenham rules, whose every step
    /// moves the longest axis (its count known without making the stepper,
    /// which for the 1,720 chords of the bench's arc-segments circle cost
    /// about as much as the difference between it and the circle), else the
    /// count the rule's stepper gives.
    pub fn steps_between(self, from: Point, to: Point) -> Option<u64> {
        match self {
            LineStepper::Regions(..) | LineStepper::Bresenham3d(..) | LineStepper::Nd(..) => {
                Some(from.chebyshev_to(&to))
            }
            _ => self.with_stepper(from, to, RemainingSteps).flatten(),
        }
    }

    /// Whether the rule takes a line that moves no axis more than a unit in
    /// one step moving every axis that differs (none for a line of no
    /// length), whatever its tie and GCD options: true of the Bresenham
    /// rules, where the largest |Δ| is 1 and every axis that moves has it,
    /// so each is active (regions) or its first decision is 2·1 - 1 > 0
    /// (bresenham3d, nd). Not of greedy and walk6, which move one axis a
    /// step, nor dda, nor a rule run by its request.
    pub fn takes_unit_lines_at_once(self) -> bool {
        matches!(
            self,
            LineStepper::Regions(..) | LineStepper::Bresenham3d(..) | LineStepper::Nd(..)
        )
    }
}

/// What is done with a line stepper of whichever type
/// [`LineStepper::with_stepper`] makes: a closure generic over the
/// stepper's type.
pub trait StepperVisitor {
    type Out;
    fn visit<S: Stepper>(self, stepper: S) -> Self::Out;
}

/// The decision columns and figure of the stepper visited: what a trace
/// registers for its segments.
pub struct ColumnsAndFigure;

impl StepperVisitor for ColumnsAndFigure {
    type Out = (&'static [Column], Option<FigureKind>);
    fn visit<S: Stepper>(self, stepper: S) -> Self::Out {
        (stepper.columns(), <S::Why as Decision>::FIGURE)
    }
}

/// A segment made again when read ([`MadeSegment`]) from the stepper made
/// for its line: where it starts and the path it is measured against (a
/// G-code move's line, an arc's chord's piece of the arc).
pub struct MakeSegment {
    pub start: Point,
    pub ideal: IdealPath,
}

impl StepperVisitor for MakeSegment {
    type Out = MadeSegment;
    fn visit<S: Stepper>(self, stepper: S) -> MadeSegment {
        MadeSegment::new(self.start, self.ideal, stepper)
    }
}

/// Runs the stepper visited into a sink of points.
pub struct IntoSink<'s, 'a>(pub &'s mut PointsSink<'a, i32>);

impl StepperVisitor for IntoSink<'_, '_> {
    type Out = ();
    fn visit<S: Stepper>(self, stepper: S) {
        self.0.run(stepper);
    }
}

/// The visited stepper's steps, where it knows them without running.
pub struct RemainingSteps;

impl StepperVisitor for RemainingSteps {
    type Out = Option<u64>;
    fn visit<S: Stepper>(self, stepper: S) -> Option<u64> {
        stepper.remaining_steps()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::Step;
    use crate::line::TieAxis;

    /// Every step a line stepper takes, by next_step.
    struct AllSteps;

    impl StepperVisitor for AllSteps {
        type Out = Vec<Step>;
        fn visit<S: Stepper>(self, mut stepper: S) -> Vec<Step> {
            std::iter::from_fn(|| stepper.next_step().map(|(step, _)| step)).collect()
        }
    }

    /// Each of the 27 moves of at most a unit a axis, from a start in each
    /// octant of the grid.
    fn unit_lines() -> impl Iterator<Item = (Point, Point)> {
        let starts: [[i64; 3]; 3] = [[0, 0, 0], [-7, 5, 1 << 30], [1 << 29, -(1 << 30), -3]];
        starts.into_iter().flat_map(|start| {
            (0..27).map(move |i| {
                let delta = [i % 3 - 1, i / 3 % 3 - 1, i / 9 - 1];
                let end: [i64; 3] = std::array::from_fn(|a| {
                    // Stay within ±2^30: step back from the edge.
                    let d = if (start[a] + delta[a]).abs() > 1 << 30 {
                        -delta[a]
                    } else {
                        delta[a]
                    };
                    start[a] + d
                });
                (Point::new(&start), Point::new(&end))
            })
        })
    }

    #[test]
    fn unit_lines_are_one_step_of_every_axis_that_differs_where_the_rule_says_so() {
        let steppers = [TiePolicy::Advance, TiePolicy::Hold]
            .into_iter()
            .flat_map(|tie| {
                [false, true].into_iter().flat_map(move |gcd| {
                    [
                        LineStepper::Regions(tie, gcd),
                        LineStepper::Bresenham3d(tie, gcd),
                        LineStepper::Nd(tie, gcd),
                    ]
                })
            });
        for stepper in steppers {
            assert!(stepper.takes_unit_lines_at_once(), "{stepper:?}");
            for (from, to) in unit_lines() {
                let code = Step::between(from.coords(), to.coords());
                let want: Vec<Step> = (code != Step::NONE).then_some(code).into_iter().collect();
                let got = stepper.with_stepper(from, to, AllSteps).expect("in place");
                assert_eq!(got, want, "{stepper:?} from {from:?} to {to:?}");
            }
        }
        // Not vacuous: a rule that moves one axis a step takes a diagonal
        // unit line in two, and says it does not take them at once.
        let greedy = LineStepper::Greedy(TieAxis::Lower);
        assert!(!greedy.takes_unit_lines_at_once());
        let (from, to) = (Point::new(&[0, 0, 0]), Point::new(&[1, 1, 0]));
        assert_eq!(
            greedy
                .with_stepper(from, to, AllSteps)
                .expect("in place")
                .len(),
            2
        );
    }
}
