//! What the run tests share: the walls of walls-file text that must parse cleanly, and
//! the ball most tests throw (mass 1, radius 0.1). Each test file uses what it needs.
#![allow(dead_code)]

use nalgebra::Vector3;
use walls_geometry::Particle;
use walls_geometry::{Wall, decode};
use walls_model::{ContactModel, Options, analyze};

/// The walls of `text` in the soft-sphere mode.
pub fn scene(text: &str) -> Vec<Wall> {
    scene_in(text, ContactModel::Ssdem)
}

/// The walls of `text` checked in `mode`; the text must parse without diagnostics.
pub fn scene_in(text: &str, mode: ContactModel) -> Vec<Wall> {
    let parsed = walls_syntax::parse(text);
    assert!(parsed.diagnostics.is_empty(), "{:?}", parsed.diagnostics);
    let options = Options {
        mode,
        ..Options::default()
    };
    decode(&analyze(&parsed.tree, &options).scene)
}

/// A ball of mass 1 and radius 0.1 at `pos` moving at `vel`, not spinning.
pub fn particle(pos: [f64; 3], vel: [f64; 3]) -> Particle {
    Particle {
        mass: 1.0,
        radius: 0.1,
        pos: Vector3::from(pos),
        vel: Vector3::from(vel),
        spin: Vector3::zeros(),
        color: 3,
        index: 0,
    }
}
