//! Throughput of lexing, parsing and linting generated walls files of 1k, 10k and 100k
//! triangle walls (the 100k file is about 11 MB, a large spacecraft hull). Run with
//! `cargo bench -p walls-cli --bench throughput`; the figures are in docs/performance.md.

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use std::fmt::Write as _;
use std::hint::black_box;
use walls_model::Mode;

/// A file of `n` triangle walls with four-decimal coordinates and a comment now and then.
fn triangles(n: usize) -> String {
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

fn throughput(c: &mut Criterion) {
    for &n in &[1_000usize, 10_000, 100_000] {
        let text = triangles(n);
        let mut group = c.benchmark_group(format!("{}k-walls", n / 1000));
        group.throughput(Throughput::Bytes(text.len() as u64));
        if n == 100_000 {
            group.sample_size(20);
        }
        group.bench_with_input(BenchmarkId::new("lex", text.len()), &text, |b, t| {
            b.iter(|| black_box(walls_syntax::lex(black_box(t))).len())
        });
        group.bench_with_input(BenchmarkId::new("parse", text.len()), &text, |b, t| {
            b.iter(|| {
                black_box(walls_syntax::parse(black_box(t.as_str())))
                    .diagnostics
                    .len()
            })
        });
        group.bench_with_input(BenchmarkId::new("lint", text.len()), &text, |b, t| {
            b.iter(|| {
                black_box(walls_cli::lint_bytes(black_box(t.as_bytes()), Mode::Hsdem))
                    .1
                    .len()
            })
        });
        group.finish();
    }
}

criterion_group!(benches, throughput);
criterion_main!(benches);
