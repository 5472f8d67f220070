//! The evaluator's types as command-line values, behind the `clap` feature: the value
//! parsers the run's options ([`crate::config::Flags`]) and the tools' other options
//! share. The types themselves derive `clap::ValueEnum` (`Integrator`, `Sliding`,
//! `advise::UnitSystem`, `advise::Contact`, and walls-geometry's `System` and
//! `OscillationStepping`) or `clap::Args` (the groups of `Flags`) where they are
//! declared.

use crate::build::Build;
use crate::io::par::Rule;
use crate::run::Planning;
use clap::builder::{BoolValueParser, TypedValueParser};

/// A value parser for a number that must obey `rule`, as the `.par` file's values must,
/// read by the tools' one rule for numbers ([`walls_keywords::number`]): overflow and
/// underflow are refused; a subnormal is warned about by the command that takes it.
pub fn ruled(rule: Rule) -> impl Fn(&str) -> Result<f64, String> + Clone {
    move |s| {
        let x = walls_keywords::number::read(s).map_err(|why| format!("`{s}` is {why}"))?;
        rule.check(x).map_err(|says| format!("it must be {says}"))
    }
}

/// `--pkdgrav-build`'s value: pkdgrav's compile options ([`Build::parse`]).
pub fn build(text: &str) -> Result<Build, String> {
    Build::parse(text).map_err(|e| e.to_string())
}

/// `--all-parts`, a flag: every part of the model when given, else those the scene
/// needs.
pub fn all_parts() -> impl TypedValueParser<Value = Planning> {
    BoolValueParser::new().map(|all| {
        if all {
            Planning::Everything
        } else {
            Planning::Needed
        }
    })
}
