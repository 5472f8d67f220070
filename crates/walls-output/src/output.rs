//! A command's outputs ([`Outputs`]): each planned before anything is written, a file the
//! user named ([`Outputs::plan`]) or a file in a folder the command writes to
//! ([`Outputs::folder`], [`Folder::plan`]), then written whole ([`Target::write_with`]) or
//! row by row ([`Target::stream`], [`Target::append`]).

use crate::dir::Dir;
use crate::new_file::{NewFile, Temporary};
use crate::replace::{euid, folder_of, keep_owner_and_mode, may_replace, replace_file, stamp_now};
use crate::stream::Placing;
use crate::{FileKind, Refusal, Stamp, Stream, Tool, WriteError};
use std::collections::BTreeSet;
use std::ffi::{OsStr, OsString};
use std::io::{self, BufWriter, Write};
use std::os::fd::AsFd;
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

/// A folder the command writes its outputs in, opened once: every output planned in it
/// ([`Folder::plan`]) is made relative to the folder as it was opened, through no link.
#[derive(Debug, Clone)]
pub struct Folder {
    dir: Dir,
    outputs: Outputs,
}

/// An output that may be written: where, and what is there now.
#[derive(Debug, Clone)]
pub struct Target {
    /// The folder it is in, held open.
    dir: Dir,
    /// Its name there.
    name: OsString,
    /// The path as the user gave it or the command made it: what messages show.
    shown: PathBuf,
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

/// Paths that name a process's open files rather than a file: `/dev/stdout` through
/// `/proc/self/fd/1` is whatever standard output is (a terminal, a pipe, a file opened for
/// appending), which a file put in its place would replace.
const STANDARD_STREAMS: [&str; 5] = [
    "/dev/stdin",
    "/dev/stdout",
    "/dev/stderr",
    "/dev/fd/",
    "/proc/",
];

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
    /// that no output replaces it; a path that names nothing is no input. `-` is standard
    /// input: the file it is redirected from, if any.
    pub fn reads(&mut self, path: impl AsRef<Path>) {
        let path = path.as_ref();
        if path == Path::new("-") {
            if let Ok(m) = std::io::stdin()
                .as_fd()
                .try_clone_to_owned()
                .map(std::fs::File::from)
                .and_then(|f| f.metadata())
            {
                self.inputs.insert(Stamp::from(&m).identity());
            }
            return;
        }
        if let Ok(m) = std::fs::metadata(path) {
            self.inputs.insert(Stamp::from(&m).identity());
        }
    }

    /// Plans the output `path`, named by the user: it may be written if nothing is there,
    /// or, with `--force`, a regular file that the policy lets the user replace; a
    /// symbolic link is followed to the file it names, which is replaced in its folder.
    pub fn plan(&self, path: &Path) -> Result<Target, WriteError> {
        let text = path.as_os_str().to_string_lossy();
        if STANDARD_STREAMS
            .iter()
            .any(|s| text == s.trim_end_matches('/') || text.starts_with(s))
        {
            return Err(Refusal::StandardStream.into());
        }
        let real = match std::fs::symlink_metadata(path) {
            Ok(m) if m.file_type().is_symlink() => match std::fs::canonicalize(path) {
                Ok(real) => real,
                Err(e) if e.kind() == io::ErrorKind::NotFound => {
                    let to = std::fs::read_link(path)?;
                    return Err(Refusal::DanglingLink { to }.into());
                }
                Err(e) => return Err(e.into()),
            },
            Ok(_) => path.to_path_buf(),
            Err(e) if e.kind() == io::ErrorKind::NotFound => path.to_path_buf(),
            Err(e) => return Err(e.into()),
        };
        let Some(name) = real.file_name() else {
            return Err(Refusal::NotRegular {
                kind: FileKind::Folder,
            }
            .into());
        };
        let dir = Dir::open(folder_of(&real)).map_err(|e| in_folder(e, folder_of(&real)))?;
        self.target(dir, name, path.to_path_buf(), Use::Replace)
    }

    /// The folder `path` (made, with its parents, when `make`), opened once for the
    /// outputs a command places in it.
    pub fn folder(&self, path: &Path, make: bool) -> Result<Folder, WriteError> {
        if make {
            std::fs::create_dir_all(path).map_err(|e| in_folder(e, path))?;
        }
        let dir = Dir::open(path).map_err(|e| in_folder(e, path))?;
        Ok(Folder {
            dir,
            outputs: self.clone(),
        })
    }

    /// The target `name` in `dir`, shown as `shown`, checked against the policy.
    fn target(
        &self,
        dir: Dir,
        name: &OsStr,
        shown: PathBuf,
        using: Use,
    ) -> Result<Target, WriteError> {
        let existing = dir.stat(name)?;
        if let Some(stamp) = &existing {
            self.check(&dir, name, stamp, using)?;
        }
        Ok(Target {
            dir,
            name: name.to_os_string(),
            shown,
            existing,
            tool: self.tool,
        })
    }

    /// Whether the file `name` of `dir`, now `stamp`, may be replaced (or appended to).
    fn check(&self, dir: &Dir, name: &OsStr, stamp: &Stamp, using: Use) -> Result<(), Refusal> {
        if stamp.kind() == FileKind::Symlink {
            return Err(Refusal::Link);
        }
        if stamp.kind() != FileKind::Regular {
            return Err(Refusal::NotRegular { kind: stamp.kind() });
        }
        if self.inputs.contains(&stamp.identity()) {
            return Err(Refusal::Input);
        }
        match using {
            Use::Replace if !self.force => Err(Refusal::Exists),
            Use::Replace => may_replace(stamp, dir.may_write(name), euid()),
            // Appending parts no names: only the permission to write counts.
            Use::Append => {
                let single = Stamp { nlink: 1, ..*stamp };
                may_replace(&single, dir.may_write(name), euid())
            }
        }
    }
}

/// An error opening or making the folder `path`, saying which.
fn in_folder(e: io::Error, path: &Path) -> WriteError {
    let what = match e.kind() {
        io::ErrorKind::NotADirectory | io::ErrorKind::AlreadyExists => "it is not a folder".into(),
        _ => e.to_string(),
    };
    WriteError::Io(io::Error::new(
        e.kind(),
        format!("the folder {}: {what}", path.display()),
    ))
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

/// Names `paths` for a message, in the order given: all of them when there are three or
/// fewer, else the first and the last and how many (`a-000.svg … a-999.svg, 1000 files`).
pub fn name_files(paths: &[&Path]) -> String {
    let shown: Vec<String> = paths.iter().map(|p| p.display().to_string()).collect();
    match shown.as_slice() {
        [] => String::new(),
        [one] => one.clone(),
        [first, second] => format!("{first} and {second}"),
        [first, second, third] => format!("{first}, {second} and {third}"),
        [first, .., last] => format!("{first} … {last}, {} files", shown.len()),
    }
}

impl Folder {
    /// The folder's path, as messages show it.
    pub fn path(&self) -> &Path {
        self.dir.shown()
    }

    /// Plans the output `name` in the folder: a relative path that goes down only (no
    /// `..`, no root), its sub-folders made if missing, no link on the way or in its place;
    /// then as [`Outputs::plan`] for what is there.
    pub fn plan(&self, name: &Path) -> Result<Target, WriteError> {
        self.plan_as(name, Use::Replace)
    }

    /// Plans `name` in the folder to be appended to (pkdgrav's WALLSREACT files): as
    /// [`Folder::plan`], but an existing file is no reason to refuse without `--force`,
    /// and its other names are none of the output's business, since nothing in it is
    /// replaced.
    pub fn plan_append(&self, name: &Path) -> Result<Target, WriteError> {
        self.plan_as(name, Use::Append)
    }

    fn plan_as(&self, name: &Path, using: Use) -> Result<Target, WriteError> {
        let outside = || Refusal::Outside {
            root: self.dir.shown().to_path_buf(),
        };
        let mut parts: Vec<&OsStr> = Vec::new();
        for c in name.components() {
            match c {
                Component::Normal(part) => parts.push(part),
                Component::CurDir => {}
                _ => return Err(outside().into()),
            }
        }
        let Some((last, folders)) = parts.split_last() else {
            return Err(outside().into());
        };
        let mut dir = self.dir.clone();
        for part in folders {
            dir = match dir.sub(part, true) {
                Ok(Some(sub)) => sub,
                // A link (ELOOP) or a file (ENOTDIR) where a folder should be.
                Err(e)
                    if e.raw_os_error() == Some(rustix::io::Errno::LOOP.raw_os_error())
                        || e.kind() == io::ErrorKind::NotADirectory =>
                {
                    return Err(outside().into());
                }
                Err(e) => return Err(e.into()),
                Ok(None) => return Err(outside().into()),
            };
        }
        let shown = path_in(self.dir.shown(), name);
        self.outputs.target(dir, last, shown, using)
    }

    /// The names of the files in the folder.
    pub fn names(&self) -> io::Result<Vec<OsString>> {
        self.dir.names()
    }

    /// The folder's real path now (every link followed).
    pub fn real(&self) -> io::Result<PathBuf> {
        self.dir.real()
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
    /// then put in place, replacing the file planned over (with its owner, group,
    /// extended attributes and mode, flushed to disk first, if it has not changed
    /// meanwhile) or taking a name nothing has (a file made there meanwhile is left
    /// alone). A failure, or a signal, leaves what was there.
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
                replace_file(&self.dir, &self.name, stamp, Temporary::Unnamed, buffered)
            }
            None => {
                let mut new = NewFile::create(&self.dir, Temporary::Unnamed, 0o666)?;
                buffered(new.file())?;
                new.link_new(&self.dir, &self.name)
            }
        }
    }

    /// Opens the file to be written row by row from empty ([`Stream`]): a new file in the
    /// folder, which takes the output's name at the first [`Stream::commit`] (in the place
    /// of the file planned over, with `--force`, with its owner, group, extended
    /// attributes and mode): until the first whole group of rows is written, nothing is
    /// there but what was.
    pub fn stream(&self) -> Result<Stream, WriteError> {
        let mode = if self.existing.is_some() {
            0o600
        } else {
            0o666
        };
        let mut new = NewFile::create(&self.dir, Temporary::Unnamed, mode)?;
        if let Some(stamp) = &self.existing {
            self.unchanged()?;
            keep_owner_and_mode(&self.dir, &self.name, stamp, new.file())?;
        }
        let file = new.file().try_clone()?;
        let placing = Placing {
            new,
            dir: self.dir.clone(),
            name: self.name.clone(),
            replacing: self.existing,
        };
        Ok(Stream::new(file, self.shown.clone(), 0).placing(placing))
    }

    /// Opens the file to be appended to row by row ([`Stream`]); one not there yet is
    /// made as [`Target::stream`] makes it.
    pub fn append(&self) -> Result<Stream, WriteError> {
        let Some(stamp) = &self.existing else {
            return self.stream();
        };
        let file = self
            .dir
            .open_existing(
                &self.name,
                stamp,
                rustix::fs::OFlags::WRONLY | rustix::fs::OFlags::APPEND,
            )
            .map_err(|_| Refusal::Changed)?;
        let start = file.metadata()?.len();
        Ok(Stream::new(file, self.shown.clone(), start))
    }

    /// Whether the file planned over is still the version planned.
    fn unchanged(&self) -> Result<(), WriteError> {
        match &self.existing {
            Some(stamp) if !stamp.same_version(&stamp_now(&self.dir, &self.name)?) => {
                Err(Refusal::Changed.into())
            }
            _ => Ok(()),
        }
    }
}
