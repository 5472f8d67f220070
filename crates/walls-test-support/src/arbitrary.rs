//! Random walls files for property tests: statements of any keyword with values of
//! its shape (mostly), numbers from ordinary to extreme (zero, negative, subnormal,
//! overflowing).

use proptest::prelude::*;
use walls_keywords::{Keyword, ValueShape, WallType};

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

/// Walls files of up to 40 statements: any keyword, values mostly of its shape.
pub fn walls_file() -> impl Strategy<Value = String> {
    prop::collection::vec(statement(), 0..40).prop_map(|v| v.concat())
}
