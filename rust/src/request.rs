//! Trace requests: the options of one trace, validated with errors that name
//! the option. Every algorithm declares the options it takes ([`OptionSpec`]);
//! the CLI flags and the page's inputs are generated from those declarations.

use crate::error::Error;
use crate::grid::{COORD_RANGE, Point, Step};
use crate::range::{IntegerRange, NumberRange, WHOLE_NUMBER};
use crate::text::echo;
use serde::Serialize;
use serde_json::{Map, Value};
use std::sync::Arc;
use tsify::Tsify;

/// Default limit on the length of one trace, in steps.
pub const DEFAULT_MAX_STEPS: u64 = 50_000_000;

/// The largest whole number (and, negated, the least) a request's number
/// is read as ([`Request::integer`]): every whole number up to it is exact
/// as JSON carries it (a double), past 2^53 no longer. The random lines'
/// seed, which has no bound of its own, declares this one, so that the
/// page's form refuses what the core would (a seed of 1e20 was put in the
/// link).
pub const MAX_EXACT_INTEGER: i64 = 8_999_999_999_999_999;

/// Hard limit on `maxSteps`: 2 bytes per step must fit in wasm32 memory.
pub const MAX_STEPS_LIMIT: u64 = 1_000_000_000;

/// What to do about a path or program that needs `at_least` steps, more than
/// maxSteps allows: raise maxSteps when that can be enough, else shorten
/// `what` (no maxSteps allows more than [`MAX_STEPS_LIMIT`]).
pub fn too_long_advice(at_least: u64, what: &str) -> String {
    if at_least > MAX_STEPS_LIMIT {
        format!("that is more than any maxSteps allows ({MAX_STEPS_LIMIT}): shorten {what}")
    } else {
        format!("raise maxSteps (up to {MAX_STEPS_LIMIT}) or shorten {what}")
    }
}

/// What a decision does when its discriminant is exactly zero, i.e. when the
/// ideal path passes exactly half way between the two candidate cells.
#[derive(Serialize, Tsify, Clone, Copy, Debug, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
pub enum TiePolicy {
    /// Step the axis (Liu's Table 1 and Wang's worked example: M >= 0 steps).
    Advance,
    /// Do not step the axis (Saleem's `error > delta`: strictly greater steps).
    Hold,
}

impl TiePolicy {
    pub fn label(self) -> &'static str {
        match self {
            TiePolicy::Advance => "advance",
            TiePolicy::Hold => "hold",
        }
    }

    /// Parses the `tie` option.
    pub fn parse(value: &str) -> Result<TiePolicy, Error> {
        match value {
            "advance" => Ok(TiePolicy::Advance),
            "hold" => Ok(TiePolicy::Hold),
            other => Err(Error::field(
                "tie",
                format!("expected 'advance' or 'hold', got '{}'", echo(other)),
            )),
        }
    }
}

/// The type of an option's value.
#[derive(Serialize, Tsify, Clone, Copy, Debug, PartialEq)]
#[serde(tag = "type", rename_all = "camelCase")]
pub enum OptionKind {
    /// Integer grid coordinates, one per axis, each within its range
    /// ([`crate::grid::COORD_RANGE`]).
    // Crosses as IntegerRangeInfo, as Integer does.
    Point(#[tsify(type = "IntegerRangeInfo")] IntegerRange),
    /// A real number within its range, in its unit.
    // Crosses as NumberRangeInfo: the bounds with their words.
    Number(#[tsify(type = "NumberRangeInfo")] NumberRange),
    /// A whole number, within its range where it has one (a small declared
    /// range is what a check tries every value of, see `check`).
    // Crosses as IntegerRangeInfo: the bounds with their words, which no
    // stored field holds.
    Integer(#[tsify(type = "IntegerRangeInfo")] IntegerRange),
    /// One of a fixed set of words.
    Choice { values: &'static [&'static str] },
    /// true or false.
    Boolean,
    /// A number for every axis, or one per axis ([x, y, z]), each within
    /// the range (a machine setting such as stepsPerMm or maxRate; whole
    /// numbers where the range says so, as microsteps).
    // Crosses as PerAxisInfo: the range's words and how many values a list
    // must hold, with the words for one that does not.
    PerAxis(
        #[serde(serialize_with = "crate::machine::serialize_per_axis")]
        #[tsify(type = "PerAxisInfo")]
        NumberRange,
    ),
}

/// One option an algorithm takes.
#[derive(Serialize, Tsify, Clone, Copy, Debug, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct OptionSpec {
    /// Name in the JS API (camelCase); the CLI flag is its kebab-case form.
    pub name: &'static str,
    pub kind: OptionKind,
    pub required: bool,
    /// Default shown to users (None when required or when it depends on input).
    pub default: Option<&'static str>,
    /// The value another of the algorithm's choice options must have for
    /// this one to apply (the helix's chord options, with method segments):
    /// given with any other, it is refused, naming this option. None where
    /// it always applies.
    pub applies_with: Option<AppliesWith>,
    pub doc: &'static str,
}

impl OptionSpec {
    /// The range a real-number option or a per-axis setting declares.
    pub fn number_range(&self) -> NumberRange {
        match self.kind {
            OptionKind::Number(range) | OptionKind::PerAxis(range) => range,
            _ => unreachable!(
                "{} is declared as a number or a per-axis setting",
                self.name
            ),
        }
    }
}

/// An option's condition ([`OptionSpec::applies_with`]): the choice option
/// named, at this value (given, or by its default).
#[derive(Serialize, Tsify, Clone, Copy, Debug, PartialEq)]
pub struct AppliesWith {
    pub option: &'static str,
    pub value: &'static str,
}

pub const FROM: OptionSpec = OptionSpec {
    name: "from",
    kind: OptionKind::Point(COORD_RANGE),
    required: true,
    default: None,
    applies_with: None,
    doc: "Start point, integer grid units, |coordinate| <= 2^30.",
};

pub const TO: OptionSpec = OptionSpec {
    name: "to",
    kind: OptionKind::Point(COORD_RANGE),
    required: true,
    default: None,
    applies_with: None,
    doc: "End point, grid units, as many axes as from.",
};

pub const MAX_STEPS: OptionSpec = OptionSpec {
    name: "maxSteps",
    kind: OptionKind::Integer(IntegerRange {
        min: Some(0),
        max: Some(MAX_STEPS_LIMIT as i64),
        whole: WHOLE_NUMBER,
    }),
    required: false,
    default: Some("50000000"),
    applies_with: None,
    doc: "Refuse paths longer than this many steps (at most 1000000000).",
};

/// The `tie` option with the default its source document uses.
pub const fn tie_option(default: &'static str) -> OptionSpec {
    OptionSpec {
        name: "tie",
        kind: OptionKind::Choice {
            values: &["advance", "hold"],
        },
        required: false,
        default: Some(default),
        applies_with: None,
        doc: "What a discriminant of exactly 0 does: advance steps the axis, hold does not.",
    }
}

/// The options of one trace as the JS API gives them: the algorithm, the
/// options every algorithm takes, and the further options its catalogue
/// entry lists (`AlgorithmInfo::options`), which the core checks by name.
/// Points may be any array-like of numbers (an Int32Array, say).
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct TraceOptions {
    /// Algorithm id, as the catalogue lists it (for example "regions").
    #[tsify(type = "AlgorithmId")]
    pub algorithm: String,
    /// Start point, grid units (2 to 6 axes, |coordinate| <= 2^30).
    #[tsify(type = "ArrayLike<number>")]
    pub from: Vec<i64>,
    /// End point, as many axes as `from`.
    #[tsify(type = "ArrayLike<number>")]
    pub to: Vec<i64>,
    /// What a zero discriminant does; the default is the algorithm's source's.
    #[tsify(optional)]
    pub tie: Option<TiePolicy>,
    /// Refuse paths longer than this many steps (default 50,000,000).
    #[tsify(optional)]
    pub max_steps: Option<u64>,
    /// The algorithm's further options, by name.
    #[serde(flatten)]
    #[tsify(type = "Record<string, unknown>")]
    pub more: Map<String, Value>,
}

/// A parsed request: an algorithm id and its options (already checked to be
/// among the options the algorithm declares).
#[derive(Debug, Clone)]
pub struct Request {
    pub algorithm: String,
    options: Map<String, Value>,
    /// Steps the trace is to follow, set by code, never by an option: a
    /// trace that parts from them stops there with an error (see
    /// [`crate::trace::TraceBuilder::for_request`]), so a check trying many
    /// rules against a learner's path stops each wrong one early.
    follow: Option<Arc<[Step]>>,
}

impl Request {
    /// A request built in code, with `options` as a JSON object would give
    /// them (for example one line of an arc split into chords).
    pub fn new(algorithm: &str, options: Map<String, Value>) -> Request {
        Request {
            algorithm: algorithm.to_string(),
            options,
            follow: None,
        }
    }

    /// The options of a JSON object, with null ones removed (absent and
    /// null mean the same: use the default).
    pub fn options_from_json(text: &str) -> Result<Map<String, Value>, Error> {
        let value: Value = serde_json::from_str(text)
            .map_err(|e| Error::field("request", format!("not valid JSON: {e}")))?;
        let Value::Object(mut options) = value else {
            return Err(Error::field("request", "expected an object of options"));
        };
        options.retain(|_, v| !v.is_null());
        Ok(options)
    }

    /// Parses `{"algorithm": "...", ...options}` from JSON text.
    pub fn from_json(text: &str) -> Result<Request, Error> {
        let mut options = Request::options_from_json(text)?;
        let algorithm = match options.remove("algorithm") {
            Some(Value::String(s)) => s,
            Some(other) => {
                return Err(Error::field(
                    "algorithm",
                    format!("expected a name, got {}", shown(&other)),
                ));
            }
            None => return Err(Error::field("algorithm", "missing (for example 'regions')")),
        };
        Ok(Request {
            algorithm,
            options,
            follow: None,
        })
    }

    /// Rejects options that are not among `accepted`, naming the first one,
    /// then any given where it does not apply ([`OptionSpec::applies_with`]).
    pub fn check_options(&self, accepted: &[OptionSpec]) -> Result<(), Error> {
        self.check_options_of(&self.algorithm, accepted)
    }

    /// [`Self::check_options`] for a run that is not the algorithm's alone
    /// (`taker`, as the refusal names it: "random-lines with regions").
    pub fn check_options_of(&self, taker: &str, accepted: &[OptionSpec]) -> Result<(), Error> {
        for name in self.options.keys() {
            if !accepted.iter().any(|o| o.name == name) {
                let names: Vec<&str> = accepted.iter().map(|o| o.name).collect();
                // The name as a message quotes it: a megabyte-long key is
                // named by its start.
                return Err(Error::field(
                    &echo(name),
                    format!(
                        "{taker} does not take this option (it takes {})",
                        names.join(", ")
                    ),
                ));
            }
        }
        if let Some(spec) = self.inapplicable(accepted)?.first() {
            let AppliesWith { option, value } = spec
                .applies_with
                .expect("an inapplicable option has a condition");
            return Err(Error::field(
                spec.name,
                format!("applies to {option} {value} only"),
            ));
        }
        Ok(())
    }

    /// The options of `accepted` given here where they do not apply: with
    /// the option their [`OptionSpec::applies_with`] names at another value
    /// (given, or by its default). An error where that option's own value
    /// is not one of its choices.
    pub fn inapplicable<'a>(
        &self,
        accepted: &'a [OptionSpec],
    ) -> Result<Vec<&'a OptionSpec>, Error> {
        let mut out = Vec::new();
        for spec in accepted {
            let Some(AppliesWith { option, value }) = spec.applies_with else {
                continue;
            };
            if self.get(spec.name).is_none() {
                continue;
            }
            let governing = accepted
                .iter()
                .find(|o| o.name == option)
                .expect("an option applies with another option of the same algorithm");
            if self.choice(governing)?.or(governing.default) != Some(value) {
                out.push(spec);
            }
        }
        Ok(out)
    }

    /// This request without the named options (for a request that drives
    /// other requests, such as an experiment over many lines).
    pub fn without(&self, names: &[&str]) -> Request {
        let mut options = self.options.clone();
        options.retain(|k, _| !names.contains(&k.as_str()));
        Request {
            algorithm: self.algorithm.clone(),
            options,
            follow: self.follow.clone(),
        }
    }

    /// This request, to be traced only as long as it takes `steps`.
    pub fn following(mut self, steps: Arc<[Step]>) -> Request {
        self.follow = Some(steps);
        self
    }

    /// The steps set by [`Self::following`].
    pub fn follow(&self) -> Option<&Arc<[Step]>> {
        self.follow.as_ref()
    }

    /// The options as given (without `algorithm`).
    pub fn options(&self) -> &Map<String, Value> {
        &self.options
    }

    /// Sets an option.
    pub fn set(&mut self, name: &str, value: Value) {
        self.options.insert(name.to_string(), value);
    }

    fn get(&self, name: &str) -> Option<&Value> {
        self.options.get(name)
    }

    /// Whether the option `name` was given.
    pub fn has(&self, name: &str) -> bool {
        self.options.contains_key(name)
    }

    /// A required point option.
    pub fn point(&self, name: &str) -> Result<Point, Error> {
        self.optional_point(name)?
            .ok_or_else(|| Error::field(name, "missing: give one integer per axis, e.g. [0, 0, 0]"))
    }

    pub fn optional_point(&self, name: &str) -> Result<Option<Point>, Error> {
        let Some(value) = self.get(name) else {
            return Ok(None);
        };
        let Value::Array(items) = value else {
            return Err(Error::field(
                name,
                format!("expected a list of coordinates, got {}", shown(value)),
            ));
        };
        let mut coords = Vec::with_capacity(items.len());
        for (axis, item) in items.iter().enumerate() {
            match item.as_f64() {
                Some(v) => coords.push(v),
                None => {
                    let axis_name = crate::grid::AXIS_NAMES.get(axis).unwrap_or(&"coordinate");
                    return Err(Error::field(
                        name,
                        format!("{axis_name} must be a number, got {}", shown(item)),
                    )
                    .on_axis(axis));
                }
            }
        }
        Point::parse(name, &coords).map(Some)
    }

    pub fn number(&self, name: &str) -> Result<Option<f64>, Error> {
        match self.get(name) {
            None => Ok(None),
            Some(v) => match v.as_f64() {
                Some(x) if x.is_finite() => Ok(Some(x)),
                _ => Err(Error::field(
                    name,
                    format!("expected a number, got {}", shown(v)),
                )),
            },
        }
    }

    pub fn integer(&self, name: &str) -> Result<Option<i64>, Error> {
        match self.number(name)? {
            None => Ok(None),
            Some(x) if x.fract() == 0.0 && x.abs() <= MAX_EXACT_INTEGER as f64 => {
                Ok(Some(x as i64))
            }
            // Whole, but past what a double holds exactly: 9007199254740993
            // arrives as ...992. Said so, not "not a whole number".
            Some(x) if x.fract() == 0.0 => Err(Error::field(
                name,
                format!(
                    "must be within ±9e15, where every whole number is exact as JSON carries it, got {x}"
                ),
            )),
            Some(x) => Err(Error::field(
                name,
                format!("must be {WHOLE_NUMBER}, got {x}"),
            )),
        }
    }

    /// The whole number of option `spec`, within the range its kind
    /// declares (the one statement of that range and its words: the
    /// catalogue gives both to the page's form, which checks every field as
    /// it is typed). Checked against the range as a number first, so that a
    /// value out of range (1e20 for maxSteps) is told its range, not that
    /// it is not a whole number.
    pub fn declared_integer(&self, spec: &OptionSpec) -> Result<Option<i64>, Error> {
        let OptionKind::Integer(range) = spec.kind else {
            unreachable!("{} is declared as an integer option", spec.name)
        };
        let Some(x) = self.number(spec.name)? else {
            return Ok(None);
        };
        if let Some(words) = range.must_be_if_outside(x) {
            return Err(Error::field(spec.name, format!("{words}, got {x}")));
        }
        // In the declaration's words, as the form says them.
        if x.fract() != 0.0 {
            return Err(Error::field(
                spec.name,
                format!("{}, got {x}", range.not_whole()),
            ));
        }
        self.integer(spec.name)
    }

    /// The real number of option `spec`, within the range its kind
    /// declares (the one statement of that range and its words, which the
    /// catalogue gives to the page's form).
    pub fn declared_number(&self, spec: &OptionSpec) -> Result<Option<f64>, Error> {
        self.number(spec.name)?
            .map(|x| spec.number_range().check(spec.name, x))
            .transpose()
    }

    pub fn boolean(&self, name: &str) -> Result<Option<bool>, Error> {
        match self.get(name) {
            None => Ok(None),
            Some(Value::Bool(b)) => Ok(Some(*b)),
            Some(v) => Err(Error::field(
                name,
                format!("expected true or false, got {}", shown(v)),
            )),
        }
    }

    pub fn choice(&self, spec: &OptionSpec) -> Result<Option<&str>, Error> {
        let OptionKind::Choice { values } = spec.kind else {
            unreachable!("choice() is for choice options");
        };
        match self.get(spec.name) {
            None => Ok(None),
            Some(Value::String(s)) if values.contains(&s.as_str()) => Ok(Some(s)),
            Some(v) => Err(Error::field(
                spec.name,
                format!("expected one of {}, got {}", values.join(", "), shown(v)),
            )),
        }
    }

    /// The tie policy, or `default` when not given.
    pub fn tie(&self, default: TiePolicy) -> Result<TiePolicy, Error> {
        match self.get("tie") {
            None => Ok(default),
            Some(Value::String(s)) => TiePolicy::parse(s),
            Some(v) => Err(Error::field(
                "tie",
                format!("expected 'advance' or 'hold', got {}", shown(v)),
            )),
        }
    }

    pub fn max_steps(&self) -> Result<u64, Error> {
        Ok(self
            .declared_integer(&MAX_STEPS)?
            .map_or(DEFAULT_MAX_STEPS, |n| n as u64))
    }

    /// `from` and `to`, checked to have the same number of axes, within the
    /// algorithm's range of axis counts.
    pub fn endpoints(&self, min_dims: usize, max_dims: usize) -> Result<(Point, Point), Error> {
        let from = self.point("from")?;
        let to = self.point("to")?;
        let dims = from.dims();
        if !(min_dims..=max_dims).contains(&dims) {
            let wanted = if min_dims == max_dims {
                format!("{min_dims}")
            } else {
                format!("{min_dims} to {max_dims}")
            };
            return Err(Error::field(
                "from",
                format!("{} takes {wanted} coordinates, got {dims}", self.algorithm),
            ));
        }
        if to.dims() != dims {
            return Err(Error::field(
                "to",
                format!("has {} coordinates but from has {dims}", to.dims()),
            ));
        }
        Ok((from, to))
    }
}

/// A JSON value as a message quotes it: its JSON text, a long one by its
/// start and length ([`echo`]), so that a 10 MB string is not said back whole.
pub(crate) fn shown(value: &Value) -> String {
    match value {
        // How the JS API sends a number JSON cannot carry (JSON would make
        // it null): said as the number it was, not as text.
        Value::String(text) if matches!(text.as_str(), "NaN" | "Infinity" | "-Infinity") => {
            text.clone()
        }
        // Its items so too: [NaN, 1, 1] was said ["NaN",1,1], as if text.
        Value::Array(items) => format!(
            "[{}]",
            items.iter().map(shown).collect::<Vec<_>>().join(",")
        ),
        _ => echo(&value.to_string()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_number_json_cannot_carry_is_shown_as_the_number_it_was_in_a_list_too() {
        use serde_json::json;
        assert_eq!(shown(&json!("NaN")), "NaN");
        assert_eq!(shown(&json!(["NaN", 1, "Infinity"])), "[NaN,1,Infinity]");
        assert_eq!(
            shown(&json!(["a", [1, "-Infinity"]])),
            "[\"a\",[1,-Infinity]]"
        );
    }

    #[test]
    fn a_declared_integer_is_held_to_its_declared_range_in_words_for_each_bound() {
        let spec = |min, max| OptionSpec {
            name: "n",
            kind: OptionKind::Integer(IntegerRange {
                min,
                max,
                whole: WHOLE_NUMBER,
            }),
            required: false,
            default: None,
            applies_with: None,
            doc: "",
        };
        let read = |json: &str, min, max| {
            Request::from_json(json)
                .unwrap()
                .declared_integer(&spec(min, max))
                .map_err(|e| e.message)
        };
        let n = |v: i64| format!(r#"{{"algorithm":"regions","n":{v}}}"#);
        assert_eq!(read(&n(5), Some(1), Some(5)), Ok(Some(5)));
        assert_eq!(read(&n(1), Some(1), Some(5)), Ok(Some(1)));
        assert_eq!(
            read(&n(6), Some(1), Some(5)),
            Err("must be 1 to 5, got 6".into())
        );
        assert_eq!(
            read(&n(0), Some(1), Some(5)),
            Err("must be 1 to 5, got 0".into())
        );
        assert_eq!(
            read(&n(-1), Some(0), None),
            Err("must be 0 or more, got -1".into())
        );
        assert_eq!(
            read(&n(i64::MAX / 4096), Some(0), None),
            Ok(Some(i64::MAX / 4096))
        );
        assert_eq!(
            read(&n(8), None, Some(7)),
            Err("must be 7 or less, got 8".into())
        );
        assert_eq!(read(&n(-3), None, None), Ok(Some(-3)));
        assert_eq!(
            read(r#"{"algorithm":"regions"}"#, Some(1), Some(5)),
            Ok(None)
        );
        assert_eq!(
            read(&n(0).replace('0', "0.5"), Some(0), Some(5)),
            Err("must be a whole number, got 0.5".into())
        );
    }

    #[test]
    fn long_values_are_quoted_by_their_start() {
        // A 10 MB value was said back whole in a 10 MB message.
        let long = "x".repeat(100);
        let short = format!("{}... (100 characters)", "x".repeat(16));
        let request = |extra: String| {
            Request::from_json(&format!(r#"{{"algorithm":"regions",{extra}}}"#)).unwrap()
        };
        assert_eq!(
            request(format!(r#""tie":"{long}""#))
                .tie(TiePolicy::Hold)
                .unwrap_err()
                .to_string(),
            format!("tie: expected 'advance' or 'hold', got '{short}'")
        );
        // JSON text: the quotes count among its characters.
        let dir = OptionSpec {
            name: "dir",
            kind: OptionKind::Choice {
                values: &["cw", "ccw"],
            },
            required: false,
            default: None,
            applies_with: None,
            doc: "",
        };
        assert_eq!(
            request(format!(r#""dir":"{long}""#))
                .choice(&dir)
                .unwrap_err()
                .to_string(),
            format!(
                "dir: expected one of cw, ccw, got \"{}... (102 characters)",
                "x".repeat(15)
            )
        );
        assert_eq!(
            request(format!(r#""{long}":1"#))
                .check_options(&[dir])
                .unwrap_err()
                .to_string(),
            format!("{short}: regions does not take this option (it takes dir)")
        );
    }

    #[test]
    fn errors_name_the_option() {
        let e = |json: &str| {
            Request::from_json(json)
                .and_then(|r| r.endpoints(3, 3).map(|_| ()))
                .unwrap_err()
                .to_string()
        };
        assert_eq!(
            e(r#"{"from":[0,0,0],"to":[1,2,3]}"#),
            "algorithm: missing (for example 'regions')"
        );
        assert_eq!(
            e(r#"{"algorithm":"regions","to":[1,2,3]}"#),
            "from: missing: give one integer per axis, e.g. [0, 0, 0]"
        );
        assert_eq!(
            e(r#"{"algorithm":"regions","from":[0,"a",0],"to":[1,2,3]}"#),
            "from: y must be a number, got \"a\""
        );
        assert_eq!(
            e(r#"{"algorithm":"regions","from":[0,0],"to":[1,2]}"#),
            "from: regions takes 3 coordinates, got 2"
        );
        assert_eq!(
            e(r#"{"algorithm":"regions","from":[0,0,0],"to":[1,2]}"#),
            "to: has 2 coordinates but from has 3"
        );
        assert_eq!(
            e("[1"),
            "request: not valid JSON: EOF while parsing a list at line 1 column 2"
        );
    }

    #[test]
    fn unknown_options_are_named() {
        let r = Request::from_json(
            r#"{"algorithm":"regions","from":[0,0,0],"to":[1,2,3],"center":[1,1,1]}"#,
        )
        .unwrap();
        let e = r.check_options(&[FROM, TO, MAX_STEPS]).unwrap_err();
        assert_eq!(
            e.to_string(),
            "center: regions does not take this option (it takes from, to, maxSteps)"
        );
    }

    #[test]
    fn max_steps_and_tie_are_checked() {
        let r = Request::from_json(r#"{"algorithm":"x","maxSteps":-1,"tie":"sometimes"}"#).unwrap();
        assert_eq!(
            r.max_steps().unwrap_err().to_string(),
            "maxSteps: must be 0 to 1000000000, got -1"
        );
        assert_eq!(
            r.tie(TiePolicy::Advance).unwrap_err().to_string(),
            "tie: expected 'advance' or 'hold', got 'sometimes'"
        );
        // Whole, but past the range: the range is the fault, not the form.
        let r = Request::from_json(r#"{"algorithm":"x","maxSteps":1e20}"#).unwrap();
        assert_eq!(
            r.max_steps().unwrap_err().to_string(),
            "maxSteps: must be 0 to 1000000000, got 100000000000000000000"
        );
        let r = Request::from_json(r#"{"algorithm":"x","maxSteps":2.5}"#).unwrap();
        assert_eq!(
            r.max_steps().unwrap_err().to_string(),
            "maxSteps: must be a whole number, got 2.5"
        );
        // Whole, but past what JSON carries exactly: said so, not "not whole".
        let r = Request::from_json(r#"{"algorithm":"x","seed":9007199254740991}"#).unwrap();
        assert_eq!(
            r.integer("seed").unwrap_err().to_string(),
            "seed: must be within ±9e15, where every whole number is exact as JSON carries it, got 9007199254740991"
        );
    }

    #[test]
    fn booleans_are_json_true_or_false() {
        let r = Request::from_json(r#"{"algorithm":"x","gcd":true,"other":"yes"}"#).unwrap();
        assert_eq!(r.boolean("gcd").unwrap(), Some(true));
        assert_eq!(r.boolean("absent").unwrap(), None);
        assert_eq!(
            r.boolean("other").unwrap_err().to_string(),
            "other: expected true or false, got \"yes\""
        );
        assert_eq!(
            serde_json::to_value(OptionKind::Boolean).unwrap(),
            serde_json::json!({"type": "boolean"})
        );
    }
}
