//! R007 `no-output`: the code, its explanation and examples; walls-sim's
//! `precheck::rules::no_output` is its check.

use walls_diagnostics::Code;

/// Outputs that are never (or only once) written.
pub static NO_OUTPUT: Code = Code {
    id: "R007",
    name: "no-output",
    summary: "pkdgrav runs no step and writes nothing (nSteps ≤ iStartStep), or writes only the last step (iOutInterval 0 or longer than the run)",
    explanation: concat!(
        "`nSteps` is the number of the last step, not a count: pkdgrav runs steps
`iStartStep`+1 to `nSteps` and exits with status 0 without a step, or a word, when
`nSteps` is not above `iStartStep`. It writes a full output after each step whose number
`iOutInterval` divides and after the last step always: an `iOutInterval` of 0, or longer
than the run, leaves the last step's output alone, which may be meant (an info).

Bad:
```par\n",
        run_par!(),
        "dDelta               = 1e-7
nSteps               = 1000
iStartStep           = 1000
dKn                  = 1e5
```

Good:
```par\n",
        run_par!(),
        "dDelta               = 1e-7
nSteps               = 2000
iStartStep           = 1000
dKn                  = 1e5
```
"
    ),
};
