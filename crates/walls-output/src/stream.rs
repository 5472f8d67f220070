//! A file written row by row ([`Stream`]): a run's trajectory, pkdgrav's WALLSREACT
//! files. What is written is buffered and goes to the file when the buffer fills or on
//! [`Stream::commit`], which marks the end of a whole group of rows (a run's output step);
//! after a failed write, [`Stream::rollback`] cuts the file back to the last mark, so
//! that it ends on whole rows of whole steps, and nothing before is lost.

use crate::dir::Dir;
use crate::new_file::NewFile;
use crate::replace::stamp_now;
use crate::{Refusal, Stamp, WriteError};
use std::ffi::OsString;
use std::fs::File;
use std::io::{self, Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};

/// A new file to be given its name at the first mark.
#[derive(Debug)]
pub(crate) struct Placing {
    /// The new file (written through the stream's own handle on it).
    pub(crate) new: NewFile,
    /// Its folder.
    pub(crate) dir: Dir,
    /// Its name there.
    pub(crate) name: OsString,
    /// The version of the file it replaces, if there is one.
    pub(crate) replacing: Option<Stamp>,
}

/// What is held before it goes to the file.
const BUFFER: usize = 1 << 16;

/// A file written row by row, with marks at whole groups of rows.
#[derive(Debug)]
pub struct Stream {
    file: File,
    path: PathBuf,
    buffer: Vec<u8>,
    /// How long the file is: what it had, and what has gone to it.
    on_disk: u64,
    /// Its length at the last mark.
    committed: u64,
    /// Whether sending to the file has failed.
    failed: bool,
    /// The new file's name, given at the first mark: until then it has none.
    placing: Option<Placing>,
}

impl Stream {
    /// A stream onto `file` (shown as `path`), which holds `start` bytes already.
    pub(crate) fn new(file: File, path: PathBuf, start: u64) -> Stream {
        Stream {
            file,
            path,
            buffer: Vec::with_capacity(BUFFER),
            on_disk: start,
            committed: start,
            failed: false,
            placing: None,
        }
    }

    /// The stream, whose file takes its name (and replaces what had it) at its first
    /// mark.
    pub(crate) fn placing(self, placing: Placing) -> Stream {
        Stream {
            placing: Some(placing),
            ..self
        }
    }

    /// The file's path, as messages show it.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The file's length at the last mark.
    pub fn committed(&self) -> u64 {
        self.committed
    }

    /// Whether sending to the file has failed (a full disk): the stream to name in a
    /// message.
    pub fn failed(&self) -> bool {
        self.failed
    }

    /// Sends what is buffered to the file and marks its end: the rows written so far are
    /// whole, and [`Stream::rollback`] keeps them.
    pub fn commit(&mut self) -> io::Result<()> {
        self.send()?;
        if let Some(placing) = self.placing.take() {
            place(placing).map_err(|e| match e {
                WriteError::Io(e) => e,
                WriteError::Refused(r) => io::Error::other(match r {
                    Refusal::Changed => "it changed while it was being written".to_string(),
                    other => format!("{other:?}"),
                }),
            })?;
        }
        self.committed = self.on_disk;
        Ok(())
    }

    /// After a failed write: drops what is buffered and cuts the file back to its last
    /// mark, so that it ends on whole rows (a new file not given its name yet goes, and
    /// what had the name stays).
    pub fn rollback(&mut self) -> io::Result<()> {
        if self.placing.take().is_some() {
            self.buffer.clear();
            return Ok(());
        }
        self.buffer.clear();
        self.file.set_len(self.committed)?;
        self.file.seek(SeekFrom::Start(self.committed))?;
        self.on_disk = self.committed;
        Ok(())
    }

    /// Marks the end, and flushes the file to disk.
    pub fn finish(mut self) -> io::Result<()> {
        self.commit()?;
        self.file.sync_data()
    }

    /// Sends the buffer to the file; on a failure, what did not go stays buffered.
    fn send(&mut self) -> io::Result<()> {
        let mut sent = 0;
        let result = loop {
            if sent == self.buffer.len() {
                break Ok(());
            }
            match self.file.write(&self.buffer[sent..]) {
                Ok(0) => break Err(io::Error::from(io::ErrorKind::WriteZero)),
                Ok(n) => {
                    sent += n;
                    self.on_disk += n as u64;
                }
                Err(e) if e.kind() == io::ErrorKind::Interrupted => {}
                Err(e) => break Err(e),
            }
        };
        self.buffer.drain(..sent);
        self.failed |= result.is_err();
        result
    }
}

/// Gives the new file of `placing` its name: in the place of the file it replaces, if
/// that has not changed, or a name nothing has.
fn place(placing: Placing) -> Result<(), WriteError> {
    let Placing {
        new,
        dir,
        name,
        replacing,
    } = placing;
    match replacing {
        Some(stamp) => {
            if !stamp.same_version(&stamp_now(&dir, &name)?) {
                return Err(Refusal::Changed.into());
            }
            new.rename_over(&dir, &name)
        }
        None => new.link_new(&dir, &name),
    }
}

impl Write for Stream {
    fn write(&mut self, bytes: &[u8]) -> io::Result<usize> {
        self.buffer.extend_from_slice(bytes);
        if self.buffer.len() >= BUFFER {
            self.send()?;
        }
        Ok(bytes.len())
    }

    fn flush(&mut self) -> io::Result<()> {
        self.send()
    }
}
