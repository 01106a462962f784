//! Liu & Cheng (2002) as Wang et al. (2020) reproduce it (section 3.2, eq.
//! (14)-(15), Table 1) and criticise it (section 4, Fig. 10): the 3D
//! Bresenham extension with a decimal decision parameter per passive axis,
//! kept to a fixed number of decimals.
//!
//! epsilon(y) starts at k_yx - 0.5 (eq. 14), y steps when epsilon >= 0 and
//! then epsilon loses 1, and every step epsilon gains k_yx. With exact
//! arithmetic this is Bresenham's rule (epsilon = Wang's M / 2Δx); kept to d
//! decimals, the slope k itself is rounded and the error accumulates.

use super::{
    GUARD_LABELS, Guard, MIN_UNGUARDED_SPAN, Mirror, Unguarded, axis_list, step_target,
    wang_discriminant,
};
use super::{LineRun, PlanLine, Record};
use crate::algorithm_info::{AlgorithmInfo, Example, Family};
use crate::error::{Error, counted};
use crate::grid::{AXIS_NAMES, Point, Step, written_steps};
use crate::range::{IntegerRange, WHOLE_NUMBER};
use crate::request::{FROM, MAX_STEPS, OptionKind, OptionSpec, Request, TO, TiePolicy, tie_option};
use crate::trace::{Column, ColumnKind, Decision, Filled, Stepper, fill_by_next_step};
use std::mem::MaybeUninit;

pub const ID: &str = "liu-float";

/// Most decimals the `decimals` option accepts: beyond 10 the rounding is
/// below the f64 spacing of the values it rounds and changes nothing.
pub const MAX_DECIMALS: i64 = 10;

pub const DECIMALS: OptionSpec = OptionSpec {
    name: "decimals",
    kind: OptionKind::Integer(IntegerRange {
        min: Some(0),
        max: Some(MAX_DECIMALS),
        whole: WHOLE_NUMBER,
    }),
    required: false,
    default: Some("1"),
    applies_with: None,
    doc: "Decimal places kept of the slope k and of each decision parameter, 0 to 10 (1 drifts as Wang's Fig. 10 shows; 4 reproduces Liu's Table 1).",
};

/// The first line from the origin with x active (in order of |Δx|, then
/// |Δy|, then |Δz|) where one decimal strays beyond sqrt(2)/2; named in the
/// teaching text, and found again by a search in tests/line_goldens.rs.
pub const DRIFT_EXAMPLE: [i64; 3] = [7, 1, 1];

pub const INFO: AlgorithmInfo = AlgorithmInfo {
    id: ID,
    example: Example {
        options: r#"{"from": [0, 0, 0], "to": [7, 1, 1], "decimals": 1}"#,
        why: "With one decimal, k = 1/7 is kept as 0.1 and the path strays beyond sqrt(2)/2 (Wang Fig. 10).",
    },
    family: Family::Line,
    title: "Liu's 3D Bresenham with a decimal discriminant kept to d places",
    citation: "Liu & Cheng (2002), Three-dimensional extension of Bresenham's algorithm, as given in Wang et al. (2020) section 3.2, eq. (14)-(15), Table 1, and discussed in section 4, Fig. 10",
    teaching: "Liu's rule in decimals: the slope of each passive axis against the active one, k = Δy/Δx, and a decision parameter epsilon(y) = k - 0.5 to start (eq. 14-15). Every step the active axis moves; y moves when epsilon(y) >= 0 (the line is past the middle of the cell), and then epsilon(y) loses 1; every step epsilon(y) gains k. With exact numbers this is Bresenham's rule (epsilon = Wang's M / 2Δx). A controller that keeps only d decimals rounds k and each new epsilon, and the error of the rounded slope piles up every step until it flips a decision, and a flip can take a point beyond the sqrt(2)/2 of every exact rule. On (0,0,0)->(7,1,1), the first line with x active where one decimal takes a point that far (earlier ones, such as (6,0,4), flip a decision but stay within it), one decimal keeps k = 1/7 = 0.142857 as 0.1: epsilon runs -0.4, -0.3, -0.2, -0.1, 0 instead of crossing 0 at x = 4, so y and z step at x = 5 and the point (4,0,0) is sqrt(32/51) = 0.792 from the line, beyond the sqrt(2)/2 of every exact rule (Wang Fig. 10). With 4 decimals the same line is Bresenham's, at most 0.594 away. More decimals shrink the drift but, for most slopes, never remove it (a slope written exactly in d decimals, such as Wang's 0.7 and 0.6, does not drift): an exact tie (epsilon = 0) comes out a hair above or below 0, so (0,0,0)->(14,13,0) steps y at x = 7 even with ten decimals and tie = hold (k = 13/14 kept to ten decimals is 3e-11 too large). Rounding here: v·10^d is rounded to an integer half away from zero and divided by 10^d, in f64 (so a value whose double lies just below a half rounds by its binary value: 0.145 to two decimals is 0.14, as 0.145 × 100 is 14.499999999999998). Because a drifting axis could miss its end point, a finish rule holds an axis that has arrived and forces one that has as many units left as steps; the guard column shows when it acted.",
    errata: &[
        "Wang's Table 1 prints epsilon(z_9) = 0.1 at i = 8; eq. (15) with k_zx = 0.6 gives 0.3 - 1 + 0.6 = -0.1 there (z holds at step 9, as the table's own z column shows, and 0.5 follows at i = 9).",
        "Table 1's Error 0.225064 for (7,5,4) should read 0.220564 (see regions).",
        "Wang's section 4 reports the drift with one decimal but not which line; voxpath's example is (0,0,0)->(7,1,1), the first line from the origin with x active, in order of |Δx|, |Δy|, |Δz|, where one decimal takes a point beyond sqrt(2)/2 of the line (earlier lines, such as (6,0,4), flip a decision but stay within it).",
    ],
    columns: LiuWhy::COLUMNS,
    options: &[FROM, TO, DECIMALS, tie_option("advance"), MAX_STEPS],
    min_dims: 3,
    max_dims: 3,
    default_tie: Some(TiePolicy::Advance),
    compared_by: None,
    trace: |req, _| run(req, Record),
    plan: Some(|req, _| run(req, PlanLine)),
};

/// Reads this algorithm's own options and runs its stepper as `run` says
/// (recorded or planned: [`LineRun`]).
fn run<R: LineRun>(req: &Request, run: R) -> Result<R::Out, Error> {
    let decimals = decimals_option(req)?;
    run.run(&INFO, req, |from, to, tie| {
        LiuFloat::new(from, to, tie, decimals)
    })
}

fn decimals_option(req: &Request) -> Result<u32, Error> {
    Ok(req.declared_integer(&DECIMALS)?.unwrap_or(1) as u32)
}

/// `v` kept to `decimals` places: v·10^d rounded half away from zero (f64
/// `round`), divided by 10^d. The product is itself an f64, so a decimal
/// half that binary cannot store exactly rounds the way its stored value lies.
pub fn round_decimals(v: f64, decimals: u32) -> f64 {
    round_to_scale(v, decimal_scale(decimals))
}

/// 10^d, as [`round_decimals`] scales by it (exact: every power of ten up
/// to 10^22 is an f64, and so is each partial product).
pub fn decimal_scale(decimals: u32) -> f64 {
    10f64.powi(decimals as i32)
}

/// [`round_decimals`] with its scale computed once, for a stepper that
/// rounds every step.
#[inline(always)]
fn round_to_scale(v: f64, scale: f64) -> f64 {
    (v * scale).round() / scale
}

/// The fewest decimals, from 1, that give the same path as any more
/// decimals (up to [`MAX_DECIMALS`], same tie policy) on the line from
/// `from` to `to`: the first d at which every passive axis's slope
/// k = |Δa| / n (n = |Δactive|) is a decimal of d places, |Δa| * 10^d a
/// multiple of n. None when no d up to [`MAX_DECIMALS`] has that.
///
/// Why this is exact. With 10^d = S and K = |Δa| * S / n a whole number,
/// [`LiuFloat::new`] keeps k as the f64 nearest K / S and epsilon_1 as the
/// f64 nearest (K - S/2) / S (S/2 is whole from d = 1; each product with S
/// is within 10^-5 of K or K - S/2 before it is rounded). Say epsilon stands
/// for the integer E = epsilon * S. Every step then computes
/// E - S * moved + K exactly, as long as |E|, K and S stay below [`EXACT_SCALED`] (the
/// argument there, which holds for `advance` and for `fill`'s integer loop
/// alike), and compares epsilon with 0, which is comparing E with 0. So
/// E / S is exactly Liu's epsilon in exact arithmetic, k(i + 1) - 1/2 - y_i,
/// the same rational number for every such d: each decision, and the path,
/// is the same for all of them. The bound holds: without the finish rule,
/// epsilon stays in [k - 1, k] (from k - 1/2; a step from epsilon >= 0,
/// or above 0 with hold, lands in [k - 1, 2k - 1], a hold from epsilon <= 0 in
/// [2k - 1, k]), so |E| <= S <= 10^10; and the finish rule never acts, since
/// y_n = kn + k - 1/2 - epsilon_n is a whole number within 1/2 of |Δa|,
/// so it is |Δa|, and y never passes |Δa| nor falls so far behind that it
/// needs a forced step. A line with no passive axis (every axis moves as
/// far, or none moves) has the same path at every d: 1.
pub fn exact_decimals(from: Point, to: Point) -> Option<u32> {
    let mirror = Mirror::new(from, to);
    let n = mirror.longest() as u128;
    (1..=MAX_DECIMALS as u32).find(|&d| {
        let scale = 10u128.pow(d);
        (0..mirror.dims())
            .filter(|&a| !mirror.is_active(a))
            .all(|a| (mirror.magnitude(a) as u128 * scale) % n == 0)
    })
}

/// Magnitude below which [`LiuFloat::fill`] runs Liu's rule on integers:
/// with |E|, 10^d and |K| below it, the three f64 operations of a step
/// (e - 1, + k, x 10^d) err by less than 4 * 2^-53 * 2^48 = 1/8 in all,
/// so rounding their result gives the integer E - 10^d + K exactly.
const EXACT_SCALED: i64 = 1 << 48;

/// The decision behind one step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LiuWhy {
    /// Per axis, epsilon before the step; None for active axes.
    pub epsilon: [Option<f64>; 3],
    /// Per axis, epsilon minus its exact value at this point (Wang's
    /// discriminant / 2Δx): the accumulated rounding.
    pub drift: [Option<f64>; 3],
    pub guards: [Guard; 3],
    pub tie: bool,
    pub tie_policy: TiePolicy,
    pub decimals: u32,
}

impl Decision for LiuWhy {
    const COLUMNS: &'static [Column] = &[
        Column::new(
            "epsX",
            ColumnKind::Float,
            "Liu's epsilon(x) before the step, kept to d decimals; empty when x is active.",
        ),
        Column::new(
            "epsY",
            ColumnKind::Float,
            "Liu's epsilon(y) before the step (eq. 14), kept to d decimals.",
        ),
        Column::new(
            "epsZ",
            ColumnKind::Float,
            "Liu's epsilon(z) before the step (eq. 15), kept to d decimals.",
        ),
        Column::new(
            "driftX",
            ColumnKind::Float,
            "epsX minus its exact value at this point (Wang's discriminant / 2|Δactive|).",
        ),
        Column::new(
            "driftY",
            ColumnKind::Float,
            "epsY minus its exact value: the rounding accumulated so far (Wang Fig. 10).",
        ),
        Column::new("driftZ", ColumnKind::Float, "epsZ minus its exact value."),
        Column::new(
            "guard",
            ColumnKind::Category {
                labels: GUARD_LABELS,
            },
            "rule: epsilon decided every axis; held / forced: the finish rule overrode a drifting axis.",
        ),
        Column::new(
            "tie",
            ColumnKind::Flag,
            "1 when an epsilon was exactly 0 and the tie policy decided.",
        ),
    ];

    fn write(&self, row: &mut [f64]) {
        for axis in 0..3 {
            row[axis] = self.epsilon[axis].unwrap_or(f64::NAN);
            row[3 + axis] = self.drift[axis].unwrap_or(f64::NAN);
        }
        row[6] = Guard::of_step(&self.guards) as u8 as f64;
        row[7] = self.tie as u8 as f64;
    }

    fn is_tie(&self) -> bool {
        self.tie
    }

    fn explain(&self, _from: &Point, step: Step) -> String {
        let d = self.decimals as usize;
        let active: Vec<usize> = (0..3).filter(|&a| self.epsilon[a].is_none()).collect();
        let verb = if active.len() == 1 { "steps" } else { "step" };
        let mut s = format!("{} {verb} as active", axis_list(active.into_iter()));
        for axis in 0..3 {
            let (Some(e), Some(drift)) = (self.epsilon[axis], self.drift[axis]) else {
                continue;
            };
            let name = AXIS_NAMES[axis];
            let verdict = if e == 0.0 {
                format!(", a tie that '{}' decides", self.tie_policy.label())
            } else if e > 0.0 {
                " > 0".to_string()
            } else {
                " < 0".to_string()
            };
            let decided = self.guards[axis].decided(axis, step.delta(axis) != 0, "holds");
            s.push_str(&format!("; epsilon({name}) = {e:.d$}{verdict}, {decided}"));
            if drift.abs() >= 0.5 * 10f64.powi(-(self.decimals as i32)) {
                s.push_str(&format!(
                    " (it has drifted {drift:+.3} from its exact value)"
                ));
            }
            s.push_str(&self.guards[axis].clause(axis));
        }
        s.push_str(&format!("; the step goes to {}.", step_target(step, 3)));
        s
    }
}

/// Liu's stepper with decision parameters kept to `decimals` places.
#[derive(Clone, Debug)]
pub struct LiuFloat {
    mirror: Mirror,
    /// Per passive axis, the slope |Δa| / |Δactive| kept to `decimals`.
    slope: [Option<f64>; 3],
    epsilon: [Option<f64>; 3],
    /// Units left per axis.
    left: [i64; 3],
    remaining: u64,
    decimals: u32,
    /// 10^decimals ([`decimal_scale`]).
    scale: f64,
    tie: TiePolicy,
}

impl LiuFloat {
    pub fn new(from: Point, to: Point, tie: TiePolicy, decimals: u32) -> LiuFloat {
        let mirror = Mirror::new(from, to);
        let longest = mirror.longest();
        let slope = std::array::from_fn(|a| {
            (!mirror.is_active(a))
                .then(|| round_decimals(mirror.magnitude(a) as f64 / longest as f64, decimals))
        });
        // Eq. (14)-(15): epsilon(y_1) = k_yx - 0.5.
        let epsilon = slope.map(|k| k.map(|k| round_decimals(k - 0.5, decimals)));
        LiuFloat {
            mirror,
            slope,
            epsilon,
            left: [0, 1, 2].map(|a| mirror.magnitude(a)),
            remaining: longest as u64,
            decimals,
            scale: decimal_scale(decimals),
            tie,
        }
    }

    /// One step of Liu's rule: the step, the guard of each axis and whether
    /// an epsilon was exactly 0; epsilon and the units left move on.
    #[inline(always)]
    fn advance(&mut self) -> (Step, [Guard; 3], bool) {
        let mut step = Step::NONE;
        let mut guards = [Guard::Rule; 3];
        let mut tie = false;
        for axis in 0..3 {
            let (Some(e), Some(k)) = (self.epsilon[axis], self.slope[axis]) else {
                // Active: one unit every step.
                step = self.mirror.toward(step, axis);
                self.left[axis] -= 1;
                continue;
            };
            // Past the middle of the cell: step (Liu: epsilon >= 0, so a
            // tie steps; hold makes it strict).
            let wants = e > 0.0 || (e == 0.0 && self.tie == TiePolicy::Advance);
            tie |= e == 0.0;
            let (moves, guard) = Guard::apply(wants, self.left[axis], self.remaining);
            guards[axis] = guard;
            let mut next = e;
            if moves {
                step = self.mirror.toward(step, axis);
                self.left[axis] -= 1;
                next -= 1.0;
            }
            // Every step epsilon gains k, and the sum is kept to d decimals.
            self.epsilon[axis] = Some(round_to_scale(next + k, self.scale));
        }
        self.remaining -= 1;
        (step, guards, tie)
    }

    /// For [`Stepper::fill`]: each passive axis's epsilon and slope as the
    /// integers E = epsilon * 10^d and K = k * 10^d they stand for (every
    /// epsilon and k is such an integer rounded and divided by 10^d), when
    /// they and `steps` more steps stay below [`EXACT_SCALED`]: then each
    /// step's f64 arithmetic rounds to E - (10^d if the axis steps) + K
    /// exactly, and epsilon > 0, = 0 are E > 0, = 0. None otherwise.
    fn scaled(&self, steps: u64) -> Option<[Option<(i64, i64)>; 3]> {
        let mut out = [None; 3];
        for axis in 0..3 {
            let (Some(e), Some(k)) = (self.epsilon[axis], self.slope[axis]) else {
                continue;
            };
            let (big_e, big_k) = ((e * self.scale).round(), (k * self.scale).round());
            // Each must give its value back exactly (it does below the bound).
            let reach = big_e.abs() + steps as f64 * (big_k.abs() + self.scale);
            // (A NaN reach is not below the bound either.)
            let exact = reach < EXACT_SCALED as f64;
            if !exact || big_e / self.scale != e || big_k / self.scale != k {
                return None;
            }
            out[axis] = Some((big_e as i64, big_k as i64));
        }
        Some(out)
    }

    /// Liu's epsilon for `axis` computed exactly at the current point:
    /// Wang's discriminant (eq. 6) over 2|Δactive|.
    fn exact_epsilon(&self, axis: usize) -> f64 {
        let (dx, da) = (self.mirror.longest(), self.mirror.magnitude(axis));
        let reference = dx - self.left[self.mirror.major()];
        let m = wang_discriminant(da, dx, reference, da - self.left[axis]);
        m as f64 / (2 * dx) as f64
    }
}

/// Liu's rule on the scaled integers ([`LiuFloat::scaled`]), per axis: the
/// step toward its end, K (0 for an active axis) and 10^d (0 for an active
/// axis, whose value stays 1: it always wants to step).
struct ScaledRule {
    toward: [Step; 3],
    /// E > threshold steps.
    threshold: i64,
    k: [i64; 3],
    scale: [i64; 3],
}

impl ScaledRule {
    /// `out.len()` steps over which the finish rule changes nothing
    /// ([`Guard::unguarded`]): the rule on the `FREE` free axes alone (in
    /// registers: their number a constant), the forced axes' bits on every
    /// step; then the other axes' values and units moved on in closed form
    /// (exact: [`LiuFloat::scaled`] bounds them over the whole chunk).
    #[inline(always)]
    fn unguarded<const FREE: usize>(
        &self,
        plan: &Unguarded<3>,
        values: &mut [i64; 3],
        left: &mut [i64; 3],
        out: &mut [MaybeUninit<Step>],
    ) {
        let free: [usize; FREE] = std::array::from_fn(|i| plan.free[i]);
        let bits: [u16; FREE] = free.map(|a| self.toward[a].0);
        let k: [i64; FREE] = free.map(|a| self.k[a]);
        let scale: [i64; FREE] = free.map(|a| self.scale[a]);
        let mut value: [i64; FREE] = free.map(|a| values[a]);
        let mut moved = [0i64; FREE];
        let forced_bits = (0..3)
            .filter(|&a| plan.forced[a])
            .fold(0, |bits, a| bits | self.toward[a].0);
        for slot in out.iter_mut() {
            let mut step = forced_bits;
            for i in 0..FREE {
                let moves = value[i] > self.threshold;
                step |= bits[i] * moves as u16;
                moved[i] += moves as i64;
                value[i] += k[i] - scale[i] * moves as i64;
            }
            slot.write(Step(step));
        }
        let n = out.len() as i64;
        for axis in 0..3 {
            if let Some(i) = free.iter().position(|&a| a == axis) {
                values[axis] = value[i];
                left[axis] -= moved[i];
            } else if plan.forced[axis] {
                values[axis] += n * (self.k[axis] - self.scale[axis]);
                left[axis] -= n;
            } else {
                values[axis] += n * self.k[axis];
            }
        }
    }
}

// SAFETY: its fill's Filled counts the slots it wrote (see its Filled::written).
unsafe impl Stepper for LiuFloat {
    type Why = LiuWhy;

    fn next_step(&mut self) -> Option<(Step, LiuWhy)> {
        if self.remaining == 0 {
            return None;
        }
        // Measured before any axis moves: the exact value at this point.
        let drift: [Option<f64>; 3] =
            std::array::from_fn(|a| Some(self.epsilon[a]? - self.exact_epsilon(a)));
        let epsilon = self.epsilon;
        let (step, guards, tie) = self.advance();
        let why = LiuWhy {
            epsilon,
            drift,
            guards,
            tie,
            tie_policy: self.tie,
            decimals: self.decimals,
        };
        Some((step, why))
    }

    /// Liu's rule on the integers epsilon and k stand for ([`Self::scaled`]),
    /// no rounding, no division, no decision built; the last step of the
    /// chunk by [`Self::advance`] in f64, so the state left behind is the
    /// rule's to the bit (a zero epsilon keeps the sign its f64 arithmetic
    /// gives it). Falls back to `next_step` where the integers could leave
    /// the exact range.
    fn fill(&mut self, out: &mut [MaybeUninit<Step>]) -> Filled {
        let taken = out.len().min(self.remaining as usize);
        let Some(scaled) = self.scaled(taken as u64).filter(|_| taken > 0) else {
            return fill_by_next_step(self, out);
        };
        let scale = self.scale as i64;
        // epsilon > threshold steps: >= 0 with tie = advance, > 0 with hold.
        let threshold = -i64::from(self.tie == TiePolicy::Advance);
        let toward: [Step; 3] = std::array::from_fn(|a| self.mirror.toward(Step::NONE, a));
        let start_left = self.left;
        // One loop body for every axis, no case per axis: an active axis
        // (no epsilon) is a value that always wants to step and never
        // changes (k = 0, and 0 taken off when it steps); it has as many
        // units left as steps, so the finish rule lets it step every time.
        let k_by_axis = scaled.map(|v| v.map_or(0, |(_, k)| k));
        let scale_by_axis = scaled.map(|v| v.map_or(0, |_| scale));
        let mut values = scaled.map(|v| v.map_or(1, |(e, _)| e));
        let mut remaining = self.remaining;
        // Counted in a local (a register), not through `self`.
        let mut left = self.left;
        let body = taken - 1;
        let mut done = 0;
        while done < body {
            // Where the finish rule changes nothing, the rule runs on the
            // free axes alone (most of a line); near its ends, guarded.
            let plan = Guard::unguarded(&left, remaining);
            // Where the proven span is too short, a block unguarded all
            // the same, checked after.
            let (proven, span) = plan.run_span(body - done);
            let rule = ScaledRule {
                toward,
                threshold,
                k: k_by_axis,
                scale: scale_by_axis,
            };
            let unguarded =
                |values: &mut [i64; 3], left: &mut [i64; 3], block: &mut [MaybeUninit<Step>]| {
                    match plan.free_count {
                        0 => rule.unguarded::<0>(&plan, values, left, block),
                        1 => rule.unguarded::<1>(&plan, values, left, block),
                        2 => rule.unguarded::<2>(&plan, values, left, block),
                        _ => rule.unguarded::<3>(&plan, values, left, block),
                    }
                };
            if span >= MIN_UNGUARDED_SPAN {
                let before = (values, left);
                unguarded(&mut values, &mut left, &mut out[done..done + span]);
                let kept = if span > proven {
                    // SAFETY: `unguarded` wrote every slot of the block.
                    let block = unsafe { written_steps(&out[done..done + span]) };
                    plan.steps_as_guarded(&before.1, &left, remaining, &toward, block)
                } else {
                    span
                };
                if kept < span {
                    // The finish rule would have changed step `kept`: the
                    // steps before it again from where the block began,
                    // unguarded (guarded, chords at 1 decimal, which the
                    // finish rule acts on near every end, took 12% longer
                    // than before blocks were checked); past it the plan
                    // holds that axis or forces it.
                    (values, left) = before;
                    unguarded(&mut values, &mut left, &mut out[done..done + kept]);
                }
                remaining -= kept as u64;
                done += kept;
                if kept > 0 {
                    continue;
                }
            }
            let guarded = MIN_UNGUARDED_SPAN.min(body - done);
            for slot in &mut out[done..done + guarded] {
                let mut step = Step::NONE;
                for axis in 0..3 {
                    let wants = values[axis] > threshold;
                    // Branch-free: the step's bit and the counts move by 0 or 1.
                    let moves = Guard::moves(wants, left[axis], remaining);
                    step = Step(step.0 | (toward[axis].0 * moves as u16));
                    left[axis] -= moves as i64;
                    values[axis] += k_by_axis[axis] - scale_by_axis[axis] * moves as i64;
                }
                slot.write(step);
                remaining -= 1;
            }
            done += guarded;
        }
        self.left = left;
        for axis in 0..3 {
            if scaled[axis].is_some() {
                self.epsilon[axis] = Some(values[axis] as f64 / self.scale);
            }
        }
        self.remaining = remaining;
        out[taken - 1].write(self.advance().0);
        let displacement = std::array::from_fn(|a| {
            if a < 3 {
                self.mirror.sign(a) * (start_left[a] - self.left[a])
            } else {
                0
            }
        });
        // SAFETY: the loop ran until `done` reached `body` = taken - 1,
        // every slot before it written by a block or the guarded loop, and
        // the last one just above.
        unsafe { Filled::written(taken, displacement) }
    }

    fn remaining_steps(&self) -> Option<u64> {
        Some(self.remaining)
    }

    /// Liu's rule a step at a time ([`LiuFloat::advance`], which says
    /// whether an epsilon was 0) without the decision, whose drift (each
    /// epsilon against its exact value, in i128) cost most of a step: with
    /// its ties counted by replay, the metrics of the bench's
    /// 2,000,000-step line took 150 ms in Node, 45 ms so.
    fn ties_ahead(mut self, steps: u64) -> u64 {
        (0..steps.min(self.remaining))
            .filter(|_| self.advance().2)
            .count() as u64
    }

    fn setup_note(&self) -> String {
        let d = self.decimals as usize;
        let longest = self.mirror.longest();
        let mut parts = Vec::new();
        for axis in 0..3 {
            let (Some(k), Some(e)) = (self.slope[axis], self.epsilon[axis]) else {
                continue;
            };
            let exact = self.mirror.magnitude(axis) as f64 / longest as f64;
            parts.push(format!(
                "k_{n} = {}/{longest} = {exact:.6} kept as {k:.d$} (off by {:+.6} per step), epsilon({n})_1 = {e:.d$}",
                self.mirror.magnitude(axis),
                k - exact,
                n = AXIS_NAMES[axis],
            ));
        }
        let mut s = format!(
            "{} kept (eq. 14-15): ",
            counted(self.decimals.into(), "decimal")
        );
        s.push_str(&if parts.is_empty() {
            "every moving axis is active.".to_string()
        } else {
            parts.join("; ") + "."
        });
        s.push_str(self.mirror.mirror_note());
        s
    }
}
