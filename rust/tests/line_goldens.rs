//! Worked examples from the four source documents. Every expected number is
//! derived by hand from the equation or table named beside it (see also
//! shared/SEED-NOTES.md), never copied from voxpath's own output.

mod common;

use common::{path, points, run, trace};
use voxpath::grid::Point;
use voxpath::ideal::IdealPath;
use voxpath::line::bresenham2d::{Bresenham2d, Variant};
use voxpath::line::bresenham3d::Bresenham3d;
use voxpath::line::dda::Dda;
use voxpath::line::greedy::Greedy;
use voxpath::line::liu_float::{DRIFT_EXAMPLE, LiuFloat};
use voxpath::line::nd::Nd;
use voxpath::line::regions_wang::{Corner, Region, RegionsWang};
use voxpath::line::walk6::Walk6;
use voxpath::line::{Guard, TieAxis};
use voxpath::request::TiePolicy;
use voxpath::trace::{Decision, Stepper};

const SQRT1_2: f64 = std::f64::consts::FRAC_1_SQRT_2;

fn origin_to(to: &[i64]) -> (Point, Point) {
    (Point::origin(to.len()), Point::new(to))
}

#[test]
fn regions_type_one_line_of_wang_table_2_from_the_equations() {
    // SEED-NOTES / Wang eq. (6)-(10) for (0,0,0)->(10,7,6), ties advance:
    // M_1 = 2*7 - 10 = 4, N_1 = 2*6 - 10 = 2, then eq. (8) per step.
    let (from, to) = origin_to(&[10, 7, 6]);
    let steps = run(RegionsWang::new(from, to, TiePolicy::Advance), from);
    let m: Vec<i64> = steps
        .iter()
        .map(|(_, w)| w.discriminants[0].unwrap())
        .collect();
    let n: Vec<i64> = steps
        .iter()
        .map(|(_, w)| w.discriminants[1].unwrap())
        .collect();
    assert_eq!(m, [4, -2, 12, 6, 0, -6, 8, 2, -4, 10]);
    assert_eq!(n, [2, -6, 6, -2, 10, 2, -6, 6, -2, 10]);
    let got: Vec<Point> = steps.iter().map(|(p, _)| *p).collect();
    assert_eq!(got, points(&common::WANG_10_7_6));
    // Step 5 (M = 0, N = 10 > 0) is segment g: a tie between C and D.
    assert_eq!(steps[4].1.region, Some(Region::G));
    assert!(steps[4].1.tie);
    assert_eq!(steps[4].1.corner, Some(Corner::D));
    // Wang section 3.2 / Fig. 6b: y and z passive, so within √2/2.
    let t = trace(r#"{"algorithm":"regions","from":[0,0,0],"to":[10,7,6]}"#);
    assert_eq!(
        t.deviation_bound().unwrap().value,
        std::f64::consts::FRAC_1_SQRT_2
    );
}

#[test]
fn saleem_3d_holds_on_the_tie_at_step_5() {
    // Saleem section 3 pseudo-code on (0,0,0)->(10,7,6): x is major,
    // ErrorY += 14, ErrorZ += 12, a minor axis steps when its error > 10 and
    // then loses 20. ErrorY runs 14, 8, 22, 16, 10 (= 10: no step), 24, 18,
    // 12, 6, 20; ErrorZ 12, 4, 16, 8, 20, 12, 4, 16, 8, 20.
    let (from, to) = origin_to(&[10, 7, 6]);
    let steps = run(Bresenham3d::new(from, to, TiePolicy::Hold, false), from);
    let error = |axis: usize| -> Vec<i64> {
        steps
            .iter()
            .map(|(_, w)| w.tests[axis].unwrap().tested)
            .collect()
    };
    assert_eq!(error(1), [14, 8, 22, 16, 10, 24, 18, 12, 6, 20]);
    assert_eq!(error(2), [12, 4, 16, 8, 20, 12, 4, 16, 8, 20]);
    let got: Vec<Point> = steps.iter().map(|(p, _)| *p).collect();
    let mut expected = common::WANG_10_7_6;
    expected[4] = [5, 3, 3]; // where Wang and Liu have (5,4,3)
    assert_eq!(got, points(&expected));
    assert!(steps[4].1.is_tie() && steps.iter().filter(|(_, w)| w.is_tie()).count() == 1);
    // Liu's rule (tie = advance) steps there and gives Wang's path.
    let liu = path(Bresenham3d::new(from, to, TiePolicy::Advance, false), from);
    assert_eq!(liu[1..], points(&common::WANG_10_7_6));
}

/// Saleem section 2, eq. (4)-(5) on (0,0)->(10,3), by hand: the error gains 6
/// per step and a y step takes 20 off: 6, 12 (step), -2, 4, 10 (a tie), 16
/// (step), 2, 8, 14 (step), 0. y after each x step, ties held (Saleem's '>').
const SALEEM_10_3_Y: [i64; 10] = [0, 1, 1, 1, 1, 2, 2, 2, 3, 3];

#[test]
fn saleem_2d_in_all_eight_octants() {
    // The other octants are the same rule mirrored (section 2: "this concept
    // can be utilized for movement in other octants"): the major axis takes
    // the role of x, each axis travels toward its end.
    for (to, octant) in [
        ([10, 3], 1),
        ([3, 10], 2),
        ([-3, 10], 3),
        ([-10, 3], 4),
        ([-10, -3], 5),
        ([-3, -10], 6),
        ([3, -10], 7),
        ([10, -3], 8),
    ] {
        let (from, to_p) = origin_to(&to);
        let steps = run(
            Bresenham2d::new(from, to_p, TiePolicy::Hold, Variant::Corrected),
            from,
        );
        let (sx, sy) = (to[0].signum(), to[1].signum());
        let x_major = to[0].abs() == 10;
        let expected: Vec<Point> = (1..=10)
            .map(|k| {
                let (major, minor) = (k, SALEEM_10_3_Y[k as usize - 1]);
                if x_major {
                    Point::new(&[sx * major, sy * minor])
                } else {
                    Point::new(&[sx * minor, sy * major])
                }
            })
            .collect();
        let got: Vec<Point> = steps.iter().map(|(p, _)| *p).collect();
        assert_eq!(got, expected, "to {to:?}");
        assert!(steps.iter().all(|(_, w)| w.octant == octant), "to {to:?}");
        assert!(steps[4].1.is_tie(), "the half-way point at k = 5");
    }
    // Stepping on the tie instead moves y at x = 5.
    let (from, to) = origin_to(&[10, 3]);
    let advance = path(
        Bresenham2d::new(from, to, TiePolicy::Advance, Variant::Corrected),
        from,
    );
    assert_eq!(advance[5], Point::new(&[5, 2]));
}

#[test]
fn saleem_2d_as_printed_runs_ahead_and_is_held() {
    // The pseudo-code as printed takes only Δx = 10 off after a y step:
    // errors 6, 12 (step, 2), 8, 14 (step, 4), 10 (hold), 16 (step, 6),
    // 12 (step: y would be 4), 8, 14 (y would be 5), 10. The printed program
    // ends at (10, 5); voxpath holds y at 3.
    let (from, to) = origin_to(&[10, 3]);
    let steps = run(
        Bresenham2d::new(from, to, TiePolicy::Hold, Variant::Printed),
        from,
    );
    let tested: Vec<i64> = steps.iter().map(|(_, w)| w.test.tested).collect();
    assert_eq!(tested, [6, 12, 8, 14, 10, 16, 12, 8, 14, 10]);
    let y: Vec<i64> = steps.iter().map(|(p, _)| p.get(1)).collect();
    assert_eq!(y, [0, 1, 1, 2, 2, 3, 3, 3, 3, 3]);
    let overshoot: Vec<i64> = steps.iter().map(|(_, w)| w.overshoot.unwrap()).collect();
    assert_eq!(overshoot, [0, 0, 0, 0, 0, 0, 1, 1, 2, 2]);
    assert_eq!(steps[6].1.guard, Guard::Held);
    assert_eq!(steps.last().unwrap().0, to);
}

#[test]
fn liu_table_1_with_four_decimals() {
    // Wang eq. (14)-(15): epsilon_1 = k - 0.5 with k_yx = 0.7, k_zx = 0.6;
    // a passive axis steps when epsilon >= 0, then loses 1; each step adds k.
    // Table 1's epsilon(y_{i+1}) and epsilon(z_{i+1}) of rows i = 0..9 are the
    // values that decide step i + 1.
    let (from, to) = origin_to(&[10, 7, 6]);
    let steps = run(LiuFloat::new(from, to, TiePolicy::Advance, 4), from);
    let eps_y = [0.2, -0.1, 0.6, 0.3, 0.0, -0.3, 0.4, 0.1, -0.2, 0.5];
    // Row 8 prints 0.1; eq. (15) gives 0.3 - 1 + 0.6 = -0.1 (an erratum: z
    // holds at step 9 in the table's own z column).
    let eps_z = [0.1, -0.3, 0.3, -0.1, 0.5, 0.1, -0.3, 0.3, -0.1, 0.5];
    for (i, (_, why)) in steps.iter().enumerate() {
        assert!(
            (why.epsilon[1].unwrap() - eps_y[i]).abs() < 1e-12,
            "row {i}"
        );
        assert!(
            (why.epsilon[2].unwrap() - eps_z[i]).abs() < 1e-12,
            "row {i}"
        );
        assert!(why.guards.iter().all(|&g| g == Guard::Rule));
    }
    let got: Vec<Point> = steps.iter().map(|(p, _)| *p).collect();
    assert_eq!(got, points(&common::WANG_10_7_6));
    // Row 4: epsilon(y) = 0, the tie Liu steps on.
    assert!(steps[4].1.tie);
}

#[test]
fn liu_with_one_decimal_strays_beyond_the_exact_bound() {
    // Wang section 4 / Fig. 10. Search the lines from the origin with x
    // active, in order of |Δx|, |Δy|, |Δz|, for the first one where one
    // decimal strays beyond sqrt(2)/2: it is the one the teaching text names.
    let max_deviation = |to: Point, decimals: u32| {
        let from = Point::origin(3);
        let ideal = IdealPath::Line { from, to };
        path(LiuFloat::new(from, to, TiePolicy::Advance, decimals), from)
            .iter()
            .map(|p| ideal.deviation(p))
            .fold(0.0, f64::max)
    };
    let first = (1..=12)
        .flat_map(|x| (0..x).flat_map(move |y| (0..x).map(move |z| [x, y, z])))
        .find(|to| max_deviation(Point::new(to), 1) > SQRT1_2)
        .expect("one decimal strays on some short line");
    assert_eq!(first, DRIFT_EXAMPLE);
    // By hand: k = 1/7 kept as 0.1, epsilon = -0.4, -0.3, -0.2, -0.1, 0, so
    // y and z first step at x = 5 and (4,0,0) is |(4,0,0) x (7,1,1)| / |(7,1,1)|
    // = sqrt(32/51) from the line.
    let to = Point::new(&DRIFT_EXAMPLE);
    let drifted = path(
        LiuFloat::new(Point::origin(3), to, TiePolicy::Advance, 1),
        Point::origin(3),
    );
    assert_eq!(drifted[4], Point::new(&[4, 0, 0]));
    assert!((max_deviation(to, 1) - (32.0f64 / 51.0).sqrt()).abs() < 1e-12);
    // Four decimals keep it within the bound (it is then Bresenham's path).
    assert!(max_deviation(to, 4) <= SQRT1_2);
}

#[test]
fn greedy_runs_along_x_first_as_seed_notes_say() {
    // SEED-NOTES: (0,0)->(8,3) goes (1,0)...(6,0),(6,1),(7,1),(7,2),(8,2),(8,3):
    // the axis with the most left moves, ties to x (the post's xDist <= yDist).
    let (from, to) = origin_to(&[8, 3]);
    let steps = run(Greedy::new(from, to, TieAxis::Lower), from);
    let got: Vec<Point> = steps.iter().map(|(p, _)| *p).collect();
    let expected = points(&[
        [1, 0],
        [2, 0],
        [3, 0],
        [4, 0],
        [5, 0],
        [6, 0],
        [6, 1],
        [7, 1],
        [7, 2],
        [8, 2],
        [8, 3],
    ]);
    assert_eq!(got, expected);
    // First decision: moving x leaves 7^2 + 3^2 = 58, moving y 8^2 + 2^2 = 68.
    assert_eq!(steps[0].1.candidates[..2], [Some(58), Some(68)]);
    // At (5,0), 3 left on each axis: 2^2 + 3^2 = 13 either way, x goes.
    assert_eq!(steps[5].1.candidates[..2], [Some(13), Some(13)]);
    assert!(steps[5].1.tie);
    // The metrics: the farthest point is (6,0), 18/sqrt(73) from the line;
    // the time-based error of eq. (11) peaks there too: 6 - 8·6/11 = 18/11 on
    // x and 0 - 3·6/11 on y.
    let t = trace(r#"{"algorithm":"greedy","from":[0,0],"to":[8,3]}"#);
    let m = t.metrics();
    assert_eq!(m.steps, 11);
    assert_eq!(m.steps_moving_axes, [11, 0]);
    assert_eq!(m.pulses_by_axis, [8, 3]);
    assert!((m.max_deviation - 18.0 / 73f64.sqrt()).abs() < 1e-12);
    for e in &m.max_axis_error {
        assert!((e - 18.0 / 11.0).abs() < 1e-12);
    }
    assert_eq!(m.ties, 3);
    let tie_steps: Vec<usize> = steps
        .iter()
        .enumerate()
        .filter(|(_, (_, w))| w.tie)
        .map(|(k, _)| k)
        .collect();
    // Equal remaining distances at (5,0) (3,3), (6,1) (2,2) and (7,2) (1,1).
    assert_eq!(tie_steps, [5, 7, 9]);
}

#[test]
fn nd_five_axes_follow_eq_16_and_17() {
    // (0,0,0,0,0)->(10,7,6,5,3), x active. Eq. (17): H_1 = 2·5 - 10 = 0,
    // K_1 = 2·3 - 10 = -4; eq. (16): H gains 10, K gains 6, each loses 20 when
    // its axis steps. Ties advance: H = 0, -10, 0, -10, ... (A steps every
    // other step from the first); K = -4, 2, -12, -6, 0, -14, -8, -2, 4, -10.
    // y and z are Wang's M and N of the 3D example.
    let (from, to) = origin_to(&[10, 7, 6, 5, 3]);
    let steps = run(Nd::new(from, to, TiePolicy::Advance, false), from);
    let column = |axis: usize| -> Vec<i64> {
        steps
            .iter()
            .map(|(_, w)| w.discriminants[axis].unwrap())
            .collect()
    };
    assert_eq!(column(1), [4, -2, 12, 6, 0, -6, 8, 2, -4, 10]);
    assert_eq!(column(2), [2, -6, 6, -2, 10, 2, -6, 6, -2, 10]);
    assert_eq!(column(3), [0, -10, 0, -10, 0, -10, 0, -10, 0, -10]);
    assert_eq!(column(4), [-4, 2, -12, -6, 0, -14, -8, -2, 4, -10]);
    let a: Vec<i64> = steps.iter().map(|(p, _)| p.get(3)).collect();
    let b: Vec<i64> = steps.iter().map(|(p, _)| p.get(4)).collect();
    assert_eq!(a, [1, 1, 2, 2, 3, 3, 4, 4, 5, 5]);
    assert_eq!(b, [0, 1, 1, 1, 2, 2, 2, 2, 3, 3]);
    let xyz: Vec<Point> = steps
        .iter()
        .map(|(p, _)| Point::new(&p.coords()[..3]))
        .collect();
    assert_eq!(xyz, points(&common::WANG_10_7_6));
}

#[test]
fn walk6_visits_the_cells_the_segment_crosses() {
    // (0,0)->(3,2): x faces at t = 1/6, 3/6, 5/6 and y faces at 1/4, 3/4
    // (t = (2k + 1) / 2|Δ|), in order x, y, x, y, x.
    let (from, to) = origin_to(&[3, 2]);
    let steps = run(Walk6::new(from, to, TieAxis::Lower), from);
    let got: Vec<Point> = steps.iter().map(|(p, _)| *p).collect();
    assert_eq!(got, points(&[[1, 0], [1, 1], [2, 1], [2, 2], [3, 2]]));
    let first = steps[0].1.crossings;
    assert_eq!((first[0].unwrap().num, first[0].unwrap().den), (1, 6));
    assert_eq!((first[1].unwrap().num, first[1].unwrap().den), (1, 4));
    // (0,0)->(2,2) passes exactly through the corners at t = 1/4 and 3/4:
    // lower-first steps x there, higher-first y.
    let (from, to) = origin_to(&[2, 2]);
    let lower = path(Walk6::new(from, to, TieAxis::Lower), from);
    let higher = path(Walk6::new(from, to, TieAxis::Higher), from);
    assert_eq!(lower[1..], points(&[[1, 0], [1, 1], [2, 1], [2, 2]]));
    assert_eq!(higher[1..], points(&[[0, 1], [1, 1], [1, 2], [2, 2]]));
}

#[test]
fn dda_float_breaks_an_exact_half() {
    // (0,0)->(14,1): after 7 steps the exact accumulator is 7·(1/14) = 1/2,
    // which floor(acc + 0.5) rounds up; seven additions of the f64 nearest
    // 1/14 give 0.4999999999999999, so the DDA keeps y = 0 there.
    let (from, to) = origin_to(&[14, 1]);
    let steps = run(Dda::new(from, to), from);
    assert!(steps[6].1.acc[1] < 0.5);
    assert_eq!(steps[6].0, Point::new(&[7, 0]));
    assert_eq!(steps[7].0, Point::new(&[8, 1]));
    // The exact rules put the step at x = 7 when ties advance.
    let exact = path(Nd::new(from, to, TiePolicy::Advance, false), from);
    assert_eq!(exact[7], Point::new(&[7, 1]));
}

#[test]
fn dda_far_from_the_origin_drifts_and_the_finish_rule_lands_it() {
    // Near 2^29 the f64 spacing is 2^-23; adding 4000001/12000000 there
    // rounds the same way each time, and after 12,000,000 additions the y
    // accumulator is more than half a cell short: floor(acc + 0.5) gives the
    // end y minus 1. The finish rule forces y on the last step.
    let y0 = (1i64 << 29) + 1;
    let from = Point::new(&[0, y0]);
    let to = Point::new(&[12_000_000, y0 + 4_000_001]);
    let mut dda = Dda::new(from, to);
    let mut p = from;
    let mut last = None;
    let mut forced = 0;
    while let Some((step, why)) = dda.next_step() {
        p.apply(step);
        forced += (why.guards[1] == Guard::Forced) as u32;
        last = Some(why);
    }
    assert_eq!(p, to);
    assert_eq!(last.unwrap().rounded[1], to.get(1) - 1);
    assert!(forced >= 1);
}

#[test]
fn gcd_reduction_keeps_the_path_and_divides_the_discriminants() {
    // Wang section 4: Δ = (8000, 6000, 5000) has GCD 1000 and reduces to
    // (8, 6, 5); the discriminants are linear in Δ, so every one is 1000
    // times smaller and the pattern of 8 steps repeats 1000 times.
    for (algorithm, columns) in [("regions", 0..2), ("nd", 1..3), ("bresenham3d", 1..3)] {
        let json = |gcd: bool| {
            format!(
                r#"{{"algorithm":"{algorithm}","from":[0,0,0],"to":[8000,6000,5000],"gcd":{gcd}}}"#
            )
        };
        let (full, reduced) = (trace(&json(false)), trace(&json(true)));
        assert_eq!(
            full.points_flat(0, 8001),
            reduced.points_flat(0, 8001),
            "{algorithm}"
        );
        let (a, b) = (full.decisions(0, 8000), reduced.decisions(0, 8000));
        for c in columns {
            for k in 0..8000 {
                assert_eq!(
                    a.columns[c][k],
                    1000.0 * b.columns[c][k],
                    "{algorithm} column {c} step {k}"
                );
                assert_eq!(
                    b.columns[c][k],
                    b.columns[c][k % 8],
                    "{algorithm} repeats every 8 steps"
                );
            }
        }
        assert!(reduced.segment_note(0).contains("(8, 6, 5)"), "{algorithm}");
    }
}

#[test]
fn every_algorithm_names_the_field_it_rejects() {
    let e = |json: &str| voxpath::trace_json(json).err().unwrap().to_string();
    assert_eq!(
        e(r#"{"algorithm":"bresenham2d","from":[0,0,0],"to":[1,2,3]}"#),
        "from: bresenham2d takes 2 coordinates, got 3"
    );
    assert_eq!(
        e(r#"{"algorithm":"bresenham3d","from":[0,0],"to":[1,2]}"#),
        "from: bresenham3d takes 3 coordinates, got 2"
    );
    assert_eq!(
        e(r#"{"algorithm":"liu-float","from":[0,0,0],"to":[1,2,3],"decimals":11}"#),
        "decimals: must be 0 to 10, got 11"
    );
    assert_eq!(
        e(r#"{"algorithm":"nd","from":[0,0,0],"to":[1,2,3],"gcd":"yes"}"#),
        "gcd: expected true or false, got \"yes\""
    );
    assert_eq!(
        e(r#"{"algorithm":"walk6","from":[0,0],"to":[1,2],"tieAxis":"x"}"#),
        "tieAxis: expected one of lower, higher, got \"x\""
    );
    assert_eq!(
        e(r#"{"algorithm":"bresenham2d","from":[0,0],"to":[1,2],"variant":"typo"}"#),
        "variant: expected one of corrected, printed, got \"typo\""
    );
    assert_eq!(
        e(r#"{"algorithm":"greedy","from":[0,0],"to":[1,2],"tie":"hold"}"#),
        "tie: greedy does not take this option (it takes from, to, tieAxis, maxSteps)"
    );
    assert_eq!(
        e(r#"{"algorithm":"dda","from":[0,0,0,0,0,0,0],"to":[1,2]}"#),
        "from: expected 2 to 6 coordinates, got 7"
    );
}

#[test]
fn every_algorithm_takes_a_zero_length_move_as_an_empty_trace() {
    let lines = voxpath::algorithms::ALGORITHMS
        .iter()
        .filter(|a| a.family == voxpath::algorithms::Family::Line);
    for a in lines {
        let coords = vec![7; a.min_dims];
        let t = trace(&format!(
            r#"{{"algorithm":"{}","from":{coords:?},"to":{coords:?}}}"#,
            a.id
        ));
        assert_eq!(t.steps(), 0, "{}", a.id);
        assert_eq!(t.metrics().max_deviation, 0.0, "{}", a.id);
        assert!(!t.segment_note(0).is_empty(), "{}", a.id);
    }
}

#[test]
fn explanations_name_the_values_that_decided() {
    let explain = |json: &str, k: u64| trace(json).explain(k);
    assert_eq!(
        explain(
            r#"{"algorithm":"bresenham3d","from":[0,0,0],"to":[10,7,6]}"#,
            4
        ),
        "x is the major axis and steps; errorY = 10 = 10 (a tie), and the tie policy 'hold' says y holds; errorZ = 20 > 10, so z steps; the step goes to (x+1, y, z+1)."
    );
    assert_eq!(
        explain(
            r#"{"algorithm":"nd","from":[0,0,0,0,0],"to":[10,7,6,5,3]}"#,
            1
        ),
        "x steps as active; Dy = -2 < 0, so y holds; Dz = -6 < 0, so z holds; Da = -10 < 0, so a holds; Db = 2 > 0, so b steps; the step goes to (x+1, y, z, a, b+1)."
    );
    assert_eq!(
        explain(
            r#"{"algorithm":"liu-float","from":[0,0,0],"to":[7,1,1]}"#,
            4
        ),
        "x steps as active; epsilon(y) = 0.0, a tie that 'advance' decides, so y steps (it has drifted -0.214 from its exact value); epsilon(z) = 0.0, a tie that 'advance' decides, so z steps (it has drifted -0.214 from its exact value); the step goes to (x+1, y+1, z+1)."
    );
    assert_eq!(
        explain(r#"{"algorithm":"greedy","from":[0,0],"to":[8,3]}"#, 5),
        "Squared distance to the goal after moving x 13, y 13: x is the smallest (tied; the lower axis goes first), so x steps to (x+1, y)."
    );
    assert_eq!(
        explain(r#"{"algorithm":"walk6","from":[0,0,0],"to":[2,2,1]}"#, 2),
        "The segment leaves this cell through its z face first, at t = 1/2; x crosses at 3/4 (1·4 = 4 < 3·2 = 6), so z steps to (x, y, z+1)."
    );
    assert_eq!(
        explain(r#"{"algorithm":"dda","from":[0,0],"to":[14,1]}"#, 6),
        "x accumulator 7 rounds to 7, so x steps; y accumulator 0.4999999999999999 rounds to 0, so y stays; the step goes to (x+1, y)."
    );
    assert_eq!(
        explain(
            r#"{"algorithm":"bresenham2d","from":[0,0],"to":[10,3],"variant":"printed"}"#,
            6
        ),
        "Octant 1: x steps every time; the error is 12 > 10, so the rule says y steps; y has reached its end coordinate, so the finish rule holds it (the printed program would now be 1 past the end); the step goes to (x+1, y)."
    );
    // A step the finish rule forced is said as the rule's decision and then
    // the override, as bresenham2d's is: it read "epsilon(y) = -1 < 0, so y
    // steps", the comparison credited with the step it refused.
    assert_eq!(
        explain(
            r#"{"algorithm":"liu-float","from":[0,0,0],"to":[7,3,1],"decimals":0}"#,
            4
        ),
        "x steps as active; epsilon(y) = -1 < 0, so the rule says y holds (it has drifted -2.643 from its exact value); y has as many units left as there are steps, so the finish rule forces it; epsilon(z) = -1 < 0, so z holds (it has drifted -1.214 from its exact value); the step goes to (x+1, y+1, z)."
    );
    // dda's words (the finish rule seldom acts on its f64 drift): the same
    // three cases.
    use voxpath::line::Guard;
    assert_eq!(Guard::Rule.decided(1, false, "stays"), "so y stays");
    assert_eq!(
        Guard::Held.decided(1, false, "stays"),
        "so the rule says y steps"
    );
    assert_eq!(
        Guard::Forced.decided(0, true, "stays"),
        "so the rule says x stays"
    );
}
