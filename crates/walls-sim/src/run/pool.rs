//! Where a run steps, and the pool's other threads kept at hand while it does.
//!
//! A run of many particles with more than one thread steps on one of rayon's threads
//! (its home), so that each pass of a step is split between the threads where it is
//! rather than handed to the pool from outside (docs/performance-history.md, "Eighth round";
//! `tests/pool.rs`). A soft-sphere step splits five or six passes, each of some tens of
//! microseconds at 10⁴ particles. Between them rayon puts a thread with nothing to do to
//! sleep, and waking it for the next pass costs a system call and the kernel's wake-up,
//! a large part of a pass on a virtual machine. So while the soft stepper runs, each of
//! the pool's other threads runs a helper: a job that takes rayon's work as it comes
//! (`rayon::yield_now`) and spins between, as an MPI rank polls.
//!
//! A helper ends when the run does, or after [`IDLE`] with nothing to do (a serial part
//! of the run, such as the candidate list's rebuild, or the pool busy elsewhere), and the
//! stepper asks for helpers again before its next step ([`Helpers::keep`]). Helpers are
//! jobs of the run's scope that any free thread takes, not one sent to each thread: a
//! thread of the pool blocked outside rayon does not hold the run, and a helper no other
//! thread has taken is taken by the home thread when it waits, which ends it at once, so
//! the stepper asks again. A thread already helping takes no second helper.
//!
//! The bound matters beyond the threads' time: a helper blocks the stack of the thread it
//! runs on. With runs nested in a parallel loop over runs on one pool, a helper that
//! waited only for its own run's end could sit above another run on its thread while
//! that run's helper sat above the first on the other: each waiting for the other's run.
//! With the bound, a helper with nothing to take ends, and the runs go on
//! (`tests/pool_nested.rs`; it did not hang without the bound either, so the bound rests
//! on this reasoning, not on a failure seen). A run nested under another's helper still
//! waits while that helper finds work.

use std::cell::Cell;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::{Duration, Instant};

/// How long a helper spins with nothing to do before it ends: longer than the gaps
/// between a step's parallel passes, shorter than a rebuild of the candidate list of
/// 10⁵ particles.
const IDLE: Duration = Duration::from_millis(1);

/// The pool's other threads, helping the run that holds this (on its home thread).
pub(super) struct Helpers<'a, 'scope> {
    scope: &'a rayon::Scope<'scope>,
    home: Option<usize>,
    shared: &'scope Shared,
}

/// What the home thread and its helpers share.
#[derive(Default)]
struct Shared {
    /// Set when the run ends, by a return or a panic.
    done: AtomicBool,
    /// Helpers asked for and not yet ended (those taken by the home thread, or by a
    /// thread already helping, end at once).
    pending: AtomicUsize,
}

impl Helpers<'_, '_> {
    /// Asks for a helper for each of the pool's other threads, unless some asked for
    /// before have not ended.
    pub(super) fn keep(&self) {
        let others = rayon::current_num_threads().saturating_sub(1);
        if others == 0 || self.shared.pending.load(Ordering::Acquire) > 0 {
            return;
        }
        self.shared.pending.store(others, Ordering::Release);
        let (home, shared) = (self.home, self.shared);
        for _ in 0..others {
            self.scope.spawn(move |_| {
                if rayon::current_thread_index() != home && !HELPING.replace(true) {
                    help(shared);
                    HELPING.set(false);
                }
                shared.pending.fetch_sub(1, Ordering::AcqRel);
            });
        }
    }
}

thread_local! {
    /// Whether this thread is running a helper (of any run): a helper that took another
    /// through `yield_now` would only sit on top of it.
    static HELPING: Cell<bool> = const { Cell::new(false) };
}

/// Takes the pool's jobs as they come until the run ends or nothing has come for
/// [`IDLE`].
fn help(shared: &Shared) {
    let mut last = Instant::now();
    while !shared.done.load(Ordering::Acquire) {
        if rayon::yield_now() == Some(rayon::Yield::Executed) {
            last = Instant::now();
        } else if last.elapsed() > IDLE {
            break;
        } else {
            std::hint::spin_loop();
        }
    }
}

/// Sets the run's end when dropped, so that its helpers stop even if it panics.
struct Done<'a>(&'a AtomicBool);

impl Drop for Done<'_> {
    fn drop(&mut self) {
        self.0.store(true, Ordering::Release);
    }
}

/// `body` run on a thread of rayon's pool, with the means to keep the pool's other
/// threads at hand, when `parallel`; else on this thread, without.
pub(super) fn on_the_pool<R: Send>(
    parallel: bool,
    body: impl FnOnce(Option<&Helpers>) -> R + Send,
) -> R {
    if !parallel {
        return body(None);
    }
    let shared = Shared::default();
    rayon::scope(|scope| {
        let helpers = Helpers {
            scope,
            home: rayon::current_thread_index(),
            shared: &shared,
        };
        let _done = Done(&shared.done);
        body(Some(&helpers))
    })
}
