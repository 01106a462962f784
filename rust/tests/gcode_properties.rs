//! Property: a program of straight moves in G90 ends every move exactly on
//! its target rounded to steps, however many moves come before (no drift),
//! with every line algorithm.

use proptest::prelude::*;
use voxpath::Point;
use voxpath::gcode::{Settings, run};

/// Thousandths of a mm, within ±500 mm.
fn micro() -> impl Strategy<Value = i64> {
    -500_000i64..=500_000
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn g90_moves_end_on_their_rounded_targets(
        tenths_per_mm in 10u32..=2000,
        targets in prop::collection::vec((micro(), micro(), micro()), 1..12),
        line in prop::sample::select(voxpath::arc::arc_segments::LINE_ALGORITHMS),
    ) {
        let steps_per_mm = tenths_per_mm as f64 / 10.0;
        let mut source = String::from("G90 G21\n");
        let mut expected = Vec::new();
        for &(x, y, z) in &targets {
            let text = [x, y, z].map(|v| format!("{:.3}", v as f64 / 1000.0));
            source.push_str(&format!("G1 X{} Y{} Z{} F500\n", text[0], text[1], text[2]));
            // The value as written, times steps per mm, halves away from 0.
            expected.push(text.map(|t| (t.parse::<f64>().unwrap() * steps_per_mm).round() as i64));
        }
        let settings = Settings::from_json(&format!(
            r#"{{"stepsPerMm": {steps_per_mm}, "lineAlgorithm": "{line}"}}"#
        )).unwrap();
        let p = run(&source, settings);
        prop_assert_eq!(&p.info.errors, &vec![]);
        prop_assert_eq!(p.moves.len(), targets.len());
        for (m, want) in p.moves.iter().zip(&expected) {
            prop_assert_eq!(m.to_steps, *want);
            // Where the trace really is after the move's last step.
            prop_assert_eq!(p.trace.point(m.first_step + m.steps), Point::new(want));
        }
    }
}
