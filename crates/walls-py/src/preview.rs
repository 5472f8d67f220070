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
    m.add_function(wrap_pyfunction!(_preview, m)?)
}

/// The most frames a page has, as `walls-sim preview --frames` allows.
const MOST_FRAMES: i128 = 10_000;

/// The page of the walls file `text` over times 0 to `until` in `frames` frames, with the
/// particles of `radii` and `colors` at `times` (`positions`: three native doubles per
/// particle per time, time after time), interpolated between them; no particles when
/// `radii` is empty. A walls file with errors raises `WallsError` with them, as does a
/// scene or particle with a number the page cannot draw.
#[pyfunction]
#[pyo3(signature = (text, radii, colors, times, positions, until, frames))]
fn _preview(
    py: Python<'_>,
    text: &Bound<'_, PyAny>,
    radii: Vec<f64>,
    colors: Vec<i64>,
    times: Vec<f64>,
    positions: &[u8],
    until: &Bound<'_, PyAny>,
    frames: &Bound<'_, PyAny>,
) -> PyResult<String> {
    let until = args::number(until, &"until")?;
    let frames = args::integer(frames, &"frames", 1..=MOST_FRAMES)? as usize;
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
    let doubles: Vec<f64> = positions
        .chunks_exact(8)
        .map(|b| f64::from_ne_bytes(b.try_into().expect("8 bytes")))
        .collect();
    let particles = (!radii.is_empty()).then(|| Particles {
        frames: doubles
            .chunks_exact(3 * radii.len())
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
    });
    let mut page = Vec::new();
    py.detach(|| html::write(&mut page, &checked.scene, particles.as_ref(), until, frames))
        .map_err(|e| diagnostics::plain(py, format!("the preview cannot be drawn: {e}")))?;
    String::from_utf8(page).map_err(|e| diagnostics::plain(py, e.to_string()))
}
