//! pkdgrav's parameter files (`.par`) as pkdgrav reads them, for a given build: its
//! reader's rules (docs/pkdgrav-physics.md §14), the keys each build registers with
//! their types and defaults (§18, [`keys`]), and what it checks, warns about and
//! changes when it starts (§19, [`startup`]); and what walls-sim does with each key
//! ([`evaluator`]). [`check`] turns a file into diagnostics (`P…` codes, [`codes`]),
//! which walls-lint and the language server report as they report a walls file's;
//! [`write`] writes a file pkdgrav reads as meant.
//!
//! The build is a set of compile options ([`Build`]); the default is pkdgrav's default
//! soft-sphere build with walls ([`options::DEFAULT`]).

/// The lines every code's example `.par` shares (the `.par` rules' and the run
/// directory's), of a run directory pkdgrav's default build runs without a word: the
/// examples add the lines they are about.
macro_rules! settled {
    () => {
        "achInFile            = ss.ic
achWallsFile         = walls.dat
iOutInterval         = 100
iForceOverrideOption = 2
iOutcomes            = 0
bDoSelfGravity       = 0
"
    };
}

pub mod check;
pub mod codes;
pub mod evaluator;
pub mod keys;
pub mod options;
pub mod rules;
pub mod run_codes;
pub mod startup;
pub mod syntax;
pub mod value;
pub mod write;

pub use check::check;

/// The name of `candidates` nearest to `name`, if one is near enough to be a slip: the
/// same letters in another case, or a quarter of them off (at least one). The one
/// "did you mean" of `.par` keys and build options.
pub fn nearest<'a>(name: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    let lower = name.to_ascii_lowercase();
    let budget = (name.len() / 4).max(1);
    candidates
        .into_iter()
        // No edit distance within the budget between names whose lengths differ more.
        .filter(|c| c.len().abs_diff(name.len()) <= budget)
        .map(|c| {
            (
                strsim::damerau_levenshtein(&c.to_ascii_lowercase(), &lower),
                c,
            )
        })
        .filter(|&(d, _)| d <= budget)
        .min_by_key(|&(d, _)| d)
        .map(|(_, c)| c)
}

/// Whether a file named `name` (its last path component) is a pkdgrav parameter file:
/// `.par`, but not `ssdraw.par` in any case (ssdraw's own, labels and values, no
/// `key = value`). walls-lint and the language server decide a file's language by it.
pub fn is_par_file(name: &str) -> bool {
    name.ends_with(".par") && !is_ssdraw_par(name)
}

/// Whether a file named `name` is ssdraw's parameter file, `ssdraw.par` in any case.
pub fn is_ssdraw_par(name: &str) -> bool {
    name.eq_ignore_ascii_case("ssdraw.par")
}
pub use options::{Build, UnknownOption};
pub use startup::KT_PER_KN;
pub use walls_diagnostics::{Diagnostic, Severity};
