//! A particle as pkdgrav's files hold it: the sphere that meets the walls. The run, its
//! inputs and outputs, and the previews share this one record.

use nalgebra::Vector3;

type Vec3 = Vector3<f64>;

/// One particle.
#[derive(Debug, Clone, PartialEq)]
pub struct Particle {
    /// Mass.
    pub mass: f64,
    /// Radius.
    pub radius: f64,
    /// Position.
    pub pos: Vec3,
    /// Velocity.
    pub vel: Vec3,
    /// Spin (angular velocity).
    pub spin: Vec3,
    /// ssdraw colour.
    pub color: i32,
    /// Index in the original file.
    pub index: i32,
}

/// A particle is its own particle: what reads particles takes them or whatever holds
/// one (a run's states).
impl AsRef<Particle> for Particle {
    fn as_ref(&self) -> &Particle {
        self
    }
}

impl Particle {
    /// A particle of radius `radius` and unit density at rest at `pos`, not spinning,
    /// drawn in ssdraw's blue (colour 3), with `index` as its place in the file.
    pub fn at_rest(radius: f64, pos: Vec3, index: usize) -> Particle {
        Particle {
            mass: 4.0 / 3.0 * std::f64::consts::PI * radius.powi(3),
            radius,
            pos,
            vel: Vec3::zeros(),
            spin: Vec3::zeros(),
            color: 3,
            index: index as i32,
        }
    }
}
