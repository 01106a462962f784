//! Fuzzing every entry point that `wasm.rs` calls, on stable Rust, with
//! proptest as the engine: random and mutated trace requests (drawn from the
//! catalogue's own option declarations, so a new algorithm or option is
//! fuzzed without an edit here), comparisons, Wang's random-lines
//! experiment, and G-code programs with their machine settings.
//!
//! Every call must return, never panic (overflow checks are on: the test
//! profile has them, and `npm run fuzz` uses the `fuzz` profile, which is
//! release with overflow checks and debug assertions). On every success the
//! documented invariants are checked:
//! - a trace starts on its `from`, and a line ends exactly on its `to`;
//! - it has steps + 1 points, each step moving each axis by at most one
//!   unit and some axis by one, and its step count within `maxSteps`;
//! - its summary, deviations and metrics are finite numbers;
//! - every reason can be read (`explain`, a point's `step_detail`), and the
//!   decision rows are full;
//! - a program's diagnostics name lines inside the program, its step
//!   instants never go back in time, and its steps are its trace's.
//!
//! `VOXPATH_FUZZ_CASES` sets the number of cases per target (10,000 by
//! default, which `npm test` runs: about 2 s); `npm run fuzz` runs 5,000,000
//! per target, 10,000,000 in all.
use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
use serde_json::{Map, Value, json};
use voxpath::algorithms::ALGORITHMS;
use voxpath::experiment::EXPERIMENTS;
use voxpath::gcode::{Runner, Settings};
use voxpath::request::{OptionKind, OptionSpec};
use voxpath::{Request, Trace};

/// Largest |coordinate| a request may use.
const COORDINATE_LIMIT: i64 = 1 << 30;
/// Steps any one case may take: keeps each case quick; larger requests are refused, which is fuzzed too.
const CASE_MAX_STEPS: u64 = 20_000;

fn cases() -> u32 {
    std::env::var("VOXPATH_FUZZ_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(10_000)
}

/// A runner with a fixed seed, so that `npm test` runs the same cases every time.
fn runner(seed: u8) -> TestRunner {
    let config = Config {
        cases: cases(),
        failure_persistence: None,
        ..Config::default()
    };
    TestRunner::new_with_rng(
        config,
        TestRng::from_seed(RngAlgorithm::ChaCha, &[seed; 32]),
    )
}

/// Where a request's points lie: near the origin mostly, else against the
/// ±2^30 edge (every point of the request near the same corner, so that
/// the move stays short), else anywhere an integer can be.
fn base() -> impl Strategy<Value = i64> {
    prop_oneof![
        16 => Just(0i64),
        2 => Just(COORDINATE_LIMIT - 40),
        2 => Just(-COORDINATE_LIMIT + 40),
        1 => prop_oneof![Just(i64::MAX / 2), Just(i64::MIN / 2), Just(i32::MAX as i64 - 20), any::<i64>().prop_map(|v| v / 2)],
    ]
}

/// A point of `dims` coordinates around `base`.
fn point(base: i64, dims: usize) -> impl Strategy<Value = Value> {
    prop::collection::vec(-45i64..45, dims)
        .prop_map(move |offsets| json!(offsets.iter().map(|o| base + o).collect::<Vec<_>>()))
}

/// Any JSON value a careless caller might send where an option goes.
fn junk() -> impl Strategy<Value = Value> {
    prop_oneof![
        Just(Value::Null),
        any::<bool>().prop_map(Value::from),
        any::<f64>()
            .prop_map(|f| serde_json::Number::from_f64(f).map_or(Value::Null, Value::Number)),
        any::<i64>().prop_map(Value::from),
        "[a-z0-9 ,.\\-]{0,12}".prop_map(Value::from),
        prop::collection::vec(any::<i64>(), 0..5).prop_map(|v| json!(v)),
    ]
}

/// A value for `option`: mostly of its declared kind (so the algorithm
/// runs), sometimes junk (so the checks run).
fn option_value(option: &'static OptionSpec, dims: usize, base: i64) -> BoxedStrategy<Value> {
    let valid: BoxedStrategy<Value> = match option.kind {
        OptionKind::Point(_) => point(base, dims).boxed(),
        OptionKind::Number(_) => prop_oneof![
            4 => (-1e3f64..1e3).prop_map(Value::from),
            1 => any::<f64>().prop_map(|f| serde_json::Number::from_f64(f).map_or(Value::Null, Value::Number)),
            1 => prop_oneof![Just(0.0), Just(1e-300), Just(1e300), Just(-0.0)].prop_map(Value::from),
        ]
        .boxed(),
        OptionKind::Integer(_) => prop_oneof![
            4 => (0i64..(CASE_MAX_STEPS as i64 * 2)).prop_map(Value::from),
            1 => any::<i64>().prop_map(Value::from),
        ]
        .boxed(),
        OptionKind::Choice { values } => prop::sample::select(values).prop_map(Value::from).boxed(),
        OptionKind::Boolean => any::<bool>().prop_map(Value::from).boxed(),
        // A machine setting: one number for every axis, or one per axis.
        OptionKind::PerAxis(_) => prop_oneof![
            (0.001f64..1e3).prop_map(Value::from),
            prop::collection::vec(0.001f64..1e3, 3).prop_map(Value::from),
        ]
        .boxed(),
    };
    prop_oneof![40 => valid, 1 => junk()].boxed()
}

/// A request for one catalogue algorithm: each declared option present or
/// not, plus now and then an option nobody declared.
fn algorithm_request() -> impl Strategy<Value = Map<String, Value>> {
    (
        0..ALGORITHMS.len(),
        1usize..=6,
        prop::bool::weighted(0.03),
        base(),
    )
        .prop_flat_map(|(index, dims_guess, stranger, base)| {
            let info = ALGORITHMS[index];
            // Mostly a dimension the algorithm takes, sometimes one it does not.
            let dims = if dims_guess <= 5 {
                dims_guess.clamp(info.min_dims, info.max_dims)
            } else {
                dims_guess
            };
            let options: Vec<_> = info
                .options
                .iter()
                .map(|o| {
                    let required = o.required;
                    prop::option::weighted(
                        if required { 0.99 } else { 0.5 },
                        option_value(o, dims, base),
                    )
                    .prop_map(move |v| (o.name, v))
                })
                .collect();
            (options, prop::option::of(junk()), prop::bool::weighted(0.2)).prop_map(
                move |(chosen, extra, closed)| {
                    let mut map = Map::new();
                    map.insert("algorithm".into(), Value::from(info.id));
                    for (name, value) in chosen {
                        if let Some(value) = value {
                            map.insert(name.into(), value);
                        }
                    }
                    // A move to where it starts: a line of no steps, a full circle.
                    if let (true, Some(from)) = (closed, map.get("from").cloned()) {
                        map.insert("to".into(), from);
                    }
                    // maxSteps kept small unless the case chose it; a too-long move is then refused.
                    map.entry("maxSteps").or_insert(Value::from(CASE_MAX_STEPS));
                    if let (true, Some(extra)) = (stranger, extra) {
                        map.insert("notAnOption".into(), extra);
                    }
                    map
                },
            )
        })
}

fn assert_finite(what: &str, values: &[f64]) {
    assert!(
        values.iter().all(|v| v.is_finite()),
        "{what} has a value that is not finite: {values:?}"
    );
}

/// The documented invariants of a trace returned for `request`.
fn check_trace(trace: &Trace, request: &Map<String, Value>) {
    let steps = trace.steps();
    let dims = trace.dims();
    if let Some(Value::Number(max)) = request.get("maxSteps") {
        if let Some(max) = max.as_u64() {
            assert!(steps <= max, "{steps} steps past maxSteps {max}");
        }
    }
    let points = trace.points_flat(0, steps + 1);
    assert_eq!(points.len() as u64, (steps + 1) * dims as u64);
    if let Some(from) = request.get("from").and_then(Value::as_array) {
        let from: Vec<i64> = from.iter().filter_map(Value::as_i64).collect();
        assert_eq!(&points[..dims], &from[..], "does not start on from");
    }
    for pair in points.chunks(dims).collect::<Vec<_>>().windows(2) {
        let moved: Vec<i64> = pair[0].iter().zip(pair[1]).map(|(a, b)| b - a).collect();
        assert!(
            moved.iter().all(|d| d.abs() <= 1) && moved.iter().any(|d| *d != 0),
            "a step of {moved:?}"
        );
    }
    for point in points.chunks(dims) {
        assert!(
            point.iter().all(|c| c.abs() <= COORDINATE_LIMIT),
            "a point past ±2^30: {point:?}"
        );
    }
    let metrics = trace.metrics();
    assert_finite(
        "metrics",
        &[
            metrics.max_deviation,
            metrics.mean_deviation,
            metrics.std_deviation,
        ],
    );
    assert_finite("max axis error", &metrics.max_axis_error);
    assert_finite("deviation", &trace.deviation_range(0, steps + 1));
    assert_eq!(
        trace.decisions_flat(0, steps).len() as u64,
        steps * trace.columns().len() as u64
    );
    serde_json::to_string(&trace.summary()).expect("the summary serializes");
    assert_finite("ideal polyline", &trace.ideal_polyline());
    for k in [0, steps / 2, steps.saturating_sub(1)] {
        if k < steps {
            assert!(!trace.explain(k).is_empty());
        }
    }
    // A point's detail replays its step (figure included) and serializes;
    // its picture is one of those the trace lists.
    for p in [0, 1.min(steps), steps / 2, steps] {
        let detail = voxpath::step_detail::step_detail(trace, p);
        if let Some(figure) = &detail.figure {
            assert!(trace.figures().contains(&figure.kind()));
        }
        // None only where no segment measures it (a program with no move).
        assert_eq!(detail.deviation.is_some(), (trace.segment_count() > 0));
        assert_finite(
            "a point's deviation",
            &detail.deviation.into_iter().collect::<Vec<_>>(),
        );
        serde_json::to_string(&detail).expect("a step's detail serializes");
    }
    let rows = trace.chart_rows(0, steps + 1, 100);
    let count = rows.len() / (3 + 2 * dims);
    assert_eq!(rows.len(), count * (3 + 2 * dims));
    // The point indices and positions; the ideal and deviations where a segment measures them.
    let measured = if trace.segment_count() == 0 {
        1 + dims
    } else {
        3 + 2 * dims
    };
    assert_finite("chart rows", &rows[..count * measured]);
}

/// Of `tried` cases, at least a twentieth must have been `checked`: the
/// invariants hold only of what runs, and a change that refused every
/// request would otherwise pass. (On the fixed seeds: 4,611 of 10,000 trace
/// requests, 1,144 comparisons, 6,771 G-code programs.)
fn assert_enough_checked(what: &str, checked: u32, tried: u32) {
    assert!(
        checked * 20 >= tried,
        "only {checked} of {tried} {what} ran far enough to be checked"
    );
}

#[test]
fn trace_requests_never_panic_and_keep_their_invariants() {
    let traced = std::cell::Cell::new(0u32);
    runner(1)
        .run(&algorithm_request(), |request| {
            let text = Value::Object(request.clone()).to_string();
            if let Ok(trace) = voxpath::trace_json(&text) {
                traced.set(traced.get() + 1);
                check_trace(&trace, &request);
                // Lines end exactly on `to` (an arc ends there too, a full circle included).
                if let Some(to) = request.get("to").and_then(Value::as_array) {
                    let to: Vec<i64> = to.iter().filter_map(Value::as_i64).collect();
                    assert_eq!(trace.end().coords(), &to[..], "does not end on to");
                }
            }
            Ok(())
        })
        .unwrap();
    assert_enough_checked("trace requests", traced.get(), cases());
}

#[test]
fn comparisons_and_experiments_never_panic() {
    let pair = (
        algorithm_request(),
        0..ALGORITHMS.len(),
        prop::option::of(junk()),
    );
    let (compared, experimented) = (std::cell::Cell::new(0u32), std::cell::Cell::new(0u32));
    runner(2)
        .run(&pair, |(mut request, other, junk)| {
            // The experiment takes the request as a trace does, algorithm
            // included, less the ends (it draws every line's own) and with
            // options of its own.
            let mut experiment_request = request.clone();
            experiment_request.remove("from");
            experiment_request.remove("to");
            let first = request.remove("algorithm").unwrap();
            request.insert(
                "algorithms".into(),
                junk.unwrap_or_else(|| json!([first, ALGORITHMS[other].id])),
            );
            let text = Value::Object(request.clone()).to_string();
            if let Ok(comparison) = voxpath::compare::compare_request(&text) {
                serde_json::to_string(&comparison).expect("the comparison serializes");
                compared.set(compared.get() + 1);
            }
            let experiment = &EXPERIMENTS[0];
            for option in experiment.options {
                if matches!(option.kind, OptionKind::Integer(_)) {
                    let value = experiment_request.len() as u64 % 50;
                    experiment_request.insert(option.name.into(), Value::from(value));
                }
            }
            let text = Value::Object(experiment_request).to_string();
            if let Ok(request) = Request::from_json(&text) {
                if let Ok(result) = voxpath::experiment::random_lines(&request) {
                    serde_json::to_string(&result).expect("the experiment serializes");
                    experimented.set(experimented.get() + 1);
                }
            }
            Ok(())
        })
        .unwrap();
    assert_enough_checked("comparisons", compared.get(), cases());
    assert_enough_checked("experiments", experimented.get(), cases());
}

/// A number as a careless or hostile program might write it.
fn gcode_number() -> impl Strategy<Value = String> {
    prop_oneof![
        6 => (-60.0f64..60.0).prop_map(|f| format!("{f:.3}")),
        2 => (-5i32..5).prop_map(|n| n.to_string()),
        1 => any::<u64>().prop_map(|n| n.to_string()),
        1 => prop::sample::select(&["1e300", "4294967296", "2147483649", "99999999999999999999999", "-", "", "1.2.3", ".", "-.5", "0x10", "+3"][..]).prop_map(String::from),
    ]
}

/// One G-code line: a motion or modal code, axis and arc words, a feed; now
/// and then a stranger word, a comment or bytes of any kind.
fn gcode_line() -> impl Strategy<Value = String> {
    let code = prop::sample::select(
        &[
            "G0",
            "G1",
            "G2",
            "G3",
            "G17",
            "G18",
            "G19",
            "G20",
            "G21",
            "G90",
            "G91",
            "G93",
            "G94",
            "M2",
            "M30",
            "G4",
            "G28",
            "G2147483649",
            "M1000000000",
            "g1",
            "G1.5",
            "N10 G1",
            "",
        ][..],
    );
    let axis = (
        prop::sample::select(&['X', 'Y', 'Z', 'I', 'J', 'K', 'R', 'P', 'F', 'S', 'Q'][..]),
        gcode_number(),
    )
        .prop_map(|(l, n)| format!("{l}{n}"));
    let odd = prop_oneof![
        Just(String::new()),
        "\\([^)\n]{0,10}\\)".prop_map(String::from),
        "; [a-z ]{0,8}".prop_map(String::from),
        "[\\x00-\\x7f]{0,4}".prop_map(String::from),
        any::<String>().prop_map(|s| s.chars().take(4).collect()),
    ];
    (
        code,
        prop::collection::vec(axis, 0..5),
        prop::option::weighted(0.08, odd),
    )
        .prop_map(|(code, words, odd)| {
            format!("{code} {}{}", words.join(" "), odd.unwrap_or_default())
        })
}

fn program() -> impl Strategy<Value = String> {
    let ending = prop::sample::select(&["\n", "\n", "\n", "\r\n", "\r"][..]);
    (
        prop::bool::weighted(0.8),
        prop::collection::vec((gcode_line(), ending), 0..12),
    )
        .prop_map(|(feed, lines)| {
            let first = if feed { "G21 G90 F600\n" } else { "" };
            first.to_string()
                + &lines
                    .into_iter()
                    .map(|(l, e)| format!("{l}{e}"))
                    .collect::<String>()
        })
}

fn settings() -> impl Strategy<Value = Value> {
    let steps_per_mm = prop_oneof![
        4 => (0.5f64..20.0).prop_map(Value::from),
        1 => prop::collection::vec(0.5f64..20.0, 3).prop_map(|v| json!(v)),
        1 => junk(),
    ];
    (
        steps_per_mm,
        prop::option::of(prop::sample::select(
            &["circle", "arc-segments", "helix"][..],
        )),
        prop::option::weighted(0.05, junk()),
    )
        .prop_map(|(steps, arc, extra)| {
            let mut map = json!({ "stepsPerMm": steps, "maxSteps": CASE_MAX_STEPS });
            if let Some(arc) = arc {
                map["arcAlgorithm"] = Value::from(arc);
            }
            if let Some(extra) = extra {
                map["acceleration"] = extra;
            }
            map
        })
}

#[test]
fn gcode_programs_never_panic_and_keep_their_invariants() {
    let ran = std::cell::Cell::new(0u32);
    runner(3)
        .run(&(program(), settings()), |(source, settings)| {
            let Ok(settings) = Settings::from_json(&settings.to_string()) else {
                return Ok(());
            };
            ran.set(ran.get() + 1);
            let lines = source.split_inclusive(['\n', '\r']).count().max(1) as u32 + 1;
            let mut runner = Runner::new(source, settings);
            // Small slices, as the page's worker takes them.
            while !runner.advance(3).done {}
            let program = runner.finish();
            let info = &program.info;
            for diagnostic in info.warnings.iter().chain(&info.errors) {
                assert!(
                    diagnostic.line >= 1 && diagnostic.line <= lines,
                    "{diagnostic:?} outside {lines} lines"
                );
                assert!(!diagnostic.message.is_empty());
            }
            assert_eq!(info.steps, program.trace.steps());
            assert!(info.steps <= CASE_MAX_STEPS);
            assert!(
                info.duration_seconds.is_finite() && info.duration_seconds >= 0.0,
                "{}",
                info.duration_seconds
            );
            let times = program.timeline.step_seconds(0, info.steps);
            assert_finite("step times", &times);
            assert!(
                times.windows(2).all(|w| w[0] <= w[1]),
                "step instants go back in time"
            );
            assert_finite("speed profile", &program.timeline.speed_profile());
            // The page's chart rows: bounded, finite, and the buckets keep
            // the corners' extremes.
            let spm = info.steps_per_mm;
            let end = info.duration_seconds.max(1e-9);
            let corners = program
                .timeline
                .motion_chart(&spm, 0.0, end, 100_000)
                .unwrap();
            let buckets = program.timeline.motion_chart(&spm, 0.0, end, 3).unwrap();
            assert!(buckets.seconds.len() <= 3);
            let top = |c: &voxpath::gcode::motion_chart::MotionChart| {
                c.speed_max.iter().flatten().fold(0.0f64, |m, &v| m.max(v))
            };
            assert_finite("chart times", &corners.seconds);
            assert!((top(&corners) - top(&buckets)).abs() <= 1e-9 * (1.0 + top(&corners)));
            let reached = program.timeline.points_reached_at(end);
            assert_eq!(reached, info.steps, "every step is taken by the end");
            serde_json::to_string(info).expect("the program serializes");
            check_trace(&program.trace, &Map::new());
            Ok(())
        })
        .unwrap();
    assert_enough_checked("G-code programs", ran.get(), cases());
}
