//! The invariants of ARCHITECTURE.md, checked on the workspace's manifests and sources.
//!
//! Each test is one invariant of the "Invariants" section and says, when it fails, what
//! broke and where. The manifests are read with `toml` (the workspace's members from the
//! root `Cargo.toml`, each member's `[dependencies]`, `[build-dependencies]`,
//! `[dev-dependencies]` and their `[target.*]` forms); the sources are walked with
//! `std::fs` and scanned as code: comments, string and character literals are blanked
//! first, so prose and messages never match, and where a test says so, `#[cfg(test)]`
//! items are skipped too. Nothing here runs cargo or touches the network.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

// ---------------------------------------------------------------------------------------
// The architecture, as data.

/// Every workspace crate's layer: a crate's `[dependencies]` and `[build-dependencies]`
/// may name only workspace crates of a lower layer. A new crate must be placed here (and
/// in ARCHITECTURE.md's code map).
const LAYERS: &[(&str, u8)] = &[
    ("walls-keywords", 0),
    ("walls-diagnostics", 0),
    ("walls-output", 0),
    ("tree-sitter-walls", 0),
    ("walls-syntax", 1),
    ("walls-par", 1),
    ("walls-model", 2),
    ("walls-format", 2),
    ("walls-ide", 3),
    ("walls-geometry", 3),
    ("walls-sim", 4),
    ("walls-preview", 4),
    ("walls-config", 4),
    ("walls-build", 4),
    ("walls-test-support", 4),
    ("walls-lsp", 5),
    ("walls-cli", 5),
    ("walls-charts", 5),
    ("walls-py", 6),
];

/// What each crate must not know: none of these may be among its `[dependencies]`,
/// directly or through other workspace crates.
const KNOWS_NOTHING_OF: &[(&str, &[&str])] = &[
    (
        "walls-syntax",
        &[
            "walls-model",
            "walls-format",
            "walls-ide",
            "walls-geometry",
            "walls-sim",
            "walls-preview",
            "walls-lsp",
            "walls-cli",
        ],
    ),
    (
        "walls-model",
        &[
            "walls-format",
            "walls-ide",
            "walls-geometry",
            "walls-sim",
            "walls-preview",
            "walls-lsp",
            "walls-cli",
        ],
    ),
    (
        "walls-format",
        &[
            "walls-model",
            "walls-ide",
            "walls-geometry",
            "walls-sim",
            "walls-preview",
            "walls-lsp",
            "walls-cli",
        ],
    ),
    (
        "walls-ide",
        &[
            "walls-geometry",
            "walls-sim",
            "walls-preview",
            "walls-lsp",
            "walls-cli",
        ],
    ),
    (
        "walls-geometry",
        &[
            "walls-format",
            "walls-ide",
            "walls-sim",
            "walls-preview",
            "walls-lsp",
            "walls-cli",
        ],
    ),
    (
        "walls-sim",
        &[
            "walls-format",
            "walls-ide",
            "walls-preview",
            "walls-lsp",
            "walls-cli",
        ],
    ),
    (
        "walls-preview",
        &[
            "walls-sim",
            "walls-format",
            "walls-ide",
            "walls-lsp",
            "walls-cli",
        ],
    ),
    (
        "walls-config",
        &[
            "walls-geometry",
            "walls-sim",
            "walls-preview",
            "walls-lsp",
            "walls-cli",
        ],
    ),
    (
        "walls-lsp",
        &["walls-geometry", "walls-sim", "walls-preview", "walls-cli"],
    ),
    (
        "walls-build",
        &[
            "walls-geometry",
            "walls-sim",
            "walls-preview",
            "walls-lsp",
            "walls-cli",
        ],
    ),
];

/// The crates whose types are the Language Server Protocol's.
const LSP_CRATES: &[&str] = &[
    "tower-lsp-server",
    "tower-lsp",
    "ls-types",
    "lsp-types",
    "lsp-server",
    "async-lsp",
];

/// The token-level front end, which reads keywords by design: every other crate reads a
/// wall through walls-geometry's typed parts.
const FRONT_END: &[&str] = &[
    "walls-keywords",
    "walls-diagnostics",
    "walls-syntax",
    "walls-model",
    "walls-format",
    "walls-ide",
    "walls-config",
    "walls-lsp",
    "walls-test-support",
    "walls-build",
    "tree-sitter-walls",
];

/// The files outside the front end that read a resolved wall's keywords, each with its
/// reason.
const READS_KEYWORDS: &[(&str, &str)] = &[
    (
        "crates/walls-geometry/src/wall.rs",
        "the decoder: the one place a wall becomes typed parts",
    ),
    (
        "crates/walls-geometry/src/json.rs",
        "`walls-sim scene` prints every token of every wall",
    ),
    (
        "crates/walls-preview/src/html.rs",
        "the page's hover lists a wall's tokens as written",
    ),
];

/// How code reads a `walls_model::Wall`'s tokens: naming a `Keyword`, or its accessors.
const KEYWORD_READS: &[&str] = &[
    "Keyword",
    ".number(",
    ".integer(",
    ".vector(",
    ".setting(",
    ".settings.get(",
    ".settings.iter(",
];

/// The print macros a library must not call.
const PRINTS: &[&str] = &["print", "println", "eprint", "eprintln", "dbg"];

/// The edge: library files that print by design (the commands render their output).
/// The most lines a `walls-cli` binary may have: binaries parse and dispatch.
const BIN_MAX_LINES: usize = 300;

// ---------------------------------------------------------------------------------------
// The invariants.

/// Every crate is in a layer, and depends only on crates of lower layers.
#[test]
fn dependencies_go_down_the_layers() {
    let ws = Workspace::load();
    let layer: BTreeMap<&str, u8> = LAYERS.iter().copied().collect();
    let mut broken = Vec::new();
    for m in &ws.members {
        let Some(&own) = layer.get(m.name.as_str()) else {
            broken.push(format!(
                "{} ({}) has no layer: add it to LAYERS in this test and to ARCHITECTURE.md's code map",
                m.name,
                m.manifest_path()
            ));
            continue;
        };
        for dep in ws.workspace_deps(m, Kind::Build) {
            let theirs = layer.get(dep.as_str()).copied().unwrap_or(u8::MAX);
            if theirs >= own {
                broken.push(format!(
                    "{} (layer {own}) depends on {dep} (layer {theirs}) in {}: a crate may use only crates of lower layers",
                    m.name,
                    m.manifest_path()
                ));
            }
        }
    }
    for (name, _) in LAYERS {
        if ws.member(name).is_none() {
            broken.push(format!(
                "LAYERS names {name}, which is not a workspace member: remove it"
            ));
        }
    }
    assert_none(
        "dependencies must go down the layers (ARCHITECTURE.md, \"Code map\")",
        &broken,
    );
}

/// Each crate knows nothing of the stages after it, directly or through another crate.
#[test]
fn each_crate_knows_nothing_of_what_comes_after_it() {
    let ws = Workspace::load();
    let mut broken = Vec::new();
    for (name, forbidden) in KNOWS_NOTHING_OF {
        let m = ws.member(name).expect("a workspace member");
        let known = ws.closure(name);
        for f in *forbidden {
            if known.contains(*f) {
                broken.push(format!(
                    "{name} depends on {f} ({}): {}",
                    ws.path_to(name, f).join(" → "),
                    m.manifest_path()
                ));
            }
        }
    }
    for name in ["walls-keywords", "walls-diagnostics"] {
        let m = ws.member(name).expect("a workspace member");
        for dep in ws.workspace_deps(m, Kind::Build) {
            broken.push(format!(
                "{name} must know no other workspace crate, but depends on {dep} ({})",
                m.manifest_path()
            ));
        }
    }
    // The one exception: clap, optional, behind the `clap` feature that lets the
    // command-line tools take a ContactModel as an argument.
    let keywords = ws.member("walls-keywords").expect("a workspace member");
    for dep in keywords.deps(Kind::Build) {
        if dep == "clap" && keywords.optional(&dep) {
            continue;
        }
        broken.push(format!(
            "walls-keywords, the table everything reads, must have no dependency (but an optional clap), but has {dep} ({})",
            keywords.manifest_path()
        ));
    }
    assert_none(
        "a crate must know nothing of what comes after it (ARCHITECTURE.md, \"Code map\")",
        &broken,
    );
}

/// The previews do not depend on the simulator, and know walls-geometry, walls-model
/// and walls-keywords only.
#[test]
fn previews_do_not_depend_on_the_simulator() {
    let ws = Workspace::load();
    let preview = ws.member("walls-preview").expect("a workspace member");
    let mut broken = Vec::new();
    if ws.closure("walls-preview").contains("walls-sim") {
        broken.push(format!(
            "walls-preview depends on walls-sim ({}): {}",
            ws.path_to("walls-preview", "walls-sim").join(" → "),
            preview.manifest_path()
        ));
    }
    let allowed = ["walls-geometry", "walls-model", "walls-keywords"];
    for dep in ws.workspace_deps(preview, Kind::Build) {
        if !allowed.contains(&dep.as_str()) {
            broken.push(format!(
                "walls-preview depends on {dep} ({}); it may know only {}",
                preview.manifest_path(),
                allowed.join(", ")
            ));
        }
    }
    assert_none(
        "previews must not depend on the simulator (ARCHITECTURE.md, \"Invariants\")",
        &broken,
    );
}

/// walls-sim works on walls-geometry's typed walls: walls-model is not among its
/// `[dependencies]` (its tests may build scenes from text with it). Besides
/// walls-geometry it knows only walls-keywords, for the `ContactModel` the whole
/// toolkit shares, and walls-par, pkdgrav's `.par` files (no walls file in it).
#[test]
fn the_simulator_knows_geometry_not_the_model() {
    let ws = Workspace::load();
    let sim = ws.member("walls-sim").expect("a workspace member");
    // walls-diagnostics (which knows no wall): the run directory's check before the
    // job (`precheck`) returns its findings as diagnostics.
    let allowed = [
        "walls-diagnostics",
        "walls-geometry",
        "walls-keywords",
        "walls-par",
    ];
    let broken: Vec<String> = ws
        .workspace_deps(sim, Kind::Build)
        .into_iter()
        .filter(|dep| !allowed.contains(&dep.as_str()))
        .map(|dep| {
            format!(
                "walls-sim depends on {dep} ({}); it may depend on {} only",
                sim.manifest_path(),
                allowed.join(", ")
            )
        })
        .collect();
    assert_none(
        "the simulator must know the typed walls only (ARCHITECTURE.md, \"Invariants\")",
        &broken,
    );
}

/// The crates that may depend on walls-lsp: the Python module, whose `walls-lsp` console
/// script runs the server in-process. They still name no LSP type.
const SERVES_LSP: &[&str] = &["walls-py"];

/// Only walls-lsp knows LSP types: no other crate depends on an LSP crate (in any
/// dependency table) or names one in its code, and no crate but those of [`SERVES_LSP`]
/// depends on walls-lsp.
#[test]
fn only_the_language_server_knows_lsp_types() {
    let ws = Workspace::load();
    let mut broken = Vec::new();
    for m in ws.members.iter().filter(|m| m.name != "walls-lsp") {
        for dep in m.deps(Kind::Dev) {
            let lsp_dep = dep == "walls-lsp" && !SERVES_LSP.contains(&m.name.as_str());
            if LSP_CRATES.contains(&dep.as_str()) || lsp_dep {
                broken.push(format!(
                    "{} depends on {dep} ({})",
                    m.name,
                    m.manifest_path()
                ));
            }
        }
        for file in rust_files(&m.dir) {
            let code = code_only(&read(&file));
            for path in [
                "ls_types",
                "lsp_types",
                "tower_lsp",
                "tower_lsp_server",
                "lsp_server",
                "async_lsp",
            ] {
                for at in find_word(&code, path) {
                    broken.push(format!(
                        "{}:{} names `{path}`",
                        ws.relative(&file),
                        line_of(&code, at)
                    ));
                }
            }
        }
    }
    assert_none(
        "only walls-lsp may know LSP types (ARCHITECTURE.md, \"Invariants\")",
        &broken,
    );
}

/// No library prints: `print!`, `println!`, `eprint!`, `eprintln!` and `dbg!` appear only
/// in binaries (`src/main.rs`, `src/bin/`, `[[bin]]` paths), build scripts, unit tests
/// (`#[cfg(test)]` items). The command-line tools' commands print through
/// `walls_cli::console`'s macros, which never panic on a closed stream.
#[test]
fn no_library_prints() {
    let ws = Workspace::load();
    let mut broken = Vec::new();
    for m in &ws.members {
        let binaries = m.binary_paths();
        for file in rust_files(&m.lib_dir()) {
            let rel = ws.relative(&file);
            if binaries.contains(&file) || rel.contains("/src/bin/") {
                continue;
            }
            let code = without_test_items(&code_only(&read(&file)));
            for name in PRINTS {
                for at in find_word(&code, name) {
                    if code[at + name.len()..].trim_start().starts_with('!') {
                        broken.push(format!("{rel}:{} calls `{name}!`", line_of(&code, at)));
                    }
                }
            }
        }
    }
    assert_none(
        "a library must return what it has to say; only binaries print, and the CLI's commands through its console (ARCHITECTURE.md, \"Invariants\")",
        &broken,
    );
}

/// The crates that may write files themselves: the one writer; the charts, which draw
/// the documentation's figures; and the tests' support (neither is a tool of the user's).
const WRITES_FILES: &[&str] = &["walls-output", "walls-charts", "walls-test-support"];

/// What opens a file for writing or writes one.
const FILE_WRITES: &[&str] = &[
    "File::create",
    "fs::write",
    "OpenOptions",
    "create_new",
    "persist",
    "fs::rename",
    "fs::copy",
    "set_len",
];

/// One writer: outside `WRITES_FILES`, no library or binary creates, writes, renames or
/// truncates a file (unit tests aside); every file the tools write goes through
/// walls-output, under its one policy (docs/reliability.md, "Files").
#[test]
fn every_file_goes_through_the_one_writer() {
    let ws = Workspace::load();
    let mut broken = Vec::new();
    for m in ws
        .members
        .iter()
        .filter(|m| !WRITES_FILES.contains(&m.name.as_str()))
    {
        for file in rust_files(&m.lib_dir()) {
            let rel = ws.relative(&file);
            // A unit-test module of its own file (`#[cfg(test)] mod tests;`).
            if file.file_name().is_some_and(|n| n == "tests.rs") {
                continue;
            }
            let code = without_test_items(&code_only(&read(&file)));
            for name in FILE_WRITES {
                for at in find_word(&code, name) {
                    broken.push(format!("{rel}:{} uses `{name}`", line_of(&code, at)));
                }
            }
        }
    }
    assert_none(
        "only walls-output writes files: plan the output with walls_output::Outputs and write it through its Target (ARCHITECTURE.md, \"Invariants\")",
        &broken,
    );
}

/// A wall is decoded once: outside the token-level front end, only the files of
/// `READS_KEYWORDS` read a resolved wall's keywords; everything else reads
/// walls-geometry's typed parts.
#[test]
fn a_wall_is_decoded_once() {
    let ws = Workspace::load();
    let mut broken = Vec::new();
    let mut excused_and_reading = BTreeSet::new();
    for m in ws
        .members
        .iter()
        .filter(|m| !FRONT_END.contains(&m.name.as_str()))
    {
        for file in rust_files(&m.lib_dir()) {
            let rel = ws.relative(&file);
            let code = code_only(&read(&file));
            let mut hits = Vec::new();
            for pattern in KEYWORD_READS {
                let at: Vec<usize> = if pattern.starts_with('.') {
                    code.match_indices(pattern).map(|(i, _)| i).collect()
                } else {
                    find_word(&code, pattern)
                };
                for i in at {
                    hits.push(format!("{rel}:{} reads `{pattern}`", line_of(&code, i)));
                }
            }
            if READS_KEYWORDS.iter().any(|(path, _)| *path == rel) {
                if !hits.is_empty() {
                    excused_and_reading.insert(rel);
                }
            } else {
                broken.extend(hits);
            }
        }
    }
    for (path, why) in READS_KEYWORDS {
        if !excused_and_reading.contains(*path) {
            broken.push(format!(
                "{path} is excused ({why}) but reads no keyword any more: remove it from READS_KEYWORDS and from ARCHITECTURE.md"
            ));
        }
    }
    assert_none(
        "a wall's keywords are read once, by walls_geometry::decode; read its Shape, Motion, Material, Appearance or Reactive instead (ARCHITECTURE.md, \"Invariants\")",
        &broken,
    );
}

/// Every Rust file of the repository opens with its module doc (`//!`).
#[test]
fn every_rust_file_has_a_module_doc() {
    let ws = Workspace::load();
    let broken: Vec<String> = rust_files(&ws.root)
        .into_iter()
        .filter(|file| {
            let text = read(file);
            let first = text.lines().find(|l| !l.trim().is_empty());
            !first.is_some_and(|l| l.starts_with("//!"))
        })
        .map(|file| {
            format!(
                "{} does not open with a `//!` module doc",
                ws.relative(&file)
            )
        })
        .collect();
    assert_none(
        "every Rust file says what it is for (ARCHITECTURE.md, \"Invariants\")",
        &broken,
    );
}

/// The command-line binaries parse arguments and dispatch; the work is in the command
/// modules.
#[test]
fn command_line_binaries_stay_thin() {
    let ws = Workspace::load();
    let dir = ws.root.join("crates/walls-cli/src/bin");
    let files = rust_files(&dir);
    assert!(!files.is_empty(), "no binaries in {}", dir.display());
    let broken: Vec<String> = files
        .iter()
        .map(|file| (file, read(file).lines().count()))
        .filter(|(_, lines)| *lines >= BIN_MAX_LINES)
        .map(|(file, lines)| {
            format!(
                "{} has {lines} lines: move the work into a module of src/commands/",
                ws.relative(file)
            )
        })
        .collect();
    assert_none(
        &format!(
            "each walls-cli binary stays under {BIN_MAX_LINES} lines (ARCHITECTURE.md, \"Invariants\")"
        ),
        &broken,
    );
}

// ---------------------------------------------------------------------------------------
// The workspace's manifests.

/// Which dependency tables to read.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Kind {
    /// `[dependencies]` and `[build-dependencies]`: what the crate is built with.
    Build,
    /// Those and `[dev-dependencies]`: what its tests are built with too.
    Dev,
}

struct Member {
    name: String,
    dir: PathBuf,
    /// Its `Cargo.toml`, relative to the workspace's root, for messages.
    manifest_path: String,
    manifest: toml::Table,
}

impl Member {
    fn manifest_path(&self) -> &str {
        &self.manifest_path
    }

    /// The package names of its dependencies of `kind`, with `[target.*]` tables too.
    /// Whether its dependency `name` is optional (behind a feature).
    fn optional(&self, name: &str) -> bool {
        self.manifest
            .get("dependencies")
            .and_then(|d| d.get(name))
            .and_then(|spec| spec.get("optional"))
            .and_then(|o| o.as_bool())
            .unwrap_or(false)
    }

    fn deps(&self, kind: Kind) -> BTreeSet<String> {
        let mut tables = vec!["dependencies", "build-dependencies"];
        if kind == Kind::Dev {
            tables.push("dev-dependencies");
        }
        let mut scopes = vec![&self.manifest];
        if let Some(targets) = self.manifest.get("target").and_then(|t| t.as_table()) {
            scopes.extend(targets.values().filter_map(|t| t.as_table()));
        }
        let mut out = BTreeSet::new();
        for scope in scopes {
            for table in &tables {
                let Some(deps) = scope.get(*table).and_then(|d| d.as_table()) else {
                    continue;
                };
                for (key, spec) in deps {
                    let package = spec
                        .as_table()
                        .and_then(|s| s.get("package"))
                        .and_then(|p| p.as_str())
                        .unwrap_or(key);
                    out.insert(package.to_string());
                }
            }
        }
        out
    }

    /// The directory of its library's sources: `src/`, or the directory of `[lib] path`.
    fn lib_dir(&self) -> PathBuf {
        self.manifest
            .get("lib")
            .and_then(|lib| lib.get("path"))
            .and_then(|p| p.as_str())
            .and_then(|p| Path::new(p).parent().map(|d| self.dir.join(d)))
            .unwrap_or_else(|| self.dir.join("src"))
    }

    /// Its binaries' and build script's files, which may print.
    fn binary_paths(&self) -> BTreeSet<PathBuf> {
        let mut out = BTreeSet::from([self.dir.join("src/main.rs"), self.dir.join("build.rs")]);
        if let Some(build) = self
            .manifest
            .get("package")
            .and_then(|p| p.get("build"))
            .and_then(|b| b.as_str())
        {
            out.insert(self.dir.join(build));
        }
        let bins = self.manifest.get("bin").and_then(|b| b.as_array());
        for bin in bins.into_iter().flatten() {
            if let Some(path) = bin.get("path").and_then(|p| p.as_str()) {
                out.insert(self.dir.join(path));
            }
        }
        out.into_iter()
            .map(|p| p.canonicalize().unwrap_or(p))
            .collect()
    }
}

struct Workspace {
    root: PathBuf,
    members: Vec<Member>,
}

impl Workspace {
    fn load() -> Workspace {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        let root = root.canonicalize().unwrap_or(root);
        let manifest = parse(&root.join("Cargo.toml"));
        let patterns = manifest
            .get("workspace")
            .and_then(|w| w.get("members"))
            .and_then(|m| m.as_array())
            .expect("the root Cargo.toml lists workspace.members");
        let mut dirs = Vec::new();
        for pattern in patterns.iter().filter_map(|p| p.as_str()) {
            match pattern.strip_suffix("/*") {
                Some(parent) => {
                    let mut found: Vec<PathBuf> = fs::read_dir(root.join(parent))
                        .unwrap_or_else(|e| panic!("{parent}: {e}"))
                        .map(|e| e.expect("a directory entry").path())
                        .filter(|p| p.join("Cargo.toml").is_file())
                        .collect();
                    found.sort();
                    dirs.extend(found);
                }
                None => dirs.push(root.join(pattern)),
            }
        }
        let members = dirs
            .into_iter()
            .map(|dir| {
                let manifest = parse(&dir.join("Cargo.toml"));
                let name = manifest
                    .get("package")
                    .and_then(|p| p.get("name"))
                    .and_then(|n| n.as_str())
                    .unwrap_or_else(|| panic!("{}: no package.name", dir.display()))
                    .to_string();
                Member {
                    name,
                    manifest_path: relative_to(&root, &dir.join("Cargo.toml")),
                    dir,
                    manifest,
                }
            })
            .collect();
        Workspace { root, members }
    }

    fn member(&self, name: &str) -> Option<&Member> {
        self.members.iter().find(|m| m.name == name)
    }

    /// The workspace crates among `m`'s dependencies of `kind`.
    fn workspace_deps(&self, m: &Member, kind: Kind) -> BTreeSet<String> {
        m.deps(kind)
            .into_iter()
            .filter(|d| self.member(d).is_some())
            .collect()
    }

    /// Every workspace crate `name` builds with, directly or through others.
    fn closure(&self, name: &str) -> BTreeSet<String> {
        let mut seen = BTreeSet::new();
        let mut todo = vec![name.to_string()];
        while let Some(next) = todo.pop() {
            if let Some(m) = self.member(&next) {
                for dep in self.workspace_deps(m, Kind::Build) {
                    if seen.insert(dep.clone()) {
                        todo.push(dep);
                    }
                }
            }
        }
        seen
    }

    /// A chain of dependencies from `from` to `to`, for messages.
    fn path_to(&self, from: &str, to: &str) -> Vec<String> {
        let mut parent: BTreeMap<String, String> = BTreeMap::new();
        let mut todo = vec![from.to_string()];
        while let Some(next) = todo.pop() {
            if next == to {
                break;
            }
            if let Some(m) = self.member(&next) {
                for dep in self.workspace_deps(m, Kind::Build) {
                    if dep != from && !parent.contains_key(&dep) {
                        parent.insert(dep.clone(), next.clone());
                        todo.push(dep);
                    }
                }
            }
        }
        let mut chain = vec![to.to_string()];
        while let Some(p) = parent.get(chain.last().expect("not empty")) {
            chain.push(p.clone());
        }
        chain.reverse();
        chain
    }

    fn relative(&self, path: &Path) -> String {
        relative_to(&self.root, path)
    }
}

fn parse(path: &Path) -> toml::Table {
    read(path)
        .parse()
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn relative_to(root: &Path, path: &Path) -> String {
    let path = path.canonicalize().unwrap_or_else(|_| path.to_path_buf());
    path.strip_prefix(root)
        .unwrap_or(&path)
        .to_string_lossy()
        .replace('\\', "/")
}

// ---------------------------------------------------------------------------------------
// The sources.

fn read(path: &Path) -> String {
    fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// Every `.rs` file under `dir`, skipping build output, version control and npm's.
fn rust_files(dir: &Path) -> Vec<PathBuf> {
    files_ending(dir, &[".rs"])
}

/// The code of a Rust file with every comment, string literal and character literal
/// replaced by spaces (line breaks kept, so offsets and line numbers stay those of the
/// file).
fn code_only(text: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    let blank = |out: &mut String, c: char| {
        if c == '\n' {
            out.push('\n');
        } else {
            out.extend(std::iter::repeat_n(' ', c.len_utf8()));
        }
    };
    let ident = |c: char| c.is_alphanumeric() || c == '_';
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let next = chars.get(i + 1).copied();
        if c == '/' && next == Some('/') {
            while i < chars.len() && chars[i] != '\n' {
                blank(&mut out, chars[i]);
                i += 1;
            }
        } else if c == '/' && next == Some('*') {
            let mut depth = 0;
            while i < chars.len() {
                if chars[i] == '/' && chars.get(i + 1) == Some(&'*') {
                    depth += 1;
                    out.push_str("  ");
                    i += 2;
                } else if chars[i] == '*' && chars.get(i + 1) == Some(&'/') {
                    depth -= 1;
                    out.push_str("  ");
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    blank(&mut out, chars[i]);
                    i += 1;
                }
            }
        } else if c == 'r'
            && (i == 0
                || !ident(chars[i - 1])
                || (matches!(chars[i - 1], 'b' | 'c') && (i < 2 || !ident(chars[i - 2]))))
            && raw_string_hashes(&chars[i + 1..]).is_some()
        {
            let hashes = raw_string_hashes(&chars[i + 1..]).expect("checked");
            let closing: Vec<char> = std::iter::once('"')
                .chain(std::iter::repeat_n('#', hashes))
                .collect();
            let start = i;
            i += 2 + hashes;
            while i < chars.len() && !chars[i..].starts_with(&closing) {
                i += 1;
            }
            i = (i + closing.len()).min(chars.len());
            for &c in &chars[start..i] {
                blank(&mut out, c);
            }
        } else if c == '"' {
            blank(&mut out, c);
            i += 1;
            while i < chars.len() && chars[i] != '"' {
                if chars[i] == '\\' {
                    blank(&mut out, chars[i]);
                    i += 1;
                }
                if i < chars.len() {
                    blank(&mut out, chars[i]);
                    i += 1;
                }
            }
            if i < chars.len() {
                blank(&mut out, chars[i]);
                i += 1;
            }
        } else if c == '\'' && (next == Some('\\') || chars.get(i + 2) == Some(&'\'')) {
            // A character literal (a lifetime or label has no closing quote after one
            // character).
            let start = i;
            i += 1;
            if chars.get(i) == Some(&'\\') {
                i += 1;
            }
            i += 1;
            while i < chars.len() && chars[i] != '\'' {
                i += 1;
            }
            i = (i + 1).min(chars.len());
            for &c in &chars[start..i] {
                blank(&mut out, c);
            }
        } else {
            out.push(c);
            i += 1;
        }
    }
    out
}

/// The number of `#` of a raw string whose `r` precedes `rest`, if it is one.
fn raw_string_hashes(rest: &[char]) -> Option<usize> {
    let hashes = rest.iter().take_while(|&&c| c == '#').count();
    (rest.get(hashes) == Some(&'"')).then_some(hashes)
}

/// `code` (from [`code_only`]) with every `#[cfg(test)]` item blanked: the attribute
/// and the item after it, to its closing brace or semicolon.
fn without_test_items(code: &str) -> String {
    let mut out: Vec<char> = code.chars().collect();
    let attribute: Vec<char> = "#[cfg(test)]".chars().collect();
    let mut i = 0;
    while i < out.len() {
        if !out[i..].starts_with(&attribute) {
            i += 1;
            continue;
        }
        let start = i;
        let mut depth = 0usize;
        let mut j = i + attribute.len();
        while j < out.len() {
            match out[j] {
                '{' => depth += 1,
                '}' => {
                    depth = depth.saturating_sub(1);
                    if depth == 0 {
                        break;
                    }
                }
                ';' if depth == 0 => break,
                _ => {}
            }
            j += 1;
        }
        let end = (j + 1).min(out.len());
        for c in &mut out[start..end] {
            if *c != '\n' {
                *c = ' ';
            }
        }
        i = end;
    }
    out.into_iter().collect()
}

/// The byte offsets where `word` stands as a whole identifier in `code`.
fn find_word(code: &str, word: &str) -> Vec<usize> {
    let ident = |c: Option<char>| c.is_some_and(|c| c.is_alphanumeric() || c == '_');
    code.match_indices(word)
        .map(|(at, _)| at)
        .filter(|&at| {
            !ident(code[..at].chars().next_back()) && !ident(code[at + word.len()..].chars().next())
        })
        .collect()
}

fn line_of(code: &str, offset: usize) -> usize {
    code[..offset].matches('\n').count() + 1
}

fn assert_none(invariant: &str, broken: &[String]) {
    assert!(broken.is_empty(), "{invariant}:\n  {}", broken.join("\n  "));
}

// ---------------------------------------------------------------------------------------
// The scanner itself.

#[test]
fn the_scanner_sees_only_code() {
    let text = "let a = \"println!(x)\"; // println!\n/* Keyword:: /* nested */ */ b'{' '\\'' 'a\nr#\"Keyword\"# br\"{\" x.number(1) 'x' Keyword::Origin\n";
    let code = code_only(text);
    assert_eq!(code.len(), text.len(), "offsets are kept");
    assert_eq!(code.lines().count(), text.lines().count(), "lines are kept");
    assert!(!code.contains("println"), "{code}");
    assert!(!code.contains('{'), "{code}");
    assert_eq!(find_word(&code, "Keyword").len(), 1, "{code}");
    assert_eq!(line_of(&code, find_word(&code, "Keyword")[0]), 3);
    assert!(code.contains("'a\n"), "a lifetime stays: {code}");
    assert!(code.contains("x.number("), "{code}");

    let tests = "fn f() {}\n#[cfg(test)]\nmod tests {\n    fn g() { println!(\"{}\", 1); }\n}\nfn h() { dbg!(1); }\n";
    let code = without_test_items(&code_only(tests));
    assert!(!code.contains("println"), "{code}");
    assert!(code.contains("dbg!"), "{code}");
    assert_eq!(code.lines().count(), tests.lines().count());
    assert_eq!(find_word("eprintln!(x)", "println"), Vec::<usize>::new());
}

// ---------------------------------------------------------------------------------------
// pkdgrav's units, written once.

/// The one file that writes pkdgrav's unit constants.
const UNIT_CONSTANTS: &str = "crates/walls-keywords/src/pkdgrav_units.rs";

/// pkdgrav's unit constants are written in one file, `walls_keywords::pkdgrav_units`
/// ([`UNIT_CONSTANTS`]); every other place takes them from it. Every number written in
/// every other file of a crate's `src/` (Rust) and of `python/` (`.py`, `.pyi`) — in
/// code, strings and comments alike, `_` separators allowed — is compared with each
/// set's AU (m and cm), solar mass (kg and g), time unit and year (s) and the G its units
/// make 1 (SI and cgs), and with `G_SI`: one within 10⁻³ of any is a copy. So a
/// rounded copy (`1.496e11`, `1.989e30`, `5.023e6`, `6.674e-11`) is caught as well as an
/// exact one, and a doc that states a value (it would go stale) too. Not caught, by
/// design: tests and benchmarks (`crates/*/tests`, `benches`), which state the figures
/// they expect; the reciprocals a walls file writes (`lengthunit 6.68445e-14`, a
/// centimetre in AU), which are the user's statement of their units; and prose with
/// thousands separators or spaces between digits.
#[test]
fn unit_constants_are_written_once() {
    use walls_keywords::pkdgrav_units::{G_SI, SETS, Time};
    let mut constants = vec![("G", G_SI), ("G (cgs)", G_SI * 1e3)];
    for set in SETS {
        constants.extend([
            ("AU (m)", set.au_m),
            ("AU (cm)", set.au_m * 1e2),
            ("M_sun (kg)", set.solar_mass_kg),
            ("M_sun (g)", set.solar_mass_kg * 1e3),
        ]);
        constants.extend(set.time_unit_s().map(|t| ("time unit (s)", t)));
        if let Time::Year(year) = set.time {
            constants.push(("year (s)", year));
        }
        if let Some(g) = set.g_si() {
            constants.extend([("G", g), ("G (cgs)", g * 1e3)]);
        }
    }
    let copies = |text: &str| -> Vec<(usize, String, &'static str)> {
        number_literals(text)
            .into_iter()
            .filter_map(|(at, literal, value)| {
                let (name, _) = constants
                    .iter()
                    .find(|(_, c)| (value / c - 1.0).abs() < 1e-3)?;
                Some((at, literal.to_string(), *name))
            })
            .collect()
    };

    let caught =
        copies("const AU: f64 = 1.496e11; m = 1.988_47e30 // 6.674e-11\nt = \"5.023e6 s\"");
    assert_eq!(caught.len(), 4, "{caught:?}");
    let legitimate = "lengthunit 6.68445e-14\nmassunit 5.02739933e-34 # 2e33 g, 1.47 s, v1.496";
    assert_eq!(copies(legitimate), Vec::new());

    let ws = Workspace::load();
    let mut files: Vec<PathBuf> = ws
        .members
        .iter()
        .flat_map(|m| rust_files(&m.dir.join("src")))
        .collect();
    files.extend(files_ending(&ws.root.join("python"), &[".py", ".pyi"]));
    let mut broken = Vec::new();
    for file in files {
        let path = ws.relative(&file);
        if path == UNIT_CONSTANTS {
            continue;
        }
        let text = read(&file);
        for (at, literal, name) in copies(&text) {
            broken.push(format!(
                "{path}:{}: `{literal}` is pkdgrav's {name}: take it from walls_keywords::pkdgrav_units",
                line_of(&text, at)
            ));
        }
    }
    assert_none(
        "pkdgrav's unit constants are written in one file (ARCHITECTURE.md, \"Invariants\")",
        &broken,
    );
}

/// Every number written in `text`: its byte offset, its text and its value (`_`
/// separators dropped). A number starts with a digit that no letter, digit, `_` or `.`
/// precedes.
fn number_literals(text: &str) -> Vec<(usize, &str, f64)> {
    let b = text.as_bytes();
    let digits = |mut j: usize| {
        while j < b.len() && (b[j].is_ascii_digit() || b[j] == b'_') {
            j += 1;
        }
        j
    };
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let starts = b[i].is_ascii_digit()
            && (i == 0 || !(b[i - 1].is_ascii_alphanumeric() || matches!(b[i - 1], b'_' | b'.')));
        if !starts {
            i += 1;
            continue;
        }
        let mut j = digits(i);
        if j + 1 < b.len() && b[j] == b'.' && b[j + 1].is_ascii_digit() {
            j = digits(j + 1);
        }
        if j < b.len() && matches!(b[j], b'e' | b'E') {
            let mut k = j + 1;
            if k < b.len() && matches!(b[k], b'+' | b'-') {
                k += 1;
            }
            if k < b.len() && b[k].is_ascii_digit() {
                j = digits(k);
            }
        }
        let literal = &text[i..j];
        if let Ok(value) = literal.replace('_', "").parse::<f64>() {
            out.push((i, literal, value));
        }
        i = j;
    }
    out
}

/// Every file under `dir` whose name ends with one of `endings`, skipping build output,
/// version control, npm's and Python's caches and virtual environments.
fn files_ending(dir: &Path, endings: &[&str]) -> Vec<PathBuf> {
    const SKIPPED: &[&str] = &["target", ".git", "node_modules", "__pycache__", ".venv"];
    let mut out = Vec::new();
    let mut todo = vec![dir.to_path_buf()];
    while let Some(dir) = todo.pop() {
        let Ok(entries) = fs::read_dir(&dir) else {
            continue;
        };
        for entry in entries {
            let path = entry.expect("a directory entry").path();
            let name = path.file_name().unwrap_or_default().to_string_lossy();
            if path.is_dir() {
                if !SKIPPED.contains(&name.as_ref()) {
                    todo.push(path);
                }
            } else if endings.iter().any(|e| name.ends_with(e)) {
                out.push(path.canonicalize().unwrap_or(path));
            }
        }
    }
    out.sort();
    out
}

// ---------------------------------------------------------------------------------------
// Wall motion.

/// The code that turns angles into sines and cosines: the sinusoid of an oscillating
/// wall, a vector turned with a wall's spin.
const TRIGONOMETRY: &[&str] = &[
    ".sin(",
    ".cos(",
    "sin_cos(",
    "from_axis_angle(",
    "from_scaled_axis(",
];

/// The crates past walls-geometry that place or move walls.
const MOVE_WALLS: &[&str] = &["crates/walls-sim/src", "crates/walls-preview/src"];

/// The files of `MOVE_WALLS` whose sines and cosines are not a wall's motion, each with
/// its reason.
const TRIGONOMETRY_NOT_WALL_MOTION: &[(&str, &str)] = &[
    (
        "crates/walls-sim/src/contact/ssdem.rs",
        "a contact's springs turned with the contact (pkdgrav's law, docs/pkdgrav-physics.md §1.3–§1.5)",
    ),
    (
        "crates/walls-sim/src/contact/lanes.rs",
        "the same turn of the springs, four contacts at a time",
    ),
    (
        "crates/walls-sim/src/dynamics/rigid.rs",
        "an aggregate's principal axes turned as it tumbles (a body's integration, §9)",
    ),
    (
        "crates/walls-sim/src/dynamics/reactive.rs",
        "a reactive assembly turned by the spin its torques give it: integrated, not a wall's given motion",
    ),
    (
        "crates/walls-preview/src/mesh.rs",
        "half a turn between opposite axes, placing a round wall's mesh where a run put it",
    ),
    (
        "crates/walls-preview/src/pov.rs",
        "the camera's field of view",
    ),
];

/// Wall motion is computed in walls-geometry (`motion`): where a wall is, how fast its
/// material moves, how it turns. Outside it, the simulator and the previews take no sine
/// or cosine but in `TRIGONOMETRY_NOT_WALL_MOTION`'s files; an exception that stops
/// using them must be removed.
#[test]
fn wall_motion_is_computed_in_geometry() {
    let ws = Workspace::load();
    let mut broken = Vec::new();
    let mut excused_and_using = BTreeSet::new();
    for dir in MOVE_WALLS {
        let files = rust_files(&ws.root.join(dir));
        assert!(!files.is_empty(), "no sources in {dir}");
        for file in files {
            let rel = ws.relative(&file);
            let code = code_only(&read(&file));
            let mut hits = Vec::new();
            for pattern in TRIGONOMETRY {
                for (at, _) in code.match_indices(pattern) {
                    hits.push(format!("{rel}:{} uses `{pattern}`", line_of(&code, at)));
                }
            }
            if TRIGONOMETRY_NOT_WALL_MOTION
                .iter()
                .any(|(path, _)| *path == rel)
            {
                if !hits.is_empty() {
                    excused_and_using.insert(rel);
                }
            } else {
                broken.extend(hits);
            }
        }
    }
    for (path, why) in TRIGONOMETRY_NOT_WALL_MOTION {
        if !excused_and_using.contains(*path) {
            broken.push(format!(
                "{path} is excused ({why}) but takes no sine or cosine any more: remove it from TRIGONOMETRY_NOT_WALL_MOTION and from ARCHITECTURE.md"
            ));
        }
    }
    assert_none(
        "wall motion is computed in walls-geometry's motion (Motion, Moving, turned); call it instead (ARCHITECTURE.md, \"Invariants\")",
        &broken,
    );
}

/// The crate whose files and structs are held small: the evaluator, where a step's stages
/// are functions of the sets they touch.
const SMALL_FILES_AND_STRUCTS: &str = "walls-sim";
/// The most lines of code (not blank, not comments, not tests) a file of
/// [`SMALL_FILES_AND_STRUCTS`] may have.
const MAX_CODE_LINES: usize = 900;
/// The most fields a struct of [`SMALL_FILES_AND_STRUCTS`] may have: more is a set of sets
/// not yet named.
const MAX_FIELDS: usize = 30;

/// The evaluator stays a house to live in: no file of walls-sim over [`MAX_CODE_LINES`]
/// lines of non-test code, and no struct over [`MAX_FIELDS`] fields.
#[test]
fn the_evaluators_files_and_structs_stay_small() {
    let ws = Workspace::load();
    let mut broken = Vec::new();
    for m in ws
        .members
        .iter()
        .filter(|m| m.name == SMALL_FILES_AND_STRUCTS)
    {
        for file in rust_files(&m.lib_dir()) {
            let rel = ws.relative(&file);
            let code = without_test_items(&code_only(&read(&file)));
            let lines = code.lines().filter(|l| !l.trim().is_empty()).count();
            if lines > MAX_CODE_LINES {
                broken.push(format!(
                    "{rel} has {lines} lines of code (at most {MAX_CODE_LINES})"
                ));
            }
            for (at, name, fields) in structs(&code) {
                if fields > MAX_FIELDS {
                    broken.push(format!(
                        "{rel}:{} struct {name} has {fields} fields (at most {MAX_FIELDS})",
                        line_of(&code, at)
                    ));
                }
            }
        }
    }
    assert_none(
        "split what grew: a module per stage or set, a struct per named set (ARCHITECTURE.md, \"Invariants\")",
        &broken,
    );
}

/// Each struct with named fields in `code` (comments and strings blanked): where it
/// starts, its name and how many fields it has.
fn structs(code: &str) -> Vec<(usize, String, usize)> {
    let mut out = Vec::new();
    for at in find_word(code, "struct") {
        let rest = &code[at + "struct".len()..];
        let name: String = rest
            .trim_start()
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        // Past the name and its generics, a `;` or `(` is a unit or tuple struct; else
        // the body opens at the first `{` (after any `where` clause).
        let mut after = rest.trim_start()[name.len()..].trim_start();
        if after.starts_with('<') {
            let mut depth = 0usize;
            let end = after.char_indices().find_map(|(i, c)| {
                match c {
                    '<' => depth += 1,
                    '>' => depth -= 1,
                    _ => {}
                }
                (depth == 0).then_some(i + 1)
            });
            after = after[end.unwrap_or(after.len())..].trim_start();
        }
        if after.starts_with([';', '(']) {
            continue;
        }
        let Some(open) = rest
            .len()
            .checked_sub(after.len())
            .and_then(|skip| rest[skip..].find('{').map(|i| skip + i))
        else {
            continue;
        };
        let (mut depth, mut fields, mut any) = (0usize, 0, false);
        let mut prev = ' ';
        for c in rest[open..].chars() {
            match c {
                '{' | '(' | '[' | '<' => depth += 1,
                '>' if prev == '-' => {}
                '}' | ')' | ']' | '>' => {
                    depth -= 1;
                    if depth == 0 {
                        break;
                    }
                }
                ',' if depth == 1 => {
                    fields += 1;
                    any = false;
                }
                c if depth == 1 && !c.is_whitespace() => any = true,
                _ => {}
            }
            prev = c;
        }
        out.push((at, name, fields + usize::from(any)));
    }
    out
}

/// [`structs`] counts named fields, whatever their types hold, and skips unit and tuple
/// structs.
#[test]
fn fields_are_counted_at_the_top_of_a_struct() {
    let code = "struct Unit;\nstruct Pair(u8, u8);\nstruct W<T> where T: Fn(u8) {\n    f: T,\n}\nstruct S<'a, T> {\n    a: Vec<(u8, u8)>,\n    b: &'a dyn Fn(T) -> [u8; 2],\n    c: HashMap<u8, Vec<u8>>\n}\n";
    let found: Vec<(String, usize)> = structs(code).into_iter().map(|(_, n, f)| (n, f)).collect();
    assert_eq!(found, [("W".to_string(), 1), ("S".to_string(), 3)]);
}
