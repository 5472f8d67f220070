//! What a run reads and writes, each reader next to its writer:
//!
//! * [`particles`]: particles from CSV and pkdgrav `.ss` files;
//! * [`par`]: pkdgrav parameter files;
//! * [`cohesion`]: pkdgrav's per-colour cohesion files (`achCohesionFile`);
//! * [`trajectory`]: the `particles.csv` and `walls.csv` of `walls-sim run --out`,
//!   written and read back as the same rows;
//! * [`wallsreact`]: pkdgrav's `WALLSREACTdata.out` and `WALLSREACTviz.out`, and the
//!   viz file read back as the [`wallsreact::VizWall`]s written.

pub mod cohesion;
pub mod par;
pub mod particles;
pub mod trajectory;
pub mod wallsreact;

use crate::warning::Warning;
use walls_keywords::number::Problem;

/// A number's text as every reader of a run's inputs takes it, by the tools' one rule
/// ([`walls_keywords::number`]): its value, or why it is refused (not a number, not
/// finite, overflow, underflow). A subnormal is read, and warned about in `warnings`
/// (W701) at `at` (where it is; called only then).
pub(crate) fn number(
    text: &str,
    at: impl FnOnce() -> String,
    warnings: &mut Vec<Warning>,
) -> Result<f64, Problem> {
    let x = walls_keywords::number::read(text)?;
    subnormal(x, at, warnings);
    Ok(x)
}

/// Warns in `warnings` (W701) about `x`, read at `at`, if it is subnormal.
pub(crate) fn subnormal(x: f64, at: impl FnOnce() -> String, warnings: &mut Vec<Warning>) {
    if walls_keywords::number::subnormal(x).is_some() {
        warnings.push(Warning::SubnormalInput { at: at(), value: x });
    }
}

/// `warnings` about numbers of the file `path`, located in it (`path: line 3: …`).
fn in_file(path: &str, warnings: Vec<Warning>) -> Vec<Warning> {
    warnings
        .into_iter()
        .map(|w| match w {
            Warning::SubnormalInput { at, value } => Warning::SubnormalInput {
                at: format!("{path}: {at}"),
                value,
            },
            other => other,
        })
        .collect()
}

/// Why an input could not be read, and where.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct InputError {
    /// "line 4", "byte 112", …
    pub at: String,
    /// What is wrong.
    pub message: String,
}

impl std::fmt::Display for InputError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.at.is_empty() {
            return f.write_str(&self.message);
        }
        write!(f, "{}: {}", self.at, self.message)
    }
}

fn error(at: impl Into<String>, message: impl Into<String>) -> InputError {
    InputError {
        at: at.into(),
        message: message.into(),
    }
}

/// A file that could not be read, or whose contents are wrong: its path and why.
#[derive(Debug)]
pub enum FileError {
    /// The file could not be read.
    Read {
        /// The path as given.
        path: String,
        /// Why.
        error: std::io::Error,
    },
    /// The file was read but is not what it should be.
    Input {
        /// The path as given.
        path: String,
        /// What is wrong, and where.
        error: InputError,
    },
}

impl FileError {
    fn read(path: &str, error: std::io::Error) -> Self {
        FileError::Read {
            path: path.to_string(),
            error,
        }
    }

    fn input(path: &str, error: InputError) -> Self {
        FileError::Input {
            path: path.to_string(),
            error,
        }
    }
}

impl std::fmt::Display for FileError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            FileError::Read { path, error } => write!(f, "cannot read {path}: {error}"),
            FileError::Input { path, error } => write!(f, "{path}: {error}"),
        }
    }
}

impl std::error::Error for FileError {}

/// The most characters of a file's text a message quotes.
const EXCERPT: usize = 60;

/// `text`, a value of an input file, as a message quotes it: whole when short, else its
/// first [`EXCERPT`] characters and how long it is (a 10 MB number is not echoed).
pub(crate) fn excerpt(text: &str) -> String {
    match text.char_indices().nth(EXCERPT) {
        None => text.to_string(),
        Some((cut, _)) => format!("{}… ({} characters)", &text[..cut], text.chars().count()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_ten_megabyte_value_is_quoted_in_sixty_characters() {
        assert_eq!(excerpt("0.5"), "0.5");
        let long = format!("0.{}1", "0".repeat(10_000_000));
        let error = particles::read_csv(&format!(
            "mass,radius,x,y,z,vx,vy,vz\n{long},1,0,0,0,0,0,0\n"
        ))
        .unwrap_err()
        .to_string();
        assert!(error.len() < 300, "{} bytes", error.len());
        assert!(error.contains("… (10000003 characters)"), "{error}");
    }
}
