//! "CNC Line Following Algorithm" (blog post, 6 July 2009): one axis per
//! step, choosing the move that brings the tool closest to the goal.
//!
//! Moving axis a one unit toward the goal changes the squared distance to
//! the goal by -(2|r_a| - 1), r_a being what is left on that axis; so the
//! rule steps the axis with the most left. It runs along the longer axis
//! until the distances left are equal, then alternates: it heads for the
//! goal, not along the line.

use super::{LineRun, PlanLine, Record};
use super::{Mirror, TIE_AXIS, TieAxis, step_target};
use crate::algorithm_info::{AlgorithmInfo, Example, Family};
use crate::error::Error;
use crate::grid::{AXIS_NAMES, MAX_AXES, Point, Step, by_axis_count};
use crate::request::{FROM, MAX_STEPS, Request, TO};
use crate::trace::{Column, ColumnKind, Decision, Filled, Stepper};
use std::mem::MaybeUninit;

pub const ID: &str = "greedy";

pub const INFO: AlgorithmInfo = AlgorithmInfo {
    id: ID,
    example: Example {
        options: r#"{"from": [0, 0], "to": [8, 3]}"#,
        why: "The blog's rule runs along x until the remaining distances are equal.",
    },
    family: Family::Line,
    title: "Greedy step toward the goal, one axis at a time",
    citation: "\"CNC Line Following Algorithm\", blog post of 6 July 2009 (low-cost 3D printer series)",
    teaching: "Treat each step as a decision between single-axis moves toward the goal. Try each one in thought, compute the squared distance from where it would land to the goal (no square root needed: the smaller square is the smaller distance), and take the smallest; on a tie the lower axis (the post's xDist <= yDist picks x). Because a unit move on axis a shrinks the squared distance by 2|left on a| - 1, this always moves the axis with the most left: (0,0)->(8,3) runs along x to (6,0) and only then alternates up to (8,3). The speed is constant, but the path heads for the goal rather than following the line: it strays up to about a fifth of the move's length (0.22·|Δx| when |Δy| = 0.4·|Δx|), and the error per axis at each moment (Wang et al.'s eq. 11, against the ideal position after as many steps) is larger still. Compare walk6, which also moves one axis per step but follows the line.",
    errata: &[
        "The post's Python takes parameters (z0, y0, x1, y1) but uses x0: z0 should be x0.",
        "yIter = 1 if (x1 > x0) tests x instead of y (y1 > y0), so y's direction follows x's: while x still rises a y that should fall waits, and once x has arrived (x1 > x0 false, yIter = -1) a y that should rise never gets there. The post's own move (0,0)->(8,3) never ends, bouncing between (7,2) and (8,2) (the other typos fixed); so does every move with Δy > 0 (all 36 with |Δx|, |Δy| <= 4).",
        "y0 += tIter: tIter is undefined, it should be yIter.",
        "The function calls itself once per step, so Python's default recursion limit (1000) stops any move longer than about 1000 steps. voxpath runs it as a loop.",
    ],
    columns: GreedyWhy::COLUMNS,
    options: &[FROM, TO, TIE_AXIS, MAX_STEPS],
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
    let order = TieAxis::from_request(req)?;
    run.run(&INFO, req, |from, to, _| Greedy::new(from, to, order))
}

/// The decision behind one step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GreedyWhy {
    /// Per axis, the squared distance to the goal after a unit move on it
    /// toward the goal; None for an axis already at its goal coordinate.
    pub candidates: [Option<i128>; MAX_AXES],
    pub dims: usize,
    pub chosen: usize,
    /// Another candidate was exactly as close.
    pub tie: bool,
    pub order: TieAxis,
}

impl Decision for GreedyWhy {
    const COLUMNS: &'static [Column] = &[
        Column::new(
            "distSqX",
            ColumnKind::Float,
            "Squared distance to the goal if x moved one unit toward it (grid units^2, exact below 2^53); empty when x is already there.",
        )
        .formerly("dist2X"),
        Column::new(
            "distSqY",
            ColumnKind::Float,
            "Squared distance to the goal if y moved.",
        )
        .formerly("dist2Y"),
        Column::new(
            "distSqZ",
            ColumnKind::Float,
            "Squared distance to the goal if z moved.",
        )
        .formerly("dist2Z"),
        Column::new(
            "distSqA",
            ColumnKind::Float,
            "Squared distance to the goal if a moved.",
        )
        .formerly("dist2A"),
        Column::new(
            "distSqB",
            ColumnKind::Float,
            "Squared distance to the goal if b moved.",
        )
        .formerly("dist2B"),
        Column::new(
            "distSqC",
            ColumnKind::Float,
            "Squared distance to the goal if c moved.",
        )
        .formerly("dist2C"),
        Column::new(
            "axis",
            ColumnKind::Category { labels: &AXIS_NAMES },
            "The axis that moved: the candidate closest to the goal.",
        ),
        Column::new(
            "tie",
            ColumnKind::Flag,
            "1 when another axis was exactly as close and the tie order chose.",
        ),
    ];

    /// In the layout of its move's columns (`columns_of_axes!`): its axes only.
    fn write(&self, row: &mut [f64]) {
        for axis in 0..self.dims {
            row[axis] = self.candidates[axis].map_or(f64::NAN, |v| v as f64);
        }
        row[self.dims] = self.chosen as f64;
        row[self.dims + 1] = self.tie as u8 as f64;
    }

    fn is_tie(&self) -> bool {
        self.tie
    }

    fn explain(&self, _from: &Point, step: Step) -> String {
        let options: Vec<String> = (0..self.dims)
            .filter_map(|a| Some(format!("{} {}", AXIS_NAMES[a], self.candidates[a]?)))
            .collect();
        let name = AXIS_NAMES[self.chosen];
        let mut s = format!(
            "Squared distance to the goal after moving {}: {name} is the smallest",
            options.join(", ")
        );
        if self.tie {
            s.push_str(&format!(
                " (tied; the {} axis goes first)",
                self.order.label()
            ));
        }
        s.push_str(&format!(
            ", so {name} steps to {}.",
            step_target(step, self.dims)
        ));
        s
    }
}

/// The blog's greedy stepper, as a loop.
#[derive(Clone, Debug)]
pub struct Greedy {
    mirror: Mirror,
    /// Units left per axis to the goal.
    left: [i64; MAX_AXES],
    remaining: u64,
    order: TieAxis,
}

impl Greedy {
    pub fn new(from: Point, to: Point, order: TieAxis) -> Greedy {
        let mirror = Mirror::new(from, to);
        Greedy {
            mirror,
            left: std::array::from_fn(|a| {
                if a < from.dims() {
                    mirror.magnitude(a)
                } else {
                    0
                }
            }),
            remaining: mirror.total(),
            order,
        }
    }
}

// SAFETY: its fill's Filled counts the slots it wrote (see its Filled::written).
unsafe impl Stepper for Greedy {
    type Why = GreedyWhy;

    fn next_step(&mut self) -> Option<(Step, GreedyWhy)> {
        if self.remaining == 0 {
            return None;
        }
        self.remaining -= 1;
        let dims = self.mirror.dims();
        // Squared distance to the goal now, in i128: six axes of 2^31 squared.
        let now: i128 = self.left[..dims]
            .iter()
            .map(|&l| l as i128 * l as i128)
            .sum();
        let mut candidates = [None; MAX_AXES];
        let mut chosen: Option<usize> = None;
        for axis in 0..dims {
            let l = self.left[axis] as i128;
            if l == 0 {
                // The post's half-plane trick: only moves toward the goal.
                continue;
            }
            // Take a fake step: (l - 1)^2 replaces l^2 in the sum.
            let after = now - l * l + (l - 1) * (l - 1);
            candidates[axis] = Some(after);
            if chosen.is_none_or(|best| self.order.replaces(after.cmp(&candidates[best].unwrap())))
            {
                chosen = Some(axis);
            }
        }
        let chosen = chosen.expect("a move with steps left has an axis not yet at its goal");
        let best = candidates[chosen];
        let tie = (0..dims).any(|a| a != chosen && candidates[a] == best);
        self.left[chosen] -= 1;
        let why = GreedyWhy {
            candidates,
            dims,
            chosen,
            tie,
            order: self.order,
        };
        Some((self.mirror.toward(Step::NONE, chosen), why))
    }

    /// The same choices as [`Stepper::next_step`] without the squared
    /// distances ([`Greedy::fill_axes`]), with the number of axes a constant.
    fn fill(&mut self, out: &mut [MaybeUninit<Step>]) -> Filled {
        by_axis_count!(self.mirror.dims(), self.fill_axes(out))
    }

    fn remaining_steps(&self) -> Option<u64> {
        Some(self.remaining)
    }

    /// A run at a time ([`Greedy::ties_with`]), with the number of axes a
    /// constant.
    fn ties_ahead(self, steps: u64) -> u64 {
        by_axis_count!(self.mirror.dims(), self.ties_with(steps))
    }

    fn columns(&self) -> &'static [Column] {
        columns_of_axes!(GreedyWhy, 0, self.mirror.dims())
    }

    fn setup_note(&self) -> String {
        format!(
            "|Δ| = {}: {} single-axis steps, each to the candidate nearest the goal; ties go to the {} axis.{}",
            self.mirror.magnitudes_text(1),
            self.mirror.total(),
            self.order.label(),
            self.mirror.mirror_note()
        )
    }
}

impl Greedy {
    /// The runs the next `steps` steps come in, from the units left now: a
    /// step along `axis` turns l^2 into (l - 1)^2, changing the sum by
    /// 1 - 2l, so the candidate nearest the goal is the axis with the most
    /// units left, ties going in the order's turn. So the path is levels:
    /// the axes with the most left (one at first) each step once per
    /// round, in tie order, and after as many rounds as their lead over the
    /// next axis, that axis joins them; an axis at its goal is no
    /// candidate. `run` is called with each run's leaders in tie order
    /// and its length (whole rounds, the last one perhaps cut short by
    /// `steps`); returns the units left after them.
    #[inline(always)]
    fn for_each_run<const DIMS: usize>(
        &self,
        steps: u64,
        mut run: impl FnMut(&[usize], u64),
    ) -> [i64; MAX_AXES] {
        // The axes in the order a tie goes: the lower axis first, or the higher.
        let tie_order: [usize; DIMS] = std::array::from_fn(|k| match self.order {
            TieAxis::Lower => k,
            TieAxis::Higher => DIMS - 1 - k,
        });
        let mut left = self.left;
        let mut done = 0;
        while done < steps {
            // Within `steps` <= remaining, some axis has units left.
            let most = (0..DIMS).map(|a| left[a]).max().unwrap_or(0);
            debug_assert!(most > 0, "steps remain, so some axis has units left");
            let below = (0..DIMS)
                .map(|a| left[a])
                .filter(|&l| l < most)
                .max()
                .unwrap_or(0);
            let mut leaders = [0usize; DIMS];
            let mut count = 0;
            for &axis in &tie_order {
                if left[axis] == most {
                    leaders[count] = axis;
                    count += 1;
                }
            }
            // Rounds until the leaders are down to the next axis's units
            // left (or to their goal); the last may be cut short.
            let length = ((most - below) as u64)
                .saturating_mul(count as u64)
                .min(steps - done);
            run(&leaders[..count], length);
            // A leader steps once per whole round, and once more if the cut
            // round reached it (the cut round takes them in tie order).
            let count = count as u64;
            for (k, &axis) in (0u64..).zip(&leaders[..count as usize]) {
                left[axis] -= (length / count + u64::from(k < length % count)) as i64;
            }
            done += length;
        }
        left
    }

    /// [`Stepper::fill`] for `DIMS` axes: the same choices as
    /// [`Stepper::next_step`] without the squared distances, a run at a
    /// time ([`Self::for_each_run`]), each run written as one repeated
    /// pattern, with no comparison per step.
    #[inline(always)]
    fn fill_axes<const DIMS: usize>(&mut self, out: &mut [MaybeUninit<Step>]) -> Filled {
        let taken = out.len().min(self.remaining as usize);
        let toward: [Step; MAX_AXES] = std::array::from_fn(|a| self.mirror.toward(Step::NONE, a));
        let start = self.left;
        let mut written = 0;
        self.left = self.for_each_run::<DIMS>(taken as u64, |leaders, run| {
            let run = run as usize;
            // The run's first round, then what is written so far copied
            // after itself until the run is full: the copied stretch is a
            // whole number of rounds, so each step keeps its place in the
            // round. A run of n steps takes about log2(n / count) copies; in
            // wasm each copy is a memory.copy, a call into the engine, and a
            // copy of each round into a block of 64 made 115,840 of them in
            // the bench's line.
            let steps = &mut out[written..written + run];
            let first = leaders.len().min(run);
            for (slot, &axis) in steps.iter_mut().zip(&leaders[..first]) {
                slot.write(toward[axis]);
            }
            let mut filled = first;
            while filled < run {
                let more = filled.min(run - filled);
                steps.copy_within(..more, filled);
                filled += more;
            }
            written += run;
        });
        self.remaining -= taken as u64;
        // One step per unit no longer left, toward the end.
        let left = self.left;
        let displacement = std::array::from_fn(|a| self.mirror.sign(a) * (start[a] - left[a]));
        // SAFETY: each run wrote its `run` slots (its first round, then
        // copies of what it had written), the runs end to end up to `taken`.
        unsafe { Filled::written(taken, displacement) }
    }

    /// [`Stepper::ties_ahead`] for `DIMS` axes, a run at a time
    /// ([`Self::for_each_run`]): a step ties where another candidate is as
    /// near the goal, an axis with as many units left, which in a round of
    /// `count` leaders is every step but its last (the leaders after it
    /// are still level with it), and every step of a round cut short.
    /// With its ties counted by replay (a
    /// squared distance in i128 per candidate), the metrics of the bench's
    /// 4,600,004-step line took 296 ms in Node, 38 ms so.
    #[inline(always)]
    fn ties_with<const DIMS: usize>(&self, steps: u64) -> u64 {
        let mut ties = 0;
        self.for_each_run::<DIMS>(steps.min(self.remaining), |leaders, run| {
            let count = leaders.len() as u64;
            ties += run / count * (count - 1) + run % count;
        });
        ties
    }
}
