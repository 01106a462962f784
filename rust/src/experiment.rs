//! The batch experiment of Wang et al. (2020), section 3.2 and Figure 9:
//! many seeded random lines from the origin, each traced by one algorithm,
//! and the distribution of their error statistics.
//!
//! Two error measures per point, because the paper uses both:
//! - the perpendicular distance to the ideal line (the Error column of its
//!   Tables 1 and 2, and the radius of the straightness cylinder of Fig. 6b);
//! - the norm of the per-axis error vector of eq. (11),
//!   delta_i = sqrt(phi_x^2 + phi_y^2 + phi_z^2), the error against the ideal
//!   position after the same number of steps, which reaches 0.7071 exactly
//!   where both passive axes are half a unit off.

use crate::algorithm_info::Family;
use crate::error::Error;
use crate::grid::{MAX_AXES, Point};
use crate::range::{IntegerRange, WHOLE_NUMBER};
use crate::request::{MAX_EXACT_INTEGER, MAX_STEPS_LIMIT, OptionKind, OptionSpec, Request};
use serde::Serialize;
use serde_json::Value;
use tsify::Tsify;

/// Most lines one experiment may trace.
pub const MAX_LINES: u64 = 100_000;

/// SplitMix64 (Steele, Lea & Flood 2014): a tiny, well-mixed generator whose
/// sequence for a seed never changes, so an experiment is reproducible from
/// its seed on every machine and in every future version.
struct SplitMix64(u64);

impl SplitMix64 {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in 0..=max, without modulo bias (rejects the incomplete top range).
    fn up_to(&mut self, max: u64) -> u64 {
        let span = max + 1;
        let limit = u64::MAX - u64::MAX % span;
        loop {
            let v = self.next();
            if v < limit {
                return v % span;
            }
        }
    }
}

/// Max, mean and (population) standard deviation of one line's errors.
#[derive(Serialize, Tsify, Debug, Clone, Copy, PartialEq)]
pub struct ErrorStats {
    pub max: f64,
    pub mean: f64,
    pub std: f64,
}

impl ErrorStats {
    fn of(values: &[f64]) -> ErrorStats {
        let n = values.len() as f64;
        let mean = values.iter().sum::<f64>() / n;
        let var = values.iter().map(|v| (v - mean) * (v - mean)).sum::<f64>() / n;
        ErrorStats {
            max: values.iter().copied().fold(0.0, f64::max),
            mean,
            std: var.sqrt(),
        }
    }
}

/// One random line and its errors.
#[derive(Serialize, Tsify, Debug, Clone, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct LineResult {
    pub to: Vec<i64>,
    pub steps: u64,
    /// Perpendicular distance of each point to the ideal line.
    pub perpendicular: ErrorStats,
    /// Norm of the per-axis error vector, Wang eq. (11).
    pub axis_error: ErrorStats,
}

/// Max, min and mean over all lines of one per-line statistic (Fig. 9 names
/// them delta_(Mean-Max), delta_(Mean-Min), delta_(Mean-Mean), ...).
#[derive(Serialize, Tsify, Debug, Clone, Copy, PartialEq)]
pub struct Spread {
    pub max: f64,
    pub min: f64,
    pub mean: f64,
}

impl Spread {
    fn of(values: impl Iterator<Item = f64> + Clone) -> Spread {
        let n = values.clone().count() as f64;
        Spread {
            max: values.clone().fold(f64::NEG_INFINITY, f64::max),
            min: values.clone().fold(f64::INFINITY, f64::min),
            mean: values.sum::<f64>() / n,
        }
    }
}

/// The spread of each per-line statistic of one error measure.
#[derive(Serialize, Tsify, Debug, Clone, Copy, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct MeasureSummary {
    pub max: Spread,
    pub mean: Spread,
    pub std: Spread,
}

impl MeasureSummary {
    fn of(lines: &[LineResult], pick: impl Fn(&LineResult) -> ErrorStats) -> MeasureSummary {
        MeasureSummary {
            max: Spread::of(lines.iter().map(|l| pick(l).max)),
            mean: Spread::of(lines.iter().map(|l| pick(l).mean)),
            std: Spread::of(lines.iter().map(|l| pick(l).std)),
        }
    }
}

#[derive(Serialize, Tsify, Debug, Clone, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct RandomLines {
    pub experiment: &'static str,
    #[tsify(type = "AlgorithmId")]
    pub algorithm: String,
    pub seed: u64,
    pub max_coordinate: i64,
    pub lines: Vec<LineResult>,
    pub perpendicular: MeasureSummary,
    pub axis_error: MeasureSummary,
    /// Wang's Figure 9, for comparison with `axis_error`.
    pub paper_figure_9: MeasureSummary,
    pub paper_figure_9_erratum: &'static str,
}

/// The request of `random-lines` as the JS API gives it: the algorithm that
/// traces every line, the experiment's own options ([`OPTIONS`], which
/// document them) and any option of that algorithm but from and to, by name.
#[derive(Serialize, Tsify)]
pub struct RandomLinesOptions {
    /// Catalogue id of the algorithm that traces every line (for example "regions").
    #[tsify(type = "AlgorithmId")]
    pub algorithm: String,
    #[serde(flatten)]
    #[tsify(type = "Record<string, unknown>")]
    pub options: serde_json::Map<String, Value>,
}

/// The options `random-lines` takes itself; any other option is passed to
/// the algorithm of every line (and checked by it).
pub const OPTIONS: &[OptionSpec] = &[COUNT, SEED, MAX_COORDINATE, DIMS];

const COUNT: OptionSpec = OptionSpec {
    name: "count",
    kind: OptionKind::Integer(IntegerRange {
        min: Some(1),
        max: Some(MAX_LINES as i64),
        whole: WHOLE_NUMBER,
    }),
    required: false,
    default: Some("100"),
    applies_with: None,
    doc: "How many random lines (Wang: 100), at most 100000.",
};

const SEED: OptionSpec = OptionSpec {
    name: "seed",
    kind: OptionKind::Integer(IntegerRange {
        min: Some(0),
        max: Some(MAX_EXACT_INTEGER),
        whole: WHOLE_NUMBER,
    }),
    required: false,
    default: Some("1"),
    applies_with: None,
    doc: "Seed of the SplitMix64 generator: the same seed gives the same lines everywhere.",
};

const MAX_COORDINATE: OptionSpec = OptionSpec {
    name: "maxCoordinate",
    kind: OptionKind::Integer(IntegerRange {
        min: Some(1),
        max: Some(10_000),
        whole: WHOLE_NUMBER,
    }),
    required: false,
    default: Some("100"),
    applies_with: None,
    doc: "End coordinates are drawn uniformly from 0 to this (Wang: 100), at most 10000.",
};

const DIMS: OptionSpec = OptionSpec {
    name: "dims",
    kind: OptionKind::Integer(IntegerRange {
        min: None,
        max: None,
        whole: WHOLE_NUMBER,
    }),
    required: false,
    default: None,
    applies_with: None,
    doc: "Axes per line (default 3, within what the algorithm takes).",
};

/// One experiment of the catalogue.
#[derive(Serialize, Tsify)]
pub struct ExperimentInfo {
    pub id: &'static str,
    pub title: &'static str,
    pub citation: &'static str,
    /// The family of algorithm it takes: the page offers only those.
    pub family: Family,
    pub options: &'static [OptionSpec],
}

pub const EXPERIMENTS: &[ExperimentInfo] = &[RANDOM_LINES];

const RANDOM_LINES: ExperimentInfo = ExperimentInfo {
    id: "random-lines",
    title: "Error statistics of seeded random lines from the origin",
    citation: "Wang et al. (2020), section 3.2 and Figure 9",
    family: Family::Line,
    options: OPTIONS,
};

/// Wang's Figure 9 as printed: the spread over their 100 lines of the
/// per-line max, mean and standard deviation of the eq. (11) error.
// 0.7071 is the paper's printed value (four decimals), not a stand-in for sqrt(2)/2.
#[allow(clippy::approx_constant)]
pub const PAPER_FIGURE_9: MeasureSummary = MeasureSummary {
    max: Spread {
        max: 0.7071,
        min: 0.7071,
        mean: 0.6472,
    },
    mean: Spread {
        max: 0.4119,
        min: 0.2469,
        mean: 0.3792,
    },
    std: Spread {
        max: 0.2250,
        min: 0.1390,
        mean: 0.1534,
    },
};

/// What is wrong with Figure 9 as printed.
pub const PAPER_FIGURE_9_ERRATUM: &str = "Figure 9 gives 0.7071 as both the largest and the smallest per-line maximum, yet 0.6472 as their mean, which cannot be: a mean lies between the smallest and the largest value. The method of the paper (regions), run on 100 lines with seed 1, gives a smallest per-line maximum of 0.4472 and matches the other eight values to within 0.02, which also shows that Figure 9 measures the error of eq. (11), not the perpendicular distance.";

/// How far a [`RandomLinesRun`] has got.
#[derive(Serialize, Tsify, Debug, Clone, Copy, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct ExperimentProgress {
    /// Lines traced so far, of `lines`.
    pub lines_done: u32,
    pub lines: u32,
    /// Steps of the lines traced so far.
    pub steps: u64,
    pub done: bool,
}

/// `random-lines` being run a slice of lines at a time, as a G-code program
/// runs (`gcode::Runner`): 100,000 lines of up to 10,000 steps take tens of
/// seconds, and a worker must be able to report progress and stop between
/// slices. The lines are drawn from the generator in order, so the result
/// does not depend on how the run was sliced.
pub struct RandomLinesRun {
    info: &'static crate::algorithm_info::AlgorithmInfo,
    /// The request every line is traced with: the algorithm's options,
    /// without the experiment's own; each line sets its from and to.
    line_request: Request,
    dims: usize,
    count: u32,
    seed: u64,
    max_coordinate: i64,
    rng: SplitMix64,
    steps: u64,
    lines: Vec<LineResult>,
}

impl RandomLinesRun {
    /// Checks the request (each fault names its field) and starts the run:
    /// `count` lines from the origin to points with coordinates drawn
    /// uniformly from 0..=maxCoordinate (Wang: 100 lines, 0..=100, 3 axes),
    /// traced with `algorithm`.
    pub fn new(request: &Request) -> Result<RandomLinesRun, Error> {
        let info = crate::algorithms::find(&request.algorithm)?;
        let family = RANDOM_LINES.family;
        if info.family != family {
            return Err(Error::field(
                "algorithm",
                format!(
                    "random-lines traces {}s; {} traces {}s",
                    family.label(),
                    info.id,
                    info.family.label()
                ),
            ));
        }
        // Each line's ends are the experiment's to draw: a from or to given
        // would be replaced, line after line, without a word.
        for own_end in ["from", "to"] {
            if request.has(own_end) {
                return Err(Error::field(
                    own_end,
                    "random-lines draws every line's ends itself (from the origin to a random point); give count, seed, maxCoordinate or dims instead",
                ));
            }
        }
        // An option neither the experiment nor its lines take, refused now
        // and named with what the experiment takes: the line algorithm's
        // own refusal, line by line, listed from and to, which are refused
        // above, and not count, seed, maxCoordinate or dims.
        let accepted: Vec<OptionSpec> = OPTIONS
            .iter()
            .chain(
                info.options
                    .iter()
                    .filter(|o| !["from", "to"].contains(&o.name)),
            )
            .copied()
            .collect();
        request.check_options_of(&format!("random-lines with {}", info.id), &accepted)?;
        let count = request.declared_integer(&COUNT)?.unwrap_or(100);
        let seed = request.declared_integer(&SEED)?.unwrap_or(1);
        let max_coordinate = request.declared_integer(&MAX_COORDINATE)?.unwrap_or(100);
        let dims = request
            .integer("dims")?
            .unwrap_or(info.min_dims.max(3).min(info.max_dims) as i64);
        if !(info.min_dims as i64..=info.max_dims as i64).contains(&dims) {
            return Err(Error::field(
                "dims",
                if info.min_dims == info.max_dims {
                    format!("{} takes {} axes, got {dims}", info.id, info.min_dims)
                } else {
                    format!(
                        "{} takes {} to {} axes, got {dims}",
                        info.id, info.min_dims, info.max_dims
                    )
                },
            ));
        }
        debug_assert!(dims as usize <= MAX_AXES);
        let own: Vec<&str> = OPTIONS.iter().map(|o| o.name).collect();
        Ok(RandomLinesRun {
            info,
            line_request: request.without(&own),
            dims: dims as usize,
            count: count as u32,
            seed: seed as u64,
            max_coordinate,
            rng: SplitMix64(seed as u64),
            steps: 0,
            lines: Vec::with_capacity(count as usize),
        })
    }

    /// Traces up to `max_lines` more lines. An option the algorithm refuses
    /// is refused at the first line, naming the option.
    pub fn advance(&mut self, max_lines: u32) -> Result<ExperimentProgress, Error> {
        let end = (self.lines.len() as u64 + max_lines as u64).min(self.count as u64) as usize;
        while self.lines.len() < end {
            let line = self.next_line()?;
            self.steps += line.steps;
            self.lines.push(line);
        }
        Ok(self.progress())
    }

    pub fn progress(&self) -> ExperimentProgress {
        ExperimentProgress {
            lines_done: self.lines.len() as u32,
            lines: self.count,
            steps: self.steps,
            done: self.lines.len() == self.count as usize,
        }
    }

    /// The next line drawn and traced, with its errors.
    fn next_line(&mut self) -> Result<LineResult, Error> {
        let dims = self.dims;
        let to: Vec<i64> = (0..dims)
            .map(|_| self.rng.up_to(self.max_coordinate as u64) as i64)
            .collect();
        let mut line = self.line_request.clone();
        line.set("from", Value::from(vec![0; dims]));
        line.set("to", Value::from(to.clone()));
        let trace = (self.info.trace)(&line, crate::algorithms::find).map_err(|e| {
            // "Shorten the move" is no advice where the experiment draws the
            // moves: the line is named, and the options that bound it.
            match (e.field_name(), &e.limit) {
                (Some("maxSteps"), Some(limit)) => Error::field(
                    "maxSteps",
                    format!(
                        "random line {} (from the origin to {}) needs more than {} steps (at least {}); raise maxSteps (up to {MAX_STEPS_LIMIT}) or lower maxCoordinate",
                        // Numbered from 1, as the table and CSV number the lines.
                        self.lines.len() + 1,
                        Point::new(&to),
                        limit.value,
                        limit.at_least
                    ),
                )
                .with_limit(limit.clone()),
                _ => e,
            }
        })?;
        let n = trace.steps();
        let perpendicular = ErrorStats::of(&trace.deviation_range(0, n + 1));
        let phi = trace.axis_error_range(0, n + 1);
        let norms: Vec<f64> = phi
            .chunks(dims)
            .map(|p| p.iter().map(|v| v * v).sum::<f64>().sqrt())
            .collect();
        Ok(LineResult {
            to,
            steps: n,
            perpendicular,
            axis_error: ErrorStats::of(&norms),
        })
    }

    /// The result of the lines traced so far (all of them once `done`).
    pub fn finish(self) -> RandomLines {
        let lines = self.lines;
        RandomLines {
            experiment: "random-lines",
            algorithm: self.info.id.to_string(),
            seed: self.seed,
            max_coordinate: self.max_coordinate,
            perpendicular: MeasureSummary::of(&lines, |l| l.perpendicular),
            axis_error: MeasureSummary::of(&lines, |l| l.axis_error),
            paper_figure_9: PAPER_FIGURE_9,
            paper_figure_9_erratum: PAPER_FIGURE_9_ERRATUM,
            lines,
        }
    }
}

/// Runs `random-lines` whole (see [`RandomLinesRun::new`]).
pub fn random_lines(request: &Request) -> Result<RandomLines, Error> {
    let mut run = RandomLinesRun::new(request)?;
    run.advance(u32::MAX)?;
    Ok(run.finish())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(json: &str) -> Result<RandomLines, Error> {
        random_lines(&Request::from_json(json).unwrap())
    }

    #[test]
    fn a_seed_past_what_json_carries_exactly_is_told_its_declared_range() {
        let e = run(r#"{"algorithm":"regions","count":1,"seed":9000000000000000}"#).unwrap_err();
        assert_eq!(
            e.to_string(),
            "seed: must be 0 to 8999999999999999, got 9000000000000000"
        );
        assert!(run(r#"{"algorithm":"regions","count":1,"seed":8999999999999999}"#).is_ok());
    }

    #[test]
    fn a_line_past_max_steps_is_named_with_the_options_that_bound_it() {
        let e = run(r#"{"algorithm":"regions","count":10,"seed":3,"maxSteps":10}"#).unwrap_err();
        assert_eq!(e.field_name(), Some("maxSteps"));
        let limit = e.limit.clone().expect("the cap");
        assert_eq!(limit.value, 10);
        let expected = format!(
            "random line 1 (from the origin to {}) needs more than 10 steps (at least {}); raise maxSteps (up to 1000000000) or lower maxCoordinate",
            Point::new(
                &run(r#"{"algorithm":"regions","count":1,"seed":3}"#)
                    .unwrap()
                    .lines[0]
                    .to
            ),
            limit.at_least
        );
        assert_eq!(e.message, expected);
    }

    #[test]
    fn splitmix64_matches_the_reference_sequence() {
        // First outputs for seed 1234567 of the reference C implementation
        // (Vigna, splitmix64.c), as used to seed xoshiro generators.
        let mut r = SplitMix64(1234567);
        assert_eq!(r.next(), 6457827717110365317);
        assert_eq!(r.next(), 3203168211198807973);
        assert_eq!(r.next(), 9817491932198370423);
    }

    #[test]
    fn same_seed_same_lines_and_errors_within_wang_s_bound() {
        let a = run(r#"{"algorithm":"regions","count":100,"seed":7}"#).unwrap();
        let b = run(r#"{"algorithm":"regions","count":100,"seed":7}"#).unwrap();
        assert_eq!(a, b);
        assert_eq!(a.lines.len(), 100);
        assert!(
            a.lines
                .iter()
                .all(|l| l.to.iter().all(|&c| (0..=100).contains(&c)))
        );
        // Section 3.2: no error exceeds sqrt(2)/2, by either measure.
        assert!(a.perpendicular.max.max <= std::f64::consts::FRAC_1_SQRT_2);
        assert!(a.axis_error.max.max <= std::f64::consts::FRAC_1_SQRT_2 + 1e-12);
        // The perpendicular distance never exceeds the error at equal progress.
        for l in &a.lines {
            assert!(l.perpendicular.max <= l.axis_error.max + 1e-12);
        }
        let c = run(r#"{"algorithm":"regions","count":100,"seed":8}"#).unwrap();
        assert_ne!(a.lines, c.lines);
    }

    #[test]
    fn seed_1_reproduces_figure_9_except_its_erratum() {
        // The claim PAPER_FIGURE_9_ERRATUM makes, checked.
        let r = run(r#"{"algorithm":"regions","count":100,"seed":1}"#).unwrap();
        let (ours, paper) = (r.axis_error, PAPER_FIGURE_9);
        for (a, b) in [
            (ours.max.max, paper.max.max),
            (ours.max.mean, paper.max.mean),
            (ours.mean.max, paper.mean.max),
            (ours.mean.min, paper.mean.min),
            (ours.mean.mean, paper.mean.mean),
            (ours.std.max, paper.std.max),
            (ours.std.min, paper.std.min),
            (ours.std.mean, paper.std.mean),
        ] {
            assert!((a - b).abs() < 0.02, "{a} vs {b}");
        }
        assert!((ours.max.min - 0.4472).abs() < 1e-4);
        // The perpendicular distance is smaller: Figure 9 is not about it.
        assert!(r.perpendicular.mean.mean < paper.mean.mean - 0.04);
    }

    #[test]
    fn a_run_in_slices_gives_the_whole_run_s_result() {
        let json = r#"{"algorithm":"bresenham3d","count":37,"seed":5,"maxCoordinate":50}"#;
        let whole = run(json).unwrap();
        for slice in [1, 2, 7, 36, 37, 100] {
            let mut sliced = RandomLinesRun::new(&Request::from_json(json).unwrap()).unwrap();
            assert_eq!(sliced.advance(0).unwrap().lines_done, 0);
            let mut reports = 0;
            loop {
                let progress = sliced.advance(slice).unwrap();
                reports += 1;
                assert_eq!(progress.lines, 37);
                assert_eq!(progress.lines_done, (reports * slice).min(37));
                let steps: u64 = whole.lines[..progress.lines_done as usize]
                    .iter()
                    .map(|l| l.steps)
                    .sum();
                assert_eq!(progress.steps, steps);
                if progress.done {
                    break;
                }
            }
            assert_eq!(reports, 37_u32.div_ceil(slice));
            assert_eq!(sliced.finish(), whole, "slices of {slice} lines");
        }
    }

    #[test]
    fn an_option_the_algorithm_refuses_is_refused_at_the_first_line() {
        let mut run = RandomLinesRun::new(
            &Request::from_json(r#"{"algorithm":"regions","count":5,"tie":"sideways"}"#).unwrap(),
        )
        .unwrap();
        let error = run.advance(1).unwrap_err();
        assert_eq!(
            error.location,
            crate::error::Location::Field("tie".into()),
            "{error:?}"
        );
    }

    #[test]
    fn an_option_nothing_takes_is_refused_naming_what_the_experiment_takes() {
        // The line algorithm's own refusal listed from and to (which the
        // experiment refuses) and not count, seed, maxCoordinate or dims.
        let error = RandomLinesRun::new(
            &Request::from_json(r#"{"algorithm":"regions","cuont":5}"#).unwrap(),
        )
        .err()
        .unwrap();
        assert_eq!(
            error.to_string(),
            "cuont: random-lines with regions does not take this option (it takes count, seed, maxCoordinate, dims, tie, gcd, maxSteps)"
        );
    }

    #[test]
    fn summary_is_the_spread_of_the_per_line_statistics() {
        let r = run(r#"{"algorithm":"regions","count":20,"seed":3}"#).unwrap();
        let means: Vec<f64> = r.lines.iter().map(|l| l.axis_error.mean).collect();
        assert_eq!(
            r.axis_error.mean.max,
            means.iter().copied().fold(f64::MIN, f64::max)
        );
        assert_eq!(
            r.axis_error.mean.min,
            means.iter().copied().fold(f64::MAX, f64::min)
        );
        assert!((r.axis_error.mean.mean - means.iter().sum::<f64>() / 20.0).abs() < 1e-15);
    }

    #[test]
    fn options_are_checked_and_passed_through() {
        assert_eq!(
            run(r#"{"algorithm":"regions","count":0}"#)
                .unwrap_err()
                .to_string(),
            "count: must be 1 to 100000, got 0"
        );
        // maxCoordinate's range, as its doc and the README state it.
        for (max, ok) in [(0, false), (1, true), (10_000, true), (10_001, false)] {
            let result = run(&format!(
                r#"{{"algorithm":"regions","count":2,"maxCoordinate":{max}}}"#
            ));
            assert_eq!(result.is_ok(), ok, "{max}");
            if let Err(e) = result {
                assert_eq!(
                    e.to_string(),
                    format!("maxCoordinate: must be 1 to 10000, got {max}")
                );
            }
        }
        assert_eq!(
            run(r#"{"algorithm":"regions","dims":2}"#)
                .unwrap_err()
                .to_string(),
            "dims: regions takes 3 axes, got 2"
        );
        assert_eq!(
            run(r#"{"algorithm":"nd","dims":7}"#)
                .unwrap_err()
                .to_string(),
            "dims: nd takes 2 to 6 axes, got 7"
        );
        // The experiment draws the ends: a from or to given was overwritten.
        for end in ["from", "to"] {
            let e = run(&format!(r#"{{"algorithm":"regions","{end}":[1,1,1]}}"#)).unwrap_err();
            assert_eq!(e.field_name(), Some(end));
        }
        assert_eq!(
            run(r#"{"algorithm":"circle"}"#).unwrap_err().to_string(),
            "algorithm: random-lines traces lines; circle traces arcs"
        );
        // Unknown options reach the algorithm, which names them.
        assert_eq!(
            run(r#"{"algorithm":"regions","center":1}"#)
                .unwrap_err()
                .field_name(),
            Some("center")
        );
        // Options reach every line: each is measured as a trace of it with
        // the same option measures it, and the option changes them (liu-float
        // rounds its float error term to `decimals` places; a tie option
        // would not show: a tie's two cells are equally far off the line).
        let options = |decimals: u32| {
            format!(r#"{{"algorithm":"liu-float","count":100,"seed":1,"decimals":{decimals}}}"#)
        };
        let coarse = run(&options(0)).unwrap();
        let fine = run(&options(6)).unwrap();
        assert_eq!(
            coarse.lines.iter().map(|l| &l.to).collect::<Vec<_>>(),
            fine.lines.iter().map(|l| &l.to).collect::<Vec<_>>()
        );
        for (result, decimals) in [(&coarse, 0), (&fine, 6)] {
            for line in &result.lines {
                let t = crate::algorithms::trace_json(&format!(
                    r#"{{"algorithm":"liu-float","from":[0,0,0],"to":{:?},"decimals":{decimals}}}"#,
                    line.to
                ))
                .unwrap();
                let metrics = t.metrics();
                let case = format!("{:?} at {decimals} decimals", line.to);
                assert_eq!(line.steps, t.steps(), "{case}");
                assert_eq!(line.perpendicular.max, metrics.max_deviation, "{case}");
                // Summed in another order: equal to the last bits or so.
                let mean_gap = (line.perpendicular.mean - metrics.mean_deviation).abs();
                assert!(mean_gap < 1e-12, "{case}");
            }
        }
        let changed = coarse
            .lines
            .iter()
            .zip(&fine.lines)
            .filter(|(c, f)| (c.perpendicular.mean - f.perpendicular.mean).abs() > 1e-9)
            .count();
        assert!(changed > 50, "decimals changed {changed} of 100 lines");
    }
}
