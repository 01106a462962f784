//! Saleem & Saleem (2004), section 3: Bresenham's rule extended to 3D by
//! splitting the line into two plane lines that share the major axis; and
//! Liu & Cheng (2002), the same extension stepping on a tie (as Wang's
//! Table 1 reproduces it).
//!
//! The major axis steps every time; each of the two other axes runs the 2D
//! rule of section 2 ([`SaleemTerm`]) on its own plane line.

use super::bresenham2d::{SaleemTerm, SaleemTest};
use super::terms::{Term, Terms};
use super::{GCD, Mirror, axis_list, step_target};
use super::{LineRun, PlanLine, Record};
use crate::algorithm_info::{AlgorithmInfo, Example, Family};
use crate::error::Error;
use crate::figure::{DecisionFigure, ErrorTerm, ErrorTerms, FigureKind};
use crate::grid::{AXIS_NAMES, Point, Step};
use crate::request::{FROM, MAX_STEPS, Request, TO, TiePolicy, tie_option};
use crate::trace::{Column, ColumnKind, ColumnRole, Decision, DeviationBound, Filled, Stepper};
use std::mem::MaybeUninit;

pub const ID: &str = "bresenham3d";

pub const INFO: AlgorithmInfo = AlgorithmInfo {
    id: ID,
    example: Example {
        options: r#"{"from": [0, 0, 0], "to": [10, 7, 6]}"#,
        why: "Wang's line: Saleem's strict rule holds at step 5 where Wang steps.",
    },
    family: Family::Line,
    title: "Bresenham's line in 3D (Saleem; with tie = advance, Liu's rule)",
    citation: "Saleem & Saleem (2004), Bresenham type fast algorithm for 3-D linear and helical movement in CNC machines, section 3; Liu & Cheng (2002), as reproduced in Wang et al. (2020), Table 1",
    teaching: "Find the axis that moves farthest (the major axis): it steps every time. The 3D line is then two plane lines sharing that axis, and each other axis runs the 2D rule on its own: its error starts at 0, grows by 2|Δminor| per step, and when it exceeds |Δmajor| the axis steps and the error drops by 2|Δmajor|. Saleem steps only when the error is strictly greater (tie = hold): on (0,0,0)->(10,7,6) step 5 goes to (5,3,3). Liu (2002) steps on equality too (tie = advance), which gives Wang's (5,4,3) and equals the method of discriminate regions point for point: Saleem's error minus |Δmajor| is Wang's discriminant.",
    errata: &[
        "The pseudo-code writes out only the z-major case ('Other two cases can be implemented in similar way'); voxpath runs the same rule with x or y as the major axis.",
        "The printed test 'DeltaZ > DeltaX & DeltaZ > DeltaY' is strict, so a line whose two largest |Δ| are equal (for example (4,4,1)) matches none of the three cases. voxpath takes the lower-index axis as major; the other one's error then exceeds |Δmajor| every step, so it steps every time too.",
        "Spelling slips a literal transcription would trip on: 'errorX'/'ErrorX', 'incremenetY' for incY, '2DelatZ' for 2DeltaZ.",
    ],
    columns: Bresenham3dWhy::COLUMNS,
    options: &[FROM, TO, tie_option("hold"), GCD, MAX_STEPS],
    min_dims: 3,
    max_dims: 3,
    default_tie: Some(TiePolicy::Hold),
    compared_by: None,
    trace: |req, _| run(req, Record),
    plan: Some(|req, _| run(req, PlanLine)),
};

/// Reads this algorithm's own options and runs its stepper as `run` says
/// (recorded or planned: [`LineRun`]).
fn run<R: LineRun>(req: &Request, run: R) -> Result<R::Out, Error> {
    let gcd = super::gcd_option(req)?;
    run.run(&INFO, req, |from, to, tie| {
        Bresenham3d::new(from, to, tie, gcd)
    })
}

/// The decision behind one step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bresenham3dWhy {
    pub major: usize,
    /// Per axis: the error test of a minor axis, None for the major axis.
    pub tests: [Option<SaleemTest>; 3],
    pub threshold: i64,
    pub tie_policy: TiePolicy,
}

impl Decision for Bresenham3dWhy {
    const COLUMNS: &'static [Column] = &[
        Column::new(
            "errorX",
            ColumnKind::Int,
            "Saleem's ErrorX after adding 2|Δx| (section 3), compared with |Δmajor|; empty when x is the major axis.",
        )
        .with_role(ColumnRole::ErrorTerm),
        Column::new(
            "errorY",
            ColumnKind::Int,
            "Saleem's ErrorY after adding 2|Δy|, compared with |Δmajor|; empty when y is the major axis.",
        )
        .with_role(ColumnRole::ErrorTerm),
        Column::new(
            "errorZ",
            ColumnKind::Int,
            "Saleem's ErrorZ after adding 2|Δz|, compared with |Δmajor|; empty when z is the major axis.",
        )
        .with_role(ColumnRole::ErrorTerm),
        Column::new(
            "threshold",
            ColumnKind::Int,
            "|Δmajor| (divided by the GCD with gcd = true): a minor axis steps when its error exceeds it.",
        )
        .with_role(ColumnRole::Threshold),
        Column::new(
            "major",
            ColumnKind::Category { labels: &["x", "y", "z"] },
            "The major axis, which steps every time.",
        ),
        Column::new(
            "tie",
            ColumnKind::Flag,
            "1 when an error equalled the threshold and the tie policy decided.",
        ),
    ];

    fn write(&self, row: &mut [f64]) {
        for axis in 0..3 {
            row[axis] = self.tests[axis].map_or(f64::NAN, |t| t.tested as f64);
        }
        row[3] = self.threshold as f64;
        row[4] = self.major as f64;
        row[5] = self.is_tie() as u8 as f64;
    }

    fn is_tie(&self) -> bool {
        self.tests.iter().flatten().any(|t| t.tie)
    }

    const FIGURE: Option<FigureKind> = Some(FigureKind::ErrorTerms);

    /// Each minor axis's error; its column (errorX, ...) is the axis's, the
    /// first three of [`Decision::COLUMNS`].
    fn figure(&self, _from: &Point, _step: Step) -> Option<DecisionFigure> {
        let terms = (0..3)
            .filter_map(|axis| {
                self.tests[axis].map(|t| ErrorTerm {
                    name: Self::COLUMNS[axis].name,
                    value: t.tested,
                    steps: t.steps,
                })
            })
            .collect();
        Some(DecisionFigure::ErrorTerms(ErrorTerms {
            terms,
            threshold: self.threshold,
        }))
    }

    fn explain(&self, _from: &Point, step: Step) -> String {
        let mut s = format!("{} is the major axis and steps", AXIS_NAMES[self.major]);
        for (axis, test) in self.tests.iter().enumerate() {
            let Some(t) = test else { continue };
            let name = AXIS_NAMES[axis];
            let verdict = match t.tested.cmp(&self.threshold) {
                std::cmp::Ordering::Greater => {
                    format!("{} > {}, so {name} steps", t.tested, self.threshold)
                }
                std::cmp::Ordering::Less => {
                    format!("{} < {}, so {name} holds", t.tested, self.threshold)
                }
                std::cmp::Ordering::Equal => format!(
                    "{} = {} (a tie), and the tie policy '{}' says {name} {}",
                    t.tested,
                    self.threshold,
                    self.tie_policy.label(),
                    if t.steps { "steps" } else { "holds" }
                ),
            };
            s.push_str(&format!("; error{} = {verdict}", name.to_uppercase()));
        }
        s.push_str(&format!("; the step goes to {}.", step_target(step, 3)));
        s
    }
}

/// The 3D stepper of Saleem section 3 (Liu's with tie = advance).
#[derive(Clone, Debug)]
pub struct Bresenham3d {
    mirror: Mirror,
    major: usize,
    divisor: i64,
    /// The two minor axes, in axis order, and their error terms.
    minors: [usize; 2],
    terms: [SaleemTerm; 2],
    remaining: u64,
    tie: TiePolicy,
}

impl Bresenham3d {
    /// With `gcd`, the error terms run on |Δ| divided by their GCD (Wang
    /// section 4): each is then that many times smaller, same decisions.
    pub fn new(from: Point, to: Point, tie: TiePolicy, gcd: bool) -> Bresenham3d {
        let mirror = Mirror::new(from, to);
        let major = mirror.major();
        let divisor = mirror.divisor(gcd);
        let major_len = mirror.reduced(major, divisor);
        let minors = match major {
            0 => [1, 2],
            1 => [0, 2],
            _ => [0, 1],
        };
        let terms = minors
            .map(|axis| SaleemTerm::new(mirror.reduced(axis, divisor), major_len, 2 * major_len));
        Bresenham3d {
            mirror,
            major,
            divisor,
            minors,
            terms,
            remaining: mirror.longest() as u64,
            tie,
        }
    }
}

// SAFETY: its fill's Filled counts the slots it wrote (see its Filled::written).
unsafe impl Stepper for Bresenham3d {
    type Why = Bresenham3dWhy;

    fn next_step(&mut self) -> Option<(Step, Bresenham3dWhy)> {
        if self.remaining == 0 {
            return None;
        }
        self.remaining -= 1;
        // "currentZ will increase in every iteration" (the major axis).
        let mut step = self.mirror.toward(Step::NONE, self.major);
        let mut tests = [None; 3];
        for (&axis, term) in self.minors.iter().zip(&mut self.terms) {
            // Each minor axis decides on its own plane line (section 3).
            let t = term.test(self.tie);
            if t.steps {
                step = self.mirror.toward(step, axis);
            }
            tests[axis] = Some(t);
        }
        let threshold = self.mirror.magnitude(self.major) / self.divisor;
        let why = Bresenham3dWhy {
            major: self.major,
            tests,
            threshold,
            tie_policy: self.tie,
        };
        Some((step, why))
    }

    /// The steps of [`Stepper::next_step`] through the shared branch-free
    /// loop ([`Terms`]), with no decision built.
    fn fill(&mut self, out: &mut [MaybeUninit<Step>]) -> Filled {
        let taken = out.len().min(self.remaining as usize);
        let toward = |axis| self.mirror.toward(Step::NONE, axis);
        let mut terms = Terms {
            always: toward(self.major),
            terms: [0, 1].map(|i| self.terms[i].as_term(self.tie, toward(self.minors[i]))),
        };
        let displacement = terms.fill(&mut out[..taken]);
        for (term, reached) in self.terms.iter_mut().zip(&terms.terms) {
            term.resume(reached);
        }
        self.remaining -= taken as u64;
        // SAFETY: Terms::fill wrote every one of the `taken` slots.
        unsafe { Filled::written(taken, displacement) }
    }

    fn remaining_steps(&self) -> Option<u64> {
        Some(self.remaining)
    }

    /// A step is a tie where either error term equals |Δmajor| (the
    /// threshold both compare with), counted from the terms in closed form
    /// ([`Term::values_equal_in_any`]): with its ties counted by replay,
    /// the metrics of the bench's 2,000,000-step line took 82 ms in Node,
    /// 17 to 20 ms so.
    fn ties_ahead(self, steps: u64) -> u64 {
        let terms = self.terms.map(|t| t.as_term(self.tie, Step::NONE));
        let threshold = self.terms[0].threshold;
        Term::values_equal_in_any(&terms, threshold, steps.min(self.remaining))
    }

    fn deviation_bound(&self) -> Option<DeviationBound> {
        Some(super::half_cell_per_passive_axis(&self.mirror))
    }

    fn setup_note(&self) -> String {
        format!(
            "{} is the major axis (|Δ| = {}); {} each run Saleem's 2D rule against it, stepping when the error is {} |Δ{}|.{}{}",
            AXIS_NAMES[self.major],
            self.mirror.magnitudes_text(1),
            axis_list(self.minors.into_iter()),
            match self.tie {
                TiePolicy::Hold => "greater than",
                TiePolicy::Advance => "at least",
            },
            AXIS_NAMES[self.major],
            self.mirror.divisor_note(self.divisor),
            self.mirror.mirror_note(),
        )
    }
}
