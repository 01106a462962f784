//! A trace's metrics and a chart's rows made a stretch of points at a time
//! (`Trace::advance_metrics`, `Trace::advance_chart_rows`), as a worker makes
//! them to report progress and stop between slices: the values of one pass,
//! to the bit, however the points are sliced.

use voxpath::trace::Trace;

/// Traces of each way a point is measured: a line walked, an arc
/// walked, a helix point by point, chords of a helix (segments kept),
/// and a G-code program (segments made when read, lines and arcs).
fn traces() -> Vec<(&'static str, Trace)> {
    let requests = [
        r#"{"algorithm": "regions", "from": [0, 0, 0], "to": [9001, 5003, 2999]}"#,
        r#"{"algorithm": "circle", "from": [40, 0, 0], "to": [40, 0, 0], "center": [0, 0, 0], "plane": "xy", "turns": 2}"#,
        r#"{"algorithm": "helix", "from": [30, 0, 0], "to": [30, 0, 50], "center": [0, 0, 0], "plane": "xy", "turns": 3}"#,
        r#"{"algorithm": "helix", "method": "segments", "from": [30, 0, 0], "to": [30, 0, 50], "center": [0, 0, 0], "plane": "xy", "turns": 3}"#,
    ];
    let mut traces: Vec<_> = requests
        .iter()
        .map(|r| (*r, voxpath::algorithms::trace_json(r).unwrap()))
        .collect();
    let settings = voxpath::gcode::Settings::from_json(r#"{"stepsPerMm": 20}"#).unwrap();
    let program = voxpath::gcode::run("G1 X10 Y7 F600\nG2 X20 Y7 I5 J0\nG1 X0 Y0 Z3\n", settings);
    traces.push(("gcode", program.trace));
    traces
}

#[test]
fn metrics_made_in_slices_are_the_ones_of_one_pass() {
    for (name, whole) in traces() {
        for slice in [1, 7, 4096, 10_000] {
            let (_, sliced) = traces().into_iter().find(|(n, _)| *n == name).unwrap();
            let mut calls = 0;
            while !sliced.advance_metrics(slice).done {
                calls += 1;
            }
            assert!(calls > 0 || slice > whole.steps(), "{name}: sliced");
            assert_eq!(
                sliced.metrics(),
                whole.metrics(),
                "{name}, {slice} points a slice"
            );
        }
    }
}

#[test]
fn a_metrics_pass_left_halfway_is_finished_by_metrics() {
    for (name, whole) in traces() {
        let (_, sliced) = traces().into_iter().find(|(n, _)| *n == name).unwrap();
        let progress = sliced.advance_metrics(whole.steps() / 2);
        assert!(!progress.done, "{name}");
        assert_eq!(sliced.metrics(), whole.metrics(), "{name}");
    }
}

#[test]
fn chart_rows_made_in_slices_are_the_ones_of_one_pass() {
    let bits = |rows: Vec<f64>| rows.iter().map(|v| v.to_bits()).collect::<Vec<_>>();
    for (name, trace) in traces() {
        let points = trace.steps() + 1;
        for (from, to) in [(0, points), (3, points - 5)] {
            for max_rows in [1, 7, 500, points] {
                let whole = bits(trace.chart_rows(from, to, max_rows));
                for slice in [1, 9, 1000] {
                    let mut progress = trace.advance_chart_rows(from, to, max_rows, slice);
                    while !progress.done {
                        let next = trace.advance_chart_rows(from, to, max_rows, slice);
                        assert!(next.points_done > progress.points_done, "{name}");
                        progress = next;
                    }
                    assert_eq!(
                        bits(trace.take_chart_rows(from, to, max_rows)),
                        whole,
                        "{name}, points {from}..{to} in {max_rows} rows, {slice} points a slice"
                    );
                }
                // Rows begun for another chart are dropped, not mixed in.
                trace.advance_chart_rows(from, to, max_rows + 1, 1);
                assert_eq!(
                    bits(trace.take_chart_rows(from, to, max_rows)),
                    whole,
                    "{name}"
                );
            }
        }
    }
}
