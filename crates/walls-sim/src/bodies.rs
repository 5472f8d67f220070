//! The bodies: the particles of a run as the steppers carry them, one [`State`] per
//! particle in the input's order (its position, velocity and spin, whether it is still
//! in the run, the sticky wall holding it, its last accelerations). The steppers
//! ([`crate::run`]) move them; the readers and writers of [`crate::io`] and the
//! aggregates of [`crate::dynamics`] read and make them.

use nalgebra::Vector3;
use walls_geometry::Particle;

type Vec3 = Vector3<f64>;

/// A particle's state.
#[derive(Debug, Clone, PartialEq)]
pub struct State {
    /// The particle (position, velocity, spin as they are now).
    pub particle: Particle,
    /// Whether it is still in the simulation.
    pub alive: bool,
    /// The sticky wall holding it, with the contact point relative to the wall's origin
    /// (boxed: few particles are ever held, and every pass over the particles carries
    /// this field, 8 bytes so rather than 40).
    pub stuck_to: Option<Box<(usize, Vec3)>>,
    pub(crate) acc: Vec3,
    pub(crate) alpha: Vec3,
    /// A member of a rigid aggregate (docs/pkdgrav-physics.md §9): moved with it, never
    /// kicked or drifted on its own.
    pub(crate) member: bool,
}

// The soft-sphere drift reads and writes every state every step, and with 10⁵
// particles the step's data nears the processor's last cache: a field added here is
// paid for by every particle in every step (docs/performance-history.md, "Thirteenth round").
// What the state can do without is kept beside it (the soft stepper's 1/m and 1/I).
#[cfg(target_pointer_width = "64")]
const _: () = assert!(std::mem::size_of::<State>() == 160);

impl State {
    /// A particle at the start of a run: alive, free, not yet accelerated.
    pub fn new(particle: &Particle) -> State {
        State::from(particle.clone())
    }

    /// Whether it is out of the run, or its position, velocity and spin are all finite.
    #[inline]
    pub(crate) fn finite(&self) -> bool {
        self.finite_with(self.particle.vel.sum() + self.particle.spin.sum())
    }

    /// [`State::finite`], given the sum of the velocity's and spin's components (which
    /// the stepper has in hand after a kick).
    #[inline]
    pub(crate) fn finite_with(&self, motion: f64) -> bool {
        let p = &self.particle;
        // A sum of finite numbers is finite unless it overflows: only then look closer.
        let sum = p.pos.sum() + motion;
        !self.alive
            || sum.is_finite()
            || (p.pos.iter().chain(p.vel.iter()).chain(p.spin.iter())).all(|x| x.is_finite())
    }

    /// The particle as pkdgrav writes it in an output: its colour −1 − the wall's number
    /// once stuck to a wall (unless it was already negative; docs/pkdgrav-physics.md §6).
    pub fn as_written(&self) -> Particle {
        let mut p = self.particle.clone();
        if let Some(&(w, _)) = self.stuck_to.as_deref()
            && p.color >= 0
        {
            p.color = -1 - i32::try_from(w).unwrap_or(i32::MAX - 1);
        }
        p
    }

    /// Whether it moves freely: alive and not held by a sticky wall.
    pub(crate) fn free(&self) -> bool {
        self.alive && self.stuck_to.is_none()
    }
}

/// The particle a state holds, for what reads particles ([`crate::config::load_as`]).
impl AsRef<Particle> for State {
    fn as_ref(&self) -> &Particle {
        &self.particle
    }
}

impl From<Particle> for State {
    /// The particle at the start of a run ([`State::new`]), taken rather than copied.
    fn from(particle: Particle) -> State {
        State {
            particle,
            alive: true,
            stuck_to: None,
            acc: Vec3::zeros(),
            alpha: Vec3::zeros(),
            member: false,
        }
    }
}
