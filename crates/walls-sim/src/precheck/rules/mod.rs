//! The checks of a run directory, one code a file (`R…`): each file holds its code's
//! `Code`, with the explanation and the bad and good examples, and its check. An
//! example is a `.par` file of a run directory whose walls file and particles the line
//! before it describes; the tests of [`super`] build each and check it.

/// The `.par` lines every code's example shares: a run directory pkdgrav's default
/// build runs without a word (the `.par`'s own check finds nothing in it); the examples
/// add the lines they are about.
macro_rules! run_par {
    () => {
        "achInFile            = ss.ic
achWallsFile         = walls.dat
iOutInterval         = 100
iForceOverrideOption = 2
iOutcomes            = 0
bDoSelfGravity       = 0
iCheckInterval       = 0
"
    };
}

pub mod build_lacks;
pub mod few_steps;
pub mod no_output;
pub mod outside_container;
pub mod pair_overlap;
pub mod wall_overlap;
pub mod wall_too_fast;
pub mod wide_steps;

use walls_diagnostics::{Code, Severity};

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
];

/// pkdgrav's overlap levels for a run (`dMinorFrac`, `dMajorFrac`, `dErrorFrac`, the
/// defaults of [`crate::advise::OVERLAP_LEVELS`] where the `.par` leaves them).
pub(crate) struct Levels {
    minor: f64,
    major: f64,
    error: f64,
}

impl Levels {
    pub(crate) fn of(par: &walls_par::check::File) -> Levels {
        let [minor, major, error] = crate::advise::OVERLAP_LEVELS;
        let get =
            |key: &str, default: f64| par.real(key).filter(|x| !x.is_nan()).unwrap_or(default);
        Levels {
            minor: get("dMinorFrac", minor),
            major: get("dMajorFrac", major),
            error: get("dErrorFrac", error),
        }
    }

    /// The level an overlap of `fraction` (of the radius that counts) reaches, worst
    /// first, each strictly above its fraction as pkdgrav compares: the severity, the key
    /// and its value; `None` at or below the minor level.
    pub(crate) fn of_overlap(&self, fraction: f64) -> Option<(Severity, &'static str, f64)> {
        if fraction > self.error {
            Some((Severity::Error, "dErrorFrac", self.error))
        } else if fraction > self.major {
            Some((Severity::Warning, "dMajorFrac", self.major))
        } else if fraction > self.minor {
            Some((Severity::Info, "dMinorFrac", self.minor))
        } else {
            None
        }
    }
}

/// What pkdgrav does at an overlap of `severity`'s level.
pub(crate) fn consequence(severity: Severity) -> &'static str {
    match severity {
        Severity::Error => "pkdgrav aborts at step 0 (an assertion, nothing written)",
        Severity::Warning => "pkdgrav prints a major-overlap warning at step 0 and runs on",
        Severity::Info => "pkdgrav counts a minor overlap at step 0 and runs on",
    }
}
