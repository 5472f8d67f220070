//! Property tests: for any text, the checker never panics and the scene holds only
//! finite numbers, with `orient` and `osc-vec` of unit length (or zero, which the
//! checker reports).

use proptest::prelude::*;
use walls_keywords::Keyword;
use walls_model::{ContactModel, Options, Value, analyze};
use walls_test_support::arbitrary::walls_file as file;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1500))]

    #[test]
    fn scenes_hold_finite_normalised_values(text in file(), hsdem in any::<bool>()) {
        let tree = walls_syntax::parse(text.as_str()).tree;
        let options = Options {
            mode: if hsdem { ContactModel::Hsdem } else { ContactModel::Ssdem },
            min_radius: Some(0.01),
            dt: Some(1e-3),
            ..Options::default()
        };
        let analysis = analyze(&tree, &options);
        for wall in &analysis.scene.walls {
            for &k in Keyword::ALL {
                match wall.value(k) {
                    Some(Value::Number(x)) => prop_assert!(x.is_finite(), "{k:?} = {x}\n{text}"),
                    Some(Value::Vector(v)) => {
                        prop_assert!(v.iter().all(|x| x.is_finite()), "{k:?} = {v:?}\n{text}");
                        if matches!(k, Keyword::Orient | Keyword::OscVec) && v.norm() != 0.0 {
                            prop_assert!((v.norm() - 1.0).abs() < 1e-12, "{k:?} = {v:?}\n{text}");
                        }
                    }
                    _ => {}
                }
            }
            let n = wall.normal();
            prop_assert!(n.iter().all(|x| x.is_finite()));
        }
        for d in &analysis.diagnostics {
            prop_assert!(d.span.end <= text.len() && text.is_char_boundary(d.span.start) && text.is_char_boundary(d.span.end));
        }
    }
}
