//! Properties of Wang's method of discriminate regions on random lines in
#![allow(clippy::needless_range_loop)]
//! every octant and of all seven types (Wang section 2.2).

mod common;

use proptest::prelude::*;
use voxpath::grid::{COORD_LIMIT, Point, SIGNED_AXIS_LABELS};
use voxpath::ideal::IdealPath;
use voxpath::line::regions_wang::{Region, RegionsWang};
use voxpath::request::TiePolicy;
use voxpath::trace::Stepper;

/// Wang's bound (section 3.2): the chosen corner is at most sqrt(2)/2 from
/// the ideal line, as the line crosses the exit plane within 1/2 of it along
/// each passive axis (though not always within the unit face: see
/// `the_face_crossing_is_the_ideal_line_s_and_lies_in_the_region`).
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
        // What a trace records (fill, in chunks) against the steps one by one.
        common::check_fill(|| RegionsWang::with_gcd(from, to, tie, gcd), chunk).map_err(TestCaseError::fail)?;
    }
}

/// The signs of the face coordinates (u along the first passive axis, v
/// along the second; 0 on the line between two regions) each region and
/// segment of Wang's Figure 4b stands for, read off the figure and the rules
/// of section 2.5 rather than from the code under test. A line with one
/// passive axis has no v: it counts as below the center, as a missing N
/// counts as negative. None for a line with no passive axis (no region).
fn region_signs(region: Option<Region>) -> Option<(i64, i64)> {
    Some(match region? {
        Region::A => (1, -1),
        Region::B => (-1, -1),
        Region::C => (-1, 1),
        Region::D => (1, 1),
        Region::E => (0, -1),
        Region::F => (-1, 0),
        Region::G => (0, 1),
        Region::H => (1, 0),
        Region::O => (0, 0),
    })
}

fn sign(v: f64) -> i64 {
    if v > 0.0 {
        1
    } else if v < 0.0 {
        -1
    } else {
        0
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn the_face_crossing_is_the_ideal_line_s_and_lies_in_the_region(
        (from, to, tie) in line_strategy(), gcd in any::<bool>()
    ) {
        let delta = from.delta_to(&to);
        let longest = delta[..3].iter().map(|d| d.abs()).max().unwrap();
        let reference = (0..3).find(|&a| delta[a].abs() == longest).unwrap();
        let travel = |axis: usize| if delta[axis] < 0 { -1 } else { 1 };
        let mut stepper = RegionsWang::with_gcd(from, to, tie, gcd);
        let mut p = from;
        while let Some((step, why)) = stepper.next_step() {
            let mut next = p;
            next.apply(step);
            let crossing = why.face_crossing();
            let axes = why.face_axes();
            let passive: Vec<usize> = (0..3).filter(|&a| delta[a].abs() < longest).collect();
            match region_signs(why.region) {
                None => {
                    prop_assert!(passive.is_empty());
                    prop_assert_eq!(crossing, [None, None]);
                    prop_assert_eq!(axes, [None, None]);
                }
                Some((u_sign, v_sign)) => {
                    for (i, &axis) in passive.iter().enumerate() {
                        // The axis and the way it grows: the direction of travel.
                        let label = axes[i].map(|a| SIGNED_AXIS_LABELS[a as usize]).unwrap_or("none");
                        let expected = format!("{}{}", if travel(axis) < 0 { '-' } else { '+' }, ["x", "y", "z"][axis]);
                        prop_assert_eq!(label, expected.as_str());
                        // From the ideal line itself (Wang eq. 2), in units of
                        // travel: at the exit plane the line has gone
                        // |Δa| t / |Δref| along the axis, where t is how far
                        // the reference axis has gone at the next point; the
                        // face's center is half a cell past the current point.
                        // Times 2 |Δref|, an exact integer.
                        let t = travel(reference) * (next.coords()[reference] - from.coords()[reference]);
                        let at = travel(axis) * (p.coords()[axis] - from.coords()[axis]);
                        let scaled = 2 * delta[axis].abs() * t - 2 * longest * at - longest;
                        let u = crossing[i].unwrap();
                        prop_assert_eq!(u, scaled as f64 / (2 * longest) as f64, "face {} at {:?}", i, p);
                        prop_assert_eq!(sign(u), if i == 0 { u_sign } else { v_sign }, "{:?} at {:?}", why.region, p);
                        // Within [|Δa|/|Δref| - 1, |Δa|/|Δref|]: so inside (-1, 1).
                        prop_assert!(scaled >= 2 * delta[axis].abs() - 2 * longest && scaled <= 2 * delta[axis].abs());
                        prop_assert!(u > -1.0 && u < 1.0);
                        // The corner agrees: the axis stepped past the center,
                        // or on it as the tie policy says.
                        let stepped = step.delta(axis) != 0;
                        let expected_step = u > 0.0 || (u == 0.0 && tie == TiePolicy::Advance);
                        prop_assert_eq!(stepped, expected_step);
                        // So the chosen corner (+-1/2 on the face) is within 1/2 of the crossing.
                        let corner = if stepped { 0.5 } else { -0.5 };
                        prop_assert!((u - corner).abs() <= 0.5, "corner {} and crossing {}", corner, u);
                    }
                    if passive.len() < 2 {
                        prop_assert_eq!(crossing[1], None);
                        prop_assert_eq!(axes[1], None);
                        prop_assert_eq!(v_sign, -1, "one passive axis: the region is a, b or e");
                    }
                }
            }
            p = next;
        }
    }
}

#[test]
fn face_crossings_of_wang_s_example_from_the_paper_s_equations() {
    // (0,0,0)->(10,7,6), x active. Eq. (2) puts the line at y = 0.7 (x_i + 1)
    // and z = 0.6 (x_i + 1) on the exit plane; the face's center is at
    // (y_i + 1/2, z_i + 1/2), with (x_i, y_i, z_i) the points of SEED-NOTES
    // from (0,0,0). Step 3, from (2,1,1): y = 2.1, so u = 2.1 - 1.5 = 0.6,
    // off the face (the line leaves the unit cell through its top first),
    // yet in region d as M = 12 says. Step 10 ends on corner D itself.
    // The points each step starts from: the start, then Wang's points.
    let points = std::iter::once([0, 0, 0]).chain(common::WANG_10_7_6[..9].iter().copied());
    let expected: Vec<[f64; 2]> = points
        .map(|[x, y, z]| {
            let (x, y, z) = (x as f64, y as f64, z as f64);
            [0.7 * (x + 1.0) - (y + 0.5), 0.6 * (x + 1.0) - (z + 0.5)]
        })
        .collect();
    let mut stepper = RegionsWang::new(
        Point::new(&[0, 0, 0]),
        Point::new(&[10, 7, 6]),
        TiePolicy::Advance,
    );
    let mut got = Vec::new();
    while let Some((_, why)) = stepper.next_step() {
        let [u, v] = why.face_crossing();
        got.push([u.unwrap(), v.unwrap()]);
        assert_eq!(
            why.face_axes()
                .map(|a| a.map(|a| SIGNED_AXIS_LABELS[a as usize])),
            [Some("+y"), Some("+z")]
        );
    }
    assert_eq!(got.len(), expected.len());
    for (k, (g, e)) in got.iter().zip(&expected).enumerate() {
        assert!(
            (g[0] - e[0]).abs() < 1e-12 && (g[1] - e[1]).abs() < 1e-12,
            "step {}: {g:?} vs {e:?}",
            k + 1
        );
    }
    // And exactly M/20 and N/20 (SEED-NOTES' M and N): 0.6 and 0.5 are exact.
    assert_eq!(got[2], [0.6, 0.3]);
    assert_eq!(got[9], [0.5, 0.5]);
    assert_eq!(got[4], [0.0, 0.5]);
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
