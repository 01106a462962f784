//! Saleem & Saleem (2004), "Bresenham type fast algorithm for 3-D linear and
//! helical movement in CNC machines", section 2: Bresenham's line in the
//! plane, in all eight octants.
//!
//! The major axis (the one that moves farther) steps every time. The minor
//! axis keeps the error term 2·Δmajor·ε (eq. 4): it grows by 2·Δminor per
//! step, and the minor axis steps when it exceeds Δmajor (eq. 5), after which
//! it drops by 2·Δmajor (ε drops by 1, times 2·Δmajor). The paper prints
//! "-= Δmajor" there: the `variant` option runs that too.

use super::terms::{Term, Terms};
use super::{Guard, Mirror, step_target};
use super::{LineRun, PlanLine, Record};
use crate::algorithm_info::{AlgorithmInfo, Example, Family};
use crate::error::Error;
use crate::figure::{DecisionFigure, ErrorTerm, ErrorTerms, FigureKind};
use crate::grid::{AXIS_NAMES, OCTANT_LABELS, Point, Step};
use crate::request::{FROM, MAX_STEPS, OptionKind, OptionSpec, Request, TO, TiePolicy, tie_option};
use crate::trace::{
    Column, ColumnKind, ColumnRole, Decision, DeviationBound, Filled, Stepper, fill_by_next_step,
    ties_by_steps,
};
use std::mem::MaybeUninit;

pub const ID: &str = "bresenham2d";

/// The `variant` option: Saleem's rule as derived, or the pseudo-code as printed.
pub const VARIANT: OptionSpec = OptionSpec {
    name: "variant",
    kind: OptionKind::Choice {
        values: &["corrected", "printed"],
    },
    required: false,
    default: Some("corrected"),
    applies_with: None,
    doc: "corrected: after a minor step the error drops by 2·Δmajor (eq. 4-5); printed: by Δmajor, as Saleem's pseudo-code prints it (the minor axis then runs ahead; the finish rule holds it at its end coordinate).",
};

pub const INFO: AlgorithmInfo = AlgorithmInfo {
    id: ID,
    example: Example {
        options: r#"{"from": [0, 0], "to": [10, 3]}"#,
        why: "A first-octant line with a tie at step 5.",
    },
    family: Family::Line,
    title: "Bresenham's line in 2D, all eight octants",
    citation: "Saleem & Saleem (2004), Bresenham type fast algorithm for 3-D linear and helical movement in CNC machines, section 2, eq. (1)-(5)",
    teaching: "Find the octant: the axis that moves farther (the major axis) steps every time, so only the other (minor) axis needs a decision. The minor axis carries an error: how far the ideal line has risen above it, in units of 1/(2·Δmajor) so that every quantity is an integer. Each step adds 2·Δminor; when the error exceeds Δmajor (the line is more than half a cell away) the minor axis steps and the error drops by 2·Δmajor (one whole cell). An error exactly equal to Δmajor means the line passes exactly half way: Saleem's strict '>' holds there (tie = hold). Other octants run the same rule on |Δ| and step toward the end point.",
    errata: &[
        "Section 2's text and pseudo-code both subtract Δx ('2DeltaXErrorY -= DeltaX') after a y step; multiplying 'ε -= 1' by 2Δx gives 2Δx, as the 3D pseudo-code of section 3 does. With Δx the error drops only half as much, so y steps about twice as often as it should and the printed loop, which only tests x, ends with y past its end point: (0,0)->(10,3) would end at (10,5). variant = printed runs the pseudo-code as printed; voxpath's finish rule holds y at its end coordinate so the trace stays a valid move, and the overshoot column counts how far past the end the printed program would be.",
        "The pseudo-code is written for the first octant only (currentX += 1, currentY += 1); the other seven are described in words ('call the correct procedure'). voxpath mirrors negative directions and swaps the roles of x and y in octants 2, 3, 6 and 7.",
    ],
    columns: Bresenham2dWhy::COLUMNS,
    options: &[FROM, TO, tie_option("hold"), VARIANT, MAX_STEPS],
    min_dims: 2,
    max_dims: 2,
    default_tie: Some(TiePolicy::Hold),
    compared_by: None,
    trace: |req, _| run(req, Record),
    plan: Some(|req, _| run(req, PlanLine)),
};

/// Reads this algorithm's own options and runs its stepper as `run` says
/// (recorded or planned: [`LineRun`]).
fn run<R: LineRun>(req: &Request, run: R) -> Result<R::Out, Error> {
    let variant = Variant::from_request(req)?;
    run.run(&INFO, req, |from, to, tie| {
        Bresenham2d::new(from, to, tie, variant)
    })
}

/// Which subtraction the error term makes after a minor step.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Variant {
    /// 2·Δmajor: eq. (4)-(5) and the 3D pseudo-code.
    Corrected,
    /// Δmajor: the 2D pseudo-code as printed.
    Printed,
}

impl Variant {
    fn from_request(req: &Request) -> Result<Variant, Error> {
        Ok(match req.choice(&VARIANT)? {
            Some("printed") => Variant::Printed,
            _ => Variant::Corrected,
        })
    }
}

/// Saleem's error term for one minor axis (section 2 eq. 4-5, and section 3
/// once per minor axis): the error scaled by 2·Δmajor so that it stays an
/// integer. It equals Wang's discriminant plus Δmajor (Wang eq. 6).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SaleemTerm {
    /// 2·Δmajor·ε: starts at 0 ("initially ε_y is 0").
    pub error: i64,
    /// 2·Δminor, added every step (eq. 4).
    two_minor: i64,
    /// Δmajor, the threshold (eq. 5).
    pub threshold: i64,
    /// What a minor step subtracts: 2·Δmajor, or Δmajor as printed in section 2.
    drop: i64,
}

/// One decision of a [`SaleemTerm`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SaleemTest {
    /// The error after adding 2·Δminor: the value compared with the threshold.
    pub tested: i64,
    /// The rule says the minor axis steps.
    pub steps: bool,
    /// The error equalled the threshold and the tie policy decided.
    pub tie: bool,
}

impl SaleemTerm {
    /// |Δminor|, |Δmajor| and what a minor step subtracts.
    pub fn new(minor: i64, major: i64, drop: i64) -> SaleemTerm {
        SaleemTerm {
            error: 0,
            two_minor: 2 * minor,
            threshold: major,
            drop,
        }
    }

    /// One major step: add 2·Δminor, compare with Δmajor, and drop the error
    /// when the minor axis steps. In i64: with drop = 2·Δmajor the error
    /// stays within (-Δmajor, 2·Δminor]; as printed it grows by at most
    /// 2·Δminor - Δmajor <= Δmajor per step, under 2^62 over 2^31 steps.
    pub fn test(&mut self, tie: TiePolicy) -> SaleemTest {
        self.error += self.two_minor;
        let tested = self.error;
        let at_half = tested == self.threshold;
        // More than half a cell away: step. Exactly half: the tie policy.
        let steps = tested > self.threshold || (at_half && tie == TiePolicy::Advance);
        if steps {
            self.error -= self.drop;
        }
        SaleemTest {
            tested,
            steps,
            tie: at_half,
        }
    }

    /// This term as the shared recording loop steps it ([`Term`]): the value
    /// compared next is the error with 2·Δminor already added.
    pub fn as_term(&self, tie: TiePolicy, step: Step) -> Term {
        Term {
            value: self.error + self.two_minor,
            increment: self.two_minor,
            decrement: self.drop,
            steps_above: Term::steps_above(self.threshold, tie),
            step,
        }
    }

    /// Takes up the state `term` reached in the recording loop.
    pub fn resume(&mut self, term: &Term) {
        self.error = term.value - self.two_minor;
    }
}

/// The octant of a direction (Saleem Fig. 1), numbered counter-clockwise
/// from +x, each the half-open range [45°·(k-1), 45°·k); 0 for no motion.
pub fn octant(dx: i64, dy: i64) -> u8 {
    if dx == 0 && dy == 0 {
        0
    } else if dy >= 0 && dy < dx {
        1
    } else if dx > 0 && dy >= dx {
        2
    } else if dx <= 0 && dy > -dx {
        3
    } else if dy > 0 {
        4
    } else if -dy < -dx {
        5
    } else if dx < 0 {
        6
    } else if dx < -dy {
        7
    } else {
        8
    }
}

/// The decision behind one step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bresenham2dWhy {
    pub test: SaleemTest,
    pub threshold: i64,
    pub octant: u8,
    /// Index of the major axis (0 = x).
    pub major: usize,
    pub guard: Guard,
    /// Variant printed: how far past its end coordinate the printed program's
    /// minor axis is after this step.
    pub overshoot: Option<i64>,
    pub tie_policy: TiePolicy,
}

impl Decision for Bresenham2dWhy {
    const COLUMNS: &'static [Column] = &[
        Column::new(
            "error",
            ColumnKind::Int,
            "Saleem's 2·Δmajor·ε after adding 2·Δminor (eq. 4), the value compared with the threshold. As printed it can grow without bound (beyond 2^53 it is shown rounded).",
        )
        .with_role(ColumnRole::ErrorTerm),
        Column::new(
            "threshold",
            ColumnKind::Int,
            "Δmajor (eq. 5): the minor axis steps when the error exceeds it.",
        )
        .with_role(ColumnRole::Threshold),
        Column::new(
            "octant",
            ColumnKind::Category { labels: &OCTANT_LABELS },
            "Octant 1-8 of the move (Saleem Fig. 1), counter-clockwise from +x; 1, 4, 5, 8 are x-major, 2, 3, 6, 7 y-major.",
        ),
        Column::new(
            "tie",
            ColumnKind::Flag,
            "1 when the error equalled the threshold and the tie policy decided.",
        ),
        Column::new(
            "overshoot",
            ColumnKind::Int,
            "variant = printed: units the printed program's minor axis would be past its end coordinate (voxpath holds it there); empty for corrected.",
        ),
    ];

    fn write(&self, row: &mut [f64]) {
        row[0] = self.test.tested as f64;
        row[1] = self.threshold as f64;
        // A step has motion, so an octant 1-8: label index octant - 1.
        row[2] = f64::from(self.octant) - 1.0;
        row[3] = self.test.tie as u8 as f64;
        row[4] = self.overshoot.map_or(f64::NAN, |v| v as f64);
    }

    fn is_tie(&self) -> bool {
        self.test.tie
    }

    const FIGURE: Option<FigureKind> = Some(FigureKind::ErrorTerms);

    fn figure(&self, _from: &Point, _step: Step) -> Option<DecisionFigure> {
        Some(DecisionFigure::ErrorTerms(ErrorTerms {
            terms: vec![ErrorTerm {
                name: Self::COLUMNS[0].name,
                value: self.test.tested,
                steps: self.test.steps,
            }],
            threshold: self.threshold,
        }))
    }

    fn explain(&self, _from: &Point, step: Step) -> String {
        let (major, minor) = (AXIS_NAMES[self.major], AXIS_NAMES[1 - self.major]);
        let t = self.test;
        let comparison = match t.tested.cmp(&self.threshold) {
            std::cmp::Ordering::Greater => format!("{} > {}", t.tested, self.threshold),
            std::cmp::Ordering::Equal => format!("{} = {} (a tie)", t.tested, self.threshold),
            std::cmp::Ordering::Less => format!("{} < {}", t.tested, self.threshold),
        };
        let mut s = format!(
            "Octant {}: {major} steps every time; the error is {comparison}",
            self.octant
        );
        if t.tie {
            s.push_str(&format!(
                ", the tie policy '{}' decides",
                self.tie_policy.label()
            ));
        }
        let verb = if t.steps { "steps" } else { "holds" };
        if self.guard == Guard::Rule {
            s.push_str(&format!(", so {minor} {verb}"));
        } else {
            s.push_str(&format!(", so the rule says {minor} {verb}"));
        }
        s.push_str(&self.guard.clause(1 - self.major));
        if let Some(over) = self.overshoot.filter(|&o| o > 0) {
            s.push_str(&format!(
                " (the printed program would now be {over} past the end)"
            ));
        }
        s.push_str(&format!("; the step goes to {}.", step_target(step, 2)));
        s
    }
}

/// Saleem's 2D stepper.
#[derive(Clone, Debug)]
pub struct Bresenham2d {
    mirror: Mirror,
    major: usize,
    octant: u8,
    term: SaleemTerm,
    variant: Variant,
    /// Minor steps the printed program has taken (variant printed only).
    printed_minor: i64,
    minor_left: i64,
    remaining: u64,
    tie: TiePolicy,
}

impl Bresenham2d {
    pub fn new(from: Point, to: Point, tie: TiePolicy, variant: Variant) -> Bresenham2d {
        let mirror = Mirror::new(from, to);
        let d = from.delta_to(&to);
        let octant = octant(d[0], d[1]);
        let major = usize::from(matches!(octant, 2 | 3 | 6 | 7));
        let (major_len, minor_len) = (mirror.magnitude(major), mirror.magnitude(1 - major));
        let drop = match variant {
            Variant::Corrected => 2 * major_len,
            Variant::Printed => major_len,
        };
        Bresenham2d {
            mirror,
            major,
            octant,
            term: SaleemTerm::new(minor_len, major_len, drop),
            variant,
            printed_minor: 0,
            minor_left: minor_len,
            remaining: major_len as u64,
            tie,
        }
    }
}

// SAFETY: its fill's Filled counts the slots it wrote (see its Filled::written).
unsafe impl Stepper for Bresenham2d {
    type Why = Bresenham2dWhy;

    fn next_step(&mut self) -> Option<(Step, Bresenham2dWhy)> {
        if self.remaining == 0 {
            return None;
        }
        let test = self.term.test(self.tie);
        // The finish rule only ever acts on the printed variant: the
        // corrected rule reaches the end coordinate exactly (Bresenham).
        let (moves, guard) = Guard::apply(test.steps, self.minor_left, self.remaining);
        self.remaining -= 1;
        let mut step = self.mirror.toward(Step::NONE, self.major);
        if moves {
            step = self.mirror.toward(step, 1 - self.major);
            self.minor_left -= 1;
        }
        self.printed_minor += test.steps as i64;
        let overshoot = (self.variant == Variant::Printed)
            .then(|| (self.printed_minor - self.mirror.magnitude(1 - self.major)).max(0));
        let why = Bresenham2dWhy {
            test,
            threshold: self.term.threshold,
            octant: self.octant,
            major: self.major,
            guard,
            overshoot,
            tie_policy: self.tie,
        };
        Some((step, why))
    }

    /// The corrected rule through the shared branch-free loop ([`Terms`]):
    /// it reaches the end coordinate by itself, so the finish rule never
    /// acts and the steps are the term's alone. The printed variant, which
    /// the finish rule holds back, takes its steps one by one.
    fn fill(&mut self, out: &mut [MaybeUninit<Step>]) -> Filled {
        if self.variant == Variant::Printed {
            return fill_by_next_step(self, out);
        }
        let taken = out.len().min(self.remaining as usize);
        let out = &mut out[..taken];
        let toward = |axis| self.mirror.toward(Step::NONE, axis);
        let mut terms = Terms {
            always: toward(self.major),
            terms: [self.term.as_term(self.tie, toward(1 - self.major))],
        };
        let displacement = terms.fill(out);
        self.term.resume(&terms.terms[0]);
        let minor_steps = displacement[1 - self.major].abs();
        self.minor_left -= minor_steps;
        self.printed_minor += minor_steps;
        self.remaining -= taken as u64;
        // SAFETY: Terms::fill wrote every one of the `taken` slots.
        unsafe { Filled::written(taken, displacement) }
    }

    fn remaining_steps(&self) -> Option<u64> {
        Some(self.remaining)
    }

    /// The corrected rule's ties in closed form, where its error equals
    /// |Δmajor| ([`Term::values_equal`]); as printed, the error leaves the
    /// window the closed form needs (it drops by |Δmajor| only), so its
    /// steps are taken.
    fn ties_ahead(self, steps: u64) -> u64 {
        if self.variant == Variant::Printed {
            return ties_by_steps(self, steps);
        }
        let term = self.term.as_term(self.tie, Step::NONE);
        term.values_equal(self.term.threshold, steps.min(self.remaining))
    }

    /// The corrected rule only: as printed, the minor axis runs ahead of
    /// the line until the finish rule holds it.
    fn deviation_bound(&self) -> Option<DeviationBound> {
        (self.variant == Variant::Corrected)
            .then(|| super::half_cell_per_passive_axis(&self.mirror))
    }

    fn setup_note(&self) -> String {
        if self.octant == 0 {
            return "No motion: the start is the end, so there is no octant and no step."
                .to_string();
        }
        let (major, minor) = (AXIS_NAMES[self.major], AXIS_NAMES[1 - self.major]);
        // Said as the tie policy decides: with advance an error equal to
        // |Δmajor| steps too (the note said "exceeds" whatever the policy).
        let reaches = match self.tie {
            TiePolicy::Hold => "exceeds",
            TiePolicy::Advance => "reaches",
        };
        let mut s = format!(
            "Octant {} (Saleem Fig. 1): |Δ{major}| = {} is the major axis and steps every time; {minor} steps when its error, starting at 0 and growing by 2|Δ{minor}| = {}, {reaches} |Δ{major}| = {}.",
            self.octant, self.term.threshold, self.term.two_minor, self.term.threshold,
        );
        if self.variant == Variant::Printed {
            s.push_str(&format!(
                " Variant printed: after a {minor} step the error drops by |Δ{major}| = {} instead of 2|Δ{major}|, as Saleem's pseudo-code prints it; {minor} runs ahead and is held at its end coordinate.",
                self.term.threshold
            ));
        }
        s.push_str(self.mirror.mirror_note());
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_setup_note_says_the_tie_policy_s_test() {
        let note = |tie| {
            Bresenham2d::new(
                Point::new(&[0, 0]),
                Point::new(&[10, 5]),
                tie,
                Variant::Corrected,
            )
            .setup_note()
        };
        assert!(
            note(TiePolicy::Hold).contains("10, exceeds |Δx| = 10."),
            "{}",
            note(TiePolicy::Hold)
        );
        assert!(
            note(TiePolicy::Advance).contains("10, reaches |Δx| = 10."),
            "{}",
            note(TiePolicy::Advance)
        );
    }

    #[test]
    fn octants_are_half_open_45_degree_ranges() {
        let cases = [
            ((5, 0), 1),
            ((5, 5), 2),
            ((0, 5), 3),
            ((-5, 5), 4),
            ((-5, 0), 5),
            ((-5, -5), 6),
            ((0, -5), 7),
            ((5, -5), 8),
            ((10, 3), 1),
            ((3, 10), 2),
            ((-3, 10), 3),
            ((-10, 3), 4),
            ((-10, -3), 5),
            ((-3, -10), 6),
            ((3, -10), 7),
            ((10, -3), 8),
            ((0, 0), 0),
        ];
        for ((dx, dy), o) in cases {
            assert_eq!(octant(dx, dy), o, "({dx}, {dy})");
        }
    }

    #[test]
    fn the_error_term_steps_past_half_a_cell() {
        // Saleem eq. (4)-(5) for Δmajor = 10, Δminor = 3: +6 per step,
        // compare with 10, -20 on a step: 6, 12, -2, 4, 10 (tie), 16, ...
        let mut t = SaleemTerm::new(3, 10, 20);
        let tested: Vec<i64> = (0..6).map(|_| t.test(TiePolicy::Hold).tested).collect();
        assert_eq!(tested, [6, 12, -2, 4, 10, 16]);
        let mut t = SaleemTerm::new(3, 10, 20);
        let ties: Vec<bool> = (0..6).map(|_| t.test(TiePolicy::Hold).tie).collect();
        assert_eq!(ties, [false, false, false, false, true, false]);
    }

    #[test]
    fn explains_the_comparison_and_the_tie() {
        let mut s = Bresenham2d::new(
            Point::origin(2),
            Point::new(&[10, 3]),
            TiePolicy::Hold,
            Variant::Corrected,
        );
        let (step, why) = s.next_step().unwrap();
        assert_eq!(
            why.explain(&Point::origin(2), step),
            "Octant 1: x steps every time; the error is 6 < 10, so y holds; the step goes to (x+1, y)."
        );
        for _ in 0..3 {
            s.next_step();
        }
        let (step, why) = s.next_step().unwrap();
        assert_eq!(
            why.explain(&Point::new(&[4, 1]), step),
            "Octant 1: x steps every time; the error is 10 = 10 (a tie), the tie policy 'hold' decides, so y holds; the step goes to (x+1, y)."
        );
    }
}
