//! Reactive walls (the document's section 7, docs/spec.md §3 "Reactive walls"):
//! finite-mass assemblies of walls that move in response to the particles that touch
//! them.
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
    /// The torque in the body frame, (p̂₁·τ, p̂₂·τ, p̂₃·τ) with the axes at the force
    /// evaluation: what pkdgrav's rotation holds fixed over the next step.
    pub torque_body: Vec3,
    /// pkdgrav's motion ([`Assembly::follow_pkdgrav`]): each wall's shape where it now
    /// is, moved and turned step by step as pkdgrav moves it.
    placed: Option<Vec<Shape>>,
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
                torque_body: Vec3::zeros(),
                placed: None,
            }),
        }
    }
    out.sort_by_key(|a| a.number);
    out
}

/// The spin a reactive wall of shape `shape` turning at `omega` shows a particle's
/// rolling and twisting springs (docs/pkdgrav-physics.md §10, §1.4): along the face
/// normal for a triangle or rectangle, along `orient` for a disk or cylinder, the whole
/// of it for a shell (and for the infinite shapes, which cannot be reactive).
pub fn relative_spin(shape: &Shape, omega: &Vec3) -> Vec3 {
    let along = |a: Vec3| a * a.dot(omega);
    match shape {
        Shape::Triangle(_) | Shape::Rectangle(_) => match shape.edges() {
            Some((e1, e2)) => match e1.cross(&e2).try_normalize(0.0) {
                Some(n) => along(n),
                None => Vec3::zeros(),
            },
            None => Vec3::zeros(),
        },
        Shape::Disk(_) | Shape::FiniteCylinder(_) => along(shape.axis().unwrap_or_default()),
        Shape::Shell(_) | Shape::Plane(_) | Shape::InfiniteCylinder(_) => *omega,
    }
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
    /// Switches the assembly to pkdgrav's motion (docs/pkdgrav-physics.md §10), for
    /// `Integrator::Pkdgrav`: [`Assembly::move_pkdgrav`] moves it, its angular velocity
    /// is not kicked, and its contacts see the body-frame `rot-vec` as if it were a
    /// space vector. `scene` is the walls it was made from.
    pub fn follow_pkdgrav(&mut self, scene: &[Wall]) {
        self.placed = Some(self.walls.iter().map(|&w| scene[w].shape.clone()).collect());
    }

    /// Whether the assembly moves as pkdgrav moves it ([`Assembly::follow_pkdgrav`]).
    pub fn is_pkdgrav(&self) -> bool {
        self.placed.is_some()
    }

    /// pkdgrav's wall move for the assembly (docs/pkdgrav-physics.md §10), after the
    /// opening kick of its velocity: the centre of gravity and every wall's origin move
    /// by velocity·dt; then ω (body frame) and the principal axes are integrated together
    /// over `dt` by Euler's equations with the body torque of the last force evaluation
    /// held fixed ([`crate::dynamics::euler_rigid`]); then each wall turns about the
    /// centre of gravity by three successive right-handed rotations, about the new p̂₁,
    /// p̂₂ and p̂₃ by ω₁·dt, ω₂·dt and ω₃·dt (the new ω). Only for an assembly that
    /// follows pkdgrav. Returns what the rotation's integration cost, whether it reached
    /// the minimum step and whether it failed ([`crate::dynamics::euler_rigid::Cost`]).
    pub fn move_pkdgrav(&mut self, dt: f64) -> crate::dynamics::euler_rigid::Cost {
        let travel = self.velocity * dt;
        self.cog += travel;
        let Some(placed) = self.placed.as_mut() else {
            return Default::default();
        };
        for shape in placed.iter_mut() {
            *shape = shape.at(shape.origin() + travel);
        }
        let cost = crate::dynamics::euler_rigid::integrate(
            &mut self.rotation,
            &self.inertia,
            &self.torque_body,
            dt,
        );
        for k in 0..3 {
            let angle = self.rotation.omega[k] * dt;
            if angle == 0.0 {
                continue;
            }
            let axis = nalgebra::Unit::new_normalize(self.rotation.axes[k]);
            let turn = Rotation3::from_axis_angle(&axis, angle);
            for shape in placed.iter_mut() {
                let origin = self.cog + turn * (shape.origin() - self.cog);
                *shape = shape.turned(origin, &turn);
            }
        }
        cost
    }

    /// The body-frame torque from the space-frame torque summed at a force evaluation,
    /// with the axes as they are then.
    pub fn note_torque_body(&mut self) {
        let a = &self.rotation.axes;
        self.torque_body = Vec3::new(
            a[0].dot(&self.torque),
            a[1].dot(&self.torque),
            a[2].dot(&self.torque),
        );
    }

    /// The rotation from the start to now: the principal axes then to now.
    pub fn turn(&self) -> Rotation3<f64> {
        let now = Matrix3::from_columns(&self.rotation.axes);
        let then = Matrix3::from_columns(&self.axes0);
        Rotation3::from_matrix_unchecked(now * then.transpose())
    }

    /// The angular velocity in the world frame; for an assembly that follows pkdgrav,
    /// the body-frame `rot-vec` itself, which pkdgrav's contacts take for a space vector
    /// (docs/pkdgrav-physics.md §10).
    pub fn spin(&self) -> Vec3 {
        if self.is_pkdgrav() {
            return self.rotation.omega;
        }
        let (w, a) = (&self.rotation.omega, &self.rotation.axes);
        a[0] * w.x + a[1] * w.y + a[2] * w.z
    }

    /// Whether its numbers are all finite: where it is, how it moves and turns, and the
    /// load on it.
    pub fn finite(&self) -> bool {
        let r = &self.rotation;
        [self.cog, self.velocity, r.omega, self.force, self.torque]
            .iter()
            .chain(&r.axes)
            .all(|v| v.iter().all(|x| x.is_finite()))
    }

    /// Where the `k`-th wall's origin is now.
    pub fn origin(&self, k: usize) -> Vec3 {
        if let Some(placed) = &self.placed {
            return placed[k].origin();
        }
        self.cog + self.turn() * self.offsets[k]
    }

    /// The `k`-th wall's shape now, from its shape at the start.
    pub fn shape(&self, start: &Shape, k: usize) -> Shape {
        if let Some(placed) = &self.placed {
            return placed[k].clone();
        }
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
