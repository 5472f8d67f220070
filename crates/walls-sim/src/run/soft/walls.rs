//! The wall pass of the soft-sphere run ([`wall_contacts`]): each particle's contacts
//! with the walls it may touch, added to its load, then its closing kick; and what they
//! did, noted in the file's order ([`note_wall_contacts`]).

use super::law::Side;
use super::near::NearWalls;
use super::numbering::Numbering;
use super::{
    Bodies, Broad, CHUNK, ChunkOpens, ContactLaw, Deferred, Event, EventKind, Flow, Journal, Kicks,
    Law, Load, Overlapping, Rigid, Rules, State, Vec3, WallNow, WallSet, Warning, carry, inertia,
};
use crate::contact::ssdem::{
    Dashpot, Optional, Record, Rolling, Touch, contact, contact_radius, dashpot_contact_with,
    normal_contact, resistance,
};
use crate::dynamics::aggregate::{self, Aggregates};
use crate::run::optional::OptionalPhysics;
use crate::run::plan::Plan;
use rayon::prelude::*;
use thin_vec::ThinVec;

/// An open wall contact: its springs (the tangential spring alone, but with
/// [`crate::run::Integrator::Pkdgrav`] every spring pkdgrav keeps) and the normal speed it began
/// with.
pub(super) struct Open {
    record: Record,
    vn_in: f64,
}

/// The wall pass's reports and scratch, kept from step to step to save allocating: what
/// the wall contacts of each particle (by place) with something to note did this step,
/// in the file's order once the pass is done ([`WallPass::in_file_order`]), and each
/// chunk's list of the walls to visit.
#[derive(Default)]
pub(super) struct WallPass {
    pub(super) reports: Vec<Vec<(usize, ParticleStep)>>,
    visits: Vec<Vec<usize>>,
}

impl WallPass {
    /// The reports, each chunk's in the order of its places, put in the file's order:
    /// everything that follows them (events, warnings, the reactions' sums on the
    /// assemblies) takes them in that order, the order of a run kept in the file's.
    fn in_file_order(&mut self, numbering: &Numbering) {
        if numbering.in_file_order() {
            return;
        }
        let Some((first, rest)) = self.reports.split_first_mut() else {
            return;
        };
        for chunk in rest {
            first.append(chunk);
        }
        first.sort_unstable_by_key(|(i, _)| numbering.file(*i));
    }
}

/// What every particle's wall contacts share in a step: the walls as they stand, with
/// their materials and constants ([`WallSet`], compiled at set-up), the walls near each
/// particle, the contact law, the kicks and the closing kick, and the time.
pub(super) struct Walls<'a> {
    set: &'a WallSet,
    /// The walls as they stand (none without forces: `bDoGravity = 0`).
    now: &'a [WallNow],
    /// The fixed walls near each particle and the walls that move ([`NearWalls`]; none
    /// without walls or forces).
    near: Option<&'a NearWalls>,
    plan: &'a Plan,
    kicks: Kicks,
    contact: ContactLaw,
    /// The closing kick (its timestep is the step's).
    closing: Closing,
    /// Cohesion and two-layer contacts (pkdgrav's optional builds).
    optional: &'a OptionalPhysics,
    /// pkdgrav's aggregates, if any (for their members' rolling pseudo-forces).
    aggregates: Option<&'a Aggregates>,
    /// The overlap (a fraction of the particle's radius) past which a wall contact is
    /// one of pkdgrav's overlap events: `dMinorFrac`.
    minor: f64,
    /// The time at the step's end.
    t: f64,
    /// Which particle of the file each place holds: an event names the file's.
    numbering: &'a Numbering,
}

/// What one particle's wall contacts did in a step.
#[derive(Default)]
pub(super) struct ParticleStep {
    pub(super) events: Vec<Event>,
    /// The overlaps past `dMinorFrac` (as fractions of the particle's radius) and their
    /// walls, in the walls' order: pkdgrav's overlap events (docs/pkdgrav-physics.md §15).
    pub(super) past: Vec<(f64, usize)>,
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
            && self.past.is_empty()
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
    open: &'a mut ThinVec<(usize, Open)>,
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
    let dt = walls.closing.dt;
    let mut out = ParticleStep::default();
    if !s.alive {
        return out;
    }
    if let Some(&(w, _)) = s.stuck_to.as_deref() {
        // pkdgrav carries a stuck particle with its wall's move, before the forces
        // (docs/pkdgrav-physics.md §6; `super::carry_stuck`).
        if !walls.kicks.pkdgrav_levers {
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
        // Its aggregate takes the load (`super::rigid::gather_aggregates`).
        return out;
    }
    close_step(s, work.load, work.inverse, walls.closing);
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

/// Whether particle `i` (state `s`) touches no wall and cannot: no contact open, and
/// every wall near it surely out of its reach ([`walls_geometry::shape::Cull::clear_of`], the test
/// [`touch_walls`] makes first): nothing to look at. Most particles near a wall are not
/// touching it.
#[inline]
pub(super) fn clear_of_walls(i: usize, s: &State, open: &[(usize, Open)], walls: &Walls) -> bool {
    open.is_empty() && clear_of_near(i, &s.particle.pos, s.particle.radius, walls.near, walls.now)
}

/// [`clear_of_walls`] for particle `i` (at `pos`, of radius `r`) with no contact open: its near walls (`near`, as they stand: `now`) all surely
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
    let dt = walls.closing.dt;
    let moved = s.particle.vel.norm_squared() * dt * dt;
    let motion = close_step(s, load, inverse, walls.closing);
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
/// with the same arithmetic ([`super::drift::kick_drift`]): a change here is a change
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
    let (t, dt) = (walls.t, walls.closing.dt);
    let r = s.particle.radius;
    let (mut resist, mut stop) = (Vec3::zeros(), 0.0f64);
    walls_to_visit(i, open, visit, walls.near);
    for at in 0..visit.len() {
        let w = visit[at];
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
                    particle: walls.numbering.file(i),
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
        // A death wall removes the particle before pkdgrav looks at the overlap (§15).
        if overlap / r > walls.minor && walls.set.materials[w].eps_n >= 0.0 {
            out.past.push((overlap / r, w));
        }
        let vel = s.particle.vel + s.acc * (dt * walls.kicks.predict);
        let spin = if walls.kicks.predict_all != 0.0 {
            s.particle.spin + s.alpha * (dt * walls.kicks.predict_all)
        } else {
            s.particle.spin
        };
        let lever = if walls.kicks.pkdgrav_levers {
            r - overlap
        } else {
            r
        };
        let u = vel + spin.cross(&(-n * lever)) - wall_v;
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
        let eps_n = walls.set.materials[w].eps_n;
        if eps_n <= 0.0 {
            let vn_in = open.swap_remove(k).1.vn_in;
            out.events.push(hold(
                walls.numbering.file(i),
                s,
                w,
                wall,
                wall_v,
                eps_n,
                (t, vn_in),
            ));
            return true;
        }
        let touch = WallTouch {
            w,
            overlap,
            normal: n,
            velocity: u,
            lever,
            spin,
        };
        let record = &mut open[k].1.record;
        if walls.contact.law == Law::Pkdgrav {
            pkdgrav_wall_contact(i, s, &touch, record, walls, load, out);
        } else {
            let resisted = linear_wall_contact(s, &touch, record, walls, load, out);
            if let Some((resisted, most)) = resisted {
                resist += resisted;
                stop = stop.max(most);
            }
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

/// Into `visit`, the walls particle `i` is to visit, in wall order: those near it
/// ([`NearWalls`]), those of reactive assemblies, and those it touched last step
/// (`open`), whose contacts may end.
#[inline(always)]
fn walls_to_visit(
    i: usize,
    open: &[(usize, Open)],
    visit: &mut Vec<usize>,
    near: Option<&NearWalls>,
) {
    visit.clear();
    if let Some(near) = near {
        visit.extend_from_slice(near.listed_of(i));
        visit.extend(near.moving.iter().copied());
        visit.extend(open.iter().map(|(w, _)| *w));
        if visit.len() > 1 {
            visit.sort_unstable();
            visit.dedup();
        }
    }
}

/// A death wall (`eps_n` < 0) removes particle `i`, an aggregate's member too (its
/// aggregate keeps its mass and shape, docs/pkdgrav-physics.md §17); a sticky wall (0)
/// holds it where it touched, moving and spinning with the wall (§6). An aggregate's
/// member does not stick (pkdgrav asserts, §9.5): the event alone, and
/// `note_wall_contacts` stops the run. The event, at time
/// `t`, of a contact that began at normal speed `vn_in` (`i`: the particle's number in
/// the file).
#[inline(always)]
fn hold(
    i: usize,
    s: &mut State,
    w: usize,
    wall: &WallNow,
    wall_v: Vec3,
    eps_n: f64,
    (t, vn_in): (f64, f64),
) -> Event {
    let kind = if eps_n < 0.0 {
        EventKind::Remove
    } else {
        EventKind::Stick
    };
    if kind == EventKind::Remove {
        s.alive = false;
    } else if !s.member {
        s.stuck_to = Some(Box::new((w, s.particle.pos - wall.origin)));
        s.particle.vel = wall_v;
        s.particle.spin = wall.spin;
    }
    Event {
        t,
        particle: i,
        wall: w,
        kind,
        vn_in,
        vn_out: 0.0,
    }
}

/// One wall contact as the wall pass finds it: the wall, the overlap, the unit normal
/// from the wall towards the particle, the contact point's velocity relative to the
/// wall's, the lever (the radius, or pkdgrav's r − x) and the spin the contact sees.
struct WallTouch {
    w: usize,
    overlap: f64,
    normal: Vec3,
    velocity: Vec3,
    lever: f64,
    spin: Vec3,
}

/// Particle `i`'s contact `touch` under pkdgrav's contact law, in its frame: the normal
/// towards the wall, the wall's motion relative to the particle's
/// (docs/pkdgrav-physics.md §1.1–§1.5), added to its load; a reactive wall turns the
/// springs by its spin about the face normal or axis alone and takes the reaction
/// (docs/pkdgrav-physics.md §10); an aggregate's member passes the rolling torque on as
/// a pseudo-force (docs/pkdgrav-physics.md §9.4).
#[inline(always)]
fn pkdgrav_wall_contact(
    i: usize,
    s: &State,
    touch: &WallTouch,
    record: &mut Record,
    walls: &Walls,
    load: &mut Load,
    out: &mut ParticleStep,
) {
    let WallTouch {
        w,
        overlap,
        normal: n,
        velocity: u,
        lever,
        spin,
    } = *touch;
    let (m, r) = (s.particle.mass, s.particle.radius);
    let (wall, mat) = (&walls.now[w], &walls.set.materials[w]);
    let wall_spin = match walls.set.assembly_of[w] {
        Some(_) => crate::dynamics::reactive::relative_spin(&wall.shape, &wall.spin),
        None => wall.spin,
    };
    let a = walls.contact.contact_radius(r, lever);
    let one = Side {
        radius: r,
        lever,
        spin,
        inertia: inertia(m, r),
    };
    let (radius, constant_torque) = walls.contact.rolling(a, one, None);
    let dashpot = Dashpot {
        overlap,
        normal: -n,
        velocity: -u,
        spin: wall_spin - spin,
        turn: s.particle.spin + wall_spin,
        levers: (lever, 0.0),
        mass: m,
        radius,
        wall: true,
        constant_torque,
        sliding: walls.contact.sliding,
    };
    let extra = Optional {
        restitution: Some(walls.set.restitutions[w]),
        ..walls.optional.wall(w, r, a, mat)
    };
    let c = dashpot_contact_with(&dashpot, record, walls.closing.dt, mat, &extra);
    load.force += c.force;
    load.torque += c.torque;
    if s.member
        && c.rolling != Vec3::zeros()
        && let Some(aggs) = walls.aggregates
    {
        // The rolling torque as a pseudo-force at the contact point, with its moment
        // about the aggregate's centre.
        let push = aggregate::rolling_push(&c.rolling, &-n, lever);
        let arm = aggs.offset(i, &s.particle.pos) - n * lever;
        load.torque += arm.cross(&push) - c.rolling;
    }
    react(
        out,
        walls,
        w,
        &(s.particle.pos - n * lever),
        &c.force,
        &c.resistance,
    );
}

/// The reaction of a contact with wall `w` on its reactive assembly, if it has one: the
/// contact's force `force` turned around, at `at`, the contact point on the particle's
/// surface (where the particle's own torque acts, so that angular momentum is kept
/// exactly), and its moment about the assembly's centre of gravity, less the contact's
/// rolling and twisting torques `resistance`.
#[inline(always)]
fn react(
    out: &mut ParticleStep,
    walls: &Walls,
    w: usize,
    at: &Vec3,
    force: &Vec3,
    resistance: &Vec3,
) {
    if let Some(a) = walls.set.assembly_of[w] {
        let cog = walls.set.cogs[a];
        out.reactions
            .push((a, -force, (at - cog).cross(&-force) - resistance));
    }
}

/// Particle `s`'s contact `touch` under the linear spring–dashpot (with sliding friction
/// when the plan has it), added to its load, its reaction to a reactive wall's assembly;
/// and, when the plan has rolling or twisting, its resistance with the most it may be
/// (the spin it could stop in the step), which [`touch_walls`] caps over all the
/// particle's contacts.
#[inline(always)]
fn linear_wall_contact(
    s: &State,
    touch: &WallTouch,
    record: &mut Record,
    walls: &Walls,
    load: &mut Load,
    out: &mut ParticleStep,
) -> Option<(Vec3, f64)> {
    let (w, n, lever) = (touch.w, touch.normal, touch.lever);
    let (m, r, dt) = (s.particle.mass, s.particle.radius, walls.closing.dt);
    let (wall, mat) = (&walls.now[w], &walls.set.materials[w]);
    let along = Touch {
        overlap: touch.overlap,
        normal: n,
        velocity: touch.velocity,
    };
    let c = if walls.plan.sliding_friction {
        contact(m, lever, &along, &mut record.spring, dt, mat)
    } else {
        normal_contact(&along, mat.k_n, walls.set.damping[w] * m.sqrt())
    };
    load.force += c.force;
    load.torque += c.torque;
    // The linear law's torques are the contact's own: nothing to take from the moment.
    react(
        out,
        walls,
        w,
        &(s.particle.pos - n * lever),
        &c.force,
        &Vec3::zeros(),
    );
    if !(walls.plan.rolling || walls.plan.twisting) {
        return None;
    }
    let rolling = Rolling {
        spin: touch.spin - wall.spin,
        normal: n,
        normal_force: n.dot(&c.force).abs(),
        lever: r,
        contact_radius: contact_radius(r, touch.overlap),
        inertia: inertia(m, r),
    };
    let resisted = resistance(&rolling, mat.mu_r, mat.mu_t, dt);
    Some((resisted, inertia(m, r) * rolling.spin.norm() / dt))
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

/// The contacts with the walls of each particle not owed its kick, added to its load,
/// then its closing kick (in parallel for many particles); what each did is in the
/// pass's reports.
pub(super) fn wall_contacts(
    bodies: &mut Bodies,
    deferred: &mut Deferred,
    wall_pass: &mut WallPass,
    (set, near): (&WallSet, Option<&NearWalls>),
    rigid: &Rigid,
    rules: &Rules,
    t: f64,
) {
    let settings = rules.settings;
    // Without forces (`bDoGravity = 0`) the walls are not looked at.
    let forces = settings.forces;
    let gravity = settings.gravity;
    let walls = Walls {
        set,
        now: if forces { &set.now } else { &[] },
        near: near.filter(|_| forces),
        plan: rules.plan,
        kicks: rules.kicks,
        contact: rules.contact,
        closing: Closing {
            dt: settings.dt,
            fraction: rules.kicks.closing,
            acc_crit: settings.acc_crit,
        },
        optional: &rules.optional,
        aggregates: rigid.aggregates.as_ref(),
        minor: settings.overlap_levels.minor,
        t,
        numbering: &bodies.numbering,
    };
    // A plain loop over the particles of each chunk not owed their kick, its reports
    // kept with it (in particle order within the chunk), chunks in parallel for many
    // particles. Each load, once used, starts the next step with gravity alone
    // (while it is at hand; the drift does it for the owed); an aggregate's members'
    // loads are kept for it ([`super::rigid::gather_aggregates`]).
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
            let (s, load) = (&mut states[k], &mut loads[k]);
            // Its list, or an empty one while its chunk has none (made below when a
            // contact opens).
            let mut none = ThinVec::new();
            let open = match opens.get_mut(k) {
                Some(open) => open,
                None => &mut none,
            };
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
            if !none.is_empty() {
                opens.resize_with(walled.len(), ThinVec::new);
                opens[k] = none;
            }
            report.not_finite = !s.finite();
            if !s.member {
                *load = Load::gravity(s, &gravity);
            }
            if !report.is_empty() {
                reports.push((i, report));
            }
        }
    };
    let chunks = bodies.states.len().div_ceil(CHUNK);
    wall_pass.reports.resize_with(chunks, Vec::new);
    wall_pass.visits.resize_with(chunks, Vec::new);
    // The chunks of every slice the wall pass takes, zipped in one order: rayon's
    // (`par_*`) or the plain ones, the same chain.
    macro_rules! chunks {
        ($chunks:ident, $chunks_mut:ident, $iter:ident, $iter_mut:ident) => {
            (bodies.states.$chunks_mut(CHUNK))
                .zip(bodies.loads.$chunks_mut(CHUNK))
                .zip(deferred.visited.$iter().zip(bodies.inverses.$chunks(CHUNK)))
                .zip((bodies.open_walls.$iter_mut()).zip(bodies.walled.$chunks_mut(CHUNK)))
                .zip(wall_pass.reports.$iter_mut().zip(&mut wall_pass.visits))
                .enumerate()
        };
    }
    if rules.parallel {
        chunks!(par_chunks, par_chunks_mut, par_iter, par_iter_mut)
            // Each chunk a task of its own: the particles near the walls gather in
            // a few chunks (those at the floor, in a pile), which halving the range
            // left to one thread (docs/performance-history.md, "Twelfth round").
            .with_max_len(1)
            .for_each(chunk);
    } else {
        chunks!(chunks, chunks_mut, iter, iter_mut).for_each(chunk);
    }
    wall_pass.in_file_order(&bodies.numbering);
    // The kicks the drift marked as owed are owed now.
    deferred.owing = true;
    deferred.owed_kick = walls.closing;
}

/// The wall contacts' events and warnings (overlaps, too fast, energy gained, too
/// many walls at once), in the file's order so that the outcome does not depend on the
/// threads; [`Flow::Stop`] when an overlap is past pkdgrav's abort.
#[allow(clippy::too_many_arguments)]
pub(super) fn note_wall_contacts(
    wall_pass: &mut WallPass,
    journal: &mut Journal,
    broad: &mut Broad,
    bodies: &Bodies,
    walls: &WallSet,
    rigid: &Rigid,
    rules: &Rules,
    t: f64,
) -> Flow {
    let mut stop = (rigid.aggregates.as_ref())
        .is_some_and(|aggs| aggregates_held(wall_pass, journal, bodies, aggs, t));
    for (place, report) in wall_pass.reports.iter_mut().flatten() {
        let (place, i) = (*place, bodies.numbering.file(*place));
        for &(fraction, w) in &report.past {
            stop |= journal.overlaps.check(
                fraction,
                Overlapping::Wall {
                    particle: i,
                    wall: w,
                },
                t,
                &mut journal.warnings,
            );
        }
        // A travel that overflowed is the not-finite stop's, not a warning's.
        if let Some(travel) = report.too_fast.filter(|x| x.is_finite())
            && !journal.once.fast
        {
            journal.once.fast = true;
            journal.warnings.push(Warning::TooFast {
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
                                walls.materials[e.wall].k_n,
                                bodies.states[place].particle.mass,
                                rules.settings.dt,
                            ))
                && !walls.driven[e.wall]
                && !journal.once.gain
            {
                journal.once.gain = true;
                journal.warnings.push(Warning::EnergyGain {
                    particle: i,
                    wall: e.wall,
                    vn_in: e.vn_in,
                    vn_out: e.vn_out,
                    t,
                });
            }
        }
        if report.events.iter().any(|e| e.kind == EventKind::Stick) {
            broad.candidates.held = true;
        }
        if report.events.iter().any(|e| e.kind == EventKind::Remove) {
            broad.candidates.gone = true;
        }
        journal.events.append(&mut report.events);
        if report.touching > 3 && !journal.once.crowd {
            journal.once.crowd = true;
            journal.warnings.push(Warning::Crowded {
                particle: i,
                walls: report.touching,
                t,
            });
        }
    }
    if stop { Flow::Stop } else { Flow::Continue }
}

/// Whether an aggregate's member reached a sticky wall this step (pkdgrav asserts,
/// docs/pkdgrav-physics.md §9.5: the warning, in place of the event), or death walls
/// deleted an aggregate's last member (it asserts, §17). A member a death wall deletes
/// is warned about (pkdgrav's "mass not conserved"), and its event kept.
pub(super) fn aggregates_held(
    wall_pass: &mut WallPass,
    journal: &mut Journal,
    bodies: &Bodies,
    aggregates: &Aggregates,
    t: f64,
) -> bool {
    let mut held = false;
    let mut emptied = Vec::new();
    for (place, report) in wall_pass.reports.iter_mut().flatten() {
        if !bodies.states[*place].member {
            continue;
        }
        let i = bodies.numbering.file(*place);
        let Some(a) = aggregates.of[*place] else {
            continue;
        };
        let aggregate = &aggregates.list[a as usize];
        for e in &report.events {
            match e.kind {
                EventKind::Stick => {
                    journal.warnings.push(Warning::AggregateHeld {
                        particle: i,
                        wall: e.wall,
                        t,
                    });
                    held = true;
                }
                EventKind::Remove => {
                    journal.warnings.push(Warning::MemberDeleted {
                        particle: i,
                        aggregate: aggregate.number,
                        wall: e.wall,
                        t,
                    });
                    let gone = (aggregate.members.iter()).all(|&m| !bodies.states[m].alive);
                    if gone && !emptied.contains(&a) {
                        emptied.push(a);
                        journal.warnings.push(Warning::AggregateDeleted {
                            aggregate: aggregate.number,
                            t,
                        });
                        held = true;
                    }
                }
                _ => {}
            }
        }
        report.events.retain(|e| e.kind != EventKind::Stick);
    }
    held
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
            (&'a mut ChunkOpens, &'a mut [bool]),
        ),
        (&'a mut Vec<(usize, ParticleStep)>, &'a mut Vec<usize>),
    ),
);
