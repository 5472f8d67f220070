//! ParaView collections (`.pvd`): a movie as one `.vtp` per frame ([`crate::vtk`]) and
//! the collection that lists them with their times, which ParaView opens as one dataset
//! with a time slider.
//!
//! `movie.pvd` gets its frames in a folder beside it named after its stem:
//! `movie/movie_000000.vtp`, `movie/movie_000001.vtp`… Each `<DataSet>` of the
//! collection names its frame's file relative to the `.pvd` and gives the frame's time
//! as `timestep`, in the collection's time unit (the same as the frames' `TIME`).

use crate::{MovieFrame, escape};
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use walls_geometry::units::Scale;

/// The frames' files of the collection at `path`, relative to its folder: for
/// `movie.pvd`, `movie/movie_000000.vtp` and on, one per frame.
pub fn frame_files(path: &Path, frames: usize) -> Vec<PathBuf> {
    let stem = path
        .file_stem()
        .map_or_else(|| "movie".to_string(), |s| s.to_string_lossy().into_owned());
    (0..frames)
        .map(|k| Path::new(&stem).join(format!("{stem}_{k:06}.vtp")))
        .collect()
}

/// Writes the collection `path` of `frames` in `scale`'s units: the folder of frames
/// beside it (made if missing) with one `.vtp` each, then the `.pvd`. `written` is told
/// each frame's number once its file is written. A frame with a number that cannot be
/// drawn ([`crate::finite::check`]) is refused before any folder or file is made.
pub fn write_file(
    path: &Path,
    frames: &[MovieFrame],
    scale: &Scale,
    mut written: impl FnMut(usize),
) -> io::Result<()> {
    crate::finite::check(frames)?;
    let dir = path.parent().unwrap_or(Path::new(""));
    let files = frame_files(path, frames.len());
    if let Some(folder) = files.first().and_then(|f| f.parent()) {
        std::fs::create_dir_all(dir.join(folder))?;
    }
    for (k, (frame, file)) in frames.iter().zip(&files).enumerate() {
        let mut out = io::BufWriter::new(std::fs::File::create(dir.join(file))?);
        crate::vtk::write(&mut out, &frame.walls, &frame.particles, frame.t, scale)?;
        out.flush()?;
        written(k);
    }
    let mut out = io::BufWriter::new(std::fs::File::create(path)?);
    write(&mut out, frames, &files, scale)?;
    out.flush()
}

/// Writes the `.pvd` listing `files` (one per frame, relative to the `.pvd`) at the
/// frames' times in `scale`'s time unit (checked by [`write_file`]).
fn write(
    out: &mut impl Write,
    frames: &[MovieFrame],
    files: &[PathBuf],
    scale: &Scale,
) -> io::Result<()> {
    writeln!(out, r#"<?xml version="1.0"?>"#)?;
    writeln!(
        out,
        r#"<VTKFile type="Collection" version="1.0" byte_order="LittleEndian">"#
    )?;
    writeln!(out, "  <Collection>")?;
    for (frame, file) in frames.iter().zip(files) {
        // Forward slashes on every system: the file is read anywhere.
        let name: Vec<String> = file
            .components()
            .map(|c| c.as_os_str().to_string_lossy().into_owned())
            .collect();
        writeln!(
            out,
            r#"    <DataSet timestep="{:e}" group="" part="0" file="{}"/>"#,
            scale.time.of(frame.t),
            escape(&name.join("/"))
        )?;
    }
    writeln!(out, "  </Collection>")?;
    writeln!(out, "</VTKFile>")
}
