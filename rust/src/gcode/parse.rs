//! One line of G-code -> a block of codes and words with their columns.
//!
//! The grammar is RS274/NGC's word level, as LinuxCNC and Grbl read it:
//! - a line is words (an address letter, an optional sign, a number;
//!   `G1X10Y5` needs no spaces), G, M and T codes (a letter and a whole
//!   number with at most one digit after its point: G90.1), comments
//!   `( ... )` (to the first `)`, on their line: they do not nest) and `;`
//!   to the end of the line, a line number N and a program number O before
//!   the codes;
//! - blanks and `/` are dropped wherever they stand,
//!   even inside a number, as Grbl drops them before reading a line
//!   (protocol.c): `X1 0` is X10, `/G1 X10` is G1 X10 (block delete is not
//!   supported, its `/` ignored);
//! - `%` stands on a line of its own (blanks and comments aside): it marks
//!   the program's start or end (see `program`), and anywhere else is an
//!   error;
//! - letters are read in either case and kept in upper case;
//! - values are f64, read from the word's own text (so X123.4567 is exactly
//!   what the program says), and must be finite;
//! - a code's number must fit in 32 bits, checked digit by digit: a number
//!   that does not fit is an error at its column, never another code;
//! - a letter other than G and M stands at most once on a line (X1 X2 is
//!   an error at the second X, as LinuxCNC's reader has it), a line holds at
//!   most 16 G codes (one from each modal group: LinuxCNC's block holds
//!   16) and at most 4 M codes (LinuxCNC's MAX_EMS). So a line's block
//!   holds a few dozen entries whatever its length, and a 50 MB line of
//!   repeated words stops at its second word.
//!
//! Each line is read left to right, in time linear in its length: the
//! column of every word is counted as the reader passes it, and the first
//! syntax error ends the line (a line with an error is not run, so nothing
//! after it is needed). Errors and words carry the 1-based column, in
//! characters, of their first character. A plain line (ASCII, each number
//! right after its letter, no `(` comment: what CAM programs are made of)
//! is read by a loop of its own, `read_plain`; any other line, or one it
//! finds anything wrong with, is read again from its start by the reader
//! that knows every rule and words every error.
//!
//! This reader replaced the `gcode` crate (0.7.0): its parser builds code
//! numbers as `major * 10 + minor` in u32, so G2147483649 wrapped to G1;
//! it reads every value as f32; and its push API cannot stop inside a
//! command's argument list, so an error at column 10 of a 50 MB line waited
//! for the rest of the line. Keeping it would have meant lexing every line
//! twice, once to guard it and once to parse it.

use crate::text::{echo, writes_whole_number};
use std::borrow::Cow;

/// A number's text as the line writes it, and whether blanks stand inside
/// it (`1 0`, which is 10). Its text without them is made only where it is
/// read as text (a code's number, a number of more than 15 digits, an
/// error's quote): a `Cow` on every number ran the benchmark's program 8%
/// slower natively.
#[derive(Clone, Copy)]
struct NumberText<'t> {
    raw: &'t str,
    blanks_inside: bool,
}

impl<'t> NumberText<'t> {
    fn text(self) -> Cow<'t, str> {
        if self.blanks_inside {
            Cow::Owned(
                self.raw
                    .bytes()
                    .filter(|&b| !dropped(b))
                    .map(char::from)
                    .collect(),
            )
        } else {
            Cow::Borrowed(self.raw)
        }
    }
}

/// What Grbl drops from a line before reading it (protocol.c) that
/// voxpath drops too: blanks (space, tab, CR, vertical tab, form feed) and
/// '/' (block delete, which Grbl does not support: the character is
/// ignored, the block runs). So blanks may stand anywhere, even inside a
/// number. Grbl drops every other control character as well; voxpath
/// quotes one in an error instead, as a NUL or an escape sequence in a
/// program is a damaged file, not spacing.
fn dropped(byte: u8) -> bool {
    matches!(byte, b' ' | b'\t' | b'\r' | 0x0B | 0x0C | b'/')
}

/// Whether `byte`, past the blanks, starts nothing a line may hold: no
/// letter, number, sign, comment or `%` (a `#`, a `[`, a byte of a
/// character past ASCII).
fn starts_nothing(byte: u8) -> bool {
    !matches!(byte, b';' | b'(' | b')' | b'%' | b'.' | b'-' | b'+') && !byte.is_ascii_alphanumeric()
}

/// An address letter with its value, e.g. or F600.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Word {
    /// Upper case.
    pub letter: char,
    pub value: f64,
    /// 1-based column of the letter.
    pub column: u32,
    /// Whether the number as written is whole ([`writes_whole_number`]),
    /// which its value does not tell past 15 digits: P2.99999999999999999
    /// reads as 3.0, and ran 3 turns.
    pub written_whole: bool,
}

/// [`Word::written_whole`] of a number of at most 15 digits, from its
/// value: whole exactly when the value is, as 15 significant digits
/// survive the trip to f64 and back (DBL_DIG), so a fraction so written
/// cannot read as a whole number. Spares the line's text a second look.
fn short_written_whole(magnitude: f64) -> bool {
    magnitude.fract() == 0.0
}

/// A G, M or T code: G90.1 has number 90 and minor 1.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Code {
    pub letter: char,
    pub number: u32,
    /// The digit after the point (0 when there is none).
    pub minor: u32,
    pub column: u32,
}

impl Code {
    /// "G90.1", "M3".
    pub fn name(&self) -> String {
        if self.minor == 0 {
            format!("{}{}", self.letter, self.number)
        } else {
            format!("{}{}.{}", self.letter, self.number, self.minor)
        }
    }
}

/// A problem at a column of the line.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Problem {
    pub column: u32,
    pub message: String,
}

/// One line of a program.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Block {
    pub codes: Vec<Code>,
    /// Every word of the line, whichever code it follows: in G-code a
    /// line's words belong to the line (RS274/NGC), and the interpreter
    /// decides which command uses them.
    pub words: Vec<Word>,
    /// Things the line says that voxpath ignores (program numbers).
    pub ignored: Vec<Problem>,
    /// The column of the line's `%` when the line is a `%` alone (with
    /// blanks and comments at most): the program's start or end, as
    /// LinuxCNC reads it (see `program`).
    pub percent: Option<u32>,
    /// The line's syntax error, the first one from the left: reading stops
    /// there, and a line with an error is not run.
    pub error: Option<Problem>,
}

/// Parses one line (without its line break) into a block of its own: the
/// tests' way in (a program reads every line with [`parse_line_into`]).
#[cfg(test)]
pub(crate) fn parse_line(text: &str) -> Block {
    let mut block = Block::default();
    parse_line_into(text, &mut block);
    block
}

/// Parses one line into `block`, reusing its vectors (a program reads
/// every line into the same block, so a line allocates nothing).
pub fn parse_line_into(text: &str, block: &mut Block) {
    clear(block);
    if read_plain(text, block) {
        return;
    }
    // Not a plain line: read again by the reader that knows every rule
    // and says what is wrong, from a clean block.
    clear(block);
    block.error = Reader {
        text,
        at: 0,
        column: 1,
    }
    .read(block)
    .err();
}

fn clear(block: &mut Block) {
    block.codes.clear();
    block.words.clear();
    block.ignored.clear();
    block.percent = None;
    block.error = None;
}

/// Reads a plain line into a cleared `block`, as [`Reader::read`] would
/// read it, or returns false (the block then holds part of the line) for
/// any line that is not plain. Plain: ASCII; words and G, M and T codes
/// with their sign and number right after their letter (`X-1.5`, `G90.1`,
/// at most 15 digits, no exponent), a line number N before the codes,
/// spaces, tabs or CRs between them, and a `;` comment at the end; no
/// letter twice, and within the G and M codes a line may hold. That is
/// every line a CAM program is made of, most of them; anything else (a
/// blank inside a number, a `(` comment, `/`, `%`, an O, an error of any
/// kind) goes to the reader, which takes the line from its start.
///
/// Why a second reader: the reader moves a byte offset and a character
/// column together through methods that each allow what Grbl allows (a
/// blank after a letter, inside a number, ...), and that generality cost
/// the benchmark's program about a tenth of its time in wasm. Here every
/// byte is ASCII, so a column is its offset plus one, and one loop reads
/// the line. The property test `plain_lines_are_read_as_the_reader_reads_them`
/// holds the two to the same block on random lines.
fn read_plain(text: &str, block: &mut Block) -> bool {
    let bytes = text.as_bytes();
    let mut at = 0;
    // Bit i: letter 'A' + i has stood on this line (G and M are counted).
    let mut letters_seen = 0u32;
    let (mut g_codes, mut m_codes) = (0, 0);
    let mut seen_code = false;
    loop {
        let Some(&byte) = bytes.get(at) else {
            return true;
        };
        if matches!(byte, b' ' | b'\t' | b'\r') {
            at += 1;
            continue;
        }
        if byte == b';' {
            // The rest is a comment, read as the reader reads it: any bytes.
            return true;
        }
        if !byte.is_ascii_alphabetic() {
            return false;
        }
        let letter = byte.to_ascii_uppercase();
        let column = at as u32 + 1;
        at += 1;
        let full = match letter {
            b'G' => {
                g_codes += 1;
                g_codes > MAX_G_CODES_PER_LINE
            }
            b'M' => {
                m_codes += 1;
                m_codes > MAX_M_CODES_PER_LINE
            }
            _ => {
                let bit = 1 << (letter - b'A');
                let again = letters_seen & bit != 0;
                letters_seen |= bit;
                again
            }
        };
        if full || letter == b'O' || (letter == b'N' && seen_code) {
            return false;
        }
        let negative = bytes.get(at) == Some(&b'-');
        let signed = matches!(bytes.get(at), Some(b'-' | b'+'));
        if signed && matches!(letter, b'G' | b'M' | b'T' | b'N') {
            return false;
        }
        at += usize::from(signed);
        // Digits with at most one point among them, as Reader::decimal.
        let start = at;
        let (mut mantissa, mut digits, mut fraction_digits) = (0u64, 0usize, 0usize);
        let mut point = None;
        loop {
            match bytes.get(at) {
                Some(&b) if b.is_ascii_digit() => {
                    mantissa = mantissa.wrapping_mul(10).wrapping_add(u64::from(b - b'0'));
                    digits += 1;
                    fraction_digits += usize::from(point.is_some());
                }
                Some(b'.') if point.is_none() => point = Some(at),
                _ => break,
            }
            at += 1;
        }
        // What may follow a number: its line's end, a blank, a letter that
        // cannot start an exponent, or a `;`. Anything else (a second
        // point, an exponent, a `(`) is for the reader.
        let ends = match bytes.get(at) {
            None => true,
            Some(&b) => {
                matches!(b, b' ' | b'\t' | b'\r' | b';')
                    || (b.is_ascii_alphabetic() && !matches!(b, b'e' | b'E'))
            }
        };
        if !ends || !(1..=15).contains(&digits) {
            return false;
        }
        match letter {
            b'G' | b'M' | b'T' => {
                // A whole number, or one digit after its point, within u32.
                let (number, minor) = match point {
                    None => (mantissa, 0),
                    Some(p) if p > start && fraction_digits == 1 => (mantissa / 10, mantissa % 10),
                    Some(_) => return false,
                };
                let Ok(number) = u32::try_from(number) else {
                    return false;
                };
                seen_code = true;
                block.codes.push(Code {
                    letter: letter as char,
                    number,
                    minor: minor as u32,
                    column,
                });
            }
            // A line number, read and dropped: whole, within u32.
            b'N' => {
                if point.is_some() || u32::try_from(mantissa).is_err() {
                    return false;
                }
            }
            _ => {
                let magnitude = short_value(mantissa, fraction_digits);
                block.words.push(Word {
                    letter: letter as char,
                    value: if negative { -magnitude } else { magnitude },
                    column,
                    written_whole: short_written_whole(magnitude),
                });
            }
        }
    }
}

/// The value of a number of 1 to 15 digits, `mantissa` with
/// `fraction_digits` of them after its point: the digits as an integer over
/// a power of ten, both exact in f64, so the one rounding of the division
/// gives the correctly rounded value, as `str::parse` does, without its
/// general machinery (most G-code numbers look like 25.655).
fn short_value(mantissa: u64, fraction_digits: usize) -> f64 {
    const POWERS_OF_TEN: [f64; 16] = [
        1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
    ];
    // Through i64 (below 10^15, so exact): wasm converts a signed integer
    // to f64 in one instruction, an unsigned one in several.
    mantissa as i64 as f64 / POWERS_OF_TEN[fraction_digits]
}

/// Most G codes one line may hold: one from each modal group, and
/// LinuxCNC's interpreter has 16 (its block's `g_modes[16]`).
pub const MAX_G_CODES_PER_LINE: usize = 16;
/// Most M codes one line may hold (LinuxCNC's MAX_EMS: "Too many m codes
/// on line").
pub const MAX_M_CODES_PER_LINE: usize = 4;

/// The reader's place in a line: a byte offset and the character column
/// it is at, moved forward together.
struct Reader<'t> {
    text: &'t str,
    at: usize,
    column: u32,
}

type Read<T> = Result<T, Problem>;

fn problem(column: u32, message: String) -> Problem {
    Problem { column, message }
}

/// Lets one more `letter` (upper case) onto the line at `column`, or says
/// why the line cannot hold it: a second X, a 17th G code, a fifth M code.
fn admit(block: &Block, letters_seen: &mut u32, letter: u8, column: u32) -> Read<()> {
    let count_of = |l: char| block.codes.iter().filter(|c| c.letter == l).count();
    let full = match letter {
        b'G' => count_of('G') == MAX_G_CODES_PER_LINE,
        b'M' => count_of('M') == MAX_M_CODES_PER_LINE,
        _ => {
            let bit = 1 << (letter - b'A');
            let again = *letters_seen & bit != 0;
            *letters_seen |= bit;
            if again {
                return Err(problem(
                    column,
                    format!("{} appears twice on this line", letter as char),
                ));
            }
            false
        }
    };
    if full {
        let (most, why) = match letter {
            b'G' => (MAX_G_CODES_PER_LINE, "one from each modal group"),
            _ => (MAX_M_CODES_PER_LINE, "as LinuxCNC has it"),
        };
        return Err(problem(
            column,
            format!(
                "too many {} codes on this line: a line takes at most {most} ({why})",
                letter as char
            ),
        ));
    }
    Ok(())
}

impl<'t> Reader<'t> {
    fn peek(&self) -> Option<u8> {
        self.text.as_bytes().get(self.at).copied()
    }

    /// Moves past one byte; a character's first byte starts a new column.
    fn bump(&mut self) {
        let byte = self.text.as_bytes()[self.at];
        self.at += 1;
        if byte & 0xC0 != 0x80 {
            self.column += 1;
        }
    }

    /// Moves past the bytes `keep` accepts; returns them.
    fn take_while(&mut self, keep: impl Fn(u8) -> bool) -> &'t str {
        // As bump() byte by byte, on locals: the loop runs over every
        // number and blank of a program.
        let (start, bytes) = (self.at, self.text.as_bytes());
        let (mut at, mut column) = (start, self.column);
        while at < bytes.len() && keep(bytes[at]) {
            column += u32::from(bytes[at] & 0xC0 != 0x80);
            at += 1;
        }
        (self.at, self.column) = (at, column);
        // `keep` stops only at ASCII bytes or at the end, so the slice
        // ends on a character boundary.
        &self.text[start..self.at]
    }

    fn skip_blanks(&mut self) {
        self.take_while(dropped);
    }

    /// A number's text: digits, with at most one point among or before
    /// them ("12", "1.5", ".5", "1."), without the blanks that may stand
    /// among them ("1 0" is "10"). Empty when none is here.
    fn number(&mut self) -> NumberText<'t> {
        self.decimal().0
    }

    /// [`Self::number`], and its value when it has 1 to 15 digits, read on
    /// the way ([`short_value`]). None otherwise, for `str::parse` to read.
    /// One pass over the bytes, on locals.
    ///
    /// Blanks inside a number are dropped, as Grbl drops them before it
    /// reads a line (protocol.c), so `X1 0` is X10 and `G9 0.1` is G90.1;
    /// blanks after the last digit are left for the caller.
    fn decimal(&mut self) -> (NumberText<'t>, Option<f64>) {
        let (start, bytes) = (self.at, self.text.as_bytes());
        let mut at = start;
        let (mut mantissa, mut digits, mut fraction_digits) = (0u64, 0usize, 0usize);
        let mut point = false;
        let mut blanks_inside = false;
        loop {
            match bytes.get(at) {
                Some(&b) if b.is_ascii_digit() => {
                    if digits < 15 {
                        mantissa = mantissa * 10 + u64::from(b - b'0');
                        fraction_digits += usize::from(point);
                    }
                    digits += 1;
                }
                Some(b'.') if !point => point = true,
                Some(&b) if at > start && dropped(b) => {
                    // Blanks, then more of the number: part of it.
                    let mut after = at + 1;
                    while bytes.get(after).is_some_and(|&b| dropped(b)) {
                        after += 1;
                    }
                    match bytes.get(after) {
                        Some(&b) if b.is_ascii_digit() || (b == b'.' && !point) => {
                            blanks_inside = true;
                            at = after;
                            continue;
                        }
                        _ => break,
                    }
                }
                _ => break,
            }
            at += 1;
        }
        // Digits, points and blanks are ASCII: a column each.
        self.column += (at - start) as u32;
        self.at = at;
        let value = (1..=15)
            .contains(&digits)
            .then(|| short_value(mantissa, fraction_digits));
        let text = NumberText {
            raw: &self.text[start..at],
            blanks_inside,
        };
        (text, value)
    }

    /// An exponent right after a number: e or E, then a digit, a sign or
    /// a point (1e300, 1E-3), blanks and `/` between them dropped as they
    /// are inside a number (X1E 5 is X1E5, which was the word E5).
    fn at_exponent(&self) -> bool {
        let bytes = self.text.as_bytes();
        matches!(bytes.get(self.at), Some(b'e' | b'E'))
            && bytes[self.at + 1..]
                .iter()
                .find(|&&b| !dropped(b))
                .is_some_and(|b| b.is_ascii_digit() || matches!(b, b'+' | b'-' | b'.'))
    }

    fn at_number(&self) -> bool {
        self.peek().is_some_and(|b| b.is_ascii_digit() || b == b'.')
    }

    /// What stands at the reader, as an error quotes it.
    fn next_char(&self) -> &'t str {
        let len = self.text[self.at..]
            .chars()
            .next()
            .map_or(0, char::len_utf8);
        &self.text[self.at..self.at + len]
    }

    fn read(mut self, block: &mut Block) -> Read<()> {
        let mut seen_code = false;
        // Bit i: letter 'A' + i has stood on this line (G and M never set).
        let mut letters_seen = 0u32;
        loop {
            self.skip_blanks();
            let Some(byte) = self.peek() else {
                return Ok(());
            };
            let column = self.column;
            match byte {
                b';' => return Ok(()),
                b'(' => self.comment()?,
                b'%' if letters_seen == 0 && block.codes.is_empty() => {
                    // A line of its own: the program's start or end, which
                    // the runner keeps (see `Block::percent`).
                    self.bump();
                    block.percent = Some(column);
                    return self.rest_of_percent_line();
                }
                b'%' => {
                    return Err(problem(
                        column,
                        "'%' marks a program's start or end on a line of its own: it cannot stand among words".to_string(),
                    ));
                }
                b'0'..=b'9' | b'.' => {
                    let text = self.number().text();
                    return Err(problem(
                        column,
                        format!(
                            "malformed number: '{}' belongs to no letter (a second decimal point, or a missing address letter?)",
                            echo(&text)
                        ),
                    ));
                }
                b'-' | b'+' => {
                    return Err(problem(
                        column,
                        format!(
                            "unexpected '{}': a sign belongs right after an address letter (X-1)",
                            byte as char
                        ),
                    ));
                }
                b')' => {
                    return Err(problem(
                        column,
                        "')' closes no comment: a comment ends at its first ')', as in Grbl, so comments do not nest".to_string(),
                    ));
                }
                letter if letter.is_ascii_alphabetic() => {
                    self.bump();
                    let letter = letter.to_ascii_uppercase();
                    admit(block, &mut letters_seen, letter, column)?;
                    let letter = letter as char;
                    match letter {
                        'G' | 'M' | 'T' => {
                            seen_code = true;
                            block.codes.push(self.code(letter, column)?);
                        }
                        'N' | 'O' if seen_code => {
                            return Err(problem(
                                column,
                                format!(
                                    "{letter} (a line or program number) must come before the codes of its line"
                                ),
                            ));
                        }
                        'N' | 'O' => {
                            let number = self.whole_number(letter, column)?;
                            if letter == 'O' {
                                block.ignored.push(problem(
                                    column,
                                    format!("O{number} (program number) ignored"),
                                ));
                            }
                        }
                        _ => block.words.push(self.word(letter, column)?),
                    }
                }
                _ => return Err(self.not_gcode(column)),
            }
        }
    }

    /// The error for text at the reader, at `column`, that starts nothing
    /// a line may hold ([`starts_nothing`]), quoting it up to what may.
    fn not_gcode(&mut self, column: u32) -> Problem {
        let text = self.take_while(|b| {
            !matches!(b, b' ' | b'\t' | b';' | b'(' | b'-' | b'+') && !b.is_ascii_alphanumeric()
        });
        problem(
            column,
            format!(
                "'{}' is not G-code voxpath reads: a line holds words such as G1 or X10.5 and comments; parameters (#1) and expressions ([1+2]) are not supported",
                echo(text)
            ),
        )
    }

    /// The rest of a `%` line: blanks and comments only. Apart from the
    /// reading of words, whose loop tests every byte of a program.
    fn rest_of_percent_line(&mut self) -> Read<()> {
        loop {
            self.skip_blanks();
            match self.peek() {
                None | Some(b';') => return Ok(()),
                Some(b'(') => self.comment()?,
                Some(_) => {
                    return Err(problem(
                        self.column,
                        "'%' marks a program's start or end on a line of its own: nothing but blanks and comments may follow it".to_string(),
                    ));
                }
            }
        }
    }

    /// A comment from its `(` to the first `)` after it: comments do not
    /// nest, as in Grbl (protocol.c ends a comment at the first ')'), so
    /// `(a (b) c)` is the comment `(a (b)` and then ` c)`, read as G-code.
    fn comment(&mut self) -> Read<()> {
        let column = self.column;
        self.bump();
        self.take_while(|b| b != b')');
        if self.peek().is_none() {
            return Err(problem(
                column,
                "comment not closed: '(' needs its ')' on the same line".to_string(),
            ));
        }
        self.bump();
        Ok(())
    }

    /// The number after a code letter at `column`: whole, or with one digit
    /// after its point, and within u32.
    fn code(&mut self, letter: char, column: u32) -> Read<Code> {
        self.skip_blanks();
        if !self.at_number() {
            return Err(match self.peek() {
                None => problem(
                    column,
                    format!("malformed number: {letter} has no number after it"),
                ),
                Some(_) => problem(
                    self.column,
                    format!(
                        "malformed number: {letter} must be followed by its number, found '{}'",
                        // An escape or a NUL is quoted, never sent to a terminal raw.
                        echo(self.next_char())
                    ),
                ),
            });
        }
        let number_column = self.column;
        let number = self.number();
        let cleaned;
        let text = match number.blanks_inside {
            false => number.raw,
            true => {
                cleaned = number.text();
                cleaned.as_ref()
            }
        };
        // By position, not split_once: a search for the point is a memchr
        // call, and every G1 of a program has a code.
        let (major, minor) = match text.bytes().position(|b| b == b'.') {
            Some(point) => (&text[..point], &text[point + 1..]),
            None => (text, "0"),
        };
        if major.is_empty() || minor.len() != 1 {
            return Err(problem(
                number_column,
                format!(
                    "malformed number: code number '{}': a code's number is a whole number with at most one digit after its point, as in G1 or G90.1",
                    echo(text)
                ),
            ));
        }
        // Digit by digit, checked: the largest code number is u32::MAX.
        let number = major
            .bytes()
            .try_fold(0u32, |n, d| n.checked_mul(10)?.checked_add(u32::from(d - b'0')))
            .ok_or_else(|| {
                problem(
                    number_column,
                    format!(
                        "malformed number: code number '{}' is too large: no {letter} code has a number past {}",
                        echo(text),
                        u32::MAX
                    ),
                )
            })?;
        Ok(Code {
            letter,
            number,
            minor: u32::from(minor.as_bytes()[0] - b'0'),
            column,
        })
    }

    /// The number at the reader (the caller has read any blanks and sign):
    /// the column it starts at, its text and its short value
    /// ([`Self::decimal`]); an error at the letter's `column` when no number
    /// follows.
    fn number_after(
        &mut self,
        letter: char,
        column: u32,
    ) -> Read<(u32, NumberText<'t>, Option<f64>)> {
        if !self.at_number() {
            // What stands there is named, where the reader would refuse it
            // anyway: X[1+2], or an invisible X\u{200b}1, was "X has no
            // number after it", pointing at an X with its number in sight.
            if self.peek().is_some_and(starts_nothing) {
                let at = self.column;
                return Err(self.not_gcode(at));
            }
            return Err(problem(
                column,
                format!("malformed number: {letter} has no number after it"),
            ));
        }
        let number_column = self.column;
        let (text, value) = self.decimal();
        Ok((number_column, text, value))
    }

    /// The whole number after N or O (its part before any point).
    fn whole_number(&mut self, letter: char, column: u32) -> Read<u32> {
        self.skip_blanks();
        // Said at the sign: `N-1` has a number after its letter, and
        // "N has no number after it" sent the reader looking for none.
        if let Some(sign @ (b'-' | b'+')) = self.peek() {
            return Err(problem(
                self.column,
                format!(
                    "malformed number: {letter} takes a whole number without a sign (a line or program number), found '{}'",
                    sign as char
                ),
            ));
        }
        let (number_column, number, _) = self.number_after(letter, column)?;
        let number = number.text();
        let text = number.as_ref();
        // Whole with or without a point ("N2.", "N2.0"); a fraction is
        // refused, as at ".5" (N1.5 was read as N1 where N.5 was refused),
        // LinuxCNC's reading: Grbl truncates both.
        let whole = match text.split_once('.') {
            None => text,
            Some((w, fraction)) if fraction.bytes().all(|b| b == b'0') => {
                if w.is_empty() {
                    "0"
                } else {
                    w
                }
            }
            Some(_) => "",
        };
        whole.parse::<u32>().map_err(|_| {
            // Digits past u32 are a whole number too large, not "not a
            // whole number" (N4294967296 was told so).
            let why = if !whole.is_empty() && whole.bytes().all(|b| b.is_ascii_digit()) {
                format!(
                    "is too large: line and program numbers are at most {}",
                    u32::MAX
                )
            } else {
                "is not a whole number (line and program numbers are)".to_string()
            };
            problem(
                number_column,
                format!("malformed number: '{}' {why}", echo(text)),
            )
        })
    }

    /// A word: its sign and number after the letter at `column`.
    fn word(&mut self, letter: char, column: u32) -> Read<Word> {
        self.skip_blanks();
        let negative = self.peek() == Some(b'-');
        if matches!(self.peek(), Some(b'-' | b'+')) {
            self.bump();
            self.skip_blanks();
        }
        let (number_column, number, short) = self.number_after(letter, column)?;
        let sign = if negative { "-" } else { "" };
        if self.at_exponent() {
            // F1e300 read as F1 and a word E300 would be neither what the
            // program means nor what any controller does: Marlin reads
            // 1e300 (strtod), LinuxCNC and Grbl refuse the E.
            let start = self.at;
            self.bump();
            self.take_while(|b| {
                b.is_ascii_digit() || matches!(b, b'+' | b'-' | b'.') || dropped(b)
            });
            let exponent = self.text[start..self.at]
                .trim_end_matches(|c: char| c.is_ascii() && dropped(c as u8));
            return Err(problem(
                column,
                format!(
                    "malformed number: {letter}{sign}{}: a G-code number has no exponent; write it out in full (an E word after a number needs a blank before it: the one blank a line keeps)",
                    echo(&format!("{}{exponent}", number.text()))
                ),
            ));
        }
        // The text only where the short read could not (past 15 digits), or to quote it.
        let Some(magnitude) = short.or_else(|| number.text().parse::<f64>().ok()) else {
            return Err(problem(
                number_column,
                format!(
                    "malformed number: '{}' is not a number",
                    echo(&number.text())
                ),
            ));
        };
        if !magnitude.is_finite() {
            return Err(problem(
                column,
                format!(
                    "malformed number: {letter}{sign}{} is too large",
                    echo(&number.text())
                ),
            ));
        }
        Ok(Word {
            letter,
            value: if negative { -magnitude } else { magnitude },
            column,
            written_whole: match short {
                Some(_) => short_written_whole(magnitude),
                None => writes_whole_number(&number.text()),
            },
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    proptest::proptest! {
        /// The short path reads every number of up to 15 digits as
        /// `str::parse` does, bit for bit, and leaves the rest to it.
        #[test]
        fn short_decimals_read_as_str_parse_reads_them(
            whole in "[0-9]{0,12}",
            fraction in proptest::option::of("[0-9]{0,12}"),
        ) {
            let text = match &fraction {
                Some(f) => format!("{whole}.{f}"),
                None => whole.clone(),
            };
            let parsed = text.parse::<f64>().ok().map(f64::to_bits);
            let digits = text.bytes().filter(u8::is_ascii_digit).count();
            // Read from a line, with what stops the number after it.
            let line = format!("{text}X");
            let mut reader = Reader { text: &line, at: 0, column: 1 };
            let (read, short) = reader.decimal();
            proptest::prop_assert_eq!(read.text(), text.as_str());
            proptest::prop_assert_eq!(reader.column as usize, 1 + text.len());
            match short {
                Some(v) => proptest::prop_assert_eq!(Some(v.to_bits()), parsed),
                None => proptest::prop_assert!(digits == 0 || digits > 15),
            }
        }

        /// A word is whole as written, whichever path reads it: from its
        /// value to 15 digits (the plain line's loop and the reader's
        /// short read), from its text past them. Numbers near whole ones
        /// (runs of 0 and 9 past the point) most of all.
        #[test]
        fn a_word_is_whole_as_its_text_writes_it(
            whole in "[1-9][0-9]{0,6}",
            fraction in proptest::option::of("(0{0,20}|9{0,20}|[0-9]{0,4})[0-9]?"),
            spaced in proptest::bool::ANY,
        ) {
            let text = match &fraction {
                Some(f) => format!("{whole}.{f}"),
                None => whole.clone(),
            };
            // "P 1.5" is no plain line: the reader takes it.
            let line = format!("G3 I-10 P{}{text}", if spaced { " " } else { "" });
            let block = parse_line(&line);
            proptest::prop_assert_eq!(&block.error, &None);
            let p = block.words.iter().find(|w| w.letter == 'P').expect("a P word");
            proptest::prop_assert_eq!(p.written_whole, writes_whole_number(&text), "{}", line);
        }
    }

    /// A line of G-code's characters, the plain ones most often, and of
    /// each other kind the reader treats apart: blanks of each kind, signs,
    /// points, comments, `%`, `/`, exponents, an O, non-ASCII, NUL.
    fn gcode_line() -> impl proptest::strategy::Strategy<Value = String> {
        use proptest::prelude::*;
        let piece = prop_oneof![
            8 => "[GMTNXYZFIJKRPSEO][-+]?[0-9]{0,3}(\\.[0-9]{0,3})?",
            3 => "[ \t\r]{1,2}",
            2 => "[0-9.eE+-]{1,3}",
            1 => "[gxmn][0-9]{1,17}",
            1 => prop::sample::select(vec![";", "; note é", "(", ")", "(c)", "%", "/", "\u{b}", "\u{c}", "é", "\0", "G90.1", "G1.10", "G4294967296", "N1.5"])
                .prop_map(str::to_string),
        ];
        proptest::collection::vec(piece, 0..8).prop_map(|pieces| pieces.concat())
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(20_000))]
        /// The plain reader reads a line to the block the reader makes of
        /// it, or leaves it to the reader: never another block.
        #[test]
        fn plain_lines_are_read_as_the_reader_reads_them(line in gcode_line()) {
            let mut plain = Block::default();
            if read_plain(&line, &mut plain) {
                let mut full = Block::default();
                full.error = Reader { text: &line, at: 0, column: 1 }.read(&mut full).err();
                proptest::prop_assert_eq!(plain, full, "{:?}", line);
            }
        }
    }

    #[test]
    fn lines_as_cam_programs_write_them_are_plain() {
        // The fast path must stay the one such lines take (the property
        // test above cannot see a plain reader that refuses every line).
        for line in [
            "G1 X25.655 Y25.305 Z0.000",
            "G2 X24.655 Y24.305 I-1 J0",
            "N120 G01 X-1.5 Y+2. F1200 ; cut",
            "g0x1y2z.5",
            "G21 G90 G17 F1200",
            "M3 S10000 T1",
            "",
            "   \t",
        ] {
            let mut block = Block::default();
            assert!(read_plain(line, &mut block), "{line}");
            assert_eq!(block, parse_line(line), "{line}");
        }
        for line in [
            "G1 X1 0", "(setup)", "%", "/G1 X1", "O100", "G1 X1e3", "X1 X2", "G 1",
        ] {
            assert!(!read_plain(line, &mut Block::default()), "{line}");
        }
    }

    fn words(b: &Block) -> Vec<(char, f64, u32)> {
        b.words
            .iter()
            .map(|w| (w.letter, w.value, w.column))
            .collect()
    }

    fn codes(b: &Block) -> Vec<(String, u32)> {
        b.codes.iter().map(|c| (c.name(), c.column)).collect()
    }

    fn errors(text: &str) -> Vec<(u32, String)> {
        parse_line(text)
            .error
            .into_iter()
            .map(|p| (p.column, p.message))
            .collect()
    }

    #[test]
    fn codes_and_words_with_and_without_spaces() {
        let b = parse_line("N10 G1X10Y-5.25 (move) F600 ; go");
        assert_eq!(codes(&b), [("G1".to_string(), 5)]);
        assert_eq!(
            words(&b),
            [('X', 10.0, 7), ('Y', -5.25, 10), ('F', 600.0, 24)]
        );
        assert!(b.error.is_none());
        let b = parse_line("g90.1 g17 G2 x1 i-2 j+0.5 p2");
        assert_eq!(
            codes(&b),
            [
                ("G90.1".to_string(), 1),
                ("G17".to_string(), 7),
                ("G2".to_string(), 11)
            ]
        );
        assert_eq!(
            words(&b),
            [
                ('X', 1.0, 14),
                ('I', -2.0, 17),
                ('J', 0.5, 21),
                ('P', 2.0, 27)
            ]
        );
    }

    #[test]
    fn values_are_exact_f64_not_the_crate_s_f32() {
        // As f32, 123.4567 is 123.45670318603516.
        let b = parse_line("X123.4567 Y.5 Z-0.000001");
        assert_eq!(
            words(&b),
            [('X', 123.4567, 1), ('Y', 0.5, 11), ('Z', -0.000001, 15)]
        );
    }

    #[test]
    fn comments_m_and_t_codes_and_program_numbers() {
        let b = parse_line("O100 M3 S1000 T2 (spindle on) ; and tool 2");
        assert_eq!(codes(&b), [("M3".to_string(), 6), ("T2".to_string(), 15)]);
        assert_eq!(words(&b), [('S', 1000.0, 9)]);
        assert_eq!(b.ignored[0].message, "O100 (program number) ignored");
        assert!(parse_line("(only a comment)").codes.is_empty());
        assert!(parse_line("").error.is_none());
    }

    #[test]
    fn syntax_errors_name_their_column() {
        assert_eq!(
            errors("G1 X1..5"),
            [(
                7,
                "malformed number: '.5' belongs to no letter (a second decimal point, or a missing address letter?)".to_string()
            )]
        );
        assert_eq!(
            errors("G1 X Y2"),
            [(4, "malformed number: X has no number after it".to_string())]
        );
        // Where a word's number should stand, what the reader refuses is
        // named, at its own column: these were "X has no number after it"
        // (and "Y ...") at the letter.
        for (line, column, quoted) in [
            ("G1 X[1+2]", 5, "'['"),
            ("G1 X\u{200b}1", 5, "'\\u{200b}'"),
            ("G1 X1 Y #5", 9, "'#'"),
            ("G1 X-\u{a0}1", 6, "'\\u{a0}'"),
        ] {
            assert_eq!(
                errors(line),
                [(
                    column,
                    format!(
                        "{quoted} is not G-code voxpath reads: a line holds words such as G1 or X10.5 and comments; parameters (#1) and expressions ([1+2]) are not supported"
                    )
                )],
                "{line}"
            );
        }
        // The crate then also finds "1" left over: only the first is kept.
        assert_eq!(
            errors("G X1"),
            [(
                3,
                "malformed number: G must be followed by its number, found 'X'".to_string()
            )]
        );
        assert_eq!(
            errors("G1.25 X1"),
            [(
                2,
                "malformed number: code number '1.25': a code's number is a whole number with at most one digit after its point, as in G1 or G90.1".to_string()
            )]
        );
        assert_eq!(
            errors("G1 #1"),
            [(
                4,
                "'#' is not G-code voxpath reads: a line holds words such as G1 or X10.5 and comments; parameters (#1) and expressions ([1+2]) are not supported".to_string()
            )]
        );
        assert_eq!(
            errors("G1 (open X10"),
            [(
                4,
                "comment not closed: '(' needs its ')' on the same line".to_string()
            )]
        );
        assert_eq!(
            errors("G1 N10 X1"),
            [(
                4,
                "N (a line or program number) must come before the codes of its line".to_string()
            )]
        );
        // A signed line or program number is named at its sign, not as a
        // letter with no number after it.
        // What follows a code's letter is quoted as echo quotes it: an
        // escape sequence reached the terminal raw.
        let [(_, message)] = &errors("G\u{1b}[31m1")[..] else {
            panic!("one error")
        };
        assert!(!message.contains('\u{1b}'), "{message:?}");
        assert!(message.contains("\\u{1b}"), "{message:?}");
        // A line number past u32 is too large, not "not a whole number".
        assert_eq!(
            errors("N4294967296 G1 X1"),
            [(
                2,
                "malformed number: '4294967296' is too large: line and program numbers are at most 4294967295".to_string()
            )]
        );
        assert!(errors("N4294967295 G1 X1").is_empty());
        // A line number with a fraction is not a whole number, wherever its
        // digits start; one with a point and no fraction is.
        for (line, number) in [
            ("N1.5 G1 X1", "1.5"),
            ("N.5 G1 X1", ".5"),
            ("N10.01 G1", "10.01"),
        ] {
            assert_eq!(
                errors(line),
                [(
                    2,
                    format!(
                        "malformed number: '{number}' is not a whole number (line and program numbers are)"
                    )
                )],
                "{line}"
            );
        }
        for line in ["N2. G1 X1", "N2.00 G1 X1", "N.0 G1 X1", "N0 G1 X1"] {
            assert!(errors(line).is_empty(), "{line}: {:?}", errors(line));
        }
        for (line, column, sign) in [("N-1 G1 X1", 2, '-'), ("O +7", 3, '+')] {
            let letter = &line[..1];
            assert_eq!(
                errors(line),
                [(
                    column,
                    format!(
                        "malformed number: {letter} takes a whole number without a sign (a line or program number), found '{sign}'"
                    )
                )],
                "{line}"
            );
        }
    }

    #[test]
    fn code_numbers_are_read_exactly_and_past_u32_are_errors() {
        // The gcode crate read these as major * 10 + minor in u32: G2147483649
        // wrapped to G1 and G2147483651 to G3.
        assert_eq!(
            codes(&parse_line("G2147483649 X10 Y5 F600")),
            [("G2147483649".to_string(), 1)]
        );
        assert_eq!(
            codes(&parse_line("G1999999999 M1000000000 G4294967295.9")),
            [
                ("G1999999999".to_string(), 1),
                ("M1000000000".to_string(), 13),
                ("G4294967295.9".to_string(), 25)
            ]
        );
        assert_eq!(
            errors("G1 G4294967296 X1"),
            [(
                5,
                "malformed number: code number '4294967296' is too large: no G code has a number past 4294967295".to_string()
            )]
        );
        let e = errors(&format!("M{}", "9".repeat(100)));
        assert_eq!(e[0].0, 2);
        assert!(
            e[0].1.starts_with(
                "malformed number: code number '9999999999999999... (100 characters)' is too large"
            ),
            "{}",
            e[0].1
        );
        assert_eq!(errors("G90.12")[0].0, 2);
        assert_eq!(errors("G1. X1")[0].0, 2);
    }

    #[test]
    fn reading_stops_at_the_first_error() {
        // Whatever follows the error is never read: a line of a million
        // words with an error at column 4 returns at once, its words unread.
        let line = format!("G1 #{}", " X1".repeat(1_000_000));
        let b = parse_line(&line);
        assert_eq!(b.error.map(|e| e.column), Some(4));
        assert!(b.words.is_empty());
    }

    #[test]
    fn a_letter_stands_once_and_codes_are_counted() {
        // The interpreter found a second X only after the whole line was
        // read into a block: a 50 MB line of X1 X1 ... held 16.7 million
        // words (400 MB), and 50 MB of M3 M3 ... took 51 s and 2 GB of wasm
        // memory for as many warnings. The reader stops at the second.
        assert_eq!(
            errors("G1 X1 Y2 X3"),
            [(10, "X appears twice on this line".to_string())]
        );
        for (line, column, message) in [
            ("N1 N2 G1", 4, "N appears twice on this line"),
            ("O1 O2", 4, "O appears twice on this line"),
            ("T1 M6 T2", 7, "T appears twice on this line"),
            ("g1 x1 X2", 7, "X appears twice on this line"),
            (
                "M3 M8 M7 M48 M5",
                14,
                "too many M codes on this line: a line takes at most 4 (as LinuxCNC has it)",
            ),
        ] {
            assert_eq!(errors(line), [(column, message.to_string())], "{line}");
        }
        let sixteen = "G17 G21 G90 G91.1 G94 G40 G49 G98 G54 G61 G97 G8 G1 G4 G10 G50";
        let b = parse_line(sixteen);
        assert_eq!((b.codes.len(), b.error), (MAX_G_CODES_PER_LINE, None));
        assert_eq!(
            errors(&format!("{sixteen} G0")),
            [(
                sixteen.len() as u32 + 2,
                "too many G codes on this line: a line takes at most 16 (one from each modal group)"
                    .to_string()
            )]
        );
    }

    #[test]
    fn a_block_holds_a_bounded_number_of_entries_whatever_the_line_length() {
        // Each line below is 3 MB; what the reader keeps of it is a word or
        // a few codes, and it stops at the first entry the line cannot hold.
        let words = format!("G1{}", " X1".repeat(1_000_000));
        let b = parse_line(&words);
        assert_eq!((b.codes.len(), b.words.len()), (1, 1));
        assert_eq!(b.error.map(|e| e.column), Some(7));
        let codes = " M3".repeat(1_000_000);
        let b = parse_line(&codes);
        assert_eq!(b.codes.len(), MAX_M_CODES_PER_LINE);
        assert_eq!(b.error.map(|e| e.column), Some(14));
        let programs = " O1".repeat(1_000_000);
        let b = parse_line(&programs);
        assert_eq!((b.ignored.len(), b.error.map(|e| e.column)), (1, Some(5)));
    }

    #[test]
    fn a_long_line_that_holds_nothing_wrong_is_read_whole() {
        // A 3 MB comment and a number of a million digits: read once, left
        // to right; the columns after them are counted as the reader passed.
        let comment = "c".repeat(3_000_000);
        let digits = format!("1{}", "0".repeat(999_999));
        let b = parse_line(&format!("G1 ({comment}) X0.{digits} Y2"));
        assert_eq!(b.error, None);
        assert_eq!(words(&b)[0].1, 0.1);
        assert_eq!(words(&b)[1], ('Y', 2.0, 3_000_000 + 1_000_000 + 11));
    }

    #[test]
    fn an_exponent_is_an_error_naming_its_word() {
        // F1e300 was read as F1 and a word E300 (ignored with a warning):
        // the move ran at 1 mm/min. Before that, the gcode crate read it as
        // an infinite feed.
        for (line, column, quoted) in [
            ("G1 X1 F1e300", 7, "F1e300"),
            ("G1 X-1.5E-3", 4, "X-1.5E-3"),
            ("G1 X1e+5 Y1", 4, "X1e+5"),
            ("G1 Y2E.5", 4, "Y2E.5"),
        ] {
            assert_eq!(
                errors(line),
                [(
                    column,
                    format!(
                        "malformed number: {quoted}: a G-code number has no exponent; write it out in full (an E word after a number needs a blank before it: the one blank a line keeps)"
                    )
                )],
                "{line}"
            );
        }
        // Blanks and `/` inside the exponent are dropped, as inside a
        // number: each of these was X1 and a word E (ignored, with a
        // warning), where X1E5 is an error.
        for (line, quoted) in [
            ("G1 X1E 5", "X1E 5"),
            ("G1 X1e/5 Y1", "X1e/5"),
            ("G1 X1E -5", "X1E -5"),
            ("G1 X1E\t 5 ", "X1E\\u{9} 5"),
        ] {
            assert_eq!(
                errors(line),
                [(
                    4,
                    format!(
                        "malformed number: {quoted}: a G-code number has no exponent; write it out in full (an E word after a number needs a blank before it: the one blank a line keeps)"
                    )
                )],
                "{line}"
            );
        }
        // An E word after a blank is a word; a code's number is followed by
        // its words without one (G1E3, as RepRap firmware writes it).
        assert_eq!(
            words(&parse_line("G1 X1 E3")),
            [('X', 1.0, 4), ('E', 3.0, 7)]
        );
        assert_eq!(words(&parse_line("G1E3")), [('E', 3.0, 3)]);
        assert_eq!(
            errors("G1 X1E"),
            [(6, "malformed number: E has no number after it".to_string())]
        );
    }

    #[test]
    fn numbers_beyond_f64_are_malformed() {
        let e = errors(&format!("G1 X1{}", "0".repeat(400)));
        assert_eq!(e[0].0, 4);
        assert_eq!(
            e[0].1,
            "malformed number: X1000000000000000... (401 characters) is too large"
        );
        assert_eq!(
            errors("G1 X.")[0],
            (5, "malformed number: '.' is not a number".to_string())
        );
    }

    #[test]
    fn blanks_and_slashes_are_dropped_even_inside_numbers_as_grbl_drops_them() {
        // Grbl's protocol.c throws away every byte up to ' ' and '/' (block
        // delete, "NOT SUPPORTED. Ignore character.") before gc_execute_line
        // reads the line: `X1 0` is X10. It was an error ("'0' belongs to
        // no letter"), and `/G1 X10` one too.
        let b = parse_line("G1 X1 0 F100");
        assert_eq!((codes(&b), &b.error), (vec![("G1".to_string(), 1)], &None));
        assert_eq!(words(&b), [('X', 10.0, 4), ('F', 100.0, 9)]);
        let b = parse_line("/G1 X10");
        assert_eq!((codes(&b), &b.error), (vec![("G1".to_string(), 2)], &None));
        assert_eq!(words(&b), [('X', 10.0, 5)]);
        let b = parse_line("G9 0.1 G 1 X - 1 .5\tY1/0");
        assert_eq!(codes(&b), [("G90.1".to_string(), 1), ("G1".to_string(), 8)]);
        assert_eq!(words(&b), [('X', -1.5, 12), ('Y', 10.0, 21)]);
        // A number past 15 digits is read by str::parse, without its blanks.
        let b = parse_line("X1 2345678901234567 8");
        assert_eq!(words(&b), [('X', 123456789012345678.0, 1)]);
        // A second point still ends a number: X1. .5 is X1. and then .5.
        assert_eq!(errors("X1. .5")[0].0, 5);
    }

    #[test]
    fn a_comment_ends_at_its_first_closing_parenthesis_as_in_grbl() {
        // protocol.c ends a comment at the first ')'. Comments nested, so
        // the Y5 below was silently part of the comment, and the second
        // line an unclosed comment.
        assert_eq!(
            errors("G0 X10 (first (second) Y5)"),
            [(
                26,
                "')' closes no comment: a comment ends at its first ')', as in Grbl, so comments do not nest".to_string()
            )]
        );
        let b = parse_line("G1 X1 F100 (see (note 3)");
        assert_eq!(b.error, None);
        assert_eq!(words(&b), [('X', 1.0, 4), ('F', 100.0, 7)]);
        let b = parse_line("G0 (a (b) X2");
        assert_eq!((words(&b), b.error), (vec![('X', 2.0, 11)], None));
    }

    #[test]
    fn percent_stands_on_a_line_of_its_own() {
        for (line, column) in [("%", 1), (" % (start) ", 2), ("%;end", 1)] {
            let b = parse_line(line);
            assert_eq!((b.percent, b.error), (Some(column), None), "{line}");
        }
        assert_eq!(parse_line("G1 X1").percent, None);
        for (line, column) in [("%G1 X1", 2), ("% %", 3), ("G1 X1 %", 7), ("N1 %", 4)] {
            let e = errors(line);
            assert_eq!(e[0].0, column, "{line}");
            assert!(
                e[0].1
                    .starts_with("'%' marks a program's start or end on a line of its own")
            );
        }
    }

    #[test]
    fn columns_count_characters_not_bytes() {
        let b = parse_line("(µm) X1 Y2");
        assert_eq!(words(&b), [('X', 1.0, 6), ('Y', 2.0, 9)]);
    }
}
