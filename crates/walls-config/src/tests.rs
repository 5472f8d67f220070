//! Discovery, precedence and located mistakes, on folders made for each test.

use super::*;
use std::path::Path;

fn write(root: &Path, name: &str, text: &str) {
    let path = root.join(name);
    std::fs::create_dir_all(path.parent().unwrap()).unwrap();
    std::fs::write(path, text).unwrap();
}

/// The error of the settings found from `dir`, relative to `root`.
fn error(root: &Path, dir: &Path) -> String {
    let e = find(dir).map(|s| s.path).expect_err("an error");
    let root = absolute(root).display().to_string();
    e.to_string().replace(&root, "ROOT")
}

#[test]
fn the_nearest_folder_with_settings_wins_whole() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    write(
        root,
        "walls.toml",
        "[lint]\nmode = \"hsdem\"\nmax-walls = 4\n",
    );
    // A pyproject without [tool.walls] does not count.
    write(root, "a/pyproject.toml", "[project]\nname = \"x\"\n");
    write(root, "a/b/pyproject.toml", "[tool.walls.lint]\ndt = 0.5\n");
    std::fs::create_dir_all(root.join("a/b/c")).unwrap();
    let s = find(&root.join("a")).unwrap();
    assert_eq!(s.path, Some(absolute(root).join("walls.toml")));
    assert_eq!(s.lint.mode, Some(ContactModel::Hsdem));
    assert_eq!(s.lint.max_walls, Some(4));
    let s = find(&root.join("a/b/c")).unwrap();
    assert_eq!(s.path, Some(absolute(root).join("a/b/pyproject.toml")));
    // Nothing is merged from further up.
    assert_eq!(
        (s.lint.mode, s.lint.max_walls, s.lint.dt),
        (None, None, Some(0.5))
    );
    let none = tempfile::tempdir().unwrap();
    assert_eq!(find(none.path()).unwrap().path, None);
}

#[test]
fn format_options_come_from_the_nearest_settings_or_walls_fmt_toml() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    write(root, ".walls-fmt.toml", "indent_width = 4\n");
    write(
        root,
        "a/.walls.toml",
        "[format]\nindent-width = 3\nkeep-blank-lines = false\n",
    );
    write(root, "a/b/walls.toml", "[lint]\nmax-walls = 30\n");
    let (o, path) = find_format(root).unwrap();
    assert_eq!(
        (o.indent_width, path),
        (4, Some(absolute(root).join(".walls-fmt.toml")))
    );
    let (o, _) = find_format(&root.join("a")).unwrap();
    assert_eq!((o.indent_width, o.keep_blank_lines), (3, false));
    // A settings file without [format]: the defaults.
    let (o, _) = find_format(&root.join("a/b")).unwrap();
    assert_eq!(o, FormatOptions::default());
    write(root, "a/.walls-fmt.toml", "indent_width = 4\n");
    let e = find_format(&root.join("a")).unwrap_err().to_string();
    let r = absolute(root).display().to_string();
    assert_eq!(
        e.replace(&r, "ROOT"),
        "ROOT/a/.walls-fmt.toml: both this file and ROOT/a/.walls.toml set the formatting options: keep one (move them to the [format] table)"
    );
}

#[test]
fn two_settings_files_in_one_folder_are_an_error() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    write(root, "walls.toml", "");
    write(root, "pyproject.toml", "[tool.walls]\n");
    assert_eq!(
        error(root, root),
        "ROOT/walls.toml: both this file and ROOT/pyproject.toml are settings files of the same folder: keep one"
    );
}

#[test]
fn every_mistake_is_located() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    for (text, expected) in [
        (
            "[lint]\nmax-wall = 3\n",
            "ROOT/walls.toml:2:1: unknown field `max-wall`, expected one of `mode`, `max-walls`, `min-radius`, `dt`, `deny-warnings`, `ignore`, `per-file-ignores`, `include`, `exclude`",
        ),
        (
            "[lint]\nmode = \"soft\"\n",
            "ROOT/walls.toml:2:8: unknown variant `soft`, expected `ssdem` or `hsdem`",
        ),
        (
            "[lint]\nmax-walls = \"4\"\n",
            "ROOT/walls.toml:2:13: invalid type: string \"4\", expected usize",
        ),
        (
            "[lint]\nignore = [\"C201\", \"C999\"]\n",
            "ROOT/walls.toml:2:19: `C999` is not a diagnostic code (walls-lint --explain CODE, docs/diagnostics.md)",
        ),
        (
            "[lint.per-file-ignores]\n\"old/*.walls\" = [\"X1\"]\n",
            "ROOT/walls.toml:2:18: `X1` is not a diagnostic code (walls-lint --explain CODE, docs/diagnostics.md)",
        ),
        (
            "[lint]\nexclude = [\"a[\"]\n",
            "ROOT/walls.toml:2:12: invalid glob `a[`: error parsing glob 'a[': unclosed character class; missing ']'",
        ),
        (
            "[lint]\nmin-radius = -1.0\n",
            "ROOT/walls.toml:2:14: min-radius must be a positive number, not -1",
        ),
        (
            "[format]\nindent-width = 20\n",
            "ROOT/walls.toml:2:16: indent-width 20 is more than 16",
        ),
        (
            "[fmt]\n",
            "ROOT/walls.toml:1:2: unknown field `fmt`, expected one of `lint`, `format`, `run`",
        ),
        (
            "[lint\n",
            "ROOT/walls.toml:1:6: unclosed table, expected `]`",
        ),
    ] {
        write(root, "walls.toml", text);
        assert_eq!(error(root, root), expected, "{text}");
    }
}

#[test]
fn ignores_hide_warnings_of_matching_files_but_never_errors() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    write(
        root,
        "walls.toml",
        "[lint]\nignore = [\"S103\"]\n[lint.per-file-ignores]\n\"old/*.walls\" = [\"ignored-by-type\"]\n",
    );
    let s = find(root).unwrap();
    let text = "wall type plane\n  radius 2\n  origin 0 0\n";
    let check = || walls_ide::check_text(text, &walls_model::Options::default()).diagnostics;
    let codes = |d: &[Diagnostic]| d.iter().map(|d| d.code.id).collect::<Vec<_>>();
    let old = absolute(root).join("old/a.walls");
    let mut d = check();
    let met = s.lint.filter(Some(&old), &mut d);
    assert_eq!(codes(&d), ["S103"]);
    assert_eq!(met.len(), 1);
    assert_eq!(met[0].code.id, "S103");
    assert_eq!(
        met[0].at.to_string(),
        format!("{}:2:11", absolute(root).join("walls.toml").display())
    );
    let mut d = check();
    s.lint
        .filter(Some(&absolute(root).join("new/a.walls")), &mut d);
    assert_eq!(codes(&d), ["C201", "S103"]);
    let mut d = check();
    s.lint.filter(None, &mut d);
    assert_eq!(codes(&d), ["C201", "S103"]);
}

#[test]
fn load_reads_the_file_named() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    write(root, "x/pyproject.toml", "[project]\n");
    assert_eq!(
        load(&root.join("x/pyproject.toml")).unwrap_err().message,
        "has no [tool.walls] table"
    );
    write(root, "x/any.toml", "[lint]\ndeny-warnings = true\n");
    let s = load(&root.join("x/any.toml")).unwrap();
    assert_eq!(s.lint.deny_warnings, Some(true));
    let e = load(&root.join("x/none.toml")).unwrap_err().to_string();
    assert!(
        e.ends_with("none.toml: cannot read: No such file or directory (os error 2)"),
        "{e}"
    );
}

#[test]
fn the_values_the_table_sets_replace_the_base_options() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    write(root, "walls.toml", "[lint]\nmode = \"hsdem\"\ndt = 0.5\n");
    let base = walls_model::Options {
        mode: ContactModel::Ssdem,
        max_walls: 30,
        min_radius: Some(0.1),
        dt: Some(2.0),
    };
    let options = find(root).unwrap().lint.options(&base);
    assert_eq!(options.mode, ContactModel::Hsdem);
    assert_eq!(options.max_walls, 30);
    assert_eq!(options.min_radius, Some(0.1));
    assert_eq!(options.dt, Some(0.5));
    // An empty table changes nothing.
    let options = Lint::default().options(&base);
    assert_eq!(
        (
            options.mode,
            options.max_walls,
            options.min_radius,
            options.dt
        ),
        (ContactModel::Ssdem, 30, Some(0.1), Some(2.0))
    );
}

#[test]
fn every_glob_is_checked_as_include_is() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    let unclosed = "error parsing glob '[': unclosed character class; missing ']'";
    for (text, expected) in [
        (
            "[lint.per-file-ignores]\n\"[\" = [\"C201\"]\n".to_string(),
            format!("ROOT/walls.toml:2:1: invalid glob `[`: {unclosed}"),
        ),
        (
            "[lint]\ninclude = [\"[\"]\n".to_string(),
            format!("ROOT/walls.toml:2:12: invalid glob `[`: {unclosed}"),
        ),
        (
            "[lint.per-file-ignores]\n\"!old/*.walls\" = [\"C201\"]\n".into(),
            "ROOT/walls.toml:2:1: invalid glob `!old/*.walls`: a glob here cannot be negated; \
             write `\\!` for a name that starts with `!`"
                .into(),
        ),
        (
            "[lint]\nexclude = [\"a\", \"#old\"]\n".into(),
            "ROOT/walls.toml:2:17: invalid glob `#old`: a glob cannot start with `#` (a comment \
             in gitignore syntax); write `\\#` for a name that starts with `#`"
                .into(),
        ),
        (
            "[lint]\ninclude = [\" \"]\n".into(),
            "ROOT/walls.toml:2:12: invalid glob ` `: an empty glob matches nothing".into(),
        ),
    ] {
        write(root, "walls.toml", &text);
        assert_eq!(error(root, root), expected, "{text}");
    }
    // Escaped, they are names.
    write(
        root,
        "walls.toml",
        "[lint.per-file-ignores]\n\"\\\\!a.walls\" = [\"C201\"]\n\"\\\\#b.walls\" = [\"C201\"]\n",
    );
    let s = find(root).unwrap();
    let root = absolute(root);
    for name in ["!a.walls", "#b.walls"] {
        assert_eq!(
            s.lint.ignores_for(Some(&root.join(name))).count(),
            1,
            "{name}"
        );
    }
}

#[cfg(unix)]
#[test]
fn a_device_or_a_folder_is_no_settings_file() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    // Named: refused at once, nothing read.
    let e = load(Path::new("/dev/zero")).unwrap_err().to_string();
    assert_eq!(
        e,
        "/dev/zero: is a character device, not a settings file (a settings file is a regular file or a pipe)"
    );
    assert_eq!(
        load(root).unwrap_err().message,
        "is a folder, not a settings file"
    );
    // Found: a FIFO is refused rather than waited on, a folder named walls.toml too.
    let fifo = root.join("a/walls.toml");
    std::fs::create_dir_all(root.join("a")).unwrap();
    let made = std::process::Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .unwrap();
    assert!(made.success());
    assert_eq!(
        error(root, &root.join("a")),
        "ROOT/a/walls.toml: is a fifo, not a settings file (a settings file found in a folder is a regular file)"
    );
    std::fs::create_dir_all(root.join("b/walls.toml")).unwrap();
    assert_eq!(
        error(root, &root.join("b")),
        "ROOT/b/walls.toml: is a folder, not a settings file"
    );
}

#[cfg(unix)]
#[test]
fn a_pipe_named_is_read_up_to_the_limit() {
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("settings");
    let made = std::process::Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .unwrap();
    assert!(made.success());
    let writer = {
        let fifo = fifo.clone();
        std::thread::spawn(move || std::fs::write(fifo, "[lint]\nmax-walls = 7\n").unwrap())
    };
    assert_eq!(load(&fifo).unwrap().lint.max_walls, Some(7));
    writer.join().unwrap();
    // The limit holds while reading: never more than it is kept.
    let endless = std::io::repeat(b'#');
    let e = read_at_most(endless, 1000).unwrap_err();
    assert_eq!(
        e.to_string(),
        "larger than 1000 bytes, the most the tools read"
    );
    assert_eq!(read_at_most(&b"abc"[..], 3).unwrap(), b"abc");
}

#[test]
fn a_file_over_the_limit_is_refused_before_it_is_read() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("walls.toml");
    // Sparse: no disk space, and no time if it is never read.
    let file = std::fs::File::create(&path).unwrap();
    file.set_len(MAX_FILE_BYTES + 1).unwrap();
    let start = std::time::Instant::now();
    let e = load(&path).unwrap_err();
    assert_eq!(
        e.message,
        "is 4294967296 bytes, larger than 4294967295 bytes, the most the tools read"
    );
    assert!(start.elapsed().as_secs() < 5, "{:?}", start.elapsed());
}

#[test]
fn a_settings_file_that_is_not_utf8_is_located() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    std::fs::write(root.join("walls.toml"), b"[lint]\nmode = \"\xff\"\n").unwrap();
    assert_eq!(
        error(root, root),
        "ROOT/walls.toml:2:9: is not UTF-8 text (byte 0xff)"
    );
}

#[test]
fn the_run_table_names_the_pkdgrav_build_and_an_unknown_option_is_located() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    write(
        root,
        "a/walls.toml",
        "[run]\npkdgrav-build = \"USE_DEM, DEM_COHESION\"\n",
    );
    let s = find(&root.join("a")).unwrap();
    assert_eq!(
        s.run.pkdgrav_build.map(|b| b.names()),
        Some("COLLISIONS DEM DEM_COHESION WALLS".to_string())
    );
    write(
        root,
        "b/walls.toml",
        "[run]\npkdgrav-build = \"DEM DEM_COHESON\"\n",
    );
    assert_eq!(
        error(root, &root.join("b")),
        "ROOT/b/walls.toml:2:17: pkdgrav-build: unknown pkdgrav compile option `DEM_COHESON`, did you mean `DEM_COHESION`?"
    );
    write(root, "c/walls.toml", "[run]\nbuild = \"DEM\"\n");
    assert!(error(root, &root.join("c")).contains("unknown field `build`"));
}
