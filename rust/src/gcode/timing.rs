//! When each move and each step of a program happens, on the planned motion
//! profile (see `crate::planner`, modelled on Grbl 1.1's planner.c).
//!
//! - A move becomes planner blocks: a line one block, from its rounded
//!   start to its rounded end in steps (Grbl's `plan_buffer_line` plans the
//!   distance between step positions); an arc one block per chord of Grbl's
//!   `mc_arc` (motion_control.c), each vertex rounded to steps as Grbl
//!   rounds every target. The steps themselves are still those the chosen
//!   algorithm took: only their instants come from the plan.
//! - Rate: G0 runs at the top rate along the move; G1-G3 at F, at most the
//!   top rate. A feed move before any F is refused by Grbl (error 22,
//!   undefined feed rate); voxpath runs it, timed at the top rate, and warns.
//! - Step k (0-based) of a move of n steps happens when the planned position
//!   along the move's blocks reaches (k + 1) / n of its length: Grbl spreads
//!   a block's step events evenly along it, one per step of its major axis
//!   (a step of the trace is one step event, whichever axes it moves). Step
//!   instants are computed on demand for any range, never stored.

use super::interpret::{Motion, MoveMm};
use crate::error::Error;
use crate::grid::{AXIS_NAMES, Point};
use crate::machine::{MACHINE_AXES, Machine, per_axis};
use crate::planner::{self, Limits, Plan, Planner, Rate, Timing};
use serde_json::{Map, Value};
use std::ops::Range;

/// Reads `acceleration`, `maxRate`, `junctionDeviation` and `maxStepRate`
/// (Grbl's defaults when absent); errors name the setting.
pub fn limits_from_settings(settings: &Map<String, Value>) -> Result<Limits, Error> {
    let defaults = Limits::default();
    let axes = |name: &str, default: [f64; MACHINE_AXES]| {
        settings
            .get(name)
            .map_or(Ok(default), |v| per_axis(name, v))
    };
    let junction_deviation_mm = match settings.get(planner::JUNCTION_DEVIATION.name) {
        None => defaults.junction_deviation_mm,
        Some(v) => v.as_f64().ok_or_else(|| {
            Error::field(
                planner::JUNCTION_DEVIATION.name,
                format!("expected a number, got {v}"),
            )
        })?,
    };
    let max_step_rate_hz = match settings.get(planner::MAX_STEP_RATE.name) {
        None => None,
        Some(v) => Some(per_axis(planner::MAX_STEP_RATE.name, v)?),
    };
    Limits::new(
        axes(planner::ACCELERATION.name, defaults.acceleration_mm_per_s2)?,
        axes(planner::MAX_RATE.name, defaults.max_rate_mm_per_min)?,
        junction_deviation_mm,
        max_step_rate_hz,
    )
}

/// Pushes the blocks of move `m`, stepped from `from` to `to` (steps);
/// returns the range of blocks it took (empty when it does not move).
pub fn push_move(
    planner: &mut Planner,
    machine: &Machine,
    m: &MoveMm,
    from: &Point,
    to: &Point,
) -> Range<usize> {
    let first = planner.len();
    let spm = machine.steps_per_mm();
    let rate = match (m.motion, m.feed_mm_per_min) {
        (Motion::Rapid, _) => Rate::Rapid,
        (_, Some(feed)) => Rate::Feed(feed),
        (_, None) => Rate::Unset,
    };
    let to: [i64; MACHINE_AXES] = to.coords().try_into().expect("3 axes");
    let mut targets = Vec::new();
    if let Some(arc) = &m.arc {
        let vertices = planner::arc_chords(
            m.from_mm,
            m.to_mm,
            arc.centre_mm,
            arc.plane.axes(),
            arc.radius_mm,
            arc.sweep_rad,
        );
        for vertex in &vertices[..vertices.len() - 1] {
            // A vertex lies within the arc's box, whose corners were
            // rounded to steps already: its rounding fits too.
            targets.push(std::array::from_fn(|axis| {
                machine.to_steps(axis, vertex[axis]).unwrap_or(to[axis])
            }));
        }
    }
    targets.push(to);
    let mut previous: [i64; MACHINE_AXES] = from.coords().try_into().expect("3 axes");
    for target in targets {
        let delta = std::array::from_fn(|axis| (target[axis] - previous[axis]) as f64 / spm[axis]);
        planner.push(delta, rate);
        previous = target;
    }
    first..planner.len()
}

/// The plan of a finished program, and which blocks and steps each move has.
#[derive(Clone, Debug, Default)]
pub struct Timeline {
    plan: Plan,
    /// Per move: its blocks, its first step index and its step count.
    moves: Vec<(Range<usize>, u64, u64)>,
}

impl Timeline {
    /// Plans `planner`'s blocks; `moves` is, per move, (blocks, first step,
    /// steps), in step order.
    pub fn new(planner: Planner, moves: Vec<(Range<usize>, u64, u64)>) -> Timeline {
        Timeline {
            plan: planner.plan(),
            moves,
        }
    }

    pub fn plan(&self) -> &Plan {
        &self.plan
    }

    pub fn duration_seconds(&self) -> f64 {
        self.plan.duration_seconds
    }

    /// The timing of move `index`.
    pub fn move_timing(&self, index: usize) -> Timing {
        let (blocks, _, _) = &self.moves[index];
        // A move with no blocks is an instant, where the last move before
        // it ended.
        let at = self.plan.blocks[..blocks.start]
            .last()
            .map_or(0.0, |b| b.start_seconds + b.duration_seconds());
        self.plan.timing(blocks.clone(), at)
    }

    /// Step-rate warnings: (move index, axis, steps/s needed, the limit).
    pub fn step_rate_excesses(
        &self,
        limits: &Limits,
        steps_per_mm: &[f64; MACHINE_AXES],
    ) -> Vec<(usize, usize, f64, f64)> {
        let Some(max) = limits.max_step_rate_hz else {
            return Vec::new();
        };
        let mut out = Vec::new();
        for (index, (blocks, _, _)) in self.moves.iter().enumerate() {
            let peak = self.plan.peak_step_rates_hz(blocks.clone(), steps_per_mm);
            for axis in 0..MACHINE_AXES {
                if peak[axis] > max[axis] * (1.0 + 1e-9) {
                    out.push((index, axis, peak[axis], max[axis]));
                }
            }
        }
        out
    }

    /// The planned speed as polyline corners, (seconds, mm/s) flat, four
    /// per block: start, end of acceleration, start of deceleration, end.
    pub fn speed_profile(&self) -> Vec<f64> {
        let mut out = Vec::with_capacity(8 * self.plan.blocks.len());
        for b in &self.plan.blocks {
            let p = b.phases();
            let t0 = b.start_seconds;
            let t1 = t0 + p.accelerate_seconds;
            let t2 = t1 + p.cruise_seconds;
            out.extend_from_slice(&[
                t0,
                b.entry_speed_mm_per_s,
                t1,
                b.peak_speed_mm_per_s,
                t2,
                b.peak_speed_mm_per_s,
                t2 + p.decelerate_seconds,
                b.exit_speed_mm_per_s,
            ]);
        }
        out
    }

    /// Each axis's planned step rate at the same corners as
    /// [`Timeline::speed_profile`]: (seconds, then steps/s per axis) flat,
    /// the speed times the axis's share of the block's direction times its
    /// steps per mm.
    pub fn step_rate_profile(&self, steps_per_mm: &[f64; MACHINE_AXES]) -> Vec<f64> {
        let speeds = self.speed_profile();
        let mut out = Vec::with_capacity(speeds.len() / 2 * (1 + MACHINE_AXES));
        for (b, corners) in self.plan.blocks.iter().zip(speeds.chunks_exact(8)) {
            for corner in corners.chunks_exact(2) {
                out.push(corner[0]);
                for axis in 0..MACHINE_AXES {
                    out.push(
                        corner[1] * (b.delta_mm[axis] / b.length_mm).abs() * steps_per_mm[axis],
                    );
                }
            }
        }
        out
    }

    /// The blocks in `blocks` that start a move after another block (where
    /// the machine turns from one move into the next), ascending.
    pub fn move_starts(&self, blocks: Range<usize>) -> Vec<usize> {
        let first = self
            .moves
            .partition_point(|(b, _, _)| b.start < blocks.start);
        let mut starts: Vec<usize> = self.moves[first..]
            .iter()
            .map(|(b, _, _)| b.start)
            .take_while(|&start| start < blocks.end)
            .filter(|&start| start > 0)
            .collect();
        // A move with no blocks starts where the next one does.
        starts.dedup();
        starts
    }

    /// The point index the machine has reached at `seconds`: how many steps
    /// happen at or before that instant (0 before the first; every step
    /// once the program has ended). Bisects the steps by their instants
    /// (`step_seconds`, monotone), so it agrees with them exactly.
    pub fn points_reached_at(&self, seconds: f64) -> u64 {
        let steps = self.moves.last().map_or(0, |(_, first, n)| first + n);
        let (mut lo, mut hi) = (0, steps);
        while lo < hi {
            let mid = lo + (hi - lo) / 2;
            if self.step_seconds(mid, mid + 1)[0] <= seconds {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        lo
    }

    /// The instant of every step index in `from..to`, seconds from the
    /// program's start (see the module comment).
    pub fn step_seconds(&self, from: u64, to: u64) -> Vec<f64> {
        let mut out = Vec::with_capacity(to.saturating_sub(from) as usize);
        if from >= to {
            return out;
        }
        // The first move whose steps end past `from`.
        let mut index = self
            .moves
            .partition_point(|(_, first, steps)| first + steps <= from);
        while out.len() < (to - from) as usize {
            let Some((blocks, first, steps)) = self.moves.get(index) else {
                break;
            };
            let (lo, hi) = (from.max(*first) - first, to.min(first + steps) - first);
            if blocks.is_empty() {
                let at = self.move_timing(index).start_seconds;
                out.extend(std::iter::repeat_n(at, (hi - lo) as usize));
            } else {
                self.plan
                    .visit_fractions(blocks.clone(), *steps, lo, hi, |_, t| out.push(t));
            }
            index += 1;
        }
        out
    }
}

/// "X needs 12000 steps/s ..." for a step-rate excess.
pub fn step_rate_message(axis: usize, needed_hz: f64, max_hz: f64) -> String {
    format!(
        "{} would step at {:.0} steps/s at the planned speed, more than maxStepRate = {} steps/s: the drivers would miss steps; lower the feed or maxRate",
        AXIS_NAMES[axis].to_uppercase(),
        needed_hz,
        max_hz
    )
}

#[cfg(test)]
mod tests {
    use crate::gcode::{Settings, run};

    fn settings(extra: &str) -> Settings {
        Settings::from_json(&format!(
            r#"{{"stepsPerMm": 80, "acceleration": 100, "maxRate": 6000{extra}}}"#
        ))
        .unwrap()
    }

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-9 * (1.0 + a.abs().max(b.abs()))
    }

    #[test]
    fn the_issues_example_takes_three_seconds() {
        // G1 X200 F6000 at 80 steps/mm and 100 mm/s², from rest: 1 s up to
        // 100 mm/s over 50 mm, 1 s at 100 mm/s, 1 s down (see
        // planner::tests::trapezoid_from_rest_to_rest).
        let program = run("G1 X200 F6000\n", settings(""));
        assert!(close(program.info.duration_seconds, 3.0));
        let t = program.info.moves[0].timing;
        assert!(close(t.cruise_speed, 100.0) && t.entry_speed == 0.0 && t.exit_speed == 0.0);
        // The 400th step (index 399) at 5 mm: s = ½at², t = √(2·5/100).
        let times = program.timeline.step_seconds(399, 400);
        assert!(close(times[0], (2.0f64 * 5.0 / 100.0).sqrt()));
        let all = program.timeline.step_seconds(0, 16_000);
        assert_eq!(all.len(), 16_000);
        assert!(close(all[15_999], 3.0));
        assert!(all.windows(2).all(|w| w[0] < w[1]));
        // Cruising at 100 mm/s along X: 8000 steps/s on X, none on Y, Z.
        let rates = program.timeline.step_rate_profile(&[80.0; 3]);
        assert_eq!(rates.len(), 4 * 4);
        assert!(close(rates[4 + 1], 8000.0) && rates[4 + 2] == 0.0);
    }

    #[test]
    fn the_point_reached_at_an_instant_counts_the_steps_at_or_before_it() {
        // G1 X200 F6000 from rest at 100 mm/s²: step k (0-based) at
        // s = (k + 1) / 80 mm, at t = √(2s/a) while accelerating; so by t
        // the machine has taken ⌊t²·a/2·80⌋ steps: 400 by √(2·5/100) s.
        let program = run("G1 X200 F6000\n", settings(""));
        let t = &program.timeline;
        assert_eq!(t.points_reached_at(-1.0), 0);
        assert_eq!(t.points_reached_at(0.0), 0);
        let at = (2.0f64 * 5.0 / 100.0).sqrt();
        assert_eq!(t.points_reached_at(at), 400);
        assert_eq!(t.points_reached_at(at * (1.0 - 1e-9)), 399);
        assert_eq!(t.points_reached_at(0.2501), 250);
        assert_eq!(t.points_reached_at(3.0), 16_000);
        assert_eq!(t.points_reached_at(1e9), 16_000);
        // Agrees with the instants at every step of a program with arcs.
        let program = run("G0 X10\nG1 Y10 F600\nG2 X20 Y0 I5 J-5\n", settings(""));
        let t = &program.timeline;
        let all = t.step_seconds(0, program.info.steps);
        for (k, &s) in all.iter().enumerate().step_by(37) {
            let reached = t.points_reached_at(s) as usize;
            assert!(reached > k && all[reached - 1] <= s, "{k}");
            assert!(reached == all.len() || all[reached] > s, "{k}");
        }
    }

    #[test]
    fn moves_join_in_time_and_ranges_cross_moves() {
        let program = run("G0 X10\nG1 Y10 F600\nG2 X20 Y0 I5 J-5\n", settings(""));
        let moves = &program.info.moves;
        for pair in moves.windows(2) {
            assert_eq!(pair[0].timing.end_seconds, pair[1].timing.start_seconds);
        }
        let end = moves.last().unwrap().timing.end_seconds;
        assert!(close(end, program.info.duration_seconds));
        let steps = program.info.steps;
        let all = program.timeline.step_seconds(0, steps);
        let part = program.timeline.step_seconds(700, 900);
        assert_eq!(&all[700..900], &part[..]);
        // The arc is planned through Grbl's chords, at most F.
        assert!(moves[2].timing.cruise_speed <= 10.0 + 1e-9);
    }

    #[test]
    fn no_feed_and_step_rate_are_warnings_on_their_line() {
        let program = run("G1 X10\n", settings(r#", "maxStepRate": 2000"#));
        let messages: Vec<(u32, String)> = program
            .info
            .warnings
            .iter()
            .map(|w| (w.line, w.message.clone()))
            .collect();
        assert!(messages[0].1.contains("error 22"), "{messages:?}");
        // Timed at the top rate, 100 mm/s, but 10 mm at 100 mm/s² peak at
        // √(100·10) = 31.6 mm/s (a triangle): 2530 steps/s on X.
        assert!(
            messages[1].1.starts_with("X would step at "),
            "{messages:?}"
        );
        assert_eq!(messages[1].0, 1);
    }

    #[test]
    fn limits_are_read_by_name() {
        let e = crate::gcode::Settings::from_json(r#"{"stepsPerMm": 80, "maxRate": [1, 2]}"#)
            .unwrap_err();
        assert_eq!(
            e.to_string(),
            "maxRate: expected one number or 3 (x, y, z), got 2"
        );
    }
}
