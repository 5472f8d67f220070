//! Ctrl-C and `kill` (SIGINT, SIGTERM, SIGHUP) without leaving a mess: the new files
//! the writer has not yet put in place go with the process.
//!
//! A thread waits for the signals (signal-hook's iterator; no code runs in the signal
//! handler itself). When one comes:
//!
//! * a command that can stop cleanly (a run writing its outputs) has called
//!   [`install_graceful`]: the first signal only sets the flag it polls with
//!   [`stop_requested`], so that it finishes the rows it is writing and exits with status
//!   1; a second signal exits at once, as below;
//! * otherwise ([`install`]) the files registered with [`remove_on_signal`] (temporary
//!   files a command writes before renaming them into place) are removed, whatever the
//!   command is doing, and the process exits with status 128 + the signal's number, as a
//!   shell reports a process the signal killed.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Mutex, MutexGuard, Once};

use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
use signal_hook::iterator::Signals;

static TEMP: Mutex<BTreeSet<PathBuf>> = Mutex::new(BTreeSet::new());
static STOP: AtomicBool = AtomicBool::new(false);
static GRACEFUL: AtomicBool = AtomicBool::new(false);
static INSTALLED: Once = Once::new();

/// Installs the handling: a signal removes the registered files and exits.
pub fn install() {
    INSTALLED.call_once(|| {
        // Registration fails only for a forbidden signal, which these are not; if it ever
        // did, the default action (terminate) stays.
        let Ok(mut signals) = Signals::new([SIGINT, SIGTERM, SIGHUP]) else {
            return;
        };
        std::thread::spawn(move || {
            for signal in signals.forever() {
                if GRACEFUL.load(Ordering::SeqCst) && !STOP.swap(true, Ordering::SeqCst) {
                    continue;
                }
                for path in temp().iter() {
                    let _ = std::fs::remove_file(path);
                }
                std::process::exit(128 + signal);
            }
        });
    });
}

/// Installs the handling for a command that stops cleanly: the first signal sets the
/// flag [`stop_requested`] reads; the second exits.
pub fn install_graceful() {
    GRACEFUL.store(true, Ordering::SeqCst);
    install();
}

/// Whether a signal asked the command to stop (after [`install_graceful`]).
pub fn stop_requested() -> bool {
    STOP.load(Ordering::Relaxed)
}

fn temp() -> MutexGuard<'static, BTreeSet<PathBuf>> {
    TEMP.lock().unwrap_or_else(|e| e.into_inner())
}

/// A file removed on a signal until this is dropped (drop it once the file has been
/// renamed into place, or removed).
#[derive(Debug)]
pub struct Registration {
    path: PathBuf,
}

/// Registers `path` for removal when a signal comes.
pub fn remove_on_signal(path: &Path) -> Registration {
    temp().insert(path.to_path_buf());
    Registration {
        path: path.to_path_buf(),
    }
}

impl Drop for Registration {
    fn drop(&mut self) {
        temp().remove(&self.path);
    }
}
