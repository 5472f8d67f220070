//! A pkdgrav build: the compile options its `Makefile.in` turns on (`DEM`,
//! `DEM_COHESION`, …), which decide the `.par` keys pkdgrav registers
//! (docs/pkdgrav-physics.md §18) and the start-up checks it makes (§19).
//!
//! A build is named as `walls-sim --pkdgrav-build` names it: option names separated by
//! spaces or commas, with or without pkdgrav's `USE_` prefix. `WALLS` and `COLLISIONS`
//! are always on (walls files are read only by such builds, and pkdgrav's Makefile turns
//! `COLLISIONS` on with `WALLS` or `DEM`). The default, [`DEFAULT`], is pkdgrav's default
//! granular build with walls.

use std::collections::BTreeSet;
use std::fmt;

/// The default build: pkdgrav's default soft-sphere options, with walls (its
/// `Makefile.in` also turns on `SLIDING_PATCH`, which it forbids with `WALLS`).
pub const DEFAULT: &str = "DEM DEM_FIXED_BALL DEM_ROTATION_DASHPOT";

/// Every compile option pkdgrav's `.par` keys or start-up checks depend on
/// (docs/pkdgrav-physics.md §18, §19), and those of the wall physics.
pub const OPTIONS: &[&str] = &[
    "AGGS",
    "BENCHMARK",
    "CHANGESOFT",
    "CHARGE",
    "COLLISIONS",
    "COLLMOD_ZML",
    "DEM",
    "DEM_COHESION",
    "DEM_FIXED_BALL",
    "DEM_ROTATION_DASHPOT",
    "DEM_TRACK_ORIENT",
    "DEM_TWOLAYERS",
    "DEM_WALLS_REACT",
    "GASOLINE",
    "GLASS",
    "NUMREC",
    "ROT_FRAME",
    "RUBBLE_ZML",
    "SIMPLESF",
    "SIMPLE_GAS_DRAG",
    "SLIDING_PATCH",
    "SPECIAL_PARTICLES",
    "SPINUP",
    "SPINUP_WITH_AGGS",
    "SPRINGS",
    "STARFORM",
    "TRAP_FPE",
    "WALLS",
];

/// The options every build here has: walls files are read only with `WALLS`, which
/// pkdgrav's Makefile builds with `COLLISIONS`.
const ALWAYS: [&str; 2] = ["COLLISIONS", "WALLS"];

/// A pkdgrav build: the set of its compile options.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Build {
    options: BTreeSet<&'static str>,
}

impl Default for Build {
    /// [`DEFAULT`].
    fn default() -> Build {
        Build::parse(DEFAULT).expect("the default build parses")
    }
}

/// A compile option name pkdgrav does not have.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UnknownOption {
    /// The name as given.
    pub name: String,
    /// The nearest option, if one is near.
    pub suggestion: Option<&'static str>,
}

impl fmt::Display for UnknownOption {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.name.trim_start_matches("USE_") == "SLIDING_PATCH" {
            return write!(
                f,
                "`{}`: pkdgrav's Makefile does not build SLIDING_PATCH with WALLS, which a build that reads walls files has",
                self.name
            );
        }
        write!(f, "unknown pkdgrav compile option `{}`", self.name)?;
        match self.suggestion {
            Some(s) => write!(f, ", did you mean `{s}`?"),
            None => write!(f, " (known: {})", OPTIONS.join(", ")),
        }
    }
}

impl std::error::Error for UnknownOption {}

impl Build {
    /// The build `text` names: option names separated by spaces or commas, with or
    /// without `USE_`, plus `WALLS` and `COLLISIONS`.
    pub fn parse(text: &str) -> Result<Build, UnknownOption> {
        let mut options: BTreeSet<&'static str> = ALWAYS.into_iter().collect();
        for word in text
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|w| !w.is_empty())
        {
            let name = word.strip_prefix("USE_").unwrap_or(word);
            let Some(&known) = OPTIONS.iter().find(|&&o| o == name) else {
                return Err(UnknownOption {
                    name: word.to_string(),
                    suggestion: nearest(name),
                });
            };
            // pkdgrav's Makefile refuses it with WALLS, which every build here has.
            if known == "SLIDING_PATCH" {
                return Err(UnknownOption {
                    name: word.to_string(),
                    suggestion: None,
                });
            }
            options.insert(known);
        }
        Ok(Build { options })
    }

    /// Whether the build has `option`.
    pub fn has(&self, option: &str) -> bool {
        self.options.contains(option)
    }

    /// The options, space separated, in name order.
    pub fn names(&self) -> String {
        self.options.iter().copied().collect::<Vec<_>>().join(" ")
    }

    /// Whether `condition` holds in this build: `always`, or options joined by `&&`,
    /// each optionally negated with `!` (par_keys.md's conditions, pkdgrav's nested
    /// `#ifdef`s).
    ///
    /// # Panics
    /// If `condition` names an option outside [`OPTIONS`] (the tables are checked by a
    /// test).
    pub fn meets(&self, condition: &str) -> bool {
        if condition == "always" || condition == "—" {
            return true;
        }
        condition.split("&&").map(str::trim).all(|term| {
            let (negated, name) = match term.strip_prefix('!') {
                Some(name) => (true, name),
                None => (false, term),
            };
            assert!(
                OPTIONS.contains(&name),
                "unknown option `{name}` in `{condition}`"
            );
            self.has(name) != negated
        })
    }
}

/// The option nearest to `name`: the same letters in another case, or a few off.
fn nearest(name: &str) -> Option<&'static str> {
    crate::nearest(name, OPTIONS.iter().copied())
}

/// A build with every option but `SLIDING_PATCH`, for the tables' tests.
#[cfg(test)]
pub(crate) fn every_build() -> Build {
    Build {
        options: OPTIONS
            .iter()
            .copied()
            .filter(|&o| o != "SLIDING_PATCH")
            .collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn builds_are_read_with_or_without_use_and_always_have_walls() {
        let b = Build::parse("USE_DEM, DEM_COHESION").unwrap();
        assert_eq!(b.names(), "COLLISIONS DEM DEM_COHESION WALLS");
        assert_eq!(
            Build::default().names(),
            "COLLISIONS DEM DEM_FIXED_BALL DEM_ROTATION_DASHPOT WALLS"
        );
        assert!(b.meets("DEM && DEM_COHESION") && b.meets("always") && b.meets("!GASOLINE"));
        assert!(!b.meets("DEM && DEM_TWOLAYERS") && !b.meets("COLLISIONS && !DEM"));
        let e = Build::parse("DEM dem_cohesoin").unwrap_err();
        assert_eq!(
            e.to_string(),
            "unknown pkdgrav compile option `dem_cohesoin`, did you mean `DEM_COHESION`?"
        );
    }
}
