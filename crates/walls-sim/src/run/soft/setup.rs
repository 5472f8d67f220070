//! The soft-sphere run's set-up ([`SoftStepper::new`]): the materials, the checks
//! before it, the walls, the assemblies that can move, pkdgrav's aggregates and the
//! candidate pairs.

use super::near::{self, NearWalls};
use super::pairs::{PairMaterial, PairPass};
use super::walls::{Closing, WallPass};
use super::{
    Bodies, Broad, CHUNK, Clock, ContactLaw, Deferred, Integrator, Journal, Kicks, Load, Materials,
    OverlapWarnings, PARALLEL_FROM, Rigid, Rules, Settings, SoftStepper, State, WallSet,
    WarnedOnce, Warning, assembly_energy, energy, in_parallel, inertia,
};
use crate::broad::pairs::PairList;
use crate::broad::wall_index::WallIndex;
use crate::contact::ssdem::{Restitution, damping_per_root_mass};
use crate::dynamics::aggregate::{self, Aggregates};
use crate::run::Origins;
use crate::run::optional::OptionalPhysics;
use crate::run::plan::Plan;
use walls_geometry::Wall;

impl<'a> SoftStepper<'a> {
    /// The run at its start: the materials, the checks before it ([`crate::run::stability`]),
    /// the walls, the assemblies that can move, the candidate pairs.
    pub(super) fn new(
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
        let reactive = plan.reactive;
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
        // drift or `super::drift::settle` after an owed kick, and for an aggregate's
        // members.
        let loads = states.iter().map(|s| Load::gravity(s, &g)).collect();
        let candidates = PairList::new(
            &states,
            plan.particle_contacts,
            in_parallel(n),
            n >= PARALLEL_FROM,
        );
        let mut warnings = Vec::new();
        let oscillating: Vec<bool> = scene
            .iter()
            .map(|w| w.motion.oscillation.amplitude != 0.0)
            .collect();
        warnings.extend(crate::run::stability::soft_warnings(
            scene, &states, settings,
        ));
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
        let mut near = None;
        if !scene.is_empty() {
            let listed = assembly_of.iter().map(Option::is_none).collect();
            let translating = scene.iter().map(|w| w.motion.translates()).collect();
            let index = plan.wall_index.then(|| WallIndex::new(scene));
            near = Some(NearWalls::new(listed, translating, index));
        }
        // Built once, with the walls near each particle when it keeps them.
        near::build_lists(&mut candidates, &mut near, &states, &now);
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
                (1.0 / p.mass, 1.0 / inertia(p.mass, p.radius))
            })
            .collect();
        let largest_inverse = (inverses.iter())
            .map(|i| largest(i.0, i.1))
            .fold(0.0, largest);
        let kicks = Kicks::of(settings.integrator);
        let contact = ContactLaw::of(settings, &kicks, plan, &optional);
        SoftStepper {
            rules: Rules {
                scene,
                settings,
                plan,
                kicks,
                contact,
                between: PairMaterial::new(between, &states),
                optional,
                parallel: in_parallel(n),
            },
            walls: WallSet {
                materials,
                damping,
                restitutions,
                oscillating,
                origins,
                now,
                assembly_of,
                cogs: Vec::with_capacity(assemblies.len()),
            },
            rigid: Rigid {
                assemblies,
                aggregates,
            },
            halted,
            deferred: Deferred {
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
                gravity_bound,
                largest_inverse,
            },
            bodies: Bodies {
                states,
                loads,
                inverses,
                open_walls: (0..n).map(|_| Vec::new()).collect(),
                walled: vec![false; n],
            },
            broad: Broad { candidates, near },
            pair_pass: PairPass::default(),
            wall_pass: WallPass::default(),
            initial,
            journal: Journal {
                events: Vec::new(),
                pair_contacts: 0,
                warnings,
                overlaps: OverlapWarnings::default(),
                once: WarnedOnce::default(),
            },
            clock: Clock {
                t: settings.t_start(),
                steps: settings.start_step,
            },
        }
    }
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
