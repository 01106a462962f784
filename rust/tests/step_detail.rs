//! One point's detail (`step_detail`) and a chart's rows (`Trace::chart_rows`)
//! are read in one replay or one pass each; they must say what the trace's
//! own range reads say, for every algorithm, and draw the papers' figures
//! where the papers' equations put them.

use voxpath::figure::{DecisionFigure, ExitFace, FigureKind};
use voxpath::step_detail::step_detail;
use voxpath::trace::{Reading, Trace};

fn trace(json: &str) -> Trace {
    voxpath::trace_json(json).unwrap()
}

/// The same number, NaN included.
fn same(a: f64, b: f64) -> bool {
    a == b || (a.is_nan() && b.is_nan())
}

fn exit_face(t: &Trace, point: u64) -> ExitFace {
    match step_detail(t, point).figure {
        Some(DecisionFigure::ExitFace(face)) => face,
        other => panic!("point {point}: expected an exit face, got {other:?}"),
    }
}

/// A face point (u, v) in grid coordinates: the face's center plus u and
/// v along their axes.
fn on_grid(face: &ExitFace, [u, v]: [f64; 2]) -> Vec<f64> {
    let mut p = face.center.clone();
    p[usize::from(face.u_axis.axis)] += f64::from(face.u_axis.sign) * u;
    if let Some(axis) = face.v_axis {
        p[usize::from(axis.axis)] += f64::from(axis.sign) * v;
    }
    p
}

#[test]
fn every_point_of_every_example_reads_as_the_trace_s_ranges_do() {
    for info in voxpath::algorithms::ALGORITHMS {
        let mut request: serde_json::Value = serde_json::from_str(info.example.options).unwrap();
        request["algorithm"] = info.id.into();
        let t = trace(&request.to_string());
        let table = t.decisions(0, t.steps());
        let deviation = t.deviation_range(0, t.steps() + 1);
        for p in 0..=t.steps() {
            let d = step_detail(&t, p);
            assert_eq!(d.point_index, p);
            assert_eq!(d.point, t.point(p).coords());
            assert_eq!(
                d.deviation,
                Some(deviation[p as usize]),
                "{} point {p}",
                info.id
            );
            assert_eq!(d.decision.len(), t.columns().len());
            let Some(k) = p.checked_sub(1) else {
                assert!(d.step_index.is_none() && d.explanation.is_none() && d.figure.is_none());
                assert!(
                    d.decision
                        .iter()
                        .all(|c| c.value.is_none() && c.reading.is_none())
                );
                assert_eq!(d.segment_index, Some(0));
                continue;
            };
            assert_eq!(d.step_index, Some(k));
            assert_eq!(d.point_before.as_deref(), Some(t.point(k).coords()));
            assert_eq!(d.explanation.as_deref(), Some(t.explain(k).as_str()));
            for ((cell, column), values) in d.decision.iter().zip(t.columns()).zip(&table.columns) {
                let value = values[k as usize];
                assert_eq!(cell.name, column.name);
                assert_eq!(
                    cell.reading,
                    column.read(value),
                    "{} point {p} {}",
                    info.id,
                    column.name
                );
                assert!(
                    cell.value.is_none_or(|v| same(v, value)),
                    "{} point {p} {}",
                    info.id,
                    column.name
                );
            }
            let segment = d.segment_index.unwrap();
            let s = t.segment(segment);
            assert!(s.first_step <= k && k < s.first_step + s.steps);
            assert_eq!(d.segment.unwrap().note, t.segment_note(segment));
            if let Some(figure) = &d.figure {
                assert!(
                    t.figures().contains(&figure.kind()),
                    "{} point {p}",
                    info.id
                );
            }
        }
    }
}

#[test]
fn wang_s_step_3_crosses_the_exit_face_where_the_line_crosses_x_3() {
    // Wang's example (0,0,0)->(10,7,6), step 3 from (2,1,1) to (3,2,2): M =
    // 12, N = 6 (eq. 8, Table 2), region d, corner D. The line crosses the
    // plane x = 3 at y = 3 * 7/10 = 2.1, z = 3 * 6/10 = 1.8 (eq. 2).
    let t = trace(r#"{"algorithm":"regions","from":[0,0,0],"to":[10,7,6]}"#);
    assert_eq!(t.figures(), [FigureKind::ExitFace]);
    let d = step_detail(&t, 3);
    let read = |name: &str| d.decision.iter().find(|c| c.name == name).unwrap().reading;
    assert_eq!(read("M"), Some(Reading::Int(12)));
    assert_eq!(read("N"), Some(Reading::Int(6)));
    assert_eq!(read("region"), Some(Reading::Label("d")));
    assert_eq!(read("corner"), Some(Reading::Label("D")));
    let face = exit_face(&t, 3);
    assert_eq!((face.region, face.corner), ("d", "D"));
    assert_eq!(face.cell, [vec![2, 1, 1], vec![3, 2, 2]]);
    assert_eq!(face.center, [3.0, 1.5, 1.5]);
    let crossing = on_grid(&face, face.crossing);
    for (got, want) in crossing.iter().zip([3.0, 2.1, 1.8]) {
        assert!((got - want).abs() < 1e-12, "{crossing:?}");
    }
    // Corner D, both passive axes stepped, is the point reached.
    let d_corner = face.corners.iter().find(|c| c.name == "D").unwrap();
    assert_eq!(on_grid(&face, d_corner.at), [3.0, 2.0, 2.0]);
    let names = |parts: Vec<&str>| parts.join("");
    assert_eq!(names(face.regions.iter().map(|r| r.name).collect()), "abcd");
    assert_eq!(
        names(face.segments.iter().map(|s| s.name).collect()),
        "efgho"
    );
    assert_eq!(names(face.corners.iter().map(|c| c.name).collect()), "ABCD");
}

#[test]
fn with_one_passive_axis_the_face_is_the_edge_b_a() {
    // (0,0,0)->(5,5,2), Wang's type ⑤: x and y active, z passive. Step 1:
    // M = 2 * 2 - 5 = -1 < 0 (eq. 10), region b, corner B; the line
    // reaches x = y = 1 at z = 2/5, 0.1 below the edge's midpoint z = 0.5.
    let t = trace(r#"{"algorithm":"regions","from":[0,0,0],"to":[5,5,2]}"#);
    let face = exit_face(&t, 1);
    assert_eq!((face.region, face.corner, face.v_axis), ("b", "B", None));
    assert_eq!(face.center, [1.0, 1.0, 0.5]);
    assert!((on_grid(&face, face.crossing)[2] - 0.4).abs() < 1e-12);
    assert_eq!(face.crossing[1], -0.5);
    assert_eq!(
        face.regions.iter().map(|r| r.name).collect::<Vec<_>>(),
        ["a", "b"]
    );
    assert_eq!(
        face.corners.iter().map(|c| c.name).collect::<Vec<_>>(),
        ["A", "B"]
    );
    assert_eq!(face.segments.len(), 1);
    assert_eq!(
        (
            face.segments[0].name,
            face.segments[0].from,
            face.segments[0].to
        ),
        ("e", [0.0, -0.5], [0.0, -0.5])
    );
    // Wang's type ②, all axes active, crosses no face.
    assert!(
        step_detail(
            &trace(r#"{"algorithm":"regions","from":[0,0,0],"to":[3,3,3]}"#),
            1
        )
        .figure
        .is_none()
    );
}

#[test]
fn the_circle_s_candidates_are_the_cells_eq_7_compares() {
    // Saleem section 4, r = 5 counter-clockwise from (5, 0): step 3 from
    // (5, 2) compares (5, 3), 25 + 9 - 25 = 9, with (4, 3), 16 + 9 - 25 =
    // 0 (eq. 6), and takes (4, 3) (eq. 7).
    let t = trace(
        r#"{"algorithm":"circle","from":[5,0,0],"to":[0,5,0],"center":[0,0,0],"dir":"ccw","plane":"xy"}"#,
    );
    let Some(DecisionFigure::ArcCandidates(c)) = step_detail(&t, 3).figure else {
        panic!("expected candidates");
    };
    let [stay, moved] = &c.candidates;
    assert_eq!(
        (stay.name, stay.cell.as_slice(), stay.residual, stay.taken),
        ("stay", &[5, 3, 0][..], 9, false)
    );
    assert_eq!(
        (
            moved.name,
            moved.cell.as_slice(),
            moved.residual,
            moved.taken
        ),
        ("move", &[4, 3, 0][..], 0, true)
    );
}

#[test]
fn bresenham_s_error_terms_meet_the_threshold_at_the_tie_of_step_5() {
    // Saleem section 3 on (0,0,0)->(10,7,6), x major, threshold |Δx| = 10:
    // errorY gains 14 a step and loses 20 when y steps: 14, 8, 22, 16, then
    // 10 at step 5, a tie held (tie = hold); errorZ gains 12: 12, 4, 16, 8,
    // then 20, which steps.
    let t = trace(r#"{"algorithm":"bresenham3d","from":[0,0,0],"to":[10,7,6]}"#);
    let Some(DecisionFigure::ErrorTerms(e)) = step_detail(&t, 5).figure else {
        panic!("expected error terms");
    };
    assert_eq!(e.threshold, 10);
    let terms: Vec<_> = e.terms.iter().map(|t| (t.name, t.value, t.steps)).collect();
    assert_eq!(terms, [("errorY", 10, false), ("errorZ", 20, true)]);
}

#[test]
fn a_program_lists_both_pictures_and_each_step_has_its_own_algorithm_s() {
    // G1 to (4, 2) steps (regions), then G2 about (4, 0) to (4, -2) (circle).
    let program = voxpath::gcode::run(
        "G21 G90\nG1 X1 Y0.5\nG2 X1 Y-0.5 I0 J-0.5\n",
        voxpath::gcode::Settings::from_json(r#"{"stepsPerMm": 4}"#).unwrap(),
    );
    let t = &program.trace;
    assert_eq!(
        t.figures(),
        [FigureKind::ExitFace, FigureKind::ArcCandidates]
    );
    let kind = |p: u64| step_detail(t, p).figure.map(|f| f.kind());
    assert_eq!(kind(4), Some(FigureKind::ExitFace));
    assert_eq!(kind(5), Some(FigureKind::ArcCandidates));
    assert_eq!(step_detail(t, 5).segment_index, Some(1));
}

#[test]
fn chart_rows_are_the_points_deviation_and_axis_error_of_their_buckets() {
    // Chords of a circle: many segments, each measured against the arc,
    // which is walked; a line, walked incrementally; a whole circle.
    let chords = trace(
        r#"{"algorithm":"arc-segments","from":[40,0,0],"to":[-40,0,0],"center":[0,0,0],"segmentLength":7}"#,
    );
    assert!(chords.segment_count() > 10);
    let line = trace(r#"{"algorithm":"bresenham3d","from":[-3,5,0],"to":[40,-17,29]}"#);
    // A circle, walked along its arc (ArcMeter::walk), in the zx plane.
    let circle = trace(
        r#"{"algorithm":"circle","from":[30,2,-5],"to":[30,2,-5],"center":[-7,2,-5],"plane":"zx"}"#,
    );
    for t in [&chords, &line, &circle] {
        chart_rows_hold(t);
    }
}

#[test]
fn chart_rows_of_a_program_without_a_move_have_no_deviation() {
    // Nothing to measure against: the point, and NaN where the deviations
    // and the ideal position would be.
    let program = voxpath::gcode::program::run(
        "G21 G90\nG4 P0.5\n",
        voxpath::gcode::program::Settings::from_json(r#"{"stepsPerMm":80}"#).unwrap(),
    );
    let t = &program.trace;
    assert_eq!((t.steps(), t.segment_count()), (0, 0));
    let rows = t.chart_rows(0, 1, 7);
    let dims = t.dims();
    assert_eq!(rows.len(), 3 + 2 * dims);
    assert_eq!(rows[0], 0.0);
    assert!(rows[1 + dims..].iter().all(|v| v.is_nan()), "{rows:?}");
}

fn chart_rows_hold(t: &Trace) {
    let (dims, points) = (t.dims(), t.steps() + 1);
    let deviation = t.deviation_range(0, points);
    let error = t.axis_error_range(0, points);
    let flat = t.points_flat(0, points);
    for (from, to, max_rows) in [
        (0, points, 10_000),
        (0, points, 7),
        (5, points - 3, 4),
        (9, 10, 1),
    ] {
        let rows_out = t.chart_rows(from, to, max_rows);
        let bucket = (to - from).div_ceil(max_rows);
        let rows = (to - from).div_ceil(bucket) as usize;
        assert_eq!(rows_out.len(), rows * (3 + 2 * dims));
        let column = |c: usize| &rows_out[c * rows..(c + 1) * rows];
        for r in 0..rows {
            let k = from as usize + r * bucket as usize;
            let end = (k + bucket as usize).min(to as usize);
            assert_eq!(column(0)[r], k as f64);
            for a in 0..dims {
                assert_eq!(column(1 + a)[r], flat[k * dims + a] as f64);
                assert_eq!(
                    column(1 + dims + a)[r],
                    flat[k * dims + a] as f64 - error[k * dims + a]
                );
            }
            let bucket_values = &deviation[k..end];
            assert_eq!(
                column(1 + 2 * dims)[r],
                bucket_values.iter().copied().fold(f64::MIN, f64::max)
            );
            assert_eq!(
                column(2 + 2 * dims)[r],
                bucket_values.iter().copied().fold(f64::MAX, f64::min)
            );
        }
    }
}
