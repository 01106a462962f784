//! Bad and huge G-code: each case is an error at the word's line and column
//! or a correct result, never a wrapped number, a panic or a value that is
//! not finite. Integration tests run with overflow checks on (the test
//! profile), so an overflow anywhere below is a failure here.

use voxpath::gcode::{Diagnostic, Program, Settings, run};

fn program(source: &str, steps_per_mm: f64) -> Program {
    run(
        source,
        Settings::from_json(&format!(r#"{{"stepsPerMm": {steps_per_mm}}}"#)).unwrap(),
    )
}

fn first_error(source: &str, steps_per_mm: f64) -> (u32, u32, String) {
    let p = program(source, steps_per_mm);
    let Diagnostic {
        line,
        column,
        message,
        ..
    } = p
        .info
        .errors
        .first()
        .unwrap_or_else(|| panic!("{source}: no error"))
        .clone();
    (line, column, message)
}

#[test]
fn a_code_number_is_never_another_code() {
    // G2147483649 was read as G1 (2147483649 * 10 wraps in u32) and ran
    // 800 steps; it is a G code voxpath does not model.
    // A code voxpath does not know might take its line's axis words as
    // something else than a move: they are not one.
    let p = program("G2147483649 X10 Y5 F600\n", 80.0);
    assert_eq!((p.info.steps, p.moves().len()), (0, 0));
    assert_eq!(
        (
            p.info.warnings[0].column,
            p.info.warnings[0].message.as_str()
        ),
        (
            1,
            "G2147483649 ignored: voxpath does not model it, so this line's axis words are not a move either"
        )
    );
    let p = program("G2147483649\nG1999999999\nM1000000000\n", 80.0);
    let warned: Vec<&str> = p.info.warnings.iter().map(|w| w.message.as_str()).collect();
    assert!(warned[0].starts_with("G2147483649 ignored"), "{warned:?}");
    assert!(warned[1].starts_with("G1999999999 ignored"), "{warned:?}");
    assert!(warned[2].starts_with("M1000000000 ignored"), "{warned:?}");
    // Past u32: an error at the number.
    let (line, column, message) = first_error("G1 X1 F100\nG21 G99999999999 X2\n", 80.0);
    assert_eq!((line, column), (2, 6));
    assert!(message.contains("'99999999999' is too large"), "{message}");
}

#[test]
fn a_far_arc_center_names_its_word() {
    // J12345678901234567890 at 1000 steps/mm was "1:1: center: y =
    // 9223372036854776000 is outside ±2^30" (wrapped, at the wrong column).
    let (line, column, message) = first_error("G3 J12345678901234567890\n", 1000.0);
    assert_eq!((line, column), (1, 4));
    assert!(
        message.starts_with("J: the arc's center Y = 12345678901234567000 mm is beyond the machine's ±2^30 steps on y"),
        "{message}"
    );
    let (_, column, message) =
        first_error(&format!("G0 X1\nG2 X2 I1{} J0\n", "0".repeat(300)), 80.0);
    assert_eq!(column, 7);
    assert!(message.starts_with("I: the arc's center X"), "{message}");
    // G90.1 absolute centers with a huge K in G18: K is the zx plane's z.
    let (_, column, message) = first_error(
        &format!("G18 G90.1 G2 X0 Z0 K-1{} I0\n", "0".repeat(30)),
        80.0,
    );
    assert_eq!(column, 20);
    assert!(message.starts_with("K: the arc's center Z"), "{message}");
}

#[test]
fn a_circle_reaching_off_the_grid_names_its_center_word() {
    // Its center is on the grid but the circle about it is not: this was
    // "1:1: center: ..." at the G2, with the core's field name.
    let (line, column, message) = first_error("G2 X0 Y0 I100000000 F100\n", 10.0);
    assert_eq!((line, column), (1, 10));
    assert_eq!(
        message,
        "I: at 10 steps/mm, the circle of radius 1000000000.000 around x = 1000000000 reaches past ±2^30 (1073741824) on x; every point of the circle must be within it"
    );
    let (_, column, message) = first_error("G0 X1 Y0\nG3 X1 Y0 I0 J-100000000 F100\n", 10.0);
    assert_eq!(column, 13);
    assert!(
        message.starts_with("J: at 10 steps/mm, the circle of radius"),
        "{message}"
    );
}

#[test]
fn a_huge_radius_is_an_error_naming_r() {
    // R = 10^200: R² overflowed, the center and sweep were NaN (null in JSON).
    let (line, column, message) =
        first_error(&format!("G1 F100\nG2 X10 Y0 R1{}\n", "0".repeat(200)), 80.0);
    assert_eq!((line, column), (2, 11));
    assert!(message.starts_with("R: the arc's center"), "{message}");
    // A large radius that does fit is a correct, finite arc.
    let p = program("G2 X10 Y0 R100000 F100\n", 10.0);
    assert_eq!(p.info.errors, []);
    let arc = p.moves()[0].arc.clone().unwrap();
    assert!(arc.center_mm.iter().all(|c| c.is_finite()) && arc.sweep_deg.is_finite());
}

#[test]
fn a_feed_past_any_machine_is_an_error_naming_f() {
    let huge = format!("G1 X1 F1{}\n", "0".repeat(300));
    let (line, column, message) = first_error(&huge, 80.0);
    assert_eq!((line, column), (1, 7));
    assert!(
        message.starts_with("F (feed) must be at most 1e9 mm/min"),
        "{message}"
    );
    // In inches the limit is on the feed in mm/min, and the message gives both.
    let (_, column, message) = first_error("G20 G1 X1 F100000000\n", 80.0);
    assert_eq!(column, 11);
    assert_eq!(
        message,
        "F (feed) must be at most 1e9 mm/min, got 100000000 in/min (2540000000 mm/min)"
    );
}

#[test]
fn a_target_off_the_grid_names_its_axis_word() {
    let (line, column, message) = first_error("G1 X1 Y1000000000000 F100\n", 80.0);
    assert_eq!((line, column), (1, 7));
    assert!(
        message.starts_with("Y = 1000000000000 mm is beyond"),
        "{message}"
    );
}

#[test]
fn lone_cr_ends_a_line() {
    // Classic Mac OS line endings: three lines, not one.
    for source in ["G1 X1 F100\rG1 X2\rG1 X3\r", "G1 X1 F100\r\nG1 X2\r\nG1 X3"] {
        let p = program(source, 10.0);
        assert_eq!(p.info.errors, []);
        assert_eq!(p.info.lines, 3, "{source:?}");
        let lines: Vec<u32> = p.moves().iter().map(|m| m.line).collect();
        assert_eq!(lines, [1, 2, 3], "{source:?}");
        assert_eq!(p.info.steps, 30);
    }
    // An error after a CR is on its own line.
    assert_eq!(first_error("G1 X1 F100\rG1 X#\r", 10.0).0, 2);
}

#[test]
fn a_megabyte_of_huge_numbers_is_read_in_one_pass() {
    // 1 MB: one line of words with 300-digit values, each finite, and a
    // duplicate X that the interpreter refuses. Every word is read once.
    let digits = "9".repeat(300);
    let line: String = (0..3300).map(|_| format!("X{digits} ")).collect();
    let (_, column, message) = first_error(&format!("G1 {line}\n"), 1.0);
    assert_eq!(column, 4 + 302);
    assert_eq!(message, "X appears twice on this line");
}

/// Found by the fuzz target (tests/fuzz.rs): an unclosed comment ended by a
/// lone CR leaves a line of 4-byte characters, whose quote in the message
/// was cut at a byte inside one, a panic (in wasm, a trap).
#[test]
fn a_line_of_wide_characters_is_quoted_whole_characters() {
    // The error of line 2, the text after the lone CR.
    let second_line_error = |source: &str| {
        let p = program(source, 0.5);
        let error = p
            .info
            .errors
            .iter()
            .find(|d| d.line == 2)
            .unwrap_or_else(|| panic!("no error on line 2: {:?}", p.info.errors));
        error.message.clone()
    };
    let message =
        second_line_error("G0 (\r\u{10000}\u{10000}:\u{10000}\u{10000}\u{80}\u{800}\u{a1})\n");
    assert!(message.contains("'\u{10000}\u{10000}"), "{message}");
    // Past 24 characters: the first 16 whole, then the count.
    let message = second_line_error(&format!("G0 (\r{})\n", "\u{10000}".repeat(30)));
    assert!(
        message.contains(&format!("{}... (31 characters)", "\u{10000}".repeat(16))),
        "{message}"
    );
}

/// A NUL or an escape byte in a program is quoted as an escape, never raw.
#[test]
fn control_characters_are_quoted_as_escapes() {
    for (source, quoted) in [
        ("G1 X1\0 F100\n", "'\\u{0}'"),
        ("G1 X1 \u{1b}[2J\n", "\\u{1b}"),
    ] {
        let (line, _, message) = first_error(source, 1.0);
        assert_eq!(line, 1);
        assert!(message.contains(quoted), "{message}");
        assert!(!message.chars().any(char::is_control), "{message:?}");
    }
}

#[test]
fn a_byte_order_mark_is_skipped_and_invisible_characters_are_named() {
    // A UTF-8 file saved with a byte order mark (Windows editors) was
    // "1:1: '\u{feff}' is not G-code", the mark quoted as nothing.
    let p = program("\u{feff}G1 X1 F100\nG1 X2\n", 10.0);
    assert_eq!(p.info.errors, []);
    assert_eq!((p.info.lines, p.info.steps), (2, 20));
    // Columns on line 1 count from after the mark.
    assert_eq!(
        first_error("\u{feff}G1 X# F100\n", 10.0),
        first_error("G1 X# F100\n", 10.0)
    );
    // A no-break space (pasted from a web page) and a zero-width space are
    // named by their code points.
    for (source, quoted) in [
        ("G1\u{a0}X1 F100\n", "\\u{a0}"),
        ("G1 X1\u{200b} F100\n", "\\u{200b}"),
    ] {
        let (_, _, message) = first_error(source, 10.0);
        assert!(message.contains(quoted), "{message}");
    }
}

/// F1e300 was read as F1 and an E300 word (ignored with a warning), so the
/// move ran at 1 mm/min; G-code numbers have no exponent.
#[test]
fn an_exponent_is_an_error_naming_its_word() {
    let p = program("G1 X1 F1e300\n", 80.0);
    assert_eq!((p.info.steps, p.info.warnings.len()), (0, 0));
    let (line, column, message) = first_error("G1 X1 F1e300\n", 80.0);
    assert_eq!((line, column), (1, 7));
    assert!(
        message.starts_with("malformed number: F1e300: a G-code number has no exponent"),
        "{message}"
    );
}

/// A line that repeats a word or a code is refused at the repeat: 3 MB of
/// M3 on one line made a million "M3 ignored" warnings (50 MB: 51 s and
/// 2 GB of wasm memory), and X1 X1 ... a million words, before the
/// interpreter found the second X.
#[test]
fn a_line_of_repeats_stops_at_the_first_one_too_many() {
    let p = program(&" M48".repeat(1_000_000), 80.0);
    assert_eq!((p.info.warnings.len(), p.info.warnings_omitted), (0, 0));
    assert_eq!(
        first_error(&" M48".repeat(1_000_000), 80.0),
        (
            1,
            18,
            "too many M codes on this line: a line takes at most 4 (as LinuxCNC has it)"
                .to_string()
        )
    );
    // Of M3 again and again the fault is the second, as M3 M3's is: the
    // reader stops at the fifth, and the codes before it are judged.
    assert_eq!(
        first_error(&" M3".repeat(1_000_000), 80.0),
        (
            1,
            5,
            "M3 and M3 are both spindle codes: give one per line".to_string()
        )
    );
    let (_, column, message) = first_error(&format!("G1{}", " X1".repeat(1_000_000)), 80.0);
    assert_eq!(
        (column, message.as_str()),
        (7, "X appears twice on this line")
    );
}

#[test]
fn a_dwell_without_seconds_or_below_zero_names_p() {
    let (line, column, message) = first_error("G1 X1 F100\nG4 P-0.5\n", 80.0);
    assert_eq!((line, column), (2, 4));
    // As Grbl refuses any negative P (gcode.c step 2, error 4).
    assert_eq!(
        message,
        "P-0.5: P cannot be negative (Grbl refuses it: error 4, negative value)"
    );
    let (line, column, message) = first_error("G4\n", 80.0);
    assert_eq!((line, column), (1, 1));
    assert!(message.starts_with("G4 (dwell) needs P"), "{message}");
    // Zero is a dwell of no time, not an error.
    assert!(program("G4 P0\n", 80.0).info.errors.is_empty());
}

#[test]
fn an_arc_s_turns_are_a_whole_number_as_written() {
    // P2.99999999999999999 reads as 3.0 in f64, and ran 3 turns: the
    // reader kept only the rounded value.
    let circle = |p: &str| format!("G1 X10 F600\nG3 I-10 {p}\n");
    let refused = "P (turns) must be a whole number from 1 to 1000000, got";
    for (p, got) in [
        (
            "P2.99999999999999999",
            "a fraction too fine for a double, which rounds it to 3",
        ),
        (
            "P1.0000000000000000001",
            "a fraction too fine for a double, which rounds it to 1",
        ),
        ("P2.5", "2.5"),
        ("P0", "0"),
        ("P1000001", "1000001"),
    ] {
        assert_eq!(
            first_error(&circle(p), 80.0),
            (2, 9, format!("{refused} {got}")),
            "{p}"
        );
    }
    // A number with an exponent is no G-code number, at the P.
    let (line, column, message) = first_error(&circle("P1e-400"), 80.0);
    assert_eq!((line, column), (2, 9));
    assert!(
        message.starts_with("malformed number: P1e-400: "),
        "{message}"
    );
    // Whole as written, with zeros past its point to any length: 3 turns.
    let arc_steps = |p: &str| {
        let run = program(&circle(p), 80.0);
        assert!(run.info.errors.is_empty(), "{p}: {:?}", run.info.errors);
        run.info.steps - program("G1 X10 F600\n", 80.0).info.steps
    };
    assert_eq!(arc_steps("P3.00000000000000000000"), 3 * arc_steps("P1"));
}
