//! A trace keeps 2 bytes per step and recomputes decisions, points and
//! deviations for any range; those must equal what a direct run of the
//! algorithm's stepper produces, for every algorithm of the catalogue.

mod common;

use voxpath::grid::Point;
use voxpath::ideal::IdealPath;
use voxpath::line::TieAxis;
use voxpath::line::bresenham2d::{Bresenham2d, Variant};
use voxpath::line::bresenham3d::Bresenham3d;
use voxpath::line::dda::Dda;
use voxpath::line::greedy::Greedy;
use voxpath::line::liu_float::LiuFloat;
use voxpath::line::nd::Nd;
use voxpath::line::regions_wang::RegionsWang;
use voxpath::line::walk6::Walk6;
use voxpath::request::TiePolicy;
use voxpath::trace::{CHECKPOINT_INTERVAL, ColumnKind, Decision, NO_VALUE, Stepper};

struct DirectRun {
    points: Vec<Point>,
    rows: Vec<Vec<f64>>,
    explanations: Vec<String>,
    ties: u64,
}

fn direct<S: Stepper>(mut stepper: S, from: Point) -> DirectRun {
    let mut p = from;
    let mut out = DirectRun {
        points: vec![p],
        rows: Vec::new(),
        explanations: Vec::new(),
        ties: 0,
    };
    let columns = stepper.columns().len();
    while let Some((step, why)) = stepper.next_step() {
        out.ties += why.is_tie() as u64;
        let mut row = vec![f64::NAN; columns];
        why.write(&mut row);
        out.rows.push(row);
        out.explanations.push(why.explain(&p, step));
        p.apply(step);
        out.points.push(p);
    }
    out
}

/// Traces `options` with `algorithm` and checks ranges that start before,
/// on and after checkpoints against a direct run of `stepper`.
fn check_replay<S: Stepper>(algorithm: &str, options: &str, from: Point, to: Point, stepper: S) {
    let columns = stepper.columns();
    let run = direct(stepper, from);
    let trace = common::trace(&format!(
        r#"{{"algorithm":"{algorithm}","from":{:?},"to":{:?}{options}}}"#,
        from.coords(),
        to.coords()
    ));
    let steps = trace.steps();
    assert_eq!(steps as usize, run.rows.len(), "{algorithm}");
    assert!(
        steps > 2 * CHECKPOINT_INTERVAL,
        "{algorithm}: the line must cross checkpoints"
    );
    assert_eq!(trace.columns(), columns, "{algorithm}");
    let ideal = IdealPath::Line { from, to };
    for (a, b) in [
        (0, 10),
        (4090, 4100),
        (4096, 8192),
        (steps - 5, steps),
        (0, steps),
        (5000, 5000),
    ] {
        let table = trace.decisions(a, b);
        for (c, column) in table.columns.iter().enumerate() {
            for (i, &v) in column.iter().enumerate() {
                let expected = run.rows[a as usize + i][c];
                assert!(
                    common::same_cell(trace.columns()[c].kind, v, expected),
                    "{algorithm} column {c} step {}: {v} vs {expected}",
                    a as usize + i
                );
            }
        }
        let flat = trace.points_flat(a, b + 1);
        let expected: Vec<i64> = run.points[a as usize..=b as usize]
            .iter()
            .flat_map(|p| p.coords().to_vec())
            .collect();
        assert_eq!(flat, expected, "{algorithm}");
        let dev = trace.deviation_range(a, b + 1);
        for (i, d) in dev.iter().enumerate() {
            assert_eq!(
                *d,
                ideal.deviation(&run.points[a as usize + i]),
                "{algorithm}"
            );
        }
    }
    let max = run
        .points
        .iter()
        .map(|p| ideal.deviation(p))
        .fold(0.0, f64::max);
    assert_eq!(trace.metrics().max_deviation, max, "{algorithm}");
    // Steps are recorded without their decisions; the metrics count ties by
    // replaying them.
    assert_eq!(trace.metrics().ties, run.ties, "{algorithm}");
    // Each axis pulses exactly |Δ| times: it only ever moves toward the end.
    let delta = from.delta_to(&to);
    let pulses: Vec<u64> = delta[..from.dims()]
        .iter()
        .map(|d| d.unsigned_abs())
        .collect();
    assert_eq!(trace.metrics().pulses_by_axis, pulses, "{algorithm}");
    assert_eq!(
        trace.metrics().steps_moving_axes.iter().sum::<u64>(),
        steps,
        "{algorithm}"
    );
    for k in [0, 4095, 4096, 9000, steps - 1] {
        assert_eq!(
            trace.explain(k),
            run.explanations[k as usize],
            "{algorithm}"
        );
    }
}

#[test]
fn ranges_across_checkpoints_equal_a_direct_run() {
    let n = 3 * CHECKPOINT_INTERVAL as i64 + 123;
    let from3 = Point::new(&[-7, 3, 100]);
    let to3 = Point::new(&[-7 + n, 3 - 5000, 100 + 777]);
    let advance = TiePolicy::Advance;
    check_replay(
        "regions",
        "",
        from3,
        to3,
        RegionsWang::new(from3, to3, advance),
    );
    check_replay(
        "bresenham3d",
        r#","gcd":true"#,
        from3,
        to3,
        Bresenham3d::new(from3, to3, TiePolicy::Hold, true),
    );
    check_replay(
        "liu-float",
        "",
        from3,
        to3,
        LiuFloat::new(from3, to3, advance, 1),
    );
    let from2 = Point::new(&[12, -40]);
    let to2 = Point::new(&[12 - 4000, -40 - n]);
    let printed = r#","variant":"printed""#;
    check_replay(
        "bresenham2d",
        printed,
        from2,
        to2,
        Bresenham2d::new(from2, to2, TiePolicy::Hold, Variant::Printed),
    );
    check_replay(
        "greedy",
        "",
        from2,
        to2,
        Greedy::new(from2, to2, TieAxis::Lower),
    );
    let from6 = Point::new(&[0, 1, 2, 3, 4, 5]);
    let to6 = Point::new(&[n, 1 - 3000, 2 + 2000, 3 + n, 4 - 10, 5]);
    check_replay(
        "nd",
        r#","tie":"hold""#,
        from6,
        to6,
        Nd::new(from6, to6, TiePolicy::Hold, false),
    );
    let from4 = Point::new(&from6.coords()[..4]);
    let to4 = Point::new(&to6.coords()[..4]);
    check_replay(
        "nd",
        "",
        from4,
        to4,
        Nd::new(from4, to4, TiePolicy::Advance, false),
    );
    check_replay("dda", "", from6, to6, Dda::new(from6, to6));
    let higher = r#","tieAxis":"higher""#;
    check_replay(
        "walk6",
        higher,
        from3,
        to3,
        Walk6::new(from3, to3, TieAxis::Higher),
    );
}

/// An nd trace has a discriminant column per axis it has, then the tie:
/// none for axes it does not have, which no step would fill.
#[test]
fn nd_columns_are_its_axes() {
    for dims in 2..=6 {
        let from = vec![0; dims];
        let to: Vec<i64> = (0..dims as i64).map(|a| 9 - 2 * a).collect();
        let t = common::trace(&format!(
            r#"{{"algorithm":"nd","from":{from:?},"to":{to:?}}}"#
        ));
        let names: Vec<&str> = t.columns().iter().map(|c| c.name).collect();
        let mut expected: Vec<String> = ["X", "Y", "Z", "A", "B", "C"][..dims]
            .iter()
            .map(|axis| format!("discriminant{axis}"))
            .collect();
        expected.push("tie".into());
        assert_eq!(names, expected, "{dims} axes");
        // Every passive axis's column holds a number at the first step.
        let first = t.decisions(0, 1);
        for (axis, column) in first.columns[1..dims].iter().enumerate() {
            assert!(!column[0].is_nan(), "{dims} axes: axis {}", axis + 1);
        }
    }
}

/// greedy, walk6 and dda too have a column per axis the move has, between
/// their other columns: a 3-axis greedy line had distSqA to distSqC, which
/// no step fills. At the first step of a move on every axis each column
/// holds a value, so each lands in its own column.
#[test]
fn per_axis_columns_are_the_moves_axes() {
    for (algorithm, per_axis, before, after) in [
        ("greedy", "distSq", &[][..], &["axis", "tie"][..]),
        ("walk6", "t", &["crosses"][..], &["tie"][..]),
        ("dda", "acc", &[][..], &["guard"][..]),
    ] {
        for dims in 2..=6 {
            let from = vec![0; dims];
            let to: Vec<i64> = (0..dims as i64).map(|a| 9 - 2 * a).collect();
            let t = common::trace(&format!(
                r#"{{"algorithm":"{algorithm}","from":{from:?},"to":{to:?}}}"#
            ));
            let names: Vec<&str> = t.columns().iter().map(|c| c.name).collect();
            let axes = ["X", "Y", "Z", "A", "B", "C"][..dims]
                .iter()
                .map(|axis| format!("{per_axis}{axis}"));
            let expected: Vec<String> = before
                .iter()
                .map(|name| name.to_string())
                .chain(axes)
                .chain(after.iter().map(|name| name.to_string()))
                .collect();
            assert_eq!(names, expected, "{algorithm}, {dims} axes");
            let first = t.decisions(0, 1);
            for (name, column) in names.iter().zip(&first.columns) {
                assert!(!column[0].is_nan(), "{algorithm}, {dims} axes: {name}");
            }
        }
    }
}

#[test]
fn a_zero_length_line_is_an_empty_trace() {
    let trace =
        voxpath::trace_json(r#"{"algorithm":"regions","from":[4,-5,6],"to":[4,-5,6]}"#).unwrap();
    assert_eq!(trace.steps(), 0);
    assert_eq!(trace.points_flat(0, 1), vec![4, -5, 6]);
    assert_eq!(trace.deviation_range(0, 1), vec![0.0]);
    assert_eq!(trace.metrics().max_deviation, 0.0);
    assert!(trace.decisions(0, 0).columns.iter().all(|c| c.is_empty()));
}

#[test]
fn too_long_a_path_names_max_steps() {
    let e = voxpath::trace_json(
        r#"{"algorithm":"regions","from":[0,0,0],"to":[1000,1,1],"maxSteps":999}"#,
    )
    .err()
    .unwrap();
    assert_eq!(e.field_name(), Some("maxSteps"));
    assert!(e.to_string().contains("more than 999 steps"), "{e}");
}

/// Every category cell of `trace` is a label index or NO_VALUE, every flag
/// cell 0, 1 or NO_VALUE: never NaN, which a byte array would read as 0 (the
/// first label, or "no").
fn check_category_cells(what: &str, trace: &voxpath::Trace) {
    let table = trace.decisions(0, trace.steps());
    for (column, values) in trace.columns().iter().zip(&table.columns) {
        if let ColumnKind::Category { labels } = column.kind {
            assert!(
                labels.len() < usize::from(NO_VALUE),
                "{what}: {}",
                column.name
            );
        }
        let valid = |v: f64| match column.kind {
            ColumnKind::Category { labels } => v < labels.len() as f64 && v.fract() == 0.0,
            ColumnKind::Flag => v == 0.0 || v == 1.0,
            ColumnKind::Int | ColumnKind::Float => true,
        };
        for (k, &v) in values.iter().enumerate() {
            assert!(
                valid(v) || v == f64::from(NO_VALUE),
                "{what}: {} at step {k} is {v}",
                column.name
            );
        }
    }
}

#[test]
fn category_and_flag_cells_are_a_label_or_no_value() {
    for info in voxpath::algorithms::ALGORITHMS {
        let mut request: serde_json::Value = serde_json::from_str(info.example.options).unwrap();
        request["algorithm"] = info.id.into();
        check_category_cells(info.id, &common::trace(&request.to_string()));
    }
    // Wang's type ② (all axes active): no region, no corner.
    let t = common::trace(r#"{"algorithm":"regions","from":[0,0,0],"to":[-4,4,4]}"#);
    check_category_cells("regions type 2", &t);
    // A helix steeper than its arc: steps of z alone, with no circle decision.
    let t = common::trace(r#"{"algorithm":"helix","from":[3,0,0],"to":[0,3,-9],"center":[0,0,0]}"#);
    check_category_cells("steep helix", &t);
}

#[test]
fn a_program_s_line_steps_have_no_circle_values_and_its_arc_steps_no_regions_values() {
    // G1 to (4, 2) steps, then G2 about (4, 0) to (4, -2): the trace unions
    // the columns of regions and circle; each step fills its own algorithm's
    // and leaves the other's as "does not apply".
    let program = voxpath::gcode::run(
        "G21 G90\nG1 X1 Y0.5\nG2 X1 Y-0.5 I0 J-0.5\n",
        voxpath::gcode::Settings::from_json(r#"{"stepsPerMm": 4}"#).unwrap(),
    );
    let t = &program.trace;
    check_category_cells("gcode", t);
    let table = t.decisions(0, t.steps());
    let column = |name: &str| {
        let i = t.columns().iter().position(|c| c.name == name).unwrap();
        &table.columns[i]
    };
    let none = f64::from(NO_VALUE);
    // Steps 0-3 are the line's (4 steps along x), 4-9 the arc's.
    for name in [
        "octant",
        "fast",
        "slowSteps",
        "correction",
        "otherCandidate",
    ] {
        assert_eq!(column(name)[..4], [none; 4], "{name}");
        assert!(column(name)[4..].iter().all(|&v| v != none), "{name}");
    }
    for name in ["region", "corner", "tie"] {
        assert!(column(name)[..4].iter().all(|&v| v != none), "{name}");
        assert_eq!(column(name)[4..], [none; 6], "{name}");
    }
    assert!(column("M")[4..].iter().all(|v| v.is_nan()));
}

/// `Trace::ideal_line_f32` as a plain per-vertex loop over the f64
/// polyline gives it: the box of the values below, then x, y, z of each
/// vertex rounded to f32 (z = 0 on 2 axes, axes past the third left out),
/// then what the rounding left of each, itself as f32.
fn ideal_line_by_vertex(t: &voxpath::trace::Trace, origin: [f64; 3]) -> Vec<f32> {
    let dims = t.dims();
    let polyline = t.ideal_polyline();
    let exact: Vec<f64> = polyline
        .chunks_exact(dims)
        .flat_map(|v| (0..3).map(move |a| v.get(a).map_or(0.0, |&c| c - origin[a])))
        .collect();
    let xyz: Vec<f32> = exact.iter().map(|&v| v as f32).collect();
    let rests: Vec<f32> = exact
        .iter()
        .zip(&xyz)
        .map(|(&v, &drawn)| (v - f64::from(drawn)) as f32)
        .collect();
    let mut line = vec![0.0f32; 6];
    if !xyz.is_empty() {
        for a in 0..3 {
            let axis = xyz.iter().skip(a).step_by(3).copied();
            line[a] = axis.clone().fold(f32::INFINITY, f32::min);
            line[3 + a] = axis.fold(f32::NEG_INFINITY, f32::max);
        }
    }
    line.extend(xyz);
    line.extend(rests);
    line
}

/// An ideal line's box, then its x, y, z, then its rests, each joined from
/// its pieces.
fn box_xyz_rests(line: &voxpath::trace::IdealLineF32) -> Vec<f32> {
    let mut flat = line.bounds().to_vec();
    flat.extend(line.xyz_pieces().flatten());
    flat.extend(line.rest_pieces().flatten());
    assert_eq!(flat.len(), 6 + 6 * line.vertices());
    flat
}

#[test]
fn the_ideal_line_for_drawing_is_the_polyline_from_its_origin_as_f32_after_its_box() {
    let settings = |json: &str| voxpath::gcode::Settings::from_json(json).unwrap();
    // Arcs both ways and a helix (vertices off the grid, on three axes),
    // then a line, whose start repeats the last arc vertex only where it
    // lies on the grid.
    let program = voxpath::gcode::run(
        "G21 G90\nG1 X10 Y-4 F500\nG2 X-2 Y-4 I-6 J0 Z3\nG3 X1 Y1 R7\nG1 X5 Y2\n",
        settings(r#"{"stepsPerMm": 80}"#),
    );
    let empty = voxpath::gcode::run("G21 G90\n", settings(r#"{"stepsPerMm": 80}"#));
    // 20,001 vertices: the line's pieces of 8,192 vertices, two full and
    // one not, joined in order.
    let zigzag: String = (1..=20_000)
        .map(|k| format!("G1 X{k} Y{}\n", k % 2))
        .collect();
    let long = voxpath::gcode::run(&zigzag, settings(r#"{"stepsPerMm": 1}"#));
    assert_eq!(long.trace.ideal_line_f32([0.0; 3]).vertices(), 20_001);
    let traces = [
        &program.trace,
        &empty.trace,
        &long.trace,
        &voxpath::algorithms::trace_json(
            r#"{"algorithm": "bresenham2d", "from": [-3, 5], "to": [40, -17]}"#,
        )
        .unwrap(),
        &voxpath::algorithms::trace_json(
            r#"{"algorithm": "nd", "from": [1, -2, 3, -4], "to": [9, 7, -5, 6]}"#,
        )
        .unwrap(),
    ];
    for t in traces {
        for origin in [[0.0; 3], [7.0, -3.0, 2.0]] {
            let line = box_xyz_rests(&t.ideal_line_f32(origin));
            assert_eq!(line, ideal_line_by_vertex(t, origin), "{} axes", t.dims());
        }
    }
    assert_eq!(
        box_xyz_rests(&empty.trace.ideal_line_f32([5.0, 6.0, 7.0])),
        [0.0; 6]
    );
    // Near 2^30 a vertex keeps its place from an origin near it, where as
    // an f32 of its own 1,073,741,800 is 2^30: the line is its two ends.
    let far = voxpath::algorithms::trace_json(
        r#"{"algorithm": "regions", "from": [1073741800, 1073741800, 1073741800], "to": [1073741824, 1073741810, 1073741805]}"#,
    )
    .unwrap();
    let line = box_xyz_rests(&far.ideal_line_f32([1073741800.0; 3]));
    assert_eq!(
        line[6..],
        [0.0, 0.0, 0.0, 24.0, 10.0, 5.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]
    );
    assert!(program.trace.ideal_polyline().len() / 3 > 20);
}
