//! The WebAssembly boundary, and the only module that knows about JavaScript.
//!
//! Bulk data crosses as flat typed arrays, copied out of wasm memory once:
//! - points: Int32Array, stride = dims, one row per point index (made on the
//!   JS side and filled from wasm memory a chunk at a time); a learner's
//!   points as a check read them: Int32Array too, stride = dims;
//! - decisions: Float64Array, column-major, one run of (to - from) values per
//!   trace column, in the order of the summary's `columns` (where a column
//!   does not apply to a step: NaN, or `trace::NO_VALUE` in a category or
//!   flag column);
//! - deviation: Float64Array, one value per point index;
//! - axis error: Float64Array, stride = dims, one row per point index;
//! - chart rows: Float64Array, column-major (see `Trace::chart_rows`);
//! - step codes: Uint16Array, one packed step per step index (see `grid::Step`);
//! - direction levels: Uint8Array, one byte per step index, bit `axis` set
//!   while that axis's DIR line is at its negative level (see `machine`).
//!
//! Small data (summary, catalogue, comparisons, a program's record, a
//! point's `StepDetail`) crosses as plain objects: serialized by serde to
//! JSON text, parsed once by the engine's JSON.parse (faster than building
//! each property through the boundary). Each is a Rust type deriving `Tsify`, which writes its
//! TypeScript twin into the package's .d.ts, and each function names that
//! type as its return type (`unchecked_return_type`): the types the JS side
//! reads are the Rust types, declared once.
//! Errors are JS `Error` objects named `VoxpathError` with `field`, or
//! `line` and `column`, set, and `limit` (a `Limit`) when a cap was met.

use crate::error::{Error, Location};
use crate::lazy_trace::LazyTrace;
use crate::trace::Trace;
use serde::Serialize;
use wasm_bindgen::prelude::*;

/// A boundary value as the plain object its Tsify type describes.
fn to_js<T: Serialize + ?Sized>(value: &T) -> JsValue {
    let json = serde_json::to_string(value).expect("boundary types serialize");
    js_sys::JSON::parse(&json).expect("serde_json writes valid JSON")
}

/// An empty Vec with room for the `len` values a range read hands out, or,
/// when the core's memory has no room for them, an error naming `to`: the
/// allocation failing was a trap ("unreachable", naming nothing), as for
/// the instants of a 600,000,000-step program (4.8 GB, past the 4 GiB a
/// wasm memory holds).
fn room_for<T>(len: u64, what: impl FnOnce() -> String) -> Result<Vec<T>, JsValue> {
    let mut out = Vec::new();
    match usize::try_from(len).map(|n| out.try_reserve_exact(n)) {
        Ok(Ok(())) => Ok(out),
        _ => Err(to_js_error(&Error::field(
            "to",
            format!(
                "{} take {} bytes, more than the core's memory has room for: read them a range at a time",
                what(),
                len.saturating_mul(std::mem::size_of::<T>() as u64)
            ),
        ))),
    }
}

fn to_js_error(error: &Error) -> JsValue {
    let js = js_sys::Error::new(&error.to_string());
    js.set_name("VoxpathError");
    let set = |key: &str, value: JsValue| {
        let _ = js_sys::Reflect::set(&js, &JsValue::from_str(key), &value);
    };
    set("detail", JsValue::from_str(&error.message));
    if let Some(axis) = error.axis {
        set("axis", JsValue::from(axis as u32));
    }
    if let Some(limit) = &error.limit {
        set("limit", to_js(limit));
    }
    match &error.location {
        Location::Field(field) => set("field", JsValue::from_str(field)),
        Location::Source { line, column } => {
            set("line", JsValue::from(*line));
            set("column", JsValue::from(*column));
        }
    }
    js.into()
}

/// [`to_js_error`] for an error in the text argument `field` (a learner's
/// points): one at a line and column names the argument too, so that a
/// caller finds which argument is wrong by `field` whatever the error.
fn to_js_text_error(error: &Error, field: &str) -> JsValue {
    let js = to_js_error(error);
    if let Location::Source { .. } = error.location {
        let _ = js_sys::Reflect::set(&js, &JsValue::from_str("field"), &JsValue::from_str(field));
    }
    js
}

/// Runs one trace. `request_json` is `{"algorithm": id, ...options}`.
/// The union type of every algorithm id, which the tsify types name as
/// `AlgorithmId` (see [`crate::algorithms::ALGORITHM_ID_TS`]).
#[wasm_bindgen(typescript_custom_section)]
const ALGORITHM_ID_TYPE: &str = crate::algorithms::ALGORITHM_ID_TS;

#[wasm_bindgen]
pub fn trace(request_json: &str) -> Result<TraceHandle, JsValue> {
    crate::algorithms::plan_json(request_json)
        .map(TraceHandle)
        .map_err(|e| to_js_error(&e))
}

/// Bytes of heap the core holds now: what every trace, program and buffer
/// not yet freed retains (`crate::memory`).
#[wasm_bindgen(js_name = heapBytes)]
pub fn heap_bytes() -> f64 {
    crate::memory::held_bytes() as f64
}

/// Everything the core offers: algorithms, experiments and G-code settings
/// (see `catalogue::Catalogue`).
#[wasm_bindgen(unchecked_return_type = "Catalogue")]
pub fn catalogue() -> JsValue {
    to_js(&crate::catalogue::CATALOGUE)
}

/// The `random-lines` experiment being run a slice of lines at a time, so
/// that a worker can report progress and stop between slices.
#[wasm_bindgen]
pub struct RandomLinesRun(crate::experiment::RandomLinesRun);

#[wasm_bindgen]
impl RandomLinesRun {
    /// `request_json`: a `RandomLinesOptions` object as JSON text. A bad
    /// option throws, naming it.
    #[wasm_bindgen(constructor)]
    pub fn new(request_json: &str) -> Result<RandomLinesRun, JsValue> {
        crate::request::Request::from_json(request_json)
            .and_then(|r| crate::experiment::RandomLinesRun::new(&r))
            .map(RandomLinesRun)
            .map_err(|e| to_js_error(&e))
    }

    /// Traces up to `max_lines` more lines; returns how far the run has got.
    #[wasm_bindgen(unchecked_return_type = "ExperimentProgress")]
    pub fn advance(&mut self, max_lines: u32) -> Result<JsValue, JsValue> {
        let progress = self.0.advance(max_lines).map_err(|e| to_js_error(&e))?;
        Ok(to_js(&progress))
    }

    /// The result of the lines traced so far (all of them once `done`).
    #[wasm_bindgen(unchecked_return_type = "RandomLines")]
    pub fn finish(self) -> JsValue {
        to_js(&self.0.finish())
    }
}

/// Runs `{"algorithms": [a, b], ...shared options}` (see
/// `compare::compare_request`).
#[wasm_bindgen(unchecked_return_type = "Comparison")]
pub fn compare(request_json: &str) -> Result<JsValue, JsValue> {
    let result = crate::compare::compare_request(request_json).map_err(|e| to_js_error(&e))?;
    Ok(to_js(&result))
}

/// Text as UTF-8 bytes, as the JS side's `TextEncoder` writes them: a
/// Uint8Array crosses the boundary by one copy, where a JS string would be
/// re-encoded a character at a time (a 20 MB CSV took longer to arrive
/// than to read).
fn utf8<'a>(field: &'static str, bytes: &'a [u8]) -> Result<&'a str, JsValue> {
    std::str::from_utf8(bytes).map_err(|e| not_utf8(field, bytes, e))
}

/// The error for text in `field` that is not UTF-8, at the line and column
/// of its first byte that is not (a caller may hand over a file's bytes),
/// counted as the readers of the text count them.
fn not_utf8(field: &'static str, bytes: &[u8], e: std::str::Utf8Error) -> JsValue {
    let before = std::str::from_utf8(&bytes[..e.valid_up_to()]).expect("valid up to there");
    let (line, column) = crate::text::line_and_column(before);
    // No "decode it to a string first": the command line hands a file's
    // bytes here too, and its user has no string to make (the README tells
    // a JavaScript caller so).
    let message = format!("not UTF-8 text ({e}): save it as UTF-8");
    let at = |n: usize| u32::try_from(n).unwrap_or(u32::MAX);
    to_js_text_error(&Error::at(at(line), at(column), message), field)
}

/// Text for the core as UTF-8 bytes in wasm memory, written there by the
/// caller (`TextEncoder.encodeInto` on [`TextBytes::view`]): a 20 MB text
/// crosses once, with no JavaScript array of its bytes made and copied in.
#[wasm_bindgen]
pub struct TextBytes(Vec<u8>);

#[wasm_bindgen]
impl TextBytes {
    /// Room for `capacity` bytes.
    #[wasm_bindgen(constructor)]
    pub fn new(capacity: u32) -> TextBytes {
        TextBytes(vec![0; capacity as usize])
    }

    /// The bytes as a view into wasm memory, for the caller to write at
    /// once: a view is detached when wasm memory grows, which any call into
    /// the core may do.
    pub fn view(&mut self) -> js_sys::Uint8Array {
        // SAFETY: the view covers this Vec's own initialised bytes, which
        // stay where they are until it is truncated or freed; the caller
        // writes it before its next call into the core (see above).
        unsafe { js_sys::Uint8Array::view_mut_raw(self.0.as_mut_ptr(), self.0.len()) }
    }

    /// Keeps the first `len` bytes, the ones written.
    pub fn truncate(&mut self, len: u32) {
        self.0.truncate(len as usize);
    }
}

/// A learner's points checked against a request's rule a slice at a time
/// (`check::SlicedCheck`: points given as text read a slice at a time
/// first), so that a worker can report the check and stop it between
/// slices; `advance(Infinity)` makes the whole check in one call.
#[wasm_bindgen]
pub struct CheckRun(crate::check::SlicedCheck);

#[wasm_bindgen]
impl CheckRun {
    /// A check of points given as text (CSV, blank-separated rows or a
    /// printed list, read here and nowhere else): the rule is traced in
    /// this call, the text read by `advance`, whose errors give the line
    /// and column. The bytes are taken, not copied (the TextBytes is left
    /// empty): the page's 19 MB of points were in wasm memory twice.
    #[wasm_bindgen(js_name = fromText)]
    pub fn from_text(request_json: &str, text: &mut TextBytes) -> Result<CheckRun, JsValue> {
        let mut bytes = std::mem::take(&mut text.0);
        // A text of other than ASCII was given room for 3 bytes a character.
        bytes.shrink_to_fit();
        let text = String::from_utf8(bytes)
            .map_err(|e| not_utf8("points", e.as_bytes(), e.utf8_error()))?;
        crate::check::SlicedCheck::from_text(request_json, text)
            .map(CheckRun)
            .map_err(|e| to_js_error(&e))
    }

    /// A check of points given as a flat Int32Array / Float64Array with
    /// `dims` values per point.
    #[wasm_bindgen(js_name = fromPoints)]
    pub fn from_points(
        request_json: &str,
        #[wasm_bindgen(unchecked_param_type = "Int32Array | Float64Array")] points: JsValue,
        dims: Option<u32>,
    ) -> Result<CheckRun, JsValue> {
        let dims = || {
            dims.map(|d| d as usize).ok_or_else(|| {
                to_js_error(&Error::field(
                    "dims",
                    "missing: give the coordinates per point",
                ))
            })
        };
        // Each array copied into wasm memory as it is: an Int32Array's
        // values are coordinates already.
        let check = if let Some(ints) = points.dyn_ref::<js_sys::Int32Array>() {
            crate::check::SlicedCheck::from_flat(request_json, &ints.to_vec(), dims()?)
        } else if let Some(floats) = points.dyn_ref::<js_sys::Float64Array>() {
            crate::check::SlicedCheck::from_flat(request_json, &floats.to_vec(), dims()?)
        } else {
            return Err(to_js_error(&Error::field(
                "points",
                "expected an Int32Array or a Float64Array",
            )));
        };
        check.map(CheckRun).map_err(|e| to_js_error(&e))
    }

    /// Takes the check on by about `units` points' worth of work
    /// (`SlicedCheck::advance`: rows of text read, steps compared, then
    /// option combinations traced, each counted as the points); Infinity
    /// runs it to its end. An error in the text gives its line and column.
    #[wasm_bindgen(unchecked_return_type = "CheckProgress")]
    pub fn advance(&mut self, units: f64) -> Result<JsValue, JsValue> {
        // `as` saturates: Infinity is u64::MAX, a negative or NaN 0 (one
        // row, step or combination, the least a call makes).
        self.0
            .advance(units as u64)
            .map(|progress| to_js(&progress))
            .map_err(|e| to_js_text_error(&e, "points"))
    }

    /// The points as read (flat, `dims` values a point), once the reading
    /// is over: for a view that draws them, the text read once. An
    /// Int32Array, as a trace's points cross (half the bytes of doubles,
    /// 18 MB at the page's cap, and drawn as they are); undefined when a
    /// coordinate does not fit one. The reader takes whole numbers up to
    /// 2^53, and the check says where such points leave the rule's path,
    /// whose grid points are within ±2^30.
    #[wasm_bindgen(js_name = readPoints)]
    pub fn read_points(&self) -> Result<Option<Vec<i32>>, JsValue> {
        let points = self.0.points().ok_or_else(|| {
            to_js_error(&Error::field(
                "points",
                "not read yet: advance the run past its reading first",
            ))
        })?;
        Ok(points
            .coords
            .iter()
            .map(|&c| i32::try_from(c).ok())
            .collect())
    }

    /// The check, once `advance` is done.
    #[wasm_bindgen(unchecked_return_type = "Check")]
    pub fn result(&self) -> Result<JsValue, JsValue> {
        let check = self.0.result().ok_or_else(|| {
            to_js_error(&Error::field(
                "check",
                "not made yet: advance the run to its end first",
            ))
        })?;
        Ok(to_js(&check))
    }
}

/// Bytes of values made in wasm memory at a time when points, deviations
/// or axis errors are read into a JS array (1 MiB and 32 KiB), each chunk
/// then copied out in one call. At least one core's L2 cache (1 MiB on the
/// AMD EPYC this was measured on), whatever the point's axis count, on
/// purpose: glibc's memmove, which V8 copies typed arrays with, uses
/// `rep movsb` on AMD processors for copies below that size, and that ran
/// a third slower whenever source and destination were not aligned alike
/// modulo 32 bytes, which a JS array's address (malloc's choice) often is
/// not. From it on, the vector loop copies at the rate of a fill whatever
/// the alignment: 20 MB of points left wasm memory in 1.45 ms in chunks of
/// 1 MiB or more, against 1.45 to 2.0 ms (by alignment) in 128 KiB ones,
/// and the 3D line's trace() and points took 4.4 ms against 5.1. The
/// values' writes then go to the shared L3 cache rather than L2, which
/// costs less than that. No larger than that: reading grows wasm memory by
/// this buffer, and a million-step helix's points would then pass the
/// 16 bytes a step that tests/scale.test.ts holds it to.
const COPY_CHUNK_BYTES: usize = (1 << 20) + (1 << 15);

/// Coordinates decoded at a time when points are read ([`COPY_CHUNK_BYTES`]).
const POINTS_CHUNK_VALUES: usize = COPY_CHUNK_BYTES / std::mem::size_of::<i32>();

/// Refuses `out` unless it holds exactly `values` values (`what` says what
/// they are, for the message).
///
/// Counted in u64: in wasm a usize is 32 bits, and points times axes of a
/// trace near the longest can pass 2^32.
fn expect_length(length: u32, values: u64, what: impl FnOnce() -> String) -> Result<(), JsValue> {
    if u64::from(length) != values {
        let message = format!("{}; got {length}", what());
        return Err(to_js_error(&Error::field("out", message)));
    }
    Ok(())
}

/// Values handed over one at a time, gathered in wasm memory and copied
/// into `out`, a JS array of exactly their number, [`COPY_CHUNK_BYTES`] at
/// a time: one copy each, and wasm memory grows by that buffer only.
struct Float64Out<'a> {
    out: &'a js_sys::Float64Array,
    buffer: Vec<f64>,
    chunk: usize,
    at: u32,
}

impl<'a> Float64Out<'a> {
    /// Writes into `out`, which must hold exactly `values` values (`what`
    /// words them for the message), the values `produce` pushes, the last
    /// chunk copied out after it.
    fn write(
        out: &'a js_sys::Float64Array,
        values: u64,
        what: impl FnOnce() -> String,
        produce: impl FnOnce(&mut Self),
    ) -> Result<(), JsValue> {
        expect_length(out.length(), values, what)?;
        let mut sink = Self::new(out);
        produce(&mut sink);
        sink.flush();
        Ok(())
    }

    fn new(out: &'a js_sys::Float64Array) -> Self {
        let chunk = (out.length() as usize).clamp(1, COPY_CHUNK_BYTES / std::mem::size_of::<f64>());
        Float64Out {
            out,
            buffer: Vec::with_capacity(chunk),
            chunk,
            at: 0,
        }
    }

    #[inline]
    fn push(&mut self, value: f64) {
        self.buffer.push(value);
        if self.buffer.len() == self.chunk {
            self.flush();
        }
    }

    fn flush(&mut self) {
        let end = self.at + self.buffer.len() as u32;
        self.out.subarray(self.at, end).copy_from(&self.buffer);
        self.at = end;
        self.buffer.clear();
    }
}

/// A learner's points read from text as `checkText` reads it (CSV,
/// blank-separated rows or a printed list), `dims` coordinates each, flat:
/// for a view that draws them beside the rule's path and then checks them
/// as a flat array, reading the text once. Errors give the line and column.
#[wasm_bindgen(js_name = readPoints)]
pub fn read_points(text: &TextBytes, dims: u32) -> Result<Vec<f64>, JsValue> {
    let axes = crate::grid::AXIS_NAMES.len();
    if dims == 0 || dims as usize > axes {
        let message = format!("{dims} coordinates per point; expected 1 to {axes}");
        return Err(to_js_error(&Error::field("dims", message)));
    }
    let points = crate::check::Points::from_text(utf8("text", &text.0)?, dims as usize)
        .map_err(|e| to_js_text_error(&e, "text"))?;
    // Exact: the reader refuses coordinates past 2^53.
    Ok(points.coords.iter().map(|&c| c as f64).collect())
}

/// A finished trace held in wasm memory.
#[wasm_bindgen]
pub struct TraceHandle(LazyTrace);

impl TraceHandle {
    /// The trace, recorded now if it was only planned.
    fn trace(&self) -> &Trace {
        self.0.trace()
    }

    fn check_range(&self, what: &str, from: u32, to: u32, len: u64) -> Result<(u64, u64), JsValue> {
        if from > to || to as u64 > len {
            return Err(to_js_error(&Error::field(
                "range",
                format!("{what} {from}..{to} is outside 0..{len}"),
            )));
        }
        Ok((from as u64, to as u64))
    }

    fn point_range(&self, from: u32, to: u32) -> Result<(u64, u64), JsValue> {
        self.check_range("point indices", from, to, self.0.steps() + 1)
    }

    fn step_range(&self, from: u32, to: u32) -> Result<(u64, u64), JsValue> {
        self.check_range("step indices", from, to, self.0.steps())
    }

    /// The point range of a chart of at most `max_rows` rows, checked.
    fn chart_range(&self, from: u32, to: u32, max_rows: u32) -> Result<(u64, u64), JsValue> {
        let range = self.point_range(from, to)?;
        if max_rows == 0 {
            return Err(to_js_error(&Error::field("maxRows", "must be at least 1")));
        }
        Ok(range)
    }
}

#[wasm_bindgen]
impl TraceHandle {
    /// Algorithm, dims, steps and the ends.
    #[wasm_bindgen(unchecked_return_type = "TraceSummary")]
    pub fn summary(&self) -> JsValue {
        to_js(&self.0.summary())
    }

    /// Decision columns, their figures and the deviation's bound.
    #[wasm_bindgen(unchecked_return_type = "TraceLegend")]
    pub fn legend(&self) -> JsValue {
        to_js(&self.trace().legend())
    }

    /// Every segment, with its ideal path and note (one per chord of an
    /// arc, one per G-code move).
    #[wasm_bindgen(unchecked_return_type = "SegmentSummary[]")]
    pub fn segments(&self) -> JsValue {
        to_js(&self.trace().segment_summaries())
    }

    /// Whole-path statistics, computed on the first call (a pass over
    /// every point and a replay of the decisions for the ties).
    #[wasm_bindgen(unchecked_return_type = "Metrics")]
    pub fn metrics(&self) -> JsValue {
        to_js(self.trace().metrics())
    }

    /// Makes the metrics' pass over at most `max_points` more points
    /// (`Trace::advance_metrics`); once done, `metrics` returns them at once.
    #[wasm_bindgen(js_name = advanceMetrics, unchecked_return_type = "PointsProgress")]
    pub fn advance_metrics(&self, max_points: u32) -> JsValue {
        to_js(&self.trace().advance_metrics(max_points.into()))
    }

    /// The box every point lies in (a pass over the steps on each call).
    #[wasm_bindgen(unchecked_return_type = "PointBounds")]
    pub fn bounds(&self) -> JsValue {
        to_js(&self.trace().bounds())
    }

    /// Writes every `every`-th point of point indices `from..to` (point
    /// indices from, from + every, ... below to; every point when `every`
    /// is 1) into `out`, an Int32Array of exactly ceil((to - from) / every)
    /// · dims values (stride dims), made on the JS side (where it need not
    /// be zeroed first: every value is written). The points are decoded a
    /// chunk at a time ([`Trace::points_by_chunk`]) into one buffer of
    /// [`POINTS_CHUNK_VALUES`] in wasm memory, and the chosen ones copied
    /// out of it. So the points cross with one copy, and reading them grows
    /// wasm memory by that buffer, whatever the trace's length. A page
    /// drawing a long path as every n-th cell asks for those alone: the
    /// decode walks every step, but only the drawn points are copied.
    pub fn points(
        &self,
        from: u32,
        to: u32,
        every: u32,
        out: &js_sys::Int32Array,
    ) -> Result<(), JsValue> {
        let (from, to) = self.point_range(from, to)?;
        if every == 0 {
            return Err(to_js_error(&Error::field(
                "every",
                "a whole number of at least 1 (1: every point)",
            )));
        }
        let every = every as u64;
        let dims = self.0.dims();
        let count = (to - from).div_ceil(every);
        let values = count * dims as u64;
        expect_length(out.length(), values, || {
            format!("an Int32Array of {values} values ({count} points of {dims})")
        })?;
        let rows = (POINTS_CHUNK_VALUES / dims) as u64;
        // Not zeroed: the decode writes every value it hands over.
        let values = rows.min(to - from).max(1) as usize * dims;
        let mut buffer = Vec::<i32>::with_capacity(values);
        let buffer = &mut buffer.spare_capacity_mut()[..values];
        if every == 1 {
            self.0.points_by_chunk(from, to, buffer, |k, chunk| {
                let at = ((k - from) as usize * dims) as u32;
                out.subarray(at, at + chunk.len() as u32).copy_from(chunk);
            });
            return Ok(());
        }
        // The chosen points of each chunk, gathered to cross in one copy.
        let mut chosen = Vec::with_capacity((buffer.len() / dims).div_ceil(every as usize) * dims);
        self.0.points_by_chunk(from, to, buffer, |k, chunk| {
            // The chunk's first chosen point, the n-th of all chosen: the
            // first index from k on that is `from` plus a multiple of `every`.
            let n = (k - from).div_ceil(every);
            let first = (from + n * every - k) as usize;
            chosen.clear();
            for row in chunk.chunks_exact(dims).skip(first).step_by(every as usize) {
                chosen.extend_from_slice(row);
            }
            let at = (n as usize * dims) as u32;
            out.subarray(at, at + chosen.len() as u32)
                .copy_from(&chosen);
        });
        Ok(())
    }

    /// Decision columns for step indices `from..to`, column-major.
    pub fn decisions(&self, from: u32, to: u32) -> Result<Vec<f64>, JsValue> {
        let (from, to) = self.step_range(from, to)?;
        Ok(self.trace().decisions_flat(from, to))
    }

    /// Writes the deviation from the ideal path of points `from..to` into
    /// `out`, a Float64Array of exactly to - from values made on the JS
    /// side: one pass over the range, copied out a chunk at a time.
    pub fn deviation(&self, from: u32, to: u32, out: &js_sys::Float64Array) -> Result<(), JsValue> {
        let (from, to) = self.point_range(from, to)?;
        let values = to - from;
        Float64Out::write(
            out,
            values,
            || format!("a Float64Array of {values} values (one a point)"),
            |sink| {
                self.trace()
                    .for_each_deviation(from, to, |deviation| sink.push(deviation))
            },
        )
    }

    /// Writes the per-axis error (Wang eq. 11) of points `from..to` into
    /// `out`, a Float64Array of exactly (to - from) · dims values (stride
    /// dims) made on the JS side, as `deviation` does.
    #[wasm_bindgen(js_name = axisError)]
    pub fn axis_error(
        &self,
        from: u32,
        to: u32,
        out: &js_sys::Float64Array,
    ) -> Result<(), JsValue> {
        let (from, to) = self.point_range(from, to)?;
        let dims = self.0.dims();
        let values = (to - from) * dims as u64;
        Float64Out::write(
            out,
            values,
            || {
                format!(
                    "a Float64Array of {values} values ({} points of {dims})",
                    to - from
                )
            },
            |sink| {
                self.trace()
                    .for_each_axis_error(from, to, |error| sink.push(error))
            },
        )
    }

    /// Packed steps (see `grid::Step`) of step indices `from..to`.
    #[wasm_bindgen(js_name = stepCodes)]
    pub fn step_codes(&self, from: u32, to: u32) -> Result<Vec<u16>, JsValue> {
        let (from, to) = self.step_range(from, to)?;
        let mut out = room_for(to - from, || format!("the codes of steps {from}..{to}"))?;
        out.extend(self.trace().step_range(from, to).iter().map(|s| s.0));
        Ok(out)
    }

    /// DIR levels of step indices `from..to` (see `machine::direction_levels`).
    #[wasm_bindgen(js_name = directionLevels)]
    pub fn direction_levels(&self, from: u32, to: u32) -> Result<Vec<u8>, JsValue> {
        let (from, to) = self.step_range(from, to)?;
        let mut out = room_for(to - from, || {
            format!("the DIR levels of steps {from}..{to}")
        })?;
        crate::machine::push_direction_levels(self.trace(), from, to, &mut out);
        Ok(out)
    }

    /// One sentence: why step index `step` was taken.
    pub fn explain(&self, step: u32) -> Result<String, JsValue> {
        let (step, _) = self.step_range(step, step + 1)?;
        Ok(self.trace().explain(step))
    }

    /// Point index `point` (0..=steps) and the step that produced it (step
    /// index point - 1): its decision with the values read, explanation,
    /// deviation, segment and picture, from one replay (see `step_detail`).
    #[wasm_bindgen(js_name = stepDetail, unchecked_return_type = "StepDetail")]
    pub fn step_detail(&self, point: u32) -> Result<JsValue, JsValue> {
        let (point, _) = self.point_range(point, point + 1)?;
        Ok(to_js(&crate::step_detail::step_detail(self.trace(), point)))
    }

    /// A chart's rows of points `from..to`, at most `max_rows` of them
    /// (buckets of points past that), column-major: see `Trace::chart_rows`.
    #[wasm_bindgen(js_name = chartRows)]
    pub fn chart_rows(&self, from: u32, to: u32, max_rows: u32) -> Result<Vec<f64>, JsValue> {
        let (from, to) = self.chart_range(from, to, max_rows)?;
        Ok(self.trace().chart_rows(from, to, max_rows.into()))
    }

    /// Makes the rows of `chartRows(from, to, max_rows)` over at most
    /// `max_points` more points (`Trace::advance_chart_rows`), kept until
    /// `takeChartRows` takes them.
    #[wasm_bindgen(js_name = advanceChartRows, unchecked_return_type = "PointsProgress")]
    pub fn advance_chart_rows(
        &self,
        from: u32,
        to: u32,
        max_rows: u32,
        max_points: u32,
    ) -> Result<JsValue, JsValue> {
        let (from, to) = self.chart_range(from, to, max_rows)?;
        Ok(to_js(&self.trace().advance_chart_rows(
            from,
            to,
            max_rows.into(),
            max_points.into(),
        )))
    }

    /// The rows of `chartRows(from, to, max_rows)`: those `advanceChartRows`
    /// made, the rest made now.
    #[wasm_bindgen(js_name = takeChartRows)]
    pub fn take_chart_rows(&self, from: u32, to: u32, max_rows: u32) -> Result<Vec<f64>, JsValue> {
        let (from, to) = self.chart_range(from, to, max_rows)?;
        Ok(self.trace().take_chart_rows(from, to, max_rows.into()))
    }

    /// This trace against `other` (same dims): both digests, the first
    /// difference with why each side stepped there, and the first cells
    /// only one visits (`compare::compare`).
    #[wasm_bindgen(js_name = compareWith, unchecked_return_type = "Comparison")]
    pub fn compare_with(&self, other: &TraceHandle) -> Result<JsValue, JsValue> {
        let result =
            crate::compare::compare(self.trace(), other.trace()).map_err(|e| to_js_error(&e))?;
        Ok(to_js(&result))
    }

    /// Every cell this trace visits and `other` never does, in this trace's
    /// order, each once (Int32Array, stride dims).
    #[wasm_bindgen(js_name = cellsOnlyIn)]
    pub fn cells_only_in(&self, other: &TraceHandle) -> Result<Vec<i32>, JsValue> {
        crate::compare::cells_only_in(self.trace(), other.trace()).map_err(|e| to_js_error(&e))
    }

    /// The tool's speed per step at one tick a step and at a constant feed
    /// (`step_clocks`), in at most `max_rows` rows.
    #[wasm_bindgen(js_name = stepClocks, unchecked_return_type = "StepClocks")]
    pub fn step_clocks(&self, max_rows: u32) -> Result<JsValue, JsValue> {
        crate::step_clocks::step_clocks(self.trace(), max_rows)
            .map(|clocks| to_js(&clocks))
            .map_err(|e| to_js_error(&e))
    }

    /// The ideal path as a polyline for drawing (Float64Array, stride dims).
    #[wasm_bindgen(js_name = idealPolyline)]
    pub fn ideal_polyline(&self) -> Vec<f64> {
        self.trace().ideal_polyline()
    }

    /// The ideal polyline as WebGL draws it, from the grid point
    /// (`origin_x`, `origin_y`, `origin_z`) (`Trace::ideal_line_f32`): held
    /// in the core until copied into an array of its length.
    #[wasm_bindgen(js_name = idealLine)]
    pub fn ideal_line(&self, origin_x: f64, origin_y: f64, origin_z: f64) -> IdealLineHandle {
        IdealLineHandle(self.trace().ideal_line_f32([origin_x, origin_y, origin_z]))
    }
}

/// A trace's ideal line for drawing, made in the core: its vertex count
/// read first, so that JavaScript makes the array it is copied into (not
/// zeroed first, in Node) and the vertices cross in one copy, with no
/// array of them all in wasm memory.
#[wasm_bindgen]
pub struct IdealLineHandle(crate::trace::IdealLineF32);

#[wasm_bindgen]
impl IdealLineHandle {
    /// How many vertices the line has.
    #[wasm_bindgen(getter)]
    pub fn vertices(&self) -> u32 {
        // A vertex is 24 bytes in wasm's 4 GiB: fewer than 2^28 of them.
        self.0.vertices() as u32
    }

    /// Smallest x, y, z over the vertices as drawn, then the largest; zeros
    /// when there is none.
    pub fn bounds(&self) -> Vec<f32> {
        self.0.bounds().to_vec()
    }

    /// x, y, z of every vertex (stride 3), then what rounding left of each,
    /// into `out`, 6 values a vertex long.
    #[wasm_bindgen(js_name = copyInto)]
    pub fn copy_into(&self, out: &js_sys::Float32Array) -> Result<(), JsValue> {
        let values = 3 * self.0.vertices() as u64;
        expect_length(out.length(), 2 * values, || {
            format!(
                "a Float32Array of {} values (x, y, z and their rests for {} vertices)",
                2 * values,
                self.0.vertices()
            )
        })?;
        let pieces = self.0.xyz_pieces().chain(self.0.rest_pieces());
        let mut at = 0u32;
        for piece in pieces {
            let end = at + piece.len() as u32;
            out.subarray(at, end).copy_from(piece);
            at = end;
        }
        Ok(())
    }
}

/// Where two traces of one move differ, as the page shows them (the first
/// point where they part, the cells only one visits), made a trace's cells
/// at a time (`compare::DifferencePass`): each call takes the two traces it
/// was made for.
#[wasm_bindgen]
pub struct DifferenceRun(crate::compare::DifferencePass);

#[wasm_bindgen]
impl DifferenceRun {
    /// The difference of `a` and `b` (same axes, each within the compared
    /// points), else an error naming `other`.
    #[wasm_bindgen(constructor)]
    pub fn new(a: &TraceHandle, b: &TraceHandle) -> Result<DifferenceRun, JsValue> {
        crate::compare::DifferencePass::new(a.trace(), b.trace())
            .map(DifferenceRun)
            .map_err(|e| to_js_error(&e))
    }

    /// Sorts the next trace's cells (`a`'s, then `b`'s, merged with `a`'s).
    #[wasm_bindgen(unchecked_return_type = "PointsProgress")]
    pub fn advance(&mut self, a: &TraceHandle, b: &TraceHandle) -> Result<JsValue, JsValue> {
        let progress = self
            .0
            .advance(a.trace(), b.trace())
            .map_err(|e| to_js_error(&e))?;
        Ok(to_js(&progress))
    }

    /// The first point where they part, with why each stepped there; null
    /// where they do not.
    #[wasm_bindgen(js_name = firstDifference, unchecked_return_type = "FirstDifference | null")]
    pub fn first_difference(&self, a: &TraceHandle, b: &TraceHandle) -> Result<JsValue, JsValue> {
        let first = self
            .0
            .first_difference(a.trace(), b.trace())
            .map_err(|e| to_js_error(&e))?;
        Ok(to_js(&first))
    }

    /// The cells only `a` (`side` 0) or only `b` (1) visits, in its order,
    /// each once (Int32Array, stride dims), once `advance` is done.
    #[wasm_bindgen(js_name = cellsOnlyIn)]
    pub fn cells_only_in(
        &self,
        side: u32,
        a: &TraceHandle,
        b: &TraceHandle,
    ) -> Result<Vec<i32>, JsValue> {
        self.0
            .cells_only_in(side as usize, a.trace(), b.trace())
            .map_err(|e| to_js_error(&e))
    }
}

/// The STEP and DIR wires of a G-code run as an IEEE 1364 VCD file
/// (`gcode::vcd`), a part at a time: `next` hands out the header, then the
/// file's lines for `CHUNK_STEPS` steps per call, so that neither the core
/// nor JS holds the whole file (1.6 GB for 50,000,000 steps).
#[wasm_bindgen]
pub struct GcodeVcd(crate::gcode::vcd::VcdChunks);

/// An error of the VCD's own (the program lasts longer than the VCD's ticks
/// reach, or two of its steps come too close for a pulse between them),
/// named as the program's: writing to memory does not fail otherwise.
fn vcd_error(e: std::io::Error) -> JsValue {
    to_js_error(&Error::field("program", e.to_string()))
}

/// `trace` must be the one taken from `result`.
fn check_vcd_trace(trace: &TraceHandle, result: &GcodeResult) -> Result<(), JsValue> {
    if trace.0.steps() != result.steps {
        return Err(to_js_error(&Error::field(
            "trace",
            "is not the trace of this G-code result",
        )));
    }
    Ok(())
}

#[wasm_bindgen]
impl GcodeVcd {
    /// The VCD of the run `result` with its trace `trace`; an error before
    /// anything is written when the program lasts past the VCD's ticks.
    #[wasm_bindgen(constructor)]
    pub fn new(trace: &TraceHandle, result: &GcodeResult) -> Result<GcodeVcd, JsValue> {
        check_vcd_trace(trace, result)?;
        crate::gcode::vcd::VcdChunks::new(&result.timeline)
            .map(GcodeVcd)
            .map_err(vcd_error)
    }

    /// The next part of the file, or undefined once it is all written.
    pub fn next(
        &mut self,
        trace: &TraceHandle,
        result: &GcodeResult,
    ) -> Result<Option<Vec<u8>>, JsValue> {
        check_vcd_trace(trace, result)?;
        let mut out = Vec::new();
        let more = self
            .0
            .write_next(trace.trace(), &result.timeline, &mut out)
            .map_err(vcd_error)?;
        Ok(more.then_some(out))
    }
}

/// A G-code program being run a slice of lines at a time, so that a worker
/// can report progress and stop between slices.
#[wasm_bindgen]
pub struct GcodeRun(crate::gcode::Runner);

#[wasm_bindgen]
impl GcodeRun {
    /// `source`: the program as UTF-8 bytes (see [`TextBytes`]);
    /// `settings_json`: a `GcodeSettings` object as JSON text (its fields
    /// are the catalogue's `gcodeSettings`). Bad settings throw, naming the
    /// setting.
    #[wasm_bindgen(constructor)]
    pub fn new(source: &mut TextBytes, settings_json: &str) -> Result<GcodeRun, JsValue> {
        let settings =
            crate::gcode::Settings::from_json(settings_json).map_err(|e| to_js_error(&e))?;
        // The bytes are taken, not copied: the TextBytes is left empty. A
        // text of other than ASCII was given room for 3 bytes a character.
        let mut bytes = std::mem::take(&mut source.0);
        bytes.shrink_to_fit();
        let source = String::from_utf8(bytes)
            .map_err(|e| not_utf8("source", e.as_bytes(), e.utf8_error()))?;
        Ok(GcodeRun(crate::gcode::Runner::new(source, settings)))
    }

    /// Runs up to `max_lines` more lines; returns how far the run has got.
    /// Throws, saying how far it got and what to change, when the program
    /// does not fit in memory (`gcode::Runner::advance`): the run is then
    /// over, and can still be freed.
    #[wasm_bindgen(unchecked_return_type = "Progress")]
    pub fn advance(&mut self, max_lines: u32) -> Result<JsValue, JsValue> {
        let progress = self.0.advance(max_lines);
        match self.0.out_of_memory() {
            Some(error) => Err(to_js_error(error)),
            None => Ok(to_js(&progress)),
        }
    }

    /// Stops the run once the core holds more than `bytes` of heap, instead
    /// of `memory::HEAP_BUDGET_BYTES` (2 GiB): for tests of that stop.
    #[wasm_bindgen(js_name = setHeapBudget)]
    pub fn set_heap_budget(&mut self, bytes: f64) {
        self.0.set_heap_budget(bytes as usize);
    }

    /// The program as run so far (all of it once `done`).
    pub fn finish(self) -> GcodeResult {
        let program = self.0.finish();
        GcodeResult {
            program: to_js(&program.info),
            moves: program.records,
            steps: program.trace.steps(),
            steps_per_mm: program.info.steps_per_mm,
            trace: Some(program.trace),
            timeline: program.timeline,
        }
    }
}

/// A finished G-code run: the program's record, and its trace.
#[wasm_bindgen]
pub struct GcodeResult {
    program: JsValue,
    moves: std::rc::Rc<crate::gcode::program::MoveRecords>,
    steps: u64,
    steps_per_mm: [f64; crate::machine::MACHINE_AXES],
    trace: Option<Trace>,
    timeline: crate::gcode::timing::Timeline,
}

impl GcodeResult {
    /// `from..to` as step indices of the program, else an error naming `range`.
    fn step_range(&self, from: u32, to: u32) -> Result<(u64, u64), JsValue> {
        if from > to || to as u64 > self.steps {
            return Err(to_js_error(&Error::field(
                "range",
                format!("step indices {from}..{to} are outside 0..{}", self.steps),
            )));
        }
        Ok((from as u64, to as u64))
    }
}

#[wasm_bindgen]
impl GcodeResult {
    /// Pulses, warnings, errors and the number of moves (see
    /// `gcode::ProgramInfo`); the moves themselves are read by range.
    #[wasm_bindgen(unchecked_return_type = "ProgramInfo")]
    pub fn program(&self) -> JsValue {
        self.program.clone()
    }

    /// The moves of indices `from..to`.
    #[wasm_bindgen(unchecked_return_type = "Move[]")]
    pub fn moves(&self, from: u32, to: u32) -> Result<JsValue, JsValue> {
        let (from, to) = (from as usize, to as usize);
        if from > to || to > self.moves.len() {
            return Err(to_js_error(&Error::field(
                "range",
                format!(
                    "move indices {from}..{to} are outside 0..{}",
                    self.moves.len()
                ),
            )));
        }
        let moves: Vec<crate::gcode::Move> = (from..to)
            .map(|i| self.moves.get(i, &self.timeline))
            .collect();
        Ok(to_js(&moves))
    }

    /// Index of the move that took step index `k` (`k` below the steps).
    #[wasm_bindgen(js_name = moveOfStep)]
    pub fn move_of_step(&self, k: u32) -> Option<u32> {
        self.moves.move_of_step(k as u64).map(|i| i as u32)
    }

    /// The 1-based source line of each step index in `from..to`.
    #[wasm_bindgen(js_name = lineByStep)]
    pub fn line_by_step(&self, from: u32, to: u32) -> Result<Vec<u32>, JsValue> {
        let (from, to) = self.step_range(from, to)?;
        let mut out = room_for(to - from, || format!("the lines of steps {from}..{to}"))?;
        self.moves.push_line_by_step(from, to, &mut out);
        Ok(out)
    }

    /// Index of the move programmed on a 1-based source line, if it moved.
    #[wasm_bindgen(js_name = moveAtLine)]
    pub fn move_at_line(&self, line: u32) -> Option<u32> {
        self.moves.move_at_line(line).map(|i| i as u32)
    }

    /// The step index where the machine is when `line` starts.
    #[wasm_bindgen(js_name = pointBeforeLine)]
    pub fn point_before_line(&self, line: u32) -> u32 {
        let k = self.moves.first_step_from_line(line).unwrap_or(self.steps);
        // At most MAX_STEPS_LIMIT (10^9) steps: a u32, as every step index here.
        u32::try_from(k).expect("at most 10^9 steps")
    }

    /// The instant of each step index in `from..to`, seconds from the
    /// program's start, on the planned profile (`gcode::timing`).
    #[wasm_bindgen(js_name = stepTimes)]
    pub fn step_times(&self, from: u32, to: u32) -> Result<Vec<f64>, JsValue> {
        let (from, to) = self.step_range(from, to)?;
        let mut out = room_for(to - from, || format!("the instants of steps {from}..{to}"))?;
        self.timeline.push_step_seconds(from, to, &mut out);
        Ok(out)
    }

    /// Seconds the machine waits at rest for a G4 dwell between
    /// `from_seconds` and `to_seconds` (the dwells whose middle is in that
    /// span): which part of a pause between two steps is a dwell.
    #[wasm_bindgen(js_name = dwellSeconds)]
    pub fn dwell_seconds(&self, from_seconds: f64, to_seconds: f64) -> Result<f64, JsValue> {
        if from_seconds.is_nan() {
            return Err(to_js_error(&Error::field("fromSeconds", "is not a number")));
        }
        if to_seconds.is_nan() {
            return Err(to_js_error(&Error::field("toSeconds", "is not a number")));
        }
        Ok(self
            .timeline
            .dwell_seconds_between(from_seconds, to_seconds))
    }

    /// The planned speed over time as corners of a polyline: (seconds,
    /// mm/s) pairs, four per planner block (start, end of acceleration,
    /// start of deceleration, end), flat.
    #[wasm_bindgen(js_name = speedProfile)]
    pub fn speed_profile(&self) -> Vec<f64> {
        self.timeline.speed_profile()
    }

    /// The planned speed and step rates over `from_seconds..to_seconds` in
    /// at most `buckets` rows (`gcode::motion_chart`).
    #[wasm_bindgen(js_name = motionChart, unchecked_return_type = "MotionChart")]
    pub fn motion_chart(
        &self,
        from_seconds: f64,
        to_seconds: f64,
        buckets: u32,
    ) -> Result<JsValue, JsValue> {
        self.timeline
            .motion_chart(&self.steps_per_mm, from_seconds, to_seconds, buckets)
            .map(|chart| to_js(&chart))
            .map_err(|e| to_js_error(&e))
    }

    /// The point index reached at `seconds` on the planned profile: how
    /// many steps happen at or before it.
    #[wasm_bindgen(js_name = pointAtSeconds)]
    pub fn point_at_seconds(&self, seconds: f64) -> Result<u32, JsValue> {
        if seconds.is_nan() {
            return Err(to_js_error(&Error::field("seconds", "is not a number")));
        }
        // At most MAX_STEPS_LIMIT (10^9) steps: a u32, as every step index here.
        Ok(u32::try_from(self.timeline.points_reached_at(seconds)).expect("at most 10^9 steps"))
    }

    /// The trace, handed over once.
    #[wasm_bindgen(js_name = takeTrace)]
    pub fn take_trace(&mut self) -> Result<TraceHandle, JsValue> {
        self.trace
            .take()
            .map(|trace| TraceHandle(trace.into()))
            .ok_or_else(|| to_js_error(&Error::field("trace", "already taken from this result")))
    }
}
