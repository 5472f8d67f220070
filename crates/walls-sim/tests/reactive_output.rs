//! `reactive_output`: C's `%.16e` reproduced exactly (against outputs of glibc's printf
//! in `tests/data/c_exp.txt`), the two files' line formats read back field by field, and
//! appending versus starting fresh; the viz file read back as the walls written.

use nalgebra::Vector3;
use walls_sim::io::wallsreact::{
    AssemblyState, DATA_FILE, ReactiveOutput, VIZ_FILE, VizError, VizWall, c_exp, data_line,
    last_viz_step, parse_viz_line, viz_line,
};

type Vec3 = Vector3<f64>;

#[test]
fn c_exp_hand_picked() {
    // Each expected string printed by glibc's printf("%.16e").
    let cases: &[(f64, &str)] = &[
        (0.0, "0.0000000000000000e+00"),
        (-0.0, "-0.0000000000000000e+00"),
        (1.0, "1.0000000000000000e+00"),
        (-1.0, "-1.0000000000000000e+00"),
        (1e-300, "1.0000000000000000e-300"),
        (1.5e300, "1.5000000000000001e+300"),
        (123.456, "1.2345600000000000e+02"),
        (0.1, "1.0000000000000001e-01"),
        (1e-5, "1.0000000000000001e-05"),
        (5e-324, "4.9406564584124654e-324"),
        (2.225_073_858_507_201e-308, "2.2250738585072009e-308"),
        (f64::MIN_POSITIVE, "2.2250738585072014e-308"),
        (f64::MAX, "1.7976931348623157e+308"),
        #[allow(clippy::excessive_precision)]
        (9.999_999_999_999_999_99e99, "1.0000000000000000e+100"),
        (0.999_999_999_999_999_9, "9.9999999999999989e-01"),
        // Exact ties at the 17th digit, 1 + 2⁻¹⁷ = 1.00000762939453125 and
        // 1 + 3·2⁻¹⁷ = 1.00002288818359375: glibc rounds to even.
        (1.0 + 1.0 / 131_072.0, "1.0000076293945312e+00"),
        (1.0 + 3.0 / 131_072.0, "1.0000228881835938e+00"),
        (f64::INFINITY, "inf"),
        (f64::NEG_INFINITY, "-inf"),
        (f64::NAN, "nan"),
        (-f64::NAN, "-nan"),
    ];
    for &(x, want) in cases {
        assert_eq!(c_exp(x), want, "c_exp({x:e})");
    }
}

#[test]
fn c_exp_matches_glibc_table() {
    let table = include_str!("data/c_exp.txt");
    let mut n = 0;
    for line in table.lines() {
        let (bits, want) = line.split_once(' ').expect("bits, space, printf output");
        let x = f64::from_bits(u64::from_str_radix(bits, 16).expect("hex bits"));
        assert_eq!(c_exp(x), want, "c_exp of bits {bits}");
        if x.is_finite() {
            assert_eq!(
                want.parse::<f64>().unwrap().to_bits(),
                x.to_bits(),
                "{want}"
            );
        }
        n += 1;
    }
    assert!(n > 800, "the table has {n} lines");
}

fn v(x: f64, y: f64, z: f64) -> Vec3 {
    Vec3::new(x, y, z)
}

fn assembly(seed: f64) -> AssemblyState {
    AssemblyState {
        cog: v(seed, -seed / 3.0, 1e-7 * seed),
        velocity: v(0.1 * seed, 2.0 / 3.0, -0.0),
        rot_vec: v(1e300, -5e-324, std::f64::consts::PI * seed),
        axes: [
            v(1.0, 0.0, 0.0),
            v(0.0, (seed).cos(), (seed).sin()),
            v(0.0, -(seed).sin(), (seed).cos()),
        ],
    }
}

fn walls(seed: f64) -> Vec<VizWall> {
    vec![
        VizWall::Polygon {
            id: 2,
            origin: v(seed, 1.0 / 7.0, -3.5),
            vertex1: v(0.0, 1.0, 0.0),
            vertex2: v(1.0, 0.0, 1e-20),
        },
        VizWall::Round {
            id: 5,
            origin: v(-seed, 0.25, 1e10),
            orient: v(0.0, 0.6, 0.8),
        },
        VizWall::Polygon {
            id: 11,
            origin: v(0.3, 0.2, 0.1),
            vertex1: v(seed, seed, seed),
            vertex2: v(-1.0, -2.0, -3.0),
        },
    ]
}

fn data_numbers(a: &AssemblyState) -> Vec<f64> {
    let mut out = Vec::new();
    for vec in [
        &a.cog,
        &a.velocity,
        &a.rot_vec,
        &a.axes[0],
        &a.axes[1],
        &a.axes[2],
    ] {
        out.extend(vec.iter().copied());
    }
    out
}

/// Checks a data line's fields: the step, then 18 numbers per assembly, bit for bit.
fn check_data_line(line: &str, step: u64, assemblies: &[AssemblyState]) {
    assert!(!line.ends_with(' ') && !line.contains("  "), "{line:?}");
    let fields: Vec<&str> = line.split(' ').collect();
    assert_eq!(fields.len(), 1 + 18 * assemblies.len());
    assert_eq!(fields[0], step.to_string());
    let want: Vec<f64> = assemblies.iter().flat_map(data_numbers).collect();
    for (field, want) in fields[1..].iter().zip(&want) {
        assert_eq!(
            field.parse::<f64>().unwrap().to_bits(),
            want.to_bits(),
            "{field}"
        );
        assert_eq!(*field, c_exp(*want));
    }
}

/// Checks a viz line's fields: the step, then per wall flag, id and 9 or 6 numbers.
fn check_viz_line(line: &str, step: u64, walls: &[VizWall]) {
    assert!(!line.ends_with(' ') && !line.contains("  "), "{line:?}");
    let fields: Vec<&str> = line.split(' ').collect();
    let expected: usize = 1 + walls.iter().map(VizWall::field_count).sum::<usize>();
    assert_eq!(fields.len(), expected);
    assert_eq!(fields[0], step.to_string());
    let mut at = 1;
    for wall in walls {
        let (flag, id, numbers): (&str, usize, Vec<f64>) = match wall {
            VizWall::Polygon {
                id,
                origin,
                vertex1,
                vertex2,
            } => (
                "0",
                *id,
                origin
                    .iter()
                    .chain(vertex1.iter())
                    .chain(vertex2.iter())
                    .copied()
                    .collect(),
            ),
            VizWall::Round { id, origin, orient } => (
                "1",
                *id,
                origin.iter().chain(orient.iter()).copied().collect(),
            ),
        };
        assert_eq!(fields[at], flag);
        assert_eq!(fields[at + 1], id.to_string());
        for (k, want) in numbers.iter().enumerate() {
            let got: f64 = fields[at + 2 + k].parse().unwrap();
            assert_eq!(got.to_bits(), want.to_bits());
        }
        at += 2 + numbers.len();
    }
    assert_eq!(at, fields.len());
}

#[test]
fn line_shapes() {
    let a = assembly(1.0);
    let line = data_line(7, &[a]);
    assert!(line.ends_with('\n'));
    // One assembly: 19 fields, as the walls document says.
    assert_eq!(line.trim_end().split(' ').count(), 19);
    assert!(line.starts_with("7 1.0000000000000000e+00 -3.3333333333333331e-01 "));
    assert_eq!(data_line(3, &[]), "3\n");
    assert_eq!(viz_line(0, &[]), "0\n");
    let wall = VizWall::Round {
        id: 4,
        origin: v(0.0, 0.0, 1.0),
        orient: v(0.0, 0.0, -1.0),
    };
    assert_eq!(
        viz_line(12, &[wall]),
        "12 1 4 0.0000000000000000e+00 0.0000000000000000e+00 1.0000000000000000e+00 \
         0.0000000000000000e+00 0.0000000000000000e+00 -1.0000000000000000e+00\n"
    );
}

/// What `record` writes: the data file's and the viz file's lines.
fn recorded(steps: &[(u64, Vec<AssemblyState>, Vec<VizWall>)]) -> (Vec<String>, Vec<String>) {
    let mut out = ReactiveOutput::new(Vec::new(), Vec::new());
    for (step, a, w) in steps {
        out.record(*step, a, w).unwrap();
    }
    let (data, viz) = out.finish().unwrap();
    let lines = |bytes: Vec<u8>| {
        let text = String::from_utf8(bytes).unwrap();
        assert!(text.is_empty() || text.ends_with('\n'));
        text.lines().map(str::to_string).collect()
    };
    (lines(data), lines(viz))
}

#[test]
fn record_round_trip() {
    assert_eq!(DATA_FILE, "WALLSREACTdata.out");
    assert_eq!(VIZ_FILE, "WALLSREACTviz.out");
    let steps: [(u64, Vec<AssemblyState>, Vec<VizWall>); 2] = [
        (0, vec![assembly(0.5), assembly(-2.0)], walls(0.5)),
        (100, vec![assembly(0.75), assembly(-2.25)], walls(0.75)),
    ];
    let (data, viz) = recorded(&steps);
    assert_eq!(data.len(), 2);
    assert_eq!(viz.len(), 2);
    for (i, (step, a, w)) in steps.iter().enumerate() {
        check_data_line(&data[i], *step, a);
        check_viz_line(&viz[i], *step, w);
        assert_eq!(viz[i].split(' ').count(), 1 + 11 + 8 + 11);
        assert_eq!(data[i].split(' ').count(), 1 + 2 * 18);
    }
    // A step with no assembly and no finite wall is its step alone.
    let (data, viz) = recorded(&[(300, Vec::new(), Vec::new())]);
    assert_eq!(
        (data, viz),
        (vec!["300".to_string()], vec!["300".to_string()])
    );
}

#[test]
fn viz_lines_read_back_as_the_walls_written() {
    for seed in [0.5, -2.25, 1e-300, 3.0e12] {
        let w = walls(seed);
        assert_eq!(parse_viz_line(&viz_line(42, &w)), Some((42, w)));
    }
    assert_eq!(parse_viz_line(&viz_line(7, &[])), Some((7, Vec::new())));
    // A wall cut short, or a word that is not a number, is not a viz line.
    let line = viz_line(1, &walls(0.5));
    let cut: Vec<&str> = line.split(' ').collect();
    assert_eq!(parse_viz_line(&cut[..cut.len() - 1].join(" ")), None);
    assert_eq!(parse_viz_line("1 0 x"), None);
    // Nor are numbers the tools' rule refuses (a wall at NaN was read).
    let nan = line.replacen("5.0000000000000000e-01", "nan", 1);
    assert_ne!(nan, line);
    assert_eq!(parse_viz_line(&nan), None);
    assert_eq!(parse_viz_line(""), None);
}

#[test]
fn the_last_viz_step_is_where_the_run_left_its_walls() {
    let mut out = ReactiveOutput::new(Vec::new(), Vec::new());
    out.record(0, &[assembly(0.5)], &walls(0.5)).unwrap();
    out.record(250, &[assembly(0.75)], &walls(0.75)).unwrap();
    let (_, viz) = out.finish().unwrap();
    let text = String::from_utf8(viz).unwrap();
    assert_eq!(last_viz_step(&text), Ok((250, walls(0.75))));
    // Blank lines after the last step are skipped.
    assert_eq!(
        last_viz_step(&format!("{text}\n  \n")),
        Ok((250, walls(0.75)))
    );
    assert_eq!(last_viz_step(" \n"), Err(VizError::NoSteps));
    assert_eq!(VizError::NoSteps.to_string(), "no steps");
    let e = last_viz_step(&format!("{text}1 0 2\n")).unwrap_err();
    assert_eq!(e, VizError::BadLine { line: 3 });
    assert_eq!(e.to_string(), "line 3: not a WALLSREACTviz.out line");
}
