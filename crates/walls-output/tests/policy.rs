//! The policy of the crate's documentation, file kind by file kind: what is refused
//! (and that nothing is touched then), what is written through, what is kept.

#![cfg(unix)]

use std::io::Write;
use std::os::unix::fs::{MetadataExt, PermissionsExt};
use std::path::Path;
use walls_output::{FileKind, Outputs, Refusal, Tool, WriteError};

fn refusal(e: WriteError) -> Refusal {
    match e {
        WriteError::Refused(r) => r,
        WriteError::Io(e) => panic!("an I/O error, not a refusal: {e}"),
    }
}

fn outputs(force: bool) -> Outputs {
    Outputs::new(Tool::MESH, force)
}

#[test]
fn a_new_output_is_written_whole_with_the_umask_s_mode() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("out.walls");
    let target = outputs(false).plan(&path).unwrap();
    assert!(!target.exists());
    target.write(b"wall\n").unwrap();
    assert_eq!(std::fs::read(&path).unwrap(), b"wall\n");
    let mode = std::fs::metadata(&path).unwrap().mode() & 0o777;
    // 0666 less the umask: the test process's umask is at least 0 and rarely above 077.
    assert!(mode & 0o600 == 0o600, "{mode:o}");
    // No temporary file is left beside it.
    let names: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
    assert_eq!(names.len(), 1);
}

#[test]
fn an_existing_output_is_replaced_only_with_force_keeping_its_mode() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("out.walls");
    std::fs::write(&path, "old\n").unwrap();
    std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o640)).unwrap();
    assert_eq!(
        refusal(outputs(false).plan(&path).unwrap_err()),
        Refusal::Exists
    );
    assert_eq!(std::fs::read(&path).unwrap(), b"old\n");
    let target = outputs(true).plan(&path).unwrap();
    assert!(target.exists());
    target.write(b"new\n").unwrap();
    assert_eq!(std::fs::read(&path).unwrap(), b"new\n");
    assert_eq!(std::fs::metadata(&path).unwrap().mode() & 0o7777, 0o640);
}

#[test]
fn devices_fifos_sockets_and_folders_are_never_replaced() {
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("fifo");
    rustix::fs::mknodat(
        rustix::fs::CWD,
        &fifo,
        rustix::fs::FileType::Fifo,
        rustix::fs::Mode::from_raw_mode(0o644),
        0,
    )
    .unwrap();
    let socket = dir.path().join("socket");
    let _listener = std::os::unix::net::UnixListener::bind(&socket).unwrap();
    let folder = dir.path().join("folder");
    std::fs::create_dir(&folder).unwrap();
    // Planning only looks: /dev/null itself is safe to plan over.
    for (path, kind) in [
        (Path::new("/dev/null"), FileKind::CharDevice),
        (&fifo, FileKind::Fifo),
        (&socket, FileKind::Socket),
        (&folder, FileKind::Folder),
    ] {
        for force in [false, true] {
            let e = outputs(force).plan(path).unwrap_err();
            assert_eq!(
                refusal(e),
                Refusal::NotRegular { kind },
                "{}",
                path.display()
            );
        }
    }
    // A link to a device is the device.
    let link = dir.path().join("null");
    std::os::unix::fs::symlink("/dev/null", &link).unwrap();
    assert_eq!(
        refusal(outputs(true).plan(&link).unwrap_err()),
        Refusal::NotRegular {
            kind: FileKind::CharDevice
        }
    );
    assert_eq!(
        std::fs::symlink_metadata(&fifo).unwrap().file_type(),
        std::fs::symlink_metadata(&fifo).unwrap().file_type()
    );
    assert!(
        std::fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink()
    );
}

#[test]
fn a_symbolic_link_is_written_through_and_stays_a_link() {
    let dir = tempfile::tempdir().unwrap();
    let real = dir.path().join("real.walls");
    std::fs::write(&real, "old\n").unwrap();
    std::fs::set_permissions(&real, std::fs::Permissions::from_mode(0o600)).unwrap();
    let link = dir.path().join("link.walls");
    std::os::unix::fs::symlink("real.walls", &link).unwrap();
    outputs(true).plan(&link).unwrap().write(b"new\n").unwrap();
    assert!(
        std::fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink()
    );
    assert_eq!(std::fs::read(&real).unwrap(), b"new\n");
    assert_eq!(std::fs::metadata(&real).unwrap().mode() & 0o7777, 0o600);
    // A link to nothing is refused: writing through it would make a file where it points.
    let dangling = dir.path().join("dangling.walls");
    std::os::unix::fs::symlink("missing/x.walls", &dangling).unwrap();
    assert_eq!(
        refusal(outputs(true).plan(&dangling).unwrap_err()),
        Refusal::DanglingLink {
            to: "missing/x.walls".into()
        }
    );
    assert!(!dir.path().join("missing").exists());
}

#[test]
fn hard_links_and_read_only_files_are_refused_even_with_force() {
    let dir = tempfile::tempdir().unwrap();
    let one = dir.path().join("one");
    std::fs::write(&one, "old\n").unwrap();
    std::fs::hard_link(&one, dir.path().join("two")).unwrap();
    assert_eq!(
        refusal(outputs(true).plan(&one).unwrap_err()),
        Refusal::HardLinks { links: 2 }
    );
    let ro = dir.path().join("ro");
    std::fs::write(&ro, "old\n").unwrap();
    std::fs::set_permissions(&ro, std::fs::Permissions::from_mode(0o444)).unwrap();
    assert_eq!(
        refusal(outputs(true).plan(&ro).unwrap_err()),
        Refusal::ReadOnly { mode: 0o100444 }
    );
    assert_eq!(std::fs::read(&ro).unwrap(), b"old\n");
    assert_eq!(std::fs::metadata(&one).unwrap().nlink(), 2);
}

#[test]
fn an_input_is_never_an_output_by_any_name() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in.obj");
    std::fs::write(&input, "v 0 0 0\n").unwrap();
    let link = dir.path().join("alias.walls");
    std::os::unix::fs::symlink("in.obj", &link).unwrap();
    let mut outputs = outputs(true);
    outputs.reads(&input);
    for path in [&input, &link] {
        assert_eq!(refusal(outputs.plan(path).unwrap_err()), Refusal::Input);
    }
    assert_eq!(std::fs::read(&input).unwrap(), b"v 0 0 0\n");
}

#[test]
fn outputs_in_a_folder_stay_in_it() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    std::fs::create_dir(&out).unwrap();
    let elsewhere = tempfile::tempdir().unwrap();
    std::os::unix::fs::symlink(elsewhere.path(), out.join("away")).unwrap();
    let outside = Refusal::Outside { root: out.clone() };
    let outputs = outputs(true);
    let folder = outputs.folder(&out, false).unwrap();
    for name in [
        "../e.00010",
        "/tmp/e.00010",
        "away/e.00010",
        "a/../../e",
        "",
    ] {
        let e = folder.plan(Path::new(name)).unwrap_err();
        assert_eq!(refusal(e), outside, "{name}");
    }
    // A link in the folder is not followed, wherever it leads.
    std::fs::write(out.join("real"), "x").unwrap();
    std::os::unix::fs::symlink("real", out.join("link")).unwrap();
    assert_eq!(
        refusal(folder.plan(Path::new("link")).unwrap_err()),
        Refusal::Link
    );
    // Down into a folder not made yet is inside.
    let t = folder.plan(Path::new("movie/movie_000000.vtp")).unwrap();
    assert_eq!(t.path(), out.join("movie/movie_000000.vtp"));
    // In the current folder, the name alone is shown.
    let here = outputs.folder(Path::new("."), false).unwrap();
    let here = here.plan(Path::new("a.svg")).unwrap();
    assert_eq!(here.path(), Path::new("a.svg"));
    assert_eq!(std::fs::read_dir(elsewhere.path()).unwrap().count(), 0);
}

#[test]
fn a_folder_swapped_for_a_link_while_the_command_runs_does_not_move_its_outputs() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    std::fs::create_dir(&out).unwrap();
    let folder = outputs(false).folder(&out, false).unwrap();
    let elsewhere = tempfile::tempdir().unwrap();
    // The folder is renamed and a link to another put in its place.
    std::fs::rename(&out, dir.path().join("moved")).unwrap();
    std::os::unix::fs::symlink(elsewhere.path(), &out).unwrap();
    folder
        .plan(Path::new("a.svg"))
        .unwrap()
        .write(b"x")
        .unwrap();
    let mut stream = folder.plan(Path::new("m/b.csv")).unwrap().stream().unwrap();
    stream.write_all(b"1\n").unwrap();
    stream.finish().unwrap();
    assert_eq!(std::fs::read_dir(elsewhere.path()).unwrap().count(), 0);
    assert_eq!(std::fs::read(dir.path().join("moved/a.svg")).unwrap(), b"x");
    assert_eq!(
        std::fs::read(dir.path().join("moved/m/b.csv")).unwrap(),
        b"1\n"
    );
}

#[test]
fn a_standard_stream_is_never_a_file_to_replace() {
    for path in [
        "/dev/stdout",
        "/dev/stderr",
        "/dev/fd/1",
        "/proc/self/fd/1",
        "/dev/stdin",
    ] {
        assert_eq!(
            refusal(outputs(true).plan(Path::new(path)).unwrap_err()),
            Refusal::StandardStream,
            "{path}"
        );
    }
}

#[test]
fn a_file_made_meanwhile_is_left_alone() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("out.walls");
    let target = outputs(false).plan(&path).unwrap();
    std::fs::write(&path, "someone else's\n").unwrap();
    assert_eq!(
        refusal(target.write(b"ours\n").unwrap_err()),
        Refusal::Changed
    );
    // A stream takes its name at its first mark, which is then taken.
    let mut stream = target.stream().unwrap();
    stream.write_all(b"ours\n").unwrap();
    assert!(stream.commit().is_err());
    assert_eq!(std::fs::read(&path).unwrap(), b"someone else's\n");
}

#[test]
fn a_stream_is_cut_back_to_its_last_whole_group_of_rows() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("particles.csv");
    let target = outputs(false).plan(&path).unwrap();
    let mut stream = target.stream().unwrap();
    stream.write_all(b"step,x\n0,1\n").unwrap();
    // Nothing has the name until the first whole group of rows.
    assert!(!path.exists());
    stream.commit().unwrap();
    // A long group of rows, part of which has reached the file.
    stream.write_all(&b"100,2\n".repeat(20_000)).unwrap();
    stream.write_all(b"200,").unwrap();
    assert!(std::fs::metadata(&path).unwrap().len() > 11);
    stream.rollback().unwrap();
    assert_eq!(std::fs::read(&path).unwrap(), b"step,x\n0,1\n");
    stream.write_all(b"100,2\n").unwrap();
    stream.finish().unwrap();
    assert_eq!(std::fs::read(&path).unwrap(), b"step,x\n0,1\n100,2\n");
}

#[test]
fn a_stream_over_an_existing_file_keeps_it_and_its_mode() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("WALLSREACTdata.out");
    std::fs::write(&path, "0 1\n").unwrap();
    std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o600)).unwrap();
    // Appending needs no --force: nothing in it is replaced.
    // Its other names do not count: appending parts none.
    std::fs::hard_link(&path, dir.path().join("other")).unwrap();
    let target = outputs(false)
        .folder(dir.path(), false)
        .unwrap()
        .plan_append(Path::new("WALLSREACTdata.out"))
        .unwrap();
    let mut stream = target.append().unwrap();
    stream.write_all(b"100 2\n").unwrap();
    stream.commit().unwrap();
    stream.write_all(b"200").unwrap();
    stream.rollback().unwrap();
    drop(stream);
    assert_eq!(std::fs::read(&path).unwrap(), b"0 1\n100 2\n");
    std::fs::remove_file(dir.path().join("other")).unwrap();
    // Replaced from empty: the old file stays as it was until the new one holds a whole
    // group of rows, which then takes its place with its mode. (The file planned before
    // the append has changed since: planned again.)
    assert_eq!(refusal(target.stream().unwrap_err()), Refusal::Changed);
    let mut stream = target_now(dir.path()).stream().unwrap();
    stream.write_all(b"5 3\n").unwrap();
    assert_eq!(std::fs::read(&path).unwrap(), b"0 1\n100 2\n");
    stream.commit().unwrap();
    assert_eq!(std::fs::read(&path).unwrap(), b"5 3\n");
    stream.write_all(b"6 4\n").unwrap();
    stream.finish().unwrap();
    assert_eq!(std::fs::read(&path).unwrap(), b"5 3\n6 4\n");
    assert_eq!(std::fs::metadata(&path).unwrap().mode() & 0o7777, 0o600);
    // One that fails before its first mark leaves the old file.
    let mut stream = target_now(dir.path()).stream().unwrap();
    stream.write_all(b"7").unwrap();
    stream.rollback().unwrap();
    drop(stream);
    assert_eq!(std::fs::read(&path).unwrap(), b"5 3\n6 4\n");
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
}

/// The WALLSREACT file in `dir`, planned again as it is now.
fn target_now(dir: &Path) -> walls_output::Target {
    outputs(true)
        .folder(dir, false)
        .unwrap()
        .plan(Path::new("WALLSREACTdata.out"))
        .unwrap()
}

#[test]
fn the_messages_name_the_file_and_what_to_do() {
    let e = WriteError::Refused(Refusal::Exists);
    assert_eq!(
        e.message("out.walls", Tool::MESH),
        "not writing out.walls: it exists: pass --force to replace it"
    );
    let e = WriteError::Refused(Refusal::Input);
    assert_eq!(
        e.message("ss.00010", Tool::RUN),
        "not writing ss.00010: walls-sim run reads it: an output never replaces one of the \
         command's inputs"
    );
    let e = WriteError::Refused(Refusal::NotRegular {
        kind: FileKind::Fifo,
    });
    assert_eq!(
        e.message("a.walls", Tool::FORMAT),
        "not writing a.walls: it is a FIFO (named pipe), not a regular file"
    );
}
