//! Advice for the real pkdgrav run: a normal spring constant `dKn`, its tangential
//! companion `dKt` and a timestep `dDelta`, from the physical inputs a user knows (the
//! typical particle's mass or density and radius, the fastest expected speed, the
//! overlap they allow, and the height of a pile under gravity).
//!
//! The rules are pkdgrav's own `demparams` tool (D. C. Richardson, `demparams.c`, 2012)
//! and Schwartz, Richardson & Michel 2012 (*Granular Matter* 14:363, §2.1 and §2.7):
//!
//! * **Kinetic**: a particle of mass m reaching a wall at the maximum speed v stops
//!   within the allowed overlap x = f·s (f a fraction of the radius s) when
//!   k_n = m·(v/x)², since its peak overlap is v·√(μ/k_n) with μ = m.
//! * **Static**: the bottom of a column of height H (packing fraction φ, particle density
//!   ρ, gravity g) bears φ·ρ·g·H per unit area, that is φ·ρ·g·H·s² per particle, and
//!   overlaps by at most x when k_n = φ·ρ·g·H·s²/x (≈ 65·ρ·g·H·s for φ = 0.65, f = 1 %).
//! * k_n is the larger of the two, and [`Advice::governs`] says which; k_t = 2/7·k_n
//!   (pkdgrav's default, which matches the tangential and normal half-periods).
//! * The contact lasts π·√(μ/k_n) undamped: μ = m/2 between equal particles and μ = m
//!   against a wall, whose contact is √2 longer. The timestep divides the shorter contact
//!   the run has (pairs, unless the particles meet only walls) into N steps:
//!   dt = π·√(m/(2k_n))/N. Damping lengthens contacts by √(1 + ln²ε/π²), so the
//!   undamped time is the safe one.
//!
//! N defaults to 30, as in `demparams` ([`DEFAULT_STEPS_PER_CONTACT`]): the rebound's
//! restitution is then within about 0.5 % of ε with pkdgrav's leapfrog (for ε = 0.5 it
//! is 4 % low at 10 steps, 1 % at 20 and 0.16 % at 50). The evaluator's
//! own runs use 100 ([`crate::run::STEPS_PER_CONTACT`]) because they are compared with
//! closed forms to 1 %; a production run does not need that.
//!
//! Inputs are SI or pkdgrav units ([`UnitSystem`]); every result is given in both
//! ([`Quantity`]). pkdgrav's units are the AU, the solar mass and a year over 2π, in SI
//! as the toolkit's set gives them ([`Units::pkdgrav`]: pkdgrav's `ss.h`, the set
//! `--units si` shows too; `demparams` itself rounds them, docs/pkdgrav-physics.md §13).
//!
//! [`text`] and [`json`] render the advice as `walls-sim advise` prints it.

use std::fmt;
use walls_keywords::pkdgrav_units::{self, UnitSet};

/// The default allowed overlap: 1 % of the radius (Schwartz et al. 2012; `demparams`).
pub const DEFAULT_OVERLAP: f64 = 0.01;

/// The default steps per contact: 30, `demparams`' default.
pub const DEFAULT_STEPS_PER_CONTACT: f64 = 30.0;

/// The default packing fraction of a pile: 0.65, `demparams`' default.
pub const DEFAULT_PACKING: f64 = 0.65;

/// pkdgrav's overlap warning levels (`dMinorFrac`, `dMajorFrac`) and its error level
/// (`dErrorFrac`), as fractions of the radius.
pub const OVERLAP_LEVELS: [f64; 3] = [0.03, 0.15, 0.5];

/// Fewer steps per contact than this draws a warning: at 10 the rebound's restitution
/// is already 4 % low, and below π/2 the leapfrog is unstable.
pub const MIN_STEPS_PER_CONTACT: f64 = 10.0;

/// A system of units for mass, length and time, each given in SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Units {
    /// Kilograms in the unit of mass.
    pub mass: f64,
    /// Metres in the unit of length.
    pub length: f64,
    /// Seconds in the unit of time.
    pub time: f64,
}

impl Units {
    /// pkdgrav's units as the toolkit converts them ([`pkdgrav_units::TOOLKIT`], pkdgrav's
    /// `ss.h`): the AU, the solar mass and a sidereal year over 2π.
    pub fn pkdgrav() -> Self {
        Units {
            mass: pkdgrav_units::SOLAR_MASS_KG,
            length: pkdgrav_units::AU_M,
            time: pkdgrav_units::TIME_UNIT_S,
        }
    }

    /// pkdgrav's units as `set` gives them, if it gives a time unit.
    pub fn of(set: &UnitSet) -> Option<Self> {
        Some(Units {
            mass: set.solar_mass_kg,
            length: set.au_m,
            time: set.time_unit_s()?,
        })
    }

    /// SI units: every factor is 1.
    pub fn si() -> Self {
        Units {
            mass: 1.0,
            length: 1.0,
            time: 1.0,
        }
    }

    /// The SI value of one unit of `dimension`.
    pub fn factor(&self, dimension: Dimension) -> f64 {
        let (m, l, t) = dimension.exponents();
        self.mass.powi(m) * self.length.powi(l) * self.time.powi(t)
    }

    /// `x` in these units, as SI.
    pub fn to_si(&self, x: f64, dimension: Dimension) -> f64 {
        x * self.factor(dimension)
    }

    /// `x` in SI, in these units.
    pub fn from_si(&self, x: f64, dimension: Dimension) -> f64 {
        x / self.factor(dimension)
    }
}

/// The physical dimension of a quantity, which says how it converts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dimension {
    /// Mass: kg, M_sun.
    Mass,
    /// Length: m, AU.
    Length,
    /// Time: s, yr/2π.
    Time,
    /// Speed: m/s, AU/(yr/2π).
    Speed,
    /// Acceleration: m/s², AU/(yr/2π)².
    Acceleration,
    /// Density: kg/m³, M_sun/AU³.
    Density,
    /// A spring constant (force per length): kg/s², M_sun/(yr/2π)².
    Stiffness,
}

impl Dimension {
    /// The powers of mass, length and time.
    pub fn exponents(self) -> (i32, i32, i32) {
        match self {
            Dimension::Mass => (1, 0, 0),
            Dimension::Length => (0, 1, 0),
            Dimension::Time => (0, 0, 1),
            Dimension::Speed => (0, 1, -1),
            Dimension::Acceleration => (0, 1, -2),
            Dimension::Density => (1, -3, 0),
            Dimension::Stiffness => (1, 0, -2),
        }
    }

    /// The SI unit, in ASCII.
    pub fn si_unit(self) -> &'static str {
        match self {
            Dimension::Mass => "kg",
            Dimension::Length => "m",
            Dimension::Time => "s",
            Dimension::Speed => "m/s",
            Dimension::Acceleration => "m/s^2",
            Dimension::Density => "kg/m^3",
            Dimension::Stiffness => "kg/s^2",
        }
    }

    /// The pkdgrav unit, in ASCII (`demparams`' spelling).
    pub fn pkdgrav_unit(self) -> &'static str {
        match self {
            Dimension::Mass => "M_sun",
            Dimension::Length => "AU",
            Dimension::Time => "yr/2pi",
            Dimension::Speed => "AU/(yr/2pi)",
            Dimension::Acceleration => "AU/(yr/2pi)^2",
            Dimension::Density => "M_sun/AU^3",
            Dimension::Stiffness => "M_sun/(yr/2pi)^2",
        }
    }
}

/// A value in SI and in pkdgrav units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Quantity {
    /// The value in SI units.
    pub si: f64,
    /// The value in pkdgrav units.
    pub pkdgrav: f64,
    /// What it measures.
    pub dimension: Dimension,
}

impl Quantity {
    /// The quantity whose SI value is `si`.
    pub fn from_si(si: f64, dimension: Dimension) -> Self {
        Quantity {
            si,
            pkdgrav: Units::pkdgrav().from_si(si, dimension),
            dimension,
        }
    }
}

/// The units the inputs are in (`--units` of `walls-sim advise`: each variant's first
/// paragraph is its help).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum UnitSystem {
    /// kg, m, s.
    ///
    /// The default.
    #[default]
    Si,
    /// pkdgrav's: M_sun, AU, yr/2pi (G = 1).
    Pkdgrav,
}

impl UnitSystem {
    /// The units, each in SI.
    pub fn units(self) -> Units {
        match self {
            UnitSystem::Si => Units::si(),
            UnitSystem::Pkdgrav => Units::pkdgrav(),
        }
    }
}

/// How the typical particle's mass is given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Amount {
    /// Its mass.
    Mass(f64),
    /// Its density: the mass is 4/3·π·s³·ρ.
    Density(f64),
}

/// The shortest contact the timestep must resolve (`--contact` of `walls-sim advise`:
/// each variant's first paragraph is its help).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum Contact {
    /// Particles touch each other (and walls).
    ///
    /// Reduced mass m/2: the shorter contact (the default).
    #[default]
    Pair,
    /// Particles touch only walls.
    ///
    /// Reduced mass m.
    Wall,
}

/// A pile under gravity, for the static criterion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Column {
    /// The acceleration of gravity (uniform, or at the surface).
    pub gravity: f64,
    /// The pile's height (or the body's radius).
    pub height: f64,
    /// The packing fraction φ (bulk density over particle density).
    pub packing: f64,
}

/// What the user knows about the run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Inputs {
    /// The units of the values below.
    pub units: UnitSystem,
    /// The typical (most energetic) particle's mass or density.
    pub amount: Amount,
    /// The typical particle's radius s.
    pub radius: f64,
    /// The maximum expected speed v: of a particle at a wall, or between two particles.
    pub speed: f64,
    /// The allowed overlap as a fraction of the radius, above 0 and below 0.5.
    pub overlap: f64,
    /// A pile under gravity, when there is one.
    pub column: Option<Column>,
    /// Steps per contact N.
    pub steps_per_contact: f64,
    /// The shortest contact of the run.
    pub contact: Contact,
}

impl Inputs {
    /// Inputs in SI with the defaults: 1 % overlap, no pile, 30 steps a pair contact.
    pub fn new(amount: Amount, radius: f64, speed: f64) -> Self {
        Inputs {
            units: UnitSystem::Si,
            amount,
            radius,
            speed,
            overlap: DEFAULT_OVERLAP,
            column: None,
            steps_per_contact: DEFAULT_STEPS_PER_CONTACT,
            contact: Contact::Pair,
        }
    }
}

/// An input outside its range.
#[derive(Debug, Clone, PartialEq)]
pub struct InvalidInput {
    /// The input's name, as the command line spells it (`overlap`, `radius`, …).
    pub name: &'static str,
    /// The value given.
    pub value: f64,
    /// What it must be.
    pub must_be: &'static str,
    /// Whether it is not an input but a value the inputs give (k_n, dDelta, …), which
    /// came out as 0, infinite or NaN: the inputs' scale is beyond a double's.
    pub derived: bool,
}

impl fmt::Display for InvalidInput {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.derived {
            write!(
                f,
                "these inputs give {} = {:e}; it must be {}: check their scale and units (a double holds about 1e-308 to 1e308)",
                self.name, self.value, self.must_be
            )
        } else {
            write!(
                f,
                "{} is {}; it must be {}",
                self.name, self.value, self.must_be
            )
        }
    }
}

impl std::error::Error for InvalidInput {}

/// Which estimate of k_n is the larger, and so is advised.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Criterion {
    /// The fastest impact: k_n = m·(v/x)².
    Kinetic,
    /// The pile's weight: k_n = φ·ρ·g·H·s²/x.
    Static,
}

/// The static criterion's inputs and results.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StaticEstimate {
    /// Gravity.
    pub gravity: Quantity,
    /// The pile's height.
    pub height: Quantity,
    /// The packing fraction.
    pub packing: f64,
    /// The bulk density φ·ρ.
    pub bulk_density: Quantity,
    /// The static estimate φ·ρ·g·H·s²/x.
    pub k_n: Quantity,
    /// The overlap at the pile's bottom with the advised k_n: φ·ρ·g·H·s²/k_n.
    pub overlap: Quantity,
    /// The speed of a fall over the height, √(2·g·H).
    pub free_fall_speed: Quantity,
}

/// The advice: inputs in both unit systems, the estimates, the parameters and warnings.
#[derive(Debug, Clone, PartialEq)]
pub struct Advice {
    /// The typical particle's mass m.
    pub mass: Quantity,
    /// Its radius s.
    pub radius: Quantity,
    /// Its density ρ = m/(4/3·π·s³).
    pub density: Quantity,
    /// The maximum expected speed v.
    pub speed: Quantity,
    /// The allowed overlap as a fraction of the radius.
    pub overlap_fraction: f64,
    /// The allowed overlap x = fraction·s.
    pub max_overlap: Quantity,
    /// Steps per contact N.
    pub steps_per_contact: f64,
    /// The contact the timestep resolves.
    pub contact: Contact,
    /// The kinetic estimate m·(v/x)².
    pub k_n_kinetic: Quantity,
    /// The static estimate and its inputs, when a pile was given.
    pub column: Option<StaticEstimate>,
    /// Which estimate is advised.
    pub governs: Criterion,
    /// The advised normal spring constant: the larger estimate.
    pub k_n: Quantity,
    /// The advised tangential spring constant, 2/7·k_n.
    pub k_t: Quantity,
    /// The undamped contact time between two typical particles, π·√(m/(2k_n)).
    pub contact_time_pair: Quantity,
    /// The undamped contact time against a wall, π·√(m/k_n).
    pub contact_time_wall: Quantity,
    /// The advised timestep: the resolved contact's time over N.
    pub dt: Quantity,
    /// Steps per wall contact at that timestep (√2·N when pairs are resolved).
    pub steps_per_wall_contact: f64,
    /// The peak overlap of a particle reaching a wall at v, v·√(m/k_n).
    pub peak_overlap_wall: Quantity,
    /// The peak overlap of two particles meeting at relative speed v, v·√(m/(2k_n)).
    pub peak_overlap_pair: Quantity,
    /// pkdgrav's units, each in SI.
    pub units: Units,
    /// What the user should know.
    pub warnings: Vec<String>,
}

/// `x` if it is finite and inside `ok`, else an error naming the input.
fn check(
    name: &'static str,
    x: f64,
    ok: impl Fn(f64) -> bool,
    must_be: &'static str,
) -> Result<f64, InvalidInput> {
    if x.is_finite() && ok(x) {
        Ok(x)
    } else {
        Err(InvalidInput {
            name,
            value: x,
            must_be,
            derived: false,
        })
    }
}

fn positive(name: &'static str, x: f64) -> Result<f64, InvalidInput> {
    check(name, x, |x| x > 0.0, "a finite number greater than 0")
}

/// The advice for `inputs`: k_n, k_t, the contact times, dt and the warnings, or the
/// first input outside its range.
pub fn advise(inputs: &Inputs) -> Result<Advice, InvalidInput> {
    use Dimension::*;
    use std::f64::consts::PI;
    let given = inputs.units.units();
    let si = |x: f64, d: Dimension| given.to_si(x, d);
    let s = si(positive("radius", inputs.radius)?, Length);
    let (m, rho) = match inputs.amount {
        Amount::Mass(m) => {
            let m = si(positive("mass", m)?, Mass);
            (m, m / (4.0 / 3.0 * PI * s.powi(3)))
        }
        Amount::Density(rho) => {
            let rho = si(positive("density", rho)?, Density);
            (4.0 / 3.0 * PI * s.powi(3) * rho, rho)
        }
    };
    let v = si(positive("speed", inputs.speed)?, Speed);
    let f = check(
        "overlap",
        inputs.overlap,
        |f| f > 0.0 && f < OVERLAP_LEVELS[2],
        "above 0 and below 0.5 (pkdgrav stops at an overlap of half the radius)",
    )?;
    let n = positive("steps-per-contact", inputs.steps_per_contact)?;
    let x = f * s;
    let k_kinetic = m * (v / x).powi(2);
    let column = match inputs.column {
        Some(c) => {
            let g = si(positive("gravity", c.gravity)?, Acceleration);
            let h = si(positive("height", c.height)?, Length);
            let phi = check(
                "packing",
                c.packing,
                |p| p > 0.0 && p <= 1.0,
                "above 0 and at most 1",
            )?;
            Some((g, h, phi, phi * rho * g * h * s * s / x))
        }
        None => None,
    };
    let (governs, k) = match column {
        Some((.., k_static)) if k_static >= k_kinetic => (Criterion::Static, k_static),
        _ => (Criterion::Kinetic, k_kinetic),
    };
    let t_pair = PI * (m / (2.0 * k)).sqrt();
    let t_wall = PI * (m / k).sqrt();
    let dt = match inputs.contact {
        Contact::Pair => t_pair,
        Contact::Wall => t_wall,
    } / n;
    let q = Quantity::from_si;
    let column = column.map(|(g, h, phi, k_static)| StaticEstimate {
        gravity: q(g, Acceleration),
        height: q(h, Length),
        packing: phi,
        bulk_density: q(phi * rho, Density),
        k_n: q(k_static, Stiffness),
        overlap: q(phi * rho * g * h * s * s / k, Length),
        free_fall_speed: q((2.0 * g * h).sqrt(), Speed),
    });
    let mut warnings = Vec::new();
    if n < MIN_STEPS_PER_CONTACT {
        warnings.push(format!(
            "{} steps per contact is below {MIN_STEPS_PER_CONTACT}: the rebound's restitution is 4 % low already at 10 steps, and below π/2 ≈ 1.6 the leapfrog gains energy; use 20 to 50",
            significant(n, 4)
        ));
    }
    if f > OVERLAP_LEVELS[1] {
        warnings.push(format!(
            "the allowed overlap ({} % of the radius) is above pkdgrav's major warning level, 15 % (dMajorFrac): every fast contact will warn, and the contact law is far from the rigid spheres it stands for",
            significant(100.0 * f, 4)
        ));
    } else if f > OVERLAP_LEVELS[0] {
        warnings.push(format!(
            "the allowed overlap ({} % of the radius) is above pkdgrav's minor warning level, 3 % (dMinorFrac): fast contacts will warn; allow less, or raise dMinorFrac",
            significant(100.0 * f, 4)
        ));
    }
    if let Some(c) = &column
        && c.free_fall_speed.si > v
    {
        warnings.push(format!(
            "a fall over the height reaches √(2gH) = {} m/s, faster than the maximum speed {} m/s: falling particles will overlap by more than allowed; take the maximum speed to be at least the fall's",
            significant(c.free_fall_speed.si, 5),
            significant(v, 5),
        ));
    }
    // Every value advised, in SI and in pkdgrav units, must be a positive finite number:
    // never NaN, 0 or infinity on a .par line.
    let derived = [
        ("the mass", m, Mass),
        ("the density", rho, Density),
        ("the allowed overlap", x, Length),
        ("dKn", k, Stiffness),
        ("the contact time", t_pair, Time),
        ("dDelta", dt, Time),
    ];
    for (name, value, dimension) in derived {
        let pkdgrav = q(value, dimension).pkdgrav;
        for x in [value, pkdgrav] {
            if !(x.is_finite() && x > 0.0) {
                return Err(InvalidInput {
                    name,
                    value: x,
                    must_be: "a positive finite number, in SI and in pkdgrav units",
                    derived: true,
                });
            }
        }
    }
    Ok(Advice {
        mass: q(m, Mass),
        radius: q(s, Length),
        density: q(rho, Density),
        speed: q(v, Speed),
        overlap_fraction: f,
        max_overlap: q(x, Length),
        steps_per_contact: n,
        contact: inputs.contact,
        k_n_kinetic: q(k_kinetic, Stiffness),
        column,
        governs,
        k_n: q(k, Stiffness),
        k_t: q(2.0 / 7.0 * k, Stiffness),
        contact_time_pair: q(t_pair, Time),
        contact_time_wall: q(t_wall, Time),
        dt: q(dt, Time),
        steps_per_wall_contact: t_wall / dt,
        peak_overlap_wall: q(v * (m / k).sqrt(), Length),
        peak_overlap_pair: q(v * (m / (2.0 * k)).sqrt(), Length),
        units: Units::pkdgrav(),
        warnings,
    })
}

impl Advice {
    /// The pkdgrav parameter-file lines, ready to paste: `dKn`, `dKt`, `dDelta` in
    /// pkdgrav units (`%e`, as `demparams` prints them) and `achWallsFile` when a walls
    /// file is named, each with a `#` comment giving the SI value and where it comes
    /// from. The file name is written as it is: check it with [`par_string`] first.
    pub fn par_lines(&self, walls_file: Option<&str>) -> Vec<String> {
        let criterion = match self.governs {
            Criterion::Kinetic => "kinetic",
            Criterion::Static => "static",
        };
        let contact = match self.contact {
            Contact::Pair => "pair",
            Contact::Wall => "wall",
        };
        let mut lines = vec![
            format!(
                "dKn = {:.6e}  # normal spring constant, M_sun/(yr/2pi)^2 = {} kg/s^2 ({criterion} criterion)",
                self.k_n.pkdgrav,
                significant(self.k_n.si, 6),
            ),
            format!(
                "dKt = {:.6e}  # tangential spring constant = 2/7 dKn = {} kg/s^2",
                self.k_t.pkdgrav,
                significant(self.k_t.si, 6),
            ),
            format!(
                "dDelta = {:.6e}  # timestep, yr/2pi = {} s ({contact} contact time / {})",
                self.dt.pkdgrav,
                significant(self.dt.si, 6),
                significant(self.steps_per_contact, 6),
            ),
        ];
        if let Some(file) = walls_file {
            // Unquoted: pkdgrav's parameter reader (param.c, prmParseParam) keeps a
            // string value as written up to a `#` or the line's end, quotes included,
            // and its sample ss.par writes `achInFile = ssgen.ss`.
            lines.push(format!("achWallsFile = {file}  # the walls file"));
        }
        lines
    }
}

/// `text` if pkdgrav's parameter reader reads it back unchanged as a string value, else
/// why not: it keeps everything up to a `#` or the line's end, skips leading blanks and
/// drops trailing ones, and does not remove quotes.
pub fn par_string(text: &str) -> Result<&str, &'static str> {
    if text.is_empty() {
        Err("it is empty")
    } else if text.contains('#') {
        Err("pkdgrav's parameter reader ends a value at `#`")
    } else if text.contains(['\n', '\r']) {
        Err("it spans lines")
    } else if text.trim() != text {
        Err("pkdgrav's parameter reader drops blanks at its ends")
    } else if text.contains('"') {
        Err("pkdgrav's parameter reader keeps quotes as part of the name")
    } else {
        Ok(text)
    }
}

/// `x` to `digits` significant figures, in C's `%g` style: fixed notation for exponents
/// from −4 to `digits` − 1, else `1.2345e-11`; trailing zeros dropped.
pub fn significant(x: f64, digits: usize) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let digits = digits.max(1);
    let sci = format!("{:.*e}", digits - 1, x);
    let (mantissa, exponent) = sci.split_once('e').unwrap_or((&sci, "0"));
    let exponent: i32 = exponent.parse().unwrap_or(0);
    let trim = |s: &str| -> String {
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s.to_string()
        }
    };
    if (-4..digits as i32).contains(&exponent) {
        let decimals = (digits as i32 - 1 - exponent).max(0) as usize;
        trim(&format!("{x:.decimals$}"))
    } else {
        format!("{}e{exponent}", trim(mantissa))
    }
}

/// The advice for people, as `walls-sim advise` prints it: the `inputs`, the derivation,
/// the units, then the .par lines (with an `achWallsFile` line for `walls_file`).
pub fn text(a: &Advice, inputs: &Inputs, walls_file: Option<&str>) -> String {
    use std::fmt::Write as _;
    let g = significant;
    let si = |q: &Quantity| format!("{} {}", g(q.si, 6), q.dimension.si_unit());
    let pkd = |q: &Quantity| format!("{} {}", g(q.pkdgrav, 6), q.dimension.pkdgrav_unit());
    let mut o = String::new();
    let row = |o: &mut String, name: &str, q: &Quantity, note: &str| {
        let line = format!("  {name:<22}{:<24}{:<30}{note}", si(q), pkd(q));
        let _ = writeln!(o, "{}", line.trim_end());
    };
    let given = match inputs.units {
        UnitSystem::Si => "given in SI",
        UnitSystem::Pkdgrav => "given in pkdgrav units",
    };
    let _ = writeln!(o, "Inputs ({given})\n  {:<22}{:<24}pkdgrav units", "", "SI");
    let (mass_note, density_note) = if matches!(inputs.amount, Amount::Mass(_)) {
        ("", "derived: m/(4/3·π·s³)")
    } else {
        ("derived: 4/3·π·s³·ρ", "")
    };
    row(&mut o, "mass m", &a.mass, mass_note);
    row(&mut o, "radius s", &a.radius, "");
    row(&mut o, "density ρ", &a.density, density_note);
    row(&mut o, "maximum speed v", &a.speed, "");
    row(
        &mut o,
        "allowed overlap x",
        &a.max_overlap,
        &format!("{} % of s", g(100.0 * a.overlap_fraction, 6)),
    );
    if let Some(c) = &a.column {
        row(&mut o, "gravity g", &c.gravity, "");
        row(&mut o, "pile height H", &c.height, "");
        let _ = writeln!(o, "  {:<22}{}", "packing φ", g(c.packing, 6));
    }
    let _ = writeln!(
        o,
        "  {:<22}{}",
        "steps per contact N",
        g(a.steps_per_contact, 6)
    );
    let _ = writeln!(o, "\nDerivation");
    let eq = |o: &mut String, what: &str, formula: &str, q: &Quantity| {
        let _ = writeln!(o, "  {what:<24}{formula:<18}= {}", si(q));
    };
    eq(&mut o, "kinetic k_n", "m·(v/x)²", &a.k_n_kinetic);
    match &a.column {
        Some(c) => eq(&mut o, "static k_n", "φ·ρ·g·H·s²/x", &c.k_n),
        None => {
            let _ = writeln!(
                o,
                "  {:<24}(no --gravity and --height: not estimated)",
                "static k_n"
            );
        }
    }
    let _ = writeln!(
        o,
        "  → k_n = {}: the {} criterion governs (the larger)",
        si(&a.k_n),
        match a.governs {
            Criterion::Kinetic => "kinetic",
            Criterion::Static => "static",
        }
    );
    eq(&mut o, "k_t", "2/7·k_n", &a.k_t);
    eq(
        &mut o,
        "contact, pair (μ = m/2)",
        "π·√(m/(2k_n))",
        &a.contact_time_pair,
    );
    eq(
        &mut o,
        "contact, wall (μ = m)",
        "π·√(m/k_n)",
        &a.contact_time_wall,
    );
    let resolved = match a.contact {
        Contact::Pair => "pair",
        Contact::Wall => "wall",
    };
    let _ = writeln!(
        o,
        "  {:<24}{:<18}= {} ({} steps per wall contact)",
        "dt",
        format!("{resolved} contact/{}", g(a.steps_per_contact, 6)),
        si(&a.dt),
        g(a.steps_per_wall_contact, 4)
    );
    let percent = |q: &Quantity| g(100.0 * q.si / a.radius.si, 4);
    let _ = writeln!(
        o,
        "  peak overlap at v: {} against a wall ({} % of s), {} between two particles ({} %)",
        si(&a.peak_overlap_wall),
        percent(&a.peak_overlap_wall),
        si(&a.peak_overlap_pair),
        percent(&a.peak_overlap_pair),
    );
    if let Some(c) = &a.column {
        let _ = writeln!(
            o,
            "  at rest at the pile's bottom: {} ({} % of s); a fall over H reaches √(2gH) = {}",
            si(&c.overlap),
            percent(&c.overlap),
            si(&c.free_fall_speed),
        );
    }
    let u = &a.units;
    let set = &pkdgrav_units::TOOLKIT;
    let _ = writeln!(
        o,
        "\nUnits: pkdgrav's AU, solar mass and year over 2pi, as pkdgrav's {} gives them ({})\n  1 AU = {} m; 1 M_sun = {} kg; 1 yr/2pi = {} s (as --units si)\n  G = 1 in these units: G = {} m^3/(kg s^2)\n  k_n: 1 M_sun/(yr/2pi)^2 = {} kg/s^2; dt: 1 yr/2pi = {} s\n  a walls file in SI units: lengthunit {}  massunit {}  timeunit {}",
        set.source,
        set.used_by,
        g(u.length, 10),
        g(u.mass, 6),
        g(u.time, 9),
        g(pkdgrav_units::TOOLKIT_G_SI, 6),
        g(u.factor(Dimension::Stiffness), 6),
        g(u.time, 6),
        g(1.0 / u.length, 6),
        g(1.0 / u.mass, 6),
        g(1.0 / u.time, 6),
    );
    let _ = writeln!(o, "\n# pkdgrav parameters: paste into the .par file");
    for line in a.par_lines(walls_file) {
        let _ = writeln!(o, "{line}");
    }
    o
}

/// The advice as JSON (`walls-sim advise --json`), with its newline: every quantity as
/// {si, pkdgrav, si_unit, pkdgrav_unit}.
pub fn json(a: &Advice, inputs: &Inputs, walls_file: Option<&str>) -> String {
    use serde_json::{Value, json};
    let q = |q: &Quantity| {
        json!({
            "si": q.si,
            "pkdgrav": q.pkdgrav,
            "si_unit": q.dimension.si_unit(),
            "pkdgrav_unit": q.dimension.pkdgrav_unit(),
        })
    };
    let column = a.column.as_ref();
    let u = &a.units;
    let mut par = json!({
        "dKn": a.k_n.pkdgrav,
        "dKt": a.k_t.pkdgrav,
        "dDelta": a.dt.pkdgrav,
    });
    if let (Some(file), Value::Object(map)) = (walls_file, &mut par) {
        map.insert("achWallsFile".into(), json!(file));
    }
    let value = json!({
        "inputs": {
            "units": match inputs.units { UnitSystem::Si => "si", UnitSystem::Pkdgrav => "pkdgrav" },
            "mass": q(&a.mass),
            "radius": q(&a.radius),
            "density": q(&a.density),
            "speed": q(&a.speed),
            "overlap": a.overlap_fraction,
            "max_overlap": q(&a.max_overlap),
            "gravity": column.map(|c| q(&c.gravity)),
            "height": column.map(|c| q(&c.height)),
            "packing": column.map(|c| c.packing),
            "steps_per_contact": a.steps_per_contact,
            "contact": match a.contact { Contact::Pair => "pair", Contact::Wall => "wall" },
        },
        "k_n_kinetic": q(&a.k_n_kinetic),
        "k_n_static": column.map(|c| q(&c.k_n)),
        "governs": match a.governs { Criterion::Kinetic => "kinetic", Criterion::Static => "static" },
        "k_n": q(&a.k_n),
        "k_t": q(&a.k_t),
        "contact_time": {"pair": q(&a.contact_time_pair), "wall": q(&a.contact_time_wall)},
        "dt": q(&a.dt),
        "steps_per_wall_contact": a.steps_per_wall_contact,
        "peak_overlap": {
            "wall": q(&a.peak_overlap_wall),
            "pair": q(&a.peak_overlap_pair),
            "pile": column.map(|c| q(&c.overlap)),
        },
        "free_fall_speed": column.map(|c| q(&c.free_fall_speed)),
        "units": {
            "set": pkdgrav_units::TOOLKIT.source,
            "length_m": u.length,
            "mass_kg": u.mass,
            "time_s": u.time,
            "g_si": pkdgrav_units::TOOLKIT_G_SI,
            "walls_file_in_si": {
                "lengthunit": 1.0 / u.length,
                "massunit": 1.0 / u.mass,
                "timeunit": 1.0 / u.time,
            },
        },
        "par": par,
        "par_lines": a.par_lines(walls_file),
        "warnings": a.warnings,
    });
    match serde_json::to_string_pretty(&value) {
        Ok(text) => text + "\n",
        Err(e) => unreachable!("JSON of numbers and strings: {e}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// pkdgrav's `etc/resample/sample/demparams.log`: its inputs in SI.
    fn demparams() -> Inputs {
        Inputs {
            column: Some(Column {
                gravity: 2.26032e-6,
                height: 10.0,
                packing: 0.65,
            }),
            ..Inputs::new(Amount::Mass(2.26195e5), 1.00377, 0.03)
        }
    }

    /// Equal to `digits` significant figures.
    fn same(a: f64, b: f64, digits: i32) -> bool {
        (a - b).abs() <= 0.5 * 10f64.powi(b.abs().log10().floor() as i32 - digits + 1)
    }

    /// Within a relative `tolerance`.
    fn near(a: f64, b: f64, tolerance: f64) -> bool {
        ((a - b) / b).abs() <= tolerance
    }

    #[test]
    fn reproduces_the_demparams_worked_example() {
        // The log prints its inputs to 6 significant figures, so its results are matched
        // to 2e-5; then to 4 significant figures.
        let a = advise(&demparams()).unwrap();
        let column = a.column.unwrap();
        // "Kinetic dKn = 2.020492e+06 kg/s^2 (recommended)"
        assert!(
            near(a.k_n_kinetic.si, 2.020492e6, 2e-5),
            "{}",
            a.k_n_kinetic.si
        );
        assert_eq!(a.governs, Criterion::Kinetic);
        assert_eq!(a.k_n.si, a.k_n_kinetic.si);
        // "Static dKn = 7.874261e+01 kg/s^2", from φ = 0.65, g = 2.26032e-6, H = 10 m.
        assert!(near(column.k_n.si, 78.74261, 2e-5), "{}", column.k_n.si);
        // "Typical overlap duration = 0.743272 s" (μ = m/2).
        assert!(near(a.contact_time_pair.si, 0.743272, 2e-5));
        // "dDelta (for recommended dKn) = 2.477574e-02 s" at 30 steps.
        assert!(near(a.dt.si, 2.477574e-2, 2e-5), "{}", a.dt.si);
        // "[DERIVED] Particle density = 53.3939 g/cc", "Bulk density = 34.706 g/cc".
        assert!(near(a.density.si, 53393.9, 2e-5));
        assert!(near(column.bulk_density.si, 34706.0, 2e-5));
        // "free-fall speed = 0.672357 cm/s": slower than v, so no warning.
        assert!(near(column.free_fall_speed.si, 0.00672357, 2e-5));
        assert!(a.warnings.is_empty(), "{:?}", a.warnings);
        // To 4 significant figures: k_n 2.020e6 (2.0205e6), t_c 0.7433 s, dt 0.02478 s
        // (0.024776), static k_n 78.74.
        assert!(same(a.k_n.si, 2.020e6, 4) && same(a.dt.si, 0.02478, 4));
        assert!(same(a.contact_time_pair.si, 0.7433, 4) && same(column.k_n.si, 78.74, 4));
    }

    #[test]
    fn demparams_own_units_give_its_pkdgrav_figures() {
        // demparams converts with its own set (§13): "2.562490e-11 M_Sun/(yr/2pi)^2",
        // "4.932949e-09 yr/2pi", "9.986537e-16". With that set the advice's SI values
        // give them to the log's inputs' 2e-5; the toolkit's set differs by its
        // rounding, under 4e-4.
        let a = advise(&demparams()).unwrap();
        let theirs = Units::of(&pkdgrav_units::DEMPARAMS).unwrap();
        let k_static = a.column.unwrap().k_n;
        for (q, log) in [
            (a.k_n, 2.562490e-11),
            (a.dt, 4.932949e-9),
            (k_static, 9.986537e-16),
        ] {
            assert!(near(theirs.from_si(q.si, q.dimension), log, 2e-5), "{q:?}");
            assert!(near(q.pkdgrav, log, 4e-4), "{q:?}");
        }
    }

    #[test]
    fn pkdgrav_units_are_the_toolkits_and_convert_both_ways() {
        let u = Units::pkdgrav();
        assert_eq!(Units::of(&pkdgrav_units::TOOLKIT), Some(u));
        // G in pkdgrav units: m³/(kg·s²) → AU³/(M☉·(yr/2π)²), 1 to 10⁻¹⁵ for the G the
        // units make 1, 0.99999 for CODATA's (§13).
        let g = |g_si: f64| g_si * u.mass * u.time.powi(2) / u.length.powi(3);
        assert!((g(pkdgrav_units::TOOLKIT_G_SI) - 1.0).abs() < 1e-15);
        assert_eq!(format!("{:.5}", g(pkdgrav_units::G_SI)), "0.99999");
        // A year of 2π time units is within a day of the Julian year.
        assert!((2.0 * std::f64::consts::PI * u.time / 86_400.0 - 365.25).abs() < 1.0);
        use Dimension::*;
        for d in [Mass, Length, Time, Speed, Acceleration, Density, Stiffness] {
            for x in [1e-30, 0.024776, 1.0, 2.0205e6, 1e30] {
                let there = u.from_si(x, d);
                let back = u.to_si(there, d);
                assert!(
                    ((back - x) / x).abs() < 1e-15,
                    "{d:?} {x} → {there} → {back}"
                );
            }
        }
        // Known values: 1 km/s = 0.0336 AU/(yr/2π) (Earth's 29.8 km/s is about 1).
        assert!((u.from_si(29_784.7, Speed) - 1.0).abs() < 1e-3);
        assert_eq!(u.from_si(pkdgrav_units::AU_M, Length), 1.0);
        assert_eq!(u.to_si(1.0, Mass), pkdgrav_units::SOLAR_MASS_KG);
    }

    #[test]
    fn inputs_in_pkdgrav_units_give_the_same_advice() {
        let si = demparams();
        let u = Units::pkdgrav();
        let c = si.column.unwrap();
        let pkd = Inputs {
            units: UnitSystem::Pkdgrav,
            amount: Amount::Mass(u.from_si(2.26195e5, Dimension::Mass)),
            radius: u.from_si(si.radius, Dimension::Length),
            speed: u.from_si(si.speed, Dimension::Speed),
            column: Some(Column {
                gravity: u.from_si(c.gravity, Dimension::Acceleration),
                height: u.from_si(c.height, Dimension::Length),
                packing: c.packing,
            }),
            ..si
        };
        let (a, b) = (advise(&si).unwrap(), advise(&pkd).unwrap());
        for (x, y) in [(a.k_n, b.k_n), (a.dt, b.dt), (a.k_t, b.k_t)] {
            assert!(((x.si - y.si) / x.si).abs() < 1e-12);
            assert!(((x.pkdgrav - y.pkdgrav) / x.pkdgrav).abs() < 1e-12);
        }
    }

    #[test]
    fn density_gives_the_mass_and_a_heavy_pile_governs() {
        // 1 cm glass bead (2500 kg/m³) at 1 m/s under a 1 m pile in Earth gravity.
        let inputs = Inputs {
            column: Some(Column {
                gravity: 9.81,
                height: 1.0,
                packing: DEFAULT_PACKING,
            }),
            ..Inputs::new(Amount::Density(2500.0), 0.01, 0.01)
        };
        let a = advise(&inputs).unwrap();
        let m = 4.0 / 3.0 * std::f64::consts::PI * 1e-6 * 2500.0;
        assert!(((a.mass.si - m) / m).abs() < 1e-14);
        // Kinetic m·(0.01/1e-4)² = 104.7; static ≈ 65·ρ·g·H·s = 15,941.
        let column = a.column.unwrap();
        assert!(same(column.k_n.si, 65.0 * 2500.0 * 9.81 * 0.01, 12));
        assert_eq!(a.governs, Criterion::Static);
        assert_eq!(a.k_n.si, column.k_n.si);
        // The pile's bottom then overlaps by exactly the allowed 1 %.
        assert!(((column.overlap.si - 1e-4) / 1e-4).abs() < 1e-12);
        // A fall over 1 m reaches 4.4 m/s, far above 1 cm/s.
        assert_eq!(a.warnings.len(), 1, "{:?}", a.warnings);
        assert!(a.warnings[0].contains("√(2gH) = 4.4294 m/s"));
    }

    #[test]
    fn contact_times_and_overlaps() {
        let a = advise(&Inputs::new(Amount::Mass(1.0), 1.0, 1.0)).unwrap();
        // k_n = 1·(1/0.01)² = 10⁴; pair π·√(1/(2·10⁴)), wall √2 longer.
        assert!(same(a.k_n.si, 1e4, 15));
        assert!(same(a.k_t.si, 1e4 * 2.0 / 7.0, 15));
        let pair = std::f64::consts::PI * (0.5e-4f64).sqrt();
        assert!(same(a.contact_time_pair.si, pair, 15));
        assert!(same(a.contact_time_wall.si, pair * 2f64.sqrt(), 15));
        assert!(same(a.dt.si, pair / 30.0, 15));
        assert!(same(a.steps_per_wall_contact, 30.0 * 2f64.sqrt(), 14));
        // The kinetic k_n stops a wall impact at v within exactly the allowed overlap.
        assert!(same(a.peak_overlap_wall.si, 0.01, 14));
        assert!(same(a.peak_overlap_pair.si, 0.01 / 2f64.sqrt(), 14));
        // Walls only: dt resolves the longer wall contact.
        let walls = advise(&Inputs {
            contact: Contact::Wall,
            ..Inputs::new(Amount::Mass(1.0), 1.0, 1.0)
        })
        .unwrap();
        assert!(same(walls.dt.si, pair * 2f64.sqrt() / 30.0, 14));
        assert!(same(walls.steps_per_wall_contact, 30.0, 14));
    }

    #[test]
    fn warnings() {
        let base = Inputs::new(Amount::Mass(1.0), 1.0, 1.0);
        let few = advise(&Inputs {
            steps_per_contact: 5.0,
            ..base
        })
        .unwrap();
        assert!(few.warnings[0].starts_with("5 steps per contact is below 10"));
        let loose = advise(&Inputs {
            overlap: 0.05,
            ..base
        })
        .unwrap();
        assert!(loose.warnings[0].contains("5 % of the radius) is above pkdgrav's minor"));
        let looser = advise(&Inputs {
            overlap: 0.2,
            ..base
        })
        .unwrap();
        assert_eq!(looser.warnings.len(), 1);
        assert!(looser.warnings[0].contains("20 % of the radius) is above pkdgrav's major"));
        assert!(
            advise(&Inputs {
                overlap: 0.03,
                ..base
            })
            .unwrap()
            .warnings
            .is_empty()
        );
    }

    #[test]
    fn refuses_values_outside_their_range() {
        let base = Inputs::new(Amount::Mass(1.0), 1.0, 1.0);
        let name = |inputs: Inputs| advise(&inputs).unwrap_err().name;
        assert_eq!(
            name(Inputs {
                radius: 0.0,
                ..base
            }),
            "radius"
        );
        assert_eq!(
            name(Inputs {
                amount: Amount::Mass(-1.0),
                ..base
            }),
            "mass"
        );
        assert_eq!(
            name(Inputs {
                amount: Amount::Density(f64::NAN),
                ..base
            }),
            "density"
        );
        assert_eq!(
            name(Inputs {
                speed: f64::INFINITY,
                ..base
            }),
            "speed"
        );
        assert_eq!(
            name(Inputs {
                overlap: 0.5,
                ..base
            }),
            "overlap"
        );
        assert_eq!(
            name(Inputs {
                steps_per_contact: 0.0,
                ..base
            }),
            "steps-per-contact"
        );
        let pile = |gravity, height, packing| Inputs {
            column: Some(Column {
                gravity,
                height,
                packing,
            }),
            ..base
        };
        assert_eq!(name(pile(0.0, 1.0, 0.6)), "gravity");
        assert_eq!(name(pile(1.0, -1.0, 0.6)), "height");
        assert_eq!(name(pile(1.0, 1.0, 1.5)), "packing");
        let e = advise(&Inputs {
            overlap: 0.7,
            ..base
        })
        .unwrap_err();
        assert!(
            e.to_string()
                .starts_with("overlap is 0.7; it must be above 0 and below 0.5")
        );
    }

    #[test]
    fn extreme_inputs_give_no_nan_zero_or_infinite_advice() {
        for (mass, radius, speed) in [
            (1e-300, 1e300, 1.0),
            (1e300, 1e-300, 1e300),
            (1.0, 1e-300, 1e-300),
        ] {
            let e = advise(&Inputs {
                amount: Amount::Mass(mass),
                radius,
                speed,
                ..demparams()
            })
            .unwrap_err();
            assert!(e.derived, "{e}");
            assert!(e.to_string().starts_with("these inputs give "), "{e}");
        }
    }

    #[test]
    fn par_lines() {
        let a = advise(&demparams()).unwrap();
        let lines = a.par_lines(Some("box.walls"));
        assert_eq!(lines.len(), 4);
        assert!(lines[0].starts_with("dKn = 2.563"), "{}", lines[0]);
        assert!(lines[0].ends_with("= 2.02049e6 kg/s^2 (kinetic criterion)"));
        assert!(lines[2].starts_with("dDelta = 4.93"), "{}", lines[2]);
        assert!(lines[2].contains("= 0.0247757 s (pair contact time / 30)"));
        assert_eq!(lines[3], "achWallsFile = box.walls  # the walls file");
        assert_eq!(a.par_lines(None).len(), 3);
        assert_eq!(par_string("walls/my box.dat"), Ok("walls/my box.dat"));
        for bad in ["", "a#b", " a", "a ", "\"a\"", "a\nb"] {
            assert!(par_string(bad).is_err(), "{bad:?}");
        }
    }

    #[test]
    fn significant_figures() {
        assert_eq!(significant(2.020492e6, 5), "2.0205e6");
        assert_eq!(significant(0.02477574, 5), "0.024776");
        assert_eq!(significant(78.74261, 4), "78.74");
        assert_eq!(significant(9.99999, 3), "10");
        assert_eq!(significant(99999.9, 3), "1e5");
        assert_eq!(significant(1e-5, 3), "1e-5");
        assert_eq!(significant(-0.5, 3), "-0.5");
        assert_eq!(significant(30.0, 6), "30");
    }
}
