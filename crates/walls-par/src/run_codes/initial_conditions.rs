//! R009 `initial-conditions-start-up`: the code, its explanation and examples; walls-sim's
//! `precheck::rules::initial_conditions` is its check.

use walls_diagnostics::Code;

/// What pkdgrav checks of the initial conditions when it starts.
pub static INITIAL_CONDITIONS: Code = Code {
    id: "R009",
    name: "initial-conditions-start-up",
    summary: "pkdgrav's start-up checks of the initial conditions: an aggregate of one particle stops it; a header time other than iStartStep·dDelta is reset, with a warning",
    explanation: concat!(
        "When pkdgrav has read the `.ss` file it checks two things (docs/pkdgrav-startup-checks.md):

* an aggregate (particles with the same negative `org_idx`, in an `AGGS` build) of
  exactly one particle stops it with exit status 1 (A127): an error at that particle;
* the header's time against `iStartStep`·`dDelta`: a time of 0 with `iStartStep` above 0
  becomes `iStartStep`·`dDelta` (B44, and pkdgrav's message prints 0 instead of the new
  time), a time above 0 with `iStartStep` 0 becomes 0 (B45), and any other time that is
  not exactly `iStartStep`·`dDelta` is reset to it (B46): a warning at `iStartStep`
  (walls with a `time`-dependent motion then start where that time puts them).

Bad: a `.ss` file written at t = 0.001 (by a run or a script) for a run of step 0:
```par\n",
        run_par!(),
        "dDelta               = 1e-5
nSteps               = 1000
dKn                  = 1e5
```

The header's time written as `iStartStep`·`dDelta` in doubles (as `walls-sim export`
writes it), or set to 0 with `iStartStep = 0`, is read without a word.

Good: the run continued from its step, the header's time 100·dDelta:
```par\n",
        run_par!(),
        "dDelta               = 1e-5
iStartStep           = 100
nSteps               = 1100
dKn                  = 1e5
```
"
    ),
};
