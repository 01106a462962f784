//! What a finished G-code run retains per source line (issue: "at most 200
//! bytes of retained state per source line, with steps held at the trace's
//! 16 B/step bound"): the core's heap, counted by its allocator
//! (`voxpath::memory`), before the program text is read and after the run,
//! while the program is held. Alone in its test binary: the count is of the
//! whole process, which no other test may share.
//!
//! Native sizes are the wasm build's or larger (pointers take 8 bytes here,
//! 4 in wasm32), so the bound holds in the browser too.

use voxpath::gcode::{Settings, run};
use voxpath::memory::held_bytes;

/// `lines` lines of a pocket-clearing mix in a 100 mm field: short G1 zig-zag
/// moves in X, Y and Z, and a clockwise quarter arc of r = 1 mm every tenth line.
fn program(lines: usize) -> String {
    let mut out = String::from("G21 G90 G17 F1200\nG0 X25 Y25 Z0\n");
    let (mut x, mut y) = (25.0f64, 25.0f64);
    for i in 2..lines {
        if i % 10 == 9 {
            out.push_str(&format!("G2 X{:.3} Y{:.3} I-1 J0\n", x - 1.0, y - 1.0));
            (x, y) = (x - 1.0, y - 1.0);
        } else {
            // Within 5..45 mm: across and back, a little further each time.
            let dx = if i % 2 == 0 { 0.731 } else { -0.517 };
            let dy = if (i / 7) % 2 == 0 { 0.613 } else { -0.389 };
            (x, y) = ((x + dx).clamp(5.0, 45.0), (y + dy).clamp(5.0, 45.0));
            let z = -0.1 * (i % 3) as f64;
            out.push_str(&format!("G1 X{x:.3} Y{y:.3} Z{z:.3}\n"));
        }
    }
    out
}

/// Heap a run of the program retains per line, less its steps (2 bytes
/// each, within a trace's 16 bytes a step), and its planner blocks per line.
fn retained_per_line(settings: &str) -> (f64, f64) {
    const LINES: usize = 200_000;
    let before = held_bytes();
    let program = run(&program(LINES), Settings::from_json(settings).unwrap());
    let retained = (held_bytes() - before) as f64;
    assert!(program.info.errors.is_empty(), "{:?}", program.info.errors);
    assert_eq!(program.info.move_count, LINES - 1, "{settings}");
    // Every step the program took is read back where it was kept.
    let steps = program.info.steps;
    assert_eq!(
        program.trace.point(steps).coords(),
        &program.moves().last().unwrap().to_steps
    );
    let lines = LINES as f64;
    let blocks = program.timeline.plan().len() as f64;
    ((retained - 2.0 * steps as f64) / lines, blocks / lines)
}

#[test]
fn a_finished_program_retains_at_most_200_bytes_a_line_besides_its_steps() {
    // At 1 step/mm (the G-code bench's resolution) most of an arc's chords
    // round onto one step; at 80 steps/mm each quarter arc of r = 1 mm is
    // Grbl's 12 chords (its 0.002 mm tolerance), a planner block each.
    for (settings, blocks_at_least) in [
        (r#"{"stepsPerMm": 1}"#, 1.0),
        (r#"{"stepsPerMm": 80}"#, 2.0),
    ] {
        let (per_line, blocks) = retained_per_line(settings);
        assert!(
            blocks >= blocks_at_least,
            "{settings}: {blocks} blocks a line"
        );
        assert!(per_line <= 200.0, "{settings}: {per_line:.1} bytes a line");
    }
}
