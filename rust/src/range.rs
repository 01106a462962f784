//! The range of a numeric input and the words a value outside it is told:
//! a whole-number input's `min..=max` ([`IntegerRange`]: integer options,
//! every coordinate of an input point) and a real number's bounds with its
//! unit ([`NumberRange`]: real options such as segmentLength, and machine
//! settings such as acceleration). Declared by the options, checked by the
//! core, and given by the catalogue to the page's form, which checks each
//! field as it is typed in the same words.

use crate::error::{Error, number_text};
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

/// The bounds of a real-number input (an option, or each axis of a machine
/// setting), in its unit: at least or more than `min`, at most `max`,
/// either absent, and whole when `whole` (microsteps). A value must also be
/// finite.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NumberRange {
    pub min: Option<f64>,
    /// Whether `min` itself is refused: "more than 0" rather than "0 or more".
    pub min_exclusive: bool,
    pub max: Option<f64>,
    /// The unit values are in ("mm/s²"), said after the bounds; "" for none.
    pub unit: &'static str,
    /// Whether only whole values are taken.
    pub whole: bool,
}

impl NumberRange {
    /// More than 0, in `unit`: a length, a rate, an acceleration.
    pub const fn positive(unit: &'static str) -> NumberRange {
        NumberRange {
            min: Some(0.0),
            min_exclusive: true,
            max: None,
            unit,
            whole: false,
        }
    }

    /// `min` or more, in `unit`.
    pub const fn at_least(min: f64, unit: &'static str) -> NumberRange {
        NumberRange {
            min: Some(min),
            min_exclusive: false,
            max: None,
            unit,
            whole: false,
        }
    }

    /// `min` to `max`, both taken, in `unit`.
    pub const fn between(min: f64, max: f64, unit: &'static str) -> NumberRange {
        NumberRange {
            min: Some(min),
            min_exclusive: false,
            max: Some(max),
            unit,
            whole: false,
        }
    }

    /// The same range, whole values only.
    pub const fn whole(self) -> NumberRange {
        NumberRange {
            whole: true,
            ..self
        }
    }

    /// What a value outside the range is told, before ", got" and the
    /// value: "must be more than 0 mm/s²", "must be 0 mm or more", "must be
    /// 0.001 to 1000000 steps per mm", "must be more than 0 and at most 360
    /// degrees"; None when neither bound is given. The one statement of
    /// these words: the core's errors and the page's form (from the
    /// catalogue) say them.
    pub fn must_be(&self) -> Option<String> {
        let unit = |text: String| {
            if self.unit.is_empty() {
                text
            } else {
                format!("{text} {}", self.unit)
            }
        };
        let expected = match (self.min, self.max) {
            (Some(low), Some(high)) if self.min_exclusive => unit(format!(
                "more than {} and at most {}",
                number_text(low),
                number_text(high)
            )),
            (Some(low), Some(high)) => {
                unit(format!("{} to {}", number_text(low), number_text(high)))
            }
            (Some(low), None) if self.min_exclusive => {
                unit(format!("more than {}", number_text(low)))
            }
            (Some(low), None) => format!("{} or more", unit(number_text(low))),
            (None, Some(high)) => format!("{} or less", unit(number_text(high))),
            (None, None) => return None,
        };
        Some(format!("must be {expected}"))
    }

    /// What `value` is told when the range refuses it ("must be more than 0
    /// mm/s², got 0"; "must be a whole number, got 2.5"), None when it takes
    /// it. Outside the range is said first, so that a value far out (1e20)
    /// is told its range, not that it is not whole; a value that is not
    /// finite is outside any range.
    pub fn refusal(&self, value: f64) -> Option<String> {
        let below = self
            .min
            .is_some_and(|low| value < low || (self.min_exclusive && value == low));
        let above = self.max.is_some_and(|high| value > high);
        let got = number_text(value);
        if below || above || !value.is_finite() {
            let words = self
                .must_be()
                .unwrap_or_else(|| "must be a finite number".to_string());
            return Some(format!("{words}, got {got}"));
        }
        (self.whole && value.fract() != 0.0).then(|| format!("must be {WHOLE_NUMBER}, got {got}"))
    }

    /// `value` when the range takes it, else the error naming `field`
    /// with [`NumberRange::refusal`]'s words.
    pub fn check(&self, field: &str, value: f64) -> Result<f64, Error> {
        match self.refusal(value) {
            Some(words) => Err(Error::field(field, words)),
            None => Ok(value),
        }
    }
}

/// A real-number input's range as the catalogue gives it: its bounds and
/// the words for a value outside them, so that the page's form refuses, as
/// each field is typed, what the core would, in the core's words.
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct NumberRangeInfo {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub min: Option<f64>,
    /// Whether `min` itself is refused ("more than 0").
    pub min_exclusive: bool,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max: Option<f64>,
    /// The unit values are in ("mm/s²"; "" for none).
    pub unit: &'static str,
    /// What the core tells a value outside the range, before ", got" and
    /// the value ("must be more than 0 mm/s²"); absent when neither bound is.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub must_be: Option<String>,
    /// What the core tells a value that is not whole, before ", got" and
    /// the value ("must be a whole number"); absent when any value is taken.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub not_whole: Option<String>,
}

impl NumberRange {
    /// This range as the catalogue gives it.
    pub fn info(&self) -> NumberRangeInfo {
        NumberRangeInfo {
            min: self.min,
            min_exclusive: self.min_exclusive,
            max: self.max,
            unit: self.unit,
            must_be: self.must_be(),
            not_whole: self.whole.then(|| format!("must be {WHOLE_NUMBER}")),
        }
    }
}

impl Serialize for NumberRange {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.info().serialize(s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn number_ranges_say_their_bounds_in_their_unit() {
        let cases = [
            (NumberRange::positive("mm/s²"), "must be more than 0 mm/s²"),
            (NumberRange::at_least(0.0, "mm"), "must be 0 mm or more"),
            (NumberRange::at_least(1.0, "").whole(), "must be 1 or more"),
            (
                NumberRange::between(0.001, 1e6, "steps per mm"),
                "must be 0.001 to 1000000 steps per mm",
            ),
            (
                NumberRange {
                    max: Some(360.0),
                    ..NumberRange::positive("degrees")
                },
                "must be more than 0 and at most 360 degrees",
            ),
        ];
        for (range, words) in cases {
            assert_eq!(range.must_be().as_deref(), Some(words));
        }
    }

    #[test]
    fn number_ranges_refuse_what_is_outside_or_not_whole() {
        let positive = NumberRange::positive("mm");
        assert_eq!(positive.refusal(1e-300), None);
        assert_eq!(
            positive.refusal(0.0).as_deref(),
            Some("must be more than 0 mm, got 0")
        );
        assert_eq!(
            positive.refusal(-1e-300).as_deref(),
            Some("must be more than 0 mm, got -1e-300")
        );
        assert_eq!(
            positive.refusal(f64::INFINITY).as_deref(),
            Some("must be more than 0 mm, got Infinity")
        );
        let at_least = NumberRange::at_least(0.0, "mm");
        assert_eq!(at_least.refusal(0.0), None);
        let between = NumberRange::between(0.001, 1e6, "steps per mm");
        assert_eq!(between.refusal(1e6), None);
        assert!(between.refusal(1e6 + 1.0).is_some());
        let whole = NumberRange::at_least(1.0, "").whole();
        assert_eq!(
            whole.refusal(2.5).as_deref(),
            Some("must be a whole number, got 2.5")
        );
        // Out of range is said before not whole.
        assert_eq!(
            whole.refusal(0.5).as_deref(),
            Some("must be 1 or more, got 0.5")
        );
        assert_eq!(whole.refusal(3.0), None);
    }
}
