//! The files `walls-lint` checks: the ones named, and those found in the folders named.
//!
//! A folder is walked with the `ignore` crate, so `.gitignore`, `.ignore` and hidden
//! files are skipped as `git` and `ripgrep` skip them. In it, walls-lint checks every
//! file matching an `--include` glob (default `*.walls`) and every walls file that a
//! `.par` file of the tree names with `achWallsFile` (relative to the `.par`), whatever
//! its name; `--exclude` globs remove files and whole folders. Globs are gitignore-style
//! and relative to the folder named. Each file is checked once, in the order found
//! (folders in name order).

use ignore::WalkBuilder;
use ignore::overrides::{Override, OverrideBuilder};
use std::collections::HashSet;
use std::path::{Path, PathBuf};

/// The include globs when none is given.
pub(super) const DEFAULT_INCLUDE: &str = "*.walls";

/// What the command line's paths expand to.
#[derive(Default)]
pub(super) struct Targets {
    /// The files to check, as paths to show (`-` for standard input).
    pub files: Vec<String>,
    /// Problems to report as I/O errors, each with the path it is about: a folder with
    /// no walls file, a `.par` that cannot be read or names a missing file.
    pub errors: Vec<(String, String)>,
}

impl Targets {
    /// Adds an error, unless a folder named twice (or inside another named) found it
    /// already.
    fn error(&mut self, path: String, error: String) {
        let error = (path, error);
        if !self.errors.contains(&error) {
            self.errors.push(error);
        }
    }
}

/// The include and exclude globs of a folder named on the command line.
pub(super) type Globs = (Vec<String>, Vec<String>);

/// Expands `paths`: files stay as given, folders become the walls files in them, walked
/// with the include and exclude globs `globs` gives for each. An invalid glob (or a
/// folder whose globs cannot be found) is a usage error.
pub(super) fn expand(
    paths: &[String],
    globs: impl Fn(&str) -> Result<Globs, String>,
) -> Result<Targets, String> {
    let mut targets = Targets::default();
    let mut seen = HashSet::new();
    for path in paths {
        if path == "-" || !Path::new(path).is_dir() {
            add(PathBuf::from(path), &mut seen, &mut targets);
            continue;
        }
        let (include, exclude) = globs(path)?;
        if walk(Path::new(path), &include, &exclude, &mut seen, &mut targets)? == 0 {
            let globs = if include.is_empty() {
                DEFAULT_INCLUDE.to_string()
            } else {
                include.join(", ")
            };
            targets.error(
                path.clone(),
                format!(
                    "{path}: no walls file in this folder (no file matching {globs}, and no .par naming one)"
                ),
            );
        }
    }
    Ok(targets)
}

/// Adds the walls files under `root` to `targets`; how many it found, counting those
/// already in (a folder named twice has them still).
fn walk(
    root: &Path,
    include: &[String],
    exclude: &[String],
    seen: &mut HashSet<PathBuf>,
    targets: &mut Targets,
) -> Result<usize, String> {
    let defaults = [DEFAULT_INCLUDE.to_string()];
    let include = if include.is_empty() {
        &defaults[..]
    } else {
        include
    };
    let includes = overrides(root, include, "")?;
    let excludes = overrides(root, exclude, "!")?;
    let walker = WalkBuilder::new(root)
        .overrides(excludes)
        // A .gitignore counts outside a git repository too (a copied or unpacked tree).
        .require_git(false)
        .sort_by_file_name(|a, b| a.cmp(b))
        .build();
    let mut found = 0;
    for entry in walker {
        let entry = match entry {
            Ok(entry) => entry,
            Err(e) => {
                targets.error(root.display().to_string(), e.to_string());
                continue;
            }
        };
        if !entry.file_type().is_some_and(|t| t.is_file()) {
            continue;
        }
        // `walls-lint .` shows `a.walls`, not `./a.walls`.
        let path = entry.path().strip_prefix(".").unwrap_or(entry.path());
        if includes.matched(path, false).is_whitelist() {
            add(path.to_path_buf(), seen, targets);
            found += 1;
        }
        if path.extension().is_some_and(|e| e == "par") {
            let shown = path.display().to_string();
            match named_walls_file(path) {
                Ok(Some(walls)) if walls.is_file() => {
                    add(walls, seen, targets);
                    found += 1;
                }
                Ok(Some(walls)) => {
                    let e = format!(
                        "{shown}: names the walls file {}, which does not exist",
                        walls.display()
                    );
                    targets.error(shown, e);
                }
                Ok(None) => {}
                Err(e) => targets.error(shown, e),
            }
        }
    }
    Ok(found)
}

/// Adds `path` unless it is already in, by any name (`a.walls`, `./a.walls`, a symbolic
/// link, or found again in a folder named).
fn add(path: PathBuf, seen: &mut HashSet<PathBuf>, targets: &mut Targets) {
    let key = std::fs::canonicalize(&path).unwrap_or_else(|_| path.clone());
    if seen.insert(key) {
        targets.files.push(path.display().to_string());
    }
}

/// The globs `patterns`, each prefixed (`!` to exclude), relative to `root`.
fn overrides(root: &Path, patterns: &[String], prefix: &str) -> Result<Override, String> {
    let mut builder = OverrideBuilder::new(root);
    for p in patterns {
        builder
            .add(&format!("{prefix}{p}"))
            .map_err(|e| format!("invalid glob `{p}`: {e}"))?;
    }
    builder.build().map_err(|e| format!("invalid glob: {e}"))
}

/// The walls file a `.par` names with `achWallsFile`, relative to the `.par`'s folder.
fn named_walls_file(par: &Path) -> Result<Option<PathBuf>, String> {
    let text =
        std::fs::read_to_string(par).map_err(|e| format!("cannot read {}: {e}", par.display()))?;
    let params = walls_sim::io::par::read_par(&text)
        .map_err(|e| format!("{}: cannot find its walls file: {e}", par.display()))?;
    Ok(params
        .walls_file
        .map(|name| par.parent().unwrap_or(Path::new("")).join(name)))
}

#[cfg(test)]
mod tests {
    use super::expand;
    use std::path::Path;

    fn write(root: &Path, name: &str, text: &str) {
        let path = root.join(name);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(path, text).unwrap();
    }

    #[test]
    fn a_tree_gives_its_walls_files_once_in_name_order() {
        let dir = tempfile::tempdir().unwrap();
        let root = dir.path();
        for name in [
            "a.walls",
            "ignored.walls",
            ".hidden/h.walls",
            "sub/b.walls",
            "sub/old/c.walls",
            "scene.dat",
        ] {
            write(root, name, "wall type plane\n");
        }
        write(root, ".gitignore", "ignored.walls\n");
        write(root, "sub/run.par", "achWallsFile = ../scene.dat\n");
        write(root, "z/missing.par", "achWallsFile = gone.walls\n");
        let r = root.display();
        let named = format!("{r}/scene.dat");
        let targets = expand(
            &[
                named.clone(),
                r.to_string(),
                r.to_string(),
                format!("{r}/sub"),
            ],
            |_| Ok((Vec::new(), vec!["old".to_string()])),
        )
        .unwrap();
        // scene.dat is named first, so the .par naming it adds nothing; the folder named
        // again, and the one inside it, add nothing and are not "folders with no walls file".
        assert_eq!(
            targets.files,
            [named, format!("{r}/a.walls"), format!("{r}/sub/b.walls")]
        );
        let par = format!("{r}/z/missing.par");
        assert_eq!(
            targets.errors,
            [(
                par.clone(),
                format!("{par}: names the walls file {r}/z/gone.walls, which does not exist")
            )]
        );
    }
}
