//! The scene's box at pkdgrav's real scale: a tube written in centimetres and converted
//! to AU (`lengthunit 6.68445e-14`) is framed as it is in centimetres, and at 1e+3; no
//! minimum size; a floor stretches the box to it and an infinite cylinder widens it to its
//! cross-section; a distant plane does not; a scene with
//! nothing finite falls back on one of the file's length units.

use nalgebra::Vector3;
use walls_geometry::{Particle, scene_bounds, scene_bounds_at};
use walls_test_support::scene;

/// A floor and a finite tube of radius 1 and length 5.5 standing on it, in the file's
/// units, scaled by `lengthunit`.
fn tube(unit: f64) -> String {
    format!(
        "lengthunit {unit}\nwall type plane\nwall type cylinder-finite\n  origin 0 0 2.75\n  radius 1\n  length 5.5\n"
    )
}

/// Asserts that the box is `lo`..`hi`, each corner within `tolerance`.
fn assert_box(found: (Vector3<f64>, Vector3<f64>), lo: [f64; 3], hi: [f64; 3], tolerance: f64) {
    let (found_lo, found_hi) = found;
    assert!(
        (found_lo - Vector3::from(lo)).amax() <= tolerance
            && (found_hi - Vector3::from(hi)).amax() <= tolerance,
        "the box is {found_lo:?}..{found_hi:?}, not {lo:?}..{hi:?}"
    );
}

#[test]
fn a_tube_is_framed_at_any_scale() {
    for unit in [6.68445e-14, 1.0, 1e3] {
        let walls = scene(&tube(unit));
        assert_box(
            scene_bounds(&walls, &[]),
            [-unit, -unit, 0.0],
            [unit, unit, 5.5 * unit],
            1e-12 * unit,
        );
    }
}

#[test]
fn particles_extend_the_box() {
    let unit = 6.68445e-14;
    let walls = scene(&tube(unit));
    let mut p = Particle::at_rest(0.1 * unit, Vector3::new(0.0, 0.0, 8.0) * unit, 0);
    p.pos.x = 3.0 * unit;
    assert_box(
        scene_bounds(&walls, &[p]),
        [-unit, -unit, 0.0],
        [3.1 * unit, unit, 8.1 * unit],
        1e-12 * unit,
    );
}

#[test]
fn an_infinite_cylinder_around_particles_is_the_container() {
    // pkdgrav's cylinder_test: a floor at z = −5 cm and an infinite tube of radius 5.5 cm
    // around particles within 1 cm of its axis.
    let unit = 6.68445e-14;
    let walls = scene(&format!(
        "lengthunit {unit}\nwall type plane\n  origin 0 0 -5\nwall type cylinder-infinite\n  radius 5.5\n"
    ));
    let p = Particle::at_rest(0.5 * unit, Vector3::new(0.5, 0.0, -4.0) * unit, 0);
    // The tube's cross-section across; the floor is within the box's size of the
    // particle, so the box reaches down to it.
    assert_box(
        scene_bounds(&walls, &[p]),
        [-5.5 * unit, -5.5 * unit, -5.0 * unit],
        [5.5 * unit, 5.5 * unit, -3.5 * unit],
        1e-9 * unit,
    );
}

#[test]
fn a_distant_plane_does_not_stretch_the_box() {
    // The disk alone: flat along z, so a hundredth of its size there.
    let walls = scene("wall type plane\n  origin 0 0 -100\nwall type disk\n  radius 1\n");
    assert_box(
        scene_bounds(&walls, &[]),
        [-1.0, -1.0, -0.01],
        [1.0, 1.0, 0.01],
        1e-12,
    );
}

#[test]
fn moving_walls_are_boxed_over_the_span() {
    // A disk of radius 1 oscillating along x with amplitude 2 (period 2π): at t = π/2 it
    // is 2 to the right.
    let walls = scene("wall type disk\n  radius 1\n  osc-ampl 2\n  osc-freq 1\n  osc-vec 1 0 0\n");
    assert_box(
        scene_bounds_at(&walls, &[], &[0.0, std::f64::consts::FRAC_PI_2]),
        [-1.0, -1.0, -0.02],
        [3.0, 1.0, 0.02],
        1e-12,
    );
}

#[test]
fn nothing_finite_is_one_file_unit_across() {
    // One unit (a centimetre in AU) around the plane's origin at z = −5 units.
    let u = 6.68445e-14;
    let walls = scene(&format!(
        "lengthunit {u}\nwall type plane\n  origin 0 0 -5\n"
    ));
    assert_box(
        scene_bounds(&walls, &[]),
        [-0.5 * u, -0.5 * u, -5.5 * u],
        [0.5 * u, 0.5 * u, -4.5 * u],
        1e-27,
    );
}
