//! The ideal (continuous) path a step sequence approximates, and the distance
//! of a grid point from it: the one interface a trace measures through.
//! Each kind of path is measured in a file of its own ([`line`], [`curve`]);
//! what a viewer is told of a path is the leaf [`info`], which those files
//! build without importing this dispatch.

pub mod curve;
pub mod info;
pub mod line;

use crate::grid::{MAX_AXES, Point};
use curve::{ArcMeter, ArcPath, HelixMeter, HelixPath};
use info::IdealPathInfo;
use line::LineMeter;

/// The path the steps approximate. Deviation is measured against it.
#[derive(Clone, Debug, PartialEq)]
pub enum IdealPath {
    /// The straight segment between two grid points.
    Line { from: Point, to: Point },
    /// A circular arc (see [`curve`]): deviation is the radial error.
    Arc(ArcPath),
    /// A helix: deviation is the distance to its nearest point.
    Helix(HelixPath),
}

impl IdealPath {
    pub fn info(&self) -> IdealPathInfo {
        match self {
            IdealPath::Line { from, to } => IdealPathInfo::Line {
                from: from.coords().to_vec(),
                to: to.coords().to_vec(),
            },
            IdealPath::Arc(arc) => arc.info(),
            IdealPath::Helix(helix) => helix.info(),
        }
    }

    /// This path ready to measure many points: its per-path constants
    /// (direction, squared length, radius, a helix's ends) computed once. Build one per
    /// segment, not per point.
    pub fn meter(&self) -> Meter<'_> {
        match self {
            IdealPath::Line { from, to } => Meter::Line(LineMeter::new(from, to)),
            IdealPath::Arc(arc) => Meter::Arc(arc.meter()),
            IdealPath::Helix(helix) => Meter::Helix(helix.meter()),
        }
    }

    /// Perpendicular distance from `p` to the ideal path, in grid units
    /// (the Error column of Wang's Tables 1 and 2). See [`Meter::deviation`].
    pub fn deviation(&self, p: &Point) -> f64 {
        self.meter().deviation(p)
    }

    /// Per-axis error of `p` against the ideal position after `step` of
    /// `steps` equal parts of the path (Wang eq. 11). See [`Meter::axis_error`].
    pub fn axis_error(&self, p: &Point, step: u64, steps: u64) -> [f64; MAX_AXES] {
        self.meter().axis_error(p, step, steps)
    }

    /// Points along the ideal path for drawing (`dims` values each: 3 for
    /// a helix, as many as its center has for an arc), each handed to `f`
    /// in order, the first left out where it equals `after` (where the
    /// path before ended).
    pub fn for_each_vertex(&self, after: Option<&[f64]>, mut f: impl FnMut(&[f64])) {
        match self {
            IdealPath::Line { from, to } => {
                let dims = from.dims();
                let from = as_f64(from);
                if after != Some(&from[..dims]) {
                    f(&from[..dims]);
                }
                f(&as_f64(to)[..dims]);
            }
            IdealPath::Arc(arc) => arc.for_each_vertex(after, f),
            IdealPath::Helix(helix) => helix.for_each_vertex(after, f),
        }
    }

    /// [`Self::for_each_vertex`] appended to `out`, flat (a whole path's
    /// polyline is one array), the first left out where `out` already ends
    /// on it.
    pub fn polyline_into(&self, out: &mut Vec<f64>) {
        let dims = match self {
            IdealPath::Line { from, .. } => from.dims(),
            IdealPath::Arc(arc) => arc.center.dims(),
            IdealPath::Helix(_) => 3,
        };
        let after: Option<[f64; MAX_AXES]> = out
            .len()
            .checked_sub(dims)
            .map(|start| std::array::from_fn(|axis| out.get(start + axis).copied().unwrap_or(0.0)));
        self.for_each_vertex(after.as_ref().map(|a| &a[..dims]), |vertex| {
            out.extend_from_slice(vertex)
        });
    }
}

/// A point's coordinates as f64, in an array as long as any point's (the
/// first `dims` of them its own): a value, not a vector per vertex.
fn as_f64(p: &Point) -> [f64; MAX_AXES] {
    let mut vertex = [0.0; MAX_AXES];
    for (v, &c) in vertex.iter_mut().zip(p.coords()) {
        *v = c as f64;
    }
    vertex
}

/// An ideal path with its per-path constants computed, measuring points.
pub enum Meter<'a> {
    Line(LineMeter),
    Arc(ArcMeter<'a>),
    Helix(HelixMeter<'a>),
}

impl Meter<'_> {
    /// Perpendicular distance from `p` to the ideal path, in grid units.
    /// Arcs: the distance to the circle; helices: to the nearest point.
    pub fn deviation(&self, p: &Point) -> f64 {
        match self {
            Meter::Line(line) => line.deviation(p),
            Meter::Arc(arc) => arc.deviation(p),
            Meter::Helix(helix) => helix.deviation(p),
        }
    }

    /// Per-axis error of `p` against the ideal position after `step` of
    /// `steps` equal parts of the path (Wang eq. 11: phi_x, phi_y, phi_z).
    /// For a line whose active axis steps every time this is 0 on that axis.
    /// For arcs and helices progress is the point's own angle ([`curve`]).
    pub fn axis_error(&self, p: &Point, step: u64, steps: u64) -> [f64; MAX_AXES] {
        match self {
            Meter::Line(line) => line.axis_error(p, step, steps),
            Meter::Arc(arc) => arc.axis_error(p),
            Meter::Helix(helix) => helix.axis_error(p),
        }
    }
}
