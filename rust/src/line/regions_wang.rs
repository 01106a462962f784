//! Wang et al. (2020), "Spatial Straight-Line Drawing Algorithm Based on
//! Method of Discriminate Regions", sections 2.2 to 2.5.
//!
//! The active axis (largest |delta|) steps every time. Each passive axis has an
//! integer discriminant (M for the first, N for the second): eq. (6) in closed
//! form, eq. (8) as a recurrence, eq. (10) for the start. The signs of M and N
//! say which region of the cell's exit face the ideal line crosses, and so
//! which corner A-D the step goes to.
//!
//! Negative directions are handled by mirroring: every quantity below is
//! measured along the direction of travel, so the paper's positive-direction
//! formulas apply unchanged (the paper's "intrinsic symmetry").

use super::terms::{Term, Terms};
use super::{GCD, Mirror, signed_comparison, step_target, wang_discriminant};
use super::{LineRun, PlanLine, Record};
use crate::algorithm_info::{AlgorithmInfo, Example, Family};
use crate::error::Error;
use crate::figure::{
    DecisionFigure, ExitFace, FaceCorner, FaceRegion, FaceSegment, FigureKind, SignedAxis,
};
use crate::grid::{AXIS_NAMES, Point, SIGNED_AXIS_LABELS, Step, signed_axis};
use crate::request::{FROM, MAX_STEPS, Request, TO, TiePolicy, tie_option};
use crate::trace::{Column, ColumnKind, Decision, DeviationBound, Filled, Stepper};
use std::fmt::Write;
use std::mem::MaybeUninit;

pub const ID: &str = "regions";

pub const INFO: AlgorithmInfo = AlgorithmInfo {
    id: ID,
    example: Example {
        options: r#"{"from": [0, 0, 0], "to": [10, 7, 6]}"#,
        why: "Wang's worked example, the line of Tables 1 and 2.",
    },
    family: Family::Line,
    title: "Method of discriminate regions (3D line)",
    citation: "Wang, Xiao, Song, Yue, Bian & Li (2020), Spatial Straight-Line Drawing Algorithm Based on Method of Discriminate Regions, sections 2.2-2.5, eq. (6), (8), (10)",
    teaching: "The axis that moves farthest is active and steps every time. Each other (passive) axis keeps an integer discriminant: M for the first, N for the second. M > 0 means the ideal line is past the middle of the cell in that axis when it leaves the cell, so that axis steps too. Together the signs of M and N say which of the four regions a-d of the cell's exit face the line crosses, and so which corner A-D is the next point. After each step, M grows by 2|Δy| and, when y stepped, shrinks by 2|Δx|: integers only, no drift.",
    errata: &[
        "Table 2 prints N_5..N_10 = 18, 10, 2, -6, 6, -2 and the points (7,5,5) and (9,6,6); eq. (8) gives N = 10, 2, -6, 6, -2, 10 and the points (7,5,4) and (9,6,5), the same as Liu's Table 1. The Error printed beside (7,5,5), 0.220564, is that of (7,5,4); the one beside (9,6,6), 0.334534, is the distance of no grid point near the line ((9,6,5) is 0.374887 from it, Table 1's value, and (9,6,6) 0.661693), so the claimed difference from Liu's algorithm at step 9 does not exist.",
        "Table 1 (Liu's algorithm, reproduced by Wang) prints the Error 0.225064 for (7,5,4); its distance from the line is 0.220564 (two digits transposed), the same as its mirror image (3,2,2).",
        "Rule (7) says segment g (M = 0, N > 0) selects A or D; N > 0 means the second passive axis steps, which A does not, so the candidates are C or D.",
        "The paper leaves ties open (\"A or B\"). voxpath makes the choice a visible option, tie = advance (as Liu's Table 1, the default) or hold, and marks every step a tie decided.",
    ],
    columns: RegionsWhy::COLUMNS,
    options: &[FROM, TO, tie_option("advance"), GCD, MAX_STEPS],
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
    let gcd = super::gcd_option(req)?;
    run.run(&INFO, req, |from, to, tie| {
        RegionsWang::with_gcd(from, to, tie, gcd)
    })
}

/// Where the ideal line crosses the exit face of the current cell
/// (Wang section 2.5, Fig. 4b). Segments e-h and the center o are ties.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Region {
    A,
    B,
    C,
    D,
    E,
    F,
    G,
    H,
    O,
}

pub const REGION_LABELS: &[&str] = &["a", "b", "c", "d", "e", "f", "g", "h", "o"];

/// The corner a step goes to: A = first passive axis steps, B = neither,
/// C = second passive axis steps, D = both (Wang Fig. 4a).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Corner {
    A,
    B,
    C,
    D,
}

pub const CORNER_LABELS: &[&str] = &["A", "B", "C", "D"];

impl Region {
    /// Classifies the signs of M and N: a table indexed by sign + 1, so no
    /// branch on the values. A line with one passive axis passes N = -1 (a
    /// missing N counts as negative: it never steps a second axis).
    fn of(m: i64, n: i64) -> Region {
        use Region::{A, B, C, D, E, F, G, H, O};
        const BY_SIGNS: [[Region; 3]; 3] = [
            // N < 0, N = 0, N > 0
            [B, F, C], // M < 0
            [E, O, G], // M = 0
            [A, H, D], // M > 0
        ];
        BY_SIGNS[(m.signum() + 1) as usize][(n.signum() + 1) as usize]
    }

    fn label(self) -> &'static str {
        REGION_LABELS[self as usize]
    }

    /// Regions a-d as quadrants of the exit plane (Wang Fig. 4b): the signs
    /// of the face coordinates (u, v) in each, which are M's and N's.
    const QUADRANTS: [(Region, [i8; 2]); 4] = [
        (Region::A, [1, -1]),
        (Region::B, [-1, -1]),
        (Region::C, [-1, 1]),
        (Region::D, [1, 1]),
    ];

    /// Segments e-h (M or N zero: between two regions, from the center o to
    /// the side between their corners) and the center o itself, face
    /// coordinates.
    const SEGMENTS: [(Region, [f64; 2], [f64; 2]); 5] = [
        (Region::E, [0.0, 0.0], [0.0, -0.5]),
        (Region::F, [0.0, 0.0], [-0.5, 0.0]),
        (Region::G, [0.0, 0.0], [0.0, 0.5]),
        (Region::H, [0.0, 0.0], [0.5, 0.0]),
        (Region::O, [0.0, 0.0], [0.0, 0.0]),
    ];
}

impl Corner {
    /// The corner of the passive axes' moves (0 or 1 each), by table.
    fn of(first_steps: u16, second_steps: u16) -> Corner {
        const BY_MOVES: [Corner; 4] = [Corner::B, Corner::A, Corner::C, Corner::D];
        BY_MOVES[(first_steps | second_steps << 1) as usize]
    }

    fn label(self) -> &'static str {
        CORNER_LABELS[self as usize]
    }

    /// Where each corner is on the exit face (Wang Fig. 4b), face
    /// coordinates: A steps the first passive axis, C the second.
    const ON_FACE: [(Corner, [f64; 2]); 4] = [
        (Corner::A, [0.5, -0.5]),
        (Corner::B, [-0.5, -0.5]),
        (Corner::C, [-0.5, 0.5]),
        (Corner::D, [0.5, 0.5]),
    ];
}

/// The decision behind one step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RegionsWhy {
    /// M and N before the step (eq. 6); None for an absent passive axis.
    pub discriminants: [Option<i64>; 2],
    /// None on a type ② line: no passive axis, so no face decides.
    pub region: Option<Region>,
    pub corner: Option<Corner>,
    /// A zero discriminant decided this step (through the tie policy).
    pub tie: bool,
    pub tie_policy: TiePolicy,
    /// 2 |delta| of the reference active axis (reduced as the discriminants
    /// are): M and N are the exit-face coordinates times this (see
    /// [`RegionsWhy::face_crossing`]).
    face_scale: i64,
    geometry: Geometry,
}

impl RegionsWhy {
    /// Where the ideal line crosses the exit plane, per passive axis: cells
    /// from the center of the cell's exit face, positive in the direction of
    /// travel. Wang eq. (3)-(5) give d_y = d_y1 - d_y2 = 2 (y - y_i) - 1 for
    /// the crossing y at x_i + 1, and eq. (6) is M = |Δx| d_y, so
    /// y - (y_i + 1/2) = M / (2 |Δx|): the discriminant is the crossing,
    /// scaled to an integer. Exact integers until this one division, which
    /// rounds once (M and 2|Δx| are below 2^53, so exact in f64).
    ///
    /// The range: M stays in [2|Δy| - 2|Δx|, 2|Δy|] (eq. 8 adds 2|Δy| and
    /// subtracts 2|Δx| exactly when it is past the tie threshold; which end
    /// is open depends on the tie policy), so the crossing lies in
    /// [|Δy|/|Δx| - 1, |Δy|/|Δx|], always inside (-1, 1). Past +-1/2 it
    /// is off the unit face: the line left Wang's unit cell through a side
    /// face first, though in the same quadrant, so the region still holds.
    pub fn face_crossing(&self) -> [Option<f64>; 2] {
        self.discriminants
            .map(|d| d.map(|d| d as f64 / self.face_scale as f64))
    }

    /// The [`SIGNED_AXIS_LABELS`] index of each face coordinate's axis; None
    /// for a passive axis the line does not have.
    pub fn face_axes(&self) -> [Option<u8>; 2] {
        self.geometry.passive_direction
    }

    /// Wang's Fig. 4 for this step from `from`: the exit face with the parts
    /// it has, placed on the grid (see [`ExitFace`]); None on a type ② line,
    /// which crosses no face.
    pub fn exit_face(&self, from: &Point, step: Step) -> Option<ExitFace> {
        let (region, corner) = (self.region?, self.corner?);
        let [u, v] = self.face_crossing();
        let [u_axis, v_axis] = self.face_axes().map(|a| a.map(SignedAxis::of_label_index));
        let (u, u_axis) = (u?, u_axis?);
        // With one passive axis the face is its edge B-A, at v = -1/2, and
        // only the parts with v < 0 lie on it (a missing N is negative).
        let edge = v_axis.is_none();
        let on_edge = |at: [f64; 2]| !edge || at[1] < 0.0;
        let mut to = *from;
        to.apply(step);
        let mut center = vec![0.0; 3];
        let mut far = from.coords().to_vec();
        for a in 0..3 {
            let passive = [Some(u_axis), v_axis]
                .into_iter()
                .flatten()
                .find(|s| usize::from(s.axis) == a);
            let travel = passive.map_or(to.get(a) - from.get(a), |s| i64::from(s.sign));
            far[a] += travel;
            center[a] = match passive {
                Some(s) => from.get(a) as f64 + f64::from(s.sign) / 2.0,
                None => to.get(a) as f64,
            };
        }
        Some(ExitFace {
            region: region.label(),
            corner: corner.label(),
            u_axis,
            v_axis,
            crossing: [u, v.unwrap_or(-0.5)],
            regions: Region::QUADRANTS
                .iter()
                .filter(|(_, q)| !edge || q[1] < 0)
                .map(|&(r, quadrant)| FaceRegion {
                    name: r.label(),
                    quadrant,
                })
                .collect(),
            segments: Region::SEGMENTS
                .iter()
                .filter(|&&(r, _, _)| !edge || r == Region::E)
                .map(|&(r, from, to)| FaceSegment {
                    name: r.label(),
                    // On an edge, e is the point between A and B, where
                    // the segment e meets the side B-A.
                    from: if edge { to } else { from },
                    to,
                })
                .collect(),
            corners: Corner::ON_FACE
                .iter()
                .filter(|(_, at)| on_edge(*at))
                .map(|&(c, at)| FaceCorner {
                    name: c.label(),
                    at,
                })
                .collect(),
            center,
            cell: [from.coords().to_vec(), far],
        })
    }
}

impl Decision for RegionsWhy {
    const COLUMNS: &'static [Column] = &[
        Column::new(
            "M",
            ColumnKind::Int,
            "Discriminant of the first passive axis before the step (Wang eq. 6, 8, 10; y when x is active); it steps when M > 0, and on M = 0 as the tie policy says.",
        ),
        Column::new(
            "N",
            ColumnKind::Int,
            "Discriminant of the second passive axis before the step (z when x is active); empty when the line has fewer than two passive axes.",
        ),
        Column::new(
            "region",
            ColumnKind::Category { labels: REGION_LABELS },
            "Where the ideal line crosses the cell's exit face: regions a-d, segments e-h, center o (Wang section 2.5); none on type ② lines, which have no passive axis.",
        ),
        Column::new(
            "corner",
            ColumnKind::Category { labels: CORNER_LABELS },
            "The corner the step goes to: A = first passive axis steps, B = neither, C = second, D = both; none on type ② lines.",
        ),
        Column::new(
            "tie",
            ColumnKind::Flag,
            "1 when M or N was exactly 0 and the tie policy decided the step.",
        ),
        Column::new(
            "faceU",
            ColumnKind::Float,
            "Where the ideal line crosses the exit plane (where the active axes arrive at this step), along the first passive axis: cells from the center of the cell's exit face, positive the way the axis travels (faceUAxis). It is M / (2|Δx|) exactly (Wang eq. 3-6), so its sign is M's and says the region. It lies in [|Δy|/|Δx| - 1, |Δy|/|Δx|], inside (-1, 1); past ±1/2 the line left Wang's unit cell through a side face first, in the same quadrant.",
        )
        .formerly("face_u"),
        Column::new(
            "faceV",
            ColumnKind::Float,
            "The crossing along the second passive axis, N / (2|Δx|) (faceVAxis). Empty with one passive axis (types ⑤-⑦): the active axes arrive together, so the line leaves through the edge where they do, and faceU alone places it there, from the edge's midpoint.",
        )
        .formerly("face_v"),
        Column::new(
            "faceUAxis",
            ColumnKind::Category { labels: SIGNED_AXIS_LABELS },
            "The grid axis faceU runs along and the way it grows (+y: toward +y, the direction of travel; an axis that does not move counts as +); empty for type ② lines, which run through the corners and cross no face.",
        )
        .formerly("face_u_axis"),
        Column::new(
            "faceVAxis",
            ColumnKind::Category { labels: SIGNED_AXIS_LABELS },
            "The grid axis faceV runs along and the way it grows; empty with fewer than two passive axes.",
        )
        .formerly("face_v_axis"),
    ];

    fn write(&self, row: &mut [f64]) {
        row[0] = self.discriminants[0].map_or(f64::NAN, |v| v as f64);
        row[1] = self.discriminants[1].map_or(f64::NAN, |v| v as f64);
        row[2] = self.region.map_or(f64::NAN, |r| r as u8 as f64);
        row[3] = self.corner.map_or(f64::NAN, |c| c as u8 as f64);
        row[4] = self.tie as u8 as f64;
        let [u, v] = self.face_crossing();
        row[5] = u.unwrap_or(f64::NAN);
        row[6] = v.unwrap_or(f64::NAN);
        let [u_axis, v_axis] = self.face_axes();
        row[7] = u_axis.map_or(f64::NAN, f64::from);
        row[8] = v_axis.map_or(f64::NAN, f64::from);
    }

    fn is_tie(&self) -> bool {
        self.tie
    }

    const FIGURE: Option<FigureKind> = Some(FigureKind::ExitFace);

    fn figure(&self, from: &Point, step: Step) -> Option<DecisionFigure> {
        self.exit_face(from, step).map(DecisionFigure::ExitFace)
    }

    fn explain(&self, _from: &Point, step: Step) -> String {
        let g = &self.geometry;
        let mut s = g.active_phrase();
        let [m, n] = self.discriminants;
        let (Some(m), Some(region), Some(corner)) = (m, self.region, self.corner) else {
            let _ = write!(
                s,
                ", so the step goes to the opposite corner {}.",
                step_target(step, 3)
            );
            return s;
        };
        let _ = write!(s, "; M = {}", signed_comparison(m));
        if let Some(n) = n {
            let _ = write!(s, " and N = {}", signed_comparison(n));
        }
        match region {
            Region::A | Region::B | Region::C | Region::D => {
                let _ = write!(
                    s,
                    ", so the line leaves the cell through region {}",
                    region.label()
                );
            }
            Region::O => {
                s.push_str(", so the line passes through the center o of the exit face (a tie)")
            }
            _ => {
                let (x, y) = match region {
                    Region::E => ("A", "B"),
                    Region::F => ("B", "C"),
                    Region::G => ("C", "D"),
                    _ => ("D", "A"),
                };
                let _ = write!(
                    s,
                    ", so the line crosses segment {} between {x} and {y} (a tie)",
                    region.label()
                );
            }
        }
        if self.tie {
            let _ = write!(s, "; the tie policy '{}' decides", self.tie_policy.label());
        }
        let _ = write!(
            s,
            ", and the step goes to {} {}.",
            corner.label(),
            step_target(step, 3)
        );
        s
    }
}

/// Which axes are active and passive for one line (fixed for the whole line).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Geometry {
    /// Bit mask of the active axes (|delta| equal to the largest).
    active_mask: u8,
    /// Passive axes in x, y, z order; the first has M, the second N.
    passive: [u8; 2],
    passive_count: u8,
    /// Per passive axis, its axis and direction of travel as a
    /// [`SIGNED_AXIS_LABELS`] index; None when absent.
    passive_direction: [Option<u8>; 2],
}

impl Geometry {
    fn active_phrase(&self) -> String {
        let names: Vec<&str> = (0..3)
            .filter(|a| self.active_mask >> a & 1 == 1)
            .map(|a| AXIS_NAMES[a])
            .collect();
        match names.len() {
            1 => format!("{} is the active axis", names[0]),
            2 => format!("{} and {} are active", names[0], names[1]),
            _ => "x, y and z are all active".to_string(),
        }
    }

    /// Line type ①-⑦ of Wang section 2.2.
    fn line_type(&self) -> u8 {
        match self.active_mask {
            0b001 => 1,
            0b111 => 2,
            0b010 => 3,
            0b100 => 4,
            0b011 => 5,
            0b110 => 6,
            _ => 7,
        }
    }
}

/// Wang's stepper for one 3D line.
#[derive(Clone, Debug)]
pub struct RegionsWang {
    mirror: Mirror,
    /// |delta| per axis divided by `divisor`: what the discriminants use.
    magnitude: [i64; 3],
    /// 1, or the GCD of the |delta| with Wang's section 4 reduction.
    divisor: i64,
    /// An active axis: the paper's x, whose |delta| scales the discriminants.
    reference: usize,
    geometry: Geometry,
    /// M and N as the terms of the shared stepping rule ([`Terms`]): a
    /// passive axis steps when its discriminant is positive, and at zero
    /// (the line passing exactly half way) as the tie policy says; then eq.
    /// (8), M_{i+1} = M_i + 2|Δy| - 2|Δx|(y_{i+1} - y_i), in i64: |M| <= 3
    /// |delta_ref| < 2^33. The active axes step every time (section 2.2).
    /// An absent passive axis holds -1 forever (increment 0, no step bits),
    /// which never steps and never ties, so every step runs the same
    /// straight-line code. Both [`Stepper::next_step`] and [`Stepper::fill`]
    /// step through these, so the rule is written once.
    terms: Terms<2>,
    remaining: u64,
    tie: TiePolicy,
}

impl RegionsWang {
    /// The line from `from` to `to` (3 axes each, validated by the caller).
    pub fn new(from: Point, to: Point, tie: TiePolicy) -> RegionsWang {
        RegionsWang::with_gcd(from, to, tie, false)
    }

    /// With `gcd`, Wang's section 4: the discriminants run on |delta|
    /// divided by their GCD (see [`Mirror::divisor`]).
    pub fn with_gcd(from: Point, to: Point, tie: TiePolicy, gcd: bool) -> RegionsWang {
        let mirror = Mirror::new(from, to);
        let divisor = mirror.divisor(gcd);
        let magnitude = [0, 1, 2].map(|a| mirror.reduced(a, divisor));
        // Found once (a G-code program sets up a line every move), as
        // Mirror::major would (the first axis of the largest |delta|: the
        // divisor divides every one, so the reduced ones share it), from
        // the three reduced ones, where major's pass over the mirror's six
        // took a sixth of the setup of an arc's chord in wasm.
        let reference = (1..3).fold(0, |best, a| {
            if magnitude[a] > magnitude[best] {
                a
            } else {
                best
            }
        });
        let largest = magnitude[reference];
        let mut geometry = Geometry {
            active_mask: 0,
            passive: [0; 2],
            passive_count: 0,
            passive_direction: [None; 2],
        };
        for axis in 0..3 {
            if magnitude[axis] == largest {
                geometry.active_mask |= 1 << axis;
            } else {
                let i = geometry.passive_count as usize;
                geometry.passive[i] = axis as u8;
                geometry.passive_direction[i] = Some(signed_axis(axis, mirror.sign(axis)));
                geometry.passive_count += 1;
            }
        }
        let mut always = Step::NONE;
        for axis in (0..3).filter(|a| geometry.active_mask >> a & 1 == 1) {
            always = mirror.toward(always, axis);
        }
        let terms = std::array::from_fn(|i| {
            let absent = Term {
                value: -1,
                increment: 0,
                decrement: 2 * largest,
                steps_above: Term::steps_above(0, tie),
                step: Step::NONE,
            };
            if i >= geometry.passive_count as usize {
                return absent;
            }
            let axis = geometry.passive[i] as usize;
            Term {
                // Eq. (10): M_1 = 2 delta_y - delta_x (and N_1 = 2 delta_z - delta_x).
                value: 2 * magnitude[axis] - largest,
                increment: 2 * magnitude[axis],
                step: mirror.toward(Step::NONE, axis),
                ..absent
            }
        });
        RegionsWang {
            mirror,
            magnitude,
            divisor,
            reference,
            geometry,
            terms: Terms { always, terms },
            remaining: mirror.magnitude(reference) as u64,
            tie,
        }
    }

    /// Eq. (6), the closed form: the discriminants at point `p` from the
    /// point alone, M = 2 dy (x - xs) - 2 dx (y - ys) + 2 dy - dx (in i128,
    /// so any point within +-2^30 is exact). Used to check the recurrence.
    pub fn closed_form(&self, p: &Point) -> [Option<i64>; 2] {
        let mut out = [None; 2];
        for i in 0..self.geometry.passive_count as usize {
            let axis = self.geometry.passive[i] as usize;
            let m = wang_discriminant(
                self.magnitude[axis],
                self.magnitude[self.reference],
                self.mirror.progress(p, self.reference),
                self.mirror.progress(p, axis),
            );
            out[i] = Some(m as i64);
        }
        out
    }
}

// SAFETY: its fill's Filled counts the slots it wrote (see its Filled::written).
unsafe impl Stepper for RegionsWang {
    type Why = RegionsWhy;

    fn next_step(&mut self) -> Option<(Step, RegionsWhy)> {
        if self.remaining == 0 {
            return None;
        }
        self.remaining -= 1;
        let [m, n] = self.terms.terms.map(|t| t.value);
        let step = self.terms.step();
        let moves = self.terms.terms.map(|t| (step.0 & t.step.0 != 0) as u16);
        // An absent passive axis holds -1: it never ties.
        let tie = m == 0 || n == 0;
        let count = self.geometry.passive_count;
        let (region, corner) = if count == 0 {
            (None, None)
        } else {
            (Some(Region::of(m, n)), Some(Corner::of(moves[0], moves[1])))
        };
        let why = RegionsWhy {
            discriminants: [(count > 0).then_some(m), (count > 1).then_some(n)],
            region,
            corner,
            tie,
            tie_policy: self.tie,
            face_scale: self.terms.terms[0].decrement,
            geometry: self.geometry,
        };
        Some((step, why))
    }

    /// The same steps as [`Stepper::next_step`], through the branch-free
    /// recording loop the integer line rules share ([`Terms`]): eq. (8) per
    /// passive axis, an absent one a term that never steps, and no decision
    /// built.
    fn fill(&mut self, out: &mut [MaybeUninit<Step>]) -> Filled {
        let taken = out.len().min(self.remaining as usize);
        let displacement = self.terms.fill(&mut out[..taken]);
        self.remaining -= taken as u64;
        // SAFETY: Terms::fill wrote every one of the `taken` slots.
        unsafe { Filled::written(taken, displacement) }
    }

    fn remaining_steps(&self) -> Option<u64> {
        Some(self.remaining)
    }

    fn deviation_bound(&self) -> Option<DeviationBound> {
        Some(super::half_cell_per_passive_axis(&self.mirror))
    }

    fn setup_note(&self) -> String {
        let g = &self.geometry;
        let names = |mask: u8| -> String {
            (0..3)
                .filter(|a| mask >> a & 1 == 1)
                .map(|a| AXIS_NAMES[a])
                .collect::<Vec<_>>()
                .join(", ")
        };
        let passive_mask = 0b111 & !g.active_mask;
        let mut s = format!(
            "Line type {} (Wang section 2.2): |Δ| = ({}, {}, {}); active: {}",
            ["①", "②", "③", "④", "⑤", "⑥", "⑦"][g.line_type() as usize - 1],
            self.magnitude[0],
            self.magnitude[1],
            self.magnitude[2],
            names(g.active_mask),
        );
        if g.passive_count > 0 {
            let _ = write!(s, "; passive: {}", names(passive_mask));
            let dx = self.magnitude[self.reference];
            let ref_name = AXIS_NAMES[self.reference];
            for (i, label) in ["M", "N"].iter().enumerate().take(g.passive_count as usize) {
                let axis = g.passive[i] as usize;
                let _ = write!(
                    s,
                    ". Eq. (10): {label}_1 = 2|Δ{p}| - |Δ{ref_name}| = 2·{} - {dx} = {}",
                    self.magnitude[axis],
                    2 * self.magnitude[axis] - dx,
                    p = AXIS_NAMES[axis],
                );
            }
        }
        s.push('.');
        s.push_str(&self.mirror.divisor_note(self.divisor));
        s.push_str(self.mirror.mirror_note());
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algorithm_info::find_none;
    use crate::trace::TraceBuilder;

    fn run(from: [i64; 3], to: [i64; 3], tie: TiePolicy) -> Vec<(Point, RegionsWhy)> {
        let mut s = RegionsWang::new(Point::new(&from), Point::new(&to), tie);
        let mut p = Point::new(&from);
        let mut out = Vec::new();
        while let Some((step, why)) = s.next_step() {
            p.apply(step);
            out.push((p, why));
        }
        out
    }

    #[test]
    fn table_2_erratum_points_are_not_what_the_equations_give() {
        // Wang's Table 2 prints (7,5,5) and (9,6,6) with N_5..N_10 = 18, 10,
        // 2, -6, 6, -2; eq. (8) gives (7,5,4) and (9,6,5) (Liu's Table 1).
        let steps = run([0, 0, 0], [10, 7, 6], TiePolicy::Advance);
        assert_eq!(steps[6].0, Point::new(&[7, 5, 4]));
        assert_eq!(steps[8].0, Point::new(&[9, 6, 5]));
        let n: Vec<i64> = steps[4..]
            .iter()
            .map(|(_, w)| w.discriminants[1].unwrap())
            .collect();
        // N_5..N_10 by eq. (8) from N_1 = 2·6 - 10 = 2: each step adds
        // 2Δz = 12, less 2Δx = 20 where z steps (2, -6, 6, -2, 10, 2, -6, 6,
        // -2, 10 over the line, as tests/line_goldens.rs works out), not the
        // printed 18, 10, 2, -6, 6, -2.
        assert_eq!(n, [10, 2, -6, 6, -2, 10]);
    }

    #[test]
    fn hold_on_ties_gives_saleem_s_point() {
        // With ties held, step 5 stays at y = 3 (Saleem's strict rule).
        let steps = run([0, 0, 0], [10, 7, 6], TiePolicy::Hold);
        assert_eq!(steps[4].0, Point::new(&[5, 3, 3]));
        assert_eq!(steps[4].1.corner, Some(Corner::C));
        assert_eq!(steps.last().unwrap().0, Point::new(&[10, 7, 6]));
    }

    #[test]
    fn explains_a_step_in_one_sentence() {
        let steps = run([0, 0, 0], [10, 7, 6], TiePolicy::Advance);
        let (_, why) = steps[0];
        let step = Step::along(0, 1).with(1, 1).with(2, 1);
        assert_eq!(
            why.explain(&Point::origin(3), step),
            "x is the active axis; M = 4 > 0 and N = 2 > 0, so the line leaves the cell through region d, and the step goes to D (x+1, y+1, z+1)."
        );
        let (_, tie) = steps[4];
        assert!(tie.explain(&Point::new(&[4, 3, 2]), step).contains(
            "M = 0 and N = 10 > 0, so the line crosses segment g between C and D (a tie); the tie policy 'advance' decides"
        ));
    }

    #[test]
    fn all_seven_types_have_their_active_axes() {
        for (to, line_type) in [
            ([5, 3, 2], 1),
            ([4, 4, 4], 2),
            ([1, 6, 2], 3),
            ([2, 3, 7], 4),
            ([5, 5, 1], 5),
            ([0, 3, 3], 6),
            ([6, 2, 6], 7),
        ] {
            let s = RegionsWang::new(Point::origin(3), Point::new(&to), TiePolicy::Advance);
            assert_eq!(s.geometry.line_type(), line_type, "{to:?}");
        }
    }

    #[test]
    fn trace_keeps_decisions_for_replay() {
        let from = Point::origin(3);
        let to = Point::new(&[10, 7, 6]);
        let mut b = TraceBuilder::new(from, 1000);
        b.run(
            RegionsWang::new(from, to, TiePolicy::Advance),
            crate::ideal::IdealPath::Line { from, to },
        )
        .unwrap();
        let t = b.finish(ID);
        let d = t.decisions(3, 6);
        assert_eq!(d.columns[0], [6.0, 0.0, -6.0]);
        assert_eq!(d.columns[2], [0.0, 6.0, 2.0]); // a, g, c
        // faceU = M / 20, faceV = N / 20; the axes +y and +z.
        assert_eq!(d.columns[5], [0.3, 0.0, -0.3]);
        assert_eq!(d.columns[6], [-0.1, 0.5, 0.1]);
        assert_eq!(d.columns[7], [2.0; 3]);
        assert_eq!(d.columns[8], [4.0; 3]);
        assert_eq!(t.metrics().ties, 1);
        let note = t.segment_note(0);
        assert!(note.contains("M_1 = 2|Δy| - |Δx| = 2·7 - 10 = 4"), "{note}");
    }

    /// The reference axis is found from the three reduced |delta| as
    /// Mirror::major finds it from the mirror's: the first of the largest,
    /// in every direction, with and without the GCD reduction.
    #[test]
    fn the_reference_axis_is_the_mirror_s_major_one() {
        let magnitudes = [0, 1, 2, 3, 6];
        for &x in &magnitudes {
            for &y in &magnitudes {
                for &z in &magnitudes {
                    for signs in 0..8 {
                        let sign = |axis: usize| if signs >> axis & 1 == 1 { -1 } else { 1 };
                        let from = Point::new(&[4, -2, 7]);
                        let to = Point::new(&[4 + sign(0) * x, -2 + sign(1) * y, 7 + sign(2) * z]);
                        for gcd in [false, true] {
                            let line = RegionsWang::with_gcd(from, to, TiePolicy::Advance, gcd);
                            assert_eq!(
                                line.reference,
                                Mirror::new(from, to).major(),
                                "{to} gcd {gcd}"
                            );
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn a_type_two_line_has_no_region_or_corner_rather_than_a_label() {
        // (0,0,0)->(3,3,3): all three axes active (Wang section 2.2, type ②),
        // so no discriminant, no exit face and no corner decides any step.
        let t = INFO
            .trace_json(
                r#"{"algorithm": "regions", "from": [0, 0, 0], "to": [3, 3, 3]}"#,
                find_none,
            )
            .unwrap();
        let d = t.decisions(0, 3);
        assert!(d.columns[0].iter().chain(&d.columns[1]).all(|v| v.is_nan()));
        let none = f64::from(crate::trace::NO_VALUE);
        assert_eq!(d.columns[2], [none; 3]);
        assert_eq!(d.columns[3], [none; 3]);
        assert_eq!(d.columns[4], [0.0; 3]);
        assert!(t.explain(0).contains("opposite corner"), "{}", t.explain(0));
    }
}
