//! Saleem & Saleem (2004), "Bresenham type fast algorithm for 3-D linear and
//! helical movement in CNC machines", section 4: the integer circle.
//!
//! Relative to the center (eq. 12-13), in the octant the current point is
//! travelling through, one axis (fast) steps every time; the other (slow)
//! steps when that puts the point nearer the circle, judged by the integer
//! error |x² + y² - r²| of the two candidates (eq. 6-9). Arithmetic is exact
//! (i128), so the path never drifts.
//!
//! Stopping: the paper's `complete()` stops "at the nearest point" once the
//! octant of the end is reached. voxpath's rule, which always ends exactly on
//! the programmed end point: follow the circle until the step that reaches or
//! passes the ray from the center through the end point (on the last turn);
//! of the points just before and just after that ray, stop at the one
//! strictly nearer the end (before, on a tie); then step straight to the end,
//! moving each in-plane axis one unit toward it while it differs. Those are
//! correction steps, marked in the `correction` column.
//!
//! Bounds: every circle step turns the point strictly forward (the fast axis
//! moves along the tangent), so a turn takes at most 8 (r + 1) steps and the
//! circle part at most (turns + 1) 8 (r + 1); the correction takes
//! max(|Δu|, |Δv|) steps from the stop point to the end.

use super::planes::{Frame, OCTANTS, OctantRule, Orientation, in_octant, octant_ahead};
use super::{ArcSpec, CENTER, DIR, PLANE, TURNS, ceil_sqrt, norm_sq};
use crate::algorithm_info::{AlgorithmInfo, Example, Family, Find};
use crate::error::Error;
use crate::figure::{ArcCandidate, ArcCandidates, DecisionFigure, FigureKind};
use crate::grid::{
    AXIS_NAMES, OCTANT_LABELS, Point, SIGNED_AXIS_LABELS, Step, signed_axis,
    within_i64_product_bound,
};
use crate::ideal::IdealPath;
use crate::lanes::{Codes8, Quad};
use crate::line::step_target;
use crate::plan::Plan;
use crate::request::{FROM, MAX_STEPS, MAX_STEPS_LIMIT, Request, TO};
use crate::trace::{
    Column, ColumnKind, Decision, Filled, Stepper, Trace, TraceBuilder, fill_by_next_step,
    path_too_long,
};
use std::fmt::Write;
use std::mem::MaybeUninit;

pub const ID: &str = "circle";

pub const INFO: AlgorithmInfo = AlgorithmInfo {
    id: ID,
    example: Example {
        options: r#"{"from": [5, 0, 0], "to": [0, 5, 0], "center": [0, 0, 0], "dir": "ccw", "plane": "xy"}"#,
        why: "A counter-clockwise quarter circle of radius 5 (Saleem eq. 7-11).",
    },
    family: Family::Arc,
    title: "Bresenham-type circle (arcs G02/G03)",
    citation: "Saleem & Saleem (2004), Bresenham type fast algorithm for 3-D linear and helical movement in CNC machines, section 4, eq. (6)-(13)",
    teaching: "Relative to the center, the circle is x² + y² - r² = 0, and |x² + y² - r²| measures how far a grid point is from it (eq. 6). The plane is cut into eight octants; in each, one axis moves faster along the circle than the other, so it steps every time, and the only question is whether the slow axis steps too. Compare the error of the two candidates, with and without the slow step, and take the smaller (eq. 7-9): integers only, no square roots. The two errors always differ by an odd number, so they are never equal and there are no ties. Clockwise arcs (G02) run the same rule on the mirror image. The path stops at the circle point nearest the programmed end and, if the end is not on the rasterised circle, steps straight to it (correction steps).",
    errata: &[
        "The pseudo-code handles counter-clockwise travel only, although the text introduces G02 (clockwise). voxpath runs clockwise arcs as counter-clockwise arcs of the mirror image (v -> -v), which keeps every error value.",
        "nextStep mixes x and x1, y and y1 (the start point) in the octant 1/4/5/8 branch and increments x1 instead of x in the other. voxpath uses the current point throughout.",
        "nextStep's tests `2*d*B + d < 0` (when d > 0) and `2*d*B + d > 0` (when d < 0), with d = 1 + 2*incX*x and B the error of the candidate that keeps x, drop the square of eq. (10)'s last term d² and keep the factor the text says to eliminate. Both reduce to 2B + 1 < 0, which is not eq. (10) (2B + d compared with 0) and in octant 1 moves x inward exactly when the kept cell is already inside the circle: from (5, 2) on r = 5 it keeps (5, 3), error 9, where eq. (7) takes (4, 3), error 0. voxpath decides by eq. (7) itself, comparing the two |x² + y² - r²|.",
        "nextStep tests `|x| > |y|` and then `|x| < |y|` with the updated point, so one call can make two moves, and on a diagonal |x| = |y| (for example (5, 5) on r² = 50) it makes none and the loop never ends. voxpath takes the octant ahead of the point: boundaries belong to the octant travel enters.",
        "complete() stops \"at the nearest point\" once the end's octant is reached, so the path can end off the programmed end point. voxpath stops at the circle point nearest the end (of the two either side of the ray from the center through it) and closes the rest with marked correction steps.",
    ],
    columns: CircleWhy::COLUMNS,
    options: &[FROM, TO, CENTER, DIR, PLANE, TURNS, MAX_STEPS],
    min_dims: 2,
    max_dims: 3,
    default_tie: None,
    compared_by: None,
    trace: trace_circle,
    plan: Some(plan_circle),
};

fn trace_circle(req: &Request, _: Find) -> Result<Trace, Error> {
    let spec = ArcSpec::of_request(req, &INFO, false)?;
    let mut builder = TraceBuilder::for_request(spec.start_point(), req)?;
    let stepper = SaleemCircle::new(&spec).within(builder.max_steps())?;
    builder.run(stepper, IdealPath::Arc(spec.ideal_arc()))?;
    Ok(builder.finish(ID))
}

/// The circle planned ([`crate::plan`]): its dry run counts its steps,
/// and its correction steps close it at its end point.
fn plan_circle(req: &Request, _: Find) -> Result<Option<Plan>, Error> {
    let spec = ArcSpec::of_request(req, &INFO, false)?;
    let max_steps = req.max_steps()?;
    let stepper = SaleemCircle::new(&spec).counted(max_steps)?;
    let end = spec.to.with_dims(spec.dims());
    Ok(Plan::of_stepper(
        spec.start_point(),
        end,
        stepper,
        max_steps,
    ))
}

pub const OCTANT: Column = Column::new(
    "octant",
    ColumnKind::Category {
        labels: &OCTANT_LABELS,
    },
    "Octant 1-8 the step travels through, counted counter-clockwise from the plane's first axis, seen from the positive end of its normal (Saleem Figure 1); a point on a boundary belongs to the octant ahead.",
);

pub const FAST: Column = Column::new(
    "fast",
    ColumnKind::Category {
        labels: &["x", "y", "z"],
    },
    "The axis that steps every time in this octant; empty for correction steps.",
);

pub const RESIDUAL_STAY: Column = Column::new(
    "residualStay",
    ColumnKind::Int,
    "u² + v² - r² (Saleem eq. 6 without its absolute value, u and v relative to the center; > 0 outside the circle, < 0 inside) of the candidate where only the fast axis steps.",
)
.formerly("residual_stay");

pub const RESIDUAL_MOVE: Column = Column::new(
    "residualMove",
    ColumnKind::Int,
    "u² + v² - r² of the candidate where the slow axis steps too; the slow axis steps when this one is nearer 0 (eq. 7 compares the absolute values, Saleem's error).",
)
.formerly("residual_move");

pub const SLOW_STEPS: Column = Column::new(
    "slowSteps",
    ColumnKind::Flag,
    "1 when the slow axis stepped.",
)
.formerly("slow_steps");

pub const CORRECTION: Column = Column::new(
    "correction",
    ColumnKind::Flag,
    "1 for a step that closes the gap between the rasterised circle and a programmed end point that is not on it.",
);

pub const OTHER_CANDIDATE: Column = Column::new(
    "otherCandidate",
    ColumnKind::Category { labels: SIGNED_AXIS_LABELS },
    "The candidate the step did not take, as a direction from the point the step reached: one cell along the slow axis that way (-x: the cell toward -x). The two candidates differ only on the slow axis, so the reached point and this cell are the pair eq. (7) compared: the reached point is the stay candidate when slowSteps is 0 and the move candidate when it is 1. (In a helix the cell is at the reached point's height on the linear axis; u² + v² - r² does not depend on it.) Empty for correction steps.",
)
.formerly("other_candidate");

/// The circle's decision columns, in [`CircleWhy::write`]'s order (the
/// helix's columns start with them).
pub const CIRCLE_COLUMNS: [Column; 7] = [
    OCTANT,
    FAST,
    RESIDUAL_STAY,
    RESIDUAL_MOVE,
    SLOW_STEPS,
    CORRECTION,
    OTHER_CANDIDATE,
];

/// Why one step of the circle was taken.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CircleWhy {
    /// Octant 1-8 in the plane's own numbering (None at the center, which
    /// only a correction step could pass through).
    pub octant: Option<u8>,
    pub kind: CircleStep,
    orientation: Orientation,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CircleStep {
    /// A step of Saleem's rule, in the local counter-clockwise frame.
    Arc {
        /// The octant's rule: which local axis is fast, which slow, and
        /// their directions (a reference keeps the decision small).
        rule: &'static OctantRule,
        /// u² + v² - r² of the two candidates (signed: > 0 outside).
        residual_stay: i64,
        residual_move: i64,
        slow_steps: bool,
        /// This is the circle point nearest the end: the circle part ends.
        last: bool,
    },
    /// A step straight toward the end point.
    Correction {
        /// 1-based index among `of` correction steps.
        index: u64,
        of: u64,
        /// u² + v² - r² of the programmed end point.
        end_residual: i64,
        /// The circle stopped before the end's ray because the next circle
        /// point was no nearer the end.
        stopped_before_ray: bool,
    },
}

impl CircleWhy {
    /// The candidate the step did not take, from the point it reached: one
    /// cell along the slow axis, as (grid axis, direction); None for a
    /// correction step. The move candidate is the stay one plus the slow
    /// axis's step, so from the reached point the other candidate is that
    /// step back (slow axis stepped) or forward (it stayed).
    fn other_candidate(&self) -> Option<(usize, i64)> {
        let CircleStep::Arc {
            rule, slow_steps, ..
        } = self.kind
        else {
            return None;
        };
        let local_dir = if slow_steps {
            -rule.slow_dir
        } else {
            rule.slow_dir
        };
        let f = &self.orientation;
        Some((f.axis(rule.slow), f.grid_direction(rule.slow, local_dir)))
    }

    /// The two candidates eq. (7) compared, for `step` taken from `from`
    /// (in a helix, at the height of the point the step reached); None for
    /// a correction step.
    pub fn candidates(&self, from: &Point, step: Step) -> Option<ArcCandidates> {
        let CircleStep::Arc {
            residual_stay,
            residual_move,
            slow_steps,
            ..
        } = self.kind
        else {
            return None;
        };
        let (axis, dir) = self.other_candidate()?;
        let mut reached = *from;
        reached.apply(step);
        let mut other = reached;
        other.coords_mut()[axis] += dir;
        let (stay, moved) = if slow_steps {
            (other, reached)
        } else {
            (reached, other)
        };
        Some(ArcCandidates {
            candidates: [
                ArcCandidate {
                    name: "stay",
                    cell: stay.coords().to_vec(),
                    residual: residual_stay,
                    taken: !slow_steps,
                },
                ArcCandidate {
                    name: "move",
                    cell: moved.coords().to_vec(),
                    residual: residual_move,
                    taken: slow_steps,
                },
            ],
        })
    }
}

impl Decision for CircleWhy {
    const COLUMNS: &'static [Column] = &CIRCLE_COLUMNS;

    const FIGURE: Option<FigureKind> = Some(FigureKind::ArcCandidates);

    fn figure(&self, from: &Point, step: Step) -> Option<DecisionFigure> {
        self.candidates(from, step)
            .map(DecisionFigure::ArcCandidates)
    }

    /// The two candidates' errors differ by an odd number: never equal.
    const NEVER_TIES: bool = true;

    fn write(&self, row: &mut [f64]) {
        row[0] = self.octant.map_or(f64::NAN, |k| (k - 1) as f64);
        match self.kind {
            CircleStep::Arc {
                rule,
                residual_stay,
                residual_move,
                slow_steps,
                ..
            } => {
                let f = &self.orientation;
                row[1] = f.axis(rule.fast) as f64;
                row[2] = residual_stay as f64;
                row[3] = residual_move as f64;
                row[4] = slow_steps as u8 as f64;
                row[5] = 0.0;
                let (axis, dir) = self.other_candidate().expect("an arc step has one");
                row[6] = f64::from(signed_axis(axis, dir));
            }
            CircleStep::Correction { .. } => {
                row[1..5].fill(f64::NAN);
                row[5] = 1.0;
                row[6] = f64::NAN;
            }
        }
    }

    fn explain(&self, from: &Point, step: Step) -> String {
        let f = &self.orientation;
        let [u, v, _] = f.plane.axes();
        let error = format!("{}² + {}² - r²", AXIS_NAMES[u], AXIS_NAMES[v]);
        let mut s = match self.octant {
            Some(k) => format!("Octant {k}: "),
            None => String::new(),
        };
        match self.kind {
            CircleStep::Arc {
                rule,
                residual_stay,
                residual_move,
                slow_steps,
                last,
            } => {
                let signed = |local: usize, d: i64| {
                    let d = f.grid_direction(local, d);
                    format!(
                        "{}{}",
                        AXIS_NAMES[f.axis(local)],
                        if d > 0 { "+1" } else { "-1" }
                    )
                };
                let slow_name = AXIS_NAMES[f.axis(rule.slow)];
                let _ = write!(
                    s,
                    "{} is the fast axis and steps {}; {slow_name} stays ({error} = {residual_stay}) or steps {} ({residual_move}); |{}| < |{}|, so {slow_name} {} (eq. 7)",
                    AXIS_NAMES[f.axis(rule.fast)],
                    &signed(rule.fast, rule.fast_dir)[1..],
                    &signed(rule.slow, rule.slow_dir)[1..],
                    if slow_steps {
                        residual_move
                    } else {
                        residual_stay
                    },
                    if slow_steps {
                        residual_stay
                    } else {
                        residual_move
                    },
                    if slow_steps { "steps" } else { "stays" },
                );
                if last {
                    s.push_str(
                        "; this is the circle point nearest the end, where the circle part stops",
                    );
                }
            }
            CircleStep::Correction {
                index,
                of,
                end_residual,
                stopped_before_ray,
            } => {
                if stopped_before_ray {
                    s.push_str("the next circle point would be no nearer the end than this one, so the circle part stops here. ");
                }
                let _ = write!(
                    s,
                    "Correction {index} of {of}: the programmed end has {error} = {end_residual}, off the rasterised circle, so the path steps straight toward it"
                );
            }
        }
        let _ = write!(s, ": {}.", step_target(step, from.dims()));
        s
    }
}

/// A circle whose [`SaleemCircle::steps_at_most`] reaches this many steps
/// is counted before it runs ([`SaleemCircle::within`]): a few microseconds
/// of leaps, against the growth of a trace of this length.
const COUNTED_FROM_STEPS: u64 = 1 << 14;

/// What the dry run learns before the real run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CirclePlan {
    pub circle_steps: u64,
    pub correction_steps: u64,
    /// Where the circle part ends and the correction (if any) starts.
    pub stop: Point,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Phase {
    Circle,
    Correction {
        of: u64,
        stopped_before_ray: bool,
        /// Where the circle part ended (the first correction's start).
        stop: [i64; 2],
    },
    Done,
}

/// Pieces of an octant's known stretch that [`SaleemCircle::laned_fill`]
/// steps side by side in i64, for circles past [`LARGEST_VECTOR_RADIUS_SQ`].
/// Two: scalar pieces, the circle of r = 300,000 took 1.8 ms natively with
/// two, 2.4 ms with four (LLVM put four in 128-bit vectors, whose 64-bit
/// compares x86-64's baseline lacks), and in wasm 2.0 to 2.2 ms with two,
/// four or eight.
const LANES: usize = 2;
/// Pieces of an octant's known stretch that [`SaleemCircle::vector_fill`]
/// steps side by side, in two vectors of four i32 lanes, for circles of
/// r <= 2^25 ([`LARGEST_VECTOR_RADIUS_SQ`]). The circle of r = 300,000
/// then took 0.57 to 0.66 ms natively to trace (1.70 to 1.79 with [`LANES`]
/// scalar pieces), and in Node 1.04 ms (2.05).
const VECTOR_PIECES: usize = 8;
/// The largest r² whose recording loop's values fit i32 lanes (see
/// [`SaleemCircle::vector_fill`]).
const LARGEST_VECTOR_RADIUS_SQ: i64 = 1 << 50;
/// Fewest steps a piece takes: shorter stretches go step by step, where
/// finding the pieces' starts (a square root each) would cost more.
const LEAST_LANE_STEPS: usize = 16;
/// Circles smaller than this go step by step: an octant of radius r is
/// about 0.7 r steps, too few for LANES pieces of LEAST_LANE_STEPS.
const SMALLEST_LANED_RADIUS_SQ: i64 = ((2 * LANES * LEAST_LANE_STEPS) as i64).pow(2);

/// The path ahead of a circle's point in its octant, known in closed form
/// ([`SaleemCircle::leap`]): in sizes X of the fast coordinate and Y of
/// the slow one, the nearest points Y = nearest_root(r² - X²), X moving
/// one unit a step (away from 0 in odd octants, toward it in even ones),
/// for `known` steps.
struct NearestRun {
    /// The local axes of the fast and slow coordinates, and their signs.
    fast: usize,
    slow: usize,
    fast_sign: i64,
    slow_sign: i64,
    /// X at the point.
    x0: i64,
    odd: bool,
    known: i64,
    radius_sq: i64,
}

impl NearestRun {
    /// The local point `steps` steps on (up to `known`).
    fn point_at(&self, steps: i64) -> [i64; 2] {
        let x = if self.odd {
            self.x0 + steps
        } else {
            self.x0 - steps
        };
        let mut p = [0; 2];
        p[self.fast] = self.fast_sign * x;
        p[self.slow] = self.slow_sign * nearest_root(self.radius_sq - x * x);
        p
    }
}

/// Saleem's circle stepper for one arc.
#[derive(Clone, Debug)]
pub struct SaleemCircle {
    frame: Frame,
    /// `unit_steps[local axis][d + 1]`: the grid step of a local move by d
    /// (-1, 0, +1) on that axis, so a step is two table reads and an OR.
    unit_steps: [[Step; 3]; 2],
    /// Height on the normal axis, for reporting points.
    height: i64,
    /// r², exact.
    radius_sq: i64,
    /// Current point in the local counter-clockwise frame.
    pos: [i64; 2],
    end: [i64; 2],
    /// Crossings of the ray through the end still to come, the last included.
    crossings_left: u64,
    phase: Phase,
    /// Steps still to take, once the dry run has counted them.
    remaining: Option<u64>,
    plan: Option<CirclePlan>,
    /// Where an odd octant's known stretch ends ([`Self::nearest_run`]):
    /// the least fast coordinate X whose nearest Y is within 2 of it, the
    /// same in every odd octant. Found by bisection when first needed and
    /// kept: the recording loop asks at every chunk of steps it fills (the
    /// circle of r = 300,000, 414 of them, spent 5% of its trace natively
    /// finding it again).
    diagonal_from: Option<i64>,
}

impl SaleemCircle {
    pub fn new(spec: &ArcSpec) -> SaleemCircle {
        let unit = |axis: usize, d: i64| {
            let mut delta = [0; 2];
            delta[axis] = d;
            spec.frame.step(delta)
        };
        SaleemCircle {
            frame: spec.frame,
            unit_steps: [0, 1].map(|axis| [-1, 0, 1].map(|d| unit(axis, d))),
            height: spec.from.get(spec.plane.normal()),
            radius_sq: spec.radius_sq,
            pos: spec.start,
            end: spec.end,
            crossings_left: spec.turns + 1,
            phase: Phase::Circle,
            remaining: None,
            plan: None,
            diagonal_from: None,
        }
    }

    /// u² + v² - r² at local point `p` (eq. 6 without the absolute value).
    /// Exact in i64: see [`local_within_bound`].
    fn residual(&self, p: [i64; 2]) -> i64 {
        debug_assert!(local_within_bound(p), "{p:?} is off the validated circle");
        p[0] * p[0] + p[1] * p[1] - self.radius_sq
    }

    /// Saleem's "dummy procedure" (section 5): runs a copy without moving
    /// anything and counts its steps, giving up soon after `limit` (within
    /// 1024 steps of it): None when there are more than `limit`.
    pub fn plan(&self, limit: u64) -> Option<CirclePlan> {
        let mut dry = self.clone();
        // The circle part by the recording loop, which leaves it on the
        // step that ends it: the last circle step, or the first correction
        // when the circle stops before the ray.
        //
        // Where the closed form knows the path ([`Self::leap`]), the count
        // jumps along it: a few isqrts an octant instead of a step each.
        let mut scratch = [MaybeUninit::uninit(); 1024];
        let mut taken = 0u64;
        // Where the pass that last crossed the ray ended, the steps taken
        // by then, and the crossings left then (see the lap skip below).
        let mut lap_end: Option<([i64; 2], u64, u64)> = None;
        while dry.phase == Phase::Circle {
            let crossings_before = dry.crossings_left;
            taken += dry.leap();
            taken += dry.octant_fill(&mut scratch, &mut || (true, 0)) as u64;
            if taken > limit {
                return None;
            }
            // A full turn that ends at the point the one before it ended
            // at takes the same steps again (each step is a function of
            // the point alone, and so is where a pass ends), every turn
            // until the last crossing: those are counted at once, so that
            // a million turns cost two or three to count.
            if dry.phase != Phase::Circle || dry.crossings_left == crossings_before {
                continue;
            }
            match lap_end {
                Some((pos, at, crossings))
                    if pos == dry.pos && crossings == dry.crossings_left + 1 =>
                {
                    let laps = dry.crossings_left - 1;
                    taken = (taken - at).saturating_mul(laps).saturating_add(taken);
                    dry.crossings_left = 1;
                    if taken > limit {
                        return None;
                    }
                }
                _ => lap_end = Some((dry.pos, taken, dry.crossings_left)),
            }
        }
        let Phase::Correction {
            of,
            stopped_before_ray,
            stop,
        } = dry.phase
        else {
            unreachable!("the circle part ends in the correction");
        };
        // Each correction step moves every in-plane axis that differs from
        // the end one unit toward it: `of` (Chebyshev distance) steps.
        let circle_steps = taken - u64::from(stopped_before_ray);
        if circle_steps + of > limit {
            return None;
        }
        Some(CirclePlan {
            circle_steps,
            correction_steps: of,
            stop: self.frame.point(stop, self.height),
        })
    }

    /// Fewer steps than this circle takes, known without running it: what
    /// its T = `crossings_left` - 1 full turns alone take, (4T - 2)(2k - 1)
    /// with k about r / sqrt(2), near the rule's own 4 sqrt(2) r a turn
    /// (r = 80 and 999,999 extra turns: 451,999,322 of its 452,000,000
    /// steps). [`Self::counted`] refuses an arc at once when this passes
    /// the largest maxSteps: a dry run whose turns do not repeat each other
    /// (none the tests meet) counts them one by one, and a million turns
    /// took 1.4 s natively, 1.8 to 3.7 s in wasm.
    ///
    /// Why it holds, in the local counter-clockwise frame (u, v):
    ///
    /// 1. Every point of the circle part has |u² + v² - r²| <= ⌈r⌉, so
    ///    |p|² >= ρ² = r² - ⌈r⌉. Let p have residual e and larger
    ///    coordinate size m (the slow axis's: |slow| >= |fast| in every
    ///    octant). In odd octants the fast axis moves away from 0 and the
    ///    slow one toward it: the stay candidate has e + 2|fast| + 1 > e,
    ///    the move one e + 2(|fast| - |slow|) + 2 <= e (there |fast| <
    ///    |slow|), and eq. 7 takes the stay one only below m - 1/2, the
    ///    move one only above 1/2 - m. In even octants the other way round:
    ///    stay e - 2|fast| + 1 < e, taken only above -m - 1/2; move e +
    ///    2(|slow| - |fast|) + 2 > e, taken only below m + 1/2. So the next
    ///    residual is between min(e, -m) and max(e, m). The start has
    ///    residual 0 (r² is its own), and a point whose residual is within
    ///    ±⌈r⌉ has |p|² < (r + 1)², so m <= ⌈r⌉: by induction, every point.
    /// 2. Each pass through a quarter takes at least 2k - 1 steps, k the
    ///    least whole number with 2k² >= ρ². In the quarter around +u,
    ///    octants 8 and 1 (-u <= v < u), every step moves v by +1. It is
    ///    entered only from octant 7 (the steps of octants 2 to 6 leave
    ///    u <= 0 or v > u): from (u - 1, w) with -w > u - 1, to (u, v) with
    ///    v <= w + 1 <= 1 - u, and -u <= v; so |v| <= u, 2u² >= ρ², u >= k,
    ///    and the pass starts at v <= 1 - k. It is left from (u, v - 1)
    ///    inside to (u', v) with u' >= u - 1 >= 0 and v >= -u', so outside
    ///    means v >= u' >= 0: 2v² >= ρ², v >= k, where the pass ends. The
    ///    rules of octants K and K + 2 are each other turned by 90°,
    ///    boundaries included, so the other quarters are alike.
    /// 3. A step enters at most one quarter (from octant 7 the next point
    ///    is in octant 7, 8 or 1: u >= 1 and v <= 1 - u <= 0, as in 2).
    ///    The circle part crosses the ray through the end T + 1 times, each
    ///    step turning forward, and takes every step but maybe the last
    ///    crossing's (it may stop short of it): its steps taken reach from
    ///    before the first crossing to within a step of the last, 2πT
    ///    further, entering quarters at all the 4T quarter boundaries in
    ///    between but maybe one. Between two entries lies a whole pass: at
    ///    least 4T - 2 passes.
    ///
    /// Without extra turns it is 0; the dry run counts such an arc.
    pub fn steps_at_least(&self) -> u64 {
        let full_turns = self.crossings_left - 1;
        let radius_sq = i128::from(self.radius_sq);
        let near_sq = radius_sq - ceil_sqrt(radius_sq);
        let k = ceil_sqrt((near_sq + 1) / 2) as u64;
        let passes = full_turns.saturating_mul(4).saturating_sub(2);
        passes.saturating_mul((2 * k).saturating_sub(1))
    }

    /// More steps than this circle can take, known without running it. In
    /// each octant the fast axis moves one unit every step, one way, within
    /// the circle's box (every point is within a cell of the circle, so
    /// |u|, |v| <= R = floor(r) + 2): at most 2R steps an octant, 16R a
    /// turn; the run ends within `crossings_left` crossings of the ray
    /// through the end, plus a partial turn before the first. The
    /// correction steps are at most the Chebyshev distance from a circle
    /// point to the end.
    pub fn steps_at_most(&self) -> u64 {
        let box_half = floor_sqrt(self.radius_sq as u64) + 2;
        let turns = self.crossings_left.saturating_add(1);
        let correction = box_half + self.end[0].unsigned_abs().max(self.end[1].unsigned_abs());
        turns
            .saturating_mul(16 * box_half)
            .saturating_add(correction)
    }

    /// This stepper ready to run within `max_steps` (a trace's maxSteps): as it is when
    /// it is short and [`Self::steps_at_most`] fits (a trace counts its
    /// steps as it records them, and the note runs the dry run when it is
    /// read), else counted ([`Self::counted`]), which refuses it when it
    /// would not fit. Even leaping, the dry run's isqrts cost more than a
    /// short arc's steps (most G-code arcs); a long one's count pays for
    /// itself, as the trace then takes room for its steps at once instead
    /// of growing into it (copying them each time).
    pub fn within(self, max_steps: u64) -> Result<SaleemCircle, Error> {
        let at_most = self.steps_at_most();
        if at_most <= max_steps && at_most < COUNTED_FROM_STEPS {
            Ok(self)
        } else {
            self.counted(max_steps)
        }
    }

    /// This stepper with its steps counted by the dry run, or the maxSteps
    /// error when it would take more than `max_steps`, with the count it
    /// takes (at once, with the full turns' bound, when no maxSteps is
    /// enough).
    pub fn counted(mut self, max_steps: u64) -> Result<SaleemCircle, Error> {
        // Past the largest maxSteps, refused before any dry run, its "at
        // least" the full turns' bound. Under it the count is the advice
        // (the maxSteps that traces it), which the dry run gives at the
        // cost of a turn or two however many there are: refused from the
        // bound, r = 80 with 999,999 extra turns was told "at least
        // 451999322", and refused again at that maxSteps (452,000,000).
        let at_least = self.steps_at_least();
        if at_least > max_steps && at_least > MAX_STEPS_LIMIT {
            return Err(path_too_long(max_steps, at_least));
        }
        let plan = self.plan(max_steps).ok_or_else(|| {
            // The steps it does take, counted on up to the largest maxSteps
            // (the count leaps along the closed form: a few isqrts an
            // octant), so that the error's advice holds: "at least
            // max_steps + 1" had a half circle of radius 2^30 (about 3
            // billion steps) refused again at the largest maxSteps the
            // advice offered.
            let needed = match max_steps >= MAX_STEPS_LIMIT {
                true => max_steps + 1,
                false => self
                    .plan(MAX_STEPS_LIMIT)
                    .map_or(MAX_STEPS_LIMIT + 1, |plan| {
                        plan.circle_steps + plan.correction_steps
                    }),
            };
            path_too_long(max_steps, needed)
        })?;
        self.remaining = Some(plan.circle_steps + plan.correction_steps);
        self.plan = Some(plan);
        Ok(self)
    }

    /// The current point in the local counter-clockwise frame.
    pub(crate) fn local(&self) -> [i64; 2] {
        self.pos
    }

    pub(crate) fn frame(&self) -> &Frame {
        &self.frame
    }

    /// True until the circle part ends (then come the correction steps).
    pub(crate) fn in_circle_part(&self) -> bool {
        self.phase == Phase::Circle
    }

    /// The current grid point.
    pub fn point(&self) -> Point {
        self.frame.point(self.pos, self.height)
    }

    /// One step of Saleem's rule from the current point.
    #[inline(always)]
    fn circle_step(&mut self) -> ([i64; 2], CircleStep, u8) {
        let k = octant_ahead(self.pos).expect("the circle never passes through its center");
        let rule = &OCTANTS[k as usize - 1];
        // The fast axis always steps (section 4: "during each iteration y
        // will always increase" in octant 1).
        let (fast, slow) = (rule.fast_move(), rule.slow_move());
        let stay = [self.pos[0] + fast[0], self.pos[1] + fast[1]];
        let moved = [stay[0] + slow[0], stay[1] + slow[1]];
        let (residual_stay, residual_move) =
            candidates(self.pos, self.residual(self.pos), fast, slow);
        debug_assert_eq!(
            (residual_stay, residual_move),
            (self.residual(stay), self.residual(moved))
        );
        let slow_steps = slow_steps(residual_stay, residual_move);
        let next = if slow_steps { moved } else { stay };
        let mut last = false;
        // The ray from the center through the end is reached when the side
        // of the end (sign of end × point) turns from negative to >= 0; the
        // turn is strictly forward, so this happens once per lap.
        let reaches_ray = cross(self.end, self.pos) < 0 && cross(self.end, next) >= 0;
        if reaches_ray {
            self.crossings_left -= 1;
            if self.crossings_left == 0 {
                let distance_sq = |p: [i64; 2]| norm_sq([self.end[0] - p[0], self.end[1] - p[1]]);
                if distance_sq(next) >= distance_sq(self.pos) {
                    // Stop before the ray: the correction starts from here.
                    self.phase = Phase::Correction {
                        of: chebyshev(self.pos, self.end),
                        stopped_before_ray: true,
                        stop: self.pos,
                    };
                    return self.correction_step();
                }
                last = true;
                self.phase = Phase::Correction {
                    of: chebyshev(next, self.end),
                    stopped_before_ray: false,
                    stop: next,
                };
            }
        }
        let delta = [next[0] - self.pos[0], next[1] - self.pos[1]];
        self.pos = next;
        let kind = CircleStep::Arc {
            rule,
            residual_stay,
            residual_move,
            slow_steps,
            last,
        };
        (delta, kind, k)
    }

    /// The recording loop of the circle part, for the circle and for a
    /// helix woven around it: up to `out.len()` iterations, stopping early
    /// only when the circle part ends (after the step that ends it). At
    /// each, `weave` says whether the arc steps and gives the step bits of
    /// other axes (the circle alone: always, none). Returns the iterations
    /// taken.
    ///
    /// The same steps as [`Stepper::next_step`], without building
    /// decisions: in each octant, a loop of its own ([`Self::octant_run`]).
    #[inline(always)]
    pub(crate) fn weave_fill(
        &mut self,
        out: &mut [MaybeUninit<Step>],
        weave: &mut impl FnMut() -> (bool, u16),
    ) -> usize {
        let mut k = 0;
        while k < out.len() && self.phase == Phase::Circle {
            k += self.octant_fill(&mut out[k..], weave);
        }
        k
    }

    /// [`Self::octant_run`] in the octant the point is in: at least one
    /// iteration unless `out` is empty (after [`Self::laned_fill`] filled
    /// it), ending where the point leaves that octant (or the circle part
    /// ends, or `out` is full).
    #[inline(always)]
    fn octant_fill(
        &mut self,
        out: &mut [MaybeUninit<Step>],
        weave: &mut impl FnMut() -> (bool, u16),
    ) -> usize {
        match octant_ahead(self.pos) {
            Some(1) => self.octant_run_watching::<1>(out, weave),
            Some(2) => self.octant_run_watching::<2>(out, weave),
            Some(3) => self.octant_run_watching::<3>(out, weave),
            Some(4) => self.octant_run_watching::<4>(out, weave),
            Some(5) => self.octant_run_watching::<5>(out, weave),
            Some(6) => self.octant_run_watching::<6>(out, weave),
            Some(7) => self.octant_run_watching::<7>(out, weave),
            Some(8) => self.octant_run_watching::<8>(out, weave),
            _ => unreachable!("the circle never passes through its center"),
        }
    }

    /// [`Self::octant_run`] in octant `K`, watching for the ray through the
    /// end only where a step of this octant can reach it: elsewhere the
    /// loop carries no side at all (its update and test took the circle's
    /// native trace from 2.65 to 3.46 ms, r = 300,000).
    ///
    /// Every point of the loop is within a cell of the circle, |p|² >=
    /// r² - r, so |p| >= r - 1, and a step moves at most one unit per axis
    /// (√2). From radius 5 on, a step therefore turns the point by less
    /// than asin(√2 / 4) < 21°: from octant K (angles [45°(K-1), 45°K)) it
    /// reaches octant K or the next, and can cross the ray only if the
    /// end's direction is in one of them. Smaller circles (r = 1 steps a
    /// quarter turn at a time) always watch.
    #[inline(always)]
    fn octant_run_watching<const K: u8>(
        &mut self,
        out: &mut [MaybeUninit<Step>],
        weave: &mut impl FnMut() -> (bool, u16),
    ) -> usize {
        if self.watches_ray(K) {
            self.octant_run::<K, true>(out, weave)
        } else {
            self.octant_run::<K, false>(out, weave)
        }
    }

    /// The dry run's jump along the path where it is known in closed form:
    /// moves the point as many circle steps ahead as it can without
    /// stepping, and returns how many (0 when it cannot).
    ///
    /// In an octant, let X be the fast coordinate's size and Y the slow
    /// one's, and call a point *nearest* when no other Y at its X has a
    /// smaller |X² + Y² - r²|: Y = [`nearest_root`](r² - X²). Each step
    /// moves X by one and keeps Y or moves it by one, whichever candidate
    /// is nearer (eq. 7), so from a nearest point the next point is
    /// nearest whenever the nearest Y of the next X is one of the two
    /// candidates. With T = r² - X², a nearest Y has
    /// Y² - Y + 1 <= T <= Y² + Y, and:
    /// - in odd octants X grows and Y shrinks (toward the diagonal): T
    ///   drops by 2X + 1, to at least Y² - Y - 2X, which is at least
    ///   (Y-1)² - (Y-1) + 1 when Y - X >= 2. So the path is the nearest
    ///   points until the first X with nearest Y - X < 2, a step or two
    ///   before the octant ends;
    /// - in even octants X shrinks and Y grows (Y >= X >= 1 there): T rises
    ///   by 2X - 1, to at most Y² + Y + 2X - 1 < (Y+1)² + (Y+1). So the
    ///   path is the nearest points down to X = 0, the next octant.
    ///
    /// The start (residual 0) is nearest. Every octant entry the tests
    /// meet is nearest too, but nothing above proves it for the entry
    /// after a diagonal, so an entry is checked: one that is not leaps
    /// nowhere, and the recording loop steps on.
    ///
    /// The circle part ends at the ray through the end: every step turns
    /// forward and an octant spans 45°, so a leap passes that ray at most
    /// once, exactly when end × point goes from negative to >= 0 over it.
    /// Passing it on an earlier lap counts the crossing; on the last lap
    /// the leap stops at the last point before it, and the loop takes the
    /// step that decides where the circle part stops.
    fn leap(&mut self) -> u64 {
        let Some((_, run)) = self.nearest_run() else {
            return 0;
        };
        let mut steps = run.known;
        if let Some(before_ray) = self.steps_before_ray(&run, steps) {
            if self.crossings_left == 1 {
                steps = before_ray;
            } else {
                self.crossings_left -= 1;
            }
        }
        self.pos = run.point_at(steps);
        steps as u64
    }

    /// The octant the point is in, and the path ahead of it there as the
    /// closed form knows it ([`Self::leap`]): None where the point is not
    /// a nearest point, or (odd octants) is already near the diagonal.
    fn nearest_run(&mut self) -> Option<(u8, NearestRun)> {
        let k = octant_ahead(self.pos)?;
        let rule = &OCTANTS[k as usize - 1];
        let odd = k % 2 == 1;
        // The signs of the fast and slow coordinates in this octant: odd
        // octants move the fast one away from 0 and the slow one toward it.
        let (fast_sign, slow_sign) = if odd {
            (rule.fast_dir, -rule.slow_dir)
        } else {
            (-rule.fast_dir, rule.slow_dir)
        };
        let x0 = self.pos[rule.fast] * fast_sign;
        let nearest_y = |x: i64| nearest_root(self.radius_sq - x * x);
        if self.pos[rule.slow] * slow_sign != nearest_y(x0) {
            return None;
        }
        // Steps to the last point the closed form knows.
        let known = if odd {
            let near_diagonal = |x: i64| nearest_y(x) - x < 2;
            if near_diagonal(x0) {
                return None;
            }
            // nearest_y(x) - x falls as x grows (past r it is -x), so the
            // first X near the diagonal lies past x0, whatever x0 is.
            let radius_sq = self.radius_sq;
            let diagonal_from = *self.diagonal_from.get_or_insert_with(|| {
                let beyond = floor_sqrt(radius_sq as u64) as i64 + 2;
                first_true(0, beyond, near_diagonal)
            });
            diagonal_from - x0
        } else {
            x0
        };
        let run = NearestRun {
            fast: rule.fast,
            slow: rule.slow,
            fast_sign,
            slow_sign,
            x0,
            odd,
            known,
            radius_sq: self.radius_sq,
        };
        Some((k, run))
    }

    /// The circle part's recording loop for the arc alone (the circle, and
    /// a helix whose arc leads, its line's steps put in after): the steps
    /// of [`Self::weave_fill`], the arc stepping every iteration. Where the
    /// closed form knows the path ([`Self::laned_fill`]) its stretch is cut
    /// in [`LANES`] pieces stepped side by side; the rest of each octant
    /// (its last steps near the diagonal, the ray through the end) goes
    /// step by step.
    pub(crate) fn arc_fill(&mut self, out: &mut [MaybeUninit<Step>]) -> usize {
        let mut k = 0;
        while k < out.len() && self.phase == Phase::Circle {
            k += match octant_ahead(self.pos) {
                Some(1) => self.laned_fill::<1>(&mut out[k..]),
                Some(2) => self.laned_fill::<2>(&mut out[k..]),
                Some(3) => self.laned_fill::<3>(&mut out[k..]),
                Some(4) => self.laned_fill::<4>(&mut out[k..]),
                Some(5) => self.laned_fill::<5>(&mut out[k..]),
                Some(6) => self.laned_fill::<6>(&mut out[k..]),
                Some(7) => self.laned_fill::<7>(&mut out[k..]),
                Some(8) => self.laned_fill::<8>(&mut out[k..]),
                _ => unreachable!("the circle never passes through its center"),
            };
            k += self.octant_fill(&mut out[k..], &mut || (true, 0));
        }
        k
    }

    /// The steps of octant `K` that the closed form knows, as many as fit
    /// in `out` (a multiple of the pieces) and end before the step that
    /// reaches the ray through the end (that step, once a lap, is left to
    /// [`Self::octant_run`], which counts the laps), or none where the path
    /// is not known there or the stretch is short.
    ///
    /// The stretch is cut in pieces of equal length ([`VECTOR_PIECES`] in
    /// i32 lanes: [`Self::vector_fill`]; else [`LANES`]), each started
    /// from its first point (a nearest point: [`NearestRun::point_at`])
    /// with the decision sum and terms [`Self::octant_run`] carries, and
    /// the pieces are stepped side by side, one step of each an iteration.
    /// Each piece's decisions still wait on one another (its sum decides
    /// its next step), but the pieces do not, so the processor takes their
    /// steps together. Nor does a step test its octant or carry its side of
    /// the ray: the stretch stays in the octant and ends before the ray.
    /// The point ends where the closed form puts the last piece's end. The
    /// circle of r = 300,000 took 4.3 ms to trace in Node, 2.0 ms so.
    #[inline(always)]
    fn laned_fill<const K: u8>(&mut self, out: &mut [MaybeUninit<Step>]) -> usize {
        if out.len() < LANES * LEAST_LANE_STEPS || self.radius_sq < SMALLEST_LANED_RADIUS_SQ {
            return 0;
        }
        let Some((k, run)) = self.nearest_run() else {
            return 0;
        };
        debug_assert_eq!(k, K);
        let mut steps = run.known.min(out.len() as i64);
        if let Some(before_ray) = self.steps_before_ray(&run, steps) {
            steps = before_ray;
        }
        if self.radius_sq <= LARGEST_VECTOR_RADIUS_SQ {
            let piece_steps = steps as usize / VECTOR_PIECES / 8 * 8;
            if piece_steps >= LEAST_LANE_STEPS {
                return self.vector_fill::<K>(&run, piece_steps, out);
            }
        }
        let lane_steps = steps as usize / LANES;
        if lane_steps < LEAST_LANE_STEPS {
            return 0;
        }
        let (fast, slow, stay_code, move_code) = self.octant_moves(K);
        // Each piece's decision sum, fast term and slow term at its start.
        let mut lanes: [[i64; 3]; LANES] = std::array::from_fn(|lane| {
            self.carried_at(run.point_at((lane * lane_steps) as i64), fast, slow)
        });
        let taken = LANES * lane_steps;
        written_in_order(&mut out[..taken]);
        let mut pieces = out[..taken].chunks_exact_mut(lane_steps);
        let mut outs: [&mut [MaybeUninit<Step>]; LANES] =
            std::array::from_fn(|_| pieces.next().expect("LANES pieces"));
        for i in 0..lane_steps {
            for (lane, piece) in lanes.iter_mut().zip(outs.iter_mut()) {
                let [sum, fast_term, slow_term] = lane;
                let moves = slow_steps_in_octant::<K>(*sum);
                piece[i].write(Step(if moves { move_code } else { stay_code }));
                *fast_term += 2;
                *sum += 2 * *fast_term + if moves { 2 * *slow_term + 2 } else { 0 };
                *slow_term += if moves { 2 } else { 0 };
            }
        }
        self.pos = run.point_at(taken as i64);
        // The last piece ends where the closed form says the stretch does.
        debug_assert_eq!(lanes[LANES - 1], self.carried_at(self.pos, fast, slow));
        if let Some(n) = self.remaining.as_mut() {
            *n -= taken as u64;
        }
        taken
    }

    /// [`Self::laned_fill`]'s steps in [`VECTOR_PIECES`] pieces of
    /// `piece_steps` steps (a multiple of 8), their carried values in i32
    /// lanes of two [`Quad`]s: a step of all eight pieces is, per vector,
    /// one compare, four adds and two ands, where each piece's scalar step
    /// took a compare, two selects, three adds and a store of its own code.
    /// Every eighth step the pieces' eight decisions of each of the last
    /// eight steps (one column a step, narrowed to 16 bits) are turned into
    /// each piece's eight in order ([`Codes8::transpose`]), each becoming
    /// its stay or move code by its mask, and stored as 16 bytes.
    ///
    /// What a lane carries: the decision sum, F = 2·(2 p·fast + 1) and
    /// G = 2·(2 p·slow + 1) + 2, so that a step adds 4 to F, F and (when
    /// the slow axis moves) G to the sum, and then 4 to G when it moved:
    /// [`Self::octant_run`]'s sum, fast term and slow term, doubled where
    /// they enter the sum. Exact in i32 for r <= 2^25
    /// ([`LARGEST_VECTOR_RADIUS_SQ`]): each candidate is within two units
    /// of the circle, so its residual is at most 2·(2r + 2) in size and
    /// the sum 8r + 8 < 2^29; F and G are at most 4r + 8, and a sum plus
    /// both stays below 2^30.
    #[inline(always)]
    fn vector_fill<const K: u8>(
        &mut self,
        run: &NearestRun,
        piece_steps: usize,
        out: &mut [MaybeUninit<Step>],
    ) -> usize {
        let (fast, slow, stay_code, move_code) = self.octant_moves(K);
        written_in_order(&mut out[..VECTOR_PIECES * piece_steps]);
        let starts: [[i64; 3]; VECTOR_PIECES] = std::array::from_fn(|piece| {
            self.lane_carried_at(run.point_at((piece * piece_steps) as i64), fast, slow)
        });
        let lanes = |half: usize, value: usize| {
            Quad::new(std::array::from_fn(|j| starts[4 * half + j][value]))
        };
        let mut sum = [lanes(0, 0), lanes(1, 0)];
        let mut fast_twice = [lanes(0, 1), lanes(1, 1)];
        let mut slow_twice = [lanes(0, 2), lanes(1, 2)];
        let (zero, four) = (Quad::splat(0), Quad::splat(4));
        let (stay, moved) = (Codes8::splat(stay_code), Codes8::splat(move_code));
        for block in (0..piece_steps).step_by(8) {
            // One step of the eight pieces: its column of decisions.
            let mut step = || {
                let mut masks = [zero; 2];
                for h in 0..2 {
                    // slow_steps_in_octant, four pieces at once.
                    let moves = if K % 2 == 1 {
                        sum[h].above(zero)
                    } else {
                        zero.above(sum[h])
                    };
                    fast_twice[h] = fast_twice[h].add(four);
                    sum[h] = sum[h].add(fast_twice[h]).add(moves.and(slow_twice[h]));
                    slow_twice[h] = slow_twice[h].add(moves.and(four));
                    masks[h] = moves;
                }
                Codes8::narrow(masks)
            };
            // Built from its eight columns in order, not zeroed then filled:
            // in wasm the zeroing was a `memory.fill` call, which V8 makes a
            // call into the engine, every eight steps (26,512 of them in
            // the r = 300,000 circle's trace).
            let columns = [
                step(),
                step(),
                step(),
                step(),
                step(),
                step(),
                step(),
                step(),
            ];
            for (piece, row) in Codes8::transpose(columns).into_iter().enumerate() {
                let at = piece * piece_steps + block;
                row.choose(stay, moved).store(&mut out[at..at + 8]);
            }
        }
        let taken = VECTOR_PIECES * piece_steps;
        self.pos = run.point_at(taken as i64);
        // The last piece ends where the closed form says the stretch does.
        debug_assert_eq!(
            [
                sum[1].lanes()[3],
                fast_twice[1].lanes()[3],
                slow_twice[1].lanes()[3]
            ],
            self.lane_carried_at(self.pos, fast, slow)
        );
        if let Some(n) = self.remaining.as_mut() {
            *n -= taken as u64;
        }
        taken
    }

    /// What a lane of [`Self::vector_fill`] carries at local point `p`:
    /// [`Self::carried_at`]'s sum, and its terms doubled where they enter
    /// the sum (F = 2·fast term, G = 2·slow term + 2).
    #[inline(always)]
    fn lane_carried_at(&self, p: [i64; 2], fast: [i64; 2], slow: [i64; 2]) -> [i64; 3] {
        let [sum, fast_term, slow_term] = self.carried_at(p, fast, slow);
        [sum, 2 * fast_term, 2 * slow_term + 2]
    }

    /// Where the first `steps` steps of `run` from the point reach the ray
    /// through the end: the steps before the first that does, or None where
    /// none does. The stretch stays in one octant, so it passes the ray at
    /// most once, exactly when end × point goes from negative to >= 0 over
    /// it.
    fn steps_before_ray(&self, run: &NearestRun, steps: i64) -> Option<i64> {
        let past_ray = |steps: i64| cross(self.end, run.point_at(steps)) >= 0;
        (steps > 0 && cross(self.end, self.pos) < 0 && past_ray(steps))
            .then(|| first_true(1, steps, past_ray) - 1)
    }

    /// Whether a step of octant `k` may reach the ray through the end (see
    /// [`Self::octant_run_watching`]).
    fn watches_ray(&self, k: u8) -> bool {
        const SMALLEST_UNWATCHED_RADIUS_SQ: i64 = 5 * 5;
        self.radius_sq < SMALLEST_UNWATCHED_RADIUS_SQ
            || in_octant(k, self.end)
            || in_octant(k % 8 + 1, self.end)
    }

    /// Octant `k`'s fast and slow unit moves (local vectors), and the codes
    /// of its two candidate steps: the fast axis alone, and with the slow.
    #[inline(always)]
    fn octant_moves(&self, k: u8) -> ([i64; 2], [i64; 2], u16, u16) {
        let rule = &OCTANTS[k as usize - 1];
        let (fast, slow) = (rule.fast_move(), rule.slow_move());
        let [a, b] = self.unit_steps;
        let code = |d: [i64; 2]| a[(d[0] + 1) as usize].0 | b[(d[1] + 1) as usize].0;
        let move_code = code([fast[0] + slow[0], fast[1] + slow[1]]);
        (fast, slow, code(fast), move_code)
    }

    /// What the recording loops ([`Self::octant_run`], [`Self::laned_fill`])
    /// carry from step to step at local point `p` of an octant with unit
    /// moves `fast` and `slow`: the decision sum (the two candidates'
    /// residuals added), and the terms 2 p·fast + 1 and 2 p·slow + 1 that
    /// move it (see octant_run).
    #[inline(always)]
    fn carried_at(&self, p: [i64; 2], fast: [i64; 2], slow: [i64; 2]) -> [i64; 3] {
        let (stay, moved) = candidates(p, self.residual(p), fast, slow);
        [stay + moved, 2 * dot(p, fast) + 1, 2 * dot(p, slow) + 1]
    }

    /// Iterations of [`Self::weave_fill`] while the point stays in octant
    /// `K` (which it is in): at least one. The rule is `circle_step`'s, on
    /// local copies (in registers) and with selects, not branches. What is
    /// carried from step to step is the decision itself, the sum of the two
    /// candidates' residuals ([`slow_steps_in_octant`]), as the midpoint
    /// circle does: with f = 2 p·fast + 1 and e = 2 p·slow + 1 at point p,
    /// the candidates' residuals are res(p) + f and res(p) + f + e
    /// ([`candidates`]), so the sum is 2 res(p) + 2f + e. A step adds f + e
    /// or f to res(p), 2 to f, and 2 to e when the slow axis moves (unit
    /// moves, fast ⊥ slow), so the next sum is this one plus 2 f_next, plus
    /// 2 e + 2 when the slow axis moved: two additions and a select behind
    /// each decision, where the residual took two absolute values more.
    /// Its side of the ray through the end (end × point) is carried too,
    /// moved by end × the step. The step that reaches that ray (once a lap)
    /// is left to `next_step`, which counts the laps and may end the circle
    /// part.
    ///
    /// Exact in i64: every point and candidate is within
    /// [`local_within_bound`], and each carried value is a sum of two
    /// residuals, a dot product or a cross product of such points (debug
    /// builds check each decision against [`candidates`] from scratch).
    #[inline(always)]
    fn octant_run<const K: u8, const WATCH_RAY: bool>(
        &mut self,
        out: &mut [MaybeUninit<Step>],
        weave: &mut impl FnMut() -> (bool, u16),
    ) -> usize {
        let (fast, slow, stay_code, move_code) = self.octant_moves(K);
        let (side_fast, side_slow) = (cross(self.end, fast), cross(self.end, slow));
        let mut pos = self.pos;
        let [mut sum, mut fast_term, mut slow_term] = self.carried_at(pos, fast, slow);
        let mut side = cross(self.end, pos);
        let mut taken = 0;
        let mut arc_steps = 0;
        // The step bits woven in at the ray, whose arc step is next_step's.
        let mut at_ray = None;
        for slot in out.iter_mut() {
            if !in_octant(K, pos) {
                break;
            }
            let moves = slow_steps_in_octant::<K>(sum);
            debug_assert!({
                let (stay, moved) = candidates(pos, self.residual(pos), fast, slow);
                stay + moved == sum && moves == slow_steps(stay, moved)
            });
            let next = [
                pos[0] + fast[0] + if moves { slow[0] } else { 0 },
                pos[1] + fast[1] + if moves { slow[1] } else { 0 },
            ];
            let next_side = side + side_fast + if moves { side_slow } else { 0 };
            let (arc, bits) = weave();
            if WATCH_RAY && arc && side < 0 && next_side >= 0 {
                at_ray = Some(bits);
                break;
            }
            if arc {
                pos = next;
                fast_term += 2;
                sum += 2 * fast_term + if moves { 2 * slow_term + 2 } else { 0 };
                slow_term += if moves { 2 } else { 0 };
                side = next_side;
                arc_steps += 1;
            }
            let arc_code = if moves { move_code } else { stay_code };
            slot.write(Step(if arc { arc_code } else { 0 } | bits));
            taken += 1;
        }
        self.pos = pos;
        if let Some(n) = self.remaining.as_mut() {
            *n -= arc_steps;
        }
        if let Some(bits) = at_ray {
            let (step, _) = self
                .next_step()
                .expect("the step onto the ray is a circle step or a correction");
            out[taken].write(Step(step.0 | bits));
            taken += 1;
        }
        taken
    }

    /// One step straight toward the end, each in-plane axis by its sign.
    fn correction_step(&mut self) -> ([i64; 2], CircleStep, u8) {
        let Phase::Correction {
            of,
            stopped_before_ray,
            ..
        } = self.phase
        else {
            unreachable!("correction steps follow the circle part");
        };
        let k = octant_ahead(self.pos).unwrap_or(0);
        let left = chebyshev(self.pos, self.end);
        let delta = [
            (self.end[0] - self.pos[0]).signum(),
            (self.end[1] - self.pos[1]).signum(),
        ];
        self.pos = [self.pos[0] + delta[0], self.pos[1] + delta[1]];
        let index = of - left + 1;
        let kind = CircleStep::Correction {
            index,
            of,
            end_residual: self.residual(self.end),
            stopped_before_ray: stopped_before_ray && index == 1,
        };
        (delta, kind, k)
    }
}

/// u² + v² - r² of the two candidates of a step from `pos`, whose own is
/// `residual`: the stay candidate pos + `fast`, and the move candidate
/// pos + `fast` + `slow` (unit moves along different axes). From
/// |p + e|² = |p|² + 2 p·e + 1 for a unit move e: no squares, and exactly
/// what squaring the candidates gives (eq. 6 without the absolute value).
#[inline(always)]
fn candidates(pos: [i64; 2], residual: i64, fast: [i64; 2], slow: [i64; 2]) -> (i64, i64) {
    let stay = [pos[0] + fast[0], pos[1] + fast[1]];
    let residual_stay = residual + 2 * dot(pos, fast) + 1;
    let residual_move = residual_stay + 2 * dot(stay, slow) + 1;
    (residual_stay, residual_move)
}

/// Eq. (7): the slow axis steps iff |error(moved)| < |error(stay)|. The
/// residuals differ by 2|slow coordinate| ± 1, an odd number, so they
/// cannot be equal in size: no tie to resolve.
#[inline(always)]
fn slow_steps(residual_stay: i64, residual_move: i64) -> bool {
    residual_move.abs() < residual_stay.abs()
}

/// [`slow_steps`] for a point in octant `K`, from the sum of the stay and
/// move candidates' residuals s and m: the sign of one number rather than
/// two sizes, which is what lets the recording loop carry the decision.
///
/// |m| < |s| exactly when (m - s)(m + s) < 0, and m - s =
/// 2 (stay · slow) + 1 has a sign fixed by the octant: in every octant the slow
/// coordinate's size Y is at least the fast one's and the point is not the
/// center, so Y >= 1; odd octants move it toward 0 (m - s = 1 - 2Y < 0),
/// even ones away (m - s = 2Y + 1 > 0). So the slow axis steps when m + s
/// is positive in odd octants and negative in even ones (never 0: m - s is
/// odd, so m + s is too).
#[inline(always)]
fn slow_steps_in_octant<const K: u8>(sum: i64) -> bool {
    if K % 2 == 1 { sum > 0 } else { sum < 0 }
}

/// True when both local coordinates are below [`I64_PRODUCT_BOUND`](crate::grid::I64_PRODUCT_BOUND), so
/// squares and cross products of such points are exact in i64. Every point
/// the circle visits or tests is: it stays within a few units of the circle
/// (or, correcting, between the circle and an end at most one unit off it),
/// and `ArcSpec::parse` keeps the center ± (r + 1) within ±2^30, so each
/// |u|, |v| is about 2^30 at most and u² + v² stays below 2^62.
fn local_within_bound(p: [i64; 2]) -> bool {
    within_i64_product_bound(&p)
}

/// a · b for a local point and a unit move, exact in i64 (the point
/// within [`local_within_bound`]).
#[inline(always)]
fn dot(a: [i64; 2], b: [i64; 2]) -> i64 {
    a[0] * b[0] + a[1] * b[1]
}

/// The z component of a × b for local points, exact in i64 (both within
/// [`local_within_bound`]: each product is below 2^62).
fn cross(a: [i64; 2], b: [i64; 2]) -> i64 {
    debug_assert!(local_within_bound(a) && local_within_bound(b));
    a[0] * b[1] - a[1] * b[0]
}

/// The Y >= 0 with the smallest |Y² - t|: for t >= 1 the one with
/// Y² - Y + 1 <= t <= Y² + Y (the candidates' errors differ by an odd
/// number, so there is one), 0 for t <= 0.
fn nearest_root(t: i64) -> i64 {
    if t <= 0 {
        return 0;
    }
    let y = floor_sqrt(t as u64) as i64;
    if t > y * y + y { y + 1 } else { y }
}

/// ⌊√t⌋ for t <= 2^62 (every r² and r² - X² here: the circle's bound keeps
/// r below 2^30), from the f64 square root, one off at most and then
/// corrected. `u64::isqrt` is a loop in software, with divisions: in Node
/// 13% of the r = 300,000 circle's trace went to it (for the starts of the
/// pieces its recording loop steps side by side, and the stretches' ends).
///
/// With n = ⌊√t⌋ <= 2^31: t converts to f64 with a relative error of at
/// most 2^-53, so √ of n² as converted is within n·2^-54 (and a hair) of
/// n, less than half an ulp of n, and the correctly rounded root is n
/// itself; rounding and the root are monotonic, so the root of any t >= n²
/// is at least n. Nor does it reach n + 2. So its whole part y is n or
/// n + 1, and n + 1 exactly when y² > t.
fn floor_sqrt(t: u64) -> u64 {
    debug_assert!(t <= 1 << 62, "{t} past 2^62");
    let y = (t as f64).sqrt() as u64;
    y - u64::from(y * y > t)
}

/// The first n in [lo, hi] where `holds` (false before it, true from it
/// on, and true at hi), by bisection.
fn first_true(mut lo: i64, mut hi: i64, holds: impl Fn(i64) -> bool) -> i64 {
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if holds(mid) { hi = mid } else { lo = mid + 1 }
    }
    lo
}

fn chebyshev(p: [i64; 2], q: [i64; 2]) -> u64 {
    (p[0] - q[0])
        .unsigned_abs()
        .max((p[1] - q[1]).unsigned_abs())
}

/// Writes `out` front to back before pieces stepped side by side
/// ([`SaleemCircle::laned_fill`], [`SaleemCircle::vector_fill`]) write it
/// again: their stores land at as many places across it at once, and
/// where its memory was not in cache (a trace after others, as a user's
/// next call meets it) each missed and waited; written in order first, the
/// processor fetches it ahead. The circle of r = 300,000 traced in 1.8 to
/// 2.1 ms in Node so measured (a garbage collection and a pause before
/// each), 1.3 to 1.4 ms with this.
#[inline(always)]
fn written_in_order(out: &mut [MaybeUninit<Step>]) {
    out.fill(MaybeUninit::new(Step::NONE));
}

// SAFETY: its fill's Filled counts the slots it wrote (see its Filled::written).
unsafe impl Stepper for SaleemCircle {
    type Why = CircleWhy;

    fn next_step(&mut self) -> Option<(Step, CircleWhy)> {
        let (delta, kind, local_octant) = match self.phase {
            Phase::Done => return None,
            Phase::Correction { .. } if self.pos == self.end => {
                self.phase = Phase::Done;
                return None;
            }
            Phase::Correction { .. } => self.correction_step(),
            Phase::Circle => self.circle_step(),
        };
        if let Some(n) = self.remaining.as_mut() {
            *n -= 1;
        }
        let why = CircleWhy {
            octant: (local_octant > 0).then(|| self.frame.orientation().grid_octant(local_octant)),
            kind,
            orientation: self.frame.orientation(),
        };
        let [a, b] = self.unit_steps;
        let step = Step(a[(delta[0] + 1) as usize].0 | b[(delta[1] + 1) as usize].0);
        Some((step, why))
    }

    /// The circle part by [`Self::arc_fill`], the few correction steps
    /// by `next_step`; the displacement is where the point moved.
    fn fill(&mut self, out: &mut [MaybeUninit<Step>]) -> Filled {
        let before = self.pos;
        let mut steps = self.arc_fill(out);
        steps += fill_by_next_step(self, &mut out[steps..]).steps();
        let delta = [self.pos[0] - before[0], self.pos[1] - before[1]];
        // SAFETY: arc_fill wrote the first steps it counts (each of its
        // loops writes from the start of the slots it is given), and
        // fill_by_next_step the ones it took after them.
        unsafe { Filled::written(steps, self.frame.displacement(delta)) }
    }

    fn remaining_steps(&self) -> Option<u64> {
        self.remaining
    }

    fn setup_note(&self) -> String {
        let f = &self.frame;
        let mut s = String::from("Saleem's rule (eq. 6-11) relative to the center (eq. 12-13)");
        if f.turn.sign() < 0 {
            let v = AXIS_NAMES[f.plane.axes()[1]];
            let _ = write!(
                s,
                ", run on the mirror image {v} -> -{v} because the paper's rule is counter-clockwise"
            );
        }
        // Saleem's dummy procedure (section 5), run now if the stepper ran
        // without it ([`Self::within`]): from the start, every step counts.
        if let Some(plan) = self.plan.or_else(|| self.plan(u64::MAX)) {
            let _ = write!(s, ": {} circle steps to {}", plan.circle_steps, plan.stop);
            let end = f.point(self.end, self.height);
            if plan.correction_steps == 0 {
                let _ = write!(s, ", which is the end point.");
            } else {
                let _ = write!(
                    s,
                    ", the circle point nearest the end {end}; the end has u² + v² - r² = {} (off the rasterised circle), so {} correction {} the gap.",
                    self.residual(self.end),
                    plan.correction_steps,
                    if plan.correction_steps == 1 {
                        "step closes"
                    } else {
                        "steps close"
                    },
                );
            }
        } else {
            s.push('.');
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algorithm_info::find_none;

    fn trace(json: &str) -> Trace {
        INFO.trace_json(json, find_none).unwrap()
    }

    #[test]
    fn i64_residuals_and_crosses_are_exact_on_the_largest_circle() {
        // r = 2^30 - 1 around the origin: the largest circle ArcSpec takes.
        // Its points and candidates reach |u|, |v| = 2^30 on each axis.
        let r = (1i64 << 30) - 1;
        let req = Request::from_json(&format!(
            r#"{{"algorithm":"circle","from":[{r},0,0],"to":[{r},5000,0],"center":[0,0,0]}}"#
        ))
        .unwrap();
        let circle = SaleemCircle::new(&ArcSpec::parse(&req, false, INFO.min_dims).unwrap());
        let edge = [-(1 << 30), -r, -1, 0, 1, r, 1 << 30];
        for a in edge {
            for b in edge {
                let exact = norm_sq([a, b]) - (r as i128) * (r as i128);
                assert_eq!(circle.residual([a, b]) as i128, exact, "({a}, {b})");
                for c in edge {
                    let (p, q) = ([a, b], [c, -a]);
                    assert_eq!(cross(p, q) as i128, crate::arc::cross_dot(p, q).0);
                }
            }
        }
        // The trace runs its debug checks of the bound at every step.
        let t = trace(&format!(
            r#"{{"algorithm":"circle","from":[{r},0,0],"to":[{r},5000,0],"center":[0,0,0]}}"#
        ));
        assert_eq!(t.end(), Point::new(&[r, 5000, 0]));
    }

    fn points(t: &Trace) -> Vec<[i64; 3]> {
        t.points_flat(0, t.steps() + 1)
            .chunks(3)
            .map(|c| [c[0], c[1], c[2]])
            .collect()
    }

    #[test]
    fn columns_hold_the_decision() {
        // Quarter circle r = 5 from (5, 0): step 1 compares (5, 1), residual
        // 1, with (4, 1), residual 16 + 1 - 25 = -8, and keeps x.
        let t = trace(r#"{"algorithm":"circle","from":[5,0,0],"to":[0,5,0],"center":[0,0,0]}"#);
        let d = t.decisions(0, 1);
        let names: Vec<&str> = t.columns().iter().map(|c| c.name).collect();
        assert_eq!(
            names,
            [
                "octant",
                "fast",
                "residualStay",
                "residualMove",
                "slowSteps",
                "correction",
                "otherCandidate"
            ]
        );
        let row: Vec<f64> = d.columns.iter().map(|c| c[0]).collect();
        assert_eq!(row, [0.0, 1.0, 1.0, -8.0, 0.0, 0.0, 1.0]);
        assert_eq!(
            t.explain(0),
            "Octant 1: y is the fast axis and steps +1; x stays (x² + y² - r² = 1) or steps -1 (-8); |1| < |-8|, so x stays (eq. 7): (x, y+1, z)."
        );
        assert!(
            t.segment(0)
                .note()
                .contains("7 circle steps to (0, 5, 0), which is the end point")
        );
    }

    #[test]
    fn both_candidates_of_a_quarter_circle_by_hand() {
        // Saleem section 4, eq. (6)-(7), r = 5 counter-clockwise from (5, 0)
        // to (0, 5). In octant 1 y steps +1 and x may step -1; from (3, 4)
        // on (octant 2) x steps -1 and y may step +1. Each step's residuals
        // x² + y² - r² of (stay, move), and the cell taken:
        //   (5,0): (5,1)   1  (4,1) -8  -> (5,1), other (4,1) = -x
        //   (5,1): (5,2)   4  (4,2) -5  -> (5,2), other (4,2) = -x
        //   (5,2): (5,3)   9  (4,3)  0  -> (4,3), other (5,3) = +x
        //   (4,3): (4,4)   7  (3,4)  0  -> (3,4), other (4,4) = +x
        //   (3,4): (2,4)  -5  (2,5)  4  -> (2,5), other (2,4) = -y
        //   (2,5): (1,5)   1  (1,6) 12  -> (1,5), other (1,6) = +y
        //   (1,5): (0,5)   0  (0,6) 11  -> (0,5), other (0,6) = +y
        let t = trace(r#"{"algorithm":"circle","from":[5,0,0],"to":[0,5,0],"center":[0,0,0]}"#);
        assert_eq!(
            points(&t)[1..],
            [
                [5, 1, 0],
                [5, 2, 0],
                [4, 3, 0],
                [3, 4, 0],
                [2, 5, 0],
                [1, 5, 0],
                [0, 5, 0]
            ]
        );
        let d = t.decisions(0, t.steps());
        assert_eq!(d.columns[2], [1.0, 4.0, 9.0, 7.0, -5.0, 1.0, 0.0]);
        assert_eq!(d.columns[3], [-8.0, -5.0, 0.0, 0.0, 4.0, 12.0, 11.0]);
        assert_eq!(d.columns[4], [0.0, 0.0, 1.0, 1.0, 1.0, 0.0, 0.0]);
        let other: Vec<&str> = d.columns[6]
            .iter()
            .map(|&k| SIGNED_AXIS_LABELS[k as usize])
            .collect();
        assert_eq!(other, ["-x", "-x", "+x", "+x", "-y", "+y", "+y"]);
    }

    #[test]
    fn an_end_off_the_circle_is_reached_by_marked_corrections() {
        // r = 5 from (5, 0) to (2, 4), r_end = sqrt(20) = 4.47. The circle
        // runs (5,1) (5,2) (4,3) (3,4); the next circle point (2,5) is past
        // the ray through (2, 4) (2*5 - 4*2 = 2 >= 0) and as far from it as
        // (3, 4) is (distance² 1 both), so the circle stops at (3, 4) and one
        // correction step x-1 reaches (2, 4).
        let t = trace(r#"{"algorithm":"circle","from":[5,0,0],"to":[2,4,0],"center":[0,0,0]}"#);
        assert_eq!(
            points(&t),
            [
                [5, 0, 0],
                [5, 1, 0],
                [5, 2, 0],
                [4, 3, 0],
                [3, 4, 0],
                [2, 4, 0]
            ]
        );
        let d = t.decisions(0, 5);
        assert_eq!(d.columns[5], [0.0, 0.0, 0.0, 0.0, 1.0]);
        // A correction step has no fast axis, candidates or slow step: its
        // fast, slowSteps and otherCandidate cells say so, rather than
        // "x", "no" and "+x".
        let none = f64::from(crate::trace::NO_VALUE);
        assert_eq!(
            [d.columns[1][4], d.columns[4][4], d.columns[6][4]],
            [none; 3]
        );
        assert!(d.columns[2][4].is_nan() && d.columns[3][4].is_nan());
        let why = t.explain(4);
        assert!(why.contains("no nearer the end"), "{why}");
        assert!(
            why.contains("Correction 1 of 1: the programmed end has x² + y² - r² = -5"),
            "{why}"
        );
        // The last circle step says it is the last when the circle steps
        // onto the ray: r = 5 to (0, 6) (r_end = 6) stops on (0, 5).
        let t = trace(r#"{"algorithm":"circle","from":[5,0,0],"to":[0,6,0],"center":[0,0,0]}"#);
        assert_eq!(points(&t)[7], [0, 5, 0]);
        assert!(t.explain(6).contains("nearest the end"));
        assert_eq!(t.end(), Point::new(&[0, 6, 0]));
        assert!(t.segment_note(0).contains("1 correction step close"));
    }

    #[test]
    fn the_paper_s_diagonal_start_needs_the_octant_ahead() {
        // (5, 5) on r² = 50: |x| = |y|, where the paper's nextStep makes no
        // move. The octant ahead (counter-clockwise) is 2: x steps -1.
        let t = trace(r#"{"algorithm":"circle","from":[5,5,0],"to":[-5,5,0],"center":[0,0,0]}"#);
        assert_eq!(points(&t)[1][0], 4);
        assert_eq!(t.decisions(0, 1).columns[0][0], 1.0);
        assert_eq!(t.end(), Point::new(&[-5, 5, 0]));
    }

    /// nextStep's printed test for moving x (octant 1/4/5/8 branch), with
    /// the current point throughout (its x1/y1 mix-up set aside): d = 1 +
    /// 2 incX x, B = x² + y² - r² + 1 + 2 incY y (the kept candidate's error).
    fn printed_moves_x(x: i64, y: i64, r_sq: i64, inc_x: i64, inc_y: i64) -> bool {
        let d = 1 + inc_x * 2 * x;
        let b = x * x + y * y - r_sq + 1 + inc_y * 2 * y;
        if inc_x * x > 0 {
            2 * d * b + d < 0
        } else {
            2 * d * b + d > 0
        }
    }

    /// floor_sqrt against the integer square root, at and beside every
    /// square where the f64 root is nearest an integer (small roots, and
    /// roots near 2^26 and 2^31, the largest), and at 2^62.
    #[test]
    fn floor_sqrt_is_the_integer_square_root() {
        let roots = (0..100_000u64)
            .chain((1 << 26) - 50_000..(1 << 26) + 50_000)
            .chain((1 << 31) - 100_000..=1 << 31);
        for y in roots {
            for t in [y * y, y * y + y, (y * y).wrapping_sub(1), y * y + 1] {
                if t <= 1 << 62 {
                    assert_eq!(floor_sqrt(t), t.isqrt(), "t = {t}");
                }
            }
        }
    }

    proptest::proptest! {
        #[test]
        fn floor_sqrt_matches_isqrt_anywhere(t in 0u64..=1 << 62) {
            proptest::prop_assert_eq!(floor_sqrt(t), t.isqrt());
        }
    }

    #[test]
    fn the_printed_next_step_test_inverts_eq_10() {
        // r = 5, at (5, 2) in octant 1 (incX = -1, incY = +1): the next row
        // y = 3 has (5, 3), error 9, and (4, 3), error 0. Eq. (7) moves x;
        // the printed test does not.
        assert!(!printed_moves_x(5, 2, 25, -1, 1));
        let t = trace(r#"{"algorithm":"circle","from":[5,0,0],"to":[0,5,0],"center":[0,0,0]}"#);
        assert_eq!(points(&t)[3], [4, 3, 0]);
        // And at (5, 0) -> y = 1 the printed test agrees only by luck:
        // (5, 1) error 1 is kept by both.
        assert!(!printed_moves_x(5, 0, 25, -1, 1));
        assert_eq!(points(&t)[1], [5, 1, 0]);
        // Where the kept cell is inside, the printed test moves x inward,
        // away from the circle: r = 9 from (9, 0) reaches (8, 3); row 4 has
        // (8, 4), error -1, and (7, 4), error -16. Eq. (7) keeps (8, 4).
        assert!(printed_moves_x(8, 3, 81, -1, 1));
        let t = trace(r#"{"algorithm":"circle","from":[9,0,0],"to":[0,9,0],"center":[0,0,0]}"#);
        assert_eq!(points(&t)[3..5], [[8, 3, 0], [8, 4, 0]]);
    }

    #[test]
    fn the_dry_run_stops_at_max_steps_and_counts_what_the_arc_needs() {
        // r = 2^20: a full circle is about 5.9 million steps; with maxSteps
        // 1000 nothing is recorded, and the error says how many it takes
        // (counted on by the dry run's leaps), which is the maxSteps that
        // traces it.
        let r = 1 << 20;
        let json = |max: &str| {
            format!(
                r#"{{"algorithm":"circle","from":[{r},0,0],"to":[{r},0,0],"center":[0,0,0]{max}}}"#
            )
        };
        let e = INFO
            .trace_json(&json(r#","maxSteps":1000"#), find_none)
            .err()
            .unwrap();
        assert_eq!(e.field_name(), Some("maxSteps"));
        let steps = trace(&json("")).steps();
        assert!(steps > 5_000_000);
        assert_eq!(e.limit.as_ref().map(|l| l.at_least), Some(steps), "{e}");
        assert!(
            e.to_string()
                .contains(&format!("(at least {steps}); raise maxSteps")),
            "{e}"
        );
        let exactly = json(&format!(r#","maxSteps":{steps}"#));
        assert_eq!(INFO.trace_json(&exactly, find_none).unwrap().steps(), steps);
    }
}
