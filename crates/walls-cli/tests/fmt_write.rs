//! `walls-fmt` writes in place by renaming a complete temporary file over the original
//! (a new inode), keeps the original's permissions, leaves no temporary file behind, and
//! does not touch files that are already formatted; a symbolic link is followed.

#![cfg(unix)]

use std::os::unix::fs::{MetadataExt, PermissionsExt};
use std::process::Command;

#[test]
fn rewrites_by_rename_keeping_permissions() {
    let dir = tempfile::tempdir().unwrap();
    let messy = dir.path().join("messy.walls");
    let clean = dir.path().join("clean.walls");
    std::fs::write(&messy, "WALL TYPE plane,origin=0,0,1\n").unwrap();
    std::fs::write(&clean, "wall type plane\n").unwrap();
    std::fs::set_permissions(&messy, std::fs::Permissions::from_mode(0o640)).unwrap();
    let (messy_inode, clean_inode) = (
        std::fs::metadata(&messy).unwrap().ino(),
        std::fs::metadata(&clean).unwrap().ino(),
    );
    let status = Command::new(env!("CARGO_BIN_EXE_walls-fmt"))
        .arg(&messy)
        .arg(&clean)
        .status()
        .unwrap();
    assert!(status.success());
    assert_eq!(
        std::fs::read_to_string(&messy).unwrap(),
        "wall type plane\n  origin 0 0 1\n"
    );
    let meta = std::fs::metadata(&messy).unwrap();
    assert_ne!(
        meta.ino(),
        messy_inode,
        "written by renaming a new file over it"
    );
    assert_eq!(meta.permissions().mode() & 0o777, 0o640);
    assert_eq!(
        std::fs::metadata(&clean).unwrap().ino(),
        clean_inode,
        "untouched"
    );
    let left: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(left.len(), 2, "no temporary file left: {left:?}");
}

#[test]
fn a_symbolic_link_stays_a_link() {
    let dir = tempfile::tempdir().unwrap();
    let target = dir.path().join("real.walls");
    let link = dir.path().join("link.walls");
    std::fs::write(&target, "WALL type plane\n").unwrap();
    std::os::unix::fs::symlink(&target, &link).unwrap();
    let status = Command::new(env!("CARGO_BIN_EXE_walls-fmt"))
        .arg(&link)
        .status()
        .unwrap();
    assert!(status.success());
    assert!(
        std::fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink()
    );
    assert_eq!(
        std::fs::read_to_string(&target).unwrap(),
        "wall type plane\n"
    );
}
