//! The soft-sphere run (SSDEM): kick-drift-kick leapfrog (or pkdgrav's variant that
//! feeds the wall dashpot velocities predicted to the step's end; or pkdgrav's whole
//! order of operations, [`Integrator::Pkdgrav`]; or, to compare, explicit Euler), with
//! the spring–dashpot of [`crate::contact::ssdem`] against every wall and every particle
//! a particle overlaps, and rolling and twisting resistance where the material has them.
//!
//! pkdgrav's overlap warnings (3 % and 15 % of the radius) are reported once each; an
//! overlap above 50 % stops the run, as pkdgrav aborts; more than 3 wall contacts at once
//! on one particle is a warning, as are a particle too fast for the timestep and a wall
//! contact that gains energy (the `W1xx` of [`super::Warning`]). Candidate particle
//! pairs, with their open contacts, and the walls near each particle are kept in a
//! Verlet list ([`PairList`], [`NearWalls`]), found again on a cell grid
//! ([`crate::broad::grid`]) when a particle or a translating wall has moved half the skin.
//!
//! The run is a [`SoftStepper`]: set up once ([`SoftStepper::new`]), then each step is
//! the pipeline of [`SoftStepper::step`]: `move_walls`, `kick_drift` (the kicks owed by
//! the last step, the opening kick and drift, the list's staleness, and which particles
//! this step's wall pass may owe their closing kick), `move_aggregates`, `carry_stuck`
//! (only once a particle is held), `move_assemblies`, the list's update, `pair_contacts`,
//! `wall_contacts` (the contacts and closing kick of the particles not owed theirs,
//! after which each load starts the next step with gravity), `note_wall_contacts`
//! (events and warnings, in particle order), `kick_assemblies` and `gather_aggregates`.
//! The passes over all the particles are plain loops over chunks, in parallel only with
//! many particles and more than one thread; what they carry per particle is kept small
//! (a 160-byte [`State`], its 1/m and 1/I beside it, a 48-byte load, a 32-byte sphere,
//! a byte marking a load that a pair touched),
//! and a free particle clear of the walls gets its closing kick in the next drift
//! rather than in a pass of its own, as memory, not arithmetic, bounds them. The kicks
//! still owed are given ([`SoftStepper::settle`]) when the particles are looked at
//! ([`super::Snapshot`]), at the run's end, and when one might overflow, so a run is bit
//! for bit what it would be with the kick in the wall pass. With
//! [`Integrator::Pkdgrav`], [`SoftStepper::start`] evaluates the forces once before the
//! first step, as pkdgrav does. pkdgrav's aggregates (`AGGS`,
//! [`crate::dynamics::aggregate`]) run only with [`Integrator::Pkdgrav`]; their members
//! are placed by their aggregate, not kicked or drifted, and hand it their loads.

use super::pool::Helpers;
use super::{
    Event, EventKind, Integrator, Materials, Observer, Origins, Outcome, OverlapWarnings,
    Overlapping, PARALLEL_FROM, Settings, State, WallNow, Warning, carry, energy, in_parallel,
};
use crate::broad::grid::{CellGrid, GridScratch};
use crate::broad::wall_index::WallIndex;
use crate::contact::lanes::{self, LANES};
use crate::contact::ssdem::{
    ConstantTorque, Dashpot, Material, Optional, Record, Restitution, Rolling, Sliding, Touch,
    contact, contact_radius, damping_per_root_mass, dashpot_contact_with, lever_contact_radius,
    normal_contact, resistance,
};
use crate::dynamics::aggregate::{self, Aggregates};
use crate::dynamics::reactive::Assembly;
use crate::dynamics::rigid::RotationIntegrator;
use crate::run::optional::OptionalPhysics;
use crate::run::plan::Plan;
use nalgebra::Vector3;
use rayon::prelude::*;
use walls_geometry::Wall;

type Vec3 = Vector3<f64>;

/// An open wall contact: its springs (the tangential spring alone, but with
/// [`Integrator::Pkdgrav`] every spring pkdgrav keeps) and the normal speed it began
/// with.
struct Open {
    record: Record,
    vn_in: f64,
}

/// The inertia of a solid sphere.
fn inertia(m: f64, r: f64) -> f64 {
    0.4 * m * r * r
}

/// The walls as they stand in a step, with their materials, and the step: what every
/// particle's wall contacts share.
struct Walls<'a> {
    now: &'a [WallNow],
    /// Each wall's reactive assembly, if any.
    assembly_of: &'a [Option<usize>],
    /// Each assembly's centre of gravity now.
    cogs: &'a [Vec3],
    /// Each wall's origin now, for the wall index.
    origins: &'a [Vec3],
    /// The wall index, when the plan uses one.
    index: Option<&'a WallIndex>,
    /// Without a wall index, the fixed walls near each particle and the walls that
    /// move ([`NearWalls`]).
    near: Option<&'a NearWalls>,
    plan: &'a Plan,
    /// Each wall's normal damping over √m, worked out once.
    damping: &'a [f64],
    /// Each wall's normal and tangential restitutions, worked out once.
    restitutions: &'a [(Restitution, Restitution)],
    materials: &'a [Material],
    /// The fraction of a step the kick after the forces covers.
    closing_kick: f64,
    /// The fraction of a step by which contact velocities are predicted ahead with the
    /// last acceleration (pkdgrav's dashpot velocity: ½).
    predict: f64,
    /// The fraction of a step by which spins are predicted ahead with the last angular
    /// acceleration.
    predict_spin: f64,
    /// Whether the lever of the contact velocity and of the tangential force is
    /// pkdgrav's r − x (else the radius), with pkdgrav's contact law.
    pkdgrav_levers: bool,
    /// pkdgrav's rolling radius is the contact radius (`bUseContactRadius`).
    contact_radius: bool,
    /// A build without `DEM_ROTATION_DASHPOT`: rolling and twisting are constant
    /// torques (docs/pkdgrav-physics.md §1.6), the rolling lever d with `bUseLegacyRoll`
    /// (the value).
    constant_torque: Option<bool>,
    /// pkdgrav's `dAccCrit` (0: off).
    acc_crit: f64,
    /// What the shear spring of a sliding contact does.
    sliding: Sliding,
    /// Cohesion and two-layer contacts (pkdgrav's optional builds).
    optional: &'a OptionalPhysics,
    /// The time at the step's end, and the timestep.
    t: f64,
    dt: f64,
    /// pkdgrav's aggregates, if any (for their members' rolling pseudo-forces).
    aggregates: Option<&'a Aggregates>,
}

/// What acts on one particle in a step: the force and torque summed so far. Every pass
/// over the particles touches it, so it holds nothing else: the open wall contacts are
/// kept beside it ([`SoftStepper::open_walls`]).
#[derive(Default, Clone, Copy)]
struct Load {
    force: Vec3,
    torque: Vec3,
}

impl Load {
    /// The load a step starts with: gravity alone.
    #[inline]
    fn gravity(s: &State, g: &Vec3) -> Load {
        Load {
            force: g * s.particle.mass,
            torque: Vec3::zeros(),
        }
    }

    /// Whether it holds the same numbers as `other`, bit for bit.
    fn same_as(&self, other: &Load) -> bool {
        let bits = |l: &Load| [l.force, l.torque].map(|v| v.map(f64::to_bits));
        bits(self) == bits(other)
    }
}

/// What one particle's wall contacts did in a step.
#[derive(Default)]
struct ParticleStep {
    events: Vec<Event>,
    /// The deepest overlap, as a fraction of the radius, and its wall.
    deepest: Option<(f64, usize)>,
    touching: usize,
    /// Radii moved in the step, when more than one: it may skip through a wall.
    too_fast: Option<f64>,
    /// The reactions on reactive walls' assemblies: (assembly, force, torque about its
    /// centre of gravity).
    reactions: Vec<(usize, Vec3, Vec3)>,
    /// Its position, velocity or spin is no longer finite.
    not_finite: bool,
}

impl ParticleStep {
    /// Whether there is nothing to note (the particle touched no wall and is well).
    fn is_empty(&self) -> bool {
        self.events.is_empty()
            && self.deepest.is_none()
            && self.touching == 0
            && self.too_fast.is_none()
            && self.reactions.is_empty()
            && !self.not_finite
    }
}

/// What the wall pass works on for one particle besides its state: its load, its 1/m and
/// 1/I, its open wall contacts (wall, contact), and its chunk's scratch list of the
/// walls to visit.
struct WallWork<'a> {
    load: &'a mut Load,
    /// 1/m and 1/I.
    inverse: (f64, f64),
    open: &'a mut Vec<(usize, Open)>,
    visit: &'a mut Vec<usize>,
}

/// One particle's contacts with the walls at the step's time, added to its load (which
/// holds gravity and the particle contacts already), then the closing kick.
fn wall_step(i: usize, s: &mut State, mut work: WallWork, walls: &Walls) -> ParticleStep {
    let dt = walls.dt;
    let mut out = ParticleStep::default();
    if !s.alive {
        return out;
    }
    if let Some(&(w, _)) = s.stuck_to.as_deref() {
        // pkdgrav carries a stuck particle with its wall's move, before the forces
        // (docs/pkdgrav-physics.md §6; `SoftStepper::carry_stuck`).
        if !walls.pkdgrav_levers {
            carry(s, &walls.now[w], dt);
        }
        return out;
    }
    let r = s.particle.radius;
    let moved = s.particle.vel.norm_squared() * dt * dt;
    if moved > r * r {
        out.too_fast = Some(moved.sqrt() / r);
    }
    if !clear_of_walls(i, s, work.open, walls) && touch_walls(i, s, &mut work, walls, &mut out) {
        return out;
    }
    if s.member {
        // Its aggregate takes the load (`SoftStepper::gather_aggregates`).
        return out;
    }
    close_step(s, work.load, work.inverse, walls.closing());
    out
}

/// The closing kick of a step, as [`close_step`] gives it: the timestep, the fraction of
/// it the kick covers, and pkdgrav's `dAccCrit`.
#[derive(Clone, Copy)]
struct Closing {
    dt: f64,
    fraction: f64,
    acc_crit: f64,
}

impl Walls<'_> {
    /// This step's closing kick.
    fn closing(&self) -> Closing {
        Closing {
            dt: self.dt,
            fraction: self.closing_kick,
            acc_crit: self.acc_crit,
        }
    }
}

/// Whether particle `i` (state `s`) touches no wall and cannot: no contact open, and
/// every wall near it surely out of its reach ([`walls_geometry::shape::Cull::clear_of`], the test
/// [`touch_walls`] makes first): nothing to look at. Most particles near a wall are not
/// touching it.
#[inline]
fn clear_of_walls(i: usize, s: &State, open: &[(usize, Open)], walls: &Walls) -> bool {
    walls.index.is_none()
        && open.is_empty()
        && clear_of_near(i, &s.particle.pos, s.particle.radius, walls.near, walls.now)
}

/// [`clear_of_walls`] for particle `i` (at `pos`, of radius `r`) without a wall index
/// and with no contact open: its near walls (`near`, as they stand: `now`) all surely
/// out of its reach, and none moving.
#[inline(always)]
fn clear_of_near(i: usize, pos: &Vec3, r: f64, near: Option<&NearWalls>, now: &[WallNow]) -> bool {
    let Some(near) = near else {
        return true;
    };
    if !near.moving.is_empty() {
        return false;
    }
    // A plain loop (most particles have no wall near, some one or two).
    for &w in near.listed_of(i) {
        if !now[w].cull.clear_of(pos, r) {
            return false;
        }
    }
    true
}

/// [`wall_step`] for a free particle clear of every wall but not owed its kick (it moved
/// far in the step, say): the closing kick alone, and a report only if there is
/// something to note.
#[inline(always)]
fn clear_step(
    s: &mut State,
    load: &Load,
    inverse: (f64, f64),
    walls: &Walls,
) -> Option<ParticleStep> {
    let r = s.particle.radius;
    let moved = s.particle.vel.norm_squared() * walls.dt * walls.dt;
    let motion = close_step(s, load, inverse, walls.closing());
    let too_fast = (moved > r * r).then(|| moved.sqrt() / r);
    let not_finite = !s.finite_with(motion);
    (too_fast.is_some() || not_finite).then(|| ParticleStep {
        too_fast,
        not_finite,
        ..ParticleStep::default()
    })
}

/// The accelerations of a free particle from its load, pkdgrav's `dAccCrit`, and the
/// kick after the forces; the sum of the new velocity's and spin's components, for
/// [`State::finite_with`] (from registers: reading back what was just stored, in wider
/// loads than it was stored with, stalls the processor). The drift gives an owed kick
/// with the same arithmetic ([`SoftStepper::kick_drift`]): a change here is a change
/// there, or a run would differ with whether its kicks are owed.
#[inline(always)]
fn close_step(s: &mut State, load: &Load, inverse: (f64, f64), kick: Closing) -> f64 {
    let Closing {
        dt,
        fraction,
        acc_crit,
    } = kick;
    s.acc = load.force * inverse.0;
    s.alpha = load.torque * inverse.1;
    if acc_crit > 0.0 {
        zero_small_motions(s, acc_crit, dt);
    }
    let vel = s.particle.vel + s.acc * (dt * fraction);
    let spin = s.particle.spin + s.alpha * (dt * fraction);
    s.particle.vel = vel;
    s.particle.spin = spin;
    vel.sum() + spin.sum()
}

/// Particle `i`'s contacts with the walls it may touch, added to its load (its open
/// contacts opened and closed); what they did goes into `out`. Whether the particle was
/// held or removed by a wall (its step ends there).
fn touch_walls(
    i: usize,
    s: &mut State,
    work: &mut WallWork,
    walls: &Walls,
    out: &mut ParticleStep,
) -> bool {
    let WallWork {
        load, open, visit, ..
    } = work;
    let (t, dt) = (walls.t, walls.dt);
    let (m, r) = (s.particle.mass, s.particle.radius);
    let (mut resist, mut stop) = (Vec3::zeros(), 0.0f64);
    // The walls within reach (from the wall index, when the plan uses one), and those
    // the particle touched last step, whose contacts may end; in wall order either way.
    visit.clear();
    let indexed = walls.index.is_some();
    match walls.index {
        Some(index) => {
            index.for_each_candidate(&s.particle.pos, r, walls.origins, |w| visit.push(w));
            // The candidates come ascending; search only them (the walls pushed after
            // them are not in order), so no wall is visited twice.
            let candidates = visit.len();
            for (w, _) in open.iter() {
                if visit[..candidates].binary_search(w).is_err() {
                    visit.push(*w);
                }
            }
            visit.sort_unstable();
        }
        None => {
            if let Some(near) = walls.near {
                visit.extend(near.of(i));
                visit.extend(near.moving.iter().copied());
                for (w, _) in open.iter() {
                    visit.push(*w);
                }
                if visit.len() > 1 {
                    visit.sort_unstable();
                    visit.dedup();
                }
            }
        }
    }
    let indexed = indexed || walls.near.is_some();
    let count = if indexed {
        visit.len()
    } else {
        walls.now.len()
    };
    let listed = |at: usize| if indexed { visit[at] } else { at };
    for at in 0..count {
        let w = listed(at);
        let wall = &walls.now[w];
        let k = open.iter().position(|(o, _)| *o == w);
        // Most particles are far from most walls: a cheap test first, unless a contact
        // is open (its end is an event).
        if k.is_none() && wall.cull.clear_of(&s.particle.pos, r) {
            continue;
        }
        let near = wall.shape.nearest(&s.particle.pos);
        let overlap = r - near.distance;
        let n = near.normal;
        if overlap <= 0.0 {
            if let Some(k) = k {
                let o = open.swap_remove(k).1;
                let wall_v = wall.point_velocity(&near.point);
                out.events.push(Event {
                    t,
                    particle: i,
                    wall: w,
                    kind: EventKind::Bounce,
                    vn_in: o.vn_in,
                    vn_out: n.dot(&(s.particle.vel - wall_v)),
                });
            }
            continue;
        }
        let wall_v = wall.point_velocity(&near.point);
        out.touching += 1;
        if out.deepest.is_none_or(|(f, _)| overlap / r > f) {
            out.deepest = Some((overlap / r, w));
        }
        let vel = s.particle.vel + s.acc * (dt * walls.predict);
        let spin = if walls.predict_spin != 0.0 {
            s.particle.spin + s.alpha * (dt * walls.predict_spin)
        } else {
            s.particle.spin
        };
        let lever = if walls.pkdgrav_levers { r - overlap } else { r };
        let u = vel + spin.cross(&(-n * lever)) - wall_v;
        let mat = &walls.materials[w];
        let k = k.unwrap_or_else(|| {
            open.push((
                w,
                Open {
                    record: Record::default(),
                    vn_in: -n.dot(&u),
                },
            ));
            open.len() - 1
        });
        if mat.eps_n <= 0.0 {
            if s.member {
                // An aggregate neither sticks nor dies (pkdgrav asserts, physics.md
                // §9.5): the event, and `note_wall_contacts` stops the run.
                out.events.push(Event {
                    t,
                    particle: i,
                    wall: w,
                    kind: if mat.eps_n < 0.0 {
                        EventKind::Remove
                    } else {
                        EventKind::Stick
                    },
                    vn_in: open[k].1.vn_in,
                    vn_out: 0.0,
                });
                open.swap_remove(k);
                return true;
            }
            // A death wall removes the particle; a sticky wall holds it.
            let kind = if mat.eps_n < 0.0 {
                s.alive = false;
                EventKind::Remove
            } else {
                s.stuck_to = Some(Box::new((w, s.particle.pos - wall.origin)));
                s.particle.vel = wall_v;
                s.particle.spin = wall.spin;
                EventKind::Stick
            };
            out.events.push(Event {
                t,
                particle: i,
                wall: w,
                kind,
                vn_in: open[k].1.vn_in,
                vn_out: 0.0,
            });
            open.swap_remove(k);
            return true;
        }
        let plan = walls.plan;
        if walls.pkdgrav_levers
            && (plan.sliding_friction || plan.rolling || plan.twisting || walls.optional.any())
        {
            // pkdgrav's contact law, in its frame: the normal towards the wall, the
            // wall's motion relative to the particle's (docs/pkdgrav-physics.md
            // §1.1–§1.5). A reactive wall turns the springs by its spin about the face
            // normal or axis alone (docs/pkdgrav-physics.md §10).
            let wall_spin = match walls.assembly_of[w] {
                Some(_) => crate::dynamics::reactive::relative_spin(&wall.shape, &wall.spin),
                None => wall.spin,
            };
            let a = walls.contact_radius.then(|| lever_contact_radius(r, lever));
            let dashpot = Dashpot {
                overlap,
                normal: -n,
                velocity: -u,
                spin: wall_spin - spin,
                turn: s.particle.spin + wall_spin,
                levers: (lever, 0.0),
                mass: m,
                radius: a.unwrap_or(r),
                wall: true,
                constant_torque: walls.constant_torque.map(|legacy| ConstantTorque {
                    spins: (spin, Vec3::zeros()),
                    roll_levers: match (a, legacy) {
                        (Some(a), _) => (a, 0.0),
                        (None, true) => (lever, 0.0),
                        (None, false) => (r, 0.0),
                    },
                    twist_radius: a.unwrap_or(0.0),
                    inertias: (inertia(m, r), f64::INFINITY),
                }),
                sliding: walls.sliding,
            };
            let extra = Optional {
                restitution: Some(walls.restitutions[w]),
                ..walls.optional.wall(w, i, r, a, mat)
            };
            let c = dashpot_contact_with(&dashpot, &mut open[k].1.record, dt, mat, &extra);
            load.force += c.force;
            load.torque += c.torque;
            if s.member
                && c.rolling != Vec3::zeros()
                && let Some(aggs) = walls.aggregates
            {
                // An aggregate feels the rolling torque as a pseudo-force at the contact
                // point, with its moment about the aggregate's centre
                // (docs/pkdgrav-physics.md §9.4).
                let push = aggregate::rolling_push(&c.rolling, &-n, lever);
                let arm = aggs.offset(i, &s.particle.pos) - n * lever;
                load.torque += arm.cross(&push) - c.rolling;
            }
            if let Some(a) = walls.assembly_of[w] {
                // The reaction (docs/pkdgrav-physics.md §10), with the rolling and
                // twisting torques.
                let at = s.particle.pos - n * lever;
                out.reactions.push((
                    a,
                    -c.force,
                    (at - walls.cogs[a]).cross(&-c.force) - c.resistance,
                ));
            }
            continue;
        }
        let touch = Touch {
            overlap,
            normal: n,
            velocity: u,
        };
        let c = if plan.sliding_friction {
            contact(m, lever, &touch, &mut open[k].1.record.spring, dt, mat)
        } else {
            normal_contact(&touch, mat.k_n, walls.damping[w] * m.sqrt())
        };
        load.force += c.force;
        load.torque += c.torque;
        if let Some(a) = walls.assembly_of[w] {
            // The reaction, at the contact point on the particle's surface (where its
            // own torque acts, so that angular momentum is kept exactly).
            let cog = walls.cogs[a];
            let at = s.particle.pos - n * lever;
            out.reactions
                .push((a, -c.force, (at - cog).cross(&-c.force)));
        }
        if walls.plan.rolling || walls.plan.twisting {
            let rolling = Rolling {
                spin: spin - wall.spin,
                normal: n,
                normal_force: n.dot(&c.force).abs(),
                lever: r,
                contact_radius: contact_radius(r, overlap),
                inertia: inertia(m, r),
            };
            resist += resistance(&rolling, mat.mu_r, mat.mu_t, dt);
            stop = stop.max(inertia(m, r) * rolling.spin.norm() / dt);
        }
    }
    // Each contact's resistance is capped, but together they must not reverse the spin
    // either (a corner's floor and side on one spin component).
    if resist != Vec3::zeros() && resist.norm() > stop {
        resist *= stop / resist.norm();
    }
    load.torque += resist;
    false
}

/// pkdgrav's `dAccCrit` zeroing (`dem.c pkdDEMZeroSmallMotions`, docs/pkdgrav-physics.md
/// §1.7): a particle slowing down (a·v < 0) with |a| < a_c and |v| < a_c·dt is stopped, v
/// and a both zeroed; its spin likewise, with |ẇ| < a_c·r and |w| < a_c·dt/r.
fn zero_small_motions(s: &mut State, a_c: f64, dt: f64) {
    let p = &mut s.particle;
    if s.acc.dot(&p.vel) < 0.0 && s.acc.norm() < a_c && p.vel.norm() < a_c * dt {
        p.vel = Vec3::zeros();
        s.acc = Vec3::zeros();
    }
    let r = p.radius;
    if s.alpha.dot(&p.spin) < 0.0 && s.alpha.norm() < a_c * r && p.spin.norm() < a_c * dt / r {
        p.spin = Vec3::zeros();
        s.alpha = Vec3::zeros();
    }
}

/// The fractions of a step each kick of the integrator covers, and how far ahead the
/// dashpot's velocities are predicted.
#[derive(Clone, Copy)]
struct Kicks {
    /// The kick before the drift.
    opening: f64,
    /// The kick after the drift, with the last acceleration.
    late: f64,
    /// The kick after the forces.
    closing: f64,
    /// The contact-velocity prediction with the last acceleration, against walls.
    predict: f64,
    /// The prediction of spins (against walls and particles) and of the velocities of
    /// particles meeting each other.
    predict_all: f64,
    /// pkdgrav's levers (docs/pkdgrav-physics.md §1.1) instead of the radii.
    pkdgrav_levers: bool,
}

impl Kicks {
    fn of(integrator: Integrator) -> Kicks {
        let (opening, late, closing, predict, predict_all) = match integrator {
            Integrator::Leapfrog => (0.5, 0.0, 0.5, 0.0, 0.0),
            Integrator::LeapfrogPredicted => (0.5, 0.0, 0.5, 0.5, 0.0),
            Integrator::ExplicitEuler => (0.0, 1.0, 0.0, 0.0, 0.0),
            Integrator::Pkdgrav => (0.5, 0.0, 0.5, 0.5, 0.5),
        };
        Kicks {
            opening,
            late,
            closing,
            predict,
            predict_all,
            pkdgrav_levers: integrator == Integrator::Pkdgrav,
        }
    }

    /// pkdgrav's force evaluation at the start (docs/pkdgrav-physics.md §2): the
    /// velocities and spins as they are (v^pred = v, w^pred = w), and no kick after it.
    fn at_start(self) -> Kicks {
        Kicks {
            closing: 0.0,
            predict: 0.0,
            predict_all: 0.0,
            ..self
        }
    }
}

/// The warnings pkdgrav gives once a run, and whether each has been given.
#[derive(Default)]
struct WarnedOnce {
    crowd: bool,
    fast: bool,
    gain: bool,
}

/// Whether a run goes on after a step.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Flow {
    Continue,
    /// An overlap past pkdgrav's abort.
    Stop,
}

/// A soft-sphere run as it goes: the particles and what acts on them, the walls and
/// assemblies as they stand, the open contacts, and what the run has seen so far. A step
/// is [`SoftStepper::step`].
struct SoftStepper<'a> {
    scene: &'a [Wall],
    settings: &'a Settings,
    plan: &'a Plan,
    states: Vec<State>,
    kicks: Kicks,
    /// Each wall's material, with the particles' values where it says so.
    materials: Vec<Material>,
    /// Each wall's normal damping over √m, worked out once.
    damping: Vec<f64>,
    /// Each wall's normal and tangential restitutions, worked out once.
    restitutions: Vec<(Restitution, Restitution)>,
    /// The particles' material, for their contacts with each other.
    between: Material,
    /// Cohesion and two-layer contacts (pkdgrav's optional builds).
    optional: OptionalPhysics,
    /// Whether each wall oscillates (a bounce off it may gain speed).
    oscillating: Vec<bool>,
    /// The wall index, when the plan uses one.
    index: Option<WallIndex>,
    origins: Origins,
    /// The walls as they stand: placed once when no wall moves (the plan), else every
    /// step; reactive assemblies' walls every step.
    now: Vec<WallNow>,
    /// Reactive assemblies (SSDEM only, as in pkdgrav), when the plan has them.
    assemblies: Vec<Assembly>,
    /// Each wall's assembly, if any.
    assembly_of: Vec<Option<usize>>,
    /// Each assembly's centre of gravity this step (kept to save allocating).
    cogs: Vec<Vec3>,
    /// pkdgrav's rigid aggregates of particles (`AGGS`, docs/pkdgrav-physics.md §9), if
    /// any.
    aggregates: Option<Aggregates>,
    /// Set up failed (an aggregate of one member): the run stops before it starts.
    halted: bool,
    loads: Vec<Load>,
    /// Each particle's 1/m and 1/I (a solid sphere's I = 0.4·m·r²), worked out once (a
    /// division costs as much as the rest of a free particle's step), and kept beside
    /// the states, which the drift writes back every step: it only reads these.
    inverses: Vec<(f64, f64)>,
    /// Whether each particle's closing kick is owed: a free particle clear of the walls
    /// gets it in the next drift ([`SoftStepper::kick_drift`]) rather than in the wall
    /// pass, which saves a pass over the particles; [`SoftStepper::settle`] gives it
    /// when the particles are looked at. Marked in the drift; owed once the wall pass
    /// has run (`owing`).
    owed: Vec<bool>,
    /// Whether each particle's load may hold more than gravity, when the last pair pass
    /// marked them (`marks_valid`): set there for both particles of every pair that
    /// touches (pair forces are all that an owed particle's load takes: the wall pass
    /// does not visit it), cleared where the drift, the marks valid, sets an owed load
    /// back to gravity. An owed load not marked is then gravity bit for bit, so the
    /// drift works it out from the particle's mass rather than reading it and writing
    /// it back: most particles touch nothing in most steps, and at 10⁵ particles those
    /// 96 bytes a particle were about a tenth of the time of the drop's first 2,000
    /// steps (docs/performance.md, "Fourteenth round"). A mark left on a load already
    /// set back (by the wall pass, by [`SoftStepper::settle`], or by the drift while
    /// the marks were not valid) only makes the drift read it.
    loaded: Vec<bool>,
    /// Whether the last pair pass marked the loads it added to ([`SoftStepper::loaded`]):
    /// when at most one pair in eight particles touched. With more, as in a pile, the
    /// drift reads every owed load, which costs less than testing each mark.
    marks_valid: bool,
    /// Whether the wall pass has run since the drift marked the kicks it may owe.
    owing: bool,
    /// The particles whose kicks are not owed, which the wall pass visits: each chunk's
    /// (its particles' places within it, ascending), listed by the drift; every particle
    /// before the first drift.
    visited: Vec<Vec<u32>>,
    /// The closing kick owed.
    owed_kick: Closing,
    /// The first particle whose numbers overflowed in an owed kick given by
    /// [`SoftStepper::settle`] this step.
    owed_bad: Option<usize>,
    /// The sum of the sizes (|x| + |y| + |z|) of every particle contact's force and
    /// torques this step, and the largest size of gravity on a particle, and 1/m or 1/I
    /// of a particle: bounds on what an owed kick can add ([`SoftStepper::surely_finite`]).
    force_bound: f64,
    gravity_bound: f64,
    largest_inverse: f64,
    /// Each particle's open wall contacts: (wall, contact), kept apart from its load so
    /// that the passes that do not need them do not carry them.
    open_walls: Vec<Vec<(usize, Open)>>,
    /// Whether each particle has a wall contact open (its [`SoftStepper::open_walls`]
    /// is not empty): set by the wall pass after each particle's contacts, the only place
    /// they change (a particle the pass skips had none, nor has it now), and read by the
    /// drift as this byte, not the 24-byte vector, which at 10⁵ particles is memory the
    /// drift's stream need not carry (docs/performance.md, "Eighth round").
    walled: Vec<bool>,
    /// Each chunk's scratch list of the walls to visit (kept to save allocating).
    visits: Vec<Vec<usize>>,
    candidates: PairList,
    /// What the wall contacts of each particle with something to note did this step,
    /// in particle order (kept to save allocating).
    reports: Vec<Vec<(usize, ParticleStep)>>,
    /// Whether a step runs on rayon's threads (many particles, and more than one
    /// thread).
    parallel: bool,
    /// The energy at the start.
    initial: f64,
    events: Vec<Event>,
    pair_contacts: u64,
    warnings: Vec<Warning>,
    overlaps: OverlapWarnings,
    once: WarnedOnce,
    t: f64,
    steps: u64,
}

impl<'a> SoftStepper<'a> {
    /// The run at its start: the materials, the checks before it ([`super::stability`]),
    /// the walls, the assemblies that can move, the candidate pairs.
    fn new(
        scene: &'a [Wall],
        states: Vec<State>,
        settings: &'a Settings,
        plan: &'a Plan,
    ) -> SoftStepper<'a> {
        let g = settings.gravity;
        let Materials {
            walls: materials,
            mut between,
        } = Materials::new(scene, &settings.material);
        // pkdgrav without DEM_WALLS_REACT reads the walls' masses and ignores them.
        let reactive = plan.reactive && settings.build.walls_react;
        if settings.build.aggs {
            // An AGGS build has no rolling or twisting between particles (§9.6).
            between.mu_r = 0.0;
            between.mu_t = 0.0;
        }
        let initial = energy(&states, &g)
            + if reactive {
                assembly_energy(&crate::dynamics::reactive::assemblies(scene), &g)
            } else {
                0.0
            };
        let n = states.len();
        // Each load starts the run with gravity alone, whichever the integrator (pkdgrav's
        // evaluation before the first step, `SoftStepper::start`, adds to it; the others
        // kick with it at once). In a step, the wall pass starts the next step's, or the
        // drift or `SoftStepper::settle` after an owed kick, and for an aggregate's
        // members.
        let loads = states.iter().map(|s| Load::gravity(s, &g)).collect();
        let candidates = PairList::new(&states, plan.particle_contacts);
        let mut warnings = Vec::new();
        let oscillating: Vec<bool> = scene
            .iter()
            .map(|w| w.motion.oscillation.amplitude != 0.0)
            .collect();
        warnings.extend(super::stability::soft_warnings(scene, &states, settings));
        let mut states = states;
        let (aggregates, halted) = set_up_aggregates(&mut states, settings, &mut warnings);
        let mut candidates = candidates;
        candidates.held |= aggregates.is_some();
        let origins = Origins::new(scene, settings.stepping, settings.t_start());
        let now = if settings.integrator == Integrator::Pkdgrav {
            origins.walls_pkdgrav(scene, settings.t_start())
        } else {
            origins.walls(scene, settings.t_start())
        };
        let heavy: Vec<usize> = (0..scene.len())
            .filter(|&w| scene[w].reactive.is_heavy())
            .collect();
        if !heavy.is_empty() && !settings.build.walls_react {
            warnings.push(Warning::MassesIgnored { walls: heavy });
        }
        let mut assemblies = if reactive {
            crate::dynamics::reactive::assemblies(scene)
        } else {
            Vec::new()
        };
        if settings.integrator == Integrator::Pkdgrav {
            for a in &mut assemblies {
                a.follow_pkdgrav(scene);
            }
        }
        let stuck = crate::dynamics::reactive::immovable(&assemblies);
        if !stuck.is_empty() {
            assemblies.retain(|a| !stuck.contains(&a.number));
            warnings.push(Warning::ImmovableAssemblies { assemblies: stuck });
        }
        let mut assembly_of = vec![None; scene.len()];
        for (a, assembly) in assemblies.iter().enumerate() {
            for &w in &assembly.walls {
                assembly_of[w] = Some(a);
            }
        }
        let index = plan.wall_index.then(|| WallIndex::new(scene));
        if index.is_none() && !scene.is_empty() {
            let listed = assembly_of.iter().map(Option::is_none).collect();
            let translating = scene.iter().map(|w| w.motion.translates()).collect();
            candidates.near = Some(NearWalls::new(listed, translating));
        }
        // Built once, with the walls near each particle when it keeps them.
        candidates.build(&states, &now);
        let optional = OptionalPhysics::new(scene, &states, settings);
        let damping: Vec<f64> = materials
            .iter()
            .map(|m| damping_per_root_mass(m.eps_n, m.k_n))
            .collect();
        let restitutions = materials
            .iter()
            .map(|m| (Restitution::new(m.eps_n), Restitution::new(m.eps_t)))
            .collect();
        // The largest, or not a number if any is (then no kick is owed unchecked).
        let largest = |a: f64, b: f64| {
            if a.is_nan() || b.is_nan() {
                f64::NAN
            } else {
                a.max(b)
            }
        };
        let gravity_bound =
            g.abs().sum() * (states.iter()).map(|s| s.particle.mass).fold(0.0, largest);
        let inverses: Vec<(f64, f64)> = (states.iter())
            .map(|s| {
                let p = &s.particle;
                (1.0 / p.mass, 1.0 / (0.4 * p.mass * p.radius * p.radius))
            })
            .collect();
        let largest_inverse = (inverses.iter())
            .map(|i| largest(i.0, i.1))
            .fold(0.0, largest);
        SoftStepper {
            restitutions,
            scene,
            settings,
            plan,
            states,
            kicks: Kicks::of(settings.integrator),
            materials,
            damping,
            between,
            optional,
            oscillating,
            index,
            origins,
            now,
            cogs: Vec::with_capacity(assemblies.len()),
            aggregates,
            halted,
            assemblies,
            assembly_of,
            gravity_bound,
            largest_inverse,
            inverses,
            loads,
            owed: vec![false; n],
            loaded: vec![false; n],
            marks_valid: false,
            owing: false,
            visited: (0..n.div_ceil(CHUNK))
                .map(|c| (0..(n - c * CHUNK).min(CHUNK) as u32).collect())
                .collect(),
            owed_kick: Closing {
                dt: settings.dt,
                fraction: 0.0,
                acc_crit: settings.acc_crit,
            },
            owed_bad: None,
            force_bound: 0.0,
            open_walls: (0..n).map(|_| Vec::new()).collect(),
            walled: vec![false; n],
            visits: Vec::new(),
            candidates,
            reports: Vec::new(),
            parallel: in_parallel(n),
            initial,
            events: Vec::new(),
            pair_contacts: 0,
            warnings,
            overlaps: OverlapWarnings::default(),
            once: WarnedOnce::default(),
            t: settings.t_start(),
            steps: settings.start_step,
        }
    }

    /// pkdgrav's force evaluation at the start, before the first step
    /// (docs/pkdgrav-physics.md §2, §12), for [`Integrator::Pkdgrav`]: gravity and every
    /// contact open at t₀, with the velocities and spins as they are, added to the loads
    /// (which start with gravity, [`SoftStepper::new`]). It sets the accelerations the
    /// first kick uses and steps the springs of those contacts once; it moves and kicks
    /// nothing.
    fn start(&mut self) -> Flow {
        let kicks = self.kicks;
        self.kicks = kicks.at_start();
        self.place_assemblies();
        let mut flow = Flow::Continue;
        if self.plan.particle_contacts
            && self.settings.forces
            && self.states.len() > 1
            && self.pair_contacts() == Flow::Stop
        {
            flow = Flow::Stop;
        }
        if flow == Flow::Continue {
            self.wall_contacts();
            flow = self.note_wall_contacts();
            self.sum_reactions();
            self.gather_aggregates(false);
        }
        self.kicks = kicks;
        flow
    }

    /// Whether another step is due before the end.
    fn running(&self) -> bool {
        self.settings.due(self.steps)
    }

    /// One step: the walls moved on, kick and drift (with the last step's owed kicks),
    /// the assemblies moved on, the forces of the
    /// particle contacts and then of the wall contacts (with the closing kick), what
    /// they did, and the assemblies' closing kick.
    fn step(&mut self) -> Flow {
        // The walls first (they do not depend on the particles): the drift finds which
        // particles are out of their reach where they stand this step.
        self.move_walls();
        // The drift compiled without pkdgrav's `dAccCrit` and with it: its test and its
        // call in the loop cost the common case about 3 % of the run
        // (docs/performance.md, "Twelfth round").
        if self.owed_kick.acc_crit > 0.0 {
            self.kick_drift::<true>();
        } else {
            self.kick_drift::<false>();
        }
        self.move_aggregates();
        if self.kicks.pkdgrav_levers {
            self.carry_stuck();
        }
        self.move_assemblies();
        self.candidates.update(&self.states, &self.now);
        if self.plan.particle_contacts
            && self.settings.forces
            && self.states.len() > 1
            && self.pair_contacts() == Flow::Stop
        {
            return Flow::Stop;
        }
        self.wall_contacts();
        let flow = self.note_wall_contacts();
        self.kick_assemblies();
        self.gather_aggregates(true);
        flow
    }

    /// pkdgrav's aggregates (docs/pkdgrav-physics.md §9.3): the opening half kick of each
    /// centre, the drift (the rotation by Euler's equations, the centre with its
    /// half-step velocity), and the members placed where it has taken them.
    fn move_aggregates(&mut self) {
        let Some(aggs) = self.aggregates.as_mut() else {
            return;
        };
        let dt = self.settings.dt;
        for a in &mut aggs.list {
            a.kick(0.5 * dt);
            a.advance(dt);
            a.place(&mut self.states, dt);
        }
    }

    /// Each aggregate's acceleration and torque from its members' loads
    /// (docs/pkdgrav-physics.md §9.4), and, after a step's forces, its closing half kick.
    fn gather_aggregates(&mut self, kick: bool) {
        let Some(aggs) = self.aggregates.as_mut() else {
            return;
        };
        let (g, dt) = (self.settings.gravity, self.settings.dt);
        let loads = &self.loads;
        for a in &mut aggs.list {
            a.gather(&self.states, |i| (loads[i].force, loads[i].torque), &g);
            if kick {
                a.kick(0.5 * dt);
            }
        }
    }

    /// The kick before the drift (leapfrog's first half; none in explicit Euler), the
    /// drift, and the kick after it (explicit Euler's), for the free particles; in the
    /// same pass, each free particle first gets the last step's closing kick if the wall
    /// pass left it owed ([`SoftStepper::owed`]), the loads of an aggregate's members
    /// start the step with gravity alone (the others' were started by the last wall pass
    /// or here, after the owed kick), the candidate pairs learn whether a drifted
    /// particle has moved far enough to rebuild them ([`PairList::drifted`]), and each
    /// particle is marked whether this step's wall pass may owe it its closing kick
    /// ([`SoftStepper::may_owe`]). `ACC_CRIT`: whether the owed kicks apply pkdgrav's
    /// `dAccCrit` (the run's `acc_crit` is positive).
    fn kick_drift<const ACC_CRIT: bool>(&mut self) {
        let dt = self.settings.dt;
        let g = self.settings.gravity;
        let Kicks { opening, late, .. } = self.kicks;
        let limit = self.candidates.limit();
        let half = self.candidates.skin / 2.0;
        // The kicks owed by the last wall pass, if it owed any.
        let pay = std::mem::take(&mut self.owing).then_some(self.owed_kick);
        let marks_valid = self.marks_valid;
        let forces = self.settings.forces;
        let PairList {
            built_at,
            spheres,
            near,
            ..
        } = &mut self.candidates;
        // The walls as the wall pass will see them (`SoftStepper::wall_contacts`). The
        // walls near a particle were found where it and they stood at the last rebuild:
        // a wall not among them was then farther than its radius and half the skin (a
        // translating one, the skin), so it cannot reach a particle that has moved less
        // than half the skin since, unless the wall itself has moved more. Such a
        // particle is owed nothing, and when a wall has moved that far, no particle is
        // (the list is found again after this pass). Nothing is owed with a wall index
        // or the walls of reactive assemblies, placed only after this pass.
        let near = near.as_ref().filter(|_| forces);
        let now: &[WallNow] = if forces { &self.now } else { &[] };
        let owing = self.index.is_none() || !forces;
        let owing = owing && near.is_none_or(|n| !n.moved(now, half));
        // The settings held by value (`move`): by reference, every particle read each
        // through a pointer to these locals.
        let kick_drift = move |i: usize, s: &mut State, work: DriftWork| {
            let DriftWork {
                load,
                loaded,
                owed,
                at,
                sphere,
                walled,
                inverse,
            } = work;
            if s.member {
                // The others' loads were started in the last wall pass, once used.
                *load = Load::gravity(s, &g);
                *owed = false;
                return false;
            }
            if !s.free() {
                *owed = false;
                return false;
            }
            // In locals, each field read once and written once: read back at once,
            // what was just written stalls the processor.
            let (mut vel, mut spin, mut acc, mut alpha) =
                (s.particle.vel, s.particle.spin, s.acc, s.alpha);
            if let (true, Some(kick)) = (*owed, pay) {
                // The last step's closing kick, as the wall pass would have given it
                // (`close_step`'s arithmetic, in its order, from the locals).
                debug_assert_eq!(ACC_CRIT, kick.acc_crit > 0.0);
                // The load paid, set back to gravity for the next step; when the marks
                // are valid, one not marked is gravity already: worked out, not read.
                let paid = if !marks_valid || std::mem::take(loaded) {
                    let taken = *load;
                    *load = Load::gravity(s, &g);
                    taken
                } else {
                    let gravity = Load::gravity(s, &g);
                    debug_assert!(gravity.same_as(load), "particle {i}: a load not marked");
                    gravity
                };
                if ACC_CRIT {
                    close_step(s, &paid, inverse, kick);
                    (vel, spin, acc, alpha) = (s.particle.vel, s.particle.spin, s.acc, s.alpha);
                } else {
                    acc = paid.force * inverse.0;
                    alpha = paid.torque * inverse.1;
                    vel += acc * (dt * kick.fraction);
                    spin += alpha * (dt * kick.fraction);
                    s.acc = acc;
                    s.alpha = alpha;
                }
            }
            vel += acc * (dt * opening);
            spin += alpha * (dt * opening);
            let pos = s.particle.pos + vel * dt;
            if late != 0.0 {
                vel += acc * (dt * late);
                spin += alpha * (dt * late);
            }
            s.particle.pos = pos;
            s.particle.vel = vel;
            s.particle.spin = spin;
            // What follows reads the locals, not the state just written.
            let r = s.particle.radius;
            *sphere = [pos.x, pos.y, pos.z, r];
            // `PairList::moved_far` (the particle is alive).
            let d2 = (pos - at).norm_squared();
            let far = d2 > limit || d2.is_nan();
            *owed = owing
                && !far
                && !walled
                && Self::may_owe(d2, &vel, &spin, r, dt)
                && clear_of_near(i, &pos, r, near, now);
            far
        };
        // A plain loop over a chunk of the particles (every one is kicked and drifted:
        // no short cut), chunks in parallel for many particles.
        let chunk = |(
            c,
            (
                ((((states, (loads, loaded)), owed), (built_at, spheres)), (walled, inverses)),
                visited,
            ),
        ): DriftChunk| {
            let mut drifted = false;
            let first = c * CHUNK;
            visited.clear();
            let rest = loads
                .iter_mut()
                .zip(loaded)
                .zip(owed)
                .zip(built_at)
                .zip(spheres)
                .zip(walled.iter().zip(inverses));
            for (k, (s, (((((load, loaded), owed), at), sphere), (&walled, &inverse)))) in
                states.iter_mut().zip(rest).enumerate()
            {
                let work = DriftWork {
                    load,
                    loaded,
                    owed: &mut *owed,
                    at,
                    sphere,
                    walled,
                    inverse,
                };
                drifted |= kick_drift(first + k, s, work);
                if !*owed {
                    visited.push(k as u32);
                }
            }
            drifted
        };
        let chunks = self.states.len().div_ceil(CHUNK);
        self.visited.resize_with(chunks, Vec::new);
        let drifted = if self.parallel {
            self.states
                .par_chunks_mut(CHUNK)
                .zip(
                    self.loads
                        .par_chunks_mut(CHUNK)
                        .zip(self.loaded.par_chunks_mut(CHUNK)),
                )
                .zip(self.owed.par_chunks_mut(CHUNK))
                .zip(
                    built_at
                        .par_chunks(CHUNK)
                        .zip(spheres.par_chunks_mut(CHUNK)),
                )
                .zip(
                    self.walled
                        .par_chunks(CHUNK)
                        .zip(self.inverses.par_chunks(CHUNK)),
                )
                .zip(self.visited.par_iter_mut())
                .enumerate()
                .map(chunk)
                .reduce(|| false, |a, b| a || b)
        } else {
            // Every chunk, not stopping at the first that drifted far (as `any` would).
            let mut drifted = false;
            let chunked = (self.states.chunks_mut(CHUNK))
                .zip(
                    self.loads
                        .chunks_mut(CHUNK)
                        .zip(self.loaded.chunks_mut(CHUNK)),
                )
                .zip(self.owed.chunks_mut(CHUNK))
                .zip(built_at.chunks(CHUNK).zip(spheres.chunks_mut(CHUNK)))
                .zip(self.walled.chunks(CHUNK).zip(self.inverses.chunks(CHUNK)))
                .zip(self.visited.iter_mut());
            for c in chunked.enumerate() {
                drifted |= chunk(c);
            }
            drifted
        };
        self.candidates.drifted = drifted;
        self.owed_bad = None;
        self.force_bound = 0.0;
    }

    /// Whether the wall pass may owe a free particle of radius `r`, whose squared
    /// distance from where the candidate pairs were found is `d2`, with velocity `vel`
    /// and spin `spin` and clear of the walls, its closing kick: it has not moved more
    /// than a radius in the step (else the wall pass warns of it), its position is
    /// finite (`d2` is: the kick does not move it), and its velocity and spin are surely
    /// finite, each shorter than [`SURELY_FINITE_LENGTH`], so that only its load could
    /// make them overflow ([`SoftStepper::surely_finite`]). All from squared lengths (the
    /// speed test needs the velocity's anyway); a NaN or an infinity fails each test.
    #[inline]
    fn may_owe(d2: f64, vel: &Vec3, spin: &Vec3, r: f64, dt: f64) -> bool {
        const LIMIT: f64 = SURELY_FINITE_LENGTH * SURELY_FINITE_LENGTH;
        let v2 = vel.norm_squared();
        (d2 < LIMIT) & (v2 * dt * dt <= r * r) & (v2 < LIMIT) & (spin.norm_squared() < LIMIT)
    }

    /// The closing kicks the last wall pass owed, given now (as the next drift would
    /// give them), so that the particles stand as the step left them. The first
    /// particle whose numbers overflowed in its kick is kept for
    /// [`SoftStepper::not_finite`].
    fn settle(&mut self) {
        if !std::mem::take(&mut self.owing) {
            return;
        }
        let kick = self.owed_kick;
        let g = self.settings.gravity;
        let mut bad = None;
        for (i, (((s, load), owed), &inverse)) in (self.states.iter_mut())
            .zip(&mut self.loads)
            .zip(&mut self.owed)
            .zip(&self.inverses)
            .enumerate()
        {
            if std::mem::take(owed) {
                let motion = close_step(s, load, inverse, kick);
                *load = Load::gravity(s, &g);
                if bad.is_none() && !s.finite_with(motion) {
                    bad = Some(i);
                }
            }
        }
        self.owed_bad = bad;
    }

    /// Whether the kicks owed cannot overflow: each owed particle's position is finite,
    /// and its velocity and spin are below [`SURELY_FINITE`] in size (shorter than
    /// [`SURELY_FINITE_LENGTH`], [`SoftStepper::may_owe`]), and its
    /// load (gravity and particle contacts) is at most gravity on the heaviest particle
    /// plus the sum of every particle contact's forces and torques this step, which
    /// times the largest 1/m or 1/I and the kick's time is below it too.
    fn surely_finite(&self) -> bool {
        let kick = self.owed_kick.dt * self.owed_kick.fraction;
        let load = self.gravity_bound + self.force_bound;
        load * self.largest_inverse * kick.max(1.0) < SURELY_FINITE
    }

    /// The clock moves on a step, and the moving walls with it.
    fn move_walls(&mut self) {
        let dt = self.settings.dt;
        let pkdgrav = self.settings.integrator == Integrator::Pkdgrav;
        if self.plan.moving_walls {
            if pkdgrav {
                self.origins.advance_pkdgrav(self.scene, self.t, dt);
            } else {
                self.origins.advance(self.scene, self.t, dt);
            }
        }
        self.steps += 1;
        self.t = self.settings.next_time(self.t, self.steps);
        if self.plan.moving_walls {
            self.now = if pkdgrav {
                // pkdgrav's walls move at the velocity of half a step later (§5).
                self.origins.walls_pkdgrav(self.scene, self.t + 0.5 * dt)
            } else {
                self.origins.walls(self.scene, self.t)
            };
        }
    }

    /// The particles stuck to walls carried with their walls' move, as pkdgrav moves
    /// them in the wall move, before the forces (docs/pkdgrav-physics.md §6): with
    /// [`Integrator::Pkdgrav`], which a particle meeting a stuck one then sees where the
    /// wall has taken it.
    fn carry_stuck(&mut self) {
        // None is stuck until some particle is held ([`PairList::held`]): no pass then.
        if !self.candidates.held {
            return;
        }
        let dt = self.settings.dt;
        for s in &mut self.states {
            if let (true, Some(&(w, _))) = (s.alive, s.stuck_to.as_deref()) {
                carry(s, &self.now[w], dt);
            }
        }
    }

    /// Each assembly's half kick of momentum and angular momentum with the last step's
    /// force and torque, its drift, and its free rotation over the step (kick-drift-kick
    /// as for the particles); its walls are placed where it has taken them.
    /// With [`Integrator::Pkdgrav`], pkdgrav's: the opening half kick of the velocity
    /// alone, then [`Assembly::move_pkdgrav`] (docs/pkdgrav-physics.md §10).
    fn move_assemblies(&mut self) {
        let (g, dt) = (self.settings.gravity, self.settings.dt);
        for a in self.assemblies.iter_mut() {
            if a.is_pkdgrav() {
                a.velocity += (a.force / a.mass + g) * (dt / 2.0);
                a.move_pkdgrav(dt);
                continue;
            }
            a.velocity += (a.force / a.mass + g) * (dt / 2.0);
            a.cog += a.velocity * dt;
            a.kick(dt / 2.0);
            let inertia = a.inertia;
            crate::dynamics::rigid::step(
                &mut a.rotation,
                &inertia,
                &Vec3::zeros(),
                dt,
                RotationIntegrator::AdaptiveRk,
            );
        }
        self.place_assemblies();
    }

    /// Each assembly's walls placed where it has taken them, and its centre of gravity
    /// noted.
    fn place_assemblies(&mut self) {
        for a in &self.assemblies {
            for (k, &w) in a.walls.iter().enumerate() {
                self.now[w] = WallNow::placed(
                    a.cog,
                    a.shape(&self.scene[w].shape, k),
                    a.velocity,
                    a.spin(),
                );
            }
        }
        self.cogs.clear();
        self.cogs.extend(self.assemblies.iter().map(|a| a.cog));
    }

    /// Adds the forces and torques of every overlapping pair of particles (free ones,
    /// or a free one and one held by a wall) to their loads, and closes the contacts
    /// not seen; [`Flow::Stop`] when an overlap is past pkdgrav's abort.
    fn pair_contacts(&mut self) -> Flow {
        self.pair_forces()
    }

    /// The forces of the candidate pairs that overlap: which overlap, in the list's
    /// order (their overlaps checked, their contacts opened and the others' closed);
    /// then their forces, added to each load in the list's order. On one thread each
    /// record is changed in place and each force added at once; in parallel, the
    /// records are laid out anew in the order of the pairs that touch, and each range
    /// of particles takes its forces in the list's order. The outcome does not depend
    /// on the threads.
    fn pair_forces(&mut self) -> Flow {
        self.scan_pairs();
        // …then, in the list's order, the overlaps checked (a deep one may stop the run,
        // before any contact is opened or closed)…
        if self.check_overlaps() {
            return Flow::Stop;
        }
        let PairList {
            pairs,
            slots,
            contacts,
            spheres,
            touching,
            forces,
            scans,
            from,
            bounds,
            ..
        } = &mut self.candidates;
        // …and the contacts closed and opened.
        touching.clear();
        from.clear();
        for scan in scans.iter() {
            if !self.parallel {
                for &k in &scan.apart {
                    contacts.close(&mut slots[k as usize]);
                }
                for &(k, _) in &scan.touching {
                    contacts.open(&mut slots[k as usize], &mut self.pair_contacts);
                    touching.push(k);
                }
                continue;
            }
            // In parallel, this step's records are laid out anew in the order of the
            // pairs that touch: each comes from its slot in the last step's (`from`).
            for &k in &scan.apart {
                slots[k as usize] = NO_CONTACT;
            }
            for &(k, _) in &scan.touching {
                let slot = &mut slots[k as usize];
                self.pair_contacts += u64::from(*slot == NO_CONTACT);
                from.push(*slot);
                *slot = touching.len() as u32;
                touching.push(k);
            }
        }
        // The loads these forces go to, marked when few (`SoftStepper::loaded`).
        self.marks_valid = 8 * touching.len() <= self.states.len();
        if self.marks_valid {
            for &k in touching.iter() {
                let (i, j) = pairs[k as usize];
                self.loaded[i as usize] = true;
                self.loaded[j as usize] = true;
            }
        }
        let states = &self.states;
        let mat = &self.between;
        let (eps_n, eps_t) = (Restitution::new(mat.eps_n), Restitution::new(mat.eps_t));
        let context = PairContext {
            states,
            settings: self.settings,
            plan: self.plan,
            kicks: self.kicks,
            mat,
            restitution: (eps_n, eps_t),
            damping: states.first().map(|s| {
                // Two free particles of the first one's mass (in a run of one size, every
                // contact).
                let m = s.particle.mass;
                let reduced = m * m / (m + m);
                let damping = |eps: Restitution, k: f64| eps.damping(k, reduced);
                (reduced, (damping(eps_n, mat.k_n), damping(eps_t, mat.k_t)))
            }),
            optional: &self.optional,
        };
        let loads = &mut self.loads;
        // What the forces could add to an owed kick (`SoftStepper::surely_finite`): the
        // sum of their sizes, block by block, the same on any number of threads.
        let mut bound = 0.0;
        if !self.parallel {
            // One thread: each contact's record changed where it lies, and its force
            // added at once, in the list's order.
            let lanes = context.lanes();
            for block in touching.chunks(BOUND_BLOCK) {
                let list = (block, pairs.as_slice(), slots.as_slice());
                let on = (
                    spheres.as_slice(),
                    &mut contacts.records[..],
                    &mut loads[..],
                );
                bound += pair_block(&context, lanes.as_ref(), list, on);
            }
            self.force_bound += bound;
            return Flow::Continue;
        }
        // In parallel: the new records, in the order of the pairs that touch, each from
        // its last slot (a new contact's from nothing), and the forces beside them…
        let lanes = context.lanes();
        let n = touching.len();
        // (Every place is written below: only the places past the last step's length
        // are filled first.)
        contacts.next.resize(n, Record::default());
        forces.resize(n, PairForce::default());
        let last = contacts.records.as_slice();
        (contacts.next.par_chunks_mut(PAIR_CHUNK))
            .zip(forces.par_chunks_mut(PAIR_CHUNK))
            .zip(
                touching
                    .par_chunks(PAIR_CHUNK)
                    .zip(from.par_chunks(PAIR_CHUNK)),
            )
            .for_each(|((records, forces), (ks, from))| {
                let list = (pairs.as_slice(), last);
                pair_chunk(
                    &context,
                    lanes.as_ref(),
                    (ks, from),
                    list,
                    spheres,
                    (records, forces),
                );
            });
        std::mem::swap(&mut contacts.records, &mut contacts.next);
        contacts.free.clear();
        // …the bound, block by block as on one thread…
        (forces.par_chunks(BOUND_BLOCK))
            .map(|block| block.iter().fold(0.0, |sum, f| sum + f.size()))
            .collect_into_vec(bounds);
        for sum in bounds.iter() {
            bound += sum;
        }
        self.force_bound += bound;
        // …and each range of particles takes the forces on its own in the list's
        // order, so that each load adds them as on one thread.
        let range = loads.len().div_ceil(rayon::current_num_threads()).max(1);
        let pairs = pairs.as_slice();
        loads
            .par_chunks_mut(range)
            .enumerate()
            .for_each(|(c, part)| {
                for (&k, f) in touching.iter().zip(forces.iter()) {
                    let (i, j) = (pairs[k as usize].0 as usize, pairs[k as usize].1 as usize);
                    f.add_to(part, c * range, i, j);
                }
            });
        Flow::Continue
    }

    /// Which candidate pairs touch (with their overlaps as fractions of the smaller
    /// radius) and which open contacts ended, in chunks of the list (in parallel for
    /// many particles), in [`PairList::scans`].
    fn scan_pairs(&mut self) {
        let states = &self.states;
        let aggregates = self.aggregates.as_ref();
        let PairList {
            pairs,
            slots,
            spheres,
            scans,
            held,
            gone,
            uniform,
            ..
        } = &mut self.candidates;
        let some_unfree = *held || *gone;
        // An overlap above this is one the ordered check must see (a NaN it would not
        // act on).
        let quiet = self.overlaps.quiet_up_to();
        // (In chunks on one thread too: the overlaps' check looks again only at those
        // with a deep one.)
        let size = pairs.len().div_ceil(SCAN_CHUNKS).max(1);
        scans.resize_with(pairs.len().div_ceil(size), Scan::default);
        // Plain slices in the loop (not the list's vectors behind references, which the
        // compiler would read again at every pair).
        let (list, open, centres) = (pairs.as_slice(), slots.as_slice(), spheres.as_slice());
        let uniform = *uniform;
        // Whether a pair is out of the test's reach besides its distance: members of one
        // aggregate never meet (docs/pkdgrav-physics.md §9.1); a particle stuck to a wall
        // is an obstacle of infinite mass (pkdgrav's rule), and two stuck ones, or a
        // removed one, meet nothing. (The states are read only once some particle is
        // held or gone.)
        let unmet = |i: usize, j: usize| {
            aggregates.is_some_and(|a| a.same(i, j))
                || (some_unfree
                    && (!states[i].alive
                        || !states[j].alive
                        || !(states[i].free() || states[j].free())))
        };
        // One pair (spheres `a` and `b`, the sum of their radii `reach`, and `beyond`,
        // the square of the distance past which they are surely apart: the sum with a
        // margin for round-off): apart, and its contact if open ends; or touching, with
        // its overlap as a fraction of the smaller radius, which pkdgrav's warnings and
        // abort judge. Whether that overlap is one the ordered check must see.
        #[inline(always)]
        fn test(
            scan: &mut Scan,
            k: usize,
            (a, b): (&[f64; 4], &[f64; 4]),
            (reach, beyond): (f64, f64),
            (open, quiet): (bool, f64),
            unmet: impl Fn() -> bool,
        ) -> bool {
            // Most candidates do not touch: the square of the distance tells (as
            // [`separation`] has it, without its square root for the many apart); the
            // contact, if open, ends.
            let d2 = Vec3::new(a[0] - b[0], a[1] - b[1], a[2] - b[2]).norm_squared();
            let overlap = if d2 > beyond || unmet() {
                0.0
            } else {
                reach - d2.sqrt()
            };
            if overlap <= 0.0 {
                if open {
                    scan.apart.push(k as u32);
                }
                false
            } else {
                let fraction = overlap / a[3].min(b[3]);
                scan.touching.push((k as u32, fraction));
                fraction > quiet
            }
        }
        let scan = |(c, scan): (usize, &mut Scan)| {
            scan.touching.clear();
            scan.apart.clear();
            let mut deep = false;
            let first = c * size;
            let end = (first + size).min(list.len());
            let pairs = (first..end).zip(list[first..end].iter().zip(&open[first..end]));
            match uniform {
                // Every particle of one radius: the reach and its square worked out once,
                // the same numbers as for each pair (10 % of the test's instructions).
                Some(reach) => {
                    let beyond = reach * reach * (1.0 + 1e-9);
                    for (k, (&(i, j), &slot)) in pairs {
                        let (i, j) = (i as usize, j as usize);
                        let spheres = (&centres[i], &centres[j]);
                        let open = (slot != NO_CONTACT, quiet);
                        deep |= test(scan, k, spheres, (reach, beyond), open, || unmet(i, j));
                    }
                }
                None => {
                    for (k, (&(i, j), &slot)) in pairs {
                        let (i, j) = (i as usize, j as usize);
                        let (a, b) = (&centres[i], &centres[j]);
                        let reach = a[3] + b[3];
                        let beyond = reach * reach * (1.0 + 1e-9);
                        let open = (slot != NO_CONTACT, quiet);
                        deep |= test(scan, k, (a, b), (reach, beyond), open, || unmet(i, j));
                    }
                }
            }
            scan.deep = deep;
        };
        if self.parallel {
            scans.par_iter_mut().enumerate().for_each(scan);
        } else {
            scans.iter_mut().enumerate().for_each(scan);
        }
    }

    /// pkdgrav's overlap warnings and abort for the pairs that touch, in the list's
    /// order (only the chunks with an overlap they may act on are looked at); true when
    /// one stops the run. The contacts the pairs before that one would have opened this
    /// step are counted, as pkdgrav counts them before it aborts, though none is opened:
    /// the run ends there (the stepper is not stepped again).
    fn check_overlaps(&mut self) -> bool {
        let PairList {
            pairs,
            slots,
            scans,
            ..
        } = &self.candidates;
        for (c, scan) in scans.iter().enumerate().filter(|(_, scan)| scan.deep) {
            for (n, &(k, fraction)) in scan.touching.iter().enumerate() {
                let (i, j) = (pairs[k as usize].0 as usize, pairs[k as usize].1 as usize);
                let what = Overlapping::Particles(i, j);
                if self
                    .overlaps
                    .check(fraction, what, self.t, &mut self.warnings)
                {
                    // The contacts the pairs before it opened.
                    let before = scans[..c].iter().flat_map(|s| &s.touching);
                    let opened = before.chain(&scan.touching[..n]);
                    let opened = opened.filter(|(k, _)| slots[*k as usize] == NO_CONTACT);
                    self.pair_contacts += opened.count() as u64;
                    return true;
                }
            }
        }
        false
    }

    /// The contacts with the walls of each particle not owed its kick, added to its
    /// load, then its closing kick (in parallel for many particles); what each did is in
    /// `reports`.
    fn wall_contacts(&mut self) {
        // Without forces (`bDoGravity = 0`) the walls are not looked at.
        let forces = self.settings.forces;
        let gravity = self.settings.gravity;
        let walls = Walls {
            now: if forces { &self.now } else { &[] },
            assembly_of: &self.assembly_of,
            cogs: &self.cogs,
            origins: &self.origins.now,
            index: self.index.as_ref().filter(|_| forces),
            near: self.candidates.near.as_ref().filter(|_| forces),
            plan: self.plan,
            damping: &self.damping,
            restitutions: &self.restitutions,
            materials: &self.materials,
            closing_kick: self.kicks.closing,
            predict: self.kicks.predict,
            predict_spin: self.kicks.predict_all,
            pkdgrav_levers: self.kicks.pkdgrav_levers,
            contact_radius: self.settings.contact_radius,
            constant_torque: (!self.settings.build.rotation_dashpot)
                .then_some(self.settings.legacy_roll),
            acc_crit: self.settings.acc_crit,
            sliding: self.settings.sliding,
            optional: &self.optional,
            t: self.t,
            dt: self.settings.dt,
            aggregates: self.aggregates.as_ref(),
        };
        // A plain loop over the particles of each chunk not owed their kick, its reports
        // kept with it (in particle order within the chunk), chunks in parallel for many
        // particles. Each load, once used, starts the next step with gravity alone
        // (while it is at hand; the drift does it for the owed); an aggregate's members'
        // loads are kept for it ([`SoftStepper::gather_aggregates`]).
        let chunk = |(
            c,
            ((((states, loads), (visited, inverses)), (opens, walled)), (reports, visit)),
        ): WallChunk| {
            reports.clear();
            let first = c * CHUNK;
            // The others are clear of the walls: their closing kicks are owed, not given
            // here.
            for &k in visited.iter() {
                let k = k as usize;
                let (s, load, open) = (&mut states[k], &mut loads[k], &mut opens[k]);
                let i = first + k;
                if s.free() && !s.member && clear_of_walls(i, s, open, &walls) {
                    // Clear of the walls, not owed: the closing kick alone. (None is
                    // open, as `walled[k]` already says: only this pass opens them.)
                    if let Some(report) = clear_step(s, load, inverses[k], &walls) {
                        reports.push((i, report));
                    }
                    *load = Load::gravity(s, &gravity);
                    continue;
                }
                let work = WallWork {
                    load,
                    inverse: inverses[k],
                    open,
                    visit,
                };
                let mut report = wall_step(i, s, work, &walls);
                walled[k] = !open.is_empty();
                report.not_finite = !s.finite();
                if !s.member {
                    *load = Load::gravity(s, &gravity);
                }
                if !report.is_empty() {
                    reports.push((i, report));
                }
            }
        };
        let chunks = self.states.len().div_ceil(CHUNK);
        self.reports.resize_with(chunks, Vec::new);
        self.visits.resize_with(chunks, Vec::new);
        if self.parallel {
            self.states
                .par_chunks_mut(CHUNK)
                .zip(self.loads.par_chunks_mut(CHUNK))
                .zip(self.visited.par_iter().zip(self.inverses.par_chunks(CHUNK)))
                .zip((self.open_walls.par_chunks_mut(CHUNK)).zip(self.walled.par_chunks_mut(CHUNK)))
                .zip(self.reports.par_iter_mut().zip(&mut self.visits))
                .enumerate()
                // Each chunk a task of its own: the particles near the walls gather in
                // a few chunks (those at the floor, in a pile), which halving the range
                // left to one thread (docs/performance.md, "Twelfth round").
                .with_max_len(1)
                .for_each(chunk);
        } else {
            self.states
                .chunks_mut(CHUNK)
                .zip(self.loads.chunks_mut(CHUNK))
                .zip(self.visited.iter().zip(self.inverses.chunks(CHUNK)))
                .zip((self.open_walls.chunks_mut(CHUNK)).zip(self.walled.chunks_mut(CHUNK)))
                .zip(self.reports.iter_mut().zip(&mut self.visits))
                .enumerate()
                .for_each(chunk);
        }
        // The kicks the drift marked as owed are owed now.
        self.owing = true;
        self.owed_kick = walls.closing();
    }

    /// The first particle whose numbers overflowed in the last step, if any: in the
    /// wall pass, or in a kick owed (given now unless surely finite).
    fn not_finite(&mut self) -> Option<usize> {
        if !self.surely_finite() {
            self.settle();
        }
        let reported = (self.reports.iter().flatten())
            .find(|(_, r)| r.not_finite)
            .map(|(i, _)| *i);
        match (reported, self.owed_bad) {
            (Some(i), Some(j)) => Some(i.min(j)),
            (i, j) => i.or(j),
        }
    }

    /// The wall contacts' events and warnings (overlaps, too fast, energy gained, too
    /// many walls at once), in particle order so that the outcome does not depend on the
    /// threads; [`Flow::Stop`] when an overlap is past pkdgrav's abort.
    fn note_wall_contacts(&mut self) -> Flow {
        let t = self.t;
        let mut stop = self.aggregates.is_some() && self.aggregates_held();
        for (i, report) in self.reports.iter_mut().flatten() {
            let i = *i;
            if let Some((fraction, w)) = report.deepest {
                stop |= self.overlaps.check(
                    fraction,
                    Overlapping::Wall {
                        particle: i,
                        wall: w,
                    },
                    t,
                    &mut self.warnings,
                );
            }
            // A travel that overflowed is the not-finite stop's, not a warning's.
            if let Some(travel) = report.too_fast.filter(|x| x.is_finite())
                && !self.once.fast
            {
                self.once.fast = true;
                self.warnings.push(Warning::TooFast {
                    particle: i,
                    radii: travel,
                    t,
                });
            }
            for e in &report.events {
                if e.kind == EventKind::Bounce
                    && e.vn_out
                        > e.vn_in
                            * (1.0
                                + gain_tolerance(
                                    self.materials[e.wall].k_n,
                                    self.states[i].particle.mass,
                                    self.settings.dt,
                                ))
                    && !self.oscillating[e.wall]
                    && !self.once.gain
                {
                    self.once.gain = true;
                    self.warnings.push(Warning::EnergyGain {
                        particle: i,
                        wall: e.wall,
                        vn_in: e.vn_in,
                        vn_out: e.vn_out,
                        t,
                    });
                }
            }
            if report.events.iter().any(|e| e.kind == EventKind::Stick) {
                self.candidates.held = true;
            }
            if report.events.iter().any(|e| e.kind == EventKind::Remove) {
                self.candidates.gone = true;
            }
            self.events.append(&mut report.events);
            if report.touching > 3 && !self.once.crowd {
                self.once.crowd = true;
                self.warnings.push(Warning::Crowded {
                    particle: i,
                    walls: report.touching,
                    t,
                });
            }
        }
        if stop { Flow::Stop } else { Flow::Continue }
    }

    /// Whether an aggregate's member reached a sticky or death wall this step (pkdgrav
    /// asserts, docs/pkdgrav-physics.md §9.5): the warning, in place of the event.
    fn aggregates_held(&mut self) -> bool {
        let mut held = false;
        for (i, report) in self.reports.iter_mut().flatten() {
            let i = *i;
            if !self.states[i].member {
                continue;
            }
            for e in &report.events {
                if matches!(e.kind, EventKind::Stick | EventKind::Remove) {
                    self.warnings.push(Warning::AggregateHeld {
                        particle: i,
                        wall: e.wall,
                        t: self.t,
                    });
                    held = true;
                }
            }
            report
                .events
                .retain(|e| !matches!(e.kind, EventKind::Stick | EventKind::Remove));
        }
        held
    }

    /// The particles' reactions on the assemblies, summed in particle order, and the
    /// assemblies' closing half kick.
    fn kick_assemblies(&mut self) {
        let (g, dt) = (self.settings.gravity, self.settings.dt);
        self.sum_reactions();
        for a in self.assemblies.iter_mut() {
            a.velocity += (a.force / a.mass + g) * (dt / 2.0);
            if !a.is_pkdgrav() {
                a.kick(dt / 2.0);
            }
        }
    }

    /// The particles' reactions on the assemblies, summed in particle order.
    fn sum_reactions(&mut self) {
        for a in self.assemblies.iter_mut() {
            a.force = Vec3::zeros();
            a.torque = Vec3::zeros();
        }
        for (_, report) in self.reports.iter().flatten() {
            for (a, f, tq) in &report.reactions {
                self.assemblies[*a].force += f;
                self.assemblies[*a].torque += tq;
            }
        }
        for a in self.assemblies.iter_mut() {
            a.note_torque_body();
        }
    }

    /// What the run came to, and why it `stopped` early (besides pkdgrav's aborts,
    /// which the warnings say).
    fn outcome(mut self, stopped: Option<super::Stop>) -> Outcome {
        self.settle();
        let g = self.settings.gravity;
        let last = energy(&self.states, &g) + assembly_energy(&self.assemblies, &g);
        Outcome {
            t: self.t,
            steps: self.steps - self.settings.start_step,
            particles: self.states,
            events: self.events,
            assemblies: self.assemblies,
            pair_contacts: self.pair_contacts,
            energy: (self.initial, last),
            warnings: self.warnings,
            stopped,
        }
    }
}

/// How much faster than it came a particle may leave a wall before W106 calls it a
/// gain of energy: the rebound error the integrator is expected to make at this
/// timestep, 1.2/N for N = π/(ω₀·dt) steps per contact (ω₀ = √(k_n/m); W202,
/// docs/run-warnings.md), and no less than round-off (10⁻⁹).
fn gain_tolerance(k_n: f64, mass: f64, dt: f64) -> f64 {
    let tolerance = super::stability::rebound_error((k_n / mass).sqrt(), dt);
    if tolerance.is_finite() {
        tolerance.max(1e-9)
    } else {
        1e-9
    }
}

impl super::Snapshot for SoftStepper<'_> {
    /// The particles after the kicks owed ([`SoftStepper::settle`]).
    fn look(&mut self) -> (&[State], &[Assembly]) {
        self.settle();
        (&self.states, &self.assemblies)
    }
}

pub(super) fn run(
    scene: &[Wall],
    states: Vec<State>,
    settings: &Settings,
    plan: &Plan,
    observe: Observer,
    interrupted: super::Interrupted,
    helpers: Option<&Helpers>,
) -> Outcome {
    let mut run = SoftStepper::new(scene, states, settings, plan);
    if run.halted {
        return run.outcome(None);
    }
    if settings.integrator == Integrator::Pkdgrav && run.start() == Flow::Stop {
        return run.outcome(None);
    }
    while run.running() {
        if let Some(helpers) = helpers {
            helpers.keep();
        }
        if run.step() == Flow::Stop {
            break;
        }
        // A step whose numbers overflowed is not shown to the observer: what it writes
        // ends at the last step whose numbers are all finite.
        let not_finite = run.not_finite();
        let assembly = run.assemblies.iter().find(|a| !a.finite());
        if let Some(number) = assembly.map(|a| a.number) {
            return run.outcome(Some(super::Stop::AssemblyNotFinite(number)));
        }
        if not_finite.is_none() {
            observe(run.steps, run.t, &mut run);
        }
        if let Some(stop) = super::halt_at(not_finite, interrupted) {
            return run.outcome(Some(stop));
        }
    }
    run.outcome(None)
}

/// pkdgrav's aggregates of the particles (docs/pkdgrav-physics.md §9), when the run
/// follows them: an `AGGS` build with pkdgrav's integrator. Members without that get a
/// warning and run as free spheres; an aggregate of one member stops the run before it
/// starts (the second value), as pkdgrav aborts.
fn set_up_aggregates(
    states: &mut [State],
    settings: &Settings,
    warnings: &mut Vec<Warning>,
) -> (Option<Aggregates>, bool) {
    let members = states
        .iter()
        .filter(|s| aggregate::aggregate_of(&s.particle).is_some())
        .count();
    if members == 0 {
        return (None, false);
    }
    if !settings.build.aggs || settings.integrator != Integrator::Pkdgrav {
        warnings.push(super::aggregates_ignored(states, settings));
        return (None, false);
    }
    let particles: Vec<_> = states.iter().map(|s| s.particle.clone()).collect();
    match Aggregates::find(&particles) {
        Ok(Some(aggs)) => {
            for (s, of) in states.iter_mut().zip(&aggs.of) {
                s.member = of.is_some();
            }
            (Some(aggs), false)
        }
        Ok(None) => (None, false),
        Err(aggregate::SetupError::SingleMember {
            aggregate,
            particle,
        }) => {
            warnings.push(Warning::SingleMemberAggregate {
                aggregate,
                particle,
            });
            (None, true)
        }
    }
}

/// The candidate particle pairs, kept from step to step (a Verlet list): the pairs whose
/// spheres, swollen by half the skin each, overlapped when the list was built. It is
/// rebuilt on the cell grid once some particle has moved more than half the skin since,
/// so every pair that overlaps now is in it. The skin is 0.4 of the largest radius: in
/// a settled pile the list lasts many steps (docs/performance.md).
struct PairList {
    pairs: Vec<(u32, u32)>,
    /// Each particle's centre and radius (x, y, z, r) as it is now: the pairs' first
    /// test reads these, compact, rather than the states.
    spheres: Vec<[f64; 4]>,
    /// Each pair's open contact in `contacts`, or [`NO_CONTACT`].
    slots: Vec<u32>,
    /// The open contacts' records.
    contacts: PairContacts,
    /// The pairs that touch this step (kept to save allocating).
    touching: Vec<u32>,
    /// In parallel, their forces, in the same order (kept to save allocating).
    forces: Vec<PairForce>,
    /// In parallel, the slot in the last step's records of each that touches (or
    /// [`NO_CONTACT`]) (kept to save allocating).
    from: Vec<u32>,
    /// In parallel, the sums of the forces' sizes, block by block (kept to save
    /// allocating).
    bounds: Vec<f64>,
    /// What each chunk of the list found this step (kept to save allocating).
    scans: Vec<Scan>,
    /// The cell grid the list was found with, and what building it works in: kept for
    /// the next build, which fills the same memory.
    grid: CellGrid,
    scratch: GridScratch,
    built_at: Vec<Vec3>,
    skin: f64,
    /// Whether a particle drifted this step has moved more than half the skin (worked
    /// out in the drift, [`SoftStepper::kick_drift`]).
    drifted: bool,
    /// Whether some particle may be moved other than by the drift (stuck to a wall, or
    /// a member of an aggregate): then every particle is looked at.
    held: bool,
    /// Whether some particle has left the run (at a death wall): until then, with none
    /// held, every particle is alive and free, and the pairs' test need not look.
    gone: bool,
    /// Whether the pairs are wanted (particles meet each other).
    wanted: bool,
    /// The walls near each particle, when the run keeps them.
    near: Option<NearWalls>,
    /// The sum of two radii when every particle has the same radius (radii never
    /// change in a run): the pairs' test then takes it as it is rather than adding
    /// the two for each pair.
    uniform: Option<f64>,
}

impl PairList {
    fn new(states: &[State], wanted: bool) -> PairList {
        let largest = states.iter().map(|s| s.particle.radius).fold(0.0, f64::max);
        PairList {
            pairs: Vec::new(),
            slots: Vec::new(),
            spheres: Vec::new(),
            contacts: PairContacts::default(),
            touching: Vec::new(),
            forces: Vec::new(),
            from: Vec::new(),
            bounds: Vec::new(),
            scans: Vec::new(),
            grid: CellGrid::default(),
            scratch: GridScratch::default(),
            built_at: Vec::new(),
            skin: 0.4 * largest,
            drifted: false,
            held: states.iter().any(|s| s.stuck_to.is_some() || s.member),
            gone: states.iter().any(|s| !s.alive),
            wanted,
            near: None,
            uniform: match states.split_first() {
                Some((first, rest)) => {
                    let r = first.particle.radius;
                    let same = |s: &State| s.particle.radius.to_bits() == r.to_bits();
                    rest.iter().all(same).then_some(r + r)
                }
                None => None,
            },
        }
    }

    /// The candidate pairs (when wanted) and the walls near each particle (when kept)
    /// where the particles are now, against the walls as they stand.
    fn build(&mut self, states: &[State], walls: &[WallNow]) {
        let half = self.skin / 2.0;
        if let Some(near) = &mut self.near {
            near.build(states, walls, half);
        }
        self.built_at.clear();
        self.built_at.extend(states.iter().map(|s| s.particle.pos));
        self.spheres.clear();
        self.spheres.extend(states.iter().map(Self::sphere));
        if !self.wanted {
            return;
        }
        // The grid, the pairs and their slots in the memory they held at the last build:
        // made anew each time, they took 15–20 MiB more for a moment at 10⁵ particles.
        self.grid.refill(
            states.len(),
            |i| {
                let s = &states[i];
                s.alive
                    .then_some((s.particle.pos, s.particle.radius + half))
            },
            &mut self.scratch,
        );
        // The open contacts go with their pairs into the new list (every pair that
        // touches is in it); any other ends. They are found by their first particle:
        // its open contacts, (second particle, slot), are `open[starts[i]..starts[i + 1]]`.
        let open_pairs = || {
            (self.pairs.iter())
                .zip(&self.slots)
                .filter(|(_, slot)| **slot != NO_CONTACT)
        };
        let mut starts = vec![0u32; states.len() + 1];
        for (&(i, _), _) in open_pairs() {
            starts[i as usize + 1] += 1;
        }
        for i in 0..states.len() {
            starts[i + 1] += starts[i];
        }
        let mut open = vec![(0, 0); starts[states.len()] as usize];
        let mut next = starts.clone();
        for (&(i, j), &slot) in open_pairs() {
            open[next[i as usize] as usize] = (j, slot);
            next[i as usize] += 1;
        }
        if in_parallel(states.len()) {
            self.grid.par_pairs_into(&mut self.pairs);
        } else {
            self.grid.pairs_into(&mut self.pairs);
        }
        // Their records are laid out again in the new list's order, which the force
        // pass follows: one after the other in memory rather than where each happened
        // to open. The others are dropped.
        let mut records = Vec::with_capacity(open.len());
        let last = &self.contacts.records;
        self.slots.clear();
        self.slots.extend(self.pairs.iter().map(|&(i, j)| {
            let of_i = &open[starts[i as usize] as usize..starts[i as usize + 1] as usize];
            match of_i.iter().find(|(second, _)| *second == j) {
                Some(&(_, slot)) => {
                    records.push(last[slot as usize]);
                    (records.len() - 1) as u32
                }
                None => NO_CONTACT,
            }
        }));
        self.contacts = PairContacts {
            records,
            free: Vec::new(),
            next: std::mem::take(&mut self.contacts.next),
        };
    }

    /// A particle's centre and radius, as the pairs' first test reads them.
    #[inline]
    fn sphere(s: &State) -> [f64; 4] {
        let p = &s.particle;
        [p.pos.x, p.pos.y, p.pos.z, p.radius]
    }

    /// The square of half the skin: how far a particle may move before a rebuild.
    fn limit(&self) -> f64 {
        (self.skin / 2.0).powi(2)
    }

    /// Whether `s`, in the run, has moved more than √`limit` from `at` (or its position
    /// is not a number).
    #[inline]
    fn moved_far(s: &State, at: &Vec3, limit: f64) -> bool {
        let d2 = (s.particle.pos - at).norm_squared();
        s.alive && (d2 > limit || d2.is_nan())
    }

    /// Rebuilds the list if some particle (free, or carried by its wall) has moved more
    /// than half the skin: the drift has said so of the free ones; the others are looked
    /// at only once some particle is held (stuck, or in an aggregate), and then all.
    fn update(&mut self, states: &[State], walls: &[WallNow]) {
        if !self.wanted && self.near.is_none() {
            return;
        }
        let limit = self.limit();
        let moved = |(s, at): (&State, &Vec3)| Self::moved_far(s, at, limit);
        if self.held {
            // Particles the drift did not move may have been carried.
            for (sphere, s) in self.spheres.iter_mut().zip(states) {
                *sphere = Self::sphere(s);
            }
        }
        let walls_moved = (self.near.as_ref()).is_some_and(|n| n.moved(walls, self.skin / 2.0));
        let stale = self.drifted
            || walls_moved
            || (self.held
                && if states.len() >= PARALLEL_FROM {
                    states.par_iter().zip(&self.built_at).any(moved)
                } else {
                    states.iter().zip(&self.built_at).any(moved)
                });
        self.drifted = false;
        if stale {
            self.build(states, walls);
        }
    }
}

/// A chunk of the particles as the drift takes it: its number, their states, loads, the
/// loads' marks and owed kicks, where the candidate pairs were found and their spheres, whether they have
/// a wall contact open and their 1/m and 1/I, and the list of those the wall pass is to
/// visit (within the chunk).
type DriftChunk<'a> = (
    usize,
    (
        (
            (
                (
                    (&'a mut [State], (&'a mut [Load], &'a mut [bool])),
                    &'a mut [bool],
                ),
                (&'a [Vec3], &'a mut [[f64; 4]]),
            ),
            (&'a [bool], &'a [(f64, f64)]),
        ),
        &'a mut Vec<u32>,
    ),
);

/// What the drift works on for one particle besides its state.
struct DriftWork<'a> {
    load: &'a mut Load,
    /// Whether its load may hold more than gravity ([`SoftStepper::loaded`]).
    loaded: &'a mut bool,
    /// Whether its closing kick is owed ([`SoftStepper::owed`]).
    owed: &'a mut bool,
    /// Where it was when the candidate pairs were found.
    at: &'a Vec3,
    sphere: &'a mut [f64; 4],
    /// Whether it has a wall contact open ([`SoftStepper::walled`]).
    walled: bool,
    /// 1/m and 1/I ([`SoftStepper::inverses`]).
    inverse: (f64, f64),
}

/// How large a particle's numbers, or a bound on its next kick, may be for the kick
/// owed to it to be surely finite ([`SoftStepper::surely_finite`]): twice it is still
/// far below the largest double (1.8·10³⁰⁸).
const SURELY_FINITE: f64 = 1e300;

/// How long an owed particle's velocity or spin may be ([`SoftStepper::may_owe`]): its
/// size |x| + |y| + |z|, at most √3 times its length, is then far below
/// [`SURELY_FINITE`], and its squared length is a double.
const SURELY_FINITE_LENGTH: f64 = 1e149;

/// A chunk of the particles as the wall pass takes it: its number, their states and
/// loads, which of them it visits and their 1/m and 1/I, their open wall contacts and
/// whether any is open, and its reports and scratch list of walls.
type WallChunk<'a> = (
    usize,
    (
        (
            (
                (&'a mut [State], &'a mut [Load]),
                (&'a Vec<u32>, &'a [(f64, f64)]),
            ),
            (&'a mut [Vec<(usize, Open)>], &'a mut [bool]),
        ),
        (&'a mut Vec<(usize, ParticleStep)>, &'a mut Vec<usize>),
    ),
);

/// How many particles a thread takes at a time in the passes over all of them.
const CHUNK: usize = 512;

/// Into how many chunks the candidate pairs are cut to find (in parallel, with many
/// particles) which touch.
const SCAN_CHUNKS: usize = 64;

/// What one chunk of the candidate pairs found in a step: the pairs that touch, with
/// their overlaps as fractions of the smaller radius, and those with an open contact
/// that no longer touch.
#[derive(Default)]
struct Scan {
    touching: Vec<(u32, f64)>,
    apart: Vec<u32>,
    /// Whether an overlap is deep enough for pkdgrav's warnings or abort to act on
    /// ([`OverlapWarnings::quiet_up_to`]).
    deep: bool,
}

/// How many touching pairs' force sizes are summed in order before the sum is added to
/// the bound ([`SoftStepper::surely_finite`]): the blocks in parallel, the same sums.
const BOUND_BLOCK: usize = 4096;

/// The force of one particle contact and its torques on particles i and j, and
/// whether each is free (a stuck one takes nothing).
#[derive(Clone, Copy, Default)]
struct PairForce {
    force: Vec3,
    torques: (Vec3, Vec3),
    free: (bool, bool),
}

impl PairForce {
    /// The sum of the sizes (|x| + |y| + |z|) of the force and both torques.
    #[inline]
    fn size(&self) -> f64 {
        self.force.abs().sum() + self.torques.0.abs().sum() + self.torques.1.abs().sum()
    }

    /// Adds the force and torques to the loads of particles i and j (of the free ones)
    /// among `loads`, the loads of the particles from `first` on.
    #[inline]
    fn add_to(&self, loads: &mut [Load], first: usize, i: usize, j: usize) {
        if self.free.0
            && let Some(load) = loads.get_mut(i.wrapping_sub(first))
        {
            load.force += self.force;
            load.torque += self.torques.0;
        }
        if self.free.1
            && let Some(load) = loads.get_mut(j.wrapping_sub(first))
        {
            load.force -= self.force;
            load.torque += self.torques.1;
        }
    }
}

/// The vector from sphere b's centre to sphere a's, its length, and how far the two
/// overlap (x, y, z, r each).
#[inline]
fn separation(a: &[f64; 4], b: &[f64; 4]) -> (Vec3, f64, f64) {
    let d = Vec3::new(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
    let distance = d.norm_squared().sqrt();
    (d, distance, a[3] + b[3] - distance)
}

/// The forces of a block of the candidate pairs that touch (`list`: their places in the
/// candidate pairs, the pairs, and each pair's slot among the records), on one thread:
/// each contact's record stepped where it lies (`on`: the spheres, the records and the
/// loads), its force added to the loads at once, in the list's order. Four contacts at a
/// time ([`crate::contact::lanes`]) when `lanes` says how and the eight particles are
/// free, else one (the last few, or the first of four with a particle held). Returns the
/// sum of the forces' sizes. Compiled as well for processors with AVX-512 and with AVX2,
/// the version chosen at run time for the processor it runs on: the lanes' vector
/// operations inline only into code compiled for them (docs/performance.md, "Tenth
/// round" and "Eleventh round"), and the numbers are the same in each, since Rust never
/// fuses a multiplication with an addition unless asked to.
#[multiversion::multiversion(targets(
    "x86_64+avx512f+avx512vl+avx512dq+avx2+fma",
    "x86_64+avx2+fma"
))]
fn pair_block(
    context: &PairContext,
    lanes: Option<&lanes::Setting>,
    (block, pairs, slots): (&[u32], &[(u32, u32)], &[u32]),
    (spheres, records, loads): (&[[f64; 4]], &mut [Record], &mut [Load]),
) -> f64 {
    let mut sum = 0.0;
    let mut rest = block;
    let ij_of = |k: usize| (pairs[k].0 as usize, pairs[k].1 as usize);
    while let Some((&first, after)) = rest.split_first() {
        if let (Some(setting), Some((group, _))) = (lanes, rest.split_first_chunk::<LANES>()) {
            let ks = group.map(|k| k as usize);
            let ij = ks.map(ij_of);
            // The four records stepped where they lie (each contact has a slot of its
            // own): copied out and back, they cost the oscillating floor about 3 % of
            // its time.
            if context.all_free(&ij)
                && let Ok(four) = records.get_disjoint_mut(ks.map(|k| slots[k] as usize))
            {
                let forces = context.force_lanes(&ij, spheres, four, setting);
                for l in 0..LANES {
                    let (i, j) = ij[l];
                    forces[l].add_to(loads, 0, i, j);
                    sum += forces[l].size();
                }
                rest = &rest[LANES..];
                continue;
            }
        }
        // One alone: the last few, or the first of four with a particle held.
        let k = first as usize;
        let (i, j) = ij_of(k);
        let record = &mut records[slots[k] as usize];
        let f = context.force(i, j, &spheres[i], &spheres[j], record);
        f.add_to(loads, 0, i, j);
        sum += f.size();
        rest = after;
    }
    sum
}

/// How many of the contacts that touch a thread takes at a time, in parallel.
const PAIR_CHUNK: usize = 256;

/// In parallel, the forces of a chunk of the candidate pairs that touch (`ks`: their
/// places in the candidate pairs `pairs`; `from`: each one's slot in the last step's
/// records `last`, or [`NO_CONTACT`]), into `records` and `forces`: each contact's record,
/// from its last slot (a new contact's from nothing), stepped, and its force. Four
/// contacts at a time as in [`pair_block`], and compiled likewise.
#[multiversion::multiversion(targets(
    "x86_64+avx512f+avx512vl+avx512dq+avx2+fma",
    "x86_64+avx2+fma"
))]
fn pair_chunk(
    context: &PairContext,
    lanes: Option<&lanes::Setting>,
    (ks, from): (&[u32], &[u32]),
    (pairs, last): (&[(u32, u32)], &[Record]),
    spheres: &[[f64; 4]],
    (records, forces): (&mut [Record], &mut [PairForce]),
) {
    let record = |slot: u32| match slot {
        NO_CONTACT => Record::default(),
        slot => last[slot as usize],
    };
    let ij_of = |k: u32| (pairs[k as usize].0 as usize, pairs[k as usize].1 as usize);
    let mut done = 0;
    while done < ks.len() {
        if let Some(setting) = lanes
            && done + LANES <= ks.len()
        {
            let ij: [(usize, usize); LANES] = std::array::from_fn(|l| ij_of(ks[done + l]));
            if context.all_free(&ij) {
                let mut four: [Record; LANES] = std::array::from_fn(|l| record(from[done + l]));
                let f = context.force_lanes(&ij, spheres, four.each_mut(), setting);
                records[done..done + LANES].copy_from_slice(&four);
                forces[done..done + LANES].copy_from_slice(&f);
                done += LANES;
                continue;
            }
        }
        // One alone: the last few, or the first of four with a particle held.
        let (i, j) = ij_of(ks[done]);
        records[done] = record(from[done]);
        forces[done] = context.force(i, j, &spheres[i], &spheres[j], &mut records[done]);
        done += 1;
    }
}

/// What the force of a particle contact depends on besides the two particles.
struct PairContext<'a> {
    states: &'a [State],
    settings: &'a Settings,
    plan: &'a Plan,
    kicks: Kicks,
    mat: &'a Material,
    /// The particles' normal and tangential restitutions.
    restitution: (Restitution, Restitution),
    /// A reduced mass and the damping coefficients (C_n, C_t) of a contact of that
    /// reduced mass, worked out once a step: a contact of that mass (two free particles
    /// of the first one's mass) takes them rather than two square roots.
    damping: Option<(f64, (f64, f64))>,
    optional: &'a OptionalPhysics,
}

impl PairContext<'_> {
    /// How the contacts go four at a time ([`crate::contact::lanes`]), when the run's
    /// contacts take pkdgrav's levers and law without its optional parts and the
    /// processor has the lanes' vector instructions ([`lanes::Simd`]).
    fn lanes(&self) -> Option<lanes::Setting<'_>> {
        let plan = self.plan;
        let dashpot = plan.sliding_friction || plan.rolling || plan.twisting;
        let settings = self.settings;
        let simd = lanes::Simd::new()?;
        (self.kicks.pkdgrav_levers
            && dashpot
            && !self.optional.any()
            && !settings.contact_radius
            && settings.build.rotation_dashpot)
            .then_some(lanes::Setting {
                simd,
                dt: settings.dt,
                predict: self.kicks.predict_all,
                mat: self.mat,
                sliding: settings.sliding,
                restitution: self.restitution,
                damping: self.damping,
            })
    }

    /// Whether the particles of four pairs are all free.
    #[inline(always)]
    fn all_free(&self, ij: &[(usize, usize); LANES]) -> bool {
        ij.iter()
            .all(|&(i, j)| self.states[i].free() && self.states[j].free())
    }

    /// [`PairContext::force`] for four pairs of free particles, `ij`, with their records,
    /// four at a time as [`PairContext::lanes`] says.
    #[inline(always)]
    fn force_lanes(
        &self,
        ij: &[(usize, usize); LANES],
        spheres: &[[f64; 4]],
        records: [&mut Record; LANES],
        setting: &lanes::Setting,
    ) -> [PairForce; LANES] {
        let states = self.states;
        let sphere = |pick: fn(&(usize, usize)) -> usize| {
            let each: [&[f64; 4]; LANES] = std::array::from_fn(|l| &spheres[pick(&ij[l])]);
            (
                lanes::V::gather(|l| [each[l][0], each[l][1], each[l][2]]),
                lanes::gather(|l| each[l][3]),
            )
        };
        let (ci, ri) = sphere(|p| p.0);
        let (cj, rj) = sphere(|p| p.1);
        let vector = |pick: fn(&(usize, usize)) -> usize, field: fn(&State) -> &Vec3| {
            lanes::V::gather(|l| (*field(&states[pick(&ij[l])])).into())
        };
        let both = |field: fn(&State) -> &Vec3| (vector(|p| p.0, field), vector(|p| p.1, field));
        let mass = |pick: fn(&(usize, usize)) -> usize| -> lanes::L {
            lanes::gather(|l| states[pick(&ij[l])].particle.mass)
        };
        let p = lanes::Pairs {
            centres: (ci, cj),
            radii: (ri, rj),
            vel: both(|s| &s.particle.vel),
            spin: both(|s| &s.particle.spin),
            acc: both(|s| &s.acc),
            alpha: both(|s| &s.alpha),
            mass: (mass(|p| p.0), mass(|p| p.1)),
        };
        let f = lanes::pair(&p, records, setting);
        let (force, torque, partner) = (
            f.force.each_lane(),
            f.torque.each_lane(),
            f.partner_torque.each_lane(),
        );
        std::array::from_fn(|l| PairForce {
            force: force[l].into(),
            torques: (torque[l].into(), partner[l].into()),
            free: (true, true),
        })
    }

    /// The force of the contact between particles i and j (spheres `a` and `b`, which
    /// overlap), with its springs in `record`. Inlined always into its two callers
    /// (one thread, many): returned through memory, the force was written out in
    /// pieces and read back whole, and the one-thread loop's sums into the loads
    /// waited on those stores.
    #[inline(always)]
    fn force(
        &self,
        i: usize,
        j: usize,
        a: &[f64; 4],
        b: &[f64; 4],
        record: &mut Record,
    ) -> PairForce {
        let (d, distance, overlap) = separation(a, b);
        let states = self.states;
        let (p, q) = (&states[i].particle, &states[j].particle);
        let (free_i, free_j) = (states[i].free(), states[j].free());
        let (dt, plan, mat) = (self.settings.dt, self.plan, self.mat);
        let Kicks {
            predict_all,
            pkdgrav_levers,
            ..
        } = self.kicks;
        // `d`'s own normalisation, with its length already known.
        let n = if distance > 0.0 {
            d / distance
        } else {
            Vec3::z()
        };
        // The velocities and spins the contact sees: as they are, or (pkdgrav's)
        // predicted to the step's end, for a free particle; a stuck one's as they are.
        let seen = |s: &State, free: bool| {
            if predict_all != 0.0 && free {
                (
                    s.particle.vel + s.acc * (dt * predict_all),
                    s.particle.spin + s.alpha * (dt * predict_all),
                )
            } else {
                (s.particle.vel, s.particle.spin)
            }
        };
        let ((vi, wi), (vj, wj)) = (seen(&self.states[i], free_i), seen(&self.states[j], free_j));
        // The levers: the radii, or pkdgrav's distances from each centre to the
        // plane where the spheres intersect (docs/pkdgrav-physics.md §1.1).
        let (li, lj) = if pkdgrav_levers {
            pair_levers(p.radius, q.radius, distance)
        } else {
            (p.radius, q.radius)
        };
        let u = vi + wi.cross(&(-n * li)) - vj - wj.cross(&(n * lj));
        let reduced = match (free_i, free_j) {
            (true, true) => p.mass * q.mass / (p.mass + q.mass),
            (true, false) => p.mass,
            _ => q.mass,
        };
        if pkdgrav_levers
            && (plan.sliding_friction || plan.rolling || plan.twisting || self.optional.any())
        {
            // pkdgrav's contact law, in its frame: particle 1 is i, the normal points
            // towards j, velocities and spins are j's relative to i's
            // (docs/pkdgrav-physics.md §1.1–§1.5).
            let a = (self.settings.contact_radius).then(|| lever_contact_radius(p.radius, li));
            let reduced_radius = p.radius * q.radius / (p.radius + q.radius);
            let legacy = self.settings.legacy_roll;
            let dashpot = Dashpot {
                overlap,
                normal: -n,
                velocity: -u,
                spin: wj - wi,
                turn: p.spin + q.spin,
                levers: (li, lj),
                mass: reduced,
                radius: match a {
                    // The contact radius is never worked out then
                    // (docs/pkdgrav-physics.md §1.6).
                    Some(_) if legacy => 0.0,
                    Some(a) => a,
                    None => reduced_radius,
                },
                wall: false,
                constant_torque: (!self.settings.build.rotation_dashpot).then(|| {
                    let inertia_of = |free: bool, m: f64, r: f64| {
                        if free { inertia(m, r) } else { f64::INFINITY }
                    };
                    ConstantTorque {
                        spins: (wi, wj),
                        roll_levers: match (a, legacy) {
                            (Some(a), _) => (a, a),
                            (None, true) => (li, lj),
                            (None, false) => (reduced_radius, reduced_radius),
                        },
                        twist_radius: a.unwrap_or(0.0),
                        inertias: (
                            inertia_of(free_i, p.mass, p.radius),
                            inertia_of(free_j, q.mass, q.radius),
                        ),
                    }
                }),
                sliding: self.settings.sliding,
            };
            let mut extra = Optional {
                restitution: Some(self.restitution),
                ..self.optional.pair(i, j, p.radius, q.radius, a, mat)
            };
            if let (None, Some((mass, damping))) = (extra.layers, self.damping)
                && mass == reduced
            {
                // Two layers change the springs, and with them the damping.
                extra.damping = Some(damping);
            }
            let c = dashpot_contact_with(&dashpot, record, dt, mat, &extra);
            return PairForce {
                force: c.force,
                torques: (c.torque, c.partner_torque),
                free: (free_i, free_j),
            };
        }
        let touch = Touch {
            overlap,
            normal: n,
            velocity: u,
        };
        let c = if plan.sliding_friction {
            contact(reduced, li, &touch, &mut record.spring, dt, mat)
        } else {
            let c_n = damping_per_root_mass(mat.eps_n, mat.k_n) * reduced.sqrt();
            normal_contact(&touch, mat.k_n, c_n)
        };
        // The tangential force acts at the contact point: −R_i·n̂ from i, +R_j·n̂
        // from j.
        let mut torque = (c.torque, c.torque * (lj / li));
        if plan.rolling || plan.twisting {
            let lever = p.radius * q.radius / (p.radius + q.radius);
            // Equal and opposite torques change the relative spin through the
            // reduced inertia (or the free one's, against a stuck particle).
            let (ii, ij) = (inertia(p.mass, p.radius), inertia(q.mass, q.radius));
            let rolling = Rolling {
                spin: wi - wj,
                normal: n,
                normal_force: n.dot(&c.force).abs(),
                lever,
                contact_radius: lens_radius(p.radius, q.radius, distance),
                inertia: match (free_i, free_j) {
                    (true, true) => ii * ij / (ii + ij),
                    (true, false) => ii,
                    _ => ij,
                },
            };
            let m = resistance(&rolling, mat.mu_r, mat.mu_t, dt);
            torque.0 += m;
            torque.1 -= m;
        }
        PairForce {
            force: c.force,
            torques: torque,
            free: (free_i, free_j),
        }
    }
}

/// The walls within reach of each particle, found when the candidate pairs are (a
/// Verlet list of walls): a particle moves at most half the skin before they are found
/// again, and so does a wall that translates (the lists are found again when one has),
/// so a fixed wall farther than the particle's radius and half the skin when they were,
/// or a translating one farther than its radius and the skin, cannot touch it. The
/// walls of reactive assemblies, which turn as well, are visited by every particle.
struct NearWalls {
    /// Whether each wall is kept in the lists: every wall but those of reactive
    /// assemblies.
    listed: Vec<bool>,
    /// Whether each wall translates.
    translating: Vec<bool>,
    /// The walls of reactive assemblies.
    moving: Vec<usize>,
    /// Each wall's origin when the lists were found.
    built_origins: Vec<Vec3>,
    /// Where each particle's walls start in `walls` (one more entry than particles).
    starts: Vec<u32>,
    walls: Vec<usize>,
}

impl NearWalls {
    fn new(listed: Vec<bool>, translating: Vec<bool>) -> NearWalls {
        let moving = (0..listed.len()).filter(|&w| !listed[w]).collect();
        NearWalls {
            listed,
            translating,
            moving,
            built_origins: Vec::new(),
            starts: Vec::new(),
            walls: Vec::new(),
        }
    }

    /// The listed walls within reach of each particle in the run, `half` (half the
    /// skin) beyond its radius for a fixed wall and twice that for a translating one,
    /// in ascending order.
    fn build(&mut self, states: &[State], walls: &[WallNow], half: f64) {
        self.built_origins.clear();
        self.built_origins.extend(walls.iter().map(|w| w.origin));
        self.starts.clear();
        self.walls.clear();
        self.starts.push(0);
        for s in states {
            if s.alive {
                let r = s.particle.radius;
                for (w, wall) in walls.iter().enumerate() {
                    let reach = if self.translating[w] {
                        r + 2.0 * half
                    } else {
                        r + half
                    };
                    if self.listed[w] && !wall.cull.clear_of(&s.particle.pos, reach) {
                        self.walls.push(w);
                    }
                }
            }
            self.starts.push(self.walls.len() as u32);
        }
    }

    /// Whether a listed wall has translated more than `half` since the lists were
    /// found.
    fn moved(&self, walls: &[WallNow], half: f64) -> bool {
        (0..walls.len()).any(|w| {
            let d2 = (walls[w].origin - self.built_origins[w]).norm_squared();
            self.listed[w] && self.translating[w] && (d2 > half * half || d2.is_nan())
        })
    }

    /// The listed walls near particle `i`.
    fn of(&self, i: usize) -> impl Iterator<Item = usize> + '_ {
        self.listed_of(i).iter().copied()
    }

    /// [`NearWalls::of`] as a slice.
    #[inline]
    fn listed_of(&self, i: usize) -> &[usize] {
        &self.walls[self.starts[i] as usize..self.starts[i + 1] as usize]
    }
}

/// A pair without an open contact.
const NO_CONTACT: u32 = u32::MAX;

/// The records of the open contacts between particles, in slots that the candidate
/// pairs point to ([`PairList::slots`]): on one thread, a closed contact's slot is
/// reused; in parallel, the records are laid out anew each step.
#[derive(Default)]
struct PairContacts {
    records: Vec<Record>,
    free: Vec<u32>,
    /// In parallel, where the next step's records are laid out (kept to save
    /// allocating).
    next: Vec<Record>,
}

impl PairContacts {
    /// The record of the contact in `slot`, opened (and counted in `began`) if it is
    /// not.
    #[inline]
    fn open(&mut self, slot: &mut u32, began: &mut u64) -> &mut Record {
        if *slot == NO_CONTACT {
            *began += 1;
            *slot = match self.free.pop() {
                Some(k) => {
                    self.records[k as usize] = Record::default();
                    k
                }
                None => {
                    self.records.push(Record::default());
                    (self.records.len() - 1) as u32
                }
            };
        }
        &mut self.records[*slot as usize]
    }

    /// Ends the contact in `slot`, if one is open.
    #[inline]
    fn close(&mut self, slot: &mut u32) {
        if *slot != NO_CONTACT {
            self.free.push(*slot);
            *slot = NO_CONTACT;
        }
    }
}

/// pkdgrav's levers of a pair contact (docs/pkdgrav-physics.md §1.1): the distances from
/// the centres of spheres of radii `a` and `b`, `d` apart, to the plane where they
/// intersect; exactly d/2 each when the radii are equal.
fn pair_levers(a: f64, b: f64, d: f64) -> (f64, f64) {
    if a == b {
        (0.5 * d, 0.5 * d)
    } else {
        let la = (a * a - b * b + d * d) / (2.0 * d);
        (la, d - la)
    }
}

/// The radius of the circle where spheres of radii `a` and `b`, `d` apart, intersect.
fn lens_radius(a: f64, b: f64, d: f64) -> f64 {
    let h = (d * d + a * a - b * b) / (2.0 * d);
    (a * a - h * h).max(0.0).sqrt()
}

/// The reactive assemblies' kinetic energy (translation and rotation) and gravitational
/// energy.
fn assembly_energy(assemblies: &[Assembly], g: &Vec3) -> f64 {
    assemblies
        .iter()
        .map(|a| {
            let w = &a.rotation.omega;
            let spin = a.inertia.x * w.x * w.x + a.inertia.y * w.y * w.y + a.inertia.z * w.z * w.z;
            0.5 * a.mass * a.velocity.norm_squared() + 0.5 * spin - a.mass * g.dot(&a.cog)
        })
        .sum()
}

#[cfg(test)]
mod tests {
    //! [`PairContext::force_lanes`] against [`PairContext::force`], contact by contact:
    //! the same forces, torques and records, bit for bit, for random free particles
    //! (radii and masses equal or not, the step's damping cached for some pairs and not
    //! others, two centres at one place, predicted or not, rolling and twisting on or
    //! off, either sliding rule, new and old records, small and large steps); and the
    //! run's pair loops, four at a time and one at a time. `tests/lanes.rs` holds the law
    //! alone.

    use super::*;
    use proptest::prelude::*;
    use walls_geometry::Particle;
    use walls_test_support::exact::{bits, number};

    /// The particles' material: pkdgrav's springs, friction, and rolling and twisting
    /// resistance as given.
    fn material(mu_r: f64, mu_t: f64) -> Material {
        Material {
            eps_n: 0.5,
            eps_t: 0.5,
            k_n: 1000.0,
            k_t: 2.0 / 7.0 * 1000.0,
            mu_s: 0.5,
            mu_r,
            mu_t,
            beta_s: 0.5,
        }
    }

    /// `test` given the pair contacts' context of a run of `states` in `settings` (whose
    /// material is the particles'), with `kicks`, and how they go four at a time; nothing
    /// to test where there are no lanes (off x86-64, or on a processor without
    /// x86-64-v3, where `tests/lanes.rs`'s `the_processor_has_the_lanes` fails instead).
    fn in_context(
        states: &[State],
        settings: &Settings,
        kicks: Kicks,
        test: impl FnOnce(&PairContext, &lanes::Setting) -> Result<(), TestCaseError>,
    ) -> Result<(), TestCaseError> {
        let mat = settings.material;
        let plan = Plan::everything();
        let optional = OptionalPhysics::new(&[], states, settings);
        let restitution = (Restitution::new(mat.eps_n), Restitution::new(mat.eps_t));
        let m = states[0].particle.mass;
        let reduced = m * m / (m + m);
        let damping = |eps: Restitution, k: f64| eps.damping(k, reduced);
        let context = PairContext {
            states,
            settings,
            plan: &plan,
            kicks,
            mat: &mat,
            restitution,
            damping: Some((
                reduced,
                (
                    damping(restitution.0, mat.k_n),
                    damping(restitution.1, mat.k_t),
                ),
            )),
            optional: &optional,
        };
        match context.lanes() {
            Some(setting) => test(&context, &setting),
            None => Ok(()),
        }
    }

    fn vector(size: f64) -> impl Strategy<Value = Vec3> {
        (-size..size, -size..size, -size..size).prop_map(|(x, y, z)| Vec3::new(x, y, z))
    }

    /// A particle of radius about 1 mm near the origin, moving and spinning, with
    /// accelerations; of one size and mass or not.
    fn state(same: bool) -> impl Strategy<Value = State> {
        (
            vector(1e-3),
            vector(0.5),
            vector(100.0),
            vector(10.0),
            vector(1e4),
            prop_oneof![Just(1.0), Just(1.1), 0.8..1.2f64],
        )
            .prop_map(move |(pos, vel, spin, acc, alpha, size)| {
                let size = if same { 1.0 } else { size };
                let radius = 1e-3 * size;
                let mut s = State::from(Particle {
                    mass: 4e-6 * size * size * size,
                    radius,
                    pos,
                    vel,
                    spin,
                    color: 3,
                    index: 0,
                });
                s.acc = acc;
                s.alpha = alpha;
                s
            })
    }

    fn record() -> impl Strategy<Value = Record> {
        (any::<bool>(), vector(1e-4), vector(1e-3), -1e-3..1e-3f64).prop_map(
            |(new, spring, roll, twist)| {
                if new {
                    Record::default()
                } else {
                    Record {
                        spring,
                        normal: Vec3::new(0.3, -0.2, 0.9).normalize(),
                        roll,
                        twist,
                        layer: 0,
                    }
                }
            },
        )
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(500))]

        #[test]
        fn four_pairs_at_a_time_are_each_alone(
            same in any::<bool>(),
            states in prop::collection::vec(state(false), 8),
            equal in prop::collection::vec(state(true), 8),
            records in prop::array::uniform4(record()),
            (mu_r, mu_t) in (prop_oneof![Just(0.0), 0.0..0.5f64], prop_oneof![Just(0.0), 0.0..0.5f64]),
            (clamp, predict) in (any::<bool>(), any::<bool>()),
            (dt, coincide) in (prop_oneof![Just(5e-6), Just(1e-3)], any::<bool>()),
        ) {
            let mut states = if same { equal } else { states };
            if coincide {
                // Two centres at one place: the normal falls back to z.
                states[1].particle.pos = states[0].particle.pos;
            }
            let mut settings = Settings::new(dt, 1.0, material(mu_r, mu_t));
            settings.sliding = if clamp { Sliding::Clamp } else { Sliding::Reset };
            let mut kicks = Kicks::of(Integrator::Pkdgrav);
            if !predict {
                kicks.predict_all = 0.0;
            }
            in_context(&states, &settings, kicks, |context, setting| {
                let spheres: Vec<[f64; 4]> = states.iter().map(PairList::sphere).collect();
                let ij = [(0, 1), (2, 3), (4, 5), (6, 7)];
                let mut four = records;
                let forces = context.force_lanes(&ij, &spheres, four.each_mut(), setting);
                for (l, &(i, j)) in ij.iter().enumerate() {
                    let mut alone = records[l];
                    let want = context.force(i, j, &spheres[i], &spheres[j], &mut alone);
                    prop_assert_eq!(bits(forces[l].force), bits(want.force), "force, lane {}", l);
                    prop_assert_eq!(bits(forces[l].torques.0), bits(want.torques.0), "torque, lane {}", l);
                    prop_assert_eq!(bits(forces[l].torques.1), bits(want.torques.1), "partner, lane {}", l);
                    prop_assert_eq!(bits(four[l].spring), bits(alone.spring), "spring, lane {}", l);
                    prop_assert_eq!(bits(four[l].normal), bits(alone.normal), "normal, lane {}", l);
                    prop_assert_eq!(bits(four[l].roll), bits(alone.roll), "roll, lane {}", l);
                    prop_assert_eq!(number(four[l].twist), number(alone.twist), "twist, lane {}", l);
                }
                Ok(())
            })?;
        }
    }

    /// A run's pair loops, four at a time and one at a time, over `n` touching pairs of
    /// random free particles and one held by a wall: the same records, loads, force
    /// sizes and forces, bit for bit, in the list's order (a tail not a multiple of
    /// four, and groups with the held particle taken one by one).
    fn loops_agree(
        states: Vec<State>,
        pairs: Vec<(u32, u32)>,
        records: Vec<Record>,
    ) -> Result<(), TestCaseError> {
        let settings = Settings::new(5e-6, 1.0, material(0.1, 0.1));
        in_context(
            &states,
            &settings,
            Kicks::of(Integrator::Pkdgrav),
            |context, setting| {
                let spheres: Vec<[f64; 4]> = states.iter().map(PairList::sphere).collect();
                let n = pairs.len();
                let touching: Vec<u32> = (0..n as u32).collect();
                // Every other contact new, the others in slots in reverse order.
                let slots: Vec<u32> = (0..n as u32).rev().collect();
                let from: Vec<u32> = (0..n)
                    .map(|k| if k % 2 == 0 { NO_CONTACT } else { slots[k] })
                    .collect();
                let record_bits = |r: &Record| {
                    (
                        bits(r.spring),
                        bits(r.normal),
                        bits(r.roll),
                        number(r.twist),
                    )
                };
                // One thread.
                let one = |lanes: Option<&lanes::Setting>| {
                    let mut records = records.clone();
                    let mut loads: Vec<Load> = states
                        .iter()
                        .map(|s| Load::gravity(s, &Vec3::zeros()))
                        .collect();
                    let list = (touching.as_slice(), pairs.as_slice(), slots.as_slice());
                    let sum =
                        pair_block(context, lanes, list, (&spheres, &mut records, &mut loads));
                    (records, loads, sum)
                };
                let (four, alone) = (one(Some(setting)), one(None));
                for (a, b) in four.0.iter().zip(&alone.0) {
                    prop_assert_eq!(record_bits(a), record_bits(b));
                }
                for (a, b) in four.1.iter().zip(&alone.1) {
                    prop_assert_eq!(
                        (bits(a.force), bits(a.torque)),
                        (bits(b.force), bits(b.torque))
                    );
                }
                prop_assert_eq!(number(four.2), number(alone.2));
                // In parallel, in chunks.
                let chunks = |lanes: Option<&lanes::Setting>| {
                    let mut out = vec![Record::default(); n];
                    let mut forces = vec![PairForce::default(); n];
                    for ((out, forces), (ks, from)) in (out.chunks_mut(PAIR_CHUNK))
                        .zip(forces.chunks_mut(PAIR_CHUNK))
                        .zip(touching.chunks(PAIR_CHUNK).zip(from.chunks(PAIR_CHUNK)))
                    {
                        let list = (pairs.as_slice(), records.as_slice());
                        pair_chunk(context, lanes, (ks, from), list, &spheres, (out, forces));
                    }
                    (out, forces)
                };
                let (four, alone) = (chunks(Some(setting)), chunks(None));
                for (a, b) in four.0.iter().zip(&alone.0) {
                    prop_assert_eq!(record_bits(a), record_bits(b));
                }
                for (a, b) in four.1.iter().zip(&alone.1) {
                    let torques = |f: &PairForce| (bits(f.torques.0), bits(f.torques.1));
                    prop_assert_eq!(
                        (bits(a.force), torques(a), a.free),
                        (bits(b.force), torques(b), b.free)
                    );
                }
                Ok(())
            },
        )
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(20))]

        #[test]
        fn the_pair_loops_four_at_a_time_are_the_loops_one_at_a_time(
            states in prop::collection::vec(state(false), 64),
            pairs in prop::collection::vec((0..64u32, 1..64u32), 600..700),
            records in prop::collection::vec(record(), 700),
        ) {
            let mut states = states;
            // One particle held by a sticky wall.
            states[5].stuck_to = Some(Box::new((0, Vec3::zeros())));
            let pairs: Vec<(u32, u32)> = pairs.into_iter().map(|(i, d)| (i, (i + d) % 64)).collect();
            let records = records[..pairs.len()].to_vec();
            loops_agree(states, pairs, records)?;
        }
    }
}
