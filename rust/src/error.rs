//! Errors a user can act on: each names the input field (or the G-code line
//! and column) it is about.

use serde::Serialize;
use std::fmt;
use tsify::Tsify;

/// Where in the input an error is.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Location {
    /// A named option, for example `from` or `maxSteps`.
    Field(String),
    /// A place in a text input, 1-based.
    Source { line: u32, column: u32 },
}

/// A cap the input ran into, for a caller to word its own advice (a page
/// whose cap is fixed cannot tell its reader to raise it): the option that
/// sets the cap, its value in force, what the input needs at least, and the
/// most the option may be set to.
#[derive(Serialize, Tsify, Clone, Debug, PartialEq, Eq)]
#[serde(rename_all = "camelCase")]
pub struct Limit {
    /// The option, e.g. `maxSteps`.
    pub option: String,
    pub value: u64,
    pub at_least: u64,
    pub most: u64,
}

/// An arc split into more chords than one trace takes (arc-segments'
/// MAX_CHORDS, which no option raises), for a caller that sets no chord
/// option, a G-code program, to word its own advice: it read the count
/// back out of the arc's message before.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TooManyChords {
    /// The count the rule gives, kept as a float: a tiny tolerance makes it
    /// hundreds of digits long, a segment length of 1e-320 infinite.
    pub chords: f64,
    /// The most chords an arc may be split into.
    pub most: u64,
}

impl TooManyChords {
    /// The count as a message says it: "70265 chords", "2.221e153
    /// chords", or, past what a double counts, not "inf chords".
    pub fn chords_text(&self) -> String {
        let n = self.chords;
        if n < 1e15 {
            format!("{n:.0} chords")
        } else if n.is_finite() {
            format!("{n:.3e} chords")
        } else {
            "more chords than can be counted".to_string()
        }
    }

    /// The arc's own words, naming `option`, the chord option (segmentLength
    /// or tolerance) whose rule gave the count: its caller can change it.
    pub fn error(self, option: &str) -> Error {
        Error {
            too_many_chords: Some(Box::new(self)),
            ..Error::field(
                option,
                format!(
                    "splits this arc into {}, more than {}; use longer chords",
                    self.chords_text(),
                    self.most
                ),
            )
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct Error {
    pub location: Location,
    pub message: String,
    /// For a point option, the axis index (0 = x) the error is about.
    pub axis: Option<usize>,
    /// The cap the input ran into, when that is what is wrong.
    pub limit: Option<Limit>,
    /// The arc's chords past their bound, when that is what is wrong
    /// (boxed: most errors are not this one, and all are returned by value).
    pub too_many_chords: Option<Box<TooManyChords>>,
}

impl Error {
    pub fn field(field: &str, message: impl Into<String>) -> Error {
        Error {
            location: Location::Field(field.to_string()),
            message: message.into(),
            axis: None,
            limit: None,
            too_many_chords: None,
        }
    }

    pub fn at(line: u32, column: u32, message: impl Into<String>) -> Error {
        Error {
            location: Location::Source { line, column },
            message: message.into(),
            axis: None,
            limit: None,
            too_many_chords: None,
        }
    }

    /// This error, about coordinate `axis` of a point option.
    pub fn on_axis(mut self, axis: usize) -> Error {
        self.axis = Some(axis);
        self
    }

    /// This error, as one of running into `limit`.
    pub fn with_limit(mut self, limit: Limit) -> Error {
        self.limit = Some(limit);
        self
    }

    /// The field this error names, if it is about an option.
    pub fn field_name(&self) -> Option<&str> {
        match &self.location {
            Location::Field(f) => Some(f),
            Location::Source { .. } => None,
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.location {
            Location::Field(field) => write!(f, "{field}: {}", self.message),
            Location::Source { line, column } => {
                write!(f, "line {line}, column {column}: {}", self.message)
            }
        }
    }
}

impl std::error::Error for Error {}

/// A count and its noun as a message says them: "1 chord", "3 chords".
pub fn counted(n: u64, noun: &str) -> String {
    format!("{n} {noun}{}", if n == 1 { "" } else { "s" })
}

/// A number as a message prints it: as Rust writes it, or in e-notation
/// where that would run to hundreds of digits (1e-300 is "1e-300", not 300
/// zeros and a 1), and an infinity as JavaScript spells it, "Infinity" (the
/// caller typed that, not Rust's "inf").
pub fn number_text(value: f64) -> String {
    if value.is_infinite() {
        return if value > 0.0 { "Infinity" } else { "-Infinity" }.to_string();
    }
    if value == 0.0 || value.is_nan() || (1e-6..1e15).contains(&value.abs()) {
        value.to_string()
    } else {
        format!("{value:e}")
    }
}
