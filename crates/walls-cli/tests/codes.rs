//! Every diagnostic code is documented with examples that are true: the bad example
//! produces the code and the good example produces no diagnostic at all. The same text
//! is `docs/diagnostics.md`, kept in step here (`UPDATE_DOCS=1` rewrites it).

use std::collections::HashSet;
use std::path::Path;
use walls_cli::{all_codes, check_bytes, find_code};
use walls_model::{ContactModel, Options};

/// The ```walls block after the line starting with `label`, with the options that line
/// names (`--mode hsdem`, `--max-walls N`, `--min-radius R`, `--dt DT`).
fn example(explanation: &str, label: &str) -> Option<(String, Options)> {
    let start = explanation.find(&format!("\n{label}"))?;
    let rest = &explanation[start + 1..];
    let line = rest.lines().next()?;
    let flag = |name: &str| {
        let at = line.find(name)? + name.len();
        let value = line[at..].trim_start().split(['`', ' ', ')']).next()?;
        value.parse::<f64>().ok()
    };
    let options = Options {
        mode: if line.contains("--mode hsdem") {
            ContactModel::Hsdem
        } else {
            ContactModel::Ssdem
        },
        max_walls: flag("--max-walls").map_or(20, |n| n as usize),
        min_radius: flag("--min-radius"),
        dt: flag("--dt"),
    };
    let after = rest.strip_prefix(line)?.trim_start_matches('\n');
    let body = after
        .strip_prefix("```walls\n")
        .or_else(|| after.strip_prefix("```par\n"))?;
    Some((body[..body.find("```")?].to_string(), options))
}

#[test]
fn examples_in_explanations_are_true() {
    let mut without_bad_block = Vec::new();
    for code in all_codes() {
        let bad = example(code.explanation, "Bad");
        // The good example is checked in the bad one's mode, so it shows the way out.
        let mode = bad.as_ref().map_or_else(Options::default, |b| b.1.clone());
        let (good, _) = example(code.explanation, "Good")
            .unwrap_or_else(|| panic!("{} has no good example", code.id));
        // The `.par` codes' examples are `.par` files, read by the default build.
        let check = |text: String, mode: &Options| {
            // The run directory's codes' examples are the `.par` of a run directory the
            // line before describes: their `.par` is clean; walls-sim's precheck tests
            // build each run directory and check the code.
            if code.id.starts_with('P') || code.id.starts_with('R') {
                walls_ide::par::check_par_text(text, &walls_par::Build::default()).diagnostics
            } else {
                check_bytes(text.into_bytes(), mode).diagnostics
            }
        };
        let diagnostics = check(good.clone(), &mode);
        assert!(
            diagnostics.is_empty(),
            "{}: good example gives {diagnostics:#?}",
            code.id
        );
        match bad {
            // Its bad `.par` is clean too: the run directory around it is what is wrong.
            Some(_) if code.id.starts_with('R') => {}
            Some((bad, mode)) => {
                let diagnostics = check(bad.clone(), &mode);
                assert!(
                    diagnostics.iter().any(|d| std::ptr::eq(d.code, code)),
                    "{}: bad example gives {diagnostics:#?}",
                    code.id
                );
            }
            None => without_bad_block.push(code.id),
        }
    }
    // These cannot be shown as a text block; the data-driven tests cover them.
    // S006's would put a terminal's control characters into the documentation.
    assert_eq!(without_bad_block, ["S001", "S002", "S003", "S006"]);
}

#[test]
fn codes_are_unique_and_found_by_id_or_name() {
    let mut seen = HashSet::new();
    for code in all_codes() {
        assert!(
            seen.insert(code.id) && seen.insert(code.name),
            "{} repeats",
            code.id
        );
        assert!(std::ptr::eq(
            find_code(&code.id.to_lowercase()).unwrap(),
            code
        ));
        assert!(std::ptr::eq(find_code(code.name).unwrap(), code));
    }
}

/// What `docs/diagnostics.md` says about `walls-lint --fix`.
const FIXING: &str = "
## Fixing

Many diagnostics carry a fix (the JSON and SARIF reports list it, and editors offer it).
A fix is *safe* when it keeps what the author evidently meant (a missing final newline,
a comment glued to a word, a repeated token) and *unsafe* when it is a judgement call
(a rectangle's vertex2 made square, a unit axis computed from the values given, walls put
in assembly 0).

Every fix, safe or unsafe, keeps what the file means, by construction: applied alone, it
changes the resolved scene in the one thing its diagnostic names and nothing else (a
token that has no effect removed: the walls pkdgrav builds are the same; a negative
frequency rewritten: every wall it reaches moves as before; an assembly given: exactly to
the walls the diagnostic lists), and the fixed file has no finding the original did not
have. A fix that cannot be made so is not offered, and the help says what to write: a
spelling suggestion (`S101`, `S106`) and a type name without `type` (`S109`) are help
only, since the statement a guess makes is judged like any other and the type decides
what every other token of a wall means. A wall whose `type` did not read is judged by no
type: the checks that depend on the type are silent on it, so no fix touches it on the
type's account. `crates/walls-cli/tests/fix_meaning.rs` checks all of this for every code
with a fix, over every walls file of the repository, the codes' examples and generated
files.

* `walls-lint --fix PATH…` applies the safe fixes and rewrites the files, then reports
  what remains, with the number of fixes applied in the summary (`1 error, 0 warnings in
  1 file; 3 fixed`). The exit status is that of what remains: 0 when no error remains
  (nor a warning, with `--deny-warnings`), 1 when some do, 2 as above, or when a fixed
  file could not be written.
* `--unsafe-fixes` applies the unsafe fixes too (it implies `--fix`).
* `--diff` (with or without `--fix`, and with `--unsafe-fixes` for those) writes nothing:
  it prints a unified diff of what the fixes would change on standard output and their
  number on standard error, and exits 1 if they would change anything, 0 if not. It
  reports no diagnostics, and takes no `--format`.
* On standard input (`-`), the fixed text (or, with nothing to fix, the text as read) goes
  to standard output and the report to standard error; a machine format would share
  standard output with the text, so `--fix` on `-` takes only `--format human` (or
  `--diff`).

The fixes are applied in rounds: each round takes every applicable fix whose edits do
not overlap an edit already taken (the first in the file wins), and the file is checked
again; the next round applies what an overlap held back or what a fix made possible, up
to 10 rounds (the editor's \"Fix all safe problems\" makes the same rounds). A round keeps
the meaning too, and adds no finding: where fixes together
would take every wall from a `defaults` value (negative frequencies or masses that share
an inherited amplitude or assembly), the last wall's fix waits for the next round, when it
edits the value in place. The diagnostics reported are those of the fixed text. A file is
rewritten as
`walls-fmt` rewrites one ([docs/formatting.md](formatting.md#what-walls-fmt-promises-about-your-files)): keeping its owner, group,
mode and links, atomically, and never over an edit saved meanwhile; a file it refuses is
reported with its unchanged text's diagnostics and an error, with exit status 2. A file
that is not UTF-8 is never rewritten (its only diagnostic, the encoding error, has no
fix).
";

/// What `docs/diagnostics.md` says about control characters in what the tools print.
const CONTROL: &str = "
## Control characters

A file, a file name or a value can hold characters that a terminal acts on instead of
showing them (`ESC ] 52 ; c ; … BEL` sets the clipboard, `ESC [ 2 J` clears the screen, a
carriage return writes over the line) or that make an editor show a line in another order
or on two lines: the C0 controls other than tab and newline (a carriage return that ends a
line, `\\r\\n`, is a line end), DEL, the C1 controls (U+0080 to U+009F), the line and
paragraph separators (U+2028, U+2029) and the bidirectional controls (U+202A to U+202E,
U+2066 to U+2069). In walls files, [S006](#s006) reports them.

Every human output of the tools (walls-lint, walls-fmt, walls-sim, walls-mesh) shows each
of them as the escape a Rust string literal would use: `\\xHH` up to U+007F (`\\x1b` for
escape, `\\x07` for bell, `\\x0d` for a carriage return), `\\u{H…}` above (`\\u{85}`,
`\\u{202e}`). Human output is the diagnostics of `--format human` (the snippet too: the
underline is under the escape), the messages, warnings and errors, summaries, `--diff`,
`--explain`, `walls-sim advise` and `plan`, and clap's usage errors. A backslash is not
escaped, so the escapes are for reading, not for reading back; a diff of a file that holds
such characters does not apply with `patch`.

Data keeps its bytes: the formatted text walls-fmt writes (to a file or to standard
output), the fixed text of `walls-lint --fix -`, the walls file walls-mesh writes, every
file a run or a preview writes. The machine formats are safe in their own way: JSON,
SARIF and GitLab reports write these characters as JSON escapes (`\\u001b`, `\\u202e`),
which any JSON reader reads back as the characters; GitHub annotations show them as in
human output, and escape `%`, carriage returns and newlines (and, in properties, `:` and
`,`), so that no input can start a workflow command or a line of its own.
";

/// What `docs/diagnostics.md` says about `walls-lint`'s inputs and exit statuses.
const LINT_COMMAND: &str = "
## Files, folders and exit statuses

`walls-lint PATH…` checks files and folders (`-` is standard input). A folder is walked
with `.gitignore`, `.ignore` and hidden files skipped (a `.gitignore` counts outside a git
repository too); in it, walls-lint checks every file matching an `--include` glob
(default `*.walls`; repeat the option for several, which replace the default), every
pkdgrav `.par` file but `ssdraw.par` (checked as pkdgrav reads it: [par-files.md](par-files.md))
and every walls file that a `.par` file of the tree names with `achWallsFile` (relative
to the `.par`), whatever its name. `--exclude GLOB` (repeatable) skips matching files and whole
folders. Globs are gitignore-style, relative to the folder named. Each file is checked
once. A folder with no walls file, a `.par` that cannot be read or names a missing walls
file, and a file that cannot be read are I/O errors.

Every format reports I/O errors: human output on standard error; `--format json` as a
file entry `{\"path\", \"error\": \"why\", \"diagnostics\": []}` after the files read;
`--format sarif` as `toolExecutionNotifications` of the run's invocation (with
`executionSuccessful: false`); `--format github` as an `::error file=PATH,title=walls-lint::why`
line; `--format gitlab` as a `blocker` issue named `unreadable-file` at line 1.

| status | meaning |
|---|---|
| 0 | every file was read and has no error (warnings and infos allowed, unless `--deny-warnings`) |
| 1 | every file was read and some have errors (or warnings, with `--deny-warnings`) |
| 2 | usage error (bad option or glob, or a settings file with a mistake: [configuration.md](configuration.md)), or an I/O error: a file, folder or `.par` that could not be read, or output that could not be written |

An I/O error wins: one unreadable file makes the status 2 even when other files have
errors, so that a script never takes a partial check for a complete one.
";

#[test]
fn docs_list_every_code() {
    let mut doc = String::from(
        "# Diagnostic codes\n\n<!-- Generated from the code registry by `UPDATE_DOCS=1 cargo test -p walls-cli --test codes`; do not edit. -->\n\n\
         `walls-lint --explain CODE` prints the same text. `S` codes are syntax (what pkdgrav refuses to read), \
         `M` codes depend on the contact model (`--mode`), `L` codes are about the suppression comments \
         (`# walls-lint: ignore CODE`, [configuration.md](configuration.md#suppression-comments)), \
         `P` codes are about pkdgrav's `.par` files, read by the `--pkdgrav-build` build ([par-files.md](par-files.md)), \
         `R` codes about a `.par` file's run directory checked before the job: its walls file and initial conditions together \
         ([pkdgrav-runs.md](pkdgrav-runs.md#checking-a-run-directory-before-the-job)).\n\n| code | name | summary |\n|---|---|---|\n",
    );
    for c in all_codes() {
        doc.push_str(&format!(
            "| [{}](#{}) | `{}` | {} |\n",
            c.id,
            c.id.to_lowercase(),
            c.name,
            c.summary
        ));
    }
    doc.push_str(LINT_COMMAND);
    doc.push_str(FIXING);
    doc.push_str(CONTROL);
    for c in all_codes() {
        doc.push_str(&format!(
            "\n## {}\n\n`{}`: {}.\n\n{}",
            c.id, c.name, c.summary, c.explanation
        ));
    }
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/diagnostics.md");
    if std::env::var_os("UPDATE_DOCS").is_some() {
        std::fs::write(&path, &doc).unwrap();
    }
    let on_disk = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        on_disk == doc,
        "docs/diagnostics.md is stale: run UPDATE_DOCS=1 cargo test -p walls-cli --test codes"
    );
}
