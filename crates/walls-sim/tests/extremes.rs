//! Inputs at the edges of what a double holds: values that underflow or overflow are
//! errors with their location, runs whose numbers would overflow or whose steps are too
//! many are refused before they start with the value's source, and a run whose state
//! stops being finite stops with a reason instead of panicking.

use nalgebra::Vector3;
use walls_keywords::number::EXACT_COUNT;
use walls_sim::config::{ConfigError, Counts, Flags, Inputs, MAX_STEPS, resolve};
use walls_sim::io::par::{Params, read_par};
use walls_sim::io::particles::{Format, format_of, read_bytes, read_csv, read_ss, write_ss};
use walls_sim::run::{ContactModel, Settings, Stop, run, run_watched};
use walls_test_support::{ball, scene};

const FLOOR: &str = "wall type plane origin 0 0 0\n";

fn one(row: &str) -> String {
    read_csv(&format!("mass,radius,x,y,z,vx,vy,vz\n{row}\n"))
        .unwrap_err()
        .to_string()
}

#[test]
fn particle_values_that_a_double_cannot_hold_are_located_errors() {
    assert_eq!(
        one("1,1e-400,0,0,1,0,0,0"),
        "line 2: `radius` is `1e-400`, too small for a double: pkdgrav reads it as 0"
    );
    assert_eq!(
        one("1,0.1,0,0,1e999,0,0,0"),
        "line 2: `z` is `1e999`, too large for a double: pkdgrav reads it as infinity"
    );
    assert_eq!(
        one("1,0.1,0,0,nan,0,0,0"),
        "line 2: `z` is `nan`, not a finite number"
    );
    assert!(one("1,1e-300,0,0,1,0,0,0").starts_with("line 2: its moment of inertia 0.4·m·r²"));
    assert!(one("1,1e300,0,0,1,0,0,0").starts_with("line 2: its moment of inertia 0.4·m·r²"));
    assert!(one("1,0.1,0,0,1,1e200,0,0").starts_with("line 2: its kinetic energy ½m|v|² is inf"));
    assert_eq!(
        read_csv("mass,radius,x,y,z,vx,vy,vz,color\n1,0.1,0,0,1,0,0,0,300\n")
            .unwrap_err()
            .to_string(),
        "line 2: `color` is 300; pkdgrav's colours are 0 to 255 (negative: stuck to wall −1 − color)"
    );
}

#[test]
fn a_nan_ss_time_is_an_error() {
    let bytes = write_ss(f64::NAN, &[ball([0.0, 0.0, 1.0], [0.0; 3])]);
    assert_eq!(
        read_ss(&bytes).unwrap_err().to_string(),
        "byte 0: the header's time is NaN, not a finite number"
    );
}

#[test]
fn the_format_follows_the_content_when_the_extension_does_not_say() {
    let csv = b"mass,radius,x,y,z,vx,vy,vz\n1,0.1,0,0,1,0,0,0\n";
    let ss = write_ss(0.0, &[ball([0.0, 0.0, 1.0], [0.0; 3])]);
    assert_eq!(format_of("p.txt", csv), Some(Format::Csv));
    assert_eq!(format_of("-", csv), Some(Format::Csv));
    assert_eq!(format_of("ss.00100", &ss), Some(Format::Ss));
    assert_eq!(format_of("p.CSV", &ss), Some(Format::Csv));
    assert_eq!(read_bytes("p.txt", csv).unwrap().particles.len(), 1);
    assert_eq!(read_bytes("-", &ss).unwrap().particles.len(), 1);
    assert!(
        read_bytes("p.txt", b"hello\n")
            .unwrap_err()
            .to_string()
            .starts_with("byte 0: neither a particle CSV")
    );
}

#[test]
fn par_values_that_underflow_are_errors() {
    assert_eq!(
        read_par("dKn = 1e-400\n").unwrap_err().to_string(),
        "line 1: `dKn` is `1e-400`, too small for a double: pkdgrav reads it as 0"
    );
    // Every real pkdgrav reads, also one of no effect on the run.
    assert_eq!(
        read_par("nSteps = 10\ndTheta = 1e999\n")
            .unwrap_err()
            .to_string(),
        "line 2: `dTheta` is `1e999`, too large for a double: pkdgrav reads it as infinity"
    );
}

/// The W701 warnings of `warnings`, as printed.
fn shown(warnings: &[walls_sim::run::Warning]) -> Vec<String> {
    warnings
        .iter()
        .map(|w| format!("{}: {w}", w.code()))
        .collect()
}

#[test]
fn subnormal_inputs_are_read_and_warned_about_where_they_are() {
    let csv = "mass,radius,x,y,z,vx,vy,vz\n1,0.1,0,0,1,0,0,0\n1,0.1,0,0,1,2.5e-320,0,0\n";
    let read = read_csv(csv).unwrap();
    assert_eq!(read.particles[1].vel.x, 2.5e-320);
    assert_eq!(
        shown(&read.warnings),
        [
            "W701: line 3: `vx`: `2.5e-320` is below the smallest normal double: pkdgrav reads it as 2.5e-320, with fewer significant digits"
        ]
    );
    let mut tiny = ball([0.0, 0.0, 1.0], [0.0; 3]);
    tiny.spin.y = -1e-310;
    let (_, read) = read_ss(&write_ss(1e-315, &[tiny])).unwrap();
    assert_eq!(
        shown(&read.warnings),
        [
            "W701: byte 0: the header's time: `1e-315` is below the smallest normal double: pkdgrav reads it as 1e-315, with fewer significant digits",
            "W701: byte 88: particle 0's `wy`: `-1e-310` is below the smallest normal double: pkdgrav reads it as -1e-310, with fewer significant digits"
        ]
    );
    let par = read_par("dDelta = 1e-3\ndMuS = 1e-310\ndTheta = 4e-320\n").unwrap();
    assert_eq!(par.mu_s, Some(1e-310));
    assert_eq!(
        shown(&par.subnormals),
        [
            "W701: line 2: `dMuS`: `1e-310` is below the smallest normal double: pkdgrav reads it as 1e-310, with fewer significant digits",
            "W701: line 3: `dTheta`: `4e-320` is below the smallest normal double: pkdgrav reads it as 4e-320, with fewer significant digits"
        ]
    );
    let (_, numbers) = walls_sim::io::cohesion::read_cohesion("1 0\n3 1e-320\n").unwrap();
    assert_eq!(
        shown(&numbers),
        [
            "W701: line 2: the coefficient of colour 3: `1e-320` is below the smallest normal double: pkdgrav reads it as 1e-320, with fewer significant digits"
        ]
    );
    // Options: a run's settings carry them, the options' first.
    let walls = scene(FLOOR);
    let flags = Flags {
        inputs: Inputs {
            gravity: Some(vec![0.0, 0.0, -1e-309]),
            mu_s: Some(2e-310),
            ..Inputs::default()
        },
        ..Flags::default()
    };
    let run = resolve(&flags, Some(&par), &walls, None).unwrap();
    assert_eq!(
        shown(&run.numbers)
            .iter()
            .map(|w| w.split(" is below").next().unwrap())
            .collect::<Vec<_>>(),
        [
            "W701: --gravity: `-1e-309`",
            "W701: --mu-s: `2e-310`",
            "W701: line 2: `dMuS`: `1e-310`",
            "W701: line 3: `dTheta`: `4e-320`"
        ]
    );
}

#[test]
fn par_switches_read_as_pkdgrav_reads_integers() {
    let p = read_par("bWallsEdgeDetect = 0.5\nbDoGravity = 1e3\niCohesionModel = 1.9\n").unwrap();
    assert_eq!(p.edge_detect, Some(false));
    assert_eq!(p.do_gravity, Some(true));
    assert_eq!(p.cohesion.model, Some(1));
    let says: Vec<String> = p.warnings.iter().map(ToString::to_string).collect();
    assert!(says[0].starts_with(
        "line 1: `bWallsEdgeDetect`: `0.5` is not a whole number: pkdgrav reads it with C's %d as 0; the run does the same (write 0)"
    ));
    assert!(says[1].starts_with("line 2: `bDoGravity`: `1e3` is not a whole number"));
    assert!(says[2].starts_with(
        "line 3: `iCohesionModel`: `1.9` is not a whole number: pkdgrav reads it with C's %d as 1"
    ));
}

#[test]
fn bang_comments_are_read_and_reported() {
    let p = read_par("dDelta = 1e-5 ! the step\n! a note\n").unwrap();
    assert_eq!(p.dt, Some(1e-5));
    let lines: Vec<Option<usize>> = p.warnings.iter().map(|w| w.line).collect();
    assert_eq!(lines[..2], [Some(1), Some(2)]);
    assert!(p.warnings[0].message.contains("write `#`"));
}

#[test]
fn unknown_and_duplicate_par_keys_are_reported() {
    let p = read_par("dDelta = 1e-5\ndDelta = 2e-5\nbWallEdgeDetect = 1\n").unwrap();
    assert_eq!(p.dt, Some(2e-5));
    let says: Vec<String> = p.warnings.iter().map(ToString::to_string).collect();
    assert!(
        says.iter()
            .any(|w| w.starts_with("line 1: `dDelta`: given again on line 2"))
    );
    assert!(
        says.iter()
            .any(|w| w.starts_with("line 3: `bWallEdgeDetect`: the evaluator does not model it"))
    );
}

fn refusal(flags: &Flags, particles: Vec<walls_geometry::Particle>) -> String {
    match resolve(flags, None, &scene(FLOOR), Some(particles)) {
        Err(ConfigError::Unusable(why)) => why,
        other => panic!("not refused: {other:?}"),
    }
}

#[test]
fn runs_whose_numbers_overflow_are_refused_naming_the_source() {
    let balls = || vec![ball([0.0, 0.0, 1.0], [0.0; 3])];
    let k = refusal(
        &Flags {
            inputs: Inputs {
                k_n: Some(1e308),
                ..Inputs::default()
            },
            ..Flags::default()
        },
        balls(),
    );
    assert!(
        k.starts_with("the timestep comes to 0e0") && k.contains("from --k-n"),
        "{k}"
    );
    let g = refusal(
        &Flags {
            inputs: Inputs {
                gravity: Some(vec![1e308, 0.0, 0.0]),
                ..Inputs::default()
            },
            ..Flags::default()
        },
        balls(),
    );
    assert!(
        g.starts_with("the spring constant k_n comes to inf (the default, derived"),
        "{g}"
    );
}

#[test]
fn runs_beyond_the_step_limit_are_refused_with_the_count() {
    let flags = Flags {
        inputs: Inputs {
            dt: Some(1e-300),
            t_end: Some(1.0),
            ..Inputs::default()
        },
        ..Flags::default()
    };
    let why = refusal(&flags, vec![ball([0.0, 0.0, 1.0], [0.0; 3])]);
    assert_eq!(
        why,
        "the run would take 9.999999999999999e299 steps of 1e-300 (--dt) to t = 1e0 (--t-end), more than the 9007199254740992 steps a run can count exactly (2^53: its step numbers are whole numbers and a step's time is step·dt in doubles): give a longer --dt or a shorter --t-end"
    );
    let flags = Flags {
        inputs: Inputs {
            dt: Some(0.01),
            t_end: Some(1.0),
            ..Inputs::default()
        },
        counts: Counts {
            max_steps: 99,
            ..Counts::default()
        },
        ..Flags::default()
    };
    let why = refusal(&flags, vec![ball([0.0, 0.0, 1.0], [0.0; 3])]);
    assert!(why.starts_with("the run would take 100 steps"), "{why}");
    assert!(why.contains("the limit of 99") && why.contains("--max-steps"));
    let flags = Flags {
        inputs: Inputs {
            dt: Some(1e-9),
            t_end: Some(1.0),
            ..Inputs::default()
        },
        ..Flags::default()
    };
    let why = refusal(&flags, vec![ball([0.0, 0.0, 1.0], [0.0; 3])]);
    assert!(why.contains(&format!("the limit of {MAX_STEPS}")), "{why}");
}

#[test]
fn step_counts_that_do_not_fit_are_refused_whatever_the_limit() {
    // t_end/dt beyond a double was NaN once rounded, and the run took 0 steps with
    // exit 0 and no reason ("t = 0 after 0 steps", "stopped": null).
    let ball = || vec![ball([0.0, 0.0, 1.0], [0.0; 3])];
    for (dt, t_end) in [(Some(1e-320), None), (Some(1e-10), Some(1e299))] {
        let flags = Flags {
            inputs: Inputs {
                dt,
                t_end,
                ..Inputs::default()
            },
            counts: Counts {
                max_steps: u64::MAX,
                ..Counts::default()
            },
            ..Flags::default()
        };
        let why = refusal(&flags, ball());
        assert!(
            why.starts_with("the run would take more than 1.8e308 steps of ")
                && why.contains(" (--dt) to t = ")
                && why.contains("more than the 9007199254740992 steps a run can count exactly"),
            "{why}"
        );
    }
    // Beyond 2^53 but within a u64: the times would not be exact.
    let flags = Flags {
        inputs: Inputs {
            dt: Some(1e-16),
            t_end: Some(1.0),
            ..Inputs::default()
        },
        counts: Counts {
            max_steps: u64::MAX,
            ..Counts::default()
        },
        ..Flags::default()
    };
    assert!(refusal(&flags, ball()).starts_with("the run would take 1e16 steps of 1e-16"));
    // Exactly 2^53 fits (and then meets the limit).
    let flags = Flags {
        inputs: Inputs {
            dt: Some(1.0),
            t_end: Some(2f64.powi(53)),
            ..Inputs::default()
        },
        ..Flags::default()
    };
    assert!(refusal(&flags, ball()).contains("more than the limit of 100000000"));
    // Step numbers given in code, counted exactly.
    let walls = scene(FLOOR);
    for (params, says) in [
        (
            Params {
                dt: Some(1e-3),
                steps: Some(EXACT_COUNT + 1),
                ..Params::default()
            },
            "the .par file's `nSteps` is 9007199254740993, more than the 9007199254740992 steps",
        ),
        (
            Params {
                dt: Some(1e-3),
                steps: Some(10),
                start_step: Some(u64::MAX),
                ..Params::default()
            },
            "the .par file's `iStartStep` is 18446744073709551615, more than",
        ),
        (
            read_par("dDelta = 1e300\nnSteps = 2147483647\n").unwrap(),
            "the end time comes to inf (the .par file's nSteps times the timestep): give --t-end",
        ),
    ] {
        match resolve(&Flags::default(), Some(&params), &walls, Some(ball())) {
            Err(ConfigError::Unusable(why)) => assert!(why.starts_with(says), "{why}"),
            other => panic!("not refused: {other:?}"),
        }
    }
}

#[test]
fn par_integers_beyond_a_c_int_are_errors() {
    // pkdgrav reads them into C ints with %d, which would take another number.
    for (text, says) in [
        (
            "nSteps = 2147483648\n",
            "line 1: `nSteps` is `2147483648`, beyond a C int, which pkdgrav reads it into with %d (it would read another number): give at most 2147483647",
        ),
        (
            "iStartStep = 99999999999999999999\n",
            "line 1: `iStartStep` is `99999999999999999999`, beyond a C int",
        ),
        (
            "bWallsEdgeDetect = 4294967296\n",
            "line 1: `bWallsEdgeDetect` is `4294967296`, beyond a C int",
        ),
        (
            "iCohesionModel = -99999999999999999999\n",
            "line 1: `iCohesionModel` is `-99999999999999999999`, beyond a C int",
        ),
    ] {
        let why = read_par(text).unwrap_err().to_string();
        assert!(why.starts_with(says), "{why}");
    }
    assert_eq!(
        read_par("nSteps = 2147483647\n").unwrap().steps,
        Some(2147483647)
    );
}

#[test]
fn a_bad_timestep_stops_before_the_first_step_instead_of_panicking() {
    let walls = scene(FLOOR);
    let settings = Settings::new(0.0, 1.0, walls_sim::config::pkdgrav_material(1e5));
    let out = run(&walls, vec![ball([0.0, 0.0, 1.0], [0.0; 3])], &settings);
    assert_eq!((out.steps, out.stopped), (0, Some(Stop::Timestep)));
    // Nor with a step count beyond a double (it was 0 steps and no reason).
    let settings = Settings::new(1e-320, 1.0, walls_sim::config::pkdgrav_material(1e5));
    let out = run(&walls, vec![ball([0.0, 0.0, 1.0], [0.0; 3])], &settings);
    assert_eq!((out.steps, out.stopped), (0, Some(Stop::Timestep)));
}

#[test]
fn a_state_that_overflows_stops_the_run_with_a_reason() {
    let walls = scene(FLOOR);
    let mut settings = Settings::new(1.0, 100.0, walls_sim::config::pkdgrav_material(1e5));
    settings.gravity = Vector3::new(1e307, 0.0, 0.0);
    let out = run(&walls, vec![ball([0.0, 0.0, 1.0], [0.0; 3])], &settings);
    assert_eq!(out.stopped, Some(Stop::NotFinite(0)));
    assert!(out.steps < 100);
}

#[test]
fn a_run_shows_no_step_whose_numbers_overflowed() {
    // The observer (which writes particles.csv, the .ss outputs and WALLSREACT files)
    // saw the step that overflowed, and wrote `inf` and `NaN` into them.
    for model in [ContactModel::Ssdem, ContactModel::Hsdem] {
        let walls = scene(FLOOR);
        let mut settings = Settings::new(1e100, 1e102, walls_sim::config::pkdgrav_material(1e5));
        settings.build = walls_sim::build::Build::default_for(model);
        settings.gravity = Vector3::new(1e150, 0.0, 0.0);
        let mut seen = Vec::new();
        let out = run_watched(
            &walls,
            vec![ball([0.0, 0.0, 1.0], [0.0; 3])],
            &settings,
            &mut |step, t, snapshot| {
                let (states, _) = snapshot.look();
                let finite = states.iter().all(|s| {
                    let p = &s.particle;
                    p.pos
                        .iter()
                        .chain(&p.vel)
                        .chain(&p.spin)
                        .all(|x| x.is_finite())
                });
                seen.push((step, t.is_finite() && finite));
            },
            &|| false,
        );
        assert_eq!(out.stopped, Some(Stop::NotFinite(0)), "{model:?}");
        assert!(
            seen.iter().all(|&(_, finite)| finite) && seen.len() as u64 + 1 == out.steps,
            "{model:?}: {seen:?} of {} steps",
            out.steps
        );
        // The report writes no number that is not finite: what overflowed is null.
        let report = walls_sim::report::Report::new(Vec::new(), &settings, &out);
        let mut json = Vec::new();
        report.write_json(&mut json).unwrap();
        let json = String::from_utf8(json).unwrap();
        assert!(!json.contains("NaN") && !json.contains("inf"), "{json}");
        assert!(json.contains("\"stopped\": \"not-finite\""));
    }
}

#[test]
fn an_interrupted_run_stops_after_the_step_it_is_in() {
    let walls = scene(FLOOR);
    let settings = Settings::new(0.01, 1.0, walls_sim::config::pkdgrav_material(1e5));
    let mut seen = 0;
    let count = std::sync::atomic::AtomicU32::new(0);
    let out = run_watched(
        &walls,
        vec![ball([0.0, 0.0, 1.0], [0.0; 3])],
        &settings,
        &mut |_, _, _| seen += 1,
        &|| count.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1 >= 5,
    );
    assert_eq!((out.steps, out.stopped), (5, Some(Stop::Interrupted)));
    assert_eq!(seen, 5);
}

/// A ball dropped on the floor with ε_n = 1 under the run's own defaults, and its
/// outcome.
fn elastic_drop(dt: Option<f64>, z: f64) -> walls_sim::run::Outcome {
    let flags = Flags {
        inputs: Inputs {
            eps_n: Some(1.0),
            gravity: Some(vec![0.0, 0.0, -1.0]),
            k_n: dt.map(|_| 1e4),
            dt,
            t_end: Some(1.0),
            ..Inputs::default()
        },
        ..Flags::default()
    };
    let walls = scene(FLOOR);
    let r = resolve(
        &flags,
        None,
        &walls,
        Some(vec![ball([0.0, 0.0, z], [0.0, 0.0, -1.0])]),
    )
    .unwrap();
    run(&walls, r.particles, &r.settings)
}

fn energy_gained(out: &walls_sim::run::Outcome) -> bool {
    out.warnings
        .iter()
        .any(|w| matches!(w, walls_sim::run::Warning::EnergyGain { .. }))
}

#[test]
fn the_leapfrog_error_at_the_default_timestep_is_no_energy_gain() {
    let mut faster = 0;
    for k in 0..12 {
        let out = elastic_drop(None, 0.3 + 0.05 * f64::from(k));
        // Some rebounds are a little faster, as the integrator's error allows ...
        faster += out
            .events
            .iter()
            .filter(|e| e.vn_out > e.vn_in * (1.0 + 1e-9))
            .count();
        // ... which is not a warning.
        assert!(!energy_gained(&out), "{:?}", out.warnings);
    }
    assert!(faster > 0);
}

#[test]
fn a_real_gain_of_energy_is_a_warning() {
    // dt at the stability limit 2/ω₀ of k_n = 10⁴, m = 1: the rebound triples.
    assert!(energy_gained(&elastic_drop(Some(0.02), 0.5)));
}

#[test]
fn spheres_at_the_smallest_and_largest_scales_meet_as_they_are() {
    // Pairs that touch, each at its own scale: spheres of 6e−23 overlapping by 2.7 % of
    // their radius (whose distances' squares fall below `f32`'s normal numbers, where
    // the pairs' first test, on centres rounded to `f32`, must not tell them apart),
    // and spheres of 1 mm meeting 1 km, 10¹⁵⁰ and −10¹⁴⁰ from the origin. Each pair
    // opens one contact.
    let row = |r: f64, p: [f64; 3], v: [f64; 3]| {
        format!(
            "1e-9,{r},{},{},{},{},{},{}",
            p[0], p[1], p[2], v[0], v[1], v[2]
        )
    };
    let settings = Settings::new(1e-6, 2e-4, walls_sim::run::defaults::default_material(1e-3));
    let contacts = |rows: &[String]| {
        let csv = format!("mass,radius,x,y,z,vx,vy,vz\n{}\n", rows.join("\n"));
        let out = run(&[], read_csv(&csv).expect("particles").particles, &settings);
        (out.pair_contacts, out.stopped)
    };
    let tiny = [
        row(6e-23, [0.0, 0.0, 0.0], [0.0; 3]),
        row(6e-23, [6.1e-23, 8e-23, 6.24e-23], [0.0; 3]),
    ];
    assert_eq!(contacts(&tiny), (1, None));
    let far: Vec<String> = [1e3, 1e150, -1e140]
        .into_iter()
        .enumerate()
        .flat_map(|(k, x)| {
            let y = 0.01 * (k + 1) as f64;
            [
                row(1e-3, [x, y, 0.0], [0.0, 0.1, 0.0]),
                row(1e-3, [x, y + 2.02e-3, 0.0], [0.0, -0.1, 0.0]),
            ]
        })
        .collect();
    assert_eq!(contacts(&far), (3, None));
}
