//! Everything the core offers, in one answer: the algorithms, the
//! experiments and the G-code machine settings, each with its options (name,
//! kind, default, doc). The CLI's flags, the page's forms, its URL keys and
//! their docs are all made from this, so a new option or setting is declared
//! once, in Rust.

use crate::algorithms::{ALGORITHMS, AlgorithmInfo};
use crate::experiment::{EXPERIMENTS, ExperimentInfo};
use crate::gcode::program::SETTINGS;
use crate::request::OptionSpec;
use serde::Serialize;
use tsify::Tsify;

#[derive(Serialize, Tsify)]
#[serde(rename_all = "camelCase")]
pub struct Catalogue {
    /// Every algorithm, in the order the page lists them.
    pub algorithms: &'static [&'static AlgorithmInfo],
    pub experiments: &'static [ExperimentInfo],
    /// The settings of a G-code run (`GcodeSettings`), per-axis ones
    /// included.
    pub gcode_settings: &'static [OptionSpec],
}

pub const CATALOGUE: Catalogue = Catalogue {
    algorithms: ALGORITHMS,
    experiments: EXPERIMENTS,
    gcode_settings: SETTINGS,
};
