//! R008 `step-wider-than-ndigits`: the code, its explanation and examples; walls-sim's
//! `precheck::rules::wide_steps` is its check.

use walls_diagnostics::Code;

/// Step numbers wider than `nDigits`.
pub static WIDE_STEPS: Code = Code {
    id: "R008",
    name: "step-wider-than-ndigits",
    summary: "nSteps has more digits than nDigits: the output names grow wider and stop sorting in step order",
    explanation: concat!(
        "pkdgrav names a full output `achOutName.%0<nDigits>d`, its step number padded with
zeros to `nDigits` digits (default 5). A step number with more digits is written whole:
`ss.99999` is followed by `ss.100000`, which sorts before it, and scripts that expect one
width (`ss.?????`) miss the later outputs.

Bad:
```par\n",
        run_par!(),
        "dDelta               = 1e-7
nSteps               = 200000
dKn                  = 1e5
```

Good:
```par\n",
        run_par!(),
        "dDelta               = 1e-7
nSteps               = 200000
nDigits              = 6
dKn                  = 1e5
```
"
    ),
};
