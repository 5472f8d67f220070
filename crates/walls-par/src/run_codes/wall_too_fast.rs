//! R005 `wall-too-fast-for-particles`: the code, its explanation and examples; walls-sim's
//! `precheck::rules::wall_too_fast` is its check.

use walls_diagnostics::Code;

/// A wall too fast for the particles.
pub static WALL_TOO_FAST: Code = Code {
    id: "R005",
    name: "wall-too-fast-for-particles",
    summary: "a wall moves more than a tenth of the smallest particle radius in one step",
    explanation: concat!(
        "pkdgrav moves a wall by its speed times its `step` (a `step` of 0 is `dDelta`) and
then looks for contacts: a wall that moves more than a tenth of the smallest radius in one
jump starts its contacts deep, and a thin particle can be stepped over. `walls-lint`
takes the wall's fastest speed (translation, oscillation, rotation at its rim) and the
smallest particle of the initial conditions, as the evaluator's W203 does.

Bad (`walls.dat`: a plane with `velocity 0 0 1000`; `ss.ic`: particles of radius 1):
```par\n",
        run_par!(),
        "dDelta               = 1e-3
nSteps               = 1000
dKn                  = 1e5
```

Good (a step a thousand times shorter):
```par\n",
        run_par!(),
        "dDelta               = 1e-6
nSteps               = 1000
dKn                  = 1e5
```
"
    ),
};
