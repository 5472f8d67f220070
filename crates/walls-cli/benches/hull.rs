//! Generated walls files for benchmarks: a hull of `n` triangle walls, deterministic.

use std::fmt::Write as _;

/// A file of `n` triangle walls with four-decimal coordinates and a comment now and then.
pub fn triangles(n: usize) -> String {
    let mut out = String::with_capacity(n * 110);
    out.push_str("# generated hull\nlengthunit 1\n");
    let mut x: u64 = 0x2545_F491_4F6C_DD1D;
    let mut next = || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        (x % 20_000) as f64 / 1e4 - 1.0
    };
    for i in 0..n {
        if i % 100 == 0 {
            writeln!(out, "# panel {}", i / 100).unwrap();
        }
        writeln!(
            out,
            "wall type triangle\n  origin {:.4} {:.4} {:.4}\n  vertex1 {:.4} {:.4} {:.4}\n  vertex2 {:.4} {:.4} {:.4}",
            next(), next(), next(), next(), next(), next(), next(), next(), next()
        )
        .unwrap();
    }
    out
}
