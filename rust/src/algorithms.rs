//! The catalogue: every algorithm voxpath runs, with its citation, teaching
//! text, decision columns and options. The CLI, the JS API and the page all
//! read this one list.

use crate::error::Error;
use crate::request::{OptionSpec, Request};
use crate::trace::{Column, ColumnKind, TiePolicy, Trace};
use serde::Serialize;
use serde::ser::{SerializeStruct, Serializer};

/// What an algorithm draws, and so which inputs it needs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Family {
    /// A straight move between two points (`from`, `to`).
    Line,
    /// An arc, circle or helix about a centre (`from`, `to`, `center`, ...).
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

impl Serialize for Family {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.label())
    }
}

/// A move that shows what an algorithm teaches: the page opens with it and
/// the README cites it. A test traces every example.
pub struct Example {
    /// The options (without `algorithm`) as JSON text.
    pub options: &'static str,
    /// Why this move: what a learner sees in it.
    pub why: &'static str,
}

/// One algorithm of the catalogue.
pub struct AlgorithmInfo {
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
    pub columns: &'static [Column],
    pub options: &'static [OptionSpec],
    pub min_dims: usize,
    pub max_dims: usize,
    pub default_tie: Option<TiePolicy>,
    /// Runs the algorithm on a request whose `algorithm` is this id.
    pub trace: fn(&Request) -> Result<Trace, Error>,
}

/// Every algorithm, in the order the page lists them.
pub const ALGORITHMS: &[&AlgorithmInfo] = &[
    &crate::line::regions_wang::INFO,
    &crate::line::bresenham2d::INFO,
    &crate::line::bresenham3d::INFO,
    &crate::line::nd::INFO,
    &crate::line::liu_float::INFO,
    &crate::line::greedy::INFO,
    &crate::line::walk6::INFO,
    &crate::line::dda::INFO,
    &crate::arc::circle_saleem::INFO,
    &crate::arc::arc_segments::INFO,
    &crate::arc::helix::INFO,
];

/// The algorithm with this id, or an error listing the known ids.
pub fn find(id: &str) -> Result<&'static AlgorithmInfo, Error> {
    ALGORITHMS
        .iter()
        .copied()
        .find(|a| a.id == id)
        .ok_or_else(|| {
            let ids: Vec<&str> = ALGORITHMS.iter().map(|a| a.id).collect();
            Error::field(
                "algorithm",
                format!("unknown algorithm '{id}' (known: {})", ids.join(", ")),
            )
        })
}

impl Serialize for Column {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut st = s.serialize_struct("Column", 4)?;
        st.serialize_field("name", self.name)?;
        let (kind, labels) = match self.kind {
            ColumnKind::Int => ("int", None),
            ColumnKind::Float => ("float", None),
            ColumnKind::Category(labels) => ("category", Some(labels)),
            ColumnKind::Flag => ("flag", None),
        };
        st.serialize_field("kind", kind)?;
        if let Some(labels) = labels {
            st.serialize_field("labels", labels)?;
        } else {
            st.skip_field("labels")?;
        }
        st.serialize_field("doc", self.doc)?;
        st.end()
    }
}

impl Serialize for AlgorithmInfo {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut st = s.serialize_struct("AlgorithmInfo", 12)?;
        st.serialize_field("id", self.id)?;
        st.serialize_field("family", &self.family)?;
        let options: serde_json::Value =
            serde_json::from_str(self.example.options).map_err(serde::ser::Error::custom)?;
        st.serialize_field(
            "example",
            &serde_json::json!({ "options": options, "why": self.example.why }),
        )?;
        st.serialize_field("title", self.title)?;
        st.serialize_field("citation", self.citation)?;
        st.serialize_field("teaching", self.teaching)?;
        st.serialize_field("errata", self.errata)?;
        st.serialize_field("columns", self.columns)?;
        st.serialize_field("options", self.options)?;
        st.serialize_field("minDims", &self.min_dims)?;
        st.serialize_field("maxDims", &self.max_dims)?;
        st.serialize_field("defaultTie", &self.default_tie.map(TiePolicy::label))?;
        st.end()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ids_are_unique_and_every_column_kind_serializes() {
        for (i, a) in ALGORITHMS.iter().enumerate() {
            assert!(
                ALGORITHMS[i + 1..].iter().all(|b| b.id != a.id),
                "duplicate id {}",
                a.id
            );
            let json = serde_json::to_value(a).unwrap();
            assert_eq!(json["id"], a.id);
            assert_eq!(json["columns"].as_array().unwrap().len(), a.columns.len());
        }
    }

    #[test]
    fn every_example_traces() {
        for a in ALGORITHMS {
            let mut request: serde_json::Value = serde_json::from_str(a.example.options).unwrap();
            request["algorithm"] = a.id.into();
            let trace =
                crate::trace_json(&request.to_string()).unwrap_or_else(|e| panic!("{}: {e}", a.id));
            assert!(trace.steps() > 0, "{}", a.id);
        }
    }

    #[test]
    fn unknown_algorithm_lists_the_known_ones() {
        let e = find("bresenham9d").err().unwrap().to_string();
        assert!(
            e.starts_with("algorithm: unknown algorithm 'bresenham9d' (known: regions"),
            "{e}"
        );
    }
}
