//! The range of a whole-number input, `min..=max`, and the words a value
//! outside it is told: declared by options (the catalogue gives both to the
//! page's form) and by every coordinate of an input point.

use serde::Serialize;
use tsify::Tsify;

/// The bounds of a whole-number input (an option, a point's coordinate),
/// `min..=max`, either absent, and what a whole value of it is called.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IntegerRange {
    pub min: Option<i64>,
    pub max: Option<i64>,
    /// A whole value, as a value that is not one is told what it must be
    /// ([`WHOLE_NUMBER`], or a coordinate's [`crate::grid::COORDINATE_UNITS`]).
    pub whole: &'static str,
}

/// What a whole-number option's value must be.
pub const WHOLE_NUMBER: &str = "a whole number";

impl IntegerRange {
    /// What a value that is not whole is told, before ", got" and the
    /// value ("must be a whole number"): the one statement of these words,
    /// as [`IntegerRange::must_be`]'s are.
    pub fn not_whole(&self) -> String {
        format!("must be {}", self.whole)
    }

    /// What a value outside the range is told, before ", got" and the
    /// value: "must be 1 to 5", "must be 0 or more", "must be 7 or less";
    /// None when neither bound is given. The one statement of these words:
    /// the core's errors and the page's form (from the catalogue) say them.
    pub fn must_be(&self) -> Option<String> {
        let expected = match (self.min, self.max) {
            (Some(low), Some(high)) => format!("{low} to {high}"),
            (Some(low), None) => format!("{low} or more"),
            (None, Some(high)) => format!("{high} or less"),
            (None, None) => return None,
        };
        Some(format!("must be {expected}"))
    }

    /// [`IntegerRange::must_be`]'s words when number `value` is outside
    /// the range, None when it is inside: compared as a number, so that a
    /// value far out (1e20) is told its range, not that it is not a whole
    /// number.
    pub fn must_be_if_outside(&self, value: f64) -> Option<String> {
        let below = self.min.is_some_and(|low| value < low as f64);
        let above = self.max.is_some_and(|high| value > high as f64);
        if below || above { self.must_be() } else { None }
    }

    /// What `value` is told when it is outside the range ("must be 1 to 5,
    /// got 6"), None when it is inside.
    /// Taken as i128, so that any i64 or u64 is compared exactly.
    pub fn refusal(&self, value: i128) -> Option<String> {
        let below = self.min.is_some_and(|low| value < low as i128);
        let above = self.max.is_some_and(|high| value > high as i128);
        if below || above {
            self.must_be().map(|words| format!("{words}, got {value}"))
        } else {
            None
        }
    }
}

/// A whole-number input's range as the catalogue gives it (an integer
/// option's, a point's coordinates'): its bounds and the words for a value
/// outside them.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct IntegerRangeInfo {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub min: Option<i64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max: Option<i64>,
    /// What the core tells a value outside `min..=max`, before ", got" and
    /// the value ("must be 1 to 100000", "must be 0 or more"), so that the
    /// page's form, checking each field as it is typed, says what the core
    /// would; absent when neither bound is.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub must_be: Option<String>,
    /// What the core tells a value that is not whole, before ", got" and
    /// the value ("must be a whole number"), for the form as `must_be`.
    pub not_whole: String,
}

impl Serialize for IntegerRange {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        IntegerRangeInfo {
            min: self.min,
            max: self.max,
            must_be: self.must_be(),
            not_whole: self.not_whole(),
        }
        .serialize(s)
    }
}
