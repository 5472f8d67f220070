//! Nothing from the input reaches the terminal as it is: each tool, given OSC 52 (`ESC ]
//! 52 ; c ; <base64> BEL`, which sets the clipboard) in a walls file's comment, a token, a
//! `.par` value, a CSV field, a mesh's solid name and line, and a file name, shows it as
//! `\x1b]52;c;aGk=\x07` in its human output (standard error, and standard output where
//! it is human text), with colour forced or not; the data it writes (formatted text, the
//! walls file of walls-mesh, JSON) keeps or encodes the bytes as its format says.
//! docs/diagnostics.md, "Control characters".

use std::ffi::OsString;
use std::path::Path;
use std::process::Command;

/// OSC 52: set the clipboard to "hi".
const OSC: &str = "\x1b]52;c;aGk=\x07";
/// The same, as the tools show it.
const SHOWN: &str = "\\x1b]52;c;aGk=\\x07";

/// What a tool printed.
struct Printed {
    status: i32,
    stdout: String,
    stderr: String,
}

/// Runs `tool` (walls-lint, …) with `args` in `dir`, with colour forced (`forced`) or off.
fn run(tool: &str, args: &[OsString], dir: &Path, forced: bool) -> Printed {
    let bin = match tool {
        "walls-lint" => env!("CARGO_BIN_EXE_walls-lint"),
        "walls-fmt" => env!("CARGO_BIN_EXE_walls-fmt"),
        "walls-sim" => env!("CARGO_BIN_EXE_walls-sim"),
        "walls-mesh" => env!("CARGO_BIN_EXE_walls-mesh"),
        other => panic!("no tool {other}"),
    };
    let mut command = Command::new(bin);
    command.args(args).current_dir(dir);
    if forced {
        command.env("CLICOLOR_FORCE", "1").env_remove("NO_COLOR");
    } else {
        command.env("NO_COLOR", "1").env_remove("CLICOLOR_FORCE");
    }
    let out = command.output().unwrap();
    Printed {
        status: out.status.code().unwrap(),
        stdout: String::from_utf8(out.stdout).unwrap(),
        stderr: String::from_utf8(out.stderr).unwrap(),
    }
}

/// `text` without its SGR sequences (`ESC [ digits ; … m`), the only ones the tools write.
fn without_sgr(text: &str) -> String {
    let mut out = String::new();
    let mut rest = text;
    while let Some(at) = rest.find("\x1b[") {
        out.push_str(&rest[..at]);
        let after = &rest[at + 2..];
        let end = after
            .find(|c: char| !(c.is_ascii_digit() || c == ';'))
            .unwrap_or(after.len());
        assert!(after[end..].starts_with('m'), "not SGR: {:?}", &rest[at..]);
        rest = &after[end + 1..];
    }
    out + rest
}

/// Asserts that `text` holds nothing a terminal acts on but SGR sequences.
fn assert_safe(text: &str, what: &str) {
    let plain = without_sgr(text);
    let unsafe_char = plain
        .char_indices()
        .find(|&(i, c)| walls_diagnostics::terminal::at_offset(&plain, i).is_some() && c != '\t');
    assert!(
        unsafe_char.is_none(),
        "{what}: {unsafe_char:?} in {plain:?}"
    );
}

/// Each case: the files to write, the tool, its arguments, and what its human output shows
/// (`SHOWN` standing for the escaped OSC 52).
struct Case {
    files: &'static [(&'static str, &'static str)],
    tool: &'static str,
    args: &'static [&'static str],
    shows: &'static str,
}

/// `{OSC}` in a file or an argument is OSC 52; `{SHOWN}` in `shows`, its escape.
const CASES: &[Case] = &[
    Case {
        files: &[("a.walls", "wall type plane # {OSC}\n")],
        tool: "walls-lint",
        args: &["a.walls"],
        shows: " 1 │ wall type plane # {SHOWN}\n   │                   ──── control character `\\x1b` in a comment\n",
    },
    Case {
        files: &[("a.walls", "wall type plane\n  colr{OSC} 3\n")],
        tool: "walls-lint",
        args: &["a.walls"],
        // `=` separates words: the word ends before the base64's `=`.
        shows: "[S101] Error: unknown word `colr\\x1b]52;c;aGk`\n",
    },
    Case {
        files: &[("n{OSC}.walls", "wall type plane\n  colr 3\n")],
        tool: "walls-lint",
        args: &["n{OSC}.walls"],
        shows: "╭─[ n{SHOWN}.walls:2:3 ]",
    },
    Case {
        files: &[("a.walls", "wall type plane # {OSC}\n  origin 0  0 1\n")],
        tool: "walls-fmt",
        args: &["--diff", "a.walls"],
        shows: " wall type plane # {SHOWN}\n-  origin 0  0 1\n+  origin 0 0 1\n",
    },
    Case {
        files: &[],
        tool: "walls-fmt",
        args: &["m{OSC}.walls"],
        shows: "walls-fmt: error: cannot read m{SHOWN}.walls: No such file",
    },
    Case {
        files: &[
            ("w.walls", "wall type plane\n"),
            (
                "a.par",
                "achWallsFile = w.walls\niForceOverrideOption = 2\niCheckInterval = 0\ndDelta = 1e-4{OSC}\n",
            ),
        ],
        tool: "walls-sim",
        args: &["run", "--par", "a.par", "--no-particles"],
        shows: "walls-sim: error: a.par: line 4: `dDelta` is `1e-4{SHOWN}`, not a number\n",
    },
    Case {
        files: &[
            ("w.walls", "wall type plane\n"),
            (
                "p.csv",
                "mass,radius,x,y,z,vx,vy,vz\n1,0.1,0,0,1{OSC},0,0,0\n",
            ),
        ],
        tool: "walls-sim",
        args: &["run", "w.walls", "--particles", "p.csv"],
        shows: "walls-sim: error: p.csv: line 2: `z` is `1{SHOWN}`, not a number\n",
    },
    Case {
        files: &[("w.walls", "wall type plane # {OSC}\n  origin 0 0 1 2\n")],
        tool: "walls-sim",
        args: &["scene", "w.walls"],
        shows: " 1 │ wall type plane # {SHOWN}\n",
    },
    Case {
        files: &[],
        tool: "walls-sim",
        args: &[
            "advise",
            "--mass",
            "1",
            "--radius",
            "1",
            "--speed",
            "1",
            "--walls",
            "w{OSC}.walls",
        ],
        shows: "achWallsFile = w{SHOWN}.walls  # the walls file\n",
    },
    Case {
        files: &[(
            "m.stl",
            "solid evil{OSC}\nfacet normal 0 0 1\n{OSC}outer loop\n",
        )],
        tool: "walls-mesh",
        args: &["m.stl"],
        shows: "walls-mesh: error: m.stl:3: expected `outer loop`, found `{SHOWN}outer loop`\n",
    },
    Case {
        files: &[("m{OSC}.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")],
        tool: "walls-mesh",
        args: &["m{OSC}.obj"],
        shows: "# Made by walls-mesh from m{SHOWN}.obj: 1 face as 1 wall",
    },
];

#[test]
fn human_output_shows_control_characters_escaped_with_colour_or_not() {
    let osc = |s: &str| s.replace("{OSC}", OSC);
    for (n, case) in CASES.iter().enumerate() {
        let dir = tempfile::tempdir().unwrap();
        for (name, text) in case.files {
            std::fs::write(dir.path().join(osc(name)), osc(text)).unwrap();
        }
        let args: Vec<OsString> = case.args.iter().map(|a| osc(a).into()).collect();
        let shows = case.shows.replace("{SHOWN}", SHOWN);
        for forced in [false, true] {
            let printed = run(case.tool, &args, dir.path(), forced);
            let what = format!("case {n} ({} {:?}, colour {forced})", case.tool, case.args);
            assert_safe(&printed.stderr, &what);
            // walls-mesh writes the walls file to standard output: data, whose only
            // input text is the comment, escaped.
            assert_safe(&printed.stdout, &what);
            let both = without_sgr(&format!("{}{}", printed.stdout, printed.stderr));
            assert!(both.contains(&shows), "{what}: {shows:?} not in\n{both}");
            assert!(printed.status <= 2, "{what}: status {}", printed.status);
        }
    }
}

#[test]
fn data_keeps_the_bytes_and_json_encodes_them() {
    let dir = tempfile::tempdir().unwrap();
    let text = format!("wall type plane # {OSC}\n  colr{OSC} 3\n");
    std::fs::write(dir.path().join("a.walls"), &text).unwrap();
    // The formatted text of standard input is data: the comment's bytes stay.
    let mut fmt = Command::new(env!("CARGO_BIN_EXE_walls-fmt"))
        .arg("-")
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let clean = format!("wall type plane # {OSC}\n  origin 0  0 1\n");
    walls_test_support::cli::feed(&mut fmt, clean.as_bytes());
    let out = fmt.wait_with_output().unwrap();
    assert_eq!(
        String::from_utf8(out.stdout).unwrap(),
        format!("wall type plane # {OSC}\n  origin 0 0 1\n")
    );
    // JSON, SARIF and GitLab reports encode them as JSON escapes, read back as they were.
    for format in ["json", "sarif", "gitlab", "github"] {
        let printed = run(
            "walls-lint",
            &["--format".into(), format.into(), "a.walls".into()],
            dir.path(),
            false,
        );
        assert_safe(&printed.stdout, format);
        assert_eq!(printed.status, 1, "{format}");
        if format == "github" {
            assert!(printed.stdout.contains("unknown word `colr\\x1b]52;c;aGk`"));
            continue;
        }
        assert!(printed.stdout.contains("colr\\u001b]52;c;aGk`"), "{format}");
        let value: serde_json::Value = serde_json::from_str(&printed.stdout).unwrap();
        assert!(value.to_string().contains("colr\\u001b"), "{format}");
    }
}
