//! One line of G-code -> a block of codes and words with their columns.
//!
//! The `gcode` crate (0.7.0, its push-based `core` parser) reads the line:
//! comments in both styles, N numbers, several codes per line, words with
//! or without spaces (`G1X10Y5`), and reports what it cannot read. This file
//! adds what the crate lacks for a machine:
//! - exact values: the crate stores numbers as f32 (7 digits, so X123.4567
//!   would come back as 123.45670318...); each word's text is read again
//!   from its span as f64;
//! - columns: the crate gives byte offsets; errors and words carry the
//!   1-based column (in characters) of their first character;
//! - messages a user can act on, worded here from the crate's diagnostics;
//! - a comment `(` with no `)` on its line is an error (the crate would read
//!   the rest of the program as the comment).
//!
//! Lines are parsed one at a time, so a program of any length is read in
//! slices and line numbers are exact.

use gcode::core::{
    BlockVisitor, CommandVisitor, ControlFlow, Diagnostics, HasDiagnostics, Number, ProgramVisitor,
    Span, TokenType, Value,
};
use std::str::FromStr;

/// The crate's error for a code number such as "1.25"; 0.7.0 does not
/// export its name, only this path to it.
type ParseNumberError = <Number as FromStr>::Err;

/// An address letter with its value, e.g. or F600.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Word {
    /// Upper case.
    pub letter: char,
    pub value: f64,
    /// 1-based column of the letter.
    pub column: u32,
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
    /// Every word of the line, whichever code the crate attached it to: in
    /// G-code a line's words belong to the line (RS274/NGC), and the
    /// interpreter decides which command uses them.
    pub words: Vec<Word>,
    /// Things the line says that voxpath ignores (program numbers).
    pub ignored: Vec<Problem>,
    /// The first syntax error of the line, by column: the crate recovers
    /// token by token, so what it reports after a first error is mostly
    /// that error's echo ("G X1" is a G without its number and then a
    /// stray "1"). A line with an error is not run.
    pub error: Option<Problem>,
}

/// Parses one line (without its line break).
pub fn parse_line(text: &str) -> Block {
    let mut parser = LineParser {
        text,
        block: Block::default(),
    };
    gcode::core::parse(text, &mut parser);
    parser.block
}

struct LineParser<'t> {
    text: &'t str,
    block: Block,
}

impl LineParser<'_> {
    /// 1-based column, in characters, of byte offset `start`.
    fn column(&self, start: usize) -> u32 {
        self.text[..start].chars().count() as u32 + 1
    }

    fn error(&mut self, span: Span, message: String) {
        let column = self.column(span.start);
        if self.block.error.as_ref().is_none_or(|e| column < e.column) {
            self.block.error = Some(Problem { column, message });
        }
    }

    /// A word from its span "X-1.5" (letter, optional sign, number; the
    /// crate allows spaces between them), its value read as f64.
    fn word(&mut self, letter: char, span: Span) {
        let digits: String = self.text[span.start..span.end()]
            .chars()
            .skip(1)
            .filter(|c| !c.is_whitespace())
            .collect();
        match digits.parse::<f64>() {
            Ok(value) if !value.is_finite() => self.error(
                span,
                format!("malformed number: {letter}{digits} is too large"),
            ),
            Ok(value) => {
                let column = self.column(span.start);
                self.block.words.push(Word {
                    letter: letter.to_ascii_uppercase(),
                    value,
                    column,
                });
            }
            Err(_) => self.error(
                span,
                format!("malformed number: '{digits}' after {letter} is not a number"),
            ),
        }
    }

    /// The character before byte offset `start`, skipping spaces.
    fn previous_char(&self, start: usize) -> Option<char> {
        self.text[..start].trim_end().chars().last()
    }
}

impl Diagnostics for LineParser<'_> {
    fn emit_unknown_content(&mut self, text: &str, span: Span) {
        self.error(
            span,
            format!(
                "'{text}' is not G-code voxpath reads: a line holds words such as G1 or X10.5 and comments; parameters (#1) and expressions ([1+2]) are not supported"
            ),
        );
    }

    fn emit_unexpected(&mut self, actual: &str, expected: &[TokenType], span: Span) {
        let message = if expected == [TokenType::Number] || expected == [TokenType::Eof] {
            // The crate reports a code letter with no number at the token
            // after it, and a word letter with no number at the letter.
            match self
                .previous_char(span.start)
                .map(|c| c.to_ascii_uppercase())
            {
                Some(code @ ('G' | 'M' | 'T')) if expected == [TokenType::Number] => {
                    format!(
                        "malformed number: {code} must be followed by its number, found '{actual}'"
                    )
                }
                _ if actual.len() == 1 && actual.chars().all(|c| c.is_ascii_alphabetic()) => {
                    format!(
                        "malformed number: {} has no number after it",
                        actual.to_ascii_uppercase()
                    )
                }
                _ => format!("malformed number: '{actual}' is not a number"),
            }
        } else if expected.contains(&TokenType::Letter) && expected.contains(&TokenType::Number) {
            format!(
                "{} (a line or program number) must come before the codes of its line",
                actual.to_ascii_uppercase()
            )
        } else if expected == [TokenType::Letter] {
            format!(
                "malformed number: '{actual}' belongs to no letter (a second decimal point, or a missing address letter?)"
            )
        } else {
            format!(
                "unexpected '{actual}': a sign belongs right after an address letter (X-1), and block delete (/) is not supported"
            )
        };
        self.error(span, message);
    }

    fn emit_parse_number_error(&mut self, value: &str, _error: ParseNumberError, span: Span) {
        self.error(
            span,
            format!(
                "malformed number: code number '{value}': a code's number is a whole number with at most one digit after its point, as in G1 or G90.1"
            ),
        );
    }

    fn emit_parse_int_error(&mut self, value: &str, _error: std::num::ParseIntError, span: Span) {
        self.error(
            span,
            format!(
                "malformed number: '{value}' is not a whole number (line and program numbers are)"
            ),
        );
    }
}

impl ProgramVisitor for LineParser<'_> {
    fn start_block(&mut self) -> ControlFlow<impl BlockVisitor + '_> {
        ControlFlow::Continue(BlockParser(self))
    }
}

struct BlockParser<'p, 't>(&'p mut LineParser<'t>);

impl HasDiagnostics for BlockParser<'_, '_> {
    fn diagnostics(&mut self) -> &mut dyn Diagnostics {
        self.0
    }
}

impl<'t> BlockParser<'_, 't> {
    fn command(&mut self, letter: char, number: Number) -> ControlFlow<CommandParser<'_, 't>> {
        ControlFlow::Continue(CommandParser {
            line: self.0,
            letter,
            number,
        })
    }
}

impl BlockVisitor for BlockParser<'_, '_> {
    fn comment(&mut self, value: &str, span: Span) {
        if value.starts_with('(') && !value.ends_with(')') {
            self.0.error(
                span,
                "comment not closed: '(' needs its ')' on the same line".to_string(),
            );
        }
    }

    fn program_number(&mut self, number: u32, span: Span) {
        let column = self.0.column(span.start);
        self.0.block.ignored.push(Problem {
            column,
            message: format!("O{number} (program number) ignored"),
        });
    }

    fn word_address(&mut self, letter: char, _value: Value<'_>, span: Span) {
        self.0.word(letter, span);
    }

    fn start_general_code(&mut self, number: Number) -> ControlFlow<impl CommandVisitor + '_> {
        self.command('G', number)
    }

    fn start_miscellaneous_code(
        &mut self,
        number: Number,
    ) -> ControlFlow<impl CommandVisitor + '_> {
        self.command('M', number)
    }

    fn start_tool_change_code(&mut self, number: Number) -> ControlFlow<impl CommandVisitor + '_> {
        self.command('T', number)
    }
}

struct CommandParser<'p, 't> {
    line: &'p mut LineParser<'t>,
    letter: char,
    number: Number,
}

impl HasDiagnostics for CommandParser<'_, '_> {
    fn diagnostics(&mut self) -> &mut dyn Diagnostics {
        self.line
    }
}

impl CommandVisitor for CommandParser<'_, '_> {
    fn argument(&mut self, letter: char, _value: Value<'_>, span: Span) {
        self.line.word(letter, span);
    }

    fn end_command(self, span: Span) {
        let column = self.line.column(span.start);
        self.line.block.codes.push(Code {
            letter: self.letter,
            number: self.number.major(),
            minor: self.number.minor().map_or(0, |m| m.get()),
            column,
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
    }

    #[test]
    fn numbers_beyond_f64_are_malformed() {
        let e = errors(&format!("G1 X1{}", "0".repeat(400)));
        assert_eq!(e[0].0, 4);
        assert!(e[0].1.starts_with("malformed number: X1000") && e[0].1.ends_with(" is too large"));
    }

    #[test]
    fn columns_count_characters_not_bytes() {
        let b = parse_line("(µm) X1 Y2");
        assert_eq!(words(&b), [('X', 1.0, 6), ('Y', 2.0, 9)]);
    }
}
