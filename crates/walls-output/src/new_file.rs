//! A new file being written in a folder before it is put in place: an unnamed one
//! (`O_TMPFILE`), which vanishes with the process whatever kills it, or, where the
//! filesystem lacks those, a named `.walls-XXXXXXXX` that is removed if it is not put in
//! place, and that a SIGINT, SIGTERM or SIGHUP removes ([`crate::interrupt`]).

use crate::dir::Dir;
use crate::interrupt::{self, Registration};
use crate::{Refusal, WriteError};
use std::ffi::{OsStr, OsString};
use std::fs::File;
use std::io;
use std::sync::atomic::{AtomicU64, Ordering};

/// The kind of new file the text is written to before it is put in place.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Temporary {
    /// Unnamed (`O_TMPFILE`) where the filesystem allows, else named.
    Unnamed,
    /// Named, `.walls-XXXXXXXX` in the file's folder.
    Named,
}

/// The new file being written.
#[derive(Debug)]
pub(crate) enum NewFile {
    /// An `O_TMPFILE` file: no name until it is complete.
    Unnamed(File),
    /// A named file, removed unless put in place.
    Named(Named),
}

/// A named new file.
#[derive(Debug)]
pub(crate) struct Named {
    file: File,
    dir: Dir,
    name: OsString,
    /// Whether it has been put in place (then it is not removed).
    placed: bool,
    _removal: Registration,
}

impl Drop for Named {
    fn drop(&mut self) {
        if !self.placed {
            let _ = self.dir.unlink(&self.name);
        }
    }
}

/// The prefix of the temporary names.
const PREFIX: &str = ".walls-";

/// A name for a temporary file, not likely to be taken (a taken one is tried again).
fn temporary_name() -> OsString {
    static COUNT: AtomicU64 = AtomicU64::new(0);
    let n = COUNT.fetch_add(1, Ordering::Relaxed);
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.subsec_nanos());
    let mixed = (u64::from(std::process::id()) << 32) ^ u64::from(nanos) ^ n.rotate_left(17);
    format!("{PREFIX}{:08x}", mixed & 0xffff_ffff).into()
}

/// Runs `make` with fresh temporary names until one is free.
fn with_free_name<T>(mut make: impl FnMut(&OsStr) -> io::Result<T>) -> io::Result<(T, OsString)> {
    loop {
        let name = temporary_name();
        match make(&name) {
            Ok(made) => return Ok((made, name)),
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists => {}
            Err(e) => return Err(e),
        }
    }
}

impl NewFile {
    /// A new file in `dir` with the permission bits `mode` (less the umask).
    pub(crate) fn create(dir: &Dir, temporary: Temporary, mode: u32) -> io::Result<NewFile> {
        interrupt::install();
        if temporary == Temporary::Unnamed
            && let Some(file) = dir.unnamed(mode)
        {
            return Ok(NewFile::Unnamed(file));
        }
        let (file, name) = with_free_name(|name| dir.create(name, mode))?;
        Ok(NewFile::Named(Named {
            file,
            dir: dir.clone(),
            _removal: interrupt::remove_on_signal(&dir.shown_name(&name)),
            name,
            placed: false,
        }))
    }

    /// The file to write.
    pub(crate) fn file(&mut self) -> &mut File {
        match self {
            NewFile::Unnamed(file) => file,
            NewFile::Named(named) => &mut named.file,
        }
    }

    /// Puts the complete file in the place of `target` in `dir`, replacing it.
    pub(crate) fn rename_over(self, dir: &Dir, target: &OsStr) -> Result<(), WriteError> {
        match self {
            NewFile::Named(mut named) => {
                dir.rename(&named.name, target)?;
                named.placed = true;
            }
            NewFile::Unnamed(file) => {
                let ((), name) = with_free_name(|name| dir.link_open(&file, name))?;
                let _removal = interrupt::remove_on_signal(&dir.shown_name(&name));
                if let Err(e) = dir.rename(&name, target) {
                    let _ = dir.unlink(&name);
                    return Err(e.into());
                }
            }
        }
        Ok(())
    }

    /// Gives the complete file the name `target` in `dir`, which must not exist: a file
    /// made there meanwhile is [`Refusal::Changed`], and stays as it is.
    pub(crate) fn link_new(self, dir: &Dir, target: &OsStr) -> Result<(), WriteError> {
        let placed = match &self {
            NewFile::Unnamed(file) => dir.link_open(file, target),
            NewFile::Named(named) => dir.link(&named.name, target),
        };
        match placed {
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists => Err(Refusal::Changed.into()),
            Err(e) => Err(e.into()),
            // A named file's temporary name goes when it is dropped.
            Ok(()) => Ok(()),
        }
    }
}
