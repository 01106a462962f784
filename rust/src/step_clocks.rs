//! The tool's speed along a trace under two clocks: the 2009 line-following
//! blog's point about Bresenham's steps, "Sometimes a step in this algorithm
//! moves in one direction, and other times the step moves in two. This
//! means the speed would not be constant if I applied this algorithm
//! directly." A step that moves m axes at once covers √m of a cell (a
//! diagonal √2, a 3D diagonal √3).
//!
//! - One tick per step (the tick model of `machine`): every step takes the
//!   same time, so the tool's speed is √m cells per tick, jumping between
//!   1, √2 and √3 from step to step.
//! - Feed-rate timing: the tool keeps one feed along the path, here 1 cell
//!   per tick, so a step takes as long as it is long (√m ticks) and the
//!   speed is constant; the path takes Σ√m ticks instead of one per step.
//!
//! For a chart: at most `max_rows` rows, each a run of steps (one step a
//! row when the trace has few enough), with the least and the greatest
//! speed of its steps, so no diagonal step is lost at any zoom.

use crate::error::Error;
use crate::gcode::motion_chart::MAX_CHART_BUCKETS;
use crate::trace::Trace;
use serde::Serialize;
use tsify::Tsify;

/// The feed of the feed-rate timing, cells per tick: an axis step takes
/// one tick, as under the tick model.
pub const FEED_CELLS_PER_TICK: f64 = 1.0;

/// Steps read from the trace at once while scanning.
const SCAN_STEPS: u64 = 1 << 16;

/// A trace's speed per step under both clocks, as chart rows.
#[derive(Serialize, Tsify, Clone, Debug, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct StepClocks {
    /// Row r covers step indices rowEdges[r]..rowEdges[r + 1] (rows + 1
    /// entries, the last one the step count).
    pub row_edges: Vec<u64>,
    /// One tick per step: the least and the greatest speed of the row's
    /// steps, cells per tick (√m for a step moving m axes).
    pub equal_tick_min: Vec<f64>,
    pub equal_tick_max: Vec<f64>,
    /// Feed-rate timing: the speed of every step, cells per tick.
    pub feed_cells_per_tick: f64,
    /// How long the whole path takes, ticks: one per step under the tick
    /// model; its length in cells (Σ√m) over the feed under feed-rate timing.
    pub equal_tick_total_ticks: u64,
    pub feed_total_ticks: f64,
}

/// The two clocks of `trace` in at most `max_rows` rows.
pub fn step_clocks(trace: &Trace, max_rows: u32) -> Result<StepClocks, Error> {
    if !(1..=MAX_CHART_BUCKETS).contains(&max_rows) {
        return Err(Error::field(
            "maxRows",
            format!("must be 1 to {MAX_CHART_BUCKETS}, got {max_rows}"),
        ));
    }
    let steps = trace.steps();
    let per_row = steps.div_ceil(u64::from(max_rows)).max(1);
    let rows = steps.div_ceil(per_row) as usize;
    let mut clocks = StepClocks {
        row_edges: (0..rows as u64)
            .map(|r| r * per_row)
            .chain(std::iter::once(steps))
            .collect(),
        equal_tick_min: vec![f64::INFINITY; rows],
        equal_tick_max: vec![0.0; rows],
        feed_cells_per_tick: FEED_CELLS_PER_TICK,
        equal_tick_total_ticks: steps,
        feed_total_ticks: 0.0,
    };
    // √m by m (a step moves at most 8 axes, its mask a u8), so a step costs a table look-up, not a square root.
    let length_by_axes: Vec<f64> = (0..=8).map(|m| f64::from(m).sqrt()).collect();
    let mut from = 0;
    while from < steps {
        let to = steps.min(from + SCAN_STEPS);
        for (i, step) in trace.step_range(from, to).iter().enumerate() {
            let cells = length_by_axes[step.axis_count() as usize];
            let row = ((from + i as u64) / per_row) as usize;
            clocks.equal_tick_min[row] = clocks.equal_tick_min[row].min(cells);
            clocks.equal_tick_max[row] = clocks.equal_tick_max[row].max(cells);
            clocks.feed_total_ticks += cells / FEED_CELLS_PER_TICK;
        }
        from = to;
    }
    Ok(clocks)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_diagonal_step_is_faster_at_one_tick_a_step_and_longer_at_a_feed() {
        // Bresenham from (0,0) to (4,2): every step moves x, every other
        // one y too (x, xy, x, xy), so at one tick a step the speed
        // alternates 1, √2, and at 1 cell a tick the line takes 2 + 2√2.
        let trace =
            crate::trace_json(r#"{"algorithm": "bresenham2d", "from": [0,0], "to": [4,2]}"#)
                .unwrap();
        let c = step_clocks(&trace, 100).unwrap();
        let r2 = 2f64.sqrt();
        let speeds: Vec<f64> = c.equal_tick_max.clone();
        let mut sorted = speeds.clone();
        sorted.sort_by(f64::total_cmp);
        assert_eq!(sorted, vec![1.0, 1.0, r2, r2]);
        assert_eq!(c.equal_tick_min, speeds);
        assert_eq!(c.row_edges, vec![0, 1, 2, 3, 4]);
        assert_eq!(c.equal_tick_total_ticks, 4);
        assert!((c.feed_total_ticks - (2.0 + 2.0 * r2)).abs() < 1e-12);
        assert_eq!(c.feed_cells_per_tick, 1.0);
    }

    #[test]
    fn rows_of_many_steps_keep_their_least_and_greatest() {
        // Wang's line (0,0,0)->(10,7,6) by regions: 10 steps, in rows of
        // 4, 4 and 2 when 3 rows are asked for.
        let trace =
            crate::trace_json(r#"{"algorithm": "regions", "from": [0,0,0], "to": [10,7,6]}"#)
                .unwrap();
        let m = &trace.metrics().steps_moving_axes;
        let c = step_clocks(&trace, 3).unwrap();
        assert_eq!(c.row_edges, vec![0, 4, 8, 10]);
        // Each row's least and greatest speed, from the axes each of its
        // steps moves as the points show them: √m for m axes moved.
        let points = trace.points_flat(0, 11);
        let speed = |k: usize| {
            let moved = (0..3).filter(|&a| points[3 * k + a] != points[3 * (k + 1) + a]);
            (moved.count() as f64).sqrt()
        };
        for (row, steps) in [0..4, 4..8, 8..10].into_iter().enumerate() {
            let speeds: Vec<f64> = steps.map(speed).collect();
            let least = speeds.iter().copied().fold(f64::INFINITY, f64::min);
            let greatest = speeds.iter().copied().fold(0.0, f64::max);
            assert_eq!(
                (c.equal_tick_min[row], c.equal_tick_max[row]),
                (least, greatest),
                "row {row}: {speeds:?}"
            );
        }
        // Rows that differ, so that rows mixed up would show.
        assert!(
            c.equal_tick_min
                .iter()
                .zip(&c.equal_tick_max)
                .any(|(a, b)| a != b)
        );
        let all = step_clocks(&trace, 1).unwrap();
        // The fastest and slowest steps are those of the most and fewest
        // axes moved, as the metrics count them.
        let moved: Vec<f64> = (0..3)
            .filter(|&k| m[k] > 0)
            .map(|k| (k as f64 + 1.0).sqrt())
            .collect();
        assert_eq!(all.equal_tick_max, vec![*moved.last().unwrap()]);
        assert_eq!(all.equal_tick_min, vec![moved[0]]);
        assert!(moved.len() >= 2, "{m:?}");
        let expected = m[0] as f64 + m[1] as f64 * 2f64.sqrt() + m[2] as f64 * 3f64.sqrt();
        assert!((c.feed_total_ticks - expected).abs() < 1e-12);
        assert_eq!(
            step_clocks(&trace, 0).unwrap_err().to_string(),
            "maxRows: must be 1 to 100000, got 0"
        );
    }
}
