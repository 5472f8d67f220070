//! Running particles against walls with the soft-sphere (SSDEM) model: uniform gravity,
//! the spring–dashpot of [`crate::ssdem`] against every wall each particle overlaps, and
//! pkdgrav's kick-drift-kick leapfrog. Walls move exactly (SPEC §1 "Motion").
//!
//! Sticky walls (`epsn 0`) hold a particle at its contact point, which then moves with
//! the wall; death walls (`epsn` < 0) remove it. Each contact that ends is an event with
//! the normal speeds in and out. pkdgrav's overlap warnings (3 % and 15 % of the
//! radius) are reported once each; an overlap above 50 % stops the run, as pkdgrav
//! aborts; more than 3 wall contacts at once on one particle is a warning.
//!
//! Not yet: particle–particle contacts, rolling and twisting resistance, HSDEM stepping.

use crate::geometry::Shape;
use crate::input::Particle;
use crate::kinematics::Motion;
use crate::ssdem::{Material, Touch, contact};
use nalgebra::Vector3;
use walls_keywords::Keyword;
use walls_model::{Scene, Wall, motion::position};

type Vec3 = Vector3<f64>;

/// The particles' material values: what walls' 99 and −1 fall back to.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParticleMaterial {
    /// Normal restitution.
    pub eps_n: f64,
    /// Tangential restitution.
    pub eps_t: f64,
    /// Normal spring constant.
    pub k_n: f64,
    /// Tangential spring constant.
    pub k_t: f64,
    /// Static friction.
    pub mu_s: f64,
}

/// What to run.
#[derive(Debug, Clone, PartialEq)]
pub struct Settings {
    /// The timestep.
    pub dt: f64,
    /// When to stop.
    pub t_end: f64,
    /// Uniform gravity.
    pub gravity: Vec3,
    /// The particles' material.
    pub material: ParticleMaterial,
}

/// Steps per pair contact in the default timestep π·√(m/(2k_n))/N: at 100 the rebound
/// is within 1 % of ε for ε from 0.1 to 0.95 (docs/evaluator.md).
pub const STEPS_PER_CONTACT: f64 = 100.0;

/// pkdgrav's suggested timestep for the lightest particle, with [`STEPS_PER_CONTACT`].
pub fn default_dt(particles: &[Particle], k_n: f64) -> f64 {
    let m = particles
        .iter()
        .map(|p| p.mass)
        .fold(f64::INFINITY, f64::min);
    std::f64::consts::PI * (m / (2.0 * k_n)).sqrt() / STEPS_PER_CONTACT
}

/// What happened to a particle at a wall.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EventKind {
    /// It touched the wall and left it.
    Bounce,
    /// It stuck to a sticky wall.
    Stick,
    /// A death wall removed it.
    Remove,
}

/// One event.
#[derive(Debug, Clone, PartialEq)]
pub struct Event {
    /// When.
    pub t: f64,
    /// Which particle (its index in the input).
    pub particle: usize,
    /// Which wall.
    pub wall: usize,
    /// What happened.
    pub kind: EventKind,
    /// Normal speed towards the wall when the contact began.
    pub vn_in: f64,
    /// Normal speed away from the wall when it ended (0 for a stick or removal).
    pub vn_out: f64,
}

/// A particle's state.
#[derive(Debug, Clone, PartialEq)]
pub struct State {
    /// The particle (position, velocity, spin as they are now).
    pub particle: Particle,
    /// Whether it is still in the simulation.
    pub alive: bool,
    /// The sticky wall holding it, with the contact point relative to the wall's origin.
    pub stuck_to: Option<(usize, Vec3)>,
    acc: Vec3,
    alpha: Vec3,
}

/// The result of a run.
#[derive(Debug, Clone, PartialEq)]
pub struct Outcome {
    /// The time reached.
    pub t: f64,
    /// Steps taken.
    pub steps: u64,
    /// The particles at the end.
    pub particles: Vec<State>,
    /// What happened at walls, in order.
    pub events: Vec<Event>,
    /// Kinetic (with spin) plus gravitational energy at the start and the end.
    pub energy: (f64, f64),
    /// Warnings, as pkdgrav would print them.
    pub warnings: Vec<String>,
}

/// An open contact: the tangential spring and the normal speed it began with.
struct Open {
    spring: Vec3,
    vn_in: f64,
}

/// The open contacts of each particle, by wall. A particle touches a few walls at most, so
/// a short list per particle is faster than a map keyed by pairs (docs/performance.md).
struct OpenContacts(Vec<Vec<(usize, Open)>>);

impl OpenContacts {
    /// Closes the contact of particle `i` with wall `w`, if open.
    fn remove(&mut self, i: usize, w: usize) -> Option<Open> {
        let list = &mut self.0[i];
        let k = list.iter().position(|(wall, _)| *wall == w)?;
        Some(list.swap_remove(k).1)
    }

    /// The contact of particle `i` with wall `w`, opened with `new` if it is not.
    fn entry(&mut self, i: usize, w: usize, new: impl FnOnce() -> Open) -> &mut Open {
        let list = &mut self.0[i];
        let k = match list.iter().position(|(wall, _)| *wall == w) {
            Some(k) => k,
            None => {
                list.push((w, new()));
                list.len() - 1
            }
        };
        &mut list[k].1
    }
}

/// A wall's material for a contact: the wall's values, the particles' where it says so.
fn wall_material(wall: &Wall, p: &ParticleMaterial) -> Material {
    let own = |k, fallback: f64| match wall.number(k) {
        -1.0 => fallback,
        x => x,
    };
    let eps = |k, fallback: f64| match wall.number(k) {
        99.0 => fallback,
        x => x,
    };
    Material {
        eps_n: eps(Keyword::Epsn, p.eps_n),
        eps_t: eps(Keyword::Epst, p.eps_t),
        k_n: own(Keyword::KN, p.k_n),
        k_t: own(Keyword::KT, p.k_t),
        mu_s: own(Keyword::MuS, p.mu_s),
    }
}

fn energy(states: &[State], g: &Vec3) -> f64 {
    states
        .iter()
        .filter(|s| s.alive)
        .map(|s| {
            let p = &s.particle;
            let inertia = 0.4 * p.mass * p.radius * p.radius;
            0.5 * p.mass * p.vel.norm_squared() + 0.5 * inertia * p.spin.norm_squared()
                - p.mass * g.dot(&p.pos)
        })
        .sum()
}

/// Runs `particles` against the walls of `scene`.
///
/// # Panics
///
/// If the timestep is not a positive finite number: the run would never end. Callers
/// check it first ([`crate::input::Rule::Positive`]).
pub fn run(scene: &Scene, particles: Vec<Particle>, settings: &Settings) -> Outcome {
    let g = settings.gravity;
    let dt = settings.dt;
    assert!(dt > 0.0 && dt.is_finite(), "timestep {dt}");
    let mut states: Vec<State> = particles
        .into_iter()
        .map(|particle| State {
            particle,
            alive: true,
            stuck_to: None,
            acc: g,
            alpha: Vec3::zeros(),
        })
        .collect();
    let materials: Vec<Material> = scene
        .walls
        .iter()
        .map(|w| wall_material(w, &settings.material))
        .collect();
    let initial = energy(&states, &g);
    let mut open = OpenContacts((0..states.len()).map(|_| Vec::new()).collect());
    let mut events = Vec::new();
    let mut warnings = Vec::new();
    let mut warned = [false; 3];
    let mut t = 0.0;
    let mut steps = 0u64;
    'run: while t < settings.t_end - dt * 1e-9 {
        // Kick and drift.
        for s in states
            .iter_mut()
            .filter(|s| s.alive && s.stuck_to.is_none())
        {
            s.particle.vel += s.acc * (dt / 2.0);
            s.particle.spin += s.alpha * (dt / 2.0);
            let v = s.particle.vel;
            s.particle.pos += v * dt;
        }
        t += dt;
        steps += 1;
        let origins: Vec<Vec3> = scene
            .walls
            .iter()
            .map(|w| position(w, t).unwrap_or_else(|| w.vector(Keyword::Origin)))
            .collect();
        let shapes: Vec<Shape> = scene
            .walls
            .iter()
            .zip(&origins)
            .map(|(w, o)| Shape::of(w, *o))
            .collect();
        for (i, s) in states.iter_mut().enumerate() {
            if !s.alive {
                continue;
            }
            if let Some((w, offset)) = s.stuck_to {
                // Carried by the wall: along with its origin, and around its spin axis.
                let wall = &scene.walls[w];
                let spin = wall.number(Keyword::AngSpeed);
                let offset = match nalgebra::Unit::try_new(wall.vector(Keyword::Orient), 0.0) {
                    Some(axis) if spin != 0.0 => {
                        nalgebra::Rotation3::from_axis_angle(&axis, spin * dt) * offset
                    }
                    _ => offset,
                };
                s.stuck_to = Some((w, offset));
                s.particle.pos = origins[w] + offset;
                s.particle.vel = Motion::new(wall).point_velocity(&s.particle.pos, &origins[w], t);
                continue;
            }
            let p = &s.particle;
            let (m, r) = (p.mass, p.radius);
            let inertia = 0.4 * m * r * r;
            let mut force = g * m;
            let mut torque = Vec3::zeros();
            let mut touching = 0;
            for (w, shape) in shapes.iter().enumerate() {
                let near = shape.nearest(&s.particle.pos);
                let overlap = r - near.distance;
                if overlap <= 0.0 {
                    if let Some(o) = open.remove(i, w) {
                        let n = near.normal;
                        let wall_v = Motion::new(&scene.walls[w]).point_velocity(
                            &near.point,
                            &origins[w],
                            t,
                        );
                        let vn_out = n.dot(&(s.particle.vel - wall_v));
                        events.push(Event {
                            t,
                            particle: i,
                            wall: w,
                            kind: EventKind::Bounce,
                            vn_in: o.vn_in,
                            vn_out,
                        });
                    }
                    continue;
                }
                touching += 1;
                let fraction = overlap / r;
                for (k, level) in [0.03, 0.15].iter().enumerate() {
                    if fraction > *level && !warned[k] {
                        warned[k] = true;
                        warnings.push(format!(
                            "overlap of {:.1}% of the radius (particle {i}, wall {w}, t = {t}): more than {:.0}%",
                            fraction * 100.0,
                            level * 100.0
                        ));
                    }
                }
                if fraction > 0.5 {
                    warnings.push(format!(
                        "overlap of {:.1}% of the radius (particle {i}, wall {w}, t = {t}): pkdgrav aborts above 50%; the run stops",
                        fraction * 100.0
                    ));
                    break 'run;
                }
                let motion = Motion::new(&scene.walls[w]);
                let wall_v = motion.point_velocity(&near.point, &origins[w], t);
                let n = near.normal;
                let u = s.particle.vel + s.particle.spin.cross(&(-n * r)) - wall_v;
                let mat = &materials[w];
                let entry = open.entry(i, w, || Open {
                    spring: Vec3::zeros(),
                    vn_in: -n.dot(&u),
                });
                if mat.eps_n <= 0.0 {
                    // A death wall removes the particle; a sticky wall holds it.
                    let kind = if mat.eps_n < 0.0 {
                        s.alive = false;
                        EventKind::Remove
                    } else {
                        s.stuck_to = Some((w, s.particle.pos - origins[w]));
                        s.particle.vel = wall_v;
                        EventKind::Stick
                    };
                    events.push(Event {
                        t,
                        particle: i,
                        wall: w,
                        kind,
                        vn_in: entry.vn_in,
                        vn_out: 0.0,
                    });
                    open.remove(i, w);
                    break;
                }
                let touch = Touch {
                    overlap,
                    normal: n,
                    velocity: u,
                };
                let c = contact(m, r, &touch, &mut entry.spring, dt, mat);
                force += c.force;
                torque += c.torque;
            }
            if touching > 3 && !warned[2] {
                warned[2] = true;
                warnings.push(format!("particle {i} touches {touching} walls at once (t = {t}); pkdgrav handles at most 3"));
            }
            if s.alive && s.stuck_to.is_none() {
                s.acc = force / m;
                s.alpha = torque / inertia;
                s.particle.vel += s.acc * (dt / 2.0);
                s.particle.spin += s.alpha * (dt / 2.0);
            }
        }
    }
    let last = energy(&states, &g);
    Outcome {
        t,
        steps,
        particles: states,
        events,
        energy: (initial, last),
        warnings,
    }
}
