//! Two traces of the same move side by side (for example direct arc
//! stepping against the same arc in chords, or two line algorithms on one
//! line): each one's step count and deviation, where the paths part and why
//! each took the step it took there, and the cells one visits and the other
//! does not. The result is a plain serializable value for the CLI and page.
//!
//! A comparison request is `{"algorithms": [a, b], ...options}`: every
//! option goes to each of the two that declares it, and one that neither
//! declares is an error naming it (see [`compare_request`]).
//!
//! Cost: each trace's cells are sorted once with the point index of their
//! first visit, 28 bytes per point (about 170 MB for each of two
//! 6-million-step circles of radius 2^20), and the two sorted lists are
//! merged: the cells one visits and the other does not come out of the
//! merge as the point indices of their first visits, 4 bytes each. A trace
//! compared has at most [`MAX_COMPARED_POINTS`].

use crate::algorithms::{self, AlgorithmInfo};
use crate::error::Error;
use crate::grid::MAX_AXES;
use crate::metrics::Metrics;
use crate::request::{OptionKind, OptionSpec, Request};
use crate::trace::{PointsProgress, Trace};
use serde::Serialize;
use serde_json::Value;
use tsify::Tsify;

/// Most cells listed per side; `count` still counts them all.
pub const CELL_LIMIT: usize = 1000;

/// Most points a compared trace may have. Its sorted cells take 28 bytes a
/// point (their point indices are u32, which this bound keeps them in), and
/// the cells only it visits 4 more: two different paths of 20,000,000 and
/// 50,000,001 points ran the core past wasm's 4 GiB into a trap, when a
/// set held those cells. Within it, regions' 10,000,001 points against
/// walk6's 19,999,999 on the same line, 9,999,998 cells only walk6 visits,
/// took 1.5 GiB of wasm memory in all with that set.
pub const MAX_COMPARED_POINTS: u64 = 20_000_000;
const _: () = assert!(
    MAX_COMPARED_POINTS <= u32::MAX as u64,
    "first visits are u32"
);

/// Points read from a trace at a time.
const CHUNK_POINTS: u64 = 1 << 16;

#[derive(Serialize, Tsify, Debug, Clone, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct Comparison {
    pub a: TraceDigest,
    pub b: TraceDigest,
    /// The first point index whose points differ (the step before it is the
    /// first differing step); None when the paths are identical.
    pub first_difference: Option<FirstDifference>,
    /// Cells a visits and b never does, in a's order, each once.
    pub only_in_a: Cells,
    /// Cells b visits and a never does, in b's order, each once.
    pub only_in_b: Cells,
}

#[derive(Serialize, Tsify, Debug, Clone, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct TraceDigest {
    #[tsify(type = "AlgorithmId")]
    pub algorithm: String,
    pub steps: u64,
    pub start: Vec<i64>,
    pub end: Vec<i64>,
    /// maxDeviation is the largest radial error for an arc.
    pub metrics: Metrics,
    /// Where an algorithm is compared with itself by an option
    /// ([`AlgorithmInfo::compared_by`]: the helix by its method), the value
    /// of it this side ran; else None.
    pub compared_value: Option<String>,
}

#[derive(Serialize, Tsify, Debug, Clone, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct FirstDifference {
    pub point_index: u64,
    /// a's point there, or None when a has already ended.
    pub a: Option<Vec<i64>>,
    pub b: Option<Vec<i64>>,
    /// Why a took the step that produced its point there (step index
    /// point_index - 1); None when a has ended, or at point 0 (the paths
    /// start apart).
    pub a_why: Option<StepWhy>,
    pub b_why: Option<StepWhy>,
}

/// Why one trace took one step: its explanation and decision values.
#[derive(Serialize, Tsify, Debug, Clone, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct StepWhy {
    pub step_index: u64,
    /// One sentence ([`Trace::explain`]).
    pub explanation: String,
    /// Decision values by column name, in the trace's column order, as
    /// people read them: numbers, category labels, true/false for flags,
    /// null where a column does not apply to the step. Serialized as one
    /// JSON object.
    #[serde(serialize_with = "as_object")]
    #[tsify(type = "Record<string, number | string | boolean | null>")]
    pub decisions: Vec<(String, Value)>,
}

/// Pairs as one JSON object, keeping their order.
pub(crate) fn as_object<S: serde::Serializer>(
    pairs: &[(String, Value)],
    s: S,
) -> Result<S::Ok, S::Error> {
    s.collect_map(pairs.iter().map(|(k, v)| (k, v)))
}

#[derive(Serialize, Tsify, Debug, Clone, PartialEq, Default)]
#[serde(rename_all = "camelCase")]
pub struct Cells {
    /// Distinct cells.
    pub count: u64,
    /// The first [`CELL_LIMIT`] of them.
    pub cells: Vec<Vec<i64>>,
}

type Key = [i32; MAX_AXES];

/// A point as a sort key. Every trace point fits in i32 (inputs and circles
/// lie within ±2^30).
fn key(p: &[i64]) -> Key {
    let mut k = [0; MAX_AXES];
    for (slot, &c) in k.iter_mut().zip(p) {
        *slot = c as i32;
    }
    k
}

/// Calls `f(point index, coordinates)` for every point.
fn for_each_point(t: &Trace, f: impl FnMut(u64, &[i64])) {
    for_each_point_to(t, t.steps() + 1, f);
}

/// Calls `f(point index, coordinates)` for point indices `0..to`.
fn for_each_point_to(t: &Trace, to: u64, mut f: impl FnMut(u64, &[i64])) {
    t.walk_points(0, to, |k, p| f(k, p.coords()));
}

/// Each cell `t` visits, with the point index of its first visit, sorted by
/// cell.
fn first_visits(t: &Trace) -> Vec<(Key, u32)> {
    let mut visits = Vec::with_capacity(t.steps() as usize + 1);
    // Point indices fit u32 within MAX_COMPARED_POINTS, checked before.
    for_each_point(t, |k, p| visits.push((key(p), k as u32)));
    // By cell, then by point index: the first of a cell's visits is its first.
    visits.sort_unstable();
    visits.dedup_by_key(|&mut (cell, _)| cell);
    visits
}

/// The point indices of the first visits of the cells `a` visits and `b`
/// does not, and of those `b` visits and `a` does not, each in path order:
/// one merge of the two sorted lists. A search of `b`'s cells for each of
/// `a`'s points and a set to list each once took the comparison of two
/// 1,400,000-step lines 0.76 s natively, 1.3 s in wasm, nine tenths of it
/// the searches and the set's hashing.
fn first_visits_only_in(a: &[(Key, u32)], b: &[(Key, u32)]) -> [Vec<u32>; 2] {
    let (mut only_a, mut only_b) = (Vec::new(), Vec::new());
    let (mut i, mut j) = (0, 0);
    while i < a.len() && j < b.len() {
        match a[i].0.cmp(&b[j].0) {
            std::cmp::Ordering::Less => {
                only_a.push(a[i].1);
                i += 1;
            }
            std::cmp::Ordering::Greater => {
                only_b.push(b[j].1);
                j += 1;
            }
            std::cmp::Ordering::Equal => {
                i += 1;
                j += 1;
            }
        }
    }
    only_a.extend(a[i..].iter().map(|&(_, k)| k));
    only_b.extend(b[j..].iter().map(|&(_, k)| k));
    for visits in [&mut only_a, &mut only_b] {
        visits.sort_unstable();
    }
    [only_a, only_b]
}

/// Calls `f` with the cell at each of `t`'s point indices `visits` (in
/// path order), reading its points once up to the last of them.
fn for_each_visited(t: &Trace, visits: &[u32], mut f: impl FnMut(&[i64])) {
    let Some(&last) = visits.last() else {
        return;
    };
    let mut next = visits.iter().peekable();
    for_each_point_to(t, u64::from(last) + 1, |k, p| {
        if next.next_if(|&&visit| u64::from(visit) == k).is_some() {
            f(p);
        }
    });
}

/// Cells `t` visits at point indices `visits`: how many, and the first
/// [`CELL_LIMIT`].
fn listed(t: &Trace, visits: &[u32]) -> Cells {
    let mut cells = Vec::new();
    for_each_visited(t, &visits[..visits.len().min(CELL_LIMIT)], |p| {
        cells.push(p.to_vec())
    });
    Cells {
        count: visits.len() as u64,
        cells,
    }
}

/// Every cell `a` visits and `b` never does, in `a`'s order, each once,
/// flat with stride dims: what a view highlights, however many there are
/// ([`Comparison::only_in_a`] lists the first [`CELL_LIMIT`]).
pub fn cells_only_in(a: &Trace, b: &Trace) -> Result<Vec<i32>, Error> {
    same_axes(a, b)?;
    within_compared_points(a, b, "other")?;
    let [only_a, _] = first_visits_only_in(&first_visits(a), &first_visits(b));
    Ok(flat_cells(a, &only_a))
}

/// The cells at `t`'s point indices `visits` (in path order), flat with
/// stride dims.
fn flat_cells(t: &Trace, visits: &[u32]) -> Vec<i32> {
    let mut flat = Vec::with_capacity(visits.len() * t.dims());
    // Trace points lie within ±2^30 (see `key`).
    for_each_visited(t, visits, |p| flat.extend(p.iter().map(|&c| c as i32)));
    flat
}

/// Where two traces of one move differ, as a view shows them: the first
/// point where they part ([`first_difference`]) and every cell only one
/// visits ([`cells_only_in`] of each), each trace's cells sorted once
/// (`compare` and `cells_only_in` both ways sorted each three times), a
/// trace at a time: [`Self::advance`] sorts `a`'s cells, then `b`'s and
/// merges the two, so that a worker reports between the two and stops
/// there (each sort of a path near the page's 1,500,000 points took 0.2 to
/// 0.3 s in wasm). The cells are those of `cells_only_in`, which sorts the
/// same cells.
pub struct DifferencePass {
    /// Each side's point count, to check it is given the same traces.
    points: [u64; 2],
    /// `a`'s cells with their first visits, sorted, until merged.
    visits_a: Option<Vec<(Key, u32)>>,
    /// The point indices of the first visits of the cells only `a` visits
    /// and of those only `b` visits, once merged.
    only: Option<[Vec<u32>; 2]>,
}

impl DifferencePass {
    /// The difference of `a` and `b`: the same axes, each within
    /// [`MAX_COMPARED_POINTS`], else an error naming `other`.
    pub fn new(a: &Trace, b: &Trace) -> Result<DifferencePass, Error> {
        same_axes(a, b)?;
        within_compared_points(a, b, "other")?;
        Ok(DifferencePass {
            points: [a, b].map(|t| t.steps() + 1),
            visits_a: None,
            only: None,
        })
    }

    /// An error naming `field` unless `a` and `b` have the points of the
    /// traces this was made for.
    fn check(&self, a: &Trace, b: &Trace) -> Result<(), Error> {
        if [a, b].map(|t| t.steps() + 1) != self.points {
            return Err(Error::field("other", "is not a trace of this difference"));
        }
        Ok(())
    }

    /// Makes the next stage: `a`'s cells sorted, then `b`'s, merged with
    /// `a`'s. Counts the points of the sides sorted.
    pub fn advance(&mut self, a: &Trace, b: &Trace) -> Result<PointsProgress, Error> {
        self.check(a, b)?;
        if self.only.is_none() {
            match self.visits_a.take() {
                None => self.visits_a = Some(first_visits(a)),
                Some(visits_a) => {
                    self.only = Some(first_visits_only_in(&visits_a, &first_visits(b)))
                }
            }
        }
        let sorted = match (&self.visits_a, &self.only) {
            (_, Some(_)) => self.points[0] + self.points[1],
            (Some(_), None) => self.points[0],
            (None, None) => 0,
        };
        Ok(PointsProgress {
            points_done: sorted,
            points: self.points[0] + self.points[1],
            done: self.only.is_some(),
        })
    }

    /// The first point where `a` and `b` part, None where they do not.
    pub fn first_difference(&self, a: &Trace, b: &Trace) -> Result<Option<FirstDifference>, Error> {
        self.check(a, b)?;
        Ok(first_difference(a, b))
    }

    /// The cells only `a` visits (`side` 0) or only `b` visits (1), in its
    /// order, each once, flat with stride dims: of `a` when `side` is 0,
    /// else of `b`. An error until [`Self::advance`] is done.
    pub fn cells_only_in(&self, side: usize, a: &Trace, b: &Trace) -> Result<Vec<i32>, Error> {
        self.check(a, b)?;
        let only = self.only.as_ref().ok_or_else(|| {
            Error::field("difference", "is not made yet: advance it to its end first")
        })?;
        Ok(flat_cells([a, b][side.min(1)], &only[side.min(1)]))
    }
}

/// Traces on different numbers of axes have no cell in common to compare:
/// an error naming `other` (the trace `a` is compared with, as the JS API
/// calls it), never cells read across mismatched strides.
fn same_axes(a: &Trace, b: &Trace) -> Result<(), Error> {
    if a.dims() == b.dims() {
        return Ok(());
    }
    Err(Error::field(
        "other",
        format!("has {} axes but this trace has {}", b.dims(), a.dims()),
    ))
}

fn digest(t: &Trace) -> TraceDigest {
    TraceDigest {
        algorithm: t.algorithm.clone(),
        steps: t.steps(),
        start: t.start().coords().to_vec(),
        end: t.end().coords().to_vec(),
        metrics: t.metrics().clone(),
        compared_value: None,
    }
}

/// Why `t` took the step that produced point index `k`, if it did.
pub(crate) fn why_at_point(t: &Trace, k: u64) -> Option<StepWhy> {
    let step = k.checked_sub(1).filter(|&s| s < t.steps())?;
    let replayed = t.replay_step(step);
    let decisions = t
        .columns()
        .iter()
        .zip(&replayed.values)
        .map(|(column, &value)| {
            let reading = serde_json::to_value(column.read(value)).expect("a reading serializes");
            (column.name.to_string(), reading)
        })
        .collect();
    Some(StepWhy {
        step_index: step,
        explanation: replayed.explanation,
        decisions,
    })
}

/// The first point index where `a` and `b` differ, walking both together.
fn first_difference(a: &Trace, b: &Trace) -> Option<FirstDifference> {
    let shared = a.steps().min(b.steps()) + 1;
    let dims = a.dims();
    let mut from = 0;
    while from < shared {
        let to = (from + CHUNK_POINTS).min(shared);
        let (pa, pb) = (a.points_flat(from, to), b.points_flat(from, to));
        if let Some(i) = pa
            .chunks(dims)
            .zip(pb.chunks(dims))
            .position(|(p, q)| p != q)
        {
            let k = from + i as u64;
            return Some(FirstDifference {
                point_index: k,
                a: Some(a.point(k).coords().to_vec()),
                b: Some(b.point(k).coords().to_vec()),
                a_why: why_at_point(a, k),
                b_why: why_at_point(b, k),
            });
        }
        from = to;
    }
    // One path is a prefix of the other.
    (a.steps() != b.steps()).then(|| {
        let at = |t: &Trace| (shared <= t.steps()).then(|| t.point(shared).coords().to_vec());
        FirstDifference {
            point_index: shared,
            a: at(a),
            b: at(b),
            a_why: why_at_point(a, shared),
            b_why: why_at_point(b, shared),
        }
    })
}

/// Compares two traces with the same number of axes.
pub fn compare(a: &Trace, b: &Trace) -> Result<Comparison, Error> {
    compare_named(a, b, "other")
}

/// Both traces within [`MAX_COMPARED_POINTS`], else an error naming
/// `field`: the argument a trace came in as (`other`, the trace `a` is
/// compared with), or the option whose move made them (`to`).
fn within_compared_points(a: &Trace, b: &Trace, field: &str) -> Result<(), Error> {
    let points = [a, b].map(|t| t.steps() + 1);
    if points.iter().all(|&n| n <= MAX_COMPARED_POINTS) {
        return Ok(());
    }
    Err(Error::field(
        field,
        format!(
            "the paths have {} and {} points; a comparison takes paths of at most {MAX_COMPARED_POINTS} points (it sorts every cell of both); compare a shorter move",
            points[0], points[1]
        ),
    ))
}

/// [`compare`], a trace past [`MAX_COMPARED_POINTS`] refused naming `field`.
fn compare_named(a: &Trace, b: &Trace, field: &str) -> Result<Comparison, Error> {
    same_axes(a, b)?;
    within_compared_points(a, b, field)?;
    let [only_a, only_b] = first_visits_only_in(&first_visits(a), &first_visits(b));
    Ok(Comparison {
        a: digest(a),
        b: digest(b),
        first_difference: first_difference(a, b),
        only_in_a: listed(a, &only_a),
        only_in_b: listed(b, &only_b),
    })
}

/// The two algorithms of a comparison request, or an error naming
/// `algorithms`.
fn pick_algorithms(value: Option<Value>) -> Result<[&'static AlgorithmInfo; 2], Error> {
    let wrong = |what: String| Error::field("algorithms", what);
    let Some(Value::Array(items)) = value else {
        return Err(wrong(
            "expected two algorithm ids, for example [\"regions\", \"greedy\"]".into(),
        ));
    };
    let ids: Vec<&str> = items.iter().filter_map(Value::as_str).collect();
    let [a, b] = ids[..] else {
        return Err(wrong(format!(
            "expected two algorithm ids, got {}",
            Value::Array(items.clone())
        )));
    };
    let find = |id| algorithms::find(id).map_err(|e| wrong(e.message));
    let pair = [find(a)?, find(b)?];
    // A line and an arc algorithm do not trace one move: the line's would
    // leave the center out and step the chord.
    if pair[0].family != pair[1].family {
        return Err(wrong(format!(
            "{} traces {}s and {} traces {}s; compare takes two of one family, which trace the same move",
            pair[0].id,
            pair[0].family.label(),
            pair[1].id,
            pair[1].family.label()
        )));
    }
    Ok(pair)
}

/// A comparison as the JS API asks for it: the two algorithms, a then b,
/// and the shared options by name. Each option goes to every one of the two
/// that declares it, but for one that applies only with another option's
/// value (the helix's chord options, with method segments), which goes to
/// the other side alone where the other side takes it; one neither
/// declares is rejected, naming it. The helix against itself runs the
/// method given (else saleem) on a and the other on b.
#[derive(Serialize, Tsify)]
pub struct CompareOptions {
    /// The two catalogue ids (for example ["circle", "arc-segments"]).
    #[tsify(type = "readonly [AlgorithmId, AlgorithmId]")]
    pub algorithms: [String; 2],
    #[serde(flatten)]
    #[tsify(type = "Record<string, unknown>")]
    pub options: serde_json::Map<String, Value>,
}

/// Runs `{"algorithms": [a, b], ...options}`: each option goes to each of
/// the two algorithms that declares it (`segmentLength` only to
/// arc-segments when compared with circle, `from` and `to` to both), and
/// an option neither declares is an error naming it. An algorithm compared
/// with itself by an option ([`AlgorithmInfo::compared_by`]) runs it as
/// given on a and another value on b ([`compared_values`]); an option a side
/// declares but where it does not apply there
/// ([`OptionSpec::applies_with`]) is left to the other side where that one
/// takes it (the page's compare mode does the same). An algorithm's own
/// error keeps its field and says which algorithm it came from.
pub fn compare_request(text: &str) -> Result<Comparison, Error> {
    let mut options = Request::options_from_json(text)?;
    let pair = pick_algorithms(options.remove("algorithms"))?;
    let takes = |info: &AlgorithmInfo, name: &str| info.options.iter().any(|o| o.name == name);
    if let Some(name) = options
        .keys()
        .find(|name| !pair.iter().any(|info| takes(info, name)))
    {
        let list = |info: &AlgorithmInfo| {
            let names: Vec<&str> = info.options.iter().map(|o| o.name).collect();
            format!("{} takes {}", info.id, names.join(", "))
        };
        return Err(Error::field(
            name,
            format!(
                "neither {} nor {} takes this option ({}; {})",
                pair[0].id,
                pair[1].id,
                list(pair[0]),
                list(pair[1])
            ),
        ));
    }
    // An error that names its algorithm already ("regions takes 3
    // coordinates") is not named twice.
    let tagged = |info: &AlgorithmInfo, e: Error| Error {
        message: if e.message.starts_with(&format!("{} ", info.id)) {
            e.message
        } else {
            format!("{}: {}", info.id, e.message)
        },
        ..e
    };
    let compared = compared_values(pair, &options).map_err(|e| tagged(pair[0], e))?;
    // Each side's request: the options it declares, with its value of the
    // compared option where the algorithm is compared with itself.
    let mut requests = [0, 1].map(|side| {
        let info = pair[side];
        let mut own: serde_json::Map<String, Value> = options
            .iter()
            .filter(|(name, _)| takes(info, name))
            .map(|(name, value)| (name.clone(), value.clone()))
            .collect();
        if let Some((spec, values)) = compared {
            own.insert(spec.name.to_string(), Value::from(values[side]));
        }
        Request::new(info.id, own)
    });
    // One set of options serves both sides: one a side declares but where
    // it does not apply (the chord options beside the helix's method
    // saleem, OptionSpec::applies_with) is the other side's alone when the
    // other side takes it, and is left to be refused, naming it, when
    // neither does.
    let mut off: [Vec<&'static str>; 2] = [Vec::new(), Vec::new()];
    for side in 0..2 {
        off[side] = requests[side]
            .inapplicable(pair[side].options)
            .map_err(|e| tagged(pair[side], e))?
            .iter()
            .map(|o| o.name)
            .collect();
    }
    let takes_it = |side: usize, name: &str| {
        requests[side].options().contains_key(name) && !off[side].contains(&name)
    };
    let dropped = [0, 1].map(|side| {
        off[side]
            .iter()
            .copied()
            .filter(|name| takes_it(1 - side, name))
            .collect::<Vec<_>>()
    });
    requests = [0, 1].map(|side| requests[side].without(&dropped[side]));
    let run = |side: usize| {
        let info = pair[side];
        (info.trace)(&requests[side], algorithms::find).map_err(|e| tagged(info, e))
    };
    let mut comparison = compare_named(&run(0)?, &run(1)?, "to")?;
    if let Some((_, [a, b])) = compared {
        comparison.a.compared_value = Some(a.to_string());
        comparison.b.compared_value = Some(b.to_string());
    }
    Ok(comparison)
}

/// For an algorithm compared with itself by an option
/// ([`AlgorithmInfo::compared_by`]): that option, and the value each side
/// runs, a's as given (else its default) and b's the first other one. None
/// for two algorithms, or one not compared by an option.
fn compared_values(
    pair: [&AlgorithmInfo; 2],
    options: &serde_json::Map<String, Value>,
) -> Result<Option<(&'static OptionSpec, [&'static str; 2])>, Error> {
    let [a, b] = pair;
    let Some(name) = a.compared_by.filter(|_| a.id == b.id) else {
        return Ok(None);
    };
    let spec = a
        .options
        .iter()
        .find(|o| o.name == name)
        .expect("compared_by names an option of the algorithm's own");
    let OptionKind::Choice { values } = spec.kind else {
        unreachable!("compared_by names a choice option");
    };
    let request = Request::new(a.id, options.clone());
    let given = request.choice(spec)?.or(spec.default);
    let first = values
        .iter()
        .copied()
        .find(|v| Some(*v) == given)
        .unwrap_or(values[0]);
    let second = values
        .iter()
        .copied()
        .find(|v| *v != first)
        .unwrap_or(first);
    Ok(Some((spec, [first, second])))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::HashSet;

    fn trace(json: &str) -> Trace {
        crate::algorithms::trace_json(json).unwrap()
    }

    #[test]
    fn a_difference_made_a_trace_at_a_time_is_the_comparison_s_and_the_cells_only_each_visits() {
        let pairs = [
            (
                r#"{"algorithm":"regions","from":[0,0,0],"to":[9001,503,299]}"#,
                r#"{"algorithm":"greedy","from":[0,0,0],"to":[9001,503,299]}"#,
            ),
            (
                r#"{"algorithm":"circle","from":[50,0,0],"to":[0,50,0],"center":[0,0,0],"turns":2}"#,
                r#"{"algorithm":"arc-segments","from":[50,0,0],"to":[0,50,0],"center":[0,0,0],"turns":2,"segmentLength":7}"#,
            ),
            (
                r#"{"algorithm":"regions","from":[0,0,0],"to":[30,7,2]}"#,
                r#"{"algorithm":"regions","from":[0,0,0],"to":[30,7,2]}"#,
            ),
        ];
        for (a, b) in pairs {
            let (a, b) = (trace(a), trace(b));
            let mut pass = DifferencePass::new(&a, &b).unwrap();
            assert!(pass.cells_only_in(0, &a, &b).is_err(), "not made yet");
            let first = pass.advance(&a, &b).unwrap();
            assert_eq!((first.points_done, first.done), (a.steps() + 1, false));
            let second = pass.advance(&a, &b).unwrap();
            assert_eq!(
                (second.points_done, second.points, second.done),
                (a.steps() + b.steps() + 2, a.steps() + b.steps() + 2, true)
            );
            let comparison = compare(&a, &b).unwrap();
            assert_eq!(
                pass.first_difference(&a, &b).unwrap(),
                comparison.first_difference
            );
            assert_eq!(
                pass.cells_only_in(0, &a, &b).unwrap(),
                cells_only_in(&a, &b).unwrap()
            );
            assert_eq!(
                pass.cells_only_in(1, &a, &b).unwrap(),
                cells_only_in(&b, &a).unwrap()
            );
            assert_eq!(
                pass.cells_only_in(1, &a, &b).unwrap().len() as u64,
                comparison.only_in_b.count * a.dims() as u64
            );
            // Given other traces, it says so.
            assert!(pass.advance(&b, &b).is_err() || a.steps() == b.steps());
        }
    }

    #[test]
    fn a_quarter_circle_against_its_single_chord() {
        // Circle r = 5 (worked in tests/arc_golden.rs): (5,0) (5,1) (5,2)
        // (4,3) (3,4) (2,5) (1,5) (0,5). One chord (segment 100 > the arc's
        // 7.85): Wang's regions on (5,0,0) -> (0,5,0), |Δx| = |Δy| = 5, both
        // active, every step diagonal: (4,1) (3,2) (2,3) (1,4) (0,5).
        let circle =
            trace(r#"{"algorithm":"circle","from":[5,0,0],"to":[0,5,0],"center":[0,0,0]}"#);
        let chord = trace(
            r#"{"algorithm":"arc-segments","from":[5,0,0],"to":[0,5,0],"center":[0,0,0],"segmentLength":100}"#,
        );
        let c = compare(&circle, &chord).unwrap();
        assert_eq!((c.a.steps, c.b.steps), (7, 5));
        assert_eq!(
            c.first_difference,
            Some(FirstDifference {
                point_index: 1,
                a: Some(vec![5, 1, 0]),
                b: Some(vec![4, 1, 0]),
                a_why: why_at_point(&circle, 1),
                b_why: why_at_point(&chord, 1),
            })
        );
        let cells = |v: &[[i64; 3]]| v.iter().map(|p| p.to_vec()).collect::<Vec<_>>();
        assert_eq!(
            c.only_in_a.cells,
            cells(&[
                [5, 1, 0],
                [5, 2, 0],
                [4, 3, 0],
                [3, 4, 0],
                [2, 5, 0],
                [1, 5, 0]
            ])
        );
        assert_eq!(
            c.only_in_b.cells,
            cells(&[[4, 1, 0], [3, 2, 0], [2, 3, 0], [1, 4, 0]])
        );
        assert_eq!((c.only_in_a.count, c.only_in_b.count), (6, 4));
        // Largest radial error: circle (5,2), sqrt(29) - 5 = 0.385; chord
        // (3,2) and (2,3), 5 - sqrt(13) = 1.394.
        assert!((c.a.metrics.max_deviation - (29f64.sqrt() - 5.0)).abs() < 1e-12);
        assert!((c.b.metrics.max_deviation - (5.0 - 13f64.sqrt())).abs() < 1e-12);
        let json = serde_json::to_value(&c).unwrap();
        assert_eq!(json["firstDifference"]["pointIndex"], 1);
        assert_eq!(json["onlyInB"]["count"], 4);
    }

    #[test]
    fn the_full_cell_lists_go_past_the_limit_and_agree_with_the_counts() {
        // regions and greedy on (0,0,0) -> (3000,2000,1000): greedy moves
        // one axis per step (6000 steps) and regions up to three (3000), so
        // their cells part by far more than CELL_LIMIT.
        let a = trace(r#"{"algorithm":"regions","from":[0,0,0],"to":[3000,2000,1000]}"#);
        let b = trace(r#"{"algorithm":"greedy","from":[0,0,0],"to":[3000,2000,1000]}"#);
        let c = compare(&a, &b).unwrap();
        let (only_a, only_b) = (
            cells_only_in(&a, &b).unwrap(),
            cells_only_in(&b, &a).unwrap(),
        );
        assert!(c.only_in_b.count as usize > CELL_LIMIT);
        assert_eq!(only_a.len() as u64, 3 * c.only_in_a.count);
        assert_eq!(only_b.len() as u64, 3 * c.only_in_b.count);
        // The listed cells are the full list's first ones, in path order.
        let listed: Vec<i32> = c
            .only_in_b
            .cells
            .concat()
            .iter()
            .map(|&v| v as i32)
            .collect();
        assert_eq!(listed[..], only_b[..listed.len()]);
        // And none of them is a cell of the other path.
        let of_a: HashSet<Vec<i32>> = (0..=a.steps())
            .map(|k| a.point(k).coords().iter().map(|&v| v as i32).collect())
            .collect();
        assert!(only_b.chunks(3).all(|cell| !of_a.contains(cell)));
        assert!(only_a.chunks(3).all(|cell| of_a.contains(cell)));
        let of_b: HashSet<Vec<i32>> = (0..=b.steps())
            .map(|k| b.point(k).coords().iter().map(|&v| v as i32).collect())
            .collect();
        assert!(only_a.chunks(3).all(|cell| !of_b.contains(cell)));
    }

    /// The cells of `a` that `b` never visits, each once at its first
    /// visit, in `a`'s order, by a set of `b`'s cells: what the merge of
    /// the sorted lists must give.
    fn only_in_by_sets(a: &Trace, b: &Trace) -> Vec<i32> {
        let cells = |t: &Trace| -> Vec<Vec<i32>> {
            (0..=t.steps())
                .map(|k| t.point(k).coords().iter().map(|&v| v as i32).collect())
                .collect()
        };
        let of_b: HashSet<Vec<i32>> = cells(b).into_iter().collect();
        let mut seen = HashSet::new();
        cells(a)
            .into_iter()
            .filter(|cell| !of_b.contains(cell) && seen.insert(cell.clone()))
            .flatten()
            .collect()
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(48))]
        /// Two algorithms on one random move, lines or circles of one to
        /// three turns (cells visited again): the cells only one visits, as
        /// listed and counted, are those a set of the other's cells finds.
        #[test]
        fn cells_only_in_one_path_match_a_set_of_the_other_s(
            pair in proptest::sample::select(vec![
                ("regions", "greedy"), ("bresenham3d", "walk6"), ("nd", "dda"), ("liu-float", "regions"),
                ("circle", "arc-segments"), ("helix", "helix\",\"method\":\"segments"),
            ]),
            to in proptest::array::uniform3(-300i64..300),
            center in proptest::array::uniform2(-40i64..40),
            turns in 0u32..3,
        ) {
            // A line to `to`; an arc from (60, 0, 0) about a center near the
            // origin back to its start, a helix rising to to's z / 10.
            let request = |algorithm: &str| -> String {
                match pair.0 {
                    "circle" | "helix" => {
                        let z = if pair.0 == "helix" { to[2] / 10 } else { 0 };
                        format!(r#"{{"algorithm":"{algorithm}","from":[60,0,0],"to":[60,0,{z}],"center":[{},{},0],"turns":{turns}}}"#, center[0], center[1])
                    }
                    _ => format!(r#"{{"algorithm":"{algorithm}","from":[0,0,0],"to":[{},{},{}]}}"#, to[0], to[1], to[2]),
                }
            };
            let (a, b) = (trace(&request(pair.0)), trace(&request(pair.1)));
            let c = compare(&a, &b).unwrap();
            for (this, other, cells) in [(&a, &b, &c.only_in_a), (&b, &a, &c.only_in_b)] {
                let want = only_in_by_sets(this, other);
                proptest::prop_assert_eq!(cells_only_in(this, other).unwrap(), want.clone());
                proptest::prop_assert_eq!(cells.count as usize, want.len() / 3);
                let listed: Vec<i32> = cells.cells.concat().iter().map(|&v| v as i32).collect();
                proptest::prop_assert_eq!(&listed[..], &want[..listed.len()]);
            }
        }
    }

    #[test]
    fn a_cell_visited_again_is_listed_once() {
        // Two turns of r = 5 visit each of the circle's 28 cells twice (one
        // turn is 28 steps, ending where it starts); a line far off shares
        // none of them.
        let twice = trace(
            r#"{"algorithm":"circle","from":[5,0,0],"to":[5,0,0],"center":[0,0,0],"turns":1}"#,
        );
        let elsewhere = trace(r#"{"algorithm":"regions","from":[100,0,0],"to":[110,7,6]}"#);
        assert_eq!(twice.steps(), 56);
        let flat = cells_only_in(&twice, &elsewhere).unwrap();
        let cells: Vec<&[i32]> = flat.chunks(3).collect();
        let distinct: HashSet<&[i32]> = cells.iter().copied().collect();
        assert_eq!((cells.len(), distinct.len()), (28, 28));
        assert_eq!(cells[0], [5, 0, 0]);
        let c = compare(&twice, &elsewhere).unwrap();
        assert_eq!(c.only_in_a.count, 28);
    }

    #[test]
    fn identical_and_prefix_paths() {
        let a = trace(r#"{"algorithm":"regions","from":[0,0,0],"to":[10,7,6]}"#);
        let c = compare(&a, &a).unwrap();
        assert_eq!(c.first_difference, None);
        assert_eq!((c.only_in_a.count, c.only_in_b.count), (0, 0));
        // One full circle of r = 5 (28 steps) is a prefix of two turns: the
        // paths part where the first ends, over the same cells.
        let once = trace(r#"{"algorithm":"circle","from":[5,0,0],"to":[5,0,0],"center":[0,0,0]}"#);
        let twice = trace(
            r#"{"algorithm":"circle","from":[5,0,0],"to":[5,0,0],"center":[0,0,0],"turns":1}"#,
        );
        let c = compare(&once, &twice).unwrap();
        let d = c.first_difference.unwrap();
        assert_eq!((d.point_index, d.a, d.b), (29, None, Some(vec![5, 1, 0])));
        assert_eq!((c.only_in_a.count, c.only_in_b.count), (0, 0));
    }

    #[test]
    fn differing_axis_counts_are_refused() {
        let a = trace(r#"{"algorithm":"regions","from":[0,0,0],"to":[1,1,1]}"#);
        let b = crate::trace::TraceBuilder::new(crate::grid::Point::origin(2), 10).finish("empty");
        assert_eq!(
            compare(&a, &b).unwrap_err().to_string(),
            "other: has 2 axes but this trace has 3"
        );
        assert_eq!(
            cells_only_in(&b, &a).unwrap_err().to_string(),
            "other: has 3 axes but this trace has 2"
        );
    }
}

#[cfg(test)]
mod request_tests {
    use super::*;

    fn run(json: &str) -> Comparison {
        compare_request(json).unwrap_or_else(|e| panic!("{json}: {e}"))
    }

    fn error(json: &str) -> Error {
        compare_request(json).unwrap_err()
    }

    #[test]
    fn a_line_and_an_arc_algorithm_are_not_compared() {
        // regions would have stepped the chord, leaving the center out.
        let e = error(
            r#"{"algorithms":["regions","circle"],"from":[5,0,0],"to":[0,5,0],"center":[0,0,0]}"#,
        );
        assert_eq!(
            e.to_string(),
            "algorithms: regions traces lines and circle traces arcs; compare takes two of one family, which trace the same move"
        );
    }

    #[test]
    fn paths_past_the_compared_points_are_refused_naming_the_move() {
        // One point past MAX_COMPARED_POINTS on one side: refused before its
        // cells are sorted. (Two different paths of 20,000,000 and
        // 50,000,001 points had trapped the core past 4 GiB.)
        let n = MAX_COMPARED_POINTS;
        let e = error(&format!(
            r#"{{"algorithms":["regions","bresenham3d"],"from":[0,0,0],"to":[{n},3,1]}}"#
        ));
        assert_eq!(e.field_name(), Some("to"));
        assert_eq!(
            e.to_string(),
            format!(
                "to: the paths have {} and {} points; a comparison takes paths of at most {n} points (it sorts every cell of both); compare a shorter move",
                n + 1,
                n + 1
            )
        );
        let trace = |json: &str| crate::algorithms::trace_json(json).unwrap();
        let (a, b) = (
            trace(&format!(
                r#"{{"algorithm":"regions","from":[0,0,0],"to":[{n},3,1]}}"#
            )),
            trace(r#"{"algorithm":"regions","from":[0,0,0],"to":[3,3,1]}"#),
        );
        assert_eq!(compare(&b, &a).unwrap_err().field_name(), Some("other"));
        assert_eq!(
            cells_only_in(&b, &a).unwrap_err().field_name(),
            Some("other")
        );
    }

    fn decisions(why: &StepWhy) -> Value {
        let map = why
            .decisions
            .iter()
            .cloned()
            .collect::<serde_json::Map<_, _>>();
        Value::Object(map)
    }

    /// Steps of arc-segments traced alone with `options` (JSON members).
    fn arc_segments_steps(options: &str) -> u64 {
        crate::algorithms::trace_json(&format!(r#"{{"algorithm":"arc-segments",{options}}}"#))
            .unwrap()
            .steps()
    }

    #[test]
    fn the_helix_compared_with_itself_runs_its_other_method_on_b() {
        let helix = r#""from":[30,0,0],"to":[0,30,20],"center":[0,0,0]"#;
        // Chords as given on a, at the segment length given, which Saleem's
        // side b is not given (it refuses it): floor(15π / 10) = 4 chords
        // (the helix's own test), against Saleem's one segment.
        let c = run(&format!(
            r#"{{"algorithms":["helix","helix"],{helix},"method":"segments","segmentLength":10}}"#
        ));
        assert_eq!(
            (c.a.compared_value.as_deref(), c.b.compared_value.as_deref()),
            (Some("segments"), Some("saleem"))
        );
        let alone = |options: &str| {
            crate::algorithms::trace_json(&format!(r#"{{"algorithm":"helix",{helix}{options}}}"#))
                .unwrap()
        };
        assert_eq!(
            c.a.steps,
            alone(r#","method":"segments","segmentLength":10"#).steps()
        );
        assert_eq!(c.b.steps, alone("").steps());
        assert!(c.first_difference.is_some());
        // The method left to its default: Saleem's on a, chords (at their
        // default tolerance) on b.
        let c = run(&format!(r#"{{"algorithms":["helix","helix"],{helix}}}"#));
        assert_eq!(
            (c.a.compared_value.as_deref(), c.b.compared_value.as_deref()),
            (Some("saleem"), Some("segments"))
        );
        assert_eq!(c.b.steps, alone(r#","method":"segments""#).steps());
        // The helix against another arc algorithm: the chord option given
        // goes to the side it applies to, arc-segments; with the circle,
        // which does not take it, the helix refuses it, naming it.
        let quarter = r#""from":[20,0,0],"to":[0,20,0],"center":[0,0,0],"segmentLength":8"#;
        let c = run(&format!(
            r#"{{"algorithms":["helix","arc-segments"],{quarter}}}"#
        ));
        assert_eq!(c.b.steps, arc_segments_steps(quarter));
        let e = error(&format!(r#"{{"algorithms":["helix","circle"],{quarter}}}"#));
        assert_eq!(
            e.to_string(),
            "segmentLength: helix: applies to method segments only"
        );
        // Two algorithms, or one not compared by an option: no value.
        let c = run(r#"{"algorithms":["regions","regions"],"from":[0,0,0],"to":[10,7,6]}"#);
        assert_eq!((c.a.compared_value, c.b.compared_value), (None, None));
        assert!(c.first_difference.is_none());
        // A method that is not one names the field and the algorithm.
        let e = error(&format!(
            r#"{{"algorithms":["helix","helix"],{helix},"method":"chords"}}"#
        ));
        assert_eq!(e.field_name(), Some("method"));
        assert!(e.to_string().contains("helix: "), "{e}");
    }

    #[test]
    fn wang_and_saleem_part_at_the_tie_of_step_5() {
        // SEED-NOTES: on (0,0,0)->(10,7,6) Saleem holds a tie (error >
        // delta, strict) and goes to (5,3,3) where Wang's discriminant
        // M = 0 advances to (5,4,3); everything before step 5 agrees.
        let c = run(r#"{"algorithms":["regions","bresenham3d"],"from":[0,0,0],"to":[10,7,6]}"#);
        let d = c.first_difference.unwrap();
        assert_eq!(d.point_index, 5);
        assert_eq!((d.a, d.b), (Some(vec![5, 4, 3]), Some(vec![5, 3, 3])));
        let (a, b) = (d.a_why.unwrap(), d.b_why.unwrap());
        assert_eq!((a.step_index, b.step_index), (4, 4));
        assert_eq!(
            a.explanation,
            "x is the active axis; M = 0 and N = 10 > 0, so the line crosses segment g between C and D (a tie); the tie policy 'advance' decides, and the step goes to D (x+1, y+1, z+1)."
        );
        // Wang eq. (8): M_5 = 0, N_5 = 10 (SEED-NOTES' lists); the crossing
        // M / 20 = 0 and N / 20 = 0.5 on the face.
        assert_eq!(
            decisions(&a),
            serde_json::json!({"M": 0, "N": 10, "region": "g", "corner": "D", "tie": true,
                "faceU": 0.0, "faceV": 0.5, "faceUAxis": "+y", "faceVAxis": "+z"})
        );
        assert_eq!(
            a.decisions
                .iter()
                .map(|(k, _)| k.as_str())
                .collect::<Vec<_>>(),
            [
                "M",
                "N",
                "region",
                "corner",
                "tie",
                "faceU",
                "faceV",
                "faceUAxis",
                "faceVAxis"
            ]
        );
        // Saleem's errorY = 2|Δy| k - 2|Δx| (steps so far) = 2·7·5 - 2·10·3
        // = 10 = |Δx|, a tie; errorZ = 2·6·5 - 2·10·2 = 20 > 10.
        assert_eq!(
            b.explanation,
            "x is the major axis and steps; errorY = 10 = 10 (a tie), and the tie policy 'hold' says y holds; errorZ = 20 > 10, so z steps; the step goes to (x+1, y, z+1)."
        );
        assert_eq!(
            decisions(&b),
            serde_json::json!({"errorX": null, "errorY": 10, "errorZ": 20, "threshold": 10, "major": "x", "tie": true})
        );
        // A shared tie rule goes to both (both declare tie): no difference.
        let same = run(
            r#"{"algorithms":["regions","bresenham3d"],"from":[0,0,0],"to":[10,7,6],"tie":"hold"}"#,
        );
        assert_eq!(same.first_difference, None);
    }

    #[test]
    fn regions_and_greedy_part_at_the_first_step() {
        // Greedy (2009 blog) from (0,0,0) to (10,7,6): squared distance 185
        // now; a unit move on an axis with l left takes 2l - 1 off it:
        // x 185 - 19 = 166, y 185 - 13 = 172, z 185 - 11 = 174: x. Regions
        // steps all three (M_1 = 4, N_1 = 2, eq. 10).
        let c = run(r#"{"algorithms":["regions","greedy"],"from":[0,0,0],"to":[10,7,6]}"#);
        let d = c.first_difference.unwrap();
        assert_eq!(
            (d.point_index, d.a, d.b),
            (1, Some(vec![1, 1, 1]), Some(vec![1, 0, 0]))
        );
        let b = d.b_why.unwrap();
        assert_eq!(
            b.explanation,
            "Squared distance to the goal after moving x 166, y 172, z 174: x is the smallest, so x steps to (x+1, y, z)."
        );
        assert_eq!(decisions(&b)["distSqY"], 172.0);
        assert_eq!(decisions(&b)["distSqA"], Value::Null);
        assert_eq!(decisions(&d.a_why.unwrap())["region"], "d");
        // Greedy moves one axis per step: 23 steps against 10.
        assert_eq!((c.a.steps, c.b.steps), (10, 23));
    }

    #[test]
    fn options_go_to_the_algorithms_that_declare_them() {
        // segmentLength is arc-segments' only; center and from go to both.
        // The circle's first step (arc_golden.rs, r = 5): y fast, x stays,
        // |1| < |-8|; the single chord (5,0,0)->(0,5,0) has x and y active
        // and z passive with M_1 = 2·0 - 5 = -5: region b, corner B.
        let c = run(
            r#"{"algorithms":["circle","arc-segments"],"from":[5,0,0],"to":[0,5,0],"center":[0,0,0],"segmentLength":100}"#,
        );
        assert_eq!((c.a.steps, c.b.steps), (7, 5));
        assert_eq!((c.only_in_a.count, c.only_in_b.count), (6, 4));
        let d = c.first_difference.unwrap();
        let (a, b) = (d.a_why.unwrap(), d.b_why.unwrap());
        assert_eq!(
            a.explanation,
            "Octant 1: y is the fast axis and steps +1; x stays (x² + y² - r² = 1) or steps -1 (-8); |1| < |-8|, so x stays (eq. 7): (x, y+1, z)."
        );
        assert_eq!(
            decisions(&a),
            serde_json::json!({"octant": "1", "fast": "y", "residualStay": 1, "residualMove": -8, "slowSteps": false, "correction": false, "otherCandidate": "-x"})
        );
        assert_eq!(
            b.explanation,
            "x and y are active; M = -5 < 0, so the line leaves the cell through region b, and the step goes to B (x-1, y+1, z)."
        );
        // The same segmentLength given to circle alone would be refused.
        let alone = crate::algorithms::trace_json(
            r#"{"algorithm":"circle","from":[5,0,0],"to":[0,5,0],"center":[0,0,0],"segmentLength":100}"#,
        );
        assert_eq!(alone.err().unwrap().field_name(), Some("segmentLength"));
    }

    #[test]
    fn bad_requests_name_the_option() {
        let e = error(
            r#"{"algorithms":["circle","arc-segments"],"from":[5,0,0],"to":[0,5,0],"center":[0,0,0],"gcd":true}"#,
        );
        assert_eq!(e.field_name(), Some("gcd"));
        assert!(
            e.message.starts_with(
                "neither circle nor arc-segments takes this option (circle takes from, to, center,"
            ),
            "{e}"
        );
        let e = error(r#"{"algorithms":["circle","arc-segments"],"from":[5,0,0],"to":[0,5,0]}"#);
        assert_eq!(
            e.to_string(),
            "center: circle: missing: give one integer per axis, e.g. [0, 0, 0]"
        );
        assert_eq!(
            error(r#"{"algorithms":["regions"],"from":[0,0,0],"to":[1,1,1]}"#).to_string(),
            r#"algorithms: expected two algorithm ids, got ["regions"]"#
        );
        assert_eq!(
            error(r#"{"algorithms":"regions,greedy"}"#).to_string(),
            r#"algorithms: expected two algorithm ids, for example ["regions", "greedy"]"#
        );
        assert!(
            error(r#"{"algorithms":["regions","bresenham9d"]}"#)
                .to_string()
                .starts_with("algorithms: unknown algorithm 'bresenham9d' (known: regions")
        );
        // Two line algorithms on different axis counts: greedy takes 2D,
        // regions does not; its own message names it, once (it was
        // "regions: regions takes ...").
        assert_eq!(
            error(r#"{"algorithms":["greedy","regions"],"from":[0,0],"to":[3,1]}"#).to_string(),
            "from: regions takes 3 coordinates, got 2"
        );
    }
}
