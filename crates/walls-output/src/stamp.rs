//! What identifies one version of a file ([`Stamp`]), and what kind of file it is
//! ([`FileKind`]).

use std::fs::Metadata;
use std::os::unix::fs::MetadataExt;

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

impl Stamp {
    /// The stamp of what `stat(2)` says.
    #[allow(
        clippy::unnecessary_cast,
        reason = "the fields' types differ between targets and backends"
    )]
    pub(crate) fn from_stat(st: &rustix::fs::Stat) -> Stamp {
        Stamp {
            dev: st.st_dev as u64,
            ino: st.st_ino as u64,
            size: st.st_size as u64,
            mtime: (st.st_mtime as i64, st.st_mtime_nsec as i64),
            ctime: (st.st_ctime as i64, st.st_ctime_nsec as i64),
            mode: st.st_mode as u32,
            uid: st.st_uid as u32,
            gid: st.st_gid as u32,
            nlink: st.st_nlink as u64,
        }
    }

    /// The kind of file.
    pub fn kind(&self) -> FileKind {
        FileKind::of(self.mode)
    }

    /// Device and inode: the file whatever its name.
    pub fn identity(&self) -> (u64, u64) {
        (self.dev, self.ino)
    }

    /// Whether `now` is still this version: same device and inode (not replaced), same
    /// size, modification and status-change times to the nanosecond.
    pub fn same_version(&self, now: &Stamp) -> bool {
        self.identity() == now.identity()
            && self.size == now.size
            && self.mtime == now.mtime
            && self.ctime == now.ctime
    }
}

/// The kinds of file, as `st_mode` tells them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FileKind {
    /// A regular file.
    Regular,
    /// A folder.
    Folder,
    /// A FIFO (named pipe).
    Fifo,
    /// A character device (`/dev/null`, a terminal).
    CharDevice,
    /// A block device (a disk).
    BlockDevice,
    /// A Unix socket.
    Socket,
    /// A symbolic link (seen only when not followed).
    Symlink,
}

impl FileKind {
    /// The kind of a file whose `st_mode` is `mode`.
    pub fn of(mode: u32) -> FileKind {
        match mode & 0o170000 {
            0o100000 => FileKind::Regular,
            0o040000 => FileKind::Folder,
            0o010000 => FileKind::Fifo,
            0o020000 => FileKind::CharDevice,
            0o060000 => FileKind::BlockDevice,
            0o140000 => FileKind::Socket,
            0o120000 => FileKind::Symlink,
            // No other type exists on Linux; anything else is as foreign as a device.
            _ => FileKind::CharDevice,
        }
    }

    /// The kind with its article, as messages name it: "a FIFO".
    pub fn named(self) -> &'static str {
        match self {
            FileKind::Regular => "a regular file",
            FileKind::Folder => "a folder",
            FileKind::Fifo => "a FIFO (named pipe)",
            FileKind::CharDevice => "a character device",
            FileKind::BlockDevice => "a block device",
            FileKind::Socket => "a socket",
            FileKind::Symlink => "a symbolic link",
        }
    }
}
