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
    pub fn for_run(walls: &[Wall], particles: &[Particle], settings: &Settings) -> Plan {
        parts(walls, particles, settings).0
    }
}

/// The plan for a run, with every part's reason, in a fixed order.
pub fn parts(walls: &[Wall], particles: &[Particle], settings: &Settings) -> (Plan, Vec<Part>) {
    let which = |test: &dyn Fn(&Wall) -> bool| -> Vec<usize> {
        walls
            .iter()
            .enumerate()
            .filter(|(_, w)| test(w))
            .map(|(i, _)| i)
            .collect()
    };
    let list = |ws: &[usize]| {
        let shown: Vec<String> = ws.iter().take(5).map(|w| w.to_string()).collect();
        let more = if ws.len() > 5 {
            format!(" and {} more", ws.len() - 5)
        } else {
            String::new()
        };
        format!("{}{more}", shown.join(", "))
    };
    let mut out = Vec::new();
    let mut part = |name: &'static str, used: bool, yes: String, no: &str| {
        out.push(Part {
            name,
            used,
            reason: if used { yes } else { no.to_string() },
        });
        used
    };
    let hard = settings.method() == ContactModel::Hsdem;
    let m: &ParticleMaterial = &settings.material;
    let moving = which(&|w| w.motion.translates());
    let moving_walls = part(
        "moving walls",
        !moving.is_empty(),
        format!("walls {} move", list(&moving)),
        "no wall moves: the walls are placed once",
    );
    let spinning = which(&|w| w.motion.ang_speed != 0.0);
    let spin = part(
        "wall spin",
        !spinning.is_empty(),
        format!("walls {} spin", list(&spinning)),
        "no wall spins",
    );
    let rubbing = which(&|w| w.material.mu_s > 0.0 || (hard && w.material.eps_t < 1.0));
    let sliding = if hard {
        m.eps_t < 1.0 || !rubbing.is_empty()
    } else {
        m.mu_s > 0.0 || !rubbing.is_empty()
    };
    let sliding_friction = part(
        if hard {
            "tangential restitution"
        } else {
            "sliding friction (tangential spring)"
        },
        sliding,
        if hard {
            format!(
                "ε_t = {} for the particles, or below 1 on walls {}",
                m.eps_t,
                list(&rubbing)
            )
        } else {
            format!(
                "μ_s = {} for the particles, or above 0 on walls {}",
                m.mu_s,
                list(&rubbing)
            )
        },
        if hard {
            "ε_t = 1 everywhere: tangential velocities are kept"
        } else {
            "μ_s = 0 everywhere: no tangential force"
        },
    );
    let soft = !hard;
    let rolling_walls = which(&|w| w.material.mu_r > 0.0);
    let rolling = part(
        "rolling resistance",
        soft && (m.mu_r > 0.0 || !rolling_walls.is_empty()),
        format!(
            "μ_r = {} for the particles, or above 0 on walls {}",
            m.mu_r,
            list(&rolling_walls)
        ),
        "μ_r = 0 everywhere (or HSDEM)",
    );
    let twisting_walls = which(&|w| w.material.mu_t > 0.0);
    let twisting = part(
        "twisting resistance",
        soft && (m.mu_t > 0.0 || !twisting_walls.is_empty()),
        format!(
            "μ_t = {} for the particles, or above 0 on walls {}",
            m.mu_t,
            list(&twisting_walls)
        ),
        "μ_t = 0 everywhere (or HSDEM)",
    );
    let edged = which(&|w| {
        matches!(
            w.shape,
            Shape::Rectangle { .. }
                | Shape::Disk { .. }
                | Shape::FiniteCylinder { .. }
                | Shape::Triangle { .. }
        )
    });
    let edges = part(
        "edge, corner and rim collisions",
        hard && settings.edges && !edged.is_empty(),
        format!("walls {} have edges, corners or rims", list(&edged)),
        if hard && settings.edges {
            "no wall has edges, corners or rims"
        } else {
            "SSDEM finds edges through the nearest point, or edge detection is off"
        },
    );
    let apart = settings.particle_contacts && particles.len() > 1 && {
        let frictionless = !sliding;
        never_meet(walls, particles, frictionless)
    };
    let particle_contacts = part(
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
    );
    let heavy = which(&|w| w.reactive.is_heavy());
    let bounded = walls
        .iter()
        .filter(|w| {
            !matches!(
                w.shape,
                Shape::Plane { .. } | Shape::InfiniteCylinder { .. }
            )
        })
        .count();
    let wall_index = part(
        "wall index (bounding-volume hierarchy)",
        bounded > WALL_INDEX_FROM && heavy.is_empty(),
        format!("{bounded} bounded walls: a hierarchy finds each particle's few"),
        &format!("{bounded} bounded walls: looking at each is as cheap"),
    );
    let reactive = part(
        "reactive walls",
        soft && !heavy.is_empty() && settings.build.walls_react,
        format!("walls {} have a mass and an assembly", list(&heavy)),
        if heavy.is_empty() {
            "no wall has both a mass and an assembly"
        } else if soft {
            "the pkdgrav build lacks DEM_WALLS_REACT: the masses are ignored (W402)"
        } else {
            "HSDEM: pkdgrav's reactive walls are SSDEM only; they stay where they are"
        },
    );
    let sticky = which(&|w| w.material.eps_n == 0.0);
    part(
        "sticky walls",
        !sticky.is_empty(),
        format!("walls {} have epsn 0", list(&sticky)),
        "no wall has epsn 0",
    );
    let death = which(&|w| w.material.eps_n < 0.0);
    part(
        "death walls",
        !death.is_empty(),
        format!("walls {} have a negative epsn", list(&death)),
        "no wall has a negative epsn",
    );
    let build = &settings.build;
    let missing = crate::build::missing(build, walls, particles);
    part(
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
    );
    let pkdgrav_law = soft && settings.integrator == crate::run::Integrator::Pkdgrav;
    part(
        "rolling and twisting model",
        pkdgrav_law && (rolling || twisting),
        if build.rotation_dashpot {
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
    );
    let g = settings.gravity.norm();
    part(
        "uniform gravity",
        g > 0.0,
        format!("|g| = {g}"),
        "no gravity",
    );
    let plan = Plan {
        moving_walls,
        spin,
        sliding_friction,
        rolling,
        twisting,
        edges,
        particle_contacts,
        wall_index,
        reactive,
    };
    (plan, out)
}

/// Whether the particles can be proved never to meet: every wall is a plane with the
/// same normal n̂ (either way), none is sticky, and nothing is frictional, so walls push
/// only along n̂; gravity is uniform; so if all particles move at the same velocity
/// across n̂, their positions across n̂ keep their separations, and if no two are within
/// the sum of their radii there, they never touch.
fn never_meet(walls: &[Wall], particles: &[Particle], frictionless: bool) -> bool {
    let Some(Shape::Plane(first)) = walls.first().map(|w| &w.shape) else {
        return false;
    };
    let n = &first.normal;
    let planes = walls.iter().all(|w| {
        matches!(&w.shape, Shape::Plane(p) if p.normal.cross(n).norm() == 0.0)
            && w.material.eps_n != 0.0
    });
    let across = |v: &nalgebra::Vector3<f64>| v - n * n.dot(v);
    let v0 = across(&particles[0].vel);
    if !frictionless || !planes || particles.iter().any(|p| across(&p.vel) != v0) {
        return false;
    }
    let grid = crate::broad::grid::CellGrid::from_fn(particles.len(), |i| {
        Some((across(&particles[i].pos), particles[i].radius))
    });
    let mut any = false;
    grid.for_each_pair(|_, _| any = true);
    !any
}
