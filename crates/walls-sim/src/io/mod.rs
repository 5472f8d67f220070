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

/// A decimal number as the tools read it: a finite double, and not one that a number
/// written with a non-zero digit rounds to 0 (`1e-400`: C's `atof`, and so pkdgrav,
/// would read 0 without a word). The error says what is wrong.
pub fn number(text: &str) -> Result<f64, String> {
    let x: f64 = text.parse().map_err(|_| "not a number".to_string())?;
    if x.is_nan() || (x.is_infinite() && !text.chars().any(|c| c.is_ascii_digit())) {
        return Err("not a finite number".into());
    }
    if x.is_infinite() {
        return Err(
            "beyond the largest double (about 1.8e308): C's atof, and so pkdgrav, would read infinity"
                .into(),
        );
    }
    let mantissa = text.split(['e', 'E']).next().unwrap_or("");
    if x == 0.0 && mantissa.chars().any(|c| ('1'..='9').contains(&c)) {
        return Err(
            "below the smallest double (about 4.9e-324): C's atof, and so pkdgrav, would read 0"
                .into(),
        );
    }
    Ok(x)
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
