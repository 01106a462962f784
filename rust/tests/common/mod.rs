//! Helpers shared by the integration tests: run a stepper directly, and
//! describe lines compactly.
#![allow(dead_code)] // each test crate uses its own subset

use voxpath::grid::{Point, displacement};
use voxpath::trace::{ColumnKind, Decision, Stepper, fill_onto};

/// Every step of `stepper` from `from`: the point after the step and why.
pub fn run<S: Stepper>(mut stepper: S, from: Point) -> Vec<(Point, S::Why)> {
    let mut p = from;
    let mut out = Vec::new();
    while let Some((step, why)) = stepper.next_step() {
        p.apply(step);
        out.push((p, why));
    }
    out
}

/// The points of a path, start included.
pub fn path<S: Stepper>(stepper: S, from: Point) -> Vec<Point> {
    std::iter::once(from)
        .chain(run(stepper, from).into_iter().map(|(p, _)| p))
        .collect()
}

/// Wang's and Liu's points for (0,0,0)->(10,7,6) (Wang eq. 6-10 with ties
/// advancing; Liu's Table 1; SEED-NOTES).
pub const WANG_10_7_6: [[i64; 3]; 10] = [
    [1, 1, 1],
    [2, 1, 1],
    [3, 2, 2],
    [4, 3, 2],
    [5, 4, 3],
    [6, 4, 4],
    [7, 5, 4],
    [8, 6, 5],
    [9, 6, 5],
    [10, 7, 6],
];

/// Points from coordinate arrays.
pub fn points<const N: usize>(coords: &[[i64; N]]) -> Vec<Point> {
    coords.iter().map(|c| Point::new(c)).collect()
}

/// The trace of a JSON request, which must succeed.
pub fn trace(json: &str) -> voxpath::Trace {
    voxpath::trace_json(json).unwrap_or_else(|e| panic!("{json}: {e}"))
}

/// The catalogue's line algorithms (arcs need a center and cannot run on from/to alone).
pub fn line_algorithms() -> impl Iterator<Item = &'static voxpath::algorithms::AlgorithmInfo> {
    voxpath::algorithms::ALGORITHMS
        .iter()
        .copied()
        .filter(|a| a.family == voxpath::algorithms::Family::Line)
}

/// The values a decision writes, as bits (NaN included), so that two
/// decisions compare exactly, the sign of a zero too.
fn decision_bits<D: Decision>(why: &D) -> Vec<u64> {
    let mut row = vec![f64::NAN; D::COLUMNS.len()];
    why.write(&mut row);
    row.iter().map(|v| v.to_bits()).collect()
}

/// Checks a stepper's recording loop (`fill`) against its steps one by one:
/// filled in chunks of `chunk`, with one `next_step` between chunks (so the
/// state `fill` leaves behind must be the rule's, to the bit of every
/// decision value that step writes), the same steps, the displacement they
/// add up to, and the steps left after each chunk.
pub fn check_fill<S: Stepper>(make: impl Fn() -> S, chunk: usize) -> Result<(), String> {
    let mut one_by_one = make();
    let mut expected = Vec::new();
    let mut expected_why = Vec::new();
    while let Some((step, why)) = one_by_one.next_step() {
        expected.push(step);
        expected_why.push(decision_bits(&why));
    }
    let mut stepper = make();
    let mut taken = Vec::new();
    loop {
        let mut out = Vec::new();
        let filled = fill_onto(&mut stepper, &mut out, chunk);
        if filled.displacement() != displacement(&out) {
            return Err(format!("displacement after {} steps", taken.len()));
        }
        taken.extend_from_slice(&out);
        if let Some((step, why)) = stepper.next_step() {
            if expected_why.get(taken.len()) != Some(&decision_bits(&why)) {
                return Err(format!("the decision of step {} after a fill", taken.len()));
            }
            taken.push(step);
        }
        if stepper.remaining_steps()
            != Some((expected.len() - taken.len().min(expected.len())) as u64)
        {
            return Err(format!("steps left after {} steps", taken.len()));
        }
        if filled.steps() < chunk {
            break;
        }
    }
    if taken != expected {
        return Err("fill took other steps than next_step".into());
    }
    Ok(())
}

/// True when `traced`, a decision value a trace gave for a column of `kind`,
/// is `written`, the value a stepper wrote (or another trace gave): equal,
/// or both "does not apply", which a stepper writes as NaN and a trace gives
/// as NaN in a number column and NO_VALUE in a category or flag column.
pub fn same_cell(kind: ColumnKind, traced: f64, written: f64) -> bool {
    let expected = if written.is_nan() {
        kind.no_value()
    } else {
        written
    };
    traced == expected || (traced.is_nan() && expected.is_nan())
}

/// The ties among a trace's steps as each step's decision records them,
/// replayed step by step: the flags of its tie columns (the lines' "tie",
/// Saleem's helix's "helixTie"; the circle's rule has no ties).
pub fn ties_by_decision(t: &voxpath::Trace) -> u64 {
    let table = t.decisions(0, t.steps());
    t.columns()
        .iter()
        .zip(&table.columns)
        .filter(|(column, _)| column.name == "tie" || column.name == "helixTie")
        .map(|(_, flags)| flags.iter().filter(|&&flag| flag == 1.0).count() as u64)
        .sum()
}

/// Checks the ties a trace's metrics count, in one pass and in a pass
/// made in `parts` slices of points (each slice's ties counted from the
/// checkpoint before it), against [`ties_by_decision`]. `make` makes the
/// trace afresh: a trace keeps its metrics once made.
pub fn check_ties(make: impl Fn() -> voxpath::Trace, parts: u64) -> Result<(), String> {
    let whole = make();
    let expected = ties_by_decision(&whole);
    let counted = whole.metrics().ties;
    if counted != expected {
        return Err(format!(
            "one pass: {counted} ties, the decisions {expected}"
        ));
    }
    let sliced = make();
    let slice = (sliced.steps() + 1).div_ceil(parts.max(1));
    while !sliced.advance_metrics(slice).done {}
    let counted = sliced.metrics().ties;
    if counted != expected {
        return Err(format!(
            "{slice} points a slice: {counted} ties, the decisions {expected}"
        ));
    }
    Ok(())
}
