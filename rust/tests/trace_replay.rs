//! A trace keeps 2 bytes per step and recomputes decisions, points and
//! deviations for any range; those must equal what a direct run produces.

use voxpath::grid::Point;
use voxpath::ideal::IdealPath;
use voxpath::line::regions_wang::RegionsWang;
use voxpath::trace::{CHECKPOINT_INTERVAL, Decision, Stepper, TiePolicy};

struct DirectRun {
    points: Vec<Point>,
    rows: Vec<[f64; 5]>,
    explanations: Vec<String>,
}

fn direct(from: Point, to: Point) -> DirectRun {
    let mut s = RegionsWang::new(from, to, TiePolicy::Advance);
    let mut p = from;
    let mut out = DirectRun {
        points: vec![p],
        rows: Vec::new(),
        explanations: Vec::new(),
    };
    while let Some((step, why)) = s.next_step() {
        let mut row = [0.0; 5];
        why.write(&mut row);
        out.rows.push(row);
        out.explanations.push(why.explain(&p, step));
        p.apply(step);
        out.points.push(p);
    }
    out
}

fn same(a: f64, b: f64) -> bool {
    a == b || (a.is_nan() && b.is_nan())
}

#[test]
fn ranges_across_checkpoints_equal_a_direct_run() {
    let from = Point::new(&[-7, 3, 100]);
    let to = Point::new(&[
        -7 + 3 * CHECKPOINT_INTERVAL as i64 + 123,
        3 - 5000,
        100 + 777,
    ]);
    let run = direct(from, to);
    let trace = voxpath::trace_json(&format!(
        r#"{{"algorithm":"regions","from":{:?},"to":{:?}}}"#,
        from.coords(),
        to.coords()
    ))
    .unwrap();
    let steps = trace.steps();
    assert_eq!(steps as usize, run.rows.len());
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
                    same(v, expected),
                    "column {c} step {}: {v} vs {expected}",
                    a as usize + i
                );
            }
        }
        let flat = trace.points_flat(a, b + 1);
        let expected: Vec<i64> = run.points[a as usize..=b as usize]
            .iter()
            .flat_map(|p| p.coords().to_vec())
            .collect();
        assert_eq!(flat, expected);
        let dev = trace.deviation_range(a, b + 1);
        for (i, d) in dev.iter().enumerate() {
            assert_eq!(*d, ideal.deviation(&run.points[a as usize + i]));
        }
    }
    let max = run
        .points
        .iter()
        .map(|p| ideal.deviation(p))
        .fold(0.0, f64::max);
    assert_eq!(trace.metrics().max_deviation, max);
    assert_eq!(trace.metrics().pulses_by_axis, vec![12411, 5000, 777]);
    for k in [0, 4095, 4096, 9000, steps - 1] {
        assert_eq!(trace.explain(k), run.explanations[k as usize]);
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
