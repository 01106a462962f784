//! voxpath: voxelized step sequences for lines, arcs and helices, with the
//! reason for every step.
//!
//! Flow: a [`Request`] names an algorithm and its options; the algorithm's
//! stepper yields `(Step, Why)` events; a [`TraceBuilder`] records the steps
//! compactly into a [`Trace`], which recomputes the decisions (`Why`) and the
//! deviation from the ideal path for any step range on demand.
//! [`wasm`] is the only module that knows about JavaScript.

// Loops over axis indices read several per-axis arrays at once; an index
// says "this axis" more plainly than zipped iterators.
#![allow(clippy::needless_range_loop)]

pub mod algorithm_info;
pub mod algorithms;
pub mod arc;
pub mod check;
pub mod catalogue;
pub mod compare;
pub mod error;
pub mod experiment;
pub mod gcode;
pub mod grid;
pub mod ideal;
pub mod line;
pub mod machine;
pub mod metrics;
pub mod planner;
pub mod points;
pub mod request;
pub mod trace;
pub mod wasm;

pub use error::Error;
pub use grid::{Point, Step};
pub use request::Request;
pub use trace::{Trace, TraceBuilder};

/// Runs the request described by JSON text, e.g.
/// `{"algorithm": "regions", "from": [0,0,0], "to": [10,7,6]}`.
pub fn trace_json(request_json: &str) -> Result<Trace, Error> {
    run(&Request::from_json(request_json)?)
}

/// Runs a parsed request with the algorithm it names.
pub fn run(request: &Request) -> Result<Trace, Error> {
    (algorithms::find(&request.algorithm)?.trace)(request, algorithms::find)
}
