//! A program's timing end to end (`gcode::timing` under `gcode::run`):
//! motion times worked from the trapezoid profile, moves that join in time,
//! and the warnings of a feed or a step rate out of range. Here rather than
//! beside `timing`, which `run`'s file imports.

use voxpath::gcode::{Settings, run};

fn settings(extra: &str) -> Settings {
    Settings::from_json(&format!(
        r#"{{"stepsPerMm": 80, "acceleration": 100, "maxRate": 6000{extra}}}"#
    ))
    .unwrap()
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * (1.0 + a.abs().max(b.abs()))
}

#[test]
fn the_issues_example_takes_three_seconds() {
    // G1 X200 F6000 at 80 steps/mm and 100 mm/s², from rest: 1 s up to
    // 100 mm/s over 50 mm, 1 s at 100 mm/s, 1 s down (see
    // voxpath::planner's test trapezoid_from_rest_to_rest).
    let program = run("G1 X200 F6000\n", settings(""));
    assert!(close(program.info.duration_seconds, 3.0));
    let t = program.moves()[0].timing;
    assert!(close(t.cruise_speed, 100.0) && t.entry_speed == 0.0 && t.exit_speed == 0.0);
    // The 400th step (index 399) at 5 mm: s = ½at², t = √(2·5/100).
    let times = program.timeline.step_seconds(399, 400);
    assert!(close(times[0], (2.0f64 * 5.0 / 100.0).sqrt()));
    let all = program.timeline.step_seconds(0, 16_000);
    assert_eq!(all.len(), 16_000);
    assert!(close(all[15_999], 3.0));
    assert!(all.windows(2).all(|w| w[0] < w[1]));
}

#[test]
fn moves_join_in_time_and_ranges_cross_moves() {
    let program = run("G0 X10\nG1 Y10 F600\nG2 X20 Y0 I5 J-5\n", settings(""));
    let moves = &program.moves();
    for pair in moves.windows(2) {
        assert_eq!(pair[0].timing.end_seconds, pair[1].timing.start_seconds);
    }
    let end = moves.last().unwrap().timing.end_seconds;
    assert!(close(end, program.info.duration_seconds));
    let steps = program.info.steps;
    let all = program.timeline.step_seconds(0, steps);
    let part = program.timeline.step_seconds(700, 900);
    assert_eq!(&all[700..900], &part[..]);
    // The arc is planned through Grbl's chords, at most F.
    assert!(moves[2].timing.cruise_speed <= 10.0 + 1e-9);
}

#[test]
fn no_feed_and_step_rate_are_warnings_on_their_line() {
    let program = run("G1 X10\n", settings(r#", "maxStepRate": 2000"#));
    let messages: Vec<(u32, String)> = program
        .info
        .warnings
        .iter()
        .map(|w| (w.line, w.message.clone()))
        .collect();
    assert!(messages[0].1.contains("error 22"), "{messages:?}");
    // Timed at the top rate, 100 mm/s, but 10 mm at 100 mm/s² peak at
    // √(100·10) = 31.6 mm/s (a triangle: v² = 2a·5 mm from rest): at
    // 80 steps/mm, 2530 steps/s on X, where the nominal 100 mm/s would be 8000.
    let peak_steps_per_s = 80.0 * (100.0f64 * 10.0).sqrt();
    assert_eq!(format!("{peak_steps_per_s:.0}"), "2530");
    assert!(
        messages[1].1.starts_with(
            "X would step at 2530 steps/s at the planned speed, more than maxStepRate = 2000 steps/s"
        ),
        "{messages:?}"
    );
    assert_eq!(messages[1].0, 1);
}

#[test]
fn a_feed_above_the_max_rate_is_capped_with_a_warning_once_per_feed() {
    // Grbl's default $110 = 500 mm/min: F6000 runs at 500 mm/min (Grbl's
    // plan_buffer_line takes min(F, the direction's top rate)), so 200 mm
    // at 8.33 mm/s and 100 mm/s² takes 200/v + v/a = 24.083 s.
    let program = run(
        "G1 X200 F6000\nG1 X0\nG1 X100 F400\nG1 X0 F7000\n",
        Settings::from_json(r#"{"stepsPerMm": 80, "acceleration": 100}"#).unwrap(),
    );
    let v = 500.0 / 60.0;
    let first = program.moves()[0].timing;
    assert!(close(first.end_seconds, 200.0 / v + v / 100.0), "{first:?}");
    let warned: Vec<(u32, &str)> = program
        .info
        .warnings
        .iter()
        .map(|w| (w.line, w.message.as_str()))
        .collect();
    // Line 2 runs at the same F6000 and line 3 below the top: no repeat.
    assert_eq!(warned.len(), 2, "{warned:?}");
    assert_eq!(warned[0].0, 1);
    assert!(
        warned[0]
            .1
            .starts_with("F6000 mm/min is above the max rate along this move (500 mm/min")
    );
    assert_eq!(warned[1].0, 4);
    assert!(warned[1].1.starts_with("F7000 mm/min"));
    // An arc's chords are capped only where their direction's top rate is
    // below F (the warning said the arc "runs at 500 mm/min"; its diagonal
    // chords ran at 600), and a top below Grbl's MINIMUM_FEED_RATE runs at 1
    // mm/min (it said 0).
    let at_max_rate = |max_rate: &str| {
        Settings::from_json(&format!(
            r#"{{"stepsPerMm": 80, "acceleration": 100, "maxRate": {max_rate}}}"#
        ))
        .unwrap()
    };
    let arc = run("G1 F600\nG2 X20 Y0 I10 J0\n", at_max_rate("500"));
    assert!(
        arc.info.warnings[0].message.starts_with(
            "F600 mm/min is above the max rate along parts of this arc (down to 500 mm/min"
        ),
        "{:?}",
        arc.info.warnings
    );
    let slow = run("G1 X1 F100\n", at_max_rate("1e-300"));
    assert!(
        slow.info.warnings[0]
            .message
            .contains("it runs at 1 mm/min"),
        "{:?}",
        slow.info.warnings
    );
    // At maxRate 6000 the same line runs at its F, silently.
    assert!(
        run("G1 X200 F6000\n", settings(""))
            .info
            .warnings
            .is_empty()
    );
}

/// Grbl synchronises its buffer (`protocol_buffer_synchronize`) before a
/// dwell (`mc_dwell`), a spindle change (`spindle_sync`), a new spindle
/// speed while it turns (`spindle_sync` again), and a coolant change
/// (`coolant_sync`): the machine comes to rest, waits out the dwell, and
/// starts again from rest. Only a change stops it: gc_execute_line's steps
/// 4, 7 and 8 compare the block's spindle, speed and coolant with the
/// state's. At Grbl's defaults (10 mm/s², 500 mm/min) a 10 mm move at F500
/// from rest to rest takes 2v/a + (L - v²/a)/v = 1.6667 + 0.3667 = 2.0333 s
/// (v = 25/3 mm/s); three of them in a line joined at full speed, one 30 mm
/// trapezoid, 4.4333 s (which voxpath gave with M3 and M5 between them,
/// taking them for nothing).
#[test]
fn a_dwell_a_spindle_or_a_coolant_change_stops_the_machine_as_grbl_does() {
    let defaults = Settings::from_json(r#"{"stepsPerMm": 80}"#).unwrap();
    let rest_to_rest =
        2.0 * (25.0 / 3.0) / 10.0 + (10.0 - (25.0f64 / 3.0).powi(2) / 10.0) / (25.0 / 3.0);
    let joined_seconds =
        2.0 * (25.0 / 3.0) / 10.0 + (30.0 - (25.0f64 / 3.0).powi(2) / 10.0) / (25.0 / 3.0);
    let joined = run("G1 X10 F500\nX20\nX30\n", defaults.clone());
    assert!(close(joined.info.duration_seconds, joined_seconds));
    // Two changes between the three moves: two stops.
    for (first, second) in [
        ("M3 S1000", "M5"),
        ("M4", "M3"),
        ("M8", "M9"),
        ("M7", "M8"),
        ("G4 P0", "G4 P0"),
        ("M3 S1000", "S2000"),
    ] {
        let program = run(
            &format!("G1 X10 F500\n{first}\nX20\n{second}\nX30\n"),
            defaults.clone(),
        );
        assert!(
            close(program.info.duration_seconds, 3.0 * rest_to_rest),
            "{first}, {second}: {}",
            program.info.duration_seconds
        );
        for m in program.moves() {
            assert_eq!(
                (m.timing.entry_speed, m.timing.exit_speed),
                (0.0, 0.0),
                "{first}, {second}"
            );
        }
    }
    // What changes nothing stops nothing: the spindle or coolant as it
    // is, the same speed again, a speed while the spindle is off (it was
    // two stops, for M5 or M9 with nothing on).
    for (first, second) in [
        ("M5", "M9"),
        ("S1000", "S2000"),
        ("M3 S1000\nM3", "S1000"),
        ("M8\nM8", "M8"),
    ] {
        let lead = first.rsplit_once('\n').map_or("", |(lead, _)| lead);
        let line = first.rsplit_once('\n').map_or(first, |(_, line)| line);
        let program = run(
            &format!("{lead}\nG1 X10 F500\n{line}\nX20\n{second}\nX30\n"),
            defaults.clone(),
        );
        assert!(
            close(program.info.duration_seconds, joined_seconds),
            "{first}, {second}: {}",
            program.info.duration_seconds
        );
    }
    // A pause or the program's end comes to rest after its line's motion
    // (gc_execute_line's step 21, after step 20's): on the move's line as on
    // the line after it. The move before joins it at full speed (it came
    // to rest before the move, at X10, then passed X30 at 14.14 mm/s).
    for flow in ["M0", "M2", "M30"] {
        let on_the_line = run(&format!("G1 X10 F500\nX30 {flow}\nX31\n"), defaults.clone());
        let after = run(
            &format!("G1 X10 F500\nX30\n{flow}\nX31\n"),
            defaults.clone(),
        );
        let speeds = |p: &voxpath::gcode::Program| -> Vec<(f64, f64)> {
            p.moves()
                .iter()
                .map(|m| (m.timing.entry_speed, m.timing.exit_speed))
                .collect()
        };
        assert_eq!(speeds(&on_the_line), speeds(&after), "{flow}");
        assert_eq!(speeds(&on_the_line)[0], (0.0, 25.0 / 3.0), "{flow}");
        assert_eq!(speeds(&on_the_line)[1].1, 0.0, "{flow}");
    }
    // The end turns the spindle off: M3 after it is a change again.
    let restarted = run(
        "M3 S1000\nG1 X10 F500\nM2\nX20\nM3\nX30\n",
        defaults.clone(),
    );
    assert!(close(restarted.info.duration_seconds, 3.0 * rest_to_rest));
    // G4 P1: a second at rest between the moves, its steps after it.
    let dwell = run("G1 X10 F500\nG4 P1\nX20\n", defaults.clone());
    assert!(close(dwell.info.duration_seconds, 2.0 * rest_to_rest + 1.0));
    let moves = dwell.moves();
    assert!(close(
        moves[1].timing.start_seconds,
        moves[0].timing.end_seconds + 1.0
    ));
    let steps = dwell.timeline.step_seconds(0, dwell.info.steps);
    // Step 799 ends the first move; step 800, the first of the next, comes
    // after the wait and 1/80 mm from rest: √(2s/a) = √(2 · 0.0125 / 10) = 0.05 s.
    assert!(close(steps[800] - steps[799], 1.0 + 0.05));
    assert!(steps.windows(2).all(|w| w[0] <= w[1]));
    // At the end too, and on the line of a move, before it (gcode.c runs the dwell first).
    assert!(close(
        run("G1 X10 F500\nG4 P2\n", defaults.clone())
            .info
            .duration_seconds,
        rest_to_rest + 2.0
    ));
    assert!(close(
        run("G1 X10 F500\nG4 P1.5 X20\n", defaults.clone())
            .info
            .duration_seconds,
        2.0 * rest_to_rest + 1.5
    ));
    // Grbl refuses G4 without P (error 28) and a negative P.
    let missing = run("G4\n", defaults.clone());
    assert_eq!(
        (missing.info.errors[0].line, missing.info.errors[0].column),
        (1, 1)
    );
    assert!(
        missing.info.errors[0]
            .message
            .starts_with("G4 (dwell) needs P")
    );
    let negative = run("G4 P-1\n", defaults);
    assert_eq!(negative.info.errors[0].column, 4);
}

#[test]
fn limits_are_read_by_name() {
    let e = Settings::from_json(r#"{"stepsPerMm": 80, "maxRate": [1, 2]}"#).unwrap_err();
    assert_eq!(
        e.to_string(),
        "maxRate: expected one number or 3 (x, y, z), got 2"
    );
}

#[test]
fn the_point_reached_at_an_instant_counts_the_steps_at_or_before_it() {
    // G1 X200 F6000 from rest at 100 mm/s²: step k (0-based) at
    // s = (k + 1) / 80 mm, at t = √(2s/a) while accelerating; so by t
    // the machine has taken ⌊t²·a/2·80⌋ steps: 400 by √(2·5/100) s.
    let program = run("G1 X200 F6000\n", settings(""));
    let t = &program.timeline;
    assert_eq!(t.points_reached_at(-1.0), 0);
    assert_eq!(t.points_reached_at(0.0), 0);
    let at = (2.0f64 * 5.0 / 100.0).sqrt();
    assert_eq!(t.points_reached_at(at), 400);
    assert_eq!(t.points_reached_at(at * (1.0 - 1e-9)), 399);
    assert_eq!(t.points_reached_at(0.2501), 250);
    assert_eq!(t.points_reached_at(3.0), 16_000);
    assert_eq!(t.points_reached_at(1e9), 16_000);
    // Agrees with the instants at every step of a program with arcs.
    let program = run("G0 X10\nG1 Y10 F600\nG2 X20 Y0 I5 J-5\n", settings(""));
    let t = &program.timeline;
    let all = t.step_seconds(0, program.info.steps);
    for (k, &s) in all.iter().enumerate().step_by(37) {
        let reached = t.points_reached_at(s) as usize;
        assert!(reached > k && all[reached - 1] <= s, "{k}");
        assert!(reached == all.len() || all[reached] > s, "{k}");
    }
}

#[test]
fn a_programs_pulses_are_counted_from_its_steps_as_the_metrics_count_them() {
    // The record counts pulses without the metrics' deviation pass; the
    // counts must be the metrics' own, on lines and arcs in both directions.
    let program = run(
        "G0 X10\nG1 Y10 Z-3 F600\nG2 X20 Y0 I5 J-5\nG3 X10 Y10 R7\n",
        settings(""),
    );
    let pulses = program.info.pulses.clone();
    assert_eq!(pulses, program.trace.metrics().pulses_by_axis);
    assert_eq!(program.trace.pulses_by_axis(), pulses);
    assert!(pulses.iter().all(|&p| p > 0), "{pulses:?}");
}

#[test]
fn a_move_that_does_not_move_is_an_instant_after_the_dwells_before_it_at_the_speed_it_passes() {
    // Grbl's defaults (10 mm/s²): 10 mm at 300 mm/min (5 mm/s) is 0.5 s up,
    // 1.5 s at 5 mm/s and 0.5 s down from rest to rest: 2.5 s.
    let defaults = Settings::from_json(r#"{"stepsPerMm": 80}"#).unwrap();
    let timing_of_line = |source: &str, line: u32| {
        let program = run(source, defaults.clone());
        let moves = program.moves();
        let standing = moves.iter().find(|m| m.line == line).unwrap();
        assert_eq!(standing.steps, 0, "{source}");
        (standing.timing, program.moves()[0].timing.end_seconds)
    };
    // After a G4 P2, line 3 is reached when the dwell is over (Grbl runs the
    // lines in order): 4.5 s, not 2.5 s where the move before ended.
    let (t, first_end) = timing_of_line("G1 X10 F300\nG4 P2\nX10\nY10\n", 3);
    assert!(close(first_end, 2.5));
    assert!(close(t.start_seconds, 4.5) && t.end_seconds == t.start_seconds);
    assert_eq!(
        (t.entry_speed, t.cruise_speed, t.exit_speed),
        (0.0, 0.0, 0.0)
    );
    // A dwell after it: it is reached where the move before ended.
    let (t, _) = timing_of_line("G1 X10 F300\nX10\nG4 P2\nY10\n", 2);
    assert!(close(t.start_seconds, 2.5));
    // Between two moves with no stop, the machine passes it at the corner's
    // junction speed (Grbl's 90°: √(a·√2·δ·s/(1−s)), s = sin 45°, δ = 0.01
    // mm), as the move before leaves and the move after enters.
    let program = run("G1 X10 F300\nX10\nY10\n", defaults.clone());
    let moves = program.moves();
    let s = 0.5f64.sqrt();
    let corner = (10.0 * 2f64.sqrt() * 0.01 * s / (1.0 - s)).sqrt();
    let t = moves[1].timing;
    assert!(
        close(t.entry_speed, corner)
            && close(t.exit_speed, corner)
            && close(t.cruise_speed, corner),
        "{t:?}"
    );
    assert!(
        close(moves[0].timing.exit_speed, corner) && close(moves[2].timing.entry_speed, corner)
    );
    assert!(close(t.start_seconds, moves[0].timing.end_seconds));
}

#[test]
fn g92_brings_the_motion_to_rest_as_a_dwell_does() {
    // Grbl synchronises its buffer for G92 (gcode.c step 19,
    // system_flag_wco_change): the move after it starts from rest, as after
    // G4 P0. voxpath ran straight on at 8.33 mm/s (3.23 s, not 4.07 s).
    let slow = settings("");
    let duration = |program: &str| run(program, slow.clone()).info.duration_seconds;
    let through_dwell = duration("G1 X10 F500\nG4 P0\nG1 X20\n");
    let through_g92 = duration("G1 X10 F500\nG92 X10\nG1 X20\n");
    let straight_on = duration("G1 X10 F500\nG1 X20\n");
    assert!(
        close(through_g92, through_dwell),
        "{through_g92} {through_dwell}"
    );
    assert!(
        through_g92 > straight_on + 0.01,
        "{through_g92} {straight_on}"
    );
    let program = run("G1 X10 F500\nG92 X0\nG1 X10\n", slow);
    assert_eq!(program.moves()[0].timing.exit_speed, 0.0);
    assert_eq!(program.moves()[1].timing.entry_speed, 0.0);
}

#[test]
fn the_dwells_between_two_steps_are_told_from_their_instants() {
    // Grbl's defaults: 2 mm at 600 mm/min (a = 10 mm/s²) is a triangle,
    // 1 mm up to √20 = 4.47 mm/s and down, 2·√(2·1/10) = 0.894 s; then G4
    // P2, the same 2 mm again (its first step 1/80 mm from rest, 50 ms), and
    // G4 P0.5 at the end. The timing diagram asks which part of the pause
    // between the last step before a dwell and the first after is one.
    let defaults = Settings::from_json(r#"{"stepsPerMm": 80}"#).unwrap();
    let program = run(
        "G21 G90\nG1 X2 F600\nG4 P2\nG1 X4\nG4 P0.5\n",
        defaults.clone(),
    );
    let timeline = &program.timeline;
    let triangle = 2.0 * 0.2f64.sqrt();
    let times = timeline.step_seconds(0, 320);
    assert!(close(times[159], triangle), "{}", times[159]);
    assert!(close(
        times[160] - times[159],
        2.0 + (2.0f64 / 80.0 / 10.0).sqrt()
    ));
    // Between the two steps: the dwell, whole, though its start is the
    // instant of the step before up to a rounding.
    assert!(close(
        timeline.dwell_seconds_between(times[159], times[160]),
        2.0
    ));
    assert!(close(
        timeline.dwell_seconds_between(times[159] + 1e-12, times[160]),
        2.0
    ));
    // Between steps of a move, none; over the whole program, both.
    assert_eq!(timeline.dwell_seconds_between(times[100], times[159]), 0.0);
    assert_eq!(timeline.dwell_seconds_between(times[160], times[319]), 0.0);
    let end = program.info.duration_seconds;
    assert!(close(end, 2.0 * triangle + 2.5));
    assert!(close(timeline.dwell_seconds_between(times[319], end), 0.5));
    assert!(close(timeline.dwell_seconds_between(0.0, end), 2.5));
    assert_eq!(timeline.dwell_seconds_between(end, f64::INFINITY), 0.0);
    // A stop with no wait (M5 after M3) has no dwell in it.
    let stopped = run("M3 S1000\nG1 X2 F600\nM5\nG1 X4\n", defaults);
    assert_eq!(
        stopped.timeline.dwell_seconds_between(0.0, f64::INFINITY),
        0.0
    );
}
