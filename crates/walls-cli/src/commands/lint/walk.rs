//! The files `walls-lint` checks: the ones named, and those found in the folders named.
//!
//! A folder is walked with the `ignore` crate, so `.gitignore`, `.ignore` and hidden
//! files are skipped as `git` and `ripgrep` skip them. In it, walls-lint checks every
//! file matching an `--include` glob (default `*.walls`) and every walls file that a
//! `.par` file of the tree names with `achWallsFile` (relative to the `.par`), whatever
//! its name, if it stays in the folder walked (no absolute path, no `..` or symbolic link
//! leading out) and reads as a walls file (its first word is a keyword): any other is an
//! error at the `.par`'s line, never read further, so that a hostile `.par` cannot have
//! a file outside the tree rewritten by `--fix` or a secrets file quoted in a report;
//! `--exclude` globs remove files and whole folders. Globs are gitignore-style
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
        .overrides(excludes.clone())
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
            match named_walls_file(root, entry.path(), &shown) {
                Ok(Some(walls)) => {
                    // A file the walk's globs exclude (or whose folder they exclude) is not
                    // checked, whoever names it.
                    let excluded = walls.strip_prefix(root).is_ok_and(|inside| {
                        inside
                            .ancestors()
                            .filter(|a| !a.as_os_str().is_empty())
                            .any(|a| excludes.matched(a, a != inside).is_ignore())
                    });
                    if !excluded {
                        let walls = walls.strip_prefix(".").unwrap_or(&walls).to_path_buf();
                        add(walls, seen, targets);
                        found += 1;
                    }
                }
                Ok(None) => {}
                // A file checked already (named, or found walking a folder above) is
                // checked: nothing is lost by not following the path again.
                Err(Named { path, .. })
                    if path
                        .as_ref()
                        .and_then(|p| std::fs::canonicalize(p).ok())
                        .is_some_and(|p| seen.contains(&p)) => {}
                Err(Named { message, .. }) => targets.error(shown, message),
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

/// The walls file that the `.par` at `par` (shown as `shown`), found walking `root`, names
/// with `achWallsFile`, relative to the `.par`'s folder; `None` when it names none. A
/// path that leaves `root`, names no file, or names a file that is not a walls file is
/// an error at the `.par`'s line: it is not followed, and nothing of that file is shown.
fn named_walls_file(root: &Path, par: &Path, shown: &str) -> Result<Option<PathBuf>, Named> {
    let bytes = std::fs::File::open(par)
        .map_err(|e| format!("cannot read {shown}: {e}"))
        .and_then(|f| crate::input::read_all(f, shown))?;
    let text = String::from_utf8_lossy(&bytes);
    let params = walls_sim::io::par::read_par(&text)
        .map_err(|e| format!("{shown}: cannot find its walls file: {e}"))?;
    let Some(name) = params.walls_file.as_deref() else {
        return Ok(None);
    };
    let at = match params.line_of("achWallsFile") {
        Some(line) => format!("{shown}:{line}: achWallsFile = {name}"),
        None => format!("{shown}: achWallsFile = {name}"),
    };
    let base = par.parent().unwrap_or(Path::new(""));
    let walls =
        walls_output::confine::within(root, base, Path::new(name)).map_err(|leaves| Named {
            message: format!(
                "{at} leaves {}, the folder walked ({leaves}): not followed; name the walls \
                 file on the command line to check it",
                root.display()
            ),
            path: Some(base.join(name)),
        })?;
    if !walls.is_file() {
        return Err(format!("{at}: no such file").into());
    }
    if !looks_like_walls(&walls) {
        return Err(format!(
            "{at}: not a walls file (its first word is no walls keyword): not checked"
        )
        .into());
    }
    Ok(Some(walls))
}

/// Why the walls file a `.par` names is not checked: the message, and where the path
/// leads when it leaves the folder walked.
struct Named {
    message: String,
    path: Option<PathBuf>,
}

impl From<String> for Named {
    fn from(message: String) -> Self {
        Named {
            message,
            path: None,
        }
    }
}

/// Whether the file at `path` reads as a walls file: its first word (after white space,
/// separators, comments and a byte-order mark) is a keyword of the language, or it has
/// none. A file a `.par` names that is not one (a settings or secrets file a hostile
/// `.par` points at) is never checked, so that no word of it reaches a report.
fn looks_like_walls(path: &Path) -> bool {
    use std::io::Read;
    let mut head = Vec::new();
    let read = std::fs::File::open(path).and_then(|f| f.take(4096).read_to_end(&mut head));
    if read.is_err() {
        // The check of the file says why it cannot be read.
        return true;
    }
    let head = head.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(&head);
    let mut rest = head;
    loop {
        let skip = rest
            .iter()
            .position(|&b| !matches!(b, b' ' | b'\t' | b'\n' | b'\r' | 0x0b | 0x0c | b',' | b'='));
        rest = &rest[skip.unwrap_or(rest.len())..];
        match rest.first() {
            None => return true,
            Some(b'#' | b'!') => {
                let end = rest.iter().position(|&b| b == b'\n').unwrap_or(rest.len());
                rest = &rest[end..];
            }
            Some(_) => break,
        }
    }
    let end = rest
        .iter()
        .position(|&b| b.is_ascii_whitespace() || matches!(b, 0x0b | b',' | b'=' | b'#' | b'!'))
        .unwrap_or(rest.len());
    std::str::from_utf8(&rest[..end]).is_ok_and(|word| walls_keywords::keyword(word).is_some())
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
                format!("{par}:1: achWallsFile = gone.walls: no such file")
            )]
        );
    }
}
