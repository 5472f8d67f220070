//! Checks made before a run of where its methods would fail (docs/stability.md): a
//! soft-sphere timestep above the stability limit of the stiffest contact, or too
//! coarse to resolve it, and walls that move too far in a step for the particles.
//! During the run, [`super::soft`] adds what only shows then: a contact that gains
//! energy, a particle that moves more than its radius in a step. Each is a coded
//! [`Warning`] (`W2xx` here).

use super::{Materials, Settings, State, Stiffest, Warning};
use walls_geometry::Wall;

/// The worst relative rebound error per step of coarseness: measured worst cases over
/// the phases of a step are about 1.2/N at N steps per contact for the leapfrog
/// (docs/accuracy.md, chart `accuracy_restitution`).
const REBOUND_ERROR_TIMES_STEPS: f64 = 1.2;

/// The relative rebound error expected of a contact of angular frequency `omega`
/// (ω₀ = √(k_n/m)) stepped by `dt`: 1.2/N for N = π/(ω₀·dt) steps per contact.
pub(super) fn rebound_error(omega: f64, dt: f64) -> f64 {
    REBOUND_ERROR_TIMES_STEPS * omega * dt / std::f64::consts::PI
}

/// The most of the smallest radius a wall may move in a step (or one jump of its `step`)
/// before W203 (and walls-lint's R005) warns: speed × step ≪ particle size
/// (docs/stability.md).
pub const WALL_TRAVEL_FRACTION: f64 = 0.1;

/// Warnings about a soft-sphere run of `states` against `scene` before it starts.
pub(super) fn soft_warnings(scene: &[Wall], states: &[State], settings: &Settings) -> Vec<Warning> {
    let mut out = Vec::new();
    let dt = settings.dt;
    let lightest = states
        .iter()
        .map(|s| s.particle.mass)
        .fold(f64::INFINITY, f64::min);
    if !lightest.is_finite() {
        return out;
    }
    // The stiffest contact: against each wall the mass is the particle's; between two
    // of the lightest particles it is half.
    let materials = Materials::new(scene, &settings.material);
    let mut stiffest: Option<(f64, Stiffest)> = None;
    let mut consider = |omega: f64, what: Stiffest| {
        if stiffest.as_ref().is_none_or(|(o, _)| omega > *o) {
            stiffest = Some((omega, what));
        }
    };
    for (w, m) in materials.walls.iter().enumerate() {
        consider(
            (m.k_n / lightest).sqrt(),
            Stiffest::Wall {
                wall: w,
                k_n: m.k_n,
            },
        );
    }
    if settings.particle_contacts && states.len() > 1 {
        let k = materials.between.k_n;
        consider((2.0 * k / lightest).sqrt(), Stiffest::Pairs { k_n: k });
    }
    if let Some((omega, what)) = stiffest {
        let limit = 2.0 / omega;
        let steps = std::f64::consts::PI / omega / dt;
        if dt >= limit {
            out.push(Warning::AboveStabilityLimit {
                dt,
                limit,
                stiffest: what,
            });
        } else if steps < crate::advise::MIN_STEPS_PER_CONTACT {
            out.push(Warning::FewStepsPerContact {
                steps,
                error_percent: 100.0 * rebound_error(omega, dt),
                stiffest: what,
            });
        }
    }
    if let Some(warning) = wall_speed_warning(scene, states, dt) {
        out.push(warning);
    }
    out
}

/// How far each wall's surface can move in one step (or in one jump of its `step`),
/// against the smallest particle: more than a tenth of its radius and a contact can
/// start deep or be skipped (the document: speed × step ≪ particle size).
fn wall_speed_warning(scene: &[Wall], states: &[State], dt: f64) -> Option<Warning> {
    let smallest = states
        .iter()
        .map(|s| s.particle.radius)
        .fold(f64::INFINITY, f64::min);
    scene.iter().enumerate().find_map(|(w, wall)| {
        let speed = wall.motion.top_speed();
        let interval = wall.motion.step.max(dt);
        let travel = speed * interval;
        (travel > WALL_TRAVEL_FRACTION * smallest).then_some(Warning::WallTooFast {
            wall: w,
            travel,
            smallest,
        })
    })
}
