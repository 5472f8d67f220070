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
//!
//! The stepper's state is kept in named sets: the walls ([`WallSet`]: materials, the
//! laws' constants, index, motion, assemblies' walls), the closing kicks deferred to the
//! next drift ([`Deferred`]), what the run has seen ([`Journal`]), the candidate pairs
//! ([`PairList`]) with the near-wall lists ([`NearWalls`]) and the pair pass's scratch,
//! and the contact law ([`Law`]), decided once at set-up for walls and pairs alike. Its
//! stages are in modules: [`setup`], [`drift`], [`pairs`] (the pair pass and law),
//! [`walls`] (the wall pass) and [`near`]; the step and the bodies' motion are here.

use super::pool::Helpers;
use super::{
    Event, EventKind, Integrator, Materials, Observer, Origins, Outcome, OverlapWarnings,
    Overlapping, PARALLEL_FROM, Settings, State, WallNow, Warning, carry, energy, in_parallel,
};
use crate::broad::pairs::PairList;
use crate::broad::wall_index::WallIndex;
use crate::contact::ssdem::{Material, Restitution};
use crate::dynamics::aggregate::Aggregates;
use crate::dynamics::reactive::Assembly;
use crate::dynamics::rigid::RotationIntegrator;
use crate::dynamics::sphere_inertia as inertia;
use crate::run::optional::OptionalPhysics;
use crate::run::plan::Plan;
use nalgebra::Vector3;
use walls_geometry::Wall;

mod drift;
mod near;
mod pairs;
mod setup;
mod walls;

use near::NearWalls;
use pairs::PairPass;
use walls::{Closing, Open, ParticleStep};

type Vec3 = Vector3<f64>;

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

/// The contact law of a run, against walls and between particles alike, decided once at
/// set-up ([`Law::of`]).
#[derive(Clone, Copy, PartialEq, Eq)]
enum Law {
    /// pkdgrav's spring–dashpot, in its frame ([`crate::contact::ssdem::dashpot_contact_with`],
    /// docs/pkdgrav-physics.md §1.1–§1.5): pkdgrav's integrator, with friction, rolling,
    /// twisting or one of its optional builds.
    Pkdgrav,
    /// The spring–dashpot of [`crate::contact::ssdem::contact`] (with sliding friction)
    /// or [`crate::contact::ssdem::normal_contact`], with rolling and twisting
    /// resistance beside it.
    Linear,
}

impl Law {
    /// The law of a run with these kicks, plan and optional physics.
    fn of(kicks: &Kicks, plan: &Plan, optional: &OptionalPhysics) -> Law {
        let dashpot = plan.sliding_friction || plan.rolling || plan.twisting;
        if kicks.pkdgrav_levers && (dashpot || optional.any()) {
            Law::Pkdgrav
        } else {
            Law::Linear
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

/// The closing kicks the wall pass defers to the next drift ([`SoftStepper::kick_drift`]),
/// which particles are owed one, and the bounds that tell whether they are surely finite
/// ([`SoftStepper::surely_finite`]).
struct Deferred {
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
    /// steps (docs/performance-history.md, "Fourteenth round"). A mark left on a load already
    /// set back (by the wall pass, by [`SoftStepper::settle`], or by the drift while
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
    /// The first particle whose numbers overflowed in an owed kick given by
    /// [`SoftStepper::settle`] this step.
    owed_bad: Option<usize>,
    /// The sum of the sizes (|x| + |y| + |z|) of every particle contact's force and
    /// torques this step, and the largest size of gravity on a particle, and 1/m or 1/I
    /// of a particle: bounds on what an owed kick can add ([`SoftStepper::surely_finite`]).
    force_bound: f64,
    gravity_bound: f64,
    largest_inverse: f64,
}

/// The walls of a run: their materials and the laws' constants worked out once, the wall
/// index, their motion and where they stand, and the reactive assemblies they belong
/// to.
struct WallSet {
    /// Each wall's material, with the particles' values where it says so.
    materials: Vec<Material>,
    /// Each wall's normal damping over √m, worked out once.
    damping: Vec<f64>,
    /// Each wall's normal and tangential restitutions, worked out once.
    restitutions: Vec<(Restitution, Restitution)>,
    /// Whether each wall oscillates (a bounce off it may gain speed).
    oscillating: Vec<bool>,
    /// The wall index, when the plan uses one.
    index: Option<WallIndex>,
    origins: Origins,
    /// The walls as they stand: placed once when no wall moves (the plan), else every
    /// step; reactive assemblies' walls every step.
    now: Vec<WallNow>,
    /// Each wall's assembly, if any.
    assembly_of: Vec<Option<usize>>,
    /// Each assembly's centre of gravity this step (kept to save allocating).
    cogs: Vec<Vec3>,
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
    /// The contact law, walls and pairs alike.
    law: Law,
    /// The walls, their materials and motion.
    walls: WallSet,
    /// The particles' material, for their contacts with each other.
    between: Material,
    /// Cohesion and two-layer contacts (pkdgrav's optional builds).
    optional: OptionalPhysics,
    /// Reactive assemblies (SSDEM only, as in pkdgrav), when the plan has them.
    assemblies: Vec<Assembly>,
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
    /// The closing kicks deferred to the next drift.
    deferred: Deferred,
    /// Each particle's open wall contacts: (wall, contact), kept apart from its load so
    /// that the passes that do not need them do not carry them.
    open_walls: Vec<Vec<(usize, Open)>>,
    /// Whether each particle has a wall contact open (its [`SoftStepper::open_walls`]
    /// is not empty): set by the wall pass after each particle's contacts, the only place
    /// they change (a particle the pass skips had none, nor has it now), and read by the
    /// drift as this byte, not the 24-byte vector, which at 10⁵ particles is memory the
    /// drift's stream need not carry (docs/performance-history.md, "Eighth round").
    walled: Vec<bool>,
    /// Each chunk's scratch list of the walls to visit (kept to save allocating).
    visits: Vec<Vec<usize>>,
    candidates: PairList,
    /// Without a wall index, the walls near each particle, found with the candidate
    /// pairs.
    near: Option<NearWalls>,
    /// What the pair pass works in (kept to save allocating).
    pair_pass: PairPass,
    /// What the wall contacts of each particle with something to note did this step,
    /// in particle order (kept to save allocating).
    reports: Vec<Vec<(usize, ParticleStep)>>,
    /// Whether a step runs on rayon's threads (many particles, and more than one
    /// thread).
    parallel: bool,
    /// The energy at the start.
    initial: f64,
    /// What the run has seen so far.
    journal: Journal,
    t: f64,
    steps: u64,
}

impl<'a> SoftStepper<'a> {
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
        // (docs/performance-history.md, "Twelfth round").
        if self.deferred.owed_kick.acc_crit > 0.0 {
            self.kick_drift::<true>();
        } else {
            self.kick_drift::<false>();
        }
        self.move_aggregates();
        if self.kicks.pkdgrav_levers {
            self.carry_stuck();
        }
        self.move_assemblies();
        near::update_lists(
            &mut self.candidates,
            &mut self.near,
            &self.states,
            &self.walls.now,
        );
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

    /// The clock moves on a step, and the moving walls with it.
    fn move_walls(&mut self) {
        let dt = self.settings.dt;
        let pkdgrav = self.settings.integrator == Integrator::Pkdgrav;
        if self.plan.moving_walls {
            if pkdgrav {
                self.walls.origins.advance_pkdgrav(self.scene, self.t, dt);
            } else {
                self.walls.origins.advance(self.scene, self.t, dt);
            }
        }
        self.steps += 1;
        self.t = self.settings.next_time(self.t, self.steps);
        if self.plan.moving_walls {
            self.walls.now = if pkdgrav {
                // pkdgrav's walls move at the velocity of half a step later (§5).
                self.walls
                    .origins
                    .walls_pkdgrav(self.scene, self.t + 0.5 * dt)
            } else {
                self.walls.origins.walls(self.scene, self.t)
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
                carry(s, &self.walls.now[w], dt);
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
                self.walls.now[w] = WallNow::placed(
                    a.cog,
                    a.shape(&self.scene[w].shape, k),
                    a.velocity,
                    a.spin(),
                );
            }
        }
        self.walls.cogs.clear();
        self.walls
            .cogs
            .extend(self.assemblies.iter().map(|a| a.cog));
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
            events: self.journal.events,
            assemblies: self.assemblies,
            pair_contacts: self.journal.pair_contacts,
            energy: (self.initial, last),
            warnings: self.journal.warnings,
            stopped,
        }
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
