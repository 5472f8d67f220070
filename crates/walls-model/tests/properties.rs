//! Property tests: for any text, the checker never panics and the scene holds only
//! finite numbers, with `orient` and `osc-vec` of unit length (or zero, which the
//! checker reports).

use proptest::prelude::*;
use walls_keywords::{Keyword, ValueShape, WallType};
use walls_model::{Mode, Options, Value, analyze};

/// Numbers from ordinary to extreme: zero, negative, subnormal, overflowing.
fn number() -> impl Strategy<Value = String> {
    prop_oneof![
        "[-+]?[0-9]{1,3}(\\.[0-9]{1,3})?",
        prop::sample::select(vec![
            "0", "-0", "1e308", "-1e308", "1e-320", "4.9e-324", "1e999", "99", "-1", "1e-300",
        ])
        .prop_map(str::to_string),
    ]
}

/// Statements with values of the right shape (mostly), units and blocks.
fn statement() -> impl Strategy<Value = String> {
    (
        prop::sample::select(Keyword::ALL.to_vec()),
        prop::collection::vec(number(), 3),
        0..7usize,
    )
        .prop_map(|(k, nums, t)| {
            let value = match k.shape() {
                ValueShape::None => String::new(),
                ValueShape::Number => nums[0].clone(),
                ValueShape::Integer => nums[0].split(['.', 'e']).next().unwrap_or("0").to_string(),
                ValueShape::Vector => nums.join(" "),
                ValueShape::TypeName => WallType::ALL[t].name().to_string(),
            };
            format!("{} {value}\n", k.name())
        })
}

fn file() -> impl Strategy<Value = String> {
    prop::collection::vec(statement(), 0..40).prop_map(|v| v.concat())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1500))]

    #[test]
    fn scenes_hold_finite_normalised_values(text in file(), hsdem in any::<bool>()) {
        let tree = walls_syntax::parse(text.as_str()).tree;
        let options = Options {
            mode: if hsdem { Mode::Hsdem } else { Mode::Ssdem },
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
            if let Some(p) = walls_model::motion::position(wall, 1.5) {
                prop_assert!(p.iter().all(|x| x.is_finite()), "position {p:?}\n{text}");
            }
            // Ordinary values always give a position.
            let ordinary = [Keyword::Origin, Keyword::Velocity]
                .iter()
                .all(|&k| wall.vector(k).norm() < 1e100)
                && [Keyword::OscAmpl, Keyword::OscFreq].iter().all(|&k| wall.number(k).abs() < 1e100);
            prop_assert!(!ordinary || walls_model::motion::position(wall, 1.5).is_some(), "{text}");
        }
        for d in &analysis.diagnostics {
            prop_assert!(d.span.end <= text.len() && text.is_char_boundary(d.span.start) && text.is_char_boundary(d.span.end));
        }
    }
}
