//! `.walls-fmt.toml`: the formatting options of a project, found upward from a file.
//!
//! ```toml
//! indent_width = 4
//! align_trailing_comments = true
//! keep_blank_lines = false
//! ```
//!
//! Every key is optional (the default stands in); an unknown key or a value of the wrong
//! type is an error that names the file, line and column.

use crate::FormatOptions;
use serde::Deserialize;
use std::path::{Path, PathBuf};

/// The name of the configuration file.
pub const CONFIG_FILE: &str = ".walls-fmt.toml";

/// A configuration file that could not be used.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ConfigError {
    /// The file.
    pub path: PathBuf,
    /// What is wrong, with its line and column where it has one.
    pub message: String,
}

impl std::fmt::Display for ConfigError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.path.display(), self.message)
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct File {
    indent_width: Option<usize>,
    align_trailing_comments: Option<bool>,
    keep_blank_lines: Option<bool>,
}

/// The options for a file in directory `dir`: those of the nearest `.walls-fmt.toml` in
/// `dir` or a parent, else the defaults. Returns the file used, if any.
pub fn discover(dir: &Path) -> Result<(FormatOptions, Option<PathBuf>), ConfigError> {
    for d in dir.ancestors() {
        let path = d.join(CONFIG_FILE);
        if path.is_file() {
            return load(&path).map(|o| (o, Some(path)));
        }
    }
    Ok((FormatOptions::default(), None))
}

fn load(path: &Path) -> Result<FormatOptions, ConfigError> {
    let error = |message: String| ConfigError {
        path: path.to_path_buf(),
        message,
    };
    let text = std::fs::read_to_string(path).map_err(|e| error(e.to_string()))?;
    let file: File = toml::from_str(&text).map_err(|e| {
        let at = e.span().map(|s| {
            let line = text[..s.start].matches('\n').count() + 1;
            let column = text[..s.start]
                .rsplit('\n')
                .next()
                .map_or(0, |l| l.chars().count())
                + 1;
            format!("{line}:{column}: ")
        });
        error(format!("{}{}", at.unwrap_or_default(), e.message()))
    })?;
    let defaults = FormatOptions::default();
    let indent_width = file.indent_width.unwrap_or(defaults.indent_width);
    if indent_width > FormatOptions::MAX_INDENT_WIDTH {
        return Err(error(format!(
            "indent_width {indent_width} is more than {}",
            FormatOptions::MAX_INDENT_WIDTH
        )));
    }
    Ok(FormatOptions {
        indent_width,
        align_trailing_comments: file
            .align_trailing_comments
            .unwrap_or(defaults.align_trailing_comments),
        keep_blank_lines: file.keep_blank_lines.unwrap_or(defaults.keep_blank_lines),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn found_upward_and_errors_located() {
        let root = std::env::temp_dir().join(format!("walls-fmt-config-{}", std::process::id()));
        let deep = root.join("a/b");
        std::fs::create_dir_all(&deep).unwrap();
        assert_eq!(discover(&deep).unwrap().1, None);
        std::fs::write(
            root.join(CONFIG_FILE),
            "indent_width = 4\nkeep_blank_lines = false\n",
        )
        .unwrap();
        let (options, path) = discover(&deep).unwrap();
        assert_eq!(path, Some(root.join(CONFIG_FILE)));
        assert_eq!(options.indent_width, 4);
        assert!(!options.keep_blank_lines && !options.align_trailing_comments);
        std::fs::write(root.join(CONFIG_FILE), "indent_width = 2\nindent = 4\n").unwrap();
        let e = discover(&deep).unwrap_err();
        assert!(
            e.message.starts_with("2:1: unknown field `indent`"),
            "{}",
            e.message
        );
        std::fs::write(root.join(CONFIG_FILE), "keep_blank_lines = \"yes\"\n").unwrap();
        let e = discover(&deep).unwrap_err();
        assert!(e.message.starts_with("1:20: "), "{}", e.message);
        std::fs::remove_dir_all(&root).unwrap();
    }
}
