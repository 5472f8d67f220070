//! The rules of a `.par` file, one code a file (the four start-up codes share
//! `startup.rs`, their one check): each file holds its code's `Code`, with the
//! explanation and the bad and good examples a test runs, and its check.

/// A whole example `.par` that pkdgrav's default build runs without a word, and that
/// has no finding: [`settled`] and the timestep, steps, spring and checkpoints.
macro_rules! clean {
    () => {
        concat!(
            settled!(),
            "dDelta               = 1e-7
nSteps               = 1000
dKn                  = 1e5
iCheckInterval       = 0
"
        )
    };
}

pub mod duplicate_key;
pub mod line_too_long;
pub mod not_finite;
pub mod not_modelled;
pub mod par_syntax;
pub mod read_as;
pub mod startup;
pub mod unknown_key;
