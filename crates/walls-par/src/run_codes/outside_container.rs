//! R003 `outside-container`: the code, its explanation and examples; walls-sim's
//! `precheck::rules::outside_container` is its check.

use walls_diagnostics::Code;

/// A particle outside the container that holds the others.
pub static OUTSIDE_CONTAINER: Code = Code {
    id: "R003",
    name: "outside-container",
    summary: "a particle lies outside the closed wall (an infinite cylinder or a closed shell) that holds the other particles",
    explanation: concat!(
        "A particle placed outside the cylinder or shell that holds the rest of the initial
conditions never meets them: it stays out, or falls away, and a run that was to follow it
follows nothing. Only walls that close a region are containers (an infinite cylinder, a
shell with `open-angle 0`); a container holds the particles when at least nine in ten of
them lie wholly inside it, and the others are reported, each at its record in the `.ss`
file, when they lie wholly outside.

Bad (`walls.dat`: a cylinder-infinite of radius 10 along z; `ss.ic`: nine particles of radius 1 on its axis, one at x = 20):
```par\n",
        run_par!(),
        "dDelta               = 1e-7
nSteps               = 1000
dKn                  = 1e5
```

Good (the tenth particle inside too):
```par\n",
        run_par!(),
        "dDelta               = 1e-7
nSteps               = 1000
dKn                  = 1e5
```
"
    ),
};
