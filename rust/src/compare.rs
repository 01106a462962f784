//! Two traces of the same move side by side (for example direct arc
//! stepping against the same arc in chords): each one's step count and
//! deviation, where the paths part, and the cells one visits and the other
//! does not. The result is a plain serializable value for the CLI and page.
//!
//! Cost: each trace's points are sorted once, 24 bytes per point (about
//! 140 MB for each of two 6-million-step circles of radius 2^20).

use crate::error::Error;
use crate::grid::MAX_AXES;
use crate::metrics::Metrics;
use crate::trace::Trace;
use serde::Serialize;
use std::collections::HashSet;

/// Most cells listed per side; `count` still counts them all.
pub const CELL_LIMIT: usize = 1000;

/// Points read from a trace at a time.
const CHUNK_POINTS: u64 = 1 << 16;

#[derive(Serialize, Debug, Clone, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct Comparison {
    pub a: TraceDigest,
    pub b: TraceDigest,
    /// The first point index whose points differ (the step before it is the
    /// first differing step); None when the paths are identical.
    pub first_difference: Option<FirstDifference>,
    /// Cells a visits and b never does, in a's order, each once.
    pub only_in_a: Cells,
    /// Cells b visits and a never does, in b's order, each once.
    pub only_in_b: Cells,
}

#[derive(Serialize, Debug, Clone, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct TraceDigest {
    pub algorithm: String,
    pub steps: u64,
    pub start: Vec<i64>,
    pub end: Vec<i64>,
    /// maxDeviation is the largest radial error for an arc.
    pub metrics: Metrics,
}

#[derive(Serialize, Debug, Clone, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct FirstDifference {
    pub point_index: u64,
    /// a's point there, or None when a has already ended.
    pub a: Option<Vec<i64>>,
    pub b: Option<Vec<i64>>,
}

#[derive(Serialize, Debug, Clone, PartialEq, Default)]
#[serde(rename_all = "camelCase")]
pub struct Cells {
    /// Distinct cells.
    pub count: u64,
    /// The first [`CELL_LIMIT`] of them.
    pub cells: Vec<Vec<i64>>,
}

type Key = [i32; MAX_AXES];

/// A point as a sort key. Every trace point fits in i32 (inputs and circles
/// lie within ±2^30).
fn key(p: &[i64]) -> Key {
    let mut k = [0; MAX_AXES];
    for (slot, &c) in k.iter_mut().zip(p) {
        *slot = c as i32;
    }
    k
}

/// Calls `f(point index, coordinates)` for every point.
fn for_each_point(t: &Trace, mut f: impl FnMut(u64, &[i64])) {
    t.walk_points(0, t.steps() + 1, |k, p| f(k, p.coords()));
}

fn sorted_cells(t: &Trace) -> Vec<Key> {
    let mut keys = Vec::with_capacity(t.steps() as usize + 1);
    for_each_point(t, |_, p| keys.push(key(p)));
    keys.sort_unstable();
    keys.dedup();
    keys
}

/// Cells of `t` missing from `other` (sorted), in `t`'s order.
fn missing(t: &Trace, other: &[Key]) -> Cells {
    let mut seen = HashSet::new();
    let mut out = Cells::default();
    for_each_point(t, |_, p| {
        let k = key(p);
        if other.binary_search(&k).is_err() && seen.insert(k) {
            out.count += 1;
            if out.cells.len() < CELL_LIMIT {
                out.cells.push(p.to_vec());
            }
        }
    });
    out
}

fn digest(t: &Trace) -> TraceDigest {
    TraceDigest {
        algorithm: t.algorithm.clone(),
        steps: t.steps(),
        start: t.start().coords().to_vec(),
        end: t.end().coords().to_vec(),
        metrics: t.metrics().clone(),
    }
}

/// The first point index where `a` and `b` differ, walking both together.
fn first_difference(a: &Trace, b: &Trace) -> Option<FirstDifference> {
    let shared = a.steps().min(b.steps()) + 1;
    let dims = a.dims();
    let mut from = 0;
    while from < shared {
        let to = (from + CHUNK_POINTS).min(shared);
        let (pa, pb) = (a.points_flat(from, to), b.points_flat(from, to));
        if let Some(i) = pa
            .chunks(dims)
            .zip(pb.chunks(dims))
            .position(|(p, q)| p != q)
        {
            let k = from + i as u64;
            return Some(FirstDifference {
                point_index: k,
                a: Some(a.point(k).coords().to_vec()),
                b: Some(b.point(k).coords().to_vec()),
            });
        }
        from = to;
    }
    // One path is a prefix of the other.
    (a.steps() != b.steps()).then(|| {
        let at = |t: &Trace| (shared <= t.steps()).then(|| t.point(shared).coords().to_vec());
        FirstDifference {
            point_index: shared,
            a: at(a),
            b: at(b),
        }
    })
}

/// Compares two traces with the same number of axes.
pub fn compare(a: &Trace, b: &Trace) -> Result<Comparison, Error> {
    if a.dims() != b.dims() {
        return Err(Error::field(
            "b",
            format!("has {} axes but a has {}", b.dims(), a.dims()),
        ));
    }
    Ok(Comparison {
        a: digest(a),
        b: digest(b),
        first_difference: first_difference(a, b),
        only_in_a: missing(a, &sorted_cells(b)),
        only_in_b: missing(b, &sorted_cells(a)),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn trace(json: &str) -> Trace {
        crate::trace_json(json).unwrap()
    }

    #[test]
    fn a_quarter_circle_against_its_single_chord() {
        // Circle r = 5 (worked in tests/arc_golden.rs): (5,0) (5,1) (5,2)
        // (4,3) (3,4) (2,5) (1,5) (0,5). One chord (segment 100 > the arc's
        // 7.85): Wang's regions on (5,0,0) -> (0,5,0), |Δx| = |Δy| = 5, both
        // active, every step diagonal: (4,1) (3,2) (2,3) (1,4) (0,5).
        let circle =
            trace(r#"{"algorithm":"circle","from":[5,0,0],"to":[0,5,0],"center":[0,0,0]}"#);
        let chord = trace(
            r#"{"algorithm":"arc-segments","from":[5,0,0],"to":[0,5,0],"center":[0,0,0],"segmentLength":100}"#,
        );
        let c = compare(&circle, &chord).unwrap();
        assert_eq!((c.a.steps, c.b.steps), (7, 5));
        assert_eq!(
            c.first_difference,
            Some(FirstDifference {
                point_index: 1,
                a: Some(vec![5, 1, 0]),
                b: Some(vec![4, 1, 0]),
            })
        );
        let cells = |v: &[[i64; 3]]| v.iter().map(|p| p.to_vec()).collect::<Vec<_>>();
        assert_eq!(
            c.only_in_a.cells,
            cells(&[
                [5, 1, 0],
                [5, 2, 0],
                [4, 3, 0],
                [3, 4, 0],
                [2, 5, 0],
                [1, 5, 0]
            ])
        );
        assert_eq!(
            c.only_in_b.cells,
            cells(&[[4, 1, 0], [3, 2, 0], [2, 3, 0], [1, 4, 0]])
        );
        assert_eq!((c.only_in_a.count, c.only_in_b.count), (6, 4));
        // Largest radial error: circle (5,2), sqrt(29) - 5 = 0.385; chord
        // (3,2) and (2,3), 5 - sqrt(13) = 1.394.
        assert!((c.a.metrics.max_deviation - (29f64.sqrt() - 5.0)).abs() < 1e-12);
        assert!((c.b.metrics.max_deviation - (5.0 - 13f64.sqrt())).abs() < 1e-12);
        let json = serde_json::to_value(&c).unwrap();
        assert_eq!(json["firstDifference"]["pointIndex"], 1);
        assert_eq!(json["onlyInB"]["count"], 4);
    }

    #[test]
    fn identical_and_prefix_paths() {
        let a = trace(r#"{"algorithm":"regions","from":[0,0,0],"to":[10,7,6]}"#);
        let c = compare(&a, &a).unwrap();
        assert_eq!(c.first_difference, None);
        assert_eq!((c.only_in_a.count, c.only_in_b.count), (0, 0));
        // One full circle of r = 5 (28 steps) is a prefix of two turns: the
        // paths part where the first ends, over the same cells.
        let once = trace(r#"{"algorithm":"circle","from":[5,0,0],"to":[5,0,0],"center":[0,0,0]}"#);
        let twice = trace(
            r#"{"algorithm":"circle","from":[5,0,0],"to":[5,0,0],"center":[0,0,0],"turns":1}"#,
        );
        let c = compare(&once, &twice).unwrap();
        let d = c.first_difference.unwrap();
        assert_eq!((d.point_index, d.a, d.b), (29, None, Some(vec![5, 1, 0])));
        assert_eq!((c.only_in_a.count, c.only_in_b.count), (0, 0));
    }

    #[test]
    fn differing_axis_counts_are_refused() {
        let a = trace(r#"{"algorithm":"regions","from":[0,0,0],"to":[1,1,1]}"#);
        let b = crate::TraceBuilder::new(crate::Point::origin(2), 10).finish("empty");
        assert_eq!(
            compare(&a, &b).unwrap_err().to_string(),
            "b: has 2 axes but a has 3"
        );
    }
}
