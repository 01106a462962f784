//! G-code programs with final positions and pulse totals worked by hand,
//! including the arc cases other tools get wrong.
//!
//! How the pulse totals are derived: a pulse is one unit move of one axis,
//! so an axis's pulses are the total distance it travels in steps. Saleem's
//! circle moves each axis monotonically between the extreme points of the
//! rasterised circle (each octant steps its axes one way only), and when r
//! is a whole number of steps the extremes are exactly r from the center
//! (the cells (±r, 0) and (0, ±r) have error 0). So a full turn is 4r
//! pulses on each axis of the plane, and a partial arc travels from its
//! start to each extreme it passes and on to its end. A straight move along
//! an axis takes |Δ| pulses on it.

use voxpath::Point;
use voxpath::gcode::{Move, Program, Settings, run};

fn program(source: &str, settings: &str) -> Program {
    run(source, Settings::from_json(settings).unwrap())
}

/// At 10 steps per mm, so 1 mm is 10 steps.
fn at10(source: &str) -> Program {
    let p = program(source, r#"{"stepsPerMm": 10}"#);
    assert_eq!(p.info.errors, [], "{source}");
    p
}

/// Pulses per axis of one move's steps.
fn pulses(p: &Program, m: &Move) -> [u64; 3] {
    let mut out = [0; 3];
    for step in p.trace.step_range(m.first_step, m.first_step + m.steps) {
        for (axis, n) in out.iter_mut().enumerate() {
            *n += step.delta(axis).unsigned_abs();
        }
    }
    out
}

fn end(p: &Program) -> Point {
    p.trace.end()
}

#[test]
fn square() {
    // 20 mm sides at 80 steps/mm: 1600 steps per side, each along one axis.
    let p = program(
        "(square)\nG21 G90 G17\nG1 X20 Y0 F600\nY20\nX0\nY0\n",
        r#"{"stepsPerMm": 80}"#,
    );
    assert_eq!(p.info.errors, []);
    assert_eq!(p.info.pulses, [3200, 3200, 0]);
    assert_eq!(end(&p), Point::new(&[0, 0, 0]));
    let lines: Vec<(u32, u64, u64)> = p
        .moves()
        .iter()
        .map(|m| (m.line, m.first_step, m.steps))
        .collect();
    assert_eq!(
        lines,
        [
            (3, 0, 1600),
            (4, 1600, 1600),
            (5, 3200, 1600),
            (6, 4800, 1600)
        ]
    );
    assert_eq!(p.moves()[1].to_steps, [1600, 1600, 0]);
}

#[test]
fn full_circle_from_ijk_is_a_full_turn() {
    // End = start with I J is a full circle (a tool that takes the sweep as
    // end angle - start angle draws nothing). r = 10 mm = 100 steps: 4r.
    let p = at10("G0 X10\nG2 I-10 J0 F100\n");
    let circle = &p.moves()[1];
    assert_eq!((circle.kind, circle.algorithm), ("arc", "circle"));
    assert_eq!(pulses(&p, circle), [400, 400, 0]);
    assert_eq!(end(&p), Point::new(&[100, 0, 0]));
    // P3: three turns, 12r each.
    let p = at10("G0 X10\nG2 I-10 J0 P3 F100\n");
    assert_eq!(pulses(&p, &p.moves()[1]), [1200, 1200, 0]);
    assert_eq!(p.moves()[1].arc.as_ref().unwrap().extra_turns, 2);
    // As chords the corners are cut: at most 4r, ending exactly at the start.
    let p = program(
        "G0 X10\nG2 I-10 J0 F100\n",
        r#"{"stepsPerMm": 10, "arcAlgorithm": "arc-segments"}"#,
    );
    let chords = pulses(&p, &p.moves()[1]);
    assert!(
        chords[0] <= 400 && chords[1] <= 400 && chords[0] > 300,
        "{chords:?}"
    );
    assert_eq!(end(&p), Point::new(&[100, 0, 0]));
}

#[test]
fn r_over_180_degrees_takes_the_long_way() {
    // (0,0) -> (8,0) mm with |R| = 5: the center is 3 mm off the chord's
    // middle (4, 0). G2 R-5 puts it above, at (4, 3): the arc starts at
    // 216.9°, goes clockwise through 180° (x = 4 - 5 = -1), 90° (y = 8) and
    // 0° (x = 9) to -36.9°. In steps: x 0 -> -10 -> 90 -> 80 = 120 pulses,
    // y 0 -> 80 -> 0 = 160.
    let p = at10("G2 X8 Y0 R-5 F100\n");
    let m = &p.moves()[0];
    assert_eq!(m.arc.as_ref().unwrap().center_steps, Some([40, 30, 0]));
    assert_eq!(pulses(&p, m), [120, 160, 0]);
    assert_eq!(end(&p), Point::new(&[80, 0, 0]));
    // R+5: center (4, -3), the short arc over the top at y = -3 + 5 = 2:
    // x 0 -> 80, y 0 -> 20 -> 0.
    let p = at10("G2 X8 Y0 R5 F100\n");
    assert_eq!(pulses(&p, &p.moves()[0]), [80, 40, 0]);
}

#[test]
fn g18_clockwise_is_seen_from_plus_y() {
    // G18 is the ZX plane with Z first, so that it is right-handed seen from
    // +Y. From X10 Z0 (angle 90° in (z, x)) clockwise to X0 Z10 (angle 0°)
    // is a quarter turn through x > 0, z > 0: 100 pulses on each. Taking
    // (x, z) as the frame instead goes the other way round: 270°, 300 each.
    let p = at10("G0 X10\nG18 G2 X0 Z10 I-10 K0 F100\n");
    let m = &p.moves()[1];
    assert_eq!(pulses(&p, m), [100, 0, 100]);
    assert_eq!(end(&p), Point::new(&[0, 0, 100]));
    let points = p
        .trace
        .points_flat(m.first_step, m.first_step + m.steps + 1);
    assert!(points.chunks(3).all(|c| c[0] >= 0 && c[2] >= 0));
}

#[test]
fn g91_arcs_are_relative_to_where_each_starts() {
    // Each: from the top of a circle of r = 10 mm (center 10 below, J-10)
    // a clockwise quarter to its right end, 10 right and 10 down.
    let p = at10("G91 G2 X10 Y-10 I0 J-10 F100\nG2 X10 Y-10 I0 J-10\n");
    assert_eq!(p.info.pulses, [200, 200, 0]);
    assert_eq!(end(&p), Point::new(&[200, -200, 0]));
    assert_eq!(
        p.moves()[1].arc.as_ref().unwrap().center_steps,
        Some([100, -200, 0])
    );
}

#[test]
fn arcs_after_g92_use_the_new_origin() {
    // G92 X0 Y0 at machine (10, 10): program (10, 0) is machine (20, 10),
    // the center (start + (5, 0)) machine (15, 10). A clockwise half turn
    // over the top (y = 15): x 100 -> 200, y 100 -> 150 -> 100.
    for center in ["G91.1 G2 X10 Y0 I5 J0", "G90.1 G2 X10 Y0 I5 J0"] {
        let p = at10(&format!("G0 X10 Y10\nG92 X0 Y0\n{center} F100\n"));
        let m = &p.moves()[1];
        assert_eq!(
            m.arc.as_ref().unwrap().center_steps,
            Some([150, 100, 0]),
            "{center}"
        );
        assert_eq!(pulses(&p, m), [100, 100, 0], "{center}");
        assert_eq!(end(&p), Point::new(&[200, 100, 0]), "{center}");
    }
}

#[test]
fn inch_arcs_are_converted_before_rounding() {
    // G20: I0.5 is 12.7 mm = 127 steps, X1 is 25.4 mm = 254 steps. A
    // clockwise half turn from (0, 0) over the top (y = 127) to (254, 0).
    let p = at10("G20\nG2 X1 Y0 I0.5 J0 F4\n");
    assert_eq!(p.info.pulses, [254, 254, 0]);
    assert_eq!(end(&p), Point::new(&[254, 0, 0]));
    // G91 in inches: ten moves of 0.1 in are 25.4 mm, 254 steps.
    let p = at10(&format!("G20 G91\n{}", "G1 X0.1 F4\n".repeat(10)));
    assert_eq!(end(&p), Point::new(&[254, 0, 0]));
}

#[test]
fn helix_moves_the_normal_axis_during_the_turns() {
    // Two full turns (P2) of r = 100 steps while Z goes down 2 mm: 8r on x
    // and y, 20 on z, whichever way the helix is stepped.
    for arcs in ["circle", "arc-segments"] {
        let p = program(
            "G0 X10\nG3 X10 Y0 Z-2 I-10 J0 P2 F100\n",
            &format!(r#"{{"stepsPerMm": 10, "arcAlgorithm": "{arcs}"}}"#),
        );
        let m = &p.moves()[1];
        assert_eq!((m.kind, m.algorithm), ("helix", "helix"));
        let got = pulses(&p, m);
        assert_eq!(got[2], 20, "{arcs}");
        assert_eq!(end(&p), Point::new(&[100, 0, -20]), "{arcs}");
        if arcs == "circle" {
            assert_eq!(got, [800, 800, 20]);
        }
    }
}

#[test]
fn small_incremental_moves_do_not_drift() {
    // 1000 × 0.01 mm at 80 steps/mm: each is 0.8 step; rounding each
    // increment would make 1000 steps, rounding the position makes 800.
    let p = program(
        &format!("G91\n{}", "G1 X0.01 F100\n".repeat(1000)),
        r#"{"stepsPerMm": 80}"#,
    );
    assert_eq!(end(&p), Point::new(&[800, 0, 0]));
    assert_eq!(p.moves().len(), 1000);
    assert_eq!(p.moves().iter().filter(|m| m.steps == 0).count(), 200);
}

#[test]
fn rounding_is_half_away_from_zero() {
    // 0.5 mm at 3 steps/mm is exactly 1.5 steps.
    let p = program("G1 X0.5 Y-0.5 F1\n", r#"{"stepsPerMm": 3}"#);
    assert_eq!(end(&p), Point::new(&[2, -2, 0]));
}

#[test]
fn steps_per_mm_from_the_drive() {
    // Wang 3.3: 1.8° at 8 microsteps on a 2 mm screw is 800 steps/mm.
    let p = program(
        "G1 X1 Y-2 Z0.5 F1\n",
        r#"{"stepAngle": 1.8, "microsteps": 8, "pitch": 2}"#,
    );
    assert_eq!(end(&p), Point::new(&[800, -1600, 400]));
}

#[test]
fn an_arc_shorter_than_a_step_is_not_a_full_circle() {
    // The end rounds onto the start: on the grid that would read as a full
    // turn (5027 steps); the programmed sweep is 0.02°.
    let p = program(
        "G0 X10\nG3 X9.99999 Y0.004 I-10 J0 F1\n",
        r#"{"stepsPerMm": 80}"#,
    );
    let m = &p.moves()[1];
    assert_eq!((m.kind, m.steps), ("arc", 0));
    assert!(m.note.contains("stepped as a straight line"), "{}", m.note);
}

#[test]
fn rounded_ends_get_a_grid_center_within_the_arc_tolerance() {
    // At 1 step per mm, r = 10.5 about (0, 0): the start (10.5, 0) rounds to
    // (11, 0), radius 11; the end at 45° (7.4246, 7.4246) to (7, 7), radius
    // 9.90. Those differ by 1.1 steps, more than the arc algorithms accept.
    // The point of the bisector of (11, 0) and (7, 7) nearest (0, 0) is
    // (0.71, -1.24); the grid point (1, -1) has radii sqrt(101) = 10.05
    // and sqrt(100) = 10: within 1 step.
    let p = program(
        "G0 X10.5\nG3 X7.424621 Y7.424621 I-10.5 J0 F1\n",
        r#"{"stepsPerMm": 1}"#,
    );
    assert_eq!(p.info.errors, []);
    let m = &p.moves()[1];
    assert_eq!(m.arc.as_ref().unwrap().center_steps, Some([1, -1, 0]));
    assert!(
        m.note.contains("center moved to (1, -1, 0) steps"),
        "{}",
        m.note
    );
    assert_eq!(end(&p), Point::new(&[7, 7, 0]));
}

#[test]
fn errors_name_line_and_column_and_keep_the_lines_before() {
    let p = program("G1 X1 F100\nG2 X10 Y0 R4\nG1 X2\n", r#"{"stepsPerMm": 80}"#);
    assert_eq!(p.info.errors.len(), 1);
    let e = &p.info.errors[0];
    assert_eq!((e.line, e.column), (2, 11));
    assert_eq!(
        e.message,
        "R arc cannot reach its end: the end is 9.0000 mm from the start, more than 2|R| = 8.0000 mm"
    );
    assert_eq!(p.info.stopped_at_line, Some(2));
    assert_eq!(p.moves().len(), 1);
    assert_eq!(end(&p), Point::new(&[80, 0, 0]));

    let first = |source: &str| {
        let p = program(source, r#"{"stepsPerMm": 80}"#);
        let e = &p.info.errors[0];
        (e.line, e.column, e.message.clone())
    };
    assert_eq!(
        first("G0 X5\nG2 X10 Y0 I3 J0\n"),
        (2, 11, "the arc's end is 2.0000 mm from its center but its start is 3.0000 mm: the radii differ by 1.0000 mm, more than the tolerance (0.0283 mm and 0.1% of the radius)".to_string())
    );
    assert_eq!(
        first("G2 X10 I0 J0\n"),
        (
            1,
            8,
            "zero-radius arc: the center is at the arc's start".to_string()
        )
    );
    assert_eq!(
        first("G1 X1 F1\nG92\n"),
        (
            2,
            1,
            "missing axis word: G92 sets the current position to X, Y and/or Z; give at least one"
                .to_string()
        )
    );
    assert_eq!(
        first("G1 X1 F1\nY2\nG1 X1..5\n"),
        (3, 7, "malformed number: '.5' belongs to no letter (a second decimal point, or a missing address letter?)".to_string())
    );
}

#[test]
fn syntax_errors_after_the_first_error_are_listed_too() {
    let p = program(
        "G1 X1 F1\nG2 X5 R1\nG2 X100 R1\nG1 Y-\n",
        r#"{"stepsPerMm": 80}"#,
    );
    let at: Vec<(u32, u32)> = p.info.errors.iter().map(|e| (e.line, e.column)).collect();
    // Line 3's R error depends on the state, which is unknown after line 2;
    // line 4's syntax error does not.
    assert_eq!(at, [(2, 7), (4, 4)]);
    assert_eq!(p.info.stopped_at_line, Some(2));
}

#[test]
fn arcs_need_equal_steps_per_mm_in_their_plane() {
    let p = program(
        "G0 X10\nG18 G2 X0 Z10 I-10\n",
        r#"{"stepsPerMm": [80, 80, 400]}"#,
    );
    let e = &p.info.errors[0];
    assert_eq!((e.line, e.column), (2, 5));
    assert!(e.message.starts_with("G2 in the zx plane (G18), seen from +y: Z and X have different steps per mm (400 and 80)"), "{}", e.message);
    // G17 helices are fine: z is the linear axis, only counted.
    let p = program(
        "G0 X10\nG2 X10 Y0 Z-1 I-10\n",
        r#"{"stepsPerMm": [80, 80, 400]}"#,
    );
    assert_eq!(p.info.errors, []);
    assert_eq!(end(&p), Point::new(&[800, 0, -400]));
}

#[test]
fn decision_columns_of_every_algorithm_pair_have_distinct_names() {
    for line in voxpath::arc::arc_segments::LINE_ALGORITHMS {
        for arcs in ["circle", "arc-segments"] {
            let p = program(
                "G0 X10 Y3 Z1\nG1 X10 Y0 Z0 F1\nG2 I-10\nG2 X-10 Z-3 I-10\n",
                &format!(
                    r#"{{"stepsPerMm": 10, "lineAlgorithm": "{line}", "arcAlgorithm": "{arcs}"}}"#
                ),
            );
            assert_eq!(p.info.errors, [], "{line} {arcs}");
            let names: Vec<&str> = p.trace.columns().iter().map(|c| c.name).collect();
            let mut unique = names.clone();
            unique.sort();
            unique.dedup();
            assert_eq!(unique.len(), names.len(), "{line} {arcs}: {names:?}");
        }
    }
}

#[test]
fn segment_notes_name_the_line_and_the_move() {
    let p = at10("G0 X1\nG1 Y1 F10\nG2 X0 Y2 I-1\n");
    for m in &p.moves() {
        for s in m.first_segment..m.first_segment + m.segments {
            let note = p.trace.segment_note(s);
            assert!(
                note.starts_with(&format!("Line {}, {}:", m.line, m.code)),
                "{note}"
            );
        }
    }
    assert!(p.trace.segment_note(0).contains("a rapid, stepped like G1"));
    assert_eq!(p.moves()[0].kind, "rapid");
}

#[test]
fn lines_are_counted_as_an_editor_counts_them() {
    // A final newline ends the last line; it does not start another.
    for (source, lines) in [
        ("G1 X1 F100\nX2\n", 2),
        ("G1 X1 F100\nX2", 2),
        ("G1 X1 F100\n\n", 2),
        ("", 1),
    ] {
        assert_eq!(
            program(source, r#"{"stepsPerMm": 10}"#).info.lines,
            lines,
            "{source:?}"
        );
    }
}

#[test]
fn a_percent_line_opens_the_program_and_the_next_one_ends_it() {
    // `%` was skipped wherever it stood, so the lines after a closing `%`
    // ran. Grbl has no `%` (protocol.c: "TODO: Install '%' feature";
    // gc_execute_line fails on it, error 1); voxpath reads LinuxCNC's
    // rule: a `%` line before the program opens it, the next one ends it.
    let p = at10("%\nG1 X1 F100\n%\nG1 X5\n(more)\nG1 X9\n");
    assert_eq!(p.moves().len(), 1);
    assert_eq!(end(&p), Point::new(&[10, 0, 0]));
    let warned: Vec<(u32, u32, &str)> = p
        .info
        .warnings
        .iter()
        .map(|w| (w.line, w.column, w.message.as_str()))
        .collect();
    assert_eq!(
        warned,
        [(
            3,
            1,
            "% ends the program: the 3 lines after it are not read (a program stands between two % lines, as in LinuxCNC)"
        )]
    );
    // Not even for their syntax; and a `%` after the program's first
    // codes ends it too. Blank lines after the end are no warning.
    let p = at10("(header)\nG1 X1 F100\n %\nG1 X1..5\n");
    assert_eq!(p.moves().len(), 1);
    assert_eq!(
        p.info.warnings[0].message.split(':').next(),
        Some("% ends the program")
    );
    assert_eq!((p.info.warnings[0].line, p.info.warnings[0].column), (3, 2));
    let p = at10("%\nG1 X1 F100\n%\n\n");
    assert_eq!((p.moves().len(), p.info.warnings.len()), (1, 0));
    // Only the lines that hold anything are counted as not read.
    let p = at10("%\nG1 X1 F100\n%\n\nG1 X2\n\n\nG1 X3\n");
    assert_eq!(
        p.info.warnings[0].message,
        "% ends the program: the 2 lines after it are not read (a program stands between two % lines, as in LinuxCNC)"
    );
    // Lines ended by a lone CR are counted as the program's lines are.
    let p = at10("%\rG1 X1 F100\r%\rG1 X2\r\rG1 X3\r");
    assert!(
        p.info.warnings[0]
            .message
            .starts_with("% ends the program: the 2 lines after it"),
        "{}",
        p.info.warnings[0].message
    );
    // A closing `%` with more on its line is that line's error, which stops
    // the program there (it ended the program without a word).
    let p = program("G1 X1 F100\n% G0 X5\nG1 X2\n", r#"{"stepsPerMm": 10}"#);
    assert_eq!(p.moves().len(), 1);
    assert!(p.info.warnings.is_empty(), "{:?}", p.info.warnings);
    assert_eq!((p.info.errors[0].line, p.info.errors[0].column), (2, 3));
    assert!(
        p.info.errors[0]
            .message
            .contains("nothing but blanks and comments may follow it"),
        "{}",
        p.info.errors[0].message
    );
}
