//! The model diagnostic codes (`M…`), each documented once with a bad and a good example.

use walls_diagnostics::Code;

/// A wall type or token that pkdgrav's hard-sphere code does not implement.
pub static NOT_IN_HSDEM: Code = Code {
    id: "M001",
    name: "not-in-hsdem",
    summary: "a wall type or token that pkdgrav's hard-sphere (HSDEM) code does not implement",
    explanation: "pkdgrav implements triangle and shell walls, and the `taper` of finite \
cylinders, only in its soft-sphere (SSDEM) code; a hard-sphere run refuses them. Checked \
with `--mode hsdem`.

Bad (with `--mode hsdem`):
```walls
wall type triangle
```

Good:
```walls
wall type rectangle
```
",
};

/// A token that only the soft-sphere code reads.
pub static IGNORED_IN_HSDEM: Code = Code {
    id: "M002",
    name: "ignored-in-hsdem",
    summary: "a soft-sphere (SSDEM) token that a hard-sphere (HSDEM) run ignores",
    explanation: "Spring constants (`k_n`, `k_t` and the two-layer `*_inner`/`*_outer` \
tokens), friction (`mu_s`, `mu_r`, `mu_t`, `beta_s`), cohesion and the reactive-wall \
tokens (`mass`, `cog`, `rot-vec`, inertia, principal axes, `assembly`) are read only by \
pkdgrav's soft-sphere code. In a hard-sphere run they change nothing. Checked with \
`--mode hsdem`.

Bad (with `--mode hsdem`):
```walls
wall type plane
  k_n 1e5
```

Good:
```walls
wall type plane
```
",
};

/// Every model code, in code order.
pub static ALL: &[&Code] = &[&NOT_IN_HSDEM, &IGNORED_IN_HSDEM];
