//! A planned trace (`lazy_trace::LazyTrace`, what `trace()` hands over)
//! is the trace its request records, to the bit: its summary before
//! anything records it, its points made straight from its steppers
//! (`plan::PointsSink`, through buffers of any size), and everything read
//! after it records. On random lines of every line algorithm in every
//! number of axes it takes, circles (in 2 and 3 axes, both ways, every
//! plane, several turns), helices by Saleem's rule and in chords, and
//! arcs in chords by every line algorithm, near +-2^30 too.

mod common;

use proptest::prelude::*;
use voxpath::algorithms::{find, run};
use voxpath::grid::COORD_LIMIT;
use voxpath::lazy_trace::LazyTrace;
use voxpath::request::Request;
use voxpath::trace::Trace;

/// The points `lazy` hands over through a buffer of `buffer_points`
/// points, checked to come in order, whole, and once each.
fn points_through(lazy: &LazyTrace, buffer_points: usize) -> Vec<i32> {
    let (dims, n) = (lazy.dims(), lazy.steps() + 1);
    let mut buffer = vec![std::mem::MaybeUninit::new(0); buffer_points * dims];
    let mut out = Vec::new();
    lazy.points_by_chunk(0, n, &mut buffer, |k, chunk| {
        assert_eq!(k as usize * dims, out.len(), "chunks in order");
        assert_eq!(chunk.len() % dims, 0, "whole points");
        out.extend_from_slice(chunk);
    });
    out
}

/// The request planned: its summary, its points through a buffer of
/// `buffer_points` and then through a large one, all as `run` records it;
/// and, once something recorded it, the same again.
fn check_plan(json: &str, buffer_points: usize) -> Result<(), TestCaseError> {
    let recorded: Trace = run(&Request::from_json(json).unwrap()).unwrap();
    let lazy = LazyTrace::new(Request::from_json(json).unwrap(), find).unwrap();
    let expected = serde_json::to_value(recorded.summary()).unwrap();
    prop_assert_eq!(
        &serde_json::to_value(lazy.summary()).unwrap(),
        &expected,
        "{}",
        json
    );
    let points = recorded.points_i32(0, recorded.steps() + 1);
    prop_assert_eq!(&points_through(&lazy, buffer_points), &points, "{}", json);
    prop_assert_eq!(&points_through(&lazy, 1 << 16), &points, "{}", json);
    // With maxSteps at its exact count it is planned as well.
    let exact = json.replacen(
        '{',
        &format!(r#"{{"maxSteps":{},"#, recorded.steps().max(1)),
        1,
    );
    let at_limit = LazyTrace::new(Request::from_json(&exact).unwrap(), find).unwrap();
    prop_assert_eq!(
        &points_through(&at_limit, buffer_points),
        &points,
        "{}",
        exact
    );
    // Decisions need the recorded trace: it records, as planned.
    let bits = |t: &Trace| -> Vec<u64> {
        t.decisions_flat(0, t.steps())
            .iter()
            .map(|v| v.to_bits())
            .collect()
    };
    prop_assert!(
        bits(lazy.trace()) == bits(&recorded),
        "decisions of {}",
        json
    );
    prop_assert_eq!(&serde_json::to_value(lazy.summary()).unwrap(), &expected);
    prop_assert_eq!(&points_through(&lazy, buffer_points), &points);
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn a_planned_arc_is_the_trace_its_request_records(
        json in common::arc_request(),
        buffer_points in 1usize..5000,
    ) {
        check_plan(&json, buffer_points)?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn a_planned_line_is_the_trace_its_request_records(
        algorithm in 0usize..8,
        dims in 1usize..=6,
        start in prop::array::uniform6(prop_oneof![-3000i64..3000, Just(COORD_LIMIT - 9000), Just(-COORD_LIMIT + 9000), Just(COORD_LIMIT), Just(-COORD_LIMIT)]),
        delta in prop::array::uniform6(prop_oneof![-6000i64..6000, -3i64..3, Just(0i64)]),
        tie in 0usize..3,
        option in 0usize..3,
        buffer_points in 1usize..5000,
    ) {
        let id = ["regions", "bresenham2d", "bresenham3d", "nd", "liu-float", "greedy", "walk6", "dda"][algorithm];
        // Each algorithm's own options, absent or given (read by the one
        // function its trace and its plan share).
        let own = match (id, option) {
            (_, 0) => "",
            ("regions" | "bresenham3d" | "nd", 1) => r#","gcd":true"#,
            ("regions" | "bresenham3d" | "nd", _) => r#","gcd":false"#,
            ("bresenham2d", 1) => r#","variant":"printed""#,
            ("bresenham2d", _) => r#","variant":"corrected""#,
            ("liu-float", 1) => r#","decimals":0"#,
            ("liu-float", _) => r#","decimals":4"#,
            ("greedy" | "walk6", 1) => r#","tieAxis":"lower""#,
            ("greedy" | "walk6", _) => r#","tieAxis":"higher""#,
            _ => "",
        };
        let info = find(id).unwrap();
        let dims = dims.clamp(info.min_dims, info.max_dims);
        // A start on the grid's edge moves along it or inward.
        let (from, to): (Vec<i64>, Vec<i64>) = (0..dims)
            .map(|a| (start[a], (start[a] + delta[a]).clamp(-COORD_LIMIT, COORD_LIMIT)))
            .unzip();
        let tie = match (info.default_tie, tie) {
            (Some(_), 1) => r#","tie":"advance""#,
            (Some(_), 2) => r#","tie":"hold""#,
            _ => "",
        };
        check_plan(&format!(r#"{{"algorithm":"{id}","from":{from:?},"to":{to:?}{tie}{own}}}"#), buffer_points)?;
    }
}

/// A request with steps to follow is recorded when made (only recording
/// checks them, stopping where they end), and reads as recorded.
#[test]
fn a_request_to_follow_is_recorded_at_once() {
    let json = r#"{"algorithm":"circle","from":[5,0,0],"to":[5,0,0],"center":[0,0,0]}"#;
    let steps: std::sync::Arc<[voxpath::grid::Step]> = run(&Request::from_json(json).unwrap())
        .unwrap()
        .step_range(0, 28)
        .into();
    let following = Request::from_json(json).unwrap().following(steps);
    let lazy = LazyTrace::new(following.clone(), find).unwrap();
    let recorded = run(&following).unwrap();
    assert_eq!(lazy.steps(), recorded.steps());
    assert_eq!(
        points_through(&lazy, 3),
        recorded.points_i32(0, recorded.steps() + 1)
    );
}

/// A plan refused (past maxSteps) is refused with its algorithm's own
/// error, the one a recorded trace gives.
#[test]
fn a_refused_plan_is_told_as_its_trace_is() {
    for json in [
        r#"{"algorithm":"circle","from":[500,0,0],"to":[500,0,0],"center":[0,0,0],"maxSteps":100}"#,
        r#"{"algorithm":"helix","from":[500,0,0],"to":[500,0,900],"center":[0,0,0],"maxSteps":800}"#,
        r#"{"algorithm":"arc-segments","from":[500,0,0],"to":[500,0,0],"center":[0,0,0],"maxSteps":100}"#,
        r#"{"algorithm":"regions","from":[0,0,0],"to":[500,1,1],"maxSteps":100}"#,
        r#"{"algorithm":"greedy","from":[0,0,0],"to":[50,60,1],"maxSteps":100}"#,
    ] {
        let recorded = run(&Request::from_json(json).unwrap()).err().unwrap();
        let planned = LazyTrace::new(Request::from_json(json).unwrap(), find)
            .err()
            .unwrap();
        assert_eq!(planned.to_string(), recorded.to_string(), "{json}");
    }
}
