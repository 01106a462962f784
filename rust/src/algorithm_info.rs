//! What the catalogue says of one algorithm: its citation, teaching text,
//! decision columns and options. A leaf: it imports no algorithm, so the
//! algorithms can declare their `INFO` with it and the list in `algorithms`
//! can import them without a loop.

use crate::error::Error;
use crate::plan::Plan;
use crate::request::{OptionSpec, Request, TiePolicy};
use crate::trace::{Column, Trace};
use serde::{Serialize, Serializer};
use tsify::Tsify;

/// Finds a catalogue algorithm by id (`algorithms::find`): handed to each
/// algorithm's `trace`, so one that steps with another (arc-segments' chords)
/// reaches it without importing the list that imports it.
pub type Find = fn(&str) -> Result<&'static AlgorithmInfo, Error>;

/// What an algorithm draws, and so which inputs it needs.
#[derive(Serialize, Tsify, Clone, Copy, Debug, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
pub enum Family {
    /// A straight move between two points (`from`, `to`).
    Line,
    /// An arc, circle or helix about a center (`from`, `to`, `center`, ...).
    Arc,
}

impl Family {
    pub fn label(self) -> &'static str {
        match self {
            Family::Line => "line",
            Family::Arc => "arc",
        }
    }
}

/// A move that shows what an algorithm teaches: the page opens with it and
/// the README cites it. A test traces every example.
#[derive(Serialize, Tsify)]
pub struct Example {
    /// The options (without `algorithm`), written as JSON text in Rust.
    #[serde(serialize_with = "json_text")]
    #[tsify(type = "Record<string, unknown>")]
    pub options: &'static str,
    /// Why this move: what a learner sees in it.
    pub why: &'static str,
}

/// JSON text as the value it spells.
fn json_text<S: Serializer>(text: &&'static str, s: S) -> Result<S::Ok, S::Error> {
    serde_json::from_str::<serde_json::Value>(text)
        .map_err(serde::ser::Error::custom)?
        .serialize(s)
}

/// Makes a plan of a request for the algorithm it names ([`crate::plan`]),
/// or None where the algorithm cannot promise its path's length and end
/// without running it. Its errors are never shown: the algorithm's `trace`
/// makes every error a request gets ([`crate::lazy_trace::LazyTrace::new`]).
pub type PlanFn = fn(&Request, Find) -> Result<Option<Plan>, Error>;

/// One algorithm of the catalogue.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct AlgorithmInfo {
    /// The id a request names (for example "regions").
    #[tsify(type = "AlgorithmId")]
    pub id: &'static str,
    pub family: Family,
    pub example: Example,
    pub title: &'static str,
    /// Document and section.
    pub citation: &'static str,
    /// The rule in plain words.
    pub teaching: &'static str,
    /// Where the source document is wrong, and what voxpath does instead.
    pub errata: &'static [&'static str],
    /// The decision columns of its traces.
    pub columns: &'static [Column],
    /// The options it takes; CLI flags, form fields and URL keys are made from these.
    pub options: &'static [OptionSpec],
    /// Axis counts it accepts.
    pub min_dims: usize,
    pub max_dims: usize,
    /// Default tie policy; null when it takes no `tie` option (it has no
    /// ties, or, like greedy and walk6, orders tied axes with `tieAxis`).
    pub default_tie: Option<TiePolicy>,
    /// The choice option by which it is compared with itself, null when it
    /// is not: compared with itself, one side runs that option's value as
    /// given (else its default), the other the first other value (the
    /// helix by its method, Saleem's rule against chords: on a move that
    /// rises no other algorithm takes, and it is the comparison a learner
    /// wants).
    pub compared_by: Option<&'static str>,
    /// Runs the algorithm on a request whose `algorithm` is this id.
    #[serde(skip)]
    pub trace: fn(&Request, Find) -> Result<Trace, Error>,
    /// Plans a request without recording it, where this algorithm knows
    /// its path's length and end before running it ([`crate::plan`]).
    #[serde(skip)]
    pub plan: Option<PlanFn>,
}

impl AlgorithmInfo {
    /// Runs this algorithm on the request `json`, with `find` for the
    /// algorithms it steps with: for a unit test in the algorithm's own file,
    /// which runs it without the catalogue (the catalogue imports the file).
    #[cfg(test)]
    pub fn trace_json(&self, json: &str, find: Find) -> Result<Trace, Error> {
        (self.trace)(&Request::from_json(json)?, find)
    }
}

/// A [`Find`] that finds no algorithm: for a test of one that steps alone.
#[cfg(test)]
pub fn find_none(id: &str) -> Result<&'static AlgorithmInfo, Error> {
    Err(Error::field(
        "algorithm",
        format!("'{id}' is not run by this test"),
    ))
}
