//! The model diagnostic codes, each documented once with a bad and a good example.
//!
//! `C1xx` are single values pkdgrav refuses, `C2xx` walls and files that are legal but
//! very likely wrong, `C3xx` reactive walls, `M0xx` what depends on the contact model.
//! The examples are tested: each bad example produces its code, each good example
//! nothing (in the mode, and with the options, the bad example names).

use walls_diagnostics::Code;

/// A unit token is zero or negative.
pub static UNIT_NOT_POSITIVE: Code = Code {
    id: "C101",
    name: "unit-not-positive",
    summary: "a unit token is zero or negative",
    explanation:
        "`lengthunit`, `massunit` and `timeunit` multiply the values read after them and must be
positive. The unit in force is kept when one is not.

Bad:
```walls
lengthunit 0
wall type plane
```

Good:
```walls
lengthunit 6.68458e-14
wall type plane
```
",
};

/// `time` is negative.
pub static NEGATIVE_TIME: Code = Code {
    id: "C102",
    name: "negative-time",
    summary: "`time` is negative",
    explanation:
        "`time` must not be negative (pkdgrav ignores its value, but refuses a negative one).

Bad:
```walls
time -1
wall type plane
```

Good:
```walls
wall type plane
```
",
};

/// A non-zero `time`, which pkdgrav ignores.
pub static TIME_IGNORED: Code = Code {
    id: "C103",
    name: "time-ignored",
    summary: "a non-zero `time`, which pkdgrav ignores",
    explanation:
        "pkdgrav reads `time` but does not use it: to place moving walls at a time, change the
time in the particle (ss) file. This is information, not a mistake.

Bad:
```walls
time 10
wall type plane
```

Good:
```walls
wall type plane
```
",
};

/// `orient`, `osc-vec`, `vertex1` or `vertex2` is the zero vector.
pub static ZERO_VECTOR: Code = Code {
    id: "C104",
    name: "zero-vector",
    summary: "`orient`, `osc-vec`, `vertex1` or `vertex2` is the zero vector",
    explanation:
        "Directions are normalised, so they need a length; vertices of triangles and rectangles
span the shape, so they need one too.

Bad:
```walls
wall type disk
  orient 0 0 0
```

Good:
```walls
wall type disk
  orient 0 0 1
```
",
};

/// A triangle's `vertex1` and `vertex2` are parallel.
pub static DEGENERATE_TRIANGLE: Code = Code {
    id: "C105",
    name: "degenerate-triangle",
    summary: "a triangle's `vertex1` and `vertex2` are parallel",
    explanation:
        "A triangle's normal is vertex1 × vertex2, so the two edges must not be parallel: a
triangle with parallel edges has no area and no normal.

Bad:
```walls
wall type triangle
  vertex1 1 0 0
  vertex2 2 0 0
```

Good:
```walls
wall type triangle
  vertex1 1 0 0
  vertex2 0 1 0
```
",
};

/// A rectangle's `vertex1` and `vertex2` are not perpendicular.
pub static RECTANGLE_NOT_RECTANGULAR: Code = Code {
    id: "C106",
    name: "rectangle-not-rectangular",
    summary: "a rectangle's `vertex1` and `vertex2` are not perpendicular",
    explanation:
        "pkdgrav's rectangles have square corners: |cos| of the angle between vertex1 and vertex2
must be at most 0.001. The fix (unsafe: it moves a vertex) replaces vertex2 by its part
perpendicular to vertex1.

Bad:
```walls
wall type rectangle
  vertex1 0.6 0.6 0
  vertex2 0.6 -0.5 0
```

Good:
```walls
wall type rectangle
  vertex1 0.6 0.6 0
  vertex2 0.6 -0.6 0
```
",
};

/// `step`, `radius`, `hole-radius`, `length` or `mass` is negative.
pub static NEGATIVE_VALUE: Code = Code {
    id: "C107",
    name: "negative-value",
    summary: "`step`, `radius`, `hole-radius`, `length` or `mass` is negative",
    explanation: "These are sizes, a time step and a mass: none may be negative.

Bad:
```walls
wall type disk
  radius -0.5
```

Good:
```walls
wall type disk
  radius 0.5
```
",
};

/// A disk's `hole-radius` is not smaller than its `radius`.
pub static HOLE_NOT_INSIDE: Code = Code {
    id: "C108",
    name: "hole-not-inside",
    summary: "a disk's `hole-radius` is not smaller than its `radius`",
    explanation: "A disk's hole must be smaller than the disk (both may be 0, a point).

Bad:
```walls
wall type disk
  radius 0.5
  hole-radius 0.5
```

Good:
```walls
wall type disk
  radius 0.5
  hole-radius 0.2
```
",
};

/// `taper` is outside 0…1.
pub static TAPER_RANGE: Code = Code {
    id: "C109",
    name: "taper-range",
    summary: "`taper` is outside 0…1",
    explanation:
        "`taper` is the fraction by which a finite cylinder narrows towards +orient: 0 is a plain
cylinder, 1 comes to a point.

Bad:
```walls
wall type cylinder-finite
  taper 1.5
```

Good:
```walls
wall type cylinder-finite
  taper 0.5
```
",
};

/// A tapered finite cylinder has length 0.
pub static TAPER_ON_RING: Code = Code {
    id: "C110",
    name: "taper-on-ring",
    summary: "a tapered finite cylinder has length 0",
    explanation: "A finite cylinder of length 0 is a ring, which cannot taper.

Bad:
```walls
wall type cylinder-finite
  length 0
  taper 0.5
```

Good:
```walls
wall type cylinder-finite
  length 1
  taper 0.5
```
",
};

/// `open-angle` is outside 0…180 degrees.
pub static OPEN_ANGLE_RANGE: Code = Code {
    id: "C111",
    name: "open-angle-range",
    summary: "`open-angle` is outside 0…180 degrees",
    explanation:
        "A shell's opening is a cap of half-angle `open-angle` degrees centred on +orient: 0 is a
closed sphere, 90 a hemisphere, 180 nothing left.

Bad:
```walls
wall type shell
  open-angle 270
```

Good:
```walls
wall type shell
  open-angle 90
```
",
};

/// `osc-phase` is outside 0…1.
pub static OSC_PHASE_RANGE: Code = Code {
    id: "C112",
    name: "osc-phase-range",
    summary: "`osc-phase` is outside 0…1",
    explanation:
        "The phase is a fraction of a cycle, from 0 to 1 (0.75 starts the wall at the bottom of
its cycle).

Bad:
```walls
wall type plane
  osc-ampl 0.1
  osc-freq 2
  osc-phase 1.25
```

Good:
```walls
wall type plane
  osc-ampl 0.1
  osc-freq 2
  osc-phase 0.25
```
",
};

/// `osc-freq` is negative.
pub static NEGATIVE_OSC_FREQ: Code = Code {
    id: "C113",
    name: "negative-osc-freq",
    summary: "`osc-freq` is negative",
    explanation: "The document allows a negative frequency but pkdgrav rejects it. Since
A·sin(−ωt + 2πφ) = (−A)·sin(ωt + 2π(1−φ)), the same motion is written with frequency
|ω|, amplitude −A and phase (1−φ) mod 1; the fix (safe) writes exactly that, editing the
amplitude and phase where the same block sets them and adding them after the frequency
otherwise.

Bad:
```walls
wall type plane
  osc-ampl 0.1
  osc-freq -2
  osc-phase 0.25
```

Good:
```walls
wall type plane
  osc-ampl -0.1
  osc-freq 2
  osc-phase 0.75
```
",
};

/// `epsn` is above 1 (and not 99).
pub static EPSN_RANGE: Code = Code {
    id: "C114",
    name: "epsn-range",
    summary: "`epsn` is above 1 (and not 99)",
    explanation:
        "The normal coefficient of restitution is at most 1 (elastic); 0 sticks, a negative value
removes the particle, and 99 means \"use the particle's value\".

Bad:
```walls
wall type plane
  epsn 1.2
```

Good:
```walls
wall type plane
  epsn 0.8
```
",
};

/// `epst` is outside its range for the contact model.
pub static EPST_RANGE: Code = Code {
    id: "C115",
    name: "epst-range",
    summary: "`epst` is outside its range for the contact model",
    explanation:
        "The tangential coefficient of restitution is −1…1 in HSDEM and 0…1 in SSDEM, or 99 for
the particle's value.

Bad:
```walls
wall type plane
  epst -0.5
```

Good:
```walls
wall type plane
  epst 0.5
```
",
};

/// `color` is outside 0…255.
pub static COLOR_RANGE: Code = Code {
    id: "C116",
    name: "color-range",
    summary: "`color` is outside 0…255",
    explanation:
        "Colours are ssdraw's palette indices, 0 to 255 (0 is not drawn, 1–15 named colours,
16–255 greys).

Bad:
```walls
wall type plane
  color 300
```

Good:
```walls
wall type plane
  color 3
```
",
};

/// `transparency` is outside 0…100.
pub static TRANSPARENCY_RANGE: Code = Code {
    id: "C117",
    name: "transparency-range",
    summary: "`transparency` is outside 0…100",
    explanation:
        "Transparency is a fraction from 0 to 1, or a percentage above 1 up to 100 (divided by
100).

Bad:
```walls
wall type plane
  transparency 150
```

Good:
```walls
wall type plane
  transparency 50
```
",
};

/// A spring constant, friction or cohesion value is negative (and not −1).
pub static MATERIAL_RANGE: Code = Code {
    id: "C118",
    name: "material-range",
    summary: "a spring constant, friction or cohesion value is negative (and not −1)",
    explanation:
        "`k_n`, `k_t`, `mu_s`, `mu_r`, `mu_t`, `beta_s`, `cohesive_coeff` and the two-layer
tokens are −1 (use the particle's value) or at least 0.

Bad:
```walls
wall type plane
  mu_s -0.5
```

Good:
```walls
wall type plane
  mu_s 0.5
```
",
};

/// `cohesion_model` is not −1, 0 or 1.
pub static COHESION_MODEL: Code = Code {
    id: "C119",
    name: "cohesion-model",
    summary: "`cohesion_model` is not −1, 0 or 1",
    explanation:
        "−1 uses the particle's model, 0 is the microscopic contact model, 1 the cohesive bridge
model.

Bad:
```walls
wall type plane
  cohesion_model 2
```

Good:
```walls
wall type plane
  cohesion_model 1
```
",
};

/// A value overflows a double once scaled by its unit.
pub static NUMBER_TOO_LARGE: Code = Code {
    id: "C120",
    name: "number-too-large",
    summary: "a value overflows a double once scaled by its unit",
    explanation:
        "A value such as `1e999`, or a large value times a large unit, is infinite as a double;
the value is ignored.

Bad:
```walls
wall type disk
  radius 1e999
```

Good:
```walls
wall type disk
  radius 1e9
```
",
};

/// A wall sets a token its type does not use.
pub static IGNORED_BY_TYPE: Code = Code {
    id: "C201",
    name: "ignored-by-type",
    summary: "a wall sets a token its type does not use",
    explanation:
        "Each wall type reads only some tokens (SPEC §1): a plane has no radius, a triangle no
orient (its normal is vertex1 × vertex2). The value is ignored, which usually means the
type is not the one intended. Judged by the wall's final type; values inherited from
`defaults` are not reported. The fix (safe: the value has no effect) removes the token.

Bad:
```walls
wall type plane
  radius 2
```

Good:
```walls
wall type disk
  radius 2
```
",
};

/// A token is set twice in one block.
pub static REPEATED_TOKEN: Code = Code {
    id: "C202",
    name: "repeated-token",
    summary: "a token is set twice in one block",
    explanation:
        "The last value wins, so the earlier one has no effect. The fix (safe) removes the earlier
one.

Bad:
```walls
wall type disk
  radius 1
  radius 2
```

Good:
```walls
wall type disk
  radius 2
```
",
};

/// `k_t` is set before `k_n` in one block, so `k_n` overwrites it.
pub static KT_BEFORE_KN: Code = Code {
    id: "C203",
    name: "k-t-before-k-n",
    summary: "`k_t` is set before `k_n` in one block, so `k_n` overwrites it",
    explanation:
        "Setting `k_n` also sets `k_t` to 2/7 of it. A `k_t` written before the `k_n` of the
same block is therefore lost; write it after. The same holds for `k_t_outer`/`k_n_outer`
and `k_t_inner`/`k_n_inner`.

Bad:
```walls
wall type plane
  k_t 3
  k_n 7
```

Good:
```walls
wall type plane
  k_n 7
  k_t 3
```
",
};

/// A wall has an oscillation amplitude but no frequency, or the reverse.
pub static LONE_OSCILLATION: Code = Code {
    id: "C204",
    name: "lone-oscillation",
    summary: "a wall has an oscillation amplitude but no frequency, or the reverse",
    explanation: "The wall moves by A·sin(ωt + 2πφ): with A or ω zero it does not oscillate at all.

Bad:
```walls
wall type plane
  osc-ampl 0.1
```

Good:
```walls
wall type plane
  osc-ampl 0.1
  osc-freq 2
```
",
};

/// An oscillating wall still shakes along +z although its normal is not +z.
pub static OSC_VEC_NOT_FOLLOWING_ORIENT: Code = Code {
    id: "C205",
    name: "osc-vec-not-following-orient",
    summary: "an oscillating wall still shakes along +z although its normal is not +z",
    explanation:
        "`osc-vec` defaults to the *initial* orient, 0 0 1, and does not follow a later `orient`
(or a triangle's or rectangle's normal). A wall tilted away from z that oscillates without
an `osc-vec` therefore shakes along z. The fix (unsafe: you may want z) sets `osc-vec` to
the wall's normal.

Bad:
```walls
wall type plane
  orient 1 0 0
  osc-ampl 0.1
  osc-freq 2
```

Good:
```walls
wall type plane
  orient 1 0 0
  osc-vec 1 0 0
  osc-ampl 0.1
  osc-freq 2
```
",
};

/// A sticky wall (`epsn 0`) comes after a non-sticky one.
pub static STICKY_WALL_ORDER: Code = Code {
    id: "C206",
    name: "sticky-wall-order",
    summary: "a sticky wall (`epsn 0`) comes after a non-sticky one",
    explanation:
        "pkdgrav stores the index of the wall a particle sticks to. If the number or order of
walls before a sticky wall changes between runs, stuck particles end up on the wrong wall,
so the document asks for sticky walls to be listed first.

Bad:
```walls
wall type plane
  epsn 0.5
wall type disk
  epsn 0
```

Good:
```walls
wall type disk
  epsn 0
wall type plane
  epsn 0.5
```
",
};

/// A `defaults` value that no later wall inherits.
pub static UNUSED_DEFAULT: Code = Code {
    id: "C207",
    name: "unused-default",
    summary: "a `defaults` value that no later wall inherits",
    explanation:
        "A default reaches only the walls created after it, and only those that do not set the
token themselves. One that no wall inherits has no effect: it comes after the last wall,
every later wall overrides it, or another default replaces it first. The fix (safe)
removes it.

Bad:
```walls
wall type plane
defaults color 3
```

Good:
```walls
defaults color 3
wall type plane
```
",
};

/// The file defines no wall.
pub static NO_WALLS: Code = Code {
    id: "C208",
    name: "no-walls",
    summary: "the file defines no wall",
    explanation:
        "A walls file without a `wall` token gives pkdgrav nothing to do; usually the file is
empty or was cut short.

Bad:
```walls
lengthunit 2
```

Good:
```walls
wall type plane
```
",
};

/// More walls than pkdgrav's compile-time limit.
pub static TOO_MANY_WALLS: Code = Code {
    id: "C209",
    name: "too-many-walls",
    summary: "more walls than pkdgrav's compile-time limit",
    explanation:
        "pkdgrav holds at most MAX_NUM_WALLS walls, 20 unless it was compiled with more. Set the
limit of your build with `--max-walls N`.

Bad (with `--max-walls 1`):
```walls
wall type plane
wall type disk
```

Good:
```walls
wall type plane
```
",
};

/// In SSDEM, a wall moves too far in one step against the smallest particle.
pub static WALL_TOO_FAST: Code = Code {
    id: "C210",
    name: "wall-too-fast",
    summary: "in SSDEM, a wall moves too far in one step against the smallest particle",
    explanation:
        "In SSDEM the wall's top speed (|velocity| + |osc-ampl·osc-freq| + |ang-speed|·radius)
times its update step (`step`, or the timestep `--dt` when step is 0) should be small
against the smallest particle radius, or overlaps grow large. Checked when
`--min-radius R` is given; the limit is 3 % of R, the first overlap pkdgrav warns about.
Spinning planes are not checked (their rim is at infinity).

Bad (with `--min-radius 0.01`):
```walls
wall type plane
  velocity 0 0 1
  step 0.01
```

Good:
```walls
wall type plane
  velocity 0 0 1
  step 0.0001
```
",
};

/// A reactive wall (with a mass) is a plane or an infinite cylinder.
pub static REACTIVE_TYPE: Code = Code {
    id: "C301",
    name: "reactive-type",
    summary: "a reactive wall (with a mass) is a plane or an infinite cylinder",
    explanation:
        "Only triangles, rectangles, finite cylinders, disks and shells can have a finite mass and
react to particles.

Bad:
```walls
wall type plane
  mass 1
  assembly 0
```

Good:
```walls
wall type disk
  mass 1
  assembly 0
```
",
};

/// A reactive wall has an `ang-speed`.
pub static REACTIVE_SPINNING: Code = Code {
    id: "C302",
    name: "reactive-spinning",
    summary: "a reactive wall has an `ang-speed`",
    explanation: "A reactive wall's rotation comes from `rot-vec` and the torques on its assembly;
`ang-speed` must be 0.

Bad:
```walls
wall type disk
  mass 1
  assembly 0
  ang-speed 2
```

Good:
```walls
wall type disk
  mass 1
  assembly 0
  rot-vec 0 0 2
```
",
};

/// A wall in an assembly has no mass.
pub static ASSEMBLY_WITHOUT_MASS: Code = Code {
    id: "C303",
    name: "assembly-without-mass",
    summary: "a wall in an assembly has no mass",
    explanation: "Every wall of an assembly needs a mass; the assembly's mass is their sum.

Bad:
```walls
wall type disk
  assembly 0
```

Good:
```walls
wall type disk
  mass 1
  assembly 0
```
",
};

/// A wall has a mass but no assembly.
pub static MASS_WITHOUT_ASSEMBLY: Code = Code {
    id: "C304",
    name: "mass-without-assembly",
    summary: "a wall has a mass but no assembly",
    explanation: "The document asks every inertial wall to be given an assembly, 0 or 1.

Bad:
```walls
wall type disk
  mass 1
```

Good:
```walls
wall type disk
  mass 1
  assembly 0
```
",
};

/// `assembly` is not 0 or 1.
pub static INVALID_ASSEMBLY: Code = Code {
    id: "C305",
    name: "invalid-assembly",
    summary: "`assembly` is not 0 or 1",
    explanation:
        "pkdgrav allows two assemblies (MAX_NUM_WALL_ASSEMBLIES is 2), numbered 0 and 1. The
default −1 (no assembly) cannot be written explicitly: leave `assembly` out instead.

Bad:
```walls
wall type disk
  mass 1
  assembly 2
```

Good:
```walls
wall type disk
  mass 1
  assembly 1
```
",
};

/// A principal axis is not a unit vector.
pub static AXIS_NOT_UNIT: Code = Code {
    id: "C306",
    name: "axis-not-unit",
    summary: "a principal axis is not a unit vector",
    explanation:
        "`pxj-vec`, `pyj-vec` and `pzj-vec` must each have length 1 ± 0.001. The fix (unsafe)
normalises the axis.

Bad:
```walls
wall type disk
  pxj-vec 2 0 0
```

Good:
```walls
wall type disk
  pxj-vec 1 0 0
```
",
};

/// A reactive wall's principal axes are not mutually orthogonal.
pub static AXES_NOT_ORTHOGONAL: Code = Code {
    id: "C307",
    name: "axes-not-orthogonal",
    summary: "a reactive wall's principal axes are not mutually orthogonal",
    explanation:
        "The principal axes should form an orthonormal basis; checked for reactive walls, with
|cos| above 0.001 reported.

Bad:
```walls
wall type disk
  mass 1
  assembly 0
  pyj-vec 0.6 0.8 0
```

Good:
```walls
wall type disk
  mass 1
  assembly 0
  pyj-vec 0 1 0
```
",
};

/// The inertia tensor has off-diagonal terms.
pub static INERTIA_OFF_DIAGONAL: Code = Code {
    id: "C308",
    name: "inertia-off-diagonal",
    summary: "the inertia tensor has off-diagonal terms",
    explanation:
        "pkdgrav uses only the diagonal of the inertia tensor given by `ixj-vec`, `iyj-vec` and
`izj-vec`: give it in the principal frame.

Bad:
```walls
wall type disk
  ixj-vec 0.2 0.1 0
```

Good:
```walls
wall type disk
  ixj-vec 0.2 0 0
```
",
};

/// A wall type or token that pkdgrav's hard-sphere (HSDEM) code does not implement.
pub static NOT_IN_HSDEM: Code = Code {
    id: "M001",
    name: "not-in-hsdem",
    summary: "a wall type or token that pkdgrav's hard-sphere (HSDEM) code does not implement",
    explanation:
        "pkdgrav implements triangle and shell walls, and the `taper` of finite cylinders, only
in its soft-sphere (SSDEM) code; a hard-sphere run refuses them. Judged per wall, by its
final type, with `--mode hsdem`.

Bad (with `--mode hsdem`):
```walls
defaults epsn 0.9 epst 1
wall type triangle
```

Good:
```walls
defaults epsn 0.9 epst 1
wall type rectangle
```
",
};

/// A soft-sphere (SSDEM) token that a hard-sphere (HSDEM) run ignores.
pub static IGNORED_IN_HSDEM: Code = Code {
    id: "M002",
    name: "ignored-in-hsdem",
    summary: "a soft-sphere (SSDEM) token that a hard-sphere (HSDEM) run ignores",
    explanation:
        "Spring constants (`k_n`, `k_t` and the two-layer `*_inner`/`*_outer` tokens), friction
(`mu_s`, `mu_r`, `mu_t`, `beta_s`), cohesion and the reactive-wall tokens (`mass`, `cog`,
`rot-vec`, inertia, principal axes, `assembly`) are read only by pkdgrav's soft-sphere
code. In a hard-sphere run they change nothing. Checked with `--mode hsdem`.

Bad (with `--mode hsdem`):
```walls
defaults epsn 0.9 epst 1
wall type plane
  k_n 1e5
```

Good:
```walls
defaults epsn 0.9 epst 1
wall type plane
```
",
};

/// In HSDEM, a wall leaves `epsn` or `epst` at 99.
pub static HSDEM_PARTICLE_VALUE: Code = Code {
    id: "M003",
    name: "hsdem-particle-value",
    summary: "in HSDEM, a wall leaves `epsn` or `epst` at 99",
    explanation:
        "99 means \"use the particle's value\" in SSDEM, but pkdgrav's hard-sphere code never
substitutes it: 99 is used as the coefficient itself. Every wall of a hard-sphere run
needs real `epsn` and `epst` values (a `defaults` line is the easy way).

Bad (with `--mode hsdem`):
```walls
wall type plane
```

Good:
```walls
defaults epsn 0.9 epst 1
wall type plane
```
",
};

/// Every model code, in code order.
pub static ALL: &[&Code] = &[
    &UNIT_NOT_POSITIVE,
    &NEGATIVE_TIME,
    &TIME_IGNORED,
    &ZERO_VECTOR,
    &DEGENERATE_TRIANGLE,
    &RECTANGLE_NOT_RECTANGULAR,
    &NEGATIVE_VALUE,
    &HOLE_NOT_INSIDE,
    &TAPER_RANGE,
    &TAPER_ON_RING,
    &OPEN_ANGLE_RANGE,
    &OSC_PHASE_RANGE,
    &NEGATIVE_OSC_FREQ,
    &EPSN_RANGE,
    &EPST_RANGE,
    &COLOR_RANGE,
    &TRANSPARENCY_RANGE,
    &MATERIAL_RANGE,
    &COHESION_MODEL,
    &NUMBER_TOO_LARGE,
    &IGNORED_BY_TYPE,
    &REPEATED_TOKEN,
    &KT_BEFORE_KN,
    &LONE_OSCILLATION,
    &OSC_VEC_NOT_FOLLOWING_ORIENT,
    &STICKY_WALL_ORDER,
    &UNUSED_DEFAULT,
    &NO_WALLS,
    &TOO_MANY_WALLS,
    &WALL_TOO_FAST,
    &REACTIVE_TYPE,
    &REACTIVE_SPINNING,
    &ASSEMBLY_WITHOUT_MASS,
    &MASS_WITHOUT_ASSEMBLY,
    &INVALID_ASSEMBLY,
    &AXIS_NOT_UNIT,
    &AXES_NOT_ORTHOGONAL,
    &INERTIA_OFF_DIAGONAL,
    &NOT_IN_HSDEM,
    &IGNORED_IN_HSDEM,
    &HSDEM_PARTICLE_VALUE,
];
