//! `walls.read_ss` and `walls.write_ss`: pkdgrav `.ss` files through the run's own reader
//! and writer (`walls_sim::io::particles`), and particles as NumPy records. Python writes
//! the file `_ss_bytes` makes through `_write` (`crate::write`, `walls-output`).
//!
//! Python sees particles as records of `walls.SS_DTYPE` (`python/walls/_analysis.py`):
//! `mass`, `radius`, `pos[3]`, `vel[3]`, `spin[3]` as native doubles, then `color` and
//! `org_idx` as native 32-bit integers, 96 bytes packed, the fields of a `.ss` record in
//! its order. Here they cross as those bytes ([`records`], [`particles`]); Python wraps
//! them with `numpy.frombuffer`, so this module needs no NumPy.

use crate::{args, diagnostics};
use nalgebra::Vector3;
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyList};
use walls_geometry::Particle;
use walls_sim::io::particles as io;

/// Bytes of one record of `walls.SS_DTYPE`.
pub const RECORD: usize = 96;

/// Adds the functions of this file to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(_read_ss, m)?)?;
    m.add_function(wrap_pyfunction!(_ss_bytes, m)?)?;
    Ok(())
}

/// `particles` as records of `walls.SS_DTYPE`.
pub fn records(particles: &[impl AsRef<Particle>]) -> Vec<u8> {
    let mut out = Vec::with_capacity(RECORD * particles.len());
    for p in particles.iter().map(AsRef::as_ref) {
        let doubles = [p.mass, p.radius]
            .into_iter()
            .chain(p.pos.iter().copied())
            .chain(p.vel.iter().copied())
            .chain(p.spin.iter().copied());
        for x in doubles {
            out.extend_from_slice(&x.to_ne_bytes());
        }
        out.extend_from_slice(&p.color.to_ne_bytes());
        out.extend_from_slice(&p.index.to_ne_bytes());
    }
    out
}

/// The particles of records of `walls.SS_DTYPE`, each checked as the `.ss` reader checks
/// a file's (positive mass and radius, finite numbers); a refusal names the record.
fn particles(bytes: &[u8]) -> Result<Vec<Particle>, String> {
    if !bytes.len().is_multiple_of(RECORD) {
        return Err(format!(
            "{} bytes are not whole records of {RECORD}",
            bytes.len()
        ));
    }
    let f64_at =
        |r: &[u8], i: usize| f64::from_ne_bytes(r[8 * i..8 * i + 8].try_into().expect("8 bytes"));
    let i32_at =
        |r: &[u8], at: usize| i32::from_ne_bytes(r[at..at + 4].try_into().expect("4 bytes"));
    let vector =
        |r: &[u8], i: usize| Vector3::new(f64_at(r, i), f64_at(r, i + 1), f64_at(r, i + 2));
    bytes
        .chunks_exact(RECORD)
        .enumerate()
        .map(|(k, r)| {
            let p = Particle {
                mass: f64_at(r, 0),
                radius: f64_at(r, 1),
                pos: vector(r, 2),
                vel: vector(r, 5),
                spin: vector(r, 8),
                color: i32_at(r, 88),
                index: i32_at(r, 92),
            };
            io::check(&p)
                .map(|()| p)
                .map_err(|says| format!("particle {k}: {says}"))
        })
        .collect()
}

/// Reads the pkdgrav `.ss` file at `path` (standard or reduced) as `walls-sim run
/// --particles` reads it: its header's time, its particles as records of
/// `walls.SS_DTYPE`, and the warnings about its numbers (subnormal values, W701), by the
/// one `.ss` file reader ([`io::read_ss_file`]). A path that is not a regular file (a
/// device, a FIFO, a folder) is refused before it is read, and a file whose length is not
/// what its header's particle count needs before its records are read; these, a file
/// that cannot be read, or one that is not a `.ss` file pkdgrav would read, raise
/// `WallsError` naming the path and the byte.
#[pyfunction]
fn _read_ss<'py>(
    py: Python<'py>,
    #[pyo3(from_py_with = args::path)] path: std::path::PathBuf,
) -> PyResult<(f64, Bound<'py, PyBytes>, Bound<'py, PyList>)> {
    let name = path.display().to_string();
    let read = py.detach(|| io::read_ss_file(&path));
    let (time, read) = read.map_err(|e| diagnostics::plain(py, e.to_string()))?;
    let warnings: Vec<String> = read
        .warnings
        .iter()
        .map(|w| format!("{name}: {w}"))
        .collect();
    Ok((
        time,
        PyBytes::new(py, &records(&read.particles)),
        PyList::new(py, warnings)?,
    ))
}

/// The pkdgrav `.ss` file of `records` (of `walls.SS_DTYPE`) with the header's `time`,
/// made by the one `.ss` writer, which [`_read_ss`] reads back exactly (`walls.write_ss`
/// writes it to its file in Python). Particles the reader would refuse, and a time that
/// is not finite, are refused: `WallsError` naming the particle, `ValueError` the time.
#[pyfunction]
fn _ss_bytes<'py>(
    py: Python<'py>,
    time: &Bound<'py, PyAny>,
    records: &[u8],
) -> PyResult<Bound<'py, PyBytes>> {
    let time = args::number(time, &"time")?;
    let particles = particles(records).map_err(|e| diagnostics::plain(py, e))?;
    if i32::try_from(particles.len()).is_err() {
        return Err(diagnostics::plain(
            py,
            format!(
                "{} particles: a .ss file holds at most 2147483647",
                particles.len()
            ),
        ));
    }
    Ok(PyBytes::new(py, &io::write_ss(time, &particles)))
}
