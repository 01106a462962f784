//! Properties of circle, arc-segments and helix on random arcs in every
//! plane, direction and octant, with centers anywhere in the ±2^30 box.
//!
//! Bounds asserted, and why they hold:
//! - circle points are less than 1/2 from the circle: the two candidates of
//!   a step sit either side of it on a line along the slow axis, at |slow|
//!   = n and n + 1, and the crossing x* has x*² = r² - fast², an integer. The
//!   outer candidate wins only if x*² >= n² + n + 1, so its error
//!   ((n+1)² - x*²) / (ρ + r) <= n / (2r) < 1/2; the inner one wins only if
//!   x*² <= n² + n, so r - ρ <= x* - n <= sqrt(n² + n) - n < 1/2.
//! - at most 2 correction steps: the end is within 1 of the circle, the ray
//!   through it crosses the step between the two points either side, so the
//!   nearer one is within 1 + 1/2 + sqrt(2)/2 < 3 of the end, and a grid
//!   point at Chebyshev distance 3 would be at least 3 away.
//! - a point between two correction steps is within 1/2 + sqrt(2) of the
//!   circle (one diagonal step from a circle point).

#![allow(clippy::needless_range_loop)]

mod common;

use proptest::prelude::*;
use std::f64::consts::{PI, SQRT_2, TAU};
use voxpath::arc::ArcSpec;
use voxpath::arc::circle_saleem::{CirclePlan, CircleStep, SaleemCircle};
use voxpath::arc::helix::SaleemHelix;
use voxpath::grid::{COORD_LIMIT, Point, SIGNED_AXIS_LABELS};
use voxpath::ideal::IdealPath;
use voxpath::ideal::info::IdealPathInfo;
use voxpath::request::{DEFAULT_MAX_STEPS, TiePolicy};
use voxpath::trace::{NO_VALUE, Stepper};
use voxpath::{Request, Trace};

const PLANES: [(&str, [usize; 3]); 3] = [("xy", [0, 1, 2]), ("zx", [2, 0, 1]), ("yz", [1, 2, 0])];

#[derive(Clone, Debug)]
struct Arc {
    plane: usize,
    ccw: bool,
    center: [i64; 3],
    /// Start and end relative to the center, in the plane's (u, v).
    start: [i64; 2],
    end: [i64; 2],
    turns: u64,
}

impl Arc {
    fn axes(&self) -> [usize; 3] {
        PLANES[self.plane].1
    }

    fn point(&self, uv: [i64; 2], height: i64) -> [i64; 3] {
        let [u, v, n] = self.axes();
        let mut p = self.center;
        p[u] += uv[0];
        p[v] += uv[1];
        p[n] += height;
        p
    }

    fn request(&self, algorithm: &str, rise: i64, extra: &str) -> String {
        format!(
            r#"{{"algorithm":"{algorithm}","from":{:?},"to":{:?},"center":{:?},"dir":"{}","plane":"{}","turns":{}{extra}}}"#,
            self.point(self.start, 0),
            self.point(self.end, rise),
            self.center,
            if self.ccw { "ccw" } else { "cw" },
            PLANES[self.plane].0,
            self.turns,
        )
    }

    fn radius_sq(&self) -> i64 {
        self.start[0].pow(2) + self.start[1].pow(2)
    }

    /// (u, v) of a grid point relative to the center.
    fn local(&self, p: &[i64; 3]) -> [i64; 2] {
        let [u, v, _] = self.axes();
        [p[u] - self.center[u], p[v] - self.center[v]]
    }
}

/// A random arc of radius up to `max_r`: the end is the arc point at a
/// random angle and a radius within 1/4 of the start's, rounded, so it is
/// within 1/4 + sqrt(2)/2 < 1 of the circle; or (one time in four) the start
/// itself, a full circle.
fn arc_strategy(max_r: i64) -> impl Strategy<Value = Arc> {
    let reach = COORD_LIMIT - max_r - 2;
    (
        0usize..3,
        any::<bool>(),
        prop_oneof![
            [-1000i64..1000, -1000i64..1000, -1000i64..1000],
            [-reach..reach, -reach..reach, -reach..reach],
        ],
        [-max_r..=max_r, -max_r..=max_r],
        0.0..TAU,
        -0.25f64..0.25,
        0u8..4,
        prop_oneof![4 => Just(0u64), 1 => 1u64..3],
    )
        .prop_filter("a radius", |(_, _, _, s, ..)| *s != [0, 0])
        .prop_map(|(plane, ccw, center, start, angle, dr, full, turns)| {
            let r = ((start[0].pow(2) + start[1].pow(2)) as f64).sqrt() + dr;
            let mut end = [
                (r * angle.cos()).round() as i64,
                (r * angle.sin()).round() as i64,
            ];
            if full == 0 || end == [0, 0] {
                end = start;
            }
            Arc {
                plane,
                ccw,
                center,
                start,
                end,
                turns,
            }
        })
}

/// The circle stepper of a circle or helix request, counted by its dry run
/// as a trace counts it.
fn counted_circle(json: &str) -> (ArcSpec, SaleemCircle) {
    let spec = ArcSpec::parse(&Request::from_json(json).unwrap(), true, 3).unwrap();
    let circle = SaleemCircle::new(&spec).counted(DEFAULT_MAX_STEPS).unwrap();
    (spec, circle)
}

/// Saleem's dry run taken one step at a time, as the paper's dummy
/// procedure does: a fresh stepper's `next_step` to the end, each step
/// counted as a circle or a correction step by its decision.
fn plan_step_by_step(spec: &ArcSpec) -> CirclePlan {
    let mut circle = SaleemCircle::new(spec);
    let (mut circle_steps, mut correction_steps, mut stop) = (0, 0, None);
    loop {
        let before = circle.point();
        let Some((_, why)) = circle.next_step() else {
            break;
        };
        if let CircleStep::Correction { .. } = why.kind {
            correction_steps += 1;
            stop.get_or_insert(before);
        } else {
            circle_steps += 1;
        }
    }
    CirclePlan {
        circle_steps,
        correction_steps,
        stop: stop.unwrap_or(circle.point()),
    }
}

/// The dry run's count (which leaps along the path where the closed form
/// knows it) against the step-by-step one.
fn check_plan(json: &str) -> Result<(), TestCaseError> {
    let spec = ArcSpec::parse(&Request::from_json(json).unwrap(), true, 3).unwrap();
    let by_leaps = SaleemCircle::new(&spec).plan(u64::MAX);
    prop_assert_eq!(by_leaps, Some(plan_step_by_step(&spec)), "{}", json);
    Ok(())
}

/// Checks the circle's and the helix's recording loops (`fill`) against
/// their `next_step`, in chunks of `chunk` (common::check_fill).
fn check_fills(json: &str, tie: TiePolicy, chunk: usize) -> Result<(), TestCaseError> {
    let (spec, circle) = counted_circle(json);
    let fail = |e: String| TestCaseError::fail(format!("{json}, chunks of {chunk}: {e}"));
    if spec.rise == 0 {
        common::check_fill(|| circle.clone(), chunk).map_err(fail)?;
    }
    common::check_fill(|| SaleemHelix::new(&spec, circle.clone(), tie), chunk).map_err(fail)?;
    Ok(())
}

fn points(t: &Trace) -> Vec<[i64; 3]> {
    t.points_flat(0, t.steps() + 1)
        .chunks(3)
        .map(|c| [c[0], c[1], c[2]])
        .collect()
}

fn cross(p: [i64; 2], q: [i64; 2]) -> i128 {
    p[0] as i128 * q[1] as i128 - p[1] as i128 * q[0] as i128
}

/// Checks the steps are single grid moves that never move `still` (the
/// normal axis, or none).
fn check_steps(p: &[[i64; 3]], still: Option<usize>) -> Result<(), TestCaseError> {
    for w in p.windows(2) {
        let d: Vec<i64> = (0..3).map(|a| w[1][a] - w[0][a]).collect();
        prop_assert!(
            d.iter().all(|v| v.abs() <= 1) && d.iter().any(|&v| v != 0),
            "{:?} -> {:?}",
            w[0],
            w[1]
        );
        if let Some(n) = still {
            prop_assert_eq!(d[n], 0, "the normal axis moved at {:?}", w[0]);
        }
    }
    Ok(())
}

/// One decision column of `t` over all its steps, by name.
fn column(t: &Trace, name: &str) -> Vec<f64> {
    let i = t.columns().iter().position(|c| c.name == name).unwrap();
    t.decisions(0, t.steps()).columns.swap_remove(i)
}

/// Checks each arc step's two candidates (Saleem section 4, eq. 6-7): the
/// point reached and the cell `otherCandidate` names from it differ by one
/// step of the in-plane axis that is not the fast one; the stay candidate is
/// one fast-axis step from the point before; the residual columns equal
/// u² + v² - r² worked out here at those two cells; and the reached one has
/// the smaller |residual|. Steps the arc did not decide (corrections, a
/// helix's linear-only steps) have no other candidate.
fn check_candidates(arc: &Arc, t: &Trace, p: &[[i64; 3]]) -> Result<(), TestCaseError> {
    let [stay_col, move_col, slow_col, fast_col, other_col] = [
        "residualStay",
        "residualMove",
        "slowSteps",
        "fast",
        "otherCandidate",
    ]
    .map(|name| column(t, name));
    let [u, v, _] = arc.axes();
    let residual = |q: [i64; 3]| {
        let [a, b] = arc.local(&q);
        a as i128 * a as i128 + b as i128 * b as i128 - arc.radius_sq() as i128
    };
    for k in 0..p.len() - 1 {
        if stay_col[k].is_nan() {
            prop_assert_eq!(other_col[k], f64::from(NO_VALUE), "step {}", k);
            continue;
        }
        let label = SIGNED_AXIS_LABELS[other_col[k] as usize];
        let axis = "xyz".find(&label[1..]).unwrap();
        let sign = if label.starts_with('-') { -1 } else { 1 };
        let reached = p[k + 1];
        let mut other = reached;
        other[axis] += sign;
        let fast = fast_col[k] as usize;
        prop_assert!(
            (axis == u || axis == v) && axis != fast,
            "step {}: {} with fast {}",
            k,
            label,
            fast
        );
        let slow_steps = slow_col[k] == 1.0;
        let stay = if slow_steps { other } else { reached };
        let (before, after) = (arc.local(&p[k]), arc.local(&stay));
        let fast_local = if fast == u { 0 } else { 1 };
        prop_assert_eq!(
            (after[fast_local] - before[fast_local]).abs(),
            1,
            "step {}",
            k
        );
        prop_assert_eq!(after[1 - fast_local], before[1 - fast_local], "step {}", k);
        let moved = if slow_steps { reached } else { other };
        prop_assert_eq!(stay_col[k] as i128, residual(stay), "step {}", k);
        prop_assert_eq!(move_col[k] as i128, residual(moved), "step {}", k);
        prop_assert!(
            residual(reached).abs() < residual(other).abs(),
            "step {}",
            k
        );
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn the_recording_loops_take_the_rule_s_steps(
        arc in prop_oneof![arc_strategy(3), arc_strategy(40), arc_strategy(300)],
        rise in prop_oneof![-40i64..40, -3000i64..3000],
        hold in any::<bool>(),
        chunk in 1usize..300,
    ) {
        // Circle and helix (method saleem) record through loops of their
        // own (one per octant, the helix's line woven in), not next_step:
        // the same steps in every plane and direction, full circles, extra
        // turns, ends off the circle (correction steps), tiny radii, the
        // arc or the linear axis major, either tie policy.
        let tie = if hold { TiePolicy::Hold } else { TiePolicy::Advance };
        check_fills(&arc.request("circle", 0, ""), tie, chunk)?;
        check_fills(&arc.request("helix", rise, ""), tie, chunk)?;
    }

    #[test]
    fn a_helix_whose_arc_steps_every_other_iteration_or_less_records_the_rule_s_steps(
        arc in prop_oneof![arc_strategy(3), arc_strategy(40), arc_strategy(300)],
        over_twice in -2i64..=2,
        times in prop_oneof![Just(2i64), 2i64..8],
        hold in any::<bool>(),
        chunk in prop_oneof![Just(4096usize), 1usize..9000],
    ) {
        // The linear axis leading and the arc stepping in at most every
        // other iteration (n_z >= 2 n_c), where the helix puts the arc's
        // steps, made by the circle's own fill, where its line says, 4,096
        // iterations at a time; around n_z = 2 n_c, where a block's arc
        // steps fill its arrays, and rises up to 8 n_c, both directions.
        let tie = if hold { TiePolicy::Hold } else { TiePolicy::Advance };
        let (_, circle) = counted_circle(&arc.request("circle", 0, ""));
        let n_c = circle.remaining_steps().unwrap() as i64;
        let rise = times * n_c + if times == 2 { over_twice } else { 0 };
        let rise = if over_twice < 0 { -rise } else { rise };
        check_fills(&arc.request("helix", rise, ""), tie, chunk)?;
    }

    #[test]
    fn wide_circles_record_the_rule_s_steps_in_the_trace_s_chunks(
        arc in arc_strategy(5000),
        rise in prop_oneof![Just(0i64), -3000i64..3000],
        chunk in prop_oneof![Just(4096usize), 64usize..5000],
    ) {
        // Radii to 5,000 in the trace builder's chunks of 4,096 steps: each
        // octant's stretch in long pieces (SaleemCircle::laned_fill), cut
        // by chunk ends, by the ray through the end on every lap, and by
        // the octant's last steps near the diagonal.
        check_fills(&arc.request("circle", 0, ""), TiePolicy::Advance, chunk)?;
        check_fills(&arc.request("helix", rise, ""), TiePolicy::Hold, chunk)?;
    }

    #[test]
    fn a_circle_takes_no_more_steps_than_its_bound(
        arc in prop_oneof![arc_strategy(3), arc_strategy(40), arc_strategy(300)],
    ) {
        // SaleemCircle::within lets a circle run without the dry run when
        // steps_at_most fits maxSteps: the bound must hold for every arc
        // (extra turns, ends off the circle, tiny radii).
        let (spec, circle) = counted_circle(&arc.request("circle", 0, ""));
        let bound = SaleemCircle::new(&spec).steps_at_most();
        let steps = circle.remaining_steps().expect("counted");
        prop_assert!(steps <= bound, "{} steps, bound {}", steps, bound);
    }

    #[test]
    fn a_circle_takes_no_fewer_steps_than_its_full_turns_bound(
        arc in prop_oneof![arc_strategy(3), arc_strategy(40), arc_strategy(3000)],
        turns in 1u64..6,
    ) {
        // SaleemCircle::counted refuses a circle without its dry run when
        // steps_at_least passes maxSteps, and says that many at least: the
        // bound must hold for every arc with full turns (ends off the
        // circle, tiny radii, every plane and direction).
        let arc = Arc { turns, ..arc };
        let (spec, circle) = counted_circle(&arc.request("circle", 0, ""));
        let bound = SaleemCircle::new(&spec).steps_at_least();
        let steps = circle.remaining_steps().expect("counted");
        prop_assert!(bound <= steps, "{} steps, bound {}", steps, bound);
    }

    #[test]
    fn the_dry_run_counts_the_steps_of_many_turns_the_rule_takes(
        arc in prop_oneof![arc_strategy(3), arc_strategy(40), arc_strategy(300)],
        turns in 3u64..12,
    ) {
        check_plan(&Arc { turns, ..arc }.request("circle", 0, ""))?;
    }

    #[test]
    fn the_dry_run_counts_the_steps_the_rule_takes(
        arc in prop_oneof![arc_strategy(3), arc_strategy(40), arc_strategy(300), arc_strategy(30_000)],
    ) {
        check_plan(&arc.request("circle", 0, ""))?;
    }

    #[test]
    fn circle_and_helix_steps_take_the_candidate_nearer_the_circle(
        arc in arc_strategy(300), rise in -400i64..400
    ) {
        let circle = voxpath::trace_json(&arc.request("circle", 0, "")).unwrap();
        check_candidates(&arc, &circle, &points(&circle))?;
        let helix = voxpath::trace_json(&arc.request("helix", rise, "")).unwrap();
        check_candidates(&arc, &helix, &points(&helix))?;
    }

    #[test]
    fn circle_steps_on_the_circle_and_ends_exactly(arc in arc_strategy(300)) {
        let t = voxpath::trace_json(&arc.request("circle", 0, "")).unwrap();
        let p = points(&t);
        let [_, _, n] = arc.axes();
        check_steps(&p, Some(n))?;
        prop_assert_eq!(*p.last().unwrap(), arc.point(arc.end, 0));
        let correction = &column(&t, "correction");
        let circle_steps = correction.iter().take_while(|&&c| c == 0.0).count();
        let corrections = correction.len() - circle_steps;
        prop_assert!(correction[circle_steps..].iter().all(|&c| c == 1.0));
        prop_assert!(corrections <= 2, "{} corrections", corrections);
        let first = t.segment(0);
        let ideal = &first.ideal;
        for (k, q) in p.iter().enumerate() {
            let e = ideal.deviation(&Point::new(q));
            if k <= circle_steps {
                prop_assert!(e < 0.5, "circle point {:?} is {} off", q, e);
            } else if k < p.len() - 1 {
                prop_assert!(e <= 0.5 + SQRT_2, "correction point {:?} is {} off", q, e);
            } else {
                prop_assert!(e <= 1.0, "the end is {} off", e);
            }
        }
        // Every circle step turns forward (counter-clockwise in the mirror
        // frame of a clockwise arc), so a turn is at most 8 (r + 1) steps.
        let sign = if arc.ccw { 1 } else { -1 };
        for w in p[..=circle_steps].windows(2) {
            prop_assert!(sign * cross(arc.local(&w[0]), arc.local(&w[1])) > 0);
        }
        let r = (arc.radius_sq() as f64).sqrt();
        prop_assert!(circle_steps as f64 <= (arc.turns + 1) as f64 * 8.0 * (r + 1.0));
    }

    #[test]
    fn a_full_circle_returns_and_visits_every_octant(arc in arc_strategy(300)) {
        let arc = Arc { end: arc.start, ..arc };
        let t = voxpath::trace_json(&arc.request("circle", 0, "")).unwrap();
        prop_assert_eq!(t.end(), t.start());
        prop_assert!(t.steps() > 0);
        let octants = &t.decisions(0, t.steps()).columns[0];
        let mut seen = [false; 8];
        for &k in octants {
            seen[k as usize] = true;
        }
        // r = 1 is the exception: its four cells sit on the axes and the
        // diagonal steps between them skip octants 2, 4, 6, 8.
        if arc.radius_sq() >= 2 {
            prop_assert!(seen.iter().all(|&s| s), "octants seen: {:?}", seen);
        }
        prop_assert_eq!(t.metrics().steps, t.steps());
    }

    #[test]
    fn reversing_an_arc_between_points_of_one_circle_visits_the_same_cells(
        arc in arc_strategy(300), image in 0usize..8
    ) {
        // B is one of the eight symmetric images of A, so both lie on the
        // same integer circle u² + v² = r² and both runs use that circle.
        // Then cw A -> B is ccw B -> A backwards, cell for cell: within an
        // octant each run takes, for each fast coordinate, the candidate
        // nearer the circle (no ties exist), and at the octant switches the
        // octant-ahead rule is the mirror image of itself.
        let [a, b] = arc.start;
        let images = [[a, b], [b, a], [-b, a], [-a, b], [-a, -b], [-b, -a], [b, -a], [a, -b]];
        let arc = Arc { end: images[image], ..arc };
        let forward = voxpath::trace_json(&Arc { ccw: false, ..arc.clone() }.request("circle", 0, "")).unwrap();
        let back = Arc { ccw: true, start: arc.end, end: arc.start, ..arc.clone() };
        let backward = voxpath::trace_json(&back.request("circle", 0, "")).unwrap();
        let mut reversed = points(&backward);
        reversed.reverse();
        prop_assert_eq!(points(&forward), reversed);
    }

    #[test]
    fn every_plane_steps_the_same_local_path(arc in arc_strategy(200)) {
        let local = |plane: usize| {
            let arc = Arc { plane, ..arc.clone() };
            let t = voxpath::trace_json(&arc.request("circle", 0, "")).unwrap();
            points(&t).iter().map(|p| arc.local(p)).collect::<Vec<_>>()
        };
        let xy = local(0);
        prop_assert_eq!(&xy, &local(1));
        prop_assert_eq!(&xy, &local(2));
    }

    #[test]
    fn a_circle_in_x_and_y_is_the_xy_plane_s_at_z_0_without_z(arc in arc_strategy(200)) {
        let arc = Arc { plane: 0, center: [arc.center[0], arc.center[1], 0], ..arc };
        let spatial = voxpath::trace_json(&arc.request("circle", 0, "")).unwrap();
        let [from, to] = [arc.start, arc.end].map(|uv| arc.point(uv, 0)[..2].to_vec());
        let planar = voxpath::trace_json(&format!(
            r#"{{"algorithm":"circle","from":{from:?},"to":{to:?},"center":{:?},"dir":"{}","turns":{}}}"#,
            &arc.center[..2],
            if arc.ccw { "ccw" } else { "cw" },
            arc.turns,
        ))
        .unwrap();
        prop_assert_eq!(planar.dims(), 2);
        prop_assert_eq!(planar.steps(), spatial.steps());
        let n = spatial.steps() + 1;
        // Every value in 3 axes with its z, which is 0, left out.
        let without_z = |values: Vec<f64>| -> Vec<f64> {
            values.chunks(3).flat_map(|p| { assert_eq!(p[2], 0.0); [p[0], p[1]] }).collect()
        };
        let points3: Vec<f64> = spatial.points_flat(0, n).into_iter().map(|c| c as f64).collect();
        let points2: Vec<f64> = planar.points_flat(0, n).into_iter().map(|c| c as f64).collect();
        prop_assert_eq!(points2, without_z(points3));
        prop_assert_eq!(planar.ideal_polyline(), without_z(spatial.ideal_polyline()));
        prop_assert_eq!(planar.axis_error_range(0, n), without_z(spatial.axis_error_range(0, n)));
        prop_assert_eq!(planar.deviation_range(0, n), spatial.deviation_range(0, n));
        // NaN where a column does not apply: compared bit for bit.
        let bits = |values: Vec<f64>| values.into_iter().map(f64::to_bits).collect::<Vec<_>>();
        prop_assert_eq!(bits(planar.decisions_flat(0, n - 1)), bits(spatial.decisions_flat(0, n - 1)));
        let (m2, m3) = (planar.metrics(), spatial.metrics());
        prop_assert_eq!(m2.max_deviation, m3.max_deviation);
        prop_assert_eq!(&m2.max_axis_error[..], &m3.max_axis_error[..2]);
        prop_assert_eq!(&m2.pulses_by_axis[..], &m3.pulses_by_axis[..2]);
        // Texts name points and moves in 2 axes: "(5, 0)" for "(5, 0, 0)",
        // "(x, y+1)" for "(x, y+1, z)".
        let (note2, note3) = (planar.segment(0).note().into_owned(), spatial.segment(0).note().into_owned());
        prop_assert_eq!(note2, note3.replace(", 0)", ")"));
        // About 64 steps spread over the arc, each replayed from its checkpoint.
        for k in (0..n - 1).step_by(((n - 1) / 64).max(1) as usize) {
            let (s2, s3) = (planar.replay_step(k), spatial.replay_step(k));
            prop_assert_eq!(s2.explanation, s3.explanation.replace(", z).", ")."));
            let cells = |figure: Option<voxpath::figure::DecisionFigure>| match figure {
                Some(voxpath::figure::DecisionFigure::ArcCandidates(c)) => {
                    c.candidates.map(|c| (c.name, c.cell[..2].to_vec(), c.residual, c.taken)).to_vec()
                }
                Some(other) => panic!("a circle's figure is its candidates, got {other:?}"),
                None => Vec::new(),
            };
            prop_assert_eq!(cells(s2.figure), cells(s3.figure));
        }
    }

    #[test]
    fn chords_stay_within_sagitta_plus_rounding_plus_line_error(
        arc in arc_strategy(200),
        length in 1.0f64..40.0,
        tolerance in 0.05f64..3.0,
        by_length in any::<bool>(),
    ) {
        let r = (arc.radius_sq() as f64).sqrt();
        prop_assume!(by_length || tolerance < 2.0 * r);
        let extra = if by_length {
            format!(r#","segmentLength":{length}"#)
        } else {
            format!(r#","tolerance":{tolerance}"#)
        };
        let t = voxpath::trace_json(&arc.request("arc-segments", 0, &extra)).unwrap();
        let p = points(&t);
        check_steps(&p, Some(arc.axes()[2]))?;
        prop_assert_eq!(*p.last().unwrap(), arc.point(arc.end, 0));
        // The widest chord's sagitta, from the pieces of arc the trace
        // measures each chord against.
        let widest = t
            .segments()
            .map(|s| match s.ideal.info() {
                IdealPathInfo::Arc { sweep_rad, .. } => sweep_rad.abs(),
                other => panic!("a chord is measured against its arc, not {other:?}"),
            })
            .fold(0.0, f64::max);
        let sagitta = r * (1.0 - (widest / 2.0).cos());
        // Rounding moves each vertex by at most sqrt(2)/2, and Wang's
        // regions stays within sqrt(2)/2 of the chord it steps.
        let bound = sagitta + SQRT_2 / 2.0 + SQRT_2 / 2.0;
        prop_assert!(t.metrics().max_deviation <= bound + 1e-9,
            "{} > {} (sagitta {})", t.metrics().max_deviation, bound, sagitta);
        for segment in t.segments() {
            prop_assert!(matches!(segment.ideal, IdealPath::Arc(_)));
        }
    }

    #[test]
    fn saleem_helix_is_the_circle_with_the_linear_axis_woven_in(
        arc in arc_strategy(100), rise in -400i64..400
    ) {
        let helix = voxpath::trace_json(&arc.request("helix", rise, "")).unwrap();
        let circle = voxpath::trace_json(&arc.request("circle", 0, "")).unwrap();
        let p = points(&helix);
        let [_, _, n] = arc.axes();
        check_steps(&p, None)?;
        prop_assert_eq!(*p.last().unwrap(), arc.point(arc.end, rise));
        // The dry run's n_c is the circle's own step count, and the helix
        // takes max(n_c, n_z) steps.
        let n_c = circle.steps();
        prop_assert_eq!(helix.steps(), n_c.max(rise.unsigned_abs()));
        let arc_steps = column(&helix, "arcSteps").iter().filter(|&&f| f == 1.0).count();
        prop_assert_eq!(arc_steps as u64, n_c);
        // The linear axis only ever moves toward its end.
        for w in p.windows(2) {
            let d = w[1][n] - w[0][n];
            prop_assert!(d == 0 || d == rise.signum());
        }
        // Without its linear-only steps, the helix is the circle.
        let mut projected: Vec<[i64; 3]> = Vec::new();
        for q in &p {
            let mut flat = *q;
            flat[n] = arc.center[n];
            if projected.last() != Some(&flat) {
                projected.push(flat);
            }
        }
        prop_assert_eq!(projected, points(&circle));
        // Height at the point's own angle: the step-versus-angle drift is
        // at most 1.05% of a turn's rise (see helix.rs); plus one arc step's
        // height for the run of linear steps taken at one arc position, one
        // more because the discrete circle's step count at an angle differs
        // from the continuous r sin(theta) by up to a step, and half a linear step.
        let IdealPathInfo::Helix { sweep_rad, .. } = helix.segment(0).ideal.info() else {
            panic!("a helix is measured against a helix")
        };
        let pitch = rise.abs() as f64 * TAU / sweep_rad.abs();
        let per_arc_step = rise.abs() as f64 / n_c.max(1) as f64;
        let bound = 0.0105 * pitch + 2.0 * per_arc_step + 0.5;
        prop_assert!(
            helix.metrics().max_axis_error[n] <= bound,
            "height error {} > {} with pitch {} and n_c {}", helix.metrics().max_axis_error[n], bound, pitch, n_c
        );
    }

    #[test]
    fn segmented_helix_ends_exactly_and_climbs_monotonically(
        arc in arc_strategy(100), rise in -400i64..400, tolerance in 0.1f64..2.0
    ) {
        let r = (arc.radius_sq() as f64).sqrt();
        prop_assume!(tolerance < 2.0 * r);
        let extra = format!(r#","method":"segments","tolerance":{tolerance}"#);
        let t = voxpath::trace_json(&arc.request("helix", rise, &extra)).unwrap();
        let p = points(&t);
        let n = arc.axes()[2];
        check_steps(&p, None)?;
        prop_assert_eq!(*p.last().unwrap(), arc.point(arc.end, rise));
        for w in p.windows(2) {
            let d = w[1][n] - w[0][n];
            prop_assert!(d == 0 || d == rise.signum());
        }
    }
}

/// Every start within `reach` of the center (on both axes), each with the
/// ends the exhaustive tests below run it to: first the start itself (a
/// full circle, `full`), then a point near each of the 16 rays 22.5° apart,
/// just past it, at the start's radius, rounded (on and beside the
/// diagonals, where the closed form hands over to the rule's steps); the
/// center is neither.
fn small_arcs(reach: i64) -> impl Iterator<Item = (i64, i64, [i64; 2], bool)> {
    (-reach..=reach)
        .flat_map(move |u| (-reach..=reach).map(move |v| (u, v)))
        .filter(|&uv| uv != (0, 0))
        .flat_map(|(u, v)| {
            let r = ((u * u + v * v) as f64).sqrt();
            let rays = (0..16).map(move |k| {
                let angle = k as f64 * PI / 8.0 + 0.01;
                [
                    (r * angle.cos()).round() as i64,
                    (r * angle.sin()).round() as i64,
                ]
            });
            std::iter::once([u, v])
                .chain(rays)
                .enumerate()
                .filter(|&(_, end)| end != [0, 0])
                .map(move |(i, end)| (u, v, end, i == 0))
        })
}

/// The circle request of a counter-clockwise arc in the xy plane about the
/// origin, from `start` to `end` with `turns` extra turns.
fn counter_clockwise_about_origin(start: [i64; 2], end: [i64; 2], turns: u64) -> String {
    let arc = Arc {
        plane: 0,
        ccw: true,
        center: [0, 0, 0],
        start,
        end,
        turns,
    };
    arc.request("circle", 0, "")
}

#[test]
fn the_dry_run_counts_every_small_circle_and_arc_exactly() {
    // Every start within 40 of the center, as a full circle (a turn more
    // from every other start) and as arcs ending near each ray.
    for (u, v, end, full) in small_arcs(40) {
        let turns = (full && (u + v) % 2 == 0) as u64;
        check_plan(&counter_clockwise_about_origin([u, v], end, turns)).unwrap();
    }
}

#[test]
fn the_dry_run_counts_every_small_circle_and_arc_of_many_turns_exactly() {
    // The dry run counts the turns that repeat the one before at once:
    // every start within 12 of the center, full circles and arcs, with 3
    // to 6 turns added (a skip from the third crossing on).
    for (u, v, end, _) in small_arcs(12) {
        let turns = 3 + (u + 2 * v).rem_euclid(4) as u64;
        check_plan(&counter_clockwise_about_origin([u, v], end, turns)).unwrap();
    }
}

#[test]
fn the_recording_loops_of_every_small_circle_and_arc_take_the_rule_s_steps() {
    // The loops watch for the ray through the end only in the octants a
    // step can cross it from, which for radii below 5 is every octant
    // (r = 1 steps a quarter turn at a time): every start within 8 of the
    // center, as a full circle and a turn more, and as arcs ending near
    // each ray, both ways round, circle and helix.
    for (u, v, end, full) in small_arcs(8) {
        for turns in 0..=u64::from(full) {
            for ccw in [true, false] {
                let arc = Arc {
                    plane: 0,
                    ccw,
                    center: [0, 0, 0],
                    start: [u, v],
                    end,
                    turns,
                };
                check_fills(&arc.request("circle", 0, ""), TiePolicy::Advance, 7).unwrap();
                check_fills(&arc.request("helix", 5, ""), TiePolicy::Advance, 7).unwrap();
            }
        }
    }
}

#[test]
fn a_full_circle_of_radius_two_to_the_twenty_near_the_limit() {
    // r = 2^20 around a center whose circle touches x = 2^30 - 1 and
    // y = -(2^30 - 1): about 4 sqrt(2) r = 5.9 million steps.
    let r = 1i64 << 20;
    let c = COORD_LIMIT - r - 1;
    let t = voxpath::trace_json(&format!(
        r#"{{"algorithm":"circle","from":[{},{},7],"to":[{},{},7],"center":[{c},{},7]}}"#,
        c + r,
        -c,
        c + r,
        -c,
        -c
    ))
    .unwrap();
    assert_eq!(t.end(), t.start());
    assert!(t.metrics().max_deviation < 0.5);
    // A full circle from an axis point is four 90°-rotated quarters.
    let quarter = voxpath::trace_json(&format!(
        r#"{{"algorithm":"circle","from":[{r},0,0],"to":[0,{r},0],"center":[0,0,0]}}"#
    ))
    .unwrap();
    assert_eq!(t.steps(), 4 * quarter.steps());
    let per_turn = t.steps() as f64 / r as f64;
    assert!((per_turn - 4.0 * SQRT_2).abs() < 1e-5, "{per_turn}");
    let p = t.point(t.steps() / 2);
    assert_eq!((p.get(0), p.get(1)), (c - r, -c));
}

#[test]
fn a_big_arc_stays_under_half_a_cell_off_and_chords_follow_grbl() {
    // A 10° arc of r = 2^20 (about 180,000 steps) in G19 far from the origin.
    let r = 1i64 << 20;
    let (a, b) = (
        (r as f64 * (10f64 * PI / 180.0).cos()).round() as i64,
        (r as f64 * (10f64 * PI / 180.0).sin()).round() as i64,
    );
    let (cy, cz) = (-(COORD_LIMIT - r - 5), COORD_LIMIT - r - 5);
    let request = |algorithm: &str| {
        format!(
            r#"{{"algorithm":"{algorithm}","from":[-3,{},{cz}],"to":[-3,{},{}],"center":[0,{cy},{cz}],"plane":"yz"}}"#,
            cy + r,
            cy + a,
            cz + b
        )
    };
    let circle = voxpath::trace_json(&request("circle")).unwrap();
    assert!(circle.metrics().max_deviation < 0.5);
    assert_eq!(circle.end(), Point::new(&[-3, cy + a, cz + b]));
    // Grbl with tolerance 0.5: floor(0.5 × 0.1745 × 2^20 / sqrt(0.5 × (2^21 - 0.5)))
    // = floor(91,503 / 1,024) = 89 chords, sagitta about 0.5 each.
    let chords = voxpath::trace_json(&request("arc-segments")).unwrap();
    assert_eq!(chords.segment_count(), 89);
    assert!(chords.metrics().max_deviation < 0.5 + SQRT_2);
    assert_eq!(chords.end(), circle.end());
}

#[test]
fn the_recording_loops_stay_exact_on_the_largest_circles() {
    // r about 2^30 - 3 around the origin, the largest radius ArcSpec takes
    // there: a short arc (about 3000 steps) from each of 16 angles, so every
    // octant's loop runs with coordinates near 2^30, in each plane and
    // direction. The debug build checks every addition for overflow. Then
    // the same about r = 2^25, the largest radius whose pieces are stepped
    // in i32 lanes (SaleemCircle::vector_fill), on either side of it.
    let radii = [COORD_LIMIT - 3, (1 << 25) - 2, 1 << 25, (1 << 25) + 2];
    for (r, k) in radii
        .iter()
        .flat_map(|&r| (0..16).map(move |k| (r as f64, k)))
    {
        let start = 0.1 + k as f64 * TAU / 16.0;
        let sweep = 3000.0 / r;
        let at = |t: f64| [(r * t.cos()).round() as i64, (r * t.sin()).round() as i64];
        for (plane, axes) in PLANES {
            for dir in ["ccw", "cw"] {
                let (from, to) = (
                    at(start),
                    at(if dir == "ccw" {
                        start + sweep
                    } else {
                        start - sweep
                    }),
                );
                let point = |uv: [i64; 2], h: i64| {
                    let mut p = [0; 3];
                    p[axes[0]] = uv[0];
                    p[axes[1]] = uv[1];
                    p[axes[2]] = h;
                    p
                };
                let json = |algorithm: &str, rise: i64| {
                    format!(
                        r#"{{"algorithm":"{algorithm}","from":{:?},"to":{:?},"center":[0,0,0],"dir":"{dir}","plane":"{plane}"}}"#,
                        point(from, 0),
                        point(to, rise)
                    )
                };
                check_plan(&json("circle", 0)).unwrap();
                for chunk in [1, 7, 300, 4096] {
                    check_fills(&json("circle", 0), TiePolicy::Hold, chunk).unwrap();
                    check_fills(&json("helix", 700), TiePolicy::Advance, chunk).unwrap();
                    check_fills(&json("helix", -9000), TiePolicy::Hold, chunk).unwrap();
                }
            }
        }
    }
}

#[test]
fn circles_that_touch_the_limit_run_within_it() {
    // Every cell of a circle, and every rounded chord vertex, is within
    // ceil(r) of its center on each axis: a circle whose ceil(r) reaches
    // exactly ±2^30 runs, in every arc algorithm, and stays within it.
    for (start, sign) in [
        ([4, 0], 1),
        ([3, 4], 1),
        ([5, 5], -1),
        ([1, 0], -1),
        ([7, 1], 1),
    ] {
        let r_sq = start[0] * start[0] + start[1] * start[1];
        let reach = (1..).find(|&k: &i64| k * k >= r_sq).unwrap();
        let c = sign * (COORD_LIMIT - reach);
        let from = [c + start[0], c + start[1]];
        for (algorithm, rise) in [("circle", 0), ("arc-segments", 0), ("helix", 9)] {
            let json = format!(
                r#"{{"algorithm":"{algorithm}","from":[{},{},0],"to":[{},{},{rise}],"center":[{c},{c},0]}}"#,
                from[0], from[1], from[0], from[1]
            );
            let t = voxpath::trace_json(&json).unwrap_or_else(|e| panic!("{json}: {e}"));
            let p = points(&t);
            let extreme = p
                .iter()
                .flat_map(|q| [q[0], q[1]])
                .map(i64::abs)
                .max()
                .unwrap();
            // The cells at the axis crossings, round(r) out.
            let round_r = ((r_sq as f64).sqrt()).round() as i64;
            assert_eq!(extreme, c.abs() + round_r, "{json}");
            assert!(extreme <= COORD_LIMIT, "{json}");
            assert_eq!(p.last().unwrap(), &[from[0], from[1], rise], "{json}");
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(100))]

    /// Steps are recorded without their decisions: the metrics count the
    /// ties by replaying the segments, which must find the ones the
    /// decisions record, whole or in slices (the wider arcs cross
    /// checkpoints), for the circle and the helix by either method, the
    /// arc or the linear axis major, either tie policy.
    #[test]
    fn the_metrics_count_the_ties_the_decisions_record(
        arc in prop_oneof![arc_strategy(40), arc_strategy(2000)],
        rise in prop_oneof![-40i64..40, -30000i64..30000],
        hold in any::<bool>(),
        parts in 1u64..12,
    ) {
        let tie = if hold { "hold" } else { "advance" };
        for request in [
            arc.request("circle", 0, ""),
            arc.request("helix", rise, &format!(r#","tie":"{tie}""#)),
            arc.request("helix", rise, &format!(r#","method":"segments","tie":"{tie}""#)),
        ] {
            common::check_ties(|| common::trace(&request), parts)
                .map_err(|e| TestCaseError::fail(format!("{request}: {e}")))?;
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Short arcs (about 3,000 steps) of random radius up to the grid's
    /// (each power of two as likely), from any angle, in any plane and
    /// direction, around a center anywhere the circle fits: the circle's
    /// and the helix's recording loops take their rules' steps, and the
    /// dry run leaps to the count stepping gives. The fixed test above
    /// checks a few radii (2^30 - 3 and either side of 2^25, where the
    /// pieces leave i32 lanes); the other tests, radii up to 5,000.
    #[test]
    fn the_recording_loops_take_the_rule_s_steps_at_any_radius(
        (bits, fraction) in (1u32..=30, 0.0f64..1.0),
        start in 0.0f64..TAU,
        center_fraction in prop::array::uniform3(-1.0f64..1.0),
        plane in 0usize..3,
        ccw: bool,
        rise in -9000i64..=9000,
        chunk in prop::sample::select(vec![1usize, 7, 300, 4096]),
    ) {
        let r = ((1i64 << (bits - 1)) as f64 * (1.0 + fraction)).min((COORD_LIMIT - 3) as f64).floor();
        // The center where every cell of the circle (within r + 1 of it on
        // each axis) stays within the grid.
        let room = (COORD_LIMIT - r as i64 - 2) as f64;
        let center = center_fraction.map(|f| (f * room) as i64);
        let sweep = (3000.0 / r).min(PI);
        let at = |t: f64| [(r * t.cos()).round() as i64, (r * t.sin()).round() as i64];
        let (from, to) = (at(start), at(if ccw { start + sweep } else { start - sweep }));
        // Each end rounds up to 0.71 off the circle: an arc takes ends
        // whose radii differ by at most 1.
        let radius = |p: [i64; 2]| (p[0] as f64).hypot(p[1] as f64);
        prop_assume!((radius(from) - radius(to)).abs() <= 1.0);
        let (name, axes) = PLANES[plane];
        let point = |uv: [i64; 2], h: i64| {
            let mut p = [0; 3];
            p[axes[0]] = uv[0] + center[axes[0]];
            p[axes[1]] = uv[1] + center[axes[1]];
            p[axes[2]] = h + center[axes[2]];
            p
        };
        let dir = if ccw { "ccw" } else { "cw" };
        let json = |algorithm: &str, rise: i64| {
            format!(
                r#"{{"algorithm":"{algorithm}","from":{:?},"to":{:?},"center":{:?},"dir":"{dir}","plane":"{name}"}}"#,
                point(from, 0),
                point(to, rise),
                center
            )
        };
        check_plan(&json("circle", 0))?;
        check_fills(&json("circle", 0), TiePolicy::Hold, chunk)?;
        check_fills(&json("helix", rise), TiePolicy::Advance, chunk)?;
    }
}
