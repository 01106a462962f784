//! Line algorithms: each turns a straight move between two grid points into
//! single steps. One file per algorithm.

pub mod regions_wang;

use crate::algorithms::AlgorithmInfo;
use crate::error::Error;
use crate::grid::Point;
use crate::ideal::IdealPath;
use crate::request::Request;
use crate::trace::{Stepper, TiePolicy, Trace, TraceBuilder};

/// Traces one straight move with the stepper `make` builds from the request's
/// endpoints and tie policy: the shape every line algorithm shares.
pub fn trace_line<S: Stepper>(
    info: &AlgorithmInfo,
    req: &Request,
    make: impl FnOnce(Point, Point, TiePolicy) -> S,
) -> Result<Trace, Error> {
    req.check_options(info.options)?;
    let (from, to) = req.endpoints(info.min_dims, info.max_dims)?;
    let tie = req.tie(info.default_tie.unwrap_or(TiePolicy::Advance))?;
    let mut builder = TraceBuilder::new(from, req.max_steps()?);
    builder.run(make(from, to, tie), IdealPath::Line { from, to })?;
    Ok(builder.finish(info.id))
}
