//! Reading the files named on the command line; `-` is standard input.

use std::io::Read;

/// One input as read: its display name and bytes, or why it could not be read.
pub struct Input {
    /// The path as given, or `<stdin>` for `-`.
    pub name: String,
    /// The bytes, or a message for people saying why they could not be read.
    pub bytes: Result<Vec<u8>, String>,
}

/// Largest file the tools accept (settings files too): spans are stored as 32-bit offsets.
pub use walls_config::MAX_FILE_BYTES;

/// The name messages give the input `path`: `<stdin>` for `-`, else the path as given.
pub fn display_name(path: &str) -> String {
    if path == "-" {
        "<stdin>".into()
    } else {
        path.into()
    }
}

/// Reads `path`, or standard input when it is `-`.
pub fn read(path: &str) -> Input {
    if path == "-" {
        return Input {
            name: display_name(path),
            bytes: read_all(std::io::stdin().lock(), "standard input"),
        };
    }
    let bytes = std::fs::File::open(path)
        .map_err(|e| format!("cannot read {path}: {e}"))
        .and_then(|f| read_all(f, path));
    Input {
        name: path.to_string(),
        bytes,
    }
}

/// Reads all of `reader`, up to [`MAX_FILE_BYTES`] (more is an error); `what` names it
/// in the messages (a path, or "standard input").
pub fn read_all(reader: impl Read, what: &str) -> Result<Vec<u8>, String> {
    read_at_most(reader, what, MAX_FILE_BYTES)
}

fn read_at_most(reader: impl Read, what: &str, limit: u64) -> Result<Vec<u8>, String> {
    walls_config::read_at_most(reader, limit).map_err(|e| format!("cannot read {what}: {e}"))
}

#[cfg(test)]
mod tests {
    use super::read_at_most;

    #[test]
    fn a_file_over_the_limit_is_refused_by_name() {
        assert_eq!(read_at_most(&b"wall"[..], "a.walls", 4).unwrap(), b"wall");
        assert_eq!(
            read_at_most(&b"wall "[..], "a.walls", 4).unwrap_err(),
            "cannot read a.walls: larger than 4 bytes, the most the tools read"
        );
    }
}
