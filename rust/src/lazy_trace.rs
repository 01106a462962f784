//! A trace recorded when first needed: what `trace()` hands over. See
//! [`crate::plan`] for why, and what a plan promises.

use crate::algorithm_info::{AlgorithmInfo, Find};
use crate::error::Error;
use crate::plan::{Plan, PointsSink};
use crate::request::Request;
use crate::trace::{Trace, TraceSummary};
use std::cell::OnceCell;
use std::mem::MaybeUninit;

/// A trace, recorded when first needed.
pub struct LazyTrace {
    /// What records it, and its plan; None for a trace recorded when made.
    planned: Option<Planned>,
    recorded: OnceCell<Trace>,
}

/// A request planned, and what records it.
struct Planned {
    algorithm: &'static AlgorithmInfo,
    find: Find,
    request: Request,
    plan: Plan,
}

impl From<Trace> for LazyTrace {
    /// A trace recorded already (a G-code program's).
    fn from(trace: Trace) -> LazyTrace {
        LazyTrace {
            planned: None,
            recorded: OnceCell::from(trace),
        }
    }
}

impl LazyTrace {
    /// `request` planned where its algorithm can plan it, else recorded
    /// now. A request the plan refuses or cannot make is recorded, so that
    /// its error is the one its algorithm's `trace` gives.
    pub fn new(request: Request, find: Find) -> Result<LazyTrace, Error> {
        let algorithm = find(&request.algorithm)?;
        let plan = match algorithm.plan {
            Some(plan) if request.follow().is_none() => plan(&request, find).ok().flatten(),
            _ => None,
        };
        let Some(plan) = plan else {
            return (algorithm.trace)(&request, find).map(LazyTrace::from);
        };
        Ok(LazyTrace {
            planned: Some(Planned {
                algorithm,
                find,
                request,
                plan,
            }),
            recorded: OnceCell::new(),
        })
    }

    /// The trace, recorded now if it was not.
    pub fn trace(&self) -> &Trace {
        self.recorded.get_or_init(|| {
            let planned = self
                .planned
                .as_ref()
                .expect("a trace not recorded when made was planned");
            let trace = (planned.algorithm.trace)(&planned.request, planned.find)
                .expect("a planned request records: its plan made the checks its trace makes");
            let plan = &planned.plan;
            debug_assert_eq!(
                (trace.start(), trace.end(), trace.steps()),
                (plan.start, plan.end, plan.steps),
                "a trace records as planned"
            );
            trace
        })
    }

    /// The plan, while the trace is not recorded.
    fn pending(&self) -> Option<(&'static str, &Plan)> {
        match (&self.planned, self.recorded.get()) {
            (Some(planned), None) => Some((planned.algorithm.id, &planned.plan)),
            _ => None,
        }
    }

    pub fn summary(&self) -> TraceSummary<'_> {
        match self.pending() {
            None => self.trace().summary(),
            Some((algorithm, plan)) => TraceSummary {
                algorithm,
                dims: plan.start.dims(),
                steps: plan.steps,
                start: plan.start.coords().to_vec(),
                end: plan.end.coords().to_vec(),
            },
        }
    }

    pub fn steps(&self) -> u64 {
        self.pending()
            .map_or_else(|| self.trace().steps(), |(_, plan)| plan.steps)
    }

    pub fn dims(&self) -> usize {
        self.pending()
            .map_or_else(|| self.trace().dims(), |(_, plan)| plan.start.dims())
    }

    /// [`Trace::points_by_chunk`]: from the plan's steppers when every
    /// point is read before anything recorded the trace, else from the
    /// recorded trace (whose checkpoints find a range's first point).
    pub fn points_by_chunk(
        &self,
        from: u64,
        to: u64,
        buffer: &mut [MaybeUninit<i32>],
        mut f: impl FnMut(u64, &[i32]),
    ) {
        match self.pending() {
            // No points: nothing to record for.
            Some(_) if from >= to => {}
            Some((_, plan)) if from == 0 && to == plan.steps + 1 => {
                let mut sink = PointsSink::new(plan.start, buffer, &mut f);
                (plan.run_into)(&mut sink);
                let (end, points) = sink.finish();
                debug_assert_eq!(
                    (end, points),
                    (plan.end, to),
                    "a plan's steppers end as planned"
                );
            }
            _ => self.trace().points_by_chunk(from, to, buffer, f),
        }
    }
}
