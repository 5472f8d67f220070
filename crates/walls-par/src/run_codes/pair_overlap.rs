//! R001 `initial-pair-overlap`: the code, its explanation and examples; walls-sim's
//! `precheck::rules::pair_overlap` is its check.

use walls_diagnostics::Code;

/// Two particles that overlap at the start.
pub static PAIR_OVERLAP: Code = Code {
    id: "R001",
    name: "initial-pair-overlap",
    summary: "two particles of the initial conditions overlap beyond pkdgrav's dMinorFrac, dMajorFrac or dErrorFrac",
    explanation: concat!(
        "pkdgrav checks every touching pair at its first force evaluation, at step 0: an
overlap x = r₁ + r₂ − d above `dErrorFrac` (default 0.5) of the smaller radius aborts the
run at once, with nothing written; above `dMajorFrac` (0.15) it warns, above `dMinorFrac`
(0.03) it counts a minor overlap. `walls-lint` reports the pair at the first particle
(its record in the `.ss` file, particles numbered from 0 in file order) and names the
other: an error, a warning or an info by the level reached. Members of one aggregate
(`AGGS`) and two stuck particles do not interact and are skipped.

Bad (`ss.ic`: two particles of radius 1, their centres 0.9 apart):
```par\n",
        run_par!(),
        "dDelta               = 1e-7
nSteps               = 1000
dKn                  = 1e5
```

Good (the centres 2 apart, or `dErrorFrac` raised above the overlap):
```par\n",
        run_par!(),
        "dDelta               = 1e-7
nSteps               = 1000
dKn                  = 1e5
```
"
    ),
};
