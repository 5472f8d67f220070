//! Units people read: pkdgrav's numbers shown in centimetres and seconds (or metres),
//! for the previews, the run's summary and the pages (docs/units.md).
//!
//! pkdgrav works in units where G = 1: the astronomical unit, the Sun's mass, and a
//! year over 2π. Their values in SI are `walls_keywords::pkdgrav_units::TOOLKIT`, the set
//! of pkdgrav's `ss.h` (docs/pkdgrav-physics.md §13), which `walls-sim advise` uses too.
//! A walls file that sets `lengthunit 6.68459e-14` speaks in centimetres.
//! [`Readout::new`] picks what to show: with [`System::Auto`] pkdgrav's number and,
//! when the file sets units, the same in the file's own (`2.927e-7 (1.47 s)`);
//! otherwise only the system asked for; [`Readout::picture`], a picture's, shows such a
//! file in its physical units alone (`t = 1.47 s`). When a file's unit is within 1 % of the
//! system's (`lengthunit 6.68445e-14` for the 6.68459e-14 of a centimetre), the file's
//! factor is used, so that what the file says reads back as written (5.5 cm, not
//! 5.49988 cm).

use walls_keywords::pkdgrav_units;
use walls_model::Units;

/// One astronomical unit in centimetres (`pkdgrav_units::AU_M`).
pub const AU_CM: f64 = pkdgrav_units::AU_M * 100.0;
/// The Sun's mass in grams (`pkdgrav_units::SOLAR_MASS_KG`).
pub const M_SUN_G: f64 = pkdgrav_units::SOLAR_MASS_KG * 1000.0;
/// pkdgrav's time unit in seconds (`pkdgrav_units::TIME_UNIT_S`).
pub const TIME_UNIT_S: f64 = pkdgrav_units::TIME_UNIT_S;

/// The systems of units a reader can ask for (`--units` of `walls-sim run` and
/// `preview`: each variant's first paragraph is its help, docs/units.md).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum System {
    /// pkdgrav's units, and the walls file's own beside them when it sets some.
    #[default]
    Auto,
    /// pkdgrav's units alone (AU, solar masses, a year over 2π).
    Pkdgrav,
    /// Centimetres, grams, seconds.
    Cgs,
    /// Metres, kilograms, seconds.
    Si,
}

/// One quantity's unit: its name and how many of it make a pkdgrav unit.
#[derive(Debug, Clone, PartialEq)]
pub struct Unit {
    /// As printed after a number (`cm`, `s`); empty for pkdgrav's.
    pub name: &'static str,
    /// This unit's value of one pkdgrav unit: shown = pkdgrav × `per_pkdgrav`.
    pub per_pkdgrav: f64,
}

impl Unit {
    const PKDGRAV: Unit = Unit {
        name: "",
        per_pkdgrav: 1.0,
    };

    /// `x` (pkdgrav units) in this unit.
    pub fn of(&self, x: f64) -> f64 {
        x * self.per_pkdgrav
    }
}

/// Lengths, masses and times of one system.
#[derive(Debug, Clone, PartialEq)]
pub struct Scale {
    /// Lengths.
    pub length: Unit,
    /// Masses.
    pub mass: Unit,
    /// Times.
    pub time: Unit,
}

impl Scale {
    /// pkdgrav's own units.
    pub const PKDGRAV: Scale = Scale {
        length: Unit::PKDGRAV,
        mass: Unit::PKDGRAV,
        time: Unit::PKDGRAV,
    };

    /// Centimetres, grams and seconds, or metres, kilograms and seconds (`si`), taking
    /// the file's factor for a unit within 1 % of either system's, else the toolkit's
    /// constants as they are.
    fn physical(si: bool, file: &Units) -> Scale {
        let own = file_base(file);
        let (cm, g) = if si { (100.0, 1000.0) } else { (1.0, 1.0) };
        let per = |own: Option<f64>, per: f64, standard: f64| match own {
            Some(own) => 1.0 / (per * own),
            None => standard,
        };
        Scale {
            length: Unit {
                name: if si { "m" } else { "cm" },
                per_pkdgrav: per(own.length, cm, AU_CM / cm),
            },
            mass: Unit {
                name: if si { "kg" } else { "g" },
                per_pkdgrav: per(
                    own.mass,
                    g,
                    if si {
                        pkdgrav_units::SOLAR_MASS_KG
                    } else {
                        M_SUN_G
                    },
                ),
            },
            time: Unit {
                name: "s",
                per_pkdgrav: per(own.time, 1.0, TIME_UNIT_S),
            },
        }
    }

    /// The file's own units, named after the unit of either system they are (within
    /// 1 %), else "file units"; pkdgrav's (no name) for a unit the file leaves at 1.
    fn of_file(file: &Units) -> Scale {
        let base = cgs_base(file);
        let name = |factor: f64, base: f64, names: [(&'static str, f64); 2]| {
            let near = |x: f64| (factor / (x * base) - 1.0).abs() < 1e-12;
            if factor == 1.0 {
                ""
            } else if near(names[0].1) {
                names[0].0
            } else if near(names[1].1) {
                names[1].0
            } else {
                "file units"
            }
        };
        Scale {
            length: Unit {
                name: name(file.length, base.length, [("cm", 1.0), ("m", 100.0)]),
                per_pkdgrav: 1.0 / file.length,
            },
            mass: Unit {
                name: name(file.mass, base.mass, [("g", 1.0), ("kg", 1000.0)]),
                per_pkdgrav: 1.0 / file.mass,
            },
            time: Unit {
                name: name(file.time, base.time, [("s", 1.0), ("s", 1.0)]),
                per_pkdgrav: 1.0 / file.time,
            },
        }
    }
}

/// pkdgrav units per centimetre, gram and second: from the constants, or the file's
/// own factor where it is within 1 % of the centimetre or metre, gram or kilogram,
/// second.
fn cgs_base(file: &Units) -> Units {
    let own = file_base(file);
    Units {
        length: own.length.unwrap_or(1.0 / AU_CM),
        mass: own.mass.unwrap_or(1.0 / M_SUN_G),
        time: own.time.unwrap_or(1.0 / TIME_UNIT_S),
    }
}

/// The file's own pkdgrav units per centimetre, gram and second, for each unit within
/// 1 % of the centimetre or metre, gram or kilogram, second; `None` for the others.
fn file_base(file: &Units) -> FileBase {
    let pick = |standard: f64, file: f64, larger: f64| {
        if (file / standard - 1.0).abs() < 0.01 {
            Some(file)
        } else if (file / (larger * standard) - 1.0).abs() < 0.01 {
            Some(file / larger)
        } else {
            None
        }
    };
    FileBase {
        length: pick(1.0 / AU_CM, file.length, 100.0),
        mass: pick(1.0 / M_SUN_G, file.mass, 1000.0),
        time: pick(1.0 / TIME_UNIT_S, file.time, 1.0),
    }
}

/// [`file_base`]'s answer: a file's factor per centimetre, gram and second, where it
/// sets one near them.
struct FileBase {
    length: Option<f64>,
    mass: Option<f64>,
    time: Option<f64>,
}

/// How numbers are shown: in one system, and maybe pkdgrav's beside it.
#[derive(Debug, Clone, PartialEq)]
pub struct Readout {
    /// The units shown.
    pub scale: Scale,
    /// Whether pkdgrav's number comes first, with `scale`'s in brackets.
    pub with_pkdgrav: bool,
}

impl Readout {
    /// The readout of `system` for a file whose units are `file`.
    pub fn new(system: System, file: &Units) -> Readout {
        match system {
            System::Auto if file.are_set() => Readout {
                scale: Scale::of_file(file),
                with_pkdgrav: true,
            },
            System::Auto | System::Pkdgrav => Readout {
                scale: Scale::PKDGRAV,
                with_pkdgrav: false,
            },
            System::Cgs => Readout {
                scale: Scale::physical(false, file),
                with_pkdgrav: false,
            },
            System::Si => Readout {
                scale: Scale::physical(true, file),
                with_pkdgrav: false,
            },
        }
    }

    /// The readout of a picture (`walls-sim preview`'s labels, its HTML page) in
    /// `system` for a file whose units are `file`: as [`Readout::new`], except that with
    /// [`System::Auto`] a file that sets units is shown in physical units alone, as its
    /// reader thinks of it: times in seconds (`t = 1.47 s`, whether or not it sets a
    /// `timeunit`), lengths in metres when its `lengthunit` is a metre, else in
    /// centimetres, each unit near the file's taken as [`System::Cgs`] takes it.
    pub fn picture(system: System, file: &Units) -> Readout {
        match system {
            System::Auto if file.are_set() => Readout {
                scale: Scale::physical(Scale::of_file(file).length.name == "m", file),
                with_pkdgrav: false,
            },
            _ => Readout::new(system, file),
        }
    }

    /// A time `t` (pkdgrav units) as shown: `1.47 s`, `2.927e-7 (1.47 s)` or `2.927e-7`.
    pub fn time(&self, t: f64) -> String {
        self.show(t, &self.scale.time)
    }

    /// A length `x` (pkdgrav units) as shown.
    pub fn length(&self, x: f64) -> String {
        self.show(x, &self.scale.length)
    }

    /// A mass `m` (pkdgrav units) as shown.
    pub fn mass(&self, m: f64) -> String {
        self.show(m, &self.scale.mass)
    }

    fn show(&self, x: f64, unit: &Unit) -> String {
        let own = if unit.name.is_empty() {
            number(unit.of(x))
        } else {
            format!("{} {}", number(unit.of(x)), unit.name)
        };
        if self.with_pkdgrav && unit.name.is_empty() {
            number(x)
        } else if self.with_pkdgrav {
            format!("{} ({own})", number(x))
        } else {
            own
        }
    }
}

/// `x` to four significant figures, as people write it: `1.47`, `5.5`, `0.0123`,
/// `50230`, `2.927e-7`, `1.2e6`.
pub fn number(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let exponent = x.abs().log10().floor() as i32;
    if (-3..6).contains(&exponent) {
        let decimals = (3 - exponent).max(0) as usize;
        // Above 9999, the digits past the fourth are rounded to zeros: 502,264 s is
        // `502300`, as it is `5.023e5` further up.
        let x = if exponent > 3 {
            let step = 10f64.powi(exponent - 3);
            (x / step).round() * step
        } else {
            x
        };
        let s = format!("{x:.decimals$}");
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    } else {
        let s = format!("{x:.3e}");
        let (m, e) = s.split_once('e').expect("an exponent");
        let m = if m.contains('.') {
            m.trim_end_matches('0').trim_end_matches('.')
        } else {
            m
        };
        format!("{m}e{e}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// pkdgrav's own `tests/orientation/cylinder` units: centimetres, grams, seconds.
    fn cgs_file() -> Units {
        Units {
            length: 6.68445e-14,
            mass: 5.02739933e-34,
            time: 1.99102e-7,
        }
    }

    #[test]
    fn numbers_read_as_people_write_them() {
        for (x, s) in [
            (1.47, "1.47"),
            (5.5, "5.5"),
            (0.012345, "0.01235"),
            (2.9268e-7, "2.927e-7"),
            (1_234_567.0, "1.235e6"),
            (100.0, "100"),
            (50_226.355, "50230"),
            (502_264.0, "502300"),
            (-3.0, "-3"),
            (0.0, "0"),
        ] {
            assert_eq!(number(x), s, "{x}");
        }
    }

    #[test]
    fn a_centimetre_file_reads_back_as_written() {
        let file = cgs_file();
        let auto = Readout::new(System::Auto, &file);
        assert_eq!(auto.length(5.5 * file.length), "3.676e-13 (5.5 cm)");
        assert_eq!(auto.time(1.47 * file.time), "2.927e-7 (1.47 s)");
        assert_eq!(auto.mass(2.0 * file.mass), "1.005e-33 (2 g)");
        let cgs = Readout::new(System::Cgs, &file);
        assert_eq!(cgs.length(5.5 * file.length), "5.5 cm");
        let si = Readout::new(System::Si, &file);
        assert_eq!(si.length(5.5 * file.length), "0.055 m");
        assert_eq!(si.mass(2.0 * file.mass), "0.002 kg");
        let pkdgrav = Readout::new(System::Pkdgrav, &file);
        assert_eq!(pkdgrav.time(1.47 * file.time), "2.927e-7");
    }

    #[test]
    fn units_of_no_system_are_the_files() {
        let odd = Units {
            length: 1e-3,
            ..Units::default()
        };
        let auto = Readout::new(System::Auto, &odd);
        assert_eq!(auto.length(2e-3), "0.002 (2 file units)");
        assert_eq!(
            auto.time(2.0),
            "2",
            "the file leaves time in pkdgrav's unit"
        );
    }
}
