//! The run's JSON (`walls-sim run --json`), written as it is serialised: the same bytes
//! as the document built whole as a `serde_json::Value`, whose map sorts the keys, for a
//! run of many particles with every kind of event, particles stuck and removed, warnings
//! and the output files, and for numbers JSON cannot hold (null) and −0; and a writer
//! that fails ends it with its error.

use nalgebra::Vector3;
use walls_geometry::Particle;
use walls_sim::report::{Report, model};
use walls_sim::run::{EventKind, ParticleMaterial, Settings, run};
use walls_test_support::scene;

/// A floor that keeps 80 % of the normal speed, a sticky ledge (wall 1) and a death
/// ledge (wall 2) above it.
const WALLS: &str = "wall type plane\n  epsn 0.8\n\
    wall type disk\n  origin 2 0 0.1\n  radius 0.6\n  epsn 0\n\
    wall type disk\n  origin 4 0 0.1\n  radius 0.6\n  epsn -1\n";

/// 30 × 20 particles of radius 0.05 falling at different speeds over the floor and both
/// ledges, with some spin; the last with a negative colour that names no wall.
fn particles() -> Vec<Particle> {
    let mut out: Vec<Particle> = (0..600)
        .map(|k| {
            let (i, j) = (k % 30, k / 30);
            let pos = Vector3::new(-0.5 + 0.2 * i as f64, -0.5 + 0.05 * j as f64, 0.4);
            Particle {
                vel: Vector3::new(0.0, 0.0, -1.0 - 0.01 * k as f64),
                spin: Vector3::new(0.0, 0.0, 0.1 * j as f64),
                ..Particle::at_rest(0.02, pos, k)
            }
        })
        .collect();
    if let Some(last) = out.last_mut() {
        last.color = -10;
    }
    out
}

#[test]
fn a_streamed_report_is_the_document_built_whole() {
    let walls = scene(WALLS);
    let particles = particles();
    let settings = Settings::new(
        1e-4,
        0.5,
        ParticleMaterial {
            eps_n: 0.8,
            ..walls_sim::run::defaults::default_material(1e3)
        },
    );
    let used = model(&walls, &particles, &settings);
    let outcome = run(&walls, particles, &settings);
    // The run this test is about: every kind of event, warnings, stuck and removed
    // particles.
    for kind in [EventKind::Bounce, EventKind::Stick, EventKind::Remove] {
        assert!(outcome.events.iter().any(|e| e.kind == kind), "no {kind:?}");
    }
    assert!(!outcome.warnings.is_empty());
    assert!(outcome.particles.iter().any(|s| s.stuck_to.is_some()));
    assert!(outcome.particles.iter().any(|s| !s.alive));

    let same_as_whole = |report: Report| {
        let mut streamed = Vec::new();
        report.write_json(&mut streamed).unwrap();
        let value = serde_json::to_value(&report).unwrap();
        let whole = serde_json::to_string_pretty(&value).unwrap() + "\n";
        assert_eq!(String::from_utf8(streamed).unwrap(), whole);
    };
    let outputs = ["out/particles.csv".to_string(), "out/walls.csv".to_string()];
    same_as_whole(Report::new(used.clone(), &settings, &outcome));
    same_as_whole(Report::new(used.clone(), &settings, &outcome).with_outputs(&outputs));
    // Numbers JSON has no word for are null, as they were; −0 keeps its sign.
    let mut odd = outcome.clone();
    odd.energy = (f64::NAN, f64::INFINITY);
    odd.t = -0.0;
    let mut text = Vec::new();
    Report::new(used.clone(), &settings, &odd)
        .write_json(&mut text)
        .unwrap();
    let text = String::from_utf8(text).unwrap();
    assert!(
        text.contains("\"final\": null,\n    \"initial\": null\n"),
        "{text}"
    );
    assert!(text.contains("\n  \"t\": -0.0,\n"), "{text}");
    same_as_whole(Report::new(used, &settings, &odd));
}

#[test]
fn a_failed_write_ends_the_report_with_its_error() {
    let walls = scene(WALLS);
    let particles = particles();
    let settings = Settings::new(1e-4, 1e-3, walls_sim::run::defaults::default_material(1e3));
    let used = model(&walls, &particles, &settings);
    let outcome = run(&walls, particles, &settings);
    let mut full = std::io::BufWriter::new(std::fs::File::create("/dev/full").unwrap());
    let e = Report::new(used, &settings, &outcome)
        .write_json(&mut full)
        .unwrap_err();
    assert_eq!(e.kind(), std::io::ErrorKind::StorageFull, "{e}");
}
