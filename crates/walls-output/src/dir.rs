//! A folder held open ([`Dir`]): every file the writer looks at, makes, links or renames
//! in it is named relative to the folder as it was opened (`*at` system calls), so that
//! renaming the folder, or putting a link in its place, while a command runs does not move
//! what the command writes; names are single components, never followed through a link.

use crate::{FileKind, Stamp};
use rustix::fs::{AtFlags, Mode, OFlags};
use std::ffi::{OsStr, OsString};
use std::fs::File;
use std::io;
use std::os::fd::{AsFd, AsRawFd, OwnedFd};
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// A folder, open.
#[derive(Debug, Clone)]
pub(crate) struct Dir {
    fd: Arc<OwnedFd>,
    /// Its path as the user sees it, for messages.
    shown: PathBuf,
}

impl Dir {
    /// Opens the folder at `path` (following links: the user named it).
    pub(crate) fn open(path: &Path) -> io::Result<Dir> {
        let path = if path.as_os_str().is_empty() {
            Path::new(".")
        } else {
            path
        };
        let fd = rustix::fs::open(
            path,
            OFlags::RDONLY | OFlags::DIRECTORY | OFlags::CLOEXEC,
            Mode::empty(),
        )?;
        Ok(Dir {
            fd: Arc::new(fd),
            shown: path.to_path_buf(),
        })
    }

    /// The folder's path, as messages show it.
    pub(crate) fn shown(&self) -> &Path {
        &self.shown
    }

    /// The path of `name` in it, as messages show it: the name alone in the current
    /// folder.
    pub(crate) fn shown_name(&self, name: &OsStr) -> PathBuf {
        crate::path_in(&self.shown, Path::new(name))
    }

    /// The sub-folder `name`, opened without following a link (`None`: there is none, or
    /// made when `make`); a link, or anything but a folder, in its place is an error
    /// (`ELOOP`, `ENOTDIR`).
    pub(crate) fn sub(&self, name: &OsStr, make: bool) -> io::Result<Option<Dir>> {
        let open = || {
            rustix::fs::openat(
                self.fd.as_fd(),
                name,
                OFlags::RDONLY | OFlags::DIRECTORY | OFlags::NOFOLLOW | OFlags::CLOEXEC,
                Mode::empty(),
            )
        };
        let fd = match open() {
            Ok(fd) => fd,
            Err(rustix::io::Errno::NOENT) if make => {
                match rustix::fs::mkdirat(self.fd.as_fd(), name, Mode::from_raw_mode(0o777)) {
                    Ok(()) | Err(rustix::io::Errno::EXIST) => {}
                    Err(e) => return Err(e.into()),
                }
                open()?
            }
            Err(rustix::io::Errno::NOENT) => return Ok(None),
            Err(e) => return Err(e.into()),
        };
        Ok(Some(Dir {
            fd: Arc::new(fd),
            shown: self.shown_name(name),
        }))
    }

    /// What is at `name`, not following a link (`None`: nothing).
    pub(crate) fn stat(&self, name: &OsStr) -> io::Result<Option<Stamp>> {
        match rustix::fs::statat(self.fd.as_fd(), name, AtFlags::SYMLINK_NOFOLLOW) {
            Ok(st) => Ok(Some(Stamp::from_stat(&st))),
            Err(rustix::io::Errno::NOENT) => Ok(None),
            Err(e) => Err(e.into()),
        }
    }

    /// Whether the user may write the file `name` (`access(2)`).
    pub(crate) fn may_write(&self, name: &OsStr) -> bool {
        rustix::fs::accessat(
            self.fd.as_fd(),
            name,
            rustix::fs::Access::WRITE_OK,
            AtFlags::empty(),
        )
        .is_ok()
    }

    /// Opens the regular file `name` with `access` (`RDONLY`, or `WRONLY | APPEND`), not
    /// through a link and without blocking on a FIFO swapped in; it must be the file
    /// `stamp` says.
    pub(crate) fn open_existing(
        &self,
        name: &OsStr,
        stamp: &Stamp,
        access: OFlags,
    ) -> io::Result<File> {
        let fd = rustix::fs::openat(
            self.fd.as_fd(),
            name,
            access | OFlags::NOFOLLOW | OFlags::NONBLOCK | OFlags::CLOEXEC,
            Mode::empty(),
        )?;
        let now = Stamp::from_stat(&rustix::fs::fstat(&fd)?);
        if now.kind() != FileKind::Regular || now.identity() != stamp.identity() {
            return Err(io::Error::other("it changed while it was being written"));
        }
        Ok(File::from(fd))
    }

    /// An unnamed new file (`O_TMPFILE`) in the folder, with the permission bits `mode`
    /// less the umask; `None` where the filesystem has none, or where it could not be
    /// linked into place (no `/proc`).
    pub(crate) fn unnamed(&self, mode: u32) -> Option<File> {
        let fd = rustix::fs::openat(
            self.fd.as_fd(),
            ".",
            OFlags::TMPFILE | OFlags::WRONLY | OFlags::CLOEXEC,
            Mode::from_raw_mode(mode),
        )
        .ok()?;
        Path::new("/proc/self/fd").is_dir().then(|| File::from(fd))
    }

    /// A new file named `name`, which must not exist, with the permission bits `mode` less
    /// the umask.
    pub(crate) fn create(&self, name: &OsStr, mode: u32) -> io::Result<File> {
        let fd = rustix::fs::openat(
            self.fd.as_fd(),
            name,
            OFlags::WRONLY | OFlags::CREATE | OFlags::EXCL | OFlags::NOFOLLOW | OFlags::CLOEXEC,
            Mode::from_raw_mode(mode),
        )?;
        Ok(File::from(fd))
    }

    /// Gives the open (unnamed) `file` the name `name` here, which must not exist.
    pub(crate) fn link_open(&self, file: &File, name: &OsStr) -> io::Result<()> {
        let fd = format!("/proc/self/fd/{}", file.as_raw_fd());
        rustix::fs::linkat(
            rustix::fs::CWD,
            fd.as_str(),
            self.fd.as_fd(),
            name,
            AtFlags::SYMLINK_FOLLOW,
        )?;
        Ok(())
    }

    /// Gives the file `from` the name `to` too, which must not exist.
    pub(crate) fn link(&self, from: &OsStr, to: &OsStr) -> io::Result<()> {
        rustix::fs::linkat(self.fd.as_fd(), from, self.fd.as_fd(), to, AtFlags::empty())?;
        Ok(())
    }

    /// Renames `from` to `to`, replacing what `to` names.
    pub(crate) fn rename(&self, from: &OsStr, to: &OsStr) -> io::Result<()> {
        rustix::fs::renameat(self.fd.as_fd(), from, self.fd.as_fd(), to)?;
        Ok(())
    }

    /// Removes the name `name`.
    pub(crate) fn unlink(&self, name: &OsStr) -> io::Result<()> {
        rustix::fs::unlinkat(self.fd.as_fd(), name, AtFlags::empty())?;
        Ok(())
    }

    /// The names in the folder.
    pub(crate) fn names(&self) -> io::Result<Vec<OsString>> {
        let fd = rustix::fs::openat(
            self.fd.as_fd(),
            ".",
            OFlags::RDONLY | OFlags::DIRECTORY | OFlags::CLOEXEC,
            Mode::empty(),
        )?;
        let mut dir = rustix::fs::Dir::new(fd)?;
        let mut names = Vec::new();
        while let Some(entry) = dir.read() {
            let name = entry?.file_name().to_bytes().to_vec();
            if name != b"." && name != b".." {
                names.push(std::os::unix::ffi::OsStringExt::from_vec(name));
            }
        }
        Ok(names)
    }

    /// The folder's real path now, every link followed (`/proc/self/fd`), for the test
    /// that it is inside another.
    pub(crate) fn real(&self) -> io::Result<PathBuf> {
        std::fs::read_link(format!("/proc/self/fd/{}", self.fd.as_raw_fd()))
            .or_else(|_| std::fs::canonicalize(&self.shown))
    }
}
