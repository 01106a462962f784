//! The ideal (continuous) path a step sequence approximates, and the distance
//! of a grid point from it.

use crate::arc::curve::{ArcPath, HelixPath};
use crate::grid::{MAX_AXES, Point};
use serde::Serialize;

/// The path the steps approximate. Deviation is measured against it.
#[derive(Clone, Debug, PartialEq)]
pub enum IdealPath {
    /// The straight segment between two grid points.
    Line { from: Point, to: Point },
    /// A circular arc (see `arc::curve`): deviation is the radial error.
    Arc(ArcPath),
    /// A helix: deviation is the distance to its nearest point.
    Helix(HelixPath),
}

/// How the ideal path is described to a viewer (grid units).
#[derive(Serialize, Debug, Clone, PartialEq)]
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

    /// Perpendicular distance from `p` to the ideal path, in grid units
    /// (the Error column of Wang's Tables 1 and 2).
    ///
    /// For a line through `from` with direction `d`, with `r = p - from`,
    /// Lagrange's identity gives |r|^2 |d|^2 - (r.d)^2 = sum over axis pairs
    /// (r_i d_j - r_j d_i)^2, a sum of squares with no cancellation. Each term
    /// is formed exactly in i128 and only then rounded to f64.
    pub fn deviation(&self, p: &Point) -> f64 {
        match self {
            IdealPath::Line { from, to } => {
                let d = from.delta_to(to);
                let r = from.delta_to(p);
                let dims = p.dims();
                let d_norm2: f64 = d[..dims].iter().map(|&v| (v as f64) * (v as f64)).sum();
                if d_norm2 == 0.0 {
                    return r[..dims]
                        .iter()
                        .map(|&v| (v as f64) * (v as f64))
                        .sum::<f64>()
                        .sqrt();
                }
                let mut cross_norm2 = 0.0;
                for i in 0..dims {
                    for j in i + 1..dims {
                        let c = r[i] as i128 * d[j] as i128 - r[j] as i128 * d[i] as i128;
                        let c = c as f64;
                        cross_norm2 += c * c;
                    }
                }
                (cross_norm2 / d_norm2).sqrt()
            }
            IdealPath::Arc(arc) => arc.deviation(p),
            IdealPath::Helix(helix) => helix.deviation(p),
        }
    }

    /// Per-axis error of `p` against the ideal position after `step` of
    /// `steps` equal parts of the path (Wang eq. 11: phi_x, phi_y, phi_z).
    /// For a line whose active axis steps every time this is 0 on that axis.
    /// For arcs and helices progress is the point's own angle (`arc::curve`).
    pub fn axis_error(&self, p: &Point, step: u64, steps: u64) -> [f64; MAX_AXES] {
        let mut phi = [0.0; MAX_AXES];
        match self {
            IdealPath::Arc(arc) => return arc.axis_error(p),
            IdealPath::Helix(helix) => return helix.axis_error(p),
            IdealPath::Line { from, to } => {
                let d = from.delta_to(to);
                let r = from.delta_to(p);
                for axis in 0..p.dims() {
                    phi[axis] = if steps == 0 {
                        r[axis] as f64
                    } else {
                        // (r * n - d * i) / n, exact until the final division.
                        let num = r[axis] as i128 * steps as i128 - d[axis] as i128 * step as i128;
                        num as f64 / steps as f64
                    };
                }
            }
        }
        phi
    }

    /// Points along the ideal path for drawing, flat with stride `dims`.
    pub fn polyline(&self) -> Vec<f64> {
        match self {
            IdealPath::Line { from, to } => from
                .coords()
                .iter()
                .chain(to.coords())
                .map(|&c| c as f64)
                .collect(),
            IdealPath::Arc(arc) => arc.polyline(),
            IdealPath::Helix(helix) => helix.polyline(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line(from: &[i64], to: &[i64]) -> IdealPath {
        IdealPath::Line {
            from: Point::new(from),
            to: Point::new(to),
        }
    }

    #[test]
    fn deviation_matches_wang_table_1_error_column() {
        // Wang 2020, Table 1 (Liu's points for (0,0,0)->(10,7,6)), last column.
        // Table 1 prints 0.225064 for (7,5,4); the distance is 0.220564 (the
        // digits transposed), as Table 2 prints beside step 7 and as the
        // point (3,2,2), the mirror image of (7,5,4) about the line's middle, has.
        let l = line(&[0, 0, 0], &[10, 7, 6]);
        for (p, err) in [
            ([1, 1, 1], 0.374887),
            ([2, 1, 1], 0.336918),
            ([3, 2, 2], 0.220564),
            ([4, 3, 2], 0.441129),
            ([5, 4, 3], 0.428700),
            ([6, 4, 4], 0.441129),
            ([7, 5, 4], 0.220564),
            ([8, 6, 5], 0.336918),
            ([9, 6, 5], 0.374887),
            ([10, 7, 6], 0.0),
        ] {
            assert!((l.deviation(&Point::new(&p)) - err).abs() < 1e-6, "{p:?}");
        }
    }

    #[test]
    fn deviation_is_exact_far_from_the_origin() {
        // A point half a unit off a line spanning the whole +-2^30 range.
        let big = 1i64 << 30;
        let l = line(&[-big, -big], &[big, -big]);
        let p = Point::new(&[12345, -big + 1]);
        assert_eq!(l.deviation(&p), 1.0);
        let l = line(&[-big, -big, -big], &[big, big, big]);
        let p = Point::new(&[big - 1, big - 1, big]);
        // r = (2^31-1, 2^31-1, 2^31), d = 2^31 (1,1,1): distance sqrt(2/3).
        assert!((l.deviation(&p) - (2.0f64 / 3.0).sqrt()).abs() < 1e-12);
    }

    #[test]
    fn axis_error_is_zero_on_the_active_axis() {
        let l = line(&[0, 0, 0], &[10, 7, 6]);
        let phi = l.axis_error(&Point::new(&[1, 1, 1]), 1, 10);
        assert_eq!(phi[0], 0.0);
        assert!((phi[1] - 0.3).abs() < 1e-12 && (phi[2] - 0.4).abs() < 1e-12);
    }
}
