//! A tool's command line as a user's shell and `man` see it, for the tests of each
//! binary: [`completion_scripts`] checks that `--completions SHELL` prints a script for
//! every shell, [`bash_completes`] loads the bash one into a real bash and asks it to
//! complete a word, and [`man_pages_in_step`] keeps `docs/man/` equal to the pages
//! clap_mangen makes from the clap definitions (`UPDATE_DOCS=1` rewrites them); [`feed`]
//! gives a spawned tool its standard input.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Child, Command};

/// Writes `input` to `child`'s piped standard input and closes it. A tool may end
/// before it reads its input (a usage error, say), and then the pipe is closed when it
/// is written, sooner or later as the processes are scheduled: that is no error, and
/// what the tool did is in its status and output. Any other failure to write panics.
pub fn feed(child: &mut Child, input: &[u8]) {
    let mut stdin = child.stdin.take().expect("standard input piped");
    if let Err(e) = stdin.write_all(input) {
        assert_eq!(
            e.kind(),
            std::io::ErrorKind::BrokenPipe,
            "writing standard input: {e}"
        );
    }
}

/// The shells `--completions` takes.
pub const SHELLS: [&str; 5] = ["bash", "zsh", "fish", "elvish", "powershell"];

/// Asserts that `bin --completions SHELL` prints, for every shell of [`SHELLS`], a
/// script that names the tool `name`, with nothing on standard error and status 0.
pub fn completion_scripts(bin: &Path, name: &str) {
    for shell in SHELLS {
        let out = Command::new(bin)
            .args(["--completions", shell])
            .output()
            .unwrap();
        let script = String::from_utf8_lossy(&out.stdout);
        assert_eq!(out.status.code(), Some(0), "{name} --completions {shell}");
        assert!(out.stderr.is_empty(), "{name} --completions {shell}");
        assert!(
            script.contains(name),
            "{name} --completions {shell} prints a script for {name}:\n{script}"
        );
    }
}

/// Loads `bin --completions bash` into bash, as `source <(walls-lint --completions
/// bash)` in a user's `.bashrc` does, and asks it to complete the command line `name
/// words...`, the last word being completed: the `complete -p name` line that loading
/// registered, then each completion offered.
pub fn bash_completes(bin: &Path, name: &str, words: &[&str]) -> Vec<String> {
    const SCRIPT: &str = r#"
bin=$1 name=$2; shift 2
source <("$bin" --completions bash) || exit 1
spec=$(complete -p "$name") || exit 1
function=${spec#*-F }; function=${function%% *}
COMP_WORDS=("$name" "$@"); COMP_CWORD=$#
COMP_LINE="${COMP_WORDS[*]}"; COMP_POINT=${#COMP_LINE}
previous=${COMP_WORDS[COMP_CWORD-1]}
"$function" "$name" "${COMP_WORDS[COMP_CWORD]}" "$previous"
printf '%s\n' "$spec" "${COMPREPLY[@]}"
"#;
    let out = Command::new("bash")
        .args(["-c", SCRIPT, "bash"])
        .arg(bin)
        .arg(name)
        .args(words)
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "bash could not load {name}'s completions: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout)
        .unwrap()
        .lines()
        .map(str::to_string)
        .collect()
}

/// The repository's `docs/man/`.
fn man_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/man")
}

/// Asserts that `docs/man/` holds exactly the pages clap_mangen makes from `command`:
/// one for the tool and one for each of its subcommands (`walls-sim-run.1`), no other
/// page of the tool, each byte for byte. With `UPDATE_DOCS` set, writes them first (and
/// removes the tool's pages that are no longer made).
pub fn man_pages_in_step(command: clap::Command) {
    let name = command.get_name().to_string();
    let made = tempfile::tempdir().unwrap();
    clap_mangen::generate_to(command, made.path()).unwrap();
    let pages = pages_of(made.path(), &name);
    let dir = man_dir();
    if std::env::var_os("UPDATE_DOCS").is_some() {
        std::fs::create_dir_all(&dir).unwrap();
        for page in pages_of(&dir, &name) {
            std::fs::remove_file(dir.join(page)).unwrap();
        }
        for page in &pages {
            std::fs::copy(made.path().join(page), dir.join(page)).unwrap();
        }
    }
    assert_eq!(
        pages_of(&dir, &name),
        pages,
        "docs/man/ lists other pages of {name} than its command line makes; \
         regenerate them with UPDATE_DOCS=1 cargo test"
    );
    for page in &pages {
        assert!(
            std::fs::read(made.path().join(page)).unwrap()
                == std::fs::read(dir.join(page)).unwrap(),
            "docs/man/{page} is not what {name}'s command line makes; regenerate it \
             with UPDATE_DOCS=1 cargo test"
        );
    }
}

/// The names of the pages of the tool `name` in `dir` (`name.1`, `name-SUBCOMMAND.1`),
/// in order; none if `dir` does not exist.
fn pages_of(dir: &Path, name: &str) -> Vec<String> {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut pages: Vec<String> = entries
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|page| {
            page.strip_prefix(name)
                .is_some_and(|rest| rest == ".1" || rest.starts_with('-'))
        })
        .collect();
    pages.sort();
    pages
}
