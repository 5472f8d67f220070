//! C104 `zero-vector`: `orient`, `osc-vec`, `vertex1` or `vertex2` is the zero vector.
//!
//! Checked as the vector is read: `ValueRange::Direction` (normalised when not zero) and
//! `ValueRange::NonZero`.

use super::Read;
use crate::scene::{Value, Vec3, direction};
use walls_diagnostics::{Code, Diagnostic};

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

/// A direction (`orient`, `osc-vec`): the value to store, normalised, or reported and
/// kept as written when it is zero.
pub(crate) fn direction_of(at: &Read, v: Vec3, out: &mut Vec<Diagnostic>) -> Value {
    match direction(&v) {
        Some(n) => Value::Vector(n),
        None => {
            report(at, out);
            Value::Vector(v)
        }
    }
}

/// A vector that must not be zero (`vertex1`, `vertex2`).
pub(crate) fn non_zero(at: &Read, v: Vec3, out: &mut Vec<Diagnostic>) {
    if v.norm() == 0.0 {
        report(at, out);
    }
}

fn report(at: &Read, out: &mut Vec<Diagnostic>) {
    out.push(Diagnostic::error(
        &ZERO_VECTOR,
        at.span.clone(),
        format!(
            "`{}` is the zero vector; it must have a direction",
            at.keyword.name()
        ),
    ));
}
