//! Memory asked for ahead of its use ([`fetch`]): the soft run's passes read each
//! particle's state, load and contact record where the pair list or the particles'
//! order sends them, and at 10⁵ particles those reads wait on memory far more than on
//! arithmetic (docs/performance.md, "Asking for memory ahead"). A pass that knows what
//! it will read a few items on asks for it now, and the wait overlaps its work; with
//! fewer particles ([`AHEAD_FROM`]) none asks. The drift asks for the states a block on
//! and the loads a pair touched, the pairs' test with a size mix for the partners'
//! spheres a block on, the forces for their contacts' states, loads and records a few
//! contacts on.

use super::State;
use std::mem::offset_of;
use walls_geometry::Particle;

/// From how many particles the soft run asks for memory ahead ([`crate::run::Ahead`]'s
/// default, checked there): with fewer, what a step
/// reads (some 400 bytes a particle) stays in the processor's caches from one step to
/// the next, and asking costs instructions that save nothing (asking always, the 10⁴
/// drop took 15 % more instructions, the cup 9 %).
pub(super) const AHEAD_FROM: usize = 1 << 15;

const _: () = assert!(AHEAD_FROM == 32_768);

/// Asks the processor to bring the cache line holding `x` into every level of its
/// cache, without waiting for it: a hint, with no effect on what the program computes
/// (no read, no fault). Nothing on processors other than x86-64.
#[inline(always)]
pub(super) fn fetch<T>(x: &T) {
    #[cfg(target_arch = "x86_64")]
    safe_arch::prefetch_t0(x);
    #[cfg(not(target_arch = "x86_64"))]
    let _ = x;
}

/// [`fetch`] for every cache line of a particle's state, wherever it lies: four of its
/// fields, none more than a line (64 bytes) past the one before, the first at its start
/// and the last in its last 8 bytes ([`STATE_LINES`]), so that each line the state
/// shares holds one (a state begins on a multiple of 8 bytes, as lines do).
#[inline(always)]
pub(super) fn fetch_state(s: &State) {
    fetch(s);
    fetch(&s.particle.spin);
    fetch(&s.alpha);
    fetch(&s.member);
}

/// Where in a state the fields [`fetch_state`] asks for lie, checked when compiled.
const STATE_LINES: [usize; 4] = [
    0,
    offset_of!(State, particle) + offset_of!(Particle, spin),
    offset_of!(State, alpha),
    offset_of!(State, member),
];

const _: () = {
    let size = size_of::<State>();
    assert!(align_of::<State>() == 8);
    let mut k = 1;
    while k < STATE_LINES.len() {
        assert!(STATE_LINES[k] > STATE_LINES[k - 1] && STATE_LINES[k] - STATE_LINES[k - 1] <= 64);
        k += 1;
    }
    assert!(STATE_LINES[3] + 8 >= size);
};
