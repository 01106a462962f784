//! A 6-connected (4-connected in 2D) walk along the line: the cells the
//! ideal segment passes through, in the order it enters them. This is the
//! voxel traversal of Amanatides & Woo (1987) between two cell centers, kept
//! in integers.
//!
//! Grid points are cell centers, so the segment leaves the cell it is in
//! through a face of axis a when it has gone half a cell plus k_a whole
//! cells on that axis: at parameter t_a = (2·k_a + 1) / (2·|Δa|), k_a being
//! the steps that axis has taken. The face crossed first is the smallest
//! t_a; two fractions compare exactly by cross-multiplying, in i128.

use super::terms::{Term, Terms};
use super::{LineRun, PlanLine, Record};
use super::{Mirror, TIE_AXIS, TieAxis, axis_list, step_target};
use crate::algorithm_info::{AlgorithmInfo, Example, Family};
use crate::error::Error;
use crate::grid::{AXIS_NAMES, MAX_AXES, Point, Step, by_axis_count, written_steps};
use crate::request::{FROM, MAX_STEPS, Request, TO};
use crate::trace::{Column, ColumnKind, Decision, DeviationBound, Filled, Stepper};
use std::cmp::Ordering;
use std::mem::MaybeUninit;

pub const ID: &str = "walk6";

pub const INFO: AlgorithmInfo = AlgorithmInfo {
    id: ID,
    example: Example {
        options: r#"{"from": [0, 0], "to": [8, 3]}"#,
        why: "The same move as greedy's example, following the line.",
    },
    family: Family::Line,
    title: "6-connected walk through the cells the line crosses",
    citation: "Amanatides & Woo (1987), A Fast Voxel Traversal Algorithm for Ray Tracing, in integers between cell centers; the one-axis-per-step counterpart of the 2009 blog's greedy rule",
    teaching: "Think of each grid point as the center of a cell (a square, or a cube in 3D). Travelling along the ideal segment from the start center, the line leaves its cell through one face; the walk steps into the cell beyond that face, so it visits exactly the cells the segment passes through, one axis per step, |Δx| + |Δy| + |Δz| steps in all. On axis a the line crosses its next face at the fraction t_a = (2k_a + 1)/(2|Δa|) of the way, where k_a is how many faces of that axis it has crossed already; the face with the smallest t comes first. Fractions are compared by cross-multiplying, (2k_a + 1)·|Δb| against (2k_b + 1)·|Δa|, so no rounding ever decides. When two t are equal the line passes exactly through an edge (or a corner) where cells meet, and any of those axes may go first: voxpath steps the lower axis first by default (tieAxis = higher reverses it); the cell it passes through then touches the line only at that edge. Every visited cell touches the segment, so no center is farther than half a cell diagonal from the line: 1/sqrt(2) in 2D, sqrt(3)/2 in 3D.",
    errata: &[],
    columns: Walk6Why::COLUMNS,
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
    run.run(&INFO, req, |from, to, _| Walk6::new(from, to, order))
}

/// t = num / den, a fraction of the way along the segment.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Crossing {
    /// 2·k + 1: half a cell plus k whole cells.
    pub num: i64,
    /// 2·|Δ|.
    pub den: i64,
}

impl Crossing {
    /// Exact comparison by cross-multiplication: each product is at most
    /// (2^32 + 1)·2^32, beyond i64, so it is formed in i128.
    pub fn compare(self, other: Crossing) -> Ordering {
        (self.num as i128 * other.den as i128).cmp(&(other.num as i128 * self.den as i128))
    }

    fn value(self) -> f64 {
        self.num as f64 / self.den as f64
    }
}

/// The decision behind one step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Walk6Why {
    /// Per axis, where the segment crosses that axis's next face; None once
    /// the axis has arrived (or never moves).
    pub crossings: [Option<Crossing>; MAX_AXES],
    pub dims: usize,
    pub crossed: usize,
    /// Another axis crosses at exactly the same t (an edge or corner).
    pub tie: bool,
    pub order: TieAxis,
}

impl Decision for Walk6Why {
    const COLUMNS: &'static [Column] = &[
        Column::new(
            "crosses",
            ColumnKind::Category {
                labels: &AXIS_NAMES,
            },
            "The axis whose cell face the segment crosses next (the axis that steps).",
        ),
        Column::new(
            "tX",
            ColumnKind::Float,
            "Where the segment crosses the next x face, as a fraction of its length: (2k_x + 1)/(2|Δx|); empty when x has arrived.",
        ),
        Column::new(
            "tY",
            ColumnKind::Float,
            "Where the segment crosses the next y face: (2k_y + 1)/(2|Δy|).",
        ),
        Column::new(
            "tZ",
            ColumnKind::Float,
            "Where the segment crosses the next z face.",
        ),
        Column::new(
            "tA",
            ColumnKind::Float,
            "Where the segment crosses the next a face.",
        ),
        Column::new(
            "tB",
            ColumnKind::Float,
            "Where the segment crosses the next b face.",
        ),
        Column::new(
            "tC",
            ColumnKind::Float,
            "Where the segment crosses the next c face.",
        ),
        Column::new(
            "tie",
            ColumnKind::Flag,
            "1 when two axes cross at exactly the same t (an edge or corner) and the tie order chose.",
        ),
    ];

    /// In the layout of its move's columns (`columns_of_axes!`): its axes only.
    fn write(&self, row: &mut [f64]) {
        row[0] = self.crossed as f64;
        for axis in 0..self.dims {
            row[1 + axis] = self.crossings[axis].map_or(f64::NAN, Crossing::value);
        }
        row[1 + self.dims] = self.tie as u8 as f64;
    }

    fn is_tie(&self) -> bool {
        self.tie
    }

    fn explain(&self, _from: &Point, step: Step) -> String {
        let name = AXIS_NAMES[self.crossed];
        let c = self.crossings[self.crossed].expect("the crossed axis has a crossing");
        let mut s = format!(
            "The segment leaves this cell through its {name} face first, at t = {}/{}",
            c.num, c.den
        );
        // The runner-up: the next crossing among the other axes.
        let next = (0..self.dims)
            .filter(|&a| a != self.crossed)
            .filter_map(|a| Some((a, self.crossings[a]?)))
            .min_by(|x, y| x.1.compare(y.1));
        if let Some((other, o)) = next {
            let (lhs, rhs) = (c.num as i128 * o.den as i128, o.num as i128 * c.den as i128);
            let relation = if lhs < rhs { "<" } else { "=" };
            s.push_str(&format!(
                "; {} crosses at {}/{} ({}·{} = {lhs} {relation} {}·{} = {rhs})",
                AXIS_NAMES[other], o.num, o.den, c.num, o.den, o.num, c.den
            ));
        }
        if self.tie {
            let tied = (0..self.dims)
                .filter(|&a| self.crossings[a].is_some_and(|o| o.compare(c) == Ordering::Equal));
            s.push_str(&format!(
                "; the segment passes exactly where the {} faces meet, and the {} axis goes first",
                axis_list(tied),
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

/// The integer traversal.
#[derive(Clone, Debug)]
pub struct Walk6 {
    mirror: Mirror,
    /// Faces crossed per axis (k_a).
    crossed: [i64; MAX_AXES],
    remaining: u64,
    order: TieAxis,
}

impl Walk6 {
    pub fn new(from: Point, to: Point, order: TieAxis) -> Walk6 {
        let mirror = Mirror::new(from, to);
        Walk6 {
            mirror,
            crossed: [0; MAX_AXES],
            remaining: mirror.total(),
            order,
        }
    }

    fn crossing(&self, axis: usize) -> Option<Crossing> {
        let m = self.mirror.magnitude(axis);
        (self.crossed[axis] < m).then(|| Crossing {
            num: 2 * self.crossed[axis] + 1,
            den: 2 * m,
        })
    }
}

// SAFETY: its fill's Filled counts the slots it wrote (see its Filled::written).
unsafe impl Stepper for Walk6 {
    type Why = Walk6Why;

    fn next_step(&mut self) -> Option<(Step, Walk6Why)> {
        if self.remaining == 0 {
            return None;
        }
        self.remaining -= 1;
        let dims = self.mirror.dims();
        let crossings: [Option<Crossing>; MAX_AXES] =
            std::array::from_fn(|a| if a < dims { self.crossing(a) } else { None });
        let mut first: Option<usize> = None;
        for axis in 0..dims {
            let Some(c) = crossings[axis] else { continue };
            // The face the segment reaches first; equal t: the tie order.
            if first.is_none_or(|f| self.order.replaces(c.compare(crossings[f].unwrap()))) {
                first = Some(axis);
            }
        }
        let crossed = first.expect("a walk with steps left has a face ahead");
        let c = crossings[crossed].unwrap();
        let tie = (0..dims)
            .any(|a| a != crossed && crossings[a].is_some_and(|o| o.compare(c) == Ordering::Equal));
        self.crossed[crossed] += 1;
        let why = Walk6Why {
            crossings,
            dims,
            crossed,
            tie,
            order: self.order,
        };
        Some((self.mirror.toward(Step::NONE, crossed), why))
    }

    /// The same walk as [`Stepper::next_step`]: along one axis, that
    /// axis's steps; else on two or three axes by rounds of the major axis
    /// ([`Walk6::fill_rounds`]), the rest (more axes, a chunk's last steps,
    /// a last tie) a step at a time ([`Walk6::fill_axes`], with the number
    /// of axes a constant).
    fn fill(&mut self, out: &mut [MaybeUninit<Step>]) -> Filled {
        let taken = out.len().min(self.remaining as usize);
        let out = &mut out[..taken];
        let start = self.crossed;
        let dims = self.mirror.dims();
        let major = self.mirror.major();
        if self.mirror.total() == self.mirror.magnitude(major) as u64 {
            // One axis moves (a move along x, CNC's commonest): the segment
            // crosses that axis's faces only, every step is its step. By
            // rounds such a line took twice the 3D line's time per step,
            // and step by step in 4 to 6 axes ten times.
            out.fill(MaybeUninit::new(self.mirror.toward(Step::NONE, major)));
            self.crossed[major] += taken as i64;
        } else {
            let by_rounds = if dims <= 3 { self.fill_rounds(out) } else { 0 };
            by_axis_count!(dims, self.fill_axes(&mut out[by_rounds..]));
        }
        self.remaining -= taken as u64;
        // One step per face crossed, toward the end.
        let displacement =
            std::array::from_fn(|a| self.mirror.sign(a) * (self.crossed[a] - start[a]));
        // SAFETY: every slot of `out`, `taken` long, was written: by the
        // one axis's fill, or by rounds and then `fill_axes` after them.
        unsafe { Filled::written(taken, displacement) }
    }

    fn remaining_steps(&self) -> Option<u64> {
        Some(self.remaining)
    }

    /// A step at a time by the gaps ([`Walk6::ties_with`]), with the
    /// number of axes a constant.
    fn ties_ahead(self, steps: u64) -> u64 {
        by_axis_count!(self.mirror.dims(), self.ties_with(steps))
    }

    fn columns(&self) -> &'static [Column] {
        columns_of_axes!(Walk6Why, 1, self.mirror.dims())
    }

    /// Every cell the walk visits contains a point of the segment, so its
    /// center is within half the cell's diagonal of it: √D / 2 in D axes.
    fn deviation_bound(&self) -> Option<DeviationBound> {
        let dims = self.mirror.dims();
        Some(DeviationBound {
            value: (dims as f64).sqrt() / 2.0,
            why: format!(
                "every cell visited holds a point of the segment, so its center is within half a cell's diagonal, √{dims}/2, of the line"
            ),
        })
    }

    fn setup_note(&self) -> String {
        format!(
            "|Δ| = {}: the segment between the two cell centers crosses {} cell faces, one step each; exact edge or corner crossings step the {} axis first.{}",
            self.mirror.magnitudes_text(1),
            self.mirror.total(),
            self.order.label(),
            self.mirror.mirror_note()
        )
    }
}

/// Rounds a batch of [`Walk6::fill_rounds`] decides at most (their codes
/// are kept on the stack: 2 KiB).
const ROUNDS_PER_BATCH: usize = 1024;

/// Fewer rounds than this are decided one at a time: a batch's setup (its
/// terms' constants, their first eight values, a division per term for
/// the moves) costs about as much as these rounds.
const MIN_ROUNDS_PER_BATCH: usize = 64;

/// A batch with at least this many rounds per passive step takes its rounds
/// eight at a time where none has one ([`Walk6::fill_rounds`]): on a line
/// whose passive axes step in most rounds, the test per group made the
/// 3D line 20% slower.
const SPARSE_ROUNDS_PER_PASSIVE_STEP: usize = 16;

impl Walk6 {
    /// The walk's next `steps` steps on `DIMS` axes, as
    /// [`Stepper::next_step`] takes them but without multiplying, each
    /// handed to `step` with its axis and whether it tied (another axis's
    /// face at the same t); the state is left as it was. For each pair of
    /// axes a < b it carries gap_ab = (2k_a + 1)·|Δb| - (2k_b + 1)·|Δa|,
    /// which is t_a - t_b times 2|Δa||Δb|: a's face comes first when
    /// gap_ab < 0 (= 0 is an edge or corner, the tie order decides). A step
    /// of axis f adds 2|Δb| to gap_fb and takes 2|Δa| from gap_af; nothing
    /// else changes. An axis that never moves has t = ∞ and every gap says
    /// so (gap_ab = |Δb| > 0 when |Δa| = 0); an arrived axis, k = |Δ|, has
    /// its next t = 1 + 1/(2|Δ|), after every face still ahead (all before
    /// t = 1), so the order leaves both out with no test, and a gap of 0
    /// with the axis that steps is a face ahead at the same t. While two
    /// axes are under way both next t lie within 1/|Δ| past the current
    /// one, so |gap| stays within 2^33: i64, where the products of the
    /// cross multiplication need more (see [`Crossing::compare`]).
    /// The tie is found only with `TIES`: a recording loop has no use for
    /// it (a first version that found it in every walk, and wrote each
    /// step through an iterator, recorded a 4-axis walk of 4,600,004 + 900,001
    /// steps in 44 ms in Node against 27).
    #[inline(always)]
    fn walk_by_gaps<const DIMS: usize, const TIES: bool>(
        &self,
        steps: usize,
        mut step: impl FnMut(usize, usize, bool),
    ) {
        let magnitude: [i64; MAX_AXES] = std::array::from_fn(|a| {
            if a < DIMS {
                self.mirror.magnitude(a)
            } else {
                0
            }
        });
        // From the faces crossed so far; each product may pass i64, their
        // difference does not.
        let mut gap = [[0i64; MAX_AXES]; MAX_AXES];
        for a in 0..DIMS {
            for b in a + 1..DIMS {
                let t = |k: i64, m: i64| (2 * k as i128 + 1) * m as i128;
                gap[a][b] =
                    (t(self.crossed[a], magnitude[b]) - t(self.crossed[b], magnitude[a])) as i64;
            }
        }
        // a (lower) before b on a tie with the lower-axis order: gap < 1
        // rather than gap < 0.
        let lower_first = i64::from(self.order == TieAxis::Lower);
        for index in 0..steps {
            // The axis whose face comes before every other's: of the pairs
            // it is in, it wins each. Exactly one axis does (the order is
            // by t, then by axis on a tie).
            let mut first = DIMS - 1;
            for f in 0..DIMS - 1 {
                let mut wins = true;
                for other in 0..DIMS {
                    if other < f {
                        wins &= gap[other][f] >= lower_first;
                    } else if other > f {
                        wins &= gap[f][other] < lower_first;
                    }
                }
                // A select, not a branch: which face comes first is as
                // good as random to a branch predictor.
                first = if wins { f } else { first };
            }
            let tie = TIES
                && (0..DIMS)
                    .any(|other| other != first && gap[other.min(first)][other.max(first)] == 0);
            for a in 0..DIMS {
                for b in a + 1..DIMS {
                    gap[a][b] += if a == first { 2 * magnitude[b] } else { 0 };
                    gap[a][b] -= if b == first { 2 * magnitude[a] } else { 0 };
                }
            }
            step(index, first, tie);
        }
    }

    /// [`Stepper::fill`] for `DIMS` axes by [`Self::walk_by_gaps`]: fills
    /// all of `out` (the walk has that many steps left); no decision.
    #[inline(always)]
    fn fill_axes<const DIMS: usize>(&mut self, out: &mut [MaybeUninit<Step>]) {
        let toward: [Step; MAX_AXES] = std::array::from_fn(|a| self.mirror.toward(Step::NONE, a));
        self.walk_by_gaps::<DIMS, false>(out.len(), |index, first, _| {
            out[index].write(toward[first]);
        });
        // SAFETY: the walk wrote every slot, one a step.
        let out = unsafe { written_steps(out) };
        // The faces each axis crossed, counted from the steps written: a
        // pass the compiler vectorises, off the walk's chain of selects.
        for axis in 0..DIMS {
            self.crossed[axis] += out.iter().filter(|s| s.0 == toward[axis].0).count() as i64;
        }
    }

    /// [`Stepper::ties_ahead`] for `DIMS` axes by [`Self::walk_by_gaps`]:
    /// with its ties counted by replay (each step's faces compared in i128,
    /// [`Crossing::compare`], and its decision built), the metrics of the
    /// bench's 4,600,004-step line took 334 ms in Node, 56 ms so.
    #[inline(always)]
    fn ties_with<const DIMS: usize>(&self, steps: u64) -> u64 {
        let steps = usize::try_from(steps.min(self.remaining))
            .expect("a trace's steps (at most maxSteps, 10^9) count in a usize");
        let mut ties = 0;
        self.walk_by_gaps::<DIMS, true>(steps, |_, _, tie| ties += u64::from(tie));
        ties
    }

    /// The walk on two or three axes by rounds, each the steps up to and
    /// including one face of the major axis M (the largest |Δ|): between
    /// two of its faces, 1/|ΔM| apart, every other axis b crosses at most
    /// one (its faces are 1/|Δb| >= 1/|ΔM| apart), so a round is that
    /// axis's step where its face comes first (gap_bM = (2k_b + 1)|ΔM| -
    /// (2k_M + 1)|Δb| below 0, or 0 and b first in the tie order), the
    /// two passive axes' steps in their own order when both step, then
    /// M's step: 1 to 3 steps for one set of decisions, where
    /// [`Self::fill_axes`] decides every step. A third axis on a 2D walk
    /// has |Δ| = 0 and never steps. Whole rounds go into `out` while four
    /// slots are left (a round stores four codes) and M has faces ahead,
    /// most of them decided a batch at a time by the line rules' loop (see
    /// the batches below); returns the steps written (the rest is
    /// [`Self::fill_axes`]'s: the last steps of a chunk, and a passive
    /// axis's last face where it comes on M's last one, after it in the
    /// tie order). The gaps stay within 2^33, as there.
    fn fill_rounds(&mut self, out: &mut [MaybeUninit<Step>]) -> usize {
        let dims = self.mirror.dims();
        let major = self.mirror.major();
        // The passive axes in axis order; on a 2D walk the third is a
        // placeholder that never moves.
        let (p, q) = match major {
            0 => (1, 2),
            1 => (0, 2),
            _ => (0, 1),
        };
        let magnitude = |a: usize| {
            if a < dims {
                self.mirror.magnitude(a)
            } else {
                0
            }
        };
        let code = |a: usize| {
            if a < dims {
                self.mirror.toward(Step::NONE, a)
            } else {
                Step::NONE
            }
        };
        let (m, mp, mq) = (magnitude(major), magnitude(p), magnitude(q));
        let (step_m, step_p, step_q) = (code(major), code(p), code(q));
        let k = self.crossed;
        // (2k_a + 1)|Δb| - (2k_b + 1)|Δa|: each product may pass i64, the
        // difference does not.
        let gap = |a: usize, b: usize| {
            let t = |k: i64, m: i64| (2 * k as i128 + 1) * m as i128;
            (t(k[a], magnitude(b)) - t(k[b], magnitude(a))) as i64
        };
        let (mut gap_pm, mut gap_qm, mut gap_pq) = (gap(p, major), gap(q, major), gap(p, q));
        // The first of a pair on a tie: the lower axis with the lower-axis
        // order; a before b when gap_ab < bias.
        let lower = i64::from(self.order == TieAxis::Lower);
        let bias = |a: usize, b: usize| if a < b { lower } else { 1 - lower };
        let (bias_pm, bias_qm, bias_pq) = (bias(p, major), bias(q, major), bias(p, q));
        let rounds = (m - k[major]).max(0) as usize;
        let (mut written, mut round) = (0, 0);
        let (mut moved_p, mut moved_q) = (0, 0);
        // A round's steps by what it decides (p steps, q steps, p's face
        // before q's), four codes of which the round's 1 to 3 count, so
        // that a round writes them with one 8-byte store and its length
        // decides where the next one starts (over the codes past it).
        let rounds_by_decisions: [[Step; 4]; 8] = std::array::from_fn(|i| {
            let (steps_p, steps_q, p_before_q) = (i & 1 == 1, i & 2 == 2, i & 4 == 4);
            let (first, second) = if p_before_q {
                (step_p, step_q)
            } else {
                (step_q, step_p)
            };
            match (steps_p, steps_q) {
                (false, false) => [step_m; 4],
                (true, false) => [step_p, step_m, step_m, step_m],
                (false, true) => [step_q, step_m, step_m, step_m],
                (true, true) => [first, second, step_m, step_m],
            }
        });
        // What a round adds to gap_pM and gap_qM: M's face is crossed
        // every round (- 2|Δp|), p's when p steps (+ 2|ΔM|); likewise q.
        let (pm_moved, pm_stayed) = (2 * m - 2 * mp, -2 * mp);
        let (qm_moved, qm_stayed) = (2 * m - 2 * mq, -2 * mq);
        let (step_pq_p, step_pq_q) = (2 * mq, 2 * mp);
        // What a round adds to gap_pq, by its code below: p's face crossed
        // (+ 2|Δq|), q's (- 2|Δp|).
        let pq_moves = [0, step_pq_p, -step_pq_q, step_pq_p - step_pq_q];
        let mut round_codes = [MaybeUninit::uninit(); ROUNDS_PER_BATCH];
        let base = out.as_mut_ptr();
        // Rounds one at a time up to `until`: first the rest of a round a
        // chunk may have ended in, so that the batches start where a round
        // does; after the batches, those too few for one.
        let mut until = rounds.min(1);
        for batches_next in [true, false] {
            while round < until && written + 4 <= out.len() {
                let steps_p = gap_pm < bias_pm;
                let steps_q = gap_qm < bias_qm;
                let p_before_q = gap_pq < bias_pq;
                let codes = rounds_by_decisions[usize::from(steps_p)
                    | usize::from(steps_q) << 1
                    | usize::from(p_before_q) << 2];
                // SAFETY: written + 4 <= out.len(): the four codes land in
                // `out`, which this call borrows mutably.
                unsafe { base.add(written).cast::<[Step; 4]>().write_unaligned(codes) };
                written += 1 + usize::from(steps_p) + usize::from(steps_q);
                // Each gap's next value by a select of two constants: the
                // gaps are the loop's chains of dependent instructions, and
                // a select is one instruction where a multiply by the 0-or-1
                // decision took three cycles.
                gap_pm += if steps_p { pm_moved } else { pm_stayed };
                gap_qm += if steps_q { qm_moved } else { qm_stayed };
                gap_pq += if steps_p { step_pq_p } else { 0 };
                gap_pq -= if steps_q { step_pq_q } else { 0 };
                moved_p += i64::from(steps_p);
                moved_q += i64::from(steps_q);
                round += 1;
            }
            if !batches_next {
                break;
            }
            // Then rounds a batch at a time, in two passes. Whether p
            // steps in a round is a line rule's term ([`Term`]): it steps
            // when -gap_pM > -bias, and a round adds 2|Δp| to -gap_pM and
            // takes 2|ΔM| off when p stepped; likewise q. So the first
            // pass is the line rules' recording loop ([`Terms::fill`],
            // eight rounds at a time where the terms fit 32 bits, with no
            // chain from one round to the next), a round's code having
            // bit 1 where p steps and bit 2 where q does. The second
            // writes each round's steps, p's and q's order from gap_pq,
            // which the codes move on: its chains are two additions, where
            // the loop above carries three of a comparison, a select and
            // an addition. At a round's start each gap lies in its term's
            // window (see [`Term::fits_i32`]), as those loops need.
            loop {
                // Each round writes four codes from where it starts, 1 to
                // 3 of which count: n rounds fit in 3n + 1 slots.
                let batch = (rounds - round)
                    .min(out.len().saturating_sub(written + 1) / 3)
                    .min(ROUNDS_PER_BATCH);
                if batch < MIN_ROUNDS_PER_BATCH {
                    break;
                }
                let term = |gap: i64, moves: i64, bias: i64, bit: u16| Term {
                    value: -gap,
                    increment: 2 * moves,
                    decrement: 2 * m,
                    steps_above: -bias,
                    step: Step(bit),
                };
                let mut terms = Terms {
                    always: Step::NONE,
                    terms: [term(gap_pm, mp, bias_pm, 1), term(gap_qm, mq, bias_qm, 2)],
                };
                // Bits 1 and 2 read as steps of +x and +y: how many of the
                // rounds p and q stepped in.
                let [steps_p, steps_q, ..] = terms.fill(&mut round_codes[..batch]);
                // Each round's steps, four codes of which 1 to 3 count.
                let write_round = |code: Step, written: &mut usize, gap_pq: &mut i64| {
                    let decided = code.0 as usize & 3;
                    let p_before_q = usize::from(*gap_pq < bias_pq);
                    // SAFETY: at most 3 codes count per round, and the batch
                    // was cut so that the last round's four land in `out`.
                    unsafe {
                        base.add(*written)
                            .cast::<[Step; 4]>()
                            .write_unaligned(rounds_by_decisions[decided | p_before_q << 2])
                    };
                    *written += 1 + (decided & 1) + (decided >> 1);
                    *gap_pq += pq_moves[decided];
                };
                // SAFETY: Terms::fill wrote every one of the batch's slots.
                let codes = unsafe { written_steps(&round_codes[..batch]) };
                let passive_steps = (steps_p + steps_q) as usize;
                if passive_steps * SPARSE_ROUNDS_PER_PASSIVE_STEP > batch {
                    for &code in codes {
                        write_round(code, &mut written, &mut gap_pq);
                    }
                } else if passive_steps == 0 {
                    // Neither passive axis steps (a line along one axis,
                    // CNC's commonest move, or a batch of a nearly aligned
                    // one): M's steps alone, gap_pq unmoved. Round by
                    // round such a line took twice the 3D line's time per
                    // step (2M steps along x: 2.1 ms natively).
                    // SAFETY: the batch's `batch` steps land in `out`.
                    unsafe { std::slice::from_raw_parts_mut(base.add(written), batch) }
                        .fill(MaybeUninit::new(step_m));
                    written += batch;
                } else {
                    // A passive axis steps now and then: eight rounds at a
                    // time where neither does, in one store.
                    for group in codes.chunks(8) {
                        if group.len() == 8 && group.iter().all(|code| code.0 == 0) {
                            // SAFETY: these 8 rounds' 8 steps count, and
                            // every step of the batch lands in `out`.
                            unsafe {
                                base.add(written)
                                    .cast::<[Step; 8]>()
                                    .write_unaligned([step_m; 8])
                            };
                            written += 8;
                        } else {
                            for &code in group {
                                write_round(code, &mut written, &mut gap_pq);
                            }
                        }
                    }
                }
                [gap_pm, gap_qm] = terms.terms.map(|t| -t.value);
                (moved_p, moved_q) = (moved_p + steps_p, moved_q + steps_q);
                round += batch;
            }
            until = rounds;
        }
        self.crossed[major] += round as i64;
        self.crossed[p] += moved_p;
        if q < dims {
            self.crossed[q] += moved_q;
        }
        written
    }
}
