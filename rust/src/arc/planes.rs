//! Arc planes and directions in G-code's right-handed convention, and the
//! local frame every arc algorithm works in.
//!
//! A plane has two in-plane axes (u, v) and a normal axis n with u × v = n:
//! G17 = (x, y; z), G18 = (z, x; y), G19 = (y, z; x). G18 lists z before x
//! so that (z, x, y) is right-handed like (x, y, z): then G03 is always
//! counter-clockwise (increasing angle atan2(v, u)) and G02 clockwise, seen
//! from the positive end of the normal axis, in all three planes.
//!
//! The algorithms are written for counter-clockwise travel only, as Saleem's
//! pseudo-code is. A clockwise arc is run as the counter-clockwise arc of its
//! mirror image (v -> -v): the local frame is (a, b) = (u - u_c, s (v - v_c))
//! with s = +1 for G03 and -1 for G02. Mirroring maps grid points to grid
//! points and keeps x² + y² - r², so every decision is the same integer
//! comparison in both directions.

use crate::error::Error;
use crate::grid::{AXIS_NAMES, MAX_AXES, Point, Step};

/// The plane of an arc (G17, G18, G19).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Plane {
    Xy,
    Zx,
    Yz,
}

pub const PLANE_VALUES: &[&str] = &["xy", "zx", "yz"];

impl Plane {
    pub fn parse(value: Option<&str>) -> Plane {
        match value {
            Some("zx") => Plane::Zx,
            Some("yz") => Plane::Yz,
            _ => Plane::Xy,
        }
    }

    /// Axis indices (u, v, n): first in-plane axis, second, normal.
    pub fn axes(self) -> [usize; 3] {
        match self {
            Plane::Xy => [0, 1, 2],
            Plane::Zx => [2, 0, 1],
            Plane::Yz => [1, 2, 0],
        }
    }

    pub fn normal(self) -> usize {
        self.axes()[2]
    }

    pub fn label(self) -> &'static str {
        match self {
            Plane::Xy => "xy",
            Plane::Zx => "zx",
            Plane::Yz => "yz",
        }
    }

    pub fn gcode(self) -> &'static str {
        match self {
            Plane::Xy => "G17",
            Plane::Zx => "G18",
            Plane::Yz => "G19",
        }
    }

    /// "xy plane (G17), seen from +z".
    pub fn describe(self) -> String {
        format!(
            "{} plane ({}), seen from +{}",
            self.label(),
            self.gcode(),
            AXIS_NAMES[self.normal()]
        )
    }
}

/// Direction of travel around the center.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Turn {
    /// G02: decreasing angle, seen from the positive end of the normal axis.
    Clockwise,
    /// G03: increasing angle.
    CounterClockwise,
}

pub const DIR_VALUES: &[&str] = &["cw", "ccw"];

impl Turn {
    pub fn parse(value: Option<&str>) -> Turn {
        match value {
            Some("cw") => Turn::Clockwise,
            _ => Turn::CounterClockwise,
        }
    }

    /// +1 for counter-clockwise, -1 for clockwise: the sign of the sweep and
    /// the mirror factor of the local frame.
    pub fn sign(self) -> i64 {
        match self {
            Turn::Clockwise => -1,
            Turn::CounterClockwise => 1,
        }
    }

    pub fn describe(self) -> &'static str {
        match self {
            Turn::Clockwise => "G02, clockwise",
            Turn::CounterClockwise => "G03, counter-clockwise",
        }
    }
}

/// Grid coordinates relative to the center, mirrored so that travel is
/// counter-clockwise: (a, b) = (u - u_c, s (v - v_c)).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Frame {
    pub plane: Plane,
    pub turn: Turn,
    /// The center, in 3 axes; its normal coordinate is the height of the
    /// arc's start.
    pub center: Point,
    /// Axes of the grid points [`Frame::point`] gives: 3, or 2 for a circle
    /// given in x and y (the xy plane at z = 0).
    pub dims: usize,
}

impl Frame {
    /// Local counter-clockwise coordinates of a grid point.
    pub fn local(&self, p: &Point) -> [i64; 2] {
        let [u, v, _] = self.plane.axes();
        [
            p.get(u) - self.center.get(u),
            self.turn.sign() * (p.get(v) - self.center.get(v)),
        ]
    }

    /// The grid point at local coordinates `ab` and height `n` on the normal axis.
    pub fn point(&self, ab: [i64; 2], n: i64) -> Point {
        let [u, v, normal] = self.plane.axes();
        let mut c = [0; 3];
        c[u] = self.center.get(u) + ab[0];
        c[v] = self.center.get(v) + self.turn.sign() * ab[1];
        c[normal] = n;
        Point::new(&c[..self.dims])
    }

    /// The grid step for a local move (da, db).
    pub fn step(&self, delta: [i64; 2]) -> Step {
        let [u, v, _] = self.plane.axes();
        Step::along(u, delta[0]).with(v, self.turn.sign() * delta[1])
    }

    /// The grid displacement of a local move by `delta` (any length).
    pub fn displacement(&self, delta: [i64; 2]) -> [i64; MAX_AXES] {
        let [u, v, _] = self.plane.axes();
        let mut d = [0; MAX_AXES];
        d[u] = delta[0];
        d[v] = self.turn.sign() * delta[1];
        d
    }

    /// The frame without its center.
    pub fn orientation(&self) -> Orientation {
        Orientation {
            plane: self.plane,
            turn: self.turn,
        }
    }
}

/// How local axes map to grid axes: a [`Frame`] without its center, two
/// bytes, small enough to travel with every step's decision (a decision
/// that carried the whole frame would copy its 56-byte center every step).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Orientation {
    pub plane: Plane,
    pub turn: Turn,
}

impl Orientation {
    /// The grid axis of local axis 0 (a) or 1 (b).
    pub fn axis(&self, local: usize) -> usize {
        self.plane.axes()[local]
    }

    /// Direction on the grid axis of a local move along `local` by `d`.
    pub fn grid_direction(&self, local: usize, d: i64) -> i64 {
        if local == 1 { self.turn.sign() * d } else { d }
    }

    /// Octant 1-8 of local octant `k` as seen in the plane's own
    /// (right-handed, counter-clockwise) numbering: a mirror image reverses it.
    pub fn grid_octant(&self, k: u8) -> u8 {
        match self.turn {
            Turn::CounterClockwise => k,
            Turn::Clockwise => 9 - k,
        }
    }
}

/// What one octant of counter-clockwise travel does (Saleem section 4,
/// Figure 1: octants counted counter-clockwise from the positive first axis).
#[derive(Debug, PartialEq, Eq)]
pub struct OctantRule {
    /// Local axis (0 = a, 1 = b) that steps every time.
    pub fast: usize,
    pub fast_dir: i64,
    /// Local axis that steps when eq. (7) says the moved candidate is closer.
    pub slow: usize,
    pub slow_dir: i64,
    pub teaching: &'static str,
}

impl OctantRule {
    /// The fast axis's unit move as a local vector, formed per component:
    /// an update through a run-time index would make the next read of the
    /// point wait for the store (a measured stall in the circle's loop).
    pub fn fast_move(&self) -> [i64; 2] {
        unit_move(self.fast, self.fast_dir)
    }

    /// The slow axis's unit move as a local vector.
    pub fn slow_move(&self) -> [i64; 2] {
        unit_move(self.slow, self.slow_dir)
    }
}

fn unit_move(local: usize, dir: i64) -> [i64; 2] {
    [dir * (local == 0) as i64, dir * (local == 1) as i64]
}

/// Index k - 1 for octant k, in the counter-clockwise local frame.
pub const OCTANTS: [OctantRule; 8] = [
    OctantRule {
        fast: 1,
        fast_dir: 1,
        slow: 0,
        slow_dir: -1,
        teaching: "Octant 1 (0°-45°): the circle rises faster than it moves inward, so y steps +1 every time and eq. (10) decides whether x steps -1.",
    },
    OctantRule {
        fast: 0,
        fast_dir: -1,
        slow: 1,
        slow_dir: 1,
        teaching: "Octant 2 (45°-90°): the circle moves left faster than it rises, so x steps -1 every time and eq. (11) decides whether y steps +1.",
    },
    OctantRule {
        fast: 0,
        fast_dir: -1,
        slow: 1,
        slow_dir: -1,
        teaching: "Octant 3 (90°-135°): x steps -1 every time and eq. (11) decides whether y steps -1.",
    },
    OctantRule {
        fast: 1,
        fast_dir: -1,
        slow: 0,
        slow_dir: -1,
        teaching: "Octant 4 (135°-180°): y steps -1 every time and eq. (10) decides whether x steps -1.",
    },
    OctantRule {
        fast: 1,
        fast_dir: -1,
        slow: 0,
        slow_dir: 1,
        teaching: "Octant 5 (180°-225°): y steps -1 every time and eq. (10) decides whether x steps +1.",
    },
    OctantRule {
        fast: 0,
        fast_dir: 1,
        slow: 1,
        slow_dir: -1,
        teaching: "Octant 6 (225°-270°): x steps +1 every time and eq. (11) decides whether y steps -1.",
    },
    OctantRule {
        fast: 0,
        fast_dir: 1,
        slow: 1,
        slow_dir: 1,
        teaching: "Octant 7 (270°-315°): x steps +1 every time and eq. (11) decides whether y steps +1.",
    },
    OctantRule {
        fast: 1,
        fast_dir: 1,
        slow: 0,
        slow_dir: 1,
        teaching: "Octant 8 (315°-360°): y steps +1 every time and eq. (10) decides whether x steps +1.",
    },
];

/// The octant (1-8) counter-clockwise travel from local point (a, b) moves
/// through: octant k holds the angles [45°(k-1), 45° k), so a point on a
/// boundary belongs to the octant ahead of it. None at the center.
///
/// This replaces the paper's `if(|x| > |y|) ... if(|x| < |y|)`, which does
/// nothing on the diagonals |x| = |y|: there the octant ahead decides.
pub fn octant_ahead(p: [i64; 2]) -> Option<u8> {
    (1..=8).find(|&k| in_octant(k, p))
}

/// True when octant `k` (1-8) is the one ahead of local point (a, b)
/// ([`octant_ahead`]). No point is in two octants (the conditions exclude
/// each other), so a loop that knows its octant tests only its own
/// condition: two comparisons when `k` is a constant.
#[inline(always)]
pub fn in_octant(k: u8, [a, b]: [i64; 2]) -> bool {
    match k {
        1 => b >= 0 && a > b,
        2 => a > 0 && b >= a,
        3 => a <= 0 && b > -a,
        4 => b > 0 && -a >= b,
        5 => b <= 0 && a < b,
        6 => a < 0 && b <= a,
        7 => a >= 0 && -b > a,
        8 => b < 0 && a >= -b,
        _ => false,
    }
}

/// Checks that `from` and `to` lie in one plane parallel to `plane`.
pub fn same_height(plane: Plane, from: &Point, to: &Point) -> Result<(), Error> {
    let n = plane.normal();
    if from.get(n) != to.get(n) {
        let name = AXIS_NAMES[n];
        return Err(Error::field(
            "to",
            format!(
                "{name} = {} differs from from's {name} = {}: an arc in the {} stays at one {name}; use the helix algorithm for a move that also travels along {name}",
                to.get(n),
                from.get(n),
                plane.describe()
            ),
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn planes_are_right_handed() {
        // u × v = n for each plane: the cyclic order (0, 1, 2) -> (1, 2, 0) -> (2, 0, 1).
        for plane in [Plane::Xy, Plane::Zx, Plane::Yz] {
            let [u, v, n] = plane.axes();
            assert_eq!((u + 1) % 3, v, "{plane:?}");
            assert_eq!((v + 1) % 3, n, "{plane:?}");
        }
    }

    #[test]
    fn every_point_but_the_center_has_one_octant_ahead() {
        // Boundaries belong to the octant ahead (counter-clockwise).
        let cases = [
            ([5, 0], 1),
            ([5, 4], 1),
            ([3, 3], 2),
            ([0, 5], 3),
            ([-3, 3], 4),
            ([-5, 0], 5),
            ([-3, -3], 6),
            ([0, -5], 7),
            ([3, -3], 8),
            ([5, -1], 8),
        ];
        for (p, k) in cases {
            assert_eq!(octant_ahead(p), Some(k), "{p:?}");
        }
        assert_eq!(octant_ahead([0, 0]), None);
        // No point is in two octants, so a loop that knows its octant may
        // test its condition alone.
        for a in -6i64..=6 {
            for b in -6i64..=6 {
                let inside = (1..=8).filter(|&k| in_octant(k, [a, b])).count();
                assert_eq!(inside, usize::from([a, b] != [0, 0]), "({a}, {b})");
            }
        }
        // Each octant's fast axis moves along the tangent (-b, a) in the
        // rule's direction at a point inside the octant.
        for a in -6i64..=6 {
            for b in -6i64..=6 {
                let Some(k) = octant_ahead([a, b]) else {
                    continue;
                };
                let rule = &OCTANTS[k as usize - 1];
                let tangent = [-b, a];
                assert!(
                    tangent[rule.fast].abs() >= tangent[rule.slow].abs(),
                    "({a}, {b}) in octant {k}"
                );
                assert!(tangent[rule.fast] * rule.fast_dir > 0, "({a}, {b})");
                assert!(tangent[rule.slow] * rule.slow_dir >= 0, "({a}, {b})");
            }
        }
    }

    #[test]
    fn clockwise_is_the_mirror_image() {
        let center = Point::new(&[10, -3, 7]);
        for plane in [Plane::Xy, Plane::Zx, Plane::Yz] {
            let cw = Frame {
                plane,
                turn: Turn::Clockwise,
                center,
                dims: 3,
            };
            let p = Point::new(&[13, -1, 9]);
            let ab = cw.local(&p);
            assert_eq!(cw.point(ab, p.get(plane.normal())), p);
            let mut q = p;
            q.apply(cw.step([1, 1]));
            let moved = cw.local(&q);
            assert_eq!(moved, [ab[0] + 1, ab[1] + 1], "{plane:?}");
        }
    }
}
