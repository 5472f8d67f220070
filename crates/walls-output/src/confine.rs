//! Paths read from files, followed only inside the folder they must stay in: a `.par`
//! file's `achWallsFile` when `walls-lint` walks a folder, `achOutName` under
//! `walls-sim run --out`. A path that leaves ([`Leaves`]) is reported where it was read,
//! and not followed.

use std::path::{Component, Path, PathBuf};

/// How a path read from a file leaves the folder it must stay in.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Leaves {
    /// It is absolute.
    Absolute,
    /// Its `..` climb above the folder.
    Up,
    /// A symbolic link on the way leads out, to `to`.
    Link {
        /// Where the path leads, every link followed.
        to: PathBuf,
    },
}

impl std::fmt::Display for Leaves {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Leaves::Absolute => f.write_str("it is absolute"),
            Leaves::Up => f.write_str("its `..` climb out"),
            Leaves::Link { to } => write!(f, "a symbolic link leads it out, to {}", to.display()),
        }
    }
}

/// `name`, read in a file in the folder `base`, as a path from here, when it stays in
/// `root` (`base` or a folder above it): relative, its `..` never climbing above `root`,
/// and, where it exists, no symbolic link on the way leading out of `root`.
pub fn within(root: &Path, base: &Path, name: &Path) -> Result<PathBuf, Leaves> {
    if name.has_root() {
        return Err(Leaves::Absolute);
    }
    // How deep below `root` the path is, component by component, starting at `base`.
    let mut depth = depth_below(root, base).ok_or(Leaves::Up)?;
    for c in name.components() {
        match c {
            Component::Normal(_) => depth += 1,
            Component::ParentDir if depth == 0 => return Err(Leaves::Up),
            Component::ParentDir => depth -= 1,
            Component::CurDir => {}
            Component::RootDir | Component::Prefix(_) => return Err(Leaves::Absolute),
        }
    }
    let path = base.join(name);
    if let (Ok(real), Ok(real_root)) = (std::fs::canonicalize(&path), std::fs::canonicalize(root))
        && !real.starts_with(&real_root)
    {
        return Err(Leaves::Link { to: real });
    }
    Ok(path)
}

/// How many folders `base` is below `root`, by their names (`None` when it is not).
fn depth_below(root: &Path, base: &Path) -> Option<usize> {
    let rest = base.strip_prefix(root).ok()?;
    let mut depth = 0usize;
    for c in rest.components() {
        match c {
            Component::Normal(_) => depth += 1,
            Component::ParentDir => depth = depth.checked_sub(1)?,
            Component::CurDir => {}
            Component::RootDir | Component::Prefix(_) => return None,
        }
    }
    Some(depth)
}
