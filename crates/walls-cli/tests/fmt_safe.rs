//! What `walls-fmt` promises about the files it writes (docs/formatting.md): it writes
//! only files the user may write, keeps owner, group, mode and hard links, never replaces
//! a file that changed since it was read, leaves no temporary file when it is killed or
//! interrupted, counts a file named twice once, and says when a file could not be read.
//!
//! The decision itself ([`check`]) is tested with made-up metadata, so that it is covered
//! whoever runs the tests; the tests that need files owned by another user create them as
//! root and run `walls-fmt` as `nobody` with `setpriv`, and fail (saying so) when not run
//! as root.

#![cfg(unix)]

use std::io::{BufRead, BufReader, Write};
use std::os::unix::fs::{MetadataExt, PermissionsExt};
use std::os::unix::process::ExitStatusExt;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use walls_cli::input::MAX_FILE_BYTES;
use walls_output::replace::{self, check};
use walls_output::{FileKind, Refusal, Stamp, Temporary, WriteError};

const MESSY: &str = "WALL TYPE plane,origin=0,0,1\n";
const CLEAN: &str = "wall type plane\n  origin 0 0 1\n";
const NOBODY: u32 = 65534;

fn walls_fmt(dir: &Path, args: &[&str]) -> Output {
    walls_fmt_fed(dir, args, b"")
}

/// `walls-fmt ARGS` in `dir`, with `stdin` piped to it.
fn walls_fmt_fed(dir: &Path, args: &[&str], stdin: &[u8]) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_walls-fmt"))
        .args(args)
        .current_dir(dir)
        .env_remove("NO_COLOR")
        .env_remove("CLICOLOR_FORCE")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    walls_test_support::cli::feed(&mut child, stdin);
    child.wait_with_output().unwrap()
}

/// What the tool printed: its own errors (standard error), then its report (standard
/// output: the files that would change, the summary).
fn printed(out: &Output) -> String {
    let mut text = String::from_utf8_lossy(&out.stderr).into_owned();
    text.push_str(&String::from_utf8_lossy(&out.stdout));
    text
}

/// The names in `dir`, sorted.
fn names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

fn write(path: &Path, text: &str, mode: u32) {
    std::fs::write(path, text).unwrap();
    std::fs::set_permissions(path, std::fs::Permissions::from_mode(mode)).unwrap();
}

/// A regular file's stamp, with the fields a test varies.
fn stamp(mode: u32, uid: u32, nlink: u64) -> Stamp {
    Stamp {
        dev: 1,
        ino: 2,
        size: 30,
        mtime: (1_700_000_000, 5),
        ctime: (1_700_000_000, 5),
        mode: 0o100000 | mode,
        uid,
        gid: uid,
        nlink,
    }
}

#[test]
fn the_decision_whoever_runs_it() {
    let own = stamp(0o644, 1000, 1);
    assert_eq!(check(&own, &own, true, 1000), Ok(()));
    // Root may rewrite another user's file: the owner is kept.
    let theirs = stamp(0o644, NOBODY, 1);
    assert_eq!(check(&theirs, &theirs, true, 0), Ok(()));
    // A read-only file stays read-only, even for root, whom access(2) lets write it.
    let read_only = stamp(0o444, 0, 1);
    assert_eq!(
        check(&read_only, &read_only, true, 0),
        Err(Refusal::ReadOnly { mode: 0o100444 })
    );
    assert_eq!(
        check(&stamp(0o555, 1000, 1), &stamp(0o555, 1000, 1), true, 1000),
        Err(Refusal::ReadOnly { mode: 0o100555 })
    );
    // access(2) says no: root's 644 file and another user.
    let roots = stamp(0o644, 0, 1);
    assert_eq!(
        check(&roots, &roots, false, NOBODY),
        Err(Refusal::NoPermission)
    );
    // Writable by everyone, but a rewrite by nobody would make the file nobody's.
    let open = stamp(0o666, 0, 1);
    assert_eq!(
        check(&open, &open, true, NOBODY),
        Err(Refusal::Owner { uid: 0, gid: 0 })
    );
    let linked = stamp(0o644, 1000, 2);
    assert_eq!(
        check(&linked, &linked, true, 1000),
        Err(Refusal::HardLinks { links: 2 })
    );
    let fifo = Stamp {
        mode: 0o010644,
        ..own
    };
    assert_eq!(
        check(&fifo, &fifo, true, 1000),
        Err(Refusal::NotRegular {
            kind: FileKind::Fifo
        })
    );
    // Any change of identity, size or time since the read, down to a nanosecond.
    for now in [
        Stamp { dev: 9, ..own },
        Stamp { ino: 9, ..own },
        Stamp { size: 31, ..own },
        Stamp {
            mtime: (1_700_000_000, 6),
            ..own
        },
        Stamp {
            ctime: (1_700_000_000, 6),
            ..own
        },
    ] {
        assert_eq!(check(&own, &now, true, 1000), Err(Refusal::Changed));
    }
}

#[test]
fn a_read_only_file_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    write(&dir.path().join("ro.walls"), MESSY, 0o444);
    write(&dir.path().join("ok.walls"), MESSY, 0o644);
    let out = walls_fmt(dir.path(), &["ro.walls", "ok.walls"]);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        printed(&out),
        "walls-fmt: error: not writing ro.walls: it is read-only (mode 0444); make it \
         writable first (chmod u+w)\n1 file reformatted, 0 unchanged, 1 not written\n"
    );
    let ro = dir.path().join("ro.walls");
    assert_eq!(std::fs::read_to_string(&ro).unwrap(), MESSY);
    assert_eq!(std::fs::metadata(&ro).unwrap().mode() & 0o7777, 0o444);
    assert_eq!(
        std::fs::read_to_string(dir.path().join("ok.walls")).unwrap(),
        CLEAN
    );
}

#[test]
fn extended_attributes_are_kept() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("a.walls");
    write(&path, MESSY, 0o644);
    rustix::fs::setxattr(
        &path,
        "user.walls.note",
        b"checked by hand",
        rustix::fs::XattrFlags::empty(),
    )
    .expect("the temporary folder's filesystem takes user extended attributes");
    let out = walls_fmt(dir.path(), &["a.walls"]);
    assert_eq!(out.status.code(), Some(0), "{}", printed(&out));
    assert_eq!(std::fs::read_to_string(&path).unwrap(), CLEAN);
    let mut value = [0; 64];
    let len = rustix::fs::getxattr(&path, "user.walls.note", &mut value[..]).unwrap();
    assert_eq!(&value[..len], b"checked by hand");
}

#[test]
fn hard_links_are_refused_not_parted() {
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (dir.path().join("a.walls"), dir.path().join("b.walls"));
    write(&a, MESSY, 0o644);
    std::fs::hard_link(&a, &b).unwrap();
    let out = walls_fmt(dir.path(), &["a.walls"]);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        printed(&out),
        "walls-fmt: error: not writing a.walls: it has 2 hard links, which a rewrite would \
         part; format a copy (walls-fmt - < FILE > COPY) and copy it back over the file\n\
         0 files reformatted, 0 unchanged, 1 not written\n"
    );
    assert_eq!(std::fs::read_to_string(&a).unwrap(), MESSY);
    assert_eq!(std::fs::metadata(&b).unwrap().nlink(), 2);
    assert_eq!(
        std::fs::metadata(&a).unwrap().ino(),
        std::fs::metadata(&b).unwrap().ino()
    );
}

#[test]
fn a_pipe_is_read_but_not_replaced() {
    for (flag, code, message) in [
        (
            None,
            2,
            "walls-fmt: error: not writing /dev/stdin: it is a FIFO (named pipe), not a regular file\n\
             0 files reformatted, 0 unchanged, 1 not written\n",
        ),
        (
            Some("--check"),
            1,
            "would reformat /dev/stdin\n1 file would be reformatted, 0 unchanged\n",
        ),
    ] {
        let dir = tempfile::tempdir().unwrap();
        let args: Vec<&str> = flag.into_iter().chain(["/dev/stdin"]).collect();
        let out = walls_fmt_fed(dir.path(), &args, MESSY.as_bytes());
        assert_eq!(out.status.code(), Some(code), "{flag:?}");
        assert_eq!(printed(&out), message);
    }
}

#[test]
fn the_same_file_named_three_ways_is_formatted_once() {
    let dir = tempfile::tempdir().unwrap();
    write(&dir.path().join("a.walls"), MESSY, 0o644);
    write(&dir.path().join("b.walls"), CLEAN, 0o644);
    std::os::unix::fs::symlink("a.walls", dir.path().join("link.walls")).unwrap();
    let out = walls_fmt(
        dir.path(),
        &["a.walls", "./a.walls", "link.walls", "b.walls", "b.walls"],
    );
    assert_eq!(out.status.code(), Some(0));
    assert_eq!(printed(&out), "1 file reformatted, 1 unchanged\n");
    assert_eq!(
        std::fs::read_to_string(dir.path().join("link.walls")).unwrap(),
        CLEAN
    );
}

#[test]
fn an_edit_saved_after_the_read_is_kept() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("a.walls");
    write(&path, MESSY, 0o644);
    let (original, bytes) = replace::read(&path, MAX_FILE_BYTES).unwrap();
    assert_eq!(bytes, MESSY.as_bytes());
    // The user appends a line and saves.
    let edited = format!("{MESSY}wall type disk\n");
    std::fs::OpenOptions::new()
        .append(true)
        .open(&path)
        .unwrap()
        .write_all(b"wall type disk\n")
        .unwrap();
    let result = original.replace(CLEAN.as_bytes());
    assert!(
        matches!(result, Err(WriteError::Refused(Refusal::Changed))),
        "{result:?}"
    );
    assert_eq!(std::fs::read_to_string(&path).unwrap(), edited);
    assert_eq!(names(dir.path()), ["a.walls"]);
}

#[test]
fn an_edit_saved_by_renaming_after_the_read_is_kept() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("a.walls");
    write(&path, MESSY, 0o644);
    let (original, _) = replace::read(&path, MAX_FILE_BYTES).unwrap();
    // An editor saves the same number of bytes by writing a new file and renaming it.
    let saved = MESSY.replace("plane", "PLANE");
    write(&dir.path().join("new"), &saved, 0o644);
    std::fs::rename(dir.path().join("new"), &path).unwrap();
    let result = original.replace(CLEAN.as_bytes());
    assert!(
        matches!(result, Err(WriteError::Refused(Refusal::Changed))),
        "{result:?}"
    );
    assert_eq!(std::fs::read_to_string(&path).unwrap(), saved);
}

#[test]
fn an_edit_saved_while_writing_is_kept() {
    for temporary in [Temporary::Unnamed, Temporary::Named] {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("a.walls");
        write(&path, MESSY, 0o644);
        let (original, _) = replace::read(&path, MAX_FILE_BYTES).unwrap();
        let result = original.replace_with(temporary, |file| {
            file.write_all(CLEAN.as_bytes())?;
            // The user saves while the new text is being written.
            std::fs::OpenOptions::new()
                .append(true)
                .open(&path)?
                .write_all(b"# mine\n")
        });
        assert!(
            matches!(result, Err(WriteError::Refused(Refusal::Changed))),
            "{temporary:?}: {result:?}"
        );
        assert_eq!(
            std::fs::read_to_string(&path).unwrap(),
            format!("{MESSY}# mine\n")
        );
        assert_eq!(names(dir.path()), ["a.walls"], "{temporary:?}");
    }
}

/// A file of about `lines` × 60 bytes that formatting changes.
fn big_messy(path: &Path, lines: usize) {
    let block = "WALL TYPE disk,radius=0.5 # r\n  origin = -1, 0,\n     0.2\n";
    write(path, &block.repeat(lines / 3), 0o644);
}

/// Runs walls-fmt on a big file that formatting changes under a 64 KiB file-size limit
/// (`ulimit -f 64`, after the shell's `setup`), and checks that the original and its
/// folder are as they were.
fn fmt_past_a_file_size_limit(setup: &str) -> Output {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("big.walls");
    big_messy(&path, 30_000);
    let before = std::fs::read(&path).unwrap();
    let out = Command::new("sh")
        .arg("-c")
        .arg(format!("{setup}ulimit -f 64 && exec \"$0\" big.walls"))
        .arg(env!("CARGO_BIN_EXE_walls-fmt"))
        .current_dir(dir.path())
        .output()
        .unwrap();
    assert_eq!(std::fs::read(&path).unwrap(), before, "{out:?}");
    assert_eq!(names(dir.path()), ["big.walls"], "{out:?}");
    out
}

#[test]
fn killed_mid_write_leaves_the_original_and_no_temporary_file() {
    // SIGXFSZ, which walls-fmt does not handle, kills it like SIGKILL while it writes.
    let out = fmt_past_a_file_size_limit("");
    assert_eq!(out.status.signal(), Some(25), "SIGXFSZ: {out:?}");
}

#[test]
fn a_full_disk_leaves_the_original() {
    // With SIGXFSZ ignored, writing past the limit fails as on a full disk (EFBIG).
    let out = fmt_past_a_file_size_limit("trap '' XFSZ && ");
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        printed(&out),
        "walls-fmt: error: cannot write big.walls: File too large (os error 27)\n\
         0 files reformatted, 0 unchanged, 1 not written\n"
    );
}

/// The variable that makes [`a_signal_while_writing_removes_the_temporary_file`] the
/// writer it runs in a child process: `SIGNAL,KIND,FOLDER`.
const CHILD: &str = "WALLS_FMT_TEST_SIGNAL_CHILD";

#[test]
fn a_signal_while_writing_removes_the_temporary_file() {
    if let Ok(job) = std::env::var(CHILD) {
        // The child: half the new text written, it says so and waits for the signal.
        let dir = PathBuf::from(job.rsplit(',').next().unwrap());
        let temporary = if job.contains(",named,") {
            Temporary::Named
        } else {
            Temporary::Unnamed
        };
        let (original, _) = replace::read(&dir.join("a.walls"), MAX_FILE_BYTES).unwrap();
        let result = original.replace_with(temporary, |file| {
            file.write_all(&CLEAN.as_bytes()[..8])?;
            file.sync_all()?;
            println!("writing");
            std::thread::sleep(std::time::Duration::from_secs(60));
            Ok(())
        });
        panic!("no signal came: {result:?}");
    }
    for (signal, name) in [(15, "TERM"), (2, "INT")] {
        for kind in ["named", "unnamed"] {
            let dir = tempfile::tempdir().unwrap();
            write(&dir.path().join("a.walls"), MESSY, 0o644);
            let mut child = Command::new(std::env::current_exe().unwrap())
                .args([
                    "--exact",
                    "a_signal_while_writing_removes_the_temporary_file",
                    "--nocapture",
                ])
                .env(CHILD, format!("{signal},{kind},{}", dir.path().display()))
                .stdout(Stdio::piped())
                .stderr(Stdio::null())
                .spawn()
                .unwrap();
            let lines = BufReader::new(child.stdout.take().unwrap()).lines();
            let mut seen = Vec::new();
            for line in lines {
                let line = line.unwrap();
                if line == "writing" {
                    break;
                }
                seen.push(line);
            }
            let during = names(dir.path());
            if kind == "named" {
                assert_eq!(during.len(), 2, "the named file is there: {during:?}");
            } else {
                assert_eq!(during, ["a.walls"], "unnamed: {seen:?}");
            }
            Command::new("kill")
                .args([format!("-{name}"), child.id().to_string()])
                .status()
                .unwrap();
            let status = child.wait().unwrap();
            assert_eq!(status.code(), Some(128 + signal), "{name} {kind}");
            assert_eq!(names(dir.path()), ["a.walls"], "{name} {kind}");
            assert_eq!(
                std::fs::read_to_string(dir.path().join("a.walls")).unwrap(),
                MESSY
            );
        }
    }
}

/// Fails, saying why, unless the tests run as root (they need files of other users).
fn require_root() {
    assert_eq!(
        rustix::process::geteuid().as_raw(),
        0,
        "this test makes files owned by root and by nobody and runs walls-fmt as nobody \
         (setpriv): run it as root"
    );
}

/// `walls-fmt ARGS` in `dir` as the user nobody.
fn walls_fmt_as_nobody(dir: &Path, args: &[&str]) -> Output {
    let setpriv = Command::new("setpriv")
        .args(["--reuid=65534", "--regid=65534", "--clear-groups"])
        .arg(env!("CARGO_BIN_EXE_walls-fmt"))
        .args(args)
        .current_dir(dir)
        .output();
    setpriv.expect("setpriv (util-linux) runs walls-fmt as nobody: install it")
}

/// A folder everyone may write (and so nobody may make and rename files in).
fn open_folder() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    std::fs::set_permissions(dir.path(), std::fs::Permissions::from_mode(0o777)).unwrap();
    dir
}

#[test]
fn root_keeps_the_owner_group_and_mode() {
    require_root();
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("theirs.walls");
    std::fs::write(&path, MESSY).unwrap();
    std::os::unix::fs::chown(&path, Some(NOBODY), Some(NOBODY)).unwrap();
    // Set-group-id too, which a chown after the chmod would clear.
    std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o2640)).unwrap();
    let out = walls_fmt(dir.path(), &["theirs.walls"]);
    assert_eq!(out.status.code(), Some(0), "{}", printed(&out));
    let meta = std::fs::metadata(&path).unwrap();
    assert_eq!((meta.uid(), meta.gid()), (NOBODY, NOBODY));
    assert_eq!(meta.mode() & 0o7777, 0o2640);
    assert_eq!(std::fs::read_to_string(&path).unwrap(), CLEAN);
}

#[test]
fn nobody_may_not_rewrite_roots_file_in_an_open_folder() {
    require_root();
    let dir = open_folder();
    write(&dir.path().join("root.walls"), MESSY, 0o644);
    let out = walls_fmt_as_nobody(dir.path(), &["root.walls"]);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        printed(&out),
        "walls-fmt: error: not writing root.walls: you do not have permission to write it\n\
         0 files reformatted, 0 unchanged, 1 not written\n"
    );
    let meta = std::fs::metadata(dir.path().join("root.walls")).unwrap();
    assert_eq!((meta.uid(), meta.mode() & 0o7777), (0, 0o644));
    assert_eq!(
        std::fs::read_to_string(dir.path().join("root.walls")).unwrap(),
        MESSY
    );
}

#[test]
fn nobody_may_not_take_roots_writable_file_nor_change_a_group() {
    require_root();
    let dir = open_folder();
    write(&dir.path().join("shared.walls"), MESSY, 0o666);
    write(&dir.path().join("own.walls"), MESSY, 0o644);
    std::os::unix::fs::chown(dir.path().join("own.walls"), Some(NOBODY), Some(NOBODY)).unwrap();
    // Nobody's file in root's group, which nobody is not in.
    write(&dir.path().join("group.walls"), MESSY, 0o664);
    std::os::unix::fs::chown(dir.path().join("group.walls"), Some(NOBODY), Some(0)).unwrap();
    let out = walls_fmt_as_nobody(dir.path(), &["shared.walls", "group.walls", "own.walls"]);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        printed(&out),
        "walls-fmt: error: not writing shared.walls: a rewrite would change its owner or \
         group (uid 0, gid 0), which you cannot keep; format it as its owner\n\
         walls-fmt: error: not writing group.walls: a rewrite would change its owner or \
         group (uid 65534, gid 0), which you cannot keep; format it as its owner\n\
         1 file reformatted, 0 unchanged, 2 not written\n"
    );
    let shared = std::fs::metadata(dir.path().join("shared.walls")).unwrap();
    assert_eq!((shared.uid(), shared.gid()), (0, 0));
    assert_eq!(
        std::fs::read_to_string(dir.path().join("shared.walls")).unwrap(),
        MESSY
    );
    let group = std::fs::metadata(dir.path().join("group.walls")).unwrap();
    assert_eq!((group.uid(), group.gid()), (NOBODY, 0));
    assert_eq!(
        std::fs::read_to_string(dir.path().join("group.walls")).unwrap(),
        MESSY
    );
    let own = std::fs::metadata(dir.path().join("own.walls")).unwrap();
    assert_eq!((own.uid(), own.gid()), (NOBODY, NOBODY));
    assert_eq!(
        std::fs::read_to_string(dir.path().join("own.walls")).unwrap(),
        CLEAN
    );
}

#[test]
fn a_folder_nobody_may_write_is_named() {
    require_root();
    let dir = tempfile::tempdir().unwrap();
    std::fs::set_permissions(dir.path(), std::fs::Permissions::from_mode(0o755)).unwrap();
    let path = dir.path().join("mine.walls");
    write(&path, MESSY, 0o644);
    std::os::unix::fs::chown(&path, Some(NOBODY), Some(NOBODY)).unwrap();
    let out = walls_fmt_as_nobody(dir.path(), &["mine.walls"]);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        printed(&out),
        format!(
            "walls-fmt: error: cannot write mine.walls: cannot make a new file in {} to put \
             in its place (Permission denied (os error 13)): rewriting a file needs \
             permission to write its folder too\n0 files reformatted, 0 unchanged, 1 not written\n",
            dir.path().canonicalize().unwrap().display()
        )
    );
    assert_eq!(std::fs::read_to_string(&path).unwrap(), MESSY);
}

#[test]
fn a_report_nobody_reads_is_no_success() {
    // `walls-fmt --check … | head -1` in a CI script with pipefail: the reader gone, the
    // files still need formatting, and the status must not say they do not.
    let dir = tempfile::tempdir().unwrap();
    for k in 0..50 {
        write(&dir.path().join(format!("f{k}.walls")), MESSY, 0o644);
    }
    let names: Vec<String> = (0..50).map(|k| format!("f{k}.walls")).collect();
    let mut child = Command::new(env!("CARGO_BIN_EXE_walls-fmt"))
        .arg("--check")
        .args(&names)
        .current_dir(dir.path())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(String::from_utf8_lossy(&out.stderr), "");
}
