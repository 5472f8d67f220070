//! What a run reports: the parts of the model it used, its outcome as JSON
//! (`walls-sim run --json`, in pkdgrav units) and its one-line summary for people (its
//! times in the units a [`Readout`] shows).

use crate::run::{ContactModel, EventKind, Outcome, Planning, Settings};
use nalgebra::Vector3;
use serde_json::{Value, json};
use walls_geometry::Particle;
use walls_geometry::Wall;
use walls_geometry::units::Readout;

/// The parts of the model a run used, for the JSON `model` field: the plan's (as the
/// run saw it), plus sticky and death walls when a particle met one.
pub fn model(scene: &[Wall], particles: &[Particle], settings: &Settings) -> Vec<&'static str> {
    let (_, parts) = crate::run::plan::parts(scene, particles, settings);
    let everything = settings.planning == Planning::Everything;
    let mut model = vec![match settings.method() {
        ContactModel::Ssdem => "ssdem: spring-dashpot",
        ContactModel::Hsdem => "hsdem: exact collision prediction",
    }];
    model.extend(
        parts
            .iter()
            .filter(|p| p.name != "pkdgrav build")
            .filter(|p| p.used || (everything && p.name != "reactive walls"))
            .map(|p| p.name),
    );
    model
}

/// The outcome as JSON: the time and steps, each particle's state, the wall events, the
/// particle contacts, the energy, the parts of the model used, the pkdgrav build, the
/// warnings, and why the run stopped early (`stopped`: null when it ran to its end).
pub fn json(scene: &[Wall], particles: &[Particle], settings: &Settings, out: &Outcome) -> Value {
    let kind = |k: EventKind| match k {
        EventKind::Bounce => "bounce",
        EventKind::Stick => "stick",
        EventKind::Remove => "remove",
    };
    let v3 = |v: &Vector3<f64>| json!([v.x, v.y, v.z]);
    json!({
        "t": out.t,
        "steps": out.steps,
        "particles": out.particles.iter().map(|s| json!({
            "pos": v3(&s.particle.pos),
            "vel": v3(&s.particle.vel),
            "spin": v3(&s.particle.spin),
            "alive": s.alive,
            "stuck_to": s.stuck_to.map(|(w, _)| w),
        })).collect::<Vec<_>>(),
        "events": out.events.iter().map(|e| json!({
            "t": e.t, "particle": e.particle, "wall": e.wall, "kind": kind(e.kind),
            "vn_in": e.vn_in, "vn_out": e.vn_out,
        })).collect::<Vec<_>>(),
        "pair_contacts": out.pair_contacts,
        "energy": {"initial": out.energy.0, "final": out.energy.1},
        "model": model(scene, particles, settings),
        "build": settings.build.names(),
        "warnings": out.warnings.iter().map(ToString::to_string).collect::<Vec<_>>(),
        "stopped": out.stopped.map(crate::run::Stop::code),
    })
}

/// One line for people: the time reached and the timestep (as `readout` shows times),
/// the steps, the particles, the events, the contacts and the energy.
pub fn summary(settings: &Settings, out: &Outcome, readout: &Readout) -> String {
    format!(
        "t = {} after {} steps of {}: {} particles ({} alive), {} wall events, {} particle contacts, energy {:.6e} → {:.6e}",
        readout.time(out.t),
        out.steps,
        readout.time(settings.dt),
        out.particles.len(),
        out.particles.iter().filter(|s| s.alive).count(),
        out.events.len(),
        out.pair_contacts,
        out.energy.0,
        out.energy.1
    )
}
