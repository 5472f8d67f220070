//! A `.par` file's run directory checked before the job ([`walls_sim::precheck`]): the
//! walls file (`achWallsFile`) and the initial conditions (`achInFile`, a `.ss` file)
//! that the `.par` names, each relative to the `.par`'s folder, the run directory.
//!
//! A file is read only if it lies in the folder the user named: the folder walked that
//! found the `.par`, or the `.par`'s own folder when the `.par` is named; whatever links
//! or `..` its path takes. One that leaves it (`../../etc/passwd`, an absolute path
//! elsewhere, a link out) is an I/O error at the `.par`'s line, naming the path as the
//! `.par` writes it and nothing of the file; so is one that is missing, not a regular
//! file, or unreadable (a truncated `.ss`: where it stops). A walked `.par`'s walls file
//! that the walk does not follow is the walk's error already ([`super::walk`]), not
//! repeated here. The findings go to the file each is about: the
//! `.par`'s to its report, the walls file's and the `.ss` file's to theirs (a `.ss`
//! file's report has no text: its findings are at particles' records).

use std::path::{Path, PathBuf};
use std::sync::Arc;
use walls_diagnostics::Diagnostic;
use walls_sim::precheck::WallPlace;

/// The findings about another file of the run directory.
pub(super) struct RunFile {
    /// Its path as shown: the `.par`'s folder joined with the name the `.par` gives.
    pub name: String,
    /// Its real path, to add the findings to its own report when it is checked too.
    pub real: PathBuf,
    /// Its text (empty for a `.ss` file).
    pub text: Arc<str>,
    /// The findings.
    pub diagnostics: Vec<Diagnostic>,
}

/// What the check of a run directory found.
#[derive(Default)]
pub(super) struct RunChecked {
    /// Findings in the `.par` file.
    pub par: Vec<Diagnostic>,
    /// Findings in the walls file and the `.ss` file.
    pub files: Vec<RunFile>,
    /// I/O errors, each with the `.par`'s line it is about.
    pub errors: Vec<(String, Option<usize>)>,
}

/// A file the `.par` names, read in the run directory.
struct Named {
    /// The name as the `.par` gives it.
    given: String,
    /// As shown: the `.par`'s folder joined with it.
    shown: String,
    real: PathBuf,
    bytes: Vec<u8>,
}

/// Checks the run directory of the `.par` file at `par_path` whose text is `text`, for
/// `build`; `walked` is the folder whose walk found the `.par`, if one did.
pub(super) fn check(
    par_path: &str,
    walked: Option<&Path>,
    text: &str,
    build: &walls_par::Build,
) -> RunChecked {
    let mut out = RunChecked::default();
    let file = walls_par::check::File::read(text, build, &mut Vec::new());
    let folder = Path::new(par_path).parent().unwrap_or(Path::new(""));
    let inside = walked.unwrap_or(folder);
    // The walls file whole; of the `.ss` file its 16-byte header (its records are read
    // below, once the header says how long the file must be).
    let read = |key: &str, out: &mut RunChecked| -> Option<Named> {
        let name = file.string(key).filter(|n| !n.is_empty())?;
        let line = file.given(key).map(|e| e.line);
        let at_most = (key == "achInFile").then_some(16);
        match read_in(inside, folder, &name, at_most) {
            Ok((real, bytes)) => Some(Named {
                shown: shown(folder, &name),
                given: name,
                real,
                bytes,
            }),
            // The walk said so already.
            Err(_) if walked.is_some() && key == "achWallsFile" => None,
            Err(why) => {
                let at = match line {
                    Some(line) => format!("{par_path}:{line}: {key} = {name}"),
                    None => format!("{par_path}: {key} = {name}"),
                };
                out.errors.push((format!("{at}: {why}"), line));
                None
            }
        }
    };
    let mut walls = read("achWallsFile", &mut out);
    let mut ss = read("achInFile", &mut out);
    // The walls file's scene, as walls-lint checks it.
    let checked = (walls.as_mut()).map(|w| {
        walls_ide::check_bytes(
            std::mem::take(&mut w.bytes),
            &walls_model::Options::default(),
        )
    });
    // The particles: a `.ss` file that does not read is an I/O error where it stops. It
    // is read header first, as a run reads it: a header that does not match the file's
    // length is refused before the records are read (a 2 GiB hole is not read whole).
    let particles = ss.as_mut().and_then(|s| {
        let standard = s.bytes.get(12..16) == Some(&(-1i32).to_be_bytes()[..]);
        let read = walls_sim::io::particles::read_ss_file(&s.real).map_err(|e| match e {
            walls_sim::io::FileError::Input { error, .. } => error,
            walls_sim::io::FileError::Read { error, .. } => walls_sim::io::InputError {
                at: "byte 0".into(),
                message: format!("cannot read it: {error}"),
            },
        });
        // pkdgrav starts only from standard records at a time of 0 or later (startup
        // rows A119, A124): anything else stops it, as a file it cannot read.
        let read = read.and_then(|(time, read)| {
            if !standard {
                Err(walls_sim::io::InputError {
                    at: "byte 12".into(),
                    message: "reduced records (magic number -10101): pkdgrav starts only from a standard .ss file (magic -1), and aborts on this one".into(),
                })
            } else if time < 0.0 {
                Err(walls_sim::io::InputError {
                    at: "byte 0".into(),
                    message: format!(
                        "the header's time is {time}: pkdgrav aborts at start-up on a negative time"
                    ),
                })
            } else {
                Ok((read, time))
            }
        });
        match read {
            Ok((read, time)) => Some((read.particles, time)),
            Err(e) => {
                let line = file.given("achInFile").map(|e| e.line);
                let at = match line {
                    Some(line) => format!("{par_path}:{line}: achInFile = {}", s.given),
                    None => format!("{par_path}: achInFile = {}", s.given),
                };
                out.errors.push((
                    format!("{at}: not a pkdgrav .ss file: {}: {e}", s.shown),
                    line,
                ));
                None
            }
        }
    });
    // Its walls decoded, and where each wall and each of its tokens is.
    let decoded = checked.as_ref().map(|c| {
        let places: Vec<WallPlace> = (c.scene.walls.iter())
            .map(|w| WallPlace {
                wall: w.span.clone(),
                tokens: walls_geometry::token_spans(w),
            })
            .collect();
        (walls_geometry::decode(&c.scene), places)
    });
    let run = walls_sim::precheck::Run {
        par: &file,
        walls: (walls.as_ref().zip(checked.as_ref()).zip(decoded.as_ref())).map(
            |((w, c), (walls, places))| walls_sim::precheck::WallsFile {
                name: &w.shown,
                text: &c.text,
                walls,
                places,
            },
        ),
        particles: ss.as_ref().zip(particles.as_ref()).map(|(s, (ps, time))| {
            walls_sim::precheck::SsFile {
                name: &s.shown,
                particles: ps,
                time: *time,
            }
        }),
    };
    let found = walls_sim::precheck::check(&run);
    out.par = found.par;
    if let (Some(w), Some(c)) = (&walls, &checked)
        && !found.walls.is_empty()
    {
        out.files.push(RunFile {
            name: w.shown.clone(),
            real: w.real.clone(),
            text: c.text.clone(),
            diagnostics: found.walls,
        });
    }
    if let Some(s) = &ss
        && !found.particles.is_empty()
    {
        out.files.push(RunFile {
            name: s.shown.clone(),
            real: s.real.clone(),
            text: Arc::from(""),
            diagnostics: found.particles,
        });
    }
    out
}

/// `name` in `folder` as messages show it (`run/particles.ss`; `particles.ss` for a
/// `.par` of the current folder).
fn shown(folder: &Path, name: &str) -> String {
    let path = folder.join(name);
    path.strip_prefix(".")
        .map(Path::to_path_buf)
        .unwrap_or(path)
        .display()
        .to_string()
}

/// The real path and bytes (its first `at_most` bytes, if given) of the file `name` in
/// `folder` (relative to it, or absolute), if it lies in `inside` and is a regular file;
/// else why it is not read (nothing of the file is said).
fn read_in(
    inside: &Path,
    folder: &Path,
    name: &str,
    at_most: Option<u64>,
) -> Result<(PathBuf, Vec<u8>), String> {
    let here = |p: &Path| {
        if p.as_os_str().is_empty() {
            Path::new(".").to_path_buf()
        } else {
            p.to_path_buf()
        }
    };
    let root = std::fs::canonicalize(here(inside))
        .map_err(|e| format!("cannot read the folder checked: {e}"))?;
    let real = std::fs::canonicalize(folder.join(name)).map_err(|_| "no such file".to_string())?;
    if !real.starts_with(&root) {
        return Err(format!(
            "leaves {}, the folder checked: not read; name a run directory that holds it",
            here(inside).display()
        ));
    }
    if !std::fs::metadata(&real).is_ok_and(|m| m.is_file()) {
        return Err("not a regular file: not read".to_string());
    }
    let file = std::fs::File::open(&real).map_err(|e| format!("cannot read {name}: {e}"))?;
    let bytes = match at_most {
        Some(n) => {
            let mut head = Vec::new();
            std::io::Read::read_to_end(&mut std::io::Read::take(file, n), &mut head)
                .map_err(|e| format!("cannot read {name}: {e}"))?;
            head
        }
        None => crate::input::read_all(file, name)?,
    };
    Ok((real, bytes))
}
