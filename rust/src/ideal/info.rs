//! What a viewer is told of an ideal path (grid units): the type that crosses
//! the boundary in each segment's summary. A leaf, so that the files that
//! measure each kind of path can describe themselves without importing the
//! dispatch in `ideal` that imports them.

use serde::Serialize;
use tsify::Tsify;

/// How the ideal path is described to a viewer (grid units).
#[derive(Serialize, Tsify, Debug, Clone, PartialEq)]
#[serde(tag = "kind", rename_all = "camelCase")]
pub enum IdealPathInfo {
    Line {
        from: Vec<i64>,
        to: Vec<i64>,
    },
    /// Angles in radians, atan2(v, u) in the plane's right-handed frame;
    /// sweep > 0 is counter-clockwise (G03).
    #[serde(rename_all = "camelCase")]
    Arc {
        center: Vec<i64>,
        plane: &'static str,
        radius: f64,
        start_rad: f64,
        sweep_rad: f64,
    },
    /// As Arc, plus the height on the normal axis: start_height + rise * t
    /// at fraction t of the sweep.
    #[serde(rename_all = "camelCase")]
    Helix {
        center: Vec<i64>,
        plane: &'static str,
        radius: f64,
        start_rad: f64,
        sweep_rad: f64,
        start_height: f64,
        rise: f64,
    },
}
