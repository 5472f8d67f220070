//! The codes of a run directory's check before the job (`R…`), one a file, each with its
//! explanation and its bad and good examples: a `.par` file of a run directory whose walls
//! file and particles the line before it describes. walls-sim's `precheck` holds the
//! checks (one a file, of the same names), and its tests build and check each example;
//! the codes are here, below the registry, so that every tool knows them (`--explain`,
//! settings' `ignore`, the language server).

/// The `.par` lines every code's example shares: `settled!`'s, with checkpoints off, of a
/// run directory pkdgrav's default build runs without a word (the `.par`'s own check finds
/// nothing in it); the examples add the lines they are about.
macro_rules! run_par {
    () => {
        concat!(settled!(), "iCheckInterval       = 0\n")
    };
}

pub mod build_lacks;
pub mod few_steps;
pub mod initial_conditions;
pub mod no_output;
pub mod outside_container;
pub mod pair_overlap;
pub mod wall_overlap;
pub mod wall_too_fast;
pub mod wide_steps;

use walls_diagnostics::Code;

/// Every `R…` code, in code order.
pub static ALL: &[&Code] = &[
    &pair_overlap::PAIR_OVERLAP,
    &wall_overlap::WALL_OVERLAP,
    &outside_container::OUTSIDE_CONTAINER,
    &few_steps::FEW_STEPS,
    &wall_too_fast::WALL_TOO_FAST,
    &build_lacks::BUILD_LACKS,
    &no_output::NO_OUTPUT,
    &wide_steps::WIDE_STEPS,
    &initial_conditions::INITIAL_CONDITIONS,
];
