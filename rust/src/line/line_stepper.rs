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
use crate::grid::Point;
use crate::ideal::IdealPath;
use crate::request::{Request, TiePolicy};
use crate::trace::{MadeSegment, Stepper};

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
}

/// What is done with a line stepper of whichever type
/// [`LineStepper::with_stepper`] makes: a closure generic over the
/// stepper's type.
pub trait StepperVisitor {
    type Out;
    fn visit<S: Stepper>(self, stepper: S) -> Self::Out;
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
