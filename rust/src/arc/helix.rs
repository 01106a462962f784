//! Helices: an arc in the plane while the normal (linear) axis travels.
//!
//! method = saleem (Saleem & Saleem 2004, section 5): a helix is a 2D line
//! between two "axes", the arc and the linear axis. A dry run of the circle
//! counts the arc's steps n_c; n_z = |Δ linear axis|. A Bresenham line
//! between n_c and n_z then decides, per iteration, whether the arc takes
//! its next step (Saleem's circle rule) and whether the linear axis steps.
//!
//! method = segments: the arc-segments method with the height interpolated
//! along with the angle, each chord a 3D line; as Grbl and most controllers
//! do. One id with a method option, rather than two ids, because both take the
//! same helix and are measured against the same ideal helix: switching the
//! method is exactly the comparison a learner wants.
//!
//! Saleem's linear axis advances evenly per arc step, not per degree. The
//! circle takes 0.9003 r steps per radian on average (4 sqrt(2) r per turn),
//! but in octant 1 it has taken r sin θ steps at angle θ, which leads or
//! lags 0.9003 r θ by up to 0.0298 r (at θ = 25.8°; the other octants
//! mirror it). That spread of 0.0596 r is 0.0596 / (2π × 0.9003) = 1.05% of a
//! turn, so at a given angle the height differs from the true helix's by up
//! to 1.05% of one turn's rise (0.53% for arcs from axis to axis), plus the
//! height of two arc steps (rise / n_c each: one for the run of linear steps
//! taken at one arc position, one because the discrete circle's count at an
//! angle differs from the continuous r sin θ by up to a step) and half a
//! linear step.
//! Method segments interpolates by angle and has no such drift.

use super::arc_segments::{LINE_ALGORITHM, SEGMENT_LENGTH, TOLERANCE, plan_chords, trace_chords};
use super::circle_saleem::{CIRCLE_COLUMNS, CircleWhy, SaleemCircle};
use super::{ArcSpec, CENTER, DIR, PLANE, TURNS};
use crate::algorithm_info::{AlgorithmInfo, Example, Family, Find};
use crate::error::Error;
use crate::figure::{DecisionFigure, FigureKind};
use crate::grid::{AXIS_NAMES, Point, Step, written_steps, written_steps_mut};
use crate::ideal::IdealPath;
use crate::ideal::curve::HelixPath;
use crate::line::step_target;
use crate::line::terms::Term;
use crate::plan::Plan;
use crate::request::{
    AppliesWith, FROM, MAX_STEPS, MAX_STEPS_LIMIT, OptionKind, OptionSpec, Request, TO, TiePolicy,
};
use crate::trace::{
    Column, ColumnKind, Decision, Filled, Stepper, Trace, TraceBuilder, concat_columns,
    path_too_long,
};
use std::fmt::Write;
use std::mem::MaybeUninit;

pub const ID: &str = "helix";

pub const METHOD: OptionSpec = OptionSpec {
    name: "method",
    kind: OptionKind::Choice {
        values: &["saleem", "segments"],
    },
    required: false,
    default: Some("saleem"),
    applies_with: None,
    doc: "saleem: the arc's steps against the linear axis as a 2D Bresenham line (Saleem section 5); segments: chords with the height interpolated by angle, each stepped by lineAlgorithm.",
};

/// Where arc-segments' chord options apply to the helix: with its method
/// segments (Saleem's method has no chords; given with it, each is refused).
const WITH_CHORDS: Option<AppliesWith> = Some(AppliesWith {
    option: METHOD.name,
    value: "segments",
});

/// arc-segments' chord options, as the helix takes them (WITH_CHORDS).
const CHORD_SEGMENT_LENGTH: OptionSpec = OptionSpec {
    applies_with: WITH_CHORDS,
    ..SEGMENT_LENGTH
};
const CHORD_TOLERANCE: OptionSpec = OptionSpec {
    applies_with: WITH_CHORDS,
    ..TOLERANCE
};
const CHORD_LINE_ALGORITHM: OptionSpec = OptionSpec {
    applies_with: WITH_CHORDS,
    ..LINE_ALGORITHM
};

pub const HELIX_TIE: OptionSpec = OptionSpec {
    name: "tie",
    kind: OptionKind::Choice {
        values: &["advance", "hold"],
    },
    required: false,
    default: None,
    applies_with: None,
    doc: "method saleem: what an error exactly at its threshold does (default hold, Saleem's strict >); method segments: passed to the line algorithm.",
};

pub const INFO: AlgorithmInfo = AlgorithmInfo {
    id: ID,
    example: Example {
        options: r#"{"from": [10, 0, 0], "to": [10, 0, 24], "center": [0, 0, 0], "dir": "ccw", "plane": "xy"}"#,
        why: "One full turn of radius 10 rising 24 units.",
    },
    family: Family::Arc,
    title: "Helix (arc plus linear axis)",
    citation: "Saleem & Saleem (2004), Bresenham type fast algorithm for 3-D linear and helical movement in CNC machines, section 5 (method saleem); chords as in arc-segments (method segments)",
    teaching: "A helix is a circle in the plane while the linear (normal) axis travels. Saleem treats it as a 2D line between two axes: the arc, which needs n_c steps (counted by a dry run of the circle, the paper's dummy procedure), and the linear axis, which needs n_z. The larger one steps every iteration; the smaller one keeps a Bresenham error, adding 2 × its count each iteration and stepping when the error exceeds the larger count (then subtracting 2 × the larger count). The linear axis thus advances evenly per arc step, not per degree: the circle takes up to sqrt(2) times more steps per degree near the axes than near the diagonals (its fast axis moves r cos θ per radian), so at a given angle the height differs from the true helix's by up to about 1% of a turn's rise (1.05%: the arc's step count runs from 0.0298 r ahead of an even rate to 0.0298 r behind it; about half that for an arc that starts on an axis: the largest of sin θ/(4 sqrt 2) - θ/2π, 0.0053 of a turn). Method segments, as most controllers do, cuts the helix into chords with the height interpolated by angle.",
    errata: &[
        "The helical() pseudo-code has no loop: the body under `if(nz > nc)` and `else` runs once. voxpath iterates max(n_c, n_z) times.",
        "helical() calls nextStep(currentX, currentY, r) with currentX and currentY never declared or set; they are the arc's current point relative to the center (eq. 12-13).",
        "The circle's own errata apply to its steps (see circle).",
    ],
    columns: HelixWhy::COLUMNS,
    options: &[
        FROM,
        TO,
        CENTER,
        DIR,
        PLANE,
        TURNS,
        METHOD,
        HELIX_TIE,
        CHORD_SEGMENT_LENGTH,
        CHORD_TOLERANCE,
        CHORD_LINE_ALGORITHM,
        MAX_STEPS,
    ],
    min_dims: 3,
    max_dims: 3,
    default_tie: Some(TiePolicy::Hold),
    compared_by: Some(METHOD.name),
    trace: trace_helix,
    plan: Some(plan_helix),
};

fn trace_helix(req: &Request, find: Find) -> Result<Trace, Error> {
    let spec = ArcSpec::of_request(req, &INFO, true)?;
    // The chord options given with method saleem were refused by
    // check_options (WITH_CHORDS).
    if req.choice(&METHOD)? == Some("segments") {
        return trace_chords(ID, req, &spec, true, find);
    }
    let tie = req.tie(TiePolicy::Hold)?;
    let mut builder = TraceBuilder::for_request(spec.from, req)?;
    let helix = saleem_helix(&spec, tie, builder.max_steps())?;
    let ideal = HelixPath::new(spec.ideal_arc(), 0.0, spec.rise as f64);
    builder.run(helix, IdealPath::Helix(ideal))?;
    Ok(builder.finish(ID))
}

/// The helix of `spec` by Saleem's rule, refused when it takes more than
/// `max_steps`: its trace's and its plan's.
fn saleem_helix(spec: &ArcSpec, tie: TiePolicy, max_steps: u64) -> Result<SaleemHelix, Error> {
    // The helix takes max(n_c, n_z) steps: a rise past maxSteps is refused
    // before it is traced, told the count that traces it, as a circle is.
    let n_z = spec.rise.unsigned_abs();
    if n_z > max_steps {
        return Err(path_too_long(max_steps, steps_past_rise(spec, n_z)));
    }
    let circle = SaleemCircle::new(spec).counted(max_steps)?;
    let helix = SaleemHelix::new(spec, circle, tie);
    if helix.remaining > max_steps {
        return Err(path_too_long(max_steps, helix.remaining));
    }
    Ok(helix)
}

/// The helix planned ([`crate::plan`]), as [`trace_helix`] would
/// trace it: its steps, max(n_c, n_z), known once its circle's dry run
/// has counted n_c, and it ends at its end point. Its chords (method
/// segments) as [`plan_chords`] plans them.
fn plan_helix(req: &Request, find: Find) -> Result<Option<Plan>, Error> {
    let spec = ArcSpec::of_request(req, &INFO, true)?;
    if req.choice(&METHOD)? == Some("segments") {
        return plan_chords(req, &spec, true, find);
    }
    let tie = req.tie(TiePolicy::Hold)?;
    let max_steps = req.max_steps()?;
    let helix = saleem_helix(&spec, tie, max_steps)?;
    Ok(Plan::of_stepper(spec.from, spec.to, helix, max_steps))
}

/// The steps of a helix whose rise `n_z` passes maxSteps, as its refusal
/// tells them: max(n_c, n_z), n_c from the circle's dry run up to the
/// largest maxSteps (a turn or two however many turns it makes:
/// [`SaleemCircle::counted`]), so that maxSteps set to it traces the helix.
/// Told the rise alone, r = 1000 with 10 extra turns rising 1000 was
/// "at least 1000", and refused again at that maxSteps (it takes 62,216). Past the largest
/// maxSteps no maxSteps traces it, and the count is a bound under it: the
/// rise, when it passes it, the circle not counted; else the circle's own
/// refusal's (its full turns' bound, or one past the largest maxSteps).
fn steps_past_rise(spec: &ArcSpec, n_z: u64) -> u64 {
    if n_z > MAX_STEPS_LIMIT {
        return n_z;
    }
    match SaleemCircle::new(spec).counted(MAX_STEPS_LIMIT) {
        Ok(circle) => circle
            .remaining_steps()
            .expect("the circle's steps are counted by the dry run")
            .max(n_z),
        Err(refused) => {
            refused
                .limit
                .expect("a circle is refused only for maxSteps")
                .at_least
        }
    }
}

/// Which of the two "axes" of Saleem's helix line steps every iteration.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Major {
    /// n_c >= n_z: the arc steps every time (the paper's `else` branch).
    Arc,
    /// n_z > n_c: the linear axis steps every time.
    Linear,
}

pub const MAJOR_LABELS: &[&str] = &["arc", "linear"];

/// Why one step of the helix was taken.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HelixWhy {
    /// The circle's decision, when the arc stepped.
    pub arc: Option<CircleWhy>,
    pub major: Major,
    /// The minor axis's Bresenham error after adding 2 × its count: the
    /// paper's errorZ (arc major) or errorCircle (linear major).
    pub error: i64,
    pub minor_steps: bool,
    pub tie: bool,
    tie_policy: TiePolicy,
    n_c: u64,
    n_z: u64,
    normal: usize,
}

impl Decision for HelixWhy {
    /// The circle's, for the arc's decision, then the helix's own.
    const COLUMNS: &'static [Column] = &concat_columns::<7, 5, 12>(
        CIRCLE_COLUMNS,
        [
            // Not "major": bresenham3d's column of that name holds an axis, and a
            // G-code program's trace unions the columns of its line and arc
            // algorithms by name.
            Column::new(
                "helixMajor",
                ColumnKind::Category { labels: MAJOR_LABELS },
                "Which steps every iteration: the arc (n_c >= n_z) or the linear axis (n_z > n_c) (Saleem section 5).",
            )
            .formerly("helix_major"),
            Column::new(
                "helixError",
                ColumnKind::Int,
                "The minor axis's Bresenham error after adding 2 × its count (errorZ or errorCircle); the minor axis steps when it exceeds the major count.",
            )
            .formerly("helix_error"),
            Column::new(
                "arcSteps",
                ColumnKind::Flag,
                "1 when the arc took a step (the circle columns then hold its decision).",
            )
            .formerly("arc_steps"),
            Column::new(
                "linearSteps",
                ColumnKind::Flag,
                "1 when the linear (normal) axis stepped.",
            )
            .formerly("linear_steps"),
            Column::new(
                "helixTie",
                ColumnKind::Flag,
                "1 when the helix error equalled the major count and the tie policy decided.",
            )
            .formerly("helix_tie"),
        ],
    );

    fn write(&self, row: &mut [f64]) {
        let circle = CircleWhy::COLUMNS.len();
        match self.arc {
            Some(arc) => arc.write(&mut row[..circle]),
            None => row[..circle].fill(f64::NAN),
        }
        let helix = &mut row[circle..];
        helix[0] = self.major as u8 as f64;
        helix[1] = self.error as f64;
        helix[2] = self.arc.is_some() as u8 as f64;
        let linear = self.major == Major::Linear || self.minor_steps;
        helix[3] = linear as u8 as f64;
        helix[4] = self.tie as u8 as f64;
    }

    fn is_tie(&self) -> bool {
        self.tie
    }

    /// The circle's, where the arc stepped.
    const FIGURE: Option<FigureKind> = CircleWhy::FIGURE;

    fn figure(&self, from: &Point, step: Step) -> Option<DecisionFigure> {
        self.arc?.figure(from, step)
    }

    fn explain(&self, from: &Point, step: Step) -> String {
        let z = AXIS_NAMES[self.normal];
        let (major_count, minor, minor_count) = match self.major {
            Major::Arc => (
                format!("n_c = {} >= n_z = {}", self.n_c, self.n_z),
                "the linear axis",
                self.n_c,
            ),
            Major::Linear => (
                format!("n_z = {} > n_c = {}", self.n_z, self.n_c),
                "the arc",
                self.n_z,
            ),
        };
        let major_name = match self.major {
            Major::Arc => "the arc".to_string(),
            Major::Linear => z.to_string(),
        };
        let mut s = format!(
            "{major_count}, so {major_name} steps every time; {minor}'s error is {} {} {minor_count}",
            self.error,
            match self.error.cmp(&(minor_count as i64)) {
                std::cmp::Ordering::Greater => ">",
                std::cmp::Ordering::Equal => "=",
                std::cmp::Ordering::Less => "<",
            },
        );
        if self.tie {
            let _ = write!(s, " (a tie, decided by '{}')", self.tie_policy.label());
        }
        let _ = write!(
            s,
            ", so {minor} {}",
            if self.minor_steps {
                "steps too"
            } else {
                "waits"
            }
        );
        match self.arc {
            Some(arc) => {
                let _ = write!(s, ". Arc: {}", arc.explain(from, step));
            }
            None => {
                let _ = write!(s, ": {}.", step_target(step, 3));
            }
        }
        s
    }
}

/// Saleem's helix: a Bresenham line between the arc's n_c steps and the
/// linear axis's n_z.
#[derive(Clone, Debug)]
pub struct SaleemHelix {
    circle: SaleemCircle,
    n_c: u64,
    n_z: u64,
    normal: usize,
    /// Direction of the linear axis: the paper's incZ.
    normal_dir: i64,
    major: Major,
    /// The minor axis's Bresenham rule as a [`Term`]: its value is the
    /// error term (errorZ or errorCircle, starting at 0) after adding twice
    /// the minor count, the value the next iteration compares with the
    /// major count. Stays within (-major count - 1, 3 × major count], so
    /// i64 holds it.
    line: Term,
    remaining: u64,
    tie: TiePolicy,
}

impl SaleemHelix {
    /// `circle` has been counted (its remaining steps are n_c).
    pub fn new(spec: &ArcSpec, circle: SaleemCircle, tie: TiePolicy) -> SaleemHelix {
        let n_c = circle
            .remaining_steps()
            .expect("the circle's steps are counted by the dry run first");
        let n_z = spec.rise.unsigned_abs();
        let major = if n_z > n_c { Major::Linear } else { Major::Arc };
        let (major_count, minor_count) = match major {
            Major::Arc => (n_c as i64, n_z as i64),
            Major::Linear => (n_z as i64, n_c as i64),
        };
        // The major axis steps every iteration; the minor one adds twice its
        // count and steps when that exceeds the major count (section 3's
        // 2D rule with n_c and n_z for the deltas), or equals it with ties
        // advancing; then twice the major count comes off.
        let line = Term {
            value: 2 * minor_count,
            increment: 2 * minor_count,
            decrement: 2 * major_count,
            steps_above: Term::steps_above(major_count, tie),
            // Unused: the helix reads the term's mask (the minor "axis" may
            // be the arc).
            step: Step::NONE,
        };
        SaleemHelix {
            circle,
            n_c,
            n_z,
            normal: spec.plane.normal(),
            normal_dir: spec.rise.signum(),
            major,
            line,
            remaining: n_c.max(n_z),
            tie,
        }
    }

    /// The count of the axis that steps every iteration: the minor
    /// axis's error equal to it is a tie.
    fn major_count(&self) -> i64 {
        match self.major {
            Major::Arc => self.n_c as i64,
            Major::Linear => self.n_z as i64,
        }
    }

    fn arc_step(&mut self) -> (Step, CircleWhy) {
        // A Bresenham line between n_c and n_z takes exactly n_c arc steps,
        // all of which the dry run counted.
        self.circle
            .next_step()
            .expect("the arc has n_c steps, as the dry run counted")
    }
}

// SAFETY: its fill's Filled counts the slots it wrote (see its Filled::written).
unsafe impl Stepper for SaleemHelix {
    type Why = HelixWhy;

    fn next_step(&mut self) -> Option<(Step, HelixWhy)> {
        if self.remaining == 0 {
            return None;
        }
        self.remaining -= 1;
        let error = self.line.value;
        let tie = error == self.major_count();
        let mut value = error;
        let minor_steps = self.line.advance_mask(&mut value) != 0;
        self.line.value = value;
        let arc_moves = self.major == Major::Arc || minor_steps;
        let linear_moves = self.major == Major::Linear || minor_steps;
        let (mut step, arc) = if arc_moves {
            let (step, why) = self.arc_step();
            (step, Some(why))
        } else {
            (Step::NONE, None)
        };
        if linear_moves {
            step = step.with(self.normal, self.normal_dir);
        }
        let why = HelixWhy {
            arc,
            major: self.major,
            error,
            minor_steps,
            tie,
            tie_policy: self.tie,
            n_c: self.n_c,
            n_z: self.n_z,
            normal: self.normal,
        };
        Some((step, why))
    }

    /// The same iterations as [`Stepper::next_step`], without decisions:
    /// when the linear axis leads and the arc steps in at most every other
    /// iteration, the linear step in every slot and the arc's steps from
    /// the circle's own fill put in where the line's term steps
    /// ([`Term::each_step_seldom`]); when it leads and the arc steps more
    /// often, the circle's recording loop ([`SaleemCircle::weave_fill`])
    /// with the line's term woven in; when the arc leads,
    /// the circle's own fill (its stretches known in closed form stepped
    /// in pieces side by side) and the line's steps put in after
    /// ([`Term::or_steps_into`]); the circle's few correction steps by its
    /// `next_step`. The displacement: where the
    /// arc's point moved, and on the linear axis every iteration (linear
    /// major) or as often as the term says its minor axis stepped.
    fn fill(&mut self, out: &mut [MaybeUninit<Step>]) -> Filled {
        let taken = out.len().min(self.remaining as usize);
        let out = &mut out[..taken];
        let before = self.circle.local();
        let linear = Step::NONE.with(self.normal, self.normal_dir).0;
        let line = self.line;
        let mut value = line.value;
        match self.major {
            // The arc steps every iteration: the circle's own fill, then
            // the linear axis's few steps put in by jumps (in wasm, its
            // term woven into the circle's loop slowed it by a fifth).
            Major::Arc => {
                let arc = self.circle.fill(out);
                assert_eq!(arc.steps(), taken, "the arc steps every iteration");
                // SAFETY: the circle's fill wrote all `taken` slots.
                let out = unsafe { written_steps_mut(out) };
                line.or_steps_into(&mut value, out, linear);
            }
            // The linear axis steps every iteration and the arc seldom (at
            // most every other one): every slot the linear step, the arc's
            // steps made by the circle's own fill and put in where the
            // term's jumps say. Woven into the circle's loop, an iteration
            // at a time, such a helix stepped about a third as fast as one
            // whose arc leads (r = 300,000 rising 5,000,000: 700 M steps/s
            // natively against 2,300 M).
            Major::Linear if line.steps_seldom() => {
                out.fill(MaybeUninit::new(Step(linear)));
                // SAFETY: every slot was just written.
                let out = unsafe { written_steps_mut(out) };
                for block in out.chunks_mut(SELDOM_ARC_BLOCK) {
                    let mut at = [0u16; SELDOM_ARC_BLOCK / 2];
                    let mut arc_steps = 0;
                    line.each_step_seldom(&mut value, block.len(), |index| {
                        at[arc_steps] = index as u16;
                        arc_steps += 1;
                    });
                    let mut arc = [MaybeUninit::uninit(); SELDOM_ARC_BLOCK / 2];
                    let filled = self.circle.fill(&mut arc[..arc_steps]);
                    assert_eq!(filled.steps(), arc_steps, "the arc has n_c steps");
                    // SAFETY: the circle's fill wrote the `arc_steps` slots.
                    let arc = unsafe { written_steps(&arc[..arc_steps]) };
                    for (&index, step) in at[..arc_steps].iter().zip(arc) {
                        block[index as usize].0 |= step.0;
                    }
                }
            }
            Major::Linear => weave(&mut self.circle, out, || {
                (line.advance_mask(&mut value) != 0, linear)
            }),
        }
        self.line.value = value;
        self.remaining -= taken as u64;
        let after = self.circle.local();
        let mut displacement = self
            .circle
            .frame()
            .displacement([after[0] - before[0], after[1] - before[1]]);
        let linear_steps = match self.major {
            Major::Arc => line.moves(taken as u64, value),
            Major::Linear => taken as i64,
        };
        displacement[self.normal] = self.normal_dir * linear_steps;
        // SAFETY: each way above writes all `taken` slots of `out`: the
        // circle's fill (its count asserted), the linear step in every
        // slot, or `weave`, which runs until every slot is written.
        unsafe { Filled::written(taken, displacement) }
    }

    /// A tie is the line's error equal to the major count, whatever the
    /// circle does: counted from the term in closed form
    /// ([`Term::values_equal`]), with no step of the circle (replaying the
    /// helix for its ties took a fifth of its metrics' time).
    fn ties_ahead(self, steps: u64) -> u64 {
        self.line
            .values_equal(self.major_count(), steps.min(self.remaining))
    }

    fn remaining_steps(&self) -> Option<u64> {
        Some(self.remaining)
    }

    fn setup_note(&self) -> String {
        let z = AXIS_NAMES[self.normal];
        format!(
            "Dry run (the paper's dummy procedure): the arc takes n_c = {} steps; the linear axis {z} needs n_z = {}. {} major: {} steps every iteration, {} iterations in all. The arc, projected on the plane of the start: {}",
            self.n_c,
            self.n_z,
            MAJOR_LABELS[self.major as usize],
            match self.major {
                Major::Arc => "the arc".to_string(),
                Major::Linear => z.to_string(),
            },
            self.n_c.max(self.n_z),
            self.circle.setup_note(),
        )
    }
}

/// Iterations of a helix whose arc steps seldom taken at a time: the arc
/// steps in at most half of them (two arrays of half as many on the stack).
const SELDOM_ARC_BLOCK: usize = 4096;

/// `out.len()` iterations of a helix: `weave` says whether the arc steps
/// and gives the linear axis's bits; the arc steps by the circle's
/// recording loop, or by its `next_step` once the circle part is over.
#[inline(always)]
fn weave(
    circle: &mut SaleemCircle,
    out: &mut [MaybeUninit<Step>],
    mut weave: impl FnMut() -> (bool, u16),
) {
    let mut k = 0;
    while k < out.len() {
        if circle.in_circle_part() {
            k += circle.weave_fill(&mut out[k..], &mut weave);
        } else {
            let (arc, bits) = weave();
            let step = if arc {
                let (step, _) = circle
                    .next_step()
                    .expect("the arc has n_c steps, as the dry run counted");
                step
            } else {
                Step::NONE
            };
            out[k].write(Step(step.0 | bits));
            k += 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::arc::arc_segments::{self, find_regions};
    use crate::grid::SIGNED_AXIS_LABELS;
    use std::f64::consts::PI;

    fn points(t: &Trace) -> Vec<[i64; 3]> {
        t.points_flat(0, t.steps() + 1)
            .chunks(3)
            .map(|c| [c[0], c[1], c[2]])
            .collect()
    }

    #[test]
    fn quarter_turn_rising_two_by_hand() {
        // r = 3 quarter, CCW: the circle alone is (3,0) (3,1) (2,2) (1,3)
        // (0,3), so n_c = 4; n_z = 2. Arc major; errorZ += 4 each time and
        // z steps when it exceeds 4: 4 (a tie: Saleem's strict > holds),
        // 8 (yes, -> 0), 4 (tie, holds), 8 (yes).
        let t = INFO
            .trace_json(
                r#"{"algorithm":"helix","from":[3,0,0],"to":[0,3,2],"center":[0,0,0]}"#,
                find_regions,
            )
            .unwrap();
        assert_eq!(
            points(&t),
            [[3, 0, 0], [3, 1, 0], [2, 2, 1], [1, 3, 1], [0, 3, 2]]
        );
        let d = t.decisions(0, 4);
        assert_eq!(d.columns[8], [4.0, 8.0, 4.0, 8.0]);
        assert_eq!(d.columns[10], [0.0, 1.0, 0.0, 1.0]);
        // The arc's candidates, whatever z did: step 1 reaches (2, 2, 1)
        // having moved x (Saleem eq. 7: (2, 2) has 4 + 4 - 9 = -1, (3, 2)
        // has 4), so the other candidate is one cell toward +x, at z = 1.
        assert_eq!(
            [d.columns[2][1], d.columns[3][1], d.columns[4][1]],
            [4.0, -1.0, 1.0]
        );
        assert_eq!(SIGNED_AXIS_LABELS[d.columns[6][1] as usize], "+x");
        assert!(t.explain(0).starts_with(
            "n_c = 4 >= n_z = 2, so the arc steps every time; the linear axis's error is 4 = 4 (a tie, decided by 'hold'), so the linear axis waits. Arc: Octant 1:"
        ), "{}", t.explain(0));
        assert!(t.segment_note(0).contains("n_c = 4 steps"));
    }

    #[test]
    fn steep_helix_lets_the_linear_axis_lead() {
        // The same quarter with z falling 9: n_z = 9 > n_c = 4. errorCircle
        // += 8 and the arc steps when it exceeds 9: 8, 16 (-> -2), 6, 14
        // (-> -4), 4, 12 (-> -6), 2, 10 (-> -8), 0.
        let t = INFO
            .trace_json(
                r#"{"algorithm":"helix","from":[3,0,0],"to":[0,3,-9],"center":[0,0,0]}"#,
                find_regions,
            )
            .unwrap();
        let d = t.decisions(0, 9);
        assert_eq!(
            d.columns[8],
            [8.0, 16.0, 6.0, 14.0, 4.0, 12.0, 2.0, 10.0, 0.0]
        );
        assert_eq!(d.columns[9], [0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0]);
        // Step 0 moves z alone: the circle made no decision, so its octant,
        // fast axis, slow step, correction and other-candidate cells hold
        // NO_VALUE (not octant "1", axis "x", "no", "no", "+x") and its
        // residuals NaN.
        let none = f64::from(crate::trace::NO_VALUE);
        let circle: Vec<f64> = d.columns[..7].iter().map(|c| c[0]).collect();
        assert_eq!(
            [circle[0], circle[1], circle[4], circle[5], circle[6]],
            [none; 5]
        );
        assert!(circle[2].is_nan() && circle[3].is_nan());
        assert_eq!(t.end(), Point::new(&[0, 3, -9]));
        assert!(
            t.explain(0)
                .contains("n_z = 9 > n_c = 4, so z steps every time")
        );
    }

    #[test]
    fn segment_options_need_segments_mode() {
        // Each chord option, with the method left to its default (saleem)
        // and named: refused, naming the option.
        for (option, value, method) in [
            ("tolerance", "0.1", ""),
            ("segmentLength", "2", r#","method":"saleem""#),
            ("lineAlgorithm", r#""dda""#, ""),
        ] {
            let e = INFO
                .trace_json(
                    &format!(
                        r#"{{"algorithm":"helix","from":[3,0,0],"to":[0,3,2],"center":[0,0,0],"{option}":{value}{method}}}"#
                    ),
                    find_regions,
                )
                .err()
                .unwrap();
            assert_eq!(
                e.to_string(),
                format!("{option}: applies to method segments only")
            );
        }
        let t = INFO
            .trace_json(
                r#"{"algorithm":"helix","from":[30,0,0],"to":[0,30,20],"center":[0,0,0],"method":"segments","segmentLength":10}"#,
                find_regions,
            )
            .unwrap();
        // floor(15π / 10) = 4 chords, heights 5, 10, 15 then 20.
        assert_eq!(t.segment_count(), 4);
        let starts: Vec<i64> = t.segments().map(|s| s.start.get(2)).collect();
        assert_eq!(starts, [0, 5, 10, 15]);
        assert!(matches!(t.segment(0).ideal, IdealPath::Helix(_)));
    }

    /// The teaching's numbers for the drift of Saleem's height against the
    /// angle: r sin θ - (2 sqrt 2 / π) r θ peaks at 0.02982 r (θ = 25.8°),
    /// 0.0053 of a turn of 4 sqrt 2 r steps. It said 0.0296 r. Found by a
    /// helper's hunt recomputing the teaching's numbers.
    #[test]
    fn the_teaching_states_the_height_drift_it_computes() {
        let rate = 2.0 * 2f64.sqrt() / PI;
        let (mut peak, mut at) = (0f64, 0f64);
        for i in 0..=1_000_000 {
            let theta = PI / 4.0 * f64::from(i) / 1e6;
            let lead = theta.sin() - rate * theta;
            if lead > peak {
                (peak, at) = (lead, theta);
            }
        }
        let teaching = INFO.teaching;
        assert!(
            teaching.contains(&format!(
                "{peak:.4} r ahead of an even rate to {peak:.4} r behind"
            )),
            "{peak}"
        );
        assert!(
            teaching.contains(&format!("{:.2}%", 200.0 * peak / (4.0 * 2f64.sqrt()))),
            "{teaching}"
        );
        assert!(teaching.contains(&format!("{:.4} of a turn", peak / (4.0 * 2f64.sqrt()))));
        assert!((at.to_degrees() - 25.8).abs() < 0.05, "{}", at.to_degrees());
    }

    /// Method segments measures every point against the helix, as method
    /// saleem does, not against its own chord's stretch of it alone: point
    /// 66 of this helix, a rounded vertex (-177, -166, -7), is 0.111 from
    /// the helix but was 0.704 from the stretch of the chord it starts
    /// (measured to that stretch's start). Found by recomputing the
    /// distance to the helix by sampling, outside voxpath.
    #[test]
    fn chords_measure_their_points_against_the_whole_helix() {
        let json = r#"{"algorithm":"helix","from":[-111,-202,-6],"to":[-129,172,-13],"center":[-50,-12,-6],"dir":"cw","method":"segments","segmentLength":2}"#;
        let t = INFO.trace_json(json, find_regions).unwrap();
        let spec = ArcSpec::parse(&Request::from_json(json).unwrap(), true, 3).unwrap();
        let whole = HelixPath::new(spec.ideal_arc(), 0.0, spec.rise as f64);
        let deviation = t.deviation_range(0, t.steps() + 1);
        let mut worst = 0f64;
        for (k, p) in points(&t).into_iter().enumerate() {
            let want = whole.deviation(&Point::new(&p));
            worst = worst.max((deviation[k] - want).abs());
        }
        assert!(worst < 1e-9, "off the whole helix's distance by {worst}");
        assert_eq!(points(&t)[66], [-177, -166, -7]);
        assert!((deviation[66] - 0.1113).abs() < 1e-4, "{}", deviation[66]);
        let max = deviation.iter().copied().fold(0.0, f64::max);
        assert_eq!(t.metrics().max_deviation, max);
    }

    /// A full circle whose rule counts 1 chord (floor(2π 10 / 1000) = 0,
    /// at least 1) is a triangle of chords around the center, ending on the
    /// start: near the origin, touching 2^30 - 1 and -(2^30 - 1), drawn by
    /// arc-segments and by helix's method segments alike.
    #[test]
    fn a_full_circle_takes_at_least_three_chords() {
        let edge = (1i64 << 30) - 1;
        for (from, center) in [
            ([10, 0, 0], [0, 0, 0]),
            ([edge, edge - 10, 5], [edge - 10, edge - 10, 5]),
            ([-edge, -edge + 10, -edge], [-edge + 10, -edge + 10, -edge]),
        ] {
            for (info, algorithm) in [
                (&arc_segments::INFO, r#""arc-segments""#),
                (&INFO, r#""helix","method":"segments""#),
            ] {
                let t = info
                    .trace_json(
                        &format!(
                            r#"{{"algorithm":{algorithm},"from":{from:?},"to":{from:?},"center":{center:?},"segmentLength":1000}}"#
                        ),
                        find_regions,
                    )
                    .unwrap();
                assert_eq!(
                    t.segment_count(),
                    arc_segments::MIN_FULL_CIRCLE_CHORDS as usize,
                    "{algorithm} {from:?}"
                );
                assert_eq!(t.end(), Point::new(&from));
                // Three chords of a circle of radius 10 (each 17.3 long, the
                // longest axis at least 10 after rounding) take at least 30 steps.
                assert!(t.steps() >= 30, "{algorithm} {from:?}: {} steps", t.steps());
                let note = t.segment_note(0);
                assert!(
                    note.contains(
                        "gives 1 chord, raised to 3, the fewest that go around a full circle"
                    ),
                    "{note}"
                );
                // Every point is within the chord bound of the circle.
                let bound = 10.0 * (1.0 - (PI / 3.0).cos()) + 2f64.sqrt();
                assert!(
                    t.metrics().max_deviation <= bound,
                    "{}",
                    t.metrics().max_deviation
                );
            }
        }
    }
}
