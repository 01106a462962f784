//! Arcs, circles and helices on the step grid: Saleem's integer circle
//! (`circle`), arcs split into chords (`arc-segments`) and Saleem's helix
//! (`helix`), in the planes G17, G18 and G19 and both directions.
//!
//! Every arc is given by absolute `from`, `to` and `center` points (3 axes;
//! a circle may be given in 2, x and y, and is then the xy plane's at
//! z = 0, its points in 2 axes), `dir` and `plane`. The radius is that of
//! the start point, r² = u² + v² relative to the center, an exact integer.
//! The end may be off that circle by at most [`RADIUS_TOLERANCE`] grid unit;
//! each algorithm says how it closes the difference.

pub mod angle;
pub mod arc_segments;
pub mod circle_saleem;
pub mod helix;
pub mod planes;

use crate::algorithm_info::AlgorithmInfo;
use crate::error::Error;
use crate::grid::{AXIS_NAMES, COORD_LIMIT, COORD_RANGE, Point};
use crate::ideal::curve::ArcPath;
use crate::range::{IntegerRange, WHOLE_NUMBER};
use crate::request::{OptionKind, OptionSpec, Request};
use angle::{atan3, degrees};
use planes::{DIR_VALUES, Frame, PLANE_VALUES, Plane, Turn, same_height};
use std::f64::consts::TAU;

/// Largest accepted |r_end - r_start|, grid units. A rounded end point is at
/// most sqrt(2)/2 off its circle, so one unit accepts every honest rounding
/// and refuses ends that belong to another circle.
pub const RADIUS_TOLERANCE: i64 = 1;

/// Largest accepted `turns`.
pub const MAX_TURNS: i64 = 1_000_000;

pub const CENTER: OptionSpec = OptionSpec {
    name: "center",
    kind: OptionKind::Point(COORD_RANGE),
    required: true,
    default: None,
    applies_with: None,
    doc: "Center of the circle, absolute grid units, as many axes as from; its coordinate on the plane's normal axis is ignored.",
};

pub const DIR: OptionSpec = OptionSpec {
    name: "dir",
    kind: OptionKind::Choice { values: DIR_VALUES },
    required: false,
    default: Some("ccw"),
    applies_with: None,
    doc: "cw = G02 (clockwise), ccw = G03 (counter-clockwise), seen from the positive end of the plane's normal axis.",
};

pub const PLANE: OptionSpec = OptionSpec {
    name: "plane",
    kind: OptionKind::Choice {
        values: PLANE_VALUES,
    },
    required: false,
    default: Some("xy"),
    applies_with: None,
    doc: "xy = G17, zx = G18 (z is the first axis, so the plane is right-handed), yz = G19; a circle given in x and y alone is in xy.",
};

/// The extra full turns an arc may take.
const TURNS_RANGE: IntegerRange = IntegerRange {
    min: Some(0),
    max: Some(MAX_TURNS),
    whole: WHOLE_NUMBER,
};

pub const TURNS: OptionSpec = OptionSpec {
    name: "turns",
    kind: OptionKind::Integer(TURNS_RANGE),
    required: false,
    default: Some("0"),
    applies_with: None,
    doc: "Extra full turns before stopping at the end (G-code P minus 1); from = to is already one full circle.",
};

/// A validated arc request.
#[derive(Clone, Debug)]
pub struct ArcSpec {
    /// The start, in 3 axes (at z = 0 for a circle given in 2: see
    /// [`Self::start_point`] for the start in the request's axes).
    pub from: Point,
    /// The end, in 3 axes.
    pub to: Point,
    pub plane: Plane,
    pub turn: Turn,
    pub turns: u64,
    /// Center, with the start's height on the normal axis.
    pub frame: Frame,
    /// r² of the start point, exact.
    pub radius_sq: i64,
    /// Start and end in the local counter-clockwise frame.
    pub start: [i64; 2],
    pub end: [i64; 2],
    /// `to - from` along the normal axis (0 for a planar arc).
    pub rise: i64,
}

impl ArcSpec {
    /// The arc `req` asks of the algorithm `info`, every option it gives
    /// checked to be one `info` takes first: what each arc algorithm's
    /// trace and plan read.
    pub fn of_request(
        req: &Request,
        info: &AlgorithmInfo,
        allow_rise: bool,
    ) -> Result<ArcSpec, Error> {
        req.check_options(info.options)?;
        ArcSpec::parse(req, allow_rise, info.min_dims)
    }

    /// Reads and checks the arc options. `allow_rise`: whether `to` may
    /// differ from `from` along the normal axis (a helix); `min_dims`: the
    /// fewest axes the algorithm takes (2: a circle may be given in x and y).
    pub fn parse(req: &Request, allow_rise: bool, min_dims: usize) -> Result<ArcSpec, Error> {
        let (from, to) = req.endpoints(min_dims, 3)?;
        let center = req.point("center")?;
        if center.dims() != from.dims() {
            return Err(Error::field(
                "center",
                format!(
                    "expected {} coordinates, as from has, got {}",
                    from.dims(),
                    center.dims()
                ),
            ));
        }
        let plane = Plane::parse(req.choice(&PLANE)?);
        let turn = Turn::parse(req.choice(&DIR)?);
        let turns = req.declared_integer(&TURNS)?.unwrap_or(0) as u64;
        ArcSpec::new(from, to, center, plane, turn, turns, allow_rise)
    }

    /// The arc from `from` to `to` about `center` (its coordinates on the
    /// plane's axes), all in 3 axes, or all in 2 for an arc in the xy plane
    /// at z = 0; checked as [`Self::parse`] checks a request's: for a
    /// caller with typed values (a G-code program's arcs), which has no
    /// request to read.
    pub fn new(
        from: Point,
        to: Point,
        center: Point,
        plane: Plane,
        turn: Turn,
        turns: u64,
        allow_rise: bool,
    ) -> Result<ArcSpec, Error> {
        if let Some(words) = TURNS_RANGE.refusal(turns.into()) {
            return Err(Error::field(TURNS.name, words));
        }
        // A circle given in x and y is the xy plane's at z = 0: it runs in
        // 3 axes like any other, and gives its points in 2 (Frame::point,
        // and the trace's start).
        let dims = from.dims();
        debug_assert!(to.dims() == dims && center.dims() == dims);
        if dims == 2 && plane != Plane::Xy {
            return Err(Error::field(
                PLANE.name,
                format!(
                    "from, to and center have 2 coordinates (x, y), so the arc is in the xy plane (G17), not {} ({}); give 3 coordinates for that plane",
                    plane.label(),
                    plane.gcode()
                ),
            ));
        }
        let (from, to, center) = (from.with_dims(3), to.with_dims(3), center.with_dims(3));
        if !allow_rise {
            same_height(plane, &from, &to)?;
        }
        let [u, v, n] = plane.axes();
        let mut c = [0; 3];
        c[u] = center.get(u);
        c[v] = center.get(v);
        c[n] = from.get(n);
        let frame = Frame {
            plane,
            turn,
            center: Point::new(&c),
            dims,
        };
        let start = frame.local(&from);
        let end = frame.local(&to);
        let start_sq = norm_sq(start);
        let end_sq = norm_sq(end);
        let (un, vn) = (AXIS_NAMES[u], AXIS_NAMES[v]);
        if start_sq == 0 {
            return Err(Error::field(
                "center",
                format!("is the start point in {un} and {vn}: the radius would be 0"),
            ));
        }
        if end_sq == 0 {
            return Err(Error::field(
                "to",
                format!("is the center in {un} and {vn}: an arc cannot end there"),
            ));
        }
        // Every point of the circle must be a valid input point, so that the
        // chords of arc-segments are valid lines and every coordinate fits
        // in i32 at the wasm boundary. The circle is stepped at the start's
        // radius r, and every cell of it, and every rounded chord vertex, is
        // within round(r) <= ceil(r) of the center on each axis (the
        // correction steps run between a circle point and `to`, both
        // valid): a circle that touches ±2^30 is allowed.
        let reach = ceil_sqrt(start_sq);
        for (axis, name) in [(u, un), (v, vn)] {
            let c = center.get(axis) as i128;
            if c.abs() + reach > COORD_LIMIT as i128 {
                return Err(Error::field(
                    "center",
                    format!(
                        "the circle of radius {:.3} around {name} = {c} reaches past ±2^30 ({COORD_LIMIT}) on {name}; every point of the circle must be within it",
                        (start_sq as f64).sqrt()
                    ),
                )
                .on_axis(axis));
            }
        }
        if !radii_within_tolerance(start_sq, end_sq) {
            let (rs, re) = ((start_sq as f64).sqrt(), (end_sq as f64).sqrt());
            return Err(Error::field(
                "to",
                format!(
                    "is {re:.3} from the center but from is {rs:.3}: the radii differ by {:.3}, more than {RADIUS_TOLERANCE} grid unit",
                    (re - rs).abs()
                ),
            ));
        }
        Ok(ArcSpec {
            from,
            to,
            plane,
            turn,
            turns,
            frame,
            radius_sq: start_sq as i64,
            start,
            end,
            rise: to.get(n) - from.get(n),
        })
    }

    /// The counter-clockwise angle from start to end in the local frame, in
    /// (0, 2π], plus the extra turns: start = end is a full circle, as in
    /// G-code. Computed as atan2(cross, dot) of the exact integer cross and
    /// dot products (as Grbl does), so the fix-up below tests exact signs.
    pub fn local_sweep_rad(&self) -> f64 {
        let (cross, dot) = cross_dot(self.start, self.end);
        let mut sweep = (cross as f64).atan2(dot as f64);
        // The end is behind the start or on its ray: the arc goes round.
        if cross < 0 || (cross == 0 && dot > 0) {
            sweep += TAU;
        }
        sweep + TAU * self.turns as f64
    }

    /// Signed sweep in the plane's right-handed frame: < 0 for G02.
    pub fn sweep_rad(&self) -> f64 {
        self.turn.sign() as f64 * self.local_sweep_rad()
    }

    /// Angle of the start point, [0, 2π), in the plane's frame.
    pub fn start_rad(&self) -> f64 {
        let [u, v, _] = self.plane.axes();
        let c = &self.frame.center;
        atan3(
            (self.from.get(v) - c.get(v)) as f64,
            (self.from.get(u) - c.get(u)) as f64,
        )
    }

    /// Axes of the arc's points: 3, or 2 for a circle given in x and y.
    pub fn dims(&self) -> usize {
        self.frame.dims
    }

    /// Where the arc starts, in its points' axes ([`Self::dims`]).
    pub fn start_point(&self) -> Point {
        self.from.with_dims(self.dims())
    }

    pub fn ideal_arc(&self) -> ArcPath {
        ArcPath::new(
            self.plane,
            self.frame.center.with_dims(self.dims()),
            self.radius_sq,
            self.start_rad(),
            self.sweep_rad(),
        )
    }

    pub fn radius(&self) -> f64 {
        (self.radius_sq as f64).sqrt()
    }

    /// One sentence about the arc for setup notes.
    pub fn describe(&self) -> String {
        let [u, v, _] = self.plane.axes();
        // (-20)², not -20², which reads as -400.
        let squared = |n: i64| {
            if n < 0 {
                format!("({n})²")
            } else {
                format!("{n}²")
            }
        };
        format!(
            "{} in the {}; center {}, r² = {} + {} = {} (r = {:.3}); sweep {:.1}°",
            self.turn.describe(),
            self.plane.describe(),
            self.frame.center.with_dims(self.dims()),
            squared(self.from.get(u) - self.frame.center.get(u)),
            squared(self.from.get(v) - self.frame.center.get(v)),
            self.radius_sq,
            self.radius(),
            degrees(self.sweep_rad()),
        )
    }
}

pub fn norm_sq([a, b]: [i64; 2]) -> i128 {
    a as i128 * a as i128 + b as i128 * b as i128
}

/// Cross and dot products of two local vectors, exact.
pub fn cross_dot(p: [i64; 2], q: [i64; 2]) -> (i128, i128) {
    let (p0, p1, q0, q1) = (p[0] as i128, p[1] as i128, q[0] as i128, q[1] as i128);
    (p0 * q1 - p1 * q0, p0 * q0 + p1 * q1)
}

/// The least s with s² >= n, for n >= 0.
pub(crate) fn ceil_sqrt(n: i128) -> i128 {
    let s = (n as u128).isqrt() as i128;
    if s * s == n { s } else { s + 1 }
}

/// |sqrt(a) - sqrt(b)| <= RADIUS_TOLERANCE for squared radii a and b,
/// exactly: sqrt(a) <= sqrt(b) + t holds iff a - b - t² <= 2 t sqrt(b),
/// i.e. the left side is negative or its square is at most 4 t² b.
pub fn radii_within_tolerance(a: i128, b: i128) -> bool {
    let t = RADIUS_TOLERANCE as i128;
    let below = |a: i128, b: i128| {
        let lhs = a - b - t * t;
        lhs <= 0 || lhs * lhs <= 4 * t * t * b
    };
    below(a, b) && below(b, a)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    fn spec(json: &str) -> Result<ArcSpec, Error> {
        ArcSpec::parse(&Request::from_json(json).unwrap(), false, 2)
    }

    #[test]
    fn sweeps_follow_gcode_directions() {
        let s = |from: &str, to: &str, dir: &str| {
            spec(&format!(
                r#"{{"algorithm":"circle","from":{from},"to":{to},"center":[0,0,0],"dir":"{dir}"}}"#
            ))
            .unwrap()
            .sweep_rad()
        };
        let close = |a: f64, b: f64| (a - b).abs() < 1e-12;
        assert!(close(s("[5,0,0]", "[0,5,0]", "ccw"), PI / 2.0));
        assert!(close(s("[5,0,0]", "[0,5,0]", "cw"), -1.5 * PI));
        assert!(close(s("[5,0,0]", "[-5,0,0]", "ccw"), PI));
        assert!(close(s("[5,0,0]", "[-5,0,0]", "cw"), -PI));
        assert!(close(s("[5,0,0]", "[5,0,0]", "ccw"), 2.0 * PI));
        assert!(close(s("[5,0,0]", "[5,0,0]", "cw"), -2.0 * PI));
        // The end one unit behind the start on a big circle: almost a full turn.
        let r = 1i64 << 20;
        let almost = s(&format!("[{r},0,0]"), &format!("[{r},-1,0]"), "ccw");
        assert!(almost > 2.0 * PI - 2.0 / r as f64 && almost < 2.0 * PI);
    }

    #[test]
    fn the_note_squares_a_negative_offset_in_parentheses() {
        let note = spec(r#"{"algorithm":"circle","from":[0,3,0],"to":[0,3,0],"center":[20,7,0]}"#)
            .unwrap()
            .describe();
        assert!(
            note.contains("r² = (-20)² + (-4)² = 416 (r = 20.396)"),
            "{note}"
        );
        let note = spec(r#"{"algorithm":"circle","from":[5,0,0],"to":[5,0,0],"center":[0,0,0]}"#)
            .unwrap()
            .describe();
        assert!(note.contains("r² = 5² + 0² = 25 (r = 5.000)"), "{note}");
    }

    #[test]
    fn bad_arcs_name_the_field() {
        let e = |json: &str| spec(json).unwrap_err().to_string();
        assert_eq!(
            e(r#"{"algorithm":"circle","from":[5,0,0],"to":[0,5,2],"center":[0,0,0]}"#),
            "to: z = 2 differs from from's z = 0: an arc in the xy plane (G17), seen from +z stays at one z; use the helix algorithm for a move that also travels along z"
        );
        assert_eq!(
            e(
                r#"{"algorithm":"circle","from":[5,0,0],"to":[0,2,5],"center":[0,0,0],"plane":"zx"}"#
            ),
            "to: y = 2 differs from from's y = 0: an arc in the zx plane (G18), seen from +y stays at one y; use the helix algorithm for a move that also travels along y"
        );
        assert_eq!(
            e(r#"{"algorithm":"circle","from":[5,0,0],"to":[0,5,0],"center":[5,0,9]}"#),
            "center: is the start point in x and y: the radius would be 0"
        );
        assert_eq!(
            e(r#"{"algorithm":"circle","from":[1,0,0],"to":[0,0,0],"center":[0,0,0]}"#),
            "to: is the center in x and y: an arc cannot end there"
        );
        assert_eq!(
            e(r#"{"algorithm":"circle","from":[5,0,0],"to":[0,7,0],"center":[0,0,0]}"#),
            "to: is 7.000 from the center but from is 5.000: the radii differ by 2.000, more than 1 grid unit"
        );
        assert_eq!(
            e(r#"{"algorithm":"circle","from":[5,0,0],"to":[0,5,0],"center":[0,0]}"#),
            "center: expected 3 coordinates, as from has, got 2"
        );
        assert_eq!(
            e(r#"{"algorithm":"circle","from":[5,0],"to":[0,5],"center":[0,0,0]}"#),
            "center: expected 2 coordinates, as from has, got 3"
        );
        assert_eq!(
            e(r#"{"algorithm":"circle","from":[5,0],"to":[0,5],"center":[0,0],"plane":"zx"}"#),
            "plane: from, to and center have 2 coordinates (x, y), so the arc is in the xy plane (G17), not zx (G18); give 3 coordinates for that plane"
        );
        assert_eq!(
            e(r#"{"algorithm":"circle","from":[5,0],"to":[0,5,0],"center":[0,0]}"#),
            "to: has 3 coordinates but from has 2"
        );
        assert_eq!(
            e(r#"{"algorithm":"circle","from":[5,0,0],"to":[0,5,0],"center":[0,"o",0]}"#),
            "center: y must be a number, got \"o\""
        );
        assert_eq!(
            e(r#"{"algorithm":"circle","from":[5,0,0],"to":[0,5,0],"center":[0,0,0],"turns":-1}"#),
            "turns: must be 0 to 1000000, got -1"
        );
        assert!(
            e(r#"{"algorithm":"circle","from":[1073741816,0,0],"to":[1073741816,0,0],"center":[1073741821,0,0]}"#)
                .starts_with("center: the circle of radius 5.000 around x = 1073741821 reaches past ±2^30")
        );
        // The axis it reaches past on is the error's too, as a point's is
        // (the page marks that coordinate): y here, then z in the zx plane.
        for (request, axis) in [
            (
                r#"{"algorithm":"circle","from":[0,1073741816,0],"to":[0,1073741816,0],"center":[0,1073741821,0]}"#,
                1,
            ),
            (
                r#"{"algorithm":"circle","from":[0,0,-1073741816],"to":[0,0,-1073741816],"center":[0,0,-1073741821],"plane":"zx"}"#,
                2,
            ),
        ] {
            let error = spec(request).expect_err(request);
            assert_eq!(
                (error.field_name(), error.axis),
                (Some("center"), Some(axis)),
                "{request}"
            );
        }
        // A circle that touches the limit is within it: r = 4 about
        // 2^30 - 4, and r = 2^30 about the origin (the largest there is).
        for (from, center) in [("1073741824,0", "1073741820,0"), ("0,-1073741824", "0,0")] {
            let request = format!(
                r#"{{"algorithm":"circle","from":[{from},0],"to":[{from},0],"center":[{center},0]}}"#
            );
            assert!(spec(&request).is_ok(), "{request}");
        }
    }

    #[test]
    fn the_center_s_normal_coordinate_is_ignored() {
        let a = spec(r#"{"algorithm":"circle","from":[5,0,3],"to":[0,5,3],"center":[0,0,-40]}"#)
            .unwrap();
        assert_eq!(a.frame.center, Point::new(&[0, 0, 3]));
        // In G19 (yz) the normal axis is x.
        let a = spec(
            r#"{"algorithm":"circle","from":[7,5,0],"to":[7,0,5],"center":[99,0,0],"plane":"yz"}"#,
        )
        .unwrap();
        assert_eq!(a.frame.center, Point::new(&[7, 0, 0]));
        assert_eq!((a.start, a.end), ([5, 0], [0, 5]));
    }

    #[test]
    fn radius_tolerance_is_exact_at_one_unit() {
        // r = 5 start; ends at distance exactly 6 and 4 pass, sqrt(37) and
        // sqrt(15) (just past 6 and just under 4) do not.
        assert!(radii_within_tolerance(36, 25) && radii_within_tolerance(16, 25));
        assert!(!radii_within_tolerance(37, 25) && !radii_within_tolerance(15, 25));
        // Large: r = 2^20 against 2^20 + 1 and 2^20 + 2.
        let r = 1i128 << 20;
        assert!(radii_within_tolerance((r + 1) * (r + 1), r * r));
        assert!(!radii_within_tolerance((r + 1) * (r + 1) + 1, r * r));
    }
}
