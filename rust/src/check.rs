//! Checking a learner's own implementation: given a trace request and the
//! points a student's program printed, replay the rule, find the first
//! point where the two part, say why the rule went where it went (the
//! trace's own explanation and decision values of that step, as
//! [`crate::compare`] reports them), and name every catalogue rule and
//! option set the points do follow ("your path is bresenham3d with tie =
//! hold").
//!
//! Index spaces are the trace's: point index k (0..=steps) is the position
//! after k steps; the step that produced point k is step index k - 1.
//!
//! Points arrive as text (one point per line, comma- or blank-separated,
//! with an optional header; or the list a program printed, one point per
//! innermost bracket: `[(0, 0, 0), (1, 1, 1)]`) or as a flat array. Input
//! that is not a path is an error naming the point: a wrong number of
//! coordinates, a non-integer, a jump of more than one cell per axis.

use crate::algorithms::{self, AlgorithmInfo, Family};
use crate::compare::{StepWhy, as_object, why_at_point};
use crate::error::{Error, counted, number_text};
use crate::grid::{AXIS_NAMES, Point, Step, jumps};
use crate::line::GCD;
use crate::line::bresenham3d;
use crate::line::liu_float::{self, DECIMALS};
use crate::range::IntegerRange;
use crate::request::tie_option;
use crate::request::{FROM, MAX_STEPS, OptionKind, OptionSpec, Request, TO};
use crate::text::{echo, split_line, writes_whole_number};
use crate::trace::Trace;
use serde::Serialize;
use serde_json::{Map, Value};
use std::borrow::Borrow;
use std::sync::Arc;
use tsify::Tsify;

/// Points shown on each side of the first difference.
pub const AROUND: u64 = 3;

/// An integer option with a declared range of at most this many values has
/// every value tried for `alsoMatches` (`decimals` 0 to 10 is 11 values;
/// `maxSteps` 0 to 10^9 is not tried).
pub const SMALL_RANGE: i64 = 16;

/// Largest coordinate magnitude read: every integer up to it is exact in f64.
const EXACT_LIMIT: f64 = 9_007_199_254_740_992.0;

/// A learner's points: `dims` coordinates per point, flat.
#[derive(Clone, Debug, PartialEq)]
pub struct Points {
    pub dims: usize,
    pub coords: Vec<i64>,
}

/// Points read from text, and their steps when asked for.
type PointsRead = (Points, Option<Arc<[Step]>>);

impl Points {
    pub fn len(&self) -> u64 {
        (self.coords.len() / self.dims) as u64
    }

    pub fn is_empty(&self) -> bool {
        self.coords.is_empty()
    }

    /// Point index k.
    pub fn get(&self, k: u64) -> &[i64] {
        let at = k as usize * self.dims;
        &self.coords[at..at + self.dims]
    }

    /// Points from a flat array of `dims` values per point (a JS array of
    /// `[x, y, z]` rows or a Float64Array as f64, an Int32Array as i32:
    /// [`FlatValue`]), checked as [`Self::from_text`] checks text; errors
    /// name the field `points` and the point index.
    pub fn from_flat<V: FlatValue>(
        values: &[V],
        dims: usize,
        move_dims: usize,
    ) -> Result<Points, Error> {
        let wrong = |message: String| Error::field("points", message);
        // An empty list has no coordinates to count ("the points have 0
        // coordinates each" said it as a mismatch).
        if values.is_empty() {
            return Err(wrong("there are no points".into()));
        }
        if dims != move_dims {
            return Err(wrong(format!(
                "the points have {} each; the move has {move_dims}",
                counted(dims as u64, "coordinate")
            )));
        }
        if values.len() % dims != 0 {
            return Err(wrong(format!(
                "{} values are not a whole number of {dims}-coordinate points",
                values.len()
            )));
        }
        let mut coords = Vec::with_capacity(values.len());
        for (i, &v) in values.iter().enumerate() {
            coords.push(v.coordinate(i / dims, i % dims).map_err(wrong)?);
        }
        let points = Points { dims, coords };
        points.check_path().map_err(|(_, message)| wrong(message))?;
        Ok(points)
    }

    /// Points from text: one point per line, its coordinates separated by
    /// commas or blanks, an optional header first (its x, y, z, ... columns
    /// are read, so voxpath's own CSV checks too), `#` comment lines; or,
    /// when the text has brackets, one point per innermost `[...]` or
    /// `(...)`, as programs print lists. Errors give the line and column,
    /// and name the point index.
    pub fn from_text(text: &str, dims: usize) -> Result<Points, Error> {
        Self::read_text(text, dims, false).map(|(points, _)| points)
    }

    /// [`Self::from_text`], and when `with_steps`, the points' steps
    /// ([`Self::steps`]) made as the rows are read, not in a second pass.
    fn read_text(text: &str, dims: usize, with_steps: bool) -> Result<PointsRead, Error> {
        let mut reading = TextReading::new(dims, with_steps);
        reading.advance(text, u64::MAX)?;
        reading.finish()
    }

    /// The step from each point to the next (a path: see [`Self::check_path`]).
    pub fn steps(&self) -> Arc<[Step]> {
        (1..self.len())
            .map(|k| Step::between(self.get(k - 1), self.get(k)))
            .collect()
    }

    /// Every point one cell or less from the one before it on each axis,
    /// and at least one point; else the point index at fault and why.
    fn check_path(&self) -> Result<(), (usize, String)> {
        if self.is_empty() {
            return Err((0, "there are no points".to_string()));
        }
        match (1..self.len()).find(|&k| jumps(self.get(k - 1), self.get(k))) {
            Some(k) => Err((k as usize, self.jump(k))),
            None => Ok(()),
        }
    }

    /// Why point k, more than one cell from point k - 1, is not a path.
    fn jump(&self, k: u64) -> String {
        format!(
            "point {k} {} is more than one cell from point {} {}: a path moves each axis at most one cell per step",
            Point::new(self.get(k)),
            k - 1,
            Point::new(self.get(k - 1))
        )
    }
}

/// A value of a flat array of points ([`Points::from_flat`]), as the
/// array holds it: f64 (a JS number), which must be a whole number read
/// exactly, or i32 (an Int32Array's, a trace's points as they cross to
/// JavaScript), every one a coordinate as it is. An Int32Array was widened
/// to f64 first: a second copy of the points, twice their bytes (36 MB at
/// the page's cap of 1,500,000 points of 3 axes).
pub trait FlatValue: Copy {
    /// This value as the coordinate of point `index` on `axis`, or why it
    /// is not one.
    fn coordinate(self, index: usize, axis: usize) -> Result<i64, String>;
}

impl FlatValue for f64 {
    fn coordinate(self, index: usize, axis: usize) -> Result<i64, String> {
        coordinate(self, index, axis)
    }
}

impl FlatValue for i32 {
    fn coordinate(self, _index: usize, _axis: usize) -> Result<i64, String> {
        Ok(self.into())
    }
}

/// A coordinate read from input: a whole number, exactly representable.
fn coordinate(value: f64, index: usize, axis: usize) -> Result<i64, String> {
    let name = AXIS_NAMES[axis];
    if !value.is_finite() {
        return Err(format!("point {index}: {name} is not a number"));
    }
    if value.fract() != 0.0 {
        return Err(format!(
            "point {index}: {name} = {} is not a whole number",
            number_text(value)
        ));
    }
    if value.abs() > EXACT_LIMIT {
        return Err(format!(
            "point {index}: {name} = {} is too large",
            number_text(value)
        ));
    }
    Ok(value as i64)
}

/// Text read into points a slice at a time ([`Self::advance`]), to the
/// points and the errors of one reading ([`Points::from_text`], which is
/// this run to its end): a check reads the 1,500,000 points of the page's
/// cap (19 MB of text, 60 ms natively, 0.1 to 0.2 s in wasm) in slices a
/// worker can report and stop between. The text is given to each call
/// (its owner keeps it), the same text every time.
pub struct TextReading {
    reader: TextReader,
    /// Where the reading stands: by lines until a line shows a bracket
    /// (then the text is read again as a printed list, from its start).
    rows: RowsRead,
    /// Bytes of the text read so far.
    bytes_read: usize,
}

/// How far [`TextReading`] has got.
enum RowsRead {
    Lines(LineRows),
    Brackets(BracketRows),
    Done,
}

impl TextReading {
    pub fn new(dims: usize, with_steps: bool) -> TextReading {
        TextReading {
            reader: TextReader::new(dims, with_steps),
            rows: RowsRead::Lines(LineRows::default()),
            bytes_read: 0,
        }
    }

    /// Reads about `units` more rows of `text` (lines, or for a printed
    /// list 16 bytes a unit), at least one; true once the whole text is
    /// read. An error is the reading's ([`Points::from_text`]).
    pub fn advance(&mut self, text: &str, units: u64) -> Result<bool, Error> {
        let text = crate::text::without_byte_order_mark(text);
        let mut budget = units.max(1);
        loop {
            match &mut self.rows {
                RowsRead::Lines(state) => {
                    // Text with a bracket anywhere is a printed list. Plain
                    // rows have none, so the rows are read until a line with
                    // one shows (then the list is read from the start), and
                    // an error before it stands only if no bracket follows:
                    // the text is read once, not searched first.
                    let read = self.reader.line_rows(text, state, &mut budget);
                    self.bytes_read = state.at;
                    match read {
                        Ok(None) => return Ok(false),
                        Ok(Some(Rows::Read)) => self.rows = RowsRead::Done,
                        Ok(Some(Rows::Listed)) => self.read_as_list(),
                        Err(_) if has_bracket(text) => self.read_as_list(),
                        Err(e) => return Err(e),
                    }
                }
                RowsRead::Brackets(state) => {
                    let done = self.reader.bracket_rows(text, state, &mut budget)?;
                    self.bytes_read = state.at;
                    if !done {
                        return Ok(false);
                    }
                    self.rows = RowsRead::Done;
                }
                RowsRead::Done => return Ok(true),
            }
        }
    }

    /// Starts the reading again, of the text as a printed list.
    fn read_as_list(&mut self) {
        self.reader = TextReader::new(self.reader.dims, self.reader.steps.is_some());
        self.rows = RowsRead::Brackets(BracketRows::default());
        self.bytes_read = 0;
    }

    /// Bytes of the text read so far (after a byte order mark).
    pub fn bytes_read(&self) -> u64 {
        self.bytes_read as u64
    }

    /// Points read so far.
    pub fn points_read(&self) -> u64 {
        self.reader.points
    }

    /// The points, and their steps when asked for, once [`Self::advance`]
    /// is done: the errors found at the end (no points, a point more than
    /// one cell from the one before).
    fn finish(self) -> Result<PointsRead, Error> {
        debug_assert!(matches!(self.rows, RowsRead::Done));
        let reader = self.reader;
        if reader.points == 0 {
            return Err(Error::at(1, 1, "there are no points"));
        }
        let points = Points {
            dims: reader.dims,
            coords: reader.coords,
        };
        match reader.first_jump {
            Some((index, line, column)) => Err(Error::at(line, column, points.jump(index))),
            None => Ok((points, reader.steps.map(Arc::from))),
        }
    }
}

/// Where a reading by lines ([`TextReader::line_rows`]) stands.
struct LineRows {
    /// The next line's byte offset and 1-based number.
    at: usize,
    line_number: u32,
    /// No row read yet: the next may be a header.
    first: bool,
    /// The columns a header named.
    pick: Option<Vec<usize>>,
}

impl Default for LineRows {
    fn default() -> LineRows {
        LineRows {
            at: 0,
            line_number: 0,
            first: true,
            pick: None,
        }
    }
}

/// Where a reading of a printed list ([`TextReader::bracket_rows`]) stands.
struct BracketRows {
    /// The next character's byte offset.
    at: usize,
    /// The line it is on and its column there (1-based; a column is a
    /// character, as in G-code, not a byte).
    line: u32,
    column: u32,
    /// The bracket open: where its row starts, its line and column.
    open: Option<(usize, u32, u32)>,
    /// Whether the line so far is blank, and whether it is a comment
    /// (`#` its first character past blanks), whose brackets are its
    /// words, not points, as in a reading by lines.
    blank: bool,
    comment: bool,
}

impl Default for BracketRows {
    fn default() -> BracketRows {
        BracketRows {
            at: 0,
            line: 1,
            column: 1,
            open: None,
            blank: true,
            comment: false,
        }
    }
}

/// Reads text into points in one pass, a row at a time, with no
/// allocation per row (a million-point file is read at the speed of its
/// bytes).
struct TextReader {
    dims: usize,
    coords: Vec<i64>,
    /// Points read so far.
    points: u64,
    /// The first point more than one cell from the one before it: its
    /// index, and the line and 1-based column where its row starts. It is
    /// reported once the whole text has been read, so that a row that is
    /// not a point is named first, wherever it is.
    first_jump: Option<(u64, u32, u32)>,
    /// The step to each point from the one before, when asked for (and
    /// only up to the first jump, after which there is no path).
    steps: Option<Vec<Step>>,
}

/// What reading text as one point per line found.
#[derive(PartialEq)]
enum Rows {
    /// Every line was read.
    Read,
    /// A line has a bracket: the text is a printed list.
    Listed,
}

/// Most digits of a coordinate [`TextReader::plain_row`] reads: every
/// 15-digit number is below 2^53, exact in f64 and far from i64's limits.
const PLAIN_DIGITS: usize = 15;

/// Most cells of a row [`TextReader::plain_row`] reads (voxpath's own CSV
/// has k, x, y, z and the M column).
const PLAIN_CELLS: usize = 8;

/// 10^0 to 10^8.
const POWERS_OF_TEN: [i64; 9] = [
    1,
    10,
    100,
    1_000,
    10_000,
    100_000,
    1_000_000,
    10_000_000,
    100_000_000,
];

/// The ASCII digits that start `word` (eight bytes of text, the first in
/// the lowest byte): how many (0 to 8), and the number they write. A loop
/// over the bytes would take a multiply and an add per digit, one after
/// the other; this takes a dozen operations on the whole word ("SWAR").
#[inline(always)]
fn leading_digits(word: u64) -> (usize, i64) {
    const ONES: u64 = 0x0101_0101_0101_0101;
    // Each byte minus '0' is below 10 for a digit. A byte below '0' wraps
    // to 0x80 or more (it may borrow from the bytes above it, which are
    // past the first non-digit and not looked at); a byte above '9' is 10
    // or more, and 10 + 0x76 sets the top bit. Digits carry nothing.
    let less = word.wrapping_sub(ONES * b'0' as u64);
    let not_digit = (less | less.wrapping_add(ONES * 0x76)) & (ONES * 0x80);
    let count = (not_digit.trailing_zeros() / 8) as usize;
    if count == 0 {
        return (0, 0);
    }
    // The digits moved to the top bytes, zeros (leading zeros) below, then
    // pairs, fours and the eight combined: d0 * 10 + d1, ... (the first
    // digit is the most significant).
    let digits = (less << (8 * (8 - count))) & (ONES * 0x0f);
    let pairs = (digits.wrapping_mul(10 << 8 | 1) >> 8) & 0x00ff_00ff_00ff_00ff;
    let fours = (pairs.wrapping_mul(100 << 16 | 1) >> 16) & 0x0000_ffff_0000_ffff;
    let eight = fours.wrapping_mul(10_000 << 32 | 1) >> 32;
    (count, eight as i64)
}

/// The bytes that separate cells within a line ([`split_cells`]).
fn is_separator(byte: u8) -> bool {
    matches!(byte, b',' | b';' | b' ' | b'\t')
}

/// The bytes that end a line (`text::split_line`).
fn is_line_break(byte: u8) -> bool {
    matches!(byte, b'\n' | b'\r')
}

impl TextReader {
    fn new(dims: usize, with_steps: bool) -> TextReader {
        TextReader {
            dims,
            coords: Vec::new(),
            points: 0,
            first_jump: None,
            steps: with_steps.then(Vec::new),
        }
    }

    /// Counts the point just appended to `coords`, written at `line` from
    /// `column`, and notes it if it is the first to jump; else its step.
    fn point_added(&mut self, line: u32, column: u32) {
        let index = self.points;
        self.points += 1;
        if index > 0 && self.first_jump.is_none() {
            let end = self.coords.len();
            let (before, now) = self.coords[end - 2 * self.dims..].split_at(self.dims);
            if jumps(before, now) {
                self.first_jump = Some((index, line, column));
            } else if let Some(steps) = &mut self.steps {
                steps.push(Step::between(before, now));
            }
        }
    }

    /// Appends one point from the cells of a row: `text`, written at `line`
    /// from `column`, which each cell's offset indexes (a row may span lines
    /// inside a quoted cell: see [`error_in`]).
    fn push_row(
        &mut self,
        line: u32,
        column: u32,
        text: &str,
        cells: &[(usize, &str)],
    ) -> Result<(), Error> {
        let index = self.points;
        let at = |offset: usize, message: String| error_in(text, line, column, offset, message);
        if let Some(&(offset, _)) = cells.iter().find(|(_, cell)| cell.is_empty()) {
            return Err(at(
                offset,
                format!(
                    "point {index}: an empty cell, between two commas or semicolons or before the first"
                ),
            ));
        }
        if cells.len() != self.dims {
            // A word among them (a comment after the point, a label with no
            // header naming the columns to read) is named: counted as a
            // coordinate, "0,0,0 # start" was "point 0 has 5 coordinates".
            if let Some(&(offset, cell)) = cells.iter().find(|(_, c)| c.parse::<f64>().is_err()) {
                return Err(at(
                    offset,
                    format!(
                        "point {index}: '{}' is not a number, and a point is its {} alone",
                        echo(cell),
                        counted(self.dims as u64, "coordinate")
                    ),
                ));
            }
            return Err(at(
                0,
                format!(
                    "point {index} has {}; the move has {}",
                    counted(cells.len() as u64, "coordinate"),
                    self.dims
                ),
            ));
        }
        let index = index as usize;
        for (axis, &(offset, cell)) in cells.iter().enumerate() {
            // Whole numbers as such (the common case, and exact at any
            // size); anything else as a number, to say what is wrong with it.
            // Both are judged by their digits, not by the double they round
            // to: 9007199254740993 was read as 2^53, and 0.99999999999999999
            // and 1e-400 as the whole numbers 1 and 0.
            let name = AXIS_NAMES[axis];
            let value = match cell.parse::<i64>() {
                Ok(v) if v.unsigned_abs() > EXACT_LIMIT as u64 => {
                    Err(format!("point {index}: {name} = {v} is too large"))
                }
                Ok(v) => Ok(v),
                Err(_) => {
                    let v = cell.parse::<f64>().map_err(|_| {
                        at(
                            offset,
                            format!("point {index}: {name} = '{}' is not a number", echo(cell)),
                        )
                    })?;
                    if v.is_finite() && !writes_whole_number(cell) {
                        Err(format!(
                            "point {index}: {name} = {cell} is not a whole number"
                        ))
                    } else {
                        coordinate(v, index, axis)
                    }
                }
            };
            self.coords.push(value.map_err(|m| at(offset, m))?);
        }
        self.point_added(line, column);
        Ok(())
    }

    /// Reads the line that starts at byte `start` as a point, if it is a
    /// plain row: whole numbers of at most [`PLAIN_DIGITS`] digits, each
    /// with an optional sign, between separators, as nearly every program
    /// writes its points; the columns `pick` names (else exactly `dims`
    /// cells). Returns the offset of the next line; None, having read
    /// nothing, for any other line (a header, a comment, a blank line,
    /// quotes, decimals, a wrong number of cells), which the general
    /// reading then reads, to the same values or to its error. This is
    /// the million-point file's path: one look at each byte, the number
    /// built as its digits go by.
    fn plain_row(
        &mut self,
        bytes: &[u8],
        start: usize,
        line: u32,
        pick: Option<&[usize]>,
    ) -> Option<usize> {
        let mut cells = [0i64; PLAIN_CELLS];
        let mut count = 0;
        let mut i = start;
        loop {
            let mut delimiters = 0usize;
            while i < bytes.len() && is_separator(bytes[i]) {
                delimiters += usize::from(is_delimiter(bytes[i]));
                i += 1;
            }
            if i == bytes.len() || is_line_break(bytes[i]) {
                break;
            }
            // An empty cell (a comma before the first value, or two between
            // two values) holds a column's place: the general reading's.
            if delimiters > usize::from(count > 0) {
                return None;
            }
            let negative = bytes[i] == b'-';
            if negative || bytes[i] == b'+' {
                i += 1;
            }
            let digits = i;
            let mut value = 0i64;
            // Eight bytes at a time while eight are left ([`leading_digits`]).
            while let Some(word) = bytes.get(i..i + 8) {
                let word = u64::from_le_bytes(word.try_into().expect("eight bytes"));
                let (count, run) = leading_digits(word);
                value = value * POWERS_OF_TEN[count] + run;
                i += count;
                if count < 8 || i - digits > PLAIN_DIGITS {
                    break;
                }
            }
            while i < bytes.len() && bytes[i].is_ascii_digit() && i - digits <= PLAIN_DIGITS {
                value = value * 10 + i64::from(bytes[i] - b'0');
                i += 1;
            }
            let ends = i == bytes.len() || is_separator(bytes[i]) || is_line_break(bytes[i]);
            if i == digits || i - digits > PLAIN_DIGITS || !ends || count == PLAIN_CELLS {
                return None;
            }
            cells[count] = if negative { -value } else { value };
            count += 1;
        }
        let row = &cells[..count];
        match pick {
            None if count == self.dims => self.coords.extend_from_slice(row),
            Some(columns) if columns.iter().all(|&c| c < count) => {
                self.coords.extend(columns.iter().map(|&c| row[c]));
            }
            _ => return None,
        }
        self.point_added(line, 1);
        // The line ends at LF, CR LF or a lone CR, as `text::split_line` says.
        Some(match bytes.get(i..i + 2) {
            None if i == bytes.len() => i,
            Some(b"\r\n") => i + 2,
            _ => i + 1,
        })
    }

    /// One row per innermost bracket pair, `[...]` or `(...)`, from where
    /// `state` stands, until about `budget` units (16 bytes each) are
    /// spent; true at the text's end.
    fn bracket_rows(
        &mut self,
        text: &str,
        state: &mut BracketRows,
        budget: &mut u64,
    ) -> Result<bool, Error> {
        let mut cells = Vec::new();
        let stop = state
            .at
            .saturating_add(usize::try_from(budget.saturating_mul(16)).unwrap_or(usize::MAX));
        for (i, c) in text[state.at..].char_indices() {
            let i = i + state.at;
            if i >= stop {
                *budget = 0;
                state.at = i;
                return Ok(false);
            }
            match c {
                // A line ends at LF, CR LF or a lone CR (`text::split_line`).
                '\r' if text.as_bytes().get(i + 1) == Some(&b'\n') => {}
                '\n' | '\r' => {
                    state.line += 1;
                    state.column = 0;
                    (state.blank, state.comment) = (true, false);
                }
                _ if state.comment => {}
                '#' if state.blank => state.comment = true,
                _ if c.is_whitespace() => {}
                '[' | '(' => {
                    state.open = Some((i + 1, state.line, state.column + 1));
                }
                ']' | ')' => {
                    if let Some((start, row_line, column)) = state.open.take() {
                        let row = &text[start..i];
                        split_cells(row, &mut cells).map_err(|(offset, message)| {
                            error_in(row, row_line, column, offset, message)
                        })?;
                        self.push_row(row_line, column, row, &cells)?;
                    }
                }
                _ => {}
            }
            state.blank &= c.is_whitespace();
            state.column += 1;
        }
        // A bracket opened after the last row closed holds a point cut
        // short ("[(0, 0, 0), (1, 1, 0), (2,"), which was dropped unread.
        if let Some((start, line, column)) = state.open {
            return Err(Error::at(
                line,
                column - 1,
                format!(
                    "'{}' opens a point that the text ends before closing: is the list cut short?",
                    &text[start - 1..start]
                ),
            ));
        }
        *budget = budget.saturating_sub(((text.len() - state.at) / 16) as u64);
        state.at = text.len();
        Ok(true)
    }

    /// One row per non-blank line; a first line with no number in it is a
    /// header, whose x, y, z, ... columns (any case) are the ones read, or,
    /// if it names none of them, its first `dims` columns. A first line
    /// with numbers in it is a point, so that a typo in it ("1 2 three",
    /// "0,0,0x1") is an error at its column, not a point silently taken for
    /// a header and dropped. Reads from where `state` stands until `budget`
    /// lines are spent: None until the text's end.
    fn line_rows(
        &mut self,
        text: &str,
        state: &mut LineRows,
        budget: &mut u64,
    ) -> Result<Option<Rows>, Error> {
        let mut cells = Vec::new();
        let mut picked = Vec::new();
        let LineRows {
            at,
            line_number,
            first,
            pick,
        } = state;
        while *at < text.len() {
            if *budget == 0 {
                return Ok(None);
            }
            *budget -= 1;
            *line_number += 1;
            if let Some(next) = self.plain_row(text.as_bytes(), *at, *line_number, pick.as_deref())
            {
                *at = next;
                *first = false;
                continue;
            }
            let record = Record::at(&text[*at..]);
            *at += record.next;
            if record.bracket {
                return Ok(Some(Rows::Listed));
            }
            // A row that spans lines (a line break inside a quoted cell)
            // moves the next row's line number past them.
            let line = record.text;
            let row_line = *line_number;
            *line_number += breaks(line);
            if line.trim_start().is_empty() || is_comment(line) {
                continue;
            }
            split_cells(line, &mut cells)
                .map_err(|(offset, message)| error_in(line, row_line, 1, offset, message))?;
            if *first {
                *first = false;
                if !cells.iter().any(|(_, c)| is_number(c)) {
                    *pick = Some(header_columns(&cells, self.dims).map_err(
                        |(offset, message)| error_in(line, row_line, 1, offset, message),
                    )?);
                    continue;
                }
            }
            match pick {
                None => self.push_row(row_line, 1, line, &cells)?,
                Some(columns) => {
                    picked.clear();
                    for &c in columns.iter() {
                        let cell = cells.get(c).copied().ok_or_else(|| {
                            Error::at(
                                row_line,
                                1,
                                format!(
                                    "point {} has {} cells; the header has more columns",
                                    self.points,
                                    cells.len()
                                ),
                            )
                        })?;
                        picked.push(cell);
                    }
                    self.push_row(row_line, 1, line, &picked)?;
                }
            }
        }
        Ok(Some(Rows::Read))
    }
}

/// The cells of `text` into `out` (cleared first), each with its byte
/// offset. A comma or a semicolon ends a field, as in CSV, so nothing
/// between two of them (or before the first) is an empty cell that keeps
/// its column's place; blanks around a field are not part of it, and
/// blanks alone (no comma or semicolon on the line) separate cells too
/// ("0 0 0"). Empty cells after the last value (a spreadsheet's trailing
/// commas) are left out. (A run of commas counted as one, so `label,x,y,z`
/// over `,1,1,1` read 1, 1, 1 as label, x, y, and `0,,0,0` as (0, 0, 0).)
///
/// A cell may be quoted, as RFC 4180 writes it: from a `"` at its start
/// to the next lone `"` (a doubled `""` inside is a quote), with commas,
/// semicolons, blanks and line breaks inside it (a spreadsheet's label
/// column: `"left, then up"`). The cell is what stands between the quotes
/// (a doubled quote stays doubled: no cell voxpath reads holds one). An
/// error is the byte offset it is at and what is wrong: a quote not
/// closed, or text after a closing quote.
fn split_cells<'a>(text: &'a str, out: &mut Vec<(usize, &'a str)>) -> Result<(), (usize, String)> {
    out.clear();
    // Bytes, not chars: every separator and the quote are ASCII, so a cut
    // beside one of them is always on a char boundary.
    let bytes = text.as_bytes();
    let delimited = fields(bytes).any(|token| matches!(token, Token::Delimiter(_)));
    let mut field_start = 0;
    let mut field_cells = 0;
    for token in fields(bytes) {
        match token {
            Token::Delimiter(at) => {
                if delimited && field_cells == 0 {
                    out.push((field_start, ""));
                }
                (field_start, field_cells) = (at + 1, 0);
            }
            Token::Cell(start, end) => {
                out.push((start, &text[start..end]));
                field_cells += 1;
            }
            Token::Quoted(start, end) => {
                let after = end + 1;
                if let Some(&b) = bytes.get(after) {
                    if !is_separator(b) && !matches!(b, b'\r' | b'\n') {
                        return Err((
                            after,
                            format!(
                                "'{}' after a quoted cell's closing quote: a comma, a semicolon or a blank comes next",
                                echo(
                                    &text[after..]
                                        .chars()
                                        .next()
                                        .map_or(String::new(), String::from)
                                )
                            ),
                        ));
                    }
                }
                out.push((start + 1, &text[start + 1..end]));
                field_cells += 1;
            }
            Token::Unclosed(start) => {
                return Err((
                    start,
                    "a quote that is not closed: a quoted cell ends at its closing quote, which may stand on a later line".to_string(),
                ));
            }
        }
    }
    if delimited && field_cells == 0 {
        out.push((field_start, ""));
    }
    while out.last().is_some_and(|(_, cell)| cell.is_empty()) {
        out.pop();
    }
    Ok(())
}

/// A piece of a row, by byte offsets ([`fields`]).
#[derive(Clone, Copy, Debug, PartialEq)]
enum Token {
    /// A comma or a semicolon.
    Delimiter(usize),
    /// An unquoted cell: start and end.
    Cell(usize, usize),
    /// A quoted cell: its opening and its closing quote.
    Quoted(usize, usize),
    /// A quote at a cell's start that nothing closes.
    Unclosed(usize),
}

/// The delimiters and cells of a row, left to right; blanks (and line
/// breaks, which stand outside quotes only in a bracketed row) between
/// them. A `"` opens a quoted cell only where a cell starts: inside one
/// (`5"`) it is the cell's own character.
fn fields(bytes: &[u8]) -> impl Iterator<Item = Token> + '_ {
    let mut at = 0;
    std::iter::from_fn(move || {
        while at < bytes.len() && matches!(bytes[at], b' ' | b'\t' | b'\r' | b'\n') {
            at += 1;
        }
        let start = at;
        match bytes.get(at)? {
            &b if is_delimiter(b) => {
                at += 1;
                Some(Token::Delimiter(start))
            }
            b'"' => match closing_quote(bytes, start) {
                Some(end) => {
                    at = end + 1;
                    Some(Token::Quoted(start, end))
                }
                None => {
                    at = bytes.len();
                    Some(Token::Unclosed(start))
                }
            },
            _ => {
                while at < bytes.len() && !is_separator(bytes[at]) && !is_line_break(bytes[at]) {
                    at += 1;
                }
                Some(Token::Cell(start, at))
            }
        }
    })
}

/// The quote that closes the quoted cell opening at `open`: the next `"`
/// that is not doubled.
fn closing_quote(bytes: &[u8], open: usize) -> Option<usize> {
    let mut at = open + 1;
    loop {
        at += memchr::memchr(b'"', &bytes[at..])?;
        if bytes.get(at + 1) != Some(&b'"') {
            return Some(at);
        }
        at += 2;
    }
}

/// One row of text read a line at a time: up to the first line break that
/// stands outside a quoted cell.
struct Record<'t> {
    /// The row, without the break that ends it.
    text: &'t str,
    /// Where the next row starts.
    next: usize,
    /// Whether a bracket stands in it outside quotes: then the text is a
    /// printed list.
    bracket: bool,
}

impl<'t> Record<'t> {
    fn at(text: &'t str) -> Record<'t> {
        let (line, next) = split_line(text);
        if is_comment(line) {
            // A comment is its line, whatever it holds: a quote in it ("5"
            // long") opened a quoted cell that ran on over the rows after
            // it, which were then dropped unread with the comment, and a
            // bracket made the whole text a printed list.
            return Record {
                text: line,
                next,
                bracket: false,
            };
        }
        if memchr::memchr(b'"', line.as_bytes()).is_none() {
            // No quote, so no quoted cell: the row is its line (found a
            // word at a time, as nearly every row is).
            let bracket = memchr::memchr2(b'[', b'(', line.as_bytes()).is_some();
            return Record {
                text: line,
                next,
                bracket,
            };
        }
        let bytes = text.as_bytes();
        let mut bracket = false;
        let mut at = 0;
        // Where a cell may start: the line's start, or after a blank or a
        // delimiter (as [`fields`] reads it).
        let mut cell_start = true;
        while at < bytes.len() {
            let b = bytes[at];
            if is_line_break(b) {
                let next = if bytes[at..].starts_with(b"\r\n") {
                    at + 2
                } else {
                    at + 1
                };
                return Record {
                    text: &text[..at],
                    next,
                    bracket,
                };
            }
            if b == b'"' && cell_start {
                match closing_quote(bytes, at) {
                    // A quote not closed: the rest of the text is the row,
                    // whose reading says so at the quote.
                    None => break,
                    Some(end) => {
                        at = end + 1;
                        cell_start = false;
                        continue;
                    }
                }
            }
            // The brackets that make text a printed list of points.
            bracket |= matches!(b, b'[' | b'(');
            cell_start = is_separator(b);
            at += 1;
        }
        Record {
            text,
            next: text.len(),
            bracket,
        }
    }
}

/// A comment line: `#` its first character past blanks.
fn is_comment(line: &str) -> bool {
    line.trim_start().starts_with('#')
}

/// Whether the text is a printed list: a bracket outside quotes and
/// comments.
fn has_bracket(text: &str) -> bool {
    let mut at = 0;
    while at < text.len() {
        let record = Record::at(&text[at..]);
        if record.bracket {
            return true;
        }
        at += record.next;
    }
    false
}

/// Line breaks in `text`: LF, CR LF or a lone CR, each one break.
fn breaks(text: &str) -> u32 {
    let bytes = text.as_bytes();
    memchr::memchr2_iter(b'\n', b'\r', bytes)
        .filter(|&i| !(bytes[i] == b'\r' && bytes.get(i + 1) == Some(&b'\n')))
        .count() as u32
}

/// The error `message` at byte `offset` of `text`, which starts at `line`
/// and `column`: past a line break inside the text (a quoted cell's, or a
/// bracketed row's), on a later line. Columns count characters, as
/// G-code's do (they counted bytes: "é,1,1,x" put the x at column 8).
fn error_in(text: &str, line: u32, column: u32, offset: usize, message: String) -> Error {
    let before = &text[..offset];
    match before.rfind(['\n', '\r']) {
        None => Error::at(line, column + before.chars().count() as u32, message),
        Some(last) => Error::at(
            line + breaks(before),
            before[last..].chars().count() as u32,
            message,
        ),
    }
}

/// A comma or a semicolon: what ends a CSV field.
fn is_delimiter(byte: u8) -> bool {
    matches!(byte, b',' | b';')
}

/// A cell that reads as a number: a digit in it, so that a header cell
/// "nan" or "inf" (which Rust's float reader takes) is not one.
fn is_number(cell: &str) -> bool {
    cell.bytes().any(|b| b.is_ascii_digit()) && cell.parse::<f64>().is_ok()
}

/// Which header cells hold the coordinates: those named x, y, z, ...
/// (any case), or the first `dims` when it names none. Past z an axis has
/// no common name (a fourth is w, a or u), so one not named there is read
/// in its own column when the axes before it are named in theirs
/// (`x,y,z,w` for 4 axes, whose fourth is called `a`). Refused: a header
/// that names some of x, y, z but not all (`k,x,y` or `x,y,w` for a 3-axis
/// move: its columns would read k as x, or w as z), one naming an axis
/// twice (which of the two holds it?), and one naming an axis the move does
/// not have (z for a move in x and y: its points have a z, which would be
/// dropped unread). An error is at the byte offset of its cell.
fn header_columns(header: &[(usize, &str)], dims: usize) -> Result<Vec<usize>, (usize, String)> {
    let axes = &AXIS_NAMES[..dims];
    let names = |cell: &str, axes: &[&str]| axes.iter().any(|axis| cell.eq_ignore_ascii_case(axis));
    // A header that names the move's axes and one past them (x, y, z for
    // a move in x and y); one of no names of the move's axes (a, b) is
    // read by its first columns, below.
    let past = header
        .iter()
        .find(|(_, cell)| names(cell, &AXIS_NAMES[dims..]));
    if let Some((offset, name)) = past.filter(|_| header.iter().any(|(_, cell)| names(cell, axes)))
    {
        return Err((
            *offset,
            format!(
                "the header names {name}, an axis the move does not have: its {dims} axes are {}",
                axes.join(", ")
            ),
        ));
    }
    let columns_of = |axis: &str| -> Vec<usize> {
        (0..header.len())
            .filter(|&c| header[c].1.eq_ignore_ascii_case(axis))
            .collect()
    };
    let mut named = Vec::with_capacity(dims);
    for axis in axes {
        match columns_of(axis)[..] {
            [] => named.push(None),
            [column] => named.push(Some(column)),
            [first, second, ..] => {
                return Err((
                    header[second].0,
                    format!(
                        "the header names {axis} twice, in columns {} and {}",
                        first + 1,
                        second + 1
                    ),
                ));
            }
        }
    }
    if named.iter().all(Option::is_some) {
        return Ok(named.into_iter().flatten().collect());
    }
    let in_place = named.iter().enumerate().all(|(axis, at)| match at {
        Some(column) => *column == axis,
        None => axis >= 3,
    });
    if named.iter().any(Option::is_some) && !in_place {
        let missing: Vec<&str> = axes
            .iter()
            .zip(&named)
            .filter(|(_, at)| at.is_none())
            .map(|(axis, _)| *axis)
            .collect();
        return Err((
            0,
            format!(
                "the header has no {} column; the move has {} axes ({})",
                missing.join(", "),
                dims,
                axes.join(", ")
            ),
        ));
    }
    if header.len() >= dims {
        return Ok((0..dims).collect());
    }
    Err((
        0,
        format!(
            "the header names none of {} and has {} columns, fewer than the move's {} axes",
            axes.join(", "),
            header.len(),
            dims
        ),
    ))
}

/// What kind of difference the first one is.
#[derive(Serialize, Tsify, Clone, Copy, Debug, PartialEq, Eq)]
#[serde(rename_all = "camelCase")]
pub enum DifferenceKind {
    /// The points start elsewhere than the move (point 0 differs).
    Start,
    /// A point the rule reaches by a different step.
    Step,
    /// The points end before the rule's path does.
    Stops,
    /// The points go on after the rule's path has ended.
    GoesOn,
}

/// The first point where the learner's path and the rule's part.
#[derive(Serialize, Tsify, Clone, Debug, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct Difference {
    pub kind: DifferenceKind,
    /// Point index k; the step that produced it is step index k - 1.
    pub point_index: u64,
    /// The rule's step index there (k - 1), when the rule takes one.
    pub step_index: Option<u64>,
    /// The rule's point k, or None after its end.
    pub expected: Option<Vec<i64>>,
    /// The learner's point k, or None after their last.
    pub got: Option<Vec<i64>>,
    /// What differs, in one sentence ("your path stops at step 7 of 10").
    pub message: String,
    /// Why the rule took its step there: the trace's own explanation
    /// ([`Trace::explain`]); for a start or a tail past the end, where the
    /// rule takes no step, what it does instead.
    pub why: String,
    /// The decision values of that step by column name (numbers, category
    /// labels, true/false), empty where the rule takes no step.
    #[serde(serialize_with = "as_object")]
    #[tsify(type = "Record<string, number | string | boolean | null>")]
    pub decisions: Vec<(String, Value)>,
    /// Point indices up to [`AROUND`] either side, each side's point.
    pub around: Vec<AroundRow>,
}

/// One point index near the difference, on both paths.
#[derive(Serialize, Tsify, Clone, Debug, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct AroundRow {
    pub point_index: u64,
    pub expected: Option<Vec<i64>>,
    pub got: Option<Vec<i64>>,
}

/// A catalogue rule the points follow exactly.
#[derive(Serialize, Tsify, Clone, Debug, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct AlsoMatch {
    #[tsify(type = "AlgorithmId")]
    pub algorithm: String,
    /// The options that choose this rule among the algorithm's variants
    /// (those with a fixed set of values); an option whose every value
    /// gives the same path here is left out. Pass it with the request's
    /// other options to trace the same path, less those that do not apply
    /// with it (the chord options beside the helix's method saleem).
    #[serde(serialize_with = "as_object")]
    #[tsify(type = "Record<string, unknown>")]
    pub options: Vec<(String, Value)>,
    /// "bresenham3d with tie = hold".
    pub label: String,
    /// The algorithm's errata about the variant chosen (for example
    /// Saleem's printed 2D pseudo-code), from the catalogue.
    pub errata: Vec<&'static str>,
}

/// The result of a check.
#[derive(Serialize, Tsify, Clone, Debug, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct Check {
    /// The learner's points are the rule's path, point for point.
    pub matches: bool,
    #[tsify(type = "AlgorithmId")]
    pub algorithm: String,
    /// Steps of the rule's path.
    pub steps: u64,
    /// Steps of the learner's path (points - 1).
    pub your_steps: u64,
    /// None when the points match.
    pub first_difference: Option<Difference>,
    /// Every catalogue rule of the same family whose path equals the points.
    pub also_matches: Vec<AlsoMatch>,
}

/// Checks text points against the request given as JSON text.
pub fn check_text(request_json: &str, text: &str) -> Result<Check, Error> {
    SlicedCheck::from_text(request_json, text.to_string())?.run()
}

/// Checks flat points (`dims` per point) against the request as JSON text.
pub fn check_flat<V: FlatValue>(
    request_json: &str,
    values: &[V],
    dims: usize,
) -> Result<Check, Error> {
    SlicedCheck::from_flat(request_json, values, dims)?.run()
}

/// Checks points against the trace of `request` (already run).
pub fn check_trace(request: &Request, trace: &Trace, points: &Points) -> Check {
    CheckPass::new(request.clone(), trace, points.clone(), points.steps()).run()
}

/// How far a check made a slice at a time has got ([`CheckPass::advance`]).
#[derive(Serialize, Tsify, Debug, Clone, Copy, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct CheckProgress {
    /// What the check does now.
    pub stage: CheckStage,
    /// Bytes of the points' text read so far, of `bytes` (both 0 for
    /// points given as numbers), and the points read so far (all of them
    /// once the reading is over).
    pub bytes_read: u64,
    pub bytes: u64,
    pub points_read: u64,
    /// Step indices compared so far, of `stepsShared`, the steps both paths
    /// have (all of them once the first difference is found).
    pub steps_compared: u64,
    pub steps_shared: u64,
    /// Option combinations of the family's rules tried for alsoMatches so
    /// far, of `variants`.
    pub variants_tried: u64,
    pub variants: u64,
    pub done: bool,
}

/// The stages of a check, in order.
#[derive(Serialize, Tsify, Clone, Copy, Debug, PartialEq, Eq)]
#[serde(rename_all = "camelCase")]
pub enum CheckStage {
    /// The points' text read ([`TextReading`]).
    Reading,
    /// The points' steps compared with the rule's, to the first that differs.
    Comparing,
    /// Every option combination of the rule's family traced along the
    /// points, for those whose path they are (alsoMatches).
    Variants,
    /// The check is made.
    Done,
}

/// A check made a slice at a time, so that a worker can report it and stop
/// it between slices: at the page's cap (1,500,000 steps) the whole check
/// took about a second in one call. The steps are compared a bounded
/// number at a time, then the family's option combinations are traced one
/// or more at a time ([`AlsoMatchesPass`]); the result is the one a whole
/// check gives, which is this pass run to its end ([`Self::run`]). The
/// rule's trace is owned (a worker's check) or borrowed (`&Trace`).
pub struct CheckPass<T: Borrow<Trace> = Trace> {
    request: Request,
    /// The rule's path.
    trace: T,
    points: Points,
    /// The points' steps, made once: compared with the rule's, and followed
    /// by every combination alsoMatches traces.
    steps: Arc<[Step]>,
    /// Step indices compared so far, below `steps_shared`.
    steps_compared: u64,
    /// The steps both paths have.
    steps_shared: u64,
    /// The first point index where the two part, once the comparison found
    /// it (0: they start apart).
    mismatch: Option<u64>,
    /// Set once the comparison is over: the first difference (None: the
    /// points are the rule's path).
    first_difference: Option<Option<Difference>>,
    variants: AlsoMatchesPass,
}

/// A check of points as given, a slice at a time: points given as text
/// are read first, a slice at a time too ([`TextReading`]: at the page's
/// cap the reading was one call of 0.1 to 0.2 s before the check's first
/// slice, which a Cancel waited for), then checked ([`CheckPass`]). The
/// request is read and its rule traced when it is made. The result is the
/// one a whole check gives ([`Self::run`]).
pub struct SlicedCheck {
    /// The text while it is read, and the rule; None once it is read.
    reading: Option<Box<ReadingStage>>,
    /// The check, once there are points.
    pass: Option<CheckPass>,
    /// Bytes of the text (0 for points given as numbers).
    bytes: u64,
}

/// What [`SlicedCheck`] holds while it reads the points' text.
struct ReadingStage {
    request: Request,
    trace: Trace,
    text: String,
    reading: TextReading,
}

impl SlicedCheck {
    /// A check of points read from text ([`Points::from_text`]) against the
    /// request given as JSON text. A bad request is an error here; one in
    /// the text, from [`Self::advance`].
    pub fn from_text(request_json: &str, text: String) -> Result<SlicedCheck, Error> {
        let request = Request::from_json(request_json)?;
        let trace = crate::algorithms::run(&request)?;
        let reading = TextReading::new(trace.dims(), true);
        Ok(SlicedCheck {
            bytes: crate::text::without_byte_order_mark(&text).len() as u64,
            reading: Some(Box::new(ReadingStage {
                request,
                trace,
                text,
                reading,
            })),
            pass: None,
        })
    }

    /// A check of flat points (`dims` per point, [`Points::from_flat`])
    /// against the request given as JSON text.
    pub fn from_flat<V: FlatValue>(
        request_json: &str,
        values: &[V],
        dims: usize,
    ) -> Result<SlicedCheck, Error> {
        let request = Request::from_json(request_json)?;
        let trace = crate::algorithms::run(&request)?;
        let points = Points::from_flat(values, dims, trace.dims())?;
        let steps = points.steps();
        Ok(SlicedCheck {
            reading: None,
            pass: Some(CheckPass::new(request, trace, points, steps)),
            bytes: 0,
        })
    }

    /// The whole check, in one call.
    pub fn run(mut self) -> Result<Check, Error> {
        self.advance(u64::MAX)?;
        Ok(self.result().expect("advanced to the end"))
    }

    /// Takes the check on by about `units` points' worth of work: rows of
    /// the text read, then [`CheckPass::advance`]'s (both in the call that
    /// ends the reading). An error is the
    /// text's ([`Points::from_text`]), once the reading comes to it.
    pub fn advance(&mut self, units: u64) -> Result<CheckProgress, Error> {
        if let Some(stage) = &mut self.reading {
            if !stage.reading.advance(&stage.text, units)? {
                return Ok(self.progress());
            }
            let ReadingStage {
                request,
                trace,
                reading,
                ..
            } = *self.reading.take().expect("read above");
            let (points, steps) = reading.finish()?;
            let steps = steps.expect("asked for with the points");
            // The check goes on in this call, by as much again at most (so
            // that Infinity makes the whole check).
            self.pass = Some(CheckPass::new(request, trace, points, steps));
        }
        let pass = self.pass.as_mut().expect("points read");
        pass.advance(units);
        Ok(self.progress())
    }

    pub fn progress(&self) -> CheckProgress {
        match (&self.reading, &self.pass) {
            (Some(stage), _) => CheckProgress {
                stage: CheckStage::Reading,
                bytes_read: stage.reading.bytes_read(),
                bytes: self.bytes,
                points_read: stage.reading.points_read(),
                steps_compared: 0,
                steps_shared: 0,
                variants_tried: 0,
                variants: 0,
                done: false,
            },
            (None, Some(pass)) => CheckProgress {
                bytes_read: self.bytes,
                bytes: self.bytes,
                ..pass.progress()
            },
            (None, None) => unreachable!("a check reads its points or has them"),
        }
    }

    /// The learner's points, once read.
    pub fn points(&self) -> Option<&Points> {
        self.pass.as_ref().map(CheckPass::points)
    }

    /// The check, once [`Self::advance`] is done; else None.
    pub fn result(&self) -> Option<Check> {
        self.pass.as_ref()?.result()
    }
}

impl<T: Borrow<Trace>> CheckPass<T> {
    /// A check of `points` (with their `steps`) against `trace`, the path
    /// of `request`.
    pub fn new(request: Request, trace: T, points: Points, steps: Arc<[Step]>) -> CheckPass<T> {
        let rule = trace.borrow();
        let starts_apart = rule.start().coords() != points.get(0);
        let steps_shared = rule.steps().min(steps.len() as u64);
        CheckPass {
            variants: AlsoMatchesPass::new(&request, &points),
            mismatch: starts_apart.then_some(0),
            // Nothing to compare past a start that differs.
            steps_compared: if starts_apart { steps_shared } else { 0 },
            steps_shared,
            request,
            trace,
            points,
            steps,
            first_difference: None,
        }
    }

    /// The learner's points.
    pub fn points(&self) -> &Points {
        &self.points
    }

    /// The whole check, in one call.
    pub fn run(mut self) -> Check {
        self.advance(u64::MAX);
        self.finish()
    }

    /// Takes the check on by about `units` points' worth of work: up to
    /// `units` steps compared, then option combinations traced, each
    /// counted as the points (what tracing one along the points can take),
    /// at least one a call. A call after the end does nothing.
    pub fn advance(&mut self, units: u64) -> CheckProgress {
        let mut budget = units.max(1);
        while budget > 0 && self.first_difference.is_none() {
            let to = self
                .steps_compared
                .saturating_add(budget)
                .min(self.steps_shared);
            let from = self.steps_compared as usize;
            let rule = self.trace.borrow().step_range(self.steps_compared, to);
            let parted = rule
                .iter()
                .zip(&self.steps[from..to as usize])
                .position(|(a, b)| a != b);
            budget -= to - self.steps_compared;
            match parted {
                // Point k + 1 is the first the differing step k reaches.
                Some(at) => {
                    self.mismatch = Some(from as u64 + at as u64 + 1);
                    self.steps_compared = self.steps_shared;
                }
                None => self.steps_compared = to,
            }
            if self.steps_compared == self.steps_shared {
                self.first_difference = Some(first_difference(
                    self.trace.borrow(),
                    &self.points,
                    self.mismatch,
                ));
            }
        }
        let combination_cost = self.points.len();
        while budget > 0 && !self.variants.is_done() {
            self.variants
                .try_next(&self.request, &self.points, &self.steps);
            budget = budget.saturating_sub(combination_cost);
        }
        self.progress()
    }

    pub fn progress(&self) -> CheckProgress {
        let stage = if self.first_difference.is_none() {
            CheckStage::Comparing
        } else if !self.variants.is_done() {
            CheckStage::Variants
        } else {
            CheckStage::Done
        };
        CheckProgress {
            stage,
            bytes_read: 0,
            bytes: 0,
            points_read: self.points.len(),
            steps_compared: self.steps_compared,
            steps_shared: self.steps_shared,
            variants_tried: self.variants.combinations_tried,
            variants: self.variants.combinations,
            done: stage == CheckStage::Done,
        }
    }

    /// The check, once [`Self::advance`] is done; else None.
    pub fn result(&self) -> Option<Check> {
        if !self.variants.is_done() {
            return None;
        }
        let first_difference = self.first_difference.clone()?;
        let rule = self.trace.borrow();
        Some(Check {
            matches: first_difference.is_none(),
            algorithm: rule.algorithm.clone(),
            steps: rule.steps(),
            your_steps: self.points.len() - 1,
            first_difference,
            also_matches: self.variants.matches.clone(),
        })
    }

    fn finish(self) -> Check {
        self.result().expect("advanced to the end")
    }
}

/// Whether `trace`, traced to follow `steps` (the points' own steps), is
/// the points' path: it took them all (it took no other, or it would have
/// stopped) from the same start.
fn follows(trace: &Trace, points: &Points, steps: &[Step]) -> bool {
    trace.steps() == steps.len() as u64 && trace.start().coords() == points.get(0)
}

/// The first difference of `points` from `trace`'s path, given `mismatch`,
/// the first point index below both lengths where they differ. Two paths
/// from the same start are the same points exactly as far as their steps
/// are the same, and the step that differs first leads to the first point
/// that does: so the step codes (2 bytes a step) are compared, not the
/// points (8 bytes a coordinate, decoded from the trace's steps first).
fn first_difference(trace: &Trace, points: &Points, mismatch: Option<u64>) -> Option<Difference> {
    let steps = trace.steps();
    let (kind, k) = match mismatch {
        Some(0) => (DifferenceKind::Start, 0),
        Some(k) => (DifferenceKind::Step, k),
        None if points.len() < steps + 1 => (DifferenceKind::Stops, points.len()),
        None if points.len() > steps + 1 => (DifferenceKind::GoesOn, steps + 1),
        None => return None,
    };
    let expected = |i: u64| (i <= steps).then(|| trace.point(i).coords().to_vec());
    let got = |i: u64| (i < points.len()).then(|| points.get(i).to_vec());
    let show = |p: &Option<Vec<i64>>| p.as_deref().map(Point::new).map(|p| p.to_string());
    let step = why_at_point(trace, k);
    let message = match kind {
        DifferenceKind::Start => format!(
            "your path starts at {}; the move starts at {}",
            show(&got(0)).unwrap_or_default(),
            trace.start()
        ),
        DifferenceKind::Step => format!(
            "at point {k} your path goes to {}; the rule goes to {}",
            show(&got(k)).unwrap_or_default(),
            show(&expected(k)).unwrap_or_default()
        ),
        DifferenceKind::Stops => format!("your path stops at step {} of {steps}", k - 1),
        DifferenceKind::GoesOn => "your path goes on after the end".to_string(),
    };
    let why = match (&step, kind) {
        (Some(s), _) => s.explanation.clone(),
        (None, DifferenceKind::GoesOn) => format!(
            "the rule's path ends at {} after {steps} steps",
            trace.end()
        ),
        (None, _) => format!("every path of the move starts at from = {}", trace.start()),
    };
    let first = k.saturating_sub(AROUND);
    let last = (k + AROUND).min(steps.max(points.len() - 1));
    Some(Difference {
        kind,
        point_index: k,
        step_index: step.as_ref().map(|s| s.step_index),
        expected: expected(k),
        got: got(k),
        message,
        why,
        decisions: step.map(|s: StepWhy| s.decisions).unwrap_or_default(),
        around: (first..=last)
            .map(|i| AroundRow {
                point_index: i,
                expected: expected(i),
                got: got(i),
            })
            .collect(),
    })
}

/// The options of `info` that a check tries, each with its values (see
/// [`tried_values`]), in the order `info` declares them.
fn tried_options(info: &AlgorithmInfo) -> Vec<(&OptionSpec, Vec<Value>)> {
    info.options
        .iter()
        .filter_map(|spec| tried_values(spec).map(|values| (spec, values)))
        .collect()
}

/// The values of an option that a check tries: every choice, both booleans,
/// each integer of a small declared range; None for any other option (kept
/// as the request gives it).
fn tried_values(spec: &OptionSpec) -> Option<Vec<Value>> {
    match spec.kind {
        OptionKind::Choice { values } => Some(values.iter().map(|&v| Value::from(v)).collect()),
        OptionKind::Boolean => Some(vec![Value::from(false), Value::from(true)]),
        OptionKind::Integer(IntegerRange {
            min: Some(lo),
            max: Some(hi),
            ..
        }) if hi - lo < SMALL_RANGE => Some((lo..=hi).map(Value::from).collect()),
        _ => None,
    }
}

/// The family of the requested algorithm (an unknown one was refused when
/// the request ran).
fn family_of(request: &Request) -> Option<Family> {
    algorithms::find(&request.algorithm).ok().map(|a| a.family)
}

/// Every algorithm of the request's family, with every combination of the
/// values [`tried_values`] gives, whose path equals `points`. The request's
/// other options go to each algorithm that takes them; `maxSteps` is held
/// to the points' length, so a rule that needs more steps stops early.
pub fn also_matches(request: &Request, points: &Points, steps: &Arc<[Step]>) -> Vec<AlsoMatch> {
    let mut pass = AlsoMatchesPass::new(request, points);
    while !pass.is_done() {
        pass.try_next(request, points, steps);
    }
    pass.matches
}

/// [`also_matches`] made one option combination at a time, so that a
/// check can be run in slices: at the page's cap each combination traces
/// up to the whole path (a helix's circle is counted by a dry run of every
/// turn first), and a helix's family has 200 of them.
struct AlsoMatchesPass {
    /// The algorithms of the request's family, in the catalogue's order.
    family: Vec<&'static AlgorithmInfo>,
    /// `maxSteps` as each combination is traced: the points' steps at most.
    max_steps: u64,
    /// The algorithm being tried, by index into `family`, and its
    /// combinations' state; None once every algorithm has been tried.
    algorithm: Option<(usize, AlgorithmTrial)>,
    /// The combinations traced so far, by algorithm, each with whether it
    /// matched, for those whose path is known to be the path of one of them.
    traced: Vec<(&'static str, Vec<Option<Value>>, bool)>,
    /// Combinations tried so far, of `combinations` (every algorithm's).
    combinations_tried: u64,
    combinations: u64,
    /// The entries of the algorithms tried to the end.
    matches: Vec<AlsoMatch>,
}

/// One algorithm's combinations, tried in the odometer's order.
struct AlgorithmTrial {
    info: &'static AlgorithmInfo,
    tried: Vec<(&'static OptionSpec, Vec<Value>)>,
    /// The request's options this algorithm takes and the check does not vary.
    base: Map<String, Value>,
    /// The next combination: an index into each tried option's values.
    choice: Vec<usize>,
    /// The combinations whose path is the points'.
    matched: Vec<Vec<Option<Value>>>,
}

impl AlgorithmTrial {
    fn new(info: &'static AlgorithmInfo, request: &Request, max_steps: u64) -> AlgorithmTrial {
        let tried = tried_options(info);
        let mut base = Map::new();
        for (name, value) in request.options() {
            let declared = info.options.iter().find(|o| o.name == name);
            if declared.is_some_and(|o| tried_values(o).is_none()) {
                base.insert(name.clone(), value.clone());
            }
        }
        if info.options.iter().any(|o| o.name == MAX_STEPS.name) {
            base.insert(MAX_STEPS.name.to_string(), Value::from(max_steps));
        }
        AlgorithmTrial {
            info,
            choice: vec![0; tried.len()],
            tried,
            base,
            matched: Vec::new(),
        }
    }

    /// The matching combinations as entries ([`describe_matches`]).
    fn finish(self) -> Vec<AlsoMatch> {
        let AlgorithmTrial {
            info,
            tried,
            matched,
            ..
        } = self;
        // A combination with an option the move refused (None: traced
        // without it, so with its default) is the one with that default
        // given, when that matched too: a circle in x and y refuses plane
        // zx and yz, and was listed both "with plane = xy" and without it.
        let stands_for_another = |m: &Vec<Option<Value>>| {
            m.iter().enumerate().any(|(option, value)| {
                value.is_none()
                    && tried[option].0.default.is_some_and(|default| {
                        let mut given = m.clone();
                        given[option] = Some(Value::from(default));
                        matched.contains(&given)
                    })
            })
        };
        let distinct: Vec<_> = matched
            .iter()
            .filter(|m| !stands_for_another(m))
            .cloned()
            .collect();
        describe_matches(info, &tried, distinct)
    }
}

/// How many combinations of its tried options' values `info` has.
fn combination_count(info: &AlgorithmInfo) -> u64 {
    tried_options(info)
        .iter()
        .map(|(_, values)| values.len() as u64)
        .product()
}

impl AlsoMatchesPass {
    fn new(request: &Request, points: &Points) -> AlsoMatchesPass {
        let family: Vec<&'static AlgorithmInfo> = match family_of(request) {
            Some(family) => algorithms::ALGORITHMS
                .iter()
                .copied()
                .filter(|a| a.family == family)
                .collect(),
            None => Vec::new(),
        };
        let max_steps = request.max_steps().unwrap_or(0).min(points.len() - 1);
        AlsoMatchesPass {
            algorithm: family
                .first()
                .map(|&info| (0, AlgorithmTrial::new(info, request, max_steps))),
            combinations: family.iter().map(|info| combination_count(info)).sum(),
            family,
            max_steps,
            traced: Vec::new(),
            combinations_tried: 0,
            matches: Vec::new(),
        }
    }

    fn is_done(&self) -> bool {
        self.algorithm.is_none()
    }

    /// Tries the next combination (traced along `steps`, unless its path is
    /// known to be one traced before), and when it was its algorithm's
    /// last, lists that algorithm's matches and moves to the next one.
    fn try_next(&mut self, request: &Request, points: &Points, steps: &Arc<[Step]>) {
        let Some((index, trial)) = &mut self.algorithm else {
            return;
        };
        let (info, tried) = (trial.info, &trial.tried);
        let mut combination: Vec<Option<Value>> = tried
            .iter()
            .zip(&trial.choice)
            .map(|((_, values), &i)| Some(values[i].clone()))
            .collect();
        leave_out_inapplicable(info, &trial.base, tried, &mut combination);
        // The combination traced before whose path is this one's: one
        // paired with it, or this one itself, reached again with an option
        // it leaves out at another value.
        let (id, earlier) = same_path_as(info, request, tried, &combination)
            .unwrap_or_else(|| (info.id, combination.clone()));
        let known = self
            .traced
            .iter()
            .find(|(i, c, _)| *i == id && *c == earlier)
            .map(|&(_, _, path_follows)| path_follows);
        let path_follows = known.unwrap_or_else(|| {
            let asked = combination.clone();
            let path_follows = trace_combination(info, &trial.base, tried, steps, &mut combination)
                .is_some_and(|trace| follows(&trace, points, steps));
            // Only a combination traced as asked stands for another.
            if combination == asked {
                self.traced.push((info.id, asked, path_follows));
            }
            path_follows
        });
        if path_follows && !trial.matched.contains(&combination) {
            trial.matched.push(combination);
        }
        self.combinations_tried += 1;
        if next_combination(&mut trial.choice, &trial.tried) {
            return;
        }
        let next = *index + 1;
        let next_trial = self
            .family
            .get(next)
            .map(|&info| (next, AlgorithmTrial::new(info, request, self.max_steps)));
        let (_, done) = std::mem::replace(&mut self.algorithm, next_trial).expect("tried above");
        self.matches.extend(done.finish());
    }
}

/// The name of the `tie` option.
const TIE: &str = tie_option("advance").name;

/// A combination traced before this one (an algorithm earlier in the
/// catalogue, or a combination earlier in the odometer's order, each
/// option's values in their declared order) whose path is this
/// combination's on the request's line, known without tracing either; None
/// when there is none. `gcd` never changes a path (Wang section 4,
/// [`crate::line::Mirror::divisor`]), so gcd = true has the path of
/// gcd = false. liu-float's epsilon is exactly Liu's rule in exact
/// arithmetic at every `decimals` from [`liu_float::exact_decimals`] up
/// (the argument is there): epsilon = M / 2|Δactive|, M Wang's discriminant
/// (eq. 6), and a passive axis steps when epsilon > 0, a tie (0) going to
/// the tie policy. That is bresenham3d's rule: Saleem's error, 2|Δa| added
/// each step and 2|Δmajor| taken off when the axis steps, exceeds
/// |Δmajor| exactly when M > 0, and a tie goes to the same policy (an axis
/// as long as the major one steps every time under both). So those have
/// bresenham3d's path with the same tie. Either way, the combination
/// follows the points exactly when the one it is paired with does:
/// alsoMatches does not trace the same path twice, and is what it would be
/// if it did (property-tested, full paths compared).
fn same_path_as(
    info: &AlgorithmInfo,
    request: &Request,
    tried: &[(&OptionSpec, Vec<Value>)],
    combination: &[Option<Value>],
) -> Option<(&'static str, Vec<Option<Value>>)> {
    let value_of = |name: &str| {
        tried
            .iter()
            .zip(combination)
            .find(|((spec, _), _)| spec.name == name)
            .and_then(|(_, value)| value.clone())
    };
    if info.id == liu_float::ID {
        let (from, to) = (request.point(FROM.name).ok()?, request.point(TO.name).ok()?);
        let exact = (from.dims() == to.dims()).then(|| liu_float::exact_decimals(from, to))??;
        if value_of(DECIMALS.name)?.as_i64()? < i64::from(exact) {
            return None;
        }
        let tie = value_of(TIE)?;
        let earlier = bresenham3d::INFO
            .options
            .iter()
            .filter(|spec| tried_values(spec).is_some())
            .map(|spec| match spec.name {
                TIE => Some(Some(tie.clone())),
                name if name == GCD.name => Some(Some(Value::from(false))),
                _ => None,
            })
            .collect::<Option<Vec<_>>>()?;
        return Some((bresenham3d::ID, earlier));
    }
    let mut earlier = combination.to_vec();
    for ((spec, _), value) in tried.iter().zip(earlier.iter_mut()) {
        if spec.name == GCD.name && *value == Some(Value::from(true)) {
            *value = Some(Value::from(false));
        }
    }
    (earlier != combination).then_some((info.id, earlier))
}

/// Traces `info` with `base` and the combination's values, following
/// `steps`: a rule that parts from them stops there, as an error. An option
/// the algorithm refuses in this combination (lineAlgorithm with helix's
/// method saleem: "applies to method segments only") is left out, marked
/// None, and the trace tried again; None when it fails for any other reason.
fn trace_combination(
    info: &AlgorithmInfo,
    base: &Map<String, Value>,
    tried: &[(&OptionSpec, Vec<Value>)],
    steps: &Arc<[Step]>,
    combination: &mut [Option<Value>],
) -> Option<Trace> {
    loop {
        let mut request = combination_request(info, base, tried, combination);
        // An option of the request that does not apply with this
        // combination's values (the chord options, segmentLength and
        // tolerance, beside the helix's method saleem) is the request's
        // setting of another variant, not part of this one: left out, as
        // compare leaves it to the side it applies to. Kept, it refused the
        // trace, and helix with method = saleem was never listed when the
        // request gave a chord option.
        if let Ok(off) = request.inapplicable(info.options) {
            let off: Vec<&str> = off
                .iter()
                .map(|spec| spec.name)
                .filter(|&name| base.contains_key(name))
                .collect();
            request = request.without(&off);
        }
        match (info.trace)(&request.following(steps.clone()), algorithms::find) {
            Ok(trace) => return Some(trace),
            Err(e) => {
                let refused = tried
                    .iter()
                    .position(|(spec, _)| e.field_name() == Some(spec.name))?;
                combination[refused].take()?;
            }
        }
    }
}

/// The request of `info` with `base` and the combination's values (those
/// not left out, None).
fn combination_request(
    info: &AlgorithmInfo,
    base: &Map<String, Value>,
    tried: &[(&OptionSpec, Vec<Value>)],
    combination: &[Option<Value>],
) -> Request {
    let mut options = base.clone();
    for ((spec, _), value) in tried.iter().zip(combination) {
        if let Some(value) = value {
            options.insert(spec.name.to_string(), value.clone());
        }
    }
    Request::new(info.id, options)
}

/// Leaves out (None) each option of the combination that does not apply
/// with its other values ([`Request::inapplicable`]: the helix's
/// lineAlgorithm beside its method saleem), as its trace would refuse it
/// and be made again without it ([`trace_combination`]). So combinations
/// that differ only there are one request, traced once: the helix's seven
/// line algorithms had Saleem's method traced seven times over, a dry run
/// of its circle each (a third of alsoMatches at the page's cap).
fn leave_out_inapplicable(
    info: &AlgorithmInfo,
    base: &Map<String, Value>,
    tried: &[(&OptionSpec, Vec<Value>)],
    combination: &mut [Option<Value>],
) {
    // A value not among its choices is the trace's to refuse.
    let Ok(off) = combination_request(info, base, tried, combination).inapplicable(info.options)
    else {
        return;
    };
    for ((spec, _), value) in tried.iter().zip(combination.iter_mut()) {
        if off.iter().any(|o| o.name == spec.name) {
            *value = None;
        }
    }
}

/// Advances `choice` (an index into each option's values) like an
/// odometer; false after the last combination.
fn next_combination(choice: &mut [usize], tried: &[(&OptionSpec, Vec<Value>)]) -> bool {
    for (slot, (_, values)) in choice.iter_mut().zip(tried).rev() {
        *slot += 1;
        if *slot < values.len() {
            return true;
        }
        *slot = 0;
    }
    false
}

/// The matching combinations of one algorithm as entries, leaving out each
/// option whose every value matched wherever the others matched (`gcd`,
/// which never changes the path; `tie` on a line without ties) and each
/// one the combination could not take (None).
fn describe_matches(
    info: &AlgorithmInfo,
    tried: &[(&OptionSpec, Vec<Value>)],
    mut matched: Vec<Vec<Option<Value>>>,
) -> Vec<AlsoMatch> {
    for (option, (_, values)) in tried.iter().enumerate() {
        let irrelevant = matched.iter().any(|m| m[option].is_some())
            && matched.iter().filter(|m| m[option].is_some()).all(|m| {
                values.iter().all(|v| {
                    let mut other = m.clone();
                    other[option] = Some(v.clone());
                    matched.contains(&other)
                })
            });
        if irrelevant {
            let mut unique: Vec<Vec<Option<Value>>> = Vec::new();
            for mut m in matched {
                m[option] = None;
                if !unique.contains(&m) {
                    unique.push(m);
                }
            }
            matched = unique;
        }
    }
    matched
        .into_iter()
        .map(|m| {
            let options: Vec<(String, Value)> = tried
                .iter()
                .zip(m)
                .filter_map(|((spec, _), value)| Some((spec.name.to_string(), value?)))
                .collect();
            let settings: Vec<String> = options
                .iter()
                .map(|(name, value)| format!("{name} = {}", plain(value)))
                .collect();
            let label = if settings.is_empty() {
                info.id.to_string()
            } else {
                format!("{} with {}", info.id, settings.join(", "))
            };
            let errata = info
                .errata
                .iter()
                .copied()
                .filter(|e| settings.iter().any(|s| e.contains(s.as_str())))
                .collect();
            AlsoMatch {
                algorithm: info.id.to_string(),
                options,
                label,
                errata,
            }
        })
        .collect()
}

/// An option value as written in a label: text without quotes.
fn plain(value: &Value) -> String {
    match value {
        Value::String(s) => s.clone(),
        other => other.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::arc::arc_segments::LINE_ALGORITHMS;
    use proptest::prelude::*;

    fn request(json: &str) -> Request {
        Request::from_json(json).unwrap()
    }

    fn points_of(trace: &Trace) -> Points {
        Points {
            dims: trace.dims(),
            coords: trace.points_flat(0, trace.steps() + 1),
        }
    }

    fn check(request_json: &str, points: &Points) -> Check {
        let r = request(request_json);
        let trace = crate::algorithms::run(&r).unwrap();
        check_trace(&r, &trace, points)
    }

    /// The request of an alsoMatches entry: the checked request with the
    /// entry's algorithm and options.
    fn entry_request(base: &Request, entry: &AlsoMatch) -> Request {
        let info = algorithms::find(&entry.algorithm).unwrap();
        let mut options = Map::new();
        for (name, value) in base.options() {
            if info.options.iter().any(|o| o.name == name) {
                options.insert(name.clone(), value.clone());
            }
        }
        for (name, value) in &entry.options {
            options.insert(name.clone(), value.clone());
        }
        // Less the request's options that do not apply with the entry's
        // (a chord option beside the helix's method saleem).
        let r = Request::new(&entry.algorithm, options);
        let off: Vec<&str> = r
            .inapplicable(info.options)
            .unwrap()
            .iter()
            .map(|spec| spec.name)
            .collect();
        r.without(&off)
    }

    /// The points `points` with changes that make them part from their
    /// path at various places: the path itself, started elsewhere, two
    /// unequal steps swapped (point k alone moves) near the start, the
    /// middle and the end, cut short, and gone on a step past the end.
    fn deviations(points: &Points) -> Vec<Points> {
        let dims = points.dims;
        let n = points.len() as usize;
        let mut out = vec![points.clone()];
        let mut shifted = points.clone();
        shifted
            .coords
            .iter_mut()
            .step_by(dims)
            .for_each(|x| *x += 1);
        out.push(shifted);
        for near in [1, n / 2, n - 2] {
            // Point k between steps k - 1 and k, swapped: the first two
            // unequal steps from `near` on.
            let step = |k: usize| -> Vec<i64> {
                (0..dims)
                    .map(|a| points.coords[k * dims + a] - points.coords[(k - 1) * dims + a])
                    .collect()
            };
            if let Some(k) = (near.max(1)..n - 1).find(|&k| step(k) != step(k + 1)) {
                let mut swapped = points.clone();
                for a in 0..dims {
                    swapped.coords[k * dims + a] =
                        points.coords[(k - 1) * dims + a] + step(k + 1)[a];
                }
                out.push(swapped);
            }
        }
        out.push(Points {
            dims,
            coords: points.coords[..(n / 2).max(1) * dims].to_vec(),
        });
        let mut longer = points.clone();
        let last = points.get(n as u64 - 1).to_vec();
        longer
            .coords
            .extend(last.iter().enumerate().map(|(a, &c)| c + i64::from(a == 0)));
        out.push(longer);
        out
    }

    /// The first point index below both lengths where the rule's points
    /// and the learner's differ, by the points themselves.
    fn first_differing_point(trace: &Trace, points: &Points) -> Option<u64> {
        (0..points.len().min(trace.steps() + 1)).find(|&k| trace.point(k).coords() != points.get(k))
    }

    #[test]
    fn a_check_made_in_slices_is_the_whole_check_bit_for_bit() {
        let requests = [
            r#"{"algorithm":"regions","from":[0,0,0],"to":[30,17,11]}"#,
            r#"{"algorithm":"bresenham3d","from":[-3,5,2],"to":[40,-9,17],"tie":"hold"}"#,
            r#"{"algorithm":"bresenham2d","from":[0,0],"to":[25,10]}"#,
            r#"{"algorithm":"circle","from":[10,0,0],"to":[0,10,0],"center":[0,0,0],"dir":"ccw","plane":"xy"}"#,
            r#"{"algorithm":"arc-segments","from":[12,0,0],"to":[-12,0,0],"center":[0,0,0],"dir":"cw","plane":"xy"}"#,
            r#"{"algorithm":"helix","from":[10,0,0],"to":[10,0,24],"center":[0,0,0],"dir":"ccw","plane":"xy"}"#,
            r#"{"algorithm":"helix","from":[8,0,0],"to":[8,0,40],"center":[0,0,0],"plane":"xy","turns":2,"method":"segments"}"#,
        ];
        for json in requests {
            let r = request(json);
            let trace = crate::algorithms::run(&r).unwrap();
            for points in deviations(&points_of(&trace)) {
                let whole = check_trace(&r, &trace, &points);
                // The comparison of steps finds the first point that differs.
                let differs = first_differing_point(&trace, &points);
                let kind = whole.first_difference.as_ref().map(|d| d.kind);
                if let Some(k) = differs {
                    assert_eq!(
                        whole.first_difference.as_ref().map(|d| d.point_index),
                        Some(k),
                        "{json}"
                    );
                } else {
                    assert!(
                        !matches!(kind, Some(DifferenceKind::Start | DifferenceKind::Step)),
                        "{json}"
                    );
                }
                let whole_json = serde_json::to_string(&whole).unwrap();
                let combinations = AlsoMatchesPass::new(&r, &points).combinations;
                for units in [1, 7, 64, points.len(), u64::MAX] {
                    let mut pass =
                        CheckPass::new(r.clone(), &trace, points.clone(), points.steps());
                    let mut before = pass.progress();
                    let mut calls = 0;
                    while !before.done {
                        assert_eq!(pass.result(), None, "{json}: a result before the end");
                        let now = pass.advance(units);
                        calls += 1;
                        // Each call does at most its units of comparing, or
                        // one combination at least.
                        assert!(
                            now.steps_compared - before.steps_compared <= units
                                || now.steps_compared == now.steps_shared,
                            "{json}"
                        );
                        if units == 1 && before.stage == CheckStage::Variants {
                            assert_eq!(now.variants_tried, before.variants_tried + 1, "{json}");
                        }
                        assert!(
                            now.variants_tried >= before.variants_tried
                                && now.steps_compared >= before.steps_compared
                        );
                        before = now;
                    }
                    assert_eq!(before.variants_tried, combinations, "{json}");
                    assert_eq!(before.steps_compared, before.steps_shared, "{json}");
                    if units == 1 {
                        assert!(calls as u64 >= combinations, "{json}: {calls} calls");
                    }
                    let sliced = pass.result().unwrap();
                    assert_eq!(sliced, whole, "{json} in slices of {units}");
                    assert_eq!(serde_json::to_string(&sliced).unwrap(), whole_json);
                    // A call after the end changes nothing.
                    assert_eq!(pass.advance(units), before);
                    assert_eq!(pass.result().unwrap(), whole);
                }
            }
        }
    }

    /// A reading of `text` a slice of `units` at a time: its points and
    /// steps, or its error with the line and column.
    fn read_in_slices(text: &str, dims: usize, units: u64) -> Result<PointsRead, Error> {
        let mut reading = TextReading::new(dims, true);
        while !reading.advance(text, units)? {}
        reading.finish()
    }

    #[test]
    fn text_read_in_slices_is_the_one_reading_bit_for_bit() {
        // Plain rows, a header and comments, a printed list (read again as
        // one at its first bracket), a list after a row that is not a point,
        // quoted cells over lines, CR line ends, a byte order mark, and
        // errors: a word, a jump (reported after the whole text), no points.
        let texts = [
            "0,0,0\n1,1,0\n2,1,1\n3,2,1\n",
            "\u{feff}x,y,z\n# start\n0,0,0\n\n1,1,0\r\n2,1,1\r3,2,1",
            "k,x,y,z\n0,0,0,0\n1,1,1,0\n2,2,1,1\n",
            "[(0, 0, 0), (1, 1, 0),\n (2, 1, 1), (3, 2, 1)]\n",
            "points:\n[0, 0, 0]\n[1, 1, 0]\n",
            "\"0\",\"0\",\"0\"\n\"1\",\"1\n\",\"0\"\n",
            "0 0 0\n1 1 # (a list)\n",
            "0,0,0\n1,1,0\n3,1,1\n4,1,1\n",
            "0,0,0\n1,one,0\n",
            "# nothing\n\n",
            "",
        ];
        for text in texts {
            let whole = Points::read_text(text, 3, true);
            for units in [1, 2, 3, 16, u64::MAX] {
                let sliced = read_in_slices(text, 3, units);
                match (&whole, &sliced) {
                    (Ok((p, s)), Ok((q, t))) => {
                        assert!(p == q && s == t, "{text:?} in slices of {units}")
                    }
                    (Err(e), Err(f)) => assert_eq!(
                        (e.to_string(), &e.location),
                        (f.to_string(), &f.location),
                        "{text:?} in slices of {units}"
                    ),
                    _ => panic!("{text:?} in slices of {units}: {whole:?} against {sliced:?}"),
                }
            }
        }
        // The helix's own points as text, in slices of 1 and 65,536 rows.
        let rule = crate::algorithms::trace_json(
            r#"{"algorithm":"helix","from":[30,0,0],"to":[30,0,40],"center":[0,0,0],"turns":3}"#,
        )
        .unwrap();
        let points = points_of(&rule);
        let text: String = (0..points.len())
            .map(|k| format!("{:?}\n", points.get(k)).replace(['[', ']'], ""))
            .collect();
        for units in [1, 65_536] {
            let (read, steps) = read_in_slices(&text, 3, units).unwrap();
            assert_eq!(read, points);
            assert_eq!(steps.unwrap(), points.steps());
        }
    }

    #[test]
    fn a_check_of_text_made_in_slices_is_the_one_call_s_bit_for_bit() {
        let json =
            r#"{"algorithm":"helix","from":[30,0,0],"to":[30,0,40],"center":[0,0,0],"turns":2}"#;
        let rule = crate::algorithms::trace_json(json).unwrap();
        let points = points_of(&rule);
        for changed in deviations(&points) {
            let text: String = (0..changed.len())
                .map(|k| format!("({:?})\n", changed.get(k)))
                .collect();
            let whole = check_text(json, &text);
            for units in [1, 7, 4096, u64::MAX] {
                let mut run = SlicedCheck::from_text(json, text.clone()).unwrap();
                let mut stages = vec![run.progress().stage];
                let sliced = loop {
                    match run.advance(units) {
                        Err(e) => break Err(e),
                        Ok(p) if p.done => break Ok(run.result().unwrap()),
                        Ok(p) => {
                            assert_eq!(run.result(), None);
                            if stages.last() != Some(&p.stage) {
                                stages.push(p.stage);
                            }
                        }
                    }
                };
                assert_eq!(stages[0], CheckStage::Reading);
                match (&whole, &sliced) {
                    (Ok(a), Ok(b)) => assert_eq!(
                        serde_json::to_string(a).unwrap(),
                        serde_json::to_string(b).unwrap()
                    ),
                    (Err(e), Err(f)) => assert_eq!(e.to_string(), f.to_string()),
                    _ => panic!("in slices of {units}: {whole:?} against {sliced:?}"),
                }
            }
        }
    }

    #[test]
    fn every_example_matches_itself_and_everything_it_also_matches() {
        for info in algorithms::ALGORITHMS {
            let mut json: Value = serde_json::from_str(info.example.options).unwrap();
            json["algorithm"] = info.id.into();
            let r = request(&json.to_string());
            let trace = crate::algorithms::run(&r).unwrap();
            let points = points_of(&trace);
            let result = check_trace(&r, &trace, &points);
            assert!(result.matches, "{}: {:?}", info.id, result.first_difference);
            assert!(
                result.also_matches.iter().any(|m| m.algorithm == info.id),
                "{} is not among its own matches: {:?}",
                info.id,
                result.also_matches
            );
            for entry in &result.also_matches {
                let other = entry_request(&r, entry);
                let trace = crate::algorithms::run(&other).unwrap();
                let again = check_trace(&other, &trace, &points);
                assert!(again.matches, "{}: {} does not match", info.id, entry.label);
            }
        }
    }

    #[test]
    fn regions_against_bresenham3d_with_tie_hold() {
        let hold = crate::algorithms::trace_json(
            r#"{"algorithm":"bresenham3d","from":[0,0,0],"to":[10,7,6],"tie":"hold"}"#,
        )
        .unwrap();
        let result = check(
            r#"{"algorithm":"regions","from":[0,0,0],"to":[10,7,6]}"#,
            &points_of(&hold),
        );
        assert!(!result.matches);
        let d = result.first_difference.unwrap();
        assert_eq!(d.kind, DifferenceKind::Step);
        assert_eq!(d.point_index, 5);
        let regions = crate::algorithms::trace_json(
            r#"{"algorithm":"regions","from":[0,0,0],"to":[10,7,6]}"#,
        )
        .unwrap();
        assert_eq!(d.why, regions.explain(4));
        assert!(
            d.why.contains("region g") || d.why.contains("segment g"),
            "{}",
            d.why
        );
        let decisions: Map<String, Value> = d.decisions.iter().cloned().collect();
        assert_eq!(decisions["tie"], Value::from(true));
        assert_eq!(decisions["region"], Value::from("g"));
        let labels: Vec<&str> = result
            .also_matches
            .iter()
            .map(|m| m.label.as_str())
            .collect();
        assert!(
            labels.contains(&"bresenham3d with tie = hold"),
            "{labels:?}"
        );
        assert!(
            !labels
                .iter()
                .any(|l| l.starts_with("regions with tie = advance"))
        );
        assert_eq!(d.around.first().unwrap().point_index, 2);
        assert_eq!(d.around.last().unwrap().point_index, 8);
    }

    #[test]
    fn a_circle_in_x_and_y_is_listed_once() {
        // It refuses plane zx and yz, traced then without plane, that is in
        // xy: listed as well as "with plane = xy" before.
        let json = r#"{"algorithm":"circle","from":[5,0],"to":[5,0],"center":[0,0]}"#;
        let circle = crate::algorithms::trace_json(json).unwrap();
        let result = check(json, &points_of(&circle));
        let labels: Vec<&str> = result
            .also_matches
            .iter()
            .filter(|m| m.algorithm == "circle")
            .map(|m| m.label.as_str())
            .collect();
        assert_eq!(labels, ["circle with dir = ccw, plane = xy"]);
    }

    #[test]
    fn a_chord_option_of_the_request_does_not_hide_the_helix_by_saleem_s_method() {
        // Saleem's helix, checked against the helix in chords of a given
        // length or tolerance (compare mode's pair), or against arc-segments
        // on a flat arc: the request's segmentLength or tolerance went to
        // the helix with method saleem too, which refused it, so the points'
        // own rule was never listed.
        let saleem = crate::algorithms::trace_json(
            r#"{"algorithm":"helix","from":[10,0,0],"to":[0,10,6],"center":[0,0,0]}"#,
        )
        .unwrap();
        for chords in [r#""segmentLength":4"#, r#""tolerance":0.25"#] {
            let json = format!(
                r#"{{"algorithm":"helix","from":[10,0,0],"to":[0,10,6],"center":[0,0,0],"method":"segments",{chords}}}"#
            );
            let result = check(&json, &points_of(&saleem));
            assert!(!result.matches, "{chords}");
            let labels: Vec<&str> = result
                .also_matches
                .iter()
                .map(|m| m.label.as_str())
                .collect();
            assert_eq!(
                labels,
                ["helix with dir = ccw, plane = xy, method = saleem"],
                "{chords}"
            );
        }
        let flat = r#"{"algorithm":"circle","from":[10,0,0],"to":[0,10,0],"center":[0,0,0]}"#;
        let circle = crate::algorithms::trace_json(flat).unwrap();
        let result = check(
            r#"{"algorithm":"arc-segments","from":[10,0,0],"to":[0,10,0],"center":[0,0,0],"segmentLength":4}"#,
            &points_of(&circle),
        );
        let algorithms: Vec<&str> = result
            .also_matches
            .iter()
            .map(|m| m.algorithm.as_str())
            .collect();
        assert_eq!(algorithms, ["circle", "helix"]);
        // Each entry, with the request's options that apply to it, traces
        // the points.
        let r = request(
            r#"{"algorithm":"arc-segments","from":[10,0,0],"to":[0,10,0],"center":[0,0,0],"segmentLength":4}"#,
        );
        for entry in &result.also_matches {
            let other = entry_request(&r, entry);
            let trace = crate::algorithms::run(&other).unwrap();
            assert!(check_trace(&other, &trace, &points_of(&circle)).matches);
        }
    }

    #[test]
    fn the_printed_2d_variant_is_named_with_its_erratum() {
        let printed = crate::algorithms::trace_json(
            r#"{"algorithm":"bresenham2d","from":[0,0],"to":[10,3],"variant":"printed"}"#,
        )
        .unwrap();
        let result = check(
            r#"{"algorithm":"bresenham2d","from":[0,0],"to":[10,3]}"#,
            &points_of(&printed),
        );
        assert!(!result.matches);
        let entry = result
            .also_matches
            .iter()
            .find(|m| m.algorithm == "bresenham2d")
            .expect("the printed variant matches");
        assert!(entry.label.contains("variant = printed"), "{}", entry.label);
        assert_eq!(
            entry.errata,
            vec![algorithms::find("bresenham2d").unwrap().errata[0]]
        );
    }

    #[test]
    fn a_trace_following_other_steps_stops_where_they_part() {
        let json = r#"{"algorithm":"regions","from":[0,0,0],"to":[10,7,6]}"#;
        let own = points_of(&crate::algorithms::trace_json(json).unwrap()).steps();
        let r = request(json);
        let again = crate::algorithms::run(&r.clone().following(own.clone())).unwrap();
        assert_eq!(again.steps(), own.len() as u64);
        let hold = crate::algorithms::trace_json(
            r#"{"algorithm":"regions","from":[0,0,0],"to":[10,7,6],"tie":"hold"}"#,
        )
        .unwrap();
        let Err(e) = crate::algorithms::run(&r.following(points_of(&hold).steps())) else {
            panic!("a trace that parts from the steps it follows stops")
        };
        assert_eq!(e.field_name(), Some("follow"));
        assert_eq!(
            e.to_string(),
            "follow: the path parts from the steps it follows at step 4"
        );
    }

    #[test]
    fn truncated_and_extended_paths_are_caught() {
        let json = r#"{"algorithm":"regions","from":[0,0,0],"to":[10,7,6]}"#;
        let trace = crate::algorithms::trace_json(json).unwrap();
        let full = points_of(&trace);
        let mut short = full.clone();
        short.coords.truncate(8 * 3);
        let d = check(json, &short).first_difference.unwrap();
        assert_eq!((d.kind, d.point_index), (DifferenceKind::Stops, 8));
        assert_eq!(d.message, "your path stops at step 7 of 10");
        assert_eq!(d.why, trace.explain(7));
        assert_eq!(d.got, None);

        let mut long = full.clone();
        long.coords.extend_from_slice(&[11, 7, 6]);
        let d = check(json, &long).first_difference.unwrap();
        assert_eq!((d.kind, d.point_index), (DifferenceKind::GoesOn, 11));
        assert_eq!(d.message, "your path goes on after the end");
        assert_eq!(d.expected, None);
        assert_eq!(d.got, Some(vec![11, 7, 6]));
        assert!(d.decisions.is_empty());

        let mut moved = full;
        moved.coords[0] = 1;
        let d = check(json, &moved).first_difference.unwrap();
        assert_eq!(
            (d.kind, d.point_index, d.step_index),
            (DifferenceKind::Start, 0, None)
        );
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        #[test]
        fn a_one_cell_change_is_found_at_its_step(
            to in proptest::collection::vec(-40i64..40, 3),
            at in 0.0f64..1.0,
            axis in 0usize..3,
            algorithm in proptest::sample::select(vec!["regions", "bresenham3d", "nd", "dda", "greedy", "walk6"]),
        ) {
            let json = format!(r#"{{"algorithm":"{algorithm}","from":[0,0,0],"to":{to:?}}}"#);
            let trace = crate::algorithms::trace_json(&json).unwrap();
            prop_assume!(trace.steps() > 0);
            let mut points = points_of(&trace);
            let k = ((at * trace.steps() as f64) as u64).min(trace.steps());
            // Move one coordinate of point k by one cell, the way that keeps
            // it a path only if it stays within a cell of its neighbours;
            // either the check finds point k, or the input is refused there.
            let i = k as usize * 3 + axis;
            points.coords[i] += 1;
            match points.check_path() {
                Ok(()) => {
                    let d = check(&json, &points).first_difference.unwrap();
                    prop_assert_eq!(d.point_index, k);
                    prop_assert_eq!(d.got, Some(points.get(k).to_vec()));
                }
                Err((index, _)) => prop_assert!(index as u64 == k || index as u64 == k + 1),
            }
        }
    }

    /// Every combination of tried values of `info`, as odometer order gives them.
    fn combinations(tried: &[(&OptionSpec, Vec<Value>)]) -> Vec<Vec<Option<Value>>> {
        let mut out = Vec::new();
        let mut choice = vec![0usize; tried.len()];
        loop {
            out.push(
                tried
                    .iter()
                    .zip(&choice)
                    .map(|((_, values), &i)| Some(values[i].clone()))
                    .collect(),
            );
            if !next_combination(&mut choice, tried) {
                return out;
            }
        }
    }

    /// The full path (steps, not following any) of `info` on `base`'s line
    /// with the combination's values, or None where it does not trace.
    fn full_path(
        info: &AlgorithmInfo,
        base: &Request,
        tried: &[(&OptionSpec, Vec<Value>)],
        combination: &[Option<Value>],
    ) -> Option<Vec<Step>> {
        let mut options = Map::new();
        for name in [FROM.name, TO.name] {
            options.insert(name.to_string(), base.options()[name].clone());
        }
        for ((spec, _), value) in tried.iter().zip(combination) {
            options.insert(spec.name.to_string(), value.clone()?);
        }
        let trace = (info.trace)(&Request::new(info.id, options), algorithms::find).ok()?;
        Some(trace.step_range(0, trace.steps()).to_vec())
    }

    /// A move's end: a round longest distance (10, 25, 1000, ... whose
    /// slopes are short decimals) or any, the other axes anywhere up to it,
    /// in any order and direction.
    fn line_end() -> impl Strategy<Value = Vec<i64>> {
        (
            prop_oneof![
                proptest::sample::select(vec![
                    1i64, 2, 4, 5, 8, 10, 16, 20, 25, 40, 50, 64, 80, 100, 125, 200, 250, 1000
                ]),
                1i64..300,
            ],
            0.0f64..=1.0,
            0.0f64..=1.0,
            0usize..3,
            proptest::collection::vec(proptest::bool::ANY, 3),
        )
            .prop_map(|(n, a, b, major, negative)| {
                let mut end = vec![
                    n,
                    (a * n as f64).round() as i64,
                    (b * n as f64).round() as i64,
                ];
                end.swap(0, major);
                for (c, &neg) in end.iter_mut().zip(&negative) {
                    if neg {
                        *c = -*c;
                    }
                }
                end
            })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        /// What alsoMatches takes without tracing is so: on random lines,
        /// each combination [`same_path_as`] pairs with an earlier one has
        /// that one's full path, step for step.
        #[test]
        fn combinations_paired_without_tracing_have_the_same_path(from in proptest::collection::vec(-50i64..50, 3), end in line_end()) {
            let to: Vec<i64> = from.iter().zip(&end).map(|(f, e)| f + e).collect();
            let base = request(&format!(r#"{{"algorithm":"regions","from":{from:?},"to":{to:?}}}"#));
            for info in algorithms::ALGORITHMS.iter().filter(|a| a.family == Family::Line) {
                let tried = tried_options(info);
                let all = combinations(&tried);
                for (at, combination) in all.iter().enumerate() {
                    let Some((id, earlier)) = same_path_as(info, &base, &tried, combination) else {
                        continue;
                    };
                    let position = |id| algorithms::ALGORITHMS.iter().position(|a| a.id == id);
                    let other = algorithms::find(id).unwrap();
                    let other_tried = tried_options(other);
                    prop_assert!(
                        position(id) < position(info.id) || (id == info.id && all[..at].contains(&earlier)),
                        "{}: {:?} pairs with a later {} {:?}", info.id, combination, id, earlier
                    );
                    prop_assert_eq!(
                        full_path(info, &base, &tried, combination),
                        full_path(other, &base, &other_tried, &earlier),
                        "{}: {:?} and {} {:?}", info.id, combination, id, earlier
                    );
                }
            }
        }

        /// alsoMatches against every combination's full path: on a random
        /// line, the points of a random rule are matched by an entry for
        /// exactly the combinations whose full path they are.
        #[test]
        fn also_matches_names_every_combination_whose_full_path_is_the_points(
            end in line_end(),
            algorithm in proptest::sample::select(vec!["regions", "bresenham3d", "nd", "liu-float", "dda", "greedy", "walk6"]),
            tie in proptest::sample::select(vec!["advance", "hold"]),
            decimals in 0i64..=10,
        ) {
            let options = match algorithm {
                "liu-float" => format!(r#","tie":"{tie}","decimals":{decimals}"#),
                "regions" | "bresenham3d" | "nd" => format!(r#","tie":"{tie}""#),
                _ => String::new(),
            };
            let json = format!(r#"{{"algorithm":"{algorithm}","from":[0,0,0],"to":{end:?}{options}}}"#);
            let r = request(&json);
            let points = points_of(&crate::algorithms::run(&r).unwrap());
            let steps = points.steps();
            let entries = also_matches(&r, &points, &steps);
            for info in algorithms::ALGORITHMS.iter().filter(|a| a.family == Family::Line) {
                let tried = tried_options(info);
                for combination in combinations(&tried) {
                    let same = full_path(info, &r, &tried, &combination).as_deref() == Some(&steps[..]);
                    let named = entries.iter().any(|e| {
                        e.algorithm == info.id
                            && e.options.iter().all(|(name, value)| {
                                tried.iter().zip(&combination).any(|((spec, _), v)| spec.name == name && v.as_ref() == Some(value))
                            })
                    });
                    prop_assert_eq!(same, named, "{}: {:?} in {:?}", info.id, combination, entries);
                }
            }
        }
    }

    /// alsoMatches with no combination taken from another: each traced
    /// as asked (an option it refuses left out and the trace made again),
    /// as alsoMatches was made before the combinations that leave out the
    /// same options were traced once.
    fn also_matches_tracing_each(request: &Request, points: &Points) -> Vec<AlsoMatch> {
        let steps = points.steps();
        let family = family_of(request).unwrap();
        let max_steps = request.max_steps().unwrap_or(0).min(points.len() - 1);
        let mut out = Vec::new();
        for info in algorithms::ALGORITHMS.iter().filter(|a| a.family == family) {
            let mut trial = AlgorithmTrial::new(info, request, max_steps);
            for mut combination in combinations(&trial.tried) {
                let traced =
                    trace_combination(info, &trial.base, &trial.tried, &steps, &mut combination);
                if traced.is_some_and(|t| follows(&t, points, &steps))
                    && !trial.matched.contains(&combination)
                {
                    trial.matched.push(combination);
                }
            }
            out.extend(trial.finish());
        }
        out
    }

    /// An arc, a helix or a circle: from (r, 0) about a center near the
    /// origin to a point a quarter, half or three quarters round (or back
    /// at the start), with turns, a rise for the helix, any direction,
    /// plane, method, tie and chords' line algorithm.
    fn arc_request() -> impl Strategy<Value = String> {
        (
            (1i64..25, -3i64..3, -3i64..3, 0usize..4, 0u64..3),
            (
                -40i64..40,
                proptest::sample::select(vec!["circle", "arc-segments", "helix"]),
                proptest::sample::select(vec!["xy", "zx", "yz"]),
                proptest::sample::select(vec!["ccw", "cw"]),
                proptest::sample::select(vec!["saleem", "segments"]),
                proptest::sample::select(vec!["advance", "hold"]),
                proptest::sample::select(LINE_ALGORITHMS.to_vec()),
                prop_oneof![Just(String::new()), (1u32..8).prop_map(|l| format!(r#","segmentLength":{l}"#))],
            ),
        )
            .prop_map(|((r, cu, cv, quarter, turns), (rise, algorithm, plane, dir, method, tie, line, chords))| {
                let axes: [usize; 3] = match plane {
                    "xy" => [0, 1, 2],
                    "zx" => [2, 0, 1],
                    _ => [1, 2, 0],
                };
                let at = |u: i64, v: i64, w: i64| {
                    let mut p = [0i64; 3];
                    p[axes[0]] = cu + u;
                    p[axes[1]] = cv + v;
                    p[axes[2]] = w;
                    p
                };
                let (u, v) = [(r, 0), (0, r), (-r, 0), (0, -r)][quarter];
                let (center, from) = (at(0, 0, 0), at(r, 0, 0));
                let rise = if algorithm == "helix" { rise } else { 0 };
                let to = at(u, v, rise);
                let options = match algorithm {
                    "circle" => String::new(),
                    "arc-segments" => format!(r#","lineAlgorithm":"{line}"{chords}"#),
                    _ if method == "segments" => format!(r#","method":"segments","lineAlgorithm":"{line}","tie":"{tie}"{chords}"#),
                    _ => format!(r#","tie":"{tie}"{chords}"#),
                };
                let tie = if algorithm == "arc-segments" && ["regions", "bresenham3d", "nd", "liu-float"].contains(&line) {
                    format!(r#","tie":"{tie}""#)
                } else {
                    String::new()
                };
                format!(
                    r#"{{"algorithm":"{algorithm}","from":{from:?},"to":{to:?},"center":{center:?},"plane":"{plane}","dir":"{dir}","turns":{turns}{options}{tie}}}"#
                )
            })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]
        /// Combinations that leave out the same options are traced once
        /// ([`leave_out_inapplicable`]): on random arcs and helices, their
        /// own points and those points changed, alsoMatches is what
        /// tracing every combination gives, entry for entry.
        #[test]
        fn also_matches_is_every_combination_traced_on_its_own(json in arc_request(), change in 0usize..8) {
            let r = request(&json);
            let rule = match crate::algorithms::run(&r) {
                Ok(rule) => rule,
                // A chord option given with Saleem's method, or a helix whose rise the circle cannot carry.
                Err(_) => return Ok(()),
            };
            let all = deviations(&points_of(&rule));
            let points = &all[change % all.len()];
            let steps = points.steps();
            prop_assert_eq!(also_matches(&r, points, &steps), also_matches_tracing_each(&r, points), "{}", json);
        }
    }

    /// Where a reading of text failed, without the column: a quoted cell
    /// starts a byte later than the same cell unquoted.
    fn line_and_message(result: Result<Points, Error>) -> Result<Vec<i64>, (String, String)> {
        result.map(|p| p.coords).map_err(|e| {
            let text = e.to_string();
            let (line, rest) = text.split_once(", column ").unwrap();
            let (_, message) = rest.split_once(": ").unwrap();
            (line.to_string(), message.to_string())
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(512))]
        /// Any text, made of the pieces a points file is made of and of
        /// characters it should not hold (a byte order mark, wide and
        /// invisible characters), is read or refused with a line and a
        /// column, never a panic.
        #[test]
        fn any_text_is_read_or_refused_never_a_panic(
            dims in 2usize..7,
            pieces in proptest::collection::vec(
                prop_oneof![
                    "[0-9]{1,20}", "[-+]", Just(",".to_string()), Just(" ".to_string()),
                    Just("\n".to_string()), Just("\r".to_string()), Just("\t".to_string()),
                    Just("\u{feff}".to_string()), Just("\u{a0}".to_string()), Just("é".to_string()),
                    "[xyzabcXYZk#\\[\\]()\".;]{1,3}", Just("nan".to_string()), Just("1e400".to_string()),
                ],
                0..40,
            ),
        ) {
            let text: String = pieces.concat();
            match Points::from_text(&text, dims) {
                Ok(points) => prop_assert_eq!(points.coords.len() % dims, 0),
                Err(e) => {
                    // "line L, column C: what is wrong", L and C from 1.
                    let message = e.to_string();
                    let place = message.strip_prefix("line ").and_then(|rest| rest.split_once(": "));
                    let located = place.and_then(|(at, what)| {
                        let (line, column) = at.split_once(", column ")?;
                        Some(line.parse::<u32>().ok()? >= 1 && column.parse::<u32>().ok()? >= 1 && !what.is_empty())
                    });
                    prop_assert_eq!(located, Some(true), "{}", message);
                }
            }
        }

        /// The plain rows' quick path reads what the general reading reads:
        /// the same text with every cell in quotes (which only the general
        /// reading takes) gives the same points, or fails at the same line
        /// with the same message.
        #[test]
        fn plain_rows_read_as_quoted_rows_do(
            dims in 2usize..4,
            header in proptest::sample::select(vec!["", "x,y,z\n", "z;y;x;k\n", "a b\n", "# points\n"]),
            rows in proptest::collection::vec(
                (
                    proptest::collection::vec(
                        prop_oneof![
                            6 => "[+-]?[01]",
                            2 => "[+-]?[0-9]{1,17}",
                            1 => "[+-]|0x1|1\\.5|1e3|x",
                        ],
                        0..5,
                    ),
                    proptest::sample::select(vec![",", ", ", " ", "\t", ";", ",,", " \t"]),
                    proptest::sample::select(vec!["\n", "\r\n", "\r", "\n\n", "\n# 1,2\n", "\n  \n", "\n,\n"]),
                ),
                0..12,
            ),
        ) {
            let write = |quote: &str| -> String {
                let mut text = header.to_string();
                for (cells, separator, end) in &rows {
                    let quoted: Vec<String> = cells.iter().map(|c| format!("{quote}{c}{quote}")).collect();
                    text += &quoted.join(separator);
                    text += end;
                }
                text
            };
            prop_assert_eq!(
                line_and_message(Points::from_text(&write(""), dims)),
                line_and_message(Points::from_text(&write("\""), dims))
            );
            // The steps made while reading are the points' steps.
            for quote in ["", "\""] {
                if let Ok((points, steps)) = Points::read_text(&write(quote), dims, true) {
                    prop_assert_eq!(steps, Some(points.steps()));
                }
            }
        }
    }

    #[test]
    fn quoted_cells_hold_separators_quotes_and_line_breaks_as_rfc_4180_writes_them() {
        // A spreadsheet's label column: commas, a semicolon, a doubled
        // quote, a bracket and line breaks (LF, CR LF) inside quotes.
        for text in [
            "note,x,y,z\n\"start, (left)\",0,0,0\n\"then\nup; \"\"fast\"\"\",1,1,1\n2,2,2,2\n",
            "x;y;z;note\r\n0;0;0;\"a\r\nb\"\r\n1;1;1;\"\"\r\n",
            "\"x\" \"y\" \"z\"\n\"0\" \"0\" \"0\"\n1 1 1\n",
        ] {
            let points = Points::from_text(text, 3).unwrap_or_else(|e| panic!("{text:?}: {e}"));
            assert_eq!(
                points.len(),
                2 + u64::from(text.contains("2,2")),
                "{text:?}"
            );
            assert_eq!(points.get(1), [1, 1, 1], "{text:?}");
        }
        // After a row that spans lines, errors name the lines as they are
        // in the file, and a cell after a break inside the row its own
        // line and column.
        let message = |text: &str| Points::from_text(text, 3).unwrap_err().to_string();
        assert_eq!(
            message("note,x,y,z\n\"a\nb\nc\",0,0,0\nd,1,1,x\n"),
            "line 5, column 7: point 1: z = 'x' is not a number"
        );
        assert_eq!(
            message("x,y,z,note\n0,0,0,\"a\nb\"\n1,1,\"\nq\",\"c\"\n"),
            "line 4, column 6: point 1: z = '\\u{a}q' is not a number"
        );
        assert_eq!(
            message("x,y,z\n0,0,\"0\n1,1,1\n"),
            "line 2, column 5: a quote that is not closed: a quoted cell ends at its closing quote, which may stand on a later line"
        );
        assert_eq!(
            message("x,y,z\n0,0,\"0\"1\n"),
            "line 2, column 8: '1' after a quoted cell's closing quote: a comma, a semicolon or a blank comes next"
        );
        // A quote inside a cell is the cell's own (an inch mark).
        assert_eq!(
            message("x,y,z\n0,0,5\"\n"),
            "line 2, column 5: point 0: z = '5\"' is not a number"
        );
        // A bracket inside quotes does not make the text a printed list.
        let labelled = "x,y,z,note\n0,0,0,\"(start)\"\n1,0,0,\"[1]\"\n";
        assert_eq!(
            Points::from_text(labelled, 3).unwrap().coords,
            [0, 0, 0, 1, 0, 0]
        );
    }

    #[test]
    fn an_empty_csv_cell_keeps_its_column_s_place() {
        // A run of commas counted as one separator: the label column's
        // empty cells shifted every coordinate one column left, silently.
        let labelled = "label,x,y,z,k\nstart,0,0,0,0\n,1,1,1,1\n,2,1,1,2\n";
        assert_eq!(
            Points::from_text(labelled, 3).unwrap().coords,
            vec![0, 0, 0, 1, 1, 1, 2, 1, 1]
        );
        assert_eq!(
            Points::from_text("note,x,y,z\n,1,1,1\n", 3).unwrap().coords,
            vec![1, 1, 1]
        );
        // An empty coordinate is an error at its column, not a 0 or a shift.
        for (text, column) in [
            ("x,y,z\n0,,0,0\n", 3),
            ("0,0,0\n1,;1,1\n", 3),
            (",0,0,0\n", 1),
        ] {
            let e = Points::from_text(text, 3).unwrap_err();
            assert!(
                e.message.contains(
                    "an empty cell, between two commas or semicolons or before the first"
                ),
                "{text}: {e}"
            );
            let crate::error::Location::Source { column: at, .. } = e.location else {
                panic!("{text}: {e} has no column");
            };
            assert_eq!(at, column, "{text}");
        }
        // Trailing commas (a spreadsheet's empty columns) and blanks around cells are not cells.
        assert_eq!(
            Points::from_text("0, 0 ,0,,\n1 ,1,1,\n", 3).unwrap().coords,
            vec![0, 0, 0, 1, 1, 1]
        );
    }

    #[test]
    fn text_reads_csv_headers_lists_and_blank_separated_rows() {
        let csv = "k,x,y,z,M\n0,0,0,0,\n1,1,1,1,0\n";
        assert_eq!(
            Points::from_text(csv, 3).unwrap().coords,
            vec![0, 0, 0, 1, 1, 1]
        );
        let blank = "# a comment\n0 0 0\n\n1 1 0\n";
        assert_eq!(
            Points::from_text(blank, 3).unwrap().coords,
            vec![0, 0, 0, 1, 1, 0]
        );
        let printed = "[ [ 0, 0, 0 ], [ 1, 0, 1 ] ]";
        assert_eq!(
            Points::from_text(printed, 3).unwrap().coords,
            vec![0, 0, 0, 1, 0, 1]
        );
        let python = "[(0, 0), (1, -1)]";
        assert_eq!(
            Points::from_text(python, 2).unwrap().coords,
            vec![0, 0, 1, -1]
        );
        // A bracket anywhere makes the text a list, even after rows read
        // as lines, or after a line that is not a point.
        for text in [
            "5 5 5\n[1, 1, 1]",
            "0,0,0\n1,a\n[[1, 1, 1]]",
            "# 1 2\n1 1 1\n(1 1 1)",
        ] {
            assert_eq!(Points::from_text(text, 3).unwrap().coords, vec![1, 1, 1]);
        }
    }

    #[test]
    fn a_comment_line_is_its_line_whatever_it_holds() {
        let rows = "0,0,0\n1,1,0\n2,1,1\n";
        let all = vec![0, 0, 0, 1, 1, 0, 2, 1, 1];
        // Brackets in a comment are words, not points: they made the whole
        // text a printed list, whose points were the comment's
        // ("point 1 (4, 2, 1) is more than one cell from point 0").
        for comment in [
            "# regions from (0,0,0) to (4,2,1)",
            "# points (x, y, z)",
            "  # [a list]",
        ] {
            let text = format!("{comment}\n{rows}");
            assert_eq!(Points::from_text(&text, 3).unwrap().coords, all, "{text}");
            let listed = format!("{comment}\n[(0, 0, 0), (1, 1, 0)]\n{comment}\n[(2, 1, 1)]");
            assert_eq!(
                Points::from_text(&listed, 3).unwrap().coords,
                all,
                "{listed}"
            );
        }
        // A quote in a comment opens no quoted cell: one did, and the rows
        // after it to the next quote, or to the end, went unread with the
        // comment ("there are no points", or a path that stops early).
        for text in [
            "# a 5\" long line\n0,0,0\n1,1,0\n2,1,1\n",
            "0,0,0\n# \"skip\n1,1,0\n2,1,1\n",
            "0,0,0\n# \"left\n1,1,0\n# right\"\n2,1,1\n",
            "x,y,z\n# \"\n0,0,0\r\n1,1,0\r2,1,1",
        ] {
            assert_eq!(Points::from_text(text, 3).unwrap().coords, all, "{text}");
        }
        // Not a comment: a # past the line's first character.
        assert_eq!(
            Points::from_text("0 0 0\n1 1 # (a list)\n", 3)
                .unwrap_err()
                .to_string(),
            "line 2, column 8: point 0: 'a' is not a number, and a point is its 3 coordinates alone"
        );
    }

    #[test]
    fn a_first_line_with_numbers_is_a_point_and_a_header_names_every_axis_or_none() {
        let e = |text: &str| Points::from_text(text, 3).unwrap_err().to_string();
        // Each was taken for a header and dropped, the points read from line 2.
        assert_eq!(
            e("1 2 three\n1 1 1\n"),
            "line 1, column 5: point 0: z = 'three' is not a number"
        );
        assert_eq!(
            e("0,0,0x1\n1,1,1\n"),
            "line 1, column 5: point 0: z = '0x1' is not a number"
        );
        assert_eq!(
            e("0,0,0 # start\n1,1,1\n"),
            "line 1, column 7: point 0: '#' is not a number, and a point is its 3 coordinates alone"
        );
        assert_eq!(
            e("0 0 0\n1 1 1 label\n"),
            "line 2, column 7: point 1: 'label' is not a number, and a point is its 3 coordinates alone"
        );
        // k, x, y read k as x.
        assert_eq!(
            e("k,x,y\n0,5,5\n"),
            "line 1, column 1: the header has no z column; the move has 3 axes (x, y, z)"
        );
        // x, y and a third column for 3 axes: w is not z.
        assert_eq!(
            e("x,y,w\n0,0,9\n"),
            "line 1, column 1: the header has no z column; the move has 3 axes (x, y, z)"
        );
        assert_eq!(
            e("x,y\n0,0\n"),
            "line 1, column 1: the header has no z column; the move has 3 axes (x, y, z)"
        );
        assert_eq!(
            e("x,x,y,z\n0,1,0,0\n"),
            "line 1, column 3: the header names x twice, in columns 1 and 2"
        );
        // x, y and z for a move in x and y: z was dropped unread, and
        // points whose z wandered followed the 2D rule. Found by a hunt.
        assert_eq!(
            Points::from_text("x,y,z\n0,0,0\n1,0,1\n", 2)
                .unwrap_err()
                .to_string(),
            "line 1, column 5: the header names z, an axis the move does not have: its 2 axes are x, y"
        );
        assert_eq!(
            Points::from_text("X;Y;Time;C\n0;0;0;0\n", 2)
                .unwrap_err()
                .to_string(),
            "line 1, column 10: the header names C, an axis the move does not have: its 2 axes are x, y"
        );
        assert_eq!(
            Points::from_text("x,y,time\n3,4,0\n", 2).unwrap().coords,
            vec![3, 4]
        );
        assert_eq!(
            e("a,b\n0,0\n"),
            "line 1, column 1: the header names none of x, y, z and has 2 columns, fewer than the move's 3 axes"
        );
        // Names in their own columns are read in place past z: x, y, z, w
        // for 4 axes (the fourth axis is called a) was refused for its
        // missing a.
        assert_eq!(
            Points::from_text("x,y,z,w\n1,2,3,4\n", 4).unwrap().coords,
            vec![1, 2, 3, 4]
        );
        // A header cell that Rust's float reader takes (nan, inf) is still text.
        assert_eq!(
            Points::from_text("nan,x,y,z\n9,1,2,3\n", 3).unwrap().coords,
            vec![1, 2, 3]
        );
        // A header of no axis names is its first columns, as before.
        assert_eq!(
            Points::from_text("a b c d\n1 2 3 4\n", 3).unwrap().coords,
            vec![1, 2, 3]
        );
        // A byte order mark (a spreadsheet's UTF-8 CSV) is not part of the first line.
        for text in ["\u{feff}0,0,0\n1,1,1\n", "\u{feff}x,y,z\n0,0,0\n1,1,1\n"] {
            assert_eq!(
                Points::from_text(text, 3).unwrap().coords,
                vec![0, 0, 0, 1, 1, 1]
            );
        }
    }

    #[test]
    fn malformed_input_names_the_point_and_line() {
        let e = |text: &str| Points::from_text(text, 3).unwrap_err().to_string();
        assert_eq!(
            e("0,0,0\n1,1\n"),
            "line 2, column 1: point 1 has 2 coordinates; the move has 3"
        );
        assert_eq!(
            e("0,0,0\n1,1.5,1\n"),
            "line 2, column 3: point 1: y = 1.5 is not a whole number"
        );
        assert_eq!(
            e("0,0,0\n1,a,1\n"),
            "line 2, column 3: point 1: y = 'a' is not a number"
        );
        // A huge value as JavaScript writes it, not in 301 digits.
        assert_eq!(
            e("0,0,0\n1,1e300,1\n"),
            "line 2, column 3: point 1: y = 1e300 is too large"
        );
        assert_eq!(
            e("0,0,0\n1,1,1\n3,1,1\n"),
            "line 3, column 1: point 2 (3, 1, 1) is more than one cell from point 1 (1, 1, 1): a path moves each axis at most one cell per step"
        );
        assert_eq!(
            e("[[0,0,0],\n [1,2]]"),
            "line 2, column 3: point 1 has 2 coordinates; the move has 3"
        );
        assert_eq!(e("x,y,z\n"), "line 1, column 1: there are no points");
        let f = |values: &[f64], dims| Points::from_flat(values, dims, 3).unwrap_err().to_string();
        assert_eq!(
            f(&[0.0, 0.0], 2),
            "points: the points have 2 coordinates each; the move has 3"
        );
        assert_eq!(
            f(&[0.0], 1),
            "points: the points have 1 coordinate each; the move has 3"
        );
        assert_eq!(
            e("5\n6\n"),
            "line 1, column 1: point 0 has 1 coordinate; the move has 3"
        );
        assert_eq!(
            Points::from_flat::<f64>(&[], 0, 3).unwrap_err().to_string(),
            "points: there are no points"
        );
        assert_eq!(
            f(&[0.0, 0.0, 0.0, 1.0, f64::NAN, 0.0], 3),
            "points: point 1: y is not a number"
        );
        assert_eq!(
            f(&[0.0, 0.0, 0.0, 1.0], 3),
            "points: 4 values are not a whole number of 3-coordinate points"
        );
    }

    #[test]
    fn a_coordinate_is_whole_and_in_range_as_written_not_as_its_double() {
        // Each of these rounds to a double that is a whole number within
        // 2^53, and was read as that number: 0.99999999999999999 as 1,
        // 1e-400 as 0, 2^53 + 1 as 2^53 (and quoted so in the message).
        let e = |text: &str| Points::from_text(text, 3).unwrap_err().to_string();
        assert_eq!(
            e("0,0,0\n1,0.99999999999999999,0\n"),
            "line 2, column 3: point 1: y = 0.99999999999999999 is not a whole number"
        );
        assert_eq!(
            e("1e-400 0 0\n"),
            "line 1, column 1: point 0: x = 1e-400 is not a whole number"
        );
        assert_eq!(
            e("[(0, 0, 1.00000000000000001e0)]"),
            "line 1, column 9: point 0: z = 1.00000000000000001e0 is not a whole number"
        );
        assert_eq!(
            e("0,0,1e-99999999999999999999\n"),
            "line 1, column 5: point 0: z = 1e-99999999999999999999 is not a whole number"
        );
        assert_eq!(
            e("9007199254740993,0,0\n"),
            "line 1, column 1: point 0: x = 9007199254740993 is too large"
        );
        assert_eq!(
            e("0,-9007199254740993,0\n"),
            "line 1, column 3: point 0: y = -9007199254740993 is too large"
        );
        // Whole as written, in any notation, and 2^53 itself.
        assert_eq!(
            Points::from_text("1.5e1,150E-1,-0.0\n+16,15.000,0e-99999999999999999999", 3)
                .unwrap()
                .coords,
            vec![15, 15, 0, 16, 15, 0]
        );
        assert_eq!(
            Points::from_text("-9007199254740992,0,0", 3)
                .unwrap()
                .coords,
            vec![-(1 << 53), 0, 0]
        );
    }

    #[test]
    fn a_printed_list_cut_short_inside_a_point_is_an_error_at_its_bracket() {
        // The points before the cut were read and checked as the whole path
        // ("your path stops at step 1"), the cut point dropped unread.
        let e = |text: &str| Points::from_text(text, 3).unwrap_err().to_string();
        for (text, at) in [
            ("[(0, 0, 0), (1, 1, 0), (2,", "line 1, column 24"),
            ("[(0, 0, 0), (1, 1, 0), (", "line 1, column 24"),
            ("[[0, 0, 0],\n [1, 1, 0],\n [2, 1", "line 3, column 2"),
        ] {
            let bracket = &text[text.rfind(['(', '[']).unwrap()..][..1];
            assert_eq!(
                e(text),
                format!(
                    "{at}: '{bracket}' opens a point that the text ends before closing: is the list cut short?"
                )
            );
        }
        // An outer bracket left open after its last point closed loses no point.
        assert_eq!(
            Points::from_text("[(0, 0, 0), (1, 1, 0)", 3)
                .unwrap()
                .coords,
            vec![0, 0, 0, 1, 1, 0]
        );
    }

    #[test]
    fn columns_count_characters_not_bytes() {
        // Each é is two bytes of UTF-8 and ✓ three: the columns were
        // those of the bytes, past where an editor puts the character.
        let e = |text: &str| Points::from_text(text, 3).unwrap_err().to_string();
        for (text, at, what) in [
            (
                "label,x,y,z\né,0,0,0\né,1,1,x",
                "line 3, column 7",
                "point 1: z = 'x' is not a number",
            ),
            (
                "label x y z\néé 0 0 0\néé 1 1 q",
                "line 3, column 8",
                "point 1: z = 'q' is not a number",
            ),
            (
                "label,x,y,z\n\"é\nü\",0,0,1.5",
                "line 3, column 8",
                "point 0: z = 1.5 is not a whole number",
            ),
            (
                "[(0,0,0),(1,1,0)] ✓✓ (1,1)",
                "line 1, column 23",
                "point 2 has 2 coordinates; the move has 3",
            ),
            (
                "[(0,0,0)]\n✓✓✓ (1,1, q)",
                "line 2, column 11",
                "point 1: z = 'q' is not a number",
            ),
            (
                "[(0,0,0)]\n✓ (1,\n ✓, 0)",
                "line 3, column 2",
                "point 1: y = '✓' is not a number",
            ),
            (
                "[(0,0,0)]\r\n✓✓ (5,1,1)",
                "line 2, column 5",
                "point 1 (5, 1, 1) is more than one cell from point 0 (0, 0, 0): a path moves each axis at most one cell per step",
            ),
            (
                "[(0,0,0), (1,1,1)] ✓ (",
                "line 1, column 22",
                "'(' opens a point that the text ends before closing: is the list cut short?",
            ),
        ] {
            assert_eq!(e(text), format!("{at}: {what}"), "{text}");
        }
    }

    /// An Int32Array's values, read as i32, are the points (or the error)
    /// the same values give as JS numbers: a path, a path with a jump,
    /// i32's extremes, a count that is not whole points.
    #[test]
    fn int32_values_read_as_the_same_numbers_do() {
        let cases: [&[i32]; 4] = [
            &[0, 0, 0, 1, 1, 0, 2, 1, 1],
            &[0, 0, 0, 3, 1, 1],
            &[i32::MIN, 0, i32::MAX, i32::MIN + 1, -1, i32::MAX],
            &[0, 0, 0, 1],
        ];
        let read = |points: Result<Points, Error>| {
            points
                .map(|p| (p.dims, p.coords))
                .map_err(|e| e.to_string())
        };
        for ints in cases {
            let numbers: Vec<f64> = ints.iter().map(|&v| v.into()).collect();
            assert_eq!(
                read(Points::from_flat(ints, 3, 3)),
                read(Points::from_flat(&numbers, 3, 3)),
                "{ints:?}"
            );
        }
        assert_eq!(
            read(Points::from_flat(&[i32::MIN, 0, i32::MAX], 3, 3))
                .unwrap()
                .1,
            [i32::MIN as i64, 0, i32::MAX as i64]
        );
    }

    #[test]
    fn lines_end_at_a_lone_cr_and_messages_quote_control_characters() {
        // Lone CR ends were one line of 9 coordinates ("point 0 has 9
        // coordinates"), and a NUL was printed raw inside the message.
        for text in ["0 0 0\r1 1 1\r2 1 1\r", "0 0 0\r\n1 1 1\r\n2 1 1"] {
            assert_eq!(
                Points::from_text(text, 3).unwrap().coords,
                vec![0, 0, 0, 1, 1, 1, 2, 1, 1]
            );
        }
        let e = |text: &str| Points::from_text(text, 3).unwrap_err().to_string();
        assert_eq!(
            e("0 0 0\r1 1\r"),
            "line 2, column 1: point 1 has 2 coordinates; the move has 3"
        );
        assert_eq!(
            e("[(0,0,0),\r(1,1)]"),
            "line 2, column 2: point 1 has 2 coordinates; the move has 3"
        );
        assert_eq!(
            e("[(0,0,0),\r\n(1,1)]"),
            "line 2, column 2: point 1 has 2 coordinates; the move has 3"
        );
        assert_eq!(
            e("0 0 0\n1\u{0} 1 1\n"),
            "line 2, column 1: point 1: x = '1\\u{0}' is not a number"
        );
    }
}
