//! Why a file is not written ([`Refusal`], [`WriteError`]), and the command whose
//! messages say so ([`Tool`]).

use crate::FileKind;
use std::io;
use std::path::PathBuf;

/// Why a file is not written; each is a reason the user can act on.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Refusal {
    /// Not a regular file (a FIFO, a device, a socket, a folder): replacing it would turn
    /// it into one, writing into it could block or reach hardware.
    NotRegular {
        /// What it is.
        kind: FileKind,
    },
    /// A symbolic link to nothing: writing through it would make a file wherever it
    /// points.
    DanglingLink {
        /// Where it points.
        to: PathBuf,
    },
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
    /// The file changed (or was replaced, removed or made) since it was looked at.
    Changed,
    /// An output that exists, without `--force`.
    Exists,
    /// A file the command reads.
    Input,
    /// A path that names one of the process's open files (`/dev/stdout`,
    /// `/proc/self/fd/1`), not a file: a file put in its place would replace whatever
    /// standard output is redirected to.
    StandardStream,
    /// A symbolic link where a command places an output in a folder: it would lead the
    /// output elsewhere.
    Link,
    /// Outside the folder the outputs must stay in.
    Outside {
        /// That folder.
        root: PathBuf,
    },
}

/// The command that writes, whose name and verbs the messages use.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Tool {
    /// The command line, as the user types it: "walls-fmt", "walls-lint --fix".
    pub command: &'static str,
    /// What it does to a file: "format", "fix", "write".
    pub verb: &'static str,
    /// What a file undergoes: "formatted", "fixed", "written".
    pub done: &'static str,
    /// Whether it rewrites the files it reads (walls-fmt, `walls-lint --fix`) rather than
    /// writing outputs of its own.
    pub rewrites: bool,
    /// Whether `-` names standard output, which the messages then offer (a command line;
    /// not the Python package, whose writes take a path).
    pub dash: bool,
}

impl Tool {
    /// walls-fmt, rewriting files in place.
    pub const FORMAT: Tool = Tool::rewriter("walls-fmt", "format", "formatted");
    /// `walls-lint --fix`, rewriting files in place.
    pub const FIX: Tool = Tool::rewriter("walls-lint --fix", "fix", "fixed");
    /// walls-mesh, writing a walls file.
    pub const MESH: Tool = Tool::writer("walls-mesh");
    /// `walls-sim run`, writing a run's outputs.
    pub const RUN: Tool = Tool::writer("walls-sim run");
    /// `walls-sim export`, writing a pkdgrav run directory.
    pub const EXPORT: Tool = Tool::writer("walls-sim export");
    /// `walls-sim preview`, writing pictures.
    pub const PREVIEW: Tool = Tool::writer("walls-sim preview");
    /// The Python package (`walls.write_ss`, `walls.Preview.save`), writing the file a
    /// function is given, which it replaces as `numpy.save` does.
    pub const PYTHON: Tool = Tool {
        command: "walls (Python)",
        verb: "write",
        done: "written",
        rewrites: false,
        dash: false,
    };

    const fn rewriter(command: &'static str, verb: &'static str, done: &'static str) -> Tool {
        Tool {
            command,
            verb,
            done,
            rewrites: true,
            dash: true,
        }
    }

    const fn writer(command: &'static str) -> Tool {
        Tool {
            command,
            verb: "write",
            done: "written",
            rewrites: false,
            dash: true,
        }
    }
}

impl Refusal {
    /// Why the file is not written, with advice for the user of `tool`.
    pub fn describe(&self, tool: Tool) -> String {
        let Tool { command, verb, .. } = tool;
        match self {
            Refusal::NotRegular { kind } if tool.rewrites => {
                format!("it is {}, not a regular file", kind.named())
            }
            Refusal::NotRegular { kind } if tool.dash => format!(
                "it is {}, which the walls tools never replace or write into (to write to \
                 standard output, give -)",
                kind.named()
            ),
            Refusal::NotRegular { kind } => format!(
                "it is {}, which the walls tools never replace or write into",
                kind.named()
            ),
            Refusal::DanglingLink { to } => format!(
                "it is a symbolic link to {}, which does not exist; the tools write through \
                 a link only to an existing file",
                to.display()
            ),
            Refusal::ReadOnly { mode } => format!(
                "it is read-only (mode {:04o}); make it writable first (chmod u+w)",
                mode & 0o7777
            ),
            Refusal::NoPermission => "you do not have permission to write it".into(),
            Refusal::HardLinks { links } if tool.rewrites => format!(
                "it has {links} hard links, which a rewrite would part; {verb} a copy \
                 ({command} - < FILE > COPY) and copy it back over the file"
            ),
            Refusal::HardLinks { links } => format!(
                "it has {links} hard links, which replacing it would part; remove it first, \
                 or write elsewhere"
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
                tool.done
            ),
            Refusal::Exists => "it exists: pass --force to replace it".into(),
            Refusal::Input => {
                format!("{command} reads it: an output never replaces one of the command's inputs")
            }
            Refusal::StandardStream if tool.dash => {
                "it names an open file of the process, not a file: for standard output, \
                 give - (or leave the option out) and redirect it"
                    .into()
            }
            Refusal::StandardStream => {
                "it names an open file of the process, not a file the tools replace".into()
            }
            Refusal::Link => "it is a symbolic link, which an output placed in a folder \
                 never follows: remove it, or write elsewhere"
                .into(),
            Refusal::Outside { root } => format!(
                "it is outside {}, the folder the outputs go to",
                root.display()
            ),
        }
    }
}

/// Why a file was not written.
#[derive(Debug)]
pub enum WriteError {
    /// A decision not to write it.
    Refused(Refusal),
    /// An input or output error (a full disk, a folder the user may not write).
    Io(io::Error),
}

impl WriteError {
    /// What to tell the user of `tool` about the file at `path`, which was not written.
    pub fn message(&self, path: &str, tool: Tool) -> String {
        match self {
            WriteError::Refused(why) => format!("not writing {path}: {}", why.describe(tool)),
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
