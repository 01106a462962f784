//! maxSteps is enforced before the work: a path that needs more steps than
//! allowed is refused from what is known before stepping (a line's length,
//! an arc's full turns, a helix's rise, an arc's chords), not after
//! allocating or dry-running up to the limit. The "at least N" of each
//! message is the count that was known up front, which a refusal found by
//! stepping could not give (it would say maxSteps + 1, or less); an arc
//! the dry run finds too long is counted on to the largest maxSteps, so
//! its message says what it takes, or that no maxSteps allows it.

mod common;

use voxpath::arc::ArcSpec;
use voxpath::arc::circle_saleem::SaleemCircle;
use voxpath::gcode::{Settings, run};
use voxpath::{Error, Limit};

fn refusal(json: &str) -> Error {
    match voxpath::trace_json(json) {
        Ok(t) => panic!("{json}: traced {} steps", t.steps()),
        Err(e) => e,
    }
}

/// The N of "... (at least N); ...", which the error's limit carries too.
fn at_least(e: &Error) -> u64 {
    assert_eq!(e.field_name(), Some("maxSteps"), "{e}");
    let tail = e.message.split("(at least ").nth(1).expect("a count");
    let n = tail[..tail.find(')').unwrap()].parse().unwrap();
    assert_eq!(e.limit.as_ref().map(|l| l.at_least), Some(n), "{e}");
    n
}

#[test]
fn a_line_is_refused_from_its_length() {
    // |Δx| = 2^31 steps against the largest maxSteps, 10^9.
    let e = refusal(
        r#"{"algorithm":"regions","from":[-1073741824,0,0],"to":[1073741824,5,9],"maxSteps":1000000000}"#,
    );
    assert_eq!(at_least(&e), 1 << 31);
    assert_eq!(
        e.limit,
        Some(Limit {
            option: "maxSteps".into(),
            value: 1_000_000_000,
            at_least: 1 << 31,
            most: 1_000_000_000,
        })
    );
    // No maxSteps is enough, so raising it is not the advice.
    assert!(
        e.message
            .ends_with("that is more than any maxSteps allows (1000000000): shorten the move"),
        "{e}"
    );
}

#[test]
fn a_path_that_a_higher_max_steps_allows_is_told_to_raise_it() {
    let e = refusal(r#"{"algorithm":"regions","from":[0,0,0],"to":[5000,1,1],"maxSteps":4000}"#);
    assert_eq!(
        e.limit,
        Some(Limit {
            option: "maxSteps".into(),
            value: 4000,
            at_least: 5000,
            most: 1_000_000_000,
        })
    );
    assert!(
        e.message
            .ends_with("raise maxSteps (up to 1000000000) or shorten the move"),
        "{e}"
    );
}

#[test]
fn a_program_is_stopped_at_the_move_past_max_steps_with_what_the_program_needs() {
    // 10 steps/mm: the first move is 100 steps, the second 200 (regions
    // takes |Δx| steps), so the program needs at least 300 against 250.
    let p = run(
        "G1 X10 F600\nG1 X30\n",
        Settings::from_json(r#"{"stepsPerMm": 10, "maxSteps": 250}"#).unwrap(),
    );
    let error = &p.info.errors[0];
    assert_eq!((error.line, error.column), (2, 1));
    assert_eq!(
        error.limit,
        Some(Limit {
            option: "maxSteps".into(),
            value: 250,
            at_least: 300,
            most: 1_000_000_000,
        })
    );
    assert!(
        error.message.contains("(at least 300)"),
        "{}",
        error.message
    );
}

#[test]
fn a_circle_is_refused_from_its_full_turns() {
    // r = 1000 and 10^6 extra turns: more than 4 (r - 1) = 3996 steps per
    // turn, at least 3,996,000,000; a dry run would have stopped at the
    // default maxSteps + 1 = 50,000,001.
    let e = refusal(
        r#"{"algorithm":"circle","from":[1000,0,0],"to":[1000,0,0],"center":[0,0,0],"turns":1000000}"#,
    );
    assert_eq!(at_least(&e), 3_996_000_000);
}

#[test]
fn an_arc_past_every_max_steps_is_told_so() {
    // A half circle of r = 2^30 takes about 3 * 10^9 steps: the advice to
    // raise maxSteps (to "at least 50000001") was refused again at 10^9.
    let r = 1 << 30;
    for max in ["", r#","maxSteps":1000000000"#] {
        let e = refusal(&format!(
            r#"{{"algorithm":"circle","from":[{r},0,0],"to":[-{r},0,0],"center":[0,0,0]{max}}}"#
        ));
        assert!(at_least(&e) > 1_000_000_000, "{e}");
        assert!(
            e.message
                .ends_with("that is more than any maxSteps allows (1000000000): shorten the move"),
            "{e}"
        );
    }
}

#[test]
fn the_full_turn_bound_is_below_the_real_count() {
    for r in [1, 2, 3, 5, 17, 100, 1000] {
        for turns in [0, 1, 3] {
            let json = format!(
                r#"{{"algorithm":"circle","from":[{r},0,0],"to":[{r},0,0],"center":[0,0,0],"turns":{turns}}}"#
            );
            let spec =
                ArcSpec::parse(&voxpath::Request::from_json(&json).unwrap(), false, 3).unwrap();
            let bound = SaleemCircle::new(&spec).steps_at_least();
            let steps = common::trace(&json).steps();
            assert!(
                bound < steps,
                "r {r}, {turns} extra turns: {bound} >= {steps}"
            );
        }
    }
}

#[test]
fn a_helix_is_refused_from_its_rise() {
    let e = refusal(
        r#"{"algorithm":"helix","from":[5,0,0],"to":[5,0,1000000],"center":[0,0,0],"maxSteps":1000}"#,
    );
    assert_eq!(at_least(&e), 1_000_000);
}

#[test]
fn chords_are_refused_from_their_lengths() {
    // A full circle of r = 2^29 in chords of 2^20: about 3217 chords whose
    // largest |Δ| add up to some 3 * 10^9 steps, far past the default
    // 5 * 10^7; refused before the first chord is traced.
    let r = 1 << 29;
    let e = refusal(&format!(
        r#"{{"algorithm":"arc-segments","from":[{r},0,0],"to":[{r},0,0],"center":[0,0,0],"segmentLength":1048576}}"#
    ));
    let n = at_least(&e);
    // Between the sum of chord lengths (the perimeter, 2π r) over sqrt(2)
    // and the perimeter itself, give or take a unit per chord.
    let perimeter = std::f64::consts::TAU * r as f64;
    assert!(
        (n as f64) > perimeter / 2f64.sqrt() && (n as f64) < perimeter,
        "{n}"
    );
    // The helix's method segments goes the same way.
    let e = refusal(&format!(
        r#"{{"algorithm":"helix","method":"segments","from":[{r},0,0],"to":[{r},0,7],"center":[0,0,0],"segmentLength":1048576}}"#
    ));
    assert!(at_least(&e) > 3_000_000_000);
}

#[test]
fn chords_within_the_limit_still_meet_it_exactly() {
    // A quarter circle of r = 5 in chords of 1.5, traced once to count its
    // steps, then with maxSteps at that count and one below: the budget
    // each chord gets is what the chords before it left.
    let json = |max: u64| {
        format!(
            r#"{{"algorithm":"arc-segments","from":[5,0,0],"to":[0,5,0],"center":[0,0,0],"segmentLength":1.5,"maxSteps":{max}}}"#
        )
    };
    let steps = common::trace(&json(1000)).steps();
    assert_eq!(common::trace(&json(steps)).steps(), steps);
    assert_eq!(refusal(&json(steps - 1)).field_name(), Some("maxSteps"));
}
