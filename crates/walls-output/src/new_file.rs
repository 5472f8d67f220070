//! A new file being written in a folder before it is put in place: an unnamed one
//! (`O_TMPFILE`), which vanishes with the process whatever kills it, or, where the
//! filesystem lacks those, a named `.walls-XXXXXX` that a SIGINT, SIGTERM or SIGHUP
//! removes ([`crate::interrupt`]).

use crate::WriteError;
use crate::interrupt::{self, Registration};
use std::fs::File;
use std::io;
use std::os::fd::AsRawFd;
use std::os::unix::fs::OpenOptionsExt;
use std::path::Path;

/// The kind of new file the text is written to before it is put in place.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Temporary {
    /// Unnamed (`O_TMPFILE`) where the filesystem allows, else named.
    Unnamed,
    /// Named, `.walls-XXXXXX` in the file's folder.
    Named,
}

/// The new file being written.
#[derive(Debug)]
pub(crate) enum NewFile {
    /// An `O_TMPFILE` file: no name until it is complete.
    Unnamed(File),
    /// A `.walls-XXXXXX` file, removed if the write fails or a signal comes.
    Named(tempfile::NamedTempFile<(File, Registration)>),
}

/// The prefix of the temporary names.
const PREFIX: &str = ".walls-";

impl NewFile {
    /// A new file in `dir` with the permission bits `mode` (less the umask).
    pub(crate) fn create(dir: &Path, temporary: Temporary, mode: u32) -> io::Result<NewFile> {
        interrupt::install();
        if temporary == Temporary::Named {
            return NewFile::named(dir, mode);
        }
        let unnamed = rustix::fs::open(
            dir,
            rustix::fs::OFlags::TMPFILE | rustix::fs::OFlags::WRONLY | rustix::fs::OFlags::CLOEXEC,
            rustix::fs::Mode::from_raw_mode(mode),
        );
        // Linking it into place goes through /proc/self/fd; without either, a named file.
        if let Ok(fd) = unnamed
            && Path::new("/proc/self/fd").is_dir()
        {
            return Ok(NewFile::Unnamed(File::from(fd)));
        }
        NewFile::named(dir, mode)
    }

    /// A named temporary file in `dir`, registered for removal on a signal.
    fn named(dir: &Path, mode: u32) -> io::Result<NewFile> {
        tempfile::Builder::new()
            .prefix(PREFIX)
            .make_in(dir, |path| {
                let file = std::fs::OpenOptions::new()
                    .write(true)
                    .create_new(true)
                    .mode(mode)
                    .open(path)?;
                Ok((file, interrupt::remove_on_signal(path)))
            })
            .map(NewFile::Named)
    }

    /// The file to write.
    pub(crate) fn file(&mut self) -> &mut File {
        match self {
            NewFile::Unnamed(file) => file,
            NewFile::Named(tmp) => &mut tmp.as_file_mut().0,
        }
    }

    /// Puts the complete file in the place of `target` (in `dir`), replacing it.
    pub(crate) fn rename_over(self, dir: &Path, target: &Path) -> Result<(), WriteError> {
        match self {
            NewFile::Named(tmp) => {
                tmp.persist(target).map_err(|e| e.error)?;
            }
            NewFile::Unnamed(file) => {
                let fd = format!("/proc/self/fd/{}", file.as_raw_fd());
                let linked = tempfile::Builder::new()
                    .prefix(PREFIX)
                    .make_in(dir, |path| {
                        rustix::fs::linkat(
                            rustix::fs::CWD,
                            fd.as_str(),
                            rustix::fs::CWD,
                            path,
                            rustix::fs::AtFlags::SYMLINK_FOLLOW,
                        )?;
                        Ok(interrupt::remove_on_signal(path))
                    })?;
                linked.persist(target).map_err(|e| e.error)?;
            }
        }
        Ok(())
    }

    /// Gives the complete file the name `target`, which must not exist: a file made
    /// there meanwhile is [`crate::Refusal::Changed`], and stays as it is.
    pub(crate) fn link_new(self, target: &Path) -> Result<(), WriteError> {
        let placed = match self {
            NewFile::Named(tmp) => tmp.persist_noclobber(target).map(drop).map_err(|e| e.error),
            NewFile::Unnamed(file) => {
                let fd = format!("/proc/self/fd/{}", file.as_raw_fd());
                rustix::fs::linkat(
                    rustix::fs::CWD,
                    fd.as_str(),
                    rustix::fs::CWD,
                    target,
                    rustix::fs::AtFlags::SYMLINK_FOLLOW,
                )
                .map_err(io::Error::from)
            }
        };
        match placed {
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists => {
                Err(crate::Refusal::Changed.into())
            }
            other => Ok(other?),
        }
    }
}
