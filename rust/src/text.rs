//! Text a user wrote (a G-code program, a learner's points): where its
//! lines end, and how a message quotes a piece of it. One reading for every
//! text input, so that a file reads the same in each.

/// The first line of `text` (without its break) and the offset of the
/// next: a line ends at LF, CR LF or a lone CR (classic Mac OS files, and
/// some CAM exports, end lines with CR alone).
pub fn split_line(text: &str) -> (&str, usize) {
    match memchr::memchr2(b'\n', b'\r', text.as_bytes()) {
        None => (text, text.len()),
        Some(end) if text[end..].starts_with("\r\n") => (&text[..end], end + 2),
        Some(end) => (&text[..end], end + 1),
    }
}

/// The lines of `text`, each without its break (see [`split_line`]); a
/// final break ends the last line.
pub fn lines(text: &str) -> impl Iterator<Item = &str> {
    let mut rest = text;
    std::iter::from_fn(move || {
        if rest.is_empty() {
            return None;
        }
        let (line, next) = split_line(rest);
        rest = &rest[next..];
        Some(line)
    })
}

/// The 1-based line and column (in characters) of the place right after
/// `before`, the text up to it, read as every text input is: after its
/// byte order mark, its lines ending as [`split_line`] ends them (a CR at
/// the end of `before` ends a line: what comes after it is not an LF).
pub fn line_and_column(before: &str) -> (usize, usize) {
    let mut rest = without_byte_order_mark(before);
    let mut line = 1;
    loop {
        let (text, next) = split_line(rest);
        if next == text.len() {
            return (line, text.chars().count() + 1);
        }
        line += 1;
        rest = &rest[next..];
    }
}

/// Longest number echoed whole in a message: a 1 MB number is named by its
/// first digits and its length.
const ECHO_CHARS: usize = 24;

/// `text` as a message quotes it: cut between characters (a byte offset
/// could fall inside one: the fuzz target found that panic), and control
/// characters written as escapes (\u{0}), so that a NUL or an escape
/// sequence in an input never reaches the terminal raw. Characters a
/// reader cannot see are escaped too: whitespace other than the space (a
/// no-break space pasted from a web page, \u{a0}) and the invisible
/// format characters ([`invisible`]), so that "'' is not G-code" never
/// quotes nothing.
pub fn echo(text: &str) -> String {
    let chars = text.chars().count();
    let quoted = |part: &mut dyn Iterator<Item = char>| -> String {
        part.map(|c| {
            if c.is_control() || (c.is_whitespace() && c != ' ') || invisible(c) {
                c.escape_unicode().to_string()
            } else {
                c.to_string()
            }
        })
        .collect()
    };
    if chars <= ECHO_CHARS {
        quoted(&mut text.chars())
    } else {
        format!(
            "{}... ({chars} characters)",
            quoted(&mut text.chars().take(ECHO_CHARS - 8))
        )
    }
}

/// The byte order mark an editor may put before a file's text (UTF-8
/// files saved by Windows tools, CSV exported from spreadsheets): a mark of
/// the encoding, not text, so every text input starts after it.
pub fn without_byte_order_mark(text: &str) -> &str {
    text.strip_prefix(BYTE_ORDER_MARK).unwrap_or(text)
}

/// Whether `number`, decimal text that reads as a finite number, writes a
/// whole number: no digit but 0 after its point once its exponent has moved
/// the point ("1.5e1" does, "15e-1" does not). Asked of the text, not of
/// its value: "2.99999999999999999" reads as 3.0, a whole f64, and is no
/// whole number (a learner's coordinate, a G-code arc's P turns).
pub fn writes_whole_number(number: &str) -> bool {
    let unsigned = number.trim_start_matches(['+', '-']);
    let (mantissa, exponent) = match unsigned.split_once(['e', 'E']) {
        // An exponent past i64 moves the point past every digit.
        Some((mantissa, exponent)) => (
            mantissa,
            exponent
                .parse::<i64>()
                .unwrap_or(if exponent.starts_with('-') {
                    i64::MIN
                } else {
                    i64::MAX
                }),
        ),
        None => (unsigned, 0),
    };
    let (whole, fraction) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let point = (whole.len() as i64).saturating_add(exponent);
    (whole.bytes().chain(fraction.bytes()))
        .enumerate()
        .all(|(i, digit)| (i as i64) < point || digit == b'0')
}

/// U+FEFF, the byte order mark (bytes EF BB BF in UTF-8).
const BYTE_ORDER_MARK: char = '\u{feff}';

/// Format characters that draw nothing: the soft hyphen, the zero-width
/// spaces and joiners, the direction marks, the word joiner and invisible
/// operators, and the byte order mark (Unicode's Cf characters a pasted
/// text is likely to carry).
fn invisible(c: char) -> bool {
    matches!(c, '\u{ad}' | '\u{200b}'..='\u{200f}' | '\u{202a}'..='\u{202e}' | '\u{2060}'..='\u{2064}' | BYTE_ORDER_MARK)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_end_at_lf_cr_lf_or_a_lone_cr() {
        let all: Vec<&str> = lines("a\nb\r\nc\rd\r\r\ne").collect();
        assert_eq!(all, ["a", "b", "c", "d", "", "e"]);
        assert_eq!(lines("a\n").count(), 1);
        assert_eq!(lines("").count(), 0);
    }

    #[test]
    fn a_place_is_counted_in_lines_as_they_are_read_and_in_characters() {
        assert_eq!(line_and_column(""), (1, 1));
        assert_eq!(line_and_column("G1 X1 ("), (1, 8));
        // LF, CR LF and a lone CR each end a line; a CR last ends one too.
        assert_eq!(line_and_column("a\nb\r\nc\rd"), (4, 2));
        assert_eq!(line_and_column("G21\rG1 X1 ("), (2, 8));
        assert_eq!(line_and_column("G21\r"), (2, 1));
        // The byte order mark is not a column; a two-byte character is one.
        assert_eq!(line_and_column("\u{feff}G1 X1 ("), (1, 8));
        assert_eq!(line_and_column("(é"), (1, 3));
    }

    #[test]
    fn quotes_control_characters_as_escapes_and_long_text_by_its_start() {
        assert_eq!(echo("1\u{0}"), "1\\u{0}");
        // What a reader cannot see is named, not quoted as nothing.
        assert_eq!(echo("X\u{a0}1"), "X\\u{a0}1");
        assert_eq!(echo("\u{feff}\u{200b}"), "\\u{feff}\\u{200b}");
        assert_eq!(echo("x y"), "x y");
        assert_eq!(
            echo(&"9".repeat(100)),
            format!("{}... (100 characters)", "9".repeat(16))
        );
    }
}
