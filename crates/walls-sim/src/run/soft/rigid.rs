//! The bodies of the soft-sphere run that move as wholes ([`Rigid`]): pkdgrav's
//! aggregates of particles (their opening kick and drift, their members placed, their
//! loads gathered and the closing kick) and the reactive assemblies of walls (their
//! kicks and drift, their walls placed, the particles' reactions summed).

use super::{Bodies, Flow, Journal, Rigid, Rules, State, Vec3, WallNow, WallPass, WallSet};
use crate::dynamics::euler_rigid::Failure;
use crate::dynamics::reactive::Assembly;
use crate::dynamics::rigid::RotationIntegrator;
use crate::warning::{Rigid as Body, Warning};
use walls_geometry::Wall;

/// pkdgrav's aggregates (docs/pkdgrav-physics.md §9.3): the opening half kick of each
/// centre, the drift (the rotation by Euler's equations, the centre with its half-step
/// velocity), and the members placed where it has taken them. The rotation's adaptive
/// integrator reaching its minimum step is warned of (once a run); its failing stops the
/// run ([`Flow::Stop`]), as pkdgrav exits (docs/pkdgrav-physics.md §17). `t` is the time
/// at the step's end.
pub(super) fn move_aggregates(
    rigid: &mut Rigid,
    states: &mut [State],
    journal: &mut Journal,
    rules: &Rules,
    t: f64,
) -> Flow {
    let Some(aggs) = rigid.aggregates.as_mut() else {
        return Flow::Continue;
    };
    let dt = rules.settings.dt;
    let mut flow = Flow::Continue;
    for a in &mut aggs.list {
        a.kick(0.5 * dt);
        let cost = a.advance(dt);
        a.place(states, dt);
        let body = Body::Aggregate(a.number);
        flow = flow.and(note_integration(journal, body, cost.floor, cost.failure, t));
    }
    flow
}

/// The warnings of one rigid body's adaptive integration over a step ending at `t`:
/// the first time a body's reaches its minimum step, and any failure, which stops the
/// run.
fn note_integration(
    journal: &mut Journal,
    body: Body,
    floor: bool,
    failure: Option<Failure>,
    t: f64,
) -> Flow {
    if floor && !journal.once.floor {
        journal.once.floor = true;
        journal.warnings.push(Warning::StepFloor { body, t });
    }
    match failure {
        Some(failure) => {
            journal
                .warnings
                .push(Warning::StepFailed { body, failure, t });
            Flow::Stop
        }
        None => Flow::Continue,
    }
}

/// Each aggregate's acceleration and torque from its members' loads
/// (docs/pkdgrav-physics.md §9.4), and, after a step's forces, its closing half kick.
pub(super) fn gather_aggregates(rigid: &mut Rigid, bodies: &Bodies, rules: &Rules, kick: bool) {
    let Some(aggs) = rigid.aggregates.as_mut() else {
        return;
    };
    let (g, dt) = (rules.settings.gravity, rules.settings.dt);
    let loads = &bodies.loads;
    for a in &mut aggs.list {
        a.gather(&bodies.states, |i| (loads[i].force, loads[i].torque), &g);
        if kick {
            a.kick(0.5 * dt);
        }
    }
}

/// Each assembly's half kick of momentum and angular momentum with the last step's
/// force and torque, its drift, and its free rotation over the step (kick-drift-kick as
/// for the particles); its walls are placed where it has taken them. With
/// [`super::Integrator::Pkdgrav`], pkdgrav's: the opening half kick of the velocity
/// alone, then [`Assembly::move_pkdgrav`] (docs/pkdgrav-physics.md §10). The rotation's
/// adaptive integrator is watched as the aggregates' is ([`move_aggregates`]).
pub(super) fn move_assemblies(
    rigid: &mut Rigid,
    walls: &mut WallSet,
    journal: &mut Journal,
    rules: &Rules,
    t: f64,
) -> Flow {
    let (g, dt) = (rules.settings.gravity, rules.settings.dt);
    let mut flow = Flow::Continue;
    for a in rigid.assemblies.iter_mut() {
        let body = Body::Assembly(a.number);
        if a.is_pkdgrav() {
            a.velocity += (a.force / a.mass + g) * (dt / 2.0);
            let cost = a.move_pkdgrav(dt);
            flow = flow.and(note_integration(journal, body, cost.floor, cost.failure, t));
            continue;
        }
        a.velocity += (a.force / a.mass + g) * (dt / 2.0);
        a.cog += a.velocity * dt;
        a.kick(dt / 2.0);
        let inertia = a.inertia;
        let steps = crate::dynamics::rigid::step(
            &mut a.rotation,
            &inertia,
            &Vec3::zeros(),
            dt,
            RotationIntegrator::AdaptiveRk,
        );
        flow = flow.and(note_integration(
            journal,
            body,
            steps.floor,
            steps.failure,
            t,
        ));
    }
    place_assemblies(&rigid.assemblies, walls, rules.scene);
    flow
}

/// Each assembly's walls placed where it has taken them, and its centre of gravity
/// noted.
pub(super) fn place_assemblies(assemblies: &[Assembly], walls: &mut WallSet, scene: &[Wall]) {
    for a in assemblies {
        for (k, &w) in a.walls.iter().enumerate() {
            walls.now[w] =
                WallNow::placed(a.cog, a.shape(&scene[w].shape, k), a.velocity, a.spin());
        }
    }
    walls.cogs.clear();
    walls.cogs.extend(assemblies.iter().map(|a| a.cog));
}

/// The particles' reactions on the assemblies, summed in the file's order, and the
/// assemblies' closing half kick.
pub(super) fn kick_assemblies(rigid: &mut Rigid, wall_pass: &WallPass, rules: &Rules) {
    let (g, dt) = (rules.settings.gravity, rules.settings.dt);
    sum_reactions(&mut rigid.assemblies, wall_pass);
    for a in rigid.assemblies.iter_mut() {
        a.velocity += (a.force / a.mass + g) * (dt / 2.0);
        if !a.is_pkdgrav() {
            a.kick(dt / 2.0);
        }
    }
}

/// The particles' reactions on the assemblies, summed in the file's order.
pub(super) fn sum_reactions(assemblies: &mut [Assembly], wall_pass: &WallPass) {
    for a in assemblies.iter_mut() {
        a.force = Vec3::zeros();
        a.torque = Vec3::zeros();
    }
    for (_, report) in wall_pass.reports.iter().flatten() {
        for (a, f, tq) in &report.reactions {
            assemblies[*a].force += f;
            assemblies[*a].torque += tq;
        }
    }
    for a in assemblies.iter_mut() {
        a.note_torque_body();
    }
}
