//! A command's outputs ([`Outputs`]): each planned ([`Outputs::plan`], [`Outputs::plan_in`])
//! against the policy of the crate's documentation before anything is written, then
//! written whole ([`Target::write`]) or row by row ([`Target::stream`], [`Target::append`]).

use crate::new_file::{NewFile, Temporary};
use crate::replace::{folder_of, keep_owner_and_mode, may_replace_now, replace_file, stamp_now};
use crate::stream::Placing;
use crate::{FileKind, Refusal, Stamp, Stream, Tool, WriteError};
use std::collections::BTreeSet;
use std::io::{self, BufWriter, Write};
use std::os::unix::fs::OpenOptionsExt;
use std::path::{Component, Path, PathBuf};

/// The outputs of one command: who writes them (for the messages), whether existing ones
/// may be replaced (`--force`), and the files the command reads, which no output may
/// replace.
#[derive(Debug, Clone)]
pub struct Outputs {
    tool: Tool,
    force: bool,
    inputs: BTreeSet<(u64, u64)>,
}

/// An output that may be written: where, and what is there now.
#[derive(Debug, Clone)]
pub struct Target {
    /// The path as the user gave it or the command made it: what messages show.
    shown: PathBuf,
    /// The file written: `shown` with a symbolic link followed.
    real: PathBuf,
    /// The file there when it was planned, if any (a regular file that may be replaced or
    /// appended to).
    existing: Option<Stamp>,
    tool: Tool,
}

/// Whether a planned output replaces what is there or adds to it.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Use {
    Replace,
    Append,
}

impl Outputs {
    /// The outputs of `tool`, which may replace existing files when `force`.
    pub fn new(tool: Tool, force: bool) -> Outputs {
        Outputs {
            tool,
            force,
            inputs: BTreeSet::new(),
        }
    }

    /// The command that writes.
    pub fn tool(&self) -> Tool {
        self.tool
    }

    /// Notes that the command reads the file at `path` (whatever name a link gives it), so
    /// that no output replaces it; a path that names nothing is no input.
    pub fn reads(&mut self, path: impl AsRef<Path>) {
        if let Ok(m) = std::fs::metadata(path) {
            self.inputs.insert(Stamp::from(&m).identity());
        }
    }

    /// Plans the output `path`, named by the user: it may be written if nothing is there,
    /// or, with `--force`, a regular file that the policy lets the user replace.
    pub fn plan(&self, path: &Path) -> Result<Target, WriteError> {
        self.plan_checked(path, None, Use::Replace)
    }

    /// Plans the output `name` in the folder `root`: as [`Outputs::plan`], and `name` must
    /// stay in `root` (a relative path without `..`, through no link that leaves it).
    pub fn plan_in(&self, root: &Path, name: &Path) -> Result<Target, WriteError> {
        self.plan_checked(&inside(root, name)?, Some(root), Use::Replace)
    }

    /// Plans `name` in `root` to be appended to (pkdgrav's WALLSREACT files): as
    /// [`Outputs::plan_in`], but an existing file is no reason to refuse without
    /// `--force`, since nothing in it is replaced.
    pub fn plan_append_in(&self, root: &Path, name: &Path) -> Result<Target, WriteError> {
        self.plan_checked(&inside(root, name)?, Some(root), Use::Append)
    }

    fn plan_checked(
        &self,
        shown: &Path,
        root: Option<&Path>,
        using: Use,
    ) -> Result<Target, WriteError> {
        let (real, existing) = match std::fs::symlink_metadata(shown) {
            Err(e) if e.kind() == io::ErrorKind::NotFound => (shown.to_path_buf(), None),
            Err(e) => return Err(e.into()),
            Ok(m) if m.file_type().is_symlink() => match std::fs::canonicalize(shown) {
                Ok(real) => {
                    let m = std::fs::metadata(&real)?;
                    (real, Some(Stamp::from(&m)))
                }
                Err(e) if e.kind() == io::ErrorKind::NotFound => {
                    let to = std::fs::read_link(shown)?;
                    return Err(Refusal::DanglingLink { to }.into());
                }
                Err(e) => return Err(e.into()),
            },
            Ok(m) => (shown.to_path_buf(), Some(Stamp::from(&m))),
        };
        if let Some(stamp) = existing.as_ref().filter(|s| s.kind() != FileKind::Regular) {
            return Err(Refusal::NotRegular { kind: stamp.kind() }.into());
        }
        if let Some(root) = root {
            confined(root, &real)?;
        }
        if let Some(stamp) = &existing {
            if self.inputs.contains(&stamp.identity()) {
                return Err(Refusal::Input.into());
            }
            if using == Use::Replace && !self.force {
                return Err(Refusal::Exists.into());
            }
            may_replace_now(&real, stamp)?;
        }
        Ok(Target {
            shown: shown.to_path_buf(),
            real,
            existing,
            tool: self.tool,
        })
    }
}

/// `root/name` when `name` is a relative path that goes down only (no `..`, no root).
fn inside(root: &Path, name: &Path) -> Result<PathBuf, Refusal> {
    let down = name
        .components()
        .all(|c| matches!(c, Component::Normal(_) | Component::CurDir));
    if !down || name.as_os_str().is_empty() {
        return Err(Refusal::Outside {
            root: root.to_path_buf(),
        });
    }
    Ok(path_in(root, name))
}

/// The path of `name` in the folder `root`, as messages show it: the name alone in the
/// current folder (`--out .`), as the user wrote it.
pub fn path_in(root: &Path, name: &Path) -> PathBuf {
    if root == Path::new(".") {
        name.to_path_buf()
    } else {
        root.join(name)
    }
}

/// Whether the file at `real` (whose folder may not exist yet) is in the folder `root`,
/// once every link of both is followed.
fn confined(root: &Path, real: &Path) -> Result<(), WriteError> {
    let outside = || Refusal::Outside {
        root: root.to_path_buf(),
    };
    let root = std::fs::canonicalize(root)?;
    // The nearest folder of `real` that exists, followed through its links; the rest is
    // made below it.
    let mut existing = folder_of(real).to_path_buf();
    let found = loop {
        match std::fs::canonicalize(&existing) {
            Ok(found) => break found,
            Err(e) if e.kind() == io::ErrorKind::NotFound => {
                if existing.file_name().is_none() {
                    return Err(outside().into());
                }
                existing = folder_of(&existing).to_path_buf();
            }
            Err(e) => return Err(e.into()),
        }
    };
    if found.starts_with(&root) {
        Ok(())
    } else {
        Err(outside().into())
    }
}

impl Target {
    /// The output's path as the user sees it.
    pub fn path(&self) -> &Path {
        &self.shown
    }

    /// Whether a file is there now (which writing replaces, or appending adds to).
    pub fn exists(&self) -> bool {
        self.existing.is_some()
    }

    /// What to tell the user about this output, which `e` kept from being written.
    pub fn message(&self, e: &WriteError) -> String {
        e.message(&self.shown.display().to_string(), self.tool)
    }

    /// Writes `bytes` as the whole file: see [`Target::write_with`].
    pub fn write(&self, bytes: &[u8]) -> Result<(), WriteError> {
        self.write_with(|out| out.write_all(bytes))
    }

    /// Writes the whole file with `write` (buffered): into a new file in the same folder,
    /// flushed to disk, then put in place, replacing the file planned over (with its
    /// owner, group, extended attributes and mode, if it has not changed meanwhile) or
    /// taking a name nothing has (a file made there meanwhile is left alone). A failure,
    /// or a signal, leaves what was there.
    pub fn write_with(
        &self,
        write: impl FnOnce(&mut dyn Write) -> io::Result<()>,
    ) -> Result<(), WriteError> {
        let buffered = |file: &mut std::fs::File| {
            let mut out = BufWriter::new(file);
            write(&mut out)?;
            out.flush()
        };
        match &self.existing {
            Some(stamp) => {
                self.unchanged()?;
                replace_file(&self.real, stamp, Temporary::Unnamed, buffered)
            }
            None => {
                let mut new = NewFile::create(folder_of(&self.real), Temporary::Unnamed, 0o666)?;
                buffered(new.file())?;
                new.file().sync_all()?;
                new.link_new(&self.real)
            }
        }
    }

    /// Opens the file to be written row by row from empty ([`Stream`]): a new file; or, in
    /// place of the file planned over (with `--force`), a new file in the same folder with
    /// its owner, group, extended attributes and mode, which replaces it at the first
    /// [`Stream::commit`]: until the first whole group of rows is written, the old file is
    /// there as it was.
    pub fn stream(&self) -> Result<Stream, WriteError> {
        if let Some(stamp) = &self.existing {
            self.unchanged()?;
            let folder = folder_of(&self.real);
            let mut new = NewFile::create(folder, Temporary::Unnamed, 0o600)?;
            keep_owner_and_mode(&self.real, stamp, new.file())?;
            let file = new.file().try_clone()?;
            let placing = Placing {
                new,
                target: self.real.clone(),
                stamp: *stamp,
            };
            return Ok(Stream::new(file, self.shown.clone(), 0).placing(placing));
        }
        self.open(false)
    }

    /// Opens the file to be appended to row by row ([`Stream`]), made if missing.
    pub fn append(&self) -> Result<Stream, WriteError> {
        self.open(true)
    }

    fn open(&self, append: bool) -> Result<Stream, WriteError> {
        let mut options = std::fs::OpenOptions::new();
        options.write(true).mode(0o666);
        let Some(stamp) = &self.existing else {
            let file = options
                .create_new(true)
                .open(&self.real)
                .map_err(|e| match e.kind() {
                    io::ErrorKind::AlreadyExists => Refusal::Changed.into(),
                    _ => WriteError::Io(e),
                })?;
            return Ok(Stream::new(file, self.shown.clone(), 0));
        };
        // Not through a link swapped in since, and without blocking on a FIFO swapped in:
        // the file opened must be the one planned.
        let flags = rustix::fs::OFlags::NOFOLLOW.bits() | rustix::fs::OFlags::NONBLOCK.bits();
        let file = options
            .custom_flags(flags as i32)
            .append(append)
            .open(&self.real)
            .map_err(|e| {
                if e.raw_os_error() == Some(rustix::io::Errno::LOOP.raw_os_error()) {
                    WriteError::from(Refusal::Changed)
                } else {
                    WriteError::Io(e)
                }
            })?;
        let now = Stamp::from(&file.metadata()?);
        if now.kind() != FileKind::Regular || now.identity() != stamp.identity() {
            return Err(Refusal::Changed.into());
        }
        let start = if append {
            now.size
        } else {
            file.set_len(0)?;
            0
        };
        Ok(Stream::new(file, self.shown.clone(), start))
    }

    /// Whether the file planned over is still the version planned.
    fn unchanged(&self) -> Result<(), WriteError> {
        match &self.existing {
            Some(stamp) if !stamp.same_version(&stamp_now(&self.real)?) => {
                Err(Refusal::Changed.into())
            }
            _ => Ok(()),
        }
    }
}
