//! Rewriting a file the command read, in place, without losing or stealing it: walls-fmt
//! and `walls-lint --fix` (docs/formatting.md, "What walls-fmt promises about your
//! files").
//!
//! [`read`] opens the file (following symbolic links), notes its [`Stamp`] (identity,
//! size, times, owner, group, mode, links) and reads it. [`Original::replace`] then:
//!
//! 1. looks at the file again and asks [`check`] whether it may be replaced: it must
//!    still be the same regular file, unchanged, writable by the user (`access(2)`), not
//!    read-only (no write bit: refused even for root), with one name only (a rename would
//!    part hard links) and an owner the user can keep (only root can give a file away);
//! 2. writes the text to a new file in the same folder ([`crate::Temporary`]); gives it
//!    the original's owner and group, extended attributes (a refusal if these cannot be
//!    kept) and mode, and flushes it to disk;
//! 3. checks that the file has not changed meanwhile and renames the new file over it.
//!
//! Any failure before the rename leaves the original as it was.

use crate::new_file::{NewFile, Temporary};
use crate::{FileKind, Refusal, Stamp, WriteError};
use std::fs::File;
use std::io::{self, Read, Write};
use std::os::unix::fs::PermissionsExt;
use std::path::{Path, PathBuf};

/// Whether a file read as `read`, and now `now`, may be replaced by a user whose
/// effective user id is `euid` and whom `access(2)` allows (`may_write`) or not.
pub fn check(read: &Stamp, now: &Stamp, may_write: bool, euid: u32) -> Result<(), Refusal> {
    if now.kind() != FileKind::Regular {
        return Err(Refusal::NotRegular { kind: now.kind() });
    }
    if !read.same_version(now) {
        return Err(Refusal::Changed);
    }
    may_replace(now, may_write, euid)
}

/// Whether the regular file `now` may be replaced by a user whose effective user id is
/// `euid` and whom `access(2)` allows (`may_write`) or not: the checks of [`check`] after
/// the file's kind and version.
pub(crate) fn may_replace(now: &Stamp, may_write: bool, euid: u32) -> Result<(), Refusal> {
    if now.mode & 0o222 == 0 {
        return Err(Refusal::ReadOnly { mode: now.mode });
    }
    if !may_write {
        return Err(Refusal::NoPermission);
    }
    if now.nlink > 1 {
        return Err(Refusal::HardLinks { links: now.nlink });
    }
    if euid != 0 && now.uid != euid {
        return Err(Refusal::Owner {
            uid: now.uid,
            gid: now.gid,
        });
    }
    Ok(())
}

/// [`may_replace`] for the file at `path` as it is now (`now`), asking the system.
pub(crate) fn may_replace_now(path: &Path, now: &Stamp) -> Result<(), Refusal> {
    let may_write = rustix::fs::access(path, rustix::fs::Access::WRITE_OK).is_ok();
    may_replace(now, may_write, rustix::process::geteuid().as_raw())
}

/// The stamp of the file at `path` now (through links); a file gone is
/// [`Refusal::Changed`].
pub(crate) fn stamp_now(path: &Path) -> Result<Stamp, WriteError> {
    match std::fs::metadata(path) {
        Ok(m) => Ok(Stamp::from(&m)),
        Err(e) if e.kind() == io::ErrorKind::NotFound => Err(Refusal::Changed.into()),
        Err(e) => Err(e.into()),
    }
}

/// A file as it was read for rewriting.
pub struct Original {
    /// The file's path with symbolic links resolved: the file replaced.
    path: PathBuf,
    /// The version read.
    stamp: Stamp,
}

/// Reads the file at `path` (through symbolic links), at most `limit` bytes (more is an
/// error): the file and its bytes, or a message saying why it could not be read.
pub fn read(path: &Path, limit: u64) -> Result<(Original, Vec<u8>), String> {
    let fail = |e: io::Error| format!("cannot read {}: {e}", path.display());
    let file = File::open(path).map_err(fail)?;
    let stamp = Stamp::from(&file.metadata().map_err(fail)?);
    // A path that does not resolve to a name (`/dev/stdin` on a pipe) is not a regular
    // file, which `check` refuses to replace; if a link changed meanwhile, the identity
    // differs.
    let real = std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf());
    let mut bytes = Vec::new();
    file.take(limit + 1).read_to_end(&mut bytes).map_err(fail)?;
    if bytes.len() as u64 > limit {
        return Err(format!(
            "cannot read {}: larger than {limit} bytes, the most the tools read",
            path.display()
        ));
    }
    Ok((Original { path: real, stamp }, bytes))
}

impl Original {
    /// Replaces the file with `text` if [`check`] allows it, keeping its owner, group,
    /// extended attributes and mode; see the module documentation for the steps.
    pub fn replace(&self, text: &[u8]) -> Result<(), WriteError> {
        self.replace_with(Temporary::Unnamed, |file| file.write_all(text))
    }

    /// [`Original::replace`] with the new contents written by `write` into a new file of
    /// the kind `temporary` asks for.
    pub fn replace_with(
        &self,
        temporary: Temporary,
        write: impl FnOnce(&mut File) -> io::Result<()>,
    ) -> Result<(), WriteError> {
        let now = stamp_now(&self.path)?;
        let may_write = rustix::fs::access(&self.path, rustix::fs::Access::WRITE_OK).is_ok();
        check(
            &self.stamp,
            &now,
            may_write,
            rustix::process::geteuid().as_raw(),
        )?;
        replace_file(&self.path, &self.stamp, temporary, write)
    }
}

/// Replaces the regular file at `path`, whose version `stamp` has been checked, with
/// what `write` writes: a new file in the same folder with the old one's owner, group,
/// extended attributes and mode, flushed to disk, renamed over the old one if that has
/// not changed meanwhile.
pub(crate) fn replace_file(
    path: &Path,
    stamp: &Stamp,
    temporary: Temporary,
    write: impl FnOnce(&mut File) -> io::Result<()>,
) -> Result<(), WriteError> {
    let dir = folder_of(path);
    let mut new = NewFile::create(dir, temporary, 0o600).map_err(|e| {
        io::Error::new(
            e.kind(),
            format!(
                "cannot make a new file in {} to put in its place ({e}): rewriting a \
                 file needs permission to write its folder too",
                dir.display()
            ),
        )
    })?;
    let file = new.file();
    keep_owner_and_mode(path, stamp, file)?;
    write(file)?;
    file.sync_all()?;
    if !stamp.same_version(&stamp_now(path)?) {
        return Err(Refusal::Changed.into());
    }
    new.rename_over(dir, path)
}

/// Gives `new` the owner, group, extended attributes and mode of the file at `path`
/// (whose version is `stamp`), or refuses.
pub(crate) fn keep_owner_and_mode(
    path: &Path,
    stamp: &Stamp,
    new: &File,
) -> Result<(), WriteError> {
    std::os::unix::fs::fchown(new, Some(stamp.uid), Some(stamp.gid)).map_err(|_| {
        Refusal::Owner {
            uid: stamp.uid,
            gid: stamp.gid,
        }
    })?;
    copy_attributes(path, new)?;
    // After the chown, which clears set-user-id and set-group-id bits.
    new.set_permissions(std::fs::Permissions::from_mode(stamp.mode & 0o7777))?;
    Ok(())
}

/// The folder of `path` (`.` for a bare name).
pub(crate) fn folder_of(path: &Path) -> &Path {
    path.parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."))
}

/// The most an extended attribute's value, and the list of their names, can hold (Linux).
const XATTR_MAX: usize = 1 << 16;

/// Gives `new` the extended attributes of the file at `path`, if its filesystem has any.
fn copy_attributes(path: &Path, new: &File) -> Result<(), WriteError> {
    let mut names = vec![0; XATTR_MAX];
    let len = match rustix::fs::listxattr(path, &mut names[..]) {
        Ok(len) => len,
        Err(rustix::io::Errno::NOTSUP) => return Ok(()),
        Err(e) => return Err(io::Error::from(e).into()),
    };
    let mut value = vec![0; XATTR_MAX];
    for name in names[..len].split(|&b| b == 0).filter(|n| !n.is_empty()) {
        let len = rustix::fs::getxattr(path, name, &mut value[..]).map_err(io::Error::from)?;
        rustix::fs::fsetxattr(new, name, &value[..len], rustix::fs::XattrFlags::empty()).map_err(
            |_| Refusal::Attribute {
                name: String::from_utf8_lossy(name).into_owned(),
            },
        )?;
    }
    Ok(())
}
