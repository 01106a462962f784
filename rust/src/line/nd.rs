//! Wang et al. (2020), section 3.4: the discriminant of section 2.4 once per
//! passive axis, for 2 to 6 axes (X Y Z A B C). Eq. (16)-(17) write it for
//! the fourth and fifth axes (H for A, K for B); with three axes it is the
//! method of discriminate regions, M and N.

use super::terms::{Term, Terms};
use super::{GCD, Mirror, axis_list, signed_comparison, step_target, wang_discriminant};
use super::{LineRun, PlanLine, Record};
use crate::algorithm_info::{AlgorithmInfo, Example, Family};
use crate::error::Error;
use crate::grid::{AXIS_NAMES, MAX_AXES, Point, Step};
use crate::request::{FROM, MAX_STEPS, Request, TO, TiePolicy, tie_option};
use crate::trace::{Column, ColumnKind, Decision, DeviationBound, Filled, Stepper};
use std::mem::MaybeUninit;

pub const ID: &str = "nd";

pub const INFO: AlgorithmInfo = AlgorithmInfo {
    id: ID,
    example: Example {
        options: r#"{"from": [0, 0, 0, 0, 0], "to": [10, 7, 6, 5, 3]}"#,
        why: "Five axes (Wang eq. 16-17): H and K join M and N.",
    },
    family: Family::Line,
    title: "Discriminants per passive axis, 2 to 6 axes",
    citation: "Wang, Xiao, Song, Yue, Bian & Li (2020), Spatial Straight-Line Drawing Algorithm Based on Method of Discriminate Regions, section 3.4, eq. (16)-(17) with eq. (6), (8), (10)",
    teaching: "The axes that move farthest are active and step every time. Every other axis a keeps its own integer discriminant D_a, exactly as M and N do in 3D: it starts at 2|Δa| - |Δactive| (eq. 17), grows by 2|Δa| per step and shrinks by 2|Δactive| when a steps (eq. 16). a steps when D_a > 0 (the ideal line is past the middle of the cell on that axis when it leaves the cell), and on D_a = 0 as the tie policy says. The axes never consult each other, so each passive coordinate is the one nearest the ideal line at that active position: within 1/2 per passive axis, so the point is within sqrt(P)/2 of the line for P passive axes (sqrt(2)/2 in 3D, sqrt(5)/2 with six axes).",
    errata: &[
        "Section 3.4 says 'when H_{i+1} > 0, A_{i+1} = A_i + 1', one index later than eq. (8) and the region rules, where D_i decides the step to point i + 1. voxpath follows eq. (8): the discriminant before a step decides it.",
        "The paper leaves D = 0 open; voxpath makes it the tie option (advance, as Liu's Table 1, by default).",
    ],
    columns: NdWhy::COLUMNS,
    options: &[FROM, TO, tie_option("advance"), GCD, MAX_STEPS],
    min_dims: 2,
    max_dims: MAX_AXES,
    default_tie: Some(TiePolicy::Advance),
    compared_by: None,
    trace: |req, _| run(req, Record),
    plan: Some(|req, _| run(req, PlanLine)),
};

/// Reads this algorithm's own options and runs its stepper as `run` says
/// (recorded or planned: [`LineRun`]).
fn run<R: LineRun>(req: &Request, run: R) -> Result<R::Out, Error> {
    let gcd = super::gcd_option(req)?;
    run.run(&INFO, req, |from, to, tie| Nd::new(from, to, tie, gcd))
}

/// The decision behind one step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NdWhy {
    /// Per axis, the discriminant before the step; None for active axes.
    pub discriminants: [Option<i64>; MAX_AXES],
    pub dims: usize,
    pub tie: bool,
    pub tie_policy: TiePolicy,
}

impl NdWhy {
    /// Each axis's discriminant, x to c.
    const DISCRIMINANTS: [Column; MAX_AXES] = [
        Column::new(
            "discriminantX",
            ColumnKind::Int,
            "Discriminant of x before the step (Wang eq. 6/16; Dx in the explanation); empty when x is active.",
        )
        .formerly("Dx"),
        Column::new(
            "discriminantY",
            ColumnKind::Int,
            "Discriminant of y before the step (Wang's M when x is active).",
        )
        .formerly("Dy"),
        Column::new(
            "discriminantZ",
            ColumnKind::Int,
            "Discriminant of z before the step (Wang's N when x is active).",
        )
        .formerly("Dz"),
        Column::new(
            "discriminantA",
            ColumnKind::Int,
            "Discriminant of a before the step (Wang's H, eq. 16-17).",
        )
        .formerly("Da"),
        Column::new(
            "discriminantB",
            ColumnKind::Int,
            "Discriminant of b before the step (Wang's K, eq. 16-17).",
        )
        .formerly("Db"),
        Column::new(
            "discriminantC",
            ColumnKind::Int,
            "Discriminant of c before the step.",
        )
        .formerly("Dc"),
    ];

    const TIE: Column = Column::new(
        "tie",
        ColumnKind::Flag,
        "1 when a discriminant was exactly 0 and the tie policy decided.",
    );
}

impl Decision for NdWhy {
    /// Every axis's discriminant, then the tie flag; a move carries those of
    /// its own axes (`columns_of_axes!`).
    const COLUMNS: &'static [Column] = &{
        let mut columns = [NdWhy::TIE; MAX_AXES + 1];
        let mut axis = 0;
        while axis < MAX_AXES {
            columns[axis] = NdWhy::DISCRIMINANTS[axis];
            axis += 1;
        }
        columns
    };

    /// In the layout of its move's columns (`columns_of_axes!`): its axes' discriminants, then the tie.
    fn write(&self, row: &mut [f64]) {
        for axis in 0..self.dims {
            row[axis] = self.discriminants[axis].map_or(f64::NAN, |v| v as f64);
        }
        row[self.dims] = self.tie as u8 as f64;
    }

    fn is_tie(&self) -> bool {
        self.tie
    }

    fn explain(&self, _from: &Point, step: Step) -> String {
        let active: Vec<usize> = (0..self.dims)
            .filter(|&a| self.discriminants[a].is_none())
            .collect();
        let verb = if active.len() == 1 { "steps" } else { "step" };
        let mut s = format!("{} {verb} as active", axis_list(active.into_iter()));
        for axis in 0..self.dims {
            let Some(d) = self.discriminants[axis] else {
                continue;
            };
            let name = AXIS_NAMES[axis];
            let verdict = match d.signum() {
                1 => "steps".to_string(),
                -1 => "holds".to_string(),
                _ => format!(
                    "is a tie, and '{}' {}",
                    self.tie_policy.label(),
                    if step.delta(axis) != 0 {
                        "steps it"
                    } else {
                        "holds it"
                    }
                ),
            };
            s.push_str(&format!(
                "; D{name} = {}, so {name} {verdict}",
                signed_comparison(d)
            ));
        }
        s.push_str(&format!(
            "; the step goes to {}.",
            step_target(step, self.dims)
        ));
        s
    }
}

/// Wang's n-axis stepper.
#[derive(Clone, Debug)]
pub struct Nd {
    mirror: Mirror,
    /// |Δ| per axis divided by `divisor`: what the discriminants use.
    magnitude: [i64; MAX_AXES],
    divisor: i64,
    /// |Δ| of the active axes divided by `divisor` (the paper's Δx).
    longest: i64,
    /// D per passive axis (eq. 16 recurrence); |D| <= 3·2^31 fits i64.
    discriminant: [Option<i64>; MAX_AXES],
    remaining: u64,
    tie: TiePolicy,
}

impl Nd {
    pub fn new(from: Point, to: Point, tie: TiePolicy, gcd: bool) -> Nd {
        let mirror = Mirror::new(from, to);
        let divisor = mirror.divisor(gcd);
        let magnitude = std::array::from_fn(|a| {
            if a < mirror.dims() {
                mirror.reduced(a, divisor)
            } else {
                0
            }
        });
        let longest = mirror.reduced(mirror.major(), divisor);
        let discriminant = std::array::from_fn(|a| {
            // Eq. (17): H_1 = 2ΔA - Δx.
            (a < mirror.dims() && !mirror.is_active(a)).then(|| 2 * magnitude[a] - longest)
        });
        Nd {
            mirror,
            magnitude,
            divisor,
            longest,
            discriminant,
            remaining: mirror.longest() as u64,
            tie,
        }
    }

    /// The passive axes (those with a discriminant) in axis order with
    /// their discriminants, and how many there are: at most MAX_AXES - 1,
    /// since the longest axis is active.
    fn passive_axes(&self) -> ([(usize, i64); MAX_AXES], usize) {
        let mut passive = [(0, 0); MAX_AXES];
        let mut count = 0;
        for (axis, d) in self.discriminant.iter().enumerate() {
            if let Some(d) = *d {
                passive[count] = (axis, d);
                count += 1;
            }
        }
        (passive, count)
    }

    /// The discriminants of `passive` ([`Self::passive_axes`]) as
    /// [`Terms`]' terms, in the same order (eq. 16: an axis steps when
    /// D > 0, a tie when D = 0; D grows by 2ΔA and drops by 2Δx when A
    /// steps).
    fn terms_of(&self, passive: &[(usize, i64); MAX_AXES]) -> [Term; MAX_AXES] {
        std::array::from_fn(|i| {
            let (axis, d) = passive[i];
            Term {
                value: d,
                increment: 2 * self.magnitude[axis],
                decrement: 2 * self.longest,
                steps_above: Term::steps_above(0, self.tie),
                step: self.mirror.toward(Step::NONE, axis),
            }
        })
    }

    /// Records `out` with the `N` passive axes' discriminants as [`Terms`]
    /// ([`Self::terms_of`]).
    fn fill_with<const N: usize>(&mut self, out: &mut [MaybeUninit<Step>]) -> [i64; MAX_AXES] {
        let (passive, _) = self.passive_axes();
        let passive_terms = self.terms_of(&passive);
        let always = (0..self.mirror.dims())
            .filter(|&a| self.discriminant[a].is_none())
            .fold(Step::NONE, |step, axis| self.mirror.toward(step, axis));
        let mut terms = Terms {
            always,
            terms: std::array::from_fn::<_, N, _>(|i| passive_terms[i]),
        };
        let displacement = terms.fill(out);
        for (&(axis, _), term) in passive.iter().zip(&terms.terms) {
            self.discriminant[axis] = Some(term.value);
        }
        displacement
    }

    /// Eq. (6) generalised: D_a at point `p` from the point alone (see
    /// [`wang_discriminant`]), exact anywhere within +-2^30.
    pub fn closed_form(&self, p: &Point) -> [Option<i64>; MAX_AXES] {
        let reference = self.mirror.progress(p, self.mirror.major());
        std::array::from_fn(|a| {
            self.discriminant[a]?;
            let progress = self.mirror.progress(p, a);
            Some(wang_discriminant(self.magnitude[a], self.longest, reference, progress) as i64)
        })
    }
}

// SAFETY: its fill's Filled counts the slots it wrote (see its Filled::written).
unsafe impl Stepper for Nd {
    type Why = NdWhy;

    fn next_step(&mut self) -> Option<(Step, NdWhy)> {
        if self.remaining == 0 {
            return None;
        }
        self.remaining -= 1;
        let mut step = Step::NONE;
        let mut tie = false;
        let discriminants = self.discriminant;
        for axis in 0..self.mirror.dims() {
            let Some(d) = &mut self.discriminant[axis] else {
                // Active axes progress one unit every step (section 2.2).
                step = self.mirror.toward(step, axis);
                continue;
            };
            // Past the middle of the cell: step; exactly on it: the tie policy.
            let moves = *d > 0 || (*d == 0 && self.tie == TiePolicy::Advance);
            tie |= *d == 0;
            if moves {
                step = self.mirror.toward(step, axis);
            }
            // Eq. (16): H_{i+1} = H_i + 2ΔA - 2Δx (A_{i+1} - A_i).
            *d += 2 * self.magnitude[axis] - 2 * self.longest * moves as i64;
        }
        let why = NdWhy {
            discriminants,
            dims: self.mirror.dims(),
            tie,
            tie_policy: self.tie,
        };
        Some((step, why))
    }

    /// The steps of [`Stepper::next_step`] through the shared branch-free
    /// loop ([`Terms`]), with no decision built; one loop per number of
    /// passive axes, so that each unrolls.
    fn fill(&mut self, out: &mut [MaybeUninit<Step>]) -> Filled {
        let taken = out.len().min(self.remaining as usize);
        let out = &mut out[..taken];
        let displacement = match self.passive_axes().1 {
            0 => self.fill_with::<0>(out),
            1 => self.fill_with::<1>(out),
            2 => self.fill_with::<2>(out),
            3 => self.fill_with::<3>(out),
            4 => self.fill_with::<4>(out),
            _ => self.fill_with::<5>(out),
        };
        self.remaining -= taken as u64;
        // SAFETY: Terms::fill wrote every one of the `taken` slots.
        unsafe { Filled::written(taken, displacement) }
    }

    fn remaining_steps(&self) -> Option<u64> {
        Some(self.remaining)
    }

    /// A step is a tie where any passive axis's discriminant is 0 (eq.
    /// 16), counted from the discriminants' terms in closed form
    /// ([`Term::values_equal_in_any`]): with its ties counted by replay,
    /// the metrics of the bench's 2,000,000-step 3D line took 71 ms in
    /// Node, 17 to 18 ms so.
    fn ties_ahead(self, steps: u64) -> u64 {
        let (passive, count) = self.passive_axes();
        let terms = self.terms_of(&passive);
        Term::values_equal_in_any(&terms[..count], 0, steps.min(self.remaining))
    }

    fn columns(&self) -> &'static [Column] {
        columns_of_axes!(NdWhy, 0, self.mirror.dims())
    }

    fn deviation_bound(&self) -> Option<DeviationBound> {
        Some(super::half_cell_per_passive_axis(&self.mirror))
    }

    fn setup_note(&self) -> String {
        let dims = self.mirror.dims();
        let active = (0..dims).filter(|&a| self.discriminant[a].is_none());
        let mut s = format!(
            "|Δ| = {}; active: {}",
            self.mirror.magnitudes_text(1),
            axis_list(active)
        );
        for axis in 0..dims {
            if let Some(d) = self.discriminant[axis] {
                s.push_str(&format!(
                    "; D{n}_1 = 2|Δ{n}| - |Δactive| = 2·{} - {} = {d}",
                    self.magnitude[axis],
                    self.longest,
                    n = AXIS_NAMES[axis]
                ));
            }
        }
        s.push_str(" (eq. 17).");
        s.push_str(&self.mirror.divisor_note(self.divisor));
        s.push_str(self.mirror.mirror_note());
        s
    }
}
