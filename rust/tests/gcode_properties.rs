//! Property: a program of straight moves in G90 ends every move exactly on
//! its target rounded to steps, however many moves come before (no drift),
//! with every line algorithm.

mod common;

use proptest::prelude::*;
use voxpath::Point;
use voxpath::gcode::{Settings, run};

/// numerator / denominator (denominator > 0) rounded to a whole number,
/// halves away from zero, in integers: the steps a decimal target means.
fn exact_steps(numerator: i128, denominator: i128) -> i64 {
    let (quotient, remainder) = (numerator / denominator, numerator % denominator);
    let away = i128::from(2 * remainder.abs() >= denominator) * numerator.signum();
    i64::try_from(quotient + away).unwrap()
}

/// Thousandths of a mm, within ±500 mm.
fn micro() -> impl Strategy<Value = i64> {
    -500_000i64..=500_000
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn g90_moves_end_on_their_rounded_targets(
        tenths_per_mm in 10u32..=2000,
        targets in prop::collection::vec((micro(), micro(), micro()), 1..12),
        line in prop::sample::select(voxpath::arc::arc_segments::LINE_ALGORITHMS),
    ) {
        let steps_per_mm = tenths_per_mm as f64 / 10.0;
        let mut source = String::from("G90 G21\n");
        let mut expected = Vec::new();
        for &(x, y, z) in &targets {
            let text = [x, y, z].map(|v| format!("{:.3}", v as f64 / 1000.0));
            source.push_str(&format!("G1 X{} Y{} Z{} F500\n", text[0], text[1], text[2]));
            // The value as written, times steps per mm, halves away from 0,
            // in exact decimals: thousandths times tenths, in ten-thousandths.
            expected.push([x, y, z].map(|v| exact_steps(v as i128 * tenths_per_mm as i128, 10_000)));
        }
        let settings = Settings::from_json(&format!(
            r#"{{"stepsPerMm": {steps_per_mm}, "lineAlgorithm": "{line}"}}"#
        )).unwrap();
        let p = run(&source, settings);
        prop_assert_eq!(&p.info.errors, &vec![]);
        prop_assert_eq!(p.moves().len(), targets.len());
        for (m, want) in p.moves().iter().zip(&expected) {
            prop_assert_eq!(m.to_steps, *want);
            // Where the trace really is after the move's last step.
            prop_assert_eq!(p.trace.point(m.first_step + m.steps), Point::new(want));
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// A target whose decimals make an exact half of a step (1.005 mm at
    /// 100 steps/mm, 100.5 steps) goes away from zero, in mm and in inches
    /// (25.4 mm each), though the double nearest the decimals may make it
    /// a hair less: the rounding is that of the decimals themselves.
    #[test]
    fn decimal_targets_round_as_their_decimals_do(
        value in -99_999_999i64..=99_999_999,
        decimals in 0u32..=4,
        steps_per_mm in prop::sample::select(vec!["80", "100", "12.5", "400", "3", "78.74", "1000", "6.4"]),
        inches: bool,
    ) {
        let scale = 10i128.pow(decimals);
        // steps/mm as an integer over a power of ten.
        let spm_decimals = steps_per_mm.split_once('.').map_or(0, |(_, f)| f.len() as u32);
        let spm_whole: i128 = steps_per_mm.replace('.', "").parse().unwrap();
        let (inch_numerator, inch_denominator) = if inches { (254, 10) } else { (1, 1) };
        let denominator = scale * 10i128.pow(spm_decimals) * inch_denominator;
        // A move within maxSteps' default, stepped in a moment (halves near
        // 2^30 are the rounding's own unit property, in machine.rs): the
        // value is taken modulo the most that keeps it to 4,000,000 steps,
        // not refused past it (refused, three draws in four were, and 256
        // cases ran past proptest's 1,024 rejects about once in 800 runs).
        let most = 4_000_000 * denominator / (spm_whole * inch_numerator);
        let value = value as i128 % (most + 1);
        let text = format!("{}{}.{:0width$}", if value < 0 { "-" } else { "" }, value.abs() / scale, value.abs() % scale, width = decimals as usize);
        let want = exact_steps(value * spm_whole * inch_numerator, denominator);
        prop_assert!(want.abs() <= 4_000_000);
        let source = format!("{} G1 X{text} F500\n", if inches { "G20" } else { "G21" });
        let p = run(&source, Settings::from_json(&format!(r#"{{"stepsPerMm": {steps_per_mm}}}"#)).unwrap());
        prop_assert_eq!(&p.info.errors, &vec![], "{}", source);
        prop_assert_eq!(p.moves()[0].to_steps[0], want, "{}", source);
    }

    /// Targets that are exactly k + 1/2 steps, written as the decimals
    /// that say so (k + 1/2 over steps/mm, where that ends): k + 1 steps,
    /// away from zero, whichever side of the half the doubles land.
    #[test]
    fn decimal_halves_go_away_from_zero(
        k in 0i64..4_000_000,
        negative: bool,
        (spm_whole, spm_decimals) in prop::sample::select(vec![(100i128, 0u32), (1000, 0), (80, 0), (125, 1), (400, 0), (64, 1), (25, 0), (200, 0)]),
    ) {
        // mm = (2k + 1) / 2 / (spm_whole / 10^spm_decimals), in the fewest
        // decimals that hold it exactly (each steps/mm here is 2^a 5^b).
        let (numerator, denominator) = ((2 * k as i128 + 1) * 10i128.pow(spm_decimals), 2 * spm_whole);
        let digits = (0..12).find(|&d| numerator * 10i128.pow(d) % denominator == 0).unwrap();
        let scaled = numerator * 10i128.pow(digits) / denominator;
        let scale = 10i128.pow(digits);
        let text = format!("{}{}.{:0width$}", if negative { "-" } else { "" }, scaled / scale, scaled % scale, width = digits as usize);
        let steps_per_mm = spm_whole as f64 / 10f64.powi(spm_decimals as i32);
        let source = format!("G1 X{text} F500\n");
        let p = run(&source, Settings::from_json(&format!(r#"{{"stepsPerMm": {steps_per_mm}}}"#)).unwrap());
        prop_assert_eq!(&p.info.errors, &vec![], "{}", source);
        let want = if negative { -(k + 1) } else { k + 1 };
        prop_assert_eq!(p.moves()[0].to_steps[0], want, "{}", source);
    }
}

/// One line of a random program: a straight move, an arc by its center or
/// its radius (helical or not, with extra turns), or a line that does not
/// move; coordinates in hundredths of a mm.
fn program_line() -> impl Strategy<Value = String> {
    let mm = || (-3000i64..=3000).prop_map(|v| format!("{:.2}", v as f64 / 100.0));
    prop_oneof![
        (prop::sample::select(vec!["G0", "G1"]), mm(), mm(), mm())
            .prop_map(|(g, x, y, z)| format!("{g} X{x} Y{y} Z{z} F{}", 300)),
        (
            prop::sample::select(vec!["G2", "G3"]),
            mm(),
            mm(),
            mm(),
            mm(),
            0u32..3
        )
            .prop_map(|(g, x, y, i, j, p)| format!("{g} X{x} Y{y} I{i} J{j} P{}", p + 1)),
        (
            prop::sample::select(vec!["G2", "G3"]),
            mm(),
            mm(),
            mm(),
            mm()
        )
            .prop_map(|(g, x, y, z, r)| format!("{g} X{x} Y{y} Z{z} R{r}")),
        Just("G4 P0.1".to_string()),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// A run keeps each move as a compact record and builds what users
    /// read from it on demand: the decoded move says what the run did. Its
    /// steps and segments are where the trace has them, its note is how the
    /// run's own segment notes begin (they were written from the move as
    /// it was stepped), its ends are the trace's points, its timing the
    /// plan's, its lookups agree with a scan.
    #[test]
    fn decoded_moves_are_what_the_run_stepped(
        lines in prop::collection::vec(program_line(), 1..16),
        steps_per_mm in prop::sample::select(vec![1.0, 3.0, 10.0, 80.0]),
        arcs in prop::sample::select(voxpath::gcode::program::ARC_ALGORITHMS),
    ) {
        let source = format!("G21 G90 G17 F600\n{}\n", lines.join("\n"));
        let settings = Settings::from_json(&format!(
            r#"{{"stepsPerMm": {steps_per_mm}, "arcAlgorithm": "{arcs}"}}"#
        )).unwrap();
        let p = run(&source, settings);
        let moves = p.moves();
        prop_assert_eq!(moves.len(), p.info.move_count);
        // The bounds, taken by stretches between the moves' starts: each
        // axis's extremes over every point.
        let points = p.trace.points_flat(0, p.trace.steps() + 1);
        let column = |axis: usize| points.iter().skip(axis).step_by(3).copied();
        let bounds = p.trace.bounds();
        prop_assert_eq!(bounds.min, (0..3).map(|a| column(a).min().unwrap()).collect::<Vec<_>>());
        prop_assert_eq!(bounds.max, (0..3).map(|a| column(a).max().unwrap()).collect::<Vec<_>>());
        let mut next_step = 0;
        let mut next_segment = 0;
        for (index, m) in moves.iter().enumerate() {
            prop_assert_eq!((m.first_step, m.first_segment), (next_step, next_segment));
            next_step += m.steps;
            next_segment += m.segments;
            prop_assert_eq!(p.trace.point(m.first_step), Point::new(&m.from_steps));
            prop_assert_eq!(p.trace.point(m.first_step + m.steps), Point::new(&m.to_steps));
            let prefix = format!("Line {}, {}: ", m.line, m.code);
            prop_assert!(m.note.starts_with(&prefix), "{}", m.note);
            for s in m.first_segment..m.first_segment + m.segments {
                let note = p.trace.segment_note(s);
                prop_assert!(note.starts_with(&format!("{} ", m.note)), "{} / {}", m.note, note);
            }
            prop_assert_eq!(m.timing, p.timeline.move_timing(index));
            prop_assert_eq!(m.arc.is_some(), m.code == "G2" || m.code == "G3");
            prop_assert_eq!(m.feed_mm_per_min.is_none(), m.code == "G0");
            prop_assert_eq!(
                m.kind,
                match (m.code, m.arc.as_ref().map(|a| a.center_steps)) {
                    ("G0", _) => "rapid",
                    ("G1", _) => "line",
                    _ if m.from_steps[2] != m.to_steps[2] => "helix",
                    _ => "arc",
                }
            );
            let stepped_as_line = m.arc.as_ref().is_some_and(|a| a.center_steps.is_none())
                || m.note.contains("so it is stepped as a straight line");
            prop_assert_eq!(
                m.algorithm,
                match m.kind {
                    "rapid" | "line" => "regions",
                    _ if stepped_as_line => "regions",
                    "helix" => "helix",
                    _ => arcs,
                }
            );
            prop_assert_eq!(p.records.move_at_line(m.line), Some(index));
            prop_assert_eq!(p.records.first_step_from_line(m.line), Some(m.first_step));
            if m.steps > 0 {
                prop_assert_eq!(p.records.move_of_step(m.first_step + m.steps - 1), Some(index));
            }
        }
        prop_assert_eq!(next_step, p.info.steps);
        prop_assert_eq!(next_segment, p.trace.segment_count());
        let by_scan: Vec<u32> = moves
            .iter()
            .flat_map(|m| std::iter::repeat_n(m.line, m.steps as usize))
            .collect();
        let line_by_step = |from: u64, to: u64| {
            let mut out = Vec::new();
            p.records.push_line_by_step(from, to, &mut out);
            out
        };
        prop_assert_eq!(line_by_step(0, p.info.steps), by_scan.clone());
        let (from, to) = (p.info.steps / 3, p.info.steps * 2 / 3);
        prop_assert_eq!(
            line_by_step(from, to),
            by_scan[from as usize..to as usize].to_vec()
        );
        prop_assert_eq!(p.records.move_of_step(p.info.steps), None);
        prop_assert_eq!(p.records.move_at_line(1), None);
    }

    /// Steps are recorded without their decisions: the metrics count the
    /// ties by replaying the segments (made when read, with the lines',
    /// arcs' and helices' steppers), which must find the ones the
    /// decisions record, whole or in slices.
    #[test]
    fn the_metrics_count_the_ties_the_decisions_record(
        lines in prop::collection::vec(program_line(), 1..16),
        steps_per_mm in prop::sample::select(vec![1.0, 3.0, 10.0, 80.0]),
        line in prop::sample::select(voxpath::arc::arc_segments::LINE_ALGORITHMS),
        arcs in prop::sample::select(voxpath::gcode::program::ARC_ALGORITHMS),
        parts in 1u64..12,
    ) {
        let source = format!("G21 G90 G17 F600\n{}\n", lines.join("\n"));
        let settings = format!(
            r#"{{"stepsPerMm": {steps_per_mm}, "lineAlgorithm": "{line}", "arcAlgorithm": "{arcs}"}}"#
        );
        let trace = || run(&source, Settings::from_json(&settings).unwrap()).trace;
        common::check_ties(trace, parts)
            .map_err(|e| TestCaseError::fail(format!("{settings}\n{source}: {e}")))?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// A program's trace reads as its replay, as a trace of one request
    /// does (common::check_trace): every point and any range of them, whole
    /// and a chunk at a time, against its step codes applied one by one;
    /// the bounds against those points' extremes; each point's deviation
    /// and per-axis error, measured incrementally along its move's segment,
    /// against measuring it on its own, and the metrics they add up to.
    /// Moves of no steps, dwells, arcs with extra turns and helices in each
    /// arc algorithm included; every segment is made again when read.
    #[test]
    fn a_program_reads_as_its_replay(
        lines in prop::collection::vec(program_line(), 1..16),
        steps_per_mm in prop::sample::select(vec![1.0, 3.0, 10.0, 80.0]),
        line in prop::sample::select(voxpath::arc::arc_segments::LINE_ALGORITHMS),
        arcs in prop::sample::select(voxpath::gcode::program::ARC_ALGORITHMS),
        range in (0u64..40_000, 0u64..40_000),
        chunk in 1usize..3000,
    ) {
        let source = format!("G21 G90 G17 F600\n{}\n", lines.join("\n"));
        let settings = format!(
            r#"{{"stepsPerMm": {steps_per_mm}, "lineAlgorithm": "{line}", "arcAlgorithm": "{arcs}"}}"#
        );
        // A line the program refuses (an arc of no radius) ends the run
        // there: the trace of the lines before it reads the same way.
        let p = run(&source, Settings::from_json(&settings).unwrap());
        common::check_trace(&p.trace, range, chunk)
            .map_err(|e| TestCaseError::fail(format!("{settings}\n{source}: {e}")))?;
    }
}

/// A program that makes no move (a dwell, a comment, nothing) has one
/// point and no segment, so no path: its deviation and per-axis error are
/// 0, one value for the point and one per axis, as every read of a range
/// gives one per point (they were none, and a JS array read them as the
/// zeros it was made with).
#[test]
fn a_program_of_no_move_reads_one_point_on_no_path() {
    for source in ["", "G4 P0.1\n", "(nothing)\n"] {
        let p = run(
            source,
            Settings::from_json(r#"{"stepsPerMm": 80}"#).unwrap(),
        );
        assert_eq!(
            (p.trace.steps(), p.trace.segment_count()),
            (0, 0),
            "{source:?}"
        );
        assert_eq!(p.trace.deviation_range(0, 1), vec![0.0]);
        assert_eq!(p.trace.axis_error_range(0, 1), vec![0.0; 3]);
        assert_eq!(p.trace.metrics().max_deviation, 0.0);
    }
}
