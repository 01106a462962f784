//! G-code programs on a modelled machine, down to motor pulses.
//!
//! text --parse--> blocks of codes and words with columns (`parse`, on the
//! `gcode` crate) --interpret--> moves in machine mm through the modal state
//! (`interpret`) --program--> one trace in steps, one segment (or one per
//! chord) per move, each stepped by the chosen line or arc algorithm
//! (`program`), with the step/direction signals in `machine`.
//!
//! What a program reports: its moves with their source line (and where each
//! starts in the step sequence), the trace (every step, and why it was
//! taken), pulses per axis, warnings for what voxpath does not model, and
//! errors with line and column. Execution stops at the first error: the
//! moves before it are kept, and the lines after it are still checked for
//! syntax errors.
//!
//! Read as an incremental [`Runner`] (a slice of lines at a time, so a page
//! can show progress), or all at once with [`run`].

pub mod interpret;
pub mod motion_chart;
pub mod parse;
pub mod program;
pub mod timing;
pub mod vcd;

pub use program::{Diagnostic, Move, Program, ProgramInfo, Progress, Runner, Settings, run};
