//! R006 `token-needs-build`: the code, its explanation and examples; walls-sim's
//! `precheck::rules::build_lacks` is its check.

use walls_diagnostics::Code;

/// A token the build does not follow.
pub static BUILD_LACKS: Code = Code {
    id: "R006",
    name: "token-needs-build",
    summary: "a walls-file token needs a pkdgrav compile option the build lacks (DEM_COHESION, DEM_TWOLAYERS, DEM_WALLS_REACT)",
    explanation: concat!(
        "Some wall tokens only do something in a pkdgrav built for them: `cohesion_model` and
`cohesive_coeff` with `DEM_COHESION`, `inner_overlap_boundary` and the `k_n_outer`,
`k_t_outer`, `k_n_inner`, `k_t_inner` of two-layer contacts with `DEM_TWOLAYERS`, a
wall's `mass` (with its `assembly`) with `DEM_WALLS_REACT`. A build without the option
runs as if they were not there: the cohesion is never felt, the wall never reacts.
`walls-lint` reports each such token of a run directory's walls file for the
`--pkdgrav-build` build (or the settings' `[run] pkdgrav-build`).

Bad (`walls.dat`: a plane with `cohesive_coeff 1e-3`; the default build, no DEM_COHESION):
```par\n",
        run_par!(),
        "dDelta               = 1e-7
nSteps               = 1000
dKn                  = 1e5
```

Good (checked with `--pkdgrav-build \"DEM DEM_FIXED_BALL DEM_ROTATION_DASHPOT DEM_COHESION\"`):
```par\n",
        run_par!(),
        "dDelta               = 1e-7
nSteps               = 1000
dKn                  = 1e5
```
"
    ),
};
