//! Properties of every line algorithm on random lines of 2 to 6 axes, in
//! every direction, anywhere within +-2^30; and the longest lines the grid
//! allows, checked against closed forms.
#![allow(clippy::needless_range_loop)]

mod common;

use common::{path, run};
use proptest::prelude::*;
use voxpath::grid::{COORD_LIMIT, MAX_AXES, Point, Step};
use voxpath::ideal::IdealPath;
use voxpath::line::TieAxis;
use voxpath::line::bresenham2d::{Bresenham2d, Variant};
use voxpath::line::bresenham3d::Bresenham3d;
use voxpath::line::dda::Dda;
use voxpath::line::greedy::Greedy;
use voxpath::line::liu_float::LiuFloat;
use voxpath::line::nd::Nd;
use voxpath::line::regions_wang::RegionsWang;
use voxpath::line::walk6::{Crossing, Walk6};
use voxpath::request::TiePolicy;
use voxpath::trace::{Stepper, fill_onto};

/// Algorithms that move one axis per step (sum |Δ| steps); the others step
/// every active axis every time (max |Δ| steps).
const ONE_AXIS_PER_STEP: &[&str] = &["greedy", "walk6"];

/// A random line: `dims` axes, |Δ| per axis below `scale` (small scales make
/// ties and equal magnitudes common), any direction, anywhere in the grid.
fn line_strategy(dims: std::ops::RangeInclusive<usize>) -> impl Strategy<Value = (Point, Point)> {
    let room = COORD_LIMIT - 400;
    (
        dims,
        prop::sample::select(vec![6i64, 24, 400]),
        prop::array::uniform6(0i64..400),
        prop::array::uniform6(any::<bool>()),
        prop::array::uniform6(-room..room),
    )
        .prop_map(|(dims, scale, raw, negative, start)| {
            let mut to = start;
            for axis in 0..MAX_AXES {
                let m = raw[axis] % scale;
                to[axis] += if negative[axis] { -m } else { m };
            }
            (Point::new(&start[..dims]), Point::new(&to[..dims]))
        })
}

/// How far a passive axis of [`nearly_aligned_line`] moves.
#[derive(Clone, Copy, Debug)]
enum Passive {
    Still,
    /// Up to this many units.
    Units(i64),
    /// Up to the major axis's |Δ| over this.
    Fraction(i64),
}

/// A line along one axis or nearly: a random major axis of |Δ| up to
/// 30,000, each other axis still, a few units, or up to 1/16 or 1/1024 of
/// the major's; any direction. CNC's commonest moves, on which the
/// recording loops take shortcuts of their own (a batch of the major
/// axis's steps at once, or a block past the finish rule's proven span).
fn nearly_aligned_line(
    dims: std::ops::RangeInclusive<usize>,
) -> impl Strategy<Value = (Point, Point)> {
    let passive = prop_oneof![
        Just(Passive::Still),
        Just(Passive::Units(3)),
        Just(Passive::Fraction(16)),
        Just(Passive::Fraction(1024)),
    ];
    (
        dims,
        0usize..MAX_AXES,
        1i64..30_000,
        prop::array::uniform6(passive),
        prop::array::uniform6(0i64..i64::MAX),
        prop::array::uniform6(any::<bool>()),
        prop::array::uniform6(-1000i64..1000),
    )
        .prop_map(|(dims, major, length, passive, raw, negative, start)| {
            let major = major % dims;
            let mut to = start;
            for axis in 0..dims {
                let m = match passive[axis] {
                    _ if axis == major => length,
                    Passive::Still => 0,
                    Passive::Units(n) => raw[axis] % (n.min(length) + 1),
                    Passive::Fraction(over) => raw[axis] % (length / over + 1),
                };
                to[axis] += if negative[axis] { -m } else { m };
            }
            (Point::new(&start[..dims]), Point::new(&to[..dims]))
        })
}

fn tie_strategy() -> impl Strategy<Value = TiePolicy> {
    prop_oneof![Just(TiePolicy::Advance), Just(TiePolicy::Hold)]
}

fn flip(tie: TiePolicy) -> TiePolicy {
    match tie {
        TiePolicy::Advance => TiePolicy::Hold,
        TiePolicy::Hold => TiePolicy::Advance,
    }
}

fn magnitudes(from: &Point, to: &Point) -> Vec<i64> {
    from.delta_to(to)[..from.dims()]
        .iter()
        .map(|d| d.abs())
        .collect()
}

/// sqrt(P)/2 for P passive axes: each passive coordinate is within 1/2 of
/// the ideal one at the same active position.
fn passive_bound(from: &Point, to: &Point) -> f64 {
    let m = magnitudes(from, to);
    let longest = m.iter().copied().max().unwrap_or(0);
    let passive = m.iter().filter(|&&v| v != longest).count();
    (passive as f64).sqrt() / 2.0 + 1e-9
}

/// Does the ideal line pass exactly half way between two cells on some
/// axis at some active step, i.e. is k·|Δa|/n a half for some k in 1..=n?
fn has_half(from: &Point, to: &Point) -> bool {
    let m = magnitudes(from, to);
    let n = m.iter().copied().max().unwrap_or(0);
    m.iter()
        .any(|&ma| (1..=n).any(|k| (2 * k * ma) % (2 * n) == n))
}

fn reversed(mut p: Vec<Point>) -> Vec<Point> {
    p.reverse();
    p
}

/// Is the point at t = num/den of the segment inside the closed unit cell
/// centered on `cell`? Per axis |from + t·Δ - cell| <= 1/2, times 2·den.
fn in_cell(from: &Point, to: &Point, t: Crossing, cell: &Point) -> bool {
    let d = from.delta_to(to);
    (0..from.dims()).all(|a| {
        let offset =
            (from.get(a) - cell.get(a)) as i128 * t.den as i128 + t.num as i128 * d[a] as i128;
        2 * offset.abs() <= t.den as i128
    })
}

/// Lines whose passive slopes are exact binary fractions put the DDA's
/// accumulators exactly half way between cells again and again, where its
/// rule (floor(acc + 0.5)) rounds up: the recording loop's cell-edge test
/// must take those ties as next_step does, going up and going down.
#[test]
fn the_dda_recording_loop_rounds_exact_halves_as_next_step_does() {
    for to in [
        [2000, 1000, 500],
        [-2000, 1000, -1500],
        [4096, -3072, 1024],
        [-1000, -500, 250],
        [1000, 500, 0],
    ] {
        let (from, to) = (
            Point::new(&[3, -7, 11]),
            Point::new(&[to[0] + 3, to[1] - 7, to[2] + 11]),
        );
        for chunk in [17, 100, 4096] {
            common::check_fill(|| Dda::new(from, to), chunk).unwrap();
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(150))]

    #[test]
    fn every_algorithm_steps_toward_the_end_and_lands_on_it(
        (from, to) in line_strategy(2..=6)
    ) {
        let m = magnitudes(&from, &to);
        let delta = from.delta_to(&to);
        for a in common::line_algorithms() {
            if !(a.min_dims..=a.max_dims).contains(&from.dims()) {
                continue;
            }
            let t = common::trace(&format!(
                r#"{{"algorithm":"{}","from":{:?},"to":{:?}}}"#, a.id, from.coords(), to.coords()
            ));
            let one_axis = ONE_AXIS_PER_STEP.contains(&a.id);
            let expected = if one_axis { m.iter().sum::<i64>() } else { m.iter().copied().max().unwrap() };
            prop_assert_eq!(t.steps() as i64, expected, "{}", a.id);
            prop_assert_eq!(t.end(), to, "{}", a.id);
            for step in t.step_range(0, t.steps()) {
                for axis in 0..from.dims() {
                    let d = step.delta(axis);
                    prop_assert!(d == 0 || d == delta[axis].signum(), "{} moved {} away from the end", a.id, axis);
                }
                if one_axis {
                    prop_assert_eq!(step.axis_count(), 1, "{}", a.id);
                } else {
                    // 26-connected (8 in 2D): active axes always move.
                    for axis in 0..from.dims() {
                        if m[axis] == expected {
                            prop_assert!(step.delta(axis) != 0, "{}: active axis {} held", a.id, axis);
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn no_point_strays_past_the_bound_its_algorithm_states(
        (from, to) in line_strategy(2..=6)
    ) {
        // The bound the core hands the page (Wang Fig. 6b's √2/2 line) is a
        // promise: the rules that keep each passive axis within half a cell
        // state √P/2, walk6 √D/2; the float rules and greedy state none.
        let promised = ["regions", "bresenham2d", "bresenham3d", "nd", "walk6"];
        for a in common::line_algorithms() {
            if !(a.min_dims..=a.max_dims).contains(&from.dims()) {
                continue;
            }
            let t = common::trace(&format!(
                r#"{{"algorithm":"{}","from":{:?},"to":{:?}}}"#, a.id, from.coords(), to.coords()
            ));
            let Some(bound) = t.deviation_bound() else {
                prop_assert!(!promised.contains(&a.id), "{} states no bound", a.id);
                continue;
            };
            prop_assert!(promised.contains(&a.id), "{} states a bound it does not keep in general", a.id);
            let expected = if a.id == "walk6" { (from.dims() as f64).sqrt() / 2.0 } else { passive_bound(&from, &to) - 1e-9 };
            prop_assert!((bound.value - expected).abs() < 1e-12, "{}: {} vs {}", a.id, bound.value, expected);
            prop_assert!(t.metrics().max_deviation <= bound.value + 1e-9, "{}: {} > {}", a.id, t.metrics().max_deviation, bound.value);
        }
    }

    #[test]
    fn the_recording_loops_take_the_rule_s_steps(
        (from, to) in line_strategy(2..=6), tie in tie_strategy(), gcd in any::<bool>(), chunk in 1usize..300
    ) {
        // Bresenham2d (corrected), Bresenham3d and Nd record through the
        // shared branch-free loop (line::terms), greedy and walk6 through
        // loops of their own, liu-float on the integers its decimals stand
        // for, the DDA with its number of axes a constant; none through
        // next_step.
        common::check_fill(|| Nd::new(from, to, tie, gcd), chunk).map_err(TestCaseError::fail)?;
        common::check_fill(|| Dda::new(from, to), chunk).map_err(TestCaseError::fail)?;
        for order in [TieAxis::Lower, TieAxis::Higher] {
            common::check_fill(|| Greedy::new(from, to, order), chunk).map_err(TestCaseError::fail)?;
            common::check_fill(|| Walk6::new(from, to, order), chunk).map_err(TestCaseError::fail)?;
        }
        if from.dims() == 2 {
            for variant in [Variant::Corrected, Variant::Printed] {
                common::check_fill(|| Bresenham2d::new(from, to, tie, variant), chunk).map_err(TestCaseError::fail)?;
            }
        }
        if from.dims() == 3 {
            common::check_fill(|| Bresenham3d::new(from, to, tie, gcd), chunk).map_err(TestCaseError::fail)?;
            for decimals in [0, 1, 4, 10] {
                common::check_fill(|| LiuFloat::new(from, to, tie, decimals), chunk).map_err(TestCaseError::fail)?;
            }
        }
    }

    #[test]
    fn nd_recurrence_is_the_closed_form_within_half_a_cell_per_axis(
        (from, to) in line_strategy(2..=6), tie in tie_strategy(), gcd in any::<bool>()
    ) {
        // Eq. (16) equals eq. (6) generalised before every step; each passive
        // coordinate is within 1/2 of the ideal one at the same active
        // position (eq. 11's phi, since the active axis steps every time).
        let ideal = IdealPath::Line { from, to };
        let n = magnitudes(&from, &to).into_iter().max().unwrap() as u64;
        let mut nd = Nd::new(from, to, tie, gcd);
        let mut p = from;
        let mut k = 0;
        while let Some((step, why)) = nd.clone().next_step() {
            prop_assert_eq!(why.discriminants, nd.closed_form(&p));
            nd.next_step();
            p.apply(step);
            k += 1;
            prop_assert!(ideal.deviation(&p) <= passive_bound(&from, &to));
            for phi in &ideal.axis_error(&p, k, n)[..from.dims()] {
                prop_assert!(phi.abs() <= 0.5 + 1e-9, "{:?} at {:?}", phi, p);
            }
        }
    }

    #[test]
    fn nd_with_three_axes_is_the_method_of_discriminate_regions(
        (from, to) in line_strategy(3..=3), tie in tie_strategy()
    ) {
        let regions = path(RegionsWang::new(from, to, tie), from);
        prop_assert_eq!(&path(Nd::new(from, to, tie, false), from), &regions);
        // Saleem's rule is the same (its error minus |Δmajor| is Wang's
        // discriminant): with ties advancing it is Liu's, with ties held Saleem's.
        prop_assert_eq!(&path(Bresenham3d::new(from, to, tie, false), from), &regions);
    }

    #[test]
    fn saleem_error_minus_the_threshold_is_wang_s_discriminant(
        (from, to) in line_strategy(3..=3), tie in tie_strategy()
    ) {
        let nd = Nd::new(from, to, tie, false);
        let points = path(Bresenham3d::new(from, to, tie, false), from);
        for (k, (_, why)) in run(Bresenham3d::new(from, to, tie, false), from).into_iter().enumerate() {
            let closed = nd.closed_form(&points[k]);
            for axis in 0..3 {
                if let (Some(t), Some(d)) = (why.tests[axis], closed[axis]) {
                    prop_assert_eq!(t.tested - why.threshold, d);
                }
            }
        }
    }

    #[test]
    fn bresenham2d_is_wang_s_rule_in_the_plane(
        (from, to) in line_strategy(2..=2), tie in tie_strategy()
    ) {
        let saleem = path(Bresenham2d::new(from, to, tie, Variant::Corrected), from);
        prop_assert_eq!(&saleem, &path(Nd::new(from, to, tie, false), from));
        let ideal = IdealPath::Line { from, to };
        prop_assert!(saleem.iter().all(|p| ideal.deviation(p) <= 0.5 + 1e-9));
        // As printed it runs ahead, but the finish rule still lands it.
        let printed = path(Bresenham2d::new(from, to, tie, Variant::Printed), from);
        prop_assert_eq!(printed.last(), Some(&to));
        prop_assert_eq!(printed.len(), saleem.len());
    }

    #[test]
    fn reversing_with_the_tie_rule_flipped_mirrors_the_exact_rules(
        (from, to) in line_strategy(2..=6), tie in tie_strategy(), lower in any::<bool>()
    ) {
        // A tie that advances one way is a tie that holds the other way; so
        // the reversed move with the policy flipped visits the same cells.
        prop_assert_eq!(
            path(Nd::new(from, to, tie, false), from),
            reversed(path(Nd::new(to, from, flip(tie), false), to))
        );
        if from.dims() == 2 {
            let fwd = path(Bresenham2d::new(from, to, tie, Variant::Corrected), from);
            let back = path(Bresenham2d::new(to, from, flip(tie), Variant::Corrected), to);
            prop_assert_eq!(fwd, reversed(back));
        }
        // walk6: an edge stepped lower-axis-first forwards is stepped
        // higher-axis-first backwards.
        let (order, other) = if lower { (TieAxis::Lower, TieAxis::Higher) } else { (TieAxis::Higher, TieAxis::Lower) };
        prop_assert_eq!(
            path(Walk6::new(from, to, order), from),
            reversed(path(Walk6::new(to, from, other), to))
        );
    }

    #[test]
    fn walk6_rounds_in_batches_take_the_rule_s_steps(
        (from, to) in line_strategy(2..=3), stretch in 1i64..60, chunk in 190usize..5000
    ) {
        // Walk6 on two or three axes decides most rounds of its major axis
        // a batch of 64 to 1,024 at a time: lines of up to 24,000 steps a
        // axis, stretched from the random ones so that batches of every
        // size start within rounds, after a chunk's end and where faces tie.
        // Moved in from the grid's edge to make room for the stretch.
        let room = COORD_LIMIT - 24_000;
        let start: Vec<i64> = from.coords().iter().map(|&c| c.clamp(-room, room)).collect();
        let end: Vec<i64> = (0..from.dims()).map(|a| start[a] + (to.get(a) - from.get(a)) * stretch).collect();
        let (start, end) = (Point::new(&start), Point::new(&end));
        for order in [TieAxis::Lower, TieAxis::Higher] {
            common::check_fill(|| Walk6::new(start, end, order), chunk).map_err(TestCaseError::fail)?;
        }
    }

    #[test]
    fn walk6_along_one_axis_or_nearly_takes_the_rule_s_steps(
        (from, to) in nearly_aligned_line(2..=6), chunk in 1usize..5000
    ) {
        // A line along one axis fills its steps at once; one whose passive
        // axes step seldom takes its batches' rounds where none steps
        // eight at a time, or a whole batch at once.
        for order in [TieAxis::Lower, TieAxis::Higher] {
            common::check_fill(|| Walk6::new(from, to, order), chunk).map_err(TestCaseError::fail)?;
        }
    }

    #[test]
    fn float_rules_along_one_axis_or_nearly_take_the_rule_s_steps(
        (from, to) in nearly_aligned_line(2..=3), tie in tie_strategy(), chunk in 1usize..9000
    ) {
        // A passive axis with a few units to go (or all but a few) keeps
        // the finish rule's proven span short over most of such a line:
        // the DDA and Liu's rule run blocks past it unguarded, each kept
        // whole or run again guarded up to the first step the finish rule
        // changes.
        common::check_fill(|| Dda::new(from, to), chunk).map_err(TestCaseError::fail)?;
        if from.dims() == 3 {
            for decimals in [0, 1, 4, 10] {
                common::check_fill(|| LiuFloat::new(from, to, tie, decimals), chunk).map_err(TestCaseError::fail)?;
            }
        }
    }

    #[test]
    fn walk6_visits_exactly_the_cells_the_segment_passes_through(
        (from, to) in line_strategy(2..=6), lower in any::<bool>()
    ) {
        // The crossings cut the segment [0, 1] into pieces; piece i, from the
        // crossing before cell i to the crossing after it, must lie in cell
        // i. So every visited cell touches the segment, and the visited cells
        // cover all of it (no cell it passes through is skipped).
        let order = if lower { TieAxis::Lower } else { TieAxis::Higher };
        let steps = run(Walk6::new(from, to, order), from);
        let ideal = IdealPath::Line { from, to };
        let mut cell = from;
        let mut entered = Crossing { num: 0, den: 1 };
        for (next, why) in &steps {
            let left = why.crossings[why.crossed].unwrap();
            prop_assert!(in_cell(&from, &to, entered, &cell) && in_cell(&from, &to, left, &cell), "{:?}", cell);
            prop_assert!(ideal.deviation(&cell) <= (from.dims() as f64).sqrt() / 2.0 + 1e-9);
            prop_assert!(left.compare(entered) != std::cmp::Ordering::Less, "crossings go forward");
            cell = *next;
            entered = left;
        }
        let end = Crossing { num: 1, den: 1 };
        prop_assert!(in_cell(&from, &to, entered, &cell) && in_cell(&from, &to, end, &cell));
    }

    #[test]
    fn greedy_levels_the_distances_left_and_strays_with_length(
        (from, to) in line_strategy(2..=6), lower in any::<bool>()
    ) {
        // An axis that has moved is within one unit of the largest distance
        // left (it only moves while it is the largest); so every point is
        // within |Δmax|/4 + 2 per axis of the line point with the same
        // largest distance left, and within sqrt(n)·(|Δmax|/4 + 2) of the
        // line: a bound that grows with the move, unlike the exact rules'.
        let order = if lower { TieAxis::Lower } else { TieAxis::Higher };
        let m = magnitudes(&from, &to);
        let longest = m.iter().copied().max().unwrap() as f64;
        let bound = (from.dims() as f64).sqrt() * (longest / 4.0 + 2.0);
        let ideal = IdealPath::Line { from, to };
        for p in path(Greedy::new(from, to, order), from) {
            let left: Vec<i64> = to.delta_to(&p)[..from.dims()].iter().map(|d| d.abs()).collect();
            let most = left.iter().copied().max().unwrap();
            for axis in 0..from.dims() {
                prop_assert!(left[axis] == m[axis] || left[axis] + 1 >= most, "axis {} unlevelled at {:?}", axis, p);
            }
            prop_assert!(ideal.deviation(&p) <= bound);
        }
        // Reversed, greedy is not the same path backwards: it is the forward
        // path reflected through the middle of the move (it only looks at
        // the distances left, which the reflection swaps with those done).
        let mirrored: Vec<Point> = path(Greedy::new(from, to, order), from)
            .iter()
            .map(|p| {
                let c: Vec<i64> = (0..p.dims()).map(|a| from.get(a) + to.get(a) - p.get(a)).collect();
                Point::new(&c)
            })
            .collect();
        prop_assert_eq!(path(Greedy::new(to, from, order), to), mirrored);
    }

    #[test]
    fn greedy_in_2d_strays_to_the_knee_of_its_path(
        (from, to) in line_strategy(2..=2)
    ) {
        // x-major with ties to x: along x to (a - b + 1, 0), then a staircase
        // closer to the line; the farthest point is that knee, at
        // (a - b + 1)·b / sqrt(a^2 + b^2) from the line (0 when b = 0).
        let m = magnitudes(&from, &to);
        let (a, b) = (m[0].max(m[1]) as f64, m[0].min(m[1]) as f64);
        prop_assume!(m[0] >= m[1] && m[0] > 0);
        let t = common::trace(&format!(
            r#"{{"algorithm":"greedy","from":{:?},"to":{:?}}}"#, from.coords(), to.coords()
        ));
        let knee = if b == 0.0 { 0.0 } else { (a - b + 1.0) * b / (a * a + b * b).sqrt() };
        prop_assert!((t.metrics().max_deviation - knee).abs() < 1e-9, "{} vs {}", t.metrics().max_deviation, knee);
    }

    #[test]
    fn liu_with_ten_decimals_is_the_exact_rule_where_no_half_needs_deciding(
        (from, to) in line_strategy(3..=3), tie in tie_strategy()
    ) {
        // Ten decimals round away less than 1e-10 per step, far below the
        // 1/(2|Δ|) by which a non-zero epsilon misses 0 on these short lines.
        // An exact 0 (a tie) is not kept: k = 13/14 kept to ten decimals is
        // 3e-11 too large, and six steps later epsilon is 2e-10, not 0, so
        // (0,0,0)->(14,13,0) steps y at x = 7 even when ties hold.
        prop_assume!(!has_half(&from, &to));
        prop_assert_eq!(
            path(LiuFloat::new(from, to, tie, 10), from),
            path(Nd::new(from, to, tie, false), from)
        );
    }

    #[test]
    fn dda_is_the_exact_rule_where_no_half_needs_deciding(
        (from, to) in line_strategy(2..=6)
    ) {
        // Where some k·Δa/n is exactly a half, float error decides (see
        // line_goldens.rs); elsewhere the values are 1/(2n) or more from a
        // half, much more than 400 additions can drift even near 2^30.
        prop_assume!(!has_half(&from, &to));
        prop_assert_eq!(
            path(Dda::new(from, to), from),
            path(Nd::new(from, to, TiePolicy::Advance, false), from)
        );
    }
}

const L: i64 = COORD_LIMIT;

/// The first 20,000 steps of a line spanning the whole grid: the decisions
/// must match the closed forms and the bounds must hold that far from the
/// origin, with deltas of 2^31 and products of 2^62.
const LONG_STEPS: usize = 20_000;

#[test]
fn nd_and_bresenham_on_the_longest_lines() {
    let from = Point::new(&[-L, L, -L, L, -L, 0]);
    let to = Point::new(&[L, -L + 3, L - 7, -L, L - 1, 12345]);
    let ideal = IdealPath::Line { from, to };
    let mut nd = Nd::new(from, to, TiePolicy::Advance, false);
    let mut p = from;
    for _ in 0..LONG_STEPS {
        let before = nd.closed_form(&p);
        let (step, why) = nd.next_step().unwrap();
        assert_eq!(why.discriminants, before);
        p.apply(step);
        assert!(ideal.deviation(&p) <= passive_bound(&from, &to));
    }
    assert_eq!(nd.remaining_steps(), Some((1u64 << 31) - LONG_STEPS as u64));

    let (from3, to3) = (Point::new(&[-L, L, -L]), Point::new(&[L, -L + 3, L - 7]));
    let nd3 = Nd::new(from3, to3, TiePolicy::Hold, false);
    let mut saleem = Bresenham3d::new(from3, to3, TiePolicy::Hold, false);
    let mut p = from3;
    for _ in 0..LONG_STEPS {
        let closed = nd3.closed_form(&p);
        let (step, why) = saleem.next_step().unwrap();
        for axis in 1..3 {
            assert_eq!(
                why.tests[axis].unwrap().tested - why.threshold,
                closed[axis].unwrap()
            );
        }
        p.apply(step);
    }

    let (from2, to2) = (Point::new(&[L, -L]), Point::new(&[-L, L - 1]));
    let nd2 = Nd::new(from2, to2, TiePolicy::Hold, false);
    let mut saleem = Bresenham2d::new(from2, to2, TiePolicy::Hold, Variant::Corrected);
    let mut p = from2;
    for _ in 0..LONG_STEPS {
        let closed = nd2.closed_form(&p);
        let (step, why) = saleem.next_step().unwrap();
        assert_eq!(why.test.tested - why.threshold, closed[1].unwrap());
        p.apply(step);
    }
}

/// The first LONG_STEPS steps as a trace records them.
fn first_steps_filled<S: Stepper>(mut stepper: S) -> Vec<Step> {
    let mut out = Vec::new();
    assert_eq!(
        fill_onto(&mut stepper, &mut out, LONG_STEPS).steps(),
        LONG_STEPS
    );
    out
}

/// `stepper`'s recording loop against its `next_step`, over the first
/// LONG_STEPS steps: the loop runs two chains (the second started 10,000
/// steps in by a jump) in one vector where the target has one.
fn fill_matches_next_step<S: Stepper + Clone>(name: &str, stepper: S) {
    let filled = first_steps_filled(stepper.clone());
    let mut stepper = stepper;
    for (k, &recorded) in filled.iter().enumerate() {
        let (step, _) = stepper.next_step().unwrap();
        assert_eq!(step, recorded, "{name} fill, step {k}");
    }
}

#[test]
fn integer_rules_record_the_longest_lines_as_they_step() {
    // Passive axes of about 0.7, 0.3, 0.4 and 0.8 of the major's 2^31 units,
    // and of 12,345: right after such an axis steps, its error term is
    // more than 2^31 below its threshold, so a vector mask built from half
    // of each 64-bit lane would show here. Then a line near the diagonal.
    let from = Point::new(&[-L, L, -L, L, -L, 0]);
    let to = Point::new(&[
        L,
        L - 1_503_238_553,
        -L + 644_245_094,
        L - 858_993_459,
        -L + 1_717_986_918,
        12345,
    ]);
    let diagonal = Point::new(&[L, -L + 3, L - 7, -L, L - 1, 12345]);
    for to in [to, diagonal] {
        for tie in [TiePolicy::Hold, TiePolicy::Advance] {
            fill_matches_next_step("nd", Nd::new(from, to, tie, false));
            let (from3, to3) = (
                Point::new(&from.coords()[..3]),
                Point::new(&to.coords()[..3]),
            );
            fill_matches_next_step("bresenham3d", Bresenham3d::new(from3, to3, tie, false));
            fill_matches_next_step("regions", RegionsWang::new(from3, to3, tie));
        }
        let (from2, to2) = (
            Point::new(&from.coords()[..2]),
            Point::new(&to.coords()[..2]),
        );
        fill_matches_next_step(
            "bresenham2d",
            Bresenham2d::new(from2, to2, TiePolicy::Hold, Variant::Corrected),
        );
    }
}

#[test]
fn the_dda_fills_the_finish_rule_s_steps_where_f64_drifts() {
    // line_goldens' line near 2^29, whose y accumulator ends more than half
    // a cell short: the finish rule forces y on the last step, in a block
    // the fill runs unguarded past the proven span, which is run again
    // guarded up to that step.
    let y0 = (1i64 << 29) + 1;
    let from = Point::new(&[0, y0]);
    let to = Point::new(&[12_000_000, y0 + 4_000_001]);
    common::check_fill(|| Dda::new(from, to), 70_000).unwrap();
}

#[test]
fn walk6_and_greedy_on_the_longest_lines() {
    let from = Point::new(&[-L, -L, L]);
    let to = Point::new(&[L, L - 1, -L + 2]);
    let mut walk = Walk6::new(from, to, TieAxis::Lower);
    assert_eq!(walk.remaining_steps(), Some(3 * (1u64 << 31) - 3));
    let filled = first_steps_filled(walk.clone());
    let mut cell = from;
    let mut entered = Crossing { num: 0, den: 1 };
    for k in 0..LONG_STEPS {
        let (step, why) = walk.next_step().unwrap();
        assert_eq!(step, filled[k], "walk6 fill, step {k}");
        let left = why.crossings[why.crossed].unwrap();
        assert!(in_cell(&from, &to, entered, &cell) && in_cell(&from, &to, left, &cell));
        cell.apply(step);
        entered = left;
    }

    // Walk6 by rounds of its major axis, on two axes (the third a
    // placeholder) and on three, in both tie orders, the major axis first
    // and last in axis order, across the grid: where the passive faces
    // tie with the major's (equal |Δ|) and where they do not.
    for (from, to) in [
        (Point::new(&[-L, L]), Point::new(&[L, -L + 7])),
        (Point::new(&[L, -L]), Point::new(&[-L + 2, L])),
        (Point::new(&[-L, L, 5]), Point::new(&[L - 3, -L, 1_000_005])),
        (Point::new(&[-L, -L, L]), Point::new(&[L, L, -L])),
    ] {
        for order in [TieAxis::Lower, TieAxis::Higher] {
            fill_matches_next_step("walk6", Walk6::new(from, to, order));
        }
    }

    let from = Point::new(&[-L, L, -L, L, -L, L]);
    let to = Point::new(&[L, -L, L - 5, -L + 5, L, -L]);
    let mut greedy = Greedy::new(from, to, TieAxis::Lower);
    let filled = first_steps_filled(greedy.clone());
    let mut p = from;
    for k in 0..LONG_STEPS {
        let (step, why) = greedy.next_step().unwrap();
        assert_eq!(step, filled[k], "greedy fill, step {k}");
        // The candidates are the squared distances, exact in i128
        // (six axes of 2^31 squared overflow i64).
        let left: Vec<i128> = to.delta_to(&p)[..6]
            .iter()
            .map(|&d| d.abs() as i128)
            .collect();
        let now: i128 = left.iter().map(|l| l * l).sum();
        for axis in 0..6 {
            let l = left[axis];
            assert_eq!(why.candidates[axis], Some(now - l * l + (l - 1) * (l - 1)));
        }
        p.apply(step);
    }
}

#[test]
fn float_rules_on_the_longest_lines() {
    let from = Point::new(&[-L, L, -L]);
    let to = Point::new(&[L, -L + 3, L - 7]);
    let ideal = IdealPath::Line { from, to };
    let mut dda = Dda::new(from, to);
    let mut liu = LiuFloat::new(from, to, TiePolicy::Advance, 4);
    let (mut p, mut q) = (from, from);
    for _ in 0..LONG_STEPS {
        p.apply(dda.next_step().unwrap().0);
        let (step, why) = liu.next_step().unwrap();
        q.apply(step);
        assert!(why.epsilon[1].unwrap().is_finite() && why.drift[2].unwrap().is_finite());
        // Both are still within the exact bound this early: the DDA's float
        // error and Liu's rounding need millions of steps to add up to cells.
        assert!(ideal.deviation(&p) <= passive_bound(&from, &to));
        assert!(ideal.deviation(&q) <= passive_bound(&from, &to));
    }
    // The recording loops take the same steps this far out, with every
    // number of decimals (Liu's on the integers the decimals stand for).
    let filled = first_steps_filled(Dda::new(from, to));
    let mut dda = Dda::new(from, to);
    for (k, &step) in filled.iter().enumerate() {
        assert_eq!(dda.next_step().unwrap().0, step, "dda fill, step {k}");
    }
    for decimals in 0..=10 {
        let mut liu = LiuFloat::new(from, to, TiePolicy::Hold, decimals);
        let filled = first_steps_filled(liu.clone());
        for (k, &step) in filled.iter().enumerate() {
            assert_eq!(
                liu.next_step().unwrap().0,
                step,
                "liu-float fill, {decimals} decimals, step {k}"
            );
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(100))]

    /// Steps are recorded without their decisions: the metrics count the
    /// ties by replaying the segments, which must find the ones the
    /// decisions record, whole or in slices, with every line algorithm
    /// and either tie policy.
    #[test]
    fn the_metrics_count_the_ties_the_decisions_record(
        (from, to) in line_strategy(2..=6), tie in tie_strategy(), parts in 1u64..12
    ) {
        for a in common::line_algorithms() {
            if !(a.min_dims..=a.max_dims).contains(&from.dims()) {
                continue;
            }
            let tie = if a.default_tie.is_some() {
                format!(r#","tie":"{}""#, tie.label())
            } else {
                String::new()
            };
            let request = format!(
                r#"{{"algorithm":"{}","from":{:?},"to":{:?}{tie}}}"#, a.id, from.coords(), to.coords()
            );
            common::check_ties(|| common::trace(&request), parts)
                .map_err(|e| TestCaseError::fail(format!("{request}: {e}")))?;
        }
    }
}

/// Steps of each random long line below held to the rule: fewer than the
/// fixed longest lines' LONG_STEPS, for eight algorithms a case.
const RANDOM_LONG_STEPS: usize = 3_000;

/// `stepper`'s recording loop against its `next_step` over its first
/// RANDOM_LONG_STEPS steps (or all, on a shorter line).
fn fill_starts_as_next_step<S: Stepper + Clone>(
    name: &str,
    stepper: S,
) -> Result<(), TestCaseError> {
    let mut filled = Vec::new();
    fill_onto(&mut stepper.clone(), &mut filled, RANDOM_LONG_STEPS);
    let mut stepper = stepper;
    for (k, &recorded) in filled.iter().enumerate() {
        let (step, _) = stepper.next_step().unwrap();
        prop_assert_eq!(step, recorded, "{} fill, step {}", name, k);
    }
    Ok(())
}

/// A coordinate anywhere in the grid, its edges more often than by chance.
fn anywhere() -> impl Strategy<Value = i64> {
    prop_oneof![-L..=L, Just(-L), Just(L), (-L..=L).prop_map(|v| v / 4096)]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// Lines between random points anywhere in the grid (|Δ| up to 2^31,
    /// so error terms and their vector lanes near 2^62): every algorithm's
    /// recording loop takes its rule's steps, as the fixed longest lines
    /// above check at a few chosen slopes.
    #[test]
    fn the_recording_loops_take_the_rule_s_steps_on_lines_anywhere(
        from in prop::array::uniform6(anywhere()),
        to in prop::array::uniform6(anywhere()),
        tie in prop::sample::select(vec![TiePolicy::Hold, TiePolicy::Advance]),
        decimals in 0u32..=10,
    ) {
        let (from6, to6) = (Point::new(&from), Point::new(&to));
        let (from3, to3) = (Point::new(&from[..3]), Point::new(&to[..3]));
        let (from2, to2) = (Point::new(&from[..2]), Point::new(&to[..2]));
        fill_starts_as_next_step("nd", Nd::new(from6, to6, tie, false))?;
        fill_starts_as_next_step("bresenham3d", Bresenham3d::new(from3, to3, tie, false))?;
        fill_starts_as_next_step("regions", RegionsWang::new(from3, to3, tie))?;
        fill_starts_as_next_step("bresenham2d", Bresenham2d::new(from2, to2, tie, Variant::Corrected))?;
        fill_starts_as_next_step("dda", Dda::new(from3, to3))?;
        fill_starts_as_next_step("liu-float", LiuFloat::new(from3, to3, tie, decimals))?;
        fill_starts_as_next_step("greedy", Greedy::new(from3, to3, TieAxis::Lower))?;
        fill_starts_as_next_step("walk6", Walk6::new(from6, to6, TieAxis::Higher))?;
    }
}
