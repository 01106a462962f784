//! Blocks -> moves in machine millimetres, through the modal state.
//!
//! Modal state (kept from line to line until changed): motion mode G0 G1 G2
//! G3 (G0 at the start, as in Grbl), plane G17 G18 G19 (XY, ZX, YZ), units G20 (inch) G21 (mm, the start),
//! distance mode G90 (absolute, the start) G91 (incremental), arc center
//! mode G90.1 (I J K absolute) G91.1 (incremental, relative to the arc's
//! start: the start), the G92 offset (G92.1 clears it) and the feed F. The
//! program's end (M2, M30) resets some of them, as Grbl does (see
//! [`Interpreter::end_program`]), and the lines after it run.
//!
//! Within a line, whatever the order of its words, the modes are set first,
//! then G92 or the move runs (RS274/NGC's order of execution). Positions are
//! kept in machine mm: machine = program + G92 offset, where `G92 X0` makes
//! the current machine position read as X0.
//!
//! Arcs:
//! - center format, I J K: the center's offset from the start (G91.1) or
//!   its position (G90.1) on the plane's two axes; the start and end radii
//!   must agree within LinuxCNC's default tolerance (0.0283 mm, or 0.00283
//!   in in G20, and 0.1 % of the radius). An end equal to the start is a
//!   full circle;
//! - radius format, R: the center is on the perpendicular bisector of start
//!   and end. R > 0 takes the arc of at most 180°, R < 0 the one of more
//!   than 180°: for G02 (clockwise) R > 0 puts the center to the right of
//!   the chord from start to end, seen from the positive end of the plane's
//!   normal, for G03 to the left, and R < 0 the other side. An R arc cannot
//!   be a full circle, and fails when the end is more than 2|R| from the
//!   start (LinuxCNC's tolerance: 0.00127 mm);
//! - the sweep is the angle from start to end around the center in the
//!   plane's right-handed frame (G18 is Z then X, so that G02 is clockwise
//!   seen from +Y like G17 seen from +Z), pushed a full turn the commanded
//!   way when it reads the other way within 5e-7 rad (Grbl's
//!   ARC_ANGULAR_TRAVEL_EPSILON: a rounding sliver is a full circle);
//! - P n (a whole number as written, 1 to 1000000) is the number of
//!   turns: n - 1 full turns are added (LinuxCNC);
//! - the plane's normal axis may move during the arc: a helix.
//!
//! Feed F (units per minute, G94) is kept with each move in mm/min, for the
//! planner (`timing`). In G93 (inverse time) F is how many such moves take
//! a minute: the move runs its whole path in 1/F minutes at its programmed
//! rate, F being the line's own (Grbl zeroes it before and after every G93
//! block, gcode.c step 3), never converted by G20; the planner turns it into
//! mm/min once the move's length in steps is known (`timing::push_move`).

use super::parse::{Block, Code, Problem, Word};
use crate::arc::planes::{Plane, Turn};
use crate::error::{Error, Location};
use crate::grid::AXIS_NAMES;
use crate::machine::{MACHINE_AXES, MM_PER_INCH};
use std::f64::consts::TAU;

/// LinuxCNC's RADIUS_TOLERANCE (0.00005 in, 0.00127 mm): the smallest
/// radius, and how far past 2|R| an R arc's end may be.
const RADIUS_TOLERANCE_INCH: f64 = 0.00005;
/// LinuxCNC's CENTER_ARC_RADIUS_TOLERANCE (2 × 0.001 × sqrt 2 in,
/// 2 × 0.01 × sqrt 2 mm): how much an I J K arc's end radius may differ from
/// its start radius...
const SPIRAL_TOLERANCE_INCH: f64 = 2.0 * 0.001 * std::f64::consts::SQRT_2;
const SPIRAL_TOLERANCE_MM: f64 = 2.0 * 0.01 * std::f64::consts::SQRT_2;
/// ...and at most this fraction of the radius (SPIRAL_RELATIVE_TOLERANCE).
const SPIRAL_RELATIVE_TOLERANCE: f64 = 0.001;
/// The fastest feed a program may set, mm/min (1000 km/min, past any
/// machine): a bound that keeps a planner's squared speeds finite.
pub const MAX_FEED_MM_PER_MIN: f64 = 1e9;
/// The largest F in inverse time (G93), moves a minute: a move in 60 ns.
/// The feed it asks is F times the move's length (at most about 4·10^12
/// mm: 2^31 steps an axis at MIN_STEPS_PER_MM, 0.001): its square stays far
/// inside f64, as the planner needs, without a bound of its own.
pub const MAX_INVERSE_TIME_PER_MIN: f64 = 1e9;
/// The longest dwell a program may ask for, s (G4 P; about 11.6 days): a
/// step's instant is an f64 of seconds from the program's start, and past
/// about 4.5·10^6 s it no longer tells nanoseconds apart, so one dwell of
/// 10^20 s left every later move's steps at one instant.
pub const MAX_DWELL_SECONDS: f64 = 1e6;
/// Grbl's ARC_ANGULAR_TRAVEL_EPSILON, radians.
const FULL_CIRCLE_EPSILON_RAD: f64 = 5e-7;

/// Whether G`number`.`minor`, a G code voxpath does not model, leaves the
/// X Y Z of its line to the motion mode, as Grbl leaves them to it (its
/// implicit axis command, gcode.c "Assign implicit motion-mode"): modal
/// settings of other groups, which take no axis words (cutter compensation
/// off, work coordinate systems, path control, spindle speed and canned
/// cycle return modes, lathe diameter modes), and G28.1 and G30.1 (gcode.c:
/// "If axis words are passed here, they are interpreted as an implicit
/// motion mode"). Any other code might take them as something else than a
/// move, as G10, G28, G30, G43.1, G49 (gcode.c: axis_command =
/// AXIS_COMMAND_TOOL_LENGTH_OFFSET, the Z is the offset) and G52 do: its
/// line's axis words are then not a move, never a surprise one. G53 takes
/// them too, as a move in machine coordinates (see [`Interpreter::run_line`]).
fn leaves_axis_words_to_motion(number: u32, minor: u32) -> bool {
    matches!(
        (number, minor),
        (7 | 8 | 40 | 64 | 96..=99, 0) | (28 | 30, 1) | (54..=59, 0) | (59, 1..=3) | (61, 0..=1)
    )
}

/// Whether `letter` names an axis voxpath does not model: E (a 3D
/// printer's extruder), the rotary axes A, B and C, and the parallel axes
/// U, V and W.
fn is_other_axis(letter: char) -> bool {
    matches!(letter, 'E' | 'A' | 'B' | 'C' | 'U' | 'V' | 'W')
}

/// The modal group of a G code outside the groups voxpath models, as
/// RS274/NGC (LinuxCNC) and Grbl group them, by the name an error gives it.
/// The non-modal group holds G4 and G92, which voxpath runs, beside codes
/// it ignores.
fn other_modal_group(number: u32, minor: u32) -> Option<&'static str> {
    Some(match (number, minor) {
        (4 | 10 | 28 | 30 | 53 | 92, 0) | (28 | 30, 1) | (92, 1..=3) => "non-modal",
        (40, 0) | (41 | 42, 0..=1) => "cutter compensation",
        (43, 0..=2) | (49, 0) => "tool length offset",
        (54..=59, 0) | (59, 1..=3) => "coordinate system",
        (61, 0..=1) | (64, 0) => "path control",
        (98 | 99, 0) => "canned cycle return",
        (96 | 97, 0) => "spindle speed mode",
        (7 | 8, 0) => "lathe diameter mode",
        _ => return None,
    })
}

/// The modal group of `code`, by the name an error gives it, if it has
/// one: a line holds one code of each group (Grbl refuses two: error 21,
/// modal group violation). The groups voxpath models, and
/// [`other_modal_group`]'s.
fn modal_group(code: &Code) -> Option<&'static str> {
    let (number, minor) = (code.number, code.minor);
    Some(match code.letter {
        'G' if motion_code(number, minor).is_some() => "motion",
        'G' => match (number, minor) {
            (17..=19, 0) => "plane",
            (20 | 21, 0) => "units",
            (90 | 91, 0) => "distance mode",
            (90 | 91, 1) => "arc center mode",
            (93 | 94, 0) => "feed rate mode",
            _ => return other_modal_group(number, minor),
        },
        'M' => match (number, minor) {
            (3..=5, 0) => "spindle",
            (7..=9, 0) => "coolant",
            (0 | 1 | 2 | 30, 0) => "program flow",
            _ => return None,
        },
        _ => return None,
    })
}

/// The first of `codes` (a line's, in the order it writes them) at fault
/// among them: the second of a modal group, or one refused outright
/// (G92.2, G92.3). Each is a fault whatever else the line holds, after
/// them or before, and whatever mode the machine is in.
fn codes_fault(line: u32, codes: &[Code]) -> Option<Error> {
    for (k, code) in codes.iter().enumerate() {
        if let Some(group) = modal_group(code) {
            if let Some(first) = codes[..k].iter().find(|c| modal_group(c) == Some(group)) {
                return Some(Error::at(
                    line,
                    code.column,
                    format!(
                        "{} and {} are both {group} codes: give one per line",
                        first.name(),
                        code.name()
                    ),
                ));
            }
        }
        if matches!((code.letter, code.number, code.minor), ('G', 92, 2 | 3)) {
            return Some(Error::at(
                line,
                code.column,
                format!(
                    "{} is not supported, as in Grbl (error 20, unsupported command): the positions of the lines after it would be unknown; use G92.1 to clear the G92 offset, G92 to set one",
                    code.name()
                ),
            ));
        }
    }
    None
}

/// The first fault, by column, that `block`'s words and codes show on
/// their own: a negative F, P or S (gcode.c, step 2: "Check for invalid
/// negative values for words F, N, P, T, and S", error 4; N and T take no
/// sign in the reader), or [`codes_fault`]'s. No word or code after them on
/// the line, nor the mode the machine is in, mends one or moves it, so it
/// is told of a line the reader cut short at an error of its own, when it
/// stands before that error: `M3 M3 M3 M3 M3` is read up to its fifth M
/// (column 13: "too many M codes") and its fault is the second M3 (column
/// 4), which `M3 M3` is told. What the rest of a line decides (an arc's I,
/// a dwell's P, an F in G93) is not judged here: a cut line may lack it.
///
/// Run on every line: an error is built only for a fault found, and none
/// is moved where the line has none (gathered in an array of two errors
/// and the first taken, every line moved them in wasm by a `memory.copy`,
/// a call into the engine).
pub fn first_fault_on_its_own(line: u32, block: &Block) -> Option<Error> {
    let negative = block
        .words
        .iter()
        .find(|w| matches!(w.letter, 'F' | 'P' | 'S') && w.value < 0.0);
    let Some(w) = negative else {
        // Made straight in the caller's place: kept in a local first, the
        // error (or its absence) was moved into it.
        return codes_fault(line, &block.codes);
    };
    let codes = codes_fault(line, &block.codes);
    let column = |e: &Error| match e.location {
        Location::Source { column, .. } => column,
        _ => unreachable!("a line's fault is placed at its column"),
    };
    if codes.as_ref().is_some_and(|e| column(e) < w.column) {
        return codes;
    }
    Some(Error::at(
        line,
        w.column,
        format!(
            "{}{}: {} cannot be negative (Grbl refuses it: error 4, negative value)",
            w.letter, w.value, w.letter
        ),
    ))
}

/// The motion code (modal group 1) G`number`.`minor` is, if any. The ones
/// voxpath does not model: splines (G5, G5.1, G5.2), threading (G33,
/// G33.1, G76), probing (G38.2-G38.5) and canned cycles (G73, G81-G89).
/// Each is a motion mode of its own: the axis words of its line, and of
/// later lines until another motion code, are its, never a G1 move.
fn motion_code(number: u32, minor: u32) -> Option<MotionCode> {
    Some(match (number, minor) {
        (0, 0) => MotionCode::Move(Motion::Rapid),
        (1, 0) => MotionCode::Move(Motion::Linear),
        (2, 0) => MotionCode::Move(Motion::Arc(Turn::Clockwise)),
        (3, 0) => MotionCode::Move(Motion::Arc(Turn::CounterClockwise)),
        (80, 0) => MotionCode::Cancel,
        (5, 0..=2) | (33, 0..=1) | (38, 2..=5) | (73, 0) | (76, 0) | (81..=89, 0) => {
            MotionCode::Unmodelled
        }
        _ => return None,
    })
}

/// What a line's motion code (modal group 1) selects.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum MotionCode {
    Move(Motion),
    /// G80: no motion mode, so axis words alone are an error again.
    Cancel,
    /// A motion mode voxpath does not model (see [`motion_code`]).
    Unmodelled,
}

/// Motion modes (modal group 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Motion {
    /// G0: stepped like G1, timed at the top rate along the move.
    Rapid,
    /// G1.
    Linear,
    /// G2 (clockwise) or G3.
    Arc(Turn),
}

impl Motion {
    pub fn code(self) -> &'static str {
        match self {
            Motion::Rapid => "G0",
            Motion::Linear => "G1",
            Motion::Arc(Turn::Clockwise) => "G2",
            Motion::Arc(Turn::CounterClockwise) => "G3",
        }
    }
}

/// How an arc's center was given.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ArcFormat {
    Center,
    Radius,
}

/// An arc in machine mm.
#[derive(Clone, Debug, PartialEq)]
pub struct ArcMm {
    pub plane: Plane,
    pub turn: Turn,
    pub format: ArcFormat,
    /// Center on the plane's two axes; on the normal axis, the start's.
    pub center_mm: [f64; MACHINE_AXES],
    /// Distance of the start from the center.
    pub radius_mm: f64,
    /// Signed angle travelled (< 0 for G2), extra turns included.
    pub sweep_rad: f64,
    /// Full turns added by P.
    pub extra_turns: u32,
    /// The word (letter and column) each center coordinate on the plane's
    /// two axes came from: I, J or K, or R for both; an error about the
    /// center names it.
    pub center_words: [(char, u32); 2],
}

/// One move in machine mm, with the line that asked for it.
#[derive(Clone, Debug, PartialEq)]
pub struct MoveMm {
    pub line: u32,
    /// Column of the motion code, or of the first axis word when the motion
    /// mode was set on an earlier line.
    pub column: u32,
    pub motion: Motion,
    pub from_mm: [f64; MACHINE_AXES],
    pub to_mm: [f64; MACHINE_AXES],
    /// Column of the X, Y and Z word of the line, or of the move when the
    /// axis has none: an error about the target names it.
    pub axis_columns: [u32; MACHINE_AXES],
    pub feed_mm_per_min: Option<f64>,
    /// In G93 (inverse time), the line's F instead: the move's whole path
    /// in 1/F minutes. None in G94 and for rapids.
    pub inverse_time_per_min: Option<f64>,
    pub arc: Option<ArcMm>,
}

/// What one line did besides changing modes.
#[derive(Debug, Default)]
pub struct Effects {
    pub motion: Option<MoveMm>,
    pub warnings: Vec<Problem>,
    /// The machine comes to rest before this line's motion and waits this
    /// many seconds: Grbl synchronises its buffer before a dwell (G4 P), a
    /// change of the spindle or its speed while it turns (M3-M5, S:
    /// spindle_sync) and a change of coolant (M7-M9: coolant_sync), all of
    /// which gc_execute_line runs before the line's motion (its steps 4, 7,
    /// 8 and 10; the motion is step 20).
    pub stop: Option<f64>,
    /// The machine comes to rest after this line's motion: a pause or the
    /// program's end (M0, M2, M30), gc_execute_line's step 21, after the
    /// motion.
    pub stop_after: bool,
    /// G92.1: the G92 offset is cleared after this line's motion, whose
    /// target was taken through it (Grbl computes the target while it
    /// checks the line, then clears the offset in its step 19).
    clears_offset: bool,
    /// M2 or M30: the modal state is reset after this line's motion
    /// (see [`Interpreter::end_program`]).
    ends_program: bool,
}

/// The spindle, as M3, M4 and M5 set it (Grbl's modal group M7).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Spindle {
    Off,
    Clockwise,
    CounterClockwise,
}

/// Coolant, as M7, M8 and M9 set it (Grbl's modal group M8): mist and
/// flood may both be on; M9 turns both off.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Coolant {
    mist: bool,
    flood: bool,
}

const COOLANT_OFF: Coolant = Coolant {
    mist: false,
    flood: false,
};

/// The modal state and the position, from line to line.
#[derive(Clone, Debug)]
pub struct Interpreter {
    motion: Option<Motion>,
    /// The unmodelled motion mode in force instead of `motion`, and its line.
    unmodelled_motion: Option<(Code, u32)>,
    plane: Plane,
    inches: bool,
    incremental: bool,
    absolute_centers: bool,
    /// F in force: mm/min in G94; in G93 the line's F (moves per minute),
    /// None on a G93 line without one.
    feed_mm_per_min: Option<f64>,
    /// G93 (inverse time) was programmed and not yet left by G94 or M2.
    inverse_time: bool,
    /// Programmed position, machine mm (before rounding to steps).
    position_mm: [f64; MACHINE_AXES],
    /// G92: machine = program + offset.
    offset_mm: [f64; MACHINE_AXES],
    /// The spindle, its speed (S, modal) and the coolant: voxpath models
    /// none of them, but Grbl brings the motion to rest when they change.
    spindle: Spindle,
    spindle_speed: f64,
    coolant: Coolant,
    /// The work coordinate system selected (54 to 59: G54 to G59, Grbl's)
    /// and the tool length offset (G43.1 Z, mm; G49: 0): voxpath models
    /// neither, but Grbl brings the motion to rest when either changes (see
    /// [`Interpreter::rest_for_unmodelled`]).
    coordinate_system: u32,
    tool_length_offset_mm: f64,
}

impl Default for Interpreter {
    fn default() -> Self {
        Interpreter {
            // Grbl starts in G0 (gcode.h: MOTION_MODE_SEEK is 0, and
            // gc_init memsets the parser state to 0).
            motion: Some(Motion::Rapid),
            unmodelled_motion: None,
            plane: Plane::Xy,
            inches: false,
            incremental: false,
            absolute_centers: false,
            feed_mm_per_min: None,
            inverse_time: false,
            position_mm: [0.0; MACHINE_AXES],
            offset_mm: [0.0; MACHINE_AXES],
            spindle: Spindle::Off,
            spindle_speed: 0.0,
            coolant: COOLANT_OFF,
            coordinate_system: 54,
            tool_length_offset_mm: 0.0,
        }
    }
}

/// The words of a line, by letter (the reader lets each letter onto a
/// line once: a second is a syntax error, and such a line is not run, so a
/// line has at most 26). A letter's word is found by its place among the
/// line's words, a byte a letter: a table of 26 references (104 bytes in
/// wasm) was cleared and moved by a `memory.fill` and a `memory.copy`, two
/// calls into the engine every line (scripts/engine-calls.mjs).
struct Words<'b> {
    words: &'b [Word],
    /// 1 + the index in `words` of each letter's word; 0: the line has none.
    place_by_letter: [u8; 26],
}

impl<'b> Words<'b> {
    fn new(words: &'b [Word]) -> Words<'b> {
        let mut place_by_letter = [0u8; 26];
        for (index, w) in words.iter().enumerate() {
            debug_assert!(index < 26, "each letter once on a line");
            place_by_letter[(w.letter as u8 - b'A') as usize] = index as u8 + 1;
        }
        Words {
            words,
            place_by_letter,
        }
    }

    fn get(&self, letter: char) -> Option<&'b Word> {
        let place = self.place_by_letter[(letter as u8 - b'A') as usize];
        (place > 0).then(|| &self.words[place as usize - 1])
    }

    /// X, Y and Z words by axis index.
    fn axes(&self) -> [Option<&'b Word>; MACHINE_AXES] {
        [self.get('X'), self.get('Y'), self.get('Z')]
    }

    /// I, J and K words by axis index.
    fn center(&self) -> [Option<&'b Word>; MACHINE_AXES] {
        [self.get('I'), self.get('J'), self.get('K')]
    }

    fn first_of(&self, letters: &[char]) -> Option<&'b Word> {
        letters
            .iter()
            .filter_map(|&c| self.get(c))
            .min_by_key(|w| w.column)
    }
}

impl Interpreter {
    /// mm per program unit.
    fn unit_mm(&self) -> f64 {
        if self.inches { MM_PER_INCH } else { 1.0 }
    }

    /// The units `block`'s axis words are in: its own G20 or G21 wherever it
    /// stands on the line (gcode.c converts them after reading the whole
    /// line; two of them are refused), else the mode's. Found only where a
    /// word is read before the mode is set (G43.1's Z), not for every line.
    fn line_unit_mm(&self, block: &Block) -> f64 {
        match block
            .codes
            .iter()
            .find(|c| c.letter == 'G' && c.minor == 0 && matches!(c.number, 20 | 21))
        {
            Some(c) if c.number == 20 => MM_PER_INCH,
            Some(_) => 1.0,
            None => self.unit_mm(),
        }
    }

    fn unit_name(&self) -> &'static str {
        if self.inches { "in" } else { "mm" }
    }

    /// Runs one line, writing what it did besides changing modes into
    /// `effects` (one value the caller reuses line after line: returned,
    /// it was copied out for every line). On an error the program stops,
    /// so a half-applied line is never continued from.
    pub fn run(&mut self, line: u32, block: &Block, effects: &mut Effects) -> Result<(), Error> {
        self.run_line(line, block, effects)?;
        if effects.clears_offset {
            self.offset_mm = [0.0; MACHINE_AXES];
        }
        if effects.ends_program {
            self.end_program();
        }
        Ok(())
    }

    /// The program's end (M2, M30) as Grbl 1.1 runs it (gcode.c, step 21,
    /// PROGRAM_FLOW_COMPLETED): the motion mode, plane, distance mode and
    /// feed rate mode go back to G1, G17, G90 and G94, the spindle and
    /// coolant are off (M5, M9) and the work coordinate system is G54
    /// again (remembered only for the stop a change of it makes; G40 is
    /// not modelled). The tool length offset stays, as in Grbl. The units
    /// (G20, G21), the arc center mode (G90.1, G91.1), F, S and the G92
    /// offset stay: Grbl resets none of them ("The remaining modal groups
    /// [G-code 4,6,8,10,13,14,15] and [M-code 4,5,6] and the modal words
    /// [F,S,T,H] do not reset"; its coord_offset is left as it is). The
    /// lines after it run, in that state, as Grbl reads them.
    fn end_program(&mut self) {
        self.motion = Some(Motion::Linear);
        self.unmodelled_motion = None;
        self.plane = Plane::Xy;
        self.incremental = false;
        // G94 again, F kept: gc_execute_line carries the last F forward
        // whenever the state before the line is G94, as it is after the
        // reset (switching from G93 by a G94 word is what leaves F unset).
        self.inverse_time = false;
        (self.spindle, self.coolant) = (Spindle::Off, COOLANT_OFF);
        // gcode.c: "gc_state.modal.coord_select = 0; // G54".
        self.coordinate_system = 54;
    }

    /// For G code `code`, which voxpath does not model, when Grbl brings
    /// the motion to rest before its line's motion (`effects.stop`, set
    /// here) and why, as a clause for the code's warning; "" when it does
    /// not. Grbl synchronises its buffer when the work coordinate system
    /// or the tool length offset changes (gcode.c steps 14 and 15:
    /// system_flag_wco_change, with FORCE_BUFFER_SYNC_DURING_WCO_CHANGE on
    /// by default in config.h) and before it writes coordinate data to its
    /// EEPROM (G10 L2 and L20, G28.1, G30.1: settings_write_coord_data,
    /// with FORCE_BUFFER_SYNC_DURING_EEPROM_WRITE on by default).
    fn rest_for_unmodelled(
        &mut self,
        code: &Code,
        block: &Block,
        words: &Words,
        effects: &mut Effects,
    ) -> &'static str {
        /// The clause, the why after its one statement of what happens.
        macro_rules! comes_to_rest {
            ($why:literal) => {
                concat!(
                    "; the motion comes to rest here first, as Grbl's does ",
                    $why
                )
            };
        }
        if code.letter != 'G' {
            // M56 is Grbl's parking override and T55 a tool, not G56 and G55.
            return "";
        }
        let rest = match (code.number, code.minor) {
            // G59.1 to G59.3 are LinuxCNC's: Grbl refuses them (error 23),
            // so no stop of its is said for them, and they are not remembered.
            (54..=59, 0) => {
                let changed = self.coordinate_system != code.number;
                self.coordinate_system = code.number;
                if changed {
                    comes_to_rest!("when the work coordinate system changes")
                } else {
                    ""
                }
            }
            (43, 1) | (49, 0) => {
                let offset_mm = if code.number == 49 {
                    0.0
                } else {
                    words.get('Z').map_or(self.tool_length_offset_mm, |z| {
                        z.value * self.line_unit_mm(block)
                    })
                };
                let changed = offset_mm != self.tool_length_offset_mm;
                self.tool_length_offset_mm = offset_mm;
                if changed {
                    comes_to_rest!("when the tool length offset changes")
                } else {
                    ""
                }
            }
            (10, 0)
                if words
                    .get('L')
                    .is_some_and(|l| l.value == 2.0 || l.value == 20.0) =>
            {
                comes_to_rest!("before it writes coordinate data to its EEPROM")
            }
            (28 | 30, 1) => comes_to_rest!("before it writes the position to its EEPROM"),
            _ => "",
        };
        if !rest.is_empty() {
            effects.stop.get_or_insert(0.0);
        }
        rest
    }

    /// G94 after G93 leaves F undefined, as in Grbl (gcode.c: a feed move
    /// then needs a new F, error 22).
    fn leave_inverse_time(&mut self) {
        if std::mem::take(&mut self.inverse_time) {
            self.feed_mm_per_min = None;
        }
    }

    fn run_line(&mut self, line: u32, block: &Block, effects: &mut Effects) -> Result<(), Error> {
        effects.motion = None;
        effects.stop = None;
        effects.stop_after = false;
        effects.clears_offset = false;
        effects.ends_program = false;
        effects.warnings.clone_from(&block.ignored);
        if let Some(fault) = first_fault_on_its_own(line, block) {
            return Err(fault);
        }
        let mut motion: Option<(MotionCode, Code)> = None;
        let mut plane: Option<(Plane, Code)> = None;
        let mut inches: Option<(bool, Code)> = None;
        let mut incremental: Option<(bool, Code)> = None;
        let mut absolute_centers: Option<(bool, Code)> = None;
        let mut g92: Option<(bool, Code)> = None;
        let mut axis_code: Option<Code> = None;
        // G53: this line's axis words are machine coordinates.
        let mut machine_coordinates: Option<Code> = None;
        let mut dwell: Option<Code> = None;
        let mut inverse_time: Option<(bool, Code)> = None;
        let mut spindle: Option<(Spindle, Code)> = None;
        let mut coolant: Option<(u32, Code)> = None;
        let mut flow: Option<(u32, Code)> = None;
        let words = Words::new(&block.words);
        // What axis_code's warning adds when the motion comes to rest for it.
        let mut axis_code_rest = "";
        // At most one code of each group (first_fault_on_its_own), each set here.
        for code in &block.codes {
            if let Some(m) = (code.letter == 'G')
                .then(|| motion_code(code.number, code.minor))
                .flatten()
            {
                motion = Some((m, *code));
                continue;
            }
            match (code.letter, code.number, code.minor) {
                ('G', 17, 0) => plane = Some((Plane::Xy, *code)),
                ('G', 18, 0) => plane = Some((Plane::Zx, *code)),
                ('G', 19, 0) => plane = Some((Plane::Yz, *code)),
                ('G', 20, 0) => inches = Some((true, *code)),
                ('G', 21, 0) => inches = Some((false, *code)),
                ('G', 90, 0) => incremental = Some((false, *code)),
                ('G', 91, 0) => incremental = Some((true, *code)),
                ('G', 90, 1) => absolute_centers = Some((true, *code)),
                ('G', 91, 1) => absolute_centers = Some((false, *code)),
                // One of them a line: both are non-modal.
                ('G', 92, 0) => g92 = Some((true, *code)),
                ('G', 92, 1) => g92 = Some((false, *code)),
                ('G', 92, 2 | 3) => unreachable!("{} is refused by codes_fault", code.name()),
                ('G', 93, 0) => inverse_time = Some((true, *code)),
                ('G', 94, 0) => inverse_time = Some((false, *code)),
                // G4 (dwell) takes P, its seconds: its P is then not an unused word.
                ('G', 4, 0) => dwell = Some(*code),
                ('M', 3, 0) => spindle = Some((Spindle::Clockwise, *code)),
                ('M', 4, 0) => spindle = Some((Spindle::CounterClockwise, *code)),
                ('M', 5, 0) => spindle = Some((Spindle::Off, *code)),
                ('M', n @ 7..=9, 0) => coolant = Some((n, *code)),
                ('M', n @ (0 | 1 | 2 | 30), 0) => flow = Some((n, *code)),
                // Its group (non-modal) is checked by codes_fault, as G4's and G92's.
                ('G', 53, 0) => machine_coordinates = Some(*code),
                ('G', n, m) if axis_code.is_none() && !leaves_axis_words_to_motion(n, m) => {
                    // Said below, once the line's axis words are known.
                    axis_code = Some(*code);
                    axis_code_rest = self.rest_for_unmodelled(code, block, &words, effects);
                }
                (letter, _, _) => {
                    let what = match letter {
                        'G' => "voxpath does not model it",
                        _ => {
                            "voxpath models motion only, not spindle, coolant, tools or program flow"
                        }
                    };
                    let rest = self.rest_for_unmodelled(code, block, &words, effects);
                    effects.warnings.push(Problem {
                        column: code.column,
                        message: format!("{} ignored: {what}{rest}", code.name()),
                    });
                }
            }
        }
        self.run_machine_codes(&words, inverse_time, spindle, coolant, flow, effects);
        if let Some(code) = dwell {
            // mc_dwell: P seconds at rest, after the motion before has ended.
            let Some(p) = words.get('P') else {
                return Err(Error::at(
                    line,
                    code.column,
                    "G4 (dwell) needs P, the seconds to wait (Grbl refuses it without: error 28, a value word is missing)",
                ));
            };
            if p.value > MAX_DWELL_SECONDS {
                return Err(Error::at(
                    line,
                    p.column,
                    format!(
                        "P (the dwell's seconds) must be at most {MAX_DWELL_SECONDS:e} s, got {}",
                        p.value
                    ),
                ));
            }
            *effects.stop.get_or_insert(0.0) += p.value;
        }
        if let Some((v, _)) = plane {
            self.plane = v;
        }
        if let Some((v, _)) = inches {
            self.inches = v;
        }
        if let Some((v, _)) = incremental {
            self.incremental = v;
        }
        if let Some((v, _)) = absolute_centers {
            self.absolute_centers = v;
        }
        if self.inverse_time {
            // G93: F is this line's alone, per minute (gcode.c leaves a
            // G93 block's F at 0 without an F word, and converts none by
            // G20); what it asks in mm/min is the move's length times F.
            if let Some(f) = words
                .get('F')
                .filter(|f| f.value > MAX_INVERSE_TIME_PER_MIN)
            {
                return Err(Error::at(
                    line,
                    f.column,
                    format!(
                        "F (in inverse time, G93: moves a minute) must be at most {MAX_INVERSE_TIME_PER_MIN:e}, got {}",
                        f.value
                    ),
                ));
            }
            self.feed_mm_per_min = words.get('F').map(|f| f.value).filter(|&v| v > 0.0);
        } else if let Some(f) = words.get('F') {
            let feed = f.value * self.unit_mm();
            if feed > MAX_FEED_MM_PER_MIN {
                return Err(Error::at(
                    line,
                    f.column,
                    format!(
                        "F (feed) must be at most {MAX_FEED_MM_PER_MIN:e} mm/min, got {}{}",
                        f.value,
                        // In G20 the word is in inches: its value in mm too,
                        // the unit of the limit.
                        if self.inches {
                            format!(" in/min ({feed} mm/min)")
                        } else {
                            String::new()
                        }
                    ),
                ));
            }
            // F0 is Grbl's undefined feed (gcode.c refuses a feed move with
            // it, error 22, and nothing else: a G0 line may carry it).
            self.feed_mm_per_min = (feed > 0.0).then_some(feed);
        }
        let first_axis = words.first_of(&['X', 'Y', 'Z']);
        // A G92 of other axes alone (a slicer's G92 E0) says so once, below,
        // not once for G92 and once for each of its words.
        let g92_of_other_axes = matches!(g92, Some((true, _))) && first_axis.is_none();
        for w in &block.words {
            if g92_of_other_axes && is_other_axis(w.letter) {
                continue;
            }
            if !matches!(
                w.letter,
                'X' | 'Y' | 'Z' | 'I' | 'J' | 'K' | 'R' | 'P' | 'F' | 'S'
            ) {
                effects.warnings.push(Problem {
                    column: w.column,
                    message: format!(
                        "{}{} ignored: voxpath models X, Y and Z motion only",
                        w.letter, w.value
                    ),
                });
            }
        }
        let axes = words.axes();
        let arc_word = words.first_of(&['I', 'J', 'K', 'R']);
        // G92 and G92.1 change the work coordinate offset, for which Grbl
        // brings the motion to rest before the line's motion (gcode.c step
        // 19: system_flag_wco_change, which with
        // FORCE_BUFFER_SYNC_DURING_WCO_CHANGE, on by default in config.h,
        // calls protocol_buffer_synchronize), whether or not the offset
        // changes.
        if let Some((false, _)) = g92 {
            // G92.1; its line's axis words, if any, are a move in the
            // motion mode, as in Grbl (gcode.c: "If axis words are passed
            // here, they are interpreted as an implicit motion mode").
            effects.clears_offset = true;
            effects.stop.get_or_insert(0.0);
        }
        if let Some((true, code)) = g92 {
            if let Some((_, c)) = motion {
                return Err(Error::at(
                    line,
                    c.column,
                    format!(
                        "G92 and {} both take this line's axis words: put them on separate lines",
                        c.name()
                    ),
                ));
            }
            if first_axis.is_none() {
                // A 3D printer's `G92 E0` (in most slicers' programs) sets
                // an axis voxpath does not have, whose word is a warning
                // above, as E is on a move: the line sets nothing, and the
                // program goes on.
                let others: Vec<String> = block
                    .words
                    .iter()
                    .filter(|w| is_other_axis(w.letter))
                    .map(|w| format!("{}{}", w.letter, w.value))
                    .collect();
                if !others.is_empty() {
                    effects.warnings.push(Problem {
                        column: code.column,
                        message: format!(
                            "G92 {} ignored: voxpath models X, Y and Z motion only, so this G92 sets nothing",
                            others.join(" ")
                        ),
                    });
                    return Ok(());
                }
                return Err(Error::at(
                    line,
                    code.column,
                    "missing axis word: G92 sets the current position to X, Y and/or Z; give at least one",
                ));
            }
            effects.stop.get_or_insert(0.0);
            for (axis, w) in axes.iter().enumerate() {
                if let Some(w) = w {
                    self.offset_mm[axis] = self.position_mm[axis] - w.value * self.unit_mm();
                }
            }
            return Ok(());
        }
        match motion {
            Some((MotionCode::Move(m), _)) => {
                self.motion = Some(m);
                self.unmodelled_motion = None;
            }
            Some((MotionCode::Cancel, _)) => {
                self.motion = None;
                self.unmodelled_motion = None;
            }
            Some((MotionCode::Unmodelled, code)) => {
                self.motion = None;
                self.unmodelled_motion = Some((code, line));
                effects.warnings.push(Problem {
                    column: code.column,
                    message: format!(
                        "{} ignored: voxpath does not model it, so the axis words of this line and of the lines after it, until G0, G1, G2, G3 or G80, are not moves",
                        code.name()
                    ),
                });
            }
            None => {}
        }
        if let Some(code) = axis_code {
            if first_axis.is_some() {
                effects.warnings.push(Problem {
                    column: code.column,
                    message: format!(
                        "{} ignored: voxpath does not model it, so this line's axis words are not a move either{axis_code_rest}",
                        code.name()
                    ),
                });
                return Ok(());
            }
            effects.warnings.push(Problem {
                column: code.column,
                message: format!(
                    "{} ignored: voxpath does not model it{axis_code_rest}",
                    code.name()
                ),
            });
        }
        // G53, as Grbl runs it (gcode.c, NON_MODAL_ABSOLUTE_OVERRIDE): a G0
        // or G1 move to the axis words taken as machine coordinates, past
        // the G92 offset and the distance mode; with no axis word, nothing.
        // voxpath has no work coordinate systems (G54 is the only one, at
        // the machine's origin), so only the G92 offset is passed by.
        if let Some(code) = machine_coordinates {
            if !matches!(self.motion, Some(Motion::Rapid | Motion::Linear)) {
                let mode = match (self.motion, self.unmodelled_motion) {
                    (Some(m), _) => m.code().to_string(),
                    (None, Some((c, _))) => c.name(),
                    // G80 cancelled it.
                    (None, None) => "none (G80)".to_string(),
                };
                return Err(Error::at(
                    line,
                    code.column,
                    format!(
                        "G53 moves in machine coordinates by G0 or G1 only, as in Grbl (error 30), and the motion mode is {mode}: put G0 or G1 on this line"
                    ),
                ));
            }
        }
        if let Some((code, since)) = self.unmodelled_motion {
            if let Some(w) = first_axis.or(arc_word) {
                if motion.is_none() {
                    effects.warnings.push(Problem {
                        column: w.column,
                        message: format!(
                            "{} ignored: the motion mode is {} (line {since}), which voxpath does not model",
                            w.letter,
                            code.name()
                        ),
                    });
                }
                return Ok(());
            }
        }
        if first_axis.is_none() && arc_word.is_none() {
            // A motion code alone sets the mode; nothing moves. Grbl checks
            // a feed move's F first even so (gcode.c: a motion code on the
            // line makes it a motion command, and F undefined is error 22).
            if let Some((MotionCode::Move(mode), code)) = motion {
                if mode != Motion::Rapid && self.feed_mm_per_min.is_none() {
                    effects.warnings.push(Problem {
                        column: code.column,
                        message: format!(
                            "{} with no feed rate set (F, or F0{}) and no axis word: Grbl refuses the line (error 22, undefined feed rate); voxpath sets the motion mode, and nothing moves",
                            mode.code(),
                            if self.inverse_time { "; in G93 each feed line's own" } else { "" }
                        ),
                    });
                }
            }
            self.warn_unused_p(&words, dwell.is_some(), effects);
            return Ok(());
        }
        let Some(mode) = self.motion else {
            let w = first_axis.or(arc_word).expect("one of them is present");
            return Err(Error::at(
                line,
                w.column,
                format!(
                    "{} without a motion mode: put G0, G1, G2 or G3 on this line or an earlier one",
                    w.letter
                ),
            ));
        };
        let column = motion.map_or_else(
            || {
                first_axis
                    .or(arc_word)
                    .expect("one of them is present")
                    .column
            },
            |(_, c)| c.column,
        );
        let from_mm = self.position_mm;
        let mut to_mm = from_mm;
        for (axis, w) in axes.iter().enumerate() {
            if let Some(w) = w {
                let v = w.value * self.unit_mm();
                to_mm[axis] = if machine_coordinates.is_some() {
                    v
                } else if self.incremental {
                    from_mm[axis] + v
                } else {
                    v + self.offset_mm[axis]
                };
            }
        }
        let arc = match mode {
            Motion::Rapid | Motion::Linear => {
                if let Some(w) = arc_word {
                    return Err(Error::at(
                        line,
                        w.column,
                        format!(
                            "{} is an arc word (G2, G3), but this line's motion is {}",
                            w.letter,
                            mode.code()
                        ),
                    ));
                }
                self.warn_unused_p(&words, dwell.is_some(), effects);
                None
            }
            Motion::Arc(turn) => {
                if let Some(code) = dwell {
                    // One P cannot be both: LinuxCNC refuses the line
                    // (interp_check.cc: "G4 not allowed with G2 or G3
                    // because they both use P"). Grbl has no P on an arc.
                    return Err(Error::at(
                        line,
                        code.column,
                        format!(
                            "G4 (dwell) and {} (an arc) both take this line's P (seconds, turns): put the dwell on a line of its own",
                            mode.code()
                        ),
                    ));
                }
                Some(self.arc(line, column, turn, from_mm, to_mm, &words, effects)?)
            }
        };
        // On every such line, as Grbl would refuse each (the program's
        // warnings past the first thousand are counted, not listed).
        if mode != Motion::Rapid && self.feed_mm_per_min.is_none() {
            effects.warnings.push(Problem {
                column,
                message: if self.inverse_time {
                    format!(
                        "{} in inverse time (G93) with no F on its line (or F0): Grbl would refuse it (error 22, undefined feed rate: in G93 every feed move gives its own F); voxpath runs it, timed at the max rate",
                        mode.code()
                    )
                } else {
                    format!(
                        "{} with no feed rate set (F, or F0): Grbl would refuse it (error 22, undefined feed rate); voxpath runs it, timed at the max rate",
                        mode.code()
                    )
                },
            });
        }
        let feed = (mode != Motion::Rapid)
            .then_some(self.feed_mm_per_min)
            .flatten();
        self.position_mm = to_mm;
        effects.motion = Some(MoveMm {
            line,
            column,
            motion: mode,
            from_mm,
            to_mm,
            axis_columns: axes.map(|w| w.map_or(column, |w| w.column)),
            feed_mm_per_min: feed.filter(|_| !self.inverse_time),
            inverse_time_per_min: feed.filter(|_| self.inverse_time),
            arc,
        });
        Ok(())
    }

    /// The feed rate mode (G93, G94), and what voxpath does not model but
    /// times as Grbl does: the spindle and its speed (M3, M4, M5, S), the
    /// coolant (M7, M8, M9) and the program's flow (M0, M1, M2, M30). A
    /// change of the spindle, of its speed while it turns, or of the
    /// coolant brings the motion to rest before the line's motion; the
    /// same code again changes nothing and does not (gcode.c steps 4, 7
    /// and 8). A pause or the program's end brings it to rest after the
    /// line's motion (step 21), and the end turns the spindle and coolant
    /// off.
    fn run_machine_codes(
        &mut self,
        words: &Words<'_>,
        inverse_time: Option<(bool, Code)>,
        spindle: Option<(Spindle, Code)>,
        coolant: Option<(u32, Code)>,
        flow: Option<(u32, Code)>,
        effects: &mut Effects,
    ) {
        // Said in the order of the line's words, though S is judged first
        // (by the spindle before this line's M3, M4 or M5, as in Grbl).
        let mut said: Vec<Problem> = Vec::new();
        let mut say = |column: u32, message: String| said.push(Problem { column, message });
        match inverse_time {
            // Units per minute: the feed mode voxpath runs in.
            Some((false, _)) => self.leave_inverse_time(),
            // Inverse time: this line's F and every later G93 line's own
            // (run_line reads it); the G94 feed before is not carried in.
            Some((true, _)) => self.inverse_time = true,
            None => {}
        }
        let mut stops = false;
        if let Some(s) = words.get('S') {
            let turning = self.spindle != Spindle::Off;
            let changed = s.value != self.spindle_speed;
            self.spindle_speed = s.value;
            let why = if changed && turning {
                stops = true;
                "voxpath does not model the spindle, but a new speed while it turns brings the motion to rest here first, as Grbl's does (spindle_sync)"
            } else if changed {
                "voxpath does not model the spindle: kept for when it turns (the motion does not stop while it is off)"
            } else {
                "the spindle's speed already: no change, so the motion does not stop"
            };
            say(s.column, format!("S{}: {why}", s.value));
        }
        if let Some((state, code)) = spindle {
            let why = if state != self.spindle {
                stops = true;
                "voxpath does not model the spindle, but the motion comes to rest here first, as Grbl's does before a spindle change (spindle_sync)"
            } else {
                "the spindle is so already: no change, so the motion does not stop"
            };
            self.spindle = state;
            say(code.column, format!("{}: {why}", code.name()));
        }
        if let Some((n, code)) = coolant {
            let state = match n {
                7 => Coolant {
                    mist: true,
                    ..self.coolant
                },
                8 => Coolant {
                    flood: true,
                    ..self.coolant
                },
                _ => COOLANT_OFF,
            };
            let why = if state != self.coolant {
                stops = true;
                "voxpath does not model coolant, but the motion comes to rest here first, as Grbl's does before a coolant change (coolant_sync)"
            } else {
                "the coolant is so already: no change, so the motion does not stop"
            };
            self.coolant = state;
            say(code.column, format!("{}: {why}", code.name()));
        }
        if stops {
            effects.stop.get_or_insert(0.0);
        }
        if let Some((n, code)) = flow {
            // Each follows the code's name ("M1 ignored: ...", "M0: ...").
            let why = match n {
                1 => " ignored: an optional stop, which Grbl does not support",
                0 => {
                    ": the program pauses until it is resumed: after this line's motion, timed as a stop with no wait"
                }
                _ => {
                    ": the program ends: after this line's motion the machine comes to rest, the spindle and coolant are off and the modes go back to G1 G17 G90 G94, as in Grbl; the lines after it run as a new program"
                }
            };
            if n != 1 {
                effects.stop_after = true;
            }
            effects.ends_program = n == 2 || n == 30;
            say(code.column, format!("{}{why}", code.name()));
        }
        said.sort_by_key(|p| p.column);
        effects.warnings.append(&mut said);
    }

    fn warn_unused_p(&self, words: &Words<'_>, dwell: bool, effects: &mut Effects) {
        if let (Some(p), false) = (words.get('P'), dwell) {
            effects.warnings.push(Problem {
                column: p.column,
                message: format!(
                    "P{} ignored: P counts the turns of an arc (G2, G3)",
                    p.value
                ),
            });
        }
    }

    /// Center, radius and sweep of an arc from `from_mm` to `to_mm`.
    #[allow(clippy::too_many_arguments)]
    fn arc(
        &self,
        line: u32,
        column: u32,
        turn: Turn,
        from_mm: [f64; MACHINE_AXES],
        to_mm: [f64; MACHINE_AXES],
        words: &Words<'_>,
        effects: &mut Effects,
    ) -> Result<ArcMm, Error> {
        let plane = self.plane;
        let [u, v, n] = plane.axes();
        let unit = self.unit_mm();
        let units = self.unit_name();
        let radius_tolerance_mm = RADIUS_TOLERANCE_INCH * MM_PER_INCH;
        let spiral_tolerance_mm = if self.inches {
            SPIRAL_TOLERANCE_INCH * MM_PER_INCH
        } else {
            SPIRAL_TOLERANCE_MM
        };
        // Lengths in messages are in the program's units.
        let shown = |mm: f64| format!("{:.4} {units}", mm / unit);
        let center_words = words.center();
        let extra_turns = match words.get('P') {
            None => 0,
            Some(p) if p.written_whole && p.value >= 1.0 && p.value <= 1e6 => p.value as u32 - 1,
            Some(p) => {
                // A fraction past a double's digits reads as a whole number
                // it is not: "got 3" would quote no number on the line.
                let got = if p.written_whole || p.value.fract() != 0.0 {
                    p.value.to_string()
                } else {
                    format!(
                        "a fraction too fine for a double, which rounds it to {}",
                        p.value
                    )
                };
                return Err(Error::at(
                    line,
                    p.column,
                    format!("P (turns) must be a whole number from 1 to 1000000, got {got}"),
                ));
            }
        };
        if let Some(k) = center_words[n] {
            effects.warnings.push(Problem {
                column: k.column,
                message: format!(
                    "{} ignored: an arc in the {} takes its center from {} and {}",
                    k.letter,
                    plane.describe(),
                    ["I", "J", "K"][u],
                    ["I", "J", "K"][v]
                ),
            });
        }
        let (center_uv, format, center_source) = match (
            words.get('R'),
            center_words[u].or(center_words[v]),
        ) {
            (Some(r), Some(c)) => {
                let first = if r.column < c.column { r } else { c };
                return Err(Error::at(
                    line,
                    first.column,
                    "R and I/J/K both give the arc's center: use one",
                ));
            }
            (None, None) => {
                return Err(Error::at(
                    line,
                    column,
                    format!(
                        "missing center: an arc in the {} needs {} and/or {} (its center) or R (its radius)",
                        plane.describe(),
                        ["I", "J", "K"][u],
                        ["I", "J", "K"][v]
                    ),
                ));
            }
            (Some(r), None) => {
                if from_mm[u] == to_mm[u] && from_mm[v] == to_mm[v] {
                    return Err(Error::at(
                        line,
                        r.column,
                        format!(
                            "missing axis word: an R arc needs an end point other than its start on {} or {} (a full circle needs I/J/K)",
                            AXIS_NAMES[u].to_uppercase(),
                            AXIS_NAMES[v].to_uppercase()
                        ),
                    ));
                }
                let radius = r.value * unit;
                if radius.abs() < radius_tolerance_mm {
                    let message = if radius == 0.0 {
                        "zero-radius arc: R is 0".to_string()
                    } else {
                        // Not 0, but below the smallest radius an arc may have.
                        format!(
                            "zero-radius arc: |R| = {} is below the smallest radius, {} (LinuxCNC's, {RADIUS_TOLERANCE_INCH} in)",
                            shown(radius.abs()),
                            shown(radius_tolerance_mm)
                        )
                    };
                    return Err(Error::at(line, r.column, message));
                }
                let (du, dv) = (to_mm[u] - from_mm[u], to_mm[v] - from_mm[v]);
                let chord = du.hypot(dv);
                if chord / 2.0 - radius.abs() > radius_tolerance_mm {
                    return Err(Error::at(
                        line,
                        r.column,
                        format!(
                            "R arc cannot reach its end: the end is {} from the start, more than 2|R| = {}",
                            shown(chord),
                            shown(2.0 * radius.abs())
                        ),
                    ));
                }
                // The center is on the bisector, at h from the chord's middle;
                // (-dv, du) / chord points to the left of the chord.
                let half = (chord / 2.0).min(radius.abs());
                // h = sqrt(R² - half²), written so that it stays finite for
                // any finite R (R² overflows past 1e154).
                let h = radius.abs() * (1.0 - (half / radius).powi(2)).sqrt();
                let left = match (turn, radius > 0.0) {
                    (Turn::CounterClockwise, true) | (Turn::Clockwise, false) => 1.0,
                    _ => -1.0,
                };
                let (mu, mv) = ((from_mm[u] + to_mm[u]) / 2.0, (from_mm[v] + to_mm[v]) / 2.0);
                (
                    [mu - left * h * dv / chord, mv + left * h * du / chord],
                    ArcFormat::Radius,
                    [(r.letter, r.column); 2],
                )
            }
            (None, Some(first)) => {
                let axes = words.axes();
                if axes[u].is_none() && axes[v].is_none() {
                    // Kept, as LinuxCNC's convert_arc has no such check and
                    // full circles are written so there; but Grbl fails
                    // the line (gcode.c: "[No axis words]", "[No axis words
                    // in plane]").
                    effects.warnings.push(Problem {
                        column,
                        message: format!(
                            "{} with no {} or {} word: a full circle back to its start, as LinuxCNC runs it; Grbl refuses an arc with no axis word in its plane (error 26, or 32 when the line has another axis word): write the end, the start for a full circle",
                            Motion::Arc(turn).code(),
                            AXIS_NAMES[u].to_uppercase(),
                            AXIS_NAMES[v].to_uppercase(),
                        ),
                    });
                }
                let offset = |axis: usize| center_words[axis].map_or(0.0, |w| w.value * unit);
                let center = if self.absolute_centers {
                    // G90.1: I J K are program coordinates; an absent one is 0.
                    [offset(u) + self.offset_mm[u], offset(v) + self.offset_mm[v]]
                } else {
                    [from_mm[u] + offset(u), from_mm[v] + offset(v)]
                };
                let r1 = (from_mm[u] - center[0]).hypot(from_mm[v] - center[1]);
                let r2 = (to_mm[u] - center[0]).hypot(to_mm[v] - center[1]);
                if r1 < radius_tolerance_mm || r2 < radius_tolerance_mm {
                    let which = if r1 < radius_tolerance_mm {
                        "start"
                    } else {
                        "end"
                    };
                    return Err(Error::at(
                        line,
                        first.column,
                        format!("zero-radius arc: the center is at the arc's {which}"),
                    ));
                }
                let difference = (r1 - r2).abs();
                if difference > spiral_tolerance_mm
                    || difference / r1.max(r2) > SPIRAL_RELATIVE_TOLERANCE
                {
                    return Err(Error::at(
                        line,
                        first.column,
                        format!(
                            "the arc's end is {} from its center but its start is {}: the radii differ by {}, more than the tolerance ({} and 0.1% of the radius)",
                            shown(r2),
                            shown(r1),
                            shown(difference),
                            shown(spiral_tolerance_mm)
                        ),
                    ));
                }
                // An absent word is 0: the center coordinate then comes
                // from the start (G91.1) or the offset, so an error about it
                // names the first center word.
                let source = |axis: usize| {
                    center_words[axis]
                        .map_or((first.letter, first.column), |w| (w.letter, w.column))
                };
                (center, ArcFormat::Center, [source(u), source(v)])
            }
        };
        let (a, b) = (
            [from_mm[u] - center_uv[0], from_mm[v] - center_uv[1]],
            [to_mm[u] - center_uv[0], to_mm[v] - center_uv[1]],
        );
        let mut sweep = (a[0] * b[1] - a[1] * b[0]).atan2(a[0] * b[0] + a[1] * b[1]);
        match turn {
            Turn::CounterClockwise if sweep <= FULL_CIRCLE_EPSILON_RAD => sweep += TAU,
            Turn::Clockwise if sweep >= -FULL_CIRCLE_EPSILON_RAD => sweep -= TAU,
            _ => {}
        }
        sweep += turn.sign() as f64 * TAU * extra_turns as f64;
        let mut center_mm = from_mm;
        center_mm[u] = center_uv[0];
        center_mm[v] = center_uv[1];
        Ok(ArcMm {
            plane,
            turn,
            format,
            center_mm,
            radius_mm: a[0].hypot(a[1]),
            sweep_rad: sweep,
            extra_turns,
            center_words: center_source,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gcode::parse::parse_line;

    /// Runs lines from the start; the last line's effects.
    fn run(lines: &[&str]) -> Result<(Interpreter, Effects), Error> {
        let mut it = Interpreter::default();
        let mut last = Effects::default();
        for (i, text) in lines.iter().enumerate() {
            it.run(i as u32 + 1, &parse_line(text), &mut last)?;
        }
        Ok((it, last))
    }

    #[test]
    fn comes_to_rest_where_grbl_synchronises_for_offsets_and_its_eeprom() {
        // gcode.c steps 14, 15 and 19: system_flag_wco_change and
        // settings_write_coord_data synchronise Grbl's buffer (config.h:
        // FORCE_BUFFER_SYNC_DURING_WCO_CHANGE and _EEPROM_WRITE, both on).
        let stop = |lines: &[&str]| run(lines).unwrap().1.stop;
        let warned = |lines: &[&str]| {
            run(lines)
                .unwrap()
                .1
                .warnings
                .iter()
                .any(|w| w.message.contains("comes to rest here first"))
        };
        // G92 and G92.1, whether or not the offset changes.
        assert_eq!(stop(&["G1 X1 F100", "G92 X0"]), Some(0.0));
        assert_eq!(stop(&["G92 X0", "G92 X0"]), Some(0.0));
        assert_eq!(stop(&["G92.1"]), Some(0.0));
        assert_eq!(stop(&["G92.1 G1 X2 F100"]), Some(0.0));
        // A coordinate system: only a change (G54 is the one at the start
        // and after M2).
        assert_eq!(stop(&["G54"]), None);
        assert_eq!(stop(&["G55"]), Some(0.0));
        assert!(warned(&["G55"]));
        assert_eq!(stop(&["G55", "G55 G1 X1 F100"]), None);
        assert!(!warned(&["G55", "G55"]));
        assert_eq!(stop(&["G55", "G54"]), Some(0.0));
        assert_eq!(stop(&["G55", "M2", "G54"]), None);
        // Only G codes: M56 (Grbl's parking override), T55, M49 and M10 L2
        // are not G56, G55, G49 and G10 L2.
        assert_eq!(stop(&["M56"]), None);
        assert_eq!(stop(&["T55"]), None);
        assert_eq!(stop(&["M56", "G56"]), Some(0.0));
        assert_eq!(stop(&["G43.1 Z1", "M49"]), None);
        assert_eq!(stop(&["M10 L2"]), None);
        // LinuxCNC's G59.1, which Grbl refuses: no stop of Grbl's to say.
        assert_eq!(stop(&["G59.1"]), None);
        // The tool length offset: only a change, Z in the line's units.
        assert_eq!(stop(&["G43.1 Z1"]), Some(0.0));
        assert!(warned(&["G43.1 Z1"]));
        assert_eq!(stop(&["G43.1 Z1", "G43.1 Z1"]), None);
        assert_eq!(stop(&["G20 G43.1 Z1", "G21 G43.1 Z25.4"]), None);
        assert_eq!(stop(&["G43.1 Z1 G20", "G21 G43.1 Z25.4"]), None);
        assert_eq!(stop(&["G43.1 Z1", "G49"]), Some(0.0));
        assert_eq!(stop(&["G49"]), None);
        // Coordinate data written: always.
        assert_eq!(stop(&["G10 L20 P1 X0"]), Some(0.0));
        assert_eq!(stop(&["G10 L2 P1 X0"]), Some(0.0));
        assert_eq!(stop(&["G28.1"]), Some(0.0));
        assert_eq!(stop(&["G30.1"]), Some(0.0));
        assert!(warned(&["G30.1"]));
        // Nothing else.
        assert_eq!(stop(&["G1 X1 F100", "G1 X2"]), None);
        assert_eq!(stop(&["G61"]), None);
    }

    fn arc(lines: &[&str]) -> ArcMm {
        run(lines).unwrap().1.motion.unwrap().arc.unwrap()
    }

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() < 1e-9
    }

    /// G53 as Grbl 1.1 runs it (gcode.c, NON_MODAL_ABSOLUTE_OVERRIDE): a
    /// G0 or G1 move to machine coordinates, past the G92 offset and G91;
    /// in any other motion mode, error 30.
    #[test]
    fn g53_moves_in_machine_coordinates() {
        // The G92 offset makes program X0 machine X1: G53 X4 goes to
        // machine 4, where G0 X4 goes to 5.
        let (it, e) = run(&["G0 X1", "G92 X0", "G53 G0 X4 Y2"]).unwrap();
        assert!(e.motion.is_some() && e.warnings.is_empty());
        assert_eq!(it.position_mm, [4.0, 2.0, 0.0]);
        let (it, _) = run(&["G0 X1", "G92 X0", "G0 X4"]).unwrap();
        assert_eq!(it.position_mm, [5.0, 0.0, 0.0]);
        // Absolute in G91 too, in inches, in the modal G1, with axes not
        // named left where they are; the line's own mode comes back after.
        let (it, _) = run(&["G20 G91 G1 X1 Z1 F10", "G53 X2"]).unwrap();
        assert_eq!(it.position_mm, [50.8, 0.0, 25.4]);
        let (it, _) = run(&["G91 G1 X1 F10", "G53 X2", "X1"]).unwrap();
        assert_eq!(it.position_mm, [3.0, 0.0, 0.0]);
        // The motion mode a program starts in is G0, as in Grbl.
        assert_eq!(run(&["G53 X5"]).unwrap().0.position_mm, [5.0, 0.0, 0.0]);
        // No axis word: nothing moves.
        let (it, e) = run(&["G0 X1", "G53"]).unwrap();
        assert!(e.motion.is_none() && e.warnings.is_empty());
        assert_eq!(it.position_mm, [1.0, 0.0, 0.0]);
        // Error 30 outside G0 and G1, at G53; with G92 on its line, error 21.
        for (lines, column, mode) in [
            (&["G2 X1 Y1 I1", "G53 X5"][..], 1, "G2"),
            (&["G0 X0", "G81 X1 R1 Z0", "G53 X5"][..], 1, "G81"),
            (&["G0 X1", "G53 G3 X0 Y1 R1"][..], 1, "G3"),
            (&["G0 X1", "G80", "G53 X5"][..], 1, "none (G80)"),
        ] {
            let error = run(lines).unwrap_err();
            assert_eq!(
                error.to_string(),
                format!(
                    "line {}, column {column}: G53 moves in machine coordinates by G0 or G1 only, as in Grbl (error 30), and the motion mode is {mode}: put G0 or G1 on this line",
                    lines.len()
                ),
                "{lines:?}"
            );
        }
        assert!(
            run(&["G53 G92 X1"])
                .unwrap_err()
                .to_string()
                .contains("non-modal")
        );
    }

    #[test]
    fn absolute_incremental_inches_and_g92() {
        let (it, _) = run(&["G0 X10 Y5", "G91 G1 X1 Y1 F100", "X1"]).unwrap();
        assert_eq!(it.position_mm, [12.0, 6.0, 0.0]);
        // G92 X0: the machine's 12 mm now reads 0, so X5 is machine 17.
        let (it, e) = run(&["G0 X12", "G92 X0", "G0 X5"]).unwrap();
        assert_eq!(it.position_mm, [17.0, 0.0, 0.0]);
        assert_eq!(e.motion.unwrap().from_mm, [12.0, 0.0, 0.0]);
        let (it, e) = run(&["G20 G1 X1 F10"]).unwrap();
        assert!(close(it.position_mm[0], 25.4));
        assert_eq!(e.motion.unwrap().feed_mm_per_min, Some(254.0));
    }

    #[test]
    fn r_sign_picks_the_short_or_the_long_arc() {
        // (0,0) -> (8,0), |R| = 5: center 3 below or above the chord's
        // middle; the half chord 4 = 5 sin(53.13°), so the short arc sweeps
        // 106.26° and the long one the rest of the turn.
        let short = arc(&["G2 X8 Y0 R5"]);
        assert!(close(short.center_mm[0], 4.0) && close(short.center_mm[1], -3.0));
        assert!(close(
            short.sweep_rad.to_degrees(),
            -2.0 * 53.13010235415598
        ));
        let long = arc(&["G2 X8 Y0 R-5"]);
        assert!(close(long.center_mm[1], 3.0));
        assert!(close(
            long.sweep_rad.to_degrees(),
            -(360.0 - 2.0 * 53.13010235415598)
        ));
        // G3 mirrors G2: R > 0 puts the center to the left, above.
        assert!(close(arc(&["G3 X8 Y0 R5"]).center_mm[1], 3.0));
    }

    #[test]
    fn full_circles_turns_and_planes() {
        let a = arc(&["G0 X10", "G2 I-10"]);
        assert!(close(a.sweep_rad, -TAU) && close(a.radius_mm, 10.0));
        let a = arc(&["G0 X10", "G3 I-10 P3"]);
        assert!(close(a.sweep_rad, 3.0 * TAU) && a.extra_turns == 2);
        // G18 is (z, x): from X10 to Z10 clockwise is the quarter turn.
        let a = arc(&["G0 X10", "G18 G2 X0 Z10 I-10 K0"]);
        assert!(close(a.sweep_rad, -TAU / 4.0));
    }

    #[test]
    fn errors_name_line_and_column() {
        let e = |lines: &[&str]| run(lines).unwrap_err().to_string();
        assert_eq!(
            e(&["G1 X1", "G2 X10 Y0 R4"]),
            "line 2, column 11: R arc cannot reach its end: the end is 9.0000 mm from the start, more than 2|R| = 8.0000 mm"
        );
        assert_eq!(
            e(&["G2 X10 Y0 I3 J0"]),
            "line 1, column 11: the arc's end is 7.0000 mm from its center but its start is 3.0000 mm: the radii differ by 4.0000 mm, more than the tolerance (0.0283 mm and 0.1% of the radius)"
        );
        // One code of each modal group a line, as Grbl refuses more
        // (error 21): the feed rate mode, the spindle, the coolant and the
        // program's flow too (G93 G94 ran at a feed that hung on their order).
        for (line, message) in [
            (
                "G93 G94 G1 X1",
                "line 1, column 5: G93 and G94 are both feed rate mode codes: give one per line",
            ),
            (
                "M3 M5",
                "line 1, column 4: M3 and M5 are both spindle codes: give one per line",
            ),
            (
                "M7 M8",
                "line 1, column 4: M7 and M8 are both coolant codes: give one per line",
            ),
            (
                "M0 M30",
                "line 1, column 4: M0 and M30 are both program flow codes: give one per line",
            ),
            // The groups voxpath ignores are groups all the same (G54 G55
            // gave two warnings), and G4 and G92 share the non-modal one.
            (
                "G54 G55 G1 X1",
                "line 1, column 5: G54 and G55 are both coordinate system codes: give one per line",
            ),
            (
                "G43.1 Z1 G49",
                "line 1, column 10: G43.1 and G49 are both tool length offset codes: give one per line",
            ),
            (
                "G4 P1 G92 X0",
                "line 1, column 7: G4 and G92 are both non-modal codes: give one per line",
            ),
            (
                "G61 G64",
                "line 1, column 5: G61 and G64 are both path control codes: give one per line",
            ),
        ] {
            assert_eq!(e(&[line]), message);
        }
        assert_eq!(
            e(&["G2 X10 Y0 R0"]),
            "line 1, column 11: zero-radius arc: R is 0"
        );
        assert_eq!(
            e(&["G2 X10 Y0 R-0.001"]),
            "line 1, column 11: zero-radius arc: |R| = 0.0010 mm is below the smallest radius, 0.0013 mm (LinuxCNC's, 0.00005 in)"
        );
        assert_eq!(
            e(&["G2 X10 I0 J0"]),
            "line 1, column 8: zero-radius arc: the center is at the arc's start"
        );
        assert_eq!(
            e(&["G0 X1", "G92"]),
            "line 2, column 1: missing axis word: G92 sets the current position to X, Y and/or Z; give at least one"
        );
        // A slicer's G92 E0 sets an axis voxpath does not have: warnings,
        // no stop, and the program goes on (it stopped there, its message
        // silent about the E0).
        let (it, g92_e0) = run(&["G1 X1 F100", "G92 E0"]).unwrap();
        assert_eq!(
            messages(&g92_e0),
            [(
                1,
                "G92 E0 ignored: voxpath models X, Y and Z motion only, so this G92 sets nothing"
                    .to_string()
            )]
        );
        assert_eq!(g92_e0.stop, None);
        assert_eq!(
            messages(&run(&["G92 E0 A1"]).unwrap().1),
            [(
                1,
                "G92 E0 A1 ignored: voxpath models X, Y and Z motion only, so this G92 sets nothing".to_string()
            )]
        );
        // With an axis it models, the others are said as on any line.
        assert_eq!(
            messages(&run(&["G92 X0 E0"]).unwrap().1),
            [(
                8,
                "E0 ignored: voxpath models X, Y and Z motion only".to_string()
            )]
        );
        assert_eq!(it.position_mm, [1.0, 0.0, 0.0]);
        assert_eq!(
            e(&["G3 R5"]),
            "line 1, column 4: missing axis word: an R arc needs an end point other than its start on X or Y (a full circle needs I/J/K)"
        );
        assert_eq!(
            e(&["G0 G1 X1"]),
            "line 1, column 4: G0 and G1 are both motion codes: give one per line"
        );
        assert_eq!(
            e(&["G1 X1 I2"]),
            "line 1, column 7: I is an arc word (G2, G3), but this line's motion is G1"
        );
        assert_eq!(
            e(&["G2 X1"]),
            "line 1, column 1: missing center: an arc in the xy plane (G17), seen from +z needs I and/or J (its center) or R (its radius)"
        );
        // Inch programs are told in inches.
        assert!(
            e(&["G20 G2 X1 R0.4"])
                .ends_with("the end is 1.0000 in from the start, more than 2|R| = 0.8000 in")
        );
    }

    #[test]
    fn unmodelled_motion_modes_take_their_axis_words_until_another_motion_code() {
        // A canned cycle, a spline, threading and probing are motion modes
        // (group 1): their axis words, on their line and after it, are never
        // a G1 move, as they were when only the code was ignored.
        for code in ["G81", "G83", "G73", "G5", "G5.1", "G33", "G76", "G38.2"] {
            let line = format!("{code} X5 Y5 Z-1");
            let (it, e) = run(&["G1 X1 F100", &line, "X9"]).unwrap();
            assert!(e.motion.is_none(), "{code}: X9 moved");
            assert_eq!(it.position_mm, [1.0, 0.0, 0.0], "{code}");
            assert_eq!(
                e.warnings[0].message,
                format!(
                    "X ignored: the motion mode is {code} (line 2), which voxpath does not model"
                )
            );
            let (_, e) = run(&["G1 X1 F100", &line]).unwrap();
            assert!(e.motion.is_none(), "{code}: its own line moved");
            assert!(e.warnings[0].message.starts_with(&format!(
                "{code} ignored: voxpath does not model it, so the axis words"
            )));
        }
        // G0-G3 end the mode; G80 cancels it, and then axis words alone
        // have no motion mode at all.
        let (it, e) = run(&["G81 X5 Y5 Z-1 F100", "G1 X2"]).unwrap();
        assert_eq!(it.position_mm, [2.0, 0.0, 0.0]);
        assert!(e.motion.is_some());
        let e = run(&["G1 X1 F100", "G81 X5 Y5 Z-1", "G80", "X3"]).unwrap_err();
        assert_eq!(
            e.to_string(),
            "line 4, column 1: X without a motion mode: put G0, G1, G2 or G3 on this line or an earlier one"
        );
        // One motion code per line, modelled or not.
        let e = run(&["G1 G81 X1"]).unwrap_err();
        assert_eq!(
            e.to_string(),
            "line 1, column 4: G1 and G81 are both motion codes: give one per line"
        );
    }

    #[test]
    fn unmodelled_codes_and_words_are_warnings() {
        let (_, e) = run(&["G1 F100", "M3 S1000 G4 P2", "G28 X0"]).unwrap();
        let messages: Vec<String> = e.warnings.iter().map(|w| w.message.clone()).collect();
        assert_eq!(
            messages,
            [
                "G28 ignored: voxpath does not model it, so this line's axis words are not a move either"
            ]
        );
        assert!(run(&["G28 X0"]).unwrap().1.motion.is_none());
        let (_, e) = run(&["M3 S1000 G4 P2"]).unwrap();
        let messages: Vec<(u32, String)> = e
            .warnings
            .iter()
            .map(|w| (w.column, w.message.clone()))
            .collect();
        assert_eq!(
            messages,
            [
                (1, "M3: voxpath does not model the spindle, but the motion comes to rest here first, as Grbl's does before a spindle change (spindle_sync)".to_string()),
                (4, "S1000: voxpath does not model the spindle: kept for when it turns (the motion does not stop while it is off)".to_string()),
            ]
        );
        // The line stops the machine and dwells 2 s; a tool change or M1 is not a stop.
        assert_eq!(e.stop, Some(2.0));
        assert_eq!(run(&["M6 T1"]).unwrap().1.stop, None);
        assert_eq!(
            run(&["M1"]).unwrap().1.warnings[0].message,
            "M1 ignored: an optional stop, which Grbl does not support"
        );
        // Leaving G93 for G94 leaves F undefined, as in Grbl: the next feed
        // move is the no-feed warning (it ran at the F of the G93 lines).
        let (_, e) = run(&["G93 G1 X10 F2", "G94", "X30"]).unwrap();
        assert!(
            e.warnings[0]
                .message
                .starts_with("G1 with no feed rate set (F, or F0)"),
            "{:?}",
            e.warnings
        );
        let (_, e) = run(&["G93 G1 X10 F2", "G94 F600", "X30"]).unwrap();
        assert!(e.warnings.is_empty(), "{:?}", e.warnings);
        let (_, e) = run(&["G1 X1"]).unwrap();
        assert_eq!(
            e.warnings[0].message,
            "G1 with no feed rate set (F, or F0): Grbl would refuse it (error 22, undefined feed rate); voxpath runs it, timed at the max rate"
        );
        // Each feed move before any F, on its line; none once F is set.
        let (_, e) = run(&["G1 X1", "G2 X3 Y0 R1"]).unwrap();
        assert!(
            e.warnings[0]
                .message
                .starts_with("G2 with no feed rate set (F, or F0)")
        );
        let (_, e) = run(&["G1 X1", "G1 X4 F100", "G1 X5"]).unwrap();
        assert!(e.warnings.is_empty(), "{:?}", e.warnings);
    }

    fn messages(e: &Effects) -> Vec<(u32, String)> {
        e.warnings
            .iter()
            .map(|w| (w.column, w.message.clone()))
            .collect()
    }

    #[test]
    fn axis_words_of_a_code_that_takes_them_otherwise_are_not_a_move() {
        // G43.1 and G49 are axis commands in Grbl (gcode.c: axis_command =
        // AXIS_COMMAND_TOOL_LENGTH_OFFSET): the Z is the tool length offset.
        // Only codes with no minor were matched, so G43.1 Z-2.5 moved Z.
        for line in ["G43.1 Z-2.5", "G49 Z5", "G43 Z1", "G10 L20 P1 X0"] {
            let (it, e) = run(&["G0 X1", line]).unwrap();
            assert!(e.motion.is_none(), "{line} moved");
            assert_eq!(it.position_mm, [1.0, 0.0, 0.0], "{line}");
            let code = line.split(' ').next().unwrap();
            // G43.1 Z-2.5 changes the tool length offset and G10 L20
            // writes coordinate data: the motion comes to rest for them.
            let rest = match code {
                "G43.1" => {
                    "; the motion comes to rest here first, as Grbl's does when the tool length offset changes"
                }
                "G10" => {
                    "; the motion comes to rest here first, as Grbl's does before it writes coordinate data to its EEPROM"
                }
                _ => "",
            };
            assert_eq!(
                messages(&e).last().unwrap().1,
                format!(
                    "{code} ignored: voxpath does not model it, so this line's axis words are not a move either{rest}"
                ),
                "{line}"
            );
        }
        // A code voxpath does not know might take them too.
        assert!(run(&["G2147483649 X10"]).unwrap().1.motion.is_none());
        // Modal settings that take no axis words leave them to the motion
        // mode, as Grbl does (its implicit axis command), and so do G28.1
        // and G30.1 (gcode.c: "interpreted as an implicit motion mode").
        for line in ["G54 X5", "G40 G0 X5", "G61 X5", "G28.1 X5", "G64 X5"] {
            let (it, e) = run(&["G0 X1", line]).unwrap();
            assert!(e.motion.is_some(), "{line} did not move");
            assert_eq!(it.position_mm, [5.0, 0.0, 0.0], "{line}");
        }
    }

    #[test]
    fn the_first_axis_words_run_in_g0_as_grbl_starts_in_it() {
        // gcode.h: MOTION_MODE_SEEK 0, and gc_init memsets gc_state to 0.
        // `X10` alone was "X without a motion mode".
        let (it, e) = run(&["X10"]).unwrap();
        assert_eq!(e.motion.unwrap().motion, Motion::Rapid);
        assert_eq!(it.position_mm, [10.0, 0.0, 0.0]);
        // After G80 there is no motion mode: an error, as Grbl's error 31.
        assert_eq!(
            run(&["G80", "X3"]).unwrap_err().to_string(),
            "line 2, column 1: X without a motion mode: put G0, G1, G2 or G3 on this line or an earlier one"
        );
    }

    #[test]
    fn a_dwell_and_an_arc_cannot_share_a_line_s_p() {
        // One P served as 2 s of dwell and as 2 turns (720°). LinuxCNC's
        // interp_check.cc: "G4 not allowed with G2 or G3 because they both
        // use P".
        let message = "G4 (dwell) and G2 (an arc) both take this line's P (seconds, turns): put the dwell on a line of its own";
        assert_eq!(
            run(&["G0 X10", "G4 P2 G2 I-10 F100"])
                .unwrap_err()
                .to_string(),
            format!("line 2, column 1: {message}")
        );
        // The arc's mode from an earlier line is the same P.
        assert_eq!(
            run(&["G2 X0 Y10 I0 J5 F100", "X0 Y0 I0 J-5 G4 P1"])
                .unwrap_err()
                .to_string(),
            format!("line 2, column 14: {message}")
        );
        // A dwell on a line with a straight move or no move is fine.
        assert_eq!(run(&["G4 P2 G1 X1 F100"]).unwrap().1.stop, Some(2.0));
        // A dwell past MAX_DWELL_SECONDS is refused at its P (one of 10^20 s
        // left every later move's steps at one instant); the largest is not.
        assert_eq!(
            run(&["G4 P1000000.1"]).unwrap_err().to_string(),
            "line 1, column 4: P (the dwell's seconds) must be at most 1e6 s, got 1000000.1"
        );
        assert_eq!(run(&["G4 P1000000"]).unwrap().1.stop, Some(1e6));
    }

    #[test]
    fn program_end_resets_the_modes_grbl_resets_and_the_lines_after_it_run() {
        // gcode.c, PROGRAM_FLOW_COMPLETED: motion G1, plane G17, G90, G94,
        // spindle and coolant off; units, F, S and coord_offset (G92) stay.
        // M2 and M30 changed none of the modes.
        let (it, e) = run(&[
            "G20 G91 G19 G0 X1",
            "G92 X0",
            "G1 X0 F10 M3 M8",
            "M30",
            "X2 Y0",
        ])
        .unwrap();
        let m = e.motion.unwrap();
        // G1 at F10 in/min, G90 through the G92 offset (1 in), in inches.
        assert_eq!(m.motion, Motion::Linear);
        assert!(close(m.feed_mm_per_min.unwrap(), 254.0));
        assert!(close(it.position_mm[0], 3.0 * 25.4));
        assert!(e.warnings.is_empty(), "{:?}", e.warnings);
        assert_eq!(it.plane, Plane::Xy);
        assert_eq!((it.spindle, it.coolant), (Spindle::Off, COOLANT_OFF));
        // An arc after M2 is in G17 again.
        let a = arc(&["G18", "M2", "G2 X10 Y0 I5"]);
        assert_eq!(a.plane, Plane::Xy);
        // G93 ends with it, and F stays: Grbl carries the last F into a
        // G94 line when the state before it is G94, as the reset leaves it
        // (gcode.c: "Last state is also G94"), so X2 runs at F2 mm/min...
        let (_, e) = run(&["G93 G1 X1 F2 M2", "X2"]).unwrap();
        assert!(e.warnings.is_empty(), "{:?}", e.warnings);
        assert!(close(e.motion.unwrap().feed_mm_per_min.unwrap(), 2.0));
        // ...where M2 shares F's line: an M2 line of its own is a G93 block
        // without F, which leaves F at 0 (undefined) before the reset.
        let (_, e) = run(&["G93 G1 X1 F2", "M2", "X2"]).unwrap();
        assert!(messages(&e)[0].1.starts_with("G1 with no feed rate set"));
        // A G94 word after G93 is what leaves F unset.
        let (_, e) = run(&["G93 G1 X1 F2", "G94 X2"]).unwrap();
        assert!(messages(&e)[0].1.starts_with("G1 with no feed rate set"));
    }

    #[test]
    fn inverse_time_takes_each_line_s_own_f_as_moves_a_minute() {
        // G93 F is the line's alone, per minute, not converted by G20
        // (gcode.c step 3: a G93 block's F is 0 without an F word, and only
        // G94 multiplies F by MM_PER_INCH); the planner makes it mm/min.
        let (_, e) = run(&["G20", "G93 G1 X1 F2"]).unwrap();
        let m = e.motion.unwrap();
        assert_eq!(
            (m.feed_mm_per_min, m.inverse_time_per_min),
            (None, Some(2.0))
        );
        assert!(e.warnings.is_empty(), "{:?}", e.warnings);
        // The next feed move without F: Grbl's error 22, said as G93's.
        let (_, e) = run(&["G93 G1 X1 F2", "X2"]).unwrap();
        assert_eq!(
            messages(&e),
            [(1, "G1 in inverse time (G93) with no F on its line (or F0): Grbl would refuse it (error 22, undefined feed rate: in G93 every feed move gives its own F); voxpath runs it, timed at the max rate".to_string())]
        );
        assert_eq!(e.motion.unwrap().inverse_time_per_min, None);
        // A motion code alone: no move, but Grbl's error 22 all the same.
        let (_, e) = run(&["G1"]).unwrap();
        assert_eq!(
            messages(&e),
            [(1, "G1 with no feed rate set (F, or F0) and no axis word: Grbl refuses the line (error 22, undefined feed rate); voxpath sets the motion mode, and nothing moves".to_string())]
        );
        assert!(run(&["G93 G1 F2"]).unwrap().1.warnings.is_empty());
        assert!(run(&["G0"]).unwrap().1.warnings.is_empty());
        let (_, e) = run(&["G93", "G2"]).unwrap();
        assert!(messages(&e)[0].1.starts_with(
            "G2 with no feed rate set (F, or F0; in G93 each feed line's own) and no axis word"
        ));
        // The G94 feed before is not carried into G93.
        let (_, e) = run(&["G1 X1 F100", "G93 G1 X2"]).unwrap();
        assert!(
            messages(&e)[0]
                .1
                .starts_with("G1 in inverse time (G93) with no F")
        );
        // A rapid needs none, and carries none.
        let (_, e) = run(&["G93 G0 X2 F5"]).unwrap();
        assert!(e.warnings.is_empty(), "{:?}", e.warnings);
        assert_eq!(e.motion.unwrap().inverse_time_per_min, None);
        // F's bound, said in G93's unit.
        let err = run(&["G93 G1 X1 F2000000000"]).unwrap_err();
        assert_eq!(
            err.to_string(),
            "line 1, column 11: F (in inverse time, G93: moves a minute) must be at most 1e9, got 2000000000"
        );
    }

    #[test]
    fn g92_1_clears_the_g92_offset_and_g92_2_and_g92_3_are_refused() {
        // Grbl 1.1 clears coord_offset on G92.1 (gcode.c,
        // NON_MODAL_RESET_COORDINATE_OFFSET: clear_vector); it was ignored
        // with a warning, so X5 below went to machine 15.
        let (it, _) = run(&["G0 X10", "G92 X0", "G92.1", "G0 X5"]).unwrap();
        assert_eq!(it.position_mm, [5.0, 0.0, 0.0]);
        // Its axis words are a move, through the offset before the line
        // (Grbl computes the target first, then clears the offset).
        let (it, e) = run(&["G0 X10", "G92 X0", "G92.1 X5"]).unwrap();
        assert_eq!(e.motion.unwrap().to_mm, [15.0, 0.0, 0.0]);
        assert_eq!(it.offset_mm, [0.0; MACHINE_AXES]);
        // Grbl fails G92.2 and G92.3 (error 20: only mantissa 0 or 10).
        assert_eq!(
            run(&["G0 X1", "G92.2"]).unwrap_err().to_string(),
            "line 2, column 1: G92.2 is not supported, as in Grbl (error 20, unsupported command): the positions of the lines after it would be unknown; use G92.1 to clear the G92 offset, G92 to set one"
        );
        assert!(run(&["G92.3"]).is_err());
        assert_eq!(
            run(&["G92 X0 G92.1"]).unwrap_err().to_string(),
            "line 1, column 8: G92 and G92.1 are both non-modal codes: give one per line"
        );
    }

    #[test]
    fn value_words_as_grbl_checks_them() {
        // gcode.c step 2: F, N, P, T and S cannot be negative (error 4).
        // S-100 was kept as a spindle speed.
        for (line, column, word) in [
            ("M3 S-100", 4, "S-100: S"),
            ("G1 X1 F-5", 7, "F-5: F"),
            ("G4 P-1", 4, "P-1: P"),
        ] {
            assert_eq!(
                run(&[line]).unwrap_err().to_string(),
                format!(
                    "line 1, column {column}: {word} cannot be negative (Grbl refuses it: error 4, negative value)"
                )
            );
        }
        // F0 is Grbl's undefined feed: a G0 line takes it (it was an error
        // at F), and a feed move after it has no feed (error 22 in Grbl,
        // gcode.c "[Feed rate undefined]").
        let (_, e) = run(&["G0 X1 F0"]).unwrap();
        assert!(e.warnings.is_empty(), "{:?}", e.warnings);
        let (_, e) = run(&["G1 X1 F100", "G0 X2 F0", "G1 X3"]).unwrap();
        assert!(messages(&e)[0].1.starts_with("G1 with no feed rate set"));
        // An arc with no axis word in its plane: kept as LinuxCNC's full
        // circle, with a warning that Grbl refuses it (gcode.c: "[No axis
        // words]", error 26; "[No axis words in plane]", error 32).
        let (_, e) = run(&["G0 X10", "G2 I-10 F100"]).unwrap();
        assert_eq!(
            messages(&e),
            [(
                1,
                "G2 with no X or Y word: a full circle back to its start, as LinuxCNC runs it; Grbl refuses an arc with no axis word in its plane (error 26, or 32 when the line has another axis word): write the end, the start for a full circle".to_string()
            )]
        );
        let (_, e) = run(&["G0 X10", "G2 X10 I-10 F100"]).unwrap();
        assert!(e.warnings.is_empty(), "{:?}", e.warnings);
    }
}
