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
use voxpath::trace::Stepper;
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
    // r = 1000 and 10^6 extra turns: 4 * 10^6 - 2 passes through a quarter
    // of 2k - 1 = 1413 steps each (k = 707, the least with 2k² >= 1000² -
    // 1000), 5,651,997,174 in all; a dry run would have stopped at the
    // default maxSteps + 1 = 50,000,001.
    let e = refusal(
        r#"{"algorithm":"circle","from":[1000,0,0],"to":[1000,0,0],"center":[0,0,0],"turns":1000000}"#,
    );
    assert_eq!(at_least(&e), 5_651_997_174);
}

#[test]
fn a_million_turns_under_every_max_steps_are_told_the_max_steps_that_traces_them() {
    // r = 80 steps (I1 at 80 steps/mm) and 999,999 extra turns take
    // 452,000,000 steps, under the largest maxSteps. Refused from the full
    // turns' bound (3,999,994 passes of 113 steps), the program was told
    // "at least 451999322", and refused again at that maxSteps; the dry
    // run counts the turns that repeat each other at once (it counted
    // them one by one: 1.4 s natively). A helix about it steps the same
    // circle and is told the same.
    let settings = |max_steps: u64| {
        Settings::from_json(&format!(r#"{{"stepsPerMm": 80, "maxSteps": {max_steps}}}"#)).unwrap()
    };
    for (source, steps) in [
        ("G1 F100\nG2 X0 Y0 I1 P1000000", 452_000_000),
        ("G1 F100\nG2 X0 Y0 Z1 I1 P1000000", 452_000_000),
    ] {
        let p = run(source, settings(50_000_000));
        let error = &p.info.errors[0];
        assert_eq!(
            (error.line, error.column, p.info.steps),
            (2, 1, 0),
            "{source}"
        );
        assert_eq!(
            error.limit,
            Some(Limit {
                option: "maxSteps".into(),
                value: 50_000_000,
                at_least: steps,
                most: 1_000_000_000,
            }),
            "{source}"
        );
        assert_eq!(
            error.message,
            format!(
                "the program needs more than maxSteps = 50000000 steps by this move (at least {steps}); raise maxSteps (up to 1000000000) or shorten the program or lower its steps per mm"
            )
        );
        // One step short of the count, it is told the count again.
        let short = run(source, settings(steps - 1));
        let told = short.info.errors[0].limit.as_ref().map(|l| l.at_least);
        assert_eq!(told, Some(steps), "{source}");
    }
    // And at the count, the circle is taken (counted, not traced here: 0.9 GB of steps).
    let spec = ArcSpec::parse(
        &voxpath::Request::from_json(
            r#"{"algorithm":"circle","from":[80,0,0],"to":[80,0,0],"center":[0,0,0],"turns":999999}"#,
        )
        .unwrap(),
        false,
        3,
    )
    .unwrap();
    let counted = SaleemCircle::new(&spec).counted(452_000_000).unwrap();
    assert_eq!(counted.remaining_steps(), Some(452_000_000));
}

#[test]
fn the_full_turn_bound_is_below_the_real_count() {
    // Every start of radius up to 40 in a quarter plane (the rule is alike
    // in every quarter), around a full circle and half of one, each way,
    // with 1 to 4 extra turns: the bound never passes the dry run's count.
    let count = |json: &str| {
        let spec = ArcSpec::parse(&voxpath::Request::from_json(json).unwrap(), false, 3).unwrap();
        let bound = SaleemCircle::new(&spec).steps_at_least();
        let steps = SaleemCircle::new(&spec)
            .counted(1_000_000_000)
            .unwrap()
            .remaining_steps()
            .unwrap();
        (bound, steps)
    };
    for u in 1..=40i64 {
        for v in 0..=40i64 {
            if u * u + v * v > 40 * 40 {
                continue;
            }
            for (to, dir, turns) in [[u, v], [-u, -v]]
                .into_iter()
                .flat_map(|to| ["cw", "ccw"].map(|dir| (to, dir)))
                .flat_map(|(to, dir)| (1..=4).map(move |turns| (to, dir, turns)))
            {
                let json = format!(
                    r#"{{"algorithm":"circle","from":[{u},{v},0],"to":[{},{},0],"center":[0,0,0],"dir":"{dir}","turns":{turns}}}"#,
                    to[0], to[1]
                );
                let (bound, steps) = count(&json);
                assert!(bound <= steps, "{json}: bound {bound} > {steps} steps");
            }
        }
    }
}

#[test]
fn a_helix_is_refused_from_its_rise() {
    let e = refusal(
        r#"{"algorithm":"helix","from":[5,0,0],"to":[5,0,1000000],"center":[0,0,0],"maxSteps":1000}"#,
    );
    assert_eq!(at_least(&e), 1_000_000);
    // A rise past maxSteps under a longer circle is told the circle's
    // count, the maxSteps that traces it (it was told the rise, 1000, and
    // refused again there), and one step short of it is told it again.
    let json = |max: u64| {
        format!(
            r#"{{"algorithm":"helix","from":[1000,0,0],"to":[1000,0,1000],"center":[0,0,0],"turns":10,"maxSteps":{max}}}"#
        )
    };
    let steps = at_least(&refusal(&json(500)));
    assert!(steps > 11 * 5000, "{steps}");
    assert_eq!(common::trace(&json(steps)).steps(), steps);
    assert_eq!(at_least(&refusal(&json(steps - 1))), steps);
    // A rise past the largest maxSteps is refused at once, told the rise:
    // a bound, the circle left uncounted, as no maxSteps traces it.
    let e = refusal(
        r#"{"algorithm":"helix","from":[5,0,-1073741824],"to":[5,0,1073741824],"center":[0,0,0]}"#,
    );
    assert_eq!(at_least(&e), 1 << 31);
    assert!(e.message.contains("more than any maxSteps allows"), "{e}");
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
