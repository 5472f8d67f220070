//! pkdgrav's unit system in SI: the one place the toolkit writes its constants.
//!
//! pkdgrav works with G = 1, lengths in astronomical units, masses in solar masses and
//! time in a year over 2π. Its conversions to SI are not one set of numbers: each part of
//! pkdgrav's tree carries its own copy (docs/pkdgrav-physics.md §13). [`SETS`] holds them
//! all, each [`UnitSet`] as §13 gives it; [`TOOLKIT`] is the one every walls tool converts
//! with: `walls-sim advise`, `--units si` and `--units cgs` (`walls_geometry::units`), and
//! the length units of `walls-build`.
//!
//! The toolkit uses `ss.h`'s set ([`SS_H`]): it is the set of the ss tools that make and
//! read pkdgrav's particle files and draw them (ssgen, ssinfo, ssdraw), and its AU is the
//! IAU's exact one. With it, G = 1 holds to 8 × 10⁻⁶, not exactly ([`G_SI`]).
//!
//! A walls file's own `lengthunit`, `massunit` and `timeunit` are the user's statement of
//! their units: where a file gives them, they, not these sets, say what its units are.

use std::f64::consts::TAU;

/// One part of pkdgrav's tree and what its units are in SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct UnitSet {
    /// The pkdgrav file that defines the set (`ss.h`).
    pub source: &'static str,
    /// Which pkdgrav tools use it.
    pub used_by: &'static str,
    /// Metres in an astronomical unit.
    pub au_m: f64,
    /// Kilograms in a solar mass.
    pub solar_mass_kg: f64,
    /// How the set gives pkdgrav's time unit.
    pub time: Time,
}

/// How a set gives pkdgrav's time unit (a year over 2π).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Time {
    /// As a year in seconds: the time unit is the year over 2π.
    Year(f64),
    /// As the time unit itself, in seconds.
    Unit(f64),
    /// Not at all.
    Unstated,
}

impl UnitSet {
    /// Seconds in pkdgrav's time unit, if the set gives it: a year over 2π.
    pub const fn time_unit_s(&self) -> Option<f64> {
        match self.time {
            Time::Year(year) => Some(year / TAU),
            Time::Unit(unit) => Some(unit),
            Time::Unstated => None,
        }
    }

    /// Newton's constant in m³/(kg·s²) that these units make exactly 1,
    /// AU³/(M☉·unit²), if the set gives a time unit.
    pub const fn g_si(&self) -> Option<f64> {
        match self.time_unit_s() {
            Some(t) => Some(self.au_m * self.au_m * self.au_m / (self.solar_mass_kg * t * t)),
            None => None,
        }
    }
}

/// `ss.h`'s set (§13), used by the ss tools (ssgen, ssdraw, ssinfo …): AU =
/// 1.495978707e11 m, M☉ = 1.9884e30 kg, the time unit SID_YR / 2π with the sidereal
/// year SID_YR = 3.15581497635e7 s, so 5,022,635.53 s. (Its comment says the unit
/// "was JD / GAUSS_K", 86400 / 0.01720209895 s: 1.5 × 10⁻⁶ longer.)
pub const SS_H: UnitSet = UnitSet {
    source: "ss.h",
    used_by: "the ss tools: ssgen, ssdraw, ssinfo",
    au_m: 1.495_978_707e11,
    solar_mass_kg: 1.9884e30,
    time: Time::Year(3.155_814_976_35e7),
};

/// `demparams.c`'s set (§13), the dKn / dDelta helper's: AU = 1.496e11 m, M☉ =
/// 1.989e30 kg, the time unit 5.0225e6 s.
pub const DEMPARAMS: UnitSet = UnitSet {
    source: "demparams.c",
    used_by: "demparams, the dKn / dDelta helper",
    au_m: 1.496e11,
    solar_mass_kg: 1.989e30,
    time: Time::Unit(5.0225e6),
};

/// `aggs.c`'s set (§13), the aggregates': AU = 1.49597870e11 m, M☉ = 1.9891e30 kg, the
/// time unit 3.15581497632e7 / 2π s.
pub const AGGS: UnitSet = UnitSet {
    source: "aggs.c",
    used_by: "pkdgrav's aggregates (AGGS)",
    au_m: 1.495_978_70e11,
    solar_mass_kg: 1.9891e30,
    time: Time::Year(3.155_814_976_32e7),
};

/// `rubble.h`'s and `collmod.h`'s set (§13): AU = 1.49597870e11 m, M☉ = 1.9891e30 kg,
/// no time unit.
pub const RUBBLE: UnitSet = UnitSet {
    source: "rubble.h, collmod.h",
    used_by: "the parts of pkdgrav that include them",
    au_m: 1.495_978_70e11,
    solar_mass_kg: 1.9891e30,
    time: Time::Unstated,
};

/// `grdrag.c`'s set (§13), which §13 gives in cgs: AU = 1.49598e13 cm, M☉ =
/// 1.98892e33 g, a year of 31558207.07 s (here in metres and kilograms, the same digits).
pub const GRDRAG: UnitSet = UnitSet {
    source: "grdrag.c",
    used_by: "grdrag.c",
    au_m: 1.49598e11,
    solar_mass_kg: 1.98892e30,
    time: Time::Year(31_558_207.07),
};

/// Every set of §13, in its order.
pub const SETS: [UnitSet; 5] = [SS_H, DEMPARAMS, AGGS, RUBBLE, GRDRAG];

/// The set every walls tool converts with: [`SS_H`].
pub const TOOLKIT: UnitSet = SS_H;

/// Metres in the toolkit's astronomical unit.
pub const AU_M: f64 = TOOLKIT.au_m;

/// Kilograms in the toolkit's solar mass.
pub const SOLAR_MASS_KG: f64 = TOOLKIT.solar_mass_kg;

/// Seconds in the toolkit's time unit, a year over 2π.
pub const TIME_UNIT_S: f64 = match TOOLKIT.time_unit_s() {
    Some(t) => t,
    None => panic!("the toolkit's set gives a time unit"),
};

/// Newton's constant in m³/(kg·s²) that the toolkit's units make exactly 1.
pub const TOOLKIT_G_SI: f64 = match TOOLKIT.g_si() {
    Some(g) => g,
    None => panic!("the toolkit's set gives a time unit"),
};

/// Newton's constant in m³/(kg·s²) as §13 uses it (CODATA 2018): with [`SS_H`]'s units
/// it is 0.99999, not exactly 1.
pub const G_SI: f64 = 6.6743e-11;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_toolkits_set_is_ss_h() {
        assert_eq!(TOOLKIT, SS_H);
        assert_eq!(
            (AU_M, SOLAR_MASS_KG),
            (1.495_978_707e11, 1.9884e30),
            "§13's ss.h row"
        );
        // §13: "so 5,022,635.53 s"; JD / GAUSS_K would be 5,022,642.89 s.
        assert_eq!(format!("{TIME_UNIT_S:.2}"), "5022635.53");
        assert!((86_400.0 / 0.017_202_098_95 / TIME_UNIT_S - 1.0 - 1.47e-6).abs() < 1e-8);
    }

    #[test]
    fn g_is_not_quite_one_in_ss_h_units() {
        // §13: "With the ss.h values, G in these units is 0.99999 (6.6743e-11 SI)".
        let g = G_SI / SS_H.g_si().unwrap();
        assert_eq!(format!("{g:.5}"), "0.99999");
        assert_eq!(RUBBLE.g_si(), None);
    }

    #[test]
    fn each_set_is_a_year_over_two_pi_within_a_few_parts_in_10_000() {
        for set in SETS {
            if let Some(t) = set.time_unit_s() {
                let year = t * TAU;
                assert!(
                    (year / 3.1558e7 - 1.0).abs() < 2e-4,
                    "{}: {year}",
                    set.source
                );
            }
            assert!((set.au_m / AU_M - 1.0).abs() < 2e-5, "{}", set.source);
            assert!((set.solar_mass_kg / SOLAR_MASS_KG - 1.0).abs() < 6e-4);
        }
    }
}
