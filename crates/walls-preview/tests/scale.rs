//! Every picture is right at pkdgrav's real scale: the same scene in centimetres
//! converted to AU (`lengthunit 6.68445e-14`), at 1 and at 1e+3 length units. The SVG
//! draws the same shapes at the same pixels in the same order (only its labels say the
//! unit: a depth bias once fixed at 1e-9 put every outline in front at 1e-14), and the VTK
//! file holds the same geometry scaled, or exactly the file's centimetres with
//! `--units cgs`. (POV-Ray's and the page's pictures at these scales are rendered in
//! tests/pov.rs and tests/html.rs.)

use nalgebra::Vector3;
use walls_geometry::units::{Readout, System};
use walls_geometry::{Particle, decode, scene_bounds};
use walls_model::Scene;
use walls_preview::svg::{Frame, View};
use walls_preview::{vtk, wall_meshes_in};
use walls_test_support::model_scene;

/// A floor, a tube of radius 1 and height 5.5 on it, and a particle of radius 0.3 in
/// the tube, in units scaled by `unit`.
fn scene(unit: f64) -> (Scene, Vec<Particle>) {
    let s = model_scene(&format!(
        "lengthunit {unit}\nwall type plane\n  color 180\n\
         wall type cylinder-finite\n  origin 0 0 2.75\n  radius 1\n  length 5.5\n  color 4\n"
    ));
    let mut p = Particle::at_rest(0.3 * unit, Vector3::new(0.2, 0.0, 1.0) * unit, 0);
    p.color = 2;
    (s, vec![p])
}

fn svg(unit: f64) -> String {
    let (s, particles) = scene(unit);
    let bounds = scene_bounds(&decode(&s), &particles);
    let walls = wall_meshes_in(&walls_geometry::decode(&s), 0.0, 16, &bounds);
    let frames = [Frame {
        t: 0.0,
        walls: &walls,
        particles: &particles,
    }];
    let mut out = Vec::new();
    let readout = Readout::new(System::Auto, &s.units);
    walls_preview::svg::write(&mut out, &frames, &View::default(), bounds, 1.0, &readout).unwrap();
    String::from_utf8(out).unwrap()
}

/// The drawing without its text (the time and the scale bar's label).
fn shapes(svg: &str) -> Vec<&str> {
    svg.lines().filter(|l| !l.contains("<text")).collect()
}

#[test]
fn the_svg_is_the_same_at_any_scale() {
    let one = svg(1.0);
    // The particle is a disc of 0.3/6.4 of the picture's 0.8·600 px height, not a dot.
    let disc = one
        .lines()
        .find(|l| l.contains("class=\"particle\""))
        .expect("the particle is drawn");
    let r: f64 = disc
        .split("r=\"")
        .nth(1)
        .unwrap()
        .split('"')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!(r > 15.0, "particle radius {r} px");
    for unit in [6.68445e-14, 1e3] {
        let scaled = svg(unit);
        assert_eq!(shapes(&scaled), shapes(&one), "at {unit} length units");
    }
    // The scale bar speaks the file's units: a round length in centimetres.
    assert!(svg(6.68445e-14).contains(">2 cm</text>"));
}

#[test]
fn vtk_holds_the_scene_at_its_scale() {
    let points = |unit: f64, units: System| {
        let (s, particles) = scene(unit);
        let bounds = scene_bounds(&decode(&s), &particles);
        let walls = wall_meshes_in(&walls_geometry::decode(&s), 0.0, 8, &bounds);
        let mut out = Vec::new();
        let scale = Readout::new(units, &s.units).scale;
        vtk::write(&mut out, &walls, &particles, 0.0, &scale).unwrap();
        let text = String::from_utf8(out).unwrap();
        let start = text.find("Name=\"Points\"").unwrap();
        let body = &text[text[start..].find('>').unwrap() + start + 1..];
        let body = &body[..body.find("</DataArray>").unwrap()];
        body.split_whitespace()
            .map(|x| x.parse::<f64>().unwrap())
            .collect::<Vec<f64>>()
    };
    let one = points(1.0, System::Pkdgrav);
    for unit in [6.68445e-14, 1e3] {
        let scaled = points(unit, System::Pkdgrav);
        assert_eq!(scaled.len(), one.len());
        for (a, b) in scaled.iter().zip(&one) {
            assert!((a - b * unit).abs() <= 1e-12 * unit, "{a} vs {b}·{unit}");
        }
        // In the file's own centimetres (cgs), the numbers are the file's.
        if unit == 6.68445e-14 {
            for (a, b) in points(unit, System::Cgs).iter().zip(&one) {
                assert!((a - b).abs() <= 1e-12, "{a} cm vs {b}");
            }
        }
    }
}
