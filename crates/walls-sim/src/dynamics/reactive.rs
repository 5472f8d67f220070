//! Reactive walls (the document's section 7, SPEC §3 "Reactive walls"): finite-mass
//! assemblies of walls that move in response to the particles that touch them.
//!
//! An assembly is every wall with a mass and the same `assembly` number (0 or 1). Its
//! mass is the sum of its walls'; its centre of gravity, angular velocity (`rot-vec`, in
//! the body frame), principal moments (the diagonal of `ixj-vec`, `iyj-vec`, `izj-vec`;
//! pkdgrav uses only the diagonal) and principal axes (`pxj-vec`, `pyj-vec`,
//! `pzj-vec`) are read from its first wall, and its velocity from that wall's
//! `velocity`. The walls keep their shapes relative to the centre of gravity: each is
//! turned by the rotation that takes the principal axes from where they started to
//! where they are.
//!
//! Each particle contact pushes the assembly by the reaction to the contact force, at
//! the contact point: a force and a torque about the centre of gravity. Translation is
//! integrated with the particles' leapfrog (with uniform gravity); rotation the same way,
//! half kicks of the angular momentum around the free rotation over the step, which
//! Euler's equations give in the principal frame ([`crate::dynamics::rigid`], pkdgrav's adaptive
//! Runge–Kutta). As in pkdgrav, the contact
//! itself treats the wall as infinitely massive, and reactive walls neither push nor
//! are pushed by other walls.

use crate::dynamics::rigid::Rotation;
use nalgebra::{Matrix3, Rotation3, Vector3};
use walls_geometry::{Shape, Wall};

type Vec3 = Vector3<f64>;

/// One assembly and its motion.
#[derive(Debug, Clone, PartialEq)]
pub struct Assembly {
    /// Its `assembly` number.
    pub number: i64,
    /// Its walls' indices in the scene.
    pub walls: Vec<usize>,
    /// Total mass.
    pub mass: f64,
    /// Principal moments of inertia.
    pub inertia: Vec3,
    /// Where its centre of gravity is.
    pub cog: Vec3,
    /// The velocity of its centre of gravity.
    pub velocity: Vec3,
    /// Its angular velocity (body frame) and principal axes (world frame).
    pub rotation: Rotation,
    /// The principal axes at the start.
    axes0: [Vec3; 3],
    /// Each wall's origin relative to the centre of gravity at the start.
    offsets: Vec<Vec3>,
    /// The force and torque (about the centre of gravity) of the last step's contacts.
    pub force: Vec3,
    /// See `force`.
    pub torque: Vec3,
}

/// The assemblies of `walls`, by number.
pub fn assemblies(walls: &[Wall]) -> Vec<Assembly> {
    let mut out: Vec<Assembly> = Vec::new();
    for (w, wall) in walls.iter().enumerate() {
        let r = &wall.reactive;
        if !r.is_heavy() {
            continue;
        }
        let origin = wall.motion.origin;
        match out.iter_mut().find(|a| a.number == r.assembly) {
            Some(a) => {
                a.walls.push(w);
                a.mass += r.mass;
                a.offsets.push(origin - a.cog);
            }
            None => out.push(Assembly {
                number: r.assembly,
                walls: vec![w],
                mass: r.mass,
                inertia: r.inertia,
                cog: r.cog,
                velocity: wall.motion.velocity,
                rotation: Rotation {
                    omega: r.rot_vec,
                    axes: r.axes,
                },
                axes0: r.axes,
                offsets: vec![origin - r.cog],
                force: Vec3::zeros(),
                torque: Vec3::zeros(),
            }),
        }
    }
    out.sort_by_key(|a| a.number);
    out
}

/// The assemblies that cannot move: a principal moment that is not a positive finite
/// number (a rod's moment about its own axis is 0, but Euler's equations divide by it).
/// They stay where they are, and the run says so.
pub fn immovable(assemblies: &[Assembly]) -> Vec<i64> {
    assemblies
        .iter()
        .filter(|a| !a.inertia.iter().all(|i| *i > 0.0 && i.is_finite()))
        .map(|a| a.number)
        .collect()
}

impl Assembly {
    /// The rotation from the start to now: the principal axes then to now.
    pub fn turn(&self) -> Rotation3<f64> {
        let now = Matrix3::from_columns(&self.rotation.axes);
        let then = Matrix3::from_columns(&self.axes0);
        Rotation3::from_matrix_unchecked(now * then.transpose())
    }

    /// The angular velocity in the world frame.
    pub fn spin(&self) -> Vec3 {
        let (w, a) = (&self.rotation.omega, &self.rotation.axes);
        a[0] * w.x + a[1] * w.y + a[2] * w.z
    }

    /// Where the `k`-th wall's origin is now.
    pub fn origin(&self, k: usize) -> Vec3 {
        self.cog + self.turn() * self.offsets[k]
    }

    /// The `k`-th wall's shape now, from its shape at the start.
    pub fn shape(&self, start: &Shape, k: usize) -> Shape {
        let turn = self.turn();
        start.turned(self.cog + turn * self.offsets[k], &turn)
    }

    /// Changes the angular velocity by the torque over `dt`: each principal component
    /// of the angular momentum by the torque's component along that axis.
    pub fn kick(&mut self, dt: f64) {
        let (axes, i) = (self.rotation.axes, self.inertia);
        let w = &mut self.rotation.omega;
        w.x += self.torque.dot(&axes[0]) * dt / i.x;
        w.y += self.torque.dot(&axes[1]) * dt / i.y;
        w.z += self.torque.dot(&axes[2]) * dt / i.z;
    }

    /// The velocity of the assembly's material at `q`.
    pub fn point_velocity(&self, q: &Vec3) -> Vec3 {
        self.velocity + self.spin().cross(&(q - self.cog))
    }
}
