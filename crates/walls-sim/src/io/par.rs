//! pkdgrav parameter files (`.par`): `name = value  # comment` lines, read as pkdgrav
//! reads them (docs/pkdgrav-physics.md §3–4): the input and walls files, the
//! timestep, the first and last step numbers and the output interval, the particles'
//! material with pkdgrav's sentinels (`dKt = -1` is 2/7·`dKn`; the two-layer constants'
//! −1 fall back to `dKn` and 2/7 of it), cohesion, uniform gravity and edge detection;
//! the keys only an optional build follows ([`OPTIONAL_KEYS`], which `config` checks
//! against the run's build); and the range
//! each run parameter must lie in ([`Rule`]), whether it comes from a `.par` file or the
//! command line.
//!
//! Every key pkdgrav uses in wall runs has an entry in one table ([`KEYS`]): read, of
//! no effect on what the evaluator computes, modelled at one value only, or not modelled
//! yet. A line the evaluator does not follow (a key it does not model, a value it does
//! not model, a key it does not know, with a "did you mean") is a [`ParWarning`] naming
//! the key and the line, never silently ignored; so is leaving out a key whose pkdgrav
//! default the evaluator does not follow. Every error names the `.par` line.

pub use walls_par::KT_PER_KN;
pub use walls_par::evaluator::{KEYS, Use, use_of};
pub use walls_par::syntax::LINE_LIMIT;

use super::{FileError, InputError, error};
use crate::warning::Warning;
use nalgebra::Vector3;
use std::collections::HashMap;

type Vec3 = Vector3<f64>;

/// What the evaluator reads from a pkdgrav parameter file: `None` where the file does
/// not give the key (the run then takes the flag, pkdgrav's default or the evaluator's,
/// as `config` says).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Params {
    /// `achInFile`: the particle (.ss) file.
    pub in_file: Option<String>,
    /// `achWallsFile`: the walls file.
    pub walls_file: Option<String>,
    /// `achOutName`: the outputs' base name (pkdgrav's default `ss`).
    pub out_name: Option<String>,
    /// `nDigits`: the digits of the outputs' step numbers (pkdgrav's default 5).
    pub digits: Option<usize>,
    /// `dDelta`: the timestep.
    pub dt: Option<f64>,
    /// `nSteps`: the number of the last step (steps run from `iStartStep` + 1 to it).
    pub steps: Option<u64>,
    /// `iStartStep`: the number of the step the run starts after (pkdgrav's default 0);
    /// the run starts at time `iStartStep`·`dDelta`.
    pub start_step: Option<u64>,
    /// `iOutInterval`: outputs at the steps that are multiples of it, and at the last.
    pub out_interval: Option<u64>,
    /// `iRedOutInterval`: pkdgrav's reduced outputs, at `iStartStep` and every so many
    /// steps after it (0, the default: none), where it writes its reactive-wall lines
    /// (docs/pkdgrav-physics.md §10).
    pub red_out_interval: Option<u64>,
    /// `dEpsN`, `dEpsT`: the particles' coefficients of restitution.
    pub eps_n: Option<f64>,
    /// See `eps_n`.
    pub eps_t: Option<f64>,
    /// `dKn`: the particles' normal spring constant.
    pub k_n: Option<f64>,
    /// `dKt`: the particles' tangential spring constant; `None` when the file leaves it
    /// at (or writes) pkdgrav's −1, which means [`KT_PER_KN`] times the normal constant.
    pub k_t: Option<f64>,
    /// `dMuS`, `dMuR`, `dMuT`: the particles' friction coefficients.
    pub mu_s: Option<f64>,
    /// See `mu_s`.
    pub mu_r: Option<f64>,
    /// See `mu_s`.
    pub mu_t: Option<f64>,
    /// `dBetaS`: β_s of the rolling and twisting spring–dashpot–slider
    /// (docs/pkdgrav-physics.md §1.4); pkdgrav's default is
    /// [`walls_geometry::BETA_S_DEFAULT`].
    pub beta_s: Option<f64>,
    /// `dxUnifGrav`, `dyUnifGrav`, `dzUnifGrav`: uniform gravity (missing components 0).
    pub gravity: Option<Vec3>,
    /// `bWallsEdgeDetect`: HSDEM edge detection (pkdgrav's default is on).
    pub edge_detect: Option<bool>,
    /// `bUseContactRadius`: the rolling and twisting radius is the contact radius
    /// (docs/pkdgrav-physics.md §1.4; `Integrator::Pkdgrav` follows it).
    pub contact_radius: Option<bool>,
    /// `bUseLegacyRoll`: the non-dashpot rolling lever is l₁, l₂ (d against a wall)
    /// (docs/pkdgrav-physics.md §1.6).
    pub legacy_roll: Option<bool>,
    /// `bDoGravity`: with 0, pkdgrav evaluates no forces at all: no uniform gravity,
    /// no contacts (docs/pkdgrav-physics.md §2).
    pub do_gravity: Option<bool>,
    /// `dAccCrit`: below it, small motions are zeroed (docs/pkdgrav-physics.md §1.7; 0,
    /// the default, turns it off).
    pub acc_crit: Option<f64>,
    /// `dMinorFrac`, `dMajorFrac`, `dErrorFrac`: pkdgrav's overlap levels
    /// (docs/pkdgrav-physics.md §15), each `None` where the file leaves it at pkdgrav's
    /// default (0.03, 0.15, 0.5); together, with the defaults, 0 ≤ minor ≤ major ≤ error.
    pub overlap_fracs: [Option<f64>; 3],
    /// The two-layer contact constants (`DEM_TWOLAYERS`), resolved, when the file gives
    /// any of them.
    pub two_layer: Option<TwoLayer>,
    /// Cohesion's keys (`DEM_COHESION`).
    pub cohesion: CohesionKeys,
    /// The lines of keys that only a build with an optional compile option follows
    /// (cohesion's, two-layer contacts'), in line order: `config` warns about those the
    /// run's build lacks.
    pub optional_keys: Vec<OptionalKey>,
    /// What the evaluator does not follow, in line order.
    pub warnings: Vec<ParWarning>,
    /// The line of each path the file gives ([`PATH_KEYS`]), for the messages about it.
    pub path_lines: Vec<(&'static str, usize)>,
    /// The subnormal numbers of the file's reals (W701), in line order, located in the
    /// file (`line 4: \`dDelta\``; [`read_file`] puts the file's path before).
    pub subnormals: Vec<Warning>,
}

/// The keys whose values are paths: files the run reads or writes.
pub const PATH_KEYS: [&str; 4] = ["achInFile", "achWallsFile", "achOutName", "achCohesionFile"];

impl Params {
    /// The line of the path key `key` ([`PATH_KEYS`]), if the file gives it.
    pub fn line_of(&self, key: &str) -> Option<usize> {
        self.path_lines
            .iter()
            .find_map(|&(k, n)| (k == key).then_some(n))
    }
}

/// pkdgrav's two-layer contact constants (docs/pkdgrav-physics.md §8), with its sentinels
/// resolved: `dKnOuter`, `dKnInner` = −1 are `dKn`; `dKtOuter`, `dKtInner` = −1 are
/// [`KT_PER_KN`] of their normal constant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TwoLayer {
    /// `dInnerOverlapBndry`: the boundary as a fraction of the radius.
    pub boundary: f64,
    /// `dKnOuter`.
    pub k_n_outer: f64,
    /// `dKtOuter`.
    pub k_t_outer: f64,
    /// `dKnInner`.
    pub k_n_inner: f64,
    /// `dKtInner`.
    pub k_t_inner: f64,
}

/// Cohesion's keys (`DEM_COHESION`), each `None` where the file leaves it out.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct CohesionKeys {
    /// `iCohesionModel`: 0 microscopic contact, 1 granular bridge.
    pub model: Option<i64>,
    /// `dCohesiveCoeff`, in raw pkdgrav units of stress.
    pub coefficient: Option<f64>,
    /// `achCohesionFile`: the per-colour coefficients, relative to the `.par` file's
    /// folder; `None` when absent or empty.
    pub file: Option<String>,
}

/// A `.par` line whose key only a pkdgrav build with `option` follows.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct OptionalKey {
    /// The line, 1-based.
    pub line: usize,
    /// The key.
    pub key: &'static str,
    /// The compile option (`DEM_COHESION`, `DEM_TWOLAYERS`).
    pub option: &'static str,
}

/// The `.par` keys of pkdgrav's optional builds, with the compile option each needs
/// (docs/pkdgrav-physics.md §4, §7, §8).
pub const OPTIONAL_KEYS: &[(&str, &str)] = &[
    ("iCohesionModel", "DEM_COHESION"),
    ("dCohesiveCoeff", "DEM_COHESION"),
    ("achCohesionFile", "DEM_COHESION"),
    ("dInnerOverlapBndry", "DEM_TWOLAYERS"),
    ("dKnOuter", "DEM_TWOLAYERS"),
    ("dKtOuter", "DEM_TWOLAYERS"),
    ("dKnInner", "DEM_TWOLAYERS"),
    ("dKtInner", "DEM_TWOLAYERS"),
];

/// A `.par` line (or a key left out) that the evaluator does not follow as pkdgrav would.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ParWarning {
    /// The line, 1-based; `None` for a key the file leaves out.
    pub line: Option<usize>,
    /// The key.
    pub key: String,
    /// What pkdgrav does, and what the evaluator does instead.
    pub message: String,
}

impl std::fmt::Display for ParWarning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.line {
            Some(n) => write!(f, "line {n}: `{}`: {}", self.key, self.message),
            None => write!(f, "`{}` not given: {}", self.key, self.message),
        }
    }
}

/// The integer keys the run reads as counts: a value that is not a whole number is an
/// error ([`Lines::count`]), not pkdgrav's `%d` reading.
const COUNTS: [&str; 5] = [
    "nSteps",
    "iStartStep",
    "iOutInterval",
    "iRedOutInterval",
    "nDigits",
];

/// The most digits `nDigits` may ask for: a 64-bit step number has at most 20.
pub const MAX_DIGITS: usize = 20;

/// The known key nearest to the unknown `key`, if one is near enough to be a slip: the
/// same letters in another case, or a few letters off.
pub fn suggestion(key: &str) -> Option<&'static str> {
    walls_par::nearest(key, KEYS.iter().map(|&(k, _)| k))
}

/// The range a run parameter must lie in, whether it comes from a `.par` file or the
/// command line: a zero or negative timestep would never end, a negative spring would
/// make the timestep NaN.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rule {
    /// Any finite number (gravity).
    Any,
    /// Greater than 0 (timestep, k_n, duration).
    Positive,
    /// 0 or more (k_t, friction).
    NonNegative,
    /// Normal restitution: above 0, at most 1.
    Restitution,
    /// Tangential restitution: −1 to 1.
    Tangential,
    /// An allowed overlap as a fraction of the radius: above 0, below 0.5 (pkdgrav stops
    /// at half the radius).
    Overlap,
    /// A fraction such as a packing fraction: above 0, at most 1.
    Fraction,
}

impl Rule {
    /// `x` if it obeys the rule, else what the rule asks for.
    pub fn check(self, x: f64) -> Result<f64, &'static str> {
        if !x.is_finite() {
            return Err("a finite number");
        }
        let (ok, says) = match self {
            Rule::Any => (true, ""),
            Rule::Positive => (x > 0.0, "greater than 0"),
            Rule::NonNegative => (x >= 0.0, "0 or more"),
            Rule::Restitution => (x > 0.0 && x <= 1.0, "above 0 and at most 1"),
            Rule::Tangential => ((-1.0..=1.0).contains(&x), "from -1 to 1"),
            Rule::Overlap => (
                x > 0.0 && x < 0.5,
                "above 0 and below 0.5 (pkdgrav stops at an overlap of half the radius)",
            ),
            Rule::Fraction => (x > 0.0 && x <= 1.0, "above 0 and at most 1"),
        };
        if ok { Ok(x) } else { Err(says) }
    }
}

/// One `key = value` line.
struct Line<'a> {
    n: usize,
    value: &'a str,
}

/// The lines of a `.par` file by key (a later line for a key replaces an earlier one, as
/// in pkdgrav), and the keys with their lines in file order.
struct Lines<'a> {
    by_key: HashMap<&'a str, Line<'a>>,
    order: Vec<(usize, &'a str)>,
    /// The lines with a comment begun by `!` rather than `#`.
    bangs: Vec<usize>,
}

impl<'a> Lines<'a> {
    /// Splits `text` into its `key = value` lines.
    fn split(text: &'a str) -> Result<Lines<'a>, InputError> {
        let mut by_key = HashMap::new();
        let mut order = Vec::new();
        let mut bangs = Vec::new();
        for (i, raw) in text.split('\n').enumerate() {
            let n = i + 1;
            // A CRLF line's `\r` past the limit is a blank line to pkdgrav.
            let content = raw.strip_suffix('\r').unwrap_or(raw);
            if content.len() > LINE_LIMIT {
                return Err(error(
                    format!("line {n}"),
                    format!(
                        "the line is {} bytes long; pkdgrav reads .par lines {LINE_LIMIT} bytes at a time, so it would read the rest of the line as a line of its own and stop with a syntax error: keep lines (comments included) to {LINE_LIMIT} bytes",
                        content.len()
                    ),
                ));
            }
            let line = raw.split('#').next().unwrap_or("");
            let line = match line.split_once('!') {
                Some((before, _)) => {
                    bangs.push(n);
                    before
                }
                None => line,
            }
            .trim();
            if line.is_empty() {
                continue;
            }
            let Some((name, value)) = line.split_once('=') else {
                return Err(error(
                    format!("line {n}"),
                    format!("`{line}` is not `name = value`"),
                ));
            };
            // Quotes are the value's, but the four file names' one leading and one
            // trailing `"` (docs/pkdgrav-physics.md §14).
            let (name, value) = (name.trim(), value.trim());
            let value = if walls_par::value::UNQUOTED.contains(&name) {
                let v = value.strip_prefix('"').unwrap_or(value);
                v.strip_suffix('"').unwrap_or(v)
            } else {
                value
            };
            by_key.insert(name, Line { n, value });
            order.push((n, name));
        }
        Ok(Lines {
            by_key,
            order,
            bangs,
        })
    }

    /// The line of `key`, if given.
    fn line(&self, key: &str) -> Option<usize> {
        self.by_key.get(key).map(|l| l.n)
    }

    fn text(&self, key: &str) -> Option<String> {
        self.by_key.get(key).map(|l| l.value.to_string())
    }

    /// `key`'s value as a number, with its line.
    fn real(&self, key: &str) -> Result<Option<(usize, f64)>, InputError> {
        self.real_warned(key, &mut Vec::new())
    }

    /// `key`'s value as a number, with its line; a subnormal is warned about in
    /// `warnings`.
    fn real_warned(
        &self,
        key: &str,
        warnings: &mut Vec<Warning>,
    ) -> Result<Option<(usize, f64)>, InputError> {
        self.by_key
            .get(key)
            .map(|l| {
                let x = super::number(l.value, || format!("line {}: `{key}`", l.n), warnings)
                    .map_err(|why| {
                        error(
                            format!("line {}", l.n),
                            format!("`{key}` is `{}`, {why}", l.value),
                        )
                    })?;
                Ok((l.n, x))
            })
            .transpose()
    }

    /// `key`'s value as pkdgrav's integer parameters read it (C's `%d`: an optional
    /// sign and the digits that follow, the rest of the text ignored), with its line and
    /// whether that was the whole text (`0.5` reads as 0, `1e3` as 1).
    fn percent_d(&self, key: &str) -> Result<Option<(usize, i64, bool)>, InputError> {
        self.by_key
            .get(key)
            .map(|l| {
                let text = l.value;
                let sign = usize::from(text.starts_with(['-', '+']));
                let digits = text[sign..]
                    .find(|c: char| !c.is_ascii_digit())
                    .map_or(text.len(), |k| k + sign);
                let at = || format!("line {}", l.n);
                let x = text[..digits].parse::<i64>().map_err(|e| match e.kind() {
                    std::num::IntErrorKind::PosOverflow | std::num::IntErrorKind::NegOverflow => {
                        error(at(), beyond_int(key, text))
                    }
                    _ => error(
                        at(),
                        format!("`{key}` is `{text}`; pkdgrav reads a whole number here"),
                    ),
                })?;
                if i32::try_from(x).is_err() {
                    return Err(error(at(), beyond_int(key, text)));
                }
                Ok((l.n, x, digits == text.len()))
            })
            .transpose()
    }

    /// A pkdgrav switch (an integer, any value but 0 on) as pkdgrav reads it
    /// ([`Lines::percent_d`]).
    fn switch(&self, key: &str) -> Result<Option<bool>, InputError> {
        Ok(self.percent_d(key)?.map(|(_, x, _)| x != 0))
    }

    /// `key`'s value if it obeys `rule`.
    fn checked(&self, key: &str, rule: Rule) -> Result<Option<f64>, InputError> {
        self.real(key)?
            .map(|(n, x)| {
                rule.check(x).map_err(|says| {
                    error(
                        format!("line {n}"),
                        format!("`{key}` is `{}`; it must be {says}", self.by_key[key].value),
                    )
                })
            })
            .transpose()
    }

    /// `key`'s value as a whole number of 0 or more (pkdgrav reads it with C's `%d`,
    /// which would read `2e4` as 2: an error here).
    fn count(&self, key: &str) -> Result<Option<u64>, InputError> {
        self.by_key
            .get(key)
            .map(|l| {
                let at = || format!("line {}", l.n);
                match l.value.parse::<u64>() {
                    Ok(n) if n <= i32::MAX as u64 => Ok(n),
                    Ok(_) => Err(error(at(), beyond_int(key, l.value))),
                    Err(e) if *e.kind() == std::num::IntErrorKind::PosOverflow => {
                        Err(error(at(), beyond_int(key, l.value)))
                    }
                    Err(_) => Err(error(
                        at(),
                        format!(
                            "`{key}` is `{}`; it must be a whole number, 0 or more",
                            l.value
                        ),
                    )),
                }
            })
            .transpose()
    }

    /// `nDigits`: a whole number of digits, at most [`MAX_DIGITS`] (a step number has
    /// at most 20).
    fn digits(&self) -> Result<Option<usize>, InputError> {
        match self.count("nDigits")? {
            Some(d) if d > MAX_DIGITS as u64 => Err(error(
                format!("line {}", self.by_key["nDigits"].n),
                format!("`nDigits` is `{d}`; it must be at most {MAX_DIGITS}"),
            )),
            d => Ok(d.map(|d| d as usize)),
        }
    }

    /// A spring constant with pkdgrav's −1 sentinel: `Ok(None)` for −1 (or not given),
    /// an error for any other negative value.
    fn spring(&self, key: &str) -> Result<Option<f64>, InputError> {
        match self.real(key)? {
            None => Ok(None),
            Some((_, -1.0)) => Ok(None),
            Some((n, x)) if x < 0.0 || !x.is_finite() => Err(error(
                format!("line {n}"),
                format!(
                    "`{key}` is `{}`; it must be 0 or more, or -1 (pkdgrav's \"2/7 of the normal constant\")",
                    self.by_key[key].value
                ),
            )),
            Some((_, x)) => Ok(Some(x)),
        }
    }
}

/// The error for an integer key whose value a C `int` cannot hold: pkdgrav reads it
/// with `%d` and would take another number without a word.
fn beyond_int(key: &str, text: &str) -> String {
    format!(
        "`{key}` is `{text}`, beyond a C int, which pkdgrav reads it into with %d (it would read another number): give at most {}",
        i32::MAX
    )
}

/// Reads a pkdgrav parameter file: the keys the evaluator follows into [`Params`], the
/// others into its warnings ([`KEYS`]).
pub fn read_par(text: &str) -> Result<Params, InputError> {
    read_par_overridden(text, &[], None)
}

/// [`read_par`] for a run whose command line sets the keys `overridden`: the file's lines
/// of them are not read (nor judged), as if the file left them out. With `dem` (whether
/// the run's build has DEM), a key whose one value walls-sim follows is not warned about
/// where that build does not need the value (`iOutcomes` in a DEM build, which ignores it:
/// [`walls_par::evaluator::follows_alone`]).
pub fn read_par_overridden(
    text: &str,
    overridden: &[&str],
    dem: Option<bool>,
) -> Result<Params, InputError> {
    let mut lines = Lines::split(text)?;
    lines.by_key.retain(|k, _| !overridden.contains(k));
    lines.order.retain(|(_, k)| !overridden.contains(k));
    // Every real the file gives pkdgrav (a `d…` key it knows, followed or not), by the
    // tools' rule for numbers: overflow and underflow are errors, a subnormal is read and
    // warned about.
    let mut subnormals = Vec::new();
    for &(n, key) in &lines.order {
        if key.starts_with('d') && use_of(key).is_some() && lines.line(key) == Some(n) {
            lines.real_warned(key, &mut subnormals)?;
        }
    }
    let mut warnings = Vec::new();
    let mut warn = |line: Option<usize>, key: &str, message: String| {
        warnings.push(ParWarning {
            line,
            key: key.to_string(),
            message,
        });
    };
    for &(n, key) in &lines.order {
        if let Some(last) = lines.line(key)
            && last != n
        {
            warn(
                Some(n),
                key,
                format!("given again on line {last}, which wins (as in pkdgrav)"),
            );
            continue;
        }
        // pkdgrav's integers (`b…` switches, `i…` options) are read with C's %d; the
        // counts the run reads as whole numbers are errors instead ([`Lines::count`]).
        if key.starts_with(['b', 'i'])
            && !COUNTS.contains(&key)
            && use_of(key).is_some()
            && let Some((_, x, false)) = lines.percent_d(key)?
        {
            warn(
                Some(n),
                key,
                format!(
                    "`{}` is not a whole number: pkdgrav reads it with C's %d as {x}; the run does the same (write {x})",
                    lines.by_key[key].value
                ),
            );
        }
        match use_of(key) {
            // A key pkdgrav's build registers, but the evaluator does not model (a key
            // no build registers is refused first: `read_file_for`).
            None => warn(
                Some(n),
                key,
                match suggestion(key) {
                    Some(s) => format!(
                        "the evaluator does not model it, so it is ignored (pkdgrav follows it, if its build registers it); did you mean `{s}`?"
                    ),
                    None => "the evaluator does not model it, so it is ignored (pkdgrav follows it, if its build registers it)".into(),
                },
            ),
            Some(Use::NotYet(why)) => warn(Some(n), key, why.to_string()),
            Some(Use::Only { value, why, .. }) => {
                // pkdgrav's switches (`b…`) and integers (`i…`) are C ints read with
                // %d: any value but 0 is on.
                let x = if key.starts_with(['b', 'i']) {
                    lines.percent_d(key)?.map(|(_, x, _)| x as f64)
                } else {
                    lines.real(key)?.map(|(_, x)| x)
                };
                let same = |x: f64| {
                    if key.starts_with('b') {
                        (x != 0.0) == (value != 0.0)
                    } else {
                        x == value
                    }
                };
                if let Some(x) = x
                    && !same(x)
                    && dem.is_none_or(|dem| walls_par::evaluator::follows_alone(key, dem))
                {
                    warn(Some(n), key, format!("{x} is not modelled: {why}"));
                }
            }
            Some(Use::Read) if key == "bDoGravity" => {
                if let Some((_, x, _)) = lines.percent_d(key)?
                    && x == 0
                {
                    warn(
                        Some(n),
                        key,
                        "0: pkdgrav then evaluates no forces at all (its contact forces are computed in the gravity step): no uniform gravity, no contacts; the run does the same, and particles pass through walls and each other".into(),
                    );
                }
            }
            Some(Use::Read | Use::NoEffect) => {}
        }
    }
    for &(key, u) in KEYS {
        if let Use::Only {
            value,
            default,
            why,
        } = u
            && default != value
            && lines.line(key).is_none()
        {
            warn(None, key, format!("pkdgrav's default is {default}: {why}"));
        }
    }
    for &n in &lines.bangs {
        warn(
            Some(n),
            "!",
            "read as a comment, as in walls files; pkdgrav's parameter files take `#` comments: write `#` so that pkdgrav reads the line as the run does".into(),
        );
    }
    let k_n = lines.checked("dKn", Rule::NonNegative)?;
    match (k_n, lines.line("dKn")) {
        (None, _) => warn(
            None,
            "dKn",
            "pkdgrav's default is 0 (no normal spring); the evaluator derives k_n from the scene instead (docs/evaluator.md)".into(),
        ),
        (Some(0.0), n) => warn(
            n,
            "dKn",
            "0: pkdgrav warns and runs without a normal spring, so particles pass through walls and each other".into(),
        ),
        _ => {}
    }
    let two_layer = two_layer(&lines, k_n.unwrap_or(0.0))?;
    let mut optional_keys: Vec<OptionalKey> = OPTIONAL_KEYS
        .iter()
        .filter_map(|&(key, option)| {
            Some(OptionalKey {
                line: lines.line(key)?,
                key,
                option,
            })
        })
        .collect();
    optional_keys.sort_by_key(|k| k.line);
    let cohesion_model = match lines.percent_d("iCohesionModel")? {
        None => None,
        Some((_, x, _)) if x == 0 || x == 1 => Some(x),
        Some((n, _, _)) => {
            return Err(error(
                format!("line {n}"),
                format!(
                    "`iCohesionModel` is `{}`; it must be 0 (microscopic contact) or 1 (granular bridge)",
                    lines.by_key["iCohesionModel"].value
                ),
            ));
        }
    };
    warnings.sort_by_key(|w| w.line.unwrap_or(usize::MAX));
    let g = [
        lines.checked("dxUnifGrav", Rule::Any)?,
        lines.checked("dyUnifGrav", Rule::Any)?,
        lines.checked("dzUnifGrav", Rule::Any)?,
    ];
    Ok(Params {
        in_file: lines.text("achInFile"),
        walls_file: lines.text("achWallsFile"),
        out_name: lines.text("achOutName"),
        digits: lines.digits()?,
        dt: lines.checked("dDelta", Rule::Positive)?,
        steps: lines.count("nSteps")?,
        start_step: lines.count("iStartStep")?,
        out_interval: lines.count("iOutInterval")?,
        red_out_interval: lines.count("iRedOutInterval")?,
        eps_n: lines.checked("dEpsN", Rule::Restitution)?,
        eps_t: lines.checked("dEpsT", Rule::Tangential)?,
        k_n,
        k_t: lines.spring("dKt")?,
        mu_s: lines.checked("dMuS", Rule::NonNegative)?,
        mu_r: lines.checked("dMuR", Rule::NonNegative)?,
        mu_t: lines.checked("dMuT", Rule::NonNegative)?,
        beta_s: lines.checked("dBetaS", Rule::NonNegative)?,
        gravity: g.iter().any(Option::is_some).then(|| {
            Vec3::new(
                g[0].unwrap_or(0.0),
                g[1].unwrap_or(0.0),
                g[2].unwrap_or(0.0),
            )
        }),
        edge_detect: lines.switch("bWallsEdgeDetect")?,
        contact_radius: lines.switch("bUseContactRadius")?,
        legacy_roll: lines.switch("bUseLegacyRoll")?,
        do_gravity: lines.switch("bDoGravity")?,
        acc_crit: lines.checked("dAccCrit", Rule::NonNegative)?,
        overlap_fracs: overlap_fracs(&lines)?,
        two_layer,
        cohesion: CohesionKeys {
            model: cohesion_model,
            coefficient: lines.checked("dCohesiveCoeff", Rule::Any)?,
            file: lines.text("achCohesionFile").filter(|f| !f.is_empty()),
        },
        optional_keys,
        warnings,
        path_lines: PATH_KEYS
            .into_iter()
            .filter_map(|key| Some((key, lines.line(key)?)))
            .collect(),
        subnormals,
    })
}

/// The overlap levels' keys, in order, with pkdgrav's defaults.
pub const OVERLAP_KEYS: [(&str, f64); 3] = [
    ("dMinorFrac", 0.03),
    ("dMajorFrac", 0.15),
    ("dErrorFrac", 0.5),
];

/// `dMinorFrac`, `dMajorFrac`, `dErrorFrac` as the file gives them: each 0 or more,
/// and, with pkdgrav's defaults for those it leaves out, in order (pkdgrav stops at
/// start-up otherwise, docs/pkdgrav-physics.md §15).
fn overlap_fracs(lines: &Lines) -> Result<[Option<f64>; 3], InputError> {
    let mut given = [None; 3];
    for (k, (key, _)) in OVERLAP_KEYS.iter().enumerate() {
        given[k] = lines.checked(key, Rule::NonNegative)?;
    }
    for k in 0..2 {
        let value = |k: usize| given[k].unwrap_or(OVERLAP_KEYS[k].1);
        if value(k) > value(k + 1) {
            let (low, high) = (OVERLAP_KEYS[k].0, OVERLAP_KEYS[k + 1].0);
            let at = lines
                .line(high)
                .max(lines.line(low))
                .map_or_else(String::new, |n| format!("line {n}"));
            return Err(error(
                at,
                format!(
                    "`{low}` is {} and `{high}` {}: pkdgrav stops at start-up unless 0 ≤ dMinorFrac ≤ dMajorFrac ≤ dErrorFrac (its defaults 0.03, 0.15, 0.5)",
                    value(k),
                    value(k + 1)
                ),
            ));
        }
    }
    Ok(given)
}

/// The two-layer constants when the file gives any, resolved against `k_n` (`dKn`) as
/// pkdgrav does after parsing; each must then be above 0.
fn two_layer(lines: &Lines, k_n: f64) -> Result<Option<TwoLayer>, InputError> {
    let keys = [
        "dInnerOverlapBndry",
        "dKnOuter",
        "dKtOuter",
        "dKnInner",
        "dKtInner",
    ];
    if keys.iter().all(|k| lines.line(k).is_none()) {
        return Ok(None);
    }
    let k_n_outer = lines.spring("dKnOuter")?.unwrap_or(k_n);
    let k_n_inner = lines.spring("dKnInner")?.unwrap_or(k_n);
    let layers = TwoLayer {
        boundary: lines
            .checked("dInnerOverlapBndry", Rule::NonNegative)?
            .unwrap_or(0.0),
        k_n_outer,
        k_t_outer: lines.spring("dKtOuter")?.unwrap_or(KT_PER_KN * k_n_outer),
        k_n_inner,
        k_t_inner: lines.spring("dKtInner")?.unwrap_or(KT_PER_KN * k_n_inner),
    };
    let resolved = [
        ("dKnOuter", layers.k_n_outer),
        ("dKtOuter", layers.k_t_outer),
        ("dKnInner", layers.k_n_inner),
        ("dKtInner", layers.k_t_inner),
    ];
    for (key, x) in resolved {
        if x <= 0.0 {
            let at = lines
                .line(key)
                .or(lines.line("dKn"))
                .map_or_else(|| "the file".to_string(), |n| format!("line {n}"));
            return Err(error(
                at,
                format!(
                    "`{key}` comes to {x}; pkdgrav needs every two-layer spring constant above 0 (−1 means dKn, or 2/7 of the normal constant)"
                ),
            ));
        }
    }
    Ok(Some(layers))
}

/// Reads the pkdgrav parameter file at `path`.
pub fn read_file(path: &str) -> Result<Params, FileError> {
    let text = std::fs::read_to_string(path).map_err(|e| FileError::read(path, e))?;
    let mut params = read_par(&text).map_err(|e| FileError::input(path, e))?;
    params.subnormals = super::in_file(path, std::mem::take(&mut params.subnormals));
    Ok(params)
}

/// Reads the pkdgrav parameter file at `path` as a pkdgrav of `build` reads it: a file
/// that pkdgrav refuses, or stops on ([`walls_par::check`]'s errors: a syntax error, a
/// key the build does not register, a value it stops on, at start-up or later), is an
/// error at the first such line, with how many there are (`walls-lint` lists them all).
/// The keys `overridden` are set on the command line: the file's word on them is not
/// judged.
pub fn read_file_for(
    path: &str,
    build: &walls_par::Build,
    overridden: &[&str],
) -> Result<Params, FileError> {
    let text = read_text(path)?;
    let refused: Vec<_> = walls_par::check::check_overridden(&text, build, overridden)
        .into_iter()
        .filter(|d| d.severity == walls_par::Severity::Error)
        .collect();
    // A line's error before those of keys left out (often its consequence: a line
    // refused leaves its key unset).
    let first = (refused.iter())
        .find(|d| d.span != (0..0))
        .or(refused.first());
    if let Some(first) = first {
        // A key left at a default pkdgrav stops on has no line: the message names it.
        let at = if first.span == (0..0) {
            String::new()
        } else {
            format!(
                "line {}",
                1 + text[..first.span.start].matches('\n').count()
            )
        };
        let more = match refused.len() {
            1 => String::new(),
            n => format!("; {} more (`walls-lint {path}` lists them)", n - 1),
        };
        let help = first
            .help
            .as_ref()
            .map_or(String::new(), |h| format!(": {h}"));
        let message = format!("{}{help} [{}]{more}", first.message, first.code.id);
        return Err(FileError::input(path, error(at, message)));
    }
    let mut params = read_par_overridden(&text, overridden, Some(build.has("DEM")))
        .map_err(|e| FileError::input(path, e))?;
    params.subnormals = super::in_file(path, std::mem::take(&mut params.subnormals));
    Ok(params)
}

/// The most bytes of a `.par` file read: a real one is a few kilobytes; a device or a
/// stray file is refused at this size rather than read whole.
pub const MAX_PAR_BYTES: u64 = 16 << 20;

/// The text of the `.par` file at `path`, read up to [`MAX_PAR_BYTES`]; bytes that are
/// not UTF-8 (pkdgrav reads bytes: a Latin-1 comment) read as U+FFFD.
fn read_text(path: &str) -> Result<String, FileError> {
    use std::io::Read;
    let file = std::fs::File::open(path).map_err(|e| FileError::read(path, e))?;
    let mut bytes = Vec::new();
    file.take(MAX_PAR_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| FileError::read(path, e))?;
    if bytes.len() as u64 > MAX_PAR_BYTES {
        return Err(FileError::input(
            path,
            error(
                String::new(),
                format!(
                    "over {} MiB: not a pkdgrav parameter file (a device, or another file named as one)",
                    MAX_PAR_BYTES >> 20
                ),
            ),
        ));
    }
    Ok(match String::from_utf8(bytes) {
        Ok(text) => text,
        Err(e) => String::from_utf8_lossy(e.as_bytes()).into_owned(),
    })
}
