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
pub mod catalogue;
pub mod check;
pub mod compare;
pub mod error;
pub mod experiment;
pub mod figure;
pub mod gcode;
pub mod grid;
pub mod huge_pages;
pub mod ideal;
mod lanes;
pub mod lazy_trace;
pub mod line;
pub mod machine;
pub mod memory;
pub mod metrics;
pub mod plan;
pub mod planner;
pub mod points;
pub mod range;
pub mod request;
pub mod starts;
pub mod step_clocks;
pub mod step_detail;
pub mod text;
pub mod trace;
pub mod wasm;

// The crate's API for other crates (rust/tests, examples): the modules
// themselves import from the file that declares each item, never through
// these, so that the crate root sits above every file in the import graph.
pub use algorithms::{run, trace_json};
pub use error::{Error, Limit};
pub use grid::{Point, Step};
pub use request::Request;
pub use trace::{Trace, TraceBuilder};
