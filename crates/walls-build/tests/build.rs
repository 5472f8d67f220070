//! The builder as a program uses it: each kind of refused token with its message, the
//! numbers of a dumped file read back exactly by the resolver, and a dumped file already
//! formatted and clean under the linter's check.

use walls_build::{
    BuildError, DumpOptions, Given, LengthUnit, Units, Value, Wall, describe, dumps,
};
use walls_model::Options;

fn refused(name: &str, value: impl Into<Given>) -> BuildError {
    Wall::new().set(name, value).unwrap_err()
}

fn list(items: &[Given]) -> Given {
    Given::List(items.to_vec())
}

#[test]
fn each_kind_of_mistake_is_refused_with_its_message() {
    let cases: Vec<(BuildError, &str, bool)> = vec![
        (
            refused("raduis", 1.0),
            "unknown keyword `raduis`: did you mean `radius`?",
            false,
        ),
        (refused("hello", 1.0), "unknown keyword `hello`", false),
        (
            refused("lengthunit", 1.0),
            "`lengthunit` cannot be set in a wall: give the units to dumps, and each wall as a wall of its own",
            false,
        ),
        (
            refused("wall", 1.0),
            "`wall` cannot be set in a wall: give the units to dumps, and each wall as a wall of its own",
            false,
        ),
        (
            Units::new().set("origin", 1.0).unwrap_err(),
            "`origin` is not a unit: the units are lengthunit, massunit and timeunit",
            false,
        ),
        (
            Wall::of_type("trangle").unwrap_err(),
            "unknown wall type `trangle`: did you mean `triangle`?",
            false,
        ),
        (
            Wall::of_type("cylinder").unwrap_err(),
            "unknown wall type `cylinder`: did you mean one of `cylinder-infinite`, `cylinder-finite`?",
            false,
        ),
        (
            Wall::of_type("sphere").unwrap_err(),
            "unknown wall type `sphere` (the types are plane, triangle, rectangle, disk, cylinder-infinite, cylinder-finite, shell)",
            false,
        ),
        (
            refused("type", 3),
            "`type` takes a wall type name, found the integer `3`",
            true,
        ),
        (
            refused("radius", [1.0, 2.0, 3.0]),
            "`radius` takes a number, found a list of 3 values",
            true,
        ),
        (
            refused("radius", true),
            "`radius` takes a number, found the bool `true`",
            true,
        ),
        (
            refused("radius", "big"),
            "`radius` takes a number, found the word `big`",
            true,
        ),
        (
            refused("origin", list(&[Given::Int(1), Given::Int(2)])),
            "`origin` takes a vector of 3 numbers, found a list of 2 values",
            true,
        ),
        (
            refused("origin", 1.5),
            "`origin` takes a vector of 3 numbers, found the number `1.5`",
            true,
        ),
        (
            refused(
                "vertex1",
                list(&[Given::Int(1), Given::Bool(false), Given::Int(0)]),
            ),
            "`vertex1` takes a vector of 3 numbers, found a list holding the bool `false`",
            true,
        ),
        (
            refused("color", 12.5),
            "`color` takes an integer, found `12.5` (pkdgrav would read it with atoi, dropping the fraction)",
            false,
        ),
        (
            refused("assembly", true),
            "`assembly` takes an integer, found the bool `true`",
            true,
        ),
        (
            refused("radius", f64::NAN),
            "`radius` takes a finite number, found `NaN`",
            false,
        ),
        (
            refused("osc_vec", [f64::NEG_INFINITY, 0.0, 1.0]),
            "`osc-vec` takes a finite number, found `-inf`",
            false,
        ),
        (
            refused("color", f64::INFINITY),
            "`color` takes a finite number, found `inf`",
            false,
        ),
    ];
    for (error, message, type_error) in cases {
        assert_eq!(error.to_string(), message);
        assert_eq!(error.is_type_error(), type_error, "{message}");
    }
}

#[test]
fn values_of_other_kinds_that_fit_are_taken() {
    let wall = Wall::of_type("Disc")
        .unwrap()
        .with("color", 7.0)
        .unwrap()
        .with("radius", 2)
        .unwrap()
        .with("osc_ampl", 0.5)
        .unwrap()
        .with(
            "ORIGIN",
            list(&[Given::Int(1), Given::Float(0.5), Given::Int(-2)]),
        )
        .unwrap();
    let tokens: Vec<_> = wall.tokens().collect();
    assert_eq!(
        tokens,
        [
            ("type", Value::Type(walls_keywords::WallType::Disk)),
            ("color", Value::Integer(7)),
            ("radius", Value::Number(2.0)),
            ("osc-ampl", Value::Number(0.5)),
            ("origin", Value::Vector([1.0, 0.5, -2.0])),
        ]
    );
}

#[test]
fn numbers_read_back_exactly() {
    let values = [
        0.1 + 0.2,
        1e-300,
        6.68e-14,
        -2.5e20,
        1.0 / 3.0,
        123456789.125,
        5.0,
        f64::MAX,
        4.9e-324 * 1e16,
    ];
    // A vector no rule limits (an origin of f64::MAX is C121's, whose squares overflow).
    let walls: Vec<Wall> = values
        .chunks(3)
        .map(|v| {
            Wall::of_type("plane")
                .unwrap()
                .with("rot-vec", [v[0], v[1], v[2]])
                .unwrap()
        })
        .collect();
    let dumped = dumps(&walls, &DumpOptions::default()).unwrap();
    let checked = walls_ide::check_text(dumped.text.as_str(), &Options::default());
    let read: Vec<f64> = checked
        .scene
        .walls
        .iter()
        .flat_map(|w| {
            let v = w.vector(walls_keywords::Keyword::RotVec);
            [v.x, v.y, v.z]
        })
        .collect();
    assert_eq!(
        read.iter().map(|x| x.to_bits()).collect::<Vec<_>>(),
        values.iter().map(|x| x.to_bits()).collect::<Vec<_>>(),
        "{}",
        dumped.text
    );
    assert!(
        dumped
            .text
            .contains("rot-vec 0.30000000000000004 1e-300 6.68e-14\n")
    );
}

#[test]
fn a_dumped_file_is_formatted_and_clean() {
    let mut units = Units::length(LengthUnit::Cm);
    units.set("timeunit", 1.99102e-7).unwrap();
    let mut defaults = Wall::new();
    defaults.set("color", 3).unwrap().set("epsn", 0.8).unwrap();
    let walls = [
        Wall::of_type("triangle")
            .unwrap()
            .with("origin", [0.0, 0.0, 0.0])
            .unwrap()
            .with("vertex1", [1.0, 0.0, 0.0])
            .unwrap()
            .with("vertex2", [0.0, 2.5, 0.0])
            .unwrap(),
        Wall::of_type("disk")
            .unwrap()
            .with("radius", 0.5)
            .unwrap()
            .with("velocity", [0.0, 0.0, -1.0])
            .unwrap(),
    ];
    let options = DumpOptions {
        units,
        defaults: Some(defaults),
        comment: Some("A hopper.\n\nTwo walls.".into()),
        ..DumpOptions::default()
    };
    let dumped = dumps(&walls, &options).unwrap();
    assert_eq!(
        dumped.text,
        "# A hopper.
#
# Two walls.
lengthunit 6.684587122268446e-14
timeunit 1.99102e-7

defaults color 3
  epsn 0.8

wall type triangle
  origin 0 0 0
  vertex1 1 0 0
  vertex2 0 2.5 0

wall type disk
  radius 0.5
  velocity 0 0 -1
"
    );
    assert!(dumped.warnings.is_empty(), "{:?}", dumped.warnings);
    // What `walls-fmt --check` and `walls-lint` decide.
    assert_eq!(
        walls_format::format_text(&dumped.text, &Default::default()).unwrap(),
        dumped.text
    );
    let checked = walls_ide::check_text(dumped.text.as_str(), &Options::default());
    assert!(checked.diagnostics.is_empty(), "{:?}", checked.diagnostics);
}

#[test]
fn errors_fail_the_dump_and_warnings_come_back() {
    let crooked = Wall::of_type("rectangle")
        .unwrap()
        .with("vertex1", [1.0, 0.0, 0.0])
        .unwrap()
        .with("vertex2", [1.0, 1.0, 0.0])
        .unwrap();
    let error = dumps(&[crooked], &DumpOptions::default()).unwrap_err();
    assert_eq!(
        describe(&error.text, &error.diagnostics),
        "3:11: error[C106]: rectangle wall 0 has vertex1 and vertex2 at 45.000° (|cos| 0.7071 > 0.001) (`vertex2 1 1 0`)\n"
    );
    let mut bad_unit = DumpOptions::default();
    bad_unit.units.set("lengthunit", -1.0).unwrap();
    let error = dumps(&[Wall::new()], &bad_unit).unwrap_err();
    assert_eq!(
        error.to_string(),
        "the walls make a file with 1 error:\n1:12: error[C101]: `lengthunit` must be positive, not -1; the unit in force is kept (`lengthunit -1`)\n"
    );

    let odd = Wall::of_type("triangle")
        .unwrap()
        .with("radius", 2.0)
        .unwrap();
    let dumped = dumps(&[odd], &DumpOptions::default()).unwrap();
    assert_eq!(
        describe(&dumped.text, &dumped.warnings),
        "2:3: warning[C201]: a triangle wall ignores `radius` (`radius 2`)\n"
    );

    // A subnormal number is a warning (S110), as walls-lint gives it: the file is written
    // and the warning comes back (it failed with no error before).
    let tiny = Wall::of_type("disk")
        .unwrap()
        .with("radius", 1e-320)
        .unwrap();
    let dumped = dumps(&[tiny], &DumpOptions::default()).unwrap();
    assert_eq!(dumped.text, "wall type disk\n  radius 1e-320\n");
    assert_eq!(
        describe(&dumped.text, &dumped.warnings),
        "2:10: warning[S110]: `1e-320` is below the smallest normal double: pkdgrav reads it as 1e-320, with fewer significant digits (`radius 1e-320`)\n"
    );
}
