//! The hard-sphere run (HSDEM): kick-drift-kick as in pkdgrav, where each drift moves
//! particles in straight lines from one predicted collision to the next (docs/spec.md
//! §3).
//!
//! Within a step each wall translates at a constant velocity, the chord from where it
//! is at the start of the step to where it is at the end (for a wall moving at constant
//! velocity that is exact; an oscillating wall follows the sinusoid at the ends of every
//! step and straight lines between); its spin adds to the velocity a contact feels.
//! Collisions are processed in time order from a queue; each particle keeps its own
//! clock, and a particle's queued collision is dropped when it, or its partner, has
//! collided since (a version count per particle).
//!
//! Things the prediction cannot see are caught at the start of the next prediction: a
//! particle that overlaps a wall or another particle and is moving into it collides at
//! once. Particle pairs are candidates when their spheres, swollen by the distance each
//! travels in the step at its speed after the first kick, overlap ([`crate::broad::grid`]); a
//! collision that speeds a particle up beyond that can miss a pair within the step, and
//! is then caught as an overlap at the next.
//!
//! A particle colliding more than [`COLLISION_CAP`] times in one step is in inelastic
//! collapse (pkdgrav switches to other coefficients there): it is held where it is for
//! the rest of the step, and the run says so.
//!
//! The run is a [`HardStepper`]: set up once (with the warnings about walls the
//! hard-sphere code does not handle as given), then one method per stage of a step.

use super::{
    Event, EventKind, Materials, Observer, Origins, Outcome, PARALLEL_FROM, Settings, State,
    WallNow, Warning, carry, energy, turned,
};
use crate::broad::grid::CellGrid;
use crate::broad::wall_index::WallIndex;
use crate::contact::hsdem::{Body, COLLISION_CAP, bounce, pair_bounce};
use crate::contact::ssdem::Material;
use crate::run::plan::Plan;
use nalgebra::Vector3;
use rayon::prelude::*;
use std::cmp::Ordering;
use std::collections::BinaryHeap;
use walls_geometry::Feature;
use walls_geometry::impact::sphere_entry;
use walls_geometry::motion::Moving;
use walls_geometry::{Shape, Wall};

type Vec3 = Vector3<f64>;

/// A wall during one step: as it stands at the start, and its chord velocity.
struct WallStep {
    start: WallNow,
    chord: Vec3,
}

impl WallStep {
    /// Where the wall's origin is at `tau` into the step.
    fn origin(&self, tau: f64) -> Vec3 {
        self.start.origin + self.chord * tau
    }

    /// The velocity of the wall's material at `q`, at `tau` into the step: the wall
    /// moving along its chord, spinning as it stood at the start.
    fn point_velocity(&self, q: &Vec3, tau: f64) -> Vec3 {
        let moving = Moving {
            origin: self.origin(tau),
            velocity: self.chord,
            spin: self.start.spin,
        };
        moving.point_velocity(q)
    }
}

/// What a particle meets.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Partner {
    Wall(usize),
    Particle(usize),
}

/// A queued collision of particle `i`, valid while both versions are unchanged.
#[derive(Debug, Clone, Copy)]
struct Queued {
    tau: f64,
    i: usize,
    partner: Partner,
    version_i: u32,
    version_j: u32,
}

impl PartialEq for Queued {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}
impl Eq for Queued {}
impl PartialOrd for Queued {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for Queued {
    /// Earliest first in a max-heap; ties by particle for a deterministic order.
    fn cmp(&self, other: &Self) -> Ordering {
        other
            .tau
            .total_cmp(&self.tau)
            .then_with(|| other.i.cmp(&self.i))
    }
}

/// The state of one drift.
struct Drift<'a> {
    states: &'a mut [State],
    walls: &'a [WallStep],
    /// The wall index, when the plan uses one, and the walls' origins at the start of
    /// the step it is queried with.
    index: Option<&'a WallIndex>,
    start_origins: &'a [Vec3],
    usable: &'a [bool],
    materials: &'a [Material],
    between: Material,
    edges: bool,
    dt: f64,
    /// pkdgrav's carry of a particle that sticks within the step
    /// ([`Integrator::Pkdgrav`](super::Integrator::Pkdgrav)): the wall's travel over the
    /// whole step, added at its end (docs/pkdgrav-physics.md §6), not the travel after
    /// the impact.
    whole_step_carry: bool,
    /// Each particle's own clock within the step.
    clock: Vec<f64>,
    version: Vec<u32>,
    collisions: Vec<u32>,
    candidates: Candidates,
    queue: BinaryHeap<Queued>,
}

impl Drift<'_> {
    /// Whether particle `j` has hit the collision cap in this step: it stays where it is.
    fn held(&self, j: usize) -> bool {
        self.collisions[j] >= COLLISION_CAP
    }

    /// Whether particle `j` moves in this drift: alive and not held (a particle stuck
    /// to a wall moves with it).
    fn moves(&self, j: usize) -> bool {
        self.states[j].alive && !self.held(j)
    }

    /// Whether particle `j` is an obstacle of infinite mass to the others: stuck to a
    /// wall (pkdgrav's rule) or held.
    fn immovable(&self, j: usize) -> bool {
        self.states[j].stuck_to.is_some() || self.held(j)
    }

    /// The velocity of particle `j` in this drift.
    fn velocity(&self, j: usize) -> Vec3 {
        if self.moves(j) {
            self.states[j].particle.vel
        } else {
            Vec3::zeros()
        }
    }

    /// Where particle `j` is at `tau` into the step.
    fn position(&self, j: usize, tau: f64) -> Vec3 {
        self.states[j].particle.pos + self.velocity(j) * (tau - self.clock[j])
    }

    /// Moves particle `i` to `tau` into the step.
    fn advance(&mut self, i: usize, tau: f64) {
        self.states[i].particle.pos = self.position(i, tau);
        self.clock[i] = tau;
    }

    /// Particle `i` has become an obstacle (stuck to a wall, or held at the cap) and
    /// predicts nothing itself any more: its neighbours look again, from `tau`.
    fn alert_neighbours(&mut self, i: usize, tau: f64) {
        for k in self.candidates.neighbours[i].clone() {
            if self.states[k].free() && !self.held(k) {
                self.advance(k, tau);
                self.predict(k);
            }
        }
    }

    /// After particle `i` changed velocity: if it may now travel beyond the margin it
    /// was binned with, widens the margin and finds its candidates again (rare: margins
    /// allow for twice each particle's speed, so only a collision that more than doubles
    /// it does this), among the particles whose start lies within reach along x.
    fn widen(&mut self, i: usize) {
        let c = &mut self.candidates;
        let s = &self.states[i];
        let reach = (s.particle.pos - c.start[i]).norm()
            + s.particle.vel.norm() * (self.dt - self.clock[i]);
        if !s.alive || reach <= c.margin[i] {
            return;
        }
        c.margin[i] = reach;
        let span = s.particle.radius + reach + c.widest;
        let x = c.start[i].x;
        let start = &c.start;
        let by_x = c.by_x.get_or_insert_with(|| {
            let mut order: Vec<usize> = (0..start.len())
                .filter(|&k| start[k].x.is_finite())
                .collect();
            order.sort_by(|&a, &b| start[a].x.total_cmp(&start[b].x));
            order
        });
        let from = by_x.partition_point(|&k| start[k].x < x - span);
        for &k in &by_x[from..] {
            if c.start[k].x > x + span {
                break;
            }
            let near = (c.start[i] - c.start[k]).norm()
                < s.particle.radius + self.states[k].particle.radius + c.margin[i] + c.margin[k];
            if k != i && self.states[k].alive && near && !c.neighbours[i].contains(&k) {
                c.neighbours[i].push(k);
                c.neighbours[k].push(i);
            }
        }
        c.widest = c.widest.max(s.particle.radius + reach);
    }

    /// Queues the first collision of particle `i` from its clock on, if any in the step.
    fn predict(&mut self, i: usize) {
        if let Some(q) = self.prediction(i) {
            self.queue.push(q);
        }
    }

    /// The first collision of particle `i` from its clock on, if any in the step.
    fn prediction(&self, i: usize) -> Option<Queued> {
        if !self.states[i].free() || self.held(i) {
            return None;
        }
        let tau = self.clock[i];
        let left = self.dt - tau;
        let p = self.states[i].particle.clone();
        let mut best: Option<(f64, Partner)> = None;
        let mut consider = |t: f64, partner: Partner| {
            if best.is_none_or(|(b, _)| t < b) {
                best = Some((t, partner));
            }
        };
        let mut wall_check = |w: usize| {
            let wall = &self.walls[w];
            if !self.usable[w] {
                return;
            }
            // In the wall's frame at the start of the step.
            let here = p.pos - wall.chord * tau;
            let d = p.vel - wall.chord;
            let near = wall.start.shape.nearest(&here);
            let counts = self.edges || matches!(near.feature, Feature::Face | Feature::Side);
            if counts && near.distance <= p.radius {
                let v = wall.point_velocity(&(near.point + wall.chord * tau), tau);
                if near.normal.dot(&(p.vel - v)) < 0.0 {
                    consider(0.0, Partner::Wall(w));
                    return;
                }
            }
            // Too far to reach the wall within the step: its distance falls at most at
            // the relative speed.
            if near.distance > p.radius + d.norm() * left {
                return;
            }
            if let Some(hit) = wall
                .start
                .shape
                .first_hit(&here, &d, p.radius, left, self.edges)
            {
                consider(hit.t, Partner::Wall(w));
            }
        };
        match self.index {
            // Walls moving alike share a chord: one query per group, with its point and
            // reach in that frame (the same test as the skip above, so the same walls).
            Some(index) => index.for_each_candidate_by_group(
                self.start_origins,
                |g| {
                    let c = self.walls[g].chord;
                    (p.pos - c * tau, p.radius + (p.vel - c).norm() * left)
                },
                &mut wall_check,
            ),
            None => (0..self.walls.len()).for_each(&mut wall_check),
        }
        for &j in &self.candidates.neighbours[i] {
            if !self.states[j].alive {
                continue;
            }
            let a = p.pos - self.position(j, tau);
            let b = p.vel - self.velocity(j);
            let s = p.radius + self.states[j].particle.radius;
            if a.norm() <= s && a.dot(&b) < 0.0 {
                consider(0.0, Partner::Particle(j));
            } else if let Some(t) = sphere_entry(&a, &b, s).filter(|t| *t <= left) {
                consider(t, Partner::Particle(j));
            }
        }
        let (t, partner) = best?;
        let version_j = match partner {
            Partner::Particle(j) => self.version[j],
            Partner::Wall(_) => 0,
        };
        Some(Queued {
            tau: tau + t,
            i,
            partner,
            version_i: self.version[i],
            version_j,
        })
    }
}

/// What happened in one drift.
#[derive(Default)]
struct DriftReport {
    events: Vec<Event>,
    pair_collisions: u64,
    collapsed: Vec<usize>,
}

/// Moves the free particles over one step from collision to collision.
fn drift(d: &mut Drift, t0: f64) -> DriftReport {
    let mut report = DriftReport::default();
    // The first predictions are most of the work when collisions are rare: in parallel
    // for many particles, queued in particle order.
    let first: Vec<Option<Queued>> = if d.states.len() >= PARALLEL_FROM {
        (0..d.states.len())
            .into_par_iter()
            .map(|i| d.prediction(i))
            .collect()
    } else {
        (0..d.states.len()).map(|i| d.prediction(i)).collect()
    };
    d.queue.extend(first.into_iter().flatten());
    while let Some(q) = d.queue.pop() {
        let i = q.i;
        if q.version_i != d.version[i] {
            continue;
        }
        if let Partner::Particle(j) = q.partner
            && q.version_j != d.version[j]
        {
            // The partner moved on: look again from now.
            d.advance(i, q.tau);
            d.predict(i);
            continue;
        }
        d.advance(i, q.tau);
        d.version[i] += 1;
        d.collisions[i] += 1;
        match q.partner {
            Partner::Wall(w) => {
                report.events.push(wall_collision(d, i, w, q.tau, t0));
                if d.states[i].stuck_to.is_some() {
                    d.alert_neighbours(i, q.tau);
                }
            }
            Partner::Particle(j) => {
                d.advance(j, q.tau);
                pair_collision(d, i, j);
                report.pair_collisions += 1;
                if !d.immovable(j) {
                    d.version[j] += 1;
                    d.collisions[j] += 1;
                    if d.collisions[j] == COLLISION_CAP {
                        report.collapsed.push(j);
                        d.alert_neighbours(j, q.tau);
                    }
                    d.widen(j);
                    d.predict(j);
                }
            }
        }
        if d.collisions[i] == COLLISION_CAP {
            report.collapsed.push(i);
            d.alert_neighbours(i, q.tau);
        }
        d.widen(i);
        d.predict(i);
    }
    for i in 0..d.states.len() {
        d.advance(i, d.dt);
    }
    report
}

/// Particle `i` meets wall `w` at `tau` into the step that began at `t0`: a bounce, a
/// stick or a removal.
fn wall_collision(d: &mut Drift, i: usize, w: usize, tau: f64, t0: f64) -> Event {
    let whole_step_carry = d.whole_step_carry;
    let wall = &d.walls[w];
    let s = &mut d.states[i];
    let p = &s.particle;
    let near = wall.start.shape.nearest(&(p.pos - wall.chord * tau));
    let point = near.point + wall.chord * tau;
    let n = near.normal;
    let wall_v = wall.point_velocity(&point, tau);
    let contact_v = p.vel + p.spin.cross(&(-n * p.radius)) - wall_v;
    let vn_in = -n.dot(&contact_v);
    let mat = &d.materials[w];
    let kind = if mat.eps_n < 0.0 {
        s.alive = false;
        EventKind::Remove
    } else if mat.eps_n == 0.0 {
        let offset = if whole_step_carry {
            // pkdgrav's: held where it touched, then carried at the end of the step by
            // the wall's whole step of travel and turn, as if it had been held from the
            // step's start (docs/pkdgrav-physics.md §6).
            p.pos - wall.start.origin
        } else {
            // Held from τ on: the carry at the end of the step turns it by the wall's
            // spin over the whole step, so start it turned back by τ's worth.
            turned(&wall.start.spin, -tau, p.pos - wall.origin(tau))
        };
        s.stuck_to = Some(Box::new((w, offset)));
        s.particle.vel = wall_v;
        s.particle.spin = wall.start.spin;
        EventKind::Stick
    } else {
        let b = bounce(p.radius, &p.vel, &p.spin, &wall_v, &n, mat.eps_n, mat.eps_t);
        s.particle.vel = b.velocity;
        s.particle.spin = b.spin;
        EventKind::Bounce
    };
    let vn_out = match kind {
        EventKind::Bounce => n.dot(&(s.particle.vel - wall_v)),
        _ => 0.0,
    };
    Event {
        t: t0 + tau,
        particle: i,
        wall: w,
        kind,
        vn_in,
        vn_out,
    }
}

/// Particles `i` and `j`, both at the same clock, collide.
fn pair_collision(d: &mut Drift, i: usize, j: usize) {
    let body = |s: &State| Body {
        mass: s.particle.mass,
        radius: s.particle.radius,
        velocity: s.particle.vel,
        spin: s.particle.spin,
    };
    let a = body(&d.states[i]);
    let mut b = body(&d.states[j]);
    b.velocity = d.velocity(j);
    if d.immovable(j) {
        b.mass = f64::INFINITY;
    }
    let n = (d.states[i].particle.pos - d.states[j].particle.pos)
        .try_normalize(0.0)
        .unwrap_or_else(Vec3::z);
    let (ba, bb) = pair_bounce(&a, &b, &n, d.between.eps_n, d.between.eps_t);
    d.states[i].particle.vel = ba.velocity;
    d.states[i].particle.spin = ba.spin;
    if !d.immovable(j) {
        d.states[j].particle.vel = bb.velocity;
        d.states[j].particle.spin = bb.spin;
    }
}

/// A hard-sphere run as it goes: the particles, where the walls are, and what the run
/// has seen so far. A step is [`HardStepper::step`]: the opening kick, the walls' chords
/// over the step, the drift from collision to collision, the closing kick.
struct HardStepper<'a> {
    scene: &'a [Wall],
    settings: &'a Settings,
    plan: &'a Plan,
    states: Vec<State>,
    /// Each wall's material, with the particles' values where it says so.
    materials: Vec<Material>,
    /// The particles' material, for their collisions with each other.
    between: Material,
    origins: Origins,
    /// The wall index, when the plan uses one.
    index: Option<WallIndex>,
    /// Whether pkdgrav's hard-sphere code supports each wall (particles pass through the
    /// others).
    usable: Vec<bool>,
    /// The energy at the start.
    initial: f64,
    events: Vec<Event>,
    pair_contacts: u64,
    warnings: Vec<Warning>,
    /// Whether the collision cap has been reported (once a run).
    collapse_warned: bool,
    t: f64,
    steps: u64,
}

impl<'a> HardStepper<'a> {
    /// The run at its start: the materials, the walls' origins and index, and the
    /// warnings about walls the hard-sphere code does not handle as given.
    fn new(
        scene: &'a [Wall],
        states: Vec<State>,
        settings: &'a Settings,
        plan: &'a Plan,
    ) -> HardStepper<'a> {
        let Materials {
            walls: materials,
            between,
        } = Materials::new(scene, &settings.material);
        let mut warnings = Vec::new();
        if states
            .iter()
            .any(|s| crate::dynamics::aggregate::aggregate_of(&s.particle).is_some())
        {
            warnings.push(super::aggregates_ignored(&states, settings));
        }
        let origins = Origins::new(scene, settings.stepping, settings.t_start());
        let index = plan.wall_index.then(|| WallIndex::new(scene));
        let usable: Vec<bool> = origins
            .walls(scene, settings.t_start())
            .iter()
            .map(|w| w.shape.hard_sphere_supported())
            .collect();
        for (w, wall) in scene.iter().enumerate() {
            if !usable[w] {
                warnings.push(Warning::UnsupportedWall {
                    wall: w,
                    wall_type: wall.shape.wall_type(),
                    taper: matches!(&wall.shape, Shape::FiniteCylinder(c) if c.taper != 0.0),
                });
            }
        }
        let literal: Vec<usize> = scene
            .iter()
            .enumerate()
            .filter(|(_, w)| w.material.restitution_falls_back())
            .map(|(i, _)| i)
            .collect();
        if !literal.is_empty() {
            warnings.push(Warning::RestitutionAt99 { walls: literal });
        }
        let initial = energy(&states, &settings.gravity);
        HardStepper {
            scene,
            settings,
            plan,
            states,
            materials,
            between,
            origins,
            index,
            usable,
            initial,
            events: Vec::new(),
            pair_contacts: 0,
            warnings,
            collapse_warned: false,
            t: settings.t_start(),
            steps: settings.start_step,
        }
    }

    /// Whether another step is due before the end.
    fn running(&self) -> bool {
        self.settings.due(self.steps)
    }

    /// One step: kick, drift from collision to collision, kick.
    fn step(&mut self) {
        self.opening_kick();
        let walls = self.walls_over_step();
        self.drift(&walls);
        self.closing_kick();
    }

    /// Half a kick of gravity for the free particles.
    fn opening_kick(&mut self) {
        let (g, dt) = (self.settings.gravity, self.settings.dt);
        for s in self.states.iter_mut().filter(|s| s.free()) {
            s.particle.vel += g * (dt / 2.0);
        }
    }

    /// The walls over the step: as they stand at its start, each with the chord to where
    /// it is at its end (the origins are moved on to there).
    fn walls_over_step(&mut self) -> Vec<WallStep> {
        let dt = self.settings.dt;
        let start = self.origins.walls(self.scene, self.t);
        if self.plan.moving_walls {
            self.origins.advance(self.scene, self.t, dt);
        }
        start
            .into_iter()
            .zip(&self.origins.now)
            .map(|(start, end)| {
                let chord = (end - start.origin) / dt;
                WallStep {
                    start,
                    chord: if chord.iter().all(|x| x.is_finite()) {
                        chord
                    } else {
                        Vec3::zeros()
                    },
                }
            })
            .collect()
    }

    /// Moves the particles over the step from collision to collision against `walls`,
    /// noting the events, the pair collisions and the first collision cap.
    fn drift(&mut self, walls: &[WallStep]) {
        let (dt, n) = (self.settings.dt, self.states.len());
        let candidates = Candidates::new(&self.states, dt, self.plan.particle_contacts && n > 1);
        let start_origins: Vec<Vec3> = walls.iter().map(|w| w.start.origin).collect();
        let mut d = Drift {
            states: &mut self.states,
            walls,
            index: self.index.as_ref(),
            start_origins: &start_origins,
            usable: &self.usable,
            materials: &self.materials,
            between: self.between,
            edges: self.plan.edges,
            dt,
            whole_step_carry: self.settings.integrator == super::Integrator::Pkdgrav,
            clock: vec![0.0; n],
            version: vec![0; n],
            collisions: vec![0; n],
            candidates,
            queue: BinaryHeap::new(),
        };
        let report = drift(&mut d, self.t);
        self.pair_contacts += report.pair_collisions;
        self.events.extend(report.events);
        if let Some(&i) = report.collapsed.first()
            && !self.collapse_warned
        {
            self.collapse_warned = true;
            self.warnings.push(Warning::CollisionCap {
                particle: i,
                t: self.t,
            });
        }
    }

    /// The end of the step: the clock moves on, the free particles get the second half
    /// kick of gravity, and those held by sticky walls move with them.
    fn closing_kick(&mut self) {
        let (g, dt) = (self.settings.gravity, self.settings.dt);
        self.steps += 1;
        self.t = self.settings.next_time(self.t, self.steps);
        for s in self.states.iter_mut() {
            if s.free() {
                s.particle.vel += g * (dt / 2.0);
            } else if s.alive
                && let Some(&(w, _)) = s.stuck_to.as_deref()
            {
                carry(
                    s,
                    &WallNow::new(&self.scene[w], self.origins.now[w], self.t),
                    dt,
                );
            }
        }
    }

    /// What the run came to, and why it `stopped` early.
    fn outcome(self, stopped: Option<super::Stop>) -> Outcome {
        let last = energy(&self.states, &self.settings.gravity);
        Outcome {
            t: self.t,
            steps: self.steps - self.settings.start_step,
            particles: self.states,
            events: self.events,
            assemblies: Vec::new(),
            pair_contacts: self.pair_contacts,
            overlaps: Default::default(),
            energy: (self.initial, last),
            warnings: self.warnings,
            stopped,
        }
    }
}

pub(super) fn run(
    scene: &[Wall],
    states: Vec<State>,
    settings: &Settings,
    plan: &Plan,
    observe: Observer,
    interrupted: super::Interrupted,
) -> Outcome {
    let mut run = HardStepper::new(scene, states, settings, plan);
    while run.running() {
        run.step();
        // As in the soft-sphere run: a step whose numbers overflowed is not observed.
        let not_finite = super::first_not_finite(&run.states);
        if not_finite.is_none() {
            observe(run.steps, run.t, &mut super::Settled(&run.states, &[]));
        }
        if let Some(stop) = super::halt_at(not_finite, interrupted) {
            return run.outcome(Some(stop));
        }
    }
    run.outcome(None)
}

/// The particles each particle could meet within a step: those whose spheres, swollen
/// by a margin of twice the distance each travels in the step at its speed after the
/// first kick, overlap at the start.
struct Candidates {
    neighbours: Vec<Vec<usize>>,
    start: Vec<Vec3>,
    margin: Vec<f64>,
    /// The particles in order of their start's x, for finding candidates again; sorted
    /// the first time it is needed in a step.
    by_x: Option<Vec<usize>>,
    /// The largest radius plus margin.
    widest: f64,
}

impl Candidates {
    /// The candidates of the particles still in; none when particles do not meet each
    /// other.
    fn new(states: &[State], dt: f64, meet: bool) -> Candidates {
        let n = states.len();
        let start: Vec<Vec3> = states.iter().map(|s| s.particle.pos).collect();
        let margin: Vec<f64> = states
            .iter()
            .map(|s| 2.0 * s.particle.vel.norm() * dt)
            .collect();
        let mut neighbours = vec![Vec::new(); n];
        if meet {
            let grid = CellGrid::from_fn(n, |i| {
                let s = &states[i];
                s.alive
                    .then_some((s.particle.pos, s.particle.radius + margin[i]))
            });
            grid.for_each_pair(|i, j| {
                neighbours[i].push(j);
                neighbours[j].push(i);
            });
        }
        let widest = states
            .iter()
            .zip(&margin)
            .map(|(s, m)| s.particle.radius + m)
            .fold(0.0, f64::max);
        Candidates {
            neighbours,
            start,
            margin,
            by_x: None,
            widest,
        }
    }
}
