//! The list of every algorithm voxpath runs, and the lookup by id. What an
//! entry holds is declared in the leaf module `algorithm_info`, which the
//! algorithms import; only this module imports the algorithms.

pub use crate::algorithm_info::{AlgorithmInfo, Family};
use crate::error::Error;
use crate::lazy_trace::LazyTrace;
use crate::request::Request;
use crate::trace::Trace;

/// Every algorithm, in the order the page lists them.
pub const ALGORITHMS: &[&AlgorithmInfo] = &[
    &crate::line::regions_wang::INFO,
    &crate::line::bresenham2d::INFO,
    &crate::line::bresenham3d::INFO,
    &crate::line::nd::INFO,
    &crate::line::liu_float::INFO,
    &crate::line::greedy::INFO,
    &crate::line::walk6::INFO,
    &crate::line::dda::INFO,
    &crate::arc::circle_saleem::INFO,
    &crate::arc::arc_segments::INFO,
    &crate::arc::helix::INFO,
];

/// The TypeScript type of an algorithm id, for the package's .d.ts
/// (`wasm::ALGORITHM_ID_TYPE`): the union of every id of [`ALGORITHMS`],
/// spelled from the list at compile time, so that a request's, a
/// summary's or a catalogue entry's `algorithm` is checked by the
/// TypeScript compiler against the ids the core runs, with no second list.
pub const ALGORITHM_ID_TS: &str = match std::str::from_utf8(&ALGORITHM_ID_TS_BYTES) {
    Ok(text) => text,
    Err(_) => panic!("algorithm ids are UTF-8"),
};

const ALGORITHM_ID_TS_HEAD: &str = "/** The id of an algorithm of the catalogue, as a request names it. */\nexport type AlgorithmId = ";
const ALGORITHM_ID_TS_TAIL: &str = ";\n";
const ALGORITHM_ID_TS_BETWEEN: &str = " | ";

/// [`ALGORITHM_ID_TS`]'s bytes: the head, each id in double quotes with
/// [`ALGORITHM_ID_TS_BETWEEN`] between them, the tail.
const ALGORITHM_ID_TS_BYTES: [u8; algorithm_id_ts(&mut [])] = {
    let mut bytes = [0; algorithm_id_ts(&mut [])];
    algorithm_id_ts(&mut bytes);
    bytes
};

/// Writes [`ALGORITHM_ID_TS`] into `out` when it is long enough (else
/// only counts), and returns its length: one const function for both, so
/// the length and the text cannot disagree.
const fn algorithm_id_ts(out: &mut [u8]) -> usize {
    let mut len = append(out, 0, ALGORITHM_ID_TS_HEAD);
    let mut i = 0;
    while i < ALGORITHMS.len() {
        if i > 0 {
            len = append(out, len, ALGORITHM_ID_TS_BETWEEN);
        }
        len = append(out, len, "\"");
        len = append(out, len, ALGORITHMS[i].id);
        len = append(out, len, "\"");
        i += 1;
    }
    append(out, len, ALGORITHM_ID_TS_TAIL)
}

/// Copies `text` into `out` at `at` when it fits (counting only, for an
/// `out` too short), and returns where it ends.
const fn append(out: &mut [u8], at: usize, text: &str) -> usize {
    let bytes = text.as_bytes();
    if at + bytes.len() <= out.len() {
        let mut i = 0;
        while i < bytes.len() {
            out[at + i] = bytes[i];
            i += 1;
        }
    }
    at + bytes.len()
}

/// The algorithm with this id, or an error listing the known ids. It is the
/// [`crate::algorithm_info::Find`] handed to every algorithm's `trace`.
pub fn find(id: &str) -> Result<&'static AlgorithmInfo, Error> {
    ALGORITHMS
        .iter()
        .copied()
        .find(|a| a.id == id)
        .ok_or_else(|| {
            let ids: Vec<&str> = ALGORITHMS.iter().map(|a| a.id).collect();
            Error::field(
                "algorithm",
                format!(
                    "unknown algorithm '{}' (known: {})",
                    crate::text::echo(id),
                    ids.join(", ")
                ),
            )
        })
}

/// Runs the request described by JSON text, e.g.
/// `{"algorithm": "regions", "from": [0,0,0], "to": [10,7,6]}`.
pub fn trace_json(request_json: &str) -> Result<Trace, Error> {
    run(&Request::from_json(request_json)?)
}

/// The request described by JSON text, planned where its algorithm plans
/// ([`crate::plan`]): recorded when something first needs its steps.
pub fn plan_json(request_json: &str) -> Result<LazyTrace, Error> {
    LazyTrace::new(Request::from_json(request_json)?, find)
}

/// Runs a parsed request with the algorithm it names.
pub fn run(request: &Request) -> Result<Trace, Error> {
    (find(&request.algorithm)?.trace)(request, find)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::arc::arc_segments::LINE_ALGORITHMS;

    #[test]
    fn ids_are_unique_and_every_column_kind_serializes() {
        for (i, a) in ALGORITHMS.iter().enumerate() {
            assert!(
                ALGORITHMS[i + 1..].iter().all(|b| b.id != a.id),
                "duplicate id {}",
                a.id
            );
            let json = serde_json::to_value(a).unwrap();
            assert_eq!(json["id"], a.id);
            assert_eq!(json["columns"].as_array().unwrap().len(), a.columns.len());
        }
    }

    #[test]
    fn every_example_traces() {
        for a in ALGORITHMS {
            let mut request: serde_json::Value = serde_json::from_str(a.example.options).unwrap();
            request["algorithm"] = a.id.into();
            let trace =
                trace_json(&request.to_string()).unwrap_or_else(|e| panic!("{}: {e}", a.id));
            assert!(trace.steps() > 0, "{}", a.id);
        }
    }

    #[test]
    fn every_option_s_condition_names_a_value_of_a_choice_of_its_algorithm() {
        let mut conditions = 0;
        for a in ALGORITHMS {
            for spec in a.options {
                let Some(condition) = spec.applies_with else {
                    continue;
                };
                conditions += 1;
                let governing = a.options.iter().find(|o| o.name == condition.option);
                let values = match governing.map(|o| o.kind) {
                    Some(crate::request::OptionKind::Choice { values }) => values,
                    _ => panic!(
                        "{}: {} applies with {}, not a choice of its own",
                        a.id, spec.name, condition.option
                    ),
                };
                assert!(values.contains(&condition.value), "{}: {}", a.id, spec.name);
            }
        }
        // The helix's three chord options.
        assert_eq!(conditions, 3);
    }

    #[test]
    fn every_algorithm_compared_with_itself_is_by_a_choice_of_two_values_or_more() {
        for a in ALGORITHMS {
            let Some(name) = a.compared_by else { continue };
            let spec = a.options.iter().find(|o| o.name == name);
            assert!(
                matches!(spec.map(|o| o.kind), Some(crate::request::OptionKind::Choice { values }) if values.len() >= 2),
                "{}: compared by {name}",
                a.id
            );
        }
        let compared: Vec<&str> = ALGORITHMS
            .iter()
            .filter(|a| a.compared_by.is_some())
            .map(|a| a.id)
            .collect();
        assert_eq!(compared, ["helix"]);
    }

    #[test]
    fn unknown_algorithm_lists_the_known_ones() {
        let e = find("bresenham9d").err().unwrap().to_string();
        assert!(
            e.starts_with("algorithm: unknown algorithm 'bresenham9d' (known: regions"),
            "{e}"
        );
        // A long name is quoted by its start (a 10 MB one was said back whole).
        let long = find(&"x".repeat(100)).err().unwrap().to_string();
        assert!(long.starts_with(&format!(
            "algorithm: unknown algorithm '{}... (100 characters)' (known: ",
            "x".repeat(16)
        )));
    }

    #[test]
    fn every_listed_line_algorithm_is_a_catalogue_line_and_no_line_is_missing() {
        for id in LINE_ALGORITHMS {
            let info = find(id).unwrap();
            assert!((info.min_dims..=info.max_dims).contains(&3), "{id}");
        }
        // Every 3-axis line algorithm of the catalogue can step a chord.
        for info in ALGORITHMS {
            let line_like =
                info.family == Family::Line && (info.min_dims..=info.max_dims).contains(&3);
            assert_eq!(
                line_like,
                LINE_ALGORITHMS.contains(&info.id),
                "{} should be listed in LINE_ALGORITHMS exactly when it is a 3-axis line algorithm",
                info.id
            );
        }
    }
}
