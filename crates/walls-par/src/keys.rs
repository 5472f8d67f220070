//! The keys pkdgrav registers, with their types, defaults and the compile options each
//! needs: `data/par_keys.md`, a copy of the reference's table (docs/pkdgrav-physics.md
//! §18), read once. A key may be registered twice under exclusive conditions
//! (`achOutName`: `GASOLINE`, `!GASOLINE`); a build registers a name if one of its rows'
//! conditions holds.

use crate::options::Build;
use std::sync::LazyLock;

/// The type pkdgrav registers a key with, which decides how its value is read
/// (docs/pkdgrav-physics.md §14).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// A switch, read as an integer (any value but 0 is on).
    Bool,
    /// An integer, read as C's `%d` reads one.
    Int,
    /// A double, read as C's `%lf` reads one.
    Double,
    /// A string, to the end of the line or the first `#`.
    Str,
}

impl Kind {
    /// The name par_keys.md and the documentation use.
    pub const fn as_str(self) -> &'static str {
        match self {
            Kind::Bool => "bool",
            Kind::Int => "int",
            Kind::Double => "double",
            Kind::Str => "string",
        }
    }
}

/// One registration of a key.
#[derive(Debug, Clone, PartialEq)]
pub struct Key {
    /// The name, case-sensitive.
    pub name: &'static str,
    /// Its type.
    pub kind: Kind,
    /// The default as the table writes it (with notes on what pkdgrav changes after
    /// reading, `post-parse: …`).
    pub default: &'static str,
    /// The compile options it needs: `always`, or options joined by `&&`, each perhaps
    /// negated with `!`.
    pub condition: &'static str,
}

impl Key {
    /// The default as a number, where the table gives one (`BOUNCE (=2)` is 2, `5.0/3.0`
    /// is its quotient); `None` for a string or a default the table does not give.
    pub fn default_value(&self) -> Option<f64> {
        let text = self.default;
        // `BOUNCE (=2)`, `= dTheta at registration (0.8)`: the number in parentheses.
        if let Some(at) =
            (text.find("(=")).or_else(|| text.find("at registration (").map(|k| k + 16))
        {
            let inner = text[at..].trim_start_matches([' ', '(', '=']);
            let end = inner.find(')').unwrap_or(inner.len());
            if let Some(x) = number(&inner[..end]) {
                return Some(x);
            }
        }
        let head = text.split([';', '[']).next().unwrap_or("").trim();
        number(head)
    }
}

/// A number as the table writes one: a decimal, or a quotient `a/b`.
fn number(text: &str) -> Option<f64> {
    let text = text.trim();
    if let Some((a, b)) = text.split_once('/') {
        return Some(a.trim().parse::<f64>().ok()? / b.trim().parse::<f64>().ok()?);
    }
    text.parse().ok()
}

static TABLE: LazyLock<Vec<Key>> = LazyLock::new(|| read(include_str!("../data/par_keys.md")));

/// The rows of par_keys.md's table: `name | type | default | condition`.
fn read(text: &'static str) -> Vec<Key> {
    text.lines()
        .filter_map(|line| {
            let cells: Vec<&'static str> = line.split(" | ").map(str::trim).collect();
            let [name, kind, default, condition] = cells[..] else {
                return None;
            };
            let kind = match kind {
                "bool" => Kind::Bool,
                "int" => Kind::Int,
                "double" => Kind::Double,
                "string" => Kind::Str,
                _ => return None,
            };
            Some(Key {
                name,
                kind,
                default,
                condition,
            })
        })
        .collect()
}

/// Every registration pkdgrav makes, in its order.
pub fn all() -> &'static [Key] {
    &TABLE
}

/// The registration of `name` that `build` makes, if it makes one.
pub fn registered(name: &str, build: &Build) -> Option<&'static Key> {
    all()
        .iter()
        .find(|k| k.name == name && build.meets(k.condition))
}

/// Every registration of `name`, in any build.
pub fn any(name: &str) -> impl Iterator<Item = &'static Key> + '_ {
    all().iter().filter(move |k| k.name == name)
}

/// The key `build` registers nearest to `name`, if one is near enough to be a slip: the
/// same letters in another case, or a few letters off.
pub fn nearest(name: &str, build: &Build) -> Option<&'static str> {
    let registered = all().iter().filter(|k| build.meets(k.condition));
    crate::nearest(name, registered.map(|k| k.name))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_is_read_whole_and_its_conditions_name_known_options() {
        // 368 rows, 359 names (§18).
        assert_eq!(all().len(), 368);
        let mut names: Vec<_> = all().iter().map(|k| k.name).collect();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), 359);
        let every = crate::options::every_build();
        for k in all() {
            // Panics on an option the table names that OPTIONS lacks.
            let _ = every.meets(k.condition);
        }
    }

    #[test]
    fn the_golden_scenes_build_registers_217_keys() {
        let b = Build::parse(
            "COLLISIONS WALLS DEM DEM_FIXED_BALL DEM_ROTATION_DASHPOT DEM_TRACK_ORIENT NUMREC",
        )
        .unwrap();
        let mut names: Vec<_> = all()
            .iter()
            .filter(|k| b.meets(k.condition))
            .map(|k| k.name)
            .collect();
        names.dedup();
        assert_eq!(names.len(), 217);
    }

    #[test]
    fn defaults_are_read_as_numbers_where_the_table_gives_one() {
        let b = Build::default();
        let default = |n: &str| registered(n, &b).unwrap().default_value();
        assert_eq!(default("iCheckInterval"), Some(10.0));
        assert_eq!(default("iForceOverrideOption"), Some(0.0));
        assert_eq!(default("dMinorFrac"), Some(0.03));
        assert_eq!(default("dKt"), Some(-1.0));
        assert_eq!(default("iOutcomes"), Some(2.0));
        assert_eq!(default("achInFile"), None);
        assert_eq!(nearest("nstep", &b), Some("nSteps"));
        assert_eq!(nearest("dKnInner", &b), None);
    }
}
