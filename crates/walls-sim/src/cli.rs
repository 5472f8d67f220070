//! The evaluator's types as command-line values, behind the `clap` feature: what a
//! derive on the type itself cannot say. [`Integrator`]'s values are listed with
//! pkdgrav's step first (the default) and explicit Euler as `euler`; the other types
//! (`Sliding`, `advise::UnitSystem`, `advise::Contact`, and walls-geometry's `System`
//! and `OscillationStepping`) derive `clap::ValueEnum` where they are declared.

use crate::run::Integrator;
use clap::builder::PossibleValue;

impl clap::ValueEnum for Integrator {
    fn value_variants<'a>() -> &'a [Self] {
        &[
            Integrator::Pkdgrav,
            Integrator::Leapfrog,
            Integrator::LeapfrogPredicted,
            Integrator::ExplicitEuler,
        ]
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        let (name, help) = match self {
            Integrator::Pkdgrav => (
                "pkdgrav",
                "pkdgrav's step order and contact law (docs/pkdgrav-physics.md §1–§2, §5)",
            ),
            Integrator::Leapfrog => ("leapfrog", "Kick-drift-kick leapfrog"),
            Integrator::LeapfrogPredicted => (
                "leapfrog-predicted",
                "Kick-drift-kick with the dashpot at the velocity predicted to the step's end",
            ),
            Integrator::ExplicitEuler => ("euler", "Explicit Euler"),
        };
        Some(PossibleValue::new(name).help(help))
    }
}
