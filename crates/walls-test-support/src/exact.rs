//! Numbers compared to the last bit, for the tests that hold two ways of computing
//! something to the same result (the contact law four at a time against one at a time):
//! −0 and 0 apart, and any NaN as one, since Rust leaves the sign and payload of a NaN
//! an operation makes unspecified and the compiler may order a multiplication's operands
//! either way.

use nalgebra::Vector3;

/// `x`'s bits, any NaN as one.
pub fn number(x: f64) -> u64 {
    if x.is_nan() { u64::MAX } else { x.to_bits() }
}

/// [`number`] of each component of `v`.
pub fn bits(v: Vector3<f64>) -> [u64; 3] {
    [number(v.x), number(v.y), number(v.z)]
}
