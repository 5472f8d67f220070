//! Cohesion (`DEM_COHESION`, docs/pkdgrav-physics.md §7) and two-layer contacts
//! (`DEM_TWOLAYERS`, §8): the cohesive force of each model against particles and walls
//! (with and without `bUseContactRadius`), added after the friction limits; the
//! per-colour cohesion file, its combination rules and its located errors; the two-layer
//! force across the boundary and the shear spring's rescaling; the `.par` sentinels; and
//! the warnings of a run whose build lacks the option.

use nalgebra::Vector3;
use std::f64::consts::PI;
use walls_geometry::Particle;
use walls_sim::build::Build;
use walls_sim::config::{Flags, Inputs, Stepping, load, read_par, resolve};
use walls_sim::contact::cohesion::{
    Cohesion, Colours, Model, Rule, against_wall, between_particles,
};
use walls_sim::contact::ssdem::{
    Dashpot, Layers, Material, Optional, Record, Sliding, dashpot_contact, dashpot_contact_with,
};
use walls_sim::io::cohesion::{read_cohesion, read_file};
use walls_sim::io::par::{KT_PER_KN, read_par as parse_par};
use walls_sim::run::{Integrator, ParticleMaterial, Settings, Warning, run};
use walls_test_support::{ball, scene};

type Vec3 = Vector3<f64>;

fn close(got: f64, want: f64) {
    assert!(
        (got - want).abs() <= 1e-14 * want.abs().max(1e-300),
        "{got} is not {want}"
    );
}

#[test]
fn microscopic_contact_model_scales_with_beta_s_and_the_reduced_radius() {
    let (c, beta, r1, r2) = (3e-3, 0.5, 0.1, 0.3);
    let reduced = r1 * r2 / (r1 + r2);
    close(
        between_particles(Model::Contact, c, beta, r1, r2, None),
        c * 4.0 * beta * beta * reduced * reduced,
    );
    // Against a wall, R* is the particle's radius.
    close(
        against_wall(Model::Contact, c, beta, r1, None),
        c * 4.0 * beta * beta * r1 * r1,
    );
    // With bUseContactRadius, the contact radius a: c·π·β_s²·a².
    let a = 0.02;
    close(
        between_particles(Model::Contact, c, beta, r1, r2, Some(a)),
        c * PI * beta * beta * a * a,
    );
    close(
        against_wall(Model::Contact, c, beta, r1, Some(a)),
        c * PI * beta * beta * a * a,
    );
}

#[test]
fn granular_bridge_model_ignores_beta_s_and_the_contact_radius() {
    let (c, r1, r2) = (6e-3, 0.1, 0.3);
    let want = c * 2.0 * PI * r1 * r1 * r2 * r2 / (r1 * r1 + r2 * r2);
    close(between_particles(Model::Bridge, c, 0.5, r1, r2, None), want);
    close(
        between_particles(Model::Bridge, c, 0.9, r1, r2, Some(0.01)),
        want,
    );
    close(
        against_wall(Model::Bridge, c, 0.5, r1, None),
        c * 2.0 * PI * r1 * r1,
    );
    close(
        against_wall(Model::Bridge, c, 0.9, r1, Some(0.01)),
        c * 2.0 * PI * r1 * r1,
    );
}

fn material(mu_s: f64) -> Material {
    Material {
        eps_n: 0.5,
        eps_t: 0.5,
        k_n: 1e5,
        k_t: KT_PER_KN * 1e5,
        mu_s,
        mu_r: 0.0,
        mu_t: 0.0,
        beta_s: 0.5,
    }
}

/// A particle of mass 1 pressed into a wall below it by `x`, with the contact point
/// slipping at `slip` (the wall's motion relative to the particle).
fn pressed(x: f64, slip: Vec3) -> Dashpot {
    Dashpot {
        overlap: x,
        normal: -Vec3::z(),
        velocity: slip,
        spin: Vec3::zeros(),
        turn: Vec3::zeros(),
        levers: (0.1 - x, 0.0),
        mass: 1.0,
        radius: 0.1,
        wall: true,
        constant_torque: None,
        sliding: Sliding::Reset,
    }
}

#[test]
fn cohesion_pulls_along_the_normal_and_does_not_raise_the_friction_limit() {
    let mat = material(0.5);
    let c = pressed(1e-3, Vec3::new(1.0, 0.0, 0.0));
    let plain = dashpot_contact(&c, &mut Record::default(), 1e-4, &mat);
    let pull = 7.0;
    let with = dashpot_contact_with(
        &c,
        &mut Record::default(),
        1e-4,
        &mat,
        &Optional {
            cohesion: pull,
            ..Optional::default()
        },
    );
    // Towards the wall (n̂ points from the particle to the wall), by exactly `pull`.
    let diff = with.force - plain.force;
    close(diff.z, -pull);
    assert_eq!((diff.x, diff.y), (0.0, 0.0));
    // The tangential force, slid to its cap μ_s·N, is the same: N excludes cohesion.
    assert_eq!(with.torque, plain.torque);
}

#[test]
fn colours_take_their_own_coefficient_and_combine_by_the_rule() {
    let table = |rule| Cohesion {
        model: Model::Contact,
        coefficient: 1e-3,
        colours: Some(Colours {
            rule,
            coefficients: vec![(1, 2e-3), (2, 6e-3)],
        }),
    };
    let t = table(Rule::Mean);
    assert_eq!(t.of_colour(1), 2e-3);
    assert_eq!(t.of_colour(7), 1e-3, "an unlisted colour: dCohesiveCoeff");
    assert_eq!(t.between(2, 2), 6e-3);
    assert_eq!(t.between(1, 2), 4e-3);
    assert_eq!(t.between(1, 7), 1.5e-3);
    assert_eq!(table(Rule::Max).between(1, 2), 6e-3);
    assert_eq!(table(Rule::Min).between(2, 1), 2e-3);
    assert_eq!(table(Rule::None).between(1, 2), 0.0);
    assert_eq!(table(Rule::None).between(1, 1), 2e-3);
    // Without a file, every particle has dCohesiveCoeff.
    let plain = Cohesion {
        coefficient: 1e-3,
        ..Cohesion::default()
    };
    assert_eq!(plain.between(1, 2), 1e-3);
}

#[test]
fn the_cohesion_file_is_n_then_the_rule_then_colour_coefficient_lines() {
    let t = read_cohesion("2\n1\n0 1e-3\n5 2.5e-3\n").unwrap();
    assert_eq!(
        t,
        (
            Colours {
                rule: Rule::Mean,
                coefficients: vec![(0, 1e-3), (5, 2.5e-3)],
            },
            vec![]
        )
    );
    // N and the rule may share a line.
    assert_eq!(read_cohesion("1 3\n4 1\n").unwrap().0.rule, Rule::Min);
    assert_eq!(read_cohesion("0 0\n").unwrap().0.coefficients, vec![]);
}

#[test]
fn the_cohesion_files_errors_name_the_file_and_the_line() {
    let err = |text: &str| read_cohesion(text).unwrap_err().to_string();
    assert_eq!(
        err("x\n"),
        "line 1: the number of colours is `x`, not a whole number of 0 or more"
    );
    assert_eq!(
        err("2\n4\n"),
        "line 2: the rule is `4`; it must be 0 (none), 1 (mean), 2 (max) or 3 (min)"
    );
    assert_eq!(
        err("2\n1\n0 1e-3\n1 abc\n"),
        "line 4: the coefficient of colour 1 is `abc`, not a number"
    );
    assert_eq!(
        err("1\n1\n0 nan\n"),
        "line 3: the coefficient of colour 0 is `nan`, not a finite number"
    );
    // Numbers a double cannot hold, which pkdgrav's reading would turn into 0 or
    // infinity without a word.
    assert_eq!(
        err("1\n1\n0 1e-400\n"),
        "line 3: the coefficient of colour 0 is `1e-400`, too small for a double: pkdgrav reads it as 0"
    );
    assert_eq!(
        err("1\n1\n0 1e999\n"),
        "line 3: the coefficient of colour 0 is `1e999`, too large for a double: pkdgrav reads it as infinity"
    );
    // A huge announced count is an error about the file, not memory reserved for it.
    assert_eq!(
        err("444444444 0 444444444 0 444444444"),
        "line 1: the file ends where the coefficient of colour 444444444 should be"
    );
    // A count beyond a C int, which pkdgrav would read as another number.
    assert_eq!(
        err("4444444444 0 444444444 0 444444444"),
        "line 1: the number of colours is `4444444444`, beyond a C int, which pkdgrav reads it into (it would read another number): give at most 2147483647"
    );
    assert_eq!(
        err("2\n1\n0 1e-3\n"),
        "line 3: the file ends where colour 2 of 2 should be"
    );
    assert_eq!(
        err("2\n1\n3 1e-3\n3 2e-3\n"),
        "line 4: colour 3 is listed twice"
    );
    assert_eq!(
        err("1\n1\n3 1e-3\n4 2e-3\n"),
        "line 4: `4` follows the 1 colours the file's first number announces"
    );
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("coh.txt");
    std::fs::write(&path, "1\n2\n1.5 2e-3\n").unwrap();
    let path = path.to_str().unwrap();
    assert_eq!(
        read_file(path).unwrap_err().to_string(),
        format!("{path}: line 3: the colour is `1.5`, not a whole number")
    );
}

fn layers() -> Layers {
    Layers {
        boundary: 1e-3,
        k_n_outer: 1e4,
        k_t_outer: KT_PER_KN * 1e4,
        k_n_inner: 1e5,
        k_t_inner: 3e4,
    }
}

#[test]
fn the_two_layer_normal_force_is_continuous_at_the_boundary() {
    let l = layers();
    let b = l.boundary;
    let (outer, _, _, at) = l.at(b);
    assert_eq!(outer, 1);
    close(at, l.k_n_outer * b);
    let just = b * (1.0 + 1e-12);
    let (inner, k_n, k_t, above) = l.at(just);
    assert_eq!((inner, k_n, k_t), (-1, l.k_n_inner, l.k_t_inner));
    assert!((above - at).abs() <= 1e-9 * at, "{above} vs {at}");
    close(l.at(2.0 * b).3, l.k_n_inner * b + l.k_n_outer * b);
    // Through the dashpot law: the force is the layer's spring, continuous too.
    let mat = material(10.0);
    let force = |x: f64| {
        let c = pressed(x, Vec3::zeros());
        let extra = Optional {
            cohesion: 0.0,
            layers: Some(l),
            ..Optional::default()
        };
        dashpot_contact_with(&c, &mut Record::default(), 1e-4, &mat, &extra)
            .force
            .z
    };
    assert!((force(just) - force(b)).abs() <= 1e-9 * force(b).abs());
    close(force(b), l.k_n_outer * b);
}

#[test]
fn crossing_the_boundary_rescales_the_shear_spring_and_keeps_its_energy() {
    let l = layers();
    let mat = material(1e6);
    let extra = Optional {
        cohesion: 0.0,
        layers: Some(l),
        ..Optional::default()
    };
    let spring = Vec3::new(2e-4, -1e-4, 0.0);
    let energy = |k: f64, s: &Vec3| 0.5 * k * s.norm_squared();
    // Outer last step, inner now: S·√(k_t,out/k_t,in).
    let mut record = Record {
        spring,
        normal: -Vec3::z(),
        layer: 1,
        ..Record::default()
    };
    dashpot_contact_with(
        &pressed(2e-3, Vec3::zeros()),
        &mut record,
        1e-4,
        &mat,
        &extra,
    );
    assert_eq!(record.layer, -1);
    close(
        energy(l.k_t_inner, &record.spring),
        energy(l.k_t_outer, &spring),
    );
    // And back out.
    let inner = record.spring;
    dashpot_contact_with(
        &pressed(5e-4, Vec3::zeros()),
        &mut record,
        1e-4,
        &mat,
        &extra,
    );
    assert_eq!(record.layer, 1);
    close(
        energy(l.k_t_outer, &record.spring),
        energy(l.k_t_inner, &inner),
    );
    close(record.spring.x, spring.x);
    // A new contact (layer 0) starting in the inner layer keeps its spring.
    let mut fresh = Record {
        spring,
        normal: -Vec3::z(),
        ..Record::default()
    };
    dashpot_contact_with(
        &pressed(2e-3, Vec3::zeros()),
        &mut fresh,
        1e-4,
        &mat,
        &extra,
    );
    assert_eq!((fresh.layer, fresh.spring), (-1, spring));
}

/// Resolves `par` (a `.par` file's text) for a floor scene with `build`.
fn settings_of(par: &str, build: &str) -> (Settings, Vec<String>) {
    settings_with(par, build, Integrator::Pkdgrav)
}

/// [`settings_of`] with `integrator`.
fn settings_with(par: &str, build: &str, integrator: Integrator) -> (Settings, Vec<String>) {
    let params = parse_par(par).unwrap();
    let flags = Flags {
        inputs: Inputs {
            build: Some(Build::parse(build).unwrap()),
            ..Inputs::default()
        },
        stepping: Stepping {
            integrator,
            ..Stepping::default()
        },
        ..Flags::default()
    };
    let run = resolve(
        &flags,
        Some(&params),
        &scene("wall type plane\n"),
        Some(vec![ball([0.0, 0.0, 0.5], [0.0; 3])]),
    )
    .unwrap();
    let warned = run.warnings.iter().map(ToString::to_string).collect();
    (run.settings, warned)
}

#[test]
fn par_two_layer_sentinels_fall_back_to_dkn_and_two_sevenths() {
    let (s, warned) = settings_of(
        "dKn = 1e5\ndInnerOverlapBndry = 0.01\ndKnOuter = -1\ndKtOuter = -1\ndKnInner = 3e5\n",
        "DEM DEM_ROTATION_DASHPOT DEM_TWOLAYERS",
    );
    let t = s.two_layer.unwrap();
    assert_eq!((t.boundary, t.k_n_outer, t.k_n_inner), (0.01, 1e5, 3e5));
    assert_eq!(
        (t.k_t_outer, t.k_t_inner),
        (KT_PER_KN * 1e5, KT_PER_KN * 3e5)
    );
    assert_eq!(warned, Vec::<String>::new());
}

#[test]
fn par_keys_of_a_build_option_the_run_lacks_are_warned_about() {
    let text = "dKn = 1e5\niCohesionModel = 1\ndCohesiveCoeff = 2e-3\ndKnOuter = 1e4\n";
    let (s, warned) = settings_of(text, "DEM DEM_ROTATION_DASHPOT");
    assert_eq!(warned.len(), 3, "{warned:?}");
    assert!(warned[0].starts_with("line 2: `iCohesionModel`: the build lacks DEM_COHESION"));
    assert!(warned[1].starts_with("line 3: `dCohesiveCoeff`: the build lacks DEM_COHESION"));
    assert!(warned[2].starts_with("line 4: `dKnOuter`: the build lacks DEM_TWOLAYERS"));
    // The values are still read.
    assert_eq!(
        (s.cohesion.model, s.cohesion.coefficient),
        (Model::Bridge, 2e-3)
    );
    // With the options, no warning.
    let (_, warned) = settings_of(text, "DEM DEM_ROTATION_DASHPOT DEM_COHESION DEM_TWOLAYERS");
    assert_eq!(warned, Vec::<String>::new());
    // With the options but another integrator, each key is ignored, saying which one
    // follows it.
    let (_, warned) = settings_with(
        "dKn = 1e5\ndCohesiveCoeff = 2e-3\n",
        "DEM DEM_ROTATION_DASHPOT DEM_COHESION",
        Integrator::Leapfrog,
    );
    assert_eq!(
        warned,
        [
            "line 2: `dCohesiveCoeff`: cohesion (docs/pkdgrav-physics.md §7) is followed only with pkdgrav's contact law (--integrator pkdgrav, the default): the run ignores the key"
        ]
    );
    // An invalid model is an error on its line.
    assert_eq!(
        parse_par("iCohesionModel = 2\n").unwrap_err().to_string(),
        "line 1: `iCohesionModel` is `2`; it must be 0 (microscopic contact) or 1 (granular bridge)"
    );
}

#[test]
fn the_cohesion_file_is_read_beside_the_par_file() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("coh.txt"), "1\n2\n4 5e-3\n").unwrap();
    std::fs::write(
        dir.path().join("ball.csv"),
        "mass,radius,x,y,z,vx,vy,vz\n1,0.1,0,0,0.3,0,0,0\n",
    )
    .unwrap();
    let par = dir.path().join("run.par");
    // A run directory pkdgrav's DEM build runs (its input file, the two settings every
    // DEM run needs), with cohesion's keys.
    std::fs::write(
        &par,
        "achInFile = ball.csv\niForceOverrideOption = 2\niCheckInterval = 0\ndKn = 1e5\ndCohesiveCoeff = 1e-3\nachCohesionFile = coh.txt\n",
    )
    .unwrap();
    let flags = Flags {
        inputs: Inputs {
            par: Some(par.to_str().unwrap().to_string()),
            build: Some(Build::parse("DEM DEM_ROTATION_DASHPOT DEM_COHESION").unwrap()),
            ..Inputs::default()
        },
        stepping: Stepping {
            integrator: Integrator::Pkdgrav,
            ..Stepping::default()
        },
        ..Flags::default()
    };
    let params = read_par(&flags).unwrap();
    let walls = scene("wall type plane\n");
    let run = load(&flags, params.as_ref(), &walls).unwrap();
    let colours = run.settings.cohesion.colours.unwrap();
    assert_eq!(
        (colours.rule, colours.coefficients),
        (Rule::Max, vec![(4, 5e-3)])
    );
    // A bad file stops the run, naming it and the line.
    std::fs::write(dir.path().join("coh.txt"), "1\n9\n").unwrap();
    let e = load(&flags, params.as_ref(), &walls)
        .unwrap_err()
        .to_string();
    assert!(
        e.ends_with(
            "coh.txt: line 2: the rule is `9`; it must be 0 (none), 1 (mean), 2 (max) or 3 (min)"
        ),
        "{e}"
    );
}

fn pkdgrav(build: &str, integrator: Integrator) -> Settings {
    let mat = ParticleMaterial {
        eps_n: 0.5,
        eps_t: 0.5,
        k_n: 1e5,
        k_t: KT_PER_KN * 1e5,
        mu_s: 0.5,
        mu_r: 0.0,
        mu_t: 0.0,
        beta_s: 0.5,
    };
    Settings {
        integrator,
        build: Build::parse(build).unwrap(),
        gravity: Vector3::new(0.0, 0.0, -9.8),
        cohesion: Cohesion {
            coefficient: 1e3,
            ..Cohesion::default()
        },
        ..Settings::new(1e-4, 0.05, mat)
    }
}

#[test]
fn walls_tokens_of_a_build_option_the_run_lacks_are_warned_about() {
    let walls = scene(
        "wall type plane\nwall type plane origin 0 0 -1 cohesive_coeff 1e-3 cohesion_model 1 k_n_outer 1e4\n",
    );
    let p = vec![ball([0.0, 0.0, 0.099], [0.0; 3])];
    let codes = |s: &Settings| -> Vec<(String, String)> {
        run(&walls, p.clone(), s)
            .warnings
            .iter()
            .filter(|w| w.code().starts_with("W5"))
            .map(|w| (w.code().to_string(), w.to_string()))
            .collect()
    };
    let lacking = codes(&pkdgrav("DEM DEM_ROTATION_DASHPOT", Integrator::Pkdgrav));
    assert_eq!(lacking.len(), 2, "{lacking:?}");
    assert_eq!(lacking[0].0, "W501");
    assert!(
        lacking[0].1.contains("cohesion_model, cohesive_coeff"),
        "{}",
        lacking[0].1
    );
    assert!(lacking[0].1.contains("the build lacks DEM_COHESION"));
    assert_eq!(lacking[1].0, "W502");
    // k_n_outer also sets k_t_outer (to 2/7 of it): both are the wall's.
    assert!(
        lacking[1]
            .1
            .contains("k_n_outer, k_t_outer: the build lacks DEM_TWOLAYERS"),
        "{}",
        lacking[1].1
    );
    // Another integrator does not follow them either.
    let leapfrog = codes(&pkdgrav(
        "DEM DEM_ROTATION_DASHPOT DEM_COHESION DEM_TWOLAYERS",
        Integrator::Leapfrog,
    ));
    assert_eq!(leapfrog.len(), 2);
    assert_eq!(
        leapfrog[0].1,
        "walls [1] set cohesion_model, cohesive_coeff: DEM_COHESION is followed only with pkdgrav's contact law (--integrator pkdgrav, the default), so the run has no cohesion and ignores them"
    );
    let full = pkdgrav(
        "DEM DEM_ROTATION_DASHPOT DEM_COHESION DEM_TWOLAYERS",
        Integrator::Pkdgrav,
    );
    assert_eq!(codes(&full), vec![]);
    assert!(matches!(
        Warning::CohesionTokensIgnored {
            walls: vec![],
            tokens: vec![],
            reason: String::new()
        }
        .code(),
        "W501"
    ));
}

/// Two particles of colours 1 and 2 overlapping at rest, with no gravity.
fn pair() -> Vec<Particle> {
    let mut a = ball([0.0, 0.0, 1.0], [0.0; 3]);
    let mut b = ball([0.0, 0.0, 1.199], [0.0; 3]);
    a.color = 1;
    b.color = 2;
    vec![a, b]
}

#[test]
fn a_pair_of_two_colours_coheres_with_the_combined_coefficient() {
    let walls = scene("wall type plane origin 0 0 -5\n");
    let base = Settings {
        gravity: Vec3::zeros(),
        t_end: 0.01,
        ..pkdgrav("DEM DEM_ROTATION_DASHPOT DEM_COHESION", Integrator::Pkdgrav)
    };
    let coloured = Settings {
        cohesion: Cohesion {
            model: Model::Contact,
            coefficient: 0.0,
            colours: Some(Colours {
                rule: Rule::Mean,
                coefficients: vec![(1, 1e3), (2, 3e3)],
            }),
        },
        ..base.clone()
    };
    let uniform = Settings {
        cohesion: Cohesion {
            coefficient: 2e3,
            ..Cohesion::default()
        },
        ..base.clone()
    };
    let none = Settings {
        cohesion: Cohesion::default(),
        ..base
    };
    let end = |s: &Settings| run(&walls, pair(), s).particles[1].particle.pos.z;
    assert_eq!(end(&coloured), end(&uniform));
    // Cohesion pulls the pair closer than the springs alone leave it.
    assert!(
        end(&uniform) < end(&none),
        "{} {}",
        end(&uniform),
        end(&none)
    );
}

#[test]
fn a_walls_cohesive_coefficient_of_minus_one_is_dcohesivecoeff_not_the_colour_table() {
    use walls_sim::run::optional::OptionalPhysics;
    // pkdgrav-physics §17: a wall's −1 (its default) is the global dCohesiveCoeff, never
    // the particle's colour's coefficient.
    let walls = scene("wall type plane\nwall type plane\n  cohesive_coeff 7e3\n");
    let settings = Settings {
        cohesion: Cohesion {
            model: Model::Contact,
            coefficient: 2e3,
            colours: Some(Colours {
                rule: Rule::Mean,
                coefficients: vec![(3, 5e3)],
            }),
        },
        ..pkdgrav("DEM DEM_ROTATION_DASHPOT DEM_COHESION", Integrator::Pkdgrav)
    };
    let mut p = ball([0.0, 0.0, 0.05], [0.0; 3]);
    p.color = 3;
    let states = vec![walls_sim::run::State::new(&p)];
    let physics = OptionalPhysics::new(&walls, &states, &settings);
    let mat = material(0.5);
    let force = |w: usize| physics.wall(w, 0.1, None, &mat).cohesion;
    let want = |c: f64| against_wall(Model::Contact, c, mat.beta_s, 0.1, None);
    assert_eq!(force(0), want(2e3));
    assert_eq!(force(1), want(7e3));
}
