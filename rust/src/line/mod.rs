//! Line algorithms: each turns a straight move between two grid points into
//! single steps. One file per algorithm; the pieces they share live here:
//! mirroring of negative directions, Wang's GCD reduction, the order in which
//! tied axes go, and the finish rule of the algorithms that can drift.

/// The columns of a move of `$dims` axes, for a decision type `$why` whose
/// [`Decision::COLUMNS`](crate::trace::Decision::COLUMNS) (the catalogue's
/// six-axis list) holds one column per axis from index `$first`: those of
/// the axes the move has, with the columns before and after them, so that a
/// trace carries no column its steps never fill (a 3-axis greedy line had
/// distSqA to distSqC, empty at every step). One list per axis count, made
/// at compile time; defined before the modules so that they can use it.
macro_rules! columns_of_axes {
    ($why:ty, $first:expr, $dims:expr) => {{
        use crate::line::without_axes_past;
        use crate::trace::{Column, Decision};
        const ALL: &[Column] = <$why as Decision>::COLUMNS;
        const BY_DIMS: [&[Column]; crate::grid::MAX_AXES] = [
            &without_axes_past::<{ ALL.len() - 5 }>(ALL, $first),
            &without_axes_past::<{ ALL.len() - 4 }>(ALL, $first),
            &without_axes_past::<{ ALL.len() - 3 }>(ALL, $first),
            &without_axes_past::<{ ALL.len() - 2 }>(ALL, $first),
            &without_axes_past::<{ ALL.len() - 1 }>(ALL, $first),
            &without_axes_past::<{ ALL.len() }>(ALL, $first),
        ];
        BY_DIMS[$dims - 1]
    }};
}

pub mod bresenham2d;
pub mod bresenham3d;
pub mod dda;
pub mod greedy;
pub mod line_stepper;
pub mod liu_float;
pub mod nd;
pub mod regions_wang;
pub mod terms;
pub mod walk6;

use crate::algorithm_info::AlgorithmInfo;
use crate::error::Error;
use crate::grid::{AXIS_NAMES, MAX_AXES, Point, Step, gcd};
use crate::ideal::IdealPath;
use crate::plan::Plan;
use crate::request::{OptionKind, OptionSpec, Request, TiePolicy};
use crate::trace::{Column, DeviationBound, Stepper, Trace, TraceBuilder};
use std::cmp::Ordering;

/// What is done with a line algorithm's stepper once its request's own
/// options are read: recorded into a trace ([`Record`]) or planned
/// ([`PlanLine`]). Each line algorithm reads its options and makes its
/// stepper once, in one function generic over this, that its `trace` and
/// its `plan` both call.
pub trait LineRun: Sized {
    type Out;

    /// What is done with `stepper`, made for the line `ends` (from, to)
    /// of `info`'s algorithm once the request's checks have passed.
    fn take<S: Stepper>(
        self,
        info: &AlgorithmInfo,
        req: &Request,
        ends: (Point, Point),
        stepper: S,
    ) -> Result<Self::Out, Error>;

    /// Runs the stepper `make` builds from the request's endpoints and tie
    /// policy, after the checks every line algorithm shares.
    fn run<S: Stepper>(
        self,
        info: &AlgorithmInfo,
        req: &Request,
        make: impl FnOnce(Point, Point, TiePolicy) -> S,
    ) -> Result<Self::Out, Error> {
        req.check_options(info.options)?;
        let (from, to) = req.endpoints(info.min_dims, info.max_dims)?;
        let tie = req.tie(info.default_tie.unwrap_or(TiePolicy::Advance))?;
        self.take(info, req, (from, to), make(from, to, tie))
    }
}

/// The line recorded: the shape every line algorithm's trace shares.
pub struct Record;

impl LineRun for Record {
    type Out = Trace;
    fn take<S: Stepper>(
        self,
        info: &AlgorithmInfo,
        req: &Request,
        (from, to): (Point, Point),
        stepper: S,
    ) -> Result<Trace, Error> {
        let mut builder = TraceBuilder::for_request(from, req)?;
        let bound = stepper.deviation_bound();
        builder.run(stepper, IdealPath::Line { from, to })?;
        Ok(builder.finish(info.id).with_deviation_bound(bound))
    }
}

/// The line planned ([`crate::plan`]), as [`Record`] would record it: its
/// stepper counts its steps, and a line ends at its end point.
pub struct PlanLine;

impl LineRun for PlanLine {
    type Out = Option<Plan>;
    fn take<S: Stepper>(
        self,
        _: &AlgorithmInfo,
        req: &Request,
        (from, to): (Point, Point),
        stepper: S,
    ) -> Result<Option<Plan>, Error> {
        Ok(Plan::of_stepper(from, to, stepper, req.max_steps()?))
    }
}

/// The first `N` columns of `all` once the per-axis columns
/// `all[first..first + MAX_AXES]` of the axes past the move's are left out
/// (`all.len() - N` of them): see `columns_of_axes!`.
pub const fn without_axes_past<const N: usize>(all: &[Column], first: usize) -> [Column; N] {
    let absent = all.len() - N;
    let after_axes = first + MAX_AXES - absent;
    let mut out = [all[0]; N];
    let mut i = 0;
    while i < N {
        out[i] = all[if i < after_axes { i } else { i + absent }];
        i += 1;
    }
    out
}

/// The bound of the rules that keep every passive coordinate within half a
/// cell of the ideal line's at the same active position (Wang section 3.2;
/// Bresenham's, in 2D): with P passive axes a point is then within √P / 2 of
/// the line, √2 / 2 for Wang's 3D lines (his maximum theoretical error,
/// section 3.2 and Figure 8).
pub fn half_cell_per_passive_axis(mirror: &Mirror) -> DeviationBound {
    let passive = (0..mirror.dims()).filter(|&a| !mirror.is_active(a)).count();
    DeviationBound {
        value: (passive as f64).sqrt() / 2.0,
        why: match passive {
            0 => {
                "every axis moves as far as the longest, so every point is on the line".to_string()
            }
            1 => "the one passive axis stays within 1/2 cell of the line at each active position"
                .to_string(),
            p => format!(
                "each of the {p} passive axes stays within 1/2 cell of the line at each active position, so a point is within √{p}/2 of it"
            ),
        },
    }
}

/// A move seen along its direction of travel. The documents derive their
/// rules for positive directions only ("intrinsic symmetry", Wang section
/// 2.2; "other octants", Saleem section 2): every algorithm here runs those
/// rules on |Δ| and then steps each axis toward the end point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Mirror {
    from: Point,
    /// Direction of travel per axis (+1 for an axis that does not move).
    sign: [i64; MAX_AXES],
    /// |Δ| per axis, grid units (at most 2^31).
    magnitude: [i64; MAX_AXES],
}

impl Mirror {
    pub fn new(from: Point, to: Point) -> Mirror {
        let delta = from.delta_to(&to);
        let mut sign = [1; MAX_AXES];
        let mut magnitude = [0; MAX_AXES];
        for axis in 0..from.dims() {
            sign[axis] = if delta[axis] < 0 { -1 } else { 1 };
            magnitude[axis] = delta[axis].abs();
        }
        Mirror {
            from,
            sign,
            magnitude,
        }
    }

    pub fn dims(&self) -> usize {
        self.from.dims()
    }

    pub fn sign(&self, axis: usize) -> i64 {
        self.sign[axis]
    }

    /// |Δ| of `axis`, grid units.
    pub fn magnitude(&self, axis: usize) -> i64 {
        self.magnitude[axis]
    }

    /// The largest |Δ|: the step count of every one-step-per-active-unit rule.
    pub fn longest(&self) -> i64 {
        self.magnitude[..self.dims()]
            .iter()
            .copied()
            .max()
            .unwrap_or(0)
    }

    /// Sum of |Δ|: the step count of every one-axis-per-step rule.
    pub fn total(&self) -> u64 {
        self.magnitude[..self.dims()].iter().sum::<i64>() as u64
    }

    /// The lowest-index axis with the largest |Δ| (the documents' "x" when
    /// two axes share the largest distance).
    pub fn major(&self) -> usize {
        let longest = self.longest();
        (0..self.dims())
            .find(|&a| self.magnitude[a] == longest)
            .unwrap_or(0)
    }

    /// True when `axis` moves as far as any axis (Wang's "active" axes).
    pub fn is_active(&self, axis: usize) -> bool {
        self.magnitude[axis] == self.longest()
    }

    /// Units travelled toward the end point on `axis` at point `p`.
    pub fn progress(&self, p: &Point, axis: usize) -> i64 {
        (p.get(axis) - self.from.get(axis)) * self.sign[axis]
    }

    /// `step` with `axis` also moved one unit toward the end point.
    pub fn toward(&self, step: Step, axis: usize) -> Step {
        step.with(axis, self.sign[axis])
    }

    /// Wang section 4: the greatest common divisor of the |Δ| when `reduce`,
    /// else 1. Dividing every |Δ| by it leaves every discriminant's sign (it
    /// is linear in the deltas) and so the path unchanged, and after
    /// |Δ_major| / divisor steps the discriminants are back at their initial
    /// values: the pattern repeats `divisor` times with no extra code.
    pub fn divisor(&self, reduce: bool) -> i64 {
        if !reduce {
            return 1;
        }
        let g = self.magnitude[..self.dims()]
            .iter()
            .fold(0, |g, &m| gcd(g, m as u64)) as i64;
        g.max(1)
    }

    /// |Δ| of `axis` divided by `divisor` ([`Self::divisor`]), with no
    /// division when it is 1 (most lines): an i64 division takes tens of
    /// cycles, and a G-code program sets up a stepper every move.
    pub fn reduced(&self, axis: usize, divisor: i64) -> i64 {
        if divisor == 1 {
            self.magnitude[axis]
        } else {
            self.magnitude[axis] / divisor
        }
    }

    /// "(8, 6, 5)": |Δ| per axis divided by `divisor`.
    pub fn magnitudes_text(&self, divisor: i64) -> String {
        let parts: Vec<String> = (0..self.dims())
            .map(|a| self.reduced(a, divisor).to_string())
            .collect();
        format!("({})", parts.join(", "))
    }

    /// The sentence of a setup note about GCD reduction, or "" without it.
    pub fn divisor_note(&self, divisor: i64) -> String {
        if divisor == 1 {
            return String::new();
        }
        format!(
            " GCD reduction (Wang section 4): |Δ| = {} / {divisor} = {}, so the decision values are {divisor} times smaller and their pattern of {} steps repeats {divisor} times.",
            self.magnitudes_text(1),
            self.magnitudes_text(divisor),
            self.reduced(self.major(), divisor),
        )
    }

    /// The sentence of a setup note about mirroring, or "" when every axis
    /// moves in the positive direction.
    pub fn mirror_note(&self) -> &'static str {
        if self.sign[..self.dims()].contains(&-1) {
            " Negative directions are mirrored: the rule runs on |Δ| and steps each axis toward the end point."
        } else {
            ""
        }
    }
}

/// The `gcd` option (Wang section 4).
pub const GCD: OptionSpec = OptionSpec {
    name: "gcd",
    kind: OptionKind::Boolean,
    required: false,
    default: Some("false"),
    applies_with: None,
    doc: "Wang section 4: divide the deltas by their greatest common divisor; the discriminants shrink by that factor and repeat their pattern GCD times (the path is the same).",
};

/// The `gcd` option of a request.
pub fn gcd_option(req: &Request) -> Result<bool, Error> {
    Ok(req.boolean(GCD.name)?.unwrap_or(false))
}

/// Which axis goes first when several are exactly tied. Used by the rules
/// that move one axis per step, where a tie is about order, not about
/// whether an axis steps at all (so advance/hold does not apply).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TieAxis {
    /// x before y before z (the 2009 blog's `xDist <= yDist`).
    Lower,
    Higher,
}

pub const TIE_AXIS: OptionSpec = OptionSpec {
    name: "tieAxis",
    kind: OptionKind::Choice {
        values: &["lower", "higher"],
    },
    required: false,
    default: Some("lower"),
    applies_with: None,
    doc: "Which axis steps first when two or more are exactly tied: the lower (x before y before z) or the higher.",
};

impl TieAxis {
    pub fn from_request(req: &Request) -> Result<TieAxis, Error> {
        Ok(match req.choice(&TIE_AXIS)? {
            Some("higher") => TieAxis::Higher,
            _ => TieAxis::Lower,
        })
    }

    pub fn label(self) -> &'static str {
        match self {
            TieAxis::Lower => "lower",
            TieAxis::Higher => "higher",
        }
    }

    /// Scanning axes in increasing order, should `candidate` replace the best
    /// so far, given how its key compares (smaller key = better)?
    pub fn replaces(self, candidate_vs_best: Ordering) -> bool {
        match self {
            TieAxis::Lower => candidate_vs_best == Ordering::Less,
            TieAxis::Higher => candidate_vs_best != Ordering::Greater,
        }
    }
}

/// What decided a passive axis in a rule that can drift (float DDA, Liu's
/// rounded discriminant, Saleem's 2D pseudo-code as printed).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Guard {
    /// The algorithm's own rule.
    Rule,
    /// The rule wanted a step but the axis is already at its end coordinate.
    Held,
    /// The rule held but the axis has as many units left as there are steps.
    Forced,
}

pub const GUARD_LABELS: &[&str] = &["rule", "held", "forced"];

/// Steps a fill loop runs guarded before it looks again for a stretch the
/// finish rule leaves alone (and the shortest such stretch worth a loop of
/// its own).
pub const MIN_UNGUARDED_SPAN: usize = 16;

/// Steps a fill loop runs unguarded where the span the finish rule is
/// proven to leave alone is shorter than [`MIN_UNGUARDED_SPAN`], then
/// checks ([`Unguarded::steps_as_guarded`]): on a line whose passive axis
/// has a few units (or all but a few) to go over many steps that span
/// stays that short, and such a line ran guarded almost whole, 4 to 7
/// times slower per step. Where the check fails (once per free axis on a
/// line at most: the axis is then held or forced to its end), the block's
/// steps before the one the finish rule changes are taken again from where
/// it began: at most this many steps.
const UNCHECKED_BLOCK: usize = 1024;

/// What [`Guard::unguarded`] finds: which axes the finish rule leaves to
/// their rule, which it forces, and for how many steps.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Unguarded<const DIMS: usize> {
    /// The free axes, in increasing order; the first `free_count` count.
    pub free: [usize; DIMS],
    pub free_count: usize,
    /// Per axis, whether it steps on every step (held axes are neither).
    pub forced: [bool; DIMS],
    /// Steps over which this holds.
    pub span: u64,
}

impl<const DIMS: usize> Unguarded<DIMS> {
    /// How many of the next `steps` steps a fill runs unguarded, as
    /// (proven, run): the span this plan proves (at most `steps`), and
    /// that span where it is at least [`MIN_UNGUARDED_SPAN`], else a block
    /// of up to [`UNCHECKED_BLOCK`] run unguarded all the same and checked
    /// after ([`Self::steps_as_guarded`]). Not past a longer proven span: a
    /// block that fails is run again from its start, and chords of Liu's
    /// rule at 1 decimal, which the finish rule acts on near every end,
    /// took 2.2 times as long.
    pub fn run_span(&self, steps: usize) -> (usize, usize) {
        let proven = (self.span as usize).min(steps);
        let run = if proven >= MIN_UNGUARDED_SPAN {
            proven
        } else {
            UNCHECKED_BLOCK.min(steps)
        };
        (proven, run)
    }

    /// How many of `out`, steps taken unguarded as this plan runs them
    /// (free axes by their rule, forced ones always, held ones never) from
    /// `units_left` units per axis to `units_after`, with `steps_left`
    /// steps (the plan's), the finish rule would have left alone: all of
    /// them, or those before the first it would have changed. Past
    /// [`Unguarded::span`] the plan is not proven: this checks a block a
    /// fill loop ran unguarded past it ([`UNCHECKED_BLOCK`]).
    ///
    /// A free axis with u units left, stepped c_j times before step j, is
    /// held at step j when its rule wants a step with c_j = u, and forced
    /// when its rule holds it with u - c_j >= steps_left - j. Neither
    /// happens in the block when the axis stepped at most u times in it
    /// and held at most steps_left - u times (the holds before step j,
    /// j - c_j, only grow): one test per axis from the units before and
    /// after, and a pass over the steps only where it fails (at most once
    /// per free axis on a line: the axis is then held or forced to its
    /// end). Forced and held axes stay so.
    pub fn steps_as_guarded(
        &self,
        units_left: &[i64; DIMS],
        units_after: &[i64; DIMS],
        steps_left: u64,
        toward: &[Step; DIMS],
        out: &[Step],
    ) -> usize {
        let free = &self.free[..self.free_count];
        let steps = out.len() as i64;
        let within = |&axis: &usize| {
            let (units, moved) = (units_left[axis], units_left[axis] - units_after[axis]);
            moved <= units && steps - moved <= steps_left as i64 - units
        };
        if free.iter().all(within) {
            return out.len();
        }
        let mut moved = [0i64; DIMS];
        for (j, step) in out.iter().enumerate() {
            for &axis in free {
                let wants = step.0 & toward[axis].0 != 0;
                let units = units_left[axis] - moved[axis];
                if Guard::moves(wants, units, steps_left - j as u64) != wants {
                    return j;
                }
                moved[axis] += wants as i64;
            }
        }
        out.len()
    }
}

impl Guard {
    /// The finish rule: a passive axis never passes its end coordinate and
    /// never falls so far behind that it cannot reach it in the steps left.
    /// So the path ends exactly on the end point with one unit per axis per
    /// step, whatever the rule's drift. Returns whether the axis steps.
    pub fn apply(wants: bool, units_left: i64, steps_left: u64) -> (bool, Guard) {
        if wants && units_left == 0 {
            (false, Guard::Held)
        } else if !wants && units_left as u64 >= steps_left && units_left > 0 {
            (true, Guard::Forced)
        } else {
            (wants, Guard::Rule)
        }
    }

    /// Whether the axis steps under [`Guard::apply`], for the fill loops
    /// that need no guard: the same cases folded into one expression of
    /// non-short-circuit operators, so that the compiler can make it a few
    /// compares and bit operations instead of a branch per axis per step
    /// (a rule's decisions follow no pattern a branch predictor learns).
    /// Held: `wants` with no unit left fails the first term and the second
    /// needs a unit left; forced: the second term; otherwise `wants`.
    #[inline(always)]
    pub fn moves(wants: bool, units_left: i64, steps_left: u64) -> bool {
        (wants & (units_left != 0)) | ((units_left as u64 >= steps_left) & (units_left > 0))
    }

    /// The next steps over which the finish rule changes no decision, for
    /// the fill loops of the rules it guards: how each axis fares over
    /// them, from its units left (`units_left`) and the steps left.
    /// - Held (no unit left): it cannot step; it stays held.
    /// - Forced (as many units as steps): it steps every time; it stays
    ///   forced. (An active axis is one from the start.)
    /// - Free (otherwise): it steps exactly when its rule wants, as long as
    ///   it has a unit left and fewer units than steps: for at least
    ///   min(units, steps - units) steps, since each step takes one step
    ///   and at most one unit.
    ///
    /// `span` is the fewest of those over the free axes (every step left
    /// when none is free). Over that many steps a fill loop can run the
    /// rule on the free axes alone, with no guard, the forced axes' bits on
    /// every step: the same steps [`Guard::apply`] gives.
    pub fn unguarded<const DIMS: usize>(
        units_left: &[i64; DIMS],
        steps_left: u64,
    ) -> Unguarded<DIMS> {
        let mut out = Unguarded {
            free: [0; DIMS],
            free_count: 0,
            forced: [false; DIMS],
            span: steps_left,
        };
        for (axis, &units) in units_left.iter().enumerate() {
            let units = units.max(0) as u64;
            if units == 0 {
                continue;
            }
            if units >= steps_left {
                out.forced[axis] = true;
                continue;
            }
            out.free[out.free_count] = axis;
            out.free_count += 1;
            out.span = out.span.min(units).min(steps_left - units);
        }
        out
    }

    /// The guard of a step over several axes: the first that the finish
    /// rule overrode, else Rule.
    pub fn of_step(guards: &[Guard]) -> Guard {
        guards
            .iter()
            .copied()
            .find(|&g| g != Guard::Rule)
            .unwrap_or(Guard::Rule)
    }

    /// What the rule decided for `axis`, for an explanation before
    /// [`Guard::clause`]: the step's own move (`moved`, or `stays`, the
    /// algorithm's word for not moving) where the rule decided, else what
    /// the finish rule overrode, as bresenham2d says it ("so the rule says
    /// y steps; y has reached its end coordinate, so the finish rule holds
    /// it"). The step's move was said as the rule's: "epsilon(y) = -1 < 0,
    /// so y steps (...); y has as many units left as there are steps, so
    /// the finish rule forces it".
    pub fn decided(self, axis: usize, moved: bool, stays: &str) -> String {
        let name = AXIS_NAMES[axis];
        match self {
            Guard::Rule => format!("so {name} {}", if moved { "steps" } else { stays }),
            Guard::Held => format!("so the rule says {name} steps"),
            Guard::Forced => format!("so the rule says {name} {stays}"),
        }
    }

    /// A clause for an explanation, "" when the rule decided.
    pub fn clause(self, axis: usize) -> String {
        match self {
            Guard::Rule => String::new(),
            Guard::Held => format!(
                "; {} has reached its end coordinate, so the finish rule holds it",
                AXIS_NAMES[axis]
            ),
            Guard::Forced => format!(
                "; {} has as many units left as there are steps, so the finish rule forces it",
                AXIS_NAMES[axis]
            ),
        }
    }
}

/// Wang's eq. (6) for one passive axis against the active one, in units
/// travelled toward the end: D = 2|Δa|·x - 2|Δx|·a + 2|Δa| - |Δx|, with x and
/// a the units the active and the passive axis have gone. Its sign says
/// whether the ideal line leaves the cell past the middle of the passive
/// axis. Each product is below 2^64, so it is formed in i128.
pub fn wang_discriminant(
    passive_len: i64,
    active_len: i64,
    active_done: i64,
    passive_done: i64,
) -> i128 {
    let (da, dx) = (passive_len as i128, active_len as i128);
    2 * da * active_done as i128 - 2 * dx * passive_done as i128 + 2 * da - dx
}

/// "4 > 0", "0", "-2 < 0".
pub fn signed_comparison(v: i64) -> String {
    match v.signum() {
        1 => format!("{v} > 0"),
        -1 => format!("{v} < 0"),
        _ => "0".to_string(),
    }
}

/// "(x+1, y, z-1)": where a step goes, relative to the current point.
pub fn step_target(step: Step, dims: usize) -> String {
    let parts: Vec<String> = (0..dims)
        .map(|axis| match step.delta(axis) {
            1 => format!("{}+1", AXIS_NAMES[axis]),
            -1 => format!("{}-1", AXIS_NAMES[axis]),
            _ => AXIS_NAMES[axis].to_string(),
        })
        .collect();
    format!("({})", parts.join(", "))
}

/// "x, y and z".
pub fn axis_list(axes: impl Iterator<Item = usize>) -> String {
    let names: Vec<&str> = axes.map(|a| AXIS_NAMES[a]).collect();
    match names.split_last() {
        None => String::new(),
        Some((last, [])) => last.to_string(),
        Some((last, rest)) => format!("{} and {last}", rest.join(", ")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    proptest::proptest! {
        /// Over the span `Guard::unguarded` gives, whatever each rule wants
        /// at each step, `Guard::apply` steps a free axis exactly when it
        /// wants, a forced one always and a held one never.
        #[test]
        fn the_finish_rule_changes_nothing_over_the_unguarded_span(
            steps_left in 1u64..200,
            units in proptest::array::uniform3(0u64..=200),
            wants_seed in proptest::num::u64::ANY,
        ) {
            let mut left: [i64; 3] = units.map(|u| u.min(steps_left) as i64);
            let plan = Guard::unguarded(&left, steps_left);
            let free = |axis: usize| plan.free[..plan.free_count].contains(&axis);
            let mut seed = wants_seed;
            for j in 0..plan.span {
                for axis in 0..3 {
                    seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
                    let wants = seed >> 63 == 1;
                    let (moves, _) = Guard::apply(wants, left[axis], steps_left - j);
                    let unguarded = if free(axis) { wants } else { plan.forced[axis] };
                    proptest::prop_assert_eq!(moves, unguarded, "axis {} at step {} of {}", axis, j, plan.span);
                    left[axis] -= moves as i64;
                }
            }
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(2000))]
        /// Past the unguarded span: for any wants of free axes (run by
        /// their rule alone, as a fill loop runs them) over a block of any
        /// length, `steps_as_guarded` keeps exactly the steps before the
        /// first that `Guard::apply` would change. The rule is random but
        /// leans to steps or holds, so that axes run out of units, or of
        /// steps, within the block; short lines and blocks make the cases
        /// at the bounds common.
        #[test]
        fn steps_run_unguarded_are_kept_up_to_the_first_the_finish_rule_changes(
            steps_left in 1u64..24,
            units in proptest::array::uniform3(0u64..=24),
            lean in proptest::array::uniform3(0u64..=4),
            block in 0usize..24,
            wants_seed in proptest::num::u64::ANY,
        ) {
            let left: [i64; 3] = units.map(|u| u.min(steps_left) as i64);
            let plan = Guard::unguarded(&left, steps_left);
            let toward: [Step; 3] = std::array::from_fn(|a| Step::along(a, if a == 1 { -1 } else { 1 }));
            let block = block.min(steps_left as usize);
            let mut seed = wants_seed;
            let (mut unguarded, mut after) = (Vec::new(), left);
            let (mut guarded_left, mut first_changed) = (left, block);
            for j in 0..block {
                let mut step = Step::NONE;
                for axis in 0..3 {
                    seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
                    // Wants a step with probability lean / 4.
                    let wants = (seed >> 62) < lean[axis];
                    let free = plan.free[..plan.free_count].contains(&axis);
                    let moves = if free { wants } else { plan.forced[axis] };
                    if moves {
                        step = step.with(axis, toward[axis].delta(axis));
                        after[axis] -= 1;
                    }
                    let (guarded, _) = Guard::apply(moves, guarded_left[axis], steps_left - j as u64);
                    if guarded != moves && first_changed == block {
                        first_changed = j;
                    }
                    guarded_left[axis] -= guarded as i64;
                }
                unguarded.push(step);
            }
            proptest::prop_assert_eq!(
                plan.steps_as_guarded(&left, &after, steps_left, &toward, &unguarded),
                first_changed
            );
        }
    }

    #[test]
    fn mirror_measures_along_the_direction_of_travel() {
        let m = Mirror::new(Point::new(&[5, 0, -2]), Point::new(&[-3, 8, -2]));
        assert_eq!((m.sign(0), m.magnitude(0)), (-1, 8));
        assert_eq!((m.longest(), m.major(), m.total()), (8, 0, 16));
        assert!(m.is_active(1) && !m.is_active(2));
        assert_eq!(m.progress(&Point::new(&[2, 1, -2]), 0), 3);
        assert_eq!(m.toward(Step::NONE, 0), Step::along(0, -1));
        assert_eq!(m.divisor(true), 8);
        assert_eq!(m.divisor(false), 1);
        assert_eq!(m.magnitudes_text(8), "(1, 1, 0)");
        assert!(!m.mirror_note().is_empty());
    }

    #[test]
    fn the_finish_rule_holds_at_the_end_and_forces_when_late() {
        assert_eq!(Guard::apply(true, 0, 5), (false, Guard::Held));
        assert_eq!(Guard::apply(false, 3, 3), (true, Guard::Forced));
        assert_eq!(Guard::apply(false, 2, 3), (false, Guard::Rule));
        assert_eq!(Guard::apply(true, 2, 3), (true, Guard::Rule));
        assert_eq!(Guard::apply(false, 0, 0), (false, Guard::Rule));
        assert_eq!(Guard::of_step(&[Guard::Rule, Guard::Forced]), Guard::Forced);
        assert_eq!(Guard::of_step(&[Guard::Rule; 3]), Guard::Rule);
    }

    #[test]
    fn the_branch_free_finish_rule_moves_as_apply_does() {
        for wants in [false, true] {
            for units_left in 0..6 {
                for steps_left in 0..6u64 {
                    assert_eq!(
                        Guard::moves(wants, units_left, steps_left),
                        Guard::apply(wants, units_left, steps_left).0,
                        "wants {wants}, {units_left} units and {steps_left} steps left"
                    );
                }
            }
        }
    }

    #[test]
    fn tied_axes_go_in_the_chosen_order() {
        assert!(!TieAxis::Lower.replaces(Ordering::Equal));
        assert!(TieAxis::Higher.replaces(Ordering::Equal));
        assert!(TieAxis::Lower.replaces(Ordering::Less));
        assert!(!TieAxis::Higher.replaces(Ordering::Greater));
        assert_eq!(axis_list([0, 1, 2].into_iter()), "x, y and z");
        assert_eq!(axis_list([1].into_iter()), "y");
    }

    /// Checks a stepper's `ties_ahead` over `stretch` steps against the ties
    /// its steps decide, one by one (`ties_by_steps`), after `advance`
    /// steps of it: the check of every faster count below.
    fn ties_as_decided<S: Stepper>(
        mut line: S,
        advance: u64,
        stretch: u64,
        what: &str,
    ) -> Result<(), proptest::test_runner::TestCaseError> {
        for _ in 0..advance {
            line.next_step();
        }
        proptest::prop_assert_eq!(
            line.clone().ties_ahead(stretch),
            crate::trace::ties_by_steps(line, stretch),
            "{}",
            what
        );
        Ok(())
    }

    /// The line from the origin to `direction` (its first `dims` values)
    /// times `scale`.
    fn scaled(direction: &[i64], dims: usize, scale: i64) -> (Point, Point) {
        let to: Vec<i64> = direction[..dims].iter().map(|d| d * scale).collect();
        (Point::new(&vec![0; dims]), Point::new(&to))
    }

    /// A scale for short directions: 1 (ties come often on short lines),
    /// or up to 2^24, which ties at the same steps with error terms near
    /// 2^31. A scaled line's terms keep the short direction's periods (a
    /// term's is L / gcd(m, L), at most 24 here): long periods and the
    /// products past 2^63 are tested on terms made directly
    /// (`values_equal_in_any_counts_what_the_steps_compare`).
    fn scales() -> impl proptest::strategy::Strategy<Value = i64> {
        proptest::prop_oneof![
            proptest::strategy::Just(1i64),
            proptest::strategy::Just(1i64 << 24),
            1i64..=(1 << 24)
        ]
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(1024))]
        /// Every faster tie count is the one the steps decide. By terms: the
        /// Bresenham lines and nd in closed form from their error terms,
        /// Liu's float rule without its decisions; 2D as corrected and as
        /// printed (which takes its steps), 3D, nd in 2 to 6 axes (up to
        /// five terms by inclusion and exclusion; axes of equal |Δ| tie at
        /// the same steps, a 3D line's two terms often do, counted once),
        /// Liu's at 1 to 10 decimals, either tie policy, with and without
        /// the GCD. By runs and gaps: greedy a run of rounds at a time and
        /// walk6 by its fill's gap loop (another axis's candidate as near
        /// the goal; another axis's face at the same t, an edge or a
        /// corner), in 2 to 6 axes, either tie order, axes that never move
        /// or have arrived not counting. Each over any stretch from any
        /// step, the finish rule's last steps included.
        #[test]
        fn faster_tie_counts_are_the_ones_the_steps_decide(
            direction in proptest::array::uniform6(-24i64..=24),
            dims in 2usize..=6,
            scale in scales(),
            advance in 0u64..120,
            stretch in 0u64..400,
            advance_ties in proptest::bool::ANY,
            gcd in proptest::bool::ANY,
            printed in proptest::bool::ANY,
            decimals in 1u32..=10,
            higher_first in proptest::bool::ANY,
        ) {
            let tie = if advance_ties { TiePolicy::Advance } else { TiePolicy::Hold };
            let (from, to) = scaled(&direction, 3, scale);
            ties_as_decided(bresenham3d::Bresenham3d::new(from, to, tie, gcd), advance, stretch, &format!("bresenham3d to {to}"))?;
            ties_as_decided(liu_float::LiuFloat::new(from, to, tie, decimals), advance, stretch, &format!("liu-float to {to}"))?;
            let variant = if printed { bresenham2d::Variant::Printed } else { bresenham2d::Variant::Corrected };
            let (from, to) = scaled(&direction, 2, scale);
            ties_as_decided(bresenham2d::Bresenham2d::new(from, to, tie, variant), advance, stretch, &format!("bresenham2d to {to}"))?;
            let (from, to) = scaled(&direction, dims, scale);
            ties_as_decided(nd::Nd::new(from, to, tie, gcd), advance, stretch, &format!("nd to {to}"))?;
            let order = if higher_first { TieAxis::Higher } else { TieAxis::Lower };
            ties_as_decided(greedy::Greedy::new(from, to, order), advance, stretch, &format!("greedy to {to}"))?;
            ties_as_decided(walk6::Walk6::new(from, to, order), advance, stretch, &format!("walk6 to {to}"))?;
        }
    }
}
