//! The soft-sphere run's set-up ([`SoftStepper::new`]): the scene, particles, settings
//! and plan compiled once into the run's sets (the materials, the checks before it, the
//! walls, the assemblies that can move, pkdgrav's aggregates, the lists of what may
//! touch, the particles and the kicks deferred).

use super::ahead::AHEAD_FROM;
use super::near::{self, NearWalls};
use super::numbering::Numbering;
use super::pairs::{PairMaterial, PairPass};
use super::walls::{Closing, WallPass};
use super::{
    Bodies, Broad, CHUNK, Clock, ContactLaw, Deferred, Integrator, Inverses, Journal, Kicks, Load,
    Materials, OverlapWarnings, PARALLEL_FROM, Rigid, Rules, Settings, SoftStepper, State, Vec3,
    WallSet, WarnedOnce, Warning, assembly_energy, energy, in_parallel,
};
use crate::broad::pairs::PairList;
use crate::broad::wall_index::WallIndex;
use crate::contact::ssdem::{Material, Restitution, damping_per_root_mass};
use crate::dynamics::aggregate::{self, Aggregates};
use crate::dynamics::reactive::Assembly;
use crate::run::Ahead;
use crate::run::optional::OptionalPhysics;
use crate::run::plan::Plan;
use crate::run::{Origins, Places};
use walls_geometry::Wall;

impl<'a> SoftStepper<'a> {
    /// The run at its start, its sets compiled from the scene, the particles, the
    /// settings and the plan: the materials, the checks before it
    /// ([`crate::run::stability`]), pkdgrav's aggregates, the assemblies that can move,
    /// the walls, the lists of what may touch, the particles and the kicks deferred.
    pub(super) fn new(
        scene: &'a [Wall],
        mut states: Vec<State>,
        settings: &'a Settings,
        plan: &'a Plan,
    ) -> SoftStepper<'a> {
        let g = settings.gravity;
        let Materials {
            walls: materials,
            mut between,
        } = Materials::new(scene, &settings.material);
        if settings.build.aggs {
            // An AGGS build has no rolling or twisting between particles (§9.6).
            between.mu_r = 0.0;
            between.mu_t = 0.0;
        }
        let mut warnings = crate::run::stability::soft_warnings(scene, &states, settings);
        let (aggregates, halted) = set_up_aggregates(&mut states, settings, &mut warnings);
        let assemblies = set_up_assemblies(scene, settings, plan, &mut warnings);
        // The energy of what the run moves: the assemblies that cannot move are left
        // out, as they are from the energy at the end.
        let initial = energy(&states, &g) + assembly_energy(&assemblies, &g);
        let walls = wall_set(scene, settings, materials, &assemblies);
        // The particles' material takes its reference mass from the file's first.
        let between = PairMaterial::new(between, &states);
        // From here on each particle is at its place (`Numbering`).
        let renumber = aggregates.is_none() && settings.places == Places::Grid;
        let (broad, numbering) = broad(scene, &mut states, plan, &walls, renumber);
        let optional = OptionalPhysics::new(scene, &states, settings);
        let kicks = Kicks::of(settings.integrator);
        let contact = ContactLaw::of(settings, &kicks, plan, &optional);
        let n = states.len();
        let bodies = Bodies::new(states, numbering, &g);
        SoftStepper {
            rules: Rules {
                scene,
                settings,
                plan,
                kicks,
                contact,
                between,
                optional,
                parallel: in_parallel(n),
                ahead: match settings.ahead {
                    Ahead::ForMany => n >= AHEAD_FROM,
                    Ahead::Always => true,
                    Ahead::Never => false,
                },
            },
            deferred: Deferred::new(&bodies, settings),
            bodies,
            walls,
            broad,
            rigid: Rigid {
                assemblies,
                aggregates,
            },
            halted,
            pair_pass: PairPass::default(),
            wall_pass: WallPass::default(),
            initial,
            journal: Journal {
                events: Vec::new(),
                pair_contacts: 0,
                warnings,
                overlaps: OverlapWarnings::new(settings.overlap_levels),
                once: WarnedOnce::default(),
            },
            clock: Clock {
                t: settings.t_start(),
                steps: settings.start_step,
            },
        }
    }
}

impl Bodies {
    /// The particles `states` at the start of a run under gravity `g`: each load starts
    /// with gravity alone, whichever the integrator (pkdgrav's evaluation before the
    /// first step, `SoftStepper::start`, adds to it; the others kick with it at once; in
    /// a step, the wall pass starts the next step's, or the drift or
    /// `super::drift::settle` after an owed kick, and for an aggregate's members); no
    /// wall contact is open.
    fn new(states: Vec<State>, numbering: Numbering, g: &Vec3) -> Bodies {
        let n = states.len();
        Bodies {
            numbering,
            filed: false,
            loads: states.iter().map(|s| Load::gravity(s, g)).collect(),
            inverses: Inverses::new(&states),
            open_walls: (0..n.div_ceil(CHUNK)).map(|_| Vec::new()).collect(),
            walled: vec![false; n],
            states,
        }
    }
}

impl Deferred {
    /// No kick owed yet, every particle visited by the first wall pass, and the bounds
    /// on what an owed kick can add: gravity on the heaviest particle and the largest
    /// 1/m or 1/I.
    fn new(bodies: &Bodies, settings: &Settings) -> Deferred {
        let n = bodies.states.len();
        // The largest, or not a number if any is (then no kick is owed unchecked).
        let largest = |a: f64, b: f64| {
            if a.is_nan() || b.is_nan() {
                f64::NAN
            } else {
                a.max(b)
            }
        };
        let heaviest = (bodies.states.iter())
            .map(|s| s.particle.mass)
            .fold(0.0, largest);
        Deferred {
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
            gravity_bound: settings.gravity.abs().sum() * heaviest,
            largest_inverse: (bodies.inverses.iter())
                .map(|i| largest(i.0, i.1))
                .fold(0.0, largest),
        }
    }
}

/// The reactive assemblies that can move (pkdgrav's `DEM_WALLS_REACT`, when the plan
/// has them), following pkdgrav's integrator when the run does; the warnings for walls'
/// masses a build ignores and for assemblies that cannot move.
fn set_up_assemblies(
    scene: &[Wall],
    settings: &Settings,
    plan: &Plan,
    warnings: &mut Vec<Warning>,
) -> Vec<Assembly> {
    let heavy: Vec<usize> = (0..scene.len())
        .filter(|&w| scene[w].reactive.is_heavy())
        .collect();
    if !heavy.is_empty() && !settings.build.walls_react {
        warnings.push(Warning::MassesIgnored { walls: heavy });
    }
    let mut assemblies = if plan.reactive {
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
    assemblies
}

/// The walls at the start of a run: their `materials` and the laws' constants worked out
/// once, their origins and where they stand, and the `assemblies` they belong to.
fn wall_set(
    scene: &[Wall],
    settings: &Settings,
    materials: Vec<Material>,
    assemblies: &[Assembly],
) -> WallSet {
    let origins = Origins::new(scene, settings.stepping, settings.t_start());
    let now = if settings.integrator == Integrator::Pkdgrav {
        origins.walls_pkdgrav(scene, settings.t_start())
    } else {
        origins.walls(scene, settings.t_start())
    };
    let mut assembly_of = vec![None; scene.len()];
    for (a, assembly) in assemblies.iter().enumerate() {
        for &w in &assembly.walls {
            assembly_of[w] = Some(a);
        }
    }
    WallSet {
        damping: (materials.iter())
            .map(|m| damping_per_root_mass(m.eps_n, m.k_n))
            .collect(),
        restitutions: (materials.iter())
            .map(|m| (Restitution::new(m.eps_n), Restitution::new(m.eps_t)))
            .collect(),
        materials,
        driven: (scene.iter())
            .map(|w| w.motion.oscillation.amplitude != 0.0 || w.motion.ang_speed != 0.0)
            .collect(),
        origins,
        now,
        assembly_of,
        cogs: Vec::with_capacity(assemblies.len()),
    }
}

/// The lists of what may touch at the start of a run, found where the particles
/// `states` and the `walls` stand: the candidate pairs (when the plan has particle
/// contacts) and the walls near each particle (through the wall index when the plan
/// uses one).
fn broad(
    scene: &[Wall],
    states: &mut [State],
    plan: &Plan,
    walls: &WallSet,
    renumber: bool,
) -> (Broad, Numbering) {
    let n = states.len();
    let mut candidates = PairList::new(
        states,
        plan.particle_contacts,
        in_parallel(n),
        n >= PARALLEL_FROM,
    );
    // The particles kept in the pair grid's order when they meet (an aggregate's
    // members, which name each other, keep the file's).
    let numbering = if renumber && candidates.wanted {
        Numbering::along(candidates.grid_order(states))
    } else {
        Numbering::default()
    };
    numbering.to_places(states);
    let states = &*states;
    let mut near = None;
    if !scene.is_empty() {
        let listed = walls.assembly_of.iter().map(Option::is_none).collect();
        let translating = scene.iter().map(|w| w.motion.translates()).collect();
        let index = plan.wall_index.then(|| WallIndex::new(scene));
        near = Some(NearWalls::new(listed, translating, index));
    }
    near::build_lists(&mut candidates, &mut near, (states, &numbering), &walls.now);
    (Broad { candidates, near }, numbering)
}

/// pkdgrav's aggregates of the particles (docs/pkdgrav-physics.md §9), when the run
/// follows them: an `AGGS` build with pkdgrav's integrator. Members without that get a
/// warning and run as free spheres; an aggregate of one member stops the run before it
/// starts (the second value), as pkdgrav aborts.
pub(super) fn set_up_aggregates(
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
        warnings.push(crate::run::aggregates_ignored(states, settings));
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
