//! The machine: how many motor steps make a millimetre on each axis, and the
//! step/direction signals a trace sends to the motor drivers.
//!
//! Resolution (Wang et al. 2020, section 3.3): a motor of step angle θ
//! degrees, driven with s microsteps per full step, takes p_m = 360 / θ · s
//! pulses per revolution; on a lead screw of pitch P mm per revolution one
//! pulse moves the axis L = P / p_m mm. So steps per mm = 1 / L = p_m / P.
//! A 1.8° motor at 8 microsteps on a 2 mm screw: p_m = 200 · 8 = 1600,
//! L = 0.00125 mm, 800 steps per mm.
//!
//! Conversion: a position in mm becomes round(mm × steps/mm) steps, halves
//! away from zero (the f64 product decides what is a half). Every target is
//! converted from its absolute position, never as a sum of converted
//! increments, so a thousand moves of 0.01 mm at 80 steps/mm end at 800
//! steps (10 mm), not at 1000 (each 0.8 rounded up to 1).
//!
//! Step and direction: a driver takes a STEP pulse per step and a DIR level
//! saying which way. In voxpath's tick model one tick is one step of the
//! trace (step index k): it carries a STEP pulse on every axis that moves in
//! step k, with DIR already at that move's direction (a driver needs DIR
//! settled before the STEP edge). An axis that does not move keeps its last
//! DIR level; before its first move DIR is at the positive level. Ticks are
//! not time: a G-code program's steps get their instants from its planned
//! motion profile (`gcode::timing`).

use crate::error::Error;
use crate::grid::{COORD_LIMIT, MAX_AXES, round_half_away_within};
use crate::range::{NumberRange, NumberRangeInfo};
use crate::request::{OptionKind, OptionSpec, shown};
use crate::trace::Trace;
use serde::Serialize;
use serde_json::Value;
use tsify::Tsify;

/// The axes a machine has: X, Y and Z.
pub const MACHINE_AXES: usize = 3;

/// Millimetres per inch (G20).
pub const MM_PER_INCH: f64 = 25.4;

/// Steps per mm of each axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Machine {
    steps_per_mm: [f64; MACHINE_AXES],
}

/// Setting `spec`'s value on each axis, held to the range its spec
/// declares; errors name the setting and the axis ("acceleration: y must
/// be 1e-100 mm/s² or more, got 0").
pub(crate) fn check_axes(spec: &OptionSpec, values: &[f64; MACHINE_AXES]) -> Result<(), Error> {
    let range = spec.number_range();
    for (axis, &v) in values.iter().enumerate() {
        if let Some(words) = range.refusal(v) {
            return Err(Error::field(
                spec.name,
                format!("{} {words}", crate::grid::AXIS_NAMES[axis]),
            ));
        }
    }
    Ok(())
}

/// Setting `spec` from JSON: a number for every axis, or one per axis (x,
/// y, z). One number out of range is told so here, without an axis
/// ("acceleration: must be 1e-100 mm/s² or more, got 0"), as it was typed;
/// a list's values are held to the range by the constructor they go to
/// ([`Machine::new`], [`Machine::from_drive`], [`crate::planner::Limits::new`]: their
/// [`check_axes`] names the axis), which checks every value it is given.
/// A list's item that is not a finite number is named by its axis here, as
/// a point's is ("acceleration: y must be a number, got NaN").
pub(crate) fn per_axis(spec: &OptionSpec, value: &Value) -> Result<[f64; MACHINE_AXES], Error> {
    let field = spec.name;
    let number = |v: &Value| v.as_f64().filter(|x| x.is_finite());
    match value {
        Value::Array(items) if items.len() == MACHINE_AXES => {
            let mut out = [0.0; MACHINE_AXES];
            for (axis, item) in items.iter().enumerate() {
                out[axis] = number(item).ok_or_else(|| {
                    Error::field(
                        field,
                        format!(
                            "{} must be a number, got {}",
                            crate::grid::AXIS_NAMES[axis],
                            shown(item)
                        ),
                    )
                })?;
            }
            Ok(out)
        }
        Value::Array(items) => Err(Error::field(
            field,
            format!("{WRONG_COUNT}, got {}", items.len()),
        )),
        v => {
            let one = number(v).ok_or_else(|| {
                Error::field(field, format!("expected a number, got {}", shown(v)))
            })?;
            Ok([spec.number_range().check(field, one)?; MACHINE_AXES])
        }
    }
}

/// What a per-axis setting given as a list of another length is told,
/// before ", got" and the length.
const WRONG_COUNT: &str = "expected one number or 3 (x, y, z)";
const _: () = assert!(MACHINE_AXES == 3, "WRONG_COUNT names 3 axes");

/// A per-axis setting's declaration as the catalogue gives it: its range
/// (each value's), and how many values a list of them holds, so that the
/// page's form says a list of another length as the core does (it told
/// `10,0` y's range, and the core, once y was mended, the count).
#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct PerAxisInfo {
    #[serde(flatten)]
    pub range: NumberRangeInfo,
    /// Values in a list: one per axis of the machine.
    pub axes: usize,
    /// What the core tells a list of another length, before ", got" and
    /// its length ("expected one number or 3 (x, y, z)").
    pub wrong_count: &'static str,
}

/// [`OptionKind::PerAxis`]'s range as a [`PerAxisInfo`].
pub(crate) fn serialize_per_axis<S: serde::Serializer>(
    range: &NumberRange,
    s: S,
) -> Result<S::Ok, S::Error> {
    PerAxisInfo {
        range: range.info(),
        axes: MACHINE_AXES,
        wrong_count: WRONG_COUNT,
    }
    .serialize(s)
}

/// Fewest and most steps per mm a machine may have: one step a metre, and
/// one a nanometre. Outside them a program's moves round to no steps at all
/// (stepsPerMm 1e-300 once ran every move as 0 steps, silently) or to
/// coordinates past ±2^30 within a millimetre or so.
pub const MIN_STEPS_PER_MM: f64 = 0.001;
pub const MAX_STEPS_PER_MM: f64 = 1e6;

pub const STEPS_PER_MM: OptionSpec = OptionSpec {
    name: "stepsPerMm",
    kind: OptionKind::PerAxis(NumberRange::between(
        MIN_STEPS_PER_MM,
        MAX_STEPS_PER_MM,
        "steps per mm",
    )),
    required: false,
    default: None,
    applies_with: None,
    doc: "Steps per mm: one number for every axis, or one per axis as x,y,z (80,80,400). Or give stepAngle, microsteps and pitch.",
};

pub const STEP_ANGLE: OptionSpec = OptionSpec {
    name: "stepAngle",
    kind: OptionKind::PerAxis(NumberRange {
        max: Some(360.0),
        ..NumberRange::positive("degrees")
    }),
    required: false,
    default: None,
    applies_with: None,
    doc: "Motor step angle θ, degrees (one, or x,y,z): p_m = 360 / θ · s pulses per turn (Wang 3.3).",
};

pub const MICROSTEPS: OptionSpec = OptionSpec {
    name: "microsteps",
    kind: OptionKind::PerAxis(NumberRange::at_least(1.0, "").whole()),
    required: false,
    default: None,
    applies_with: None,
    doc: "Microsteps s per full step (one, or x,y,z).",
};

pub const PITCH: OptionSpec = OptionSpec {
    name: "pitch",
    kind: OptionKind::PerAxis(NumberRange::positive("mm per revolution")),
    required: false,
    default: None,
    applies_with: None,
    doc: "Lead-screw pitch P, mm per turn (one, or x,y,z): one step is L = P / p_m mm.",
};

impl Machine {
    /// A machine with the given steps per mm (each within STEPS_PER_MM's
    /// range, MIN_STEPS_PER_MM to MAX_STEPS_PER_MM).
    pub fn new(steps_per_mm: [f64; MACHINE_AXES]) -> Result<Machine, Error> {
        check_axes(&STEPS_PER_MM, &steps_per_mm)?;
        Ok(Machine { steps_per_mm })
    }

    /// Wang section 3.3: steps per mm = (360 / θ · s) / P, per axis.
    pub fn from_drive(
        step_angle_deg: [f64; MACHINE_AXES],
        microsteps: [f64; MACHINE_AXES],
        pitch_mm: [f64; MACHINE_AXES],
    ) -> Result<Machine, Error> {
        check_axes(&STEP_ANGLE, &step_angle_deg)?;
        check_axes(&MICROSTEPS, &microsteps)?;
        check_axes(&PITCH, &pitch_mm)?;
        let mut steps_per_mm = [0.0; MACHINE_AXES];
        let range = STEPS_PER_MM.number_range();
        for axis in 0..MACHINE_AXES {
            // p_m = 360 / θ · s pulses per revolution; L = P / p_m mm per pulse.
            let pulses_per_rev = 360.0 / step_angle_deg[axis] * microsteps[axis];
            steps_per_mm[axis] = pulses_per_rev / pitch_mm[axis];
            // Named by the settings given, not by stepsPerMm, which was not.
            if range.refusal(steps_per_mm[axis]).is_some() {
                return Err(Error::field(
                    STEP_ANGLE.name,
                    format!(
                        "stepAngle, microsteps and pitch give {} {} steps per mm, which {}",
                        crate::grid::AXIS_NAMES[axis],
                        crate::error::number_text(steps_per_mm[axis]),
                        range.must_be().expect("steps per mm have bounds")
                    ),
                ));
            }
        }
        Machine::new(steps_per_mm)
    }

    /// Reads `stepsPerMm`, or `stepAngle`, `microsteps` and `pitch`, from a
    /// settings object; each a number or one per axis.
    pub fn from_settings(settings: &serde_json::Map<String, Value>) -> Result<Machine, Error> {
        let drive = ["stepAngle", "microsteps", "pitch"];
        let given: Vec<&str> = drive
            .iter()
            .copied()
            .filter(|k| settings.contains_key(*k))
            .collect();
        match (settings.get("stepsPerMm"), given.len()) {
            (Some(_), n) if n > 0 => Err(Error::field(
                given[0],
                "give stepsPerMm or stepAngle, microsteps and pitch, not both",
            )),
            (Some(v), _) => Machine::new(per_axis(&STEPS_PER_MM, v)?),
            (None, 3) => Machine::from_drive(
                per_axis(&STEP_ANGLE, &settings[STEP_ANGLE.name])?,
                per_axis(&MICROSTEPS, &settings[MICROSTEPS.name])?,
                per_axis(&PITCH, &settings[PITCH.name])?,
            ),
            (None, 0) => Err(Error::field(
                "stepsPerMm",
                "missing: give steps per mm (80, or 80,80,400 for x, y, z), or stepAngle, microsteps and pitch",
            )),
            (None, _) => {
                let missing = drive
                    .iter()
                    .find(|k| !given.contains(k))
                    .expect("fewer than 3 given");
                Err(Error::field(
                    missing,
                    "missing: stepAngle, microsteps and pitch go together (Wang section 3.3)",
                ))
            }
        }
    }

    pub fn steps_per_mm(&self) -> [f64; MACHINE_AXES] {
        self.steps_per_mm
    }

    /// The position in steps nearest `mm` on `axis`: round(mm × steps/mm),
    /// halves away from zero, a half meant by the decimals counted as one
    /// ([`round_decimal_half_away`]). None beyond ±2^30 steps (the grid's
    /// limit).
    pub fn to_steps(&self, axis: usize, mm: f64) -> Option<i64> {
        let steps = round_decimal_half_away(mm * self.steps_per_mm[axis]);
        (steps.abs() <= COORD_LIMIT as f64).then_some(steps as i64)
    }
}

/// How far below a half, in units in the last place of the product, a
/// product of decimals still counts as that half. A program's decimal (X1.005)
/// is read as the nearest double (1.00499999999999989…), steps/mm as well,
/// and inches are multiplied by 25.4: each of these roundings is within half
/// a unit in the last place, so a product the decimals make exactly a half
/// lands at most a few units below it (1.005 mm at 100 steps/mm is
/// 100.49999999999999) and would be rounded down. 8 units covers them with
/// room; a product this close to a half without being one needs about 16
/// significant digits, which no program writes. Grbl gets most such halves
/// right by luck: it multiplies in 32-bit floats, whose rounding often
/// lands on the half.
const DECIMAL_HALF_ULPS: f64 = 8.0;

/// Below this magnitude a product may count as a half it is near (2^40).
const DECIMAL_HALVES_BELOW: f64 = (1u64 << 40) as f64;

/// `x.round()` (the nearest whole number, halves away from zero) for a
/// product of decimals: within [`DECIMAL_HALF_ULPS`] units in the last place
/// below a half, x is taken as that half ([`round_half_away_within`],
/// once per axis of every G-code move).
fn round_decimal_half_away(x: f64) -> f64 {
    // A unit in the last place of x is at most |x| ε. Past 2^40 (far past
    // the grid's 2^30, which to_steps refuses) 8 units would be a good part
    // of a step: plain rounding there.
    let slack = if x.abs() < DECIMAL_HALVES_BELOW {
        x.abs() * (DECIMAL_HALF_ULPS * f64::EPSILON)
    } else {
        0.0
    };
    round_half_away_within(x, slack)
}

/// DIR levels over step indices `from..to`: one byte per step, bit `axis`
/// set when that axis's DIR line is at its negative level during the step
/// (see the module comment for the tick model).
///
/// The levels before `from` are found by scanning back from `from` until
/// every axis has been seen moving: fast when all axes move often, at worst
/// one pass over the steps before `from` (2 bytes each).
pub fn direction_levels(trace: &Trace, from: u64, to: u64) -> Vec<u8> {
    let mut out = Vec::with_capacity(to.saturating_sub(from) as usize);
    push_direction_levels(trace, from, to, &mut out);
    out
}

/// [`direction_levels`], pushed onto `out` (which the caller may have made
/// room in).
pub fn push_direction_levels(trace: &Trace, from: u64, to: u64, out: &mut Vec<u8>) {
    let dims = trace.dims();
    let mut level = 0u8;
    let mut unknown: u8 = ((1u16 << dims) - 1) as u8;
    for step in trace.step_range(0, from).iter().rev() {
        if unknown == 0 {
            break;
        }
        let moving = step.moving_axes() & unknown;
        // Bits 8.. of a packed step are the negative directions.
        level |= moving & (step.0 >> 8) as u8;
        unknown &= !moving;
    }
    for step in trace.step_range(from, to) {
        let moving = step.moving_axes();
        level = (level & !moving) | (moving & (step.0 >> 8) as u8);
        out.push(level);
    }
}

const _: () = assert!(MACHINE_AXES <= MAX_AXES);

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::{Point, Step};
    use crate::ideal::IdealPath;
    use crate::trace::{Column, Decision, Stepper, TraceBuilder};
    use proptest::prelude::*;
    use serde_json::json;

    #[test]
    fn wang_section_3_3_gives_steps_per_mm() {
        // 1.8° at 8 microsteps: p_m = 360 / 1.8 · 8 = 1600 pulses per turn;
        // a 2 mm screw: L = 2 / 1600 = 0.00125 mm, so 800 steps per mm.
        let m = Machine::from_drive([1.8; 3], [8.0; 3], [2.0; 3]).unwrap();
        assert_eq!(m.steps_per_mm(), [800.0; 3]);
        // 0.9° full steps on an 8 mm screw: 400 / 8 = 50.
        let m = Machine::from_drive([1.8, 1.8, 0.9], [16.0, 16.0, 1.0], [40.0, 40.0, 8.0]).unwrap();
        assert_eq!(m.steps_per_mm(), [80.0, 80.0, 50.0]);
    }

    #[test]
    fn settings_name_the_field_at_fault() {
        let e = |v: serde_json::Value| {
            Machine::from_settings(v.as_object().unwrap())
                .unwrap_err()
                .to_string()
        };
        assert_eq!(
            e(json!({"stepsPerMm": [80, 80]})),
            "stepsPerMm: expected one number or 3 (x, y, z), got 2"
        );
        assert_eq!(
            e(json!({"stepsPerMm": [80, 0, 400]})),
            "stepsPerMm: y must be 0.001 to 1000000 steps per mm, got 0"
        );
        // Once 0 steps for every move, silently. One number is told as
        // typed, without an axis.
        assert_eq!(
            e(json!({"stepsPerMm": 1e-300})),
            "stepsPerMm: must be 0.001 to 1000000 steps per mm, got 1e-300"
        );
        assert_eq!(
            e(json!({"stepsPerMm": [80, 80, 2e6]})),
            "stepsPerMm: z must be 0.001 to 1000000 steps per mm, got 2000000"
        );
        assert_eq!(
            e(json!({"stepAngle": 1.8, "microsteps": 8})),
            "pitch: missing: stepAngle, microsteps and pitch go together (Wang section 3.3)"
        );
        assert_eq!(
            e(json!({"stepAngle": 1.8, "microsteps": 2.5, "pitch": 2})),
            "microsteps: must be a whole number, got 2.5"
        );
        assert_eq!(
            e(json!({"stepAngle": 1.8, "microsteps": [8, 0, 8], "pitch": 2})),
            "microsteps: y must be 1 or more, got 0"
        );
        assert_eq!(
            e(json!({"stepAngle": [1.8, 1.8, 400], "microsteps": 8, "pitch": 2})),
            "stepAngle: z must be more than 0 and at most 360 degrees, got 400"
        );
        // Steps per mm out of range from the motor's settings are told by them.
        assert_eq!(
            e(json!({"stepAngle": 1e-320, "microsteps": 8, "pitch": 2})),
            "stepAngle: stepAngle, microsteps and pitch give x Infinity steps per mm, which must be 0.001 to 1000000 steps per mm"
        );
        assert_eq!(
            e(json!({"stepAngle": 1.8, "microsteps": 8, "pitch": -2})),
            "pitch: must be more than 0 mm per revolution, got -2"
        );
        assert_eq!(
            e(json!({"stepsPerMm": 80, "pitch": 2})),
            "pitch: give stepsPerMm or stepAngle, microsteps and pitch, not both"
        );
        assert!(e(json!({})).starts_with("stepsPerMm: missing"));
        let m = Machine::from_settings(json!({"stepsPerMm": 80}).as_object().unwrap()).unwrap();
        assert_eq!(m.steps_per_mm(), [80.0; 3]);
    }

    #[test]
    fn rounding_is_half_away_from_zero() {
        // 0.5 mm at 3 steps/mm is exactly 1.5 steps in binary floating point.
        let m = Machine::new([3.0, 3.0, 3.0]).unwrap();
        assert_eq!(m.to_steps(0, 0.5), Some(2));
        assert_eq!(m.to_steps(0, -0.5), Some(-2));
        assert_eq!(m.to_steps(0, 0.4), Some(1));
        assert_eq!(m.to_steps(0, 1e9), None);
    }

    /// A stepper that replays a fixed list of steps.
    #[derive(Clone)]
    struct Script(Vec<Step>);

    #[derive(Clone, Copy)]
    struct NoWhy;

    impl Decision for NoWhy {
        const COLUMNS: &'static [Column] = &[];
        fn write(&self, _: &mut [f64]) {}
        fn explain(&self, _: &Point, _: Step) -> String {
            String::new()
        }
    }

    // SAFETY: the default fill, whose Filled counts the slots it wrote.
    unsafe impl Stepper for Script {
        type Why = NoWhy;
        fn next_step(&mut self) -> Option<(Step, NoWhy)> {
            (!self.0.is_empty()).then(|| (self.0.remove(0), NoWhy))
        }
        fn remaining_steps(&self) -> Option<u64> {
            Some(self.0.len() as u64)
        }
        fn setup_note(&self) -> String {
            String::new()
        }
    }

    #[test]
    fn direction_levels_hold_between_moves() {
        let steps = vec![
            Step::along(0, 1),
            Step::along(1, -1),
            Step::along(0, -1).with(2, 1),
            Step::along(1, 1),
            Step::NONE.with(2, -1),
        ];
        let origin = Point::new(&[0, 0, 0]);
        let mut b = TraceBuilder::new(origin, 100);
        b.run(
            Script(steps),
            IdealPath::Line {
                from: origin,
                to: origin,
            },
        )
        .unwrap();
        let t = b.finish("script");
        // Bit per axis, set = negative. x: +, +, -, -, -; y: +(never moved),
        // -, -, +, +; z: +, +, +, +, -.
        assert_eq!(
            direction_levels(&t, 0, 5),
            vec![0b000, 0b010, 0b011, 0b001, 0b101]
        );
        // A range that starts later finds the same levels by scanning back.
        assert_eq!(direction_levels(&t, 3, 5), vec![0b001, 0b101]);
        assert_eq!(direction_levels(&t, 5, 5), Vec::<u8>::new());
    }

    #[test]
    fn rounding_takes_halves_away_from_zero_as_f64_round() {
        let halves = [0.5, 1.5, 2.5, -0.5, -2.5, 4503599627370495.5];
        let special = [
            0.0,
            -0.0,
            -0.3,
            f64::INFINITY,
            f64::NEG_INFINITY,
            1e300,
            -1e-300,
        ];
        for x in halves.into_iter().chain(special) {
            assert_eq!(
                round_decimal_half_away(x).to_bits(),
                x.round().to_bits(),
                "{x}"
            );
        }
        assert!(round_decimal_half_away(f64::NAN).is_nan());
    }

    #[test]
    fn a_half_the_decimals_mean_is_a_half() {
        // Each product is a few units in the last place below the half its
        // decimals make: f64::round takes them down.
        let m = |spm: f64| Machine::new([spm; 3]).unwrap();
        for (mm, spm, steps) in [
            (1.005f64, 100.0f64, 101i64),
            (-1.005, 100.0, -101),
            (0.145, 100.0, 15),
            (1.015, 100.0, 102),
            (0.49999999999999994, 1.0, 1),
        ] {
            assert!((mm * spm).round().abs() < (steps as f64).abs(), "{mm}");
            assert_eq!(m(spm).to_steps(0, mm), Some(steps), "{mm} mm at {spm}");
        }
        // 16 significant digits short of a half is not one.
        assert_eq!(m(1.0).to_steps(0, 100.4999999999997), Some(100));
    }

    proptest! {
        #[test]
        fn rounding_is_f64_round_away_from_halves(bits in any::<u64>(), whole in 0..(1i64 << 31), negative: bool) {
            // Any bit pattern not within a thousandth of a half (or past
            // 2^40): what f64::round gives.
            let x = f64::from_bits(bits);
            let off_half = ((x - x.trunc()).abs() - 0.5).abs() > 1e-3;
            if !x.is_nan() && (off_half || x.abs() >= DECIMAL_HALVES_BELOW) {
                prop_assert_eq!(round_decimal_half_away(x).to_bits(), x.round().to_bits());
            }
            // Up to 8 units in the last place either side of a half: away
            // from zero; 17 nearer zero (more than 8 |x| ε): toward zero.
            let sign = if negative { -1.0 } else { 1.0 };
            let half = sign * (whole as f64 + 0.5);
            let ulps = |k: i64| f64::from_bits((half.to_bits() as i64 + k) as u64);
            for k in -8..=8 {
                prop_assert_eq!(round_decimal_half_away(ulps(k)), sign * (whole as f64 + 1.0), "{}", ulps(k));
            }
            prop_assert_eq!(round_decimal_half_away(ulps(-17)), sign * whole as f64, "{}", ulps(-17));
        }
    }
}
