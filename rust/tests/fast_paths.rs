//! The fast paths a trace reads through, held to the replay they replace,
//! to the bit: points decoded per number of axes (`points::decode`, as
//! i64, as i32 and a chunk at a time) against applying every step to a
//! point; deviations, per-axis errors and metrics measured incrementally
//! along line segments (`LineMeter::walk`), and deviations and per-axis
//! errors along arcs (`ArcMeter::walk`), against measuring every point on
//! its own; the bounds (`points::bounds`) against the replayed points'
//! extremes. On random lines of every line algorithm (near +-2^30 too),
//! paths of several line segments, arcs, chorded arcs and helices. The
//! check itself (`common::check_trace`) also holds random G-code programs
//! to their replay (tests/gcode_properties.rs).

mod common;

use proptest::prelude::*;
use voxpath::grid::{COORD_LIMIT, MAX_AXES, Point, Step};
use voxpath::ideal::IdealPath;
use voxpath::ideal::line::LineMeter;
use voxpath::line::bresenham3d::Bresenham3d;
use voxpath::line::dda::Dda;
use voxpath::line::nd::Nd;
use voxpath::line::regions_wang::RegionsWang;
use voxpath::request::TiePolicy;
use voxpath::trace::TraceBuilder;

/// A coordinate anywhere in the grid, or at one of its edges (so that a
/// short move from it reaches +-2^30).
fn start_coordinate() -> impl Strategy<Value = i64> {
    let room = COORD_LIMIT - 400;
    prop_oneof![-room..=room, Just(-room), Just(room)]
}

/// A move of up to 400 units per axis from an edge-or-anywhere start.
fn line(dims: std::ops::RangeInclusive<usize>) -> impl Strategy<Value = (Point, Point)> {
    (
        dims,
        prop::array::uniform6(start_coordinate()),
        prop::array::uniform6(-400i64..=400),
    )
        .prop_map(|(dims, start, delta)| {
            let to: Vec<i64> = (0..dims).map(|a| start[a] + delta[a]).collect();
            (Point::new(&start[..dims]), Point::new(&to))
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(120))]

    #[test]
    fn every_line_algorithm_reads_as_its_replay(
        (from, to) in line(2..=6),
        range in (0u64..1300, 0u64..1300),
        chunk in 1usize..200,
    ) {
        for a in common::line_algorithms() {
            if !(a.min_dims..=a.max_dims).contains(&from.dims()) {
                continue;
            }
            let t = common::trace(&format!(
                r#"{{"algorithm":"{}","from":{:?},"to":{:?}}}"#, a.id, from.coords(), to.coords()
            ));
            common::check_trace(&t, range, chunk)?;
        }
    }

    #[test]
    fn paths_of_several_lines_read_as_their_replay(
        (start, _) in line(3..=3),
        legs in prop::collection::vec((prop::array::uniform3(-300i64..=300), 0usize..4), 1..6),
        range in (0u64..3000, 0u64..3000),
        chunk in 1usize..500,
    ) {
        // As a G-code program runs its moves: one segment per leg, each
        // measured against its own line, some legs of no length.
        let mut builder = TraceBuilder::new(start, 1 << 20);
        for (delta, rule) in legs {
            let from = builder.position();
            let to = Point::new(&[0, 1, 2].map(|a| from.get(a) + delta[a]));
            let ideal = IdealPath::Line { from, to };
            match rule {
                0 => builder.run(RegionsWang::new(from, to, TiePolicy::Advance), ideal),
                1 => builder.run(Bresenham3d::new(from, to, TiePolicy::Hold, false), ideal),
                2 => builder.run(Nd::new(from, to, TiePolicy::Hold, false), ideal),
                _ => builder.run(Dda::new(from, to), ideal),
            }
            .unwrap();
        }
        common::check_trace(&builder.finish("legs"), range, chunk)?;
    }

    #[test]
    fn arcs_and_helices_read_as_their_replay(
        request in common::arc_request(),
        range in (0u64..20_000, 0u64..20_000),
        chunk in 1usize..3000,
    ) {
        let t = common::trace(&request);
        common::check_trace(&t, range, chunk)?;
    }

    #[test]
    fn the_line_walk_is_each_point_measured_at_the_edge_of_the_grid(
        dims in 2usize..=6,
        ends in (prop::array::uniform6(-COORD_LIMIT..=COORD_LIMIT), prop::array::uniform6(-COORD_LIMIT..=COORD_LIMIT)),
        start in prop::array::uniform6(-COORD_LIMIT + 600..=COORD_LIMIT - 600),
        moves in prop::collection::vec(prop::array::uniform6(-1i64..=1), 1..600),
        steps in 1u64..(1 << 30) - 1,
        fraction in 0.0f64..1.0,
    ) {
        // A line of 2 to 6 axes between any two points of the grid (so |Δ|
        // up to 2^31: cross products near 2^63), points anywhere within it,
        // any step count up to the largest: the walk gives what each point
        // gives.
        let (from, to) = (Point::new(&ends.0[..dims]), Point::new(&ends.1[..dims]));
        let meter = LineMeter::new(&from, &to);
        let ideal = IdealPath::Line { from, to };
        let first = ((steps - 1) as f64 * fraction) as u64;
        let moves: Vec<Step> = moves
            .iter()
            .map(|m| (0..dims).fold(Step::NONE, |s, a| s.with(a, m[a])))
            .collect();
        let mut expected = Vec::new();
        let mut p = Point::new(&start[..dims]);
        for k in 0..=moves.len() {
            if k > 0 {
                p.apply(moves[k - 1]);
            }
            let i = (first + k as u64).min(steps);
            expected.push((ideal.deviation(&p), ideal.axis_error(&p, i, steps)));
        }
        let mut walked = Vec::new();
        let small = (0..dims).all(|a| (ends.1[a] - ends.0[a]).abs() < 1 << 31);
        // Cases the walk does not take are drawn again (prop_assume), so
        // that a strategy that stopped reaching the walk would fail on its
        // rejects rather than pass untested.
        prop_assume!(from != to && small && first + moves.len() as u64 <= steps);
        let applied = meter.walk(&Point::new(&start[..dims]), first, steps, &moves, |d, numerator| {
            let mut e = [0.0; MAX_AXES];
            for a in 0..dims {
                e[a] = numerator[a] as f64 / steps as f64;
            }
            walked.push((d, e));
        });
        prop_assert!(applied);
        prop_assert_eq!(walked.len(), expected.len());
        for (k, ((d, e), (want_d, want_e))) in walked.iter().zip(&expected).enumerate() {
            prop_assert_eq!(d.to_bits(), want_d.to_bits(), "deviation of point {}", k);
            prop_assert_eq!(e.map(f64::to_bits), want_e.map(f64::to_bits), "axis error of point {}", k);
        }
    }
}

#[test]
fn the_line_walk_leaves_moves_past_the_product_bound_to_the_point_by_point_path() {
    // |Δx| = 2^31: products past i64's exact range, so walk declines.
    let (from, to) = (
        Point::new(&[-COORD_LIMIT, 0, 0]),
        Point::new(&[COORD_LIMIT, 3, 5]),
    );
    let meter = LineMeter::new(&from, &to);
    assert!(
        !meter.walk(&from, 0, 1 << 29, &[Step::along(0, 1)], |_, _| {
            panic!("nothing is measured")
        })
    );
    // A line of no length, and a segment of no steps, too.
    assert!(!LineMeter::new(&from, &from).walk(&from, 0, 1, &[], |_, _| panic!()));
    let short = LineMeter::new(&from, &Point::new(&[-COORD_LIMIT + 1, 0, 0]));
    assert!(!short.walk(&from, 0, 0, &[], |_, _| panic!()));
}

/// A line long enough that its points fill whole huge pages, which the
/// native reads advise for huge pages before writing (`huge_pages`), and
/// that its i32 points are written past the cache (`decode_to_new`, past
/// 8 MiB, on x86-64): the points are still the replay's, whatever backs
/// their memory and however they reach it.
#[test]
fn points_of_a_long_line_are_the_replay() {
    // Lines from the grid's corner whose points pass 8 MiB of i32, so that
    // they are written past the cache (`points::decode_to_new`), in every
    // axis count the streaming decode has a loop for (2 to 4) and past it.
    let major = |dims: usize| (9 << 20) / (4 * dims as i64) + 1;
    for dims in 2..=6 {
        let from = Point::new(&[-(1 << 30), 1 << 30, 5, -7, 11, 1 << 30][..dims]);
        let delta = [
            major(dims),
            -(major(dims) * 7 / 10) - 1,
            -(major(dims) * 6 / 10) - 3,
            1,
            -major(dims) / 3,
            -5,
        ];
        let to = Point::new(
            &(0..dims)
                .map(|a| from.get(a) + delta[a])
                .collect::<Vec<_>>(),
        );
        let mut b = TraceBuilder::new(from, u64::MAX);
        let ideal = IdealPath::Line { from, to };
        if dims == 3 {
            b.run(Bresenham3d::new(from, to, TiePolicy::Hold, false), ideal)
        } else {
            b.run(Nd::new(from, to, TiePolicy::Hold, false), ideal)
        }
        .unwrap();
        let t = b.finish("long line");
        let n = t.steps() + 1;
        assert!(
            n as usize * dims * 4 > 8 << 20,
            "more than four huge pages of i32, and past the cache"
        );
        let all = common::replayed_points(&t, 0, n);
        let narrow: Vec<i64> = t.points_i32(0, n).into_iter().map(i64::from).collect();
        assert!(narrow == all, "i32 points of {dims} axes are the replay");
        assert!(
            t.points_flat(0, n) == all,
            "i64 points of {dims} axes are the replay"
        );
    }
}
