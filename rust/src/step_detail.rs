//! One point of a trace and the step that produced it, everything a viewer
//! shows about it in one value, from one replay of that step: the decision
//! row with its values read, the explanation, the deviation, the segment
//! and its note, and the picture of the decision (`figure`).
//!
//! Indexed by point index, as a trace's exports print their rows and as the
//! page counts: point p (0..=steps) is produced by step index p - 1, so
//! point 0, the start, has no step and no decision.

use crate::figure::DecisionFigure;
use crate::trace::{ColumnKind, Reading, SegmentSummary, Trace};
use serde::Serialize;
use tsify::Tsify;

#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct StepDetail<'a> {
    /// Point index p, 0..=steps.
    pub point_index: u64,
    /// The step that produced the point: step index p - 1; null at the start.
    pub step_index: Option<u64>,
    /// Point p, grid units.
    pub point: Vec<i64>,
    /// Point p - 1, where the step started; null at the start.
    pub point_before: Option<Vec<i64>>,
    /// Distance of point p from the ideal path, grid units: the trace's
    /// deviation of that point index (null for a trace without segments,
    /// a program with no move).
    pub deviation: Option<f64>,
    /// The step's decision, one cell per trace column in the summary's
    /// column order; every cell empty at the start.
    pub decision: Vec<DecisionCell>,
    /// Why the step was taken, in one sentence; null at the start.
    pub explanation: Option<String>,
    /// The picture of the decision, where its algorithm has one for it.
    pub figure: Option<DecisionFigure>,
    /// The segment (line, chord, G-code move) whose stepper took the step;
    /// at the start, the one that takes the first step.
    pub segment_index: Option<usize>,
    pub segment: Option<SegmentSummary<'a>>,
}

/// One decision value of a step.
#[derive(Serialize, Tsify)]
pub struct DecisionCell {
    /// The column's name (its doc is in the summary's columns).
    pub name: &'static str,
    #[tsify(type = "ColumnKind[\"kind\"]")]
    pub kind: &'static str,
    /// The value as the decisions array holds it (a category's label
    /// index, a flag's 0 or 1); null where the column does not apply.
    pub value: Option<f64>,
    /// The value as people read it: a number, a category's label, a flag's
    /// true or false; null where the column does not apply.
    pub reading: Option<Reading>,
}

/// The tag a column kind crosses the boundary with (its `kind`).
fn kind_name(kind: ColumnKind) -> &'static str {
    match kind {
        ColumnKind::Int => "int",
        ColumnKind::Float => "float",
        ColumnKind::Category { .. } => "category",
        ColumnKind::Flag => "flag",
    }
}

/// The detail of point index `p` (0..=steps) of `trace`.
pub fn step_detail(trace: &Trace, p: u64) -> StepDetail<'_> {
    let step_index = p.checked_sub(1);
    let replayed = step_index.map(|k| trace.replay_step(k));
    let segment_index = match step_index {
        Some(k) => Some(trace.segment_of_step(k)),
        None => (trace.segment_count() > 0).then(|| trace.segment_of_point(0)),
    };
    let decision = trace
        .columns()
        .iter()
        .enumerate()
        .map(|(i, column)| {
            let value = replayed.as_ref().map_or(f64::NAN, |r| r.values[i]);
            let reading = column.read(value);
            DecisionCell {
                name: column.name,
                kind: kind_name(column.kind),
                value: reading.is_some().then_some(value),
                reading,
            }
        })
        .collect();
    let (explanation, figure) = match replayed {
        Some(r) => (Some(r.explanation), r.figure),
        None => (None, None),
    };
    StepDetail {
        point_index: p,
        step_index,
        point: trace.point(p).coords().to_vec(),
        point_before: step_index.map(|k| trace.point(k).coords().to_vec()),
        // No segment, no ideal path to measure from: null, where the
        // trace's deviations read 0 for the point.
        deviation: (trace.segment_count() > 0).then(|| trace.deviation_range(p, p + 1)[0]),
        decision,
        explanation,
        figure,
        segment_index,
        segment: segment_index.map(|s| trace.segment_summary(s)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cell_s_kind_is_the_tag_its_column_kind_crosses_with() {
        for kind in [
            ColumnKind::Int,
            ColumnKind::Float,
            ColumnKind::Category { labels: &["a"] },
            ColumnKind::Flag,
        ] {
            assert_eq!(serde_json::to_value(kind).unwrap()["kind"], kind_name(kind));
        }
    }
}
