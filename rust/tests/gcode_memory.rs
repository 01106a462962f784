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
use voxpath::planner::Block;

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

/// Heap `program` retains, less its steps (2 bytes each) and its planner
/// blocks, per line; and its planner blocks per line.
fn retained_per_line(settings: &str) -> (f64, f64, f64) {
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
    let blocks = program.timeline.plan().blocks.len() as f64;
    let besides = retained - 2.0 * steps as f64 - blocks * size_of::<Block>() as f64;
    let lines = LINES as f64;
    eprintln!(
        "{settings}: {:.1} B a line, {:.1} besides steps and blocks, {:.2} blocks a line",
        retained / lines,
        besides / lines,
        blocks / lines
    );
    (retained / lines, besides / lines, blocks / lines)
}

#[test]
fn a_finished_program_retains_at_most_200_bytes_a_line() {
    // At 1 step/mm (the G-code bench's resolution) all of it.
    let (all, _, _) = retained_per_line(r#"{"stepsPerMm": 1}"#);
    assert!(all <= 200.0, "{all:.1} bytes a line");
    // At 80 steps/mm an arc's chords are Grbl's (12 for each quarter arc of
    // r = 1 mm at its 0.002 mm tolerance, most of which round onto the same
    // step at 1 step/mm): each a planner block of 80 bytes, which the
    // README's Limits states. All the rest, per line, besides the steps:
    let (_, besides, blocks) = retained_per_line(r#"{"stepsPerMm": 80}"#);
    assert!(besides <= 120.0, "{besides:.1} bytes a line");
    assert!(blocks > 1.5, "{blocks} blocks a line");
}
