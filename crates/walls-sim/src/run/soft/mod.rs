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
//! (events and warnings, in the file's order), `kick_assemblies` and `gather_aggregates`.
//! The passes over all the particles are plain loops over chunks, in parallel only with
//! many particles and more than one thread; what they carry per particle is kept small
//! (a 160-byte [`State`], its 1/m and 1/I beside it, a 48-byte load, a 16-byte sphere
//! rounded to `f32` for the pairs' first test, a byte marking a load that a pair
//! touched), the particles lie in the pair grid's
//! order, not the file's ([`numbering`]: a pair's two spheres near each other in
//! memory, every output the same),
//! and a free particle clear of the walls gets its closing kick in the next drift
//! rather than in a pass of its own, as memory, not arithmetic, bounds them. The kicks
//! still owed are given ([`drift::settle`]) when the particles are looked at
//! ([`super::Snapshot`]), at the run's end, and when one might overflow, so a run is bit
//! for bit what it would be with the kick in the wall pass. With
//! [`Integrator::Pkdgrav`], [`SoftStepper::start`] evaluates the forces once before the
//! first step, as pkdgrav does. pkdgrav's aggregates (`AGGS`,
//! [`crate::dynamics::aggregate`]) run only with [`Integrator::Pkdgrav`]; their members
//! are placed by their aggregate, not kicked or drifted, and hand it their loads.
//!
//! The stepper's state is kept in named sets, as rapier keeps its bodies and colliders:
//! what set-up decided ([`Rules`]: the kicks, the [`ContactLaw`] for walls and pairs
//! alike, the particles' material, the optional physics), the particles ([`Bodies`]),
//! the walls ([`WallSet`]: materials and the laws' constants, motion, assemblies'
//! walls), what may touch ([`Broad`]: the candidate pairs, [`PairList`], and the
//! near-wall lists, [`NearWalls`]), the assemblies and aggregates ([`Rigid`]), the closing
//! kicks deferred to the next drift ([`Deferred`]), the passes' scratch and reports
//! ([`PairPass`], [`WallPass`]) and what the run has seen ([`Journal`]). Each stage of a
//! step is a function of the sets it touches, in its module: [`setup`] (the sets
//! compiled once), [`drift`], [`pairs`] (the pair pass and law), [`walls`] (the wall
//! pass), [`near`], [`rigid`] (assemblies and aggregates) and [`law`] (the kicks and the
//! contact law); the step is here.

use super::pool::Helpers;
use super::{
    Event, EventKind, Integrator, Materials, Observer, Origins, Outcome, OverlapWarnings,
    Overlapping, PARALLEL_FROM, Settings, State, WallNow, Warning, carry, energy, in_parallel,
};
use crate::broad::pairs::PairList;
use crate::contact::ssdem::{Material, Restitution};
use crate::dynamics::aggregate::Aggregates;
use crate::dynamics::reactive::Assembly;
use crate::dynamics::sphere_inertia as inertia;
use crate::run::optional::OptionalPhysics;
use crate::run::plan::Plan;
use nalgebra::Vector3;
use thin_vec::ThinVec;
use walls_geometry::Wall;

mod ahead;
mod drift;
mod inverses;
mod law;
mod near;
mod numbering;
mod pairs;
mod rigid;
mod setup;
mod walls;

use inverses::Inverses;
use law::{ContactLaw, Kicks, Law};
use near::NearWalls;
use numbering::Numbering;
use pairs::{PairMaterial, PairPass};
use walls::{Closing, Open, WallPass};

type Vec3 = Vector3<f64>;

/// The open wall contacts (wall, contact) of a chunk's particles, one list each (8
/// bytes when empty), or no lists at all while none of them has touched a wall.
type ChunkOpens = Vec<ThinVec<(usize, Open)>>;

/// What acts on one particle in a step: the force and torque summed so far. Every pass
/// over the particles touches it, so it holds nothing else: the open wall contacts are
/// kept beside it ([`Bodies::open_walls`]).
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

/// The warnings pkdgrav gives once a run, and whether each has been given.
#[derive(Default)]
struct WarnedOnce {
    crowd: bool,
    fast: bool,
    gain: bool,
    /// A rigid body's adaptive integrator reached its minimum step.
    floor: bool,
}

/// Whether a run goes on after a step.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Flow {
    Continue,
    /// Where pkdgrav aborts or exits: an overlap past `dErrorFrac`, an aggregate member
    /// held by a wall, a rigid body's adaptive integrator failing.
    Stop,
}

impl Flow {
    /// [`Flow::Stop`] if either says so.
    fn and(self, other: Flow) -> Flow {
        if self == Flow::Stop { self } else { other }
    }
}

/// What a run has seen so far: its events, the pair contacts begun, its warnings, and
/// pkdgrav's overlap warnings and the warnings it gives once.
#[derive(Default)]
struct Journal {
    events: Vec<Event>,
    pair_contacts: u64,
    warnings: Vec<Warning>,
    overlaps: OverlapWarnings,
    once: WarnedOnce,
}

/// The closing kicks the wall pass defers to the next drift ([`drift::kick_drift`]),
/// which particles are owed one, and the bounds that tell whether they are surely finite
/// ([`drift::surely_finite`]).
struct Deferred {
    /// Whether each particle's closing kick is owed: a free particle clear of the walls
    /// gets it in the next drift ([`drift::kick_drift`]) rather than in the wall
    /// pass, which saves a pass over the particles; [`drift::settle`] gives it
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
    /// steps (docs/performance-history.md, "Fourteenth round"). A mark left on a load already
    /// set back (by the wall pass, by [`drift::settle`], or by the drift while
    /// the marks were not valid) only makes the drift read it.
    loaded: Vec<bool>,
    /// Whether the last pair pass marked the loads it added to ([`Deferred::loaded`]):
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
    /// The first particle (in the file's order) whose numbers overflowed in an owed
    /// kick given by [`drift::settle`] this step.
    owed_bad: Option<usize>,
    /// The sum of the sizes (|x| + |y| + |z|) of every particle contact's force and
    /// torques this step, and the largest size of gravity on a particle, and 1/m or 1/I
    /// of a particle: bounds on what an owed kick can add ([`drift::surely_finite`]).
    force_bound: f64,
    gravity_bound: f64,
    largest_inverse: f64,
}

/// The walls of a run: their materials and the laws' constants worked out once, their
/// motion and where they stand, and the reactive assemblies they belong to.
struct WallSet {
    /// Each wall's material, with the particles' values where it says so.
    materials: Vec<Material>,
    /// Each wall's normal damping over √m, worked out once.
    damping: Vec<f64>,
    /// Each wall's normal and tangential restitutions, worked out once.
    restitutions: Vec<(Restitution, Restitution)>,
    /// Whether each wall oscillates or spins: it does work on what touches it, so a
    /// bounce off it may gain speed (its friction turns a spinning wall's speed into a
    /// particle's).
    driven: Vec<bool>,
    origins: Origins,
    /// The walls as they stand: placed once when no wall moves (the plan), else every
    /// step; reactive assemblies' walls every step.
    now: Vec<WallNow>,
    /// Each wall's assembly, if any.
    assembly_of: Vec<Option<usize>>,
    /// Each assembly's centre of gravity this step (kept to save allocating).
    cogs: Vec<Vec3>,
}

/// What set-up decided for the whole run, which the stages read and none changes (but
/// [`SoftStepper::start`], for pkdgrav's evaluation before the first step, the kicks):
/// the scene, settings and plan the run was compiled from, the kicks, the contact law,
/// the particles' material between them with its constants, the optional physics, and
/// whether the passes over the particles run on rayon's threads.
struct Rules<'a> {
    scene: &'a [Wall],
    settings: &'a Settings,
    plan: &'a Plan,
    kicks: Kicks,
    /// The contact law, walls and pairs alike.
    contact: ContactLaw,
    /// The particles' material, for their contacts with each other, and its constants.
    between: PairMaterial,
    /// Cohesion and two-layer contacts (pkdgrav's optional builds).
    optional: OptionalPhysics,
    /// Whether a step runs on rayon's threads (many particles, and more than one
    /// thread).
    parallel: bool,
    /// Whether the passes ask for memory ahead of its use ([`ahead`]): with more
    /// particles than the caches hold ([`ahead::AHEAD_FROM`]).
    ahead: bool,
}

/// The particles, one entry each at its place ([`Numbering`]: the pair grid's order),
/// laid out as the passes read them:
/// each [`State`], its [`Load`], its 1/m and 1/I ([`Inverses`]), its open wall contacts
/// (wall, contact), kept apart from its load so that the passes that do not need them do
/// not carry them, and whether it has one open.
struct Bodies {
    /// Which particle of the file each place holds.
    numbering: Numbering,
    /// Whether the states are in the file's order for a look at them
    /// ([`super::Snapshot::look`]), not at their places: put back before the next step.
    filed: bool,
    states: Vec<State>,
    loads: Vec<Load>,
    inverses: Inverses,
    /// Each chunk's particles' open wall contacts ([`ChunkOpens`]): made for a chunk
    /// when one of its particles first touches a wall, so that the particles away from
    /// the walls (most, in a large run) hold nothing.
    open_walls: Vec<ChunkOpens>,
    /// Whether each particle has a wall contact open (its list in its chunk's
    /// `open_walls` exists and is not empty): set by the wall pass after each
    /// particle's contacts, the only place they change (a particle the pass skips had
    /// none, nor has it now), and read by the drift as this byte, not the 8-byte list,
    /// which at 10⁵ particles is memory the drift's stream need not carry
    /// (docs/performance-history.md, "Eighth round").
    walled: Vec<bool>,
}

/// What may touch: the candidate pairs, with their open contacts, and the walls near
/// each particle, found with them (through the wall index among many bounded walls).
struct Broad {
    candidates: PairList,
    near: Option<NearWalls>,
}

/// The bodies that move as wholes: reactive assemblies (SSDEM only, as in pkdgrav),
/// when the plan has them, and pkdgrav's rigid aggregates of particles (`AGGS`,
/// docs/pkdgrav-physics.md §9), if any.
struct Rigid {
    assemblies: Vec<Assembly>,
    aggregates: Option<Aggregates>,
}

/// Where the run is: its time and the steps taken.
#[derive(Clone, Copy)]
struct Clock {
    t: f64,
    steps: u64,
}

/// A soft-sphere run as it goes, in named sets: what set-up decided ([`Rules`]), the
/// particles ([`Bodies`]), the walls ([`WallSet`]), what may touch ([`Broad`]), the
/// assemblies and aggregates ([`Rigid`]), the kicks deferred ([`Deferred`]), the passes'
/// scratch ([`PairPass`], [`WallPass`]) and what the run has seen ([`Journal`]). A step
/// is [`SoftStepper::step`]: each of its stages a function of the sets it touches.
struct SoftStepper<'a> {
    rules: Rules<'a>,
    bodies: Bodies,
    walls: WallSet,
    broad: Broad,
    rigid: Rigid,
    deferred: Deferred,
    pair_pass: PairPass,
    wall_pass: WallPass,
    journal: Journal,
    clock: Clock,
    /// The energy at the start.
    initial: f64,
    /// Set up failed (an aggregate of one member): the run stops before it starts.
    halted: bool,
}

impl<'a> SoftStepper<'a> {
    /// pkdgrav's force evaluation at the start, before the first step
    /// (docs/pkdgrav-physics.md §2, §12), for [`Integrator::Pkdgrav`]: gravity and every
    /// contact open at t₀, with the velocities and spins as they are, added to the loads
    /// (which start with gravity, [`SoftStepper::new`]). It sets the accelerations the
    /// first kick uses and steps the springs of those contacts once; it moves and kicks
    /// nothing.
    fn start(&mut self) -> Flow {
        let kicks = self.rules.kicks;
        self.rules.kicks = kicks.at_start();
        rigid::place_assemblies(&self.rigid.assemblies, &mut self.walls, self.rules.scene);
        let flow = self.contacts();
        if flow.is_some() {
            rigid::sum_reactions(&mut self.rigid.assemblies, &self.wall_pass);
            rigid::gather_aggregates(&mut self.rigid, &self.bodies, &self.rules, false);
        }
        self.rules.kicks = kicks;
        flow.unwrap_or(Flow::Stop)
    }

    /// Whether another step is due before the end.
    fn running(&self) -> bool {
        self.rules.settings.due(self.clock.steps)
    }

    /// One step, each stage a function of the sets it touches: the walls moved on, kick
    /// and drift (with the last step's owed kicks), the aggregates and assemblies moved
    /// on, the lists found again if stale, the contacts ([`SoftStepper::contacts`]), and
    /// the assemblies' and aggregates' closing kick.
    fn step(&mut self) -> Flow {
        self.bodies.place_order();
        let SoftStepper {
            rules,
            bodies,
            walls,
            broad,
            rigid,
            deferred,
            journal,
            clock,
            ..
        } = self;
        // The walls first (they do not depend on the particles): the drift finds which
        // particles are out of their reach where they stand this step.
        move_walls(walls, clock, rules);
        // The drift compiled without pkdgrav's `dAccCrit` and with it: its test and its
        // call in the loop cost the common case about 3 % of the run
        // (docs/performance-history.md, "Twelfth round").
        if deferred.owed_kick.acc_crit > 0.0 {
            drift::kick_drift::<true>(bodies, deferred, broad, walls, rules);
        } else {
            drift::kick_drift::<false>(bodies, deferred, broad, walls, rules);
        }
        let t = clock.t;
        let moved = rigid::move_aggregates(rigid, &mut bodies.states, journal, rules, t);
        if rules.kicks.pkdgrav_levers {
            carry_stuck(&mut bodies.states, broad, walls, rules);
        }
        // pkdgrav exits in the drift when a rigid body's integrator fails.
        if moved.and(rigid::move_assemblies(rigid, walls, journal, rules, t)) == Flow::Stop {
            return Flow::Stop;
        }
        let particles = (bodies.states.as_slice(), &bodies.numbering);
        near::update_lists(
            &mut broad.candidates,
            &mut broad.near,
            particles,
            &walls.now,
        );
        let Some(flow) = self.contacts() else {
            return Flow::Stop;
        };
        rigid::kick_assemblies(&mut self.rigid, &self.wall_pass, &self.rules);
        rigid::gather_aggregates(&mut self.rigid, &self.bodies, &self.rules, true);
        flow
    }

    /// The forces of the particle contacts and then of the wall contacts (with the
    /// closing kick), and what they did: whether the run goes on after the wall
    /// contacts, or `None` when a pair's overlap is past pkdgrav's abort (the wall
    /// contacts are not taken then).
    fn contacts(&mut self) -> Option<Flow> {
        let SoftStepper {
            rules,
            bodies,
            walls,
            broad,
            rigid,
            deferred,
            pair_pass,
            wall_pass,
            journal,
            clock,
            ..
        } = self;
        let t = clock.t;
        if pairs_meet(rules, bodies) {
            let sets = (&mut broad.candidates, pair_pass, &mut *journal);
            if pairs::pair_contacts(bodies, deferred, sets, rigid, rules, t) == Flow::Stop {
                return None;
            }
        }
        let near = broad.near.as_ref();
        walls::wall_contacts(bodies, deferred, wall_pass, (walls, near), rigid, rules, t);
        let flow =
            walls::note_wall_contacts(wall_pass, journal, broad, bodies, walls, rigid, rules, t);
        Some(flow)
    }

    /// The first particle (in the file's order) whose numbers overflowed in the last
    /// step, if any: in the wall pass, or in a kick owed (given now unless surely
    /// finite).
    fn not_finite(&mut self) -> Option<usize> {
        if !drift::surely_finite(&self.deferred) {
            drift::settle(&mut self.bodies, &mut self.deferred, &self.rules);
        }
        let numbering = &self.bodies.numbering;
        let reported = (self.wall_pass.reports.iter().flatten())
            .find(|(_, r)| r.not_finite)
            .map(|(i, _)| numbering.file(*i));
        match (reported, self.deferred.owed_bad) {
            (Some(i), Some(j)) => Some(i.min(j)),
            (i, j) => i.or(j),
        }
    }

    /// What the run came to, and why it `stopped` early (besides pkdgrav's aborts,
    /// which the warnings say).
    fn outcome(mut self, stopped: Option<super::Stop>) -> Outcome {
        drift::settle(&mut self.bodies, &mut self.deferred, &self.rules);
        self.bodies.file_order();
        let g = self.rules.settings.gravity;
        let assemblies = self.rigid.assemblies;
        let last = energy(&self.bodies.states, &g) + assembly_energy(&assemblies, &g);
        Outcome {
            t: self.clock.t,
            steps: self.clock.steps - self.rules.settings.start_step,
            particles: self.bodies.states,
            events: self.journal.events,
            assemblies,
            pair_contacts: self.journal.pair_contacts,
            overlaps: self.journal.overlaps.counts,
            energy: (self.initial, last),
            warnings: self.journal.warnings,
            stopped,
        }
    }
}

impl Bodies {
    /// The states put in the file's order, to be looked at.
    fn file_order(&mut self) {
        if !self.filed {
            self.numbering.to_file(&mut self.states);
            self.filed = true;
        }
    }

    /// The states back at their places after a look ([`Bodies::file_order`]).
    fn place_order(&mut self) {
        if self.filed {
            self.numbering.to_places(&mut self.states);
            self.filed = false;
        }
    }
}

/// Whether the particles meet each other in this run: the plan has particle contacts,
/// forces are on (`bDoGravity`) and there are two particles or more.
fn pairs_meet(rules: &Rules, bodies: &Bodies) -> bool {
    rules.plan.particle_contacts && rules.settings.forces && bodies.states.len() > 1
}

/// The clock moves on a step, and the moving walls with it.
fn move_walls(walls: &mut WallSet, clock: &mut Clock, rules: &Rules) {
    let (scene, settings) = (rules.scene, rules.settings);
    let dt = settings.dt;
    let pkdgrav = settings.integrator == Integrator::Pkdgrav;
    if rules.plan.moving_walls {
        if pkdgrav {
            walls.origins.advance_pkdgrav(scene, clock.t, dt);
        } else {
            walls.origins.advance(scene, clock.t, dt);
        }
    }
    clock.steps += 1;
    clock.t = settings.next_time(clock.t, clock.steps);
    if rules.plan.moving_walls {
        walls.now = if pkdgrav {
            // pkdgrav's walls move at the velocity of half a step later (§5).
            walls.origins.walls_pkdgrav(scene, clock.t + 0.5 * dt)
        } else {
            walls.origins.walls(scene, clock.t)
        };
    }
}

/// The particles stuck to walls carried with their walls' move, as pkdgrav moves them
/// in the wall move, before the forces (docs/pkdgrav-physics.md §6): with
/// [`Integrator::Pkdgrav`], which a particle meeting a stuck one then sees where the
/// wall has taken it.
fn carry_stuck(states: &mut [State], broad: &Broad, walls: &WallSet, rules: &Rules) {
    // None is stuck until some particle is held ([`PairList::held`]): no pass then.
    if !broad.candidates.held {
        return;
    }
    let dt = rules.settings.dt;
    for s in states {
        if let (true, Some(&(w, _))) = (s.alive, s.stuck_to.as_deref()) {
            carry(s, &walls.now[w], dt);
        }
    }
}

impl super::Snapshot for SoftStepper<'_> {
    /// The particles after the kicks owed ([`drift::settle`]), in the file's order.
    fn look(&mut self) -> (&[State], &[Assembly]) {
        drift::settle(&mut self.bodies, &mut self.deferred, &self.rules);
        self.bodies.file_order();
        (&self.bodies.states, &self.rigid.assemblies)
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
        let assembly = run.rigid.assemblies.iter().find(|a| !a.finite());
        if let Some(number) = assembly.map(|a| a.number) {
            return run.outcome(Some(super::Stop::AssemblyNotFinite(number)));
        }
        if not_finite.is_none() {
            observe(run.clock.steps, run.clock.t, &mut run);
        }
        if let Some(stop) = super::halt_at(not_finite, interrupted) {
            return run.outcome(Some(stop));
        }
    }
    run.outcome(None)
}

/// How many particles a thread takes at a time in the passes over all of them.
const CHUNK: usize = 512;

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
