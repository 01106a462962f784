//! The phases of checking a learner's points at the page's cap, natively:
//! the helix of 264 turns of r = 1000 (1,498,841 points) checked against
//! its own points. Prints each phase's milliseconds of CPU time, median of the runs
//! asked (`cargo run --release --example check_read -- RUNS`).

use voxpath::Request;
use voxpath::check::{CheckStage, Points, SlicedCheck};

const RULE: &str = r#"{"algorithm":"helix","from":[1000,0,0],"to":[1000,0,300],"center":[0,0,0],"plane":"xy","turns":264}"#;

/// This thread's CPU time, ms: the machine is shared, and wall time counts
/// the waits for a core.
fn cpu_ms() -> f64 {
    let mut now = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: clock_gettime writes the timespec it is given.
    unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut now) };
    now.tv_sec as f64 * 1000.0 + now.tv_nsec as f64 / 1e6
}

/// CPU ms since `start` ([`cpu_ms`]).
fn ms(start: f64) -> f64 {
    cpu_ms() - start
}

fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

fn main() {
    let runs: usize = std::env::args()
        .nth(1)
        .map_or(5, |a| a.parse().expect("runs"));
    let request = Request::from_json(RULE).expect("the rule");
    let rule = voxpath::run(&request).expect("traced");
    // The points walked from the start by the rule's steps (Trace::point
    // for each would decode from the nearest checkpoint every time).
    let mut text = String::new();
    let mut at = rule.start();
    let row = |p: &voxpath::grid::Point| format!("{},{},{}\n", p.get(0), p.get(1), p.get(2));
    text.push_str(&row(&at));
    for &step in rule.step_range(0, rule.steps()) {
        at.apply(step);
        text.push_str(&row(&at));
    }
    println!(
        "{} points, {:.1} MB of text",
        rule.steps() + 1,
        text.len() as f64 / 1e6
    );
    let names = [
        "read text",
        "request",
        "trace",
        "from_flat",
        "steps",
        "SlicedCheck::from_flat",
        "SlicedCheck::from_text, then reading in slices of 65,536 rows",
        "longest reading slice",
        "compare",
        "alsoMatches",
        "alsoMatches longest combination",
    ];
    let mut times: Vec<Vec<f64>> = vec![Vec::new(); names.len()];
    for _ in 0..runs {
        let t = cpu_ms();
        let points = Points::from_text(&text, 3).expect("read");
        times[0].push(ms(t));
        let values: Vec<f64> = points.coords.iter().map(|&c| c as f64).collect();
        let t = cpu_ms();
        let request = Request::from_json(RULE).expect("the rule");
        times[1].push(ms(t));
        let t = cpu_ms();
        let trace = voxpath::run(&request).expect("traced");
        times[2].push(ms(t));
        drop(trace);
        let t = cpu_ms();
        let flat = Points::from_flat(&values, 3, 3).expect("flat");
        times[3].push(ms(t));
        let t = cpu_ms();
        let steps = flat.steps();
        times[4].push(ms(t));
        drop(steps);
        let t = cpu_ms();
        let pass = SlicedCheck::from_flat(RULE, &values, 3).expect("pass");
        times[5].push(ms(t));
        drop(pass);
        // The reading by itself: a slice of 65,536 rows at most reads on
        // into the comparison only in the call that ends it.
        let t = cpu_ms();
        let mut pass = SlicedCheck::from_text(RULE, text.clone()).expect("pass");
        let mut longest: f64 = 0.0;
        let mut progress = pass.progress();
        while progress.stage == CheckStage::Reading {
            let c = cpu_ms();
            progress = pass.advance(65_536).expect("read");
            longest = longest.max(ms(c));
        }
        times[6].push(ms(t));
        times[7].push(longest);
        let t = cpu_ms();
        while progress.stage == CheckStage::Comparing {
            progress = pass.advance(65_536).expect("compared");
        }
        times[8].push(ms(t));
        let t = cpu_ms();
        let mut longest: f64 = 0.0;
        while !progress.done {
            let c = cpu_ms();
            progress = pass.advance(1).expect("tried");
            longest = longest.max(ms(c));
        }
        times[9].push(ms(t));
        times[10].push(longest);
        assert!(pass.result().expect("done").matches);
    }
    for (name, values) in names.iter().zip(times) {
        let (lo, hi) = values
            .iter()
            .fold((f64::MAX, 0f64), |(lo, hi), &v| (lo.min(v), hi.max(v)));
        println!(
            "{name}: median {:.1} ms ({lo:.1} to {hi:.1})",
            median(values)
        );
    }
}
