//! Property tests: for any text, every wall decodes, and its position at a time is a
//! finite point whenever it is given, and always for ordinary values.

use proptest::prelude::*;
use walls_geometry::decode;
use walls_model::{Options, analyze};
use walls_test_support::arbitrary::walls_file;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1500))]

    #[test]
    fn positions_are_finite(text in walls_file()) {
        let tree = walls_syntax::parse(text.as_str()).tree;
        let scene = analyze(&tree, &Options::default()).scene;
        for wall in decode(&scene) {
            let m = &wall.motion;
            if let Some(p) = m.position(1.5) {
                prop_assert!(p.iter().all(|x| x.is_finite()), "position {p:?}\n{text}");
            }
            // Ordinary values always give a position.
            let ordinary = [m.origin, m.velocity].iter().all(|v| v.norm() < 1e100)
                && [m.oscillation.amplitude, m.oscillation.frequency].iter().all(|x| x.abs() < 1e100);
            prop_assert!(!ordinary || m.position(1.5).is_some(), "{text}");
        }
    }
}
