//! R004 `few-steps-per-contact`: the code, its explanation and examples; walls-sim's
//! `precheck::rules::few_steps` is its check.

use walls_diagnostics::Code;

/// Too few steps per contact.
pub static FEW_STEPS: Code = Code {
    id: "R004",
    name: "few-steps-per-contact",
    summary: "dDelta resolves the stiffest contact of the lightest particle in fewer than 10 steps",
    explanation: concat!(
        "A soft-sphere contact of mass μ and spring k_n lasts π·√(μ/k_n) (μ = m/2 between two
equal particles, m against a wall). pkdgrav's leapfrog needs many steps in it: at 10 the
rebound's restitution is already 4 % off, and at a step of 2/ω or more (ω = √(k_n/μ)) it
gains energy and the run blows up. `walls-lint` takes the lightest particle of the initial
conditions, `dKn` between two of them and each wall's `k_n` against it, and warns at
`dDelta` when the shortest contact has fewer than 10 steps, the rule of `walls-sim advise`.
`walls-sim advise` gives a `dKn` and `dDelta` that fit.

Bad (`ss.ic`: particles of mass 1; with `dKn = 1e5` a pair's contact lasts 7e-3, 7 steps):
```par\n",
        run_par!(),
        "dDelta               = 1e-3
nSteps               = 1000
dKn                  = 1e5
```

Good (a shorter step: 7,000 steps a contact):
```par\n",
        run_par!(),
        "dDelta               = 1e-6
nSteps               = 1000
dKn                  = 1e5
```
"
    ),
};
