//! Particles and run parameters from the files a pkdgrav user has.
//!
//! * CSV (SPEC §2): header `mass,radius,x,y,z,vx,vy,vz`, optionally followed by
//!   `wx,wy,wz,color`; one particle a row, in pkdgrav units.
//! * pkdgrav `.ss` files: big-endian XDR. A 16-byte header (double time, int32 count,
//!   int32 magic: −1 standard, −10101 reduced), then per particle either 96 bytes (double
//!   mass, radius, pos[3], vel[3], spin[3]; int32 color, original index) or 28 bytes
//!   (float mass, radius, pos[3]; int32 color, index).
//! * pkdgrav parameter files: `name = value  # comment` lines, of which the evaluator
//!   reads the input and walls files, the timestep and step count, the material values,
//!   uniform gravity and edge detection.
//!
//! Every error says where: the CSV line, the `.ss` byte offset, the `.par` line.

use nalgebra::Vector3;
use std::collections::HashMap;

type Vec3 = Vector3<f64>;

/// One particle.
#[derive(Debug, Clone, PartialEq)]
pub struct Particle {
    /// Mass.
    pub mass: f64,
    /// Radius.
    pub radius: f64,
    /// Position.
    pub pos: Vec3,
    /// Velocity.
    pub vel: Vec3,
    /// Spin (angular velocity).
    pub spin: Vec3,
    /// ssdraw colour.
    pub color: i32,
    /// Index in the original file.
    pub index: i32,
}

/// Why an input could not be read, and where.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct InputError {
    /// "line 4", "byte 112", …
    pub at: String,
    /// What is wrong.
    pub message: String,
}

impl std::fmt::Display for InputError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.at, self.message)
    }
}

fn error(at: impl Into<String>, message: impl Into<String>) -> InputError {
    InputError {
        at: at.into(),
        message: message.into(),
    }
}

/// Reads particles from CSV text.
pub fn read_csv(text: &str) -> Result<Vec<Particle>, InputError> {
    let mut reader = csv::ReaderBuilder::new()
        .trim(csv::Trim::All)
        .from_reader(text.as_bytes());
    let header: Vec<String> = reader
        .headers()
        .map_err(|e| error("line 1", e.to_string()))?
        .iter()
        .map(str::to_string)
        .collect();
    const REQUIRED: [&str; 8] = ["mass", "radius", "x", "y", "z", "vx", "vy", "vz"];
    const OPTIONAL: [&str; 4] = ["wx", "wy", "wz", "color"];
    let column = |name: &str| header.iter().position(|h| h == name);
    for name in REQUIRED {
        if column(name).is_none() {
            return Err(error(
                "line 1",
                format!("the header has no `{name}` column (it needs mass,radius,x,y,z,vx,vy,vz)"),
            ));
        }
    }
    if let Some(extra) = header
        .iter()
        .find(|h| !REQUIRED.contains(&h.as_str()) && !OPTIONAL.contains(&h.as_str()))
    {
        return Err(error("line 1", format!("unknown column `{extra}`")));
    }
    let mut out = Vec::new();
    for (n, record) in reader.records().enumerate() {
        let line = format!("line {}", n + 2);
        let record = record.map_err(|e| error(line.clone(), e.to_string()))?;
        let number = |name: &str| -> Result<f64, InputError> {
            let Some(i) = column(name) else {
                return Ok(0.0);
            };
            let field = record.get(i).unwrap_or("");
            field
                .parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .ok_or_else(|| {
                    error(
                        line.clone(),
                        format!("`{name}` is `{field}`, not a finite number"),
                    )
                })
        };
        let particle = Particle {
            mass: number("mass")?,
            radius: number("radius")?,
            pos: Vec3::new(number("x")?, number("y")?, number("z")?),
            vel: Vec3::new(number("vx")?, number("vy")?, number("vz")?),
            spin: Vec3::new(number("wx")?, number("wy")?, number("wz")?),
            color: match column("color") {
                Some(i) => {
                    let field = record.get(i).unwrap_or("");
                    field.parse::<i32>().map_err(|_| {
                        error(
                            line.clone(),
                            format!("`color` is `{field}`, not an integer"),
                        )
                    })?
                }
                None => 3,
            },
            index: n as i32,
        };
        particle.check().map_err(|says| error(line, says))?;
        out.push(particle);
    }
    Ok(out)
}

impl Particle {
    /// Whether a run can use it: a positive mass and radius, finite values.
    fn check(&self) -> Result<(), &'static str> {
        if !(self.mass > 0.0 && self.radius > 0.0) {
            return Err("mass and radius must be positive");
        }
        let values = [self.mass, self.radius];
        let vectors = [self.pos, self.vel, self.spin];
        if values
            .iter()
            .chain(vectors.iter().flatten())
            .all(|x| x.is_finite())
        {
            Ok(())
        } else {
            Err("its values must be finite numbers")
        }
    }
}

/// A cursor over big-endian XDR data that reports the byte offset of a short read.
struct Xdr<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl Xdr<'_> {
    fn take<const N: usize>(&mut self) -> Result<[u8; N], InputError> {
        let slice = self.bytes.get(self.at..self.at + N).ok_or_else(|| {
            error(
                format!("byte {}", self.at),
                format!(
                    "the file ends inside a record ({} bytes in all)",
                    self.bytes.len()
                ),
            )
        })?;
        self.at += N;
        Ok(slice.try_into().expect("the slice has N bytes"))
    }
    fn f64(&mut self) -> Result<f64, InputError> {
        self.take::<8>().map(f64::from_be_bytes)
    }
    fn f32(&mut self) -> Result<f64, InputError> {
        self.take::<4>().map(|b| f32::from_be_bytes(b) as f64)
    }
    fn i32(&mut self) -> Result<i32, InputError> {
        self.take::<4>().map(i32::from_be_bytes)
    }
}

/// The `.ss` magic numbers.
const STANDARD: i32 = -1;
const REDUCED: i32 = -10101;

/// Reads a pkdgrav `.ss` file: its time and particles.
pub fn read_ss(bytes: &[u8]) -> Result<(f64, Vec<Particle>), InputError> {
    let mut x = Xdr { bytes, at: 0 };
    let time = x.f64()?;
    let count = x.i32()?;
    let magic = x.i32()?;
    let record = match magic {
        STANDARD => 96,
        REDUCED => 28,
        m => {
            return Err(error(
                "byte 12",
                format!("magic number {m}: a .ss file has −1 (standard) or −10101 (reduced)"),
            ));
        }
    };
    if count < 0 || bytes.len() != 16 + count as usize * record {
        return Err(error(
            "byte 8",
            format!(
                "{count} particles of {record} bytes need {} bytes, the file has {}",
                16 + count.max(0) as usize * record,
                bytes.len()
            ),
        ));
    }
    let mut out = Vec::with_capacity(count as usize);
    for k in 0..count {
        let start = x.at;
        let p = if magic == STANDARD {
            let mass = x.f64()?;
            let radius = x.f64()?;
            let pos = Vec3::new(x.f64()?, x.f64()?, x.f64()?);
            let vel = Vec3::new(x.f64()?, x.f64()?, x.f64()?);
            let spin = Vec3::new(x.f64()?, x.f64()?, x.f64()?);
            Particle {
                mass,
                radius,
                pos,
                vel,
                spin,
                color: x.i32()?,
                index: x.i32()?,
            }
        } else {
            let mass = x.f32()?;
            let radius = x.f32()?;
            let pos = Vec3::new(x.f32()?, x.f32()?, x.f32()?);
            Particle {
                mass,
                radius,
                pos,
                vel: Vec3::zeros(),
                spin: Vec3::zeros(),
                color: x.i32()?,
                index: x.i32()?,
            }
        };
        p.check()
            .map_err(|says| error(format!("byte {start}"), format!("particle {k}: {says}")))?;
        out.push(p);
    }
    Ok((time, out))
}

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
