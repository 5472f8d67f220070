//! The interactive page of a movie of 100 frames of 1,000 particles in a scene in
//! centimetres (pkdgrav's `lengthunit 6.68445e-14`): how long `html::write_movie` takes
//! and how large the page is. `cargo bench -p walls-preview --bench html_movie` prints
//! both; with `HTML_MOVIE_OUT=page.html` it also writes the page there (to measure the
//! browser's memory, docs/preview.md "HTML movies").

use nalgebra::{Rotation3, Vector3};
use std::time::Instant;
use walls_geometry::Particle;
use walls_geometry::units::{Readout, System};
use walls_preview::html::{self, MovieOptions};
use walls_preview::mesh::{Placement, place};
use walls_preview::{MovieFrame, wall_meshes_in};

const CM: f64 = 6.68445e-14;
const FRAMES: usize = 100;
const PARTICLES: usize = 1000;

/// A box of 10 cm with a floor, two side walls and a reactive paddle turning about z.
const SCENE: &str = "\
lengthunit 6.68445e-14
massunit 5.02739933e-34
timeunit 1.99102e-7
wall type rectangle
  origin -5 -5 -5
  vertex1 10 0 0
  vertex2 0 10 0
  color 4
wall type rectangle
  origin -5 -5 -5
  vertex1 0 10 0
  vertex2 0 0 10
  color 7
  transparency 0.5
wall type cylinder-finite
  radius 5
  length 10
  color 15
  transparency 0.7
wall type rectangle
  origin -3 -0.5 -4
  vertex1 6 0 0
  vertex2 0 1 0
  mass 1
  color 2
";

fn main() {
    let scene = movie_scene();
    let decoded = walls_geometry::decode(&scene);
    let scene_box = (Vector3::repeat(-5.0 * CM), Vector3::repeat(5.0 * CM));
    // Particles falling in a spiral, deterministic; one in ten leaves half-way through.
    let frames: Vec<MovieFrame> = (0..FRAMES)
        .map(|k| {
            let t = 1e-7 * k as f64;
            let mut walls = wall_meshes_in(&decoded, t, 64, &scene_box);
            let turn = Rotation3::from_axis_angle(&Vector3::z_axis(), 0.05 * k as f64);
            place(
                &mut walls,
                &decoded,
                &[Placement::Polygon {
                    wall: 3,
                    origin: turn * Vector3::new(-3.0, -0.5, -4.0) * CM,
                    vertex1: turn * Vector3::new(6.0, 0.0, 0.0) * CM,
                    vertex2: turn * Vector3::new(0.0, 1.0, 0.0) * CM,
                }],
            );
            let particles = (0..PARTICLES)
                .filter(|i| i % 10 != 0 || k < FRAMES / 2)
                .map(|i| {
                    let a = i as f64 * 2.399 + 0.03 * k as f64;
                    let r = 4.0 * ((i % 97) as f64 / 97.0).sqrt();
                    let z = 4.5 - 9.0 * ((i as f64 * 0.618 + 0.004 * k as f64) % 1.0);
                    let pos = Vector3::new(r * a.cos(), r * a.sin(), z) * CM;
                    let mut p = Particle::at_rest(0.1 * CM, pos, i);
                    p.color = (i % 15 + 1) as i32;
                    p
                })
                .collect();
            MovieFrame {
                t,
                step: Some(100 * k as u64),
                walls,
                particles,
            }
        })
        .collect();
    let options = MovieOptions {
        readout: Readout::new(System::Auto, &scene.units),
        trails: Some(10),
        title: "html_movie bench".to_string(),
    };
    let runs = 10;
    let mut page = Vec::new();
    let start = Instant::now();
    for _ in 0..runs {
        page.clear();
        if let Err(e) = html::write_movie(&mut page, &scene, &frames, &options) {
            eprintln!("html_movie: {e}");
            return;
        }
    }
    let each = start.elapsed() / runs;
    println!(
        "write_movie: {FRAMES} frames x {PARTICLES} particles: {:.1} ms, {} bytes",
        each.as_secs_f64() * 1e3,
        page.len()
    );
    if let Some(path) = std::env::var_os("HTML_MOVIE_OUT")
        && let Err(e) = std::fs::write(&path, &page)
    {
        eprintln!("html_movie: cannot write {}: {e}", path.to_string_lossy());
    }
}

/// The bench's scene, resolved as `walls-sim` resolves a file.
fn movie_scene() -> walls_model::Scene {
    walls_test_support::model_scene(SCENE)
}
