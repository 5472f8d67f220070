//! Shared pieces of the walls command-line tools: reading inputs (files or standard
//! input) and the `--mode` argument. The whole check of one file and the registry of
//! diagnostic codes that `--explain` and SARIF read are `walls-ide`'s, re-exported here
//! for the tools.

pub mod commands;
pub mod input;

pub use walls_ide::{Checked, all_codes, check_bytes, find_code};

/// `--mode`: the contact model a file is for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum ModeArg {
    /// Soft-sphere DEM (the default).
    Ssdem,
    /// Hard-sphere DEM.
    Hsdem,
}

impl From<ModeArg> for walls_model::Mode {
    fn from(mode: ModeArg) -> Self {
        match mode {
            ModeArg::Ssdem => walls_model::Mode::Ssdem,
            ModeArg::Hsdem => walls_model::Mode::Hsdem,
        }
    }
}
