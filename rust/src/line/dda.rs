//! The floating-point digital differential analyser (DDA), for comparison
//! with the integer rules: add Δa/n to a float accumulator per axis every
//! step and round it to the nearest cell.

use super::{GUARD_LABELS, Guard, MIN_UNGUARDED_SPAN, Mirror, step_target};
use super::{LineRun, PlanLine, Record};
use crate::algorithm_info::{AlgorithmInfo, Example, Family};
use crate::error::Error;
use crate::grid::{AXIS_NAMES, MAX_AXES, Point, Step, by_axis_count, written_steps};
use crate::request::{FROM, MAX_STEPS, Request, TO};
use crate::trace::{Column, ColumnKind, Decision, Filled, Stepper};
use std::mem::MaybeUninit;

pub const ID: &str = "dda";

pub const INFO: AlgorithmInfo = AlgorithmInfo {
    id: ID,
    example: Example {
        options: r#"{"from": [0, 0], "to": [14, 1]}"#,
        why: "Seven float additions of 1/14 give 0.4999999999999999, not 0.5.",
    },
    family: Family::Line,
    title: "Floating-point DDA",
    citation: "The digital differential analyser as textbooks give it (cited by Wang et al. 2020, section 1, refs. 8-10), in f64",
    teaching: "Take n = the largest |Δ| steps. Each axis a keeps a float accumulator that starts at its start coordinate and gains Δa/n every step; the point is each accumulator rounded to the nearest cell, floor(acc + 0.5) (halves round up, toward +infinity, whichever way the axis travels). In exact arithmetic that is Bresenham's rule. In floating point it is not, in two ways. Δa/n is rarely exact in binary (0.3 is not), so after k additions the accumulator is not k·Δa/n; where the exact value is a half (the line passes exactly between two cells) the stored error alone decides which cell wins. And each addition is rounded to the spacing of floats at the accumulator's size, 2^-23 near 2^30 instead of 2^-52 near 1, always the same way for the same increment: over millions of steps far from the origin the error piles up into whole cells, and the last point can miss the end point. voxpath's finish rule keeps the trace exact: an axis that has reached its end coordinate is held, one with as many units left as steps is forced, and the guard column shows when that happened.",
    errata: &[],
    columns: DdaWhy::COLUMNS,
    options: &[FROM, TO, MAX_STEPS],
    min_dims: 2,
    max_dims: MAX_AXES,
    default_tie: None,
    compared_by: None,
    trace: |req, _| run(req, Record),
    plan: Some(|req, _| run(req, PlanLine)),
};

/// Reads this algorithm's own options and runs its stepper as `run` says
/// (recorded or planned: [`LineRun`]).
fn run<R: LineRun>(req: &Request, run: R) -> Result<R::Out, Error> {
    run.run(&INFO, req, |from, to, _| Dda::new(from, to))
}

/// The decision behind one step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DdaWhy {
    /// Per axis, the accumulator after this step's addition.
    pub acc: [f64; MAX_AXES],
    /// Per axis, the accumulator rounded: floor(acc + 0.5).
    pub rounded: [i64; MAX_AXES],
    pub guards: [Guard; MAX_AXES],
    pub dims: usize,
}

impl Decision for DdaWhy {
    const COLUMNS: &'static [Column] = &[
        Column::new(
            "accX",
            ColumnKind::Float,
            "x accumulator after adding Δx/n (f64, grid units); the point's x is floor(accX + 0.5).",
        ),
        Column::new(
            "accY",
            ColumnKind::Float,
            "y accumulator after adding Δy/n.",
        ),
        Column::new(
            "accZ",
            ColumnKind::Float,
            "z accumulator after adding Δz/n.",
        ),
        Column::new(
            "accA",
            ColumnKind::Float,
            "a accumulator after adding Δa/n.",
        ),
        Column::new(
            "accB",
            ColumnKind::Float,
            "b accumulator after adding Δb/n.",
        ),
        Column::new(
            "accC",
            ColumnKind::Float,
            "c accumulator after adding Δc/n.",
        ),
        Column::new(
            "guard",
            ColumnKind::Category {
                labels: GUARD_LABELS,
            },
            "rule: rounding decided every axis; held / forced: the finish rule overrode float drift.",
        ),
    ];

    /// Rounding has no tie rule to apply: floor(acc + 0.5) takes halves up.
    const NEVER_TIES: bool = true;

    /// In the layout of its move's columns (`columns_of_axes!`): its axes only.
    fn write(&self, row: &mut [f64]) {
        row[..self.dims].copy_from_slice(&self.acc[..self.dims]);
        row[self.dims] = Guard::of_step(&self.guards[..self.dims]) as u8 as f64;
    }

    fn explain(&self, _from: &Point, step: Step) -> String {
        let parts: Vec<String> = (0..self.dims)
            .map(|a| {
                let name = AXIS_NAMES[a];
                format!(
                    "{name} accumulator {} rounds to {}, {}{}",
                    self.acc[a],
                    self.rounded[a],
                    self.guards[a].decided(a, step.delta(a) != 0, "stays"),
                    self.guards[a].clause(a)
                )
            })
            .collect();
        format!(
            "{}; the step goes to {}.",
            parts.join("; "),
            step_target(step, self.dims)
        )
    }
}

/// The float DDA stepper.
#[derive(Clone, Debug)]
pub struct Dda {
    mirror: Mirror,
    /// Position now, grid units.
    at: Point,
    acc: [f64; MAX_AXES],
    /// Δa / n per axis (exactly ±1 or 0 on the active axes).
    inc: [f64; MAX_AXES],
    remaining: u64,
}

impl Dda {
    pub fn new(from: Point, to: Point) -> Dda {
        let mirror = Mirror::new(from, to);
        let n = mirror.longest();
        let delta = from.delta_to(&to);
        Dda {
            mirror,
            at: from,
            acc: std::array::from_fn(|a| {
                if a < from.dims() {
                    from.get(a) as f64
                } else {
                    0.0
                }
            }),
            inc: std::array::from_fn(|a| {
                if n > 0 {
                    delta[a] as f64 / n as f64
                } else {
                    0.0
                }
            }),
            remaining: n as u64,
        }
    }
}

// SAFETY: its fill's Filled counts the slots it wrote (see its Filled::written).
unsafe impl Stepper for Dda {
    type Why = DdaWhy;

    fn next_step(&mut self) -> Option<(Step, DdaWhy)> {
        if self.remaining == 0 {
            return None;
        }
        let dims = self.mirror.dims();
        let mut step = Step::NONE;
        let mut rounded = [0; MAX_AXES];
        let mut guards = [Guard::Rule; MAX_AXES];
        for axis in 0..dims {
            self.acc[axis] += self.inc[axis];
            // Round half up: floor(acc + 0.5), the textbook int(x + 0.5).
            rounded[axis] = (self.acc[axis] + 0.5).floor() as i64;
            let sign = self.mirror.sign(axis);
            let wants = (rounded[axis] - self.at.get(axis)) * sign > 0;
            let units_left = self.mirror.magnitude(axis) - self.mirror.progress(&self.at, axis);
            let (moves, guard) = Guard::apply(wants, units_left, self.remaining);
            guards[axis] = guard;
            if moves {
                step = self.mirror.toward(step, axis);
            }
        }
        self.remaining -= 1;
        self.at.apply(step);
        let why = DdaWhy {
            acc: self.acc,
            rounded,
            guards,
            dims,
        };
        Some((step, why))
    }

    /// The steps of [`Stepper::next_step`], with the number of axes a
    /// constant ([`Dda::fill_axes`]) and no decision built.
    fn fill(&mut self, out: &mut [MaybeUninit<Step>]) -> Filled {
        by_axis_count!(self.mirror.dims(), self.fill_axes(out))
    }

    fn remaining_steps(&self) -> Option<u64> {
        Some(self.remaining)
    }

    fn columns(&self) -> &'static [Column] {
        columns_of_axes!(DdaWhy, 0, self.mirror.dims())
    }

    fn setup_note(&self) -> String {
        let incs: Vec<String> = (0..self.mirror.dims())
            .map(|a| format!("{} += {}", AXIS_NAMES[a], self.inc[a]))
            .collect();
        format!(
            "n = {} steps; per step {} (f64), each rounded with floor(acc + 0.5).",
            self.mirror.longest(),
            incs.join(", ")
        )
    }
}

impl Dda {
    /// [`Stepper::fill`] for `DIMS` axes: `next_step`'s arithmetic, the
    /// same f64 additions in the same order, on local copies (in
    /// registers); the units left per axis are counted down instead of
    /// found from the position.
    #[inline(always)]
    fn fill_axes<const DIMS: usize>(&mut self, out: &mut [MaybeUninit<Step>]) -> Filled {
        let taken = out.len().min(self.remaining as usize);
        let toward: [Step; DIMS] = std::array::from_fn(|a| self.mirror.toward(Step::NONE, a));
        let sign: [i64; DIMS] = std::array::from_fn(|a| self.mirror.sign(a));
        let inc: [f64; DIMS] = std::array::from_fn(|a| self.inc[a]);
        let mut acc: [f64; DIMS] = std::array::from_fn(|a| self.acc[a]);
        let start: [i64; DIMS] = std::array::from_fn(|a| self.at.get(a));
        let mut at = start;
        let mut left: [i64; DIMS] =
            std::array::from_fn(|a| self.mirror.magnitude(a) - self.mirror.progress(&self.at, a));
        let mut remaining = self.remaining;
        let mut done = 0;
        while done < taken {
            // Where the finish rule changes nothing, the rule runs on the
            // free axes alone (most of a line); near its ends, guarded.
            let plan = Guard::unguarded(&left, remaining);
            // Where the proven span is too short, a block unguarded all
            // the same, checked after.
            let (proven, span) = plan.run_span(taken - done);
            let mut guarded = if DIMS <= 3 {
                MIN_UNGUARDED_SPAN.min(taken - done)
            } else {
                taken - done
            };
            if span >= MIN_UNGUARDED_SPAN && DIMS <= 3 {
                let before = (acc, at, left);
                let axes = Axes {
                    toward: &toward,
                    sign: &sign,
                    inc: &inc,
                    acc: &mut acc,
                    at: &mut at,
                    left: &mut left,
                };
                let (free, forced, block) = (
                    &plan.free[..plan.free_count],
                    &plan.forced,
                    &mut out[done..done + span],
                );
                match (DIMS, plan.free_count) {
                    (2, 0) => axes.unguarded::<0, 2>(free, forced, block),
                    (2, 1) => axes.unguarded::<1, 1>(free, forced, block),
                    (2, _) => axes.unguarded::<2, 0>(free, forced, block),
                    (_, 0) => axes.unguarded::<0, 3>(free, forced, block),
                    (_, 1) => axes.unguarded::<1, 2>(free, forced, block),
                    (_, 2) => axes.unguarded::<2, 1>(free, forced, block),
                    _ => axes.unguarded::<3, 0>(free, forced, block),
                }
                // SAFETY: `unguarded` wrote every slot of the block.
                let block = unsafe { written_steps(block) };
                let kept = if span > proven {
                    plan.steps_as_guarded(&before.2, &left, remaining, &toward, block)
                } else {
                    span
                };
                if kept == span {
                    remaining -= span as u64;
                    done += span;
                    continue;
                }
                // The finish rule would have changed step `kept`: from
                // where the block began (the same f64 additions), guarded
                // up to that step; past it the plan holds that axis or
                // forces it. (Run again unguarded, the steps before it
                // made the DDA's loop 6% slower in wasm.)
                (acc, at, left) = before;
                guarded = kept + 1;
            }
            for slot in &mut out[done..done + guarded] {
                let mut step = Step::NONE;
                for axis in 0..DIMS {
                    acc[axis] += inc[axis];
                    let rounded = (acc[axis] + 0.5).floor() as i64;
                    let wants = (rounded - at[axis]) * sign[axis] > 0;
                    // Branch-free: the step's bit and the counts move by 0 or 1.
                    let moves = Guard::moves(wants, left[axis], remaining);
                    step = Step(step.0 | (toward[axis].0 * moves as u16));
                    at[axis] += sign[axis] * moves as i64;
                    left[axis] -= moves as i64;
                }
                slot.write(step);
                remaining -= 1;
            }
            done += guarded;
        }
        self.acc[..DIMS].copy_from_slice(&acc);
        self.at.coords_mut().copy_from_slice(&at);
        self.remaining = remaining;
        let displacement = std::array::from_fn(|a| if a < DIMS { at[a] - start[a] } else { 0 });
        // SAFETY: the loop ran until `done` reached `taken`, every slot
        // before it written by a block or the guarded loop.
        unsafe { Filled::written(taken, displacement) }
    }
}

/// The DDA's state per axis, for [`Axes::unguarded`].
struct Axes<'a> {
    toward: &'a [Step],
    sign: &'a [i64],
    inc: &'a [f64],
    acc: &'a mut [f64],
    at: &'a mut [i64],
    left: &'a mut [i64],
}

impl Axes<'_> {
    /// `out.len()` steps over which the finish rule changes nothing
    /// ([`Guard::unguarded`]): each accumulator gains its increment every
    /// step, the same f64 additions in the same order as
    /// [`Stepper::next_step`]'s, but only the `FREE` free axes are rounded
    /// and compared; the `FIXED` others (forced: step every time; held:
    /// never) need only their sums. Their numbers are constants, so every
    /// value stays in a register. Compiled on its own, not into the fill:
    /// inlined beside the check of a block run past the proven span, its
    /// loop kept the 0.5 in memory and the 2D line took 5% longer natively.
    #[inline(never)]
    fn unguarded<const FREE: usize, const FIXED: usize>(
        self,
        free: &[usize],
        forced: &[bool],
        out: &mut [MaybeUninit<Step>],
    ) {
        let free: [usize; FREE] = std::array::from_fn(|i| free[i]);
        let mut others = (0..self.acc.len()).filter(|a| !free.contains(a));
        let fixed: [usize; FIXED] =
            std::array::from_fn(|_| others.next().expect("an axis not free"));
        let bits = free.map(|a| self.toward[a].0);
        let sign = free.map(|a| self.sign[a]);
        let inc = free.map(|a| self.inc[a]);
        let mut acc = free.map(|a| self.acc[a]);
        // floor(acc + 0.5) passes the position `at` (the rule's test)
        // exactly when acc + 0.5 >= at + 1 going up, or < at going down
        // (at is an integer, exact in f64): one compare against the edge
        // of the cell, no float-to-integer conversion.
        let down = sign.map(|s| s < 0);
        let mut edge = free.map(|a| (self.at[a] + (self.sign[a] > 0) as i64) as f64);
        let step_f = sign.map(|s| s as f64);
        let fixed_inc = fixed.map(|a| self.inc[a]);
        let mut fixed_acc = fixed.map(|a| self.acc[a]);
        let forced_bits = fixed
            .iter()
            .filter(|&&a| forced[a])
            .fold(0, |bits, &a| bits | self.toward[a].0);
        for slot in out.iter_mut() {
            for j in 0..FIXED {
                fixed_acc[j] += fixed_inc[j];
            }
            let mut step = forced_bits;
            for i in 0..FREE {
                acc[i] += inc[i];
                let moves = (acc[i] + 0.5 >= edge[i]) != down[i];
                step |= bits[i] * moves as u16;
                edge[i] += if moves { step_f[i] } else { 0.0 };
            }
            slot.write(Step(step));
        }
        let n = out.len() as i64;
        for (i, &a) in free.iter().enumerate() {
            let at = edge[i] as i64 - (sign[i] > 0) as i64;
            self.left[a] -= (at - self.at[a]) * sign[i];
            self.acc[a] = acc[i];
            self.at[a] = at;
        }
        for (j, &a) in fixed.iter().enumerate() {
            self.acc[a] = fixed_acc[j];
            if forced[a] {
                self.at[a] += self.sign[a] * n;
                self.left[a] -= n;
            }
        }
    }
}
