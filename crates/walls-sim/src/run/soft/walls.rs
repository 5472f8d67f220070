//! The wall pass of the soft-sphere run ([`SoftStepper::wall_contacts`]): each
//! particle's contacts with the walls it may touch, added to its load, then its closing
//! kick; and what they did, noted in particle order
//! ([`SoftStepper::note_wall_contacts`]).

use super::near::NearWalls;
use super::{
    CHUNK, Event, EventKind, Flow, Law, Load, Overlapping, SoftStepper, State, Vec3, WallNow,
    Warning, carry, inertia,
};
use crate::broad::wall_index::WallIndex;
use crate::contact::ssdem::{
    ConstantTorque, Dashpot, Material, Optional, Record, Restitution, Rolling, Sliding, Touch,
    contact, contact_radius, dashpot_contact_with, lever_contact_radius, normal_contact,
    resistance,
};
use crate::dynamics::aggregate::{self, Aggregates};
use crate::run::optional::OptionalPhysics;
use crate::run::plan::Plan;
use rayon::prelude::*;

/// An open wall contact: its springs (the tangential spring alone, but with
/// [`crate::run::Integrator::Pkdgrav`] every spring pkdgrav keeps) and the normal speed it began
/// with.
pub(super) struct Open {
    record: Record,
    vn_in: f64,
}

/// The walls as they stand in a step, with their materials, and the step: what every
/// particle's wall contacts share.
pub(super) struct Walls<'a> {
    now: &'a [WallNow],
    /// Each wall's reactive assembly, if any.
    assembly_of: &'a [Option<usize>],
    /// Each assembly's centre of gravity now.
    cogs: &'a [Vec3],
    /// Each wall's origin now, for the wall index.
    origins: &'a [Vec3],
    /// The wall index, when the plan uses one.
    index: Option<&'a WallIndex>,
    /// Without a wall index, the fixed walls near each particle and the walls that
    /// move ([`NearWalls`]).
    near: Option<&'a NearWalls>,
    plan: &'a Plan,
    /// Each wall's normal damping over √m, worked out once.
    damping: &'a [f64],
    /// Each wall's normal and tangential restitutions, worked out once.
    restitutions: &'a [(Restitution, Restitution)],
    materials: &'a [Material],
    /// The fraction of a step the kick after the forces covers.
    closing_kick: f64,
    /// The fraction of a step by which contact velocities are predicted ahead with the
    /// last acceleration (pkdgrav's dashpot velocity: ½).
    predict: f64,
    /// The fraction of a step by which spins are predicted ahead with the last angular
    /// acceleration.
    predict_spin: f64,
    /// Whether the lever of the contact velocity and of the tangential force is
    /// pkdgrav's r − x (else the radius), with pkdgrav's contact law.
    pkdgrav_levers: bool,
    /// The contact law.
    law: Law,
    /// pkdgrav's rolling radius is the contact radius (`bUseContactRadius`).
    contact_radius: bool,
    /// A build without `DEM_ROTATION_DASHPOT`: rolling and twisting are constant
    /// torques (docs/pkdgrav-physics.md §1.6), the rolling lever d with `bUseLegacyRoll`
    /// (the value).
    constant_torque: Option<bool>,
    /// pkdgrav's `dAccCrit` (0: off).
    acc_crit: f64,
    /// What the shear spring of a sliding contact does.
    sliding: Sliding,
    /// Cohesion and two-layer contacts (pkdgrav's optional builds).
    optional: &'a OptionalPhysics,
    /// The time at the step's end, and the timestep.
    t: f64,
    dt: f64,
    /// pkdgrav's aggregates, if any (for their members' rolling pseudo-forces).
    aggregates: Option<&'a Aggregates>,
}

/// What one particle's wall contacts did in a step.
#[derive(Default)]
pub(super) struct ParticleStep {
    pub(super) events: Vec<Event>,
    /// The deepest overlap, as a fraction of the radius, and its wall.
    pub(super) deepest: Option<(f64, usize)>,
    pub(super) touching: usize,
    /// Radii moved in the step, when more than one: it may skip through a wall.
    pub(super) too_fast: Option<f64>,
    /// The reactions on reactive walls' assemblies: (assembly, force, torque about its
    /// centre of gravity).
    pub(super) reactions: Vec<(usize, Vec3, Vec3)>,
    /// Its position, velocity or spin is no longer finite.
    pub(super) not_finite: bool,
}

impl ParticleStep {
    /// Whether there is nothing to note (the particle touched no wall and is well).
    pub(super) fn is_empty(&self) -> bool {
        self.events.is_empty()
            && self.deepest.is_none()
            && self.touching == 0
            && self.too_fast.is_none()
            && self.reactions.is_empty()
            && !self.not_finite
    }
}

/// What the wall pass works on for one particle besides its state: its load, its 1/m and
/// 1/I, its open wall contacts (wall, contact), and its chunk's scratch list of the
/// walls to visit.
pub(super) struct WallWork<'a> {
    load: &'a mut Load,
    /// 1/m and 1/I.
    inverse: (f64, f64),
    open: &'a mut Vec<(usize, Open)>,
    visit: &'a mut Vec<usize>,
}

/// One particle's contacts with the walls at the step's time, added to its load (which
/// holds gravity and the particle contacts already), then the closing kick.
pub(super) fn wall_step(
    i: usize,
    s: &mut State,
    mut work: WallWork,
    walls: &Walls,
) -> ParticleStep {
    let dt = walls.dt;
    let mut out = ParticleStep::default();
    if !s.alive {
        return out;
    }
    if let Some(&(w, _)) = s.stuck_to.as_deref() {
        // pkdgrav carries a stuck particle with its wall's move, before the forces
        // (docs/pkdgrav-physics.md §6; `SoftStepper::carry_stuck`).
        if !walls.pkdgrav_levers {
            carry(s, &walls.now[w], dt);
        }
        return out;
    }
    let r = s.particle.radius;
    let moved = s.particle.vel.norm_squared() * dt * dt;
    if moved > r * r {
        out.too_fast = Some(moved.sqrt() / r);
    }
    if !clear_of_walls(i, s, work.open, walls) && touch_walls(i, s, &mut work, walls, &mut out) {
        return out;
    }
    if s.member {
        // Its aggregate takes the load (`SoftStepper::gather_aggregates`).
        return out;
    }
    close_step(s, work.load, work.inverse, walls.closing());
    out
}

/// The closing kick of a step, as [`close_step`] gives it: the timestep, the fraction of
/// it the kick covers, and pkdgrav's `dAccCrit`.
#[derive(Clone, Copy)]
pub(super) struct Closing {
    pub(super) dt: f64,
    pub(super) fraction: f64,
    pub(super) acc_crit: f64,
}

impl Walls<'_> {
    /// This step's closing kick.
    pub(super) fn closing(&self) -> Closing {
        Closing {
            dt: self.dt,
            fraction: self.closing_kick,
            acc_crit: self.acc_crit,
        }
    }
}

/// Whether particle `i` (state `s`) touches no wall and cannot: no contact open, and
/// every wall near it surely out of its reach ([`walls_geometry::shape::Cull::clear_of`], the test
/// [`touch_walls`] makes first): nothing to look at. Most particles near a wall are not
/// touching it.
#[inline]
pub(super) fn clear_of_walls(i: usize, s: &State, open: &[(usize, Open)], walls: &Walls) -> bool {
    walls.index.is_none()
        && open.is_empty()
        && clear_of_near(i, &s.particle.pos, s.particle.radius, walls.near, walls.now)
}

/// [`clear_of_walls`] for particle `i` (at `pos`, of radius `r`) without a wall index
/// and with no contact open: its near walls (`near`, as they stand: `now`) all surely
/// out of its reach, and none moving.
#[inline(always)]
pub(super) fn clear_of_near(
    i: usize,
    pos: &Vec3,
    r: f64,
    near: Option<&NearWalls>,
    now: &[WallNow],
) -> bool {
    let Some(near) = near else {
        return true;
    };
    if !near.moving.is_empty() {
        return false;
    }
    // A plain loop (most particles have no wall near, some one or two).
    for &w in near.listed_of(i) {
        if !now[w].cull.clear_of(pos, r) {
            return false;
        }
    }
    true
}

/// [`wall_step`] for a free particle clear of every wall but not owed its kick (it moved
/// far in the step, say): the closing kick alone, and a report only if there is
/// something to note.
#[inline(always)]
pub(super) fn clear_step(
    s: &mut State,
    load: &Load,
    inverse: (f64, f64),
    walls: &Walls,
) -> Option<ParticleStep> {
    let r = s.particle.radius;
    let moved = s.particle.vel.norm_squared() * walls.dt * walls.dt;
    let motion = close_step(s, load, inverse, walls.closing());
    let too_fast = (moved > r * r).then(|| moved.sqrt() / r);
    let not_finite = !s.finite_with(motion);
    (too_fast.is_some() || not_finite).then(|| ParticleStep {
        too_fast,
        not_finite,
        ..ParticleStep::default()
    })
}

/// The accelerations of a free particle from its load, pkdgrav's `dAccCrit`, and the
/// kick after the forces; the sum of the new velocity's and spin's components, for
/// [`State::finite_with`] (from registers: reading back what was just stored, in wider
/// loads than it was stored with, stalls the processor). The drift gives an owed kick
/// with the same arithmetic ([`SoftStepper::kick_drift`]): a change here is a change
/// there, or a run would differ with whether its kicks are owed.
#[inline(always)]
pub(super) fn close_step(s: &mut State, load: &Load, inverse: (f64, f64), kick: Closing) -> f64 {
    let Closing {
        dt,
        fraction,
        acc_crit,
    } = kick;
    s.acc = load.force * inverse.0;
    s.alpha = load.torque * inverse.1;
    if acc_crit > 0.0 {
        zero_small_motions(s, acc_crit, dt);
    }
    let vel = s.particle.vel + s.acc * (dt * fraction);
    let spin = s.particle.spin + s.alpha * (dt * fraction);
    s.particle.vel = vel;
    s.particle.spin = spin;
    vel.sum() + spin.sum()
}

/// Particle `i`'s contacts with the walls it may touch, added to its load (its open
/// contacts opened and closed); what they did goes into `out`. Whether the particle was
/// held or removed by a wall (its step ends there).
pub(super) fn touch_walls(
    i: usize,
    s: &mut State,
    work: &mut WallWork,
    walls: &Walls,
    out: &mut ParticleStep,
) -> bool {
    let WallWork {
        load, open, visit, ..
    } = work;
    let (t, dt) = (walls.t, walls.dt);
    let (m, r) = (s.particle.mass, s.particle.radius);
    let (mut resist, mut stop) = (Vec3::zeros(), 0.0f64);
    // The walls within reach (from the wall index, when the plan uses one), and those
    // the particle touched last step, whose contacts may end; in wall order either way.
    visit.clear();
    let indexed = walls.index.is_some();
    match walls.index {
        Some(index) => {
            index.for_each_candidate(&s.particle.pos, r, walls.origins, |w| visit.push(w));
            // The candidates come ascending; search only them (the walls pushed after
            // them are not in order), so no wall is visited twice.
            let candidates = visit.len();
            for (w, _) in open.iter() {
                if visit[..candidates].binary_search(w).is_err() {
                    visit.push(*w);
                }
            }
            visit.sort_unstable();
        }
        None => {
            if let Some(near) = walls.near {
                visit.extend(near.of(i));
                visit.extend(near.moving.iter().copied());
                for (w, _) in open.iter() {
                    visit.push(*w);
                }
                if visit.len() > 1 {
                    visit.sort_unstable();
                    visit.dedup();
                }
            }
        }
    }
    let indexed = indexed || walls.near.is_some();
    let count = if indexed {
        visit.len()
    } else {
        walls.now.len()
    };
    let listed = |at: usize| if indexed { visit[at] } else { at };
    for at in 0..count {
        let w = listed(at);
        let wall = &walls.now[w];
        let k = open.iter().position(|(o, _)| *o == w);
        // Most particles are far from most walls: a cheap test first, unless a contact
        // is open (its end is an event).
        if k.is_none() && wall.cull.clear_of(&s.particle.pos, r) {
            continue;
        }
        let near = wall.shape.nearest(&s.particle.pos);
        let overlap = r - near.distance;
        let n = near.normal;
        if overlap <= 0.0 {
            if let Some(k) = k {
                let o = open.swap_remove(k).1;
                let wall_v = wall.point_velocity(&near.point);
                out.events.push(Event {
                    t,
                    particle: i,
                    wall: w,
                    kind: EventKind::Bounce,
                    vn_in: o.vn_in,
                    vn_out: n.dot(&(s.particle.vel - wall_v)),
                });
            }
            continue;
        }
        let wall_v = wall.point_velocity(&near.point);
        out.touching += 1;
        if out.deepest.is_none_or(|(f, _)| overlap / r > f) {
            out.deepest = Some((overlap / r, w));
        }
        let vel = s.particle.vel + s.acc * (dt * walls.predict);
        let spin = if walls.predict_spin != 0.0 {
            s.particle.spin + s.alpha * (dt * walls.predict_spin)
        } else {
            s.particle.spin
        };
        let lever = if walls.pkdgrav_levers { r - overlap } else { r };
        let u = vel + spin.cross(&(-n * lever)) - wall_v;
        let mat = &walls.materials[w];
        let k = k.unwrap_or_else(|| {
            open.push((
                w,
                Open {
                    record: Record::default(),
                    vn_in: -n.dot(&u),
                },
            ));
            open.len() - 1
        });
        if mat.eps_n <= 0.0 {
            // A death wall removes the particle; a sticky wall holds it. An aggregate's
            // member neither sticks nor dies (pkdgrav asserts, docs/pkdgrav-physics.md
            // §9.5): the event alone, and `note_wall_contacts` stops the run.
            let kind = if mat.eps_n < 0.0 {
                EventKind::Remove
            } else {
                EventKind::Stick
            };
            if !s.member {
                if kind == EventKind::Remove {
                    s.alive = false;
                } else {
                    s.stuck_to = Some(Box::new((w, s.particle.pos - wall.origin)));
                    s.particle.vel = wall_v;
                    s.particle.spin = wall.spin;
                }
            }
            out.events.push(Event {
                t,
                particle: i,
                wall: w,
                kind,
                vn_in: open[k].1.vn_in,
                vn_out: 0.0,
            });
            open.swap_remove(k);
            return true;
        }
        let plan = walls.plan;
        if walls.law == Law::Pkdgrav {
            // pkdgrav's contact law, in its frame: the normal towards the wall, the
            // wall's motion relative to the particle's (docs/pkdgrav-physics.md
            // §1.1–§1.5). A reactive wall turns the springs by its spin about the face
            // normal or axis alone (docs/pkdgrav-physics.md §10).
            let wall_spin = match walls.assembly_of[w] {
                Some(_) => crate::dynamics::reactive::relative_spin(&wall.shape, &wall.spin),
                None => wall.spin,
            };
            let a = walls.contact_radius.then(|| lever_contact_radius(r, lever));
            let dashpot = Dashpot {
                overlap,
                normal: -n,
                velocity: -u,
                spin: wall_spin - spin,
                turn: s.particle.spin + wall_spin,
                levers: (lever, 0.0),
                mass: m,
                radius: a.unwrap_or(r),
                wall: true,
                constant_torque: walls.constant_torque.map(|legacy| ConstantTorque {
                    spins: (spin, Vec3::zeros()),
                    roll_levers: match (a, legacy) {
                        (Some(a), _) => (a, 0.0),
                        (None, true) => (lever, 0.0),
                        (None, false) => (r, 0.0),
                    },
                    twist_radius: a.unwrap_or(0.0),
                    inertias: (inertia(m, r), f64::INFINITY),
                }),
                sliding: walls.sliding,
            };
            let extra = Optional {
                restitution: Some(walls.restitutions[w]),
                ..walls.optional.wall(w, i, r, a, mat)
            };
            let c = dashpot_contact_with(&dashpot, &mut open[k].1.record, dt, mat, &extra);
            load.force += c.force;
            load.torque += c.torque;
            if s.member
                && c.rolling != Vec3::zeros()
                && let Some(aggs) = walls.aggregates
            {
                // An aggregate feels the rolling torque as a pseudo-force at the contact
                // point, with its moment about the aggregate's centre
                // (docs/pkdgrav-physics.md §9.4).
                let push = aggregate::rolling_push(&c.rolling, &-n, lever);
                let arm = aggs.offset(i, &s.particle.pos) - n * lever;
                load.torque += arm.cross(&push) - c.rolling;
            }
            if let Some(a) = walls.assembly_of[w] {
                // The reaction (docs/pkdgrav-physics.md §10), with the rolling and
                // twisting torques.
                let at = s.particle.pos - n * lever;
                out.reactions.push((
                    a,
                    -c.force,
                    (at - walls.cogs[a]).cross(&-c.force) - c.resistance,
                ));
            }
            continue;
        }
        let touch = Touch {
            overlap,
            normal: n,
            velocity: u,
        };
        let c = if plan.sliding_friction {
            contact(m, lever, &touch, &mut open[k].1.record.spring, dt, mat)
        } else {
            normal_contact(&touch, mat.k_n, walls.damping[w] * m.sqrt())
        };
        load.force += c.force;
        load.torque += c.torque;
        if let Some(a) = walls.assembly_of[w] {
            // The reaction, at the contact point on the particle's surface (where its
            // own torque acts, so that angular momentum is kept exactly).
            let cog = walls.cogs[a];
            let at = s.particle.pos - n * lever;
            out.reactions
                .push((a, -c.force, (at - cog).cross(&-c.force)));
        }
        if walls.plan.rolling || walls.plan.twisting {
            let rolling = Rolling {
                spin: spin - wall.spin,
                normal: n,
                normal_force: n.dot(&c.force).abs(),
                lever: r,
                contact_radius: contact_radius(r, overlap),
                inertia: inertia(m, r),
            };
            resist += resistance(&rolling, mat.mu_r, mat.mu_t, dt);
            stop = stop.max(inertia(m, r) * rolling.spin.norm() / dt);
        }
    }
    // Each contact's resistance is capped, but together they must not reverse the spin
    // either (a corner's floor and side on one spin component).
    if resist != Vec3::zeros() && resist.norm() > stop {
        resist *= stop / resist.norm();
    }
    load.torque += resist;
    false
}

/// pkdgrav's `dAccCrit` zeroing (`dem.c pkdDEMZeroSmallMotions`, docs/pkdgrav-physics.md
/// §1.7): a particle slowing down (a·v < 0) with |a| < a_c and |v| < a_c·dt is stopped, v
/// and a both zeroed; its spin likewise, with |ẇ| < a_c·r and |w| < a_c·dt/r.
pub(super) fn zero_small_motions(s: &mut State, a_c: f64, dt: f64) {
    let p = &mut s.particle;
    if s.acc.dot(&p.vel) < 0.0 && s.acc.norm() < a_c && p.vel.norm() < a_c * dt {
        p.vel = Vec3::zeros();
        s.acc = Vec3::zeros();
    }
    let r = p.radius;
    if s.alpha.dot(&p.spin) < 0.0 && s.alpha.norm() < a_c * r && p.spin.norm() < a_c * dt / r {
        p.spin = Vec3::zeros();
        s.alpha = Vec3::zeros();
    }
}

impl SoftStepper<'_> {
    /// The contacts with the walls of each particle not owed its kick, added to its
    /// load, then its closing kick (in parallel for many particles); what each did is in
    /// `reports`.
    pub(super) fn wall_contacts(&mut self) {
        // Without forces (`bDoGravity = 0`) the walls are not looked at.
        let forces = self.settings.forces;
        let gravity = self.settings.gravity;
        let walls = Walls {
            now: if forces { &self.walls.now } else { &[] },
            assembly_of: &self.walls.assembly_of,
            cogs: &self.walls.cogs,
            origins: &self.walls.origins.now,
            index: self.walls.index.as_ref().filter(|_| forces),
            near: self.near.as_ref().filter(|_| forces),
            plan: self.plan,
            damping: &self.walls.damping,
            restitutions: &self.walls.restitutions,
            materials: &self.walls.materials,
            closing_kick: self.kicks.closing,
            predict: self.kicks.predict,
            predict_spin: self.kicks.predict_all,
            pkdgrav_levers: self.kicks.pkdgrav_levers,
            law: self.law,
            contact_radius: self.settings.contact_radius,
            constant_torque: (!self.settings.build.rotation_dashpot)
                .then_some(self.settings.legacy_roll),
            acc_crit: self.settings.acc_crit,
            sliding: self.settings.sliding,
            optional: &self.optional,
            t: self.t,
            dt: self.settings.dt,
            aggregates: self.aggregates.as_ref(),
        };
        // A plain loop over the particles of each chunk not owed their kick, its reports
        // kept with it (in particle order within the chunk), chunks in parallel for many
        // particles. Each load, once used, starts the next step with gravity alone
        // (while it is at hand; the drift does it for the owed); an aggregate's members'
        // loads are kept for it ([`SoftStepper::gather_aggregates`]).
        let chunk = |(
            c,
            ((((states, loads), (visited, inverses)), (opens, walled)), (reports, visit)),
        ): WallChunk| {
            reports.clear();
            let first = c * CHUNK;
            // The others are clear of the walls: their closing kicks are owed, not given
            // here.
            for &k in visited.iter() {
                let k = k as usize;
                let (s, load, open) = (&mut states[k], &mut loads[k], &mut opens[k]);
                let i = first + k;
                if s.free() && !s.member && clear_of_walls(i, s, open, &walls) {
                    // Clear of the walls, not owed: the closing kick alone. (None is
                    // open, as `walled[k]` already says: only this pass opens them.)
                    if let Some(report) = clear_step(s, load, inverses[k], &walls) {
                        reports.push((i, report));
                    }
                    *load = Load::gravity(s, &gravity);
                    continue;
                }
                let work = WallWork {
                    load,
                    inverse: inverses[k],
                    open,
                    visit,
                };
                let mut report = wall_step(i, s, work, &walls);
                walled[k] = !open.is_empty();
                report.not_finite = !s.finite();
                if !s.member {
                    *load = Load::gravity(s, &gravity);
                }
                if !report.is_empty() {
                    reports.push((i, report));
                }
            }
        };
        let chunks = self.states.len().div_ceil(CHUNK);
        self.reports.resize_with(chunks, Vec::new);
        self.visits.resize_with(chunks, Vec::new);
        // The chunks of every slice the wall pass takes, zipped in one order: rayon's
        // (`par_*`) or the plain ones, the same chain.
        macro_rules! chunks {
            ($chunks:ident, $chunks_mut:ident, $iter:ident, $iter_mut:ident) => {
                (self.states.$chunks_mut(CHUNK))
                    .zip(self.loads.$chunks_mut(CHUNK))
                    .zip(
                        self.deferred
                            .visited
                            .$iter()
                            .zip(self.inverses.$chunks(CHUNK)),
                    )
                    .zip((self.open_walls.$chunks_mut(CHUNK)).zip(self.walled.$chunks_mut(CHUNK)))
                    .zip(self.reports.$iter_mut().zip(&mut self.visits))
                    .enumerate()
            };
        }
        if self.parallel {
            chunks!(par_chunks, par_chunks_mut, par_iter, par_iter_mut)
                // Each chunk a task of its own: the particles near the walls gather in
                // a few chunks (those at the floor, in a pile), which halving the range
                // left to one thread (docs/performance-history.md, "Twelfth round").
                .with_max_len(1)
                .for_each(chunk);
        } else {
            chunks!(chunks, chunks_mut, iter, iter_mut).for_each(chunk);
        }
        // The kicks the drift marked as owed are owed now.
        self.deferred.owing = true;
        self.deferred.owed_kick = walls.closing();
    }

    /// The first particle whose numbers overflowed in the last step, if any: in the
    /// wall pass, or in a kick owed (given now unless surely finite).
    pub(super) fn not_finite(&mut self) -> Option<usize> {
        if !self.surely_finite() {
            self.settle();
        }
        let reported = (self.reports.iter().flatten())
            .find(|(_, r)| r.not_finite)
            .map(|(i, _)| *i);
        match (reported, self.deferred.owed_bad) {
            (Some(i), Some(j)) => Some(i.min(j)),
            (i, j) => i.or(j),
        }
    }

    /// The wall contacts' events and warnings (overlaps, too fast, energy gained, too
    /// many walls at once), in particle order so that the outcome does not depend on the
    /// threads; [`Flow::Stop`] when an overlap is past pkdgrav's abort.
    pub(super) fn note_wall_contacts(&mut self) -> Flow {
        let t = self.t;
        let mut stop = self.aggregates.is_some() && self.aggregates_held();
        for (i, report) in self.reports.iter_mut().flatten() {
            let i = *i;
            if let Some((fraction, w)) = report.deepest {
                stop |= self.journal.overlaps.check(
                    fraction,
                    Overlapping::Wall {
                        particle: i,
                        wall: w,
                    },
                    t,
                    &mut self.journal.warnings,
                );
            }
            // A travel that overflowed is the not-finite stop's, not a warning's.
            if let Some(travel) = report.too_fast.filter(|x| x.is_finite())
                && !self.journal.once.fast
            {
                self.journal.once.fast = true;
                self.journal.warnings.push(Warning::TooFast {
                    particle: i,
                    radii: travel,
                    t,
                });
            }
            for e in &report.events {
                if e.kind == EventKind::Bounce
                    && e.vn_out
                        > e.vn_in
                            * (1.0
                                + gain_tolerance(
                                    self.walls.materials[e.wall].k_n,
                                    self.states[i].particle.mass,
                                    self.settings.dt,
                                ))
                    && !self.walls.oscillating[e.wall]
                    && !self.journal.once.gain
                {
                    self.journal.once.gain = true;
                    self.journal.warnings.push(Warning::EnergyGain {
                        particle: i,
                        wall: e.wall,
                        vn_in: e.vn_in,
                        vn_out: e.vn_out,
                        t,
                    });
                }
            }
            if report.events.iter().any(|e| e.kind == EventKind::Stick) {
                self.candidates.held = true;
            }
            if report.events.iter().any(|e| e.kind == EventKind::Remove) {
                self.candidates.gone = true;
            }
            self.journal.events.append(&mut report.events);
            if report.touching > 3 && !self.journal.once.crowd {
                self.journal.once.crowd = true;
                self.journal.warnings.push(Warning::Crowded {
                    particle: i,
                    walls: report.touching,
                    t,
                });
            }
        }
        if stop { Flow::Stop } else { Flow::Continue }
    }

    /// Whether an aggregate's member reached a sticky or death wall this step (pkdgrav
    /// asserts, docs/pkdgrav-physics.md §9.5): the warning, in place of the event.
    pub(super) fn aggregates_held(&mut self) -> bool {
        let mut held = false;
        for (i, report) in self.reports.iter_mut().flatten() {
            let i = *i;
            if !self.states[i].member {
                continue;
            }
            for e in &report.events {
                if matches!(e.kind, EventKind::Stick | EventKind::Remove) {
                    self.journal.warnings.push(Warning::AggregateHeld {
                        particle: i,
                        wall: e.wall,
                        t: self.t,
                    });
                    held = true;
                }
            }
            report
                .events
                .retain(|e| !matches!(e.kind, EventKind::Stick | EventKind::Remove));
        }
        held
    }
}

/// How much faster than it came a particle may leave a wall before W106 calls it a
/// gain of energy: the rebound error the integrator is expected to make at this
/// timestep, 1.2/N for N = π/(ω₀·dt) steps per contact (ω₀ = √(k_n/m); W202,
/// docs/run-warnings.md), and no less than round-off (10⁻⁹).
pub(super) fn gain_tolerance(k_n: f64, mass: f64, dt: f64) -> f64 {
    let tolerance = crate::run::stability::rebound_error((k_n / mass).sqrt(), dt);
    if tolerance.is_finite() {
        tolerance.max(1e-9)
    } else {
        1e-9
    }
}

/// A chunk of the particles as the wall pass takes it: its number, their states and
/// loads, which of them it visits and their 1/m and 1/I, their open wall contacts and
/// whether any is open, and its reports and scratch list of walls.
pub(super) type WallChunk<'a> = (
    usize,
    (
        (
            (
                (&'a mut [State], &'a mut [Load]),
                (&'a Vec<u32>, &'a [(f64, f64)]),
            ),
            (&'a mut [Vec<(usize, Open)>], &'a mut [bool]),
        ),
        (&'a mut Vec<(usize, ParticleStep)>, &'a mut Vec<usize>),
    ),
);
