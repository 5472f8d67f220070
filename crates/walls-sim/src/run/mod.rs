//! Running particles against walls: what both contact models share (settings, events,
//! the outcome, the walls as they stand during a step) and the choice between them. The
//! particles they move are [`crate::bodies`]'s [`State`]s.
//!
//! * `soft`: the soft-sphere model (SSDEM), pkdgrav's kick-drift-kick leapfrog with the
//!   spring–dashpot of [`crate::contact::ssdem`] against every wall and particle a particle
//!   overlaps.
//! * `hard`: the hard-sphere model (HSDEM), kick-drift-kick too, but each drift moves
//!   particles in straight lines from one predicted collision to the next (docs/spec.md
//!   §3).
//!
//! Sticky walls (`epsn 0`) hold a particle at its contact point, which then moves with
//! the wall; death walls (`epsn` < 0) remove it. Each wall contact that ends is an event
//! with the normal speeds in and out.
//!
//! What a run warns about (the stability checks before it starts, the steppers during
//! it) is a coded [`Warning`] ([`warning`]; docs/run-warnings.md lists the codes).

pub mod defaults;
mod hard;
pub mod optional;
pub mod plan;
mod pool;
mod soft;
pub mod stability;

pub use crate::bodies::State;
pub use crate::contact::hsdem::COLLISION_CAP;
pub use crate::warning;
pub use crate::warning::{Overlapping, Stiffest, Warning};

use crate::contact::ssdem::Material;
use crate::run::plan::Plan;
use nalgebra::Vector3;
use walls_geometry::Particle;
use walls_geometry::motion::{Moving, turned};
use walls_geometry::{OscillationStepping, Shape, Wall};
pub use walls_keywords::ContactModel;

type Vec3 = Vector3<f64>;

/// The particles' material values, which walls' 99 and −1 fall back to, and which
/// particles meet each other with.
pub type ParticleMaterial = Material;

/// How the soft-sphere run integrates the equations of motion. As a command-line value
/// (the `clap` feature), the variants are listed in this order, pkdgrav's (the default)
/// first, with the short help of `--integrator`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum Integrator {
    /// pkdgrav's own step, in its order (docs/pkdgrav-physics.md §2): the forces
    /// evaluated once at the start (stepping the springs of contacts open then); every
    /// contact, with a wall or a particle, fed the velocities and spins predicted to the
    /// step's end with the last accelerations (v_n + a_n·dt, w_n + ẇ_n·dt); pkdgrav's
    /// levers (r − x against a wall, the distances to the plane of intersection between
    /// particles, §1.1); and the walls moved as its soft-sphere build moves them (§5:
    /// in steps of `step`, or of dt when it is 0, to the sinusoid's value, with the
    /// velocity half a step after the step's end), whatever the oscillation stepping;
    /// particles stuck to walls carried with the wall's move, before the forces (§6);
    /// and pkdgrav's contact law (§1.3–§1.5, `contact::ssdem::dashpot_contact`): the
    /// shear spring turned with the contact and reset when it slides, rolling and
    /// twisting as spring–dashpot–sliders with β_s (or, in a build without
    /// `DEM_ROTATION_DASHPOT`, the constant torques of §1.6). The default: runs show
    /// what pkdgrav will do.
    #[default]
    #[cfg_attr(
        feature = "clap",
        value(help = "pkdgrav's step order and contact law (docs/pkdgrav-physics.md §1–§2, §5)")
    )]
    Pkdgrav,
    /// Kick-drift-kick leapfrog: half a kick, a drift, the forces, half a kick. Second
    /// order; the dashpot sees the velocity of the first half kick.
    #[cfg_attr(feature = "clap", value(help = "Kick-drift-kick leapfrog"))]
    Leapfrog,
    /// The same leapfrog, with the dashpot fed velocities predicted to the end of the
    /// step with the last acceleration, as pkdgrav does.
    #[cfg_attr(
        feature = "clap",
        value(
            help = "Kick-drift-kick with the dashpot at the velocity predicted to the step's end"
        )
    )]
    LeapfrogPredicted,
    /// Explicit Euler: a drift with the last velocity, a whole kick with the last
    /// acceleration, then the forces. First order and not symplectic; for comparison
    /// (docs/accuracy.md).
    #[cfg_attr(feature = "clap", value(name = "euler", help = "Explicit Euler"))]
    ExplicitEuler,
}

/// What to run.
#[derive(Debug, Clone, PartialEq)]
pub struct Settings {
    /// The pkdgrav build whose physics the run follows (docs/pkdgrav-physics.md §0): soft
    /// or hard spheres (`DEM`, [`Settings::method`]), and which of cohesion, two-layer
    /// contacts, reactive walls, aggregates and the rolling model it has.
    pub build: crate::build::Build,
    /// The timestep.
    pub dt: f64,
    /// When to stop, unless `last_step` says.
    pub t_end: f64,
    /// Whether the timestep is the user's (`--dt`, the `.par` file's `dDelta`) rather
    /// than a default shortened to end on `t_end`: a run of time whose `t_end` is not a
    /// whole number of such steps ends after it, and says so (W108). [`Settings::new`]
    /// leaves it off.
    pub dt_given: bool,
    /// The number of the step the run starts after: it starts at `start_step`·`dt`, and
    /// its steps are numbered from `start_step` + 1 (pkdgrav's `iStartStep`).
    pub start_step: u64,
    /// The number of the last step, when the run counts steps rather than time
    /// (pkdgrav's `nSteps`): it then runs exactly the steps `start_step` + 1 … `last_step`.
    pub last_step: Option<u64>,
    /// Uniform gravity.
    pub gravity: Vec3,
    /// The particles' material.
    pub material: ParticleMaterial,
    /// Whether particles collide with each other (they always collide with walls).
    pub particle_contacts: bool,
    /// HSDEM: whether edges, corners and rims count (pkdgrav's `bWallsEdgeDetect`, on by
    /// default); with it off only faces and cylinder sides do.
    pub edges: bool,
    /// How oscillating walls advance: the exact sinusoid, or pkdgrav's steps.
    pub stepping: OscillationStepping,
    /// SSDEM: the integrator (HSDEM is always kick-drift-kick).
    pub integrator: Integrator,
    /// Which parts of the model run: those the scene needs, or all of them.
    pub planning: Planning,
    /// [`Integrator::Pkdgrav`]: whether the rolling and twisting radius R* is the
    /// contact radius instead of the reduced radius (pkdgrav's `bUseContactRadius`,
    /// docs/pkdgrav-physics.md §1.4; off by default).
    pub contact_radius: bool,
    /// [`Integrator::Pkdgrav`] in a build without `DEM_ROTATION_DASHPOT`: whether the
    /// rolling lever is l₁, l₂ (d against a wall) instead of the reduced radius
    /// (pkdgrav's `bUseLegacyRoll`, docs/pkdgrav-physics.md §1.6; off by default).
    pub legacy_roll: bool,
    /// Whether forces are evaluated at all (pkdgrav's `bDoGravity`,
    /// docs/pkdgrav-physics.md §2): without, SSDEM particles feel no contacts (config
    /// also drops uniform gravity).
    pub forces: bool,
    /// [`Integrator::Pkdgrav`]: pkdgrav's `dAccCrit` (docs/pkdgrav-physics.md §1.7):
    /// after the forces, a particle slowing down with |a| below it and |v| below it·dt is
    /// stopped (and likewise its spin, with the thresholds over and times its radius); 0
    /// turns it off.
    pub acc_crit: f64,
    /// SSDEM: pkdgrav's overlap levels (`dMinorFrac`, `dMajorFrac`, `dErrorFrac`,
    /// docs/pkdgrav-physics.md §15): overlaps past them are counted and warned of, and
    /// past the error level the run stops, as pkdgrav aborts.
    pub overlap_levels: OverlapLevels,
    /// Cohesion's `.par` values (docs/pkdgrav-physics.md §7): followed when the build has
    /// `DEM_COHESION` and the integrator is [`Integrator::Pkdgrav`].
    pub cohesion: crate::contact::cohesion::Cohesion,
    /// The two-layer constants of the `.par` file (docs/pkdgrav-physics.md §8), `None`
    /// for pkdgrav's defaults (no boundary, every constant from k_n): followed when the
    /// build has `DEM_TWOLAYERS` and the integrator is [`Integrator::Pkdgrav`].
    pub two_layer: Option<crate::io::par::TwoLayer>,
    /// [`Integrator::Pkdgrav`]: what the shear spring of a sliding contact does:
    /// pkdgrav's reset (the default) or the Coulomb clamp (docs/accuracy.md, "Sliding
    /// friction").
    pub sliding: crate::contact::ssdem::Sliding,
    /// SSDEM: where the run keeps its particles in memory (not an option of the tools:
    /// the outputs are the same bit for bit, and tests compare the two).
    pub places: Places,
    /// SSDEM: whether the run asks for memory ahead of its use (not an option of the
    /// tools either, for the same reason).
    pub ahead: Ahead,
}

/// Where the soft-sphere run keeps its particles in memory: what it does and reports is
/// the same either way, bit for bit, but not how fast (docs/performance.md).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Places {
    /// In the order of the pair grid's cells, where a pair's two are near each other
    /// in memory as they are in space (but an aggregate's members, which name each
    /// other, keep the file's order).
    #[default]
    Grid,
    /// In the file's order.
    File,
}

/// Whether the soft-sphere run's passes ask the processor for the memory they will read
/// a few particles or pairs on (a hint: what the run does and reports is the same
/// either way, bit for bit, but not how fast; docs/performance.md, "Asking for memory
/// ahead").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Ahead {
    /// With 32,768 particles or more, where a step's data no longer stays in the
    /// processor's caches.
    #[default]
    ForMany,
    /// Always.
    Always,
    /// Never.
    Never,
}

/// How a run chooses the parts of the model it runs ([`crate::run::plan`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Planning {
    /// Only the parts the scene needs.
    #[default]
    Needed,
    /// Every part, whatever the scene: for comparison.
    Everything,
    /// These parts (for tests and benchmarks that compare one part on and off).
    Exactly(Plan),
}

impl Settings {
    /// Settings with pkdgrav's defaults for what is not given: SSDEM, no gravity,
    /// particle contacts and edge detection on, from time 0 until `t_end`.
    pub fn new(dt: f64, t_end: f64, material: ParticleMaterial) -> Self {
        Settings {
            build: crate::build::Build::default(),
            dt,
            t_end,
            dt_given: false,
            start_step: 0,
            last_step: None,
            gravity: Vec3::zeros(),
            material,
            particle_contacts: true,
            edges: true,
            stepping: OscillationStepping::Pkdgrav,
            integrator: Integrator::Pkdgrav,
            planning: Planning::Needed,
            contact_radius: false,
            legacy_roll: false,
            forces: true,
            acc_crit: 0.0,
            overlap_levels: OverlapLevels::default(),
            cohesion: crate::contact::cohesion::Cohesion::default(),
            two_layer: None,
            sliding: crate::contact::ssdem::Sliding::Reset,
            places: Places::Grid,
            ahead: Ahead::ForMany,
        }
    }

    /// The contact model: soft spheres when the build has `DEM`, else hard spheres.
    pub fn method(&self) -> ContactModel {
        self.build.contact_model()
    }

    /// The time the run starts at: `start_step`·`dt` (pkdgrav's t₀).
    pub fn t_start(&self) -> f64 {
        self.start_step as f64 * self.dt
    }

    /// The number of the run's last step: `last_step`, else the first whose time
    /// reaches `t_end` (up to [`round_off`]: a count a billionth above a whole number,
    /// never more than a thousandth of a step, is that number); `u64::MAX` when t_end/dt
    /// is not a finite number (NaN or beyond a double), which `config` refuses with the
    /// options that made it.
    pub fn end_step(&self) -> u64 {
        match self.last_step {
            Some(last) => last,
            None => {
                let x = self.t_end / self.dt;
                if !x.is_finite() {
                    // (inf − round-off of inf is NaN, which `max(0.0)` would make 0 steps.)
                    return u64::MAX;
                }
                (x - round_off(x)).ceil().max(0.0) as u64
            }
        }
    }

    /// Whether a run of time (no `last_step`) ends exactly on `t_end`: whether `t_end`
    /// is a whole number of steps (to [`round_off`]).
    fn ends_on_t_end(&self) -> bool {
        let x = self.t_end / self.dt;
        (self.end_step() as f64 - x).abs() <= round_off(x)
    }

    /// The time after step number `step`: `step`·`dt`, the start time plus whole steps
    /// with no accumulated round-off, and exactly `t_end` at the last step of a run
    /// that ends on it.
    pub fn time_at(&self, step: u64) -> f64 {
        if self.last_step.is_none() && step == self.end_step() && self.ends_on_t_end() {
            self.t_end
        } else {
            step as f64 * self.dt
        }
    }

    /// The time after step number `step`, the previous step's time being `previous`:
    /// a pkdgrav run (its steps counted, `last_step`) adds `dt` to the time as pkdgrav
    /// does, so that the times it writes (the `.ss` headers) are pkdgrav's to the last
    /// bit; a run of time takes [`Settings::time_at`].
    pub fn next_time(&self, previous: f64, step: u64) -> f64 {
        if self.last_step.is_some() {
            previous + self.dt
        } else {
            self.time_at(step)
        }
    }

    /// Whether a run that has reached step number `step` takes another.
    fn due(&self, step: u64) -> bool {
        step < self.end_step()
    }
}

/// Below this many particles a step runs on one thread: handing the work to rayon costs
/// more than it saves (docs/performance-history.md).
const PARALLEL_FROM: usize = 1024;

/// Whether a run of `n` particles takes its passes in parallel: with many particles and
/// more than one thread. With one thread, the plain loops: the same outcome, without
/// rayon's splitting and collecting.
fn in_parallel(n: usize) -> bool {
    n >= PARALLEL_FROM && rayon::current_num_threads() > 1
}

/// Steps per pair contact in the default timestep π·√(m/(2k_n))/N: at 100 the rebound
/// is within 1 % of ε for ε from 0.1 to 0.95 (docs/evaluator.md).
pub const STEPS_PER_CONTACT: f64 = 100.0;

/// pkdgrav's suggested timestep for the lightest particle, with [`STEPS_PER_CONTACT`].
pub fn default_dt(particles: &[impl AsRef<Particle>], k_n: f64) -> f64 {
    let m = particles
        .iter()
        .map(|p| p.as_ref().mass)
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

/// The result of a run.
#[derive(Debug, Clone, PartialEq)]
pub struct Outcome {
    /// The time reached.
    pub t: f64,
    /// Steps taken (from `start_step`: the last step's number is `start_step` + this).
    pub steps: u64,
    /// The particles at the end.
    pub particles: Vec<State>,
    /// What happened at walls, in order.
    pub events: Vec<Event>,
    /// The reactive walls' assemblies at the end (SSDEM).
    pub assemblies: Vec<crate::dynamics::reactive::Assembly>,
    /// Particle–particle contacts that began (SSDEM) or collisions (HSDEM).
    pub pair_contacts: u64,
    /// SSDEM: the overlap events past pkdgrav's levels ([`Settings::overlap_levels`]),
    /// for pairs and for walls, as pkdgrav counts them.
    pub overlaps: OverlapCounts,
    /// Kinetic (with spin) plus gravitational energy at the start and the end.
    pub energy: (f64, f64),
    /// Warnings, in the order they arose; each prints as pkdgrav users read it.
    pub warnings: Vec<Warning>,
    /// Why the run stopped before its end, if it did.
    pub stopped: Option<Stop>,
}

/// Why a run stopped before its last step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stop {
    /// An overlap past `dErrorFrac` of the radius, where pkdgrav aborts (W103).
    Overlap,
    /// An aggregate of a single member, where pkdgrav aborts.
    SingleMemberAggregate,
    /// A member of an aggregate at a sticky wall, or an aggregate's last member deleted
    /// by a death wall, where pkdgrav aborts.
    AggregateHeld,
    /// A rigid body's adaptive integrator (a reactive assembly's or an aggregate's
    /// rotation) failed: more than 10,000 substeps, or a substep too small to move the
    /// clock, where pkdgrav exits (W404).
    Integration,
    /// A particle's position, velocity or spin became infinite or NaN (the particle's
    /// index): the numbers outgrew what a double holds.
    NotFinite(usize),
    /// A reactive assembly's position, velocity, rotation or load became infinite or NaN
    /// (its `assembly` number).
    AssemblyNotFinite(i64),
    /// The caller asked the run to stop (an interrupt).
    Interrupted,
    /// The timestep is not a positive finite number, or the steps it makes cannot be
    /// counted (more than [`walls_keywords::number::EXACT_COUNT`]): the run could not
    /// start.
    Timestep,
}

impl Stop {
    /// A short name for machines (the JSON `stopped` field).
    pub fn code(self) -> &'static str {
        match self {
            Stop::Overlap => "overlap",
            Stop::SingleMemberAggregate => "single-member-aggregate",
            Stop::AggregateHeld => "aggregate-held",
            Stop::Integration => "integration",
            Stop::NotFinite(_) | Stop::AssemblyNotFinite(_) => "not-finite",
            Stop::Interrupted => "interrupted",
            Stop::Timestep => "timestep",
        }
    }
}

impl std::fmt::Display for Stop {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Stop::Overlap => write!(
                f,
                "an overlap above dErrorFrac of the radius, where pkdgrav aborts"
            ),
            Stop::SingleMemberAggregate => {
                write!(f, "an aggregate of a single member, where pkdgrav aborts")
            }
            Stop::AggregateHeld => write!(
                f,
                "a member of an aggregate at a sticky wall, or an aggregate's last member deleted by a death wall, where pkdgrav aborts"
            ),
            Stop::Integration => write!(
                f,
                "the adaptive integrator of a rigid body's rotation failed, where pkdgrav exits"
            ),
            Stop::NotFinite(i) => write!(
                f,
                "particle {i}'s position, velocity or spin became infinite or NaN (the values outgrew a double: shorten the timestep or check the input's scale)"
            ),
            Stop::AssemblyNotFinite(n) => write!(
                f,
                "reactive assembly {n}'s position, velocity, rotation or load became infinite or NaN (the values outgrew a double: shorten the timestep or check the walls' masses and moments)"
            ),
            Stop::Interrupted => write!(f, "interrupted (Ctrl-C, SIGTERM or SIGHUP)"),
            Stop::Timestep => write!(
                f,
                "the timestep is not a positive finite number, or makes more steps than a run can count (2^53)"
            ),
        }
    }
}

/// The first particle still in the run whose position, velocity or spin is not finite.
fn first_not_finite(states: &[State]) -> Option<usize> {
    states.iter().position(|s| !s.finite())
}

/// How a stepper asks whether to go on after a step, the first particle whose numbers
/// overflowed being `not_finite` (if any): [`Stop::NotFinite`] then,
/// [`Stop::Interrupted`] when `interrupted` says so.
fn halt_at(not_finite: Option<usize>, interrupted: Interrupted) -> Option<Stop> {
    if let Some(i) = not_finite {
        return Some(Stop::NotFinite(i));
    }
    interrupted().then_some(Stop::Interrupted)
}

/// What watches a run: called after every step with the step number (pkdgrav's, counted
/// from [`Settings::start_step`]), the time, and the step's [`Snapshot`] of the particles
/// and the reactive walls' assemblies; not after a step whose numbers overflowed (the run
/// stops there, [`Stop::NotFinite`], [`Stop::AssemblyNotFinite`]), so that what it
/// writes is finite. It is `Send`: a run on several threads steps on one of rayon's, and
/// calls it there (`pool::on_the_pool`).
pub type Observer<'a> = &'a mut (dyn FnMut(u64, f64, &mut dyn Snapshot) + Send);

/// Whether a run is asked to stop after a step ([`run_watched`]); `Sync` for the same
/// reason as [`Observer`].
pub type Interrupted<'a> = &'a (dyn Fn() -> bool + Sync);

/// The particles and the reactive walls' assemblies as a step left them, for an
/// [`Observer`] that looks. The soft stepper gives most free particles the step's closing
/// kick in the next step's first pass, with their drift (one pass over the particles
/// rather than two); it gives the kicks owed when the particles are looked at, so an
/// observer that does not look (a progress bar, an output every hundred steps) does not
/// cost the pass it saves.
pub trait Snapshot {
    /// The particles and the assemblies at the step's end.
    fn look(&mut self) -> (&[State], &[crate::dynamics::reactive::Assembly]);
}

/// A [`Snapshot`] of states that owe nothing.
pub(crate) struct Settled<'a>(
    pub &'a [State],
    pub &'a [crate::dynamics::reactive::Assembly],
);

impl Snapshot for Settled<'_> {
    fn look(&mut self) -> (&[State], &[crate::dynamics::reactive::Assembly]) {
        (self.0, self.1)
    }
}

/// Runs `particles` against `walls` (and each other), calling `observe` after every
/// step with the step number, the time and a [`Snapshot`] of the particles
/// ([`run_watched`] never interrupted).
pub fn run_observed(
    walls: &[Wall],
    particles: Vec<Particle>,
    settings: &Settings,
    observe: Observer,
) -> Outcome {
    run_watched(walls, particles, settings, observe, &|| false)
}

/// [`run_observed`], asking `interrupted` after every step whether to stop there
/// ([`Stop::Interrupted`]). A run also stops when a particle's numbers stop being
/// finite ([`Stop::NotFinite`]), and does not start when the timestep is not a
/// positive finite number or its steps cannot be counted exactly ([`Stop::Timestep`];
/// callers check both first with `config::check`).
///
/// A run of 1,024 particles or more, with more than one thread in rayon's pool, runs on
/// one of the pool's threads, `observe` and `interrupted` included, while the calling
/// thread waits. So neither may wait on the calling thread (a lock it holds, a channel
/// it would read), and runs started together from several threads share the pool: one
/// may wait for another to finish.
///
/// The particles may come as [`Particle`]s or as [`State`]s (those a reader made of them,
/// [`crate::io::particles::read_file_as`]): a state's particle alone is taken, and the
/// states become the run's own in the memory they hold, where particles are copied into
/// states made for them.
pub fn run_watched<P: AsRef<Particle> + Into<State>>(
    walls: &[Wall],
    particles: Vec<P>,
    settings: &Settings,
    observe: Observer,
    interrupted: Interrupted,
) -> Outcome {
    let dt = settings.dt;
    let t0 = settings.t_start();
    let countable = |step: u64| step <= walls_keywords::number::EXACT_COUNT;
    let steps_fit = countable(settings.start_step) && countable(settings.end_step());
    if !(dt > 0.0 && dt.is_finite() && steps_fit) {
        let start = |p: P| State::from(p.into().particle);
        let states: Vec<State> = particles.into_iter().map(start).collect();
        let e = energy(&states, &settings.gravity);
        return Outcome {
            t: t0,
            steps: 0,
            particles: states,
            events: Vec::new(),
            assemblies: Vec::new(),
            pair_contacts: 0,
            overlaps: OverlapCounts::default(),
            energy: (e, e),
            warnings: Vec::new(),
            stopped: Some(Stop::Timestep),
        };
    }
    let mut plan = match settings.planning {
        Planning::Needed => Plan::for_run(walls, &particles, settings),
        Planning::Everything => Plan::everything(),
        Planning::Exactly(plan) => plan,
    };
    // Walls react only where the run can have them ([`plan::reactive`]: a build with
    // `DEM_WALLS_REACT`), whatever plan was asked for.
    plan.reactive &= plan::reactive(walls, settings);
    // The particles become the states, each as a run starts it whatever state it came
    // in: the run does not keep them twice (states given are made anew where they lie,
    // the same type collected in place).
    let states: Vec<State> = particles
        .into_iter()
        .map(|p| {
            let p = p.into().particle;
            State {
                acc: settings.gravity,
                stuck_to: stuck_from_the_start(&p, walls, t0).map(Box::new),
                ..State::from(p)
            }
        })
        .collect();
    // Negative colours naming no wall, warned about after the run.
    let nowhere: Vec<usize> = states
        .iter()
        .enumerate()
        .filter(|(_, s)| s.particle.color < 0 && s.stuck_to.is_none())
        .map(|(i, _)| i)
        .collect();
    let parallel = in_parallel(states.len());
    let mut outcome = pool::on_the_pool(parallel, |helpers| match settings.method() {
        ContactModel::Ssdem => soft::run(
            walls,
            states,
            settings,
            &plan,
            observe,
            interrupted,
            helpers,
        ),
        ContactModel::Hsdem => hard::run(walls, states, settings, &plan, observe, interrupted),
    });
    // Where pkdgrav would abort, the run stopped.
    if outcome.stopped.is_none() {
        outcome.stopped = outcome.warnings.iter().find_map(|w| match w {
            Warning::OverlapStop { .. } => Some(Stop::Overlap),
            Warning::SingleMemberAggregate { .. } => Some(Stop::SingleMemberAggregate),
            Warning::AggregateHeld { .. } | Warning::AggregateDeleted { .. } => {
                Some(Stop::AggregateHeld)
            }
            Warning::StepFailed { .. } => Some(Stop::Integration),
            _ => None,
        });
    }
    // Walls' tokens the build (or the integrator) does not follow come first, then
    // negative colours naming no wall.
    let mut first = optional::token_warnings(walls, settings);
    if !nowhere.is_empty() {
        first.push(Warning::StuckToNoWall {
            particles: nowhere,
            walls: walls.len(),
        });
    }
    let step = settings.end_step();
    if settings.dt_given
        && settings.last_step.is_none()
        && !settings.ends_on_t_end()
        && settings.start_step + outcome.steps == step
    {
        first.push(Warning::EndsAfterTEnd {
            step,
            t: settings.time_at(step),
            t_end: settings.t_end,
        });
    }
    outcome.warnings.splice(0..0, first);
    outcome
}

/// The wall a particle is stuck to from the start, with its offset from the wall's
/// origin at `t0`: pkdgrav's negative `color`, −1 − the wall's number
/// (docs/pkdgrav-physics.md §0, `PARTICLE_STUCK`), when that wall exists.
fn stuck_from_the_start(p: &Particle, walls: &[Wall], t0: f64) -> Option<(usize, Vec3)> {
    let w = usize::try_from(-1 - i64::from(p.color)).ok()?;
    let wall = walls.get(w)?;
    Some((w, p.pos - wall.motion.position_or_origin(t0)))
}

/// The warning for particles that are members of aggregates (negative `org_idx`) in a
/// run that does not follow aggregates (W601), saying why.
fn aggregates_ignored(states: &[State], settings: &Settings) -> Warning {
    let mut numbers: Vec<u32> = states
        .iter()
        .filter_map(|s| crate::dynamics::aggregate::aggregate_of(&s.particle))
        .collect();
    let members = numbers.len();
    numbers.sort_unstable();
    numbers.dedup();
    let reason = if !settings.build.aggs {
        "the build has no AGGS"
    } else if settings.method() == ContactModel::Hsdem {
        "aggregates are followed in soft-sphere (DEM) runs only"
    } else {
        "the integrator is not pkdgrav's"
    };
    Warning::AggregatesIgnored {
        members,
        aggregates: numbers.len(),
        reason,
    }
}

/// Runs `particles` against `walls` ([`run_observed`] without watching).
pub fn run(walls: &[Wall], particles: Vec<Particle>, settings: &Settings) -> Outcome {
    run_observed(walls, particles, settings, &mut |_, _, _| {})
}

/// The materials of a run: each wall's, with the particles' values where the wall says
/// so (99 and −1), and the particles' own for contacts between them.
struct Materials {
    walls: Vec<Material>,
    between: Material,
}

impl Materials {
    fn new(walls: &[Wall], p: &ParticleMaterial) -> Materials {
        let walls = walls.iter().map(|wall| wall.material.against(p)).collect();
        Materials { walls, between: *p }
    }
}

/// Kinetic energy with spin, plus gravitational energy, of the particles still in.
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
        .fold(0.0, |e, x| e + x)
}

/// A wall as it stands at one time: where its origin is, its shape there, and how its
/// material moves (read from the scene once per step, not per contact).
#[derive(Debug, Clone)]
struct WallNow {
    origin: Vec3,
    shape: Shape,
    velocity: Vec3,
    spin: Vec3,
    /// The cheap test of whether a particle is out of reach, before any nearest-point
    /// query.
    cull: walls_geometry::shape::Cull,
}

impl WallNow {
    /// `shape` placed with its origin at `origin`, moving at `velocity` and spinning at
    /// `spin`.
    fn placed(origin: Vec3, shape: Shape, velocity: Vec3, spin: Vec3) -> WallNow {
        WallNow {
            origin,
            cull: walls_geometry::shape::Cull::of(&shape),
            shape,
            velocity,
            spin,
        }
    }

    /// `wall` at time `t` with its origin at `origin`.
    fn new(wall: &Wall, origin: Vec3, t: f64) -> WallNow {
        Self::moving(wall, origin, wall.motion.origin_velocity(t))
    }

    /// `wall` with its origin at `origin` and its origin's velocity `velocity`.
    fn moving(wall: &Wall, origin: Vec3, velocity: Vec3) -> WallNow {
        Self::placed(origin, wall.shape.at(origin), velocity, wall.motion.spin())
    }

    /// How it moves now: its origin, the origin's velocity and its spin.
    fn motion(&self) -> Moving {
        Moving {
            origin: self.origin,
            velocity: self.velocity,
            spin: self.spin,
        }
    }

    /// The velocity of the wall's material at `q`.
    fn point_velocity(&self, q: &Vec3) -> Vec3 {
        self.motion().point_velocity(q)
    }
}

/// Where the walls' origins are as a run goes on: at the exact position of docs/spec.md
/// §1 "Motion", or moved step by step as pkdgrav does ([`OscillationStepping`]). A wall
/// whose motion overflows stays where it was.
struct Origins {
    now: Vec<Vec3>,
    stepping: OscillationStepping,
}

impl Origins {
    /// The origins at the start time `t0`.
    fn new(walls: &[Wall], stepping: OscillationStepping, t0: f64) -> Origins {
        let now = walls
            .iter()
            .map(|w| w.motion.position_or_origin(t0))
            .collect();
        Origins { now, stepping }
    }

    /// Moves every origin over the step from `t` to `t + dt`.
    fn advance(&mut self, walls: &[Wall], t: f64, dt: f64) {
        for (o, w) in self.now.iter_mut().zip(walls) {
            if let Some(next) = w.motion.step(o, t, dt, self.stepping) {
                *o = next;
            }
        }
    }

    /// Moves every origin as pkdgrav's soft-sphere build does over the step from `t`
    /// to `t + dt` ([`walls_geometry::Motion::soft_sphere_step`]).
    fn advance_pkdgrav(&mut self, walls: &[Wall], t: f64, dt: f64) {
        for (o, w) in self.now.iter_mut().zip(walls) {
            if let Some(next) = w.motion.soft_sphere_step(o, t, dt) {
                *o = next;
            }
        }
    }

    /// The walls as they stand at time `t`.
    fn walls(&self, walls: &[Wall], t: f64) -> Vec<WallNow> {
        walls
            .iter()
            .zip(&self.now)
            .map(|(w, o)| WallNow::new(w, *o, t))
            .collect()
    }

    /// The walls where they stand, their origins moving at pkdgrav's velocity for time
    /// `t` ([`walls_geometry::Motion::smooth_velocity`]).
    fn walls_pkdgrav(&self, walls: &[Wall], t: f64) -> Vec<WallNow> {
        walls
            .iter()
            .zip(&self.now)
            .map(|(w, o)| WallNow::moving(w, *o, w.motion.smooth_velocity(t)))
            .collect()
    }
}

/// Moves a particle held by a sticky wall along with it over a step of `dt` ending with
/// the wall as `now`: with its origin, and around its spin axis; it spins with the wall
/// (as pkdgrav sets it).
fn carry(s: &mut State, now: &WallNow, dt: f64) {
    let Some((_, offset)) = s.stuck_to.as_deref_mut() else {
        return;
    };
    (s.particle.pos, s.particle.vel) = now.motion().carry(offset, dt);
    s.particle.spin = now.spin;
}

/// pkdgrav's overlap levels (`dMinorFrac`, `dMajorFrac`, `dErrorFrac`,
/// docs/pkdgrav-physics.md §15), as fractions of a radius: the smaller radius of a pair,
/// the particle's against a wall. An overlap x is past a level when x > level·radius
/// (strictly); past `error`, pkdgrav aborts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OverlapLevels {
    /// `dMinorFrac` (pkdgrav's default 0.03).
    pub minor: f64,
    /// `dMajorFrac` (pkdgrav's default 0.15).
    pub major: f64,
    /// `dErrorFrac` (pkdgrav's default 0.5): past it pkdgrav aborts, and the run stops.
    pub error: f64,
}

impl Default for OverlapLevels {
    /// pkdgrav's defaults: 0.03, 0.15, 0.5.
    fn default() -> Self {
        OverlapLevels {
            minor: 0.03,
            major: 0.15,
            error: 0.5,
        }
    }
}

impl OverlapLevels {
    /// The worst level an overlap of `fraction` of the radius is past, checked from the
    /// worst down with a strict `>` as pkdgrav does; `None` below (or at) the minor one.
    pub fn level_of(&self, fraction: f64) -> Option<OverlapLevel> {
        if fraction > self.error {
            Some(OverlapLevel::Error)
        } else if fraction > self.major {
            Some(OverlapLevel::Major)
        } else if fraction > self.minor {
            Some(OverlapLevel::Minor)
        } else {
            None
        }
    }
}

/// One of pkdgrav's overlap levels ([`OverlapLevels`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OverlapLevel {
    /// Past `dMinorFrac`, not past `dMajorFrac`.
    Minor,
    /// Past `dMajorFrac`, not past `dErrorFrac`.
    Major,
    /// Past `dErrorFrac`: pkdgrav aborts.
    Error,
}

/// How many overlap events a run met at each of pkdgrav's levels, each event counted at
/// the worst level it is past (once per force evaluation per pair, or per particle and
/// wall).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct LevelCounts {
    /// Past `dMinorFrac` only.
    pub minor: u64,
    /// Past `dMajorFrac`, not `dErrorFrac`.
    pub major: u64,
    /// Past `dErrorFrac` (at most one: the run stops there).
    pub error: u64,
}

impl LevelCounts {
    /// Every event, whatever its level: pkdgrav's counter, which decides whether it
    /// prints a minor event (at 1 and every 1,000,000th).
    pub fn total(&self) -> u64 {
        self.minor + self.major + self.error
    }

    fn add(&mut self, level: OverlapLevel) {
        *match level {
            OverlapLevel::Minor => &mut self.minor,
            OverlapLevel::Major => &mut self.major,
            OverlapLevel::Error => &mut self.error,
        } += 1;
    }
}

/// The overlap events of a run, counted apart for particle pairs and for particles
/// against walls, as pkdgrav keeps one counter for each (docs/pkdgrav-physics.md §15).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct OverlapCounts {
    /// Particle–particle overlaps.
    pub pairs: LevelCounts,
    /// Particle–wall overlaps.
    pub walls: LevelCounts,
}

impl OverlapCounts {
    /// Whether no overlap passed a level.
    pub fn is_empty(&self) -> bool {
        self.pairs.total() == 0 && self.walls.total() == 0
    }
}

/// pkdgrav's overlap checks as the run keeps them: every event past a level counted
/// ([`OverlapCounts`]), the first of each warning level warned of (W101, W102), and an
/// event past the error level warned of (W103), where the run stops.
#[derive(Default)]
struct OverlapWarnings {
    levels: OverlapLevels,
    warned: [bool; 2],
    counts: OverlapCounts,
}

impl OverlapWarnings {
    /// The checks at `levels`.
    fn new(levels: OverlapLevels) -> OverlapWarnings {
        OverlapWarnings {
            levels,
            ..OverlapWarnings::default()
        }
    }

    /// The overlap (a fraction of the radius) at or below which
    /// [`OverlapWarnings::check`] does nothing: `dMinorFrac`, as every event past it
    /// counts.
    pub(crate) fn quiet_up_to(&self) -> f64 {
        self.levels.minor
    }

    /// Notes an overlap of `fraction` of the radius between `what` at time `t`: counted
    /// at its level, warned of if it is the first at a warning level, or past the error
    /// level; true then, where pkdgrav aborts.
    fn check(
        &mut self,
        fraction: f64,
        what: Overlapping,
        t: f64,
        warnings: &mut Vec<Warning>,
    ) -> bool {
        let Some(level) = self.levels.level_of(fraction) else {
            return false;
        };
        match what {
            Overlapping::Particles(..) => self.counts.pairs.add(level),
            Overlapping::Wall { .. } => self.counts.walls.add(level),
        }
        let levels = self.levels;
        match level {
            OverlapLevel::Minor if !self.warned[0] => {
                self.warned[0] = true;
                warnings.push(Warning::OverlapMinor {
                    fraction,
                    level: levels.minor,
                    what,
                    t,
                });
            }
            OverlapLevel::Major if !self.warned[1] => {
                self.warned[1] = true;
                warnings.push(Warning::OverlapMajor {
                    fraction,
                    level: levels.major,
                    what,
                    t,
                });
            }
            OverlapLevel::Error => warnings.push(Warning::OverlapStop {
                fraction,
                level: levels.error,
                what,
                t,
            }),
            _ => {}
        }
        level == OverlapLevel::Error
    }
}

/// How far from a whole number a count of steps t_end/dt may be and still be that number:
/// a billionth of it (the round-off of the quotient), but never more than a thousandth of
/// a step (a billion steps are not one fewer).
fn round_off(count: f64) -> f64 {
    (1e-9 * count.max(1.0)).min(1e-3)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_billion_steps_are_a_billion() {
        let material = crate::config::pkdgrav_material(1.0);
        for (dt, t_end, steps) in [
            (1e-17, 1e-8, 1_000_000_000),
            (0.1, 0.3, 3),
            (0.1, 0.35, 4),
            (1e-3, 1.0000000001, 1000),
            (1e-6, 7.0, 7_000_000),
        ] {
            let s = Settings::new(dt, t_end, material);
            assert_eq!(s.end_step(), steps, "{t_end}/{dt}");
        }
    }
}
