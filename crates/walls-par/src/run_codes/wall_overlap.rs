//! R002 `initial-wall-overlap`: the code, its explanation and examples; walls-sim's
//! `precheck::rules::wall_overlap` is its check.

use walls_diagnostics::Code;

/// A particle that overlaps a wall at the start.
pub static WALL_OVERLAP: Code = Code {
    id: "R002",
    name: "initial-wall-overlap",
    summary: "a particle of the initial conditions overlaps a wall beyond pkdgrav's dMinorFrac, dMajorFrac or dErrorFrac",
    explanation: concat!(
        "pkdgrav checks every particle against the walls at its first force evaluation, at
step 0: an overlap x = r − d above `dErrorFrac` (default 0.5) of the particle's radius
aborts the run at once, with nothing written; above `dMajorFrac` (0.15) it warns, above
`dMinorFrac` (0.03) it counts a minor overlap. `walls-lint` reports it at the particle
(its record in the `.ss` file, particles numbered from 0 in file order), naming the wall
and its line in the walls file: an error, a warning or an info by the level reached. The
walls are where their motion puts them at the start; a death wall the particle overlaps
deletes it first, a sticky one holds it.

Bad (`walls.dat`: a plane through the origin, normal +z; `ss.ic`: a particle of radius 1 at z = 0.4):
```par\n",
        run_par!(),
        "dDelta               = 1e-7
nSteps               = 1000
dKn                  = 1e5
```

Good (the particle at height 1 or more):
```par\n",
        run_par!(),
        "dDelta               = 1e-7
nSteps               = 1000
dKn                  = 1e5
```
"
    ),
};
