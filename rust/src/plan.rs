//! A trace planned and not yet recorded: what `trace()` hands over, its
//! steps recorded when something first reads them, and its points, when
//! they are the first thing read, made straight from its steppers.
//!
//! A trace records every step as a 2-byte code, keeps checkpoints of its
//! steppers, and its points are decoded from those codes when read. A
//! caller who reads only the points (most headless callers: `(await
//! trace({...})).points`) then pays for codes written to memory and read
//! back, 3.4 MB for a circle of r = 300,000, out of cache both times.
//! Where an algorithm knows, before running, how many steps its path
//! takes and where it ends (a line's stepper counts them, a circle's and a
//! helix's dry run, a chord's line its |Δ|), it plans instead ([`Plan`]): the summary is
//! known, and the points come from its steppers a few thousand steps at a
//! time, each run of codes decoded while it is still in cache
//! ([`PointsSink`]). In Node the circle of r = 300,000 in x and y, traced
//! and read after a collection and a pause as the end-to-end bench runs
//! it, took 4.6 ms recorded and 3.5 ms so (medians of 30), its 3-axis twin
//! 5.7 and 4.7 ms.
//!
//! Everything else a trace offers (decisions, metrics, a range of points,
//! ...) records it first, by the algorithm's own `trace` on the same
//! request: one path makes every recorded trace.

use crate::grid::{Point, Step, written_steps};
use crate::points::{Coordinate, decode};
use crate::trace::Stepper;
use std::mem::MaybeUninit;

/// Runs a plan's steppers, in order, into a sink of points.
pub type RunInto = Box<dyn Fn(&mut PointsSink<'_, i32>)>;

/// What a trace will be, known before it is recorded.
pub struct Plan {
    /// Point 0 and point `steps`.
    pub start: Point,
    pub end: Point,
    pub steps: u64,
    /// Its steppers from their first states, run into a sink.
    pub run_into: RunInto,
}

impl Plan {
    /// The plan of one stepper from `start` to `end`: its steps its own
    /// count, None where it has none or it passes `max_steps` (the trace
    /// then records, and says why).
    pub fn of_stepper<S: Stepper>(
        start: Point,
        end: Point,
        stepper: S,
        max_steps: u64,
    ) -> Option<Plan> {
        let steps = stepper.remaining_steps().filter(|&n| n <= max_steps)?;
        Some(Plan {
            start,
            end,
            steps,
            run_into: Box::new(move |sink| sink.run(stepper.clone())),
        })
    }
}

/// Steps a stepper takes at a time into [`PointsSink`]'s scratch before
/// they are decoded: 8 KB of codes, which stay in the L1 cache between
/// their writing and their reading.
const STEPS_AT_ONCE: usize = 4096;

/// The points of one or more steppers run one after another from a start,
/// decoded a few thousand steps at a time from the codes just taken into
/// `buffer`, which is handed to `f` (with the point index of its first
/// point) each time it is full of whole points, and at the end.
pub struct PointsSink<'a, C: Coordinate> {
    point: Point,
    buffer: &'a mut [MaybeUninit<C>],
    /// Values of `buffer` written and not yet handed over.
    held: usize,
    /// Point index of the buffer's first point.
    first_point: u64,
    f: &'a mut dyn FnMut(u64, &[C]),
}

impl<'a, C: Coordinate> PointsSink<'a, C> {
    /// A sink whose first point is `start`; `buffer` need not be
    /// initialised, and holds at least one point.
    pub fn new(
        start: Point,
        buffer: &'a mut [MaybeUninit<C>],
        f: &'a mut dyn FnMut(u64, &[C]),
    ) -> Self {
        let dims = start.dims();
        let whole = buffer.len() / dims * dims;
        assert!(whole > 0, "a buffer of at least one point");
        let buffer = &mut buffer[..whole];
        for (c, &v) in buffer.iter_mut().zip(start.coords()) {
            c.write(C::from_i64(v));
        }
        PointsSink {
            point: start,
            buffer,
            held: dims,
            first_point: 0,
            f,
        }
    }

    /// Where the last stepper run ended.
    pub fn position(&self) -> Point {
        self.point
    }

    /// The points of `stepper`'s steps, taken from where the sink is.
    pub fn run<S: Stepper>(&mut self, mut stepper: S) {
        let dims = self.point.dims();
        let mut scratch = [MaybeUninit::<Step>::uninit(); STEPS_AT_ONCE];
        loop {
            let room = (self.buffer.len() - self.held) / dims;
            if room == 0 {
                self.hand_over();
                continue;
            }
            let want = room.min(STEPS_AT_ONCE);
            let filled = stepper.fill(&mut scratch[..want]);
            // SAFETY: a fill writes the first `steps` slots it is given
            // (the Stepper trait's contract, which Filled::written states).
            let steps = unsafe { written_steps(&scratch[..filled.steps()]) };
            let end = self.held + steps.len() * dims;
            self.point = decode(&self.point, steps, &mut self.buffer[self.held..end]);
            self.held = end;
            if filled.steps() < want {
                return;
            }
        }
    }

    fn hand_over(&mut self) {
        let dims = self.point.dims();
        let written = &self.buffer[..self.held];
        // SAFETY: the first `held` values were written (by `new` or a
        // decode, which writes every value it is given); MaybeUninit<C>
        // has C's layout.
        let written = unsafe { &*(written as *const [MaybeUninit<C>] as *const [C]) };
        (self.f)(self.first_point, written);
        self.first_point += (self.held / dims) as u64;
        self.held = 0;
    }

    /// Hands over the points not yet handed over: the last point, and how
    /// many points were handed over in all.
    pub fn finish(mut self) -> (Point, u64) {
        if self.held > 0 {
            self.hand_over();
        }
        (self.point, self.first_point)
    }
}
