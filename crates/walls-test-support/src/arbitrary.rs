//! Random walls files for property tests: statements of any keyword with values of
//! its shape (mostly), numbers from ordinary to extreme (zero, negative, subnormal,
//! overflowing).

use proptest::prelude::*;
use walls_keywords::{Keyword, ValueShape, WallType};

/// Numbers from ordinary to extreme: zero, negative, subnormal, overflowing.
fn number() -> impl Strategy<Value = String> {
    prop_oneof![
        "[-+]?[0-9]{1,3}(\\.[0-9]{1,3})?",
        prop::sample::select(vec![
            "0", "-0", "1e308", "-1e308", "1e-320", "4.9e-324", "1e999", "99", "-1", "1e-300",
        ])
        .prop_map(str::to_string),
    ]
}

/// Statements with values of the right shape (mostly), units and blocks.
fn statement() -> impl Strategy<Value = String> {
    (
        prop::sample::select(Keyword::ALL.to_vec()),
        prop::collection::vec(number(), 3),
        0..7usize,
    )
        .prop_map(|(k, nums, t)| {
            let value = match k.shape() {
                ValueShape::None => String::new(),
                ValueShape::Number => nums[0].clone(),
                ValueShape::Integer => nums[0].split(['.', 'e']).next().unwrap_or("0").to_string(),
                ValueShape::Vector => nums.join(" "),
                ValueShape::TypeName => WallType::ALL[t].name().to_string(),
            };
            format!("{} {value}\n", k.name())
        })
}

/// Walls files of up to 40 statements: any keyword, values mostly of its shape.
pub fn walls_file() -> impl Strategy<Value = String> {
    prop::collection::vec(statement(), 0..40).prop_map(|v| v.concat())
}

/// The keywords whose values reach the rules that carry fixes, each with values that
/// trigger them and values that do not.
const FIXABLE: &[(&str, &[&str])] = &[
    ("type", &[]),
    ("osc-ampl", &["0.1", "-0.1", "0", "0.05", "2"]),
    ("osc-freq", &["-2", "2", "-0.5", "3", "0"]),
    ("osc-phase", &["0.25", "0", "0.75", "0.5"]),
    ("osc-vec", &["0 0 1", "1 0 0", "0 2 0"]),
    ("orient", &["0 0 1", "1 0 0", "0 1 1", "0 0 -1", "3 0 4"]),
    (
        "vertex1",
        &["1 0 0", "0.6 0.6 0", "0 1 0", "2 0 0", "1 1 0"],
    ),
    (
        "vertex2",
        &[
            "0 1 0",
            "0.6 -0.5 0",
            "1 0 0",
            "-3 0 0",
            "0 0 2",
            "1 0.01 0",
        ],
    ),
    ("mass", &["0", "1", "2", "0.5"]),
    ("assembly", &["-1", "0", "1"]),
    ("radius", &["0.5", "1", "2", "0"]),
    ("hole-radius", &["0", "0.2", "3"]),
    ("length", &["1", "2"]),
    ("taper", &["0", "0.5", "1"]),
    ("open-angle", &["0", "30", "90"]),
    ("ang-speed", &["0", "1", "-2"]),
    ("velocity", &["0 0 0", "1 0 0", "0 0 -1"]),
    ("pxj-vec", &["1 0 0", "2 0 0", "0 0.5 0", "0.6 0.8 0"]),
    ("pyj-vec", &["0 1 0", "0 3 0", "1 0 0"]),
    ("pzj-vec", &["0 0 1", "0 0 0.9", "0 1 0"]),
    ("k_n", &["-1", "100", "2"]),
    ("k_t", &["-1", "10"]),
    ("color", &["0", "3", "223"]),
    ("origin", &["0 0 0", "1 2 3", "0 0 0.5"]),
    ("step", &["0", "0.1"]),
    ("epsn", &["0.5", "99", "1"]),
    ("transparency", &["0", "0.5"]),
];

/// Misspellings of keywords (S101 with one suggestion) and of wall types (S106).
const MISSPELLED: &[&str] = &[
    "raduis",
    "radus",
    "orinet",
    "osc_ampl",
    "osc-frq",
    "colour",
    "mas",
    "assembyl",
    "vertex_1",
    "tpye",
    "origni",
    "wal",
    "defualts",
    "lenghtunit",
    "veloicty",
];
const MISSPELLED_TYPES: &[&str] = &[
    "dsk",
    "plan",
    "trangle",
    "shel",
    "cylinder_finite",
    "rectngle",
];

/// Codes a suppression comment may name: used, unused, unknown, errors.
const SUPPRESSED: &[&str] = &[
    "C201", "C202", "C207", "C113", "C205", "C106", "C304", "M001", "S101", "C299",
];

/// One statement of a generated block, with the mistakes it is written with.
#[derive(Debug, Clone)]
struct Stmt {
    keyword: &'static str,
    value: String,
    /// 0: as written; 1: keyword misspelled; 2: type misspelled; 3: `type` dropped
    /// before a type name; 4: bare `type`.
    mistake: u8,
    /// The values on the next line (S107).
    split: bool,
    /// A comment glued to the last value (S004).
    glued: bool,
    /// A suppression comment after it, naming this code (L003).
    suppress: Option<&'static str>,
}

/// Keywords that meet in the fixing rules: motion (C113, C205; a tilted wall that
/// oscillates), rectangles (C106),
/// reactive walls (C304, C306).
const MOTION: &[&str] = &[
    "type",
    "orient",
    "osc-ampl",
    "osc-freq",
    "osc-phase",
    "osc-vec",
    "ang-speed",
];
const OSCILLATING: &[&str] = &["orient", "osc-ampl", "osc-freq", "osc-phase"];
const RECTANGLE: &[&str] = &["vertex1", "vertex2", "origin", "vertex2"];
const REACTIVE: &[&str] = &[
    "mass", "assembly", "pxj-vec", "pyj-vec", "pzj-vec", "type", "mass",
];

/// A statement of any of `FIXABLE`'s keywords (`among` empty), or of those named.
fn stmt(among: &'static [&'static str]) -> impl Strategy<Value = Stmt> {
    let pool: Vec<usize> = if among.is_empty() {
        (0..FIXABLE.len()).collect()
    } else {
        among
            .iter()
            .filter_map(|k| FIXABLE.iter().position(|(name, _)| name == k))
            .collect()
    };
    (
        prop::sample::select(pool),
        0..8usize,
        prop::sample::select(WallType::SPELLINGS.iter().map(|s| s.0).collect::<Vec<_>>()),
        prop_oneof![30 => Just(0u8), 1 => Just(1), 1 => Just(2), 1 => Just(3), 1 => Just(4)],
        prop::bool::weighted(0.04),
        prop::bool::weighted(0.04),
        prop::option::weighted(0.05, prop::sample::select(SUPPRESSED.to_vec())),
        number(),
    )
        .prop_map(|(k, v, type_name, mistake, split, glued, suppress, any)| {
            let (keyword, values) = FIXABLE[k];
            let value = if keyword == "type" {
                type_name.to_string()
            } else if v < 6 || values[0].contains(' ') {
                values[v % values.len()].to_string()
            } else {
                any
            };
            Stmt {
                keyword,
                value,
                mistake,
                split,
                glued,
                suppress,
            }
        })
}

/// A block: `wall` or `defaults` with its statements (a rectangle's with `type
/// rectangle` first), or a general token.
#[derive(Debug, Clone)]
enum Part {
    Block(bool, Vec<Stmt>),
    Rectangle(Vec<Stmt>),
    General(&'static str, &'static str),
}

fn block(
    among: &'static [&'static str],
    walls: f64,
    size: std::ops::Range<usize>,
) -> impl Strategy<Value = Part> {
    (
        prop::bool::weighted(walls),
        prop::collection::vec(stmt(among), size),
    )
        .prop_map(|(wall, s)| Part::Block(wall, s))
}

fn part() -> impl Strategy<Value = Part> {
    prop_oneof![
        5 => block(&[], 0.8, 0..7),
        3 => block(MOTION, 0.7, 0..7),
        2 => block(OSCILLATING, 0.95, 3..6),
        2 => block(REACTIVE, 0.7, 0..7),
        1 => prop::collection::vec(stmt(RECTANGLE), 1..4).prop_map(Part::Rectangle),
        1 => prop::sample::select(vec![
            ("lengthunit", "2"), ("lengthunit", "0.5"), ("timeunit", "3"), ("massunit", "2"), ("time", "1"),
        ])
        .prop_map(|(k, v)| Part::General(k, v)),
    ]
}

fn write_stmt(out: &mut String, s: &Stmt, pick: usize) {
    let keyword = match s.mistake {
        1 => MISSPELLED[pick % MISSPELLED.len()],
        _ => s.keyword,
    };
    let value = match (s.keyword, s.mistake) {
        ("type", 2) => MISSPELLED_TYPES[pick % MISSPELLED_TYPES.len()].to_string(),
        _ => s.value.clone(),
    };
    match (s.keyword, s.mistake) {
        ("type", 3) => out.push_str(&value),
        ("type", 4) => out.push_str("type"),
        _ => {
            out.push_str(keyword);
            out.push_str(if s.split { "\n    " } else { " " });
            out.push_str(&value);
        }
    }
    if s.glued {
        out.push_str("#glued");
    }
    if let Some(code) = s.suppress {
        out.push_str("  # walls-lint: ignore ");
        out.push_str(code);
    }
}

/// Walls files that carry the diagnostics with fixes: blocks of the keywords the fixing
/// rules judge (negative frequencies, tilted oscillating walls, skewed rectangles, axes
/// that are not unit, masses without assemblies, tokens a type ignores or a block
/// repeats, defaults no wall inherits), with mistakes made on purpose: misspelled
/// keywords and types, type names without `type`, bare `type`, values on the next line,
/// glued comments, suppression comments, a byte-order mark, no final newline.
pub fn fixable_file() -> impl Strategy<Value = String> {
    (
        prop::collection::vec(part(), 1..8),
        prop::collection::vec(any::<usize>(), 8),
        prop::bool::weighted(0.05),
        prop::bool::weighted(0.1),
        prop::bool::weighted(0.3),
    )
        .prop_map(|(parts, picks, bom, no_newline, one_line)| {
            let mut out = String::new();
            if bom {
                out.push('\u{feff}');
            }
            let mut n = 0;
            // A comment (a suppression, or one glued to a value) runs to the end of its
            // line: the next statement starts a line.
            let mut commented = false;
            for part in &parts {
                match part {
                    Part::General(k, v) => {
                        out.push_str(&format!("{k} {v}\n"));
                    }
                    Part::Rectangle(stmts) | Part::Block(_, stmts) => {
                        match part {
                            Part::Rectangle(_) => out.push_str("wall type rectangle"),
                            Part::Block(true, _) => out.push_str("wall"),
                            _ => out.push_str("defaults"),
                        }
                        for (i, s) in stmts.iter().enumerate() {
                            // Some blocks on one line, the first statement on the head's.
                            let same_line = (one_line || i == 0 && s.keyword == "type")
                                && !commented
                                && !s.split;
                            // Now and then a vertical tab or a form feed between words,
                            // which pkdgrav reads as a space (S006's fix).
                            let space = match picks[n % picks.len()] % 11 {
                                0 => "\u{b}",
                                1 => "\u{c}",
                                _ => " ",
                            };
                            out.push_str(if same_line { space } else { "\n  " });
                            write_stmt(&mut out, s, picks[n % picks.len()].wrapping_add(n));
                            commented = s.suppress.is_some() || s.glued;
                            n += 1;
                        }
                        out.push('\n');
                        commented = false;
                    }
                }
            }
            if no_newline {
                out.pop();
            }
            out
        })
}
