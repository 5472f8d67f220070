//! The formatting options as a settings file writes them: the keys of `.walls-fmt.toml`
//! and of the `[format]` table of `walls.toml` (found and read by `walls-config`).
//!
//! ```toml
//! indent-width = 4
//! align-trailing-comments = true
//! keep-blank-lines = false
//! ```
//!
//! Every key is optional (the default stands in) and may also be spelled with `_`
//! (`indent_width`), as `.walls-fmt.toml` files have them; an unknown key or a value of
//! the wrong type is a deserialisation error with its span.

use crate::FormatOptions;
use serde::Deserialize;
use std::ops::Range;
use toml::Spanned;

/// The most spaces `indent-width` may ask for.
pub const MAX_INDENT_WIDTH: usize = 16;

/// The formatting table of a settings file, as written.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
pub struct FormatTable {
    /// Spaces before a statement inside a block.
    #[serde(alias = "indent_width")]
    pub indent_width: Option<Spanned<usize>>,
    /// Line up the comments after consecutive statements of a block.
    #[serde(alias = "align_trailing_comments")]
    pub align_trailing_comments: Option<bool>,
    /// Keep one of the blank lines the author wrote between statements.
    #[serde(alias = "keep_blank_lines")]
    pub keep_blank_lines: Option<bool>,
}

impl FormatTable {
    /// The options the table gives (defaults for the keys it leaves out), or the span of
    /// a value out of range with the reason.
    pub fn options(&self) -> Result<FormatOptions, (Range<usize>, String)> {
        let defaults = FormatOptions::default();
        let indent_width = match &self.indent_width {
            Some(n) if *n.get_ref() > MAX_INDENT_WIDTH => {
                return Err((
                    n.span(),
                    format!(
                        "indent-width {} is more than {MAX_INDENT_WIDTH}",
                        n.get_ref()
                    ),
                ));
            }
            Some(n) => *n.get_ref(),
            None => defaults.indent_width,
        };
        Ok(FormatOptions {
            indent_width,
            align_trailing_comments: self
                .align_trailing_comments
                .unwrap_or(defaults.align_trailing_comments),
            keep_blank_lines: self.keep_blank_lines.unwrap_or(defaults.keep_blank_lines),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn both_spellings_are_read_and_limits_located() {
        let t: FormatTable =
            toml::from_str("indent_width = 4\nkeep-blank-lines = false\n").unwrap();
        let o = t.options().unwrap();
        assert_eq!(o.indent_width, 4);
        assert!(!o.keep_blank_lines && !o.align_trailing_comments);
        let t: FormatTable = toml::from_str("indent-width = 17\n").unwrap();
        assert_eq!(
            t.options().unwrap_err(),
            (15..17, "indent-width 17 is more than 16".to_string())
        );
        let e = toml::from_str::<FormatTable>("indent = 4\n").unwrap_err();
        assert!(e.message().starts_with("unknown field `indent`"), "{e}");
    }
}
