//! The ideal curves arcs and helices approximate: distance of a grid point
//! from them, per-axis error, and a polyline for drawing.
//!
//! Progress along a curve (for the per-axis error of Wang's eq. 11) is the
//! angle of the point itself around the center: the ideal position "at the
//! same progress" is the point of the curve at the same angle. For an arc
//! that is the radial projection, so the in-plane part of the error is the
//! radial error split per axis; for a helix the normal-axis part is the
//! height error at that angle (on the turn nearest the point's height).
//! Step-count progress would instead measure how unevenly a constant step
//! rate moves around a circle (the fast axis alternates), which is a feed-rate
//! question, not a question of where the steps land.

use super::info::IdealPathInfo;
use crate::arc::angle::sin_cos_turns;
use crate::arc::planes::Plane;
use crate::grid::{MAX_AXES, Point, Step, within_i64_product_bound};
use std::f64::consts::{PI, TAU};

/// Sagitta, in grid units, of the polyline's chords on small circles.
const DRAW_SAGITTA: f64 = 0.25;
/// Fewest vertices per full turn, so small circles look round.
const MIN_VERTICES_PER_TURN: f64 = 64.0;
/// Most polyline segments for a whole arc or helix, whatever its size.
pub const MAX_POLYLINE_SEGMENTS: f64 = 16384.0;

/// A drawn arc's vertices computed from their own angle, one in this many
/// (the others turned from the one before: [`ArcPath::vertices_with`]).
const ANCHOR_EVERY: usize = 64;

/// A circular arc around an axis parallel to the plane's normal.
#[derive(Clone, Debug, PartialEq)]
pub struct ArcPath {
    pub plane: Plane,
    /// The center; its normal coordinate is the height of the arc's plane.
    /// In 2 axes for a circle given in x and y (the xy plane at z = 0),
    /// whose points have 2 too.
    pub center: Point,
    /// r², exact: the squared distance of the start point from the center.
    pub radius_sq: i64,
    /// Angle of the start, radians, atan2(v, u) in the plane's right-handed frame.
    pub start_rad: f64,
    /// Signed sweep, radians: > 0 counter-clockwise (G03), < 0 clockwise
    /// (G02), extra turns included.
    pub sweep_rad: f64,
    /// Angle between polyline vertices, fixed by the whole arc so that the
    /// pieces of a split arc draw as densely as the whole.
    draw_step_rad: f64,
}

impl ArcPath {
    pub fn new(
        plane: Plane,
        center: Point,
        radius_sq: i64,
        start_rad: f64,
        sweep_rad: f64,
    ) -> ArcPath {
        let r = (radius_sq as f64).sqrt();
        let sagitta_step = 2.0 * (1.0 - (DRAW_SAGITTA / r).min(1.0)).acos();
        let draw_step_rad = sagitta_step
            .min(TAU / MIN_VERTICES_PER_TURN)
            .max(sweep_rad.abs() / MAX_POLYLINE_SEGMENTS);
        ArcPath {
            plane,
            center,
            radius_sq,
            start_rad,
            sweep_rad,
            draw_step_rad,
        }
    }

    /// The part of this arc between angles `start_rad` and `start_rad + sweep_rad`.
    pub fn piece(&self, start_rad: f64, sweep_rad: f64) -> ArcPath {
        ArcPath {
            start_rad,
            sweep_rad,
            ..self.clone()
        }
    }

    pub fn radius(&self) -> f64 {
        (self.radius_sq as f64).sqrt()
    }

    /// (u, v, n) of `p` relative to the center, in the plane's frame; n is 0
    /// for a point in 2 axes, which the arc's plane holds.
    fn relative(&self, p: &Point) -> [i64; 3] {
        let axes = self.plane.axes();
        axes.map(|a| {
            if a < p.dims() {
                p.get(a) - self.center.get(a)
            } else {
                0
            }
        })
    }

    /// This arc ready to measure many points (its radius computed once).
    pub fn meter(&self) -> ArcMeter<'_> {
        ArcMeter {
            arc: self,
            radius: self.radius(),
        }
    }

    /// Grid coordinates of the arc's point at angle `theta` and height
    /// `height` above the center's normal coordinate.
    #[cfg(test)]
    fn point_at(&self, theta: f64, height: f64) -> [f64; 3] {
        let (sin, cos) = sin_cos_turns(theta);
        self.point_of(sin, cos, self.radius(), height)
    }

    /// Grid coordinates of the point at radius `r` whose angle has sine
    /// `sin` and cosine `cos`, at `height` above the center (x, y and 0
    /// for an arc in 2 axes, which is in the xy plane).
    fn point_of(&self, sin: f64, cos: f64, r: f64, height: f64) -> [f64; 3] {
        let [au, av, an] = self.plane.axes();
        let mut c = [0.0; 3];
        c[au] = self.center.get(au) as f64 + r * cos;
        c[av] = self.center.get(av) as f64 + r * sin;
        if an < self.center.dims() {
            c[an] = self.center.get(an) as f64 + height;
        }
        c
    }

    /// Vertices for drawing, each handed to `f` in order: `height(t)`
    /// gives the height at fraction t. The first is left out where it
    /// equals `after` (where the path before ended): leaving it in and
    /// taking it out again moved every vertex after it.
    ///
    /// Each vertex's angle is the one before's turned by the same step, a
    /// complex multiplication, rather than a sine and a cosine of its own:
    /// in wasm both come from a software libm, and they were the largest
    /// part of a program's ideal polyline (the G-code bench's program: 10,001
    /// arcs, about 160,000 of its 250,000 vertices). Every [`ANCHOR_EVERY`]-th vertex
    /// and the last are computed from their angle, so the rounding of the
    /// turns cannot gather (under 1e-14 of the radius between anchors), and
    /// an arc ends exactly where its next piece starts.
    fn vertices_with(
        &self,
        after: Option<&[f64]>,
        height: impl Fn(f64) -> f64,
        mut f: impl FnMut(&[f64]),
    ) {
        let segments = (self.sweep_rad.abs() / self.draw_step_rad).ceil().max(1.0) as usize;
        let r = self.radius();
        let (step_sin, step_cos) = sin_cos_turns(self.sweep_rad / segments as f64);
        let (mut sin, mut cos) = (0.0, 1.0);
        for i in 0..=segments {
            let t = i as f64 / segments as f64;
            (sin, cos) = if i % ANCHOR_EVERY == 0 || i == segments {
                sin_cos_turns(self.start_rad + self.sweep_rad * t)
            } else {
                (
                    sin * step_cos + cos * step_sin,
                    cos * step_cos - sin * step_sin,
                )
            };
            let vertex = self.point_of(sin, cos, r, height(t));
            // In the points' axes: an arc in 2 (the xy plane) leaves out z.
            let vertex = &vertex[..self.center.dims()];
            if i > 0 || after != Some(vertex) {
                f(vertex);
            }
        }
    }

    /// Vertices for drawing (stride: the center's axes), each handed to
    /// `f`, the first left out where it equals `after`.
    pub fn for_each_vertex(&self, after: Option<&[f64]>, f: impl FnMut(&[f64])) {
        self.vertices_with(after, |_| 0.0, f)
    }

    #[cfg(test)]
    fn polyline(&self) -> Vec<f64> {
        let mut out = Vec::new();
        self.for_each_vertex(None, |v| out.extend_from_slice(v));
        out
    }

    pub fn info(&self) -> IdealPathInfo {
        IdealPathInfo::Arc {
            center: self.center.coords().to_vec(),
            plane: self.plane.label(),
            radius: self.radius(),
            start_rad: self.start_rad,
            sweep_rad: self.sweep_rad,
        }
    }
}

/// An arc with its radius computed, measuring points.
pub struct ArcMeter<'a> {
    arc: &'a ArcPath,
    /// sqrt(r²), grid units.
    radius: f64,
}

impl ArcMeter<'_> {
    /// ρ² - r² and ρ² = u² + v² of in-plane offsets `u`, `v`, each formed
    /// exactly and rounded once to f64: in i64 when both are below
    /// [`I64_PRODUCT_BOUND`](crate::grid::I64_PRODUCT_BOUND) (each square
    /// below 2^62, the sum below 2^63; every point of a validated circle
    /// is), else in i128. The i64 path forms no i128 at all: an i128's
    /// conversion to f64 is a library call, in wasm as natively, and took
    /// half of a circle's deviation (a conversion through i64 of the same
    /// i128 value, LLVM folded back into it).
    fn excess_and_rho_sq(&self, u: i64, v: i64) -> (f64, f64) {
        if within_i64_product_bound(&[u, v]) {
            let rho_sq = u * u + v * v;
            ((rho_sq - self.arc.radius_sq) as f64, rho_sq as f64)
        } else {
            let rho_sq = u as i128 * u as i128 + v as i128 * v as i128;
            ((rho_sq - self.arc.radius_sq as i128) as f64, rho_sq as f64)
        }
    }

    /// ρ, and ρ - r from ρ² - r² and ρ², of the point at in-plane offsets
    /// `u`, `v`: divided by ρ + r only at the end, so ρ - r keeps full f64
    /// precision where sqrt(u² + v²) - r would cancel away every digit at
    /// r = 2^20 far from the origin.
    #[inline]
    fn rho_and_radial_error(&self, u: i64, v: i64) -> (f64, f64) {
        let (excess, rho_sq) = self.excess_and_rho_sq(u, v);
        let rho = rho_sq.sqrt();
        (rho, excess / (rho + self.radius))
    }

    /// Signed radial error ρ - r of `p` (> 0 outside), ρ = distance from the
    /// center axis. For the tests: a deviation reads it through
    /// [`Self::deviation_at`].
    #[cfg(test)]
    fn radial_error(&self, p: &Point) -> f64 {
        let [u, v, _] = self.arc.relative(p);
        self.rho_and_radial_error(u, v).1
    }

    /// Distance from `p` to the circle: radial error and height off the plane.
    pub fn deviation(&self, p: &Point) -> f64 {
        self.deviation_at(self.arc.relative(p))
    }

    /// [`Self::deviation`] of the point at offsets (u, v, n) from the center.
    #[inline]
    pub fn deviation_at(&self, [u, v, n]: [i64; 3]) -> f64 {
        Self::deviation_of(self.rho_and_radial_error(u, v).1, n)
    }

    /// The distance of a point ρ - r off the circle radially and n off its
    /// plane.
    #[inline]
    fn deviation_of(radial: f64, n: i64) -> f64 {
        // hypot(x, 0) is |x| exactly; hypot itself is a library call, and
        // every point of an arc in its plane has n = 0.
        if n == 0 {
            radial.abs()
        } else {
            radial.hypot(n as f64)
        }
    }

    /// [`Self::deviation_at`] and [`Self::axis_error_at`] at once, ρ and
    /// ρ - r found once for both (the metrics want both of every point).
    #[inline]
    pub fn measure_at(&self, offsets: [i64; 3]) -> (f64, [f64; MAX_AXES]) {
        let [u, v, n] = offsets;
        let (rho, radial) = self.rho_and_radial_error(u, v);
        (
            Self::deviation_of(radial, n),
            self.axis_error_of(offsets, rho, radial),
        )
    }

    /// The offsets (u, v, n) from the center, in the plane's frame, of
    /// `start` and of the point after each of `moves` after it, handed to
    /// `f` in order: carried from step to step (a step moves each by -1, 0
    /// or 1), where measuring point by point rebuilt each point and took
    /// its offsets from it. For [`Self::deviation_at`] and
    /// [`Self::axis_error_at`], which then give the same values to the bit.
    pub fn walk(&self, start: &Point, moves: &[Step], mut f: impl FnMut([i64; 3])) {
        let [au, av, an] = self.arc.plane.axes();
        let mut offsets = self.arc.relative(start);
        f(offsets);
        for &step in moves {
            offsets[0] += step.delta(au);
            offsets[1] += step.delta(av);
            offsets[2] += step.delta(an);
            f(offsets);
        }
    }

    /// `p` minus the arc's point at the same angle (the radial projection).
    pub fn axis_error(&self, p: &Point) -> [f64; MAX_AXES] {
        self.axis_error_at(self.arc.relative(p))
    }

    /// The point at offsets (u, v, n) from the center: what
    /// [`ArcPath::relative`] takes apart, put together again.
    pub fn point_at(&self, offsets: [i64; 3]) -> Point {
        let mut p = self.arc.center;
        let dims = p.dims();
        for (axis, offset) in self.arc.plane.axes().into_iter().zip(offsets) {
            // An arc in 2 axes has no normal axis, and every offset on it is 0.
            if axis < dims {
                p.coords_mut()[axis] += offset;
            }
        }
        p
    }

    /// [`Self::axis_error`] of the point at offsets (u, v, n) from the center.
    #[inline]
    pub fn axis_error_at(&self, offsets: [i64; 3]) -> [f64; MAX_AXES] {
        let (rho, radial) = self.rho_and_radial_error(offsets[0], offsets[1]);
        self.axis_error_of(offsets, rho, radial)
    }

    /// [`Self::axis_error_at`] given the point's ρ and ρ - r.
    #[inline]
    fn axis_error_of(&self, [u, v, n]: [i64; 3], rho: f64, radial: f64) -> [f64; MAX_AXES] {
        let [au, av, an] = self.arc.plane.axes();
        let mut phi = [0.0; MAX_AXES];
        if rho == 0.0 {
            // The center has no angle: compare with the start of the arc.
            phi[au] = -self.radius * self.arc.start_rad.cos();
            phi[av] = -self.radius * self.arc.start_rad.sin();
        } else {
            let scale = radial / rho;
            phi[au] = u as f64 * scale;
            phi[av] = v as f64 * scale;
        }
        phi[an] = n as f64;
        phi
    }
}

/// A helix: an arc whose height rises linearly with the angle.
#[derive(Clone, Debug, PartialEq)]
pub struct HelixPath {
    pub arc: ArcPath,
    /// Height of the helix's start above the center's normal coordinate
    /// (0 for a whole helix; fractional for a piece of one).
    pub start_height: f64,
    /// Change of height over the whole sweep, grid units.
    pub rise: f64,
    /// The fractions of this path's sweep between which a point is
    /// measured (its nearest point sought): [0, 1] for a whole helix
    /// ([`HelixPath::new`]). A piece ([`HelixPath::piece`], a chord's
    /// stretch of the helix) keeps the whole helix's, so a chord's point is
    /// measured against the helix, not against its own stretch of it alone:
    /// a vertex rounded back past its fraction was measured to the end of
    /// the next chord's stretch (0.704 where the helix passes 0.111 away).
    pub measured: [f64; 2],
}

/// Newton iterations per candidate in [`HelixMeter::deviation_at`], at most.
const NEWTON_ITERATIONS: usize = 8;

/// A Newton step in [`HelixMeter::deviation_at`] shorter than this along the
/// helix, grid units, ends the candidate's iterations: the distance there
/// is flat to the square of the step (about 10^-18 of a cell), and the
/// steps after it only wander in the last bits of t. Without it, every
/// candidate ran all NEWTON_ITERATIONS, since a step is rarely exactly 0:
/// the deviations of the arcs bench's 1,018,225-point helix took 1.12 s
/// natively, 0.70 s with it.
const CONVERGED_STEP_UNITS: f64 = 1e-9;

impl HelixPath {
    /// The whole helix: `arc` rising `rise` from `start_height`.
    pub fn new(arc: ArcPath, start_height: f64, rise: f64) -> HelixPath {
        HelixPath {
            arc,
            start_height,
            rise,
            measured: [0.0, 1.0],
        }
    }

    /// The stretch between two fractions of this helix's sweep, measuring
    /// points against the same helix as this one ([`Self::measured`]).
    pub fn piece(&self, start_fraction: f64, end_fraction: f64) -> HelixPath {
        let sweep = self.arc.sweep_rad;
        let span = end_fraction - start_fraction;
        HelixPath {
            measured: self.measured.map(|t| (t - start_fraction) / span),
            arc: self.arc.piece(
                self.arc.start_rad + sweep * start_fraction,
                sweep * (end_fraction - start_fraction),
            ),
            start_height: self.start_height + self.rise * start_fraction,
            rise: self.rise * (end_fraction - start_fraction),
        }
    }

    /// This helix ready to measure many points: its constants, and the
    /// sine and cosine of the angles at the ends of [`Self::measured`],
    /// computed once.
    pub fn meter(&self) -> HelixMeter<'_> {
        let s = self.arc.sweep_rad;
        let arc = self.arc.meter();
        let end = |t: f64| {
            let (sin, cos) = sin_cos_turns(self.arc.start_rad + s * t);
            SinCos { sin, cos }
        };
        HelixMeter {
            helix: self,
            converged: CONVERGED_STEP_UNITS / (arc.radius * s).hypot(self.rise),
            half_turn: PI / s.abs(),
            ends: self.measured.map(end),
            arc,
        }
    }

    /// Distance from `p` to the helix: [`HelixMeter::deviation`].
    pub fn deviation(&self, p: &Point) -> f64 {
        self.meter().deviation(p)
    }

    /// `p` minus the helix's point at the same angle: [`HelixMeter::axis_error`].
    pub fn axis_error(&self, p: &Point) -> [f64; MAX_AXES] {
        self.meter().axis_error(p)
    }

    /// Vertices for drawing (stride 3), each handed to `f`, the first left
    /// out where it equals `after`.
    pub fn for_each_vertex(&self, after: Option<&[f64]>, f: impl FnMut(&[f64])) {
        self.arc
            .vertices_with(after, |t| self.start_height + self.rise * t, f)
    }

    pub fn info(&self) -> IdealPathInfo {
        IdealPathInfo::Helix {
            center: self.arc.center.coords().to_vec(),
            plane: self.arc.plane.label(),
            radius: self.arc.radius(),
            start_rad: self.arc.start_rad,
            sweep_rad: self.arc.sweep_rad,
            start_height: self.start_height,
            rise: self.rise,
        }
    }
}

/// A turn in [`HelixMeter::deviation_at`]'s iterations no longer than this,
/// radians, finds the new angle's sine and cosine by turning the old ones
/// ([`SinCos::turned`]); a longer one (a first step on a small or steep
/// helix) computes them.
const SMALL_TURN_RAD: f64 = 0.125;

/// The sine and cosine of an angle.
#[derive(Clone, Copy, Debug, PartialEq)]
struct SinCos {
    sin: f64,
    cos: f64,
}

impl SinCos {
    /// This angle turned by `delta` radians, |delta| at most
    /// [`SMALL_TURN_RAD`]: by the Taylor series of sin δ (to δ^9) and of
    /// cos δ - 1 (to δ^10), whose next terms are under 3e-18 there. In
    /// wasm, sin and cos come from a software libm; a helix's per-point
    /// distance called them once per Newton iterate, and they were its
    /// largest part.
    #[inline]
    fn turned(self, delta: f64) -> SinCos {
        let d2 = delta * delta;
        let sin_delta = delta
            * (1.0
                - d2 * (1.0 / 6.0)
                    * (1.0
                        - d2 * (1.0 / 20.0)
                            * (1.0 - d2 * (1.0 / 42.0) * (1.0 - d2 * (1.0 / 72.0)))));
        let cos_delta_less_1 = -d2
            * 0.5
            * (1.0
                - d2 * (1.0 / 12.0)
                    * (1.0
                        - d2 * (1.0 / 30.0)
                            * (1.0 - d2 * (1.0 / 56.0) * (1.0 - d2 * (1.0 / 90.0)))));
        SinCos {
            sin: self.sin + (self.sin * cos_delta_less_1 + self.cos * sin_delta),
            cos: self.cos + (self.cos * cos_delta_less_1 - self.sin * sin_delta),
        }
    }
}

/// A point as a helix measures it ([`HelixMeter::place`]): found once, for
/// both its distance and its per-axis error, which share its angle (one
/// atan2 a point, where each took its own).
#[derive(Clone, Copy, Debug)]
pub struct HelixPoint {
    /// (a, b, h): offsets from the center in the plane's frame, h measured
    /// from the start height.
    q: [f64; 3],
    /// Distance from the helix's axis less the radius (ρ - r, exact to
    /// the rounding of f64: [`ArcMeter`]).
    radial: f64,
    /// ρ, the point's distance from the helix's axis.
    rho: f64,
    /// The point's own angle around the axis, φ = atan2(b, a), radians
    /// (0 on the axis itself), and its sine and cosine (b / ρ, a / ρ).
    phi: f64,
    angle: SinCos,
    /// The whole number of turns k at which the helix has the point's own
    /// angle (at fraction (φ + 2πk - θ0) / s) on the turn whose height is
    /// nearest the point's, or the next turn inward near an end
    /// ([`HelixMeter::place`]).
    turn: f64,
    /// That turn's fraction, clamped onto [`HelixPath::measured`].
    nearest: f64,
}

/// A helix with its constants computed, measuring points: each point on its
/// own (no state carried from one point to the next, so a stretch of points
/// measures the same whichever point it starts from).
pub struct HelixMeter<'a> {
    helix: &'a HelixPath,
    /// The helix's circle (its radius, and ρ - r of a point).
    arc: ArcMeter<'a>,
    /// Fractions of t a step of [`CONVERGED_STEP_UNITS`] along the helix spans.
    converged: f64,
    /// Fractions of t in half a turn.
    half_turn: f64,
    /// sin and cos of the angles at the two ends of [`HelixPath::measured`].
    ends: [SinCos; 2],
}

impl HelixMeter<'_> {
    /// The point at offsets (u, v, n) from the center, in the plane's frame
    /// ([`ArcMeter::walk`]), placed around the helix.
    pub fn place(&self, [u, v, n]: [i64; 3]) -> HelixPoint {
        let helix = self.helix;
        let (a, b) = (u as f64, v as f64);
        let q = [a, b, n as f64 - helix.start_height];
        let (rho, radial) = self.arc.rho_and_radial_error(u, v);
        let (phi, angle) = if rho == 0.0 {
            (0.0, SinCos { sin: 0.0, cos: 1.0 })
        } else {
            (
                b.atan2(a),
                SinCos {
                    sin: b / rho,
                    cos: a / rho,
                },
            )
        };
        let sweep = helix.arc.sweep_rad;
        let [lo, hi] = helix.measured;
        // t_k = (phi + 2πk - θ0) / s for whole k: the angles equal to phi.
        let t_of = |k: f64| (phi + TAU * k - helix.arc.start_rad) / sweep;
        let height_fraction = if helix.rise == 0.0 {
            0.5
        } else {
            (q[2] / helix.rise).clamp(lo, hi)
        };
        let mut k = ((helix.arc.start_rad + sweep * height_fraction - phi) / TAU).round();
        // That turn may have no point at this angle within the fractions
        // measured (a point near an end, at an angle past the end's): then
        // the next turn inward, where it has one and its point at this
        // angle is nearer than the end. Clamped onto the end always, a
        // point was compared with the end's angle: on a helix of pitch
        // 0.5, points at height 0 half a turn from the start were 2 r off
        // in x. (The end itself, its fraction rounded past the end, stays
        // with the end.)
        let past = t_of(k);
        if past < lo || past > hi {
            let (end, end_t, inner_k) = if past < lo {
                (self.ends[0], lo, k + sweep.signum())
            } else {
                (self.ends[1], hi, k - sweep.signum())
            };
            let inner_t = t_of(inner_k);
            let r = self.arc.radius;
            let to_end = (a - r * end.cos).powi(2)
                + (b - r * end.sin).powi(2)
                + (q[2] - helix.rise * end_t).powi(2);
            let to_inner = radial * radial + (q[2] - helix.rise * inner_t).powi(2);
            if (lo..=hi).contains(&inner_t) && to_inner < to_end {
                k = inner_k;
            }
        }
        HelixPoint {
            q,
            radial,
            rho,
            phi,
            angle,
            turn: k,
            nearest: t_of(k).clamp(lo, hi),
        }
    }

    /// The points at `start` and after each of `moves`, placed
    /// ([`Self::place`]) and handed to `f` in order, their offsets from the
    /// center carried from step to step ([`ArcMeter::walk`]).
    pub fn walk(&self, start: &Point, moves: &[Step], mut f: impl FnMut(&HelixPoint)) {
        self.arc.walk(
            start,
            moves,
            #[inline(always)]
            |offsets| f(&self.place(offsets)),
        );
    }

    /// Distance from `p` to the helix (its nearest point, ends included;
    /// for a piece, the whole helix's: [`HelixPath::measured`]).
    pub fn deviation(&self, p: &Point) -> f64 {
        self.deviation_at(&self.place(self.helix.arc.relative(p)))
    }

    /// sin and cos at fraction `t` when it is an end of the fractions
    /// measured (computed once, in [`HelixPath::meter`]).
    fn at_end(&self, t: f64) -> Option<SinCos> {
        let [lo, hi] = self.helix.measured;
        if t == lo {
            Some(self.ends[0])
        } else if t == hi {
            Some(self.ends[1])
        } else {
            None
        }
    }

    /// [`Self::deviation`] of a placed point.
    ///
    /// Method: D(t) = |q - H(t)|² over t in [`HelixPath::measured`], where
    /// H(t) is the helix at angle θ0 + s t and height rise t:
    /// D'(t)/2 = r s (a sin θ - b cos θ) - rise (h - rise t),
    /// D''(t)/2 = r s² (a cos θ + b sin θ) + rise²
    ///          = r s² ρ cos(θ - φ) + rise².
    /// The nearest point is an end, or a t inside where D' = 0 and
    /// D'' >= 0, so where cos(θ - φ) >= -c with c = rise² / (r s² ρ): within
    /// π/2 + asin c <= (π/2)(1 + c) of the point's own angle φ (anywhere for
    /// c >= 1). Around each turn's fraction at angle φ that makes a zone of
    /// t in which D is convex ([`Self::convex_half_width`]); D is measured at
    /// both ends, and Newton's method on D'(t) = 0 runs from the angle φ of
    /// each zone that reaches the fractions measured and could hold a
    /// nearer point (its heights apart, besides the radial gap): the turn
    /// nearest the point's height first, the turns either side, and the
    /// turns within a turn of either end. The smallest D is the distance.
    /// A start at the point's own angle has the point's sine and cosine
    /// (b / ρ, a / ρ), an end the ones the meter keeps, and each iterate
    /// turns the one before's by its step ([`SinCos::turned`]): sin and
    /// cos are computed only for a step longer than [`SMALL_TURN_RAD`].
    ///
    /// Each end was a Newton start of its own before, searching a turn
    /// from it, and the turns either side of the nearest were searched from
    /// the end they were clamped onto wherever the heights allowed: the
    /// metrics of the end-to-end bench's helix (one turn, 1,697,057
    /// points; 5.5 evaluations of D a point) took 267 ms natively and 304
    /// ms in Node, 205 to 216 and 242 ms so; the arcs bench's helix (nine
    /// turns, 1,018,225 points) 115 -> 103 to 108 ms natively.
    pub fn deviation_at(&self, point: &HelixPoint) -> f64 {
        let helix = self.helix;
        let s = helix.arc.sweep_rad;
        let [lo, hi] = helix.measured;
        let zone = self.convex_half_width(point.rho);
        let mut best = f64::INFINITY;
        let k = point.turn;
        let near = [k, k - 1.0, k + 1.0];
        for j in near {
            self.search_turn(point, j, zone, &mut best);
        }
        // Each end, and the turns within a turn of it (at most three for a
        // stretch of one turn and two zones) other than those, where that
        // stretch could hold a nearer point.
        let turn_at = |t: f64| (helix.arc.start_rad + s * t - point.phi) / TAU;
        let turn = 2.0 * self.half_turn;
        let mut at_lo = [f64::NAN; 3];
        let ends = [
            (lo, self.ends[0], [lo - zone, lo + turn + zone]),
            (hi, self.ends[1], [hi - turn - zone, hi + zone]),
        ];
        for (index, (end, along, [from, to])) in ends.into_iter().enumerate() {
            // The end, and every zone of the turns whose fractions lie in
            // [from, to], lie in [from - zone, to + zone].
            if self.least_distance_sq_within(point, (from - zone).max(lo), (to + zone).min(hi))
                >= best
            {
                continue;
            }
            best = best.min(self.distance_sq(point, end, along));
            let (a, b) = (turn_at(from), turn_at(to));
            let (first, last) = (a.min(b), a.max(b));
            if first > k - 2.0 && last < k + 2.0 {
                continue;
            }
            let first = first.ceil();
            let turns =
                [first, first + 1.0, first + 2.0].map(|j| if j <= last { j } else { f64::NAN });
            for j in turns {
                if !(j.is_nan() || near.contains(&j) || at_lo.contains(&j)) {
                    self.search_turn(point, j, zone, &mut best);
                }
            }
            if index == 0 {
                at_lo = turns;
            }
        }
        best.sqrt()
    }

    /// D(t) of [`Self::deviation_at`] at fraction `t`, whose angle has sine
    /// and cosine `along`.
    #[inline(always)]
    fn distance_sq(&self, point: &HelixPoint, t: f64, along: SinCos) -> f64 {
        let (q, r) = (point.q, self.arc.radius);
        let height = q[2] - self.helix.rise * t;
        (q[0] - r * along.cos).powi(2) + (q[1] - r * along.sin).powi(2) + height * height
    }

    /// The least D(t) can be for t in [from, to] (infinite where that is
    /// empty): the radial gap, and the heights apart.
    #[inline(always)]
    fn least_distance_sq_within(&self, point: &HelixPoint, from: f64, to: f64) -> f64 {
        if from > to {
            return f64::INFINITY;
        }
        let rise = self.helix.rise;
        let (low, high) = (rise * from, rise * to);
        let h = point.q[2];
        let height_gap = (low.min(high) - h).max(h - low.max(high)).max(0.0);
        point.radial * point.radial + height_gap * height_gap
    }

    /// Newton's method on D'(t) = 0 from turn `j`'s fraction at the
    /// point's own angle (clamped onto the fractions measured), where its
    /// zone (`zone` either side) reaches them and could hold a point
    /// nearer than `best`, which it lowers to each iterate's D.
    fn search_turn(&self, point: &HelixPoint, j: f64, zone: f64, best: &mut f64) {
        let helix = self.helix;
        let q = point.q;
        let r = self.arc.radius;
        let s = helix.arc.sweep_rad;
        let rise = helix.rise;
        let [lo, hi] = helix.measured;
        let own = (point.phi + TAU * j - helix.arc.start_rad) / s;
        if self.least_distance_sq_within(point, (own - zone).max(lo), (own + zone).min(hi)) >= *best
        {
            return;
        }
        let mut t = own.clamp(lo, hi);
        let mut along = self.at_end(t).unwrap_or(point.angle);
        // D at each iterate, and D' and D'' from the same sine and cosine.
        for iteration in 0..=NEWTON_ITERATIONS {
            let SinCos { sin, cos } = along;
            *best = best.min(self.distance_sq(point, t, along));
            let curvature = r * s * s * (q[0] * cos + q[1] * sin) + rise * rise;
            if iteration == NEWTON_ITERATIONS || curvature <= 0.0 {
                break;
            }
            let slope = r * s * (q[0] * sin - q[1] * cos) - rise * (q[2] - rise * t);
            let next = (t - slope / curvature).clamp(lo, hi);
            if (next - t).abs() <= self.converged {
                break;
            }
            let turn = s * (next - t);
            along = match self.at_end(next) {
                Some(end) => end,
                None if turn.abs() <= SMALL_TURN_RAD => along.turned(turn),
                None => {
                    let (sin, cos) = sin_cos_turns(helix.arc.start_rad + s * next);
                    SinCos { sin, cos }
                }
            };
            t = next;
        }
    }

    /// Half the width, in fractions of t, of the zone about each turn's
    /// fraction at a point's own angle within which the nearest point can
    /// lie ([`Self::deviation_at`]): (π/2)(1 + c) / |s| with
    /// c = rise² / (r s² ρ), which bounds (π/2 + asin c) / |s| from above
    /// without an asin, or half a turn where c >= 1 (D convex everywhere:
    /// a steep helix, or a point on or near the axis, ρ = 0).
    fn convex_half_width(&self, rho: f64) -> f64 {
        let s = self.helix.arc.sweep_rad;
        let rise_sq = self.helix.rise * self.helix.rise;
        let bend = self.arc.radius * s * s * rho;
        if rise_sq >= bend {
            self.half_turn
        } else {
            0.5 * self.half_turn * (1.0 + rise_sq / bend)
        }
    }

    /// `p` minus the helix's point at the same angle, on the turn nearest
    /// the point's height (an end of the fractions measured where that
    /// turn's point lies past it).
    pub fn axis_error(&self, p: &Point) -> [f64; MAX_AXES] {
        self.axis_error_at(&self.place(self.helix.arc.relative(p)))
    }

    /// [`Self::axis_error`] of a placed point: the helix's point at its
    /// angle has its sine and cosine, an end's the ones the meter keeps.
    pub fn axis_error_at(&self, point: &HelixPoint) -> [f64; MAX_AXES] {
        let t = point.nearest;
        let SinCos { sin, cos } = self.at_end(t).unwrap_or(point.angle);
        let r = self.arc.radius;
        let [au, av, an] = self.helix.arc.plane.axes();
        let mut phi = [0.0; MAX_AXES];
        phi[au] = point.q[0] - r * cos;
        phi[av] = point.q[1] - r * sin;
        phi[an] = point.q[2] - self.helix.rise * t;
        phi
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn arc(center: [i64; 3], radius_sq: i64, start_rad: f64, sweep_rad: f64) -> ArcPath {
        ArcPath::new(
            Plane::Xy,
            Point::new(&center),
            radius_sq,
            start_rad,
            sweep_rad,
        )
    }

    #[test]
    fn radial_error_is_exact_for_a_big_circle_far_out() {
        // r = 5 * 2^18 = 1,310,720 (a 3-4-5 circle, so grid points lie on
        // it), centered near the +2^30 corner. The naive sqrt(u² + v²) - r
        // rounds u² + v² ≈ 2^41 well, but the test point 2^30 from the origin
        // would not; here the center is subtracted first and ρ² - r² is exact.
        let k = 1i64 << 18;
        let c = (1i64 << 30) - 6 * k;
        let a = arc([c, c, c], 25 * k * k, 0.0, TAU);
        let meter = a.meter();
        assert_eq!(
            meter.radial_error(&Point::new(&[c + 3 * k, c + 4 * k, c])),
            0.0
        );
        assert_eq!(meter.radial_error(&Point::new(&[c + 5 * k + 1, c, c])), 1.0);
        assert_eq!(
            meter.radial_error(&Point::new(&[c, c - 5 * k + 1, c])),
            -1.0
        );
        // One unit off along the diagonal direction (3, 4)/5 is not a grid
        // point; (3k+1, 4k+1) is 7/5 out along it, to first order.
        let e = meter.radial_error(&Point::new(&[c + 3 * k + 1, c + 4 * k + 1, c]));
        assert!((e - 1.4).abs() < 1e-6, "{e}");
        // Off the plane: distance combines radial and height.
        assert_eq!(
            meter.deviation(&Point::new(&[c + 5 * k + 3, c, c + 4])),
            5.0
        );
    }

    #[test]
    fn fast_squares_equal_i128_at_the_bound() {
        // r² near the largest squares the i64 path forms, so that ρ² - r²
        // needs every bit of it.
        let path = arc([0, 0, 0], (1 << 62) - 12_345, 0.0, TAU);
        let meter = path.meter();
        let edge = [
            0,
            1,
            -1,
            (1 << 31) - 1,
            -(1 << 31) + 1,
            1 << 31,
            -(1 << 31),
            1 << 40,
        ];
        for u in edge {
            for v in edge {
                let exact = u as i128 * u as i128 + v as i128 * v as i128;
                let want = ((exact - meter.arc.radius_sq as i128) as f64, exact as f64);
                assert_eq!(meter.excess_and_rho_sq(u, v), want, "({u}, {v})");
            }
        }
    }

    #[test]
    fn axis_error_is_the_radial_error_split_per_axis() {
        let a = arc([-7, -9, 2], 25, 0.0, TAU);
        let meter = a.meter();
        // (-7 + 6, -9 + 8) is 10 from the center: 5 outside along (3, 4)/5.
        let phi = meter.axis_error(&Point::new(&[-1, -1, 2]));
        assert!((phi[0] - 3.0).abs() < 1e-12 && (phi[1] - 4.0).abs() < 1e-12);
        assert_eq!(phi[2], 0.0);
    }

    #[test]
    fn polyline_is_smooth_and_bounded() {
        // Small circle: at least 64 vertices per turn.
        let small = arc([0, 0, 0], 9, 0.0, TAU).polyline();
        assert_eq!(small.len() / 3, 65);
        // Big circle: chords of sagitta 1/4 unit.
        let r = 1i64 << 20;
        let big = arc([0, 0, 0], r * r, 0.0, PI / 2.0);
        let line = big.polyline();
        let n = line.len() / 3 - 1;
        let sagitta = r as f64 * (1.0 - (PI / 4.0 / n as f64).cos());
        assert!(sagitta <= DRAW_SAGITTA, "{n} segments, sagitta {sagitta}");
        // Many turns of a huge circle: capped.
        let huge = 1i64 << 29;
        let capped = arc([0, 0, 0], huge * huge, 0.0, 100.0 * TAU).polyline();
        assert_eq!(capped.len() / 3 - 1, MAX_POLYLINE_SEGMENTS as usize);
        // Ends exactly where the arc starts and stops.
        assert!((line[0] - r as f64).abs() < 1e-9 && line[1].abs() < 1e-9);
        let end = &line[line.len() - 3..];
        assert!(end[0].abs() < 1e-6 && (end[1] - (1 << 20) as f64).abs() < 1e-9);
    }

    #[test]
    fn polyline_vertices_are_the_arcs_points_at_their_angles() {
        // Turned from the vertex before, each vertex stays at its own angle's
        // point, to within 1e-12 of the radius: on small arcs, on a huge one
        // of 100 turns (capped at 16,384 vertices) and in either direction.
        for (radius, start_rad, sweep_rad) in [
            (3i64, 0.0, TAU),
            (1 << 20, 0.7, -PI / 2.0),
            (1 << 29, -2.0, 100.0 * TAU),
            (12_345, 5.5, 3.0),
        ] {
            let a = arc([5, -7, 2], radius * radius, start_rad, sweep_rad);
            let line = a.polyline();
            let n = line.len() / 3 - 1;
            for (i, vertex) in line.chunks_exact(3).enumerate() {
                let want = a.point_at(start_rad + sweep_rad * (i as f64 / n as f64), 0.0);
                for axis in 0..3 {
                    let off = (vertex[axis] - want[axis]).abs();
                    assert!(
                        off <= 1e-12 * radius as f64,
                        "r {radius}, vertex {i} of {n}, axis {axis}: {off}"
                    );
                }
            }
        }
    }

    /// Squared distance from local point `q` to the helix at fraction t.
    fn distance_sq(h: &HelixPath, q: [f64; 3], t: f64) -> f64 {
        let theta = h.arc.start_rad + h.arc.sweep_rad * t;
        let r = h.arc.radius();
        let (s, c) = sin_cos_turns(theta);
        (q[0] - r * c).powi(2) + (q[1] - r * s).powi(2) + (q[2] - h.rise * t).powi(2)
    }

    /// Nearest distance by sampling t finely over the fractions measured,
    /// then golden-section refinement around every sample nearer than its
    /// neighbours. Refining only the best sample is not enough: where the
    /// turns lie closer together than the sampling's own error (turns
    /// 0.06 apart, samples 0.4 grid units apart along r = 2858), the best
    /// sample can sit on a turn whose true minimum is not the nearest.
    fn brute_force(h: &HelixPath, p: &Point) -> f64 {
        let [u, v, n] = h.arc.relative(p);
        let q = [u as f64, v as f64, n as f64 - h.start_height];
        let samples = 200_000;
        let [first, last] = h.measured;
        let spacing = (last - first) / samples as f64;
        let sampled: Vec<f64> = (0..=samples)
            .map(|i| distance_sq(h, q, first + i as f64 * spacing))
            .collect();
        let refine = |t: f64| {
            let (mut lo, mut hi) = ((t - spacing).max(first), (t + spacing).min(last));
            let g = (5f64.sqrt() - 1.0) / 2.0;
            for _ in 0..100 {
                let (a, b) = (hi - g * (hi - lo), lo + g * (hi - lo));
                if distance_sq(h, q, a) < distance_sq(h, q, b) {
                    hi = b;
                } else {
                    lo = a;
                }
            }
            distance_sq(h, q, (lo + hi) / 2.0)
        };
        let mut best = f64::INFINITY;
        for (i, &d) in sampled.iter().enumerate() {
            let left = if i == 0 {
                f64::INFINITY
            } else {
                sampled[i - 1]
            };
            let right = sampled.get(i + 1).copied().unwrap_or(f64::INFINITY);
            if d <= left && d <= right {
                best = best.min(d).min(refine(first + i as f64 * spacing));
            }
        }
        best.sqrt()
    }

    #[test]
    fn helix_distance_matches_brute_force() {
        let helices = [
            // One turn of r = 10 rising 40: steep.
            (100, 0.0, TAU, 40.0),
            // Three turns, shallow, clockwise, starting at 90°.
            (400, PI / 2.0, -3.0 * TAU, 6.0),
            // A quarter turn falling.
            (25, 1.0, PI / 2.0, -7.0),
            // Five turns of r = 1000 rising only 2: turns closer than the
            // distance to them.
            (1_000_000, 0.0, 5.0 * TAU, 2.0),
        ];
        let points = [
            [10, 0, 0],
            [11, 3, 7],
            [-9, -4, 20],
            [0, 0, 3],
            [3, 4, -2],
            [-6, 8, 39],
            [700, -700, 1],
            [1001, 2, 2],
            [0, 20, 5],
        ];
        for (radius_sq, start, sweep, rise) in helices {
            let h = HelixPath::new(arc([0, 0, 0], radius_sq, start, sweep), 0.0, rise);
            for p in points {
                let p = Point::new(&p);
                let (fast, slow) = (h.deviation(&p), brute_force(&h, &p));
                assert!(
                    (fast - slow).abs() <= 1e-7 * slow.max(1.0),
                    "r² {radius_sq} sweep {sweep} rise {rise} {p:?}: newton {fast}, brute force {slow}"
                );
            }
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(128))]
        /// Points near random helices and pieces of them (turns from far
        /// apart to closer than the points stray, either direction, small
        /// radii to large), the axis's own points, and points anywhere
        /// about them (a learner's points may stray far, or sit near the
        /// axis, where the zones the search keeps to are widest or cover
        /// everything): the distance with the turns whose zone is provably
        /// farther left out, and each search's iterations stopped once
        /// converged, is the brute force's.
        #[test]
        fn helix_distance_with_starts_left_out_matches_brute_force(
            radius in 1i64..3_000,
            start in 0.0..TAU,
            turns in -6.0f64..6.0,
            pitch in proptest::prop_oneof![-4.0f64..4.0, -3_000.0f64..3_000.0],
            piece in proptest::option::of((0.0f64..0.5, 0.5f64..1.0)),
            at in 0.0f64..1.0,
            offset in proptest::array::uniform3(-4i64..=4),
            across in proptest::array::uniform2(-2.5f64..2.5),
            height in -1.5f64..2.5,
        ) {
            let sweep = if turns.abs() < 0.05 { 0.05 * TAU } else { turns * TAU };
            // Height gained a turn (pitch), closer than the points stray in half the cases.
            let rise = pitch * sweep.abs() / TAU;
            let whole = HelixPath::new(arc([0, 0, 0], radius * radius, start, sweep), 0.0, rise);
            let h = match piece {
                Some((from, to)) => whole.piece(from, to),
                None => whole.clone(),
            };
            // The helix's point at fraction `at` of the whole, rounded, moved by `offset`.
            let on = whole.arc.point_at(start + sweep * at, rise * at);
            let p = Point::new(&std::array::from_fn::<i64, 3, _>(|axis| on[axis].round() as i64 + offset[axis]));
            let (fast, slow) = (h.deviation(&p), brute_force(&h, &p));
            proptest::prop_assert!(
                (fast - slow).abs() <= 1e-7 * slow.max(1.0),
                "newton {fast}, brute force {slow}"
            );
            let axis_point = Point::new(&[0, 0, (rise * at).round() as i64]);
            let (fast, slow) = (h.deviation(&axis_point), brute_force(&h, &axis_point));
            proptest::prop_assert!((fast - slow).abs() <= 1e-7 * slow.max(1.0), "on the axis: newton {fast}, brute force {slow}");
            let span = radius as f64 + 4.0;
            let anywhere = Point::new(&[
                (across[0] * span).round() as i64,
                (across[1] * span).round() as i64,
                (height * rise.abs().max(span)).round() as i64,
            ]);
            let (fast, slow) = (h.deviation(&anywhere), brute_force(&h, &anywhere));
            proptest::prop_assert!(
                (fast - slow).abs() <= 1e-7 * slow.max(1.0),
                "{anywhere:?}: newton {fast}, brute force {slow}"
            );
        }
    }

    /// `p` minus the helix's point at the same angle on the turn nearest
    /// its height, as the definition reads: the angle by atan2, the point
    /// by its own sine and cosine, in grid coordinates.
    fn axis_error_by_definition(h: &HelixPath, p: &Point) -> [f64; 3] {
        let [u, v, n] = h.arc.relative(p);
        let phi = (v as f64).atan2(u as f64);
        let [lo, hi] = h.measured;
        let sweep = h.arc.sweep_rad;
        let h_rel = n as f64 - h.start_height;
        let height_fraction = if h.rise == 0.0 {
            0.5
        } else {
            (h_rel / h.rise).clamp(lo, hi)
        };
        // The nearest turn by height (its point clamped onto the end), or
        // the nearest turn with a point at angle phi within the fractions
        // measured: whichever's point is nearer.
        let t_of = |k: f64| (phi + TAU * k - h.arc.start_rad) / sweep;
        let x = ((h.arc.start_rad + sweep * height_fraction - phi) / TAU).round();
        let at = |t: f64| {
            h.arc
                .point_at(h.arc.start_rad + sweep * t, h.start_height + h.rise * t)
        };
        let distance = |t: f64| {
            (0..3)
                .map(|axis| (p.get(axis) as f64 - at(t)[axis]).powi(2))
                .sum::<f64>()
        };
        let clamped = t_of(x).clamp(lo, hi);
        let t = (-3..=3)
            .map(|i| t_of(x + i as f64))
            .filter(|t| (lo..=hi).contains(t))
            .min_by(|a, b| {
                (a - height_fraction)
                    .abs()
                    .total_cmp(&(b - height_fraction).abs())
            })
            .filter(|&inner| distance(inner) < distance(clamped))
            .unwrap_or(clamped);
        let ideal = h
            .arc
            .point_at(h.arc.start_rad + sweep * t, h.start_height + h.rise * t);
        std::array::from_fn(|axis| p.get(axis) as f64 - ideal[axis])
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]
        /// A walk of steps near a random helix or piece of one (turns far
        /// apart or closer together than a cell, either direction, centers
        /// anywhere up to ±2^30): each walked point measures as it does on
        /// its own, to the bit (so a stretch of points measures the same
        /// wherever it starts), its distance is the brute force's and its
        /// axis error the definition's.
        #[test]
        fn walked_helix_points_measure_as_each_alone(
            radius in 1i64..3_000,
            center in proptest::array::uniform3(proptest::prop_oneof![
                -(1i64 << 30) + 3_100..=(1i64 << 30) - 3_100,
                proptest::strategy::Just((1i64 << 30) - 3_100),
                proptest::strategy::Just(-(1i64 << 30) + 3_100),
            ]),
            start in 0.0..TAU,
            turns in -6.0f64..6.0,
            pitch in proptest::prop_oneof![-0.5f64..0.5, -4.0f64..4.0, -3_000.0f64..3_000.0],
            piece in proptest::option::of((0.0f64..0.5, 0.5f64..1.0)),
            at in 0.0f64..1.0,
            moves in proptest::collection::vec(proptest::array::uniform3(-1i64..=1), 0..6),
        ) {
            let sweep = if turns.abs() < 0.05 { 0.05 * TAU } else { turns * TAU };
            let rise = (pitch * sweep.abs() / TAU).clamp(-1e5, 1e5);
            let whole = HelixPath::new(arc(center, radius * radius, start, sweep), 0.0, rise);
            let h = match piece {
                Some((from, to)) => whole.piece(from, to),
                None => whole.clone(),
            };
            let on = whole.arc.point_at(start + sweep * at, rise * at);
            let first = Point::new(&std::array::from_fn::<i64, 3, _>(|axis| on[axis].round() as i64));
            let moves: Vec<Step> = moves
                .iter()
                .map(|m| (0..3).fold(Step::NONE, |step, a| step.with(a, m[a])))
                .collect();
            let meter = h.meter();
            let mut walked = Vec::new();
            meter.walk(&first, &moves, |point| walked.push((meter.deviation_at(point), meter.axis_error_at(point))));
            let mut p = first;
            for (k, (deviation, error)) in walked.into_iter().enumerate() {
                if k > 0 {
                    p.apply(moves[k - 1]);
                }
                proptest::prop_assert_eq!(deviation.to_bits(), h.deviation(&p).to_bits(), "point {}", k);
                proptest::prop_assert_eq!(error.map(f64::to_bits), h.axis_error(&p).map(f64::to_bits), "point {}", k);
                let slow = brute_force(&h, &p);
                proptest::prop_assert!(
                    (deviation - slow).abs() <= 1e-7 * slow.max(1.0),
                    "point {}: newton {}, brute force {}", k, deviation, slow
                );
                let want = axis_error_by_definition(&h, &p);
                for axis in 0..3 {
                    // The definition's point has the rounding of coordinates
                    // up to 2^30; the meter's offsets from the center are exact.
                    proptest::prop_assert!(
                        (error[axis] - want[axis]).abs() <= 1e-9 * (radius as f64).max(1e3) + 1e-15 * center[axis].abs() as f64,
                        "point {} axis {}: {:?}, by definition {:?}", k, axis, error, want
                    );
                }
            }
        }
    }

    #[test]
    fn helix_axis_error_takes_a_turn_that_has_the_points_angle() {
        // Three turns of r = 10 rising 1.5 (0.5 a turn): at -90°, three
        // quarters of the first turn, the helix is at height 0.375. The
        // point (0, -10, 0) is nearest in height to the turn before the
        // start, which has no point there: it was compared with the start
        // (10, 0, 0), 10 off in x and y.
        let h = HelixPath::new(arc([0, 0, 0], 100, 0.0, 3.0 * TAU), 0.0, 1.5);
        let phi = h.axis_error(&Point::new(&[0, -10, 0]));
        assert!(phi[0].abs() < 1e-12 && phi[1].abs() < 1e-12, "{phi:?}");
        assert!((phi[2] + 0.375).abs() < 1e-12, "{phi:?}");
        // The same at the end, clockwise: at -90° the last turn passed
        // a quarter turn before the end, at height 1.125; (0, -10, 2) was
        // compared with the end (10, 0, 1.5).
        let h = HelixPath::new(arc([0, 0, 0], 100, 0.0, -3.0 * TAU), 0.0, 1.5);
        let phi = h.axis_error(&Point::new(&[0, -10, 2]));
        assert!(phi[0].abs() < 1e-12 && phi[1].abs() < 1e-12, "{phi:?}");
        assert!((phi[2] - 0.875).abs() < 1e-12, "{phi:?}");
    }

    #[test]
    fn helix_axis_error_compares_at_the_same_angle() {
        // One turn of r = 5 rising 80 from height 0: at angle 90° the helix
        // is at height 20. A point at (0, 5, 23) is 3 high there.
        let h = HelixPath::new(arc([0, 0, 0], 25, 0.0, TAU), 0.0, 80.0);
        let phi = h.axis_error(&Point::new(&[0, 5, 23]));
        assert!(phi[0].abs() < 1e-12 && phi[1].abs() < 1e-12, "{phi:?}");
        assert!((phi[2] - 3.0).abs() < 1e-12, "{phi:?}");
        // A piece keeps the parent's heights.
        let piece = h.piece(0.25, 0.5);
        assert_eq!(piece.start_height, 20.0);
        assert!((piece.axis_error(&Point::new(&[0, 5, 23]))[2] - 3.0).abs() < 1e-12);
    }
}
