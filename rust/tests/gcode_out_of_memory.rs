//! Issue 15 item 6: a program past the wasm instance's 4 GiB trapped. The
//! run now stops between lines once the core holds more heap than its
//! budget. Alone in its test binary: the heap count is the whole
//! process's, which a test freeing memory on another thread would change.

use voxpath::gcode::{Runner, Settings};
use voxpath::memory::held_bytes;

#[test]
fn a_program_that_does_not_fit_in_memory_stops_cleanly_saying_how_far_it_got() {
    // Issue 15 item 6: a program past the wasm instance's 4 GiB trapped.
    // The run now stops between lines once the core holds more heap than
    // its budget; here the budget is what is held once the run has made
    // room for its moves, and 1 MiB more, which its steps outgrow.
    let lines = 100_000;
    let source: String = (0..lines)
        .map(|i| format!("G1 X{} Y{} F600\n", i % 50, (i * 7) % 50))
        .collect();
    let mut runner = Runner::new(source, Settings::from_json(r#"{"stepsPerMm": 1}"#).unwrap());
    runner.set_heap_budget(held_bytes() + (1 << 20));
    let progress = runner.advance(u32::MAX);
    assert!(progress.done, "a stopped run is over");
    let error = runner
        .out_of_memory()
        .expect("the run stopped for memory")
        .clone();
    let p = runner.finish();
    // The lines before the stop ran, one move each; the stop is the last error, at the next line.
    let ran = p.moves().len() as u32;
    assert!(ran > 0 && ran < lines, "{ran} moves");
    assert_eq!(p.info.stopped_at_line, Some(ran + 1));
    let last = p.info.errors.last().unwrap();
    assert_eq!((last.line, last.column), (ran + 1, 1));
    assert_eq!(last.message, error.message);
    assert!(
        error.message.starts_with(&format!(
            "the program does not fit in memory: after {ran} of its {lines} lines ({ran} moves, "
        )),
        "{}",
        error.message
    );
    assert!(
        error.message.contains("run it in parts of fewer lines"),
        "{}",
        error.message
    );
    // What ran is a whole trace: it ends where the last move ended.
    assert_eq!(
        p.trace.point(p.info.steps).coords(),
        p.moves().last().unwrap().to_steps
    );
}
