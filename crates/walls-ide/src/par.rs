//! The one check of a pkdgrav `.par` file for a build ([`walls_par::check`]), from its
//! bytes as a walls file's are read: bytes that are not UTF-8 give the encoding error
//! only, at the valid prefix.

use std::sync::Arc;
use walls_diagnostics::Diagnostic;
use walls_par::Build;

/// A checked `.par` file.
#[derive(Debug, Clone)]
pub struct ParChecked {
    /// The text the spans refer to (the valid prefix, for bytes that are not UTF-8).
    pub text: Arc<str>,
    /// Its diagnostics, sorted by position.
    pub diagnostics: Vec<Diagnostic>,
}

/// Checks the `.par` text `text` for `build`.
pub fn check_par_text(text: String, build: &Build) -> ParChecked {
    let diagnostics = walls_par::check(&text, build);
    ParChecked {
        text: text.into(),
        diagnostics,
    }
}

/// Checks the `.par` bytes `bytes` for `build`.
pub fn check_par_bytes(bytes: Vec<u8>, build: &Build) -> ParChecked {
    match walls_syntax::decode(bytes) {
        Ok(text) => check_par_text(text, build),
        Err((prefix, diagnostic)) => ParChecked {
            text: prefix.into(),
            diagnostics: vec![*diagnostic],
        },
    }
}
