//! `walls-sim scene`: prints the resolved scene as JSON (docs/spec.md §2): every wall
//! with the effective value of every token, in pkdgrav units; diagnostics go to standard
//! error.

use super::error;
use crate::{ContactModel, check_bytes, input};
use std::io::Write;
use walls_diagnostics::Severity;
use walls_diagnostics::render::{self, FileReport};
use walls_model::Options;

/// Prints the scene of the walls file at `path` (`-`: standard input) as JSON, with each
/// wall's position at `time` if given, checked in `mode`; the exit status.
pub fn run(path: &str, time: Option<f64>, mode: ContactModel) -> i32 {
    let read = input::read(path);
    let bytes = match read.bytes {
        Ok(bytes) => bytes,
        Err(e) => return error(e),
    };
    let options = Options {
        mode,
        ..Options::default()
    };
    let checked = check_bytes(bytes, &options);
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    let written = walls_geometry::json::write_scene(&mut out, &checked.scene, &checked.text, time)
        .and_then(|()| out.flush());
    if let Err(e) = written {
        if e.kind() != std::io::ErrorKind::BrokenPipe {
            crate::errln!("walls-sim: error: cannot write output: {e}");
        }
        return 2;
    }
    let report = FileReport {
        path: &read.name,
        source: &checked.text,
        diagnostics: &checked.diagnostics,
    };
    let color = crate::console::color_stderr();
    // Standard error is only for people here; if it is gone there is nobody to tell.
    crate::console::err_data(|err| render::human(err, &report, color));
    if checked
        .diagnostics
        .iter()
        .any(|d| d.severity == Severity::Error)
    {
        1
    } else {
        0
    }
}
