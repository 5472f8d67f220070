//! pkdgrav parameter files: `name = value  # comment` lines, of which the evaluator reads
//! the input and walls files, the timestep and step count, the material values, uniform
//! gravity and edge detection; and the range each run parameter must lie in ([`Rule`]),
//! whether it comes from a `.par` file or the command line.
//!
//! Every error names the `.par` line.

use super::{FileError, InputError, error};
use nalgebra::Vector3;
use std::collections::HashMap;

type Vec3 = Vector3<f64>;

/// What the evaluator reads from a pkdgrav parameter file.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Params {
    /// `achInFile`: the particle (.ss) file.
    pub in_file: Option<String>,
    /// `achWallsFile`: the walls file.
    pub walls_file: Option<String>,
    /// `dDelta`: the timestep.
    pub dt: Option<f64>,
    /// `nSteps`: the number of steps.
    pub steps: Option<u64>,
    /// `dEpsN`, `dEpsT`: the particles' coefficients of restitution.
    pub eps_n: Option<f64>,
    /// See `eps_n`.
    pub eps_t: Option<f64>,
    /// `dKn`, `dKt`: the particles' spring constants.
    pub k_n: Option<f64>,
    /// See `k_n`.
    pub k_t: Option<f64>,
    /// `dMuS`, `dMuR`, `dMuT`: the particles' friction coefficients.
    pub mu_s: Option<f64>,
    /// See `mu_s`.
    pub mu_r: Option<f64>,
    /// See `mu_s`.
    pub mu_t: Option<f64>,
    /// `dxUnifGrav`, `dyUnifGrav`, `dzUnifGrav`: uniform gravity (missing components 0).
    pub gravity: Option<Vec3>,
    /// `bWallsEdgeDetect`: HSDEM edge detection (pkdgrav's default is on).
    pub edge_detect: Option<bool>,
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
        if ok && x.is_finite() {
            Ok(x)
        } else {
            Err(says)
        }
    }
}

/// Reads a pkdgrav parameter file; other parameters are ignored.
pub fn read_par(text: &str) -> Result<Params, InputError> {
    let mut values: HashMap<&str, (usize, &str)> = HashMap::new();
    for (n, raw) in text.lines().enumerate() {
        let line = raw.split('#').next().unwrap_or("").trim();
        if line.is_empty() {
            continue;
        }
        let Some((name, value)) = line.split_once('=') else {
            return Err(error(
                format!("line {}", n + 1),
                format!("`{line}` is not `name = value`"),
            ));
        };
        values.insert(name.trim(), (n + 1, value.trim().trim_matches('"')));
    }
    let number = |name: &str, rule: Rule| -> Result<Option<f64>, InputError> {
        values
            .get(name)
            .map(|&(n, v)| {
                let x = v.parse::<f64>().map_err(|_| {
                    error(
                        format!("line {n}"),
                        format!("`{name}` is `{v}`, not a number"),
                    )
                })?;
                rule.check(x).map_err(|says| {
                    error(
                        format!("line {n}"),
                        format!("`{name}` is `{v}`; it must be {says}"),
                    )
                })
            })
            .transpose()
    };
    let text_of = |name: &str| values.get(name).map(|&(_, v)| v.to_string());
    let gravity = ["dxUnifGrav", "dyUnifGrav", "dzUnifGrav"];
    let g = [
        number(gravity[0], Rule::Any)?,
        number(gravity[1], Rule::Any)?,
        number(gravity[2], Rule::Any)?,
    ];
    Ok(Params {
        in_file: text_of("achInFile"),
        walls_file: text_of("achWallsFile"),
        dt: number("dDelta", Rule::Positive)?,
        steps: match number("nSteps", Rule::NonNegative)? {
            Some(x) if x >= 0.0 && x.fract() == 0.0 => Some(x as u64),
            Some(x) => {
                return Err(error(
                    format!("line {}", values["nSteps"].0),
                    format!("`nSteps` is {x}, not a whole number"),
                ));
            }
            None => None,
        },
        eps_n: number("dEpsN", Rule::Restitution)?,
        eps_t: number("dEpsT", Rule::Tangential)?,
        k_n: number("dKn", Rule::Positive)?,
        k_t: number("dKt", Rule::NonNegative)?,
        mu_s: number("dMuS", Rule::NonNegative)?,
        mu_r: number("dMuR", Rule::NonNegative)?,
        mu_t: number("dMuT", Rule::NonNegative)?,
        gravity: g.iter().any(Option::is_some).then(|| {
            Vec3::new(
                g[0].unwrap_or(0.0),
                g[1].unwrap_or(0.0),
                g[2].unwrap_or(0.0),
            )
        }),
        edge_detect: number("bWallsEdgeDetect", Rule::Any)?.map(|x| x != 0.0),
    })
}

/// Reads the pkdgrav parameter file at `path`.
pub fn read_file(path: &str) -> Result<Params, FileError> {
    let text = std::fs::read_to_string(path).map_err(|e| FileError::read(path, e))?;
    read_par(&text).map_err(|e| FileError::input(path, e))
}
