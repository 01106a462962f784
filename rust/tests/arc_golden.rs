//! Circles worked by hand with Saleem's eq. (6)-(11), in every plane and
//! both directions, around centers in negative quadrants.
//!
//! How the expected cells were derived. In the local frame (u, v relative to
//! the center) each step moves the fast axis of the current octant and keeps
//! the slow axis or moves it, whichever candidate has the smaller
//! |u² + v² - r²|. For example r = 5 from (5, 0), octant 1 (v fast, +1; u
//! slow, -1):
//!   v = 1: (5,1) error 1,  (4,1) error 8  -> (5,1)
//!   v = 2: (5,2) error 4,  (4,2) error 5  -> (5,2)
//!   v = 3: (5,3) error 9,  (4,3) error 0  -> (4,3)
//!   v = 4: (4,4) error 7,  (3,4) error 0  -> (3,4)   now v >= u: octant 2
//!   u = 2: (2,4) error 5,  (2,5) error 4  -> (2,5)   (u fast, -1; v slow, +1)
//!   u = 1: (1,5) error 1,  (1,6) error 12 -> (1,5)
//!   u = 0: (0,5) error 0                  -> (0,5), the end.
//! The other lists below were worked the same way (each line of work is in
//! the comment above the list). A clockwise arc is, by G-code's definition,
//! the mirror image (v -> -v) of the counter-clockwise arc between the
//! mirrored end points, so its expected list is the mirrored list. Each
//! plane then puts (u, v) on its own axes: G17 (x, y), G18 (z, x), G19 (y, z).

use voxpath::Trace;

/// r = 5, (5,0) -> (0,5) counter-clockwise; worked in the module comment.
const QUARTER_R5: &[[i64; 2]] = &[
    [5, 0],
    [5, 1],
    [5, 2],
    [4, 3],
    [3, 4],
    [2, 5],
    [1, 5],
    [0, 5],
];

/// r = 3, (3,0) -> (-3,0) counter-clockwise.
///   oct 1 (v +1, u -1?): v=1 (3,1) 1 | (2,1) 4 -> (3,1); v=2 (3,2) 4 | (2,2) 1 -> (2,2)
///   oct 2 (u -1, v +1?): u=1 (1,2) 4 | (1,3) 1 -> (1,3); u=0 (0,3) 0 | (0,4) 7 -> (0,3)
///   oct 3 (u -1, v -1?): u=-1 (-1,3) 1 | (-1,2) 4 -> (-1,3); u=-2 (-2,3) 4 | (-2,2) 1 -> (-2,2)
///   oct 4 (v -1, u -1?): v=1 (-2,1) 4 | (-3,1) 1 -> (-3,1); v=0 (-3,0) 0 | (-4,0) 7 -> (-3,0)
const HALF_R3: &[[i64; 2]] = &[
    [3, 0],
    [3, 1],
    [2, 2],
    [1, 3],
    [0, 3],
    [-1, 3],
    [-2, 2],
    [-3, 1],
    [-3, 0],
];

/// r = 4, full circle from (4,0) counter-clockwise.
///   oct 1: v=1 (4,1) 1 | (3,1) 6 -> (4,1); v=2 (4,2) 4 | (3,2) 3 -> (3,2);
///          v=3 (3,3) 2 | (2,3) 3 -> (3,3)
///   oct 2: u=2 (2,3) 3 | (2,4) 4 -> (2,3); u=1 (1,3) 6 | (1,4) 1 -> (1,4);
///          u=0 (0,4) 0 | (0,5) 9 -> (0,4)
///   oct 3: u=-1 (-1,4) 1 | (-1,3) 6 -> (-1,4); u=-2 (-2,4) 4 | (-2,3) 3 -> (-2,3);
///          u=-3 (-3,3) 2 | (-3,2) 3 -> (-3,3)
///   oct 4: v=2 (-3,2) 3 | (-4,2) 4 -> (-3,2); v=1 (-3,1) 6 | (-4,1) 1 -> (-4,1);
///          v=0 (-4,0) 0 | (-5,0) 9 -> (-4,0)
///   octants 5-8 repeat 1-4 turned by 180°, ending on (4,0).
const FULL_R4: &[[i64; 2]] = &[
    [4, 0],
    [4, 1],
    [3, 2],
    [3, 3],
    [2, 3],
    [1, 4],
    [0, 4],
    [-1, 4],
    [-2, 3],
    [-3, 3],
    [-3, 2],
    [-4, 1],
    [-4, 0],
    [-4, -1],
    [-3, -2],
    [-3, -3],
    [-2, -3],
    [-1, -4],
    [0, -4],
    [1, -4],
    [2, -3],
    [3, -3],
    [3, -2],
    [4, -1],
    [4, 0],
];

const PLANES: [(&str, [usize; 3]); 3] = [("xy", [0, 1, 2]), ("zx", [2, 0, 1]), ("yz", [1, 2, 0])];

/// The grid point at (u, v) relative to `center` in the plane with axes `axes`.
fn grid(axes: [usize; 3], center: [i64; 3], uv: [i64; 2]) -> [i64; 3] {
    let mut p = center;
    p[axes[0]] += uv[0];
    p[axes[1]] += uv[1];
    p
}

fn points(t: &Trace) -> Vec<[i64; 3]> {
    t.points_flat(0, t.steps() + 1)
        .chunks(3)
        .map(|c| [c[0], c[1], c[2]])
        .collect()
}

#[test]
fn quarter_half_and_full_circles_in_every_plane_and_direction() {
    let center = [-7, -9, -12];
    for (plane, axes) in PLANES {
        for dir in ["ccw", "cw"] {
            for hand in [QUARTER_R5, HALF_R3, FULL_R4] {
                let mirror = |uv: &[i64; 2]| if dir == "cw" { [uv[0], -uv[1]] } else { *uv };
                let expected: Vec<[i64; 3]> = hand
                    .iter()
                    .map(|uv| grid(axes, center, mirror(uv)))
                    .collect();
                let (from, to) = (expected[0], *expected.last().unwrap());
                let t = voxpath::trace_json(&format!(
                    r#"{{"algorithm":"circle","from":{from:?},"to":{to:?},"center":{center:?},"dir":"{dir}","plane":"{plane}"}}"#
                ))
                .unwrap();
                assert_eq!(
                    points(&t),
                    expected,
                    "{plane} {dir} r² = {}",
                    hand[0][0].pow(2)
                );
                assert_eq!(t.metrics().steps, hand.len() as u64 - 1);
            }
        }
    }
}

#[test]
fn clockwise_half_in_g18_reports_octants_in_the_plane_s_own_numbering() {
    // G18 clockwise from z = 3 to z = -3 (x = v goes negative): the angle
    // atan2(x, z) falls from 0° to -180°, through octants 8, 7, 6, 5 of the
    // zx plane. The fast axis alternates x (octants 8, 5: near the z axis
    // the circle moves mostly along x) and z (octants 7, 6).
    let t = voxpath::trace_json(
        r#"{"algorithm":"circle","from":[-10,7,-17],"to":[-10,7,-23],"center":[-10,7,-20],"dir":"cw","plane":"zx"}"#,
    )
    .unwrap();
    let d = t.decisions(0, t.steps());
    let octants: Vec<f64> = d.columns[0].iter().map(|k| k + 1.0).collect();
    assert_eq!(octants, [8.0, 8.0, 7.0, 7.0, 6.0, 6.0, 5.0, 5.0]);
    assert_eq!(d.columns[1], [0.0, 0.0, 2.0, 2.0, 2.0, 2.0, 0.0, 0.0]);
    // Step 1: z stays at 3 with x = -1 (residual 1) rather than moving to
    // z = 2 (residual 4 + 1 - 9 = -4), so the candidate not taken is one
    // cell toward -z from the reached point (Saleem eq. 6-7).
    assert_eq!([d.columns[2][0], d.columns[3][0]], [1.0, -4.0]);
    assert_eq!(
        voxpath::grid::SIGNED_AXIS_LABELS[d.columns[6][0] as usize],
        "-z"
    );
    assert_eq!(
        t.explain(0),
        "Octant 8: x is the fast axis and steps -1; z stays (z² + x² - r² = 1) or steps -1 (-4); |1| < |-4|, so z stays (eq. 7): (x-1, y, z)."
    );
}

#[test]
fn clockwise_quarter_by_hand_is_the_counter_clockwise_one_reversed() {
    // Worked directly, clockwise from (0,5) to (5,0) (no mirror argument):
    // in the mirror frame this is counter-clockwise from (0,-5), octant 7
    // (u fast +1, v slow +1): u=1 (1,-5) 1 | (1,-4) 8 -> stay; u=2 (2,-5) 4 |
    // (2,-4) 5 -> stay; u=3 (3,-5) 9 | (3,-4) 0 -> move; u=4 (4,-4) 7 |
    // (4,-3) 0 -> move; octant 8 (v fast +1, u slow +1): v=-2 (4,-2) 5 |
    // (5,-2) 4 -> move; v=-1 (5,-1) 1 | (6,-1) 12 -> stay; v=0 (5,0) 0.
    let center = [-3, -4, 2];
    let t = voxpath::trace_json(
        r#"{"algorithm":"circle","from":[-3,1,2],"to":[2,-4,2],"center":[-3,-4,2],"dir":"cw"}"#,
    )
    .unwrap();
    let expected: Vec<[i64; 3]> = [
        [0, 5],
        [1, 5],
        [2, 5],
        [3, 4],
        [4, 3],
        [5, 2],
        [5, 1],
        [5, 0],
    ]
    .iter()
    .map(|uv| grid([0, 1, 2], center, *uv))
    .collect();
    assert_eq!(points(&t), expected);
    let mut reversed: Vec<[i64; 3]> = QUARTER_R5
        .iter()
        .map(|uv| grid([0, 1, 2], center, *uv))
        .collect();
    reversed.reverse();
    assert_eq!(points(&t), reversed);
}

#[test]
fn tiny_radii() {
    // r = 1: the four cells on the circle, joined by diagonal steps
    // (octant 1 from (1,0): (1,1) error 1 | (0,1) error 0 -> (0,1), and so on).
    let t = voxpath::trace_json(
        r#"{"algorithm":"circle","from":[1,0,0],"to":[1,0,0],"center":[0,0,0]}"#,
    )
    .unwrap();
    assert_eq!(
        points(&t),
        [[1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0], [1, 0, 0]]
    );
    // r² = 2 from (1,1): the eight neighbours of the center (octant 2:
    // (0,1) error 1 | (0,2) error 2 -> (0,1); octant 3: (-1,1) error 0 ...).
    let t = voxpath::trace_json(
        r#"{"algorithm":"circle","from":[1,1,0],"to":[1,1,0],"center":[0,0,0]}"#,
    )
    .unwrap();
    assert_eq!(
        points(&t),
        [
            [1, 1, 0],
            [0, 1, 0],
            [-1, 1, 0],
            [-1, 0, 0],
            [-1, -1, 0],
            [0, -1, 0],
            [1, -1, 0],
            [1, 0, 0],
            [1, 1, 0]
        ]
    );
    // r = 2, a quarter: octant 1: v=1 (2,1) 1 | (1,1) 2 -> (2,1); v=2 (2,2)
    // 4 | (1,2) 1 -> (1,2); octant 2: u=0 (0,2) 0 -> (0,2).
    let t = voxpath::trace_json(
        r#"{"algorithm":"circle","from":[2,0,0],"to":[0,2,0],"center":[0,0,0]}"#,
    )
    .unwrap();
    assert_eq!(points(&t), [[2, 0, 0], [2, 1, 0], [1, 2, 0], [0, 2, 0]]);
}

#[test]
fn extra_turns_go_round_again() {
    // Quarter r = 5 with one extra turn: 7 + 28 steps (the full r = 5
    // circle is four quarters of 7), same end.
    let t = voxpath::trace_json(
        r#"{"algorithm":"circle","from":[5,0,0],"to":[0,5,0],"center":[0,0,0],"turns":1}"#,
    )
    .unwrap();
    assert_eq!(t.steps(), 35);
    let p = points(&t);
    // The ray through the end is passed once after 7 steps and reached
    // again after the extra turn.
    assert_eq!((p[7], p[21], p[35]), ([0, 5, 0], [0, -5, 0], [0, 5, 0]));
}
