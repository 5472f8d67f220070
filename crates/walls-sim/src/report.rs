//! What a run reports: the parts of the model it used, its outcome as JSON
//! (`walls-sim run --json`, in pkdgrav units; a [`Report`] serialised as it is written)
//! and its one-line summary for people (its times in the units a [`Readout`] shows).

use crate::run::{
    ContactModel, Event, EventKind, LevelCounts, Outcome, Planning, Settings, State, Warning,
};
use serde::{Serialize, Serializer};
use walls_geometry::Particle;
use walls_geometry::Wall;
use walls_geometry::units::Readout;

/// The parts of the model a run used, for the JSON `model` field: the plan's (as the
/// run saw it), plus sticky and death walls when a particle met one.
pub fn model(
    scene: &[Wall],
    particles: &[impl AsRef<Particle>],
    settings: &Settings,
) -> Vec<&'static str> {
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

/// The outcome as `walls-sim run --json` writes it: the time and steps, each particle's
/// state, the wall events, the particle contacts, the overlap events past pkdgrav's
/// levels (`overlaps`: `pairs` and `walls`, each `minor`, `major`, `error`), the energy, the parts of the model used,
/// the pkdgrav build, the warnings, why the run stopped early (`stopped`: null when it ran
/// to its end; `"output"` when its outputs could not be written), and, when the run wrote
/// some, its output files (`outputs`) and, after a failed write, what failed and where the
/// outputs end (`output_error`).
///
/// It borrows the outcome and serialises it as it goes (`serde_json::to_writer_pretty`
/// into a buffered writer): a run of 10⁵ particles never holds its JSON whole. The keys
/// are in alphabetical order (the fields' order here), as serde_json's map wrote them.
#[derive(Serialize)]
pub struct Report<'a> {
    build: String,
    energy: Energy,
    events: Each<'a, Event, EventView>,
    model: Vec<&'static str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    output_error: Option<OutputError<'a>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    outputs: Option<&'a [String]>,
    overlaps: Overlaps,
    pair_contacts: u64,
    particles: Each<'a, State, StateView>,
    steps: u64,
    stopped: Option<&'static str>,
    t: f64,
    warnings: Each<'a, Warning, Shown<'a, Warning>>,
}

impl<'a> Report<'a> {
    /// The report of `out`, a run with `settings` that used the parts `model` (its
    /// [`model`], found before the run: the particles are the run's then).
    pub fn new(model: Vec<&'static str>, settings: &Settings, out: &'a Outcome) -> Report<'a> {
        Report {
            build: settings.build.names(),
            energy: Energy {
                final_: out.energy.1,
                initial: out.energy.0,
            },
            events: Each(&out.events, EventView::new),
            model,
            output_error: None,
            outputs: None,
            overlaps: Overlaps {
                pairs: Levels::new(&out.overlaps.pairs),
                walls: Levels::new(&out.overlaps.walls),
            },
            pair_contacts: out.pair_contacts,
            particles: Each(&out.particles, StateView::new),
            steps: out.steps,
            stopped: out.stopped.map(crate::run::Stop::code),
            t: out.t,
            warnings: Each(&out.warnings, Shown),
        }
    }

    /// The report with the files the run wrote (`outputs`).
    pub fn with_outputs(self, outputs: &'a [String]) -> Report<'a> {
        Report {
            outputs: Some(outputs),
            ..self
        }
    }

    /// The report of a run whose outputs could not be written (`error`): it stopped there.
    pub fn with_output_error(self, error: OutputError<'a>) -> Report<'a> {
        Report {
            output_error: Some(error),
            stopped: Some("output"),
            ..self
        }
    }

    /// Writes the report to `w` as indented JSON and a newline, as it is serialised;
    /// the first error of `w` ends it.
    pub fn write_json(&self, mut w: impl std::io::Write) -> std::io::Result<()> {
        serde_json::to_writer_pretty(&mut w, self)?;
        w.write_all(b"\n")
    }
}

/// Why a run's outputs could not be written: what failed, at which output step and time,
/// and the last output step every file holds whole (`null`: none).
#[derive(Serialize)]
pub struct OutputError<'a> {
    /// What could not be written, and why.
    pub message: &'a str,
    /// The output step being written.
    pub step: u64,
    /// Its time.
    pub t: f64,
    /// The last output step every file holds whole, and its time.
    pub whole_until: Option<(u64, f64)>,
}

/// The energy at the start and the end.
#[derive(Serialize)]
struct Energy {
    #[serde(rename = "final")]
    final_: f64,
    initial: f64,
}

/// The overlap events past pkdgrav's levels (`dMinorFrac`, `dMajorFrac`, `dErrorFrac`),
/// for pairs and for walls, as pkdgrav counts them.
#[derive(Serialize)]
struct Overlaps {
    pairs: Levels,
    walls: Levels,
}

/// The events at each level.
#[derive(Serialize)]
struct Levels {
    error: u64,
    major: u64,
    minor: u64,
}

impl Levels {
    fn new(c: &LevelCounts) -> Levels {
        Levels {
            error: c.error,
            major: c.major,
            minor: c.minor,
        }
    }
}

/// One wall event.
#[derive(Serialize)]
struct EventView {
    kind: &'static str,
    particle: usize,
    t: f64,
    vn_in: f64,
    vn_out: f64,
    wall: usize,
}

impl EventView {
    fn new(e: &Event) -> EventView {
        EventView {
            kind: match e.kind {
                EventKind::Bounce => "bounce",
                EventKind::Stick => "stick",
                EventKind::Remove => "remove",
            },
            particle: e.particle,
            t: e.t,
            vn_in: e.vn_in,
            vn_out: e.vn_out,
            wall: e.wall,
        }
    }
}

/// One particle at the end: vectors as three numbers, the sticky wall holding it.
#[derive(Serialize)]
struct StateView {
    alive: bool,
    pos: [f64; 3],
    spin: [f64; 3],
    stuck_to: Option<usize>,
    vel: [f64; 3],
}

impl StateView {
    fn new(s: &State) -> StateView {
        let p = &s.particle;
        StateView {
            alive: s.alive,
            pos: p.pos.into(),
            spin: p.spin.into(),
            stuck_to: s.stuck_to.as_deref().map(|&(w, _)| w),
            vel: p.vel.into(),
        }
    }
}

/// A list written item by item, each as `view` shows it: never built whole.
struct Each<'a, T, V>(&'a [T], fn(&'a T) -> V);

impl<'a, T, V: Serialize> Serialize for Each<'a, T, V> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_seq(self.0.iter().map(self.1))
    }
}

/// A value as the string it displays, written as it is formatted.
struct Shown<'a, T>(&'a T);

impl<T: std::fmt::Display> Serialize for Shown<'_, T> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_str(self.0)
    }
}

/// One line for people: the time reached and the timestep (as `readout` shows times),
/// the steps, the particles, the events, the contacts and the energy; and, when some
/// overlap passed one of pkdgrav's levels, how many did at each, for pairs and walls.
pub fn summary(settings: &Settings, out: &Outcome, readout: &Readout) -> String {
    let mut line = format!(
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
    );
    if !out.overlaps.is_empty() {
        let levels = |c: &LevelCounts| format!("{}/{}/{}", c.minor, c.major, c.error);
        line.push_str(&format!(
            "; overlaps past pkdgrav's levels (minor/major/error): pairs {}, walls {}",
            levels(&out.overlaps.pairs),
            levels(&out.overlaps.walls)
        ));
    }
    line
}
