//! Angles of arcs: sin and cos of many turns, the angle of a direction, and
//! degrees for notes. Shared by the arc algorithms, the ideal curves they
//! approximate and the planner's chords.

use std::f64::consts::{PI, TAU};

/// sin and cos of an angle of any number of turns, reduced into [0, 2π)
/// first. In wasm, Rust's sin and cos (libm) reduce an argument past about
/// 2^20 π/2 rad through their slow multi-word path, so a helix of hundreds
/// of thousands of turns took ten times longer per point than one of fewer
/// (400,000 turns: 13.7 s for 1.6M steps, against 1.4 s for half of them).
/// Reducing by TAU, which is 2π rounded, moves the angle by k × 2.4e-16 rad
/// after k turns: 2.4e-10 rad after a million, under the spacing of f64
/// values near the angle itself (9.3e-10 at 2π × 10^6). Angles under
/// [`REDUCE_PAST_RAD`] go to sin_cos as they are: below libm's slow path,
/// and spared the cost of the remainder.
pub fn sin_cos_turns(theta: f64) -> (f64, f64) {
    if theta.abs() < REDUCE_PAST_RAD {
        theta.sin_cos()
    } else {
        theta.rem_euclid(TAU).sin_cos()
    }
}

/// Angles from here on are reduced by [`sin_cos_turns`] (2^16 rad, about
/// 10,430 turns: well under libm's 2^20 π/2).
const REDUCE_PAST_RAD: f64 = 65536.0;

/// Angle in [0, 2π) of direction (u, v): the blog's `atan3`.
pub fn atan3(v: f64, u: f64) -> f64 {
    let a = v.atan2(u);
    if a < 0.0 { a + TAU } else { a }
}

/// Degrees, for notes.
pub fn degrees(rad: f64) -> f64 {
    rad * 180.0 / PI
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Past REDUCE_PAST_RAD the angle is reduced first: sin and cos agree
    /// with the unreduced ones to the spacing of f64 near the angle (times
    /// a few roundings), a million turns out included.
    #[test]
    fn sin_cos_of_many_turns_agree_with_the_unreduced_angle() {
        for theta in [
            1.0,
            65535.9,
            65536.0,
            1e5 + 0.3,
            -2e6 - 0.7,
            TAU * 1e6 + 1.0,
            7e7,
        ] {
            let (s, c) = sin_cos_turns(theta);
            let (s0, c0) = f64::sin_cos(theta);
            // ulp of theta, and the TAU rounding: k × 2.45e-16.
            let tolerance =
                4.0 * (theta.abs() * f64::EPSILON + theta.abs() / TAU * 2.5e-16) + 1e-15;
            assert!(
                (s - s0).abs() <= tolerance && (c - c0).abs() <= tolerance,
                "{theta}: {s} {s0} {c} {c0}"
            );
        }
    }

    #[test]
    fn atan3_is_in_zero_to_two_pi() {
        assert_eq!(atan3(0.0, 1.0), 0.0);
        assert!((atan3(-1.0, 0.0) - 1.5 * PI).abs() < 1e-15);
        assert!((atan3(-1e-9, 1.0) - TAU).abs() < 1e-8);
    }
}
