//! Whole-path statistics: step counts, pulses, deviation from the ideal path.

use crate::grid::{MAX_AXES, Step};
use serde::Serialize;
use tsify::Tsify;

/// Statistics of one trace. Deviations are in grid units; mean and standard
/// deviation are taken over all points, start and end included (as the Error
/// columns of Wang's Tables 1 and 2 list them).
#[derive(Serialize, Tsify, Debug, Clone, Default, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct Metrics {
    pub steps: u64,
    /// `steps_moving_axes[k]` = steps that move exactly k + 1 axes.
    pub steps_moving_axes: Vec<u64>,
    /// Unit moves per axis.
    pub pulses_by_axis: Vec<u64>,
    pub max_deviation: f64,
    pub mean_deviation: f64,
    /// Population standard deviation of the per-point deviation.
    pub std_deviation: f64,
    /// Largest |phi| per axis (Wang eq. 11).
    pub max_axis_error: Vec<f64>,
    /// Decisions that were ties, resolved by the tie policy.
    pub ties: u64,
}

pub struct MetricsAccumulator {
    dims: usize,
    steps: u64,
    steps_moving_axes: [u64; MAX_AXES],
    pulses_by_axis: [u64; MAX_AXES],
    points: u64,
    max_deviation: f64,
    /// Welford's running mean and sum of squared differences: stable for
    /// 10^7 points where a naive sum of squares loses digits.
    mean: f64,
    m2: f64,
    max_axis_error: [f64; MAX_AXES],
}

impl MetricsAccumulator {
    pub fn new(dims: usize) -> MetricsAccumulator {
        MetricsAccumulator {
            dims,
            steps: 0,
            steps_moving_axes: [0; MAX_AXES],
            pulses_by_axis: [0; MAX_AXES],
            points: 0,
            max_deviation: 0.0,
            mean: 0.0,
            m2: 0.0,
            max_axis_error: [0.0; MAX_AXES],
        }
    }

    /// Counts `steps`: how many move 1, 2, ... axes, and each axis's
    /// pulses. One increment a step, of a count per set of moving axes,
    /// summed per axis after: a loop over the axes at every step was most
    /// of the time a long program took to finish.
    ///
    /// Consecutive steps mostly move the same axes, so one table's count
    /// would be read right after the store before it, a wait each step;
    /// eight tables, a step to each in turn, let eight counts run at once
    /// (the pulses of the 100,000-line bench program at 80 steps/mm,
    /// natively: 6.6 -> 1.8 ms; four tables, 2.6 ms).
    pub fn add_steps(&mut self, steps: &[Step]) {
        const TABLES: usize = 8;
        let mut tables = [[0u64; 256]; TABLES];
        let mut quads = steps.chunks_exact(TABLES);
        for quad in &mut quads {
            for (table, step) in tables.iter_mut().zip(quad) {
                table[step.moving_axes() as usize] += 1;
            }
        }
        for step in quads.remainder() {
            tables[0][step.moving_axes() as usize] += 1;
        }
        let by_moving: [u64; 256] =
            std::array::from_fn(|moving| tables.iter().map(|table| table[moving]).sum());
        for (moving, &count) in by_moving.iter().enumerate() {
            if count == 0 {
                continue;
            }
            if let Some(i) = (moving.count_ones() as usize).checked_sub(1) {
                self.steps_moving_axes[i] += count;
            }
            for axis in 0..self.dims {
                self.pulses_by_axis[axis] += (moving >> axis & 1) as u64 * count;
            }
        }
        self.steps += steps.len() as u64;
    }

    pub fn add_point(&mut self, deviation: f64, axis_error: &[f64; MAX_AXES]) {
        self.add_deviation(deviation);
        self.add_axis_error(axis_error);
    }

    /// A point's deviation alone (its axis error added apart, as the largest
    /// of a stretch of points: [`Self::add_axis_error`]).
    #[inline]
    pub fn add_deviation(&mut self, deviation: f64) {
        self.points += 1;
        self.max_deviation = self.max_deviation.max(deviation);
        let delta = deviation - self.mean;
        self.mean += delta / self.points as f64;
        self.m2 += delta * (deviation - self.mean);
    }

    /// A per-axis error (of one point, or the largest of several).
    pub fn add_axis_error(&mut self, axis_error: &[f64; MAX_AXES]) {
        for axis in 0..self.dims {
            self.max_axis_error[axis] = self.max_axis_error[axis].max(axis_error[axis].abs());
        }
    }

    /// Pulses per axis of the steps added so far (the STEP edges of each).
    pub fn pulses_by_axis(&self) -> Vec<u64> {
        self.pulses_by_axis[..self.dims].to_vec()
    }

    pub fn finish(self, ties: u64) -> Metrics {
        Metrics {
            steps: self.steps,
            steps_moving_axes: self.steps_moving_axes[..self.dims].to_vec(),
            pulses_by_axis: self.pulses_by_axis(),
            max_deviation: self.max_deviation,
            mean_deviation: self.mean,
            std_deviation: if self.points > 0 {
                (self.m2 / self.points as f64).sqrt()
            } else {
                0.0
            },
            max_axis_error: self.max_axis_error[..self.dims].to_vec(),
            ties,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn welford_matches_the_two_pass_formula() {
        let values = [0.0, 0.374887, 0.336918, 0.220564, 0.441129, 0.0];
        let mut acc = MetricsAccumulator::new(3);
        for v in values {
            acc.add_point(v, &[0.0; MAX_AXES]);
        }
        let m = acc.finish(0);
        let mean = values.iter().sum::<f64>() / values.len() as f64;
        let var = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / values.len() as f64;
        assert!((m.mean_deviation - mean).abs() < 1e-15);
        assert!((m.std_deviation - var.sqrt()).abs() < 1e-15);
        assert_eq!(m.max_deviation, 0.441129);
    }

    #[test]
    fn counts_axes_per_step_and_pulses() {
        let mut acc = MetricsAccumulator::new(3);
        acc.add_steps(&[
            Step::along(0, 1).with(1, -1),
            Step::along(0, 1),
            Step::along(0, -1).with(1, 1).with(2, 1),
        ]);
        let m = acc.finish(0);
        assert_eq!(m.steps_moving_axes, vec![1, 1, 1]);
        assert_eq!(m.pulses_by_axis, vec![3, 2, 1]);
    }

    proptest::proptest! {
        #[test]
        fn the_table_counts_are_the_step_by_step_counts(
            moving in proptest::collection::vec(0u8..64, 0..100),
            split in 0usize..100,
        ) {
            // Any length (a remainder past the tables' turns), in two calls.
            let steps: Vec<Step> = moving
                .iter()
                .map(|&m| (0..6).filter(|a| m >> a & 1 != 0).fold(Step::NONE, |s, a| s.with(a, 1)))
                .collect();
            let mut acc = MetricsAccumulator::new(6);
            let (first, second) = steps.split_at(split.min(steps.len()));
            acc.add_steps(first);
            acc.add_steps(second);
            let m = acc.finish(0);
            let mut pulses = vec![0u64; 6];
            let mut steps_moving_axes = vec![0u64; 6];
            for step in &steps {
                for (axis, p) in pulses.iter_mut().enumerate() {
                    *p += u64::from(step.moving_axes() >> axis & 1);
                }
                if let Some(k) = (step.axis_count() as usize).checked_sub(1) {
                    steps_moving_axes[k] += 1;
                }
            }
            proptest::prop_assert_eq!(m.pulses_by_axis, pulses);
            proptest::prop_assert_eq!(m.steps_moving_axes, steps_moving_axes);
        }
    }
}
