//! The drift of the soft-sphere run ([`kick_drift`]): the kicks owed by the last step,
//! the opening kick and drift, the list's staleness, and which particles this step's
//! wall pass may owe their closing kick; and the owed kicks given when the particles are
//! looked at ([`settle`]).

use super::ahead::{fetch, fetch_state};
use super::walls::{clear_of_near, close_step};
use super::{Bodies, Broad, CHUNK, Deferred, Kicks, Load, Rules, State, Vec3, WallNow, WallSet};
use crate::broad::pairs::PairList;
use rayon::prelude::*;

/// The kick before the drift (leapfrog's first half; none in explicit Euler), the
/// drift, and the kick after it (explicit Euler's), for the free particles; in the
/// same pass, each free particle first gets the last step's closing kick if the wall
/// pass left it owed ([`super::Deferred::owed`]), the loads of an aggregate's members
/// start the step with gravity alone (the others' were started by the last wall pass
/// or here, after the owed kick), the candidate pairs learn whether a drifted
/// particle has moved far enough to rebuild them ([`PairList::drifted`]), and each
/// particle is marked whether this step's wall pass may owe it its closing kick
/// ([`may_owe`]). `ACC_CRIT`: whether the owed kicks apply pkdgrav's
/// `dAccCrit` (the run's `acc_crit` is positive).
pub(super) fn kick_drift<const ACC_CRIT: bool>(
    bodies: &mut Bodies,
    deferred: &mut Deferred,
    broad: &mut Broad,
    walls: &WallSet,
    rules: &Rules,
) {
    let dt = rules.settings.dt;
    let g = rules.settings.gravity;
    let Kicks { opening, late, .. } = rules.kicks;
    let limit = broad.candidates.limit();
    let half = broad.candidates.skin / 2.0;
    // The kicks owed by the last wall pass, if it owed any.
    let pay = std::mem::take(&mut deferred.owing).then_some(deferred.owed_kick);
    let marks_valid = deferred.marks_valid;
    let forces = rules.settings.forces;
    let ahead = rules.ahead;
    let PairList {
        built_at, spheres, ..
    } = &mut broad.candidates;
    // The walls as the wall pass will see them (`super::walls::wall_contacts`). The
    // walls near a particle were found where it and they stood at the last rebuild:
    // a wall not among them was then farther than its radius and half the skin (a
    // translating one, the skin), so it cannot reach a particle that has moved less
    // than half the skin since, unless the wall itself has moved more. Such a
    // particle is owed nothing, and when a wall has moved that far, no particle is
    // (the list is found again after this pass). Nothing is owed with the walls of
    // reactive assemblies, placed only after this pass.
    let near = broad.near.as_ref().filter(|_| forces);
    let now: &[WallNow] = if forces { &walls.now } else { &[] };
    let owing = near.is_none_or(|n| !n.moved(now, half));
    // The settings held by value (`move`): by reference, every particle read each
    // through a pointer to these locals. Says whether the particle moved far enough
    // to rebuild the pairs, and whether this step's wall pass may owe it its kick.
    let kick_drift = move |i: usize, s: &mut State, work: DriftWork| {
        let DriftWork {
            load,
            loaded,
            owed,
            at,
            sphere,
            walled,
            inverse,
        } = work;
        if s.member {
            // The others' loads were started in the last wall pass, once used.
            *load = Load::gravity(s, &g);
            *owed = false;
            return (false, false);
        }
        if !s.free() {
            *owed = false;
            return (false, false);
        }
        // In locals, each field read once and written once: read back at once,
        // what was just written stalls the processor.
        let (mut vel, mut spin, mut acc, mut alpha) =
            (s.particle.vel, s.particle.spin, s.acc, s.alpha);
        if let (true, Some(kick)) = (*owed, pay) {
            // The last step's closing kick, as the wall pass would have given it
            // (`close_step`'s arithmetic, in its order, from the locals).
            debug_assert_eq!(ACC_CRIT, kick.acc_crit > 0.0);
            // The load paid, set back to gravity for the next step; when the marks
            // are valid, one not marked is gravity already: worked out, not read.
            let paid = if !marks_valid || std::mem::take(loaded) {
                let taken = *load;
                *load = Load::gravity(s, &g);
                taken
            } else {
                let gravity = Load::gravity(s, &g);
                debug_assert!(gravity.same_as(load), "particle {i}: a load not marked");
                gravity
            };
            if ACC_CRIT {
                close_step(s, &paid, inverse, kick);
                (vel, spin, acc, alpha) = (s.particle.vel, s.particle.spin, s.acc, s.alpha);
            } else {
                acc = paid.force * inverse.0;
                alpha = paid.torque * inverse.1;
                vel += acc * (dt * kick.fraction);
                spin += alpha * (dt * kick.fraction);
                s.acc = acc;
                s.alpha = alpha;
            }
        }
        vel += acc * (dt * opening);
        spin += alpha * (dt * opening);
        let pos = s.particle.pos + vel * dt;
        if late != 0.0 {
            vel += acc * (dt * late);
            spin += alpha * (dt * late);
        }
        s.particle.pos = pos;
        s.particle.vel = vel;
        s.particle.spin = spin;
        // What follows reads the locals, not the state just written.
        let r = s.particle.radius;
        // (Its radius, which never changes, is there since the list was built.)
        sphere[..3].copy_from_slice(&[pos.x as f32, pos.y as f32, pos.z as f32]);
        // `PairList::moved_far` (the particle is alive).
        let d2 = (pos - at).norm_squared();
        let far = d2 > limit || d2.is_nan();
        *owed = owing
            && !far
            && !walled
            && may_owe(d2, &vel, &spin, r, dt)
            && clear_of_near(i, &pos, r, near, now);
        (far, *owed)
    };
    // A plain loop over a chunk of the particles (every one is kicked and drifted:
    // no short cut), chunks in parallel for many particles.
    let chunk = |(
        c,
        (((((states, (loads, loaded)), owed), (built_at, spheres)), (walled, inverses)), visited),
    ): DriftChunk| {
        let mut drifted = false;
        let first = c * CHUNK;
        visited.clear();
        // The loads a pair touched, asked for before the loop reaches them (the pair
        // list sends its forces to them here and there, which no prefetcher guesses).
        if ahead {
            for (load, _) in loads
                .iter()
                .zip(loaded.iter())
                .filter(|(_, loaded)| **loaded)
            {
                fetch(load);
            }
        }
        let mut works = loads
            .iter_mut()
            .zip(loaded)
            .zip(owed)
            .zip(built_at)
            .zip(spheres)
            .zip(walled.iter().zip(inverses))
            .map(
                |(((((load, loaded), owed), at), sphere), (&walled, &inverse))| DriftWork {
                    load,
                    loaded,
                    owed,
                    at,
                    sphere,
                    walled,
                    inverse,
                },
            )
            .enumerate();
        // The states in blocks when asking ahead, each asking first for the next
        // block's: read in order, yet the processor's own prefetching fell behind
        // on them (asked for, the drift of the polydisperse 10⁵ took ~14 % less time).
        let mut blocks = states
            .chunks_mut(if ahead { STATE_BLOCK } else { CHUNK })
            .peekable();
        while let Some(block) = blocks.next() {
            if ahead && let Some(next) = blocks.peek() {
                next.iter().for_each(fetch_state);
            }
            for (s, (k, work)) in block.iter_mut().zip(&mut works) {
                let (far, owed) = kick_drift(first + k, s, work);
                drifted |= far;
                if !owed {
                    visited.push(k as u32);
                }
            }
        }
        drifted
    };
    let chunks = bodies.states.len().div_ceil(CHUNK);
    deferred.visited.resize_with(chunks, Vec::new);
    // The chunks of every slice the drift takes, zipped in one order: rayon's
    // (`par_*`) or the plain ones, the same chain.
    macro_rules! chunks {
        ($chunks:ident, $chunks_mut:ident, $iter_mut:ident) => {
            (bodies.states.$chunks_mut(CHUNK))
                .zip((bodies.loads.$chunks_mut(CHUNK)).zip(deferred.loaded.$chunks_mut(CHUNK)))
                .zip(deferred.owed.$chunks_mut(CHUNK))
                .zip(built_at.$chunks(CHUNK).zip(spheres.$chunks_mut(CHUNK)))
                .zip(
                    bodies
                        .walled
                        .$chunks(CHUNK)
                        .zip(bodies.inverses.$chunks(CHUNK)),
                )
                .zip(deferred.visited.$iter_mut())
                .enumerate()
        };
    }
    let drifted = if rules.parallel {
        chunks!(par_chunks, par_chunks_mut, par_iter_mut)
            .map(chunk)
            .reduce(|| false, |a, b| a || b)
    } else {
        // Every chunk, not stopping at the first that drifted far (as `any` would).
        let mut drifted = false;
        for c in chunks!(chunks, chunks_mut, iter_mut) {
            drifted |= chunk(c);
        }
        drifted
    };
    broad.candidates.drifted = drifted;
    deferred.owed_bad = None;
    deferred.force_bound = 0.0;
}

/// Whether the wall pass may owe a free particle of radius `r`, whose squared
/// distance from where the candidate pairs were found is `d2`, with velocity `vel`
/// and spin `spin` and clear of the walls, its closing kick: it has not moved more
/// than a radius in the step (else the wall pass warns of it), its position is
/// finite (`d2` is: the kick does not move it), and its velocity and spin are surely
/// finite, each shorter than [`SURELY_FINITE_LENGTH`], so that only its load could
/// make them overflow ([`surely_finite`]). All from squared lengths (the
/// speed test needs the velocity's anyway); a NaN or an infinity fails each test.
#[inline]
pub(super) fn may_owe(d2: f64, vel: &Vec3, spin: &Vec3, r: f64, dt: f64) -> bool {
    const LIMIT: f64 = SURELY_FINITE_LENGTH * SURELY_FINITE_LENGTH;
    let v2 = vel.norm_squared();
    (d2 < LIMIT) & (v2 * dt * dt <= r * r) & (v2 < LIMIT) & (spin.norm_squared() < LIMIT)
}

/// The closing kicks the last wall pass owed, given now (as the next drift would
/// give them), so that the particles stand as the step left them. The first
/// particle (in the file's order) whose numbers overflowed in its kick is kept for
/// [`super::SoftStepper::not_finite`].
pub(super) fn settle(bodies: &mut Bodies, deferred: &mut Deferred, rules: &Rules) {
    if !std::mem::take(&mut deferred.owing) {
        return;
    }
    let kick = deferred.owed_kick;
    let g = rules.settings.gravity;
    let mut bad = None;
    for (i, (((s, load), owed), &inverse)) in (bodies.states.iter_mut())
        .zip(&mut bodies.loads)
        .zip(&mut deferred.owed)
        .zip(bodies.inverses.iter())
        .enumerate()
    {
        if std::mem::take(owed) {
            let motion = close_step(s, load, inverse, kick);
            *load = Load::gravity(s, &g);
            if !s.finite_with(motion) {
                let i = bodies.numbering.file(i);
                bad = Some(bad.map_or(i, |first: usize| first.min(i)));
            }
        }
    }
    deferred.owed_bad = bad;
}

/// Whether the kicks owed cannot overflow: each owed particle's position is finite,
/// and its velocity and spin are below [`SURELY_FINITE`] in size (shorter than
/// [`SURELY_FINITE_LENGTH`], [`may_owe`]), and its
/// load (gravity and particle contacts) is at most gravity on the heaviest particle
/// plus the sum of every particle contact's forces and torques this step, which
/// times the largest 1/m or 1/I and the kick's time is below it too.
pub(super) fn surely_finite(deferred: &Deferred) -> bool {
    let kick = deferred.owed_kick.dt * deferred.owed_kick.fraction;
    let load = deferred.gravity_bound + deferred.force_bound;
    load * deferred.largest_inverse * kick.max(1.0) < SURELY_FINITE
}

/// A chunk of the particles as the drift takes it: its number, their states, loads, the
/// loads' marks and owed kicks, where the candidate pairs were found and their spheres, whether they have
/// a wall contact open and their 1/m and 1/I, and the list of those the wall pass is to
/// visit (within the chunk).
pub(super) type DriftChunk<'a> = (
    usize,
    (
        (
            (
                (
                    (&'a mut [State], (&'a mut [Load], &'a mut [bool])),
                    &'a mut [bool],
                ),
                (&'a [Vec3], &'a mut [[f32; 4]]),
            ),
            (&'a [bool], &'a [(f64, f64)]),
        ),
        &'a mut Vec<u32>,
    ),
);

/// What the drift works on for one particle besides its state.
pub(super) struct DriftWork<'a> {
    load: &'a mut Load,
    /// Whether its load may hold more than gravity ([`super::Deferred::loaded`]).
    loaded: &'a mut bool,
    /// Whether its closing kick is owed ([`super::Deferred::owed`]).
    owed: &'a mut bool,
    /// Where it was when the candidate pairs were found.
    at: &'a Vec3,
    sphere: &'a mut [f32; 4],
    /// Whether it has a wall contact open ([`Bodies::walled`]).
    walled: bool,
    /// 1/m and 1/I ([`Bodies::inverses`]).
    inverse: (f64, f64),
}

/// How large a particle's numbers, or a bound on its next kick, may be for the kick
/// owed to it to be surely finite ([`surely_finite`]): twice it is still
/// far below the largest double (1.8·10³⁰⁸).
pub(super) const SURELY_FINITE: f64 = 1e300;

/// How many particles' states the drift asks for at a time ([`fetch_state`]), a block
/// ahead of the one it drifts.
const STATE_BLOCK: usize = 4;

/// How long an owed particle's velocity or spin may be ([`may_owe`]): its
/// size |x| + |y| + |z|, at most √3 times its length, is then far below
/// [`SURELY_FINITE`], and its squared length is a double.
pub(super) const SURELY_FINITE_LENGTH: f64 = 1e149;
