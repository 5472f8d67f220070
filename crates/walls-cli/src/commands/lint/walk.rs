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
    /// Problems to report as I/O errors: a folder with no walls file, a `.par` that
    /// cannot be read or names a file that is not followed.
    pub errors: Vec<TargetError>,
    /// The folder walked that found each `.par` file a walk found (as shown): its run
    /// directory's files are read inside that folder ([`super::run`]).
    pub walked: std::collections::HashMap<String, PathBuf>,
}

/// A problem with a path of the command line, or a file found walking a folder.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) struct TargetError {
    /// The path it is about, as shown.
    pub path: String,
    /// What is wrong, for people.
    pub message: String,
    /// The line of the file it is about (a `.par`'s line), if any.
    pub line: Option<usize>,
}

impl Targets {
    /// Adds an error, unless a folder named twice (or inside another named) found it
    /// already.
    fn error(&mut self, error: TargetError) {
        if !self.errors.contains(&error) {
            self.errors.push(error);
        }
    }
}

/// The include and exclude globs of a folder named on the command line.
pub(super) type Globs = (Vec<String>, Vec<String>);

/// Expands `paths`: files stay as given, folders become the walls files in them, walked
/// with the include and exclude globs `globs` gives for each. An invalid glob (or a
/// folder whose globs cannot be found) is a usage error. A `.par`'s walls file that a
/// walk does not follow is an error unless the file is checked anyway (named, or listed by
/// another walk), whatever the order of the paths.
pub(super) fn expand(
    paths: &[String],
    globs: impl Fn(&str) -> Result<Globs, String>,
) -> Result<Targets, String> {
    let mut targets = Targets::default();
    let mut seen = HashSet::new();
    let mut not_followed = Vec::new();
    for path in paths {
        if path == "-" || !Path::new(path).is_dir() {
            add(PathBuf::from(path), &mut seen, &mut targets);
            continue;
        }
        let (include, exclude) = globs(path)?;
        let walked = Walk {
            root: Path::new(path),
            include: &include,
            exclude: &exclude,
        };
        if walked.run(&mut seen, &mut targets, &mut not_followed)? == 0 {
            let globs = if include.is_empty() {
                DEFAULT_INCLUDE.to_string()
            } else {
                include.join(", ")
            };
            targets.error(TargetError {
                path: path.clone(),
                message: format!(
                    "{path}: no walls file in this folder (no file matching {globs}, and no .par naming one)"
                ),
                line: None,
            });
        }
    }
    for (error, file) in not_followed {
        if !file.is_some_and(|f| seen.contains(&f)) {
            targets.error(error);
        }
    }
    Ok(targets)
}

/// A folder to walk, with its globs.
struct Walk<'a> {
    root: &'a Path,
    include: &'a [String],
    exclude: &'a [String],
}

impl Walk<'_> {
    /// Adds the walls files under the root to `targets`; how many it found, counting
    /// those already in (a folder named twice has them still). The walls files its `.par`
    /// files name but that it does not follow go to `not_followed`, with the file each
    /// leads to (to drop the error if that file is checked anyway).
    fn run(
        &self,
        seen: &mut HashSet<PathBuf>,
        targets: &mut Targets,
        not_followed: &mut Vec<(TargetError, Option<PathBuf>)>,
    ) -> Result<usize, String> {
        let root = self.root;
        let defaults = [DEFAULT_INCLUDE.to_string()];
        let include = if self.include.is_empty() {
            &defaults[..]
        } else {
            self.include
        };
        let includes = overrides(root, include, "")?;
        let excludes = overrides(root, self.exclude, "!")?;
        let walker = WalkBuilder::new(root)
            .overrides(excludes)
            // A .gitignore counts outside a git repository too (a copied or unpacked tree).
            .require_git(false)
            .sort_by_file_name(|a, b| a.cmp(b))
            .build();
        // Every file the walk lists (not hidden, not ignored, not excluded), in order: a
        // `.par` is followed to these only.
        let mut files = Vec::new();
        for entry in walker {
            match entry {
                Ok(entry) if entry.file_type().is_some_and(|t| t.is_file()) => {
                    files.push(entry.into_path());
                }
                Ok(_) => {}
                Err(e) => targets.error(TargetError {
                    path: root.display().to_string(),
                    message: e.to_string(),
                    line: None,
                }),
            }
        }
        let listed: HashSet<PathBuf> = files
            .iter()
            .filter_map(|f| std::fs::canonicalize(f).ok())
            .collect();
        let mut found = 0;
        for file in &files {
            // `walls-lint .` shows `a.walls`, not `./a.walls`.
            let path = file.strip_prefix(".").unwrap_or(file);
            if includes.matched(path, false).is_whitelist() {
                add(path.to_path_buf(), seen, targets);
                found += 1;
            }
            // A pkdgrav `.par` is checked itself ([`super::Language`]), and followed to
            // the walls file it names.
            if super::is_pkdgrav_par(path) && !includes.matched(path, false).is_whitelist() {
                add(path.to_path_buf(), seen, targets);
                found += 1;
            }
            if super::is_pkdgrav_par(path) {
                (targets.walked)
                    .entry(path.display().to_string())
                    .or_insert_with(|| root.to_path_buf());
            }
            if path.extension().is_some_and(|e| e == "par") {
                match self.named_walls_file(file, &path.display().to_string(), &listed) {
                    Ok(Some(walls)) => {
                        add(walls, seen, targets);
                        found += 1;
                    }
                    Ok(None) => {}
                    Err(not) => not_followed.push(not),
                }
            }
        }
        Ok(found)
    }

    /// The walls file that the `.par` at `par` (shown as `shown`) names with
    /// `achWallsFile`, relative to the `.par`'s folder (or absolute); `None` when it names
    /// none. It is followed only to a file the walk lists (`listed`: inside the folder,
    /// not hidden, not ignored, not excluded, whatever links or `..` the path takes) that
    /// reads as a walls file; anything else is an error at the `.par`'s line, and nothing
    /// of that file is read or shown.
    fn named_walls_file(
        &self,
        par: &Path,
        shown: &str,
        listed: &HashSet<PathBuf>,
    ) -> Result<Option<PathBuf>, (TargetError, Option<PathBuf>)> {
        let error = |message: String, line: Option<usize>| TargetError {
            path: shown.to_string(),
            message,
            line,
        };
        let bytes = std::fs::File::open(par)
            .map_err(|e| format!("cannot read {shown}: {e}"))
            .and_then(|f| crate::input::read_all(f, shown))
            .map_err(|e| (error(e, None), None))?;
        let text = String::from_utf8_lossy(&bytes);
        // Read as pkdgrav reads it (the file's own findings are its check's to report).
        let build = walls_par::Build::default();
        let file = walls_par::check::File::read(&text, &build, &mut Vec::new());
        let Some(name) = file.string("achWallsFile").filter(|n| !n.is_empty()) else {
            return Ok(None);
        };
        let name = name.as_str();
        let line = file.given("achWallsFile").map(|e| e.line);
        let at = match line {
            Some(line) => format!("{shown}:{line}: achWallsFile = {name}"),
            None => format!("{shown}: achWallsFile = {name}"),
        };
        let base = par.parent().unwrap_or(Path::new(""));
        let path = base.join(name);
        let Ok(real) = std::fs::canonicalize(&path) else {
            return Err((error(format!("{at}: no such file"), line), None));
        };
        let root = self.root.display();
        if !listed.contains(&real) {
            let inside = std::fs::canonicalize(self.root).is_ok_and(|r| real.starts_with(r));
            let message = if inside {
                format!(
                    "{at} names a file the walk of {root} does not check (hidden, ignored or \
                     excluded): not followed; name it on the command line to check it"
                )
            } else {
                format!(
                    "{at} leaves {root}, the folder walked: not followed; name the walls \
                     file on the command line to check it"
                )
            };
            return Err((error(message, line), Some(real)));
        }
        if !looks_like_walls(&real) {
            let message = format!(
                "{at}: not a walls file (it does not begin with `wall` or `defaults` and a \
                 keyword or a type, or a unit or `time` and a number): not checked; name it on \
                 the command line to check it"
            );
            return Err((error(message, line), None));
        }
        // Shown as the walk shows its files: the folder walked, then the path in it.
        let shown_path = std::fs::canonicalize(self.root)
            .ok()
            .and_then(|r| real.strip_prefix(r).ok().map(|rest| self.root.join(rest)))
            .unwrap_or(path);
        Ok(Some(
            shown_path
                .strip_prefix(".")
                .map(Path::to_path_buf)
                .unwrap_or(shown_path),
        ))
    }
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

/// The most of a file read to tell whether it is a walls file.
const SNIFF_BYTES: u64 = 1 << 20;

/// Whether the file at `path` reads as a walls file: its first word (after white space,
/// separators, comments and a byte-order mark, within its first MiB) is `wall` or
/// `defaults`, followed by a keyword, a type or nothing, or a unit or `time` followed by a
/// number; or it has no word at all. A file a `.par` names that is not one (a settings or
/// secrets file a hostile `.par` points at) is never checked, so that no word of it
/// reaches a report.
fn looks_like_walls(path: &Path) -> bool {
    use std::io::Read;
    let mut head = Vec::new();
    let read = std::fs::File::open(path).and_then(|f| f.take(SNIFF_BYTES).read_to_end(&mut head));
    if read.is_err() {
        return false;
    }
    let whole = (head.len() as u64) < SNIFF_BYTES;
    let text = head.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(&head);
    let mut words = Words { rest: text };
    let Some(first) = words.next() else {
        return whole;
    };
    let first = std::str::from_utf8(first)
        .unwrap_or("")
        .to_ascii_lowercase();
    let second = words
        .next()
        .map(|w| std::str::from_utf8(w).unwrap_or("\u{0}"));
    match first.as_str() {
        "wall" | "defaults" => second.is_none_or(|w| {
            walls_keywords::keyword(w).is_some() || walls_keywords::wall_type(w).is_some()
        }),
        "time" | "lengthunit" | "massunit" | "timeunit" => second.is_some_and(|w| {
            w.bytes()
                .all(|b| b.is_ascii_digit() || matches!(b, b'.' | b'e' | b'E' | b'+' | b'-'))
                && w.parse::<f64>().is_ok()
        }),
        _ => false,
    }
}

/// The words of a walls file's text, as pkdgrav splits them: white space, `,` and `=`
/// separate them, and a `#` or `!` at a word's start comments out the line.
struct Words<'a> {
    rest: &'a [u8],
}

impl<'a> Iterator for Words<'a> {
    type Item = &'a [u8];

    fn next(&mut self) -> Option<&'a [u8]> {
        let separator =
            |b: u8| matches!(b, b' ' | b'\t' | b'\n' | b'\r' | 0x0b | 0x0c | b',' | b'=');
        loop {
            let skip = self.rest.iter().position(|&b| !separator(b))?;
            self.rest = &self.rest[skip..];
            if matches!(self.rest.first(), Some(b'#' | b'!')) {
                let end = self
                    .rest
                    .iter()
                    .position(|&b| b == b'\n')
                    .unwrap_or(self.rest.len());
                self.rest = &self.rest[end..];
                continue;
            }
            let end = self
                .rest
                .iter()
                .position(|&b| separator(b) || matches!(b, b'#' | b'!'))
                .unwrap_or(self.rest.len());
            let (word, rest) = self.rest.split_at(end);
            self.rest = rest;
            return Some(word);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{TargetError, expand};
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
        // scene.dat is named first, so the .par naming it adds only itself; the folder
        // named again, and the one inside it, add nothing and are not "folders with no
        // walls file". The .par files are checked too, in the order found.
        assert_eq!(
            targets.files,
            [
                named,
                format!("{r}/a.walls"),
                format!("{r}/sub/b.walls"),
                format!("{r}/sub/run.par"),
                format!("{r}/z/missing.par"),
            ]
        );
        let par = format!("{r}/z/missing.par");
        assert_eq!(
            targets.errors,
            [TargetError {
                path: par.clone(),
                message: format!("{par}:1: achWallsFile = gone.walls: no such file"),
                line: Some(1),
            }]
        );
    }
}
