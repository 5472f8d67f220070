//! The settings `walls-lint` and `walls-fmt` use for each file (docs/configuration.md):
//! the nearest settings file above it, the one `--config` names, or none with
//! `--isolated`. Command-line flags win over the file; the commands apply them.

use clap::Args;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};
use walls_config::{Settings, SettingsError};
use walls_format::FormatOptions;

/// `--config` and `--isolated`, shared by `walls-lint` and `walls-fmt`.
#[derive(Args, Clone, Default)]
pub struct SettingsArgs {
    /// Use this settings file for every file (walls.toml, .walls.toml, pyproject.toml's
    /// [tool.walls], .walls-fmt.toml) instead of the nearest one above each file.
    #[arg(long, value_name = "PATH", conflicts_with = "isolated")]
    pub config: Option<PathBuf>,
    /// Ignore every settings file: the flags and the defaults only.
    #[arg(long)]
    pub isolated: bool,
}

/// Where each file's settings come from, with the ones found so far by folder (so that
/// a hundred thousand files of one folder look for them once).
pub(crate) struct Resolver {
    /// The settings of `--config` or `--isolated`, the same for every file.
    fixed: Option<Arc<Settings>>,
    /// The settings found upward from each folder asked about.
    by_dir: Found<Arc<Settings>>,
    /// The formatting options found upward from each folder asked about.
    format_by_dir: Found<FormatOptions>,
}

/// What was found upward from each folder asked about.
type Found<T> = Mutex<HashMap<PathBuf, Result<T, SettingsError>>>;

/// What `found` has for `dir`, else what `find` finds from it, kept.
fn found<T: Clone>(
    found: &Found<T>,
    dir: PathBuf,
    find: impl FnOnce(&Path) -> Result<T, SettingsError>,
) -> Result<T, SettingsError> {
    let mut found = found.lock().unwrap_or_else(|e| e.into_inner());
    found.entry(dir).or_insert_with_key(|dir| find(dir)).clone()
}

impl Resolver {
    /// Reads `--config`'s file, if one is named.
    pub(crate) fn new(args: &SettingsArgs) -> Result<Self, SettingsError> {
        let fixed = if args.isolated {
            Some(Arc::new(Settings::default()))
        } else if let Some(path) = &args.config {
            Some(Arc::new(walls_config::load(path)?))
        } else {
            None
        };
        Ok(Resolver {
            fixed,
            by_dir: Mutex::default(),
            format_by_dir: Mutex::default(),
        })
    }

    /// The settings for the file or folder at `path` as given on the command line (`-`:
    /// standard input, found from the current folder): for a folder, those found from the
    /// folder itself.
    pub(crate) fn settings(&self, path: &str) -> Result<Arc<Settings>, SettingsError> {
        if let Some(fixed) = &self.fixed {
            return Ok(fixed.clone());
        }
        found(&self.by_dir, folder_of(path), |dir| {
            walls_config::find(dir).map(Arc::new)
        })
    }

    /// The formatting options for the file at `path` (`-`: standard input), before the
    /// flags.
    pub(crate) fn format_options(&self, path: &str) -> Result<FormatOptions, SettingsError> {
        match &self.fixed {
            Some(fixed) => Ok(fixed.format.clone().unwrap_or_default()),
            None => found(&self.format_by_dir, folder_of(path), |dir| {
                walls_config::find_format(dir).map(|(options, _)| options)
            }),
        }
    }
}

/// The folder whose settings apply to `path`: itself for a folder, the current folder
/// for standard input, else the file's folder.
fn folder_of(path: &str) -> PathBuf {
    let p = Path::new(path);
    if path == "-" {
        PathBuf::from(".")
    } else if p.is_dir() {
        p.to_path_buf()
    } else {
        p.parent()
            .filter(|d| !d.as_os_str().is_empty())
            .map_or_else(|| PathBuf::from("."), Path::to_path_buf)
    }
}

/// The absolute path of the file at `path`, which per-file globs match (`None` for
/// standard input).
pub(crate) fn absolute_file(path: &str) -> Option<PathBuf> {
    if path == "-" {
        return None;
    }
    let p = Path::new(path);
    Some(walls_config::absolute(&folder_of(path)).join(p.file_name()?))
}
