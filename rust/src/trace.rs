//! A trace: the steps an algorithm took, and everything needed to say why.
//!
//! Memory layout, chosen so that a 10,000,000-step path stays small:
//! - one packed [`Step`] (2 bytes) per step;
//! - a position every [`CHECKPOINT_INTERVAL`] steps, so any point is a short
//!   decode away;
//! - a copy of the stepper's state every [`CHECKPOINT_INTERVAL`] steps of each
//!   segment, so the decisions (discriminants, error terms, ...) of any step
//!   range are recomputed exactly by replaying at most that many steps,
//!   instead of being stored for every step. A short segment may instead be
//!   made again, whole, when read ([`SegmentMaker`]), so that a trace of a
//!   million short segments (a G-code program's moves) keeps 12 bytes per
//!   segment, not its ideal path, start and stepper state.
//!
//! Index spaces: a *step index* k (0..steps) names the step from point k to
//! point k + 1; a *point index* k (0..=steps) names the position after k steps.

use crate::error::{Error, Limit};
use crate::figure::{DecisionFigure, FigureKind};
use crate::grid::{MAX_AXES, Point, Step, displacement, written_steps};
use crate::ideal::curve::{ArcMeter, HelixMeter, HelixPoint};
use crate::ideal::info::IdealPathInfo;
use crate::ideal::line::LineMeter;
use crate::ideal::{IdealPath, Meter};
use crate::metrics::{Metrics, MetricsAccumulator};
use crate::points::Coordinate;
use crate::request::{MAX_STEPS_LIMIT, Request, too_long_advice};
use crate::starts::Starts;
use serde::Serialize;
use std::borrow::Cow;
use std::cell::{Cell, OnceCell, RefCell};
use std::mem::MaybeUninit;
use std::ops::Range;
use std::rc::Rc;
use std::sync::Arc;
use tsify::Tsify;

/// Steps between two stored positions / stepper states.
pub const CHECKPOINT_INTERVAL: u64 = 4096;

/// The value a category or flag column holds at a step it does not apply to
/// (a correction step has no fast axis, a line step of a G-code program no
/// octant): an index no label list reaches, and neither 0 nor 1, so it fits
/// the byte arrays such columns are read into and is never taken for a real
/// value. Number columns hold NaN there instead.
pub const NO_VALUE: u8 = 255;

/// How to read the values of one decision column. Crosses the boundary
/// flattened into its [`Column`]: `{ kind: "category", labels: [...] }`.
#[derive(Serialize, Tsify, Clone, Copy, Debug, PartialEq)]
#[serde(tag = "kind", rename_all = "camelCase")]
pub enum ColumnKind {
    /// An exact integer (|v| < 2^53, so exact in f64).
    Int,
    /// A real number.
    Float,
    /// An index into `labels` (fewer than [`NO_VALUE`] of them).
    Category { labels: &'static [&'static str] },
    /// 0 or 1.
    Flag,
}

impl ColumnKind {
    /// What a column of this kind holds at a step it does not apply to:
    /// [`NO_VALUE`] for categories and flags, NaN for numbers.
    pub fn no_value(self) -> f64 {
        match self {
            ColumnKind::Category { .. } | ColumnKind::Flag => f64::from(NO_VALUE),
            ColumnKind::Int | ColumnKind::Float => f64::NAN,
        }
    }

    /// True when `value` says the column does not apply to its step.
    pub fn is_no_value(self, value: f64) -> bool {
        value.is_nan() || value == self.no_value()
    }

    /// A value a stepper wrote, as the trace hands it out: a stepper marks
    /// a column that does not apply with NaN whatever its kind
    /// ([`Decision::write`]), and a category or flag cell turns that into
    /// [`NO_VALUE`] here.
    fn cell(self, written: f64) -> f64 {
        if written.is_nan() {
            self.no_value()
        } else {
            written
        }
    }
}

/// What part a column plays in its step's decision, where a view draws that
/// part: the page finds the columns it draws by role, never by name.
#[derive(Serialize, Tsify, Clone, Copy, Debug, PartialEq, Eq)]
#[serde(rename_all = "camelCase")]
pub enum ColumnRole {
    /// An error term the rule compares with the trace's `threshold` column
    /// (Bresenham's `error`, `errorX`, ...): an axis steps when its term
    /// passes the threshold.
    ErrorTerm,
    /// The value the error terms are compared with.
    Threshold,
}

/// One decision column: a quantity the algorithm computes at each step.
/// Where it does not apply to a step it holds NaN (int, float) or
/// [`NO_VALUE`] (category, flag).
#[derive(Serialize, Tsify, Clone, Copy, Debug)]
#[serde(rename_all = "camelCase")]
pub struct Column {
    /// Column name, camelCase, with a per-axis quantity's axis as an upper-case
    /// suffix (errorX); a single-letter symbol of the source paper keeps the
    /// paper's letter (Wang's M and N). See the README's Conventions.
    pub name: &'static str,
    #[serde(flatten)]
    // Named as a type, not an interface to extend: ColumnKind is a union.
    #[tsify(type = "ColumnKind")]
    pub kind: ColumnKind,
    /// One sentence: what the value is and where it comes from.
    pub doc: &'static str,
    /// The part it plays, for the columns a view draws as such.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub role: Option<ColumnRole>,
    /// The name it had before it was renamed to [`Column::name`]: the JS
    /// API's decision objects still answer to it (deprecated) until the
    /// release the README's Conventions name; CSV and JSON use `name` only.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub former_name: Option<&'static str>,
}

impl Column {
    /// A column with no role and no former name.
    pub const fn new(name: &'static str, kind: ColumnKind, doc: &'static str) -> Column {
        Column {
            name,
            kind,
            doc,
            role: None,
            former_name: None,
        }
    }

    /// This column, playing `role`.
    pub const fn with_role(self, role: ColumnRole) -> Column {
        Column {
            role: Some(role),
            ..self
        }
    }

    /// This column, renamed from `former_name`.
    pub const fn formerly(self, former_name: &'static str) -> Column {
        Column {
            former_name: Some(former_name),
            ..self
        }
    }
}

impl Column {
    /// A value of this column as people read it: a category's label, a
    /// flag's true or false, a number; None where the column does not apply
    /// to the step.
    pub fn read(&self, value: f64) -> Option<Reading> {
        if self.kind.is_no_value(value) {
            return None;
        }
        Some(match self.kind {
            ColumnKind::Category { labels } => labels
                .get(value as usize)
                .map_or(Reading::Float(value), |&label| Reading::Label(label)),
            ColumnKind::Flag => Reading::Flag(value == 1.0),
            // Exact integers stay integers in JSON (|v| < 2^53).
            ColumnKind::Int => Reading::Int(value as i64),
            ColumnKind::Float => Reading::Float(value),
        })
    }
}

/// A decision value as people read it (see [`Column::read`]).
#[derive(Serialize, Tsify, Clone, Copy, Debug, PartialEq)]
#[serde(untagged)]
pub enum Reading {
    Int(i64),
    Float(f64),
    Label(&'static str),
    Flag(bool),
}

/// Two columns are one when they declare the same name, kind and doc. The
/// same column is nearly always the same constant, whose doc is then the
/// same string in memory: compared by address first, the long sentences are
/// read only for copies (a trace joins every segment's columns this way, a
/// G-code program once per move).
impl PartialEq for Column {
    fn eq(&self, other: &Column) -> bool {
        self.name == other.name
            && self.kind == other.kind
            && (std::ptr::eq(self.doc, other.doc) || self.doc == other.doc)
    }
}

/// `first` then `second`, as one array of `N` = A + B columns (checked when
/// the constant is evaluated): for a decision that extends another's
/// columns, so the two lists cannot drift apart.
pub const fn concat_columns<const A: usize, const B: usize, const N: usize>(
    first: [Column; A],
    second: [Column; B],
) -> [Column; N] {
    assert!(A + B == N && A > 0, "N must be A + B, A at least 1");
    let mut out = [first[0]; N];
    let mut i = 0;
    while i < N {
        out[i] = if i < A { first[i] } else { second[i - A] };
        i += 1;
    }
    out
}

/// The reason for one step, as recorded by a [`Stepper`].
pub trait Decision: Copy {
    /// The columns [`Decision::write`] fills, in order.
    const COLUMNS: &'static [Column];

    /// Writes this decision's values, one per column (NaN where a column does
    /// not apply to this step, whatever its kind: the trace hands a category
    /// or flag cell out as [`NO_VALUE`]).
    fn write(&self, row: &mut [f64]);

    /// True when a tie (a discriminant exactly 0) was resolved by the tie policy.
    fn is_tie(&self) -> bool {
        false
    }

    /// True when [`Decision::is_tie`] is always false: the metrics pass, which
    /// counts ties by replaying each segment ([`Stepper::ties_ahead`]),
    /// then skips the replay.
    const NEVER_TIES: bool = false;

    /// One plain sentence saying why `step` was taken from `from`.
    fn explain(&self, from: &Point, step: Step) -> String;

    /// The picture [`Decision::figure`] makes of this type's steps, if any:
    /// a trace lists the pictures its steps can have, so a viewer knows
    /// before asking for a step.
    const FIGURE: Option<FigureKind> = None;

    /// The picture of this decision, for `step` taken from `from`: of kind
    /// [`Decision::FIGURE`], or None where a step has none (a correction
    /// step of the circle, a line of Wang's type ② with no face).
    fn figure(&self, _from: &Point, _step: Step) -> Option<DecisionFigure> {
        None
    }
}

/// An algorithm in motion: each call yields one step and the decision that
/// produced it. A step and its reason are one event.
///
/// # Safety
/// The [`Filled`] that [`Stepper::fill`] returns counts slots of the `out`
/// it was given that hold steps when it returns: its first that many.
/// [`fill_onto`] lengthens a vector over them on that promise. Each fill
/// makes its `Filled` by [`Filled::written`], saying there why its count
/// holds; the trait is unsafe to implement because safe code could still
/// break the promise (return another buffer's `Filled`, or put an
/// uninitialised value back into a slot it had written).
pub unsafe trait Stepper: Clone + 'static {
    type Why: Decision;

    /// The next step and why it was taken, or None at the end of the path.
    fn next_step(&mut self) -> Option<(Step, Self::Why)>;

    /// Takes up to `out.len()` steps into `out`, fewer only at the end of
    /// the path: how many, and where they moved ([`Filled::written`]: the
    /// first that many slots are written, the rest left as they were). This
    /// is how a trace records; it calls [`Stepper::next_step`], inlined into
    /// this loop for each stepper type, so the decisions, which nothing
    /// reads here, are never built (they are rebuilt by replay when asked
    /// for, ties included). A stepper that can take its steps or find their
    /// displacement more cheaply may override this.
    ///
    /// `out` is memory not yet written (the trace's step array past its
    /// end): each step is written once. Zeroed first, every chunk was
    /// written twice, and in wasm each zeroing was a call into the engine
    /// (memory.fill): trace() in Node of the bench's 3D line took 1.03 to
    /// 1.08 ms with it, 0.91 to 0.93 without, its 2D line 0.68 and 0.60.
    /// (The circle's pieces, which store at eight places of a chunk at
    /// once, write their stretch in order first: `written_in_order` in
    /// arc/circle_saleem.rs.) [`fill_onto`] runs it into a vector.
    #[inline]
    fn fill(&mut self, out: &mut [MaybeUninit<Step>]) -> Filled {
        fill_by_next_step(self, out)
    }

    /// How many of its next `steps` steps (fewer where the path ends
    /// first) a tie decides ([`Decision::is_tie`]): the metrics count the
    /// ties of a recorded stretch so, from the stepper's state before it.
    /// By taking the steps ([`ties_by_steps`]); a stepper that can count
    /// them for less overrides this: in closed form from its terms
    /// (Saleem's helix, whose ties its line's term alone decides, and whose
    /// circle the steps would take; the Bresenham lines; nd), a run at a
    /// time (greedy), or by a loop that builds no decision (walk6).
    fn ties_ahead(self, steps: u64) -> u64 {
        ties_by_steps(self, steps)
    }

    /// Steps this stepper will still take, when known without running it.
    /// When known, it drops by exactly the steps each `fill` or `next_step`
    /// takes: the trace reserves room by it, cuts its chunks to it, and
    /// keeps no first state of a segment made when read that it says ends
    /// before its first checkpoint ([`TraceBuilder::run_made_when_read`]).
    fn remaining_steps(&self) -> Option<u64>;

    /// The columns its decisions fill ([`Decision::write`]), in order: its
    /// decision type's, unless they depend on the move (nd's, on how many
    /// axes it has), so that a trace carries no column its steps never fill.
    fn columns(&self) -> &'static [Column] {
        Self::Why::COLUMNS
    }

    /// The largest distance from the ideal path any of this stepper's points
    /// can have, where its rule guarantees one; None where it makes no such
    /// promise (a float rule that can drift, greedy's).
    fn deviation_bound(&self) -> Option<DeviationBound> {
        None
    }

    /// What a learner should know about this particular move before it starts
    /// (line type, active axis, initial discriminants, ...).
    fn setup_note(&self) -> String;
}

/// [`Stepper::fill`] by [`Stepper::next_step`]: the default, and what an
/// override falls back to where its faster loop does not apply.
#[inline]
pub fn fill_by_next_step<S: Stepper>(stepper: &mut S, out: &mut [MaybeUninit<Step>]) -> Filled {
    let mut taken = out.len();
    for (k, slot) in out.iter_mut().enumerate() {
        let Some((step, _)) = stepper.next_step() else {
            taken = k;
            break;
        };
        slot.write(step);
    }
    // SAFETY: the loop wrote the first `taken` slots.
    let steps = unsafe { written_steps(&out[..taken]) };
    // SAFETY: the same.
    unsafe { Filled::written(taken, displacement(steps)) }
}

/// Appends up to `steps` more steps of `stepper` to `out` ([`Stepper::fill`],
/// fewer only at the end of its path), written once into room reserved
/// for them: how a trace records, and what the tests fill a vector with.
pub fn fill_onto<S: Stepper>(stepper: &mut S, out: &mut Vec<Step>, steps: usize) -> Filled {
    out.reserve(steps);
    let filled = stepper.fill(&mut out.spare_capacity_mut()[..steps]);
    assert!(
        filled.steps <= steps,
        "a fill takes at most the room it is given"
    );
    // SAFETY: the fill wrote the first `filled.steps` slots past the
    // vector's length (the promise of every Stepper's fill).
    unsafe { out.set_len(out.len() + filled.steps) };
    filled
}

/// A distance from the ideal path that no point of a trace exceeds, as its
/// algorithm guarantees, and the reason in a sentence.
#[derive(Serialize, Tsify, Clone, Debug, PartialEq)]
pub struct DeviationBound {
    /// Grid units.
    pub value: f64,
    pub why: String,
}

/// What [`Stepper::fill`] took: how many steps, written into the first
/// slots of its `out`, and where they moved, per axis (what
/// [`displacement`] gives). Made only by [`Filled::written`], whose
/// promise lets [`fill_onto`] count those slots as written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Filled {
    steps: usize,
    displacement: [i64; MAX_AXES],
}

impl Filled {
    /// What a fill took: `steps` steps, moving by `displacement`.
    ///
    /// # Safety
    /// The fill making it wrote every one of the first `steps` slots of the
    /// `out` it was given (and `steps` is at most its length).
    #[inline(always)]
    pub unsafe fn written(steps: usize, displacement: [i64; MAX_AXES]) -> Filled {
        Filled {
            steps,
            displacement,
        }
    }

    /// The steps taken.
    pub fn steps(&self) -> usize {
        self.steps
    }

    /// Where they moved, per axis.
    pub fn displacement(&self) -> [i64; MAX_AXES] {
        self.displacement
    }
}

/// A type-erased stepper whose state can be copied: the replay engine.
trait Replay {
    fn clone_box(&self) -> Box<dyn Replay>;
    /// Takes the next step, writing its decision into `row` (segment columns).
    fn replay_step(&mut self, row: &mut [f64]) -> Option<Step>;
    /// Takes the next step, explaining it.
    fn explain_step(&mut self, from: &Point) -> Option<String>;
    /// Takes the next step, writing its decision into `row` (segment
    /// columns): its explanation and its picture.
    fn detail_step(
        &mut self,
        from: &Point,
        row: &mut [f64],
    ) -> Option<(String, Option<DecisionFigure>)>;
    /// How many of the next `steps` steps a tie decides
    /// ([`Stepper::ties_ahead`]).
    fn count_ties(self: Box<Self>, steps: u64) -> u64;
    /// The stepper's [`Stepper::setup_note`] (of the state it is in).
    fn setup_note(&self) -> String;
}

impl<S: Stepper> Replay for S {
    fn clone_box(&self) -> Box<dyn Replay> {
        Box::new(self.clone())
    }

    fn replay_step(&mut self, row: &mut [f64]) -> Option<Step> {
        let (step, why) = self.next_step()?;
        why.write(row);
        Some(step)
    }

    fn explain_step(&mut self, from: &Point) -> Option<String> {
        let (step, why) = self.next_step()?;
        Some(why.explain(from, step))
    }

    fn detail_step(
        &mut self,
        from: &Point,
        row: &mut [f64],
    ) -> Option<(String, Option<DecisionFigure>)> {
        let (step, why) = self.next_step()?;
        why.write(row);
        let figure = why.figure(from, step);
        debug_assert!(
            figure
                .as_ref()
                .is_none_or(|f| Some(f.kind()) == S::Why::FIGURE),
            "a decision's figure is of the kind its type declares"
        );
        Some((why.explain(from, step), figure))
    }

    fn count_ties(self: Box<Self>, steps: u64) -> u64 {
        self.ties_ahead(steps)
    }

    fn setup_note(&self) -> String {
        Stepper::setup_note(self)
    }
}

/// The indices among a trace's columns of a stepper type's `columns`, where
/// they were found before ([`TraceBuilder::column_slots`], kept by the
/// trace for its segments made when read): by address, a constant's being
/// nearly always one, else by content, since it is not promised to be.
fn known_column_slots(
    known: &[(&'static [Column], Rc<[usize]>)],
    columns: &[Column],
) -> Option<Rc<[usize]>> {
    known
        .iter()
        .find(|(c, _)| std::ptr::eq(*c, columns) || **c == *columns)
        .map(|(_, slots)| Rc::clone(slots))
}

/// [`Stepper::ties_ahead`] by taking the steps and reading each one's
/// decision: the default, and the reference a closed form is held to.
pub fn ties_by_steps<S: Stepper>(mut stepper: S, steps: u64) -> u64 {
    if S::Why::NEVER_TIES {
        return 0;
    }
    (0..steps)
        .map_while(|_| stepper.next_step())
        .filter(|(_, why)| why.is_tie())
        .count() as u64
}

/// A stretch of the trace produced by one stepper against one ideal path
/// (a whole line, one chord of a segmented arc, one G-code move).
pub struct Segment {
    /// Step index of the segment's first step.
    pub first_step: u64,
    pub steps: u64,
    pub start: Point,
    pub ideal: IdealPath,
    /// The note of its stepper, or None when it is made when read from the
    /// stepper's state at the segment's start ([`Segment::note`]).
    pub setup_note: Option<String>,
    /// For each of the stepper's columns, its index among the trace columns
    /// (shared by the segments of one stepper type).
    column_index: Rc<[usize]>,
    /// Stepper state before the segment's first step.
    first_state: Box<dyn Replay>,
    /// Stepper state before segment step j * CHECKPOINT_INTERVAL, j >= 1
    /// (at index j - 1): a segment shorter than that keeps none.
    states: Vec<Box<dyn Replay>>,
}

/// A segment as read: kept by the trace, or made again when read.
// Returned, never stored: boxing the larger variant would add an
// allocation to every read.
#[allow(clippy::large_enum_variant)]
pub enum SegmentRef<'a> {
    Kept(&'a Segment),
    Made(Segment),
}

impl std::ops::Deref for SegmentRef<'_> {
    type Target = Segment;

    fn deref(&self) -> &Segment {
        match self {
            SegmentRef::Kept(segment) => segment,
            SegmentRef::Made(segment) => segment,
        }
    }
}

/// What a segment run by [`TraceBuilder::run_made_when_read`] is made
/// again from when read: where it starts, its ideal path and its stepper
/// as it was before the segment's first step.
pub struct MadeSegment {
    start: Point,
    ideal: IdealPath,
    first_state: Box<dyn Replay>,
    columns: &'static [Column],
}

impl MadeSegment {
    /// `stepper` must be the one the segment was run with, in the state it
    /// was in before its first step.
    pub fn new<S: Stepper>(start: Point, ideal: IdealPath, stepper: S) -> MadeSegment {
        MadeSegment {
            start,
            ideal,
            columns: stepper.columns(),
            first_state: Box::new(stepper),
        }
    }
}

/// Makes segment `index` of a trace again ([`Trace::with_segment_maker`]):
/// the owner of a trace of many short segments (a G-code program, from its
/// move records) knows each one's line and stepper without a copy here.
pub type SegmentMaker = Rc<dyn Fn(usize) -> MadeSegment>;

/// The ideal path of segment `index` alone ([`Trace::with_segment_maker`]),
/// for a reader that needs no stepper (the whole path's polyline).
pub type IdealMaker = Rc<dyn Fn(usize) -> IdealPath>;

/// The point segment `index` starts at ([`Trace::with_segment_maker`]), for
/// a reader that needs its place alone (the path's bounds).
pub type StartMaker = Rc<dyn Fn(usize) -> Point>;

/// A stretch of the bounds' walk at least this long that ends where a
/// segment starts takes its end from the segment's start rather than by
/// summing its steps: summing them was two thirds of the bounds of a
/// 100,000-line program at 80 steps/mm (5.5 million steps), and a made
/// segment's start, read from its owner's record, costs about what
/// summing a few dozen steps does.
const START_READ_STEPS: u64 = 32;

/// What a trace asks its owner for about a segment made when read
/// ([`Trace::with_segment_maker`]).
struct SegmentMakers {
    segment: SegmentMaker,
    ideal: IdealMaker,
    start: StartMaker,
}

/// Sentinel of [`Segments::kept_index`]: the segment is made when read.
const MADE: u32 = u32::MAX;

/// The segments of a trace, in step order: where each one's steps start,
/// and the segment itself where it is kept.
#[derive(Default)]
struct Segments {
    /// Each segment's steps, as where they start (ending at the trace's
    /// last step once finished).
    steps: Starts<u64>,
    /// Per segment: its index in `kept`, or [`MADE`].
    kept_index: Vec<u32>,
    kept: Vec<Segment>,
}

impl Segments {
    fn len(&self) -> usize {
        self.steps.len()
    }

    fn is_empty(&self) -> bool {
        self.steps.is_empty()
    }

    fn push_kept(&mut self, segment: Segment) {
        self.steps.push(segment.first_step);
        self.kept_index
            .push(u32::try_from(self.kept.len()).expect("fewer than 2^32 segments"));
        self.kept.push(segment);
    }

    fn reserve(&mut self, more: usize) {
        self.steps.reserve(more);
        self.kept_index.reserve(more);
    }

    fn push_made(&mut self, first_step: u64) {
        self.steps.push(first_step);
        self.kept_index.push(MADE);
    }

    /// Index of the last segment that took a step (0 when none did).
    fn last_stepping(&self) -> usize {
        self.steps.holding(self.steps.end().saturating_sub(1))
    }

    /// Ends the last segment at the trace's `total` steps, and gives back
    /// the memory the vectors grew past their length.
    fn finish(&mut self, total: u64) {
        self.steps.finish(total);
        self.kept_index.shrink_to_fit();
        self.kept.shrink_to_fit();
    }
}

/// A finished trace.
pub struct Trace {
    pub algorithm: String,
    start: Point,
    end: Point,
    steps: Vec<Step>,
    /// Position after k * CHECKPOINT_INTERVAL steps.
    positions: Vec<Point>,
    segments: Segments,
    /// Makes the segments that are made when read, and their ideal paths
    /// and starts alone.
    segment_maker: Option<SegmentMakers>,
    columns: Vec<Column>,
    /// Each stepper type's columns and their indices among `columns`, as
    /// the builder found them ([`TraceBuilder::column_slots`]): a segment
    /// made when read takes its indices from here ([`known_column_slots`]).
    column_slots: Vec<(&'static [Column], Rc<[usize]>)>,
    /// The pictures its steps' decisions can have ([`Decision::FIGURE`]).
    figures: Vec<FigureKind>,
    /// Computed on first use: a pass over every point (deviation and axis
    /// error) and a replay of the decisions (ties), which a caller that only
    /// reads points or appends this trace to another (a chord of an arc)
    /// never pays for.
    metrics: OnceCell<Metrics>,
    /// The metrics' pass made so far, while it is made a stretch of points
    /// at a time ([`Trace::advance_metrics`]) and not finished.
    metrics_pass: RefCell<Option<MetricsPass>>,
    /// A chart's rows made so far a stretch of points at a time
    /// ([`Trace::advance_chart_rows`]), until they are taken.
    chart_pass: RefCell<Option<ChartPass>>,
    /// What the algorithm promises of the deviation, when it promises one.
    deviation_bound: Option<DeviationBound>,
    /// What starts the note of segment i, made when read (a G-code move's
    /// sentence, so a program keeps no text per move).
    note_prefix: Option<NotePrefix>,
}

/// Makes the text that starts a segment's note from the segment's index
/// ([`Trace::with_note_prefix`]).
pub type NotePrefix = Rc<dyn Fn(usize) -> String>;

/// The error for a path found to need at least `steps` steps, more than
/// `max_steps` allows (for steppers that count before running).
pub fn path_too_long(max_steps: u64, steps: u64) -> Error {
    Error::field(
        "maxSteps",
        format!(
            "the path needs more than {max_steps} steps (at least {steps}); {}",
            too_long_advice(steps, "the move")
        ),
    )
    .with_limit(Limit {
        option: "maxSteps".into(),
        value: max_steps,
        at_least: steps,
        most: MAX_STEPS_LIMIT,
    })
}

/// Builds a trace by running steppers one after another from a start point.
pub struct TraceBuilder {
    start: Point,
    position: Point,
    steps: Vec<Step>,
    positions: Vec<Point>,
    segments: Segments,
    columns: Vec<Column>,
    figures: Vec<FigureKind>,
    max_steps: u64,
    /// Steps this trace must take ([`Request::following`]), if any.
    follow: Option<Arc<[Step]>>,
    /// The stepper columns run so far and their indices among the
    /// trace's, so that stepper types taking turns (a G-code program's
    /// lines and arcs) find theirs once.
    known_slots: Vec<(&'static [Column], Rc<[usize]>)>,
}

impl TraceBuilder {
    /// `max_steps` bounds the whole trace; exceeding it is an error naming
    /// the `maxSteps` option.
    pub fn new(start: Point, max_steps: u64) -> TraceBuilder {
        TraceBuilder {
            start,
            position: start,
            steps: Vec::new(),
            positions: vec![start],
            segments: Segments::default(),
            columns: Vec::new(),
            figures: Vec::new(),
            max_steps,
            follow: None,
            known_slots: Vec::new(),
        }
    }

    /// A builder for `req`: its `maxSteps`, and the steps it is to follow,
    /// if any ([`Request::following`]).
    pub fn for_request(start: Point, req: &Request) -> Result<TraceBuilder, Error> {
        let mut builder = TraceBuilder::new(start, req.max_steps()?);
        builder.follow = req.follow().cloned();
        Ok(builder)
    }

    /// Checks `taken`, steps `from..` of the trace, against the steps to
    /// follow: an error at the first one that differs or goes beyond them.
    fn check_follows(&self, from: usize, taken: &[Step]) -> Result<(), Error> {
        let Some(follow) = &self.follow else {
            return Ok(());
        };
        let wanted = follow.get(from..).unwrap_or(&[]);
        let same = taken.iter().zip(wanted).take_while(|(a, b)| a == b).count();
        if same < taken.len() {
            return Err(Error::field(
                "follow",
                format!(
                    "the path parts from the steps it follows at step {}",
                    from + same
                ),
            ));
        }
        Ok(())
    }

    /// Current position (the end of the last segment).
    pub fn position(&self) -> Point {
        self.position
    }

    /// Runs `stepper` to its end from the current position, measuring its
    /// points against `ideal`. Its note is made from its first state when
    /// read ([`Segment::note`]): nobody may read it, and a circle's note
    /// runs Saleem's dry run.
    pub fn run<S: Stepper>(&mut self, stepper: S, ideal: IdealPath) -> Result<(), Error> {
        self.run_segment(stepper, || ideal, false)
    }

    /// [`Self::run`], keeping, when the segment is shorter
    /// than [`CHECKPOINT_INTERVAL`], nothing of it but where it starts: the
    /// finished trace's [`SegmentMaker`] makes it again when read (a longer
    /// one is kept, with its checkpoints, whose steps outweigh it). For a
    /// caller that runs many steppers into one trace (a G-code program's
    /// moves), whose segments few read. `ideal` is called only for a kept
    /// segment: an arc's ideal path costs its angles.
    pub fn run_made_when_read<S: Stepper>(
        &mut self,
        stepper: S,
        ideal: impl FnOnce() -> IdealPath,
    ) -> Result<(), Error> {
        self.run_segment(stepper, ideal, true)
    }

    /// Indices of `columns` among the trace's, adding the new ones.
    fn column_slots(&mut self, columns: &'static [Column]) -> Rc<[usize]> {
        if let Some(slots) = known_column_slots(&self.known_slots, columns) {
            return slots;
        }
        let slots: Rc<[usize]> = columns.iter().map(|c| self.column_slot(c)).collect();
        self.known_slots.push((columns, Rc::clone(&slots)));
        slots
    }

    fn run_segment<S: Stepper>(
        &mut self,
        mut stepper: S,
        ideal: impl FnOnce() -> IdealPath,
        made_when_read: bool,
    ) -> Result<(), Error> {
        let first_step = self.steps.len() as u64;
        let known_steps = stepper.remaining_steps();
        let column_index = self.begin_segment(known_steps, stepper.columns(), S::Why::FIGURE)?;
        // A copy on the stack, boxed if the segment is kept; none for one
        // made when read that ends before its first checkpoint (an arc's
        // chords, a program's moves), which is never kept.
        let made_for_sure = made_when_read && known_steps.is_some_and(|n| n < CHECKPOINT_INTERVAL);
        let first_state = (!made_for_sure).then(|| stepper.clone());
        let start = self.position;
        let mut segment_steps = 0;
        let mut states: Vec<Box<dyn Replay>> = Vec::new();
        // `stepper` is stepped where it was passed: moved into a local of
        // its own, it was copied (a regions stepper is 296 bytes, in wasm a
        // memory.copy, a call into the engine) once per segment.
        // Steps go in chunks that end where a stepper state (every
        // CHECKPOINT_INTERVAL steps of the segment) or a position (every
        // CHECKPOINT_INTERVAL steps of the trace) is due, written straight
        // into the array; the position moves by each chunk's displacement.
        loop {
            if segment_steps > 0 && segment_steps % CHECKPOINT_INTERVAL == 0 {
                states.push(Box::new(stepper.clone()));
            }
            let total = self.steps.len() as u64;
            let mut chunk = (CHECKPOINT_INTERVAL - segment_steps % CHECKPOINT_INTERVAL)
                .min(CHECKPOINT_INTERVAL - total % CHECKPOINT_INTERVAL);
            if let Some(left) = stepper.remaining_steps() {
                // Known lengths were reserved: the chunk stays within them.
                chunk = chunk.min(left);
            }
            if chunk == 0 {
                break;
            }
            let start = self.steps.len();
            let filled = fill_onto(&mut stepper, &mut self.steps, chunk as usize);
            self.end_chunk(start, &filled.displacement)?;
            segment_steps += filled.steps as u64;
            if (filled.steps as u64) < chunk {
                break;
            }
        }
        self.check_length(self.steps.len() as u64)?;
        if made_when_read && states.is_empty() {
            self.segments.push_made(first_step);
        } else {
            self.segments.push_kept(Segment {
                first_step,
                steps: segment_steps,
                start,
                ideal: ideal(),
                setup_note: None,
                column_index,
                first_state: Box::new(
                    first_state.expect("a segment that may be kept keeps its first state"),
                ),
                states,
            });
        }
        Ok(())
    }

    /// What starts every segment: room for its steps when their number is
    /// known (`known_steps`, refused past maxSteps), its decision columns
    /// (their indices among the trace's, new ones added) and its figure.
    fn begin_segment(
        &mut self,
        known_steps: Option<u64>,
        columns: &'static [Column],
        figure: Option<FigureKind>,
    ) -> Result<Rc<[usize]>, Error> {
        if let Some(n) = known_steps {
            self.check_length(self.steps.len() as u64 + n)?;
            let capacity = self.steps.capacity();
            self.steps.reserve(n as usize);
            // Advised once per new allocation, not once per segment: a
            // program of a million short moves would make a million calls.
            if self.steps.capacity() != capacity {
                crate::huge_pages::advise(self.steps.spare_capacity_mut());
            }
        }
        let column_index = self.column_slots(columns);
        self.add_figure(figure);
        Ok(column_index)
    }

    /// After the steps from `start` on were written: checks them against
    /// the steps followed, moves the position by `displacement`, and keeps
    /// it where a checkpoint is due.
    fn end_chunk(&mut self, start: usize, displacement: &[i64; MAX_AXES]) -> Result<(), Error> {
        self.check_follows(start, &self.steps[start..])?;
        self.position.displace(displacement);
        let total = self.steps.len() as u64;
        if self.steps.len() > start && total % CHECKPOINT_INTERVAL == 0 {
            self.check_length(total)?;
            self.positions.push(self.position);
        }
        Ok(())
    }

    /// [`Self::run_made_when_read`] for a segment whose one step (or none)
    /// is known without running its stepper: a straight move of at most a
    /// unit on every axis by a rule that takes such a line in one step
    /// moving every axis that differs ([`LineStepper::takes_unit_lines_at_once`]).
    /// `columns` and `figure` are that rule's, registered as its stepper's
    /// would be; the segment is made again from its ends when read. Most
    /// moves of a program at a coarse resolution are such lines (98% of
    /// the G-code bench's straight moves at 1 step/mm), and making their
    /// steppers took about a tenth of its run.
    ///
    /// [`LineStepper::takes_unit_lines_at_once`]: crate::line::line_stepper::LineStepper::takes_unit_lines_at_once
    pub fn run_unit_made_when_read(
        &mut self,
        step: Option<Step>,
        columns: &'static [Column],
        figure: Option<FigureKind>,
    ) -> Result<(), Error> {
        let first_step = self.steps.len() as u64;
        self.begin_segment(Some(step.is_some() as u64), columns, figure)?;
        if let Some(step) = step {
            let start = self.steps.len();
            self.steps.push(step);
            self.end_chunk(start, &displacement(&self.steps[start..]))?;
        }
        self.check_length(self.steps.len() as u64)?;
        self.segments.push_made(first_step);
        Ok(())
    }

    fn check_length(&self, steps: u64) -> Result<(), Error> {
        if steps > self.max_steps {
            return Err(self.too_long(steps));
        }
        Ok(())
    }

    /// The most steps this trace may have (the `maxSteps` option).
    pub fn max_steps(&self) -> u64 {
        self.max_steps
    }

    /// Steps taken so far.
    pub fn steps(&self) -> u64 {
        self.steps.len() as u64
    }

    /// Makes room for `more` segments, for a caller that knows about how
    /// many it will run (a G-code program, a segment per line), so that
    /// their table is not copied as it grows.
    pub fn reserve_segments(&mut self, more: usize) {
        self.segments.reserve(more);
    }

    /// Steps the trace holds room for.
    pub fn step_capacity(&self) -> u64 {
        self.steps.capacity() as u64
    }

    /// Makes room for exactly `more` steps, after checking them against
    /// `maxSteps`: for a caller that knows the length of what it will
    /// append, so the steps are not copied into ever larger arrays (which
    /// would hold up to three times their size while the last copy is made).
    pub fn reserve(&mut self, more: u64) -> Result<(), Error> {
        self.check_length(self.steps() + more)?;
        self.steps.reserve_exact(more as usize);
        crate::huge_pages::advise(self.steps.spare_capacity_mut());
        Ok(())
    }

    /// The error for a path found to need at least `steps` steps, more than
    /// [`Self::max_steps`] (for steppers that count before running).
    pub fn too_long(&self, steps: u64) -> Error {
        path_too_long(self.max_steps, steps)
    }

    /// Appends a finished trace that starts where this one ends (a chord of
    /// an arc run by a line algorithm, for example): its steps, its segments
    /// with their replay states. Its columns join this trace's
    /// by equality, as in [`Self::run`]. `adapt` may change each segment's
    /// ideal path and note: a chord is measured against the arc it stands for.
    pub fn append(
        &mut self,
        mut part: Trace,
        mut adapt: impl FnMut(&mut Segment),
    ) -> Result<(), Error> {
        assert_eq!(
            part.start, self.position,
            "an appended trace starts where this one ends"
        );
        let offset = self.steps.len() as u64;
        self.check_length(offset + part.steps())?;
        let slots: Vec<usize> = part.columns.iter().map(|c| self.column_slot(c)).collect();
        for &figure in &part.figures {
            self.add_figure(Some(figure));
        }
        // A note the part would make when read with its prefix (an arc's
        // chords) is made now: this trace has no prefix of the part's.
        let mut prefixed_notes = part.note_prefix.is_some().then(|| {
            (0..part.segments.len())
                .map(|index| part.segment_note(index).into_owned())
                .collect::<Vec<_>>()
                .into_iter()
        });
        // Its segments made when read (an arc's chords) are made now and
        // kept: this trace has no maker of the part's.
        let mut made: Vec<Option<Segment>> = (0..part.segments.len())
            .map(|index| match part.segment(index) {
                SegmentRef::Made(segment) => Some(segment),
                SegmentRef::Kept(_) => None,
            })
            .collect();
        let part_segments = std::mem::take(&mut part.segments);
        let mut kept: Vec<Option<Segment>> = part_segments.kept.into_iter().map(Some).collect();
        for (index, &slot) in part_segments.kept_index.iter().enumerate() {
            let taken = if slot == MADE {
                made[index].take()
            } else {
                kept[slot as usize].take()
            };
            let mut segment = taken.expect("each segment is kept or made once");
            if let Some(notes) = &mut prefixed_notes {
                segment.setup_note = notes.next();
            }
            segment.first_step += offset;
            segment.column_index = segment.column_index.iter().map(|&i| slots[i]).collect();
            adapt(&mut segment);
            self.segments.push_kept(segment);
        }
        self.check_follows(self.steps.len(), &part.steps)?;
        self.steps.extend_from_slice(&part.steps);
        // A position where one is due: the part's own point there, found
        // from the part's checkpoints (a chord's steps are not walked).
        let mut due = (offset / CHECKPOINT_INTERVAL + 1) * CHECKPOINT_INTERVAL;
        while due <= self.steps() {
            self.positions.push(part.point(due - offset));
            due += CHECKPOINT_INTERVAL;
        }
        self.position = part.end;
        Ok(())
    }

    /// Index of a column among the trace's columns, adding it if new. Two
    /// segments share a column when they declare the same one.
    fn column_slot(&mut self, column: &Column) -> usize {
        match self.columns.iter().position(|c| c == column) {
            Some(i) => i,
            None => {
                self.columns.push(*column);
                self.columns.len() - 1
            }
        }
    }

    /// Lists `figure` among the trace's pictures, once.
    fn add_figure(&mut self, figure: Option<FigureKind>) {
        if let Some(figure) = figure.filter(|f| !self.figures.contains(f)) {
            self.figures.push(figure);
        }
    }

    /// The finished trace. Its metrics are computed on first use
    /// ([`Trace::metrics`]).
    pub fn finish(mut self, algorithm: &str) -> Trace {
        // Kept as long as the trace: without the slack of their growth (a
        // G-code program's steps grow move by move).
        self.steps.shrink_to_fit();
        self.positions.shrink_to_fit();
        self.segments.finish(self.steps.len() as u64);
        Trace {
            algorithm: algorithm.to_string(),
            start: self.start,
            end: self.position,
            steps: self.steps,
            positions: self.positions,
            segments: self.segments,
            segment_maker: None,
            columns: self.columns,
            column_slots: self.known_slots,
            figures: self.figures,
            metrics: OnceCell::new(),
            metrics_pass: RefCell::new(None),
            chart_pass: RefCell::new(None),
            deviation_bound: None,
            note_prefix: None,
        }
    }
}

/// One step replayed ([`Trace::replay_step`]).
pub struct ReplayedStep {
    /// One value per trace column (NaN or [`NO_VALUE`] where it does not apply).
    pub values: Vec<f64>,
    pub explanation: String,
    pub figure: Option<DecisionFigure>,
}

/// Consecutive points of one segment: the first, and the steps to each
/// one after it.
struct Piece<'a> {
    segment: SegmentRef<'a>,
    /// Point index of the first point.
    first: u64,
    start: Point,
    steps: &'a [Step],
}

impl Piece<'_> {
    /// The first point's step index within the segment.
    fn local(&self) -> u64 {
        (self.first - self.segment.first_step).min(self.segment.steps)
    }

    /// Walks the points along a line segment incrementally
    /// ([`crate::ideal::LineMeter::walk`]): false, calling nothing, where
    /// the segment is no line or the walk does not apply.
    fn walk_line(&self, f: impl FnMut(f64, &[i64; MAX_AXES])) -> bool {
        let IdealPath::Line { from, to } = &self.segment.ideal else {
            return false;
        };
        LineMeter::new(from, to).walk(&self.start, self.local(), self.segment.steps, self.steps, f)
    }

    /// Walks the points along an arc segment ([`ArcMeter::walk`]), calling
    /// `f(meter, offsets of the point from the center)` for each: false,
    /// calling nothing, where the segment is no arc.
    fn walk_arc(&self, mut f: impl FnMut(&ArcMeter, [i64; 3])) -> bool {
        let IdealPath::Arc(arc) = &self.segment.ideal else {
            return false;
        };
        let meter = arc.meter();
        meter.walk(
            &self.start,
            self.steps,
            #[inline(always)]
            |offsets| f(&meter, offsets),
        );
        true
    }

    /// Walks the points along a helix segment ([`HelixMeter::walk`]),
    /// calling `f(meter, the point placed around the helix)` for each:
    /// false, calling nothing, where the segment is no helix.
    fn walk_helix(&self, mut f: impl FnMut(&HelixMeter, &HelixPoint)) -> bool {
        let IdealPath::Helix(helix) = &self.segment.ideal else {
            return false;
        };
        let meter = helix.meter();
        meter.walk(
            &self.start,
            self.steps,
            #[inline(always)]
            |point| f(&meter, point),
        );
        true
    }

    /// Calls `f(k, point k, meter, step of the segment, its steps)` for
    /// each point, each measured on its own: the reference the line, arc
    /// and helix walks are held to.
    fn for_each_point(&self, mut f: impl FnMut(u64, &Point, &Meter, u64, u64)) {
        let meter = self.segment.ideal.meter();
        let n = self.segment.steps;
        let mut p = self.start;
        let local = self.local();
        f(self.first, &p, &meter, local, n);
        for (i, &s) in self.steps.iter().enumerate() {
            p.apply(s);
            let i = i as u64 + 1;
            f(self.first + i, &p, &meter, (local + i).min(n), n);
        }
    }
}

/// Decision values over a range of steps, one array per trace column.
pub struct DecisionTable {
    pub columns: Vec<Vec<f64>>,
}

impl Trace {
    /// This trace with the deviation bound its algorithm guarantees.
    pub fn with_deviation_bound(mut self, bound: Option<DeviationBound>) -> Trace {
        self.deviation_bound = bound;
        self
    }

    pub fn deviation_bound(&self) -> Option<&DeviationBound> {
        self.deviation_bound.as_ref()
    }

    pub fn dims(&self) -> usize {
        self.start.dims()
    }

    pub fn steps(&self) -> u64 {
        self.steps.len() as u64
    }

    pub fn start(&self) -> Point {
        self.start
    }

    pub fn end(&self) -> Point {
        self.end
    }

    pub fn columns(&self) -> &[Column] {
        &self.columns
    }

    /// How many segments it has.
    pub fn segment_count(&self) -> usize {
        self.segments.len()
    }

    /// Segment `index`: kept, or made again ([`Self::with_segment_maker`]).
    pub fn segment(&self, index: usize) -> SegmentRef<'_> {
        let slot = self.segments.kept_index[index];
        if slot != MADE {
            return SegmentRef::Kept(&self.segments.kept[slot as usize]);
        }
        let made = (self.makers().segment)(index);
        // The indices the builder found for its stepper type, which ran
        // there: compared column by column and collected anew for each
        // segment (every move of a program is made twice for its metrics:
        // its ties, its points), the metrics of the G-code bench's
        // 100,000-line program took 76 ms in Node at 1 step/mm (37 so) and
        // 165 ms at 80 steps/mm (115).
        let column_index = known_column_slots(&self.column_slots, made.columns)
            .expect("a segment made when read ran in its trace's builder");
        let (first_step, end) = self.segments.steps.span(index);
        SegmentRef::Made(Segment {
            first_step,
            steps: end - first_step,
            start: made.start,
            ideal: made.ideal,
            setup_note: None,
            column_index,
            first_state: made.first_state,
            states: Vec::new(),
        })
    }

    /// Every segment, in step order (those made when read are made one at
    /// a time).
    pub fn segments(&self) -> impl Iterator<Item = SegmentRef<'_>> {
        (0..self.segments.len()).map(|i| self.segment(i))
    }

    /// This trace with `maker` making its segments run by
    /// [`TraceBuilder::run_made_when_read`] when they are read, and `ideal`
    /// and `start` their ideal paths and their starts alone, as `maker`
    /// makes them.
    pub fn with_segment_maker(
        mut self,
        maker: SegmentMaker,
        ideal: IdealMaker,
        start: StartMaker,
    ) -> Trace {
        self.segment_maker = Some(SegmentMakers {
            segment: maker,
            ideal,
            start,
        });
        self
    }

    /// What makes the segments made when read: only such a segment asks.
    fn makers(&self) -> &SegmentMakers {
        self.segment_maker
            .as_ref()
            .expect("a trace with segments made when read has their maker")
    }

    /// The point segment `index` starts at, without making it.
    fn start_of(&self, index: usize) -> Point {
        let slot = self.segments.kept_index[index];
        if slot != MADE {
            return self.segments.kept[slot as usize].start;
        }
        (self.makers().start)(index)
    }

    /// The ideal path of segment `index`, without making its stepper.
    fn ideal_of(&self, index: usize) -> IdealPath {
        let slot = self.segments.kept_index[index];
        if slot != MADE {
            return self.segments.kept[slot as usize].ideal.clone();
        }
        (self.makers().ideal)(index)
    }

    /// The pictures its steps' decisions can have ([`Decision::FIGURE`]).
    pub fn figures(&self) -> &[FigureKind] {
        &self.figures
    }

    /// Pulses per axis: one pass over the steps, or the metrics' count when
    /// they were read already. For a caller that needs the counts alone (a
    /// program's record), without the deviation pass [`Self::metrics`] makes.
    pub fn pulses_by_axis(&self) -> Vec<u64> {
        if let Some(metrics) = self.metrics.get() {
            return metrics.pulses_by_axis.clone();
        }
        let mut acc = MetricsAccumulator::new(self.dims());
        acc.add_steps(&self.steps);
        acc.pulses_by_axis()
    }

    /// Whole-path statistics, computed the first time they are asked for:
    /// one pass over the points, and the ties counted by replaying each
    /// segment from its first state (steps are recorded without their
    /// decisions; [`Stepper::ties_ahead`]). A pass begun by [`Self::advance_metrics`] is finished.
    pub fn metrics(&self) -> &Metrics {
        self.metrics.get_or_init(|| {
            let mut pass = self
                .metrics_pass
                .take()
                .unwrap_or_else(|| MetricsPass::new(self.dims()));
            pass.advance(self, u64::MAX);
            pass.finish()
        })
    }

    /// Makes the metrics' pass over at most `max_points` more points (a
    /// worker makes it a slice at a time, reporting and stopping between
    /// slices: a helix's 1,500,000 points take a second or two); once it
    /// has reached the last point, [`Self::metrics`] holds them. The
    /// points go into one accumulator in point order, so the metrics are
    /// those of one pass, to the bit, however the pass was sliced.
    pub fn advance_metrics(&self, max_points: u64) -> PointsProgress {
        let points = self.steps() + 1;
        if self.metrics.get().is_some() {
            return PointsProgress::of(points, points);
        }
        let mut pass = self
            .metrics_pass
            .take()
            .unwrap_or_else(|| MetricsPass::new(self.dims()));
        pass.advance(self, max_points);
        let progress = PointsProgress::of(pass.next_point, points);
        if progress.done {
            let _ = self.metrics.set(pass.finish());
        } else {
            *self.metrics_pass.borrow_mut() = Some(pass);
        }
        progress
    }

    /// Ties among step indices `from..to`, each segment replayed from its
    /// checkpoint before `from`.
    fn count_ties(&self, from: u64, to: u64) -> u64 {
        let mut ties = 0;
        self.for_each_replay(from, to, |_, stepper, steps| {
            ties += stepper.count_ties(steps.end - steps.start);
        });
        ties
    }

    /// Adds the deviation and axis error of points `from..to` to `acc`, in
    /// point order.
    fn measure_points(&self, from: u64, to: u64, acc: &mut MetricsAccumulator) {
        self.for_each_piece(from, to, |piece| {
            let mut largest = [0i64; MAX_AXES];
            let walked = piece.walk_line(|deviation, numerator| {
                acc.add_deviation(deviation);
                for (l, v) in largest.iter_mut().zip(numerator) {
                    *l = (*l).max(v.abs());
                }
            });
            if walked {
                // max |numerator / n| is max |numerator| / n: the division
                // and the rounding keep the order (so too across pieces of
                // one segment, when a pass is sliced).
                let n = piece.segment.steps as f64;
                acc.add_axis_error(&largest.map(|l| l as f64 / n));
            } else if !piece.walk_arc(|meter, offsets| {
                let (deviation, error) = meter.measure_at(offsets);
                acc.add_point(deviation, &error);
            }) && !piece.walk_helix(|meter, point| {
                acc.add_point(meter.deviation_at(point), &meter.axis_error_at(point));
            }) {
                piece.for_each_point(|_, p, meter, local, n| {
                    acc.add_point(meter.deviation(p), &meter.axis_error(p, local, n));
                });
            }
        });
    }

    /// The packed steps with step indices in `from..to`.
    pub fn step_range(&self, from: u64, to: u64) -> &[Step] {
        &self.steps[from as usize..to as usize]
    }

    /// Point index k: the position after k steps.
    pub fn point(&self, k: u64) -> Point {
        let mut p = self.positions[(k / CHECKPOINT_INTERVAL) as usize];
        p.displace(&displacement(
            &self.steps[(k - k % CHECKPOINT_INTERVAL) as usize..k as usize],
        ));
        p
    }

    /// Index of the segment that point index k belongs to: the segment whose
    /// step k starts from it; the last point belongs to the last segment
    /// that took a step.
    pub fn segment_of_point(&self, k: u64) -> usize {
        if k < self.steps() {
            self.segment_of_step(k)
        } else {
            self.segments.last_stepping()
        }
    }

    /// Calls `f(k, point k)` for point indices `from..to`, decoding the
    /// steps as it goes: no array of points is built.
    pub fn walk_points(&self, from: u64, to: u64, mut f: impl FnMut(u64, &Point)) {
        if from >= to {
            return;
        }
        let mut p = self.point(from);
        f(from, &p);
        for k in from + 1..to {
            p.apply(self.steps[k as usize - 1]);
            f(k, &p);
        }
    }

    /// Points with point indices `from..to`, flat with stride `dims`.
    pub fn points_flat(&self, from: u64, to: u64) -> Vec<i64> {
        self.points_vec(from, to)
    }

    /// The same as i32, the type every trace coordinate fits (see
    /// [`Coordinate`]) and the one that crosses to JavaScript.
    pub fn points_i32(&self, from: u64, to: u64) -> Vec<i32> {
        self.points_vec(from, to)
    }

    /// Points `from..to` in a new vector, written once, straight into its
    /// memory (not zeroed first), which is advised for huge pages before
    /// ([`crate::huge_pages`]): an allocation this large comes untouched
    /// from the kernel, or reused from the allocator's own.
    fn points_vec<C: Coordinate>(&self, from: u64, to: u64) -> Vec<C> {
        let values = (to - from) as usize * self.dims();
        let mut out = Vec::with_capacity(values);
        let memory = &mut out.spare_capacity_mut()[..values];
        crate::huge_pages::advise(memory);
        self.write_points(from, memory);
        // SAFETY: write_points has written all `values` values.
        unsafe { out.set_len(values) };
        out
    }

    /// Writes the points with point indices `from..` into `out`, stride
    /// `dims`, as many as it holds, every value of it: the first from its
    /// checkpoint, the others by the decode specialised for this trace's
    /// number of axes, straight into `out`, past the cache when they are
    /// too many to stay in it ([`crate::points::decode_to_new`]).
    fn write_points<C: Coordinate>(&self, from: u64, out: &mut [MaybeUninit<C>]) {
        let dims = self.dims();
        assert_eq!(out.len() % dims, 0, "whole points");
        let count = (out.len() / dims) as u64;
        if count == 0 {
            return;
        }
        let first = self.point(from);
        let (head, rest) = out.split_at_mut(dims);
        for (c, &v) in head.iter_mut().zip(first.coords()) {
            c.write(C::from_i64(v));
        }
        crate::points::decode_to_new(&first, self.step_range(from, from + count - 1), rest);
    }

    /// Points `from..to` through `buffer`, a chunk at a time: each chunk,
    /// as many whole points as `buffer` holds, is decoded into it and
    /// handed to `f` with the point index of its first point. Each chunk
    /// goes on from the last point of the one before, so only the first
    /// point is found from a checkpoint. `buffer` need not be initialised
    /// (every value handed to `f` is written first): its megabyte is not
    /// zeroed on every read of the points.
    pub fn points_by_chunk<C: Coordinate>(
        &self,
        from: u64,
        to: u64,
        buffer: &mut [MaybeUninit<C>],
        mut f: impl FnMut(u64, &[C]),
    ) {
        let dims = self.dims();
        let rows = (buffer.len() / dims) as u64;
        assert!(rows > 0, "a buffer of at least one point");
        if from >= to {
            return;
        }
        let mut p = self.point(from);
        for (c, &v) in buffer.iter_mut().zip(p.coords()) {
            c.write(C::from_i64(v));
        }
        // The first chunk holds the first point and the points of the
        // steps after it; every later chunk the points of its steps.
        let mut k = from;
        let mut head = 1;
        while k < to {
            let end = to.min(k + rows);
            let steps = self.step_range(k + head - 1, end - 1);
            let chunk = &mut buffer[..(end - k) as usize * dims];
            p = crate::points::decode(&p, steps, &mut chunk[head as usize * dims..]);
            // SAFETY: the chunk's first `head` points were written above,
            // and `decode` writes every value of the rest; MaybeUninit<C>
            // has C's layout.
            let written = unsafe { &*(chunk as *const [MaybeUninit<C>] as *const [C]) };
            f(k, written);
            k = end;
            head = 0;
        }
    }

    /// The box every point lies in ([`PointBounds`]): one pass over the
    /// steps, made when asked (the page frames a path with it), not when
    /// the trace is made.
    ///
    /// The steps are taken in stretches that end at each segment's start
    /// and at each stored position. A stretch on which no axis turns back
    /// (a line, a G-code move, an arc's octant) has its extremes at its
    /// ends, so only an OR of its codes is taken. Its end is a stored
    /// position, the start of the segment after it, or, for a short
    /// stretch ([`START_READ_STEPS`]), its start displaced by its steps.
    /// The others are walked.
    pub fn bounds(&self) -> PointBounds {
        let (mut min, mut max) = (self.start.coords().to_vec(), self.start.coords().to_vec());
        let mut widen = |low: &Point, high: &Point| {
            for axis in 0..min.len() {
                min[axis] = min[axis].min(low.get(axis));
                max[axis] = max[axis].max(high.get(axis));
            }
        };
        let steps = self.steps();
        let mut position = self.start;
        let (mut from, mut segment) = (0, 0);
        while from < steps {
            while segment < self.segments.len() && self.segments.steps.span(segment).0 <= from {
                segment += 1;
            }
            let next_segment = if segment < self.segments.len() {
                self.segments.steps.span(segment).0
            } else {
                steps
            };
            let next_position = (from / CHECKPOINT_INTERVAL + 1) * CHECKPOINT_INTERVAL;
            let to = next_segment.min(next_position).min(steps);
            let stretch = self.step_range(from, to);
            if crate::points::one_way(stretch) {
                position = if to % CHECKPOINT_INTERVAL == 0 {
                    self.positions[(to / CHECKPOINT_INTERVAL) as usize]
                } else if to == steps {
                    self.end
                } else if to == next_segment && to - from >= START_READ_STEPS {
                    self.start_of(segment)
                } else {
                    let mut end = position;
                    end.displace(&displacement(stretch));
                    end
                };
                widen(&position, &position);
            } else {
                let (low, high, end) = crate::points::bounds(&position, stretch);
                widen(&low, &high);
                position = end;
            }
            from = to;
        }
        PointBounds { min, max }
    }

    /// Perpendicular deviation of points `from..to` from the ideal path.
    pub fn deviation_range(&self, from: u64, to: u64) -> Vec<f64> {
        let mut out = Vec::with_capacity((to - from) as usize);
        self.for_each_deviation(from, to, |deviation| out.push(deviation));
        out
    }

    /// [`Trace::deviation_range`] handed to `f` one point at a time, in
    /// point order: for a caller that copies them elsewhere a buffer at a
    /// time (wasm's `deviation`, into a JS array), not all at once.
    pub fn for_each_deviation(&self, from: u64, to: u64, mut f: impl FnMut(f64)) {
        if self.segments.is_empty() {
            // A program that made no move (only dwells, or nothing) has no
            // path to deviate from: its one point is where it is meant to
            // be, 0 (a point's detail and the chart, which show the ideal
            // path beside it, say there is none: null and NaN).
            (from..to).for_each(|_| f(0.0));
            return;
        }
        self.for_each_piece(from, to, |piece| {
            if !piece.walk_line(|deviation, _| f(deviation))
                && !piece.walk_arc(|meter, offsets| f(meter.deviation_at(offsets)))
                && !piece.walk_helix(|meter, point| f(meter.deviation_at(point)))
            {
                piece.for_each_point(|_, p, meter, _, _| f(meter.deviation(p)));
            }
        });
    }

    /// Per-axis error (Wang eq. 11) of points `from..to`, flat with stride `dims`.
    pub fn axis_error_range(&self, from: u64, to: u64) -> Vec<f64> {
        let mut out = Vec::with_capacity((to - from) as usize * self.dims());
        self.for_each_axis_error(from, to, |error| out.push(error));
        out
    }

    /// [`Trace::axis_error_range`] handed to `f` one value at a time, in
    /// the order of that array (point by point, axis by axis).
    pub fn for_each_axis_error(&self, from: u64, to: u64, mut f: impl FnMut(f64)) {
        let dims = self.dims();
        if self.segments.is_empty() {
            // As for_each_deviation: no path, so no error on any axis.
            (0..(to.saturating_sub(from)) * dims as u64).for_each(|_| f(0.0));
            return;
        }
        self.for_each_piece(from, to, |piece| {
            let n = piece.segment.steps as f64;
            let walked = piece.walk_line(|_, numerator| {
                for &v in &numerator[..dims] {
                    f(v as f64 / n);
                }
            }) || piece.walk_arc(|meter, offsets| {
                for &error in &meter.axis_error_at(offsets)[..dims] {
                    f(error);
                }
            }) || piece.walk_helix(|meter, point| {
                for &error in &meter.axis_error_at(point)[..dims] {
                    f(error);
                }
            });
            if !walked {
                piece.for_each_point(|_, p, meter, local, steps| {
                    for &error in &meter.axis_error(p, local, steps)[..dims] {
                        f(error);
                    }
                });
            }
        });
    }

    /// The rows a chart of points `from..to` draws, at most `max_rows` of
    /// them, in one pass: every point, or, when there are more, buckets of
    /// `ceil((to - from) / max_rows)` consecutive points. Column-major, R
    /// values per column, 3 + 2 dims columns:
    /// - the point index of the row (the bucket's first point);
    /// - per axis, that point's coordinate;
    /// - per axis, where the ideal path is at the same progress: the point
    ///   less its Wang eq. (11) error ([`Trace::axis_error_range`]);
    /// - the largest and the smallest deviation in the bucket
    ///   ([`Trace::deviation_range`]), so no peak is lost.
    ///
    /// A trace without segments has no ideal path: its ideal positions
    /// and deviations are NaN.
    pub fn chart_rows(&self, from: u64, to: u64, max_rows: u64) -> Vec<f64> {
        let mut pass = ChartPass::new(self, from, to, max_rows);
        self.fill_chart_rows(&mut pass, u64::MAX);
        pass.out
    }

    /// Makes the rows of [`Self::chart_rows`]`(from, to, max_rows)` over at
    /// most `max_points` more points (whole buckets of them, at least
    /// one), kept until [`Self::take_chart_rows`] takes them: a worker makes
    /// them a slice at a time, reporting and stopping between slices. A
    /// bucket is made whole in one slice, from its own points alone, so the
    /// rows are those of one pass, to the bit. Rows of another range or
    /// row count begun before are dropped.
    pub fn advance_chart_rows(
        &self,
        from: u64,
        to: u64,
        max_rows: u64,
        max_points: u64,
    ) -> PointsProgress {
        let mut pass = match self.chart_pass.take() {
            Some(pass) if (pass.from, pass.to, pass.max_rows) == (from, to, max_rows) => pass,
            _ => ChartPass::new(self, from, to, max_rows),
        };
        self.fill_chart_rows(&mut pass, max_points);
        let progress = PointsProgress::of(pass.next_point - from, to - from);
        *self.chart_pass.borrow_mut() = Some(pass);
        progress
    }

    /// The rows of [`Self::chart_rows`]`(from, to, max_rows)`: those
    /// [`Self::advance_chart_rows`] made, the rest of them made now.
    pub fn take_chart_rows(&self, from: u64, to: u64, max_rows: u64) -> Vec<f64> {
        match self.chart_pass.take() {
            Some(mut pass) if (pass.from, pass.to, pass.max_rows) == (from, to, max_rows) => {
                self.fill_chart_rows(&mut pass, u64::MAX);
                pass.out
            }
            _ => self.chart_rows(from, to, max_rows),
        }
    }

    /// Makes the rows of `pass` over at most `max_points` more points,
    /// rounded up to whole buckets.
    fn fill_chart_rows(&self, pass: &mut ChartPass, max_points: u64) {
        let dims = self.dims();
        let (origin, bucket, rows) = (pass.from, pass.bucket, pass.rows);
        let from = pass.next_point;
        let to = pass
            .to
            .min(from.saturating_add(max_points.div_ceil(bucket).max(1).saturating_mul(bucket)));
        pass.next_point = to;
        let (head, deviation) = pass.out.split_at_mut(rows * (1 + 2 * dims));
        let (largest, smallest) = deviation.split_at_mut(rows);
        if self.segments.is_empty() {
            // Nothing to measure against (a program with no move): the
            // points alone, the rest NaN.
            self.walk_points(from, to, |k, p| {
                if (k - origin) % bucket == 0 {
                    let r = ((k - origin) / bucket) as usize;
                    head[r] = k as f64;
                    for a in 0..dims {
                        head[(1 + a) * rows + r] = p.get(a) as f64;
                    }
                }
            });
        }
        // One row's share of point k: its coordinates and ideal position
        // when it starts a bucket (the error is computed only then), its
        // deviation always.
        // The points come in order, one after another: the row and the
        // points left in its bucket are counted, not divided out of k, and
        // the bucket's extremes are kept in locals and stored when it ends,
        // where a store and a load of largest[r] and smallest[r] a point
        // chained every point to the one before. What every point does is
        // inlined into each walk ([`ChartBucket::record`], the walks'
        // closures marked so), what a bucket's first point does is a call
        // ([`ChartColumns::start_row`]): with both in one closure called
        // from the four walks, the arc's walk was a call a point, and in
        // Node the rows of the circle of r = 300,000 took 58 to 63 ms (its
        // metrics, more work a point, 23), 13.6 to 14.8 so; the 3D line's
        // 27 to 28 -> 22 ms (builds run in turn).
        let mut columns = ChartColumns {
            head,
            largest,
            smallest,
            rows,
            dims,
            origin,
            bucket,
        };
        let mut state = ChartBucket {
            row: None,
            left: 0,
            high: f64::NEG_INFINITY,
            low: f64::INFINITY,
        };
        let (columns, state) = (&mut columns, &mut state);
        self.for_each_piece(from, to, |piece| {
            // A line is walked incrementally, as the metrics are; a bucket's
            // first point found from the one before, since the walk hands
            // out numerators alone (the steps between summed at once, where
            // each point decoded alongside took a step's apply a point).
            let n = piece.segment.steps as f64;
            let found = Cell::new((piece.start, 0));
            // Point i of the piece, found from the last point asked for.
            let point = |i: usize| {
                let (mut p, at) = found.get();
                p.displace(&displacement(&piece.steps[at..i]));
                found.set((p, i));
                p
            };
            let mut i = 0;
            let walked = piece.walk_line(
                #[inline(always)]
                |deviation, numerator| {
                    state.record(columns, piece.first + i as u64, deviation, || {
                        (point(i), numerator.map(|v| v as f64 / n))
                    });
                    i += 1;
                },
            );
            // An arc is walked too, a bucket's first point put together from
            // its offsets from the center.
            let walked = walked
                || piece.walk_arc(
                    #[inline(always)]
                    |meter, offsets| {
                        let deviation = meter.deviation_at(offsets);
                        state.record(columns, piece.first + i as u64, deviation, move || {
                            (meter.point_at(offsets), meter.axis_error_at(offsets))
                        });
                        i += 1;
                    },
                );
            // A helix too, its bucket's first points found as a line's are.
            let walked = walked
                || piece.walk_helix(
                    #[inline(always)]
                    |meter, placed| {
                        let deviation = meter.deviation_at(placed);
                        state.record(columns, piece.first + i as u64, deviation, || {
                            (point(i), meter.axis_error_at(placed))
                        });
                        i += 1;
                    },
                );
            if !walked {
                piece.for_each_point(|k, p, meter, local, steps| {
                    state.record(columns, k, meter.deviation(p), || {
                        (*p, meter.axis_error(p, local, steps))
                    });
                });
            }
        });
        if let Some(r) = state.row {
            // The last bucket, which no later point ends.
            (columns.largest[r], columns.smallest[r]) = (state.high, state.low);
        }
    }

    /// Calls `f` with each stretch of point indices `from..to` that belongs
    /// to one segment, in order: its first point found once, each later
    /// stretch's from the one before. Point k belongs to the segment whose
    /// step k starts from it; the last point belongs to the last segment
    /// that took a step.
    fn for_each_piece(&self, from: u64, to: u64, mut f: impl FnMut(Piece<'_>)) {
        if from >= to || self.segments.is_empty() {
            return;
        }
        let mut start = self.point(from);
        let mut k = from;
        while k < to {
            let segment = self.segment(self.segment_of_point(k));
            let seg_end = segment.first_step + segment.steps;
            // The last point belongs to the last segment that took a step.
            let end = to.min(if seg_end == self.steps() {
                seg_end + 1
            } else {
                seg_end
            });
            f(Piece {
                segment,
                first: k,
                start,
                steps: &self.steps[k as usize..(end - 1) as usize],
            });
            if end < to {
                start.displace(&displacement(&self.steps[k as usize..end as usize]));
            }
            k = end;
        }
    }

    /// Index of the segment containing step index k.
    pub fn segment_of_step(&self, k: u64) -> usize {
        self.segments.steps.holding(k)
    }

    /// Replays `segment` so that its next step is step index `k`.
    fn replay_to(segment: &Segment, k: u64) -> Box<dyn Replay> {
        let local = k - segment.first_step;
        let mut stepper = segment.state_at((local / CHECKPOINT_INTERVAL) as usize);
        let mut scratch = vec![0.0; MAX_COLUMNS];
        for _ in 0..local % CHECKPOINT_INTERVAL {
            stepper.replay_step(&mut scratch);
        }
        stepper
    }

    /// Decision columns for step indices `from..to`, recomputed by replay;
    /// where a column does not apply to a step (or to its segment), NaN in a
    /// number column and [`NO_VALUE`] in a category or flag column.
    pub fn decisions(&self, from: u64, to: u64) -> DecisionTable {
        let len = (to - from) as usize;
        let mut columns: Vec<Vec<f64>> = self
            .columns
            .iter()
            .map(|c| vec![c.kind.no_value(); len])
            .collect();
        self.replay_decisions(from, to, |column, i, value| columns[column][i] = value);
        DecisionTable { columns }
    }

    /// The same values in one column-major array: `(to - from)` values of
    /// the first trace column, then of the second, ... (what crosses the
    /// wasm boundary, written once with no per-column arrays to join).
    pub fn decisions_flat(&self, from: u64, to: u64) -> Vec<f64> {
        let len = (to - from) as usize;
        let mut flat: Vec<f64> = self
            .columns
            .iter()
            .flat_map(|c| std::iter::repeat_n(c.kind.no_value(), len))
            .collect();
        self.replay_decisions(from, to, |column, i, value| flat[column * len + i] = value);
        flat
    }

    /// Replays steps `from..to`, calling `put(trace column, step index -
    /// from, value)` for each value a segment's stepper writes (NaN in a
    /// category or flag column made [`NO_VALUE`]); columns a segment does
    /// not have are left alone.
    fn replay_decisions(&self, from: u64, to: u64, mut put: impl FnMut(usize, usize, f64)) {
        let mut row = vec![f64::NAN; MAX_COLUMNS];
        self.for_each_replay(from, to, |segment, mut stepper, steps| {
            for i in steps {
                row.fill(f64::NAN);
                let step = stepper.replay_step(&mut row);
                // The steps were recorded by the steppers' fast fills, and
                // are replayed here by their rule a step at a time: in
                // debug builds (the tests) every decision read is also a
                // check that the two agree.
                debug_assert_eq!(
                    step,
                    Some(self.steps[i as usize]),
                    "step {i} replays as it was recorded"
                );
                for (local, &global) in segment.column_index.iter().enumerate() {
                    let value = self.columns[global].kind.cell(row[local]);
                    put(global, (i - from) as usize, value);
                }
            }
        });
    }

    /// Calls `f(segment, its stepper replayed so that its next step is the
    /// first of them, step indices)` for each stretch of step indices
    /// `from..to` that belongs to one segment, in order: the one walk of
    /// the segments that [`Self::replay_decisions`] and
    /// [`Self::count_ties`] make.
    fn for_each_replay(
        &self,
        from: u64,
        to: u64,
        mut f: impl FnMut(&Segment, Box<dyn Replay>, Range<u64>),
    ) {
        let mut k = from;
        while k < to {
            let segment = self.segment(self.segment_of_step(k));
            let end = to.min(segment.first_step + segment.steps);
            f(&segment, Self::replay_to(&segment, k), k..end);
            k = end;
        }
    }

    /// Step index k replayed once: its decision values (one per trace
    /// column, as [`Trace::decisions`] gives them), its explanation and its
    /// picture.
    pub fn replay_step(&self, k: u64) -> ReplayedStep {
        let segment = self.segment(self.segment_of_step(k));
        let mut row = vec![f64::NAN; MAX_COLUMNS];
        let (explanation, figure) = Self::replay_to(&segment, k)
            .detail_step(&self.point(k), &mut row)
            .expect("a recorded step replays to the same step");
        let mut values: Vec<f64> = self.columns.iter().map(|c| c.kind.no_value()).collect();
        for (local, &global) in segment.column_index.iter().enumerate() {
            values[global] = self.columns[global].kind.cell(row[local]);
        }
        ReplayedStep {
            values,
            explanation,
            figure,
        }
    }

    /// One sentence: why step index k was taken.
    pub fn explain(&self, k: u64) -> String {
        let segment = self.segment(self.segment_of_step(k));
        let from = self.point(k);
        Self::replay_to(&segment, k)
            .explain_step(&from)
            .expect("a recorded step replays to the same step")
    }
}

/// What a trace is, handed over with it: its algorithm, its axes, its
/// length and its ends. Point index k runs 0..=steps, step index k runs
/// 0..steps-1; coordinates are grid units. What else a viewer may read is
/// asked for on its own, so that a caller that only reads points pays for
/// none of it: its legend ([`TraceLegend`], 2 to 3 KB of teaching text),
/// its metrics (a pass over every point) and its segments (one object with
/// a sentence per chord or G-code move) ([`Trace::legend`],
/// [`Trace::metrics`], [`Trace::segment_summaries`]).
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct TraceSummary<'a> {
    /// The catalogue id of the algorithm that traced it.
    #[tsify(type = "AlgorithmId")]
    pub algorithm: &'a str,
    /// Axes per point: the stride of the points array.
    pub dims: usize,
    pub steps: u64,
    /// Point 0 and point `steps`.
    pub start: Vec<i64>,
    pub end: Vec<i64>,
}

/// How to read a trace's decisions and how far its points may stray: read
/// when first asked for, not with every trace. Its columns' and figures'
/// texts are 2 to 3 KB a trace (the helix's 12 columns 2.7 KB): handed
/// over with the summary, after a collection with memory not in cache,
/// they made `trace()` of a circle of r = 10 take 0.28 ms, 0.25 ms without
/// (Node, in the end-to-end bench's order, medians of 24).
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct TraceLegend<'a> {
    /// The decision columns, in the order the decisions array holds them.
    pub columns: &'a [Column],
    /// The pictures its steps' decisions can have: a step's own is in its
    /// `StepDetail`.
    pub figures: &'a [FigureKind],
    /// Absent (null) where the algorithm guarantees none.
    pub deviation_bound: Option<&'a DeviationBound>,
}

/// The box every point of a trace lies in, grid units: on each axis the
/// smallest and the largest coordinate over point indices 0..=steps
/// ([`Trace::bounds`]).
#[derive(Serialize, Tsify, Debug, PartialEq)]
pub struct PointBounds {
    /// One coordinate per axis.
    pub min: Vec<i64>,
    /// One coordinate per axis.
    pub max: Vec<i64>,
}

/// One stretch of a trace produced by one stepper (a line, a chord, a
/// G-code move).
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct SegmentSummary<'a> {
    /// Step index of the segment's first step.
    pub first_step: u64,
    pub steps: u64,
    /// Point where the segment starts.
    pub start: Vec<i64>,
    pub ideal: IdealPathInfo,
    /// What a learner should know about this move before it starts.
    pub note: Cow<'a, str>,
}

impl Segment {
    /// A copy of the stepper's state before segment step
    /// `checkpoint` * CHECKPOINT_INTERVAL.
    fn state_at(&self, checkpoint: usize) -> Box<dyn Replay> {
        match checkpoint {
            0 => self.first_state.clone_box(),
            _ => self.states[checkpoint - 1].clone_box(),
        }
    }

    /// The stepper's note: kept, or made from its state at the start.
    pub fn note(&self) -> Cow<'_, str> {
        match &self.setup_note {
            Some(note) => Cow::Borrowed(note),
            None => Cow::Owned(self.state_at(0).setup_note()),
        }
    }
}

impl Trace {
    pub fn summary(&self) -> TraceSummary<'_> {
        TraceSummary {
            algorithm: &self.algorithm,
            dims: self.dims(),
            steps: self.steps(),
            start: self.start.coords().to_vec(),
            end: self.end.coords().to_vec(),
        }
    }

    /// Its decision columns, their figures and its deviation's bound.
    pub fn legend(&self) -> TraceLegend<'_> {
        TraceLegend {
            columns: &self.columns,
            figures: &self.figures,
            deviation_bound: self.deviation_bound(),
        }
    }

    /// This trace with `prefix` starting every segment's note (then a
    /// space, then the stepper's own note), made when a note is read.
    pub fn with_note_prefix(mut self, prefix: NotePrefix) -> Trace {
        self.note_prefix = Some(prefix);
        self
    }

    /// The note of segment `index`: what a learner should know before it.
    pub fn segment_note(&self, index: usize) -> Cow<'_, str> {
        let own = match self.segment(index) {
            SegmentRef::Kept(segment) => segment.note(),
            SegmentRef::Made(segment) => Cow::Owned(segment.note().into_owned()),
        };
        match &self.note_prefix {
            None => own,
            Some(prefix) => Cow::Owned(format!("{} {own}", prefix(index))),
        }
    }

    /// Segment `index` as a viewer reads it.
    pub fn segment_summary(&self, index: usize) -> SegmentSummary<'_> {
        let s = self.segment(index);
        SegmentSummary {
            first_step: s.first_step,
            steps: s.steps,
            start: s.start.coords().to_vec(),
            ideal: s.ideal.info(),
            note: self.segment_note(index),
        }
    }

    /// Every segment as a viewer reads it, in step order.
    pub fn segment_summaries(&self) -> Vec<SegmentSummary<'_>> {
        (0..self.segments.len())
            .map(|i| self.segment_summary(i))
            .collect()
    }

    /// The ideal path of all segments joined, for drawing (stride dims).
    /// A segment's first vertex is left out where it repeats the previous
    /// segment's last ([`IdealPath::polyline_into`]).
    pub fn ideal_polyline(&self) -> Vec<f64> {
        let dims = self.dims();
        // A vertex a segment past the first, as a line that starts where the
        // one before ended adds, and one for the first segment's start: an
        // arc's others are reserved as they come.
        let mut out: Vec<f64> = Vec::with_capacity((self.segments.len() + 1) * dims);
        for index in 0..self.segments.len() {
            self.ideal_of(index).polyline_into(&mut out);
        }
        out
    }

    /// [`Self::ideal_polyline`] as WebGL draws it ([`IdealLineF32`]), each
    /// vertex taken from `origin` (x, y, z): from an origin near the path
    /// (its start), a vertex keeps its fraction of a cell where f32 would
    /// round a coordinate near 2^30 to a multiple of 64. Converted and boxed
    /// here, in the pass that makes the vertices: a page's worker did it in
    /// JavaScript, once per run and so mostly before its JIT had optimised
    /// the loop (11 to 12 ms for a 100,000-line program's 250,000 vertices,
    /// against 3.4 ms once optimised).
    pub fn ideal_line_f32(&self, origin: [f64; 3]) -> IdealLineF32 {
        let dims = self.dims();
        let mut line = IdealLineF32::default();
        // Each vertex goes straight into the f32 pieces, with no vector of
        // f64 between (what ideal_polyline gives, without its megabytes),
        // after the last one drawn, which a segment's first is compared
        // with: a segment is most often a G-code program's line, made when
        // read, two vertices of which one is drawn.
        let mut last: Option<[f64; MAX_AXES]> = None;
        let (mut min, mut max) = ([f32::INFINITY; 3], [f32::NEG_INFINITY; 3]);
        for index in 0..self.segments.len() {
            let after = last;
            let after = after.as_ref().map(|l| &l[..dims]);
            self.ideal_of(index).for_each_vertex(after, |vertex| {
                // Made whole, not lane by lane: the box's vector reads
                // would wait on three separate stores (a failed store
                // forward, which had made this loop a third slower).
                let exact: [f64; 3] =
                    std::array::from_fn(|axis| vertex.get(axis).map_or(0.0, |&v| v - origin[axis]));
                let drawn: [f32; 3] = exact.map(|v| v as f32);
                for axis in 0..3 {
                    min[axis] = min[axis].min(drawn[axis]);
                    max[axis] = max[axis].max(drawn[axis]);
                }
                line.push(
                    drawn,
                    std::array::from_fn(|axis| (exact[axis] - f64::from(drawn[axis])) as f32),
                );
                last = Some(std::array::from_fn(|axis| {
                    vertex.get(axis).copied().unwrap_or(0.0)
                }));
            });
        }
        if line.vertices > 0 {
            let [x0, y0, z0] = min;
            let [x1, y1, z1] = max;
            line.bounds = [x0, y0, z0, x1, y1, z1];
        }
        line
    }
}

/// Vertices per piece of an [`IdealLineF32`]: 96 KiB of x, y, z and as
/// much of rests, a piece's copy out of wasm a single call.
const IDEAL_LINE_PIECE_VERTICES: usize = 8192;

/// A path's ideal polyline as WebGL draws it: x, y, z of each vertex less
/// an origin, each the f64 difference rounded to the nearest f32 (`as`; a
/// 2-axis path at z = 0, axes past the third left out), what that rounding
/// left of each (its rest: the f64 less the f32, itself as f32), and the
/// box of the f32 vertices. A million cells from the origin an f32 keeps
/// only an eighth of a cell, so the rest gives the page the vertex to about
/// 2^-48 of its distance, to draw the part of a long path the learner
/// looks at from an origin there.
///
/// Kept in pieces of [`IDEAL_LINE_PIECE_VERTICES`] vertices, their count
/// unknown until the last segment is made: one vector of them all, grown
/// by doubling, copied its values up to twice, and its abandoned blocks
/// and the whole array made from it grew wasm memory (the G-code bench's
/// 100,000-line program at 1 step/mm, 250,000 vertices: by 20.75 MB, and
/// its first line took 41 to 64 ms of CPU in Node; in pieces it took 24 to
/// 28 ms, in memory the program's run had already grown). The caller
/// copies the pieces where it wants them ([`Self::xyz_pieces`],
/// [`Self::rest_pieces`]) once it knows the count.
#[derive(Default)]
pub struct IdealLineF32 {
    /// The box of the f32 vertices, as [`Self::bounds`] gives it.
    bounds: [f32; 6],
    /// x, y, z of each vertex, full pieces then the one being filled.
    xyz: Vec<Vec<f32>>,
    /// What rounding left of each value of `xyz`, in the same pieces.
    rests: Vec<Vec<f32>>,
    vertices: usize,
}

impl IdealLineF32 {
    /// Appends a vertex's x, y, z as drawn and their rests.
    fn push(&mut self, drawn: [f32; 3], rests: [f32; 3]) {
        if self.vertices % IDEAL_LINE_PIECE_VERTICES == 0 {
            self.xyz
                .push(Vec::with_capacity(3 * IDEAL_LINE_PIECE_VERTICES));
            self.rests
                .push(Vec::with_capacity(3 * IDEAL_LINE_PIECE_VERTICES));
        }
        // A piece was pushed at the first vertex and at every
        // IDEAL_LINE_PIECE_VERTICES-th after it.
        let started = "a piece is started above";
        self.xyz
            .last_mut()
            .expect(started)
            .extend_from_slice(&drawn);
        self.rests
            .last_mut()
            .expect(started)
            .extend_from_slice(&rests);
        self.vertices += 1;
    }

    /// How many vertices the line has.
    pub fn vertices(&self) -> usize {
        self.vertices
    }

    /// The smallest x, y, z over the f32 vertices, then the largest; all
    /// zeros when there is no vertex.
    pub fn bounds(&self) -> [f32; 6] {
        self.bounds
    }

    /// x, y, z of the vertices in order (flat, stride 3), a piece at a time.
    pub fn xyz_pieces(&self) -> impl Iterator<Item = &[f32]> {
        self.xyz.iter().map(Vec::as_slice)
    }

    /// The rest of each value of [`Self::xyz_pieces`], in the same pieces.
    pub fn rest_pieces(&self) -> impl Iterator<Item = &[f32]> {
        self.rests.iter().map(Vec::as_slice)
    }
}

/// Most columns one stepper may declare.
const MAX_COLUMNS: usize = 32;

/// How far a pass over a trace's points (its metrics, a chart's rows) made
/// a slice at a time has got.
#[derive(Serialize, Tsify, Debug, Clone, Copy, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct PointsProgress {
    /// Points measured so far, of `points`.
    pub points_done: u64,
    pub points: u64,
    pub done: bool,
}

impl PointsProgress {
    fn of(points_done: u64, points: u64) -> PointsProgress {
        PointsProgress {
            points_done,
            points,
            done: points_done == points,
        }
    }
}

/// The metrics' pass made so far ([`Trace::advance_metrics`]).
struct MetricsPass {
    acc: MetricsAccumulator,
    ties: u64,
    /// The first point index not measured yet.
    next_point: u64,
}

impl MetricsPass {
    fn new(dims: usize) -> MetricsPass {
        MetricsPass {
            acc: MetricsAccumulator::new(dims),
            ties: 0,
            next_point: 0,
        }
    }

    /// Measures at most `max_points` more points of `trace`, with the steps
    /// to them (step k is counted with point k, so each once).
    fn advance(&mut self, trace: &Trace, max_points: u64) {
        let from = self.next_point;
        let to = from.saturating_add(max_points).min(trace.steps() + 1);
        let (first_step, end_step) = (from.min(trace.steps()), to.min(trace.steps()));
        self.acc.add_steps(trace.step_range(first_step, end_step));
        self.ties += trace.count_ties(first_step, end_step);
        trace.measure_points(from, to, &mut self.acc);
        self.next_point = to;
    }

    fn finish(self) -> Metrics {
        self.acc.finish(self.ties)
    }
}

/// The columns of the chart rows a pass fills ([`Trace::chart_rows`]):
/// the rows' heads (point index, coordinates, ideal position) and the
/// deviation's extremes of each row, of `bucket` points each from point
/// `origin`.
struct ChartColumns<'a> {
    head: &'a mut [f64],
    largest: &'a mut [f64],
    smallest: &'a mut [f64],
    rows: usize,
    dims: usize,
    origin: u64,
    bucket: u64,
}

impl ChartColumns<'_> {
    /// Ends the bucket `state` is filling (its row's extremes) and starts
    /// point k's, writing its row's head from the point and axis error
    /// `head` gives: a call of its own, so that what a bucket's first
    /// point computes stays out of the walks' loops, whose closures are
    /// then small enough to inline (with that code in the loop, natively
    /// the circle's rows took 58 ms, 14 so).
    #[inline(never)]
    fn start_row(
        &mut self,
        state: &mut ChartBucket,
        k: u64,
        head: impl FnOnce() -> (Point, [f64; MAX_AXES]),
    ) {
        debug_assert_eq!(
            (k - self.origin) % self.bucket,
            0,
            "point {k} starts a bucket"
        );
        if let Some(ended) = state.row {
            (self.largest[ended], self.smallest[ended]) = (state.high, state.low);
        }
        let r = ((k - self.origin) / self.bucket) as usize;
        let (p, error) = head();
        let (rows, dims) = (self.rows, self.dims);
        self.head[r] = k as f64;
        for a in 0..dims {
            self.head[(1 + a) * rows + r] = p.get(a) as f64;
            self.head[(1 + dims + a) * rows + r] = p.get(a) as f64 - error[a];
        }
        *state = ChartBucket {
            row: Some(r),
            left: self.bucket,
            high: f64::NEG_INFINITY,
            low: f64::INFINITY,
        };
    }
}

/// The bucket a chart pass is filling: its row (None before the first
/// point), the points left in it, and its deviation's extremes so far.
struct ChartBucket {
    row: Option<usize>,
    left: u64,
    high: f64,
    low: f64,
}

impl ChartBucket {
    /// Point k's share of its row: its deviation, and where it starts a
    /// bucket the row's head, from the point and axis error `head` gives,
    /// asked for then alone.
    #[inline(always)]
    fn record(
        &mut self,
        columns: &mut ChartColumns,
        k: u64,
        deviation: f64,
        head: impl FnOnce() -> (Point, [f64; MAX_AXES]),
    ) {
        if self.left == 0 {
            columns.start_row(self, k, head);
        }
        self.left -= 1;
        self.high = self.high.max(deviation);
        self.low = self.low.min(deviation);
    }
}

/// A chart's rows made so far ([`Trace::chart_rows`]), a stretch of whole
/// buckets at a time.
struct ChartPass {
    from: u64,
    to: u64,
    max_rows: u64,
    /// Points per row: `ceil((to - from) / max_rows)`.
    bucket: u64,
    rows: usize,
    /// Column-major, as [`Trace::chart_rows`] returns them.
    out: Vec<f64>,
    /// The first point index whose bucket is not made yet.
    next_point: u64,
}

impl ChartPass {
    fn new(trace: &Trace, from: u64, to: u64, max_rows: u64) -> ChartPass {
        let dims = trace.dims();
        let bucket = (to - from).div_ceil(max_rows.max(1)).max(1);
        let rows = (to - from).div_ceil(bucket) as usize;
        let mut out = vec![f64::NAN; rows * (3 + 2 * dims)];
        if !trace.segments.is_empty() {
            // A trace without segments keeps NaN deviations.
            let deviation = &mut out[rows * (1 + 2 * dims)..];
            let (largest, smallest) = deviation.split_at_mut(rows);
            largest.fill(f64::NEG_INFINITY);
            smallest.fill(f64::INFINITY);
        }
        ChartPass {
            from,
            to,
            max_rows,
            bucket,
            rows,
            out,
            next_point: from,
        }
    }
}
