//! Native end to end, for `npm run bench` (bench/end-to-end.bench.ts runs
//! this with `cargo run --release --example end_to_end`): a 3D line traced
//! by voxpath with every point read, against the `line_drawing` crate's
//! `Bresenham3d` collected into a Vec, what a Rust user would pick instead.
//!
//! Reads `{"request": {...a 3D line request...}, "rounds": n}` as the first
//! line on stdin and prints `{"points", "voxpathSeconds", "lineDrawingSeconds"}`
//! as one line: the median of `n` rounds each, the two taken in turn within
//! a round so that a slow moment of the machine falls on both (which goes
//! first alternating from round to round), after one round that is not
//! timed. Then, for each further line on stdin, it runs `line_drawing` once
//! more and prints `{"lineDrawingSeconds"}` as one line, until stdin ends:
//! the bench's wasm row takes these rounds in turn with its own, in Node.
//! Seconds are this thread's CPU time (page faults included, the kernel
//! runs them on the thread), not wall time: on a machine shared with other
//! work, wall time also counts the waits for a free core.

use serde_json::{Value, json};
use std::io::BufRead;
use voxpath::Request;

/// CPU seconds this thread has run.
fn thread_cpu_seconds() -> f64 {
    let mut now = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `now` is a valid timespec for the call to write.
    let status = unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut now) };
    assert_eq!(status, 0, "the thread's CPU clock reads");
    now.tv_sec as f64 + now.tv_nsec as f64 * 1e-9
}

/// CPU seconds of one run of `f`; its result is dropped outside the timing.
fn seconds<T>(f: impl FnOnce() -> T) -> (f64, T) {
    let start = thread_cpu_seconds();
    let out = std::hint::black_box(f());
    (thread_cpu_seconds() - start, out)
}

/// The middle value, or the mean of the two middle values of an even count
/// (the bench asks for an even number of rounds, half with each side first).
fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    let half = values.len() / 2;
    if values.len() % 2 == 1 {
        values[half]
    } else {
        (values[half - 1] + values[half]) / 2.0
    }
}

/// Keeps the memory both sides let go of in glibc's heap from round to
/// round, to be handed out again, rather than returned to the kernel and
/// faulted back in page by page: an allocation up to 32 MiB (the most
/// glibc allows here; each side's array is 24 MB) comes from the heap, and
/// the heap's free top is never given back. Left to glibc's own
/// thresholds, which of the two a round met depended on where small
/// allocations happened to sit in the heap: when a trace kept its
/// checkpoints in one array instead of a box each (751398a, undone after),
/// every round's memory became fresh pages for both sides (22,107 -> 94,918
/// faults a run, 100 `brk` calls against 15; `line_drawing` 5.5 -> 12.2 ms,
/// voxpath 2.55 -> 10.3 ms, Intel host, 2026-12-07), a change to the
/// allocator's luck, not to either side's work. With the memory kept, where
/// it lies still moves each side by several percent (`line_drawing` took
/// 4.8 to 5.7 ms by what voxpath's trace had left in the heap).
fn keep_freed_memory() {
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    {
        const LARGEST_FROM_HEAP_BYTES: libc::c_int = 32 << 20;
        const NEVER_TRIMMED_BELOW_BYTES: libc::c_int = 1 << 30;
        // SAFETY: mallopt only changes the allocator's settings; it is
        // called before any other thread exists.
        let set = unsafe {
            libc::mallopt(libc::M_MMAP_THRESHOLD, LARGEST_FROM_HEAP_BYTES)
                & libc::mallopt(libc::M_TRIM_THRESHOLD, NEVER_TRIMMED_BELOW_BYTES)
        };
        assert_eq!(set, 1, "glibc takes both settings");
    }
}

fn main() {
    keep_freed_memory();
    let mut lines = std::io::stdin().lock().lines();
    let input = lines.next().expect("a case on stdin").expect("stdin reads");
    let case: Value = serde_json::from_str(&input).expect("a JSON case");
    let request = Request::from_json(&case["request"].to_string()).expect("a valid request");
    let rounds = case["rounds"].as_u64().unwrap_or(5).max(1) as usize;
    let (from, to) = request.endpoints(3, 3).expect("a 3D line");
    let voxel = |p: &voxpath::Point| (p.get(0) as i32, p.get(1) as i32, p.get(2) as i32);

    let voxpath_points = || {
        let trace = voxpath::run(&request).expect("the request traces");
        trace.points_i32(0, trace.steps() + 1)
    };
    let line_drawing_points = || {
        line_drawing::Bresenham3d::new(voxel(&from), voxel(&to)).collect::<Vec<(i32, i32, i32)>>()
    };

    let (mut ours, mut theirs) = (Vec::new(), Vec::new());
    let mut points = 0;
    for round in 0..=rounds {
        // Every other round the other side goes first, so that neither
        // always meets the memory the other has just let go of.
        let ((a, p), (b, q)) = if round % 2 == 1 {
            let ours = seconds(voxpath_points);
            (ours, seconds(line_drawing_points))
        } else {
            let theirs = seconds(line_drawing_points);
            (seconds(voxpath_points), theirs)
        };
        assert_eq!(p.len(), 3 * q.len(), "both give every point of the line");
        points = q.len();
        if round > 0 {
            ours.push(a);
            theirs.push(b);
        }
    }
    println!(
        "{}",
        json!({
            "points": points,
            "voxpathSeconds": median(ours),
            "lineDrawingSeconds": median(theirs),
        })
    );
    for line in lines {
        line.expect("stdin reads");
        let (s, q) = seconds(line_drawing_points);
        assert_eq!(q.len(), points, "every point of the line");
        // Rust's stdout is line-buffered: each line reaches the bench whole.
        println!("{}", json!({ "lineDrawingSeconds": s }));
    }
}
