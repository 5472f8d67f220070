//! `walls-sim advise` and `--units si` convert with the same set of pkdgrav's units
//! (`walls_keywords::pkdgrav_units::TOOLKIT`): the advice's metres, kilograms and
//! seconds per pkdgrav unit are the readout's, to the last digit, and the advice names
//! the set.

use walls_geometry::units::{Readout, System};
use walls_keywords::pkdgrav_units::TOOLKIT;
use walls_sim::advise::{self, Amount, Inputs, Units};

#[test]
fn advise_and_units_si_use_the_same_set() {
    let advice = advise::advise(&Inputs::new(Amount::Mass(1.0), 1.0, 1.0)).unwrap();
    let no_units = walls_test_support::model_scene("").units;
    let si = Readout::new(System::Si, &no_units).scale;
    assert_eq!(advice.units, Units::pkdgrav());
    assert_eq!(advice.units.length, si.length.per_pkdgrav);
    assert_eq!(advice.units.mass, si.mass.per_pkdgrav);
    assert_eq!(advice.units.time, si.time.per_pkdgrav);
    assert_eq!(Units::of(&TOOLKIT), Some(advice.units));

    let inputs = Inputs::new(Amount::Mass(1.0), 1.0, 1.0);
    let text = advise::text(&advice, &inputs, None);
    assert!(
        text.contains(&format!("as pkdgrav's {} gives them", TOOLKIT.source)),
        "{text}"
    );
    let json: serde_json::Value =
        serde_json::from_str(&advise::json(&advice, &inputs, None)).unwrap();
    assert_eq!(json["units"]["set"], TOOLKIT.source);
    assert_eq!(json["units"]["mass_kg"], si.mass.per_pkdgrav);
    assert_eq!(json["units"]["length_m"], si.length.per_pkdgrav);
    assert_eq!(json["units"]["time_s"], si.time.per_pkdgrav);
}
