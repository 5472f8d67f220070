//! Throughput of lexing, parsing, linting and formatting generated walls files of 1k, 10k and 100k
//! triangle walls (the 100k file is about 11 MB, a large spacecraft hull). Run with
//! `cargo bench -p walls-cli --bench throughput`; the figures are in docs/performance.md.
//! Lint runs in the default SSDEM mode, where the generated triangle hull is valid.

use criterion::{BatchSize, BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use std::hint::black_box;
use walls_model::Options;

mod hull;
use hull::triangles;

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
            b.iter_batched(
                || t.as_bytes().to_vec(),
                |bytes| {
                    walls_cli::check_bytes(black_box(bytes), &Options::default())
                        .diagnostics
                        .len()
                },
                BatchSize::LargeInput,
            )
        });
        group.bench_with_input(BenchmarkId::new("format", text.len()), &text, |b, t| {
            let options = walls_format::FormatOptions::default();
            b.iter(|| {
                let parsed = walls_syntax::parse(black_box(t.as_str()));
                walls_format::format(&parsed, &options)
                    .map(|f| f.text.len())
                    .unwrap_or_default()
            })
        });
        group.finish();
    }
}

criterion_group!(benches, throughput);
criterion_main!(benches);
