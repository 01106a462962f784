//! A program's planned motion as chart rows for a window of time: the
//! tool's speed along the path and each axis's step rate, with the planned
//! speed at each move's start (where it meets the move before: its corner's
//! junction speed) marked. Made for a page that draws a chart a few
//! thousand pixels wide, whatever the program's length: the rows are
//! bounded by the buckets asked for, and the cost is that of the blocks in
//! the window (found by bisection) plus the rows.
//!
//! Each block's speed is a trapezoid (`crate::planner`): three linear
//! pieces in time (accelerate, cruise, decelerate). An axis's step rate is
//! the speed times the axis's share of the block's direction times its
//! steps per mm, so it is linear on the same pieces.
//! - Few blocks in the window (four corners each fit in the rows asked
//!   for): the rows are the trapezoids' corners, clipped to the window, so
//!   the chart draws the planned profile exactly. Where blocks meet, the
//!   speed is continuous but a step rate jumps (the direction changes): two
//!   rows at the same instant.
//! - Otherwise: equal buckets of time, each with the least and the greatest
//!   value within it (a linear piece's extremes over an interval are at its
//!   ends), so no slow-down into a corner is lost at any zoom.
//!
//! Time the machine spends at rest (a dwell: before the first move, between
//! two, after the last) is charted at speed 0: a row where the rest starts
//! and one at the window's end after the last move, or the buckets it
//! touches widened to 0. Without them a window inside a dwell had no rows
//! at all, and a dwell between moves was a gap in the chart.

use super::timing::Timeline;
use crate::error::{Error, number_text};
use crate::machine::MACHINE_AXES;
use serde::Serialize;
use tsify::Tsify;

/// Most rows a chart may ask for: far more pixels than a screen has.
pub const MAX_CHART_BUCKETS: u32 = 100_000;

/// The planned motion over a window of time, as chart rows (see the module
/// comment). Speeds in mm/s, step rates in steps/s (Hz).
#[derive(Serialize, Tsify, Clone, Debug, Default, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct MotionChart {
    /// The window charted, seconds from the program's start: the one asked
    /// for, within 0..durationSeconds.
    pub from_seconds: f64,
    pub to_seconds: f64,
    pub duration_seconds: f64,
    /// True: rows are the trapezoids' corners (min = max); false: rows are
    /// equal buckets of time.
    pub exact: bool,
    /// The instant of each row: a corner's, or a bucket's middle.
    pub seconds: Vec<f64>,
    /// The tool's speed along the path, least and greatest in the row.
    pub speed_min: Vec<Option<f64>>,
    pub speed_max: Vec<Option<f64>>,
    /// Per axis (x, y, z), the step rate, least and greatest in the row.
    pub step_rate_min: [Vec<Option<f64>>; MACHINE_AXES],
    pub step_rate_max: [Vec<Option<f64>>; MACHINE_AXES],
    /// The planned speed where a move starts after another (its corner's
    /// junction speed), in the row of that instant; in a bucket, the lowest
    /// of those within it; null where no move starts.
    pub junction_speed: Vec<Option<f64>>,
}

/// One linear piece of a block's profile: from (t0, v0) to (t1, v1).
struct Piece {
    t0: f64,
    v0: f64,
    t1: f64,
    v1: f64,
}

impl Piece {
    fn at(&self, t: f64) -> f64 {
        if self.t1 <= self.t0 {
            return self.v0;
        }
        self.v0 + (self.v1 - self.v0) * ((t - self.t0) / (self.t1 - self.t0))
    }
}

/// Widens the range `min..max` (None: empty) to take in `value`.
fn widen(min: &mut Option<f64>, max: &mut Option<f64>, value: f64) {
    *min = Some(min.map_or(value, |m| m.min(value)));
    *max = Some(max.map_or(value, |m| m.max(value)));
}

impl MotionChart {
    fn push_row(&mut self, seconds: f64, speed: f64, rate_per_speed: &[f64; MACHINE_AXES]) {
        self.seconds.push(seconds);
        self.speed_min.push(Some(speed));
        self.speed_max.push(Some(speed));
        for axis in 0..MACHINE_AXES {
            self.step_rate_min[axis].push(Some(speed * rate_per_speed[axis]));
            self.step_rate_max[axis].push(Some(speed * rate_per_speed[axis]));
        }
        self.junction_speed.push(None);
    }

    /// At rest from `seconds`: speed and every step rate 0.
    fn push_rest_row(&mut self, seconds: f64) {
        if self.seconds.last() != Some(&seconds) {
            self.push_row(seconds, 0.0, &[0.0; MACHINE_AXES]);
        }
    }

    /// Bucket `bucket` takes in the machine at rest.
    fn widen_at_rest(&mut self, bucket: usize) {
        widen(
            &mut self.speed_min[bucket],
            &mut self.speed_max[bucket],
            0.0,
        );
        for axis in 0..MACHINE_AXES {
            widen(
                &mut self.step_rate_min[axis][bucket],
                &mut self.step_rate_max[axis][bucket],
                0.0,
            );
        }
    }

    fn empty_rows(&mut self, rows: usize) {
        self.speed_min = vec![None; rows];
        self.speed_max = vec![None; rows];
        self.step_rate_min = std::array::from_fn(|_| vec![None; rows]);
        self.step_rate_max = std::array::from_fn(|_| vec![None; rows]);
        self.junction_speed = vec![None; rows];
    }
}

impl Timeline {
    /// The planned motion in `from_seconds..to_seconds` as at most
    /// `buckets` rows (see the module comment); the window is clipped to
    /// the program. Errors name the argument at fault.
    pub fn motion_chart(
        &self,
        steps_per_mm: &[f64; MACHINE_AXES],
        from_seconds: f64,
        to_seconds: f64,
        buckets: u32,
    ) -> Result<MotionChart, Error> {
        if !(1..=MAX_CHART_BUCKETS).contains(&buckets) {
            return Err(Error::field(
                "buckets",
                format!("must be 1 to {MAX_CHART_BUCKETS}, got {buckets}"),
            ));
        }
        for (field, seconds) in [("fromSeconds", from_seconds), ("toSeconds", to_seconds)] {
            if seconds.is_nan() {
                return Err(Error::field(field, "is not a number"));
            }
        }
        if from_seconds >= to_seconds {
            return Err(Error::field(
                "toSeconds",
                format!(
                    "must be greater than fromSeconds; got {}..{}",
                    number_text(from_seconds),
                    number_text(to_seconds)
                ),
            ));
        }
        // Clipped to the program, both ends (an infinite one included): a
        // window past its end is empty at its end, not reversed.
        let duration = self.duration_seconds();
        let (from, to) = (
            from_seconds.clamp(0.0, duration),
            to_seconds.clamp(0.0, duration),
        );
        let mut chart = MotionChart {
            from_seconds: from,
            to_seconds: to,
            duration_seconds: duration,
            ..MotionChart::default()
        };
        if from >= to {
            return Ok(chart);
        }
        let plan = self.plan();
        let first = plan.first_block_where(|b| b.start_seconds + b.duration_seconds() > from);
        let last = plan.first_block_where(|b| b.start_seconds >= to);
        // The blocks that start a move after another, in step order.
        let starts_move = self.move_starts(first..last);
        chart.exact = 4 * (last - first) as u64 <= u64::from(buckets);
        if !chart.exact {
            chart.empty_rows(buckets as usize);
        }
        let width = (to - from) / f64::from(buckets);
        let bucket_of = |t: f64| (((t - from) / width) as usize).min(buckets as usize - 1);
        // The machine at rest from `a` to `z`, within the window.
        let rest = |chart: &mut MotionChart, a: f64, z: f64| {
            if chart.exact {
                chart.push_rest_row(a);
            } else {
                for bucket in bucket_of(a)..=bucket_of(z) {
                    chart.widen_at_rest(bucket);
                }
            }
        };
        // Where the motion charted so far ends: the machine rests from there
        // until the next block starts (a block follows the one before it at
        // once, to the bit, unless a dwell comes between them).
        let mut moving_until = from;
        let mut junctions = starts_move.into_iter().peekable();
        for (i, b) in (first..last).zip(plan.blocks(first..last)) {
            if b.start_seconds > moving_until {
                rest(&mut chart, moving_until, b.start_seconds.min(to));
            }
            moving_until = moving_until.max(b.start_seconds + b.duration_seconds());
            let p = b.phases();
            let rate_per_speed: [f64; MACHINE_AXES] = std::array::from_fn(|axis| {
                (b.delta_mm[axis] / b.length_mm).abs() * steps_per_mm[axis]
            });
            let t1 = b.start_seconds + p.accelerate_seconds;
            let t2 = t1 + p.cruise_seconds;
            let (v0, vp, v1) = (
                b.entry_speed_mm_per_s,
                b.peak_speed_mm_per_s,
                b.exit_speed_mm_per_s,
            );
            let pieces = [
                Piece {
                    t0: b.start_seconds,
                    v0,
                    t1,
                    v1: vp,
                },
                Piece {
                    t0: t1,
                    v0: vp,
                    t1: t2,
                    v1: vp,
                },
                Piece {
                    t0: t2,
                    v0: vp,
                    t1: t2 + p.decelerate_seconds,
                    v1,
                },
            ];
            // The pieces that take time within the window.
            let shown = pieces
                .iter()
                .filter(|q| q.t1 > q.t0 && q.t1 > from && q.t0 < to);
            let junction = junctions.next_if(|&j| j == i).map(|_| v0);
            if chart.exact {
                let rows_before = chart.seconds.len();
                for piece in shown {
                    let (a, z) = (piece.t0.max(from), piece.t1.min(to));
                    if chart.seconds.len() == rows_before {
                        chart.push_row(a, piece.at(a), &rate_per_speed);
                    }
                    chart.push_row(z, piece.at(z), &rate_per_speed);
                }
                if b.start_seconds >= from && chart.seconds.len() > rows_before {
                    chart.junction_speed[rows_before] = junction;
                }
                continue;
            }
            for piece in shown {
                let (a, z) = (piece.t0.max(from), piece.t1.min(to));
                for bucket in bucket_of(a)..=bucket_of(z) {
                    // Within the piece, whatever the rounding of the bounds.
                    let lo = a.max(from + bucket as f64 * width).min(z);
                    let hi = z.min(from + (bucket + 1) as f64 * width).max(lo);
                    for t in [lo, hi] {
                        let v = piece.at(t);
                        widen(
                            &mut chart.speed_min[bucket],
                            &mut chart.speed_max[bucket],
                            v,
                        );
                        for axis in 0..MACHINE_AXES {
                            widen(
                                &mut chart.step_rate_min[axis][bucket],
                                &mut chart.step_rate_max[axis][bucket],
                                v * rate_per_speed[axis],
                            );
                        }
                    }
                }
            }
            if let Some(v) = junction.filter(|_| b.start_seconds >= from) {
                let slot = &mut chart.junction_speed[bucket_of(b.start_seconds)];
                *slot = Some(slot.map_or(v, |w| w.min(v)));
            }
        }
        if moving_until < to {
            rest(&mut chart, moving_until, to);
            if chart.exact {
                chart.push_rest_row(to);
            }
        }
        if !chart.exact {
            chart.seconds = (0..buckets)
                .map(|bucket| from + (f64::from(bucket) + 0.5) * width)
                .collect();
        }
        Ok(chart)
    }
}

#[cfg(test)]
mod tests {
    use crate::gcode::{Settings, run};

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-9 * (1.0 + a.abs().max(b.abs()))
    }

    fn square() -> crate::gcode::Program {
        // The page's default program at 80 steps/mm and Grbl's defaults:
        // four 20 mm sides at 500 mm/min (8.33 mm/s), a = 10 mm/s².
        run(
            "G21 G90 G17\nG0 X0 Y0 Z0\nG1 X20 Y0 F600\nY20\nX0\nY0\n",
            Settings::from_json(r#"{"stepsPerMm": 80}"#).unwrap(),
        )
    }

    #[test]
    fn few_blocks_are_charted_by_their_corners() {
        let p = square();
        let t = &p.timeline;
        let c = t.motion_chart(&[80.0; 3], 0.0, 1e9, 2000).unwrap();
        assert!(c.exact);
        assert_eq!((c.from_seconds, c.to_seconds), (0.0, t.duration_seconds()));
        // Four trapezoids of three pieces, four corners each.
        assert_eq!(c.seconds.len(), 16);
        assert_eq!(c.speed_min, c.speed_max);
        let top = 500.0 / 60.0;
        assert!(close(c.speed_max[1].unwrap(), top) && c.speed_max[0] == Some(0.0));
        // Along X at 8.33 mm/s: 666.7 steps/s on X, none on Y; then Y's turn.
        assert!(close(c.step_rate_max[0][1].unwrap(), top * 80.0));
        assert_eq!(c.step_rate_max[1][1], Some(0.0));
        assert!(close(c.step_rate_max[1][5].unwrap(), top * 80.0));
        // The three corners: Grbl's 90° junction speed, √(a_j·δ·s/(1−s)),
        // a_j = a·√2, s = sin 45°.
        let s = 0.5f64.sqrt();
        let corner = (10.0 * 2f64.sqrt() * 0.01 * s / (1.0 - s)).sqrt();
        let marked: Vec<f64> = c.junction_speed.iter().flatten().copied().collect();
        assert_eq!(marked.len(), 3);
        assert!(marked.iter().all(|&v| close(v, corner)), "{marked:?}");
        assert!(c.seconds.windows(2).all(|w| w[0] <= w[1]));
    }

    #[test]
    fn a_window_clips_the_corners_and_buckets_keep_the_extremes() {
        let p = square();
        let t = &p.timeline;
        let d = t.duration_seconds();
        // The first half second: accelerating from rest at 10 mm/s².
        let c = t.motion_chart(&[80.0; 3], 0.0, 0.5, 100).unwrap();
        assert!(c.exact);
        assert_eq!(c.seconds, vec![0.0, 0.5]);
        assert!(close(c.speed_max[1].unwrap(), 5.0));
        // Too many blocks for 8 rows: buckets, each holding its least and
        // greatest; the stops at the ends and the corners are in them.
        let c = t.motion_chart(&[80.0; 3], 0.0, d, 8).unwrap();
        assert!(!c.exact);
        assert_eq!(c.seconds.len(), 8);
        assert_eq!(c.speed_min[0], Some(0.0));
        assert_eq!(c.speed_min[7], Some(0.0));
        let top = 500.0 / 60.0;
        assert!(
            c.speed_max
                .iter()
                .all(|v| v.unwrap() <= top * (1.0 + 1e-12))
        );
        assert!(c.speed_max.iter().any(|v| close(v.unwrap(), top)));
        assert_eq!(c.junction_speed.iter().flatten().count(), 3);
        assert!(close(c.seconds[0], d / 16.0));
        // Each bucket's least and greatest speed, from the exact chart's
        // corners: the profile is linear between them, so its extremes over
        // a bucket are at the corners within it or at its edges.
        let exact = t.motion_chart(&[80.0; 3], 0.0, d, 2000).unwrap();
        assert!(exact.exact);
        let corners: Vec<(f64, f64)> = exact
            .seconds
            .iter()
            .zip(&exact.speed_max)
            .map(|(&t, v)| (t, v.unwrap()))
            .collect();
        let speed_at = |at: f64| {
            let i = corners
                .partition_point(|&(t, _)| t <= at)
                .clamp(1, corners.len() - 1);
            let ((t0, v0), (t1, v1)) = (corners[i - 1], corners[i]);
            if t1 <= t0 {
                v1
            } else {
                v0 + (v1 - v0) * (at - t0) / (t1 - t0)
            }
        };
        for bucket in 0..8 {
            let (lo, hi) = (d * bucket as f64 / 8.0, d * (bucket + 1) as f64 / 8.0);
            let inside = corners
                .iter()
                .filter(|&&(t, _)| lo <= t && t <= hi)
                .map(|&(_, v)| v);
            let speeds: Vec<f64> = inside.chain([speed_at(lo), speed_at(hi)]).collect();
            let least = speeds.iter().copied().fold(f64::INFINITY, f64::min);
            let greatest = speeds.iter().copied().fold(0.0, f64::max);
            let (min, max) = (c.speed_min[bucket].unwrap(), c.speed_max[bucket].unwrap());
            assert!(
                close(min, least) && close(max, greatest),
                "bucket {bucket}: {min}..{max} against {least}..{greatest}"
            );
        }
        // The corners slow the tool without stopping it (Grbl's 90° junction
        // at a = 10 mm/s², δ = 0.01 mm: about 0.49 mm/s), so the buckets
        // between the two stops have least speeds above 0.
        assert!(
            c.speed_min[1..7].iter().all(|v| v.unwrap() > 0.4),
            "{:?}",
            c.speed_min
        );
    }

    #[test]
    fn a_dwell_is_charted_at_rest_before_between_and_after_the_moves() {
        let program = |source: &str| {
            run(
                source,
                Settings::from_json(r#"{"stepsPerMm": 80}"#).unwrap(),
            )
        };
        // G4 P5 first: 5 s at rest, then 1 mm at 300 mm/min (5 mm/s, a =
        // 10 mm/s²: a triangle of 2·√(1/10) s, peak √10 mm/s).
        let p = program("G4 P5\nG1 X1 F300\n");
        let t = &p.timeline;
        let d = t.duration_seconds();
        assert!(close(d, 5.0 + 2.0 * 0.1f64.sqrt()));
        let c = t.motion_chart(&[80.0; 3], 0.0, d, 200).unwrap();
        assert!(c.exact);
        assert_eq!((c.seconds[0], c.speed_max[0]), (0.0, Some(0.0)));
        assert_eq!(c.step_rate_max[0][0], Some(0.0));
        assert_eq!((c.seconds[1], c.speed_max[1]), (5.0, Some(0.0)));
        assert!(close(c.speed_max[2].unwrap(), 10f64.sqrt()));
        // A window inside the dwell: at rest from end to end (it had no rows).
        let c = t.motion_chart(&[80.0; 3], 1.0, 2.0, 200).unwrap();
        assert_eq!(c.seconds, vec![1.0, 2.0]);
        assert_eq!(c.speed_max, vec![Some(0.0), Some(0.0)]);
        let c = t.motion_chart(&[80.0; 3], 1.0, 2.0, 3).unwrap();
        assert!(c.speed_max.iter().all(|&v| v == Some(0.0)));

        // A dwell after the last move: the chart runs on at rest to the end.
        let p = program("G1 X1 F300\nG4 P5\n");
        let t = &p.timeline;
        let d = t.duration_seconds();
        let c = t.motion_chart(&[80.0; 3], 0.0, d, 200).unwrap();
        assert_eq!(c.seconds.last(), Some(&d));
        assert_eq!(c.speed_max.last(), Some(&Some(0.0)));

        // 10 mm, 10 s at rest, 10 mm back, in six buckets (each trapezoid is
        // 2.5 s: 0.5 s each way at 10 mm/s², 1.5 s at 5 mm/s; 15 s in all):
        // the dwell's buckets are at rest, none is empty (a gap before).
        let p = program("G1 X10 F300\nG4 P10\nX0\n");
        let t = &p.timeline;
        let d = t.duration_seconds();
        assert!(close(d, 15.0));
        let c = t.motion_chart(&[80.0; 3], 0.0, d, 6).unwrap();
        assert!(!c.exact);
        assert!(c.speed_max.iter().all(Option::is_some), "{:?}", c.speed_max);
        assert_eq!(c.speed_max[1..5], [Some(0.0); 4]);
        assert!(close(c.speed_max[0].unwrap(), 5.0) && close(c.speed_max[5].unwrap(), 5.0));
        // The buckets that hold both a move and the rest after it go down to 0.
        assert_eq!((c.speed_min[0], c.speed_min[5]), (Some(0.0), Some(0.0)));
    }

    #[test]
    fn bad_windows_and_bucket_counts_name_the_argument() {
        let p = square();
        let t = &p.timeline;
        let e = t.motion_chart(&[80.0; 3], 1.0, 1.0, 10).unwrap_err();
        assert_eq!(
            e.to_string(),
            "toSeconds: must be greater than fromSeconds; got 1..1"
        );
        // An infinity as JavaScript, which passed it, spells it.
        let e = t
            .motion_chart(&[80.0; 3], f64::INFINITY, f64::INFINITY, 10)
            .unwrap_err();
        assert_eq!(
            e.to_string(),
            "toSeconds: must be greater than fromSeconds; got Infinity..Infinity"
        );
        let e = t.motion_chart(&[80.0; 3], 0.0, f64::NAN, 10).unwrap_err();
        assert_eq!(e.to_string(), "toSeconds: is not a number");
        let e = t.motion_chart(&[80.0; 3], f64::NAN, 1.0, 10).unwrap_err();
        assert_eq!(e.to_string(), "fromSeconds: is not a number");
        let e = t.motion_chart(&[80.0; 3], 0.0, 1.0, 0).unwrap_err();
        assert_eq!(e.to_string(), "buckets: must be 1 to 100000, got 0");
        // An infinite end is the program's: the same chart as its duration.
        let duration = t.duration_seconds();
        let whole = t.motion_chart(&[80.0; 3], 0.0, duration, 10).unwrap();
        let endless = t
            .motion_chart(&[80.0; 3], f64::NEG_INFINITY, f64::INFINITY, 10)
            .unwrap();
        assert_eq!(endless, whole);
        assert_eq!((whole.from_seconds, whole.to_seconds), (0.0, duration));
        // Past the program's end: an empty window at its end, no rows; before
        // its start, an empty one at 0.
        let c = t.motion_chart(&[80.0; 3], 1e6, 2e6, 10).unwrap();
        assert!(c.seconds.is_empty() && c.speed_max.is_empty());
        assert_eq!((c.from_seconds, c.to_seconds), (duration, duration));
        let c = t.motion_chart(&[80.0; 3], -2.0, -1.0, 10).unwrap();
        assert!(c.seconds.is_empty());
        assert_eq!((c.from_seconds, c.to_seconds), (0.0, 0.0));
    }
}
