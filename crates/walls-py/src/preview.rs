//! `walls.preview`: the interactive page of `walls-sim preview --out page.html`
//! ([`walls_preview::html::write`]) of a walls file's text, with particles along their
//! trajectories (a `walls.run` result's outputs, or one set of particles), as a string.

use crate::{api, args, diagnostics};
use nalgebra::Vector3;
use pyo3::prelude::*;
use walls_model::Options;
use walls_preview::html::{self, Particles};

/// Adds the functions of this file to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("MOVIE_FRAMES", walls_cli::movie::MOVIE_FRAMES)?;
    m.add_function(wrap_pyfunction!(_read_walls, m)?)?;
    m.add_function(wrap_pyfunction!(_preview, m)?)
}

/// The bytes of the walls file at `path`, read as the tools read one (at most
/// `walls_cli::input::MAX_FILE_BYTES`); a path that is not a regular file (a device, a
/// FIFO, a folder) is refused before it is opened. Errors raise `WallsError` naming the
/// path.
#[pyfunction]
fn _read_walls<'py>(
    py: Python<'py>,
    #[pyo3(from_py_with = args::path)] path: std::path::PathBuf,
) -> PyResult<Bound<'py, pyo3::types::PyBytes>> {
    let name = path.display().to_string();
    let read = py.detach(|| {
        let regular = std::fs::metadata(&path).map_err(|e| format!("cannot read {name}: {e}"))?;
        if !regular.is_file() {
            return Err(format!("cannot read {name}: it is not a regular file"));
        }
        let file = std::fs::File::open(&path).map_err(|e| format!("cannot read {name}: {e}"))?;
        walls_cli::input::read_all(file, &name)
    });
    let bytes = read.map_err(|e| diagnostics::plain(py, e))?;
    Ok(pyo3::types::PyBytes::new(py, &bytes))
}

/// Particles along their trajectories as Python hands them over: each one's radius and
/// colour, the times, and the positions (three native doubles per particle per time,
/// time after time).
type Given<'a> = (Vec<f64>, Vec<i64>, Vec<f64>, &'a [u8]);

/// The page of the walls file `text` over times 0 to `until` in `frames` frames, with
/// `particles` (if any) interpolated between their times. A walls file with errors
/// raises `WallsError` with them, as does a scene or particle with a number the page
/// cannot draw.
#[pyfunction]
#[pyo3(signature = (text, particles, until, frames))]
fn _preview(
    py: Python<'_>,
    text: &Bound<'_, PyAny>,
    particles: Option<Given<'_>>,
    until: &Bound<'_, PyAny>,
    frames: &Bound<'_, PyAny>,
) -> PyResult<String> {
    let until = args::number(until, &"until")?;
    let frames =
        args::integer(frames, &"frames", 1..=walls_cli::movie::MOST_FRAMES as i128)? as usize;
    let checked = api::check(py, args::text(text)?, &Options::default());
    let errors = checked.errors();
    if !errors.is_empty() {
        return Err(diagnostics::error(
            py,
            "the walls file has errors",
            &checked.text,
            &errors,
        ));
    }
    let particles = particles.map(|(radii, colors, times, positions)| {
        let doubles: Vec<f64> = positions
            .chunks_exact(8)
            .map(|b| f64::from_ne_bytes(b.try_into().expect("8 bytes")))
            .collect();
        Particles {
            frames: doubles
                .chunks_exact(3 * radii.len().max(1))
                .map(|frame| {
                    frame
                        .chunks_exact(3)
                        .map(|v| Vector3::new(v[0], v[1], v[2]))
                        .collect()
                })
                .collect(),
            radii,
            colors,
            times,
        }
    });
    let mut page = Vec::new();
    py.detach(|| html::write(&mut page, &checked.scene, particles.as_ref(), until, frames))
        .map_err(|e| diagnostics::plain(py, format!("the preview cannot be drawn: {e}")))?;
    String::from_utf8(page).map_err(|e| diagnostics::plain(py, e.to_string()))
}
