//! What `--units` shows: for a file without units, with `cgs` and `si`, pkdgrav's units as
//! the toolkit's constants (`walls_keywords::pkdgrav_units::TOOLKIT`, pkdgrav's `ss.h`)
//! give them, to four significant figures and exactly; a picture of a file with units,
//! in seconds.

use walls_geometry::units::{Readout, System};
use walls_keywords::pkdgrav_units;
use walls_model::Units;

#[test]
fn pkdgrav_units_read_as_the_toolkits_constants() {
    let none = Units::default();
    assert_eq!(Readout::new(System::Auto, &none).length(1.0), "1");
    // 1 AU is 1.496e13 cm; the time unit is 58.13 days.
    assert_eq!(Readout::new(System::Cgs, &none).length(1.0), "1.496e13 cm");
    assert_eq!(Readout::new(System::Si, &none).time(1.0), "5.023e6 s");
    assert_eq!(Readout::new(System::Si, &none).mass(1.0), "1.988e30 kg");
    assert_eq!(Readout::new(System::Cgs, &none).mass(1.0), "1.988e33 g");
}

#[test]
fn si_and_cgs_are_the_constants_to_the_last_digit() {
    let none = Units::default();
    let si = Readout::new(System::Si, &none).scale;
    assert_eq!(si.length.per_pkdgrav, pkdgrav_units::AU_M);
    assert_eq!(si.mass.per_pkdgrav, pkdgrav_units::SOLAR_MASS_KG);
    assert_eq!(si.time.per_pkdgrav, pkdgrav_units::TIME_UNIT_S);
    let cgs = Readout::new(System::Cgs, &none).scale;
    assert_eq!(cgs.length.per_pkdgrav, 100.0 * pkdgrav_units::AU_M);
    assert_eq!(cgs.mass.per_pkdgrav, 1000.0 * pkdgrav_units::SOLAR_MASS_KG);
    assert_eq!(cgs.time.per_pkdgrav, pkdgrav_units::TIME_UNIT_S);
}

#[test]
fn a_picture_of_a_file_with_units_reads_in_seconds() {
    let t = 1.47 / pkdgrav_units::TIME_UNIT_S;
    // Centimetres and grams, no `timeunit`: seconds all the same, from the constants.
    let cm_g = Units {
        length: 6.68459e-14,
        mass: 5.02739933e-34,
        time: 1.0,
    };
    let picture = Readout::picture(System::Auto, &cm_g);
    assert_eq!(picture.time(t), "1.47 s");
    assert_eq!(picture.length(5.5 * cm_g.length), "5.5 cm");
    // The run's summary keeps pkdgrav's number first.
    assert_eq!(Readout::new(System::Auto, &cm_g).time(t), "2.927e-7");
    // Metres, and the file's own second.
    let si = Units {
        length: 100.0 * 6.68459e-14,
        mass: 1.0,
        time: 1.99102e-7,
    };
    let picture = Readout::picture(System::Auto, &si);
    assert_eq!(picture.time(1.2 * si.time), "1.2 s");
    assert_eq!(picture.length(0.5 * si.length), "0.5 m");
    // A file without units, or pkdgrav's asked for: pkdgrav's.
    let none = Units::default();
    assert_eq!(Readout::picture(System::Auto, &none).time(0.5), "0.5");
    assert_eq!(Readout::picture(System::Pkdgrav, &cm_g).time(t), "2.927e-7");
}
