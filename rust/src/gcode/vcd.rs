//! A program's STEP and DIR wires as an IEEE 1364 Value Change Dump (VCD),
//! written with the `vcd` crate, so a run opens in PulseView, GTKWave or
//! sigrok like a logic-analyser capture of the motor drivers' inputs.
//!
//! Wires, in module `voxpath`: `x_step`, `x_dir`, `y_step`, ... for every
//! axis; timescale 1 ns; time 0 is the program's start.
//! - STEP: a pulse per step of the axis, rising at the step's instant on
//!   the planned profile (`timing`) and falling Grbl's
//!   DEFAULT_STEP_PULSE_MICROSECONDS (10 µs, defaults.h) later, or halfway
//!   to the next step event when that comes sooner. One rising edge = one
//!   step: `G1 X200` at 80 steps/mm is 16,000 rising edges on `x_step`.
//! - DIR: 1 while the axis runs negative (Grbl's direction_bits, no invert
//!   mask), 0 while it runs positive; 0 at the start. A change is written
//!   halfway between the previous step event and the step that needs it, so
//!   it is settled before the STEP edge, as drivers need (and after the
//!   previous pulse has fallen).

use super::timing::Timeline;
use crate::grid::AXIS_NAMES;
use crate::machine::direction_levels;
use crate::trace::Trace;
use std::io::{self, Write};
use vcd::{IdCode, TimescaleUnit, Value};

/// Grbl's DEFAULT_STEP_PULSE_MICROSECONDS, as seconds.
pub const STEP_PULSE_SECONDS: f64 = 10e-6;

/// Steps read per chunk: the times and levels of one chunk at a time.
const CHUNK_STEPS: u64 = 1 << 16;

/// The last instant a VCD of 1 ns ticks holds (u64 nanoseconds, about
/// 584 years).
const LAST_SECONDS: f64 = u64::MAX as f64 / 1e9;

fn nanoseconds(seconds: f64) -> u64 {
    (seconds * 1e9).round().max(0.0) as u64
}

/// The first two steps whose ticks come under 2 ns apart, as an error: a
/// pulse rises on the first step's tick and must fall on a tick before the
/// next step's rises. (A pulse rises on its step's own tick: every edge
/// written before it, a DIR change halfway from the step before or that
/// step's fall, is on an earlier tick, so the file's time never runs ahead.)
fn too_close_steps(timeline: &Timeline) -> io::Result<()> {
    let steps = timeline.steps();
    let mut previous: Option<f64> = None;
    let mut from = 0;
    while from < steps {
        let to = (from + CHUNK_STEPS).min(steps);
        for (i, t) in timeline.step_seconds(from, to).into_iter().enumerate() {
            if let Some(before) = previous {
                if nanoseconds(t) < nanoseconds(before) + 2 {
                    let k = from + i as u64;
                    return Err(io::Error::new(
                        io::ErrorKind::InvalidInput,
                        format!(
                            "steps {} and {k} come {:.3e} s apart at {before:.9} s on the planned profile ({:.3e} steps/s), too close for a pulse between them in a VCD of 1 ns ticks; lower maxRate or the feed",
                            k - 1,
                            t - before,
                            1.0 / (t - before)
                        ),
                    ));
                }
            }
            previous = Some(t);
        }
        from = to;
    }
    Ok(())
}

/// A program's VCD written a part at a time: the header, then
/// `CHUNK_STEPS` steps per call, so that a caller can hand each part on
/// (the CLI to its output) and hold only one: a 50,000,000-step program's
/// VCD is about 1.6 GB, which a wasm memory of 4 GiB holding the trace and
/// a doubling buffer could not take whole. Where the last part ended (the
/// tick, the DIR levels, the last step's instant) is kept between calls.
pub struct VcdChunks {
    /// The STEP and DIR wires of each axis, once the header is written.
    wires: Option<Vec<(IdCode, IdCode)>>,
    /// The first step not yet written.
    next_step: u64,
    /// The tick of the last timestamp written.
    written_ns: u64,
    /// DIR of each axis, bit per axis (1 = negative).
    level: u8,
    /// The instant of the last step written, seconds.
    previous_seconds: f64,
}

impl VcdChunks {
    /// An `InvalidInput` error, before anything is written, when the program
    /// lasts longer than a VCD's ticks reach, or when two of its steps come
    /// too close for a pulse between them (on ticks under 2 ns apart). Both
    /// are found here, in one pass over the steps' instants, so that a
    /// caller writing the parts as they come never writes part of a file
    /// that then fails: the CLI had written a 1.4 MB VCD when the steps
    /// came too close, and its status said the command line was wrong.
    pub fn new(timeline: &Timeline) -> io::Result<Self> {
        // Past the last tick every edge would be pressed onto that one tick
        // (acceleration 1e-300, before its least, made a VCD of two timestamps): refused instead.
        let duration = timeline.duration_seconds();
        if duration.is_nan() || duration + STEP_PULSE_SECONDS > LAST_SECONDS {
            return Err(io::Error::new(
                io::ErrorKind::InvalidInput,
                format!(
                    "the program lasts {duration:.3e} s on its planned profile, past the {LAST_SECONDS:.3e} s (584 years) that a VCD of 1 ns ticks reaches"
                ),
            ));
        }
        too_close_steps(timeline)?;
        Ok(Self {
            wires: None,
            next_step: 0,
            written_ns: 0,
            level: 0,
            previous_seconds: 0.0,
        })
    }

    /// Writes the next part (the header first, then up to `CHUNK_STEPS`
    /// steps) to `out`; false, writing nothing, once every step is written.
    pub fn write_next(
        &mut self,
        trace: &Trace,
        timeline: &Timeline,
        out: impl Write,
    ) -> io::Result<bool> {
        let mut w = vcd::Writer::new(out);
        let Some(wires) = &self.wires else {
            self.wires = Some(write_header(&mut w, trace.dims())?);
            return Ok(true);
        };
        let steps = trace.steps();
        let from = self.next_step;
        if from >= steps {
            return Ok(false);
        }
        // Moves the file's time to tick `ns` (never back), and says to which tick.
        let written_ns = &mut self.written_ns;
        let mut at = |w: &mut vcd::Writer<_>, ns: u64| -> io::Result<u64> {
            let ns = ns.max(*written_ns);
            if ns != *written_ns {
                w.timestamp(ns)?;
                *written_ns = ns;
            }
            Ok(ns)
        };
        let to = (from + CHUNK_STEPS).min(steps);
        let times = timeline.step_seconds(from, to);
        // One more instant, for the last pulse's fall.
        let next = if to < steps {
            timeline.step_seconds(to, to + 1)[0]
        } else {
            f64::INFINITY
        };
        let codes = trace.step_range(from, to);
        let levels = direction_levels(trace, from, to);
        for i in 0..(to - from) as usize {
            let (t, moving) = (times[i], codes[i].moving_axes());
            let changed = (levels[i] ^ self.level) & moving;
            if changed != 0 {
                at(
                    &mut w,
                    nanoseconds(self.previous_seconds + (t - self.previous_seconds) / 2.0),
                )?;
                for (axis, &(_, dir)) in wires.iter().enumerate() {
                    if changed >> axis & 1 == 1 {
                        w.change_scalar(dir, Value::from(levels[i] >> axis & 1 == 1))?;
                    }
                }
                self.level ^= changed;
            }
            let rise_ns = at(&mut w, nanoseconds(t))?;
            for (axis, &(step, _)) in wires.iter().enumerate() {
                if moving >> axis & 1 == 1 {
                    w.change_scalar(step, Value::V1)?;
                }
            }
            let following = times.get(i + 1).copied().unwrap_or(next);
            // In whole ticks: the pulse falls halfway to the next step's
            // tick, or STEP_PULSE_SECONDS after it rises if that is sooner.
            // Two steps less than 2 ticks apart leave no tick between them
            // for the fall: written as 1 and 0 at one instant, or merged with
            // the next rise, a step would be in the file that no logic
            // analyser would see.
            let pulse_ns = nanoseconds(STEP_PULSE_SECONDS);
            let fall_ns = if following.is_finite() {
                // At least 2 ticks after the rise (too_close_steps).
                let next_ns = nanoseconds(following);
                rise_ns + pulse_ns.min((next_ns - rise_ns) / 2)
            } else {
                rise_ns + pulse_ns
            };
            at(&mut w, fall_ns)?;
            for (axis, &(step, _)) in wires.iter().enumerate() {
                if moving >> axis & 1 == 1 {
                    w.change_scalar(step, Value::V0)?;
                }
            }
            self.previous_seconds = t;
        }
        self.next_step = to;
        Ok(true)
    }
}

/// The definitions and the initial values (every wire 0); returns the
/// STEP and DIR wires of each of `dims` axes.
fn write_header(w: &mut vcd::Writer<impl Write>, dims: usize) -> io::Result<Vec<(IdCode, IdCode)>> {
    w.comment("voxpath: STEP and DIR per axis on the planned motion profile (Grbl 1.1's planner); DIR 1 = negative")?;
    w.timescale(1, TimescaleUnit::NS)?;
    w.add_module("voxpath")?;
    let mut wires: Vec<(IdCode, IdCode)> = Vec::with_capacity(dims);
    for name in &AXIS_NAMES[..dims] {
        wires.push((
            w.add_wire(1, &format!("{name}_step"))?,
            w.add_wire(1, &format!("{name}_dir"))?,
        ));
    }
    w.upscope()?;
    w.enddefinitions()?;
    w.timestamp(0)?;
    w.begin(vcd::SimulationCommand::Dumpvars)?;
    for &(step, dir) in &wires {
        w.change_scalar(step, Value::V0)?;
        w.change_scalar(dir, Value::V0)?;
    }
    w.end()?;
    Ok(wires)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gcode::program::{Settings, run};
    use vcd::Command;

    /// Writes the VCD of `trace`'s steps at the instants of `timeline`, whole
    /// (see `VcdChunks` for the errors).
    fn write_vcd(trace: &Trace, timeline: &Timeline, mut out: impl Write) -> io::Result<()> {
        let mut chunks = VcdChunks::new(timeline)?;
        while chunks.write_next(trace, timeline, &mut out)? {}
        out.flush()
    }

    /// (rising edge times in ns, DIR changes as (ns, value)) per wire name.
    fn read_back(text: &[u8]) -> std::collections::HashMap<String, Vec<(u64, bool)>> {
        let mut parser = vcd::Parser::new(text);
        let header = parser.parse_header().unwrap();
        let mut names = std::collections::HashMap::new();
        for axis in ["x", "y", "z"] {
            for wire in ["step", "dir"] {
                let name = format!("{axis}_{wire}");
                let var = header.find_var(&["voxpath", name.as_str()]).unwrap();
                names.insert(var.code, name);
            }
        }
        let mut changes: std::collections::HashMap<String, Vec<(u64, bool)>> =
            std::collections::HashMap::new();
        let mut now = 0;
        for command in parser {
            match command.unwrap() {
                Command::Timestamp(t) => now = t,
                Command::ChangeScalar(id, v) => changes
                    .entry(names[&id].clone())
                    .or_default()
                    .push((now, v == Value::V1)),
                _ => {}
            }
        }
        changes
    }

    #[test]
    fn a_program_longer_than_the_ticks_reach_is_refused() {
        // 1e-100 mm/s² (the least): the planned run lasts 1.3e51 s; at
        // 1e-300 every edge was written at tick u64::MAX: two timestamps
        // for 3,200 edges.
        let settings =
            Settings::from_json(r#"{"stepsPerMm": 80, "acceleration": 1e-100}"#).unwrap();
        let program = run("G1 X10 Y5 F600\nG1 X0\n", settings);
        let mut out = Vec::new();
        let error = write_vcd(&program.trace, &program.timeline, &mut out).unwrap_err();
        assert_eq!(error.kind(), io::ErrorKind::InvalidInput);
        assert!(
            error.to_string().starts_with(
                "the program lasts 1.255e51 s on its planned profile, past the 1.845e10 s"
            ),
            "{error}"
        );
        assert!(out.is_empty());
    }

    #[test]
    fn steps_too_close_for_a_pulse_between_them_are_refused() {
        // At 1e300 mm/min and mm/s² all 800 steps came at instant 0, written
        // as 800 pulses of no width under #0.
        let settings =
            Settings::from_json(r#"{"stepsPerMm": 80, "acceleration": 1e300, "maxRate": 1e300}"#)
                .unwrap();
        let program = run("G0 X10\n", settings);
        let mut out = Vec::new();
        let error = write_vcd(&program.trace, &program.timeline, &mut out).unwrap_err();
        assert_eq!(error.kind(), io::ErrorKind::InvalidInput);
        // Found before the first part: nothing is written (the CLI wrote
        // the parts before such steps, then failed).
        assert!(out.is_empty());
        assert!(
            error.to_string().starts_with("steps 0 and 1 come "),
            "{error}"
        );
        assert!(
            error
                .to_string()
                .contains("too close for a pulse between them in a VCD of 1 ns ticks"),
            "{error}"
        );
        // Far into a program too: past two parts of slow steps, two 2 ns apart.
        let settings =
            Settings::from_json(r#"{"stepsPerMm": 100000, "maxRate": 1e9, "acceleration": 1.4e7}"#)
                .unwrap();
        let program = run("G1 X0.5 F60\nG1 X2.5 F1000000000\n", settings);
        assert!(
            program.info.steps > 2 * CHUNK_STEPS,
            "{}",
            program.info.steps
        );
        let mut out = Vec::new();
        let far = write_vcd(&program.trace, &program.timeline, &mut out).unwrap_err();
        assert!(far.to_string().contains("too close for a pulse"), "{far}");
        assert!(out.is_empty());
        // A nanosecond apart: each fall would land on the next step's rise
        // (a 0.5 ns pulse rounded onto the next tick merged the two pulses).
        let at_rate = |max_rate: &str| {
            Settings::from_json(&format!(
                r#"{{"stepsPerMm": 80, "acceleration": 1e30, "maxRate": {max_rate}}}"#
            ))
            .unwrap()
        };
        let nanosecond = run("G0 X10\n", at_rate("7.5e8"));
        assert!(write_vcd(&nanosecond.trace, &nanosecond.timeline, &mut Vec::new()).is_err());
        // Four nanoseconds apart, and 80 million steps a second (12.5 ns
        // apart, about 6 ns wide): every pulse, on ticks of its own.
        for (source, max_rate) in [("G0 X10\n", "1.875e8"), ("G1 X10 F60000000\n", "6e7")] {
            let program = run(source, at_rate(max_rate));
            assert_eq!(program.info.errors, []);
            assert_eq!(program.info.steps, 800);
            let mut out = Vec::new();
            write_vcd(&program.trace, &program.timeline, &mut out).unwrap();
            let x = &read_back(&out)["x_step"];
            assert_eq!(x.iter().filter(|c| c.1).count(), 800, "{source}");
            assert!(x.windows(2).all(|w| w[0].0 < w[1].0), "{source}");
        }
    }

    #[test]
    fn parts_of_chunk_steps_each_carry_the_time_and_dir_across_their_ends() {
        // 65,536 steps out, so that the reversal is the first step of the
        // second part, then as many back.
        let settings =
            Settings::from_json(r#"{"stepsPerMm": 80, "acceleration": 100, "maxRate": 6000}"#)
                .unwrap();
        let program = run("G1 X819.2 F6000\nG1 X0\n", settings);
        assert_eq!(program.info.steps, 2 * CHUNK_STEPS);
        let mut chunks = VcdChunks::new(&program.timeline).unwrap();
        let mut parts: Vec<Vec<u8>> = Vec::new();
        loop {
            let mut part = Vec::new();
            if !chunks
                .write_next(&program.trace, &program.timeline, &mut part)
                .unwrap()
            {
                assert!(part.is_empty());
                break;
            }
            parts.push(part);
        }
        // The header, then two parts of steps.
        assert_eq!(parts.len(), 3);
        let whole = parts.concat();
        let changes = read_back(&whole);
        let rising: Vec<u64> = changes["x_step"]
            .iter()
            .filter(|c| c.1)
            .map(|c| c.0)
            .collect();
        assert_eq!(rising.len(), 2 * CHUNK_STEPS as usize);
        let x = &changes["x_step"];
        assert!(x.windows(2).all(|w| w[0].0 < w[1].0 && w[0].1 != w[1].1));
        // DIR turns once, between the last step out and the first back.
        let dir = &changes["x_dir"];
        assert_eq!(dir.len(), 2);
        let turn = CHUNK_STEPS as usize;
        assert!(dir[1].1 && dir[1].0 > rising[turn - 1] && dir[1].0 < rising[turn]);
        // No timestamp is written twice, or back in time, across a part's end.
        let text = String::from_utf8(whole).unwrap();
        let stamps: Vec<u64> = text
            .lines()
            .filter_map(|l| l.strip_prefix('#')?.parse().ok())
            .collect();
        assert!(stamps.windows(2).all(|w| w[0] < w[1]));
    }

    #[test]
    fn the_issues_example_has_16000_timed_x_step_edges() {
        let settings =
            Settings::from_json(r#"{"stepsPerMm": 80, "acceleration": 100, "maxRate": 6000}"#)
                .unwrap();
        let program = run("G1 X200 F6000\nG1 X100\n", settings);
        let mut out = Vec::new();
        write_vcd(&program.trace, &program.timeline, &mut out).unwrap();
        let changes = read_back(&out);
        let rising: Vec<u64> = changes["x_step"]
            .iter()
            .filter(|c| c.1)
            .map(|c| c.0)
            .collect();
        // 16,000 steps out, 8,000 back.
        assert_eq!(rising.len(), 24_000);
        // The 400th at √(2·5/100) s = 0.316227766... s (s = ½at²: 5 mm at
        // 100 mm/s²), to the nanosecond.
        assert_eq!(rising[399], 316_227_766);
        assert_eq!(rising[15_999], 3_000_000_000);
        // Falls 10 µs after it rises (125 µs apart at 100 mm/s).
        let x = &changes["x_step"];
        let fall = x.iter().position(|c| !c.1 && c.0 > rising[7000]).unwrap();
        assert_eq!(x[fall].0 - rising[7000], 10_000);
        // DIR: 0 at the start, 1 before the first step back, and settled
        // before it.
        let dir = &changes["x_dir"];
        assert_eq!(dir.len(), 2);
        assert!(dir[1].1 && dir[1].0 > rising[15_999] && dir[1].0 < rising[16_000]);
        // Y and Z never pulse.
        assert_eq!(changes["y_step"].len(), 1);
    }
}
