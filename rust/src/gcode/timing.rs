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
//! - In inverse time (G93) a move's feed is F times its length, the blocks'
//!   lengths between their rounded ends summed: its whole path in 1/F
//!   minutes at that rate. For a line that is Grbl's (planner.c:
//!   `programmed_rate = feed_rate * millimeters`). For an arc it is what
//!   mc_arc's comment asks ("The inverse feed_rate should be correct for
//!   the sum of all segments") and the standard says (RS274/NGC 3.5.19: the
//!   move in 1/F minutes); Grbl 1.1's mc_arc multiplies F by its segment
//!   count and then clears the inverse-time flag, so its chords run at
//!   F·n mm/min, which has no length in it (F2 on a half circle of
//!   r = 10 mm, 78 chords: 156 mm/min, about 12 s, where 1/2 min asks for
//!   about 62.8 mm/min).
//! - Step k (0-based) of a move of n steps happens when the planned position
//!   along the move's blocks reaches (k + 1) / n of its length: Grbl spreads
//!   a block's step events evenly along it, one per step of its major axis
//!   (a step of the trace is one step event, whichever axes it moves). Step
//!   instants are computed on demand for any range, never stored.

use super::interpret::{Motion, MoveMm};
use crate::error::{Error, number_text};
use crate::grid::{AXIS_NAMES, Point};
use crate::machine::{MACHINE_AXES, Machine, per_axis};
use crate::planner::{self, Limits, Plan, Planner, Rate, Timing};
use crate::request::{OptionSpec, shown};
use crate::starts::Starts;
use serde_json::{Map, Value};
use std::ops::Range;
use std::rc::Rc;

/// Reads `acceleration`, `maxRate`, `junctionDeviation` and `maxStepRate`
/// (Grbl's defaults when absent); errors name the setting.
pub fn limits_from_settings(settings: &Map<String, Value>) -> Result<Limits, Error> {
    let defaults = Limits::default();
    let axes = |spec: &OptionSpec, default: [f64; MACHINE_AXES]| {
        settings
            .get(spec.name)
            .map_or(Ok(default), |v| per_axis(spec, v))
    };
    let junction_deviation_mm = match settings.get(planner::JUNCTION_DEVIATION.name) {
        None => defaults.junction_deviation_mm,
        Some(v) => v.as_f64().ok_or_else(|| {
            Error::field(
                planner::JUNCTION_DEVIATION.name,
                format!("expected a number, got {}", shown(v)),
            )
        })?,
    };
    let max_step_rate_hz = match settings.get(planner::MAX_STEP_RATE.name) {
        None => None,
        Some(v) => Some(per_axis(&planner::MAX_STEP_RATE, v)?),
    };
    Limits::new(
        axes(&planner::ACCELERATION, defaults.acceleration_mm_per_s2)?,
        axes(&planner::MAX_RATE, defaults.max_rate_mm_per_min)?,
        junction_deviation_mm,
        max_step_rate_hz,
    )
}

/// The blocks a move took, and the lowest top rate (mm/min) its feed was
/// capped to, if any of them capped it.
pub struct PushedMove {
    pub blocks: Range<usize>,
    pub feed_capped_to_mm_per_min: Option<f64>,
    /// The feed asked for its blocks, mm/min: F in G94, F times the move's
    /// length in G93 (the planner holds it to the max rate along each block
    /// and to Grbl's least feed); None for rapids and a feed move without F.
    pub feed_mm_per_min: Option<f64>,
}

/// Pushes the blocks of move `m`, stepped from `from` to `to` (steps):
/// the range of blocks it took (empty when it does not move).
pub fn push_move(
    planner: &mut Planner,
    machine: &Machine,
    m: &MoveMm,
    from: &Point,
    to: &Point,
) -> PushedMove {
    let first = planner.len();
    let spm = machine.steps_per_mm();
    let to: [i64; MACHINE_AXES] = to.coords().try_into().expect("3 axes");
    let from: [i64; MACHINE_AXES] = from.coords().try_into().expect("3 axes");
    let delta_mm = |a: &[i64; MACHINE_AXES], b: &[i64; MACHINE_AXES]| -> [f64; MACHINE_AXES] {
        std::array::from_fn(|axis| (b[axis] - a[axis]) as f64 / spm[axis])
    };
    let feed_mm_per_min = match (m.motion, m.feed_mm_per_min, m.inverse_time_per_min) {
        (Motion::Rapid, _, _) => None,
        (_, Some(feed), _) => Some(feed),
        (_, None, Some(per_min)) => {
            // The blocks' ends once more, for the move's length (a G93
            // arc's vertices found twice; every other move's once).
            let (mut previous, mut length_mm) = (from, 0.0);
            each_block_end(machine, m, to, |end| {
                length_mm += planner::length_mm(delta_mm(&previous, &end));
                previous = end;
            });
            // A move of no length plans no block: no feed to speak of. Not
            // held to MAX_FEED_MM_PER_MIN: F and the length are bounded, so
            // its square stays finite (past 10^9 mm/min, held there, the
            // move ran slower than asked with no word, and the cap's
            // warning quoted the held value).
            (length_mm > 0.0).then_some(per_min * length_mm)
        }
        (_, None, None) => None,
    };
    let rate = match (m.motion, feed_mm_per_min) {
        (Motion::Rapid, _) => Rate::Rapid,
        (_, Some(feed)) => Rate::Feed(feed),
        (_, None) => Rate::Unset,
    };
    let mut capped: Option<f64> = None;
    let mut previous = from;
    each_block_end(machine, m, to, |end| {
        if let Some(top) = planner.push(delta_mm(&previous, &end), rate) {
            capped = Some(capped.map_or(top, |c: f64| c.min(top)));
        }
        previous = end;
    });
    PushedMove {
        blocks: first..planner.len(),
        feed_capped_to_mm_per_min: capped,
        feed_mm_per_min,
    }
}

/// Calls `f` with the step positions move `m`'s blocks end at, in order,
/// `to` last: one block for a line, one per chord of Grbl's mc_arc for an
/// arc.
#[inline(always)]
fn each_block_end(
    machine: &Machine,
    m: &MoveMm,
    to: [i64; MACHINE_AXES],
    mut f: impl FnMut([i64; MACHINE_AXES]),
) {
    if let Some(arc) = &m.arc {
        let vertices = planner::arc_chords(
            m.from_mm,
            m.to_mm,
            arc.center_mm,
            arc.plane.axes(),
            arc.radius_mm,
            arc.sweep_rad,
        );
        let between = vertices.len() - 1;
        for vertex in vertices.take(between) {
            // A vertex lies within the arc's box, whose corners were
            // rounded to steps already: its rounding fits too.
            f(std::array::from_fn(|axis| {
                machine.to_steps(axis, vertex[axis]).unwrap_or(to[axis])
            }));
        }
    }
    f(to);
}

/// Whether any block of move `m` (stepped to `to`) ends off `from`, both in
/// steps: Grbl's planner drops a block of no steps (plan_buffer_line's
/// empty block), so a move all of whose blocks end on its start does not
/// move in Grbl, such as a full circle whose every chord vertex rounds
/// onto its start.
pub fn plans_a_step(
    machine: &Machine,
    m: &MoveMm,
    from: [i64; MACHINE_AXES],
    to: [i64; MACHINE_AXES],
) -> bool {
    let mut moves = false;
    each_block_end(machine, m, to, |end| moves |= end != from);
    moves
}

/// The warning for a feed above what maxRate allows along a move: Grbl
/// runs it at the top rate and says nothing, so a learner who times
/// `G1 X200 F6000` against the default 500 mm/min would be puzzled.
/// An arc's chords point every way, so only those whose direction's top
/// rate is below F are capped (an axis-aligned chord to maxRate, a
/// diagonal one less), and the message says so; a top rate below Grbl's
/// MINIMUM_FEED_RATE runs at that minimum, as the planner does.
pub fn feed_capped_message(
    feed_mm_per_min: f64,
    inverse_time_per_min: Option<f64>,
    top_mm_per_min: f64,
    arc: bool,
) -> String {
    // Three digits, not whole: a max rate of 2.5 mm/min was said 2 (and 0.4, 0).
    let runs = shown_feed(top_mm_per_min.max(planner::MINIMUM_FEED_RATE_MM_PER_MIN));
    let top = shown_feed(top_mm_per_min);
    let (asked, wanted) = feed_asked(feed_mm_per_min, inverse_time_per_min);
    if arc {
        format!(
            "{asked} is above the max rate along parts of this arc (down to {top} mm/min, from maxRate, Grbl's $110-$112): its chords there run at their max rate, down to {runs} mm/min, as Grbl caps them; raise maxRate to run {wanted} throughout"
        )
    } else {
        format!(
            "{asked} is above the max rate along this move ({top} mm/min, from maxRate, Grbl's $110-$112): it runs at {runs} mm/min, as Grbl caps it; raise maxRate to run {wanted}"
        )
    }
}

/// Whether a move's feed is below Grbl's least (planner.c,
/// plan_compute_profile_nominal_speed: MINIMUM_FEED_RATE, 1 mm/min), which
/// the planner runs it at instead, as Grbl does: the warning for it, which
/// Grbl does not give (a G93 move of 0.1 mm at F2 takes 6 s, not 30).
pub fn feed_raised_message(
    feed_mm_per_min: f64,
    inverse_time_per_min: Option<f64>,
) -> Option<String> {
    let least = planner::MINIMUM_FEED_RATE_MM_PER_MIN;
    (feed_mm_per_min < least).then(|| {
        let (asked, _) = feed_asked(feed_mm_per_min, inverse_time_per_min);
        format!(
            "{asked} is below Grbl's least feed, {least} mm/min (planner.c, MINIMUM_FEED_RATE): it runs at {least} mm/min, as Grbl runs it"
        )
    })
}

/// A move's feed as the program asked for it, and what running at it
/// means: in G93 the feed is F times the move's length, and both are said.
fn feed_asked(feed_mm_per_min: f64, inverse_time_per_min: Option<f64>) -> (String, String) {
    match inverse_time_per_min {
        None => (
            format!("F{feed_mm_per_min} mm/min"),
            format!("at F{feed_mm_per_min}"),
        ),
        Some(per_min) => (
            format!(
                "G93 F{per_min} ({} mm/min along this move, to run it in 1/{per_min} min)",
                shown_feed(feed_mm_per_min)
            ),
            format!("it in 1/{per_min} min"),
        ),
    }
}

/// A derived feed (mm/min) for a message: to three significant digits, or
/// whole from 100 up (62.83185307179586 mm/min is said 62.8).
fn shown_feed(feed_mm_per_min: f64) -> String {
    let digits = (2 - feed_mm_per_min.log10().floor() as i32).clamp(0, 17) as usize;
    let rounded: f64 = format!("{feed_mm_per_min:.digits$}")
        .parse()
        .unwrap_or(feed_mm_per_min);
    number_text(rounded)
}

/// Where each move of a program starts in its steps and in its planner's
/// blocks, in step order; a move ends where the next one starts (12 bytes
/// a move).
#[derive(Clone, Debug, Default)]
pub struct MoveSpans {
    steps: Starts<u64>,
    blocks: Starts<u32>,
    /// The moves with no block (that do not move) which come after a dwell,
    /// by index, with the seconds of dwell between the block before them
    /// and them: few, so kept apart.
    dwell_before_instant: Vec<(u32, f64)>,
}

impl MoveSpans {
    /// Adds a move starting at `first_step` and `first_block`, where the
    /// one before it ends; `dwell_seconds_before`: for a move with no block,
    /// the dwell since the block before it (its instant is that much later).
    pub fn push(&mut self, first_step: u64, first_block: usize, dwell_seconds_before: f64) {
        if dwell_seconds_before > 0.0 {
            let index = u32::try_from(self.len()).expect("fewer than 2^32 moves");
            self.dwell_before_instant
                .push((index, dwell_seconds_before));
        }
        self.steps.push(first_step);
        self.blocks
            .push(u32::try_from(first_block).expect("fewer than 2^32 planner blocks"));
    }

    /// Ends the last move at `steps` steps and `blocks` blocks in all, and
    /// gives back the memory the tables grew past their length.
    pub fn finish(&mut self, steps: u64, blocks: usize) {
        self.dwell_before_instant.shrink_to_fit();
        self.steps.finish(steps);
        self.blocks
            .finish(u32::try_from(blocks).expect("fewer than 2^32 planner blocks"));
    }

    pub fn len(&self) -> usize {
        self.steps.len()
    }

    /// Makes room for `more` moves.
    pub fn reserve(&mut self, more: usize) {
        self.steps.reserve(more);
        self.blocks.reserve(more);
    }

    pub fn is_empty(&self) -> bool {
        self.steps.is_empty()
    }

    /// Steps of all the moves.
    pub fn steps(&self) -> u64 {
        self.steps.end()
    }

    /// (first step index, steps) of move `index`.
    pub fn steps_of(&self, index: usize) -> (u64, u64) {
        let (first, end) = self.steps.span(index);
        (first, end - first)
    }

    /// Seconds of dwell between the block before move `index` and it, when
    /// it has no block (0 for any other move).
    fn dwell_before_instant(&self, index: usize) -> f64 {
        let found = self
            .dwell_before_instant
            .binary_search_by_key(&index, |&(move_index, _)| move_index as usize);
        found.map_or(0.0, |at| self.dwell_before_instant[at].1)
    }

    /// The planner blocks of move `index`.
    pub fn blocks_of(&self, index: usize) -> Range<usize> {
        let (first, end) = self.blocks.span(index);
        first as usize..end as usize
    }

    /// The first move whose blocks start at or after block `block`.
    pub fn first_move_from_block(&self, block: usize) -> usize {
        // Past 2^32 no block starts: every move is before it.
        u32::try_from(block).map_or(self.len(), |b| self.blocks.first_from(b))
    }

    /// Index of the move that took step index `k`, or None past their last
    /// step.
    pub fn move_of_step(&self, k: u64) -> Option<usize> {
        (k < self.steps()).then(|| self.steps.holding(k))
    }
}

/// The plan of a finished program, and which blocks and steps each move has.
#[derive(Clone, Debug, Default)]
pub struct Timeline {
    plan: Plan,
    moves: Rc<MoveSpans>,
}

impl Timeline {
    /// Plans `planner`'s blocks, which the moves of `moves` took (all of
    /// them: see [`MoveSpans::finish`]).
    pub fn new(planner: Planner, moves: Rc<MoveSpans>) -> Timeline {
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

    /// Steps of all the moves.
    pub fn steps(&self) -> u64 {
        self.moves.steps()
    }

    /// The timing of move `index`.
    pub fn move_timing(&self, index: usize) -> Timing {
        let blocks = self.moves.blocks_of(index);
        // A move with no blocks is an instant, where the last move before
        // it ended, and after any dwell between them (a G4 before it: Grbl
        // reaches the line once the dwell is over).
        let at = blocks.start.checked_sub(1).map_or(0.0, |before| {
            let b = self.plan.block(before);
            b.start_seconds + b.duration_seconds()
        }) + self.moves.dwell_before_instant(index);
        self.plan.timing(blocks, at)
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
        for index in 0..self.moves.len() {
            let peak = self
                .plan
                .peak_step_rates_hz(self.moves.blocks_of(index), steps_per_mm);
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
        let mut out = Vec::with_capacity(8 * self.plan.len());
        for b in self.plan.blocks(0..self.plan.len()) {
            let p = b.phases();
            let t0 = b.start_seconds;
            // The end as the next block's start is summed (start plus the
            // whole duration), and the corners inside it no later: summed
            // phase by phase, the end came out up to 7e-12 s after the next
            // start in 7,000 of a long arc's 262,144 corners, so the times
            // went back.
            let end = t0 + b.duration_seconds();
            let t1 = t0 + p.accelerate_seconds;
            let t2 = (t1 + p.cruise_seconds).min(end);
            out.extend_from_slice(&[
                t0,
                b.entry_speed_mm_per_s,
                t1,
                b.peak_speed_mm_per_s,
                t2,
                b.peak_speed_mm_per_s,
                end,
                b.exit_speed_mm_per_s,
            ]);
        }
        out
    }

    /// The blocks in `blocks` that start a move after another block (where
    /// the machine turns from one move into the next), ascending.
    pub fn move_starts(&self, blocks: Range<usize>) -> Vec<usize> {
        let first = self.moves.first_move_from_block(blocks.start);
        let mut starts: Vec<usize> = (first..self.moves.len())
            .map(|index| self.moves.blocks_of(index).start)
            .take_while(|&start| start < blocks.end)
            .filter(|&start| start > 0)
            .collect();
        // A move with no blocks starts where the next one does.
        starts.dedup();
        starts
    }

    /// Seconds of dwell (G4) between two instants ([`Plan::dwell_seconds_between`]).
    pub fn dwell_seconds_between(&self, from_seconds: f64, to_seconds: f64) -> f64 {
        self.plan.dwell_seconds_between(from_seconds, to_seconds)
    }

    /// The point index the machine has reached at `seconds`: how many steps
    /// happen at or before that instant (0 before the first; every step
    /// once the program has ended). Bisects the steps by their instants
    /// (`step_seconds`, monotone), so it agrees with them exactly.
    pub fn points_reached_at(&self, seconds: f64) -> u64 {
        let (mut lo, mut hi) = (0, self.moves.steps());
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
        self.push_step_seconds(from, to, &mut out);
        out
    }

    /// [`Self::step_seconds`], pushed onto `out` (which the caller may have
    /// made room in).
    pub fn push_step_seconds(&self, from: u64, to: u64, out: &mut Vec<f64>) {
        if from >= to {
            return;
        }
        // The move that took step `from`.
        let Some(mut index) = self.moves.move_of_step(from) else {
            return;
        };
        let end = out.len() + (to - from) as usize;
        while out.len() < end && index < self.moves.len() {
            let blocks = self.moves.blocks_of(index);
            let (first, steps) = self.moves.steps_of(index);
            let (lo, hi) = (from.max(first) - first, to.min(first + steps) - first);
            if blocks.is_empty() {
                let at = self.move_timing(index).start_seconds;
                out.extend(std::iter::repeat_n(at, (hi - lo) as usize));
            } else {
                self.plan
                    .visit_fractions(blocks, steps, lo, hi, |_, t| out.push(t));
            }
            index += 1;
        }
    }
}

/// "X needs 12000 steps/s ..." for a step-rate excess.
pub fn step_rate_message(axis: usize, needed_hz: f64, max_hz: f64) -> String {
    format!(
        "{} would step at {:.0} steps/s at the planned speed, more than maxStepRate = {} steps/s: the drivers would miss steps; lower the feed or maxRate",
        AXIS_NAMES[axis].to_uppercase(),
        needed_hz,
        // 1e-300 written out was 300 digits long.
        number_text(max_hz)
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_capped_feed_says_the_max_rate_to_three_digits() {
        // A max rate of 2.5 mm/min was said "2 mm/min" (and 0.4, "0").
        let message = feed_capped_message(500.0, None, 2.5, false);
        assert!(message.contains("(2.5 mm/min, from maxRate"), "{message}");
        let message = feed_capped_message(500.0, None, 559.0169943749474, false);
        assert!(message.contains("(559 mm/min, from maxRate"), "{message}");
    }

    #[test]
    fn a_step_rate_excess_says_the_max_rate_as_a_number_is_read() {
        let message = step_rate_message(0, 8.0, 1e-300);
        assert!(
            message.contains("more than maxStepRate = 1e-300 steps/s"),
            "{message}"
        );
        assert!(step_rate_message(1, 2530.4, 2000.0).starts_with(
            "Y would step at 2530 steps/s at the planned speed, more than maxStepRate = 2000 steps/s"
        ));
    }
}
