//! Reading the files named on the command line; `-` is standard input.

use std::io::Read;

/// One input as read: its display name and bytes, or why it could not be read.
pub struct Input {
    /// The path as given, or `<stdin>` for `-`.
    pub name: String,
    /// The bytes, or a message for people saying why they could not be read.
    pub bytes: Result<Vec<u8>, String>,
}

/// Largest file the tools accept: spans are stored as 32-bit offsets.
pub const MAX_FILE_BYTES: u64 = u32::MAX as u64;

/// Reads `path`, or standard input when it is `-`.
pub fn read(path: &str) -> Input {
    if path == "-" {
        let mut bytes = Vec::new();
        let result = std::io::stdin()
            .lock()
            .take(MAX_FILE_BYTES + 1)
            .read_to_end(&mut bytes)
            .map_err(|e| format!("cannot read standard input: {e}"))
            .and_then(|_| check_size(bytes));
        return Input {
            name: "<stdin>".into(),
            bytes: result,
        };
    }
    let result = std::fs::File::open(path)
        .and_then(|f| {
            let mut bytes = Vec::new();
            f.take(MAX_FILE_BYTES + 1).read_to_end(&mut bytes)?;
            Ok(bytes)
        })
        .map_err(|e| format!("cannot read {path}: {e}"))
        .and_then(check_size);
    Input {
        name: path.to_string(),
        bytes: result,
    }
}

fn check_size(bytes: Vec<u8>) -> Result<Vec<u8>, String> {
    if bytes.len() as u64 > MAX_FILE_BYTES {
        Err(format!(
            "larger than {MAX_FILE_BYTES} bytes, the most the tools read"
        ))
    } else {
        Ok(bytes)
    }
}
