//! Native throughput, for `npm run bench` (bench/measure.ts runs this with
//! `cargo run --release --example bench`): reads a JSON array of cases from
//! stdin and prints one JSON array of results, in order.
//!
//! A case is `{"request": {...a trace request...}, "repeat": n}`. Each
//! measurement is the best of `repeat` runs (the fastest is the one least
//! disturbed by other work on the machine):
//! - `recordSeconds`: `voxpath::run`, stepping and recording (2 bytes per
//!   step, a position and a stepper state every 4096 steps), no metrics;
//! - `metricsSeconds`: `Trace::metrics` on a fresh trace, the pass over
//!   every point (deviation and per-axis error);
//! - `stepperSeconds`, for `regions` only: `RegionsWang::next_step` alone,
//!   the step codes folded into a checksum so the work is not optimised
//!   away, nothing recorded.

use serde_json::{Value, json};
use std::io::Read;
use std::time::Instant;
use voxpath::Request;
use voxpath::line::regions_wang::RegionsWang;
use voxpath::request::TiePolicy;
use voxpath::trace::Stepper;

/// Seconds of the fastest of `repeat` runs of `f`.
fn best<T>(repeat: u64, mut f: impl FnMut() -> T) -> f64 {
    (0..repeat.max(1))
        .map(|_| {
            let start = Instant::now();
            let out = f();
            let seconds = start.elapsed().as_secs_f64();
            drop(std::hint::black_box(out));
            seconds
        })
        .fold(f64::INFINITY, f64::min)
}

fn run(request: &Request) -> voxpath::Trace {
    voxpath::run(request).unwrap_or_else(|e| panic!("{}: {e}", request.algorithm))
}

/// The regions stepper on the request's line, without recording.
fn stepper_seconds(request: &Request, repeat: u64) -> f64 {
    let (from, to) = request.endpoints(3, 3).expect("a 3D line");
    best(repeat, || {
        let mut stepper = RegionsWang::new(from, to, TiePolicy::Advance);
        let mut checksum = 0u64;
        while let Some((step, _)) = stepper.next_step() {
            checksum = checksum.wrapping_mul(31).wrapping_add(step.0 as u64);
        }
        checksum
    })
}

fn main() {
    let mut input = String::new();
    std::io::stdin()
        .read_to_string(&mut input)
        .expect("cases on stdin");
    let cases: Vec<Value> = serde_json::from_str(&input).expect("a JSON array of cases");
    let results: Vec<Value> = cases
        .iter()
        .map(|case| {
            let request = Request::from_json(&case["request"].to_string())
                .unwrap_or_else(|e| panic!("{case}: {e}"));
            let repeat = case["repeat"].as_u64().unwrap_or(3);
            let steps = run(&request).steps();
            let record = best(repeat, || run(&request));
            let metrics = (0..repeat.max(1))
                .map(|_| {
                    let trace = run(&request);
                    let start = Instant::now();
                    std::hint::black_box(trace.metrics());
                    start.elapsed().as_secs_f64()
                })
                .fold(f64::INFINITY, f64::min);
            let stepper =
                (request.algorithm == "regions").then(|| stepper_seconds(&request, repeat));
            json!({
                "steps": steps,
                "recordSeconds": record,
                "metricsSeconds": metrics,
                "stepperSeconds": stepper,
            })
        })
        .collect();
    println!("{}", Value::Array(results));
}
