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

use crate::dir::Dir;
use crate::new_file::{NewFile, Temporary};
use crate::{FileKind, Refusal, Stamp, WriteError};
use std::ffi::{OsStr, OsString};
use std::fs::File;
use std::io::{self, Read, Write};
use std::os::unix::fs::PermissionsExt;
use std::path::Path;

/// Whether a file read as `read`, and now `now`, may be replaced by a user whose
/// effective user id is `euid` and whom `access(2)` allows (`may_write`) or not.
pub fn check(read: &Stamp, now: &Stamp, may_write: bool, euid: u32) -> Result<(), Refusal> {
    if read.kind() != FileKind::Regular {
        return Err(Refusal::NotRegular { kind: read.kind() });
    }
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

/// The effective user id.
pub(crate) fn euid() -> u32 {
    rustix::process::geteuid().as_raw()
}

/// The stamp of `name` in `dir` now (not through a link); a file gone is
/// [`Refusal::Changed`].
pub(crate) fn stamp_now(dir: &Dir, name: &OsStr) -> Result<Stamp, WriteError> {
    dir.stat(name)?.ok_or_else(|| Refusal::Changed.into())
}

/// A file as it was read for rewriting.
pub struct Original {
    /// The folder of the file, links resolved, held open.
    dir: Dir,
    /// Its name there.
    name: OsString,
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
    let dir = Dir::open(folder_of(&real)).map_err(fail)?;
    let name = real.file_name().unwrap_or(real.as_os_str()).to_os_string();
    let mut bytes = Vec::new();
    file.take(limit + 1).read_to_end(&mut bytes).map_err(fail)?;
    if bytes.len() as u64 > limit {
        return Err(format!(
            "cannot read {}: larger than {limit} bytes, the most the tools read",
            path.display()
        ));
    }
    Ok((Original { dir, name, stamp }, bytes))
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
        let now = stamp_now(&self.dir, &self.name)?;
        check(&self.stamp, &now, self.dir.may_write(&self.name), euid())?;
        replace_file(&self.dir, &self.name, &self.stamp, temporary, write)
    }
}

/// Replaces the regular file `name` in `dir`, whose version `stamp` has been checked,
/// with what `write` writes: a new file in the same folder with the old one's owner,
/// group, extended attributes and mode, flushed to disk, renamed over the old one if that
/// has not changed meanwhile.
pub(crate) fn replace_file(
    dir: &Dir,
    name: &OsStr,
    stamp: &Stamp,
    temporary: Temporary,
    write: impl FnOnce(&mut File) -> io::Result<()>,
) -> Result<(), WriteError> {
    let mut new = NewFile::create(dir, temporary, 0o600).map_err(|e| {
        io::Error::new(
            e.kind(),
            format!(
                "cannot make a new file in {} to put in its place ({e}): rewriting a \
                 file needs permission to write its folder too",
                dir.shown().display()
            ),
        )
    })?;
    let file = new.file();
    keep_owner_and_mode(dir, name, stamp, file)?;
    write(file)?;
    file.sync_all()?;
    if !stamp.same_version(&stamp_now(dir, name)?) {
        return Err(Refusal::Changed.into());
    }
    new.rename_over(dir, name)
}

/// Gives `new` the owner, group, extended attributes and mode of the file `name` in `dir`
/// (whose version is `stamp`), or refuses.
pub(crate) fn keep_owner_and_mode(
    dir: &Dir,
    name: &OsStr,
    stamp: &Stamp,
    new: &File,
) -> Result<(), WriteError> {
    std::os::unix::fs::fchown(new, Some(stamp.uid), Some(stamp.gid)).map_err(|_| {
        Refusal::Owner {
            uid: stamp.uid,
            gid: stamp.gid,
        }
    })?;
    let old = dir
        .open_existing(name, stamp, rustix::fs::OFlags::RDONLY)
        .map_err(|_| Refusal::Changed)?;
    copy_attributes(&old, new)?;
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

/// Gives `new` the extended attributes of `old`, if its filesystem has any.
fn copy_attributes(old: &File, new: &File) -> Result<(), WriteError> {
    let mut names = vec![0; XATTR_MAX];
    let len = match rustix::fs::flistxattr(old, &mut names[..]) {
        Ok(len) => len,
        Err(rustix::io::Errno::NOTSUP) => return Ok(()),
        Err(e) => return Err(io::Error::from(e).into()),
    };
    let mut value = vec![0; XATTR_MAX];
    for name in names[..len].split(|&b| b == 0).filter(|n| !n.is_empty()) {
        let len = rustix::fs::fgetxattr(old, name, &mut value[..]).map_err(io::Error::from)?;
        rustix::fs::fsetxattr(new, name, &value[..len], rustix::fs::XattrFlags::empty()).map_err(
            |_| Refusal::Attribute {
                name: String::from_utf8_lossy(name).into_owned(),
            },
        )?;
    }
    Ok(())
}
