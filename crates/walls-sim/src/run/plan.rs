//! Deciding, before a run, which parts of the model the scene needs, and why: only
//! those run (`walls-sim plan FILE` lists them; the run's JSON `model` is the list of
//! those in use).
//!
//! A part is needed when something in the scene or the run can make it act:
//! - moving walls: a wall with a velocity or an oscillation (else the walls are placed
//!   once, not every step);
//! - wall spin: a wall with `ang-speed` (else contact velocities skip the spin);
//! - sliding friction: μ_s > 0 for the particles or a wall, or (HSDEM) ε_t < 1 (else
//!   no tangential spring is kept);
//! - rolling and twisting resistance: μ_r, μ_t > 0;
//! - edge detection: HSDEM with edge detection on and a wall that has edges, corners or
//!   rims (rectangles, disks, finite cylinders);
//! - particle–particle contacts: more than one particle, and not switched off;
//! - reactive walls: a wall with a finite mass and an assembly, in a soft-sphere run
//!   whose build has `DEM_WALLS_REACT` (without it the masses are ignored, W402);
//! - sticky and death walls: a wall with `epsn` 0 or below;
//! - the wall index: more than 16 bounded walls (planes and infinite cylinders are always
//!   looked at).
//!
//! The list also names the pkdgrav build the run follows, with the options the inputs
//! need and it lacks ([`crate::build::missing`]), and which rolling and twisting model
//! that build has.

use walls_geometry::Particle;

/// Above this many bounded walls the runs use the wall index. At 100 walls it finds a
/// particle's walls 11 times faster than looking at each (docs/accuracy.md, chart
/// `wall_scaling`); over a handful of walls a hierarchy saves little.
const WALL_INDEX_FROM: usize = 16;
use crate::run::{ContactModel, ParticleMaterial, Settings};
use walls_geometry::{Shape, Wall};

/// One part of the model: whether the run uses it, and why.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Part {
    /// Its name.
    pub name: &'static str,
    /// Whether the run uses it.
    pub used: bool,
    /// Why (or why not).
    pub reason: String,
}

/// The parts of the model a run uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Plan {
    /// Walls are placed every step (some wall moves).
    pub moving_walls: bool,
    /// Contact velocities include the walls' spin.
    pub spin: bool,
    /// Tangential springs and Coulomb friction (HSDEM: the tangential restitution).
    pub sliding_friction: bool,
    /// Rolling resistance.
    pub rolling: bool,
    /// Twisting resistance.
    pub twisting: bool,
    /// HSDEM edges, corners and rims.
    pub edges: bool,
    /// Particle–particle contacts.
    pub particle_contacts: bool,
    /// A bounding-volume hierarchy over the walls ([`crate::broad::wall_index`]).
    pub wall_index: bool,
    /// Reactive walls: assemblies that move in response to particles (SSDEM).
    pub reactive: bool,
}

impl Plan {
    /// Every part on, whatever the scene: the reference the benchmark compares with.
    pub fn everything() -> Plan {
        Plan {
            moving_walls: true,
            spin: true,
            sliding_friction: true,
            rolling: true,
            twisting: true,
            edges: true,
            particle_contacts: true,
            wall_index: true,
            reactive: true,
        }
    }

    /// The parts a run of `particles` against `walls` with `settings` needs.
    pub fn for_run(
        walls: &[Wall],
        particles: &[impl AsRef<Particle>],
        settings: &Settings,
    ) -> Plan {
        parts(walls, particles, settings).0
    }
}

/// The plan for a run, with every part's reason, in a fixed order.
pub fn parts(
    walls: &[Wall],
    particles: &[impl AsRef<Particle>],
    settings: &Settings,
) -> (Plan, Vec<Part>) {
    let scene = Scene {
        walls,
        hard: settings.method() == ContactModel::Hsdem,
    };
    let m = &settings.material;
    let moving_walls = moving_walls(&scene);
    let spin = wall_spin(&scene);
    let sliding_friction = sliding_friction(&scene, m);
    let rolling = rolling(&scene, m);
    let twisting = twisting(&scene, m);
    let edges = edges(&scene, settings);
    let particle_contacts = particle_contacts(walls, particles, settings, !sliding_friction.used);
    let wall_index = wall_index(&scene);
    let reactive = reactive_walls(&scene, settings);
    let sticky = sticky_walls(&scene);
    let death = death_walls(&scene);
    let build = pkdgrav_build(walls, particles, settings);
    let model = rolling_model(&scene, settings, rolling.used || twisting.used);
    let gravity = uniform_gravity(settings);
    let plan = Plan {
        moving_walls: moving_walls.used,
        spin: spin.used,
        sliding_friction: sliding_friction.used,
        rolling: rolling.used,
        twisting: twisting.used,
        edges: edges.used,
        particle_contacts: particle_contacts.used,
        wall_index: wall_index.used,
        reactive: reactive.used,
    };
    let out = vec![
        moving_walls,
        spin,
        sliding_friction,
        rolling,
        twisting,
        edges,
        particle_contacts,
        wall_index,
        reactive,
        sticky,
        death,
        build,
        model,
        gravity,
    ];
    (plan, out)
}

impl Part {
    /// A part named `name`, used or not, with the reason `yes` when used, else `no`.
    fn new(name: &'static str, used: bool, yes: String, no: &str) -> Part {
        Part {
            name,
            used,
            reason: if used { yes } else { no.to_string() },
        }
    }
}

/// The walls a plan looks at, and whether the run is HSDEM.
struct Scene<'a> {
    walls: &'a [Wall],
    hard: bool,
}

impl Scene<'_> {
    /// The indices of the walls that pass `test`.
    fn which(&self, test: impl Fn(&Wall) -> bool) -> Vec<usize> {
        self.walls
            .iter()
            .enumerate()
            .filter(|(_, w)| test(w))
            .map(|(i, _)| i)
            .collect()
    }
}

/// `walls`, as a reason names them: the first five, and how many more.
fn list(walls: &[usize]) -> String {
    let shown: Vec<String> = walls.iter().take(5).map(|w| w.to_string()).collect();
    let more = if walls.len() > 5 {
        format!(" and {} more", walls.len() - 5)
    } else {
        String::new()
    };
    format!("{}{more}", shown.join(", "))
}

/// Walls placed every step: some wall moves.
fn moving_walls(scene: &Scene) -> Part {
    let moving = scene.which(|w| w.motion.translates());
    Part::new(
        "moving walls",
        !moving.is_empty(),
        format!("walls {} move", list(&moving)),
        "no wall moves: the walls are placed once",
    )
}

/// The walls' spin in contact velocities: some wall spins.
fn wall_spin(scene: &Scene) -> Part {
    let spinning = scene.which(|w| w.motion.ang_speed != 0.0);
    Part::new(
        "wall spin",
        !spinning.is_empty(),
        format!("walls {} spin", list(&spinning)),
        "no wall spins",
    )
}

/// Tangential springs and Coulomb friction (HSDEM: the tangential restitution).
fn sliding_friction(scene: &Scene, m: &ParticleMaterial) -> Part {
    let hard = scene.hard;
    let rubbing = scene.which(|w| w.material.mu_s > 0.0 || (hard && w.material.eps_t < 1.0));
    let sliding = if hard {
        m.eps_t < 1.0 || !rubbing.is_empty()
    } else {
        m.mu_s > 0.0 || !rubbing.is_empty()
    };
    if hard {
        Part::new(
            "tangential restitution",
            sliding,
            format!(
                "ε_t = {} for the particles, or below 1 on walls {}",
                m.eps_t,
                list(&rubbing)
            ),
            "ε_t = 1 everywhere: tangential velocities are kept",
        )
    } else {
        Part::new(
            "sliding friction (tangential spring)",
            sliding,
            format!(
                "μ_s = {} for the particles, or above 0 on walls {}",
                m.mu_s,
                list(&rubbing)
            ),
            "μ_s = 0 everywhere: no tangential force",
        )
    }
}

/// Rolling resistance (SSDEM).
fn rolling(scene: &Scene, m: &ParticleMaterial) -> Part {
    let rolling_walls = scene.which(|w| w.material.mu_r > 0.0);
    Part::new(
        "rolling resistance",
        !scene.hard && (m.mu_r > 0.0 || !rolling_walls.is_empty()),
        format!(
            "μ_r = {} for the particles, or above 0 on walls {}",
            m.mu_r,
            list(&rolling_walls)
        ),
        "μ_r = 0 everywhere (or HSDEM)",
    )
}

/// Twisting resistance (SSDEM).
fn twisting(scene: &Scene, m: &ParticleMaterial) -> Part {
    let twisting_walls = scene.which(|w| w.material.mu_t > 0.0);
    Part::new(
        "twisting resistance",
        !scene.hard && (m.mu_t > 0.0 || !twisting_walls.is_empty()),
        format!(
            "μ_t = {} for the particles, or above 0 on walls {}",
            m.mu_t,
            list(&twisting_walls)
        ),
        "μ_t = 0 everywhere (or HSDEM)",
    )
}

/// HSDEM edges, corners and rims, with edge detection on.
fn edges(scene: &Scene, settings: &Settings) -> Part {
    let edged = scene.which(|w| {
        matches!(
            w.shape,
            Shape::Rectangle { .. }
                | Shape::Disk { .. }
                | Shape::FiniteCylinder { .. }
                | Shape::Triangle { .. }
        )
    });
    let detect = scene.hard && settings.edges;
    Part::new(
        "edge, corner and rim collisions",
        detect && !edged.is_empty(),
        format!("walls {} have edges, corners or rims", list(&edged)),
        if detect {
            "no wall has edges, corners or rims"
        } else {
            "SSDEM finds edges through the nearest point, or edge detection is off"
        },
    )
}

/// Particle–particle contacts: switched on, more than one particle, and not proved
/// never to meet (which needs `frictionless` contacts).
fn particle_contacts(
    walls: &[Wall],
    particles: &[impl AsRef<Particle>],
    settings: &Settings,
    frictionless: bool,
) -> Part {
    let apart = settings.particle_contacts
        && particles.len() > 1
        && never_meet(walls, particles, frictionless);
    Part::new(
        "particle-particle contacts (cell grid)",
        settings.particle_contacts && particles.len() > 1 && !apart,
        format!("{} particles can meet", particles.len()),
        if !settings.particle_contacts {
            "switched off"
        } else if apart {
            "the only walls are frictionless, non-sticky planes facing one way, and the particles all move at one velocity along them: their separations along the planes never change, and no two are within a diameter there"
        } else {
            "a single particle"
        },
    )
}

/// The wall index: more than [`WALL_INDEX_FROM`] bounded walls, none of them reactive.
fn wall_index(scene: &Scene) -> Part {
    let heavy = scene.walls.iter().any(|w| w.reactive.is_heavy());
    let bounded = scene
        .walls
        .iter()
        .filter(|w| {
            !matches!(
                w.shape,
                Shape::Plane { .. } | Shape::InfiniteCylinder { .. }
            )
        })
        .count();
    Part::new(
        "wall index (bounding-volume hierarchy)",
        bounded > WALL_INDEX_FROM && !heavy,
        format!("{bounded} bounded walls: a hierarchy finds each particle's few"),
        &format!("{bounded} bounded walls: looking at each is as cheap"),
    )
}

/// Reactive walls ([`reactive`]), or why the walls with a mass stay where they are.
fn reactive_walls(scene: &Scene, settings: &Settings) -> Part {
    let heavy = scene.which(|w| w.reactive.is_heavy());
    Part::new(
        "reactive walls",
        reactive(scene.walls, settings),
        format!("walls {} have a mass and an assembly", list(&heavy)),
        if heavy.is_empty() {
            "no wall has both a mass and an assembly"
        } else if !scene.hard {
            "the pkdgrav build lacks DEM_WALLS_REACT: the masses are ignored (W402)"
        } else {
            "HSDEM: pkdgrav's reactive walls are SSDEM only; they stay where they are"
        },
    )
}

/// Sticky walls: `epsn` 0.
fn sticky_walls(scene: &Scene) -> Part {
    let sticky = scene.which(|w| w.material.eps_n == 0.0);
    Part::new(
        "sticky walls",
        !sticky.is_empty(),
        format!("walls {} have epsn 0", list(&sticky)),
        "no wall has epsn 0",
    )
}

/// Death walls: a negative `epsn`.
fn death_walls(scene: &Scene) -> Part {
    let death = scene.which(|w| w.material.eps_n < 0.0);
    Part::new(
        "death walls",
        !death.is_empty(),
        format!("walls {} have a negative epsn", list(&death)),
        "no wall has a negative epsn",
    )
}

/// The pkdgrav build the run follows, with the options the inputs need and it lacks.
fn pkdgrav_build(walls: &[Wall], particles: &[impl AsRef<Particle>], settings: &Settings) -> Part {
    let build = &settings.build;
    let missing = crate::build::missing(build, walls, particles);
    Part::new(
        "pkdgrav build",
        true,
        format!(
            "{}{}",
            build.names(),
            missing
                .iter()
                .map(|(o, why)| format!("; lacks {o}, which the inputs need: {why}"))
                .collect::<String>()
        ),
        "",
    )
}

/// Which rolling and twisting model pkdgrav's contact law uses, when the run has
/// `rolling_or_twisting` resistance.
fn rolling_model(scene: &Scene, settings: &Settings, rolling_or_twisting: bool) -> Part {
    let pkdgrav_law = !scene.hard && settings.integrator == crate::run::Integrator::Pkdgrav;
    Part::new(
        "rolling and twisting model",
        pkdgrav_law && rolling_or_twisting,
        if settings.build.rotation_dashpot {
            "spring-dashpot-sliders scaled by beta_s (DEM_ROTATION_DASHPOT, docs/pkdgrav-physics.md §1.4)"
                .to_string()
        } else if settings.contact_radius {
            "directional constant torques, twisting with the contact radius (no DEM_ROTATION_DASHPOT, bUseContactRadius; docs/pkdgrav-physics.md §1.6)".to_string()
        } else {
            "directional constant torques, no twisting torque (no DEM_ROTATION_DASHPOT; docs/pkdgrav-physics.md §1.6)".to_string()
        },
        if pkdgrav_law {
            "no rolling or twisting friction"
        } else {
            "HSDEM, or an integrator other than pkdgrav's (the summary's capped torques)"
        },
    )
}

/// Uniform gravity.
fn uniform_gravity(settings: &Settings) -> Part {
    let g = settings.gravity.norm();
    Part::new(
        "uniform gravity",
        g > 0.0,
        format!("|g| = {g}"),
        "no gravity",
    )
}

/// Whether the run has reactive walls: assemblies that move in response to particles,
/// in an SSDEM run of a build with `DEM_WALLS_REACT` (without it the masses are ignored,
/// W402). Such a run writes pkdgrav's WALLSREACT files.
pub fn reactive(walls: &[Wall], settings: &Settings) -> bool {
    settings.method() == ContactModel::Ssdem
        && settings.build.walls_react
        && walls.iter().any(|w| w.reactive.is_heavy())
}

/// Whether the particles can be proved never to meet: every wall is a plane with the
/// same normal n̂ (either way), none is sticky, and nothing is frictional, so walls push
/// only along n̂; gravity is uniform; so if all particles move at the same velocity
/// across n̂, their positions across n̂ keep their separations, and if no two are within
/// the sum of their radii there, they never touch.
fn never_meet(walls: &[Wall], particles: &[impl AsRef<Particle>], frictionless: bool) -> bool {
    let particle = |i: usize| particles[i].as_ref();
    let Some(Shape::Plane(first)) = walls.first().map(|w| &w.shape) else {
        return false;
    };
    let n = &first.normal;
    let planes = walls.iter().all(|w| {
        matches!(&w.shape, Shape::Plane(p) if p.normal.cross(n).norm() == 0.0)
            && w.material.eps_n != 0.0
    });
    let across = |v: &nalgebra::Vector3<f64>| v - n * n.dot(v);
    let v0 = across(&particle(0).vel);
    if !frictionless || !planes || particles.iter().any(|p| across(&p.as_ref().vel) != v0) {
        return false;
    }
    let grid = crate::broad::grid::CellGrid::from_fn(particles.len(), |i| {
        Some((across(&particle(i).pos), particle(i).radius))
    });
    let mut any = false;
    grid.for_each_pair(|_, _| any = true);
    !any
}
