//! Runs a G-code file natively, for profiling the program path with perf:
//!
//!   cargo build --release --example gcode_run
//!   perf record -g target/release/examples/gcode_run FILE [STEPS_PER_MM]
//!
//! Prints lines, moves, steps and the seconds of the run (parse, interpret,
//! step every move, record the trace, the program's record).

fn main() {
    let mut args = std::env::args().skip(1);
    let file = args.next().expect("usage: gcode_run FILE [STEPS_PER_MM]");
    let steps_per_mm: f64 = args.next().map_or(1.0, |s| s.parse().expect("a number"));
    let source = std::fs::read_to_string(&file).expect("a readable file");
    let settings =
        voxpath::gcode::Settings::from_json(&format!(r#"{{"stepsPerMm": {steps_per_mm}}}"#))
            .expect("valid settings");
    let started = std::time::Instant::now();
    let program = voxpath::gcode::run(&source, settings);
    let seconds = started.elapsed().as_secs_f64();
    println!(
        "{} lines, {} moves, {} steps, {} errors: {seconds:.3} s ({:.0} k lines/s, {:.1} M steps/s)",
        program.info.lines,
        program.info.moves.len(),
        program.info.steps,
        program.info.errors.len(),
        f64::from(program.info.lines) / seconds / 1e3,
        program.info.steps as f64 / seconds / 1e6
    );
}
