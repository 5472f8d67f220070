//! What `walls-sim preview` costs at pkdgrav's real scale (a tube in centimetres
//! converted to AU): one frame of 100,000 particles in each picture format, and a movie
//! of 100 frames of 1,000 particles (100 `.ss` files) as a ParaView collection, an HTML
//! page and SVG frames. The command runs as the binary runs it, from its arguments,
//! writing into a temporary folder. Run with `cargo bench -p walls-cli --bench preview`;
//! the figures are in docs/performance-history.md ("Issue 16: previews at real scale and movies").

use clap::Parser;
use criterion::{Criterion, criterion_group, criterion_main};
use nalgebra::Vector3;
use std::path::{Path, PathBuf};
use walls_cli::commands::sim::preview::{self, PreviewArgs};
use walls_geometry::Particle;

/// `walls-sim preview`'s arguments, parsed as the binary parses them.
#[derive(Parser)]
struct Cli {
    #[command(flatten)]
    args: PreviewArgs,
}

/// 1 cm in AU, as pkdgrav's walls files say.
const CM: f64 = 6.68445e-14;

/// A floor and a tube of radius 10 cm and height 20 cm, in centimetres.
const WALLS: &str = "lengthunit 6.68445e-14\n\
wall type plane\n  color 180\n\
wall type cylinder-finite\n  origin 0 0 10\n  radius 10\n  length 20\n  transparency 0.8\n";

/// `n` particles of radius 0.1 cm on a lattice inside the tube, moved by `shift` cm
/// along x and y (the frames of a movie), coloured by index.
fn particles(n: usize, shift: f64) -> Vec<Particle> {
    let side = (n as f64).cbrt().ceil() as usize;
    let spacing = 10.0 / side as f64;
    (0..n)
        .map(|i| {
            let (a, b, c) = (i % side, (i / side) % side, i / (side * side));
            let pos = Vector3::new(
                -5.0 + spacing * a as f64 + shift,
                -5.0 + spacing * b as f64 + shift,
                1.0 + spacing * c as f64,
            ) * CM;
            let mut p = Particle::at_rest(0.1 * CM, pos, i);
            p.color = 1 + (i % 15) as i32;
            p
        })
        .collect()
}

fn write(path: &Path, bytes: &[u8]) {
    std::fs::write(path, bytes).expect("the temporary folder is writable");
}

/// Runs `walls-sim preview` with `args` (after the program name), asserting success.
fn preview(args: &[String]) {
    let cli = Cli::parse_from(
        std::iter::once("walls-sim-preview".to_string()).chain(args.iter().cloned()),
    );
    let status = preview::run(&cli.args);
    assert_eq!(status, 0, "{args:?}");
}

fn previews(c: &mut Criterion) {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let walls = d.join("walls.dat");
    write(&walls, WALLS.as_bytes());
    let big = d.join("big.ss");
    write(
        &big,
        &walls_sim::io::particles::write_ss(0.0, &particles(100_000, 0.0)),
    );
    let series: Vec<PathBuf> = (0..100)
        .map(|k| {
            let path = d.join(format!("ss.{:05}", 100 * k));
            let t = 1e-9 * k as f64;
            write(
                &path,
                &walls_sim::io::particles::write_ss(t, &particles(1_000, 0.02 * k as f64)),
            );
            path
        })
        .collect();
    let s = |p: &Path| p.display().to_string();

    let mut group = c.benchmark_group("frame-100k");
    group.sample_size(10);
    for ext in ["svg", "vtp", "pov", "html"] {
        let out = d.join(format!("big.{ext}"));
        let args = [
            s(&walls),
            "--particles".into(),
            s(&big),
            "--out".into(),
            s(&out),
        ];
        group.bench_function(ext, |b| b.iter(|| preview(&args)));
    }
    group.finish();

    let mut group = c.benchmark_group("movie-100x1k");
    group.sample_size(10);
    for ext in ["pvd", "html", "svg"] {
        let out = d.join(format!("movie.{ext}"));
        let mut args = vec![s(&walls), "--particles".into()];
        args.extend(series.iter().map(|p| s(p)));
        args.extend(["--out".into(), s(&out)]);
        group.bench_function(ext, |b| b.iter(|| preview(&args)));
    }
    group.finish();
}

criterion_group!(benches, previews);
criterion_main!(benches);
