//! A motion planner modelled on Grbl 1.1's (gnea/grbl, `grbl/planner.c`),
//! in mm and seconds: straight blocks in, a trapezoidal speed profile per
//! block out, and the instant at any distance along a block in closed form.
//!
//! Independent of G-code: a caller pushes straight blocks (a move's
//! displacement in mm and its rate), in program order, then [`Planner::plan`]
//! plans them all at once (Grbl plans a ring buffer of 16 or so blocks as
//! they stream in; a whole program known in advance is planned over every
//! block, which is the plan Grbl converges to with an unbounded buffer).
//!
//! Per block, as `plan_buffer_line` (planner.c) computes it:
//! - length L = |Δ| and unit vector u = Δ / L (`convert_delta_vector_to_unit_vector`,
//!   nuts_bolts.c);
//! - acceleration a and top rate along u: the largest values for which no
//!   axis exceeds its own, min over moving axes of max_i / |u_i|
//!   (`limit_value_by_axis_maximum`, nuts_bolts.c). The top rate is also the
//!   rate of a rapid (G0);
//! - nominal speed: the feed, at most the top rate, at least 1 mm/min
//!   (`plan_compute_profile_nominal_speed`, MINIMUM_FEED_RATE in config.h);
//! - the junction with the block before: θ is the angle between the reversed
//!   previous direction and this one, cos θ = −u_prev · u, and
//!   v_j² = a_j · δ · s / (1 − s), s = sin(θ/2) = √((1 − cos θ) / 2), where
//!   δ is the junction deviation and a_j the acceleration limited along
//!   u − u_prev. Straight on (cos θ < −0.999999) has no limit; a full
//!   reversal (cos θ > 0.999999) stops (MINIMUM_JUNCTION_SPEED = 0). The
//!   first block starts from rest;
//! - max entry speed: min(v_j, this nominal, the previous nominal)
//!   (`plan_compute_profile_parameters`).
//!
//! Look-ahead (`planner_recalculate`): a reverse pass from the last block,
//! which ends at rest, lowers each entry to what decelerating over the block
//! can shed, v_entry² ≤ v_exit² + 2aL; a forward pass lowers each exit to
//! what accelerating can reach, v_exit² ≤ v_entry² + 2aL.
//!
//! Profile of a block (as `st_prep_buffer`, stepper.c, executes it):
//! accelerate at a from the entry speed, cruise at the nominal speed,
//! decelerate at a to the exit speed; when the block is too short to reach
//! the nominal speed, accelerate to the peak v_p² = (2aL + v0² + v1²) / 2 and
//! decelerate at once (a triangle).
//!
//! Time at distance s inside a phase, the inverse of s = v0·t + ½·a·t²:
//! t = 2s / (v0 + √(v0² + 2as)) (the same root as (−v0 + √(v0² + 2as)) / a,
//! written without the cancellation at small a·s).

use crate::arc::angle::sin_cos_turns;
use crate::arc::arc_segments::Chording;
use crate::error::Error;
use crate::machine::{MACHINE_AXES, check_axes};
use crate::memory::reserve_moving;
use crate::range::NumberRange;
use crate::request::{OptionKind, OptionSpec};
use serde::Serialize;
use std::ops::Range;
use tsify::Tsify;

/// Grbl's defaults (defaults.h, DEFAULTS_GENERIC): 10 mm/s² per axis
/// (10·60·60 mm/min²).
pub const DEFAULT_ACCELERATION_MM_PER_S2: f64 = 10.0;
/// Grbl's DEFAULT_X/Y/Z_MAX_RATE, mm/min.
pub const DEFAULT_MAX_RATE_MM_PER_MIN: f64 = 500.0;
/// Grbl's DEFAULT_JUNCTION_DEVIATION, mm.
pub const DEFAULT_JUNCTION_DEVIATION_MM: f64 = 0.01;
/// Grbl's DEFAULT_ARC_TOLERANCE, mm: how far a chord of an arc may stray
/// from the arc (`mc_arc`, motion_control.c).
pub const ARC_TOLERANCE_MM: f64 = 0.002;
/// Grbl's MINIMUM_FEED_RATE (config.h), mm/min.
pub(crate) const MINIMUM_FEED_RATE_MM_PER_MIN: f64 = 1.0;
/// Grbl's thresholds on cos θ for a reversal and for straight on.
const JUNCTION_COS_LIMIT: f64 = 0.999999;
/// mc_arc counts its segments in a uint16_t.
const MAX_ARC_CHORDS: u64 = u16::MAX as u64;

/// The least acceleration a machine may have, mm/s². Less, the planner's
/// products underflow: at 5e-324 mm/s² a step's speed came out 0 and every
/// time infinite (durationSeconds null, and the CLI's table threw). From
/// here the longest move of the grid (2^31 steps an axis at 0.001 steps/mm,
/// 3.7e12 mm) speeds up in 2·sqrt(L/a), about 4e56 s: any plan stays finite.
pub const MIN_ACCELERATION_MM_PER_S2: f64 = 1e-100;

pub const ACCELERATION: OptionSpec = OptionSpec {
    name: "acceleration",
    kind: OptionKind::PerAxis(NumberRange::at_least(MIN_ACCELERATION_MM_PER_S2, "mm/s²")),
    required: false,
    default: Some("10"),
    applies_with: None,
    doc: "Acceleration, mm/s²: one number for every axis, or x,y,z (Grbl $120-$122; the default is Grbl's).",
};

pub const MAX_RATE: OptionSpec = OptionSpec {
    name: "maxRate",
    kind: OptionKind::PerAxis(NumberRange::positive("mm/min")),
    required: false,
    default: Some("500"),
    applies_with: None,
    doc: "Top rate, mm/min: one number, or x,y,z; also the rate of G0 (Grbl $110-$112; the default is Grbl's).",
};

pub const JUNCTION_DEVIATION: OptionSpec = OptionSpec {
    name: "junctionDeviation",
    kind: OptionKind::Number(NumberRange::at_least(0.0, "mm")),
    required: false,
    default: Some("0.01"),
    applies_with: None,
    doc: "Junction deviation δ, mm: how fast corners are taken, v² = a·δ·s/(1−s) (Grbl $11; the default is Grbl's).",
};

pub const MAX_STEP_RATE: OptionSpec = OptionSpec {
    name: "maxStepRate",
    kind: OptionKind::PerAxis(NumberRange::positive("steps/s")),
    required: false,
    default: None,
    applies_with: None,
    doc: "Fastest step rate the drivers take, steps/s: one number, or x,y,z; a move that needs more is a warning.",
};

/// The machine's motion limits.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Limits {
    pub acceleration_mm_per_s2: [f64; MACHINE_AXES],
    pub max_rate_mm_per_min: [f64; MACHINE_AXES],
    pub junction_deviation_mm: f64,
    pub max_step_rate_hz: Option<[f64; MACHINE_AXES]>,
}

impl Default for Limits {
    fn default() -> Limits {
        Limits {
            acceleration_mm_per_s2: [DEFAULT_ACCELERATION_MM_PER_S2; MACHINE_AXES],
            max_rate_mm_per_min: [DEFAULT_MAX_RATE_MM_PER_MIN; MACHINE_AXES],
            junction_deviation_mm: DEFAULT_JUNCTION_DEVIATION_MM,
            max_step_rate_hz: None,
        }
    }
}

impl Limits {
    /// Checks every value against the range its setting declares: finite
    /// and positive (the junction deviation may be 0: exact stop at every
    /// corner); errors name the setting.
    pub fn new(
        acceleration_mm_per_s2: [f64; MACHINE_AXES],
        max_rate_mm_per_min: [f64; MACHINE_AXES],
        junction_deviation_mm: f64,
        max_step_rate_hz: Option<[f64; MACHINE_AXES]>,
    ) -> Result<Limits, Error> {
        check_axes(&ACCELERATION, &acceleration_mm_per_s2)?;
        check_axes(&MAX_RATE, &max_rate_mm_per_min)?;
        if let Some(rates) = &max_step_rate_hz {
            check_axes(&MAX_STEP_RATE, rates)?;
        }
        JUNCTION_DEVIATION
            .number_range()
            .check(JUNCTION_DEVIATION.name, junction_deviation_mm)?;
        Ok(Limits {
            acceleration_mm_per_s2,
            max_rate_mm_per_min,
            junction_deviation_mm,
            max_step_rate_hz,
        })
    }
}

/// How fast a block is asked to go.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Rate {
    /// G0: the top rate along the block.
    Rapid,
    /// A feed, mm/min.
    Feed(f64),
    /// A feed move with no F set (Grbl refuses it: error 22); planned at
    /// the top rate, like a rapid.
    Unset,
}

/// The smaller of `a` and `b`, neither of them NaN. f64::min, which must
/// pass over a NaN, is a call to libm's fmin in wasm (whose f64.min
/// propagates it), made several times a block; the planner's lengths,
/// speeds and accelerations are never NaN (settings and moves are checked
/// finite first), so a comparison gives what f64::min would.
fn smaller(a: f64, b: f64) -> f64 {
    debug_assert!(!a.is_nan() && !b.is_nan());
    if b < a { b } else { a }
}

/// The larger of `a` and `b`, neither of them NaN (see [`smaller`]).
fn larger(a: f64, b: f64) -> f64 {
    debug_assert!(!a.is_nan() && !b.is_nan());
    if b > a { b } else { a }
}

/// Grbl's `limit_value_by_axis_maximum` (nuts_bolts.c): the largest value
/// along unit vector `u` for which no axis exceeds its `max`.
///
/// When every axis has the same `max` (Grbl's defaults, and most machines'
/// acceleration), one division gives the same bits as Grbl's one per
/// moving axis: a rounded division max / x never grows as x grows, so the
/// smallest of max / |u_i| is max over the largest |u_i|. A planner pushes
/// a block with two of these, and a division is the slowest of its
/// arithmetic (tens of cycles, in wasm too).
pub fn limit_value_by_axis_maximum(max: &[f64; MACHINE_AXES], u: &[f64; MACHINE_AXES]) -> f64 {
    if max.iter().all(|&m| m == max[0]) {
        let largest = u.iter().fold(0.0, |largest, &x| larger(largest, x.abs()));
        return if largest == 0.0 {
            f64::INFINITY
        } else {
            max[0] / largest
        };
    }
    let mut limit = f64::INFINITY;
    for i in 0..MACHINE_AXES {
        if u[i] != 0.0 {
            limit = smaller(limit, (max[i] / u[i]).abs());
        }
    }
    limit
}

/// `|v|`, and `v` scaled to a unit vector (unchanged when 0), as Grbl's
/// `convert_delta_vector_to_unit_vector` (nuts_bolts.c) scales it: by one
/// reciprocal of the length, multiplied in, not a division per axis.
fn unit_vector(v: [f64; MACHINE_AXES]) -> (f64, [f64; MACHINE_AXES]) {
    let length = v.iter().map(|x| x * x).sum::<f64>().sqrt();
    if length == 0.0 {
        return (0.0, v);
    }
    let inverse_length = 1.0 / length;
    (length, v.map(|x| x * inverse_length))
}

/// The length of a block of `delta_mm` (mm), as the planner measures it.
pub fn length_mm(delta_mm: [f64; MACHINE_AXES]) -> f64 {
    unit_vector(delta_mm).0
}

/// Grbl's maximum junction speed², (mm/s)², between blocks of directions
/// `previous` and `current` (units): `plan_buffer_line`, planner.c.
pub fn max_junction_speed_sqr(
    previous: &[f64; MACHINE_AXES],
    current: &[f64; MACHINE_AXES],
    limits: &Limits,
) -> f64 {
    let mut cos_theta = 0.0;
    let mut junction = [0.0; MACHINE_AXES];
    for i in 0..MACHINE_AXES {
        cos_theta -= previous[i] * current[i];
        junction[i] = current[i] - previous[i];
    }
    if cos_theta > JUNCTION_COS_LIMIT {
        // A reversal: stop (MINIMUM_JUNCTION_SPEED = 0).
        return 0.0;
    }
    if cos_theta < -JUNCTION_COS_LIMIT {
        // Straight on: no corner to slow for.
        return f64::INFINITY;
    }
    let (_, junction_unit) = unit_vector(junction);
    let junction_acceleration =
        limit_value_by_axis_maximum(&limits.acceleration_mm_per_s2, &junction_unit);
    // Half-angle identity: sin(θ/2) = √((1 − cos θ)/2), no trigonometry.
    let sin_half = (0.5 * (1.0 - cos_theta)).sqrt();
    (junction_acceleration * limits.junction_deviation_mm * sin_half / (1.0 - sin_half)).max(0.0)
}

/// One planned block as read ([`Plan::block`]): a straight piece of a move
/// at a trapezoidal profile.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Block {
    pub delta_mm: [f64; MACHINE_AXES],
    pub length_mm: f64,
    /// Along the block, limited per axis (`limit_value_by_axis_maximum`).
    pub acceleration_mm_per_s2: f64,
    pub nominal_speed_mm_per_s: f64,
    pub entry_speed_mm_per_s: f64,
    /// The highest speed reached: the nominal speed, or a triangle's peak.
    pub peak_speed_mm_per_s: f64,
    pub exit_speed_mm_per_s: f64,
    pub start_seconds: f64,
}

/// A block as a plan keeps it, in 40 bytes: its displacement, its nominal
/// speed and its planned entry speed². The rest of a [`Block`]
/// is derived when read, by the operations that planned it
/// ([`Plan::block`]), so a read gives exactly what was planned while a
/// program of a million moves keeps half the bytes of their whole profiles.
#[derive(Clone, Copy, Debug, PartialEq)]
struct StoredBlock {
    delta_mm: [f64; MACHINE_AXES],
    nominal_speed_mm_per_s: f64,
    /// The planned entry speed², (mm/s)²; while the blocks are pushed, the
    /// most it may be (the junction's limit and both nominal speeds).
    entry_speed_sqr: f64,
}

const _: () = assert!(std::mem::size_of::<StoredBlock>() == 40);

/// Blocks between two kept block starts: a block's start is at most this
/// many durations from one.
const START_INTERVAL: usize = 4;

/// A block's length and its acceleration along it
/// (`limit_value_by_axis_maximum`), as pushing, planning and reading it
/// all compute them.
fn length_and_acceleration(
    delta_mm: [f64; MACHINE_AXES],
    acceleration: &[f64; MACHINE_AXES],
) -> (f64, [f64; MACHINE_AXES], f64) {
    let (length_mm, unit) = unit_vector(delta_mm);
    (
        length_mm,
        unit,
        limit_value_by_axis_maximum(acceleration, &unit),
    )
}

/// The three phases of a block's profile, distances in mm, times in s.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Phases {
    pub accelerate_mm: f64,
    pub cruise_mm: f64,
    pub decelerate_mm: f64,
    pub accelerate_seconds: f64,
    pub cruise_seconds: f64,
    pub decelerate_seconds: f64,
}

/// Time to cover `s` from speed `v0` at acceleration `a` (a may be
/// negative, the root of s = v0·t + ½·a·t² met first).
fn time_over(s: f64, v0: f64, a: f64) -> f64 {
    if s <= 0.0 {
        return 0.0;
    }
    let root = larger(v0 * v0 + 2.0 * a * s, 0.0).sqrt();
    let sum = v0 + root;
    if sum > 0.0 { 2.0 * s / sum } else { 0.0 }
}

impl Block {
    pub fn phases(&self) -> Phases {
        let (a, l) = (self.acceleration_mm_per_s2, self.length_mm);
        let (v0, vp, v1) = (
            self.entry_speed_mm_per_s,
            self.peak_speed_mm_per_s,
            self.exit_speed_mm_per_s,
        );
        let accelerate_mm = ((vp * vp - v0 * v0) / (2.0 * a)).clamp(0.0, l);
        let decelerate_mm = ((vp * vp - v1 * v1) / (2.0 * a)).clamp(0.0, l - accelerate_mm);
        let cruise_mm = l - accelerate_mm - decelerate_mm;
        Phases {
            accelerate_mm,
            cruise_mm,
            decelerate_mm,
            accelerate_seconds: time_over(accelerate_mm, v0, a),
            cruise_seconds: if cruise_mm > 0.0 { cruise_mm / vp } else { 0.0 },
            decelerate_seconds: time_over(decelerate_mm, v1, a),
        }
    }

    pub fn duration_seconds(&self) -> f64 {
        let p = self.phases();
        p.accelerate_seconds + p.cruise_seconds + p.decelerate_seconds
    }

    /// Seconds from the block's start until it has covered `s` mm (clamped
    /// to 0..length).
    pub fn seconds_at(&self, s: f64, phases: &Phases) -> f64 {
        let a = self.acceleration_mm_per_s2;
        let s = s.clamp(0.0, self.length_mm);
        if s <= phases.accelerate_mm {
            return time_over(s, self.entry_speed_mm_per_s, a);
        }
        let s = s - phases.accelerate_mm;
        if s <= phases.cruise_mm {
            return phases.accelerate_seconds + s / self.peak_speed_mm_per_s;
        }
        // Decelerating: counted back from the end, as the time to
        // accelerate from the exit speed over the distance left (well
        // conditioned where the speed falls to 0, where the forward root
        // √(v² − 2as) loses its digits).
        let left = (phases.decelerate_mm - (s - phases.cruise_mm)).max(0.0);
        phases.accelerate_seconds + phases.cruise_seconds + phases.decelerate_seconds
            - time_over(left, self.exit_speed_mm_per_s, a).min(phases.decelerate_seconds)
    }
}

/// Blocks being collected for one plan.
pub struct Planner {
    limits: Limits,
    blocks: Vec<StoredBlock>,
    /// Per block, its length and its acceleration along it, for the
    /// passes (dropped once planned: a plan derives them when read).
    length_and_acceleration: Vec<(f64, f64)>,
    previous_unit: Option<[f64; MACHINE_AXES]>,
    previous_nominal: f64,
    /// Waits at rest ([`Planner::stop`]): before block index, seconds; one
    /// entry per index, in order.
    dwells: Vec<(usize, f64)>,
}

impl Planner {
    pub fn new(limits: Limits) -> Planner {
        Planner {
            limits,
            blocks: Vec::new(),
            length_and_acceleration: Vec::new(),
            previous_unit: None,
            previous_nominal: 0.0,
            dwells: Vec::new(),
        }
    }

    /// The machine comes to rest after the blocks pushed so far and waits
    /// `dwell_seconds` before the next: Grbl's `protocol_buffer_synchronize`,
    /// which a dwell (G4, `mc_dwell`), a spindle or coolant change
    /// (`spindle_sync`, `coolant_sync`) and a program's pause or end run
    /// before going on. The buffer is then empty, so the next block starts
    /// from rest (`plan_buffer_line`: an empty buffer gives a junction of
    /// 0), and the block before ends at rest.
    pub fn stop(&mut self, dwell_seconds: f64) {
        self.previous_unit = None;
        if dwell_seconds > 0.0 {
            let at = self.blocks.len();
            match self.dwells.last_mut() {
                Some((index, seconds)) if *index == at => *seconds += dwell_seconds,
                _ => self.dwells.push((at, dwell_seconds)),
            }
        }
    }

    /// Seconds of dwell since the last block pushed: where a move with no
    /// block (one that does not move) happens after a dwell, it happens
    /// that long after the block before it ended.
    pub fn dwell_since_last_block(&self) -> f64 {
        match self.dwells.last() {
            Some(&(index, seconds)) if index == self.blocks.len() => seconds,
            _ => 0.0,
        }
    }

    /// Bytes a block takes while the planner holds it.
    pub const BYTES_PER_BLOCK: usize =
        std::mem::size_of::<StoredBlock>() + std::mem::size_of::<(f64, f64)>();

    /// Makes room for exactly `more` blocks, for a caller that knows about
    /// how many it will push, so that they are not copied as they grow
    /// ([`reserve_moving`]: the blocks held, not the room, are copied).
    pub fn reserve(&mut self, more: usize) {
        reserve_moving(&mut self.blocks, more);
        reserve_moving(&mut self.length_and_acceleration, more);
    }

    /// Blocks the planner holds room for.
    pub fn capacity(&self) -> usize {
        self.blocks
            .capacity()
            .min(self.length_and_acceleration.capacity())
    }

    /// Blocks pushed so far.
    pub fn len(&self) -> usize {
        self.blocks.len()
    }

    pub fn is_empty(&self) -> bool {
        self.blocks.is_empty()
    }

    /// Adds a straight block of displacement `delta_mm` (`plan_buffer_line`).
    /// A block of length 0 is skipped, as Grbl skips an empty block; the
    /// junction is then between its neighbours. Returns the block's top
    /// rate (mm/min) when a programmed feed was above it and was capped to
    /// it, as Grbl caps it without a word.
    pub fn push(&mut self, delta_mm: [f64; MACHINE_AXES], rate: Rate) -> Option<f64> {
        let (length_mm, unit, acceleration) =
            length_and_acceleration(delta_mm, &self.limits.acceleration_mm_per_s2);
        if length_mm == 0.0 || !length_mm.is_finite() {
            return None;
        }
        let top_mm_per_min = limit_value_by_axis_maximum(&self.limits.max_rate_mm_per_min, &unit);
        let programmed = match rate {
            Rate::Rapid | Rate::Unset => top_mm_per_min,
            Rate::Feed(f) => smaller(f, top_mm_per_min),
        };
        let nominal = larger(programmed, MINIMUM_FEED_RATE_MM_PER_MIN) / 60.0;
        let junction_sqr = match &self.previous_unit {
            // From rest.
            None => 0.0,
            Some(previous) => max_junction_speed_sqr(previous, &unit, &self.limits),
        };
        let neighbour = smaller(nominal, self.previous_nominal);
        self.blocks.push(StoredBlock {
            delta_mm,
            nominal_speed_mm_per_s: nominal,
            entry_speed_sqr: smaller(neighbour * neighbour, junction_sqr),
        });
        self.length_and_acceleration.push((length_mm, acceleration));
        self.previous_unit = Some(unit);
        self.previous_nominal = nominal;
        match rate {
            Rate::Feed(f) if f > top_mm_per_min => Some(top_mm_per_min),
            _ => None,
        }
    }

    /// Plans every block pushed: the last one ends at rest.
    pub fn plan(self) -> Plan {
        let Planner {
            limits,
            mut blocks,
            length_and_acceleration,
            dwells,
            ..
        } = self;
        let two_al = |i: usize| {
            let (l, a) = length_and_acceleration[i];
            2.0 * a * l
        };
        // Reverse pass (planner_recalculate): entry² ≤ exit² + 2aL.
        let mut exit_sqr = 0.0;
        for (i, b) in blocks.iter_mut().enumerate().rev() {
            b.entry_speed_sqr = smaller(b.entry_speed_sqr, exit_sqr + two_al(i));
            exit_sqr = b.entry_speed_sqr;
        }
        // Forward pass: exit² (the next entry²) ≤ entry² + 2aL.
        for i in 1..blocks.len() {
            let reachable = blocks[i - 1].entry_speed_sqr + two_al(i - 1);
            if reachable < blocks[i].entry_speed_sqr {
                blocks[i].entry_speed_sqr = reachable;
            }
        }
        // Kept as long as the program: without the slack of its growth.
        blocks.shrink_to_fit();
        let n = blocks.len();
        let mut plan = Plan {
            blocks,
            acceleration_mm_per_s2: limits.acceleration_mm_per_s2,
            starts: Vec::with_capacity(n.div_ceil(START_INTERVAL)),
            dwells,
            duration_seconds: 0.0,
        };
        let mut seconds = 0.0;
        for i in 0..n {
            seconds += plan.dwell_before(i);
            if i % START_INTERVAL == 0 {
                plan.starts.push(seconds);
            }
            let (l, a) = length_and_acceleration[i];
            seconds += plan.profile_of(i, seconds, l, a).duration_seconds();
        }
        // A wait after the last block (a dwell at the program's end).
        plan.duration_seconds = seconds + plan.dwell_before(n);
        plan
    }
}

/// A planned program: every block's profile and start.
#[derive(Clone, Debug, Default)]
pub struct Plan {
    blocks: Vec<StoredBlock>,
    acceleration_mm_per_s2: [f64; MACHINE_AXES],
    /// The start of block j · [`START_INTERVAL`], seconds (2 bytes a block).
    starts: Vec<f64>,
    /// Waits at rest before a block, as [`Planner::stop`] kept them.
    dwells: Vec<(usize, f64)>,
    pub duration_seconds: f64,
}

/// The timing of one move (a range of blocks), speeds in mm/s.
#[derive(Serialize, Tsify, Clone, Copy, Debug, Default, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct Timing {
    pub start_seconds: f64,
    pub end_seconds: f64,
    pub entry_speed: f64,
    /// The highest speed planned within the move.
    pub cruise_speed: f64,
    pub exit_speed: f64,
}

impl Plan {
    /// How many blocks it has.
    pub fn len(&self) -> usize {
        self.blocks.len()
    }

    pub fn is_empty(&self) -> bool {
        self.blocks.is_empty()
    }

    /// Block `i` as planned, starting at `start_seconds`: the profile
    /// [`Planner::plan`] gave it, made again from what is kept.
    fn profile(&self, i: usize, start_seconds: f64) -> Block {
        let (length_mm, _, a) =
            length_and_acceleration(self.blocks[i].delta_mm, &self.acceleration_mm_per_s2);
        self.profile_of(i, start_seconds, length_mm, a)
    }

    /// [`Self::profile`] of a block of length `length_mm` and acceleration
    /// `a` along it (what [`length_and_acceleration`] gives for it).
    fn profile_of(&self, i: usize, start_seconds: f64, length_mm: f64, a: f64) -> Block {
        let kept = &self.blocks[i];
        let entry_sqr = kept.entry_speed_sqr;
        let exit_sqr = self
            .blocks
            .get(i + 1)
            .map_or(0.0, |next| next.entry_speed_sqr);
        let nominal_sqr = kept.nominal_speed_mm_per_s * kept.nominal_speed_mm_per_s;
        // A triangle when accelerating to nominal and decelerating from it
        // take more than the block: the peak where both meet.
        let peak_sqr = larger(
            smaller(
                nominal_sqr,
                0.5 * (2.0 * a * length_mm + entry_sqr + exit_sqr),
            ),
            larger(entry_sqr, exit_sqr),
        );
        Block {
            delta_mm: kept.delta_mm,
            length_mm,
            acceleration_mm_per_s2: a,
            nominal_speed_mm_per_s: kept.nominal_speed_mm_per_s,
            entry_speed_mm_per_s: entry_sqr.sqrt(),
            peak_speed_mm_per_s: peak_sqr.sqrt(),
            exit_speed_mm_per_s: exit_sqr.sqrt(),
            start_seconds,
        }
    }

    /// Seconds the machine waits at rest before block `i` (0 mostly).
    fn dwell_before(&self, i: usize) -> f64 {
        match self.dwells.binary_search_by_key(&i, |&(index, _)| index) {
            Ok(at) => self.dwells[at].1,
            Err(_) => 0.0,
        }
    }

    /// Seconds the machine waits at rest (G4 dwells, [`Planner::stop`])
    /// between `from_seconds` and `to_seconds`: the waits whose middle is in
    /// that span, summed. By the middle, not the ends: a wait starts where
    /// the block before it ends, the instant of that block's last step, up
    /// to a rounding of it, so a wait between two steps is found from their
    /// instants either way. For the timing diagram, which says a pause
    /// between two steps is a dwell.
    pub fn dwell_seconds_between(&self, from_seconds: f64, to_seconds: f64) -> f64 {
        // The instant each wait ends: its block's start, or the program's
        // end for a wait after the last block.
        let middle = |&(i, seconds): &(usize, f64)| {
            let end = if i < self.len() {
                self.block(i).start_seconds
            } else {
                self.duration_seconds
            };
            end - seconds / 2.0
        };
        // Waits come in block order, so in time: bisected to the first.
        let first = self.dwells.partition_point(|w| middle(w) < from_seconds);
        self.dwells[first..]
            .iter()
            .take_while(|w| middle(w) <= to_seconds)
            // From +0: an empty f64 sum is -0, which JavaScript tells apart.
            .fold(0.0, |sum, &(_, seconds)| sum + seconds)
    }

    /// Block `i` as planned: its start from the nearest kept one before it.
    pub fn block(&self, i: usize) -> Block {
        let first = i - i % START_INTERVAL;
        let mut start = self.starts[i / START_INTERVAL];
        for j in first..i {
            start += self.profile(j, start).duration_seconds() + self.dwell_before(j + 1);
        }
        self.profile(i, start)
    }

    /// Blocks `range` as planned, in order, each start found from the
    /// block before (the sums [`Planner::plan`] made, so the same values).
    pub fn blocks(&self, range: Range<usize>) -> impl Iterator<Item = Block> + '_ {
        let mut start = match range.is_empty() {
            true => 0.0,
            false => self.block(range.start).start_seconds,
        };
        range.map(move |i| {
            let block = self.profile(i, start);
            start += block.duration_seconds() + self.dwell_before(i + 1);
            block
        })
    }

    /// The first block index for which `after(block)` holds, where it holds
    /// for every block from some index on (a bisection, as
    /// `slice::partition_point` with the predicate negated).
    pub fn first_block_where(&self, after: impl Fn(&Block) -> bool) -> usize {
        let (mut lo, mut hi) = (0, self.len());
        while lo < hi {
            let mid = lo + (hi - lo) / 2;
            if after(&self.block(mid)) {
                hi = mid;
            } else {
                lo = mid + 1;
            }
        }
        lo
    }

    /// The timing of blocks `range`; an empty range is an instant at
    /// `at_seconds` at rest or passing through.
    pub fn timing(&self, range: Range<usize>, at_seconds: f64) -> Timing {
        let blocks: Vec<Block> = self.blocks(range.clone()).collect();
        let (Some(first), Some(last)) = (blocks.first(), blocks.last()) else {
            // No block: the machine passes the move's point at the speed it
            // leaves the block before with (0 when it stopped there, as it
            // does before a dwell).
            let passing = range
                .start
                .checked_sub(1)
                .map_or(0.0, |before| self.block(before).exit_speed_mm_per_s);
            return Timing {
                start_seconds: at_seconds,
                end_seconds: at_seconds,
                entry_speed: passing,
                cruise_speed: passing,
                exit_speed: passing,
            };
        };
        Timing {
            start_seconds: first.start_seconds,
            end_seconds: last.start_seconds + last.duration_seconds(),
            entry_speed: first.entry_speed_mm_per_s,
            cruise_speed: blocks
                .iter()
                .map(|b| b.peak_speed_mm_per_s)
                .fold(0.0, f64::max),
            exit_speed: last.exit_speed_mm_per_s,
        }
    }

    /// Calls `visit(i, seconds)` for the instants at which a path made of
    /// blocks `range` has covered fraction (k + 1) / n of its length, for k
    /// in `from..to` (step k of a move of n step events: Grbl's step events
    /// are spread evenly along a block, one per step of its major axis).
    /// O(blocks + steps): each block's phases are computed once.
    pub fn visit_fractions(
        &self,
        range: Range<usize>,
        n: u64,
        from: u64,
        to: u64,
        mut visit: impl FnMut(u64, f64),
    ) {
        let blocks: Vec<Block> = self.blocks(range).collect();
        let Some(last) = blocks.last() else {
            return;
        };
        // Distances are summed from the range's own start, so their
        // rounding is relative to the move, not to the whole program: near
        // a stop t = √(2s/a), and an error ε in s costs √(2ε/a) seconds.
        let length_mm: f64 = blocks.iter().map(|b| b.length_mm).sum();
        let end_seconds = last.start_seconds + last.duration_seconds();
        let (mut b, mut block_start_mm) = (0, 0.0);
        let mut phases = blocks[0].phases();
        for k in from..to {
            if k + 1 >= n {
                visit(k, end_seconds);
                continue;
            }
            let s = length_mm * ((k + 1) as f64 / n as f64);
            while b + 1 < blocks.len() && block_start_mm + blocks[b].length_mm <= s {
                block_start_mm += blocks[b].length_mm;
                b += 1;
                phases = blocks[b].phases();
            }
            let block = &blocks[b];
            visit(
                k,
                block.start_seconds + block.seconds_at(s - block_start_mm, &phases),
            );
        }
    }

    /// The highest step rate per axis in blocks `range`, steps/s: peak speed
    /// times the axis's share of the direction times its steps per mm.
    /// Each block's profile alone: a peak needs no start time, which would
    /// be derived from the nearest kept one (a program checks every move).
    pub fn peak_step_rates_hz(
        &self,
        range: Range<usize>,
        steps_per_mm: &[f64; MACHINE_AXES],
    ) -> [f64; MACHINE_AXES] {
        let mut peak = [0.0f64; MACHINE_AXES];
        for b in range.map(|i| self.profile(i, f64::NAN)) {
            for axis in 0..MACHINE_AXES {
                let rate = b.peak_speed_mm_per_s
                    * (b.delta_mm[axis] / b.length_mm).abs()
                    * steps_per_mm[axis];
                peak[axis] = peak[axis].max(rate);
            }
        }
        peak
    }
}

/// The chord vertices of an arc as Grbl's `mc_arc` (motion_control.c)
/// segments it: `floor(|½·sweep·r| / √(tol·(2r − tol)))` chords (at most
/// 65535, mc_arc's uint16_t) of equal angle, the plane's normal axis moving
/// evenly for a helix; one straight block when that is 0. Grbl
/// rotates the radius vector by a small-angle approximation and corrects it
/// every N_ARC_CORRECTION chords; the vertices here are the exact points on
/// the arc it approximates. Gives the vertices after the start, the end
/// last, in mm, one at a time (a program pushes them into its planner as
/// they come: a list per arc would be an allocation per arc).
pub fn arc_chords(
    from_mm: [f64; MACHINE_AXES],
    to_mm: [f64; MACHINE_AXES],
    center_mm: [f64; MACHINE_AXES],
    axes: [usize; 3],
    radius_mm: f64,
    sweep_rad: f64,
) -> impl ExactSizeIterator<Item = [f64; MACHINE_AXES]> {
    let [u, v, n] = axes;
    // Grbl's count (the arc-segments algorithm's rule); a radius within
    // the tolerance is one straight block, as Grbl's NaN count of 0 is.
    let chords = if 2.0 * radius_mm > ARC_TOLERANCE_MM {
        Chording::Tolerance(ARC_TOLERANCE_MM)
            .chords(radius_mm, sweep_rad)
            .unwrap_or(MAX_ARC_CHORDS)
            .clamp(1, MAX_ARC_CHORDS) as usize
    } else {
        1
    };
    let start_angle = (from_mm[v] - center_mm[v]).atan2(from_mm[u] - center_mm[u]);
    (1..chords + 1).map(move |i| {
        if i == chords {
            return to_mm;
        }
        let f = i as f64 / chords as f64;
        let angle = start_angle + sweep_rad * f;
        let mut p = from_mm;
        let (sin, cos) = sin_cos_turns(angle);
        p[u] = center_mm[u] + radius_mm * cos;
        p[v] = center_mm[v] + radius_mm * sin;
        p[n] = from_mm[n] + (to_mm[n] - from_mm[n]) * f;
        p
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn limits(acceleration: f64, max_rate: f64, junction_deviation: f64) -> Limits {
        Limits::new([acceleration; 3], [max_rate; 3], junction_deviation, None).unwrap()
    }

    fn plan(limits: Limits, blocks: &[([f64; 3], Rate)]) -> Plan {
        let mut p = Planner::new(limits);
        for &(d, r) in blocks {
            p.push(d, r);
        }
        p.plan()
    }

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-9 * (1.0 + a.abs().max(b.abs()))
    }

    #[test]
    fn trapezoid_from_rest_to_rest() {
        // Hand-computed: 200 mm at F6000 (100 mm/s), a = 100 mm/s².
        // Accelerating to 100 mm/s takes v/a = 1 s over v²/2a = 50 mm; so
        // does stopping; the 100 mm between cruise at 100 mm/s for 1 s.
        // Total 3 s.
        let p = plan(
            limits(100.0, 6000.0, 0.01),
            &[([200.0, 0.0, 0.0], Rate::Feed(6000.0))],
        );
        let b = p.block(0);
        let ph = b.phases();
        assert!(close(ph.accelerate_mm, 50.0) && close(ph.cruise_mm, 100.0));
        assert!(close(ph.decelerate_mm, 50.0));
        assert!(close(ph.accelerate_seconds, 1.0) && close(ph.cruise_seconds, 1.0));
        assert!(close(p.duration_seconds, 3.0));
        assert!(close(b.peak_speed_mm_per_s, 100.0));
        // Inside the acceleration phase s = ½at²: 5 mm at t = √(2·5/100).
        assert!(close(b.seconds_at(5.0, &ph), (2.0f64 * 5.0 / 100.0).sqrt()));
        // In the cruise: 1 s + 25 mm / 100 mm/s. Decelerating, 150 + 37.5
        // mm is 12.5 mm short of the end: 2 s + (1 − √(2·12.5/100)) s.
        assert!(close(b.seconds_at(75.0, &ph), 1.25));
        assert!(close(
            b.seconds_at(187.5, &ph),
            3.0 - (2.0f64 * 12.5 / 100.0).sqrt()
        ));
        assert!(close(b.seconds_at(200.0, &ph), 3.0));
    }

    #[test]
    fn triangle_when_too_short_to_cruise() {
        // 50 mm at a = 100 mm/s², asking for 100 mm/s (which needs 100 mm
        // to reach and leave): accelerate over 25 mm to √(2·100·25) =
        // 70.71 mm/s in √(2·25/100) s, and back down in as long.
        let p = plan(
            limits(100.0, 6000.0, 0.01),
            &[([0.0, 50.0, 0.0], Rate::Feed(6000.0))],
        );
        let b = p.block(0);
        let ph = b.phases();
        assert!(close(b.peak_speed_mm_per_s, 5000.0f64.sqrt()));
        assert!(close(ph.accelerate_mm, 25.0) && ph.cruise_mm.abs() < 1e-9);
        assert!(close(p.duration_seconds, 2.0 * 0.5f64.sqrt()));
    }

    #[test]
    fn max_rate_limits_feed_and_sets_rapids() {
        // Along a diagonal x = y, each axis moves at 1/√2 of the speed, so
        // the top rate is 500·√2 mm/min (limit_value_by_axis_maximum).
        let l = limits(10.0, 500.0, 0.01);
        let p = plan(l, &[([100.0, 100.0, 0.0], Rate::Rapid)]);
        assert!(close(
            p.block(0).nominal_speed_mm_per_s,
            500.0 * 2f64.sqrt() / 60.0
        ));
        // The same for acceleration.
        assert!(close(p.block(0).acceleration_mm_per_s2, 10.0 * 2f64.sqrt()));
        let p = plan(l, &[([100.0, 0.0, 0.0], Rate::Feed(9000.0))]);
        assert!(close(p.block(0).nominal_speed_mm_per_s, 500.0 / 60.0));
        let p = plan(l, &[([100.0, 0.0, 0.0], Rate::Unset)]);
        assert!(close(p.block(0).nominal_speed_mm_per_s, 500.0 / 60.0));
    }

    #[test]
    fn junction_speeds_from_grbls_formula() {
        // planner.c: v² = a_j·δ·s/(1−s), s = sin(θ/2), cos θ = −u_prev·u,
        // a_j limited along u − u_prev. At a 90° corner (x then y),
        // u − u_prev = (−1, 1)/√2, so a_j = a·√2, and s = sin 45° = √½.
        let (a, d) = (100.0, 0.02);
        let l = limits(a, 60000.0, d);
        let s = 0.5f64.sqrt();
        let expected = a * 2f64.sqrt() * d * s / (1.0 - s);
        let v = max_junction_speed_sqr(&[1.0, 0.0, 0.0], &[0.0, 1.0, 0.0], &l);
        assert!(close(v, expected), "{v} vs {expected}");
        // θ = 135° between the segments (the path turns by 45°): the second
        // direction is (cos 45°, sin 45°); cos θ = −cos 45°, s = sin 67.5°,
        // and u − u_prev = (cos 45° − 1, sin 45°), whose largest share is
        // y's: |sin 45°| / |u − u_prev| = cos 22.5°.
        let c = 0.5f64.sqrt();
        let s = (67.5f64).to_radians().sin();
        let a_j = a / (22.5f64).to_radians().cos();
        let expected = a_j * d * s / (1.0 - s);
        let v = max_junction_speed_sqr(&[1.0, 0.0, 0.0], &[c, c, 0.0], &l);
        assert!(close(v, expected), "{v} vs {expected}");
        // A long path through the 90° corner passes it at that speed.
        let p = plan(
            l,
            &[
                ([100.0, 0.0, 0.0], Rate::Feed(6000.0)),
                ([0.0, 100.0, 0.0], Rate::Feed(6000.0)),
            ],
        );
        let v90 = (a * 2f64.sqrt() * d * 0.5f64.sqrt() / (1.0 - 0.5f64.sqrt())).sqrt();
        assert!(close(p.block(0).exit_speed_mm_per_s, v90));
        assert!(close(p.block(1).entry_speed_mm_per_s, v90));
    }

    #[test]
    fn collinear_moves_keep_their_speed_and_a_reversal_stops() {
        let l = limits(100.0, 6000.0, 0.01);
        let p = plan(
            l,
            &[
                ([100.0, 0.0, 0.0], Rate::Feed(6000.0)),
                ([100.0, 0.0, 0.0], Rate::Feed(6000.0)),
            ],
        );
        // Two 100 mm halves of the 200 mm trapezoid: the join at 100 mm/s.
        assert!(close(p.block(0).exit_speed_mm_per_s, 100.0));
        assert!(close(p.duration_seconds, 3.0));
        let p = plan(
            l,
            &[
                ([100.0, 0.0, 0.0], Rate::Feed(6000.0)),
                ([-100.0, 0.0, 0.0], Rate::Feed(6000.0)),
            ],
        );
        assert_eq!(p.block(0).exit_speed_mm_per_s, 0.0);
        assert_eq!(p.block(1).entry_speed_mm_per_s, 0.0);
        // A slower second move: the junction is at most its nominal speed.
        let p = plan(
            l,
            &[
                ([100.0, 0.0, 0.0], Rate::Feed(6000.0)),
                ([100.0, 0.0, 0.0], Rate::Feed(600.0)),
            ],
        );
        assert!(close(p.block(0).exit_speed_mm_per_s, 10.0));
    }

    #[test]
    fn step_instants_spread_along_the_move() {
        // 200 mm at 80 steps/mm: 16,000 step events; the 400th (k = 399)
        // falls at 5 mm, t = √(2·5/100) s (s = ½at²).
        let p = plan(
            limits(100.0, 6000.0, 0.01),
            &[([200.0, 0.0, 0.0], Rate::Feed(6000.0))],
        );
        let mut times = Vec::new();
        p.visit_fractions(0..1, 16_000, 399, 400, |_, t| times.push(t));
        assert!(close(times[0], 0.1f64.sqrt()));
        let mut last = Vec::new();
        p.visit_fractions(0..1, 16_000, 15_999, 16_000, |_, t| last.push(t));
        assert!(close(last[0], 3.0));
    }

    #[test]
    fn arcs_are_planned_through_grbls_chords() {
        // r = 10, a half turn: |½·π·10| / √(0.002·(20 − 0.002)) = 78.5...
        // -> 78 chords.
        let chords: Vec<_> = arc_chords(
            [10.0, 0.0, 0.0],
            [-10.0, 0.0, 0.0],
            [0.0; 3],
            [0, 1, 2],
            10.0,
            std::f64::consts::PI,
        )
        .collect();
        let expected =
            (0.5 * std::f64::consts::PI * 10.0 / (0.002f64 * (20.0 - 0.002)).sqrt()).floor();
        assert_eq!(chords.len() as f64, expected);
        assert_eq!(*chords.last().unwrap(), [-10.0, 0.0, 0.0]);
        for p in &chords {
            assert!(close(p[0].hypot(p[1]), 10.0));
        }
    }

    #[test]
    fn settings_are_checked_by_name() {
        let e = Limits::new([0.0; 3], [500.0; 3], 0.01, None).unwrap_err();
        assert_eq!(
            e.to_string(),
            "acceleration: x must be 1e-100 mm/s² or more, got 0"
        );
        let e = Limits::new([10.0; 3], [500.0; 3], -1.0, None).unwrap_err();
        assert_eq!(
            e.to_string(),
            "junctionDeviation: must be 0 mm or more, got -1"
        );
    }

    fn block_strategy() -> impl Strategy<Value = ([f64; 3], Rate)> {
        (
            prop::array::uniform3(-50i32..50),
            prop_oneof![
                Just(Rate::Rapid),
                Just(Rate::Unset),
                (1.0f64..20000.0).prop_map(Rate::Feed)
            ],
        )
            .prop_map(|(d, r)| ([d[0] as f64 * 0.7, d[1] as f64 * 0.3, d[2] as f64 * 0.1], r))
    }

    /// A unit vector's components, zero on some axes: every pattern of
    /// moving axes, signs and sizes a block may have.
    fn unit_strategy() -> impl Strategy<Value = [f64; MACHINE_AXES]> {
        prop::array::uniform3(prop_oneof![Just(0.0), -1e3f64..1e3, -1e-6f64..1e-6])
            .prop_map(|v| unit_vector(v).1)
    }

    proptest! {
        /// The one division taken when every axis has the same limit
        /// gives the bits of Grbl's loop, a division per moving axis.
        #[test]
        fn a_shared_limit_is_limited_as_grbl_limits_each_axis(
            u in unit_strategy(),
            max in prop_oneof![1e-3f64..1e6, Just(DEFAULT_ACCELERATION_MM_PER_S2)],
        ) {
            let mut grbl = f64::INFINITY;
            for &x in &u {
                if x != 0.0 {
                    grbl = grbl.min((max / x).abs());
                }
            }
            prop_assert_eq!(limit_value_by_axis_maximum(&[max; MACHINE_AXES], &u).to_bits(), grbl.to_bits());
        }

        #[test]
        fn plans_are_monotone_within_limits_and_reachable(
            blocks in prop::collection::vec(block_strategy(), 1..30),
            acceleration in prop::array::uniform3(1.0f64..500.0),
            max_rate in prop::array::uniform3(10.0f64..10000.0),
            junction_deviation in 0.0f64..1.0,
        ) {
            let l = Limits::new(acceleration, max_rate, junction_deviation, None).unwrap();
            let p = plan(l, &blocks);
            let eps = 1e-9;
            let mut previous_end = 0.0;
            let blocks: Vec<Block> = p.blocks(0..p.len()).collect();
            for (i, b) in blocks.iter().enumerate() {
                let (v0, vp, v1) = (b.entry_speed_mm_per_s, b.peak_speed_mm_per_s, b.exit_speed_mm_per_s);
                // No speed above the block's nominal (itself within the
                // axis limits) and the acceleration within every axis's.
                prop_assert!(vp <= b.nominal_speed_mm_per_s * (1.0 + eps));
                prop_assert!(v0 <= vp * (1.0 + eps) + eps && v1 <= vp * (1.0 + eps) + eps);
                for axis in 0..3 {
                    let share = (b.delta_mm[axis] / b.length_mm).abs();
                    prop_assert!(vp * share * 60.0 <= max_rate[axis] * (1.0 + 1e-9));
                    prop_assert!(b.acceleration_mm_per_s2 * share <= acceleration[axis] * (1.0 + 1e-9));
                }
                // The exit is reachable from the entry within the length.
                let two_al = 2.0 * b.acceleration_mm_per_s2 * b.length_mm;
                prop_assert!((v1 * v1 - v0 * v0).abs() <= two_al * (1.0 + 1e-9) + eps);
                // Blocks join up in speed and time.
                if i + 1 < blocks.len() {
                    prop_assert_eq!(v1, blocks[i + 1].entry_speed_mm_per_s);
                }
                // Each block read alone is the one read in order.
                prop_assert_eq!(*b, p.block(i));
                prop_assert!((b.start_seconds - previous_end).abs() <= 1e-9 * (1.0 + previous_end));
                previous_end = b.start_seconds + b.duration_seconds();
                prop_assert!(previous_end >= b.start_seconds);
            }
            prop_assert_eq!(blocks.first().map(|b| b.entry_speed_mm_per_s), blocks.first().map(|_| 0.0));
            prop_assert_eq!(blocks.last().map(|b| b.exit_speed_mm_per_s), blocks.last().map(|_| 0.0));
            // Step instants are monotone and end at the plan's end.
            let n = 1000;
            let mut last = 0.0;
            p.visit_fractions(0..p.len(), n, 0, n, |_, t| {
                assert!(t >= last - 1e-12, "{t} after {last}");
                last = t;
            });
            if !p.is_empty() {
                prop_assert!((last - p.duration_seconds).abs() <= 1e-9 * (1.0 + p.duration_seconds));
            }
        }
    }
}
