//! Helpers shared by the integration tests: run a stepper directly,
//! describe lines compactly, and hold every read of a trace to its replay
//! (`check_trace`).
#![allow(dead_code)] // each test crate uses its own subset

use proptest::prelude::*;
use voxpath::grid::{COORD_LIMIT, Point, displacement};
use voxpath::metrics::{Metrics, MetricsAccumulator};
use voxpath::trace::{ColumnKind, Decision, Stepper, Trace, fill_onto};

/// Every step of `stepper` from `from`: the point after the step and why.
pub fn run<S: Stepper>(mut stepper: S, from: Point) -> Vec<(Point, S::Why)> {
    let mut p = from;
    let mut out = Vec::new();
    while let Some((step, why)) = stepper.next_step() {
        p.apply(step);
        out.push((p, why));
    }
    out
}

/// The points of a path, start included.
pub fn path<S: Stepper>(stepper: S, from: Point) -> Vec<Point> {
    std::iter::once(from)
        .chain(run(stepper, from).into_iter().map(|(p, _)| p))
        .collect()
}

/// Wang's and Liu's points for (0,0,0)->(10,7,6) (Wang eq. 6-10 with ties
/// advancing; Liu's Table 1; SEED-NOTES).
pub const WANG_10_7_6: [[i64; 3]; 10] = [
    [1, 1, 1],
    [2, 1, 1],
    [3, 2, 2],
    [4, 3, 2],
    [5, 4, 3],
    [6, 4, 4],
    [7, 5, 4],
    [8, 6, 5],
    [9, 6, 5],
    [10, 7, 6],
];

/// Points from coordinate arrays.
pub fn points<const N: usize>(coords: &[[i64; N]]) -> Vec<Point> {
    coords.iter().map(|c| Point::new(c)).collect()
}

/// The trace of a JSON request, which must succeed.
pub fn trace(json: &str) -> voxpath::Trace {
    voxpath::trace_json(json).unwrap_or_else(|e| panic!("{json}: {e}"))
}

/// The catalogue's line algorithms (arcs need a center and cannot run on from/to alone).
pub fn line_algorithms() -> impl Iterator<Item = &'static voxpath::algorithms::AlgorithmInfo> {
    voxpath::algorithms::ALGORITHMS
        .iter()
        .copied()
        .filter(|a| a.family == voxpath::algorithms::Family::Line)
}

/// The values a decision writes, as bits (NaN included), so that two
/// decisions compare exactly, the sign of a zero too.
fn decision_bits<D: Decision>(why: &D) -> Vec<u64> {
    let mut row = vec![f64::NAN; D::COLUMNS.len()];
    why.write(&mut row);
    row.iter().map(|v| v.to_bits()).collect()
}

/// Checks a stepper's recording loop (`fill`) against its steps one by one:
/// filled in chunks of `chunk`, with one `next_step` between chunks (so the
/// state `fill` leaves behind must be the rule's, to the bit of every
/// decision value that step writes), the same steps, the displacement they
/// add up to, and the steps left after each chunk.
pub fn check_fill<S: Stepper>(make: impl Fn() -> S, chunk: usize) -> Result<(), String> {
    let mut one_by_one = make();
    let mut expected = Vec::new();
    let mut expected_why = Vec::new();
    while let Some((step, why)) = one_by_one.next_step() {
        expected.push(step);
        expected_why.push(decision_bits(&why));
    }
    let mut stepper = make();
    let mut taken = Vec::new();
    loop {
        let mut out = Vec::new();
        let filled = fill_onto(&mut stepper, &mut out, chunk);
        if filled.displacement() != displacement(&out) {
            return Err(format!("displacement after {} steps", taken.len()));
        }
        taken.extend_from_slice(&out);
        if let Some((step, why)) = stepper.next_step() {
            if expected_why.get(taken.len()) != Some(&decision_bits(&why)) {
                return Err(format!("the decision of step {} after a fill", taken.len()));
            }
            taken.push(step);
        }
        if stepper.remaining_steps()
            != Some((expected.len() - taken.len().min(expected.len())) as u64)
        {
            return Err(format!("steps left after {} steps", taken.len()));
        }
        if filled.steps() < chunk {
            break;
        }
    }
    if taken != expected {
        return Err("fill took other steps than next_step".into());
    }
    Ok(())
}

/// True when `traced`, a decision value a trace gave for a column of `kind`,
/// is `written`, the value a stepper wrote (or another trace gave): equal,
/// or both "does not apply", which a stepper writes as NaN and a trace gives
/// as NaN in a number column and NO_VALUE in a category or flag column.
pub fn same_cell(kind: ColumnKind, traced: f64, written: f64) -> bool {
    let expected = if written.is_nan() {
        kind.no_value()
    } else {
        written
    };
    traced == expected || (traced.is_nan() && expected.is_nan())
}

/// The ties among a trace's steps as each step's decision records them,
/// replayed step by step: the flags of its tie columns (the lines' "tie",
/// Saleem's helix's "helixTie"; the circle's rule has no ties).
pub fn ties_by_decision(t: &voxpath::Trace) -> u64 {
    let table = t.decisions(0, t.steps());
    t.columns()
        .iter()
        .zip(&table.columns)
        .filter(|(column, _)| column.name == "tie" || column.name == "helixTie")
        .map(|(_, flags)| flags.iter().filter(|&&flag| flag == 1.0).count() as u64)
        .sum()
}

/// Checks the ties a trace's metrics count, in one pass and in a pass
/// made in `parts` slices of points (each slice's ties counted from the
/// checkpoint before it), against [`ties_by_decision`], and the sliced
/// pass's other figures against the one pass's. `make` makes the trace
/// afresh: a trace keeps its metrics once made.
pub fn check_ties(make: impl Fn() -> voxpath::Trace, parts: u64) -> Result<(), String> {
    let whole = make();
    let expected = ties_by_decision(&whole);
    let counted = whole.metrics().ties;
    if counted != expected {
        return Err(format!(
            "one pass: {counted} ties, the decisions {expected}"
        ));
    }
    let sliced = make();
    let slice = (sliced.steps() + 1).div_ceil(parts.max(1));
    while !sliced.advance_metrics(slice).done {}
    let counted = sliced.metrics().ties;
    if counted != expected {
        return Err(format!(
            "{slice} points a slice: {counted} ties, the decisions {expected}"
        ));
    }
    // And every other figure, to the bit: one accumulator in point order,
    // however the pass is sliced (check_trace holds the whole pass's to
    // each point measured on its own).
    if sliced.metrics() != whole.metrics() {
        return Err(format!(
            "{slice} points a slice: {:?}, in one pass {:?}",
            sliced.metrics(),
            whole.metrics()
        ));
    }
    Ok(())
}

/// Points `from..to` by the replay: every step applied to a point.
pub fn replayed_points(t: &Trace, from: u64, to: u64) -> Vec<i64> {
    let mut out = Vec::new();
    t.walk_points(from, to, |_, p| out.extend_from_slice(p.coords()));
    out
}

/// Every point's deviation and per-axis error, each measured on its own
/// against the segment it belongs to (the one whose step starts from it;
/// the last point, the last segment that took a step), and the metrics
/// they add up to (the ties, which a replay of the decisions counts, taken
/// from the trace).
pub fn measured_point_by_point(t: &Trace) -> (Vec<f64>, Vec<f64>, Metrics) {
    let dims = t.dims();
    let segments: Vec<_> = t.segments().collect();
    let last = segments.iter().rposition(|s| s.steps > 0).unwrap_or(0);
    let mut acc = MetricsAccumulator::new(dims);
    acc.add_steps(t.step_range(0, t.steps()));
    let (mut deviation, mut axis_error) = (Vec::new(), Vec::new());
    if segments.is_empty() {
        // A program that made no move: its one point on the path it has not got.
        let n = t.steps() + 1;
        acc.add_point(0.0, &[0.0; voxpath::grid::MAX_AXES]);
        return (
            vec![0.0; n as usize],
            vec![0.0; n as usize * dims],
            acc.finish(t.metrics().ties),
        );
    }
    t.walk_points(0, t.steps() + 1, |k, p| {
        let seg = if k < t.steps() {
            segments
                .iter()
                .position(|s| s.first_step <= k && k < s.first_step + s.steps)
                .unwrap()
        } else {
            last
        };
        let s = &segments[seg];
        let d = s.ideal.deviation(p);
        let e = s
            .ideal
            .axis_error(p, (k - s.first_step).min(s.steps), s.steps);
        deviation.push(d);
        axis_error.extend_from_slice(&e[..dims]);
        acc.add_point(d, &e);
    });
    (deviation, axis_error, acc.finish(t.metrics().ties))
}

pub fn bits(values: &[f64]) -> Vec<u64> {
    values.iter().map(|v| v.to_bits()).collect()
}

/// Every read of `t` against the replay: all points and a range, as i64,
/// i32 and through chunks of `chunk` points; deviation, axis error and
/// metrics of every point and of the range.
pub fn check_trace(t: &Trace, range: (u64, u64), chunk: usize) -> Result<(), TestCaseError> {
    let (dims, n) = (t.dims(), t.steps() + 1);
    let all = replayed_points(t, 0, n);
    prop_assert_eq!(&t.points_flat(0, n), &all);
    let narrow: Vec<i64> = t.points_i32(0, n).into_iter().map(i64::from).collect();
    prop_assert_eq!(&narrow, &all);
    let (a, b) = (range.0.min(n - 1), range.1.min(n));
    let (a, b) = (a.min(b), a.max(b));
    prop_assert_eq!(t.points_flat(a, b), replayed_points(t, a, b));
    let mut buffer = Vec::<i32>::with_capacity(chunk * dims);
    let mut chunked = Vec::new();
    let mut next = a;
    t.points_by_chunk(
        a,
        b,
        &mut buffer.spare_capacity_mut()[..chunk * dims],
        |k, points| {
            assert_eq!(k, next, "chunks in order");
            next += (points.len() / dims) as u64;
            chunked.extend(points.iter().map(|&c| i64::from(c)));
        },
    );
    prop_assert_eq!(chunked, replayed_points(t, a, b));
    // The bounds: each axis's extremes over every point replayed.
    let column = |axis: usize| all.iter().skip(axis).step_by(dims).copied();
    let bounds = t.bounds();
    prop_assert_eq!(
        &bounds.min,
        &(0..dims)
            .map(|a| column(a).min().unwrap())
            .collect::<Vec<_>>()
    );
    prop_assert_eq!(
        &bounds.max,
        &(0..dims)
            .map(|a| column(a).max().unwrap())
            .collect::<Vec<_>>()
    );

    let (deviation, axis_error, metrics) = measured_point_by_point(t);
    prop_assert_eq!(bits(&t.deviation_range(0, n)), bits(&deviation));
    prop_assert_eq!(bits(&t.axis_error_range(0, n)), bits(&axis_error));
    prop_assert_eq!(
        bits(&t.deviation_range(a, b)),
        bits(&deviation[a as usize..b as usize])
    );
    prop_assert_eq!(
        bits(&t.axis_error_range(a, b)),
        bits(&axis_error[a as usize * dims..b as usize * dims])
    );
    prop_assert_eq!(t.metrics(), &metrics);

    // The chart's rows over the range, made whole and a slice of points at
    // a time (as the page's worker makes them): each bucket's first point,
    // where the ideal path is at its progress (the point less its per-axis
    // error) and the extremes of the bucket's deviations; NaN for both
    // where no segment measures the points (a program with no move).
    if a < b {
        let max_rows = 1 + chunk as u64 % 61;
        let bucket = (b - a).div_ceil(max_rows);
        let rows = (b - a).div_ceil(bucket) as usize;
        let measured = t.segment_count() > 0;
        let mut want = vec![f64::NAN; rows * (3 + 2 * dims)];
        for r in 0..rows {
            let k = a as usize + r * bucket as usize;
            let end = (k + bucket as usize).min(b as usize);
            want[r] = k as f64;
            for axis in 0..dims {
                let coordinate = all[k * dims + axis] as f64;
                want[(1 + axis) * rows + r] = coordinate;
                if measured {
                    want[(1 + dims + axis) * rows + r] = coordinate - axis_error[k * dims + axis];
                }
            }
            if measured {
                let bucket_deviation = &deviation[k..end];
                want[(1 + 2 * dims) * rows + r] = bucket_deviation
                    .iter()
                    .copied()
                    .fold(f64::NEG_INFINITY, f64::max);
                want[(2 + 2 * dims) * rows + r] = bucket_deviation
                    .iter()
                    .copied()
                    .fold(f64::INFINITY, f64::min);
            }
        }
        prop_assert_eq!(bits(&t.chart_rows(a, b, max_rows)), bits(&want));
        let slice = 1 + 7 * chunk as u64;
        while !t.advance_chart_rows(a, b, max_rows, slice).done {}
        prop_assert_eq!(bits(&t.take_chart_rows(a, b, max_rows)), bits(&want));
    }
    Ok(())
}

/// A random request of an arc algorithm, as JSON: a circle (in 3 axes, or
/// in x and y), an arc in chords by any line algorithm with its segment
/// length or tolerance, a helix by Saleem's rule or in chords; radius up to
/// 2,000, from angle 0 of any plane to any angle, either way, with up to two
/// extra turns and a rise up to 3,000; its center anywhere near the origin
/// or near the grid's edge, and one case in two moved against the edge in
/// its plane, its farthest cells on +-2^30 exactly.
pub fn arc_request() -> impl Strategy<Value = String> {
    let center_coordinate = || {
        prop_oneof![
            -5000i64..5000,
            Just(COORD_LIMIT - 5100),
            Just(-COORD_LIMIT + 5100)
        ]
    };
    (
        (1i64..2000, prop::array::uniform3(center_coordinate()), 0.0f64..std::f64::consts::TAU),
        (-3000i64..=3000, 0usize..5, 0usize..3, any::<bool>(), 0u64..3),
        (
            prop::sample::select(voxpath::arc::arc_segments::LINE_ALGORITHMS),
            0usize..3,
            0usize..3,
            0usize..4,
        ),
    )
        .prop_map(|((radius, center, turn), (rise, which, plane, cw, turns), (line, tie, chording, edge))| {
            let [u, v, n] = [[0, 1, 2], [2, 0, 1], [1, 2, 0]][plane];
            let mut center = center;
            match edge {
                0 => center[u] = COORD_LIMIT - radius,
                1 => center[v] = -COORD_LIMIT + radius,
                _ => {}
            }
            let mut from = center;
            from[u] += radius;
            let mut end = center;
            end[u] += (radius as f64 * turn.cos()).round() as i64;
            end[v] += (radius as f64 * turn.sin()).round() as i64;
            let mut helix_end = end;
            helix_end[n] += rise;
            let plane = ["xy", "zx", "yz"][plane];
            let dir = if cw { "cw" } else { "ccw" };
            let tie = ["", r#","tie":"advance""#, r#","tie":"hold""#][tie];
            let arc = format!(r#""center":{center:?},"plane":"{plane}","dir":"{dir}","turns":{turns}"#);
            let chord_tie = if ["regions", "bresenham3d", "nd"].contains(&line) { tie } else { "" };
            let chording = [
                String::new(),
                format!(r#","segmentLength":{}"#, 1 + turns * 7),
                format!(r#","tolerance":{}"#, 0.002 * (1 + turns) as f64),
            ][chording]
                .clone();
            let chords = format!(r#""lineAlgorithm":"{line}"{chord_tie}{chording}"#);
            match which {
                0 => format!(r#"{{"algorithm":"circle","from":{from:?},"to":{end:?},{arc}}}"#),
                1 if plane == "xy" => format!(
                    r#"{{"algorithm":"circle","from":{:?},"to":{:?},"center":{:?},"dir":"{dir}","turns":{turns}}}"#,
                    &from[..2],
                    &end[..2],
                    &center[..2]
                ),
                1 | 2 => format!(r#"{{"algorithm":"arc-segments","from":{from:?},"to":{end:?},{arc},{chords}}}"#),
                3 => format!(r#"{{"algorithm":"helix","from":{from:?},"to":{helix_end:?},{arc}{tie}}}"#),
                _ => format!(
                    r#"{{"algorithm":"helix","method":"segments","from":{from:?},"to":{helix_end:?},{arc},{chords}}}"#
                ),
            }
        })
}
