//! ParaView collections (`.pvd`): a movie as one `.vtp` per frame ([`crate::vtk`]) and
//! the collection that lists them with their times, which ParaView opens as one dataset
//! with a time slider.
//!
//! `movie.pvd` gets its frames in a folder beside it named after its stem:
//! `movie/movie_000000.vtp`, `movie/movie_000001.vtp`… Each `<DataSet>` of the
//! collection names its frame's file relative to the `.pvd` and gives the frame's time
//! as `timestep`, in the collection's time unit (the same as the frames' `TIME`).
//! [`frame_files`] names the frames, [`crate::vtk::write`] writes each, and [`write`] the
//! collection; `walls-sim preview --out movie.pvd` writes the files.

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

/// Writes the `.pvd` listing `files` (one per frame, relative to the `.pvd`) at the
/// frames' times in `scale`'s time unit. A frame with a number that cannot be drawn
/// ([`crate::finite::check`]) is refused before anything is written.
pub fn write(
    out: &mut impl Write,
    frames: &[MovieFrame],
    files: &[PathBuf],
    scale: &Scale,
) -> io::Result<()> {
    crate::finite::check(frames)?;
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
