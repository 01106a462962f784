//! The distance of a grid point from a straight segment, and its per-axis
//! error (Wang eq. 11), exact in integers until the last rounding.

use crate::grid::{I64_PRODUCT_BOUND, MAX_AXES, Point, Step, within_i64_product_bound};

/// A straight segment ready to measure points.
pub struct LineMeter {
    from: Point,
    /// `to - from` per axis, grid units.
    direction: [i64; MAX_AXES],
    /// |to - from|², summed in f64 in axis order.
    length_sq: f64,
    /// Every |direction| is below [`I64_PRODUCT_BOUND`].
    direction_small: bool,
}

impl LineMeter {
    pub fn new(from: &Point, to: &Point) -> LineMeter {
        let direction = from.delta_to(to);
        let dims = from.dims();
        LineMeter {
            from: *from,
            direction,
            length_sq: norm_sq_f64(&direction[..dims]),
            direction_small: within_i64_product_bound(&direction[..dims]),
        }
    }

    /// Perpendicular distance from `p` to the line.
    ///
    /// With `r = p - from` and direction `d`, Lagrange's identity gives
    /// |r|^2 |d|^2 - (r.d)^2 = sum over axis pairs (r_i d_j - r_j d_i)^2, a
    /// sum of squares with no cancellation. Each term is formed exactly (in
    /// i64 when every factor is below [`I64_PRODUCT_BOUND`], else in i128)
    /// and only then rounded to f64, so both paths give the same bits.
    pub fn deviation(&self, p: &Point) -> f64 {
        let dims = p.dims();
        let r = self.from.delta_to(p);
        if self.length_sq == 0.0 {
            return norm_sq_f64(&r[..dims]).sqrt();
        }
        let cross_sq = if self.direction_small && within_i64_product_bound(&r[..dims]) {
            cross_norm_sq_i64(&r, &self.direction, dims)
        } else {
            cross_norm_sq_i128(&r, &self.direction, dims)
        };
        (cross_sq / self.length_sq).sqrt()
    }

    /// Per axis, (r * steps - d * step) / steps: exact until the final
    /// division. In i64 when r, d, step and steps are all below
    /// [`I64_PRODUCT_BOUND`] (steps never exceed 10^9 < 2^30), else in i128.
    pub fn axis_error(&self, p: &Point, step: u64, steps: u64) -> [f64; MAX_AXES] {
        let dims = p.dims();
        let r = self.from.delta_to(p);
        let mut phi = [0.0; MAX_AXES];
        if steps == 0 {
            for axis in 0..dims {
                phi[axis] = r[axis] as f64;
            }
        } else if self.direction_small
            && step.max(steps) < I64_PRODUCT_BOUND
            && within_i64_product_bound(&r[..dims])
        {
            let (i, n) = (step as i64, steps as i64);
            for axis in 0..dims {
                phi[axis] = (r[axis] * n - self.direction[axis] * i) as f64 / steps as f64;
            }
        } else {
            phi = axis_error_i128(&r, &self.direction, dims, step, steps);
        }
        phi
    }
}

impl LineMeter {
    /// Measures `start`, the point after `step` of the segment's `steps`,
    /// and the point after each of `moves` after it, calling
    /// `f(deviation, numerators)` for each: the deviation [`Self::deviation`]
    /// gives, and per axis the exact numerator of [`Self::axis_error`] (its
    /// error is numerator / steps). The same values to the bit, at loop
    /// speed: each cross product r_i d_j - r_j d_i changes by a constant per
    /// unit move of an axis (+-d_j or -+d_i), and each numerator r steps -
    /// d step by (move * steps - d), so a point costs a few additions, a
    /// division and a square root instead of rebuilding both from the point.
    ///
    /// Exact in i64 where the direction is within [`I64_PRODUCT_BOUND`]:
    /// every point is within +-2^30, so |r| <= 2^31, |r_i d_j| < 2^62 and a
    /// cross product is below 2^63; steps < 2^30 (maxSteps is at most 10^9),
    /// so a numerator is below 2^62. Returns false, calling nothing, where
    /// that does not hold or the line has no length (the callers measure
    /// point by point then).
    pub fn walk(
        &self,
        start: &Point,
        step: u64,
        steps: u64,
        moves: &[Step],
        f: impl FnMut(f64, &[i64; MAX_AXES]),
    ) -> bool {
        if !self.direction_small || self.length_sq == 0.0 || steps == 0 || steps >= 1 << 30 {
            return false;
        }
        match start.dims() {
            2 => self.walk_axes::<2>(start, step, steps, moves, f),
            3 => self.walk_axes::<3>(start, step, steps, moves, f),
            4 => self.walk_axes::<4>(start, step, steps, moves, f),
            5 => self.walk_axes::<5>(start, step, steps, moves, f),
            6 => self.walk_axes::<MAX_AXES>(start, step, steps, moves, f),
            _ => return false,
        }
        true
    }

    /// [`Self::walk`] for `DIMS` axes. The cross products are kept in the
    /// order [`cross_norm_sq_i64`] sums them (i < j, i then j), so their
    /// squares add up in f64 to the same bits.
    #[inline(always)]
    fn walk_axes<const DIMS: usize>(
        &self,
        start: &Point,
        step: u64,
        steps: u64,
        moves: &[Step],
        mut f: impl FnMut(f64, &[i64; MAX_AXES]),
    ) {
        const PAIRS: usize = MAX_AXES * (MAX_AXES - 1) / 2;
        let d = &self.direction;
        let r = self.from.delta_to(start);
        let n = steps as i64;
        // numerator[a] = r_a n - d_a i; a step adds move_a n - d_a.
        let mut numerator = [0i64; MAX_AXES];
        for axis in 0..DIMS {
            numerator[axis] = r[axis] * n - d[axis] * step as i64;
        }
        // cross[p] = r_i d_j - r_j d_i for the p-th pair (i, j); a unit move
        // of axis a adds move_a * per_axis[a][p].
        let mut cross = [0i64; PAIRS];
        let mut per_axis = [[0i64; PAIRS]; MAX_AXES];
        let mut pair = 0;
        for i in 0..DIMS {
            for j in i + 1..DIMS {
                cross[pair] = r[i] * d[j] - r[j] * d[i];
                per_axis[i][pair] = d[j];
                per_axis[j][pair] = -d[i];
                pair += 1;
            }
        }
        let pairs = pair;
        let measure = |cross: &[i64; PAIRS]| {
            let mut sum = 0.0;
            for c in &cross[..pairs] {
                let c = *c as f64;
                sum += c * c;
            }
            (sum / self.length_sq).sqrt()
        };
        f(measure(&cross), &numerator);
        for s in moves {
            for axis in 0..DIMS {
                let step_move = s.delta(axis);
                numerator[axis] += step_move * n - d[axis];
                for p in 0..pairs {
                    cross[p] += step_move * per_axis[axis][p];
                }
            }
            f(measure(&cross), &numerator);
        }
    }
}

/// Sum of squares in f64, in axis order.
fn norm_sq_f64(v: &[i64]) -> f64 {
    v.iter().map(|&x| (x as f64) * (x as f64)).sum()
}

/// Sum over axis pairs of (r_i d_j - r_j d_i)^2, each term exact in i64.
/// Every |r| and |d| must be below [`I64_PRODUCT_BOUND`].
fn cross_norm_sq_i64(r: &[i64; MAX_AXES], d: &[i64; MAX_AXES], dims: usize) -> f64 {
    let mut sum = 0.0;
    for i in 0..dims {
        for j in i + 1..dims {
            let c = (r[i] * d[j] - r[j] * d[i]) as f64;
            sum += c * c;
        }
    }
    sum
}

/// The same sum with each term exact in i128, for any i64 inputs.
fn cross_norm_sq_i128(r: &[i64; MAX_AXES], d: &[i64; MAX_AXES], dims: usize) -> f64 {
    let mut sum = 0.0;
    for i in 0..dims {
        for j in i + 1..dims {
            let c = (r[i] as i128 * d[j] as i128 - r[j] as i128 * d[i] as i128) as f64;
            sum += c * c;
        }
    }
    sum
}

/// (r * steps - d * step) / steps per axis, the numerator exact in i128.
fn axis_error_i128(
    r: &[i64; MAX_AXES],
    d: &[i64; MAX_AXES],
    dims: usize,
    step: u64,
    steps: u64,
) -> [f64; MAX_AXES] {
    let mut phi = [0.0; MAX_AXES];
    for axis in 0..dims {
        let num = r[axis] as i128 * steps as i128 - d[axis] as i128 * step as i128;
        phi[axis] = num as f64 / steps as f64;
    }
    phi
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::COORD_LIMIT;

    fn line(from: &[i64], to: &[i64]) -> LineMeter {
        LineMeter::new(&Point::new(from), &Point::new(to))
    }

    #[test]
    fn deviation_matches_wang_table_1_error_column() {
        // Wang 2020, Table 1 (Liu's points for (0,0,0)->(10,7,6)), last column.
        // Table 1 prints 0.225064 for (7,5,4); the distance is 0.220564 (the
        // digits transposed), as Table 2 prints beside step 7 and as the
        // point (3,2,2), the mirror image of (7,5,4) about the line's middle, has.
        let l = line(&[0, 0, 0], &[10, 7, 6]);
        for (p, err) in [
            ([1, 1, 1], 0.374887),
            ([2, 1, 1], 0.336918),
            ([3, 2, 2], 0.220564),
            ([4, 3, 2], 0.441129),
            ([5, 4, 3], 0.428700),
            ([6, 4, 4], 0.441129),
            ([7, 5, 4], 0.220564),
            ([8, 6, 5], 0.336918),
            ([9, 6, 5], 0.374887),
            ([10, 7, 6], 0.0),
        ] {
            assert!((l.deviation(&Point::new(&p)) - err).abs() < 1e-6, "{p:?}");
        }
    }

    #[test]
    fn deviation_is_exact_far_from_the_origin() {
        // A point half a unit off a line spanning the whole +-2^30 range.
        let big = 1i64 << 30;
        let l = line(&[-big, -big], &[big, -big]);
        let p = Point::new(&[12345, -big + 1]);
        assert_eq!(l.deviation(&p), 1.0);
        let l = line(&[-big, -big, -big], &[big, big, big]);
        let p = Point::new(&[big - 1, big - 1, big]);
        // r = (2^31-1, 2^31-1, 2^31), d = 2^31 (1,1,1): distance sqrt(2/3).
        assert!((l.deviation(&p) - (2.0f64 / 3.0).sqrt()).abs() < 1e-12);
    }

    /// Magnitudes the fast paths accept at their edge, and 0 and 1.
    const EDGE: [i64; 5] = [0, 1, (1 << 31) - 1, 1 << 30, (1 << 30) - 1];

    /// Every sign combination of EDGE values for `dims` axes, one per axis
    /// in turn (r) against the same for d: the products the bound allows
    /// at their largest.
    fn edge_vectors(dims: usize) -> Vec<[i64; MAX_AXES]> {
        let mut out = Vec::new();
        for &m in &EDGE {
            for sign_bits in 0..1u32 << dims {
                let mut v = [0; MAX_AXES];
                for axis in 0..dims {
                    let sign = if sign_bits >> axis & 1 == 1 { -1 } else { 1 };
                    // Alternate magnitude and magnitude - 1 so the cross
                    // products do not all cancel.
                    v[axis] = sign * (m - (axis as i64 & 1).min(m));
                }
                out.push(v);
            }
        }
        out
    }

    #[test]
    fn fast_cross_products_equal_i128_at_the_bound() {
        for dims in 2..=MAX_AXES {
            let vectors = edge_vectors(dims);
            for r in &vectors {
                for d in &vectors {
                    assert_eq!(
                        cross_norm_sq_i64(r, d, dims).to_bits(),
                        cross_norm_sq_i128(r, d, dims).to_bits(),
                        "{r:?} x {d:?}"
                    );
                }
            }
        }
    }

    #[test]
    fn fast_axis_error_equals_i128_at_the_bound() {
        let big = (1u64 << 31) - 1;
        let meter = LineMeter::new(
            &Point::new(&[-(1 << 30) + 1, 0, 1 << 30]),
            &Point::new(&[1 << 30, -(1 << 30), -(1 << 30) + 1]),
        );
        assert!(meter.direction_small);
        for r in edge_vectors(3) {
            let p = Point::new(&[
                meter.from.get(0) + r[0],
                meter.from.get(1) + r[1],
                meter.from.get(2) + r[2],
            ]);
            for (step, steps) in [(0, 1), (1, 1), (big, big), (big - 1, big), (12345, 1 << 30)] {
                let fast = meter.axis_error(&p, step, steps);
                let exact = axis_error_i128(&r, &meter.direction, 3, step, steps);
                assert_eq!(
                    fast.map(f64::to_bits),
                    exact.map(f64::to_bits),
                    "{r:?} {step}/{steps}"
                );
            }
        }
    }

    /// The exact deviation, all in i128 (the formula before the fast path).
    fn exact_deviation(from: &Point, to: &Point, p: &Point) -> f64 {
        let dims = p.dims();
        let (d, r) = (from.delta_to(to), from.delta_to(p));
        (cross_norm_sq_i128(&r, &d, dims) / norm_sq_f64(&d[..dims])).sqrt()
    }

    #[test]
    fn a_move_across_the_whole_range_falls_back_to_i128() {
        // |Δx| = 2^31 is past the i64 bound for products; the result is the
        // exact one all the same.
        let (from, to) = (
            Point::new(&[-(1 << 30), 5, 0]),
            Point::new(&[1 << 30, -7, 3]),
        );
        let meter = LineMeter::new(&from, &to);
        assert!(!meter.direction_small);
        for p in [
            [1 << 30, 1 << 30, 1 << 30],
            [-(1 << 30), -(1 << 30), 0],
            [0, 0, 0],
        ] {
            let p = Point::new(&p);
            assert_eq!(meter.deviation(&p), exact_deviation(&from, &to, &p));
        }
    }

    proptest::proptest! {
        #[test]
        fn fast_deviation_equals_the_exact_one(
            dims in 2usize..=MAX_AXES,
            coords in proptest::array::uniform18(-COORD_LIMIT..=COORD_LIMIT),
            near in proptest::array::uniform6(-3i64..=3),
        ) {
            // from, to and a point anywhere in the input box; and a point
            // next to the line (the case the metrics pass sees), where the
            // cross products are small and rounding matters most.
            let (from, to, far) = (
                Point::new(&coords[..dims]),
                Point::new(&coords[6..6 + dims]),
                Point::new(&coords[12..12 + dims]),
            );
            let meter = LineMeter::new(&from, &to);
            let mut close = from;
            for axis in 0..dims {
                close.coords_mut()[axis] = (from.get(axis) + to.get(axis)) / 2 + near[axis];
            }
            for p in [far, close, from, to] {
                let exact = exact_deviation(&from, &to, &p);
                if from != to {
                    proptest::prop_assert_eq!(meter.deviation(&p).to_bits(), exact.to_bits());
                }
            }
        }

        #[test]
        fn fast_axis_error_equals_the_exact_one(
            coords in proptest::array::uniform9(-COORD_LIMIT..=COORD_LIMIT),
            steps in 1u64..(1 << 31),
            fraction in 0.0f64..=1.0,
        ) {
            let (from, to, p) = (
                Point::new(&coords[..3]),
                Point::new(&coords[3..6]),
                Point::new(&coords[6..]),
            );
            let step = (steps as f64 * fraction) as u64;
            let meter = LineMeter::new(&from, &to);
            let exact = axis_error_i128(&from.delta_to(&p), &from.delta_to(&to), 3, step, steps);
            proptest::prop_assert_eq!(
                meter.axis_error(&p, step, steps).map(f64::to_bits),
                exact.map(f64::to_bits)
            );
        }
    }

    #[test]
    fn axis_error_is_zero_on_the_active_axis() {
        let l = line(&[0, 0, 0], &[10, 7, 6]);
        let phi = l.axis_error(&Point::new(&[1, 1, 1]), 1, 10);
        assert_eq!(phi[0], 0.0);
        assert!((phi[1] - 0.3).abs() < 1e-12 && (phi[2] - 0.4).abs() < 1e-12);
    }
}
