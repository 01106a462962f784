//! Properties of Wang's method of discriminate regions on random lines in
#![allow(clippy::needless_range_loop)]
//! every octant and of all seven types (Wang section 2.2).

use proptest::prelude::*;
use voxpath::grid::{COORD_LIMIT, Point, Step, displacement};
use voxpath::ideal::IdealPath;
use voxpath::line::regions_wang::RegionsWang;
use voxpath::trace::{Stepper, TiePolicy};

/// Wang's bound: the ideal line crosses the exit face within the unit square,
/// at most sqrt(2)/2 from the chosen corner (section 3.2).
const MAX_THEORETICAL_ERROR: f64 = std::f64::consts::FRAC_1_SQRT_2;

/// |delta| per axis for one of the seven line types: `line_type` picks which
/// axes share the largest magnitude; the others are strictly smaller.
fn magnitudes(line_type: u8, big: i64, small: [i64; 2]) -> [i64; 3] {
    let s = |i: usize| small[i] % big; // strictly smaller than big
    match line_type {
        1 => [big, s(0), s(1)],
        2 => [big, big, big],
        3 => [s(0), big, s(1)],
        4 => [s(0), s(1), big],
        5 => [big, big, s(0)],
        6 => [s(0), big, big],
        _ => [big, s(0), big],
    }
}

fn line_strategy() -> impl Strategy<Value = (Point, Point, TiePolicy)> {
    (
        1u8..=7,
        1i64..400,
        [0i64..400, 0i64..400],
        [any::<bool>(), any::<bool>(), any::<bool>()],
        [
            -(COORD_LIMIT - 400)..(COORD_LIMIT - 400),
            -1000i64..1000,
            -(COORD_LIMIT - 400)..(COORD_LIMIT - 400),
        ],
        any::<bool>(),
    )
        .prop_map(|(line_type, big, small, negative, start, hold)| {
            let m = magnitudes(line_type, big, small);
            let mut to = [0; 3];
            for axis in 0..3 {
                to[axis] = start[axis] + if negative[axis] { -m[axis] } else { m[axis] };
            }
            let tie = if hold {
                TiePolicy::Hold
            } else {
                TiePolicy::Advance
            };
            (Point::new(&start), Point::new(&to), tie)
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn every_line_ends_exactly_within_the_bound(
        (from, to, tie) in line_strategy(), gcd in any::<bool>()
    ) {
        let delta = from.delta_to(&to);
        let longest = delta[..3].iter().map(|d| d.abs()).max().unwrap();
        let ideal = IdealPath::Line { from, to };
        let mut stepper = RegionsWang::with_gcd(from, to, tie, gcd);
        let mut p = from;
        let mut steps = 0i64;
        // The recurrence (eq. 8) equals the closed form (eq. 6) before every
        // step, with or without the GCD reduction (section 4).
        while let Some((step, why)) = stepper.clone().next_step() {
            prop_assert_eq!(why.discriminants, stepper.closed_form(&p), "at {:?}", p);
            stepper.next_step();
            for axis in 0..3 {
                let d = step.delta(axis);
                prop_assert!(d == 0 || d == delta[axis].signum(), "axis {} moved away from the end", axis);
                if delta[axis].abs() == longest {
                    prop_assert_eq!(d, delta[axis].signum(), "an active axis must step every time");
                }
            }
            p.apply(step);
            steps += 1;
            prop_assert!(ideal.deviation(&p) <= MAX_THEORETICAL_ERROR + 1e-12, "{:?} is {} off", p, ideal.deviation(&p));
        }
        prop_assert_eq!(p, to);
        prop_assert_eq!(steps, longest);
    }

    #[test]
    fn reversing_a_line_mirrors_it_unless_a_tie_decides(
        (from, to, tie) in line_strategy()
    ) {
        // Wang's rule is symmetric except on ties: advance in one direction
        // is hold in the other. So with ties flipped, the reversed path visits
        // the same cells backwards.
        let flipped = if tie == TiePolicy::Advance { TiePolicy::Hold } else { TiePolicy::Advance };
        let collect = |a: Point, b: Point, t: TiePolicy| {
            let mut s = RegionsWang::new(a, b, t);
            let mut p = a;
            let mut out = vec![p];
            while let Some((step, _)) = s.next_step() {
                p.apply(step);
                out.push(p);
            }
            out
        };
        let forward = collect(from, to, tie);
        let mut backward = collect(to, from, flipped);
        backward.reverse();
        prop_assert_eq!(forward, backward);
    }

    #[test]
    fn fill_takes_next_step_s_steps_and_knows_their_displacement(
        (from, to, tie) in line_strategy(), gcd in any::<bool>(), chunk in 1usize..700
    ) {
        // What a trace records (fill, in chunks) against the steps one by
        // one; the displacement it derives from eq. (8) against the steps'.
        let mut one_by_one = RegionsWang::with_gcd(from, to, tie, gcd);
        let mut expected = Vec::new();
        while let Some((step, _)) = one_by_one.next_step() {
            expected.push(step);
        }
        let mut filler = RegionsWang::with_gcd(from, to, tie, gcd);
        let mut taken = Vec::new();
        loop {
            let mut out = vec![Step::NONE; chunk];
            let filled = filler.fill(&mut out);
            prop_assert_eq!(filled.displacement, displacement(&out[..filled.steps]));
            taken.extend_from_slice(&out[..filled.steps]);
            prop_assert_eq!(filler.remaining_steps(), Some((expected.len() - taken.len()) as u64));
            if filled.steps < chunk {
                break;
            }
        }
        prop_assert_eq!(taken, expected);
    }
}

#[test]
fn discriminants_stay_exact_at_the_coordinate_limit() {
    // The longest possible line: 2^31 steps from one corner of the +-2^30
    // cube to a point near the opposite one. Check the first and a late
    // stretch of steps against the closed form (eq. 6, evaluated in i128).
    let from = Point::new(&[-COORD_LIMIT, -COORD_LIMIT, COORD_LIMIT]);
    let to = Point::new(&[COORD_LIMIT, COORD_LIMIT - 3, -COORD_LIMIT + 7]);
    let mut stepper = RegionsWang::new(from, to, TiePolicy::Advance);
    let ideal = IdealPath::Line { from, to };
    let mut p = from;
    for _ in 0..20_000 {
        let before = stepper.closed_form(&p);
        let (step, why) = stepper.next_step().unwrap();
        assert_eq!(why.discriminants, before);
        p.apply(step);
        assert!(ideal.deviation(&p) <= MAX_THEORETICAL_ERROR);
    }
    assert_eq!(stepper.remaining_steps(), Some((1u64 << 31) - 20_000));
}
