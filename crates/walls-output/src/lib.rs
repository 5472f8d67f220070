//! The one writer of the walls tools. Every file that walls-fmt, `walls-lint --fix`,
//! walls-mesh, `walls-sim run --out` (the trajectory, the `.ss` outputs, pkdgrav's
//! WALLSREACT files) and `walls-sim preview` (every picture, still and movie frame) write,
//! from the command line or from the Python package, goes through this crate, under one
//! policy (docs/reliability.md, "Files: what the tools write"):
//!
//! 1. **Never replace what is not a regular file.** A device, a FIFO, a socket or a
//!    folder is refused whatever the options (`--force` included): replacing `/dev/null`
//!    with a file, or blocking on a FIFO, is never wanted. Standard output is `-`.
//! 2. **Links.** A symbolic link the user names is written through: the file it points to
//!    is replaced, in its own folder, and the link stays (a link to nothing is refused); a
//!    link where a command places an output in a folder is refused. A file with several
//!    names (hard links) is refused: replacing it would part the names.
//! 3. **Owner, group, mode and extended attributes are kept**, or the write is refused;
//!    a read-only file (no write bit) is refused even for root and even with `--force`.
//! 4. **Never overwrite what the command reads** ([`Outputs::reads`]): an output that is
//!    one of its inputs, by any name, is refused whatever the options.
//! 5. **Never outside the folder named.** Outputs a command places in a folder
//!    ([`Outputs::folder`]: `run --out DIR`, a picture's stills and frames) are made in
//!    the folder as it was opened, through no link and no `..`: renaming the folder or
//!    putting a link in its place meanwhile does not move them.
//! 6. **An existing output is replaced only when the user said so** (`--force`); without
//!    it the refusal names the file, with it the command names what it replaced
//!    ([`name_files`]). Appending to a file (pkdgrav's WALLSREACT files) is not replacing
//!    it.
//! 7. **Nothing the user had is lost on a failure.** A whole file is written to a new file
//!    in the same folder and renamed into place once complete ([`Target::write`]): a
//!    failure or a signal leaves the old file, or no file. A file written row by row
//!    ([`Stream`]) takes its name at its first whole row group (a run's first output
//!    step), and after a failed write ends at its last ([`Stream::commit`],
//!    [`Stream::rollback`]); no output is removed.
//!
//! A path that names an open file of the process (`/dev/stdout`) is no file to replace.
//! [`replace`] rewrites a file the command read (walls-fmt, `walls-lint --fix`) under the
//! same rules; [`interrupt`] removes the half-written new files when a signal ends the
//! process. The messages name the command ([`Tool`]) and say what the user can do.

mod dir;
pub mod interrupt;
mod new_file;
mod output;
mod refusal;
pub mod replace;
mod stamp;
mod stream;

pub use new_file::Temporary;
pub use output::{Folder, Outputs, Target, name_files, path_in};
pub use refusal::{Refusal, Tool, WriteError};
pub use stamp::{FileKind, Stamp};
pub use stream::Stream;
