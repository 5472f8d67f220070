//! The checks of a run directory, one code a file (`R…`): each file holds its check;
//! its code (the `Code`, with the explanation and the bad and good examples) is in
//! walls-par's `run_codes`, of the same name, below the registry. The tests of
//! [`super`] build each example and check it.

pub mod build_lacks;
pub mod few_steps;
pub mod initial_conditions;
pub mod no_output;
pub mod outside_container;
pub mod pair_overlap;
pub mod wall_overlap;
pub mod wall_too_fast;
pub mod wide_steps;

use walls_diagnostics::Severity;

/// Every `R…` code, in code order.
pub use walls_par::run_codes::ALL;

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
