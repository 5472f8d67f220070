//! What `--units cgs` and `--units si` show for a file without units: pkdgrav's units as
//! the toolkit's constants (`walls_keywords::pkdgrav_units::TOOLKIT`, pkdgrav's `ss.h`)
//! give them, to four significant figures and exactly.

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
