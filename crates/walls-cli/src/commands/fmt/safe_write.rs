//! Replacing a file with its formatted text without losing or stealing it
//! (docs/formatting.md, "What walls-fmt promises about your files"); `walls-lint --fix`
//! replaces a file with its fixed text the same way, and the messages name the command
//! ([`Rewriter`]).
//!
//! [`read`] opens the file (following symbolic links), notes its [`Stamp`] (identity,
//! size, times, owner, group, mode, links) and reads it. [`Original::replace`] then:
//!
//! 1. looks at the file again and asks [`check`] whether it may be replaced: it must
//!    still be the same regular file, unchanged, writable by the user (`access(2)`), not
//!    read-only (no write bit: refused even for root), with one name only (a rename would
//!    part hard links) and an owner the user can keep (only root can give a file away);
//! 2. writes the text to a new file in the same folder: an unnamed one (`O_TMPFILE`),
//!    which vanishes with the process whatever kills it, or, where the filesystem lacks
//!    those, a named `.walls-fmtXXXXXX` that a SIGINT, SIGTERM or SIGHUP removes
//!    ([`crate::interrupt`]); gives it the original's owner and group, extended
//!    attributes (a refusal if these cannot be kept) and mode, and flushes it to disk;
//! 3. checks that the file has not changed meanwhile ([`unchanged`]) and renames the new
//!    file over it (an unnamed file is first linked under a temporary name).
//!
//! Any failure before the rename leaves the original as it was.

use crate::interrupt::{self, Registration};
use std::fs::{File, Metadata};
use std::io::{self, Write};
use std::os::fd::AsRawFd;
use std::os::unix::fs::{MetadataExt, OpenOptionsExt, PermissionsExt};
use std::path::{Path, PathBuf};

/// What identifies one version of a file, and what a rewrite must keep.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Stamp {
    /// Device and inode: which file it is.
    pub dev: u64,
    /// See `dev`.
    pub ino: u64,
    /// Size in bytes.
    pub size: u64,
    /// Last modification, seconds and nanoseconds.
    pub mtime: (i64, i64),
    /// Last status change (contents, owner, mode or links), seconds and nanoseconds.
    pub ctime: (i64, i64),
    /// File type and permission bits, as `st_mode`.
    pub mode: u32,
    /// Owner.
    pub uid: u32,
    /// Group.
    pub gid: u32,
    /// Number of hard links (names).
    pub nlink: u64,
}

impl From<&Metadata> for Stamp {
    fn from(m: &Metadata) -> Self {
        Stamp {
            dev: m.dev(),
            ino: m.ino(),
            size: m.size(),
            mtime: (m.mtime(), m.mtime_nsec()),
            ctime: (m.ctime(), m.ctime_nsec()),
            mode: m.mode(),
            uid: m.uid(),
            gid: m.gid(),
            nlink: m.nlink(),
        }
    }
}

/// Why a file is not replaced; each is a reason the user can act on.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Refusal {
    /// Not a regular file (a pipe, a device): replacing it would turn it into one.
    NotRegular,
    /// No write permission bit is set (`chmod a-w`, 0444): read-only even for root.
    ReadOnly {
        /// The permission bits.
        mode: u32,
    },
    /// The user may not write it (`access(2)` says no).
    NoPermission,
    /// More than one name: renaming a new file over this one would part them.
    HardLinks {
        /// The number of names.
        links: u64,
    },
    /// The new file could not be given the original's owner and group.
    Owner {
        /// The original's owner.
        uid: u32,
        /// The original's group.
        gid: u32,
    },
    /// An extended attribute (an ACL, a security label, a user's own) could not be given
    /// to the new file.
    Attribute {
        /// The attribute's name.
        name: String,
    },
    /// The file changed (or was replaced or removed) since it was read.
    Changed,
}

/// The command that rewrites files, whose name and verb the messages use.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rewriter {
    /// `walls-fmt`, formatting.
    Format,
    /// `walls-lint --fix`, fixing.
    Fix,
}

impl Rewriter {
    /// The command line that rewrites a file.
    fn command(self) -> &'static str {
        match self {
            Rewriter::Format => "walls-fmt",
            Rewriter::Fix => "walls-lint --fix",
        }
    }

    /// What it does to a file: "format" or "fix".
    fn verb(self) -> &'static str {
        match self {
            Rewriter::Format => "format",
            Rewriter::Fix => "fix",
        }
    }

    /// What a file undergoes: "formatted" or "fixed".
    fn done(self) -> &'static str {
        match self {
            Rewriter::Format => "formatted",
            Rewriter::Fix => "fixed",
        }
    }
}

impl Refusal {
    /// Why the file is not replaced, with advice for the user of `rewriter`.
    pub fn describe(&self, rewriter: Rewriter) -> String {
        let (command, verb) = (rewriter.command(), rewriter.verb());
        match self {
            Refusal::NotRegular => "it is not a regular file".into(),
            Refusal::ReadOnly { mode } => format!(
                "it is read-only (mode {:04o}); make it writable first (chmod u+w)",
                mode & 0o7777
            ),
            Refusal::NoPermission => "you do not have permission to write it".into(),
            Refusal::HardLinks { links } => format!(
                "it has {links} hard links, which a rewrite would part; {verb} a copy \
                 ({command} - < FILE > COPY) and copy it back over the file"
            ),
            Refusal::Owner { uid, gid } => format!(
                "a rewrite would change its owner or group (uid {uid}, gid {gid}), which you \
                 cannot keep; {verb} it as its owner"
            ),
            Refusal::Attribute { name } => format!(
                "its extended attribute {name} cannot be kept (it may be an ACL or a \
                 security label that only root can set)"
            ),
            Refusal::Changed => format!(
                "it changed while it was being {}; run {command} again",
                rewriter.done()
            ),
        }
    }
}

/// Why [`Original::replace`] did not replace the file.
#[derive(Debug)]
pub enum WriteError {
    /// A decision not to write it.
    Refused(Refusal),
    /// An input or output error (a full disk, a folder the user may not write).
    Io(io::Error),
}

impl WriteError {
    /// What to tell the user of `rewriter` about the file at `path`, which was not
    /// written.
    pub fn message(&self, path: &str, rewriter: Rewriter) -> String {
        match self {
            WriteError::Refused(why) => format!("not writing {path}: {}", why.describe(rewriter)),
            WriteError::Io(e) => format!("cannot write {path}: {e}"),
        }
    }
}

impl From<Refusal> for WriteError {
    fn from(r: Refusal) -> Self {
        WriteError::Refused(r)
    }
}

impl From<io::Error> for WriteError {
    fn from(e: io::Error) -> Self {
        WriteError::Io(e)
    }
}

/// Whether the file is still the version that was read: same device and inode (not
/// replaced), same size, modification and status-change times to the nanosecond.
pub fn unchanged(read: &Stamp, now: &Stamp) -> Result<(), Refusal> {
    let same = read.dev == now.dev
        && read.ino == now.ino
        && read.size == now.size
        && read.mtime == now.mtime
        && read.ctime == now.ctime;
    if same { Ok(()) } else { Err(Refusal::Changed) }
}

/// Whether a file read as `read`, and now `now`, may be replaced by a user whose
/// effective user id is `euid` and whom `access(2)` allows (`may_write`) or not.
pub fn check(read: &Stamp, now: &Stamp, may_write: bool, euid: u32) -> Result<(), Refusal> {
    const TYPE: u32 = 0o170000;
    const REGULAR: u32 = 0o100000;
    if now.mode & TYPE != REGULAR {
        return Err(Refusal::NotRegular);
    }
    unchanged(read, now)?;
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

/// A file as it was read for formatting.
pub struct Original {
    /// The file's path with symbolic links resolved: the file replaced.
    path: PathBuf,
    /// The version read.
    stamp: Stamp,
}

/// Reads the file at `path` (through symbolic links), at most
/// [`MAX_FILE_BYTES`](crate::input::MAX_FILE_BYTES) (more is an error): the file and its
/// bytes, or a message saying why it could not be read.
pub fn read(path: &Path) -> Result<(Original, Vec<u8>), String> {
    let fail = |e: io::Error| format!("cannot read {}: {e}", path.display());
    let file = File::open(path).map_err(fail)?;
    let stamp = Stamp::from(&file.metadata().map_err(fail)?);
    // A path that does not resolve to a name (`/dev/stdin` on a pipe) is not a regular
    // file, which `check` refuses to replace; if a link changed meanwhile, the identity
    // differs.
    let real = std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf());
    let bytes = crate::input::read_all(file, &path.display().to_string())?;
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
        self.check_now()?;
        let dir = self
            .path
            .parent()
            .filter(|d| !d.as_os_str().is_empty())
            .unwrap_or(Path::new("."));
        let mut new = NewFile::create(dir, temporary).map_err(|e| {
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
        std::os::unix::fs::fchown(&*file, Some(self.stamp.uid), Some(self.stamp.gid)).map_err(
            |_| Refusal::Owner {
                uid: self.stamp.uid,
                gid: self.stamp.gid,
            },
        )?;
        copy_attributes(&self.path, file)?;
        // After the chown, which clears set-user-id and set-group-id bits.
        file.set_permissions(std::fs::Permissions::from_mode(self.stamp.mode & 0o7777))?;
        write(file)?;
        file.sync_all()?;
        unchanged(&self.stamp, &self.stamp_now()?)?;
        new.rename_over(dir, &self.path)
    }

    /// [`check`] on the file as it is now.
    fn check_now(&self) -> Result<(), WriteError> {
        let now = self.stamp_now()?;
        let may_write = rustix::fs::access(&self.path, rustix::fs::Access::WRITE_OK).is_ok();
        check(
            &self.stamp,
            &now,
            may_write,
            rustix::process::geteuid().as_raw(),
        )?;
        Ok(())
    }

    /// The file's stamp now; a file gone since it was read has changed.
    fn stamp_now(&self) -> Result<Stamp, WriteError> {
        match std::fs::metadata(&self.path) {
            Ok(m) => Ok(Stamp::from(&m)),
            Err(e) if e.kind() == io::ErrorKind::NotFound => Err(Refusal::Changed.into()),
            Err(e) => Err(e.into()),
        }
    }
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

/// The kind of new file the text is written to before it replaces the original.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Temporary {
    /// Unnamed (`O_TMPFILE`) where the filesystem allows, else named.
    Unnamed,
    /// Named, `.walls-fmtXXXXXX` in the file's folder.
    Named,
}

/// The new file being written.
enum NewFile {
    /// An `O_TMPFILE` file: no name until it is complete.
    Unnamed(File),
    /// A `.walls-fmtXXXXXX` file, removed if the write fails or a signal comes.
    Named(tempfile::NamedTempFile<(File, Registration)>),
}

/// The prefix of the temporary names.
const PREFIX: &str = ".walls-fmt";

impl NewFile {
    /// A new file in `dir`, readable and writable by its owner only until it is complete.
    fn create(dir: &Path, temporary: Temporary) -> io::Result<NewFile> {
        interrupt::install();
        if temporary == Temporary::Named {
            return NewFile::named(dir);
        }
        let unnamed = rustix::fs::open(
            dir,
            rustix::fs::OFlags::TMPFILE | rustix::fs::OFlags::WRONLY | rustix::fs::OFlags::CLOEXEC,
            rustix::fs::Mode::from_raw_mode(0o600),
        );
        // Linking it into place goes through /proc/self/fd; without either, a named file.
        if let Ok(fd) = unnamed
            && Path::new("/proc/self/fd").is_dir()
        {
            return Ok(NewFile::Unnamed(File::from(fd)));
        }
        NewFile::named(dir)
    }

    /// A named temporary file in `dir`, registered for removal on a signal.
    fn named(dir: &Path) -> io::Result<NewFile> {
        tempfile::Builder::new()
            .prefix(PREFIX)
            .make_in(dir, |path| {
                let file = std::fs::OpenOptions::new()
                    .write(true)
                    .create_new(true)
                    .mode(0o600)
                    .open(path)?;
                Ok((file, interrupt::remove_on_signal(path)))
            })
            .map(NewFile::Named)
    }

    /// The file to write.
    fn file(&mut self) -> &mut File {
        match self {
            NewFile::Unnamed(file) => file,
            NewFile::Named(tmp) => &mut tmp.as_file_mut().0,
        }
    }

    /// Puts the complete file in the place of `target` (in `dir`).
    fn rename_over(self, dir: &Path, target: &Path) -> Result<(), WriteError> {
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
}
