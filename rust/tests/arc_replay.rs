//! Arc traces keep 2 bytes per step and recompute decisions, explanations
//! and points by replay from checkpoints; across checkpoints those must equal
//! a direct run. For arc-segments the chords are spliced in from the line
//! algorithm's own traces, so the stored positions must still be right.

mod common;

use voxpath::arc::ArcSpec;
use voxpath::arc::circle_saleem::{CircleWhy, SaleemCircle};
use voxpath::grid::Point;
use voxpath::trace::{CHECKPOINT_INTERVAL, Decision, Stepper};
use voxpath::{Request, TraceBuilder};

#[test]
fn a_circle_with_a_correction_replays_across_checkpoints() {
    // G19 (u, v) = (y, z), clockwise from (2000, -1) almost a full turn to
    // (1999, 3), which is 0.998 inside the circle r² = 2000² + 1, so the
    // path ends with a correction; about 11,300 steps, two checkpoints.
    let json = r#"{"algorithm":"circle","from":[4,-1000,-501],"to":[4,-1001,-497],"center":[9,-3000,-500],"dir":"cw","plane":"yz"}"#;
    let trace = voxpath::trace_json(json).unwrap();
    let spec = ArcSpec::parse(&Request::from_json(json).unwrap(), false, 3).unwrap();
    let mut stepper = SaleemCircle::new(&spec);
    let mut p = spec.from;
    let (mut rows, mut explanations, mut points) = (Vec::new(), Vec::new(), vec![p]);
    while let Some((step, why)) = stepper.next_step() {
        let mut row = [0.0; CircleWhy::COLUMNS.len()];
        why.write(&mut row);
        rows.push(row);
        explanations.push(why.explain(&p, step));
        p.apply(step);
        points.push(p);
    }
    let steps = trace.steps();
    assert_eq!(steps as usize, rows.len());
    assert!(steps > 2 * CHECKPOINT_INTERVAL);
    assert_eq!(rows.last().unwrap()[5], 1.0, "ends with a correction");
    for (a, b) in [(0, 10), (4090, 4100), (8190, 8200), (steps - 5, steps)] {
        let table = trace.decisions(a, b);
        for (c, column) in table.columns.iter().enumerate() {
            for (i, &v) in column.iter().enumerate() {
                assert!(
                    common::same_cell(trace.columns()[c].kind, v, rows[a as usize + i][c]),
                    "column {c} step {}",
                    a as usize + i
                );
            }
        }
        let flat = trace.points_flat(a, b + 1);
        let expected: Vec<i64> = points[a as usize..=b as usize]
            .iter()
            .flat_map(|p| p.coords().to_vec())
            .collect();
        assert_eq!(flat, expected);
    }
    for k in [0, 4095, 4096, 9000, steps - 1] {
        assert_eq!(trace.explain(k), explanations[k as usize]);
    }
}

#[test]
fn spliced_chords_keep_their_positions_and_decisions() {
    // A half circle of r = 3000 in three 60° chords of 2598, 3000 and 2598
    // steps: checkpoints fall inside chords.
    let json = r#"{"algorithm":"arc-segments","from":[3000,0,5],"to":[-3000,0,5],"center":[0,0,0],"segmentLength":3000}"#;
    let trace = voxpath::trace_json(json).unwrap();
    assert_eq!(trace.segment_count(), 3);
    let mut builder = TraceBuilder::new(Point::new(&[3000, 0, 5]), 1 << 20);
    let mut rows: Vec<Vec<f64>> = Vec::new();
    for segment in trace.segments() {
        let end = trace.point(segment.first_step + segment.steps);
        let line = voxpath::trace_json(&format!(
            r#"{{"algorithm":"regions","from":{:?},"to":{:?}}}"#,
            segment.start.coords(),
            end.coords()
        ))
        .unwrap();
        let table = line.decisions(0, line.steps());
        for i in 0..line.steps() as usize {
            rows.push(table.columns.iter().map(|c| c[i]).collect());
        }
        builder.append(line, |_| {}).unwrap();
    }
    let direct = builder.finish("regions chords");
    let steps = trace.steps();
    assert_eq!(direct.steps(), steps);
    assert!(steps > 2 * CHECKPOINT_INTERVAL);
    for k in [1, 4095, 4096, 4097, 8192, steps - 1, steps] {
        assert_eq!(trace.point(k), direct.point(k), "point {k}");
    }
    assert_eq!(
        trace.points_flat(0, steps + 1),
        direct.points_flat(0, steps + 1)
    );
    let table = trace.decisions(4000, steps);
    for (c, column) in table.columns.iter().enumerate() {
        for (i, &v) in column.iter().enumerate() {
            let kind = trace.columns()[c].kind;
            assert!(
                common::same_cell(kind, v, rows[4000 + i][c]),
                "column {c} step {}",
                4000 + i
            );
        }
    }
}

#[test]
fn a_helix_replays_its_arc_and_linear_decisions() {
    // A full turn of r = 1000 (about 5,660 arc steps) rising 9,000 along x
    // in G19: the linear axis is major and the arc's state rides inside the
    // helix's checkpoints.
    let json = r#"{"algorithm":"helix","from":[0,1000,0],"to":[9000,1000,0],"center":[0,0,0],"plane":"yz"}"#;
    let trace = voxpath::trace_json(json).unwrap();
    assert_eq!(trace.steps(), 9000);
    let mut replayed = Vec::new();
    for k in 4090..4100 {
        replayed.push(trace.explain(k));
    }
    let whole = trace.decisions(0, trace.steps());
    let part = trace.decisions(4090, 4100);
    for (c, column) in part.columns.iter().enumerate() {
        for (i, &v) in column.iter().enumerate() {
            assert!(
                common::same_cell(trace.columns()[c].kind, v, whole.columns[c][4090 + i]),
                "column {c} step {}",
                4090 + i
            );
        }
    }
    // The explanations recomputed from the checkpoint before step 4096
    // describe the same steps as a run from the start would.
    let spec = ArcSpec::parse(&Request::from_json(json).unwrap(), true, 3).unwrap();
    let circle = SaleemCircle::new(&spec).counted(1 << 20).unwrap();
    let mut helix =
        voxpath::arc::helix::SaleemHelix::new(&spec, circle, voxpath::request::TiePolicy::Hold);
    let mut p = spec.from;
    for k in 0..4100 {
        let (step, why) = helix.next_step().unwrap();
        if k >= 4090 {
            assert_eq!(why.explain(&p, step), replayed[k - 4090]);
        }
        p.apply(step);
    }
    assert_eq!(p, trace.point(4100));
}
