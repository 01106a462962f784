//! Moves in mm -> one trace in steps: each move is stepped by the chosen
//! line or arc algorithm from the catalogue and appended to one
//! [`TraceBuilder`] as its own segment(s), with a note naming its line.
//!
//! - G0 (rapid) is stepped like G1 with the line algorithm and marked as a
//!   rapid, timed at the top rate along it (`timing`; a real G0 may also
//!   dog-leg, each axis at its own top speed).
//! - Every move is also pushed to the planner (`timing`, on Grbl 1.1's
//!   planner.c), which times the whole program when it finishes.
//! - Each target is rounded to steps from its absolute position (see
//!   `machine`), so moves never drift; a move starts where the last one
//!   ended on the grid.
//! - Arcs in their plane run `circle` (Saleem) or `arc-segments` (chords by
//!   the line algorithm), as set; arcs whose normal axis moves run `helix`
//!   (method saleem with circle, segments with arc-segments).
//! - The arc algorithms work on the step grid: the two axes of the plane
//!   need the same steps per mm (else a circle in mm is an ellipse in
//!   steps), and the center must be a grid point with the rounded start and
//!   end within 1 step of the same radius (the arc module's tolerance). The
//!   center used is the grid point nearest the programmed center's
//!   projection onto the perpendicular bisector of the rounded start and
//!   end (where both radii are equal), or one of its 8 neighbours when
//!   rounding breaks that tolerance; the move's note says when it is not
//!   simply the rounded center.
//! - On the grid the arc's sweep is measured again; the number of extra
//!   turns is chosen so that it is nearest the programmed sweep. An arc that
//!   turns through less than a step (its end rounds onto or just behind its
//!   start), or whose radius is too small for any grid center, is stepped as
//!   a straight line to its end, and its note says so.

use super::interpret::{self, ArcFormat, ArcMm, Effects, Interpreter, Motion, MoveMm};
use super::parse::{Block, Problem, parse_line_into};
use super::timing::{self, MoveSpans, Timeline};
use crate::algorithms;
use crate::arc::arc_segments::{LINE_ALGORITHM, LINE_ALGORITHMS};
use crate::arc::circle_saleem::{self, SaleemCircle};
use crate::arc::planes::Turn;
use crate::arc::{ArcSpec, CENTER, MAX_TURNS, radii_within_tolerance};
use crate::error::{Error, Limit, Location, counted};
use crate::figure::FigureKind;
use crate::grid::{AXIS_NAMES, COORD_LIMIT, Point, Step, jumps};
use crate::ideal::IdealPath;
use crate::line::line_stepper::{ColumnsAndFigure, LineStepper, MakeSegment, StepperVisitor};
use crate::machine::{MACHINE_AXES, MICROSTEPS, Machine, PITCH, STEP_ANGLE, STEPS_PER_MM};
use crate::memory::{HEAP_BUDGET_BYTES, held_bytes};
use crate::planner::{self, Limits, Planner, Timing};
use crate::request::{
    MAX_STEPS, MAX_STEPS_LIMIT, OptionKind, OptionSpec, Request, too_long_advice,
};
use crate::text::split_line;
use crate::trace::{Column, MadeSegment, Stepper, Trace, TraceBuilder};
use serde::Serialize;
use serde_json::{Map, Value};
use std::cell::Cell;
use std::f64::consts::TAU;
use std::rc::Rc;
use tsify::Tsify;

/// Arc algorithms a program may run its arcs with.
pub const ARC_ALGORITHMS: &[&str] = &["circle", "arc-segments"];

/// Warnings kept per program; the rest are counted.
pub const MAX_WARNINGS: usize = 1000;

pub const PROGRAM_LINE_ALGORITHM: OptionSpec = OptionSpec {
    applies_with: None,
    doc: "The line algorithm that steps G0 and G1 moves, and the chords of arc-segments (a catalogue id).",
    ..LINE_ALGORITHM
};

pub const ARC_ALGORITHM: OptionSpec = OptionSpec {
    name: "arcAlgorithm",
    kind: OptionKind::Choice {
        values: ARC_ALGORITHMS,
    },
    required: false,
    default: Some("circle"),
    applies_with: None,
    doc: "How arcs are stepped: circle (Saleem's integer circle) or arc-segments (chords by the line algorithm). Helical arcs run helix by the matching method.",
};

/// A setting's value as the JS API types it: one number for every axis, or
/// one per axis (x, y, z).
#[derive(Serialize, Tsify, Clone, Debug, PartialEq)]
#[serde(untagged)]
pub enum PerAxis {
    All(f64),
    Each([f64; MACHINE_AXES]),
}

/// True when two names are the same text (for the compile-time check of
/// `settings!`).
const fn same_name(a: &str, b: &str) -> bool {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

/// Declares the settings of a program run once, one row each: `name: the
/// type JS gives = its OptionSpec`. A row becomes an optional field of
/// [`GcodeSettings`] (whose TypeScript twin tsify writes into the wasm
/// package's .d.ts: the JS API's settings type) and an entry of [`SETTINGS`]
/// (the catalogue's `gcodeSettings`, from which the CLI's flags, the page's
/// machine form, its URL keys and their docs are made). The field is named
/// as the spec, which the compiler checks.
/// An algorithm id as a setting holds it: a String, which tsify writes as
/// the generated union of ids (`algorithms::ALGORITHM_ID_TS`) by this name.
type AlgorithmId = String;

macro_rules! settings {
    ($($name:ident: $ty:ty = $spec:expr;)*) => {
        /// How a G-code program is run, as the JS API takes it. Every field is
        /// a setting of the catalogue (`catalogue().gcodeSettings`), which
        /// documents it, with its unit and default.
        #[derive(Serialize, Tsify, Clone, Debug, Default, PartialEq)]
        #[allow(non_snake_case)]
        pub struct GcodeSettings {
            $(
                #[tsify(optional)]
                #[serde(skip_serializing_if = "Option::is_none")]
                pub $name: Option<$ty>,
            )*
        }

        /// Every setting of a program run, in the order forms and help list them.
        pub const SETTINGS: &[OptionSpec] = &[$($spec),*];

        $(const _: () = assert!(
            same_name(stringify!($name), $spec.name),
            concat!("the settings! row ", stringify!($name), " must be named as its spec")
        );)*
    };
}

settings! {
    stepsPerMm: PerAxis = STEPS_PER_MM;
    stepAngle: PerAxis = STEP_ANGLE;
    microsteps: PerAxis = MICROSTEPS;
    pitch: PerAxis = PITCH;
    lineAlgorithm: AlgorithmId = PROGRAM_LINE_ALGORITHM;
    arcAlgorithm: AlgorithmId = ARC_ALGORITHM;
    maxSteps: u64 = MAX_STEPS;
    acceleration: PerAxis = planner::ACCELERATION;
    maxRate: PerAxis = planner::MAX_RATE;
    junctionDeviation: f64 = planner::JUNCTION_DEVIATION;
    maxStepRate: PerAxis = planner::MAX_STEP_RATE;
}

/// How a program is run: the machine and the algorithms.
#[derive(Clone, Debug)]
pub struct Settings {
    pub machine: Machine,
    /// Acceleration, top rates and junction deviation (the planner's).
    pub limits: Limits,
    pub line_algorithm: &'static str,
    pub arc_algorithm: &'static str,
    pub max_steps: u64,
}

impl Settings {
    /// Reads `{"stepsPerMm": 80, "lineAlgorithm": "regions", ...}`; errors
    /// name the setting.
    pub fn from_json(text: &str) -> Result<Settings, Error> {
        let value: Value = serde_json::from_str(text)
            .map_err(|e| Error::field("settings", format!("not valid JSON: {e}")))?;
        let Value::Object(mut options) = value else {
            return Err(Error::field("settings", "expected an object of settings"));
        };
        options.retain(|_, v| !v.is_null());
        let machine = Machine::from_settings(&options)?;
        let limits = timing::limits_from_settings(&options)?;
        let request = Request::new("gcode", options);
        request.check_options(SETTINGS)?;
        let pick =
            |spec: &OptionSpec, values: &'static [&'static str]| -> Result<&'static str, Error> {
                let chosen = request.choice(spec)?.unwrap_or(values[0]);
                Ok(values
                    .iter()
                    .copied()
                    .find(|v| *v == chosen)
                    .expect("choice() checked it"))
            };
        Ok(Settings {
            machine,
            limits,
            line_algorithm: pick(&PROGRAM_LINE_ALGORITHM, LINE_ALGORITHMS)?,
            arc_algorithm: pick(&ARC_ALGORITHM, ARC_ALGORITHMS)?,
            max_steps: request.max_steps()?,
        })
    }
}

/// The program's line algorithm with its options at their defaults (a
/// move gives only its endpoints), read once.
fn line_stepper_of(id: &'static str) -> LineStepper {
    algorithms::find(id).map_or(LineStepper::ByRequest, |info| {
        LineStepper::for_request(info, &Request::new(id, Map::new()))
    })
}

/// Runs a straight move's stepper into the program's trace
/// ([`Runner::run_line`]).
struct RunInPlace<'a> {
    runner: &'a mut Runner,
    from: Point,
    to: Point,
}

impl StepperVisitor for RunInPlace<'_> {
    type Out = bool;
    fn visit<S: Stepper>(self, stepper: S) -> bool {
        self.runner.run_line(stepper, self.from, self.to)
    }
}

/// What a segment made when read was stepped as: a circle arc, or a line.
enum MadePath {
    Circle(ArcSpec),
    Line { from: Point, to: Point },
}

impl MadePath {
    /// The path the segment is measured against: the arc, or the line.
    fn ideal(&self) -> IdealPath {
        match self {
            MadePath::Circle(spec) => IdealPath::Arc(spec.ideal_arc()),
            MadePath::Line { from, to } => IdealPath::Line {
                from: *from,
                to: *to,
            },
        }
    }
}

/// A warning or an error at a place in the program (1-based).
#[derive(Serialize, Tsify, Clone, Debug, PartialEq, Eq)]
pub struct Diagnostic {
    pub line: u32,
    pub column: u32,
    pub message: String,
    /// The cap the program ran into, when that is what stopped it.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[tsify(optional)]
    pub limit: Option<Limit>,
}

impl Diagnostic {
    fn at(line: u32, problem: &Problem) -> Diagnostic {
        Diagnostic {
            line,
            column: problem.column,
            message: problem.message.clone(),
            limit: None,
        }
    }

    fn from_error(error: Error) -> Diagnostic {
        let Location::Source { line, column } = error.location else {
            unreachable!("program errors are placed at a line: {error}");
        };
        Diagnostic {
            line,
            column,
            message: error.message,
            limit: error.limit,
        }
    }
}

/// An arc as programmed and as stepped.
#[derive(Serialize, Tsify, Clone, Debug, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct ArcInfo {
    /// xy (G17), zx (G18) or yz (G19).
    pub plane: &'static str,
    /// cw (G2) or ccw (G3).
    pub direction: &'static str,
    /// ijk (center) or r (radius).
    pub format: &'static str,
    pub center_mm: [f64; MACHINE_AXES],
    pub radius_mm: f64,
    /// Signed (< 0 clockwise), extra turns included.
    pub sweep_deg: f64,
    /// Full turns added by P.
    pub extra_turns: u32,
    /// The grid center the arc was stepped around; None when it was stepped
    /// as a straight line.
    pub center_steps: Option<[i64; MACHINE_AXES]>,
}

/// One move of the program and the steps it took.
#[derive(Serialize, Tsify, Clone, Debug, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct Move {
    pub line: u32,
    pub column: u32,
    /// G0, G1, G2 or G3.
    pub code: &'static str,
    /// rapid, line, arc or helix.
    pub kind: &'static str,
    pub from_mm: [f64; MACHINE_AXES],
    pub to_mm: [f64; MACHINE_AXES],
    pub from_steps: [i64; MACHINE_AXES],
    pub to_steps: [i64; MACHINE_AXES],
    /// The feed the program asks for this move, mm/min: F in G94; in G93
    /// (inverse time) F times the move's length, its whole path in 1/F
    /// minutes. None for rapids and when none was set. The planner runs it
    /// at most at the max rate along the move and at least at Grbl's least
    /// feed (1 mm/min), as Grbl does, with a warning when either applies;
    /// `timing` has the speeds it reaches.
    pub feed_mm_per_min: Option<f64>,
    /// Step index of the move's first step, and its number of steps.
    pub first_step: u64,
    pub steps: u64,
    /// Index of the move's first trace segment, and how many it has (an
    /// arc-segments arc has one per chord).
    pub first_segment: usize,
    pub segments: usize,
    /// The catalogue algorithm that stepped it.
    #[tsify(type = "AlgorithmId")]
    pub algorithm: &'static str,
    pub arc: Option<ArcInfo>,
    /// What the move is, in a sentence (it also starts its segments' notes).
    pub note: String,
    /// When it runs on the planned profile, speeds in mm/s (`timing`).
    pub timing: Timing,
}

/// How far a run has got.
#[derive(Serialize, Tsify, Clone, Copy, Debug, PartialEq, Eq)]
#[serde(rename_all = "camelCase")]
pub struct Progress {
    /// The lines read: past the first error too, whose lines are read for
    /// their syntax only.
    pub lines_done: u32,
    pub lines: u32,
    /// The line of the first error, where the run stopped (as
    /// [`ProgramInfo::stopped_at_line`]), so that progress can name the
    /// line reached rather than the last line read after it.
    pub stopped_at_line: Option<u32>,
    pub moves: usize,
    pub steps: u64,
    pub done: bool,
}

/// Everything about a finished run but the trace.
#[derive(Serialize, Tsify, Clone, Debug)]
#[serde(rename_all = "camelCase")]
pub struct ProgramInfo {
    pub lines: u32,
    pub steps: u64,
    pub steps_per_mm: [f64; MACHINE_AXES],
    #[tsify(type = "AlgorithmId")]
    pub line_algorithm: &'static str,
    #[tsify(type = "AlgorithmId")]
    pub arc_algorithm: &'static str,
    /// How many moves ran; each is read on demand ([`Program::moves`], and
    /// in the JS API `move(i)` and `movesInRange(from, to)`), so a long
    /// program's record stays small.
    pub move_count: usize,
    /// How long the program takes on the planned profile, seconds.
    pub duration_seconds: f64,
    /// Pulses per axis (x, y, z) over the whole program.
    pub pulses: Vec<u64>,
    pub warnings: Vec<Diagnostic>,
    /// Warnings past the first MAX_WARNINGS, counted only.
    pub warnings_omitted: u64,
    /// Execution stops at the first error; later lines are still checked
    /// for syntax errors, which are listed too.
    pub errors: Vec<Diagnostic>,
    /// The line of the first error: every line before it ran.
    pub stopped_at_line: Option<u32>,
}

/// A finished run.
pub struct Program {
    pub trace: Trace,
    pub info: ProgramInfo,
    /// Every move, in order (`info.move_count` of them), kept compact;
    /// shared with the trace, whose segment notes start with their move's.
    pub records: Rc<MoveRecords>,
    /// When every step happens (computed on demand).
    pub timeline: Timeline,
}

impl Program {
    /// Every move, decoded (for tests and small programs; a long program's
    /// are better read one at a time with [`MoveRecords::get`]).
    pub fn moves(&self) -> Vec<Move> {
        (0..self.records.len())
            .map(|i| self.records.get(i, &self.timeline))
            .collect()
    }
}

/// Sentinel of [`MoveRecord::arc`]: the move is not an arc.
const NO_ARC: u32 = u32::MAX;

/// A move as a run keeps it: fixed size (64 bytes, which the README's
/// Limits states), no heap of its own.
/// Its note, arc and timing are made when it is read ([`MoveRecords::get`]).
/// What follows from its neighbours is not kept: a move starts where the
/// one before it ended (in mm and in steps: only a move changes the
/// position), and its segments end where the next move's begin. Its
/// steps and planner blocks are in [`MoveSpans`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MoveRecord {
    pub to_mm: [f64; MACHINE_AXES],
    /// mm/min; NaN when none was in force (never a feed's value: F is finite).
    feed_mm_per_min: f64,
    /// Grid points fit i32: coordinates stay within ±2^30.
    to_steps: [i32; MACHINE_AXES],
    pub line: u32,
    pub column: u32,
    first_segment: u32,
    /// Index among [`MoveRecords`]' arcs, or [`NO_ARC`].
    arc: u32,
    motion: Motion,
}

const _: () = assert!(std::mem::size_of::<MoveRecord>() == 64);

/// What an arc move keeps beyond its [`MoveRecord`]: the arc as programmed
/// and how it was stepped.
#[derive(Clone, Debug, PartialEq)]
struct ArcRecord {
    arc: ArcMm,
    /// The grid center it was stepped around; None when stepped as a line.
    center_steps: Option<[i64; MACHINE_AXES]>,
    /// Full turns added on the grid (see the module comment).
    turns: u64,
    /// Why it was stepped as a straight line, if it was.
    as_line: Option<&'static str>,
}

/// Why an arc is stepped as a straight line (its note says so).
const TOO_SMALL: &str = "its radius is too small for a center on the step grid";
const UNDER_ONE_STEP: &str = "on the grid it turns less than one step";
const NO_CHORD_MOVES: &str = "every chord Grbl cuts it into ends on its start step (Grbl's planner drops a block of no steps, so Grbl does not move)";

/// The moves of a run, compact, and what decoding them needs.
#[derive(Clone, Debug)]
pub struct MoveRecords {
    records: Vec<MoveRecord>,
    arcs: Vec<ArcRecord>,
    line_algorithm: &'static str,
    arc_algorithm: &'static str,
    /// How straight moves are stepped, and their segments made again.
    line_stepper: LineStepper,
    steps_per_mm: [f64; MACHINE_AXES],
    /// Where each move starts in the steps and the planner's blocks.
    spans: Rc<MoveSpans>,
    /// Trace segments of all the moves: where the last move's end.
    segments: u32,
    /// The move [`Self::move_of_segment`] found last: a reader going through
    /// the segments in order finds the next one there or just after it.
    last_found: Cell<usize>,
}

fn grid_point(c: [i32; MACHINE_AXES]) -> Point {
    Point::new(&c.map(i64::from))
}

impl MoveRecords {
    fn new(settings: &Settings) -> MoveRecords {
        MoveRecords {
            records: Vec::new(),
            arcs: Vec::new(),
            line_algorithm: settings.line_algorithm,
            arc_algorithm: settings.arc_algorithm,
            line_stepper: line_stepper_of(settings.line_algorithm),
            steps_per_mm: settings.machine.steps_per_mm(),
            spans: Rc::default(),
            segments: 0,
            last_found: Cell::new(0),
        }
    }

    /// Where move `index` starts, in mm: where the one before it ended, or
    /// the origin, where the machine starts.
    fn start_mm(&self, index: usize) -> [f64; MACHINE_AXES] {
        index
            .checked_sub(1)
            .map_or([0.0; MACHINE_AXES], |i| self.records[i].to_mm)
    }

    /// Where move `index` starts, in steps.
    fn start_steps(&self, index: usize) -> [i32; MACHINE_AXES] {
        index
            .checked_sub(1)
            .map_or([0; MACHINE_AXES], |i| self.records[i].to_steps)
    }

    /// Move `index`'s trace segments.
    fn segments_of(&self, index: usize) -> std::ops::Range<usize> {
        let end = self
            .records
            .get(index + 1)
            .map_or(self.segments, |r| r.first_segment);
        self.records[index].first_segment as usize..end as usize
    }

    /// The move whose steps trace segment `segment` holds (moves are in
    /// segment order, each with at least one segment).
    ///
    /// The search starts from the move found last: a reader of every
    /// segment in order (the whole path's polyline, the metrics) asks for
    /// that move or the next, and one that skips ahead (the bounds, which
    /// read the start of a segment only after a long stretch) asks for one
    /// a few moves on. From there the steps double (1, 2, 4, ...) until
    /// they pass the segment, and only the last of them is searched by
    /// halves: about 2 log2 d probes for a move d records on, near the one
    /// read last, where a search of every record took log2 of them, a
    /// cache miss at each (a quarter of the bounds' time on a
    /// 100,000-move program). A segment before the last found is searched
    /// for among the records before it.
    fn move_of_segment(&self, segment: usize) -> usize {
        let starts_after = |index: usize| self.records[index].first_segment as usize > segment;
        let last = self.last_found.get().min(self.records.len() - 1);
        let index = if starts_after(last) {
            self.records[..last].partition_point(|r| r.first_segment as usize <= segment) - 1
        } else {
            // records[low] starts at or before the segment; find a record
            // after it that starts past it (or the end), then search between.
            let (mut low, mut step) = (last, 1);
            let high = loop {
                let probe = low + step;
                if probe >= self.records.len() {
                    break self.records.len();
                }
                if starts_after(probe) {
                    break probe;
                }
                low = probe;
                step *= 2;
            };
            low + self.records[low..high].partition_point(|r| r.first_segment as usize <= segment)
                - 1
        };
        self.last_found.set(index);
        index
    }

    /// What segment `segment` was stepped as in place ([`Runner::run_line`],
    /// [`Runner::run_circle`]), from its record.
    fn made_path(&self, segment: usize) -> MadePath {
        let index = self.move_of_segment(segment);
        let r = &self.records[index];
        let (from, to) = (grid_point(self.start_steps(index)), grid_point(r.to_steps));
        // An arc made in place ran the circle; one stepped as a line (its
        // radius too small, or its grid sweep under a step, though it has a
        // grid center) ran the line algorithm, as every straight move.
        if let Some(a) = self.arc_of(r).filter(|a| a.as_line.is_none()) {
            debug_assert!(!self.helical(index), "a helix keeps its segments");
            let center = Point::new(&a.center_steps.expect("an arc not stepped as a line"));
            let spec = ArcSpec::new(from, to, center, a.arc.plane, a.arc.turn, a.turns, false)
                .expect("it was checked when run");
            return MadePath::Circle(spec);
        }
        MadePath::Line { from, to }
    }

    /// Segment `segment` made again, its stepper and its ideal path.
    fn made_segment(&self, segment: usize) -> MadeSegment {
        let path = self.made_path(segment);
        let ideal = path.ideal();
        match path {
            MadePath::Circle(spec) => {
                let stepper =
                    circle_arc_stepper(&spec, MAX_STEPS_LIMIT).expect("it was checked when run");
                MadeSegment::new(spec.from, ideal, stepper)
            }
            MadePath::Line { from, to } => self
                .line_stepper
                .with_stepper(from, to, MakeSegment { start: from, ideal })
                .expect("a move stepped by its request keeps its segment"),
        }
    }

    /// Where segment `segment` starts, as [`Self::made_segment`] makes it:
    /// its move's start.
    fn made_start(&self, segment: usize) -> Point {
        grid_point(self.start_steps(self.move_of_segment(segment)))
    }

    /// The ideal path of segment `segment`, as [`Self::made_segment`] makes
    /// it, without its stepper.
    fn made_ideal(&self, segment: usize) -> IdealPath {
        self.made_path(segment).ideal()
    }

    pub fn len(&self) -> usize {
        self.records.len()
    }

    pub fn is_empty(&self) -> bool {
        self.records.is_empty()
    }

    /// Move `index` as users read it, its timing from `timeline`.
    pub fn get(&self, index: usize, timeline: &Timeline) -> Move {
        let r = &self.records[index];
        let arc = self.arc_of(r);
        let helical = self.helical(index);
        let (first_step, steps) = self.spans.steps_of(index);
        let segments = self.segments_of(index);
        Move {
            line: r.line,
            column: r.column,
            code: r.motion.code(),
            kind: match (r.motion, helical) {
                (Motion::Rapid, _) => "rapid",
                (Motion::Linear, _) => "line",
                (Motion::Arc(_), false) => "arc",
                (Motion::Arc(_), true) => "helix",
            },
            from_mm: self.start_mm(index),
            to_mm: r.to_mm,
            from_steps: self.start_steps(index).map(i64::from),
            to_steps: r.to_steps.map(i64::from),
            feed_mm_per_min: (!r.feed_mm_per_min.is_nan()).then_some(r.feed_mm_per_min),
            first_step,
            steps,
            first_segment: segments.start,
            segments: segments.len(),
            algorithm: self.algorithm(index),
            arc: arc.map(|a| ArcInfo {
                plane: a.arc.plane.label(),
                direction: match a.arc.turn {
                    Turn::Clockwise => "cw",
                    Turn::CounterClockwise => "ccw",
                },
                format: match a.arc.format {
                    ArcFormat::Center => "ijk",
                    ArcFormat::Radius => "r",
                },
                center_mm: a.arc.center_mm,
                radius_mm: a.arc.radius_mm,
                sweep_deg: a.arc.sweep_rad.to_degrees(),
                extra_turns: a.arc.extra_turns,
                center_steps: a.center_steps,
            }),
            note: self.note(index),
            timing: timeline.move_timing(index),
        }
    }

    fn arc_of(&self, r: &MoveRecord) -> Option<&ArcRecord> {
        (r.arc != NO_ARC).then(|| &self.arcs[r.arc as usize])
    }

    /// True when move `index` is an arc whose normal axis moves (a helix).
    fn helical(&self, index: usize) -> bool {
        let r = &self.records[index];
        self.arc_of(r).is_some_and(|a| {
            let n = a.arc.plane.axes()[2];
            self.start_steps(index)[n] != r.to_steps[n]
        })
    }

    /// The catalogue algorithm that stepped move `index`.
    fn algorithm(&self, index: usize) -> &'static str {
        match self.arc_of(&self.records[index]) {
            Some(a) if a.as_line.is_none() => {
                if self.helical(index) {
                    "helix"
                } else {
                    self.arc_algorithm
                }
            }
            _ => self.line_algorithm,
        }
    }

    /// What a move is, in a sentence: its note, which also starts its
    /// segments' notes in the trace.
    fn note(&self, index: usize) -> String {
        use std::fmt::Write;
        let r = &self.records[index];
        let arc = self.arc_of(r);
        let mut note = String::with_capacity(160);
        let _ = write!(note, "Line {}, {}: ", r.line, r.motion.code());
        tuple_into(&mut note, &self.start_mm(index));
        note.push_str(" -> ");
        tuple_into(&mut note, &r.to_mm);
        let _ = write!(
            note,
            " mm = {} -> {} steps",
            grid_point(self.start_steps(index)),
            grid_point(r.to_steps)
        );
        let Some(a) = arc else {
            note.push_str(if r.motion == Motion::Rapid {
                ", a rapid, stepped like G1 and timed at the top rate along it (a real G0 may also dog-leg, each axis at its own top speed)."
            } else {
                ", a straight line."
            });
            return note;
        };
        let [u, v, _] = a.arc.plane.axes();
        let _ = write!(
            note,
            ", {} {}in the {}, center ",
            a.arc.turn.describe(),
            if self.helical(index) {
                "helix "
            } else {
                "arc "
            },
            a.arc.plane.describe(),
        );
        tuple_into(&mut note, &[a.arc.center_mm[u], a.arc.center_mm[v]]);
        let _ = write!(
            note,
            " mm, r = {} mm, sweep {:.3}°",
            (a.arc.radius_mm * 1e6).round() / 1e6,
            a.arc.sweep_rad.to_degrees(),
        );
        match a.arc.extra_turns {
            0 => {}
            t => {
                let _ = write!(note, " (P adds {})", counted(t.into(), "full turn"));
            }
        }
        if let Some(center) = a.center_steps {
            let spm = self.steps_per_mm;
            let center_real = [a.arc.center_mm[u] * spm[u], a.arc.center_mm[v] * spm[v]];
            let rounded = [center_real[0].round() as i64, center_real[1].round() as i64];
            let c = [center[u], center[v]];
            if c != rounded {
                let _ = write!(
                    note,
                    "; center moved to {} steps ({:.2} steps from the programmed center) so the rounded start and end are within 1 step of one radius",
                    Point::new(&center),
                    (c[0] as f64 - center_real[0]).hypot(c[1] as f64 - center_real[1])
                );
            }
        }
        match a.as_line {
            Some(why) => {
                let _ = write!(
                    note,
                    "; {why}, so it is stepped as a straight line to its end."
                );
            }
            None => note.push('.'),
        }
        note
    }

    /// The note of the move whose steps trace segment `segment` holds
    /// (moves are in segment order, each with at least one segment).
    fn note_of_segment(&self, segment: usize) -> String {
        self.note(self.move_of_segment(segment))
    }

    /// Index of the move that took step index `k` (moves are in step
    /// order), or None past their last step.
    pub fn move_of_step(&self, k: u64) -> Option<usize> {
        self.spans.move_of_step(k)
    }

    /// Index of the move programmed on a 1-based source line (moves are in
    /// line order, at most one per line), if that line moved.
    pub fn move_at_line(&self, line: u32) -> Option<usize> {
        let index = self.records.partition_point(|m| m.line < line);
        (self.records.get(index)?.line == line).then_some(index)
    }

    /// The step index where the machine is when `line` starts (every move
    /// of an earlier line done), or None when no move comes at or after it
    /// (then the program's end).
    pub fn first_step_from_line(&self, line: u32) -> Option<u64> {
        let index = self.records.partition_point(|m| m.line < line);
        (index < self.records.len()).then(|| self.spans.steps_of(index).0)
    }

    /// The 1-based source line of each step index in `from..to` (below the
    /// moves' last step), read from the records alone, pushed onto `out`
    /// (which the caller may have made room in: wasm's lineByStep, refusing
    /// a range it has no memory for).
    pub fn push_line_by_step(&self, from: u64, to: u64, out: &mut Vec<u32>) {
        let Some(first) = self.move_of_step(from) else {
            return;
        };
        let mut k = from;
        for index in first..self.records.len() {
            let (first_step, steps) = self.spans.steps_of(index);
            let end = to.min(first_step + steps);
            if end > k {
                out.resize(out.len() + (end - k) as usize, self.records[index].line);
                k = end;
            }
            if end == to {
                break;
            }
        }
    }

    fn place(&self, index: usize) -> (u32, u32) {
        let r = &self.records[index];
        (r.line, r.column)
    }
}

/// The catalogue request of a line from `from` to `to`.
fn line_request(algorithm: &str, from: Point, to: Point) -> Request {
    let mut options = Map::new();
    options.insert("from".into(), Value::from(from.coords()));
    options.insert("to".into(), Value::from(to.coords()));
    Request::new(algorithm, options)
}

/// The circle stepper of the planar arc `spec`, checked against
/// `max_steps` as the circle algorithm's own trace checks it
/// ([`SaleemCircle::within`]): the one place a circle arc's stepper is
/// made, when it is run ([`Runner::run_circle`]) and when its segment is
/// made again to be read ([`MoveRecords::made_segment`]); its segment is
/// measured against `spec.ideal_arc()`. None where the circle algorithm
/// would refuse it.
fn circle_arc_stepper(spec: &ArcSpec, max_steps: u64) -> Option<SaleemCircle> {
    SaleemCircle::new(spec).within(max_steps).ok()
}

/// The request of an arc from `from` to `to` about the grid point
/// `center`, turning as `arc` does in its plane; whoever runs it adds its
/// algorithm, its turns and its method.
fn arc_request(from: Point, to: Point, center: Point, arc: &ArcMm) -> Request {
    let mut request = line_request("", from, to);
    request.set("center", Value::from(center.coords()));
    let direction = match arc.turn {
        Turn::Clockwise => "cw",
        Turn::CounterClockwise => "ccw",
    };
    request.set("dir", Value::from(direction));
    request.set("plane", Value::from(arc.plane.label()));
    request
}

/// Runs a program a slice of lines at a time (see [`Runner::advance`]).
pub struct Runner {
    source: String,
    /// Byte offset of the next line; past the end when done.
    offset: usize,
    lines_done: u32,
    lines: u32,
    settings: Settings,
    interpreter: Interpreter,
    /// The line being run, its vectors reused from line to line.
    block: Block,
    builder: TraceBuilder,
    /// True (always, but in tests): straight moves and circle arcs run in
    /// place where they can; false: every move through the catalogue's
    /// request, the reference the in-place paths are tested against.
    in_place: bool,
    planner: Planner,
    /// Where each move starts in the steps and the planner's blocks.
    spans: MoveSpans,
    steps: u64,
    segments: usize,
    moves: MoveRecords,
    /// The line algorithm's decision columns and figure, when it takes a
    /// line of at most a unit on every axis in one step
    /// ([`LineStepper::takes_unit_lines_at_once`]): such moves are put in
    /// without making their stepper ([`TraceBuilder::run_unit_made_when_read`]).
    unit_lines: Option<(&'static [Column], Option<FigureKind>)>,
    warnings: Vec<Diagnostic>,
    warnings_omitted: u64,
    /// The last feed warned of as capped to maxRate: the G93 F it came
    /// from (None in G94) and the feed, mm/min, as the message says both.
    capped_feed_warned: Option<(Option<f64>, f64)>,
    /// The last feed below Grbl's least (1 mm/min) warned about, likewise.
    raised_feed_warned: Option<(Option<f64>, f64)>,
    errors: Vec<Diagnostic>,
    stopped_at_line: Option<u32>,
    /// A `%` line or a line with codes or words has been read: a `%` line
    /// now ends the program (see [`Runner::end_at_percent`]).
    program_begun: bool,
    /// Heap the core may hold (all of it, this run's and others') before
    /// the run stops; see [`crate::memory`].
    heap_budget_bytes: usize,
    out_of_memory: Option<Error>,
}

/// Lines of a program as an editor counts them, and as [`crate::text::lines`]
/// reads them: a final line break ends the last line, it does not start
/// another. Counted from the breaks, an LF or a CR not followed by one, by
/// two vector counts over the whole text rather than a search per line (a
/// call per line cost about 3% of a 100,000-line run at 1 step/mm in wasm).
fn count_lines(text: &str) -> u32 {
    let bytes = text.as_bytes();
    let line_feeds = memchr::memchr_iter(b'\n', bytes).count();
    // CRs are rare: each is checked for the LF after it.
    let lone_returns = memchr::memchr_iter(b'\r', bytes)
        .filter(|&at| bytes.get(at + 1) != Some(&b'\n'))
        .count();
    let last_unended = !matches!(bytes.last(), None | Some(b'\n' | b'\r'));
    let lines = line_feeds + lone_returns + usize::from(last_unended);
    // An empty program is one empty line, as an editor shows it.
    u32::try_from(lines).unwrap_or(u32::MAX).max(1)
}

/// Appends "(1, 2.5, 0)": values rounded to 6 decimals.
fn tuple_into(out: &mut String, values: &[f64]) {
    use std::fmt::Write;
    out.push('(');
    for (i, v) in values.iter().enumerate() {
        if i > 0 {
            out.push_str(", ");
        }
        let _ = write!(out, "{}", (v * 1e6).round() / 1e6);
    }
    out.push(')');
}

impl Runner {
    pub fn new(source: String, settings: Settings) -> Runner {
        let lines = count_lines(&source);
        // A line moves once at most: room for a move a line (up to a
        // million) in each table a move adds to, so that they are not
        // copied as they grow; the finish gives back what is left.
        // Bounded by the heap budget too: a reservation is held as soon as
        // it is made, and 256 bytes a move covers every table.
        let expected_moves = (lines as usize)
            .min(1 << 20)
            .min(HEAP_BUDGET_BYTES.saturating_sub(held_bytes()) / 256);
        let mut moves = MoveRecords::new(&settings);
        moves.records.reserve(expected_moves);
        let unit_lines = moves
            .line_stepper
            .takes_unit_lines_at_once()
            .then(|| {
                let origin = Point::origin(MACHINE_AXES);
                let mut unit = origin;
                unit.coords_mut()[0] = 1;
                moves
                    .line_stepper
                    .with_stepper(origin, unit, ColumnsAndFigure)
            })
            .flatten();
        let mut builder = TraceBuilder::new(Point::origin(MACHINE_AXES), settings.max_steps);
        builder.reserve_segments(expected_moves);
        let mut planner = Planner::new(settings.limits);
        planner.reserve(expected_moves);
        let mut spans = MoveSpans::default();
        spans.reserve(expected_moves);
        // Line 1 starts after a byte order mark, as every text input does.
        let offset = source.len() - crate::text::without_byte_order_mark(&source).len();
        Runner {
            source,
            offset,
            lines_done: 0,
            lines,
            builder,
            in_place: true,
            planner,
            spans,
            settings,
            interpreter: Interpreter::default(),
            block: Block::default(),
            steps: 0,
            segments: 0,
            moves,
            unit_lines,
            warnings: Vec::new(),
            warnings_omitted: 0,
            capped_feed_warned: None,
            raised_feed_warned: None,
            errors: Vec::new(),
            stopped_at_line: None,
            program_begun: false,
            heap_budget_bytes: HEAP_BUDGET_BYTES,
            out_of_memory: None,
        }
    }

    /// Stops the run once the core holds more than `bytes` of heap (the
    /// default is [`HEAP_BUDGET_BYTES`]; tests set less).
    pub fn set_heap_budget(&mut self, bytes: usize) {
        self.heap_budget_bytes = bytes;
    }

    pub fn progress(&self) -> Progress {
        Progress {
            lines_done: self.lines_done,
            lines: self.lines,
            stopped_at_line: self.stopped_at_line,
            moves: self.moves.len(),
            steps: self.steps,
            done: self.lines_done == self.lines,
        }
    }

    /// Reads and runs up to `max_lines` more lines. A slice takes time in
    /// proportion to its lines and to the steps of their moves. When the
    /// core holds more heap than the run may, the run stops where it is
    /// (done, the lines after it not even read) with the error
    /// [`Runner::out_of_memory`] returns, also the program's last error.
    pub fn advance(&mut self, max_lines: u32) -> Progress {
        self.reserve_as_so_far();
        // Out of self for the slice (run_block borrows self mutably), not
        // moved out and back for every line.
        let mut block = std::mem::take(&mut self.block);
        let mut effects = Effects::default();
        for _ in 0..max_lines {
            if self.lines_done == self.lines {
                break;
            }
            if let Err(error) = self.check_memory() {
                self.stop(Diagnostic::from_error(error.clone()));
                self.out_of_memory = Some(error);
                self.lines_done = self.lines;
                break;
            }
            let rest = &self.source[self.offset..];
            let (text, next) = split_line(rest);
            parse_line_into(text, &mut block);
            self.offset += next;
            self.lines_done += 1;
            if let Some(column) = block.percent {
                // A `%` line with more on it is an error of its line, which
                // runs as any other to say so (it ended the program
                // silently, its error never said).
                if self.program_begun && block.error.is_none() {
                    self.end_at_percent(self.lines_done, column);
                    break;
                }
            }
            self.program_begun |=
                block.percent.is_some() || !block.codes.is_empty() || !block.words.is_empty();
            self.run_block(self.lines_done, &block, &mut effects);
        }
        self.block = block;
        self.progress()
    }

    /// Makes room for the steps and planner blocks the whole program would
    /// take at the rate of the lines run so far (a line may make a dozen
    /// blocks, an arc's chords, and thousands of steps), when that is more
    /// than the room there is, so that those tables are not copied into
    /// ever larger ones as they grow (a copy of megabytes each time, with
    /// wasm memory growing past the last). Within maxSteps, and within
    /// half of the heap the run may still take.
    fn reserve_as_so_far(&mut self) {
        if self.lines_done == 0 || self.lines_done == self.lines {
            return;
        }
        let scale = |so_far: u64| so_far.saturating_mul(self.lines as u64) / self.lines_done as u64;
        let spare = self.heap_budget_bytes.saturating_sub(held_bytes()) as u64 / 2;
        let steps = self.builder.steps();
        let steps_expected = scale(steps);
        if steps_expected > self.builder.step_capacity() {
            // A quarter more than expected: the reservation is exact, and
            // an estimate that creeps past it slice after slice would copy
            // every step each time.
            let steps_wanted = steps_expected
                .saturating_add(steps_expected / 4)
                .min(self.builder.max_steps())
                .min(steps + spare / std::mem::size_of::<Step>() as u64);
            // Within maxSteps by the line above: it cannot fail.
            let _ = self.builder.reserve(steps_wanted.saturating_sub(steps));
        }
        let blocks = self.planner.len();
        let blocks_expected = scale(blocks as u64) as usize;
        if blocks_expected > self.planner.capacity() {
            // A sixteenth more: the reservation is exact, and an estimate
            // that creeps past it would move every block each time. Less
            // than the steps' quarter, as a block takes 56 bytes to a
            // step's 2: a quarter held 114 MB more on a 10,000,000-line
            // program at 1 step/mm.
            let blocks_wanted = blocks_expected
                .saturating_add(blocks_expected / 16)
                .min(blocks + spare as usize / Planner::BYTES_PER_BLOCK);
            self.planner.reserve(blocks_wanted - blocks);
        }
    }

    /// Why the run stopped for memory, if it did (see [`Runner::advance`]).
    pub fn out_of_memory(&self) -> Option<&Error> {
        self.out_of_memory.as_ref()
    }

    /// An error once more heap is held than the run may hold, placed at the
    /// line it would run next.
    fn check_memory(&self) -> Result<(), Error> {
        let held = held_bytes();
        if held <= self.heap_budget_bytes {
            return Ok(());
        }
        let mb = |bytes: usize| bytes.div_ceil(1 << 20);
        Err(Error::at(
            self.lines_done + 1,
            1,
            format!(
                "the program does not fit in memory: after {} of its {} lines ({} moves, {} steps) the core holds {} MB, past the {} MB a run may hold; run it in parts of fewer lines (this far is about {} lines), or lower stepsPerMm, or free the programs and traces held before it",
                self.lines_done,
                self.lines,
                self.moves.len(),
                self.steps,
                mb(held),
                mb(self.heap_budget_bytes),
                self.lines_done
            ),
        ))
    }

    /// A `%` line after the program has begun (after an opening `%` line,
    /// or after a line with codes or words) ends it, as LinuxCNC reads a
    /// program between two `%` lines: the lines after it are not read, and
    /// a warning says how many hold anything. Grbl has no `%` (its
    /// protocol.c leaves it as a TODO, and gc_execute_line refuses it:
    /// error 1, expected command letter).
    fn end_at_percent(&mut self, line: u32, column: u32) {
        let rest = &self.source[self.offset..];
        // The lines that hold anything, ended as the program's lines are
        // (a lone CR too: str::lines knows only LF): blank lines are not counted.
        let unread = crate::text::lines(rest)
            .filter(|l| !l.trim().is_empty())
            .count();
        if unread > 0 {
            let (lines, are) = if unread == 1 {
                ("line", "is")
            } else {
                ("lines", "are")
            };
            self.warn(Diagnostic::at(
                line,
                &Problem {
                    column,
                    message: format!(
                        "% ends the program: the {unread} {lines} after it {are} not read (a program stands between two % lines, as in LinuxCNC)"
                    ),
                },
            ));
        }
        self.offset = self.source.len();
        self.lines_done = self.lines;
    }

    /// Runs every line left.
    pub fn run_to_end(mut self) -> Program {
        self.advance(u32::MAX);
        self.finish()
    }

    fn warn(&mut self, diagnostic: Diagnostic) {
        if self.warnings.len() < MAX_WARNINGS {
            self.warnings.push(diagnostic);
        } else {
            self.warnings_omitted += 1;
        }
    }

    fn stop(&mut self, error: Diagnostic) {
        self.stopped_at_line.get_or_insert(error.line);
        self.errors.push(error);
    }

    fn run_block(&mut self, line: u32, block: &Block, effects: &mut Effects) {
        if let Some(problem) = &block.error {
            // The reader stops at its first error: a fault the words and
            // codes before it show on their own comes first in the line.
            let fault = interpret::first_fault_on_its_own(line, block)
                .map(Diagnostic::from_error)
                .filter(|fault| fault.column < problem.column);
            self.stop(fault.unwrap_or_else(|| Diagnostic::at(line, problem)));
            return;
        }
        if self.stopped_at_line.is_some() {
            // After the first error only syntax is checked: the modal
            // state a later line would run in is unknown.
            return;
        }
        if let Err(e) = self.interpreter.run(line, block, effects) {
            return self.stop(Diagnostic::from_error(e));
        }
        for w in &effects.warnings {
            self.warn(Diagnostic::at(line, w));
        }
        if let Some(dwell_seconds) = effects.stop {
            self.planner.stop(dwell_seconds);
        }
        if let Some(m) = &effects.motion {
            if let Err(e) = self.step_move(m) {
                return self.stop(Diagnostic::from_error(e));
            }
        }
        if effects.stop_after {
            self.planner.stop(0.0);
        }
    }

    /// A point in steps, or an error naming the axis word whose target
    /// leaves the grid.
    fn steps_of(&self, m: &MoveMm, mm: [f64; MACHINE_AXES]) -> Result<Point, Error> {
        let mut c = [0; MACHINE_AXES];
        for axis in 0..MACHINE_AXES {
            c[axis] = self
                .settings
                .machine
                .to_steps(axis, mm[axis])
                .ok_or_else(|| {
                    Error::at(
                        m.line,
                        m.axis_columns[axis],
                        format!(
                            "{} = {} mm is beyond the machine's ±2^30 steps on {}",
                            AXIS_NAMES[axis].to_uppercase(),
                            mm[axis],
                            AXIS_NAMES[axis]
                        ),
                    )
                })?;
        }
        Ok(Point::new(&c))
    }

    /// Runs one catalogue request and appends its trace. Returns (steps,
    /// segments) added.
    fn append(&mut self, m: &MoveMm, mut request: Request) -> Result<(u64, usize), Error> {
        let place = |e: Error| match (e.field_name(), e.too_many_chords.as_deref()) {
            (Some("maxSteps"), _) => {
                // The whole program needs the steps before this move and at least the move's.
                let at_least = self.steps + e.limit.as_ref().map_or(1, |l| l.at_least);
                Error::at(
                    m.line,
                    m.column,
                    format!(
                        "the program needs more than maxSteps = {} steps by this move (at least {at_least}); {}",
                        self.settings.max_steps,
                        too_long_advice(at_least, "the program or lower its steps per mm")
                    ),
                )
                .with_limit(Limit {
                    option: "maxSteps".into(),
                    value: self.settings.max_steps,
                    at_least,
                    most: MAX_STEPS_LIMIT,
                })
            }
            // arc-segments' chord options are no settings of a program:
            // "tolerance: ...; use longer chords" asked for one it cannot set.
            (Some(option), Some(refusal)) => Error::at(
                m.line,
                m.column,
                format!(
                    "at its default {option}, which a program does not set, arc-segments splits this arc into {}, more than {}: give the arc fewer turns (P) or a smaller radius, or run arcs with arcAlgorithm circle",
                    refusal.chords_text(),
                    refusal.most
                ),
            ),
            (Some(field), None) => Error::at(m.line, m.column, format!("{field}: {}", e.message)),
            (None, _) => e,
        };
        request.set(
            "maxSteps",
            Value::from(self.settings.max_steps - self.steps),
        );
        let info = algorithms::find(&request.algorithm).map_err(place)?;
        let part = (info.trace)(&request, algorithms::find).map_err(place)?;
        let added = (part.steps(), part.segment_count());
        self.builder.append(part, |_| {}).map_err(place)?;
        self.steps += added.0;
        self.segments += added.1;
        Ok(added)
    }

    /// Steps one move and keeps its record.
    fn step_move(&mut self, m: &MoveMm) -> Result<(), Error> {
        let from = self.builder.position();
        let to = self.steps_of(m, m.to_mm)?;
        let grid = |p: &Point| -> [i32; MACHINE_AXES] {
            std::array::from_fn(|axis| {
                i32::try_from(p.get(axis)).expect("grid coordinates are within ±2^30")
            })
        };
        let index = self.moves.len();
        debug_assert_eq!(
            (m.from_mm, grid(&from)),
            (self.moves.start_mm(index), self.moves.start_steps(index)),
            "a move starts where the one before it ended"
        );
        let first_step = self.steps;
        let mut record = MoveRecord {
            to_mm: m.to_mm,
            feed_mm_per_min: f64::NAN,
            to_steps: grid(&to),
            line: m.line,
            column: m.column,
            first_segment: u32::try_from(self.segments).expect("fewer than 2^32 segments"),
            arc: NO_ARC,
            motion: m.motion,
        };
        match &m.arc {
            None => self.step_line(m, from, to)?,
            Some(arc) => {
                let arc = self.step_arc(m, arc, from, to)?;
                record.arc = u32::try_from(self.moves.arcs.len()).expect("fewer arcs than lines");
                self.moves.arcs.push(arc);
            }
        }
        let pushed = timing::push_move(&mut self.planner, &self.settings.machine, m, &from, &to);
        let dwell_before = match pushed.blocks.is_empty() {
            true => self.planner.dwell_since_last_block(),
            false => 0.0,
        };
        self.spans
            .push(first_step, pushed.blocks.start, dwell_before);
        // In G93 the feed asked is F times the move's length.
        record.feed_mm_per_min = pushed.feed_mm_per_min.unwrap_or(f64::NAN);
        // Grbl's two feed limits, each said once per feed asked: every later
        // move at the same F (in G93, the same F and length) is held alike.
        if let Some(feed) = pushed.feed_mm_per_min {
            let asked = Some((m.inverse_time_per_min, feed));
            let said = |message: String| Diagnostic {
                line: record.line,
                column: record.column,
                message,
                limit: None,
            };
            if self.raised_feed_warned != asked && !pushed.blocks.is_empty() {
                if let Some(message) = timing::feed_raised_message(feed, m.inverse_time_per_min) {
                    self.raised_feed_warned = asked;
                    self.warn(said(message));
                }
            }
            if let Some(top) = pushed
                .feed_capped_to_mm_per_min
                .filter(|_| self.capped_feed_warned != asked)
            {
                self.capped_feed_warned = asked;
                let arc = m.arc.is_some();
                self.warn(said(timing::feed_capped_message(
                    feed,
                    m.inverse_time_per_min,
                    top,
                    arc,
                )));
            }
        }
        self.moves.records.push(record);
        Ok(())
    }

    /// The grid center of an arc from `from` to `to` (steps) about
    /// `center` (steps, real): see the module comment.
    fn grid_center(from: [i64; 2], to: [i64; 2], center: [f64; 2]) -> Option<[i64; 2]> {
        let (s, e) = (
            [from[0] as f64, from[1] as f64],
            [to[0] as f64, to[1] as f64],
        );
        let chord = [e[0] - s[0], e[1] - s[1]];
        let length = chord[0].hypot(chord[1]);
        let aim = if length == 0.0 {
            center
        } else {
            // Project onto the bisector: through the chord's middle, along
            // the chord's normal.
            let mid = [(s[0] + e[0]) / 2.0, (s[1] + e[1]) / 2.0];
            let normal = [-chord[1] / length, chord[0] / length];
            let t = (center[0] - mid[0]) * normal[0] + (center[1] - mid[1]) * normal[1];
            [mid[0] + t * normal[0], mid[1] + t * normal[1]]
        };
        let rounded = [aim[0].round() as i64, aim[1].round() as i64];
        // Nearest first, by squared distance, each found once (in an array:
        // every arc of a program looks for its center). A neighbour as near
        // as the rounded center (the aim half a step off the grid) comes
        // after it: taken first by its place in the array, the lower one
        // won, so a center at +0.5 went down and one at -0.5 away from zero,
        // and the note said the rounded one broke the tolerance.
        let mut candidates: [(f64, [i64; 2]); 9] = std::array::from_fn(|k| {
            let c = [rounded[0] + k as i64 / 3 - 1, rounded[1] + k as i64 % 3 - 1];
            let (du, dv) = (c[0] as f64 - aim[0], c[1] as f64 - aim[1]);
            (du * du + dv * dv, c)
        });
        candidates.sort_by(|a, b| {
            a.0.total_cmp(&b.0)
                .then_with(|| (a.1 != rounded).cmp(&(b.1 != rounded)))
        });
        let radius_sq = |p: [i64; 2], c: [i64; 2]| {
            let (du, dv) = ((p[0] - c[0]) as i128, (p[1] - c[1]) as i128);
            du * du + dv * dv
        };
        candidates.into_iter().map(|(_, c)| c).find(|&c| {
            let (a, b) = (radius_sq(from, c), radius_sq(to, c));
            a > 0 && b > 0 && radii_within_tolerance(a, b)
        })
    }

    /// Steps an arc move and returns what its record keeps of the arc.
    fn step_arc(
        &mut self,
        m: &MoveMm,
        arc: &ArcMm,
        from: Point,
        to: Point,
    ) -> Result<ArcRecord, Error> {
        let [u, v, n] = arc.plane.axes();
        let spm = self.settings.machine.steps_per_mm();
        if spm[u] != spm[v] {
            // Named here only: two strings made for every arc cost more
            // than the rest of this check.
            let (un, vn) = (AXIS_NAMES[u].to_uppercase(), AXIS_NAMES[v].to_uppercase());
            return Err(Error::at(
                m.line,
                m.column,
                format!(
                    "{} in the {}: {un} and {vn} have different steps per mm ({} and {}), so this circle in mm is an ellipse in steps, which voxpath's arc algorithms do not step; give {un} and {vn} the same steps per mm",
                    m.motion.code(),
                    arc.plane.describe(),
                    spm[u],
                    spm[v]
                ),
            ));
        }
        let helical = from.get(n) != to.get(n);
        let mut kept = ArcRecord {
            arc: arc.clone(),
            center_steps: None,
            turns: 0,
            as_line: None,
        };
        let center_real = [arc.center_mm[u] * spm[u], arc.center_mm[v] * spm[v]];
        for (i, axis) in [u, v].into_iter().enumerate() {
            // The grid center is found near this point in i64: it must be
            // on the grid (a far center from a huge I, J, K or R would
            // otherwise wrap). NaN is refused too.
            if center_real[i].is_nan() || center_real[i].abs() > COORD_LIMIT as f64 {
                let (letter, column) = arc.center_words[i];
                return Err(Error::at(
                    m.line,
                    column,
                    format!(
                        "{letter}: the arc's center {} = {} mm is beyond the machine's ±2^30 steps on {} ({} steps/mm)",
                        AXIS_NAMES[axis].to_uppercase(),
                        arc.center_mm[axis],
                        AXIS_NAMES[axis],
                        spm[axis]
                    ),
                ));
            }
        }
        let grid = Self::grid_center(
            [from.get(u), from.get(v)],
            [to.get(u), to.get(v)],
            center_real,
        );
        let Some(c) = grid else {
            kept.as_line = Some(TOO_SMALL);
            self.step_line(m, from, to)?;
            return Ok(kept);
        };
        let mut center = from;
        center.coords_mut()[u] = c[0];
        center.coords_mut()[v] = c[1];
        kept.center_steps = Some(center.coords().try_into().expect("3 axes"));
        let place = |e: Error| {
            if e.field_name() != Some(CENTER.name) {
                return Error::at(m.line, m.column, format!("{e}"));
            }
            // The circle about this center reaches off the grid: the fault
            // of the word that put the center there (I, J, K or R), named
            // at its column, on the axis it reaches past.
            let radius = ((from.get(u) - c[0]) as f64).hypot((from.get(v) - c[1]) as f64);
            let past = (0..2)
                .find(|&i| c[i].abs() as f64 + radius > COORD_LIMIT as f64)
                .unwrap_or(0);
            let (letter, column) = arc.center_words[past];
            Error::at(
                m.line,
                column,
                format!("{letter}: at {} steps/mm, {}", spm[[u, v][past]], e.message),
            )
        };
        let spec = ArcSpec::new(from, to, center, arc.plane, arc.turn, 0, true).map_err(place)?;
        // A full circle in steps whose chords all end on its start plans
        // no motion: a grid circle about a center found for it took steps
        // (4 diagonal ones about a center 1 step off, for a circle a
        // hundredth of a step across) that the plan gave no time to, all at
        // one instant. Only a circle that ends where it starts can, so no
        // other arc pays for its chords twice; checked once the circle is
        // known to lie on the grid, so that every vertex rounds to a step.
        let ends: [i64; MACHINE_AXES] = to.coords().try_into().expect("3 axes");
        if from == to && !timing::plans_a_step(&self.settings.machine, m, ends, ends) {
            kept.as_line = Some(NO_CHORD_MOVES);
            self.step_line(m, from, to)?;
            return Ok(kept);
        }
        let local = spec.local_sweep_rad();
        // Extra turns on the grid: those that bring the grid sweep nearest
        // the programmed one.
        let turns = ((arc.sweep_rad.abs() - local) / TAU).round();
        if turns < 0.0 {
            kept.as_line = Some(UNDER_ONE_STEP);
            self.step_line(m, from, to)?;
            return Ok(kept);
        }
        kept.turns = turns as u64;
        let circle = self.settings.arc_algorithm == circle_saleem::INFO.id;
        // A planar arc's spec with its turns is the one the circle checks
        // (same height, and turns within what a request may ask).
        if self.in_place
            && circle
            && !helical
            && kept.turns <= MAX_TURNS as u64
            && self.run_circle(&ArcSpec {
                turns: kept.turns,
                ..spec
            })
        {
            return Ok(kept);
        }
        let mut request = arc_request(from, to, center, arc);
        request.set("turns", Value::from(kept.turns));
        let segments = self.settings.arc_algorithm == "arc-segments";
        let algorithm = if helical {
            request.set(
                "method",
                Value::from(if segments { "segments" } else { "saleem" }),
            );
            "helix"
        } else {
            self.settings.arc_algorithm
        };
        if segments {
            request.set("lineAlgorithm", Value::from(self.settings.line_algorithm));
        }
        request.algorithm = algorithm.to_string();
        self.append(m, request)?;
        Ok(kept)
    }

    /// Steps a straight move from `from` to `to` with the line algorithm.
    fn step_line(&mut self, m: &MoveMm, from: Point, to: Point) -> Result<(), Error> {
        if self.in_place && self.run_unit_line(from, to) {
            return Ok(());
        }
        let line_stepper = self.moves.line_stepper;
        let direct = self.in_place
            && line_stepper
                .with_stepper(
                    from,
                    to,
                    RunInPlace {
                        runner: self,
                        from,
                        to,
                    },
                )
                .unwrap_or(false);
        if !direct {
            let line = self.settings.line_algorithm;
            self.append(m, line_request(line, from, to))?;
        }
        Ok(())
    }

    /// Puts in a straight move of at most a unit on every axis as the line
    /// algorithm would step it, where it takes such a line in one step
    /// ([`Runner::unit_lines`]): one step moving every axis that differs,
    /// none for a move that stays on its cell. False, doing nothing, for
    /// any other move or rule, or past maxSteps.
    fn run_unit_line(&mut self, from: Point, to: Point) -> bool {
        let Some((columns, figure)) = self.unit_lines else {
            return false;
        };
        if jumps(from.coords(), to.coords()) {
            return false;
        }
        let code = Step::between(from.coords(), to.coords());
        let step = (code != Step::NONE).then_some(code);
        let steps = step.is_some() as u64;
        if steps > self.settings.max_steps - self.steps {
            return false;
        }
        self.builder
            .run_unit_made_when_read(step, columns, figure)
            .expect("a step within maxSteps runs");
        self.steps += steps;
        self.segments += 1;
        true
    }

    /// Runs the planar circle arc `spec` straight into the program's
    /// trace, checked as the
    /// circle algorithm's own trace checks it (maxSteps
    /// being what the program has left), so it takes the same steps,
    /// segment and checkpoints the catalogue path would append. False,
    /// doing nothing, where that path would fail (it then says why).
    fn run_circle(&mut self, spec: &ArcSpec) -> bool {
        let left = self.settings.max_steps - self.steps;
        let Some(stepper) = circle_arc_stepper(spec, left) else {
            return false;
        };
        let before = self.builder.steps();
        self.builder
            .run_made_when_read(stepper, || IdealPath::Arc(spec.ideal_arc()))
            .expect("a circle within maxSteps runs");
        self.steps += self.builder.steps() - before;
        self.segments += 1;
        true
    }

    /// Runs a line stepper straight into the program's trace when its
    /// length is known and fits what is left of maxSteps: then it cannot
    /// fail, and it takes exactly the steps, segment, note and checkpoints
    /// the catalogue path would append. False, doing nothing, otherwise (the
    /// catalogue path then says why it cannot run).
    fn run_line<S: Stepper>(&mut self, stepper: S, from: Point, to: Point) -> bool {
        let Some(steps) = stepper.remaining_steps() else {
            return false;
        };
        if steps > self.settings.max_steps - self.steps {
            return false;
        }
        let before = self.builder.steps();
        self.builder
            .run_made_when_read(stepper, || IdealPath::Line { from, to })
            .expect("a line of known length within maxSteps runs");
        self.steps += self.builder.steps() - before;
        self.segments += 1;
        true
    }

    /// Finishes the trace (the moves run so far) and the program's record.
    pub fn finish(mut self) -> Program {
        let planner = std::mem::replace(&mut self.planner, Planner::new(self.settings.limits));
        let mut spans = std::mem::take(&mut self.spans);
        spans.finish(self.steps, planner.len());
        let spans = Rc::new(spans);
        let timeline = Timeline::new(planner, Rc::clone(&spans));
        let spm = self.settings.machine.steps_per_mm();
        for (index, axis, needed, max) in timeline.step_rate_excesses(&self.settings.limits, &spm) {
            let (line, column) = self.moves.place(index);
            self.warn(Diagnostic {
                line,
                column,
                message: timing::step_rate_message(axis, needed, max),
                limit: None,
            });
        }
        let mut moves = self.moves;
        moves.spans = spans;
        moves.segments = u32::try_from(self.segments).expect("fewer than 2^32 segments");
        moves.records.shrink_to_fit();
        moves.arcs.shrink_to_fit();
        let records = Rc::new(moves);
        let (notes, segments, ideals, starts) = (
            Rc::clone(&records),
            Rc::clone(&records),
            Rc::clone(&records),
            Rc::clone(&records),
        );
        let trace = self
            .builder
            .finish(&format!(
                "gcode ({}, {})",
                self.settings.line_algorithm, self.settings.arc_algorithm
            ))
            .with_note_prefix(Rc::new(move |segment| notes.note_of_segment(segment)))
            .with_segment_maker(
                Rc::new(move |segment| segments.made_segment(segment)),
                Rc::new(move |segment| ideals.made_ideal(segment)),
                Rc::new(move |segment| starts.made_start(segment)),
            );
        let info = ProgramInfo {
            lines: self.lines,
            steps: trace.steps(),
            steps_per_mm: self.settings.machine.steps_per_mm(),
            line_algorithm: self.settings.line_algorithm,
            arc_algorithm: self.settings.arc_algorithm,
            move_count: records.len(),
            duration_seconds: timeline.duration_seconds(),
            pulses: trace.pulses_by_axis(),
            warnings: self.warnings,
            warnings_omitted: self.warnings_omitted,
            errors: self.errors,
            stopped_at_line: self.stopped_at_line,
        };
        Program {
            trace,
            info,
            records,
            timeline,
        }
    }
}

/// Runs a whole program.
pub fn run(source: &str, settings: Settings) -> Program {
    Runner::new(source.to_string(), settings).run_to_end()
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn a_center_half_a_step_off_the_grid_rounds_as_every_coordinate_does() {
        // Halves away from zero, on either side: the rounded center keeps
        // both radii equal here (11 and 11; 401 and 400 from 0 and 801),
        // so no neighbour is needed. Found by a hunt: (0, 0.5) gave (0, 0),
        // a 169.6° arc for 180°, and 400.5 gave 400 where -400.5 gave -401.
        assert_eq!(
            Runner::grid_center([11, 1], [-11, 1], [0.0, 0.5]),
            Some([0, 1])
        );
        assert_eq!(
            Runner::grid_center([0, 0], [801, 0], [400.5, 0.0]),
            Some([401, 0])
        );
        assert_eq!(
            Runner::grid_center([0, 0], [-801, 0], [-400.5, 0.0]),
            Some([-401, 0])
        );
        assert_eq!(
            Runner::grid_center([381, 445], [281, 445], [331.0, 444.5]),
            Some([331, 445])
        );
    }

    #[test]
    fn an_arc_of_too_many_chords_is_told_what_a_program_can_change() {
        // "tolerance: splits this arc into 70265 chords, more than 65536; use
        // longer chords": a program sets no tolerance.
        let settings = r#"{"stepsPerMm": 10, "arcAlgorithm": "arc-segments"}"#;
        for (source, chords) in [
            ("G1 F100\nG2 X0 Y0 I50 P1000", "70265 chords"),
            ("G1 F100\nG2 X0 Y0 I5 P1000000", "22270159 chords"),
            // A helix's chords, counted by the same rule.
            ("G1 F100\nG2 X0 Y0 Z5 I5 P1000000", "22270159 chords"),
        ] {
            let p = run(source, Settings::from_json(settings).unwrap());
            let e = &p.info.errors[0];
            assert_eq!(
                (e.line, e.column, e.message.as_str()),
                (
                    2,
                    1,
                    format!(
                        "at its default tolerance, which a program does not set, arc-segments splits this arc into {chords}, more than 65536: give the arc fewer turns (P) or a smaller radius, or run arcs with arcAlgorithm circle"
                    )
                    .as_str()
                ),
                "{source}"
            );
        }
    }

    #[test]
    fn a_line_cut_short_by_the_reader_is_told_its_first_fault() {
        // The reader stops at its own first error (a fifth M code, a second
        // X); a fault its words and codes before that show on their own
        // comes first, as the same line without the reader's error is told.
        let first_error = |source: &str| {
            let p = run(source, Settings::from_json(r#"{"stepsPerMm": 1}"#).unwrap());
            let e = &p.info.errors[0];
            (e.line, e.column, e.message.clone())
        };
        let spindle_twice = "M3 and M3 are both spindle codes: give one per line";
        for (source, column, message) in [
            // Was column 13, "too many M codes".
            ("M3 M3 M3 M3 M3", 4, spindle_twice),
            ("M3 M3", 4, spindle_twice),
            // Was column 10, "X appears twice".
            (
                "G1 G0 X1 X2",
                4,
                "G1 and G0 are both motion codes: give one per line",
            ),
            (
                "G1 X1 F-1 X2",
                7,
                "F-1: F cannot be negative (Grbl refuses it: error 4, negative value)",
            ),
            (
                "G92.2 X1 X2",
                1,
                "G92.2 is not supported, as in Grbl (error 20, unsupported command): the positions of the lines after it would be unknown; use G92.1 to clear the G92 offset, G92 to set one",
            ),
            // Two faults on their own: the first by column (the negative
            // word was told first, at column 7).
            ("M3 M3 F-1", 4, spindle_twice),
            // Whatever the rest would have said is not judged: an arc whose
            // I stands after the cut, a dwell whose P does.
            (
                "G2 X2 M3 M7 M0 M48 M49 I1",
                20,
                "too many M codes on this line: a line takes at most 4 (as LinuxCNC has it)",
            ),
            ("G4 X1 X2 P1", 7, "X appears twice on this line"),
        ] {
            assert_eq!(
                first_error(source),
                (1, column, message.to_string()),
                "{source}"
            );
        }
        // After the program has stopped, a cut line is told its first fault too.
        let p = run(
            "G92.2\nM3 M3 M3 M3 M3",
            Settings::from_json(r#"{"stepsPerMm": 1}"#).unwrap(),
        );
        let second = &p.info.errors[1];
        assert_eq!(
            (second.line, second.column, second.message.as_str()),
            (2, 4, spindle_twice)
        );
    }

    /// A run of `source` with straight moves stepped as chosen: straight
    /// into the trace, or through the catalogue's request, as before the
    /// fast path.
    fn run_with(source: &str, settings: &str, by_request: bool) -> Program {
        let mut runner = Runner::new(source.to_string(), Settings::from_json(settings).unwrap());
        runner.in_place = !by_request;
        runner.run_to_end()
    }

    /// Everything a user reads of a program's trace and moves, as text.
    fn seen(p: &Program) -> Vec<String> {
        let t = &p.trace;
        let mut out = vec![
            serde_json::to_string(&p.info).unwrap(),
            serde_json::to_string(&p.moves()).unwrap(),
            serde_json::to_string(&t.summary()).unwrap(),
            serde_json::to_string(&t.legend()).unwrap(),
            serde_json::to_string(&t.segment_summaries()).unwrap(),
            format!("{:?}", t.points_flat(0, t.steps() + 1)),
            format!("{:?}", t.decisions_flat(0, t.steps())),
            format!("{:?}", t.metrics()),
            format!("{:?}", t.chart_rows(0, t.steps() + 1, 7)),
            format!("{:?}", t.ideal_polyline()),
        ];
        out.extend((0..t.steps()).map(|k| t.explain(k)));
        out
    }

    fn program_line() -> impl Strategy<Value = String> {
        let mm = || (-800i64..=800).prop_map(|v| format!("{:.2}", v as f64 / 100.0));
        prop_oneof![
            4 => (prop::sample::select(vec!["G0", "G1"]), mm(), mm(), mm())
                .prop_map(|(g, x, y, z)| format!("{g} X{x} Y{y} Z{z} F300")),
            1 => (prop::sample::select(vec!["G2", "G3"]), mm(), mm(), mm(), mm(), 0u32..2)
                .prop_map(|(g, x, y, i, j, p)| format!("{g} X{x} Y{y} I{i} J{j} P{}", p + 1)),
            1 => (prop::sample::select(vec!["G2", "G3"]), mm(), mm(), mm(), mm())
                .prop_map(|(g, x, y, z, r)| format!("{g} X{x} Y{y} Z{z} R{r}")),
        ]
    }

    /// A straight move longer than a checkpoint interval is kept whole,
    /// with its stepper states, beside short moves made again when read:
    /// every line algorithm reads back as the catalogue path's.
    #[test]
    fn long_straight_moves_read_back_as_the_catalogue_path() {
        let source = "G1 X70 Y-23 Z9 F600\nG1 X1 Y2 Z3\nG0 X-60 Y70 Z0";
        for line in crate::arc::arc_segments::LINE_ALGORITHMS {
            let settings = format!(r#"{{"stepsPerMm": 80, "lineAlgorithm": "{line}"}}"#);
            let fast = run_with(source, &settings, false);
            assert!(
                fast.trace.steps() > 2 * crate::trace::CHECKPOINT_INTERVAL,
                "{line}"
            );
            assert_eq!(
                seen(&fast),
                seen(&run_with(source, &settings, true)),
                "{line}"
            );
        }
    }

    /// Moves of at most a step on every axis, in all 27 directions, and
    /// past two checkpoint intervals of such steps: put in without their
    /// stepper where the line algorithm takes them in one step
    /// ([`Runner::run_unit_line`]), they read back as the catalogue path's,
    /// whatever the algorithm.
    #[test]
    fn unit_moves_read_back_as_the_catalogue_path() {
        let mut lines = vec!["G1 X0 Y0 Z0 F300".to_string()];
        let mut at = [0i64; 3];
        for k in 0..(2 * crate::trace::CHECKPOINT_INTERVAL as i64 + 1000) {
            let i = k % 27;
            let delta = [i % 3 - 1, i / 3 % 3 - 1, i / 9 - 1];
            for axis in 0..3 {
                at[axis] += delta[axis];
            }
            lines.push(format!("G1 X{} Y{} Z{}", at[0], at[1], at[2]));
        }
        let source = lines.join("\n");
        for line in crate::arc::arc_segments::LINE_ALGORITHMS {
            let settings = format!(r#"{{"stepsPerMm": 1, "lineAlgorithm": "{line}"}}"#);
            let fast = run_with(&source, &settings, false);
            assert!(
                fast.trace.steps() > 2 * crate::trace::CHECKPOINT_INTERVAL,
                "{line}"
            );
            assert_eq!(
                seen(&fast),
                seen(&run_with(&source, &settings, true)),
                "{line}"
            );
        }
    }

    /// An arc whose end rounds onto its start (or just behind it) turns
    /// less than a step on the grid and is stepped as a line, though it has
    /// a grid center: its segment, made again when read, is the line's
    /// (the fuzz target found it made as a circle, whose columns the trace
    /// did not have).
    #[test]
    fn arcs_stepped_as_lines_read_back_as_lines() {
        for source in [
            "G2 X0.001 Y0.1 I5 J0 F300",
            "G1 X1 F300\nG2 X1.001 Y0.1 I5 J0\nG1 X3",
        ] {
            let settings = r#"{"stepsPerMm": 1}"#;
            let fast = run_with(source, settings, false);
            let arc = fast.moves().into_iter().find(|m| m.arc.is_some()).unwrap();
            assert!(
                arc.note.contains("stepped as a straight line"),
                "{source}: {}",
                arc.note
            );
            assert_eq!(
                seen(&fast),
                seen(&run_with(source, settings, true)),
                "{source}"
            );
        }
    }

    /// A full circle all of whose chords end on its start step plans no
    /// motion, as in Grbl, and takes no step: it took 4 diagonal steps
    /// about a grid center 1 step off, all at one instant (8 pulses in
    /// 0 s for a circle 0.01 steps across).
    #[test]
    fn a_circle_whose_chords_all_end_on_its_start_takes_no_step() {
        let source = "G1 X0 Y0 F600\nG2 X0 Y0 I5 J0\nG1 X2000";
        let settings = r#"{"stepsPerMm": 0.001}"#;
        for by_request in [false, true] {
            let program = run_with(source, settings, by_request);
            let arc = &program.moves()[1];
            assert_eq!(arc.steps, 0, "{}", arc.note);
            assert!(arc.note.contains("Grbl does not move"), "{}", arc.note);
            assert_eq!(program.trace.steps(), 2);
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]

        /// Every move that steps has time on the planned profile to step
        /// in, whatever its size against a step: full circles from a
        /// hundredth of a step across to a few steps, about centers off the
        /// grid, at steps per mm from 0.001 to 1000.
        #[test]
        fn every_move_that_steps_takes_time(
            radius_steps in 0.005f64..4.0,
            off in (-0.5f64..0.5, -0.5f64..0.5),
            steps_per_mm in prop::sample::select(vec![0.001, 0.1, 1.0, 80.0, 1000.0]),
            arc in prop::sample::select(ARC_ALGORITHMS),
        ) {
            let mm = |steps: f64| steps / steps_per_mm;
            let source = format!(
                "G1 X{} Y{} F600\nG3 X{} Y{} I{} J0\nG1 X0 Y0",
                mm(off.0), mm(off.1), mm(off.0), mm(off.1), mm(radius_steps)
            );
            let settings = format!(r#"{{"stepsPerMm": {steps_per_mm}, "arcAlgorithm": "{arc}"}}"#);
            let program = run_with(&source, &settings, false);
            for m in program.moves() {
                prop_assert!(
                    m.steps == 0 || m.timing.end_seconds > m.timing.start_seconds,
                    "{source}: line {} takes {} steps in no time ({})", m.line, m.steps, m.note
                );
            }
        }
    }

    proptest! {
        /// The vector count of a text's lines is the count of the lines
        /// the runner reads one by one, whatever the mix of LF, CR LF and
        /// lone CR breaks, blank lines and a last line with or without one.
        #[test]
        fn lines_counted_by_their_breaks_are_the_lines_read(
            parts in proptest::collection::vec(
                prop_oneof![Just("a"), Just("G1 X1"), Just(" "), Just("\n"), Just("\r"), Just("\r\n")],
                0..40,
            )
        ) {
            let text: String = parts.concat();
            prop_assert_eq!(count_lines(&text) as usize, crate::text::lines(&text).count().max(1));
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]

        /// Straight moves and circle arcs stepped straight into the
        /// program's trace give what the catalogue path gives: the same
        /// steps, points, segments
        /// and notes, decisions, explanations, moves and diagnostics, with
        /// every line algorithm, either arc algorithm and a maxSteps the
        /// program may run into.
        #[test]
        fn straight_moves_stepped_in_place_match_the_catalogue_path(
            lines in prop::collection::vec(program_line(), 1..10),
            line in prop::sample::select(crate::arc::arc_segments::LINE_ALGORITHMS),
            arc in prop::sample::select(ARC_ALGORITHMS),
            steps_per_mm in prop::sample::select(vec![1.0, 3.0, 10.0, 80.0]),
            max_steps in prop::sample::select(vec![50u64, 2000, 50_000_000]),
        ) {
            let source = lines.join("\n");
            let settings = format!(
                r#"{{"stepsPerMm": {steps_per_mm}, "lineAlgorithm": "{line}", "arcAlgorithm": "{arc}", "maxSteps": {max_steps}}}"#
            );
            let fast = run_with(&source, &settings, false);
            let slow = run_with(&source, &settings, true);
            prop_assert_eq!(seen(&fast), seen(&slow));
        }

        /// A program's ideal polyline is its segments' own, one after the
        /// other, each one's first vertex left out only where it repeats
        /// the vertex before (a line from where the last move ended, a
        /// chord of an arc): lines, arcs in chords or by the circle, and
        /// helices. The line for drawing holds the same vertices.
        #[test]
        fn the_ideal_polyline_joins_the_segments_own(
            lines in prop::collection::vec(program_line(), 1..12),
            arc in prop::sample::select(ARC_ALGORITHMS),
            steps_per_mm in prop::sample::select(vec![1.0, 10.0, 80.0]),
        ) {
            let settings = format!(r#"{{"stepsPerMm": {steps_per_mm}, "arcAlgorithm": "{arc}"}}"#);
            let p = run_with(&lines.join("\n"), &settings, false);
            let t = &p.trace;
            let dims = t.dims();
            let mut joined: Vec<f64> = Vec::new();
            for segment in t.segments() {
                let mut own = Vec::new();
                segment.ideal.polyline_into(&mut own);
                let first = own.len().min(dims);
                let repeats = joined.len() >= dims && joined[joined.len() - dims..] == own[..first];
                joined.extend_from_slice(&own[if repeats { first } else { 0 }..]);
            }
            // The line for drawing is the same vertices less its origin as
            // f32, after their box, then what the f32 left of each.
            let origin = [3.0, -2.0, 1.0];
            let line = t.ideal_line_f32(origin);
            let exact = joined.iter().enumerate().map(|(i, &v)| v - origin[i % 3]);
            let xyz: Vec<f32> = exact.clone().map(|v| v as f32).collect();
            let rests: Vec<f32> = exact.zip(&xyz).map(|(v, &drawn)| (v - f64::from(drawn)) as f32).collect();
            prop_assert_eq!(line.vertices(), xyz.len() / 3);
            prop_assert_eq!(line.xyz_pieces().flatten().copied().collect::<Vec<f32>>(), xyz.clone());
            prop_assert_eq!(line.rest_pieces().flatten().copied().collect::<Vec<f32>>(), rests);
            let bounds = line.bounds();
            for axis in 0..3 {
                let values = || xyz.iter().skip(axis).step_by(3).copied();
                let (min, max) = match values().next() {
                    None => (0.0, 0.0),
                    Some(_) => (values().fold(f32::INFINITY, f32::min), values().fold(f32::NEG_INFINITY, f32::max)),
                };
                prop_assert_eq!((bounds[axis], bounds[3 + axis]), (min, max), "axis {}", axis);
            }
            prop_assert_eq!(t.ideal_polyline(), joined);
        }

        /// A program's bounds are its points' extremes on each axis,
        /// however its stretches end: at a stored position, at a move's
        /// start read from its record (a stretch of START_READ_STEPS or
        /// more), or summed (a shorter one), and where a move turns back
        /// (an arc by the circle, walked).
        #[test]
        fn a_program_s_bounds_are_its_points_extremes(
            lines in prop::collection::vec(program_line(), 1..12),
            arc in prop::sample::select(ARC_ALGORITHMS),
            steps_per_mm in prop::sample::select(vec![1.0, 10.0, 80.0, 400.0]),
        ) {
            let settings = format!(r#"{{"stepsPerMm": {steps_per_mm}, "arcAlgorithm": "{arc}"}}"#);
            let p = run_with(&lines.join("\n"), &settings, false);
            let t = &p.trace;
            let dims = t.dims();
            let points = t.points_flat(0, t.steps() + 1);
            let axis = |a: usize| points.iter().skip(a).step_by(dims).copied();
            let bounds = t.bounds();
            for a in 0..dims {
                prop_assert_eq!(bounds.min[a], axis(a).min().unwrap(), "axis {} min", a);
                prop_assert_eq!(bounds.max[a], axis(a).max().unwrap(), "axis {} max", a);
            }
        }

        /// The move of a segment, looked up in any order (so the move found
        /// last is sometimes the right one, sometimes the one before, and
        /// sometimes far off), is the one a search of the records finds:
        /// moves of one segment, of many (chords, helices) and of none.
        #[test]
        fn the_move_of_a_segment_is_found_in_any_order(
            lines in prop::collection::vec(program_line(), 1..12),
            arc in prop::sample::select(ARC_ALGORITHMS),
            order in prop::collection::vec(any::<prop::sample::Index>(), 1..64),
        ) {
            let source = format!("{}\nG1 X0 Y0 Z0\nG1 X0 Y0 Z0", lines.join("\n"));
            let settings = format!(r#"{{"stepsPerMm": 10, "arcAlgorithm": "{arc}"}}"#);
            let p = run_with(&source, &settings, false);
            let records = &p.records;
            let segments = records.segments as usize;
            prop_assume!(segments > 0);
            let searched = |segment: usize| {
                records.records.partition_point(|r| r.first_segment as usize <= segment) - 1
            };
            let in_order = (0..segments).chain(order.iter().map(|i| i.index(segments)));
            for segment in in_order {
                prop_assert_eq!(records.move_of_segment(segment), searched(segment), "segment {}", segment);
            }
        }
    }
}
