//! `config`: a run's settings come from the command line's flag if given, else the
//! `.par` file, else the default (pkdgrav's, for a run from a `.par` file); the walls
//! file from the argument, else the `.par` file's `achWallsFile`; the particles from
//! `--particles`, else the `.par` file's `achInFile` (both beside the `.par` file), else
//! the dropped default particles. `nSteps` and `iStartStep` are pkdgrav's step numbers.

use nalgebra::Vector3;
use walls_sim::config::{
    ConfigError, Flags, Inputs, Run, Stepping, load, particle_file, read_par, resolve, ss_base,
    walls_file,
};
use walls_sim::io::par::KT_PER_KN;
use walls_sim::io::par::Params;
use walls_sim::run::default_dt;
use walls_sim::run::defaults;
use walls_test_support::{ball as particle, scene};

const FLOOR: &str = "wall type plane origin 0 0 0\n";

/// Reads the `.par` file `flags` name, then the particles, as `walls-sim run` does.
fn load_all(flags: &Flags, walls: &[walls_geometry::Wall]) -> Result<Run, ConfigError> {
    let par = read_par(flags)?;
    load(flags, par.as_ref(), walls)
}

fn ball() -> Vec<walls_geometry::Particle> {
    vec![particle([0.0, 0.0, 0.3], [0.0, 0.0, -2.0])]
}

/// A `.par` file's values for dt, k_n and gravity.
fn par() -> Params {
    Params {
        dt: Some(2e-5),
        k_n: Some(4e5),
        gravity: Some(Vector3::new(0.0, 0.0, -9.8)),
        ..Params::default()
    }
}

#[test]
fn a_flag_beats_the_par_file() {
    let flags = Flags {
        inputs: Inputs {
            dt: Some(1e-5),
            k_n: Some(1e5),
            gravity: Some(vec![1.0, 0.0, 0.0]),
            ..Inputs::default()
        },
        ..Flags::default()
    };
    let run = resolve(&flags, Some(&par()), &scene(FLOOR), Some(ball())).unwrap();
    assert_eq!(run.settings.dt, 1e-5);
    assert_eq!(run.settings.material.k_n, 1e5);
    assert_eq!(run.settings.gravity, Vector3::new(1.0, 0.0, 0.0));
}

#[test]
fn a_gravity_of_other_than_three_numbers_is_an_error_not_a_panic() {
    for numbers in [vec![], vec![1.0], vec![1.0, 2.0, 3.0, 4.0]] {
        let flags = Flags {
            inputs: Inputs {
                gravity: Some(numbers.clone()),
                ..Inputs::default()
            },
            ..Flags::default()
        };
        let Err(ConfigError::Unusable(e)) = resolve(&flags, None, &scene(FLOOR), Some(ball()))
        else {
            panic!("{numbers:?}: accepted");
        };
        assert_eq!(
            e,
            format!(
                "--gravity takes three numbers (x, y, z), not {}",
                numbers.len()
            )
        );
    }
}

#[test]
fn the_par_file_beats_the_default() {
    let run = resolve(&Flags::default(), Some(&par()), &scene(FLOOR), Some(ball())).unwrap();
    assert_eq!(run.settings.dt, 2e-5);
    assert_eq!(run.settings.material.k_n, 4e5);
    assert_eq!(run.settings.gravity, Vector3::new(0.0, 0.0, -9.8));
    // k_t follows the k_n it was given, as the default material does.
    assert_eq!(
        run.settings.material.k_t,
        defaults::default_material(4e5).k_t
    );
}

#[test]
fn without_flag_or_par_file_the_default() {
    let floor = scene(FLOOR);
    let run = resolve(&Flags::default(), None, &floor, Some(ball())).unwrap();
    let g = Vector3::zeros();
    let k_n = defaults::default_k_n(&floor, &ball(), &g);
    assert_eq!(
        run.settings.gravity, g,
        "no gravity for particles from a file"
    );
    assert_eq!(run.settings.material.k_n, k_n);
    // pkdgrav's suggestion, shortened so that whole steps end on the default duration.
    let t_end = defaults::default_duration(&floor, &ball(), &g);
    assert_eq!(run.settings.t_end, t_end);
    let n = (t_end / default_dt(&ball(), k_n)).ceil();
    assert_eq!(run.settings.dt, t_end / n);
    assert_eq!(run.settings.end_step(), n as u64);
    assert_eq!(run.settings.time_at(n as u64), t_end);
    // The dropped default particles fall: gravity −z.
    let run = resolve(&Flags::default(), None, &floor, None).unwrap();
    assert_eq!(run.settings.gravity, Vector3::new(0.0, 0.0, -1.0));
    assert_eq!(run.particles, defaults::default_particles(&floor));
}

#[test]
fn the_par_file_gives_the_duration_and_edge_detection() {
    let par = Params {
        steps: Some(300),
        dt: Some(0.5),
        edge_detect: Some(false),
        ..Params::default()
    };
    let run = resolve(&Flags::default(), Some(&par), &scene(FLOOR), Some(ball())).unwrap();
    assert_eq!(run.settings.t_end, 150.0);
    assert!(!run.settings.edges);
    let flags = Flags {
        inputs: Inputs {
            t_end: Some(2.0),
            ..Inputs::default()
        },
        ..Flags::default()
    };
    let run = resolve(&flags, Some(&par), &scene(FLOOR), Some(ball())).unwrap();
    assert_eq!(run.settings.t_end, 2.0);
}

#[test]
fn the_particle_file_from_the_flag_else_the_par_file() {
    let par = Params {
        in_file: Some("in.ss".into()),
        ..Params::default()
    };
    let mut flags = Flags {
        inputs: Inputs {
            par: Some("runs/a/run.par".into()),
            ..Inputs::default()
        },
        ..Flags::default()
    };
    // achInFile is beside the .par file.
    let beside = std::path::Path::new("runs/a").join("in.ss");
    assert_eq!(
        particle_file(&flags, Some(&par)).as_deref(),
        beside.to_str()
    );
    flags.inputs.particles = Some("balls.csv".into());
    assert_eq!(
        particle_file(&flags, Some(&par)).as_deref(),
        Some("balls.csv")
    );
    // Neither: the default particles.
    assert_eq!(particle_file(&Flags::default(), None), None);
}

#[test]
fn load_reads_the_par_file_and_its_particles() {
    let dir = tempfile::tempdir().unwrap();
    let write = |name: &str, text: &str| std::fs::write(dir.path().join(name), text).unwrap();
    write(
        "run.par",
        "achInFile = ball.csv\ndDelta = 1e-5\ndKn = 3e5\niForceOverrideOption = 2\niCheckInterval = 0\n",
    );
    write(
        "ball.csv",
        "mass,radius,x,y,z,vx,vy,vz\n1,0.1,0,0,0.3,0,0,-2\n",
    );
    write(
        "two.csv",
        "mass,radius,x,y,z,vx,vy,vz\n1,0.1,0,0,0.3,0,0,-2\n2,0.1,1,0,0.3,0,0,0\n",
    );
    let path = |name: &str| dir.path().join(name).to_string_lossy().into_owned();
    let mut flags = Flags {
        inputs: Inputs {
            par: Some(path("run.par")),
            ..Inputs::default()
        },
        ..Flags::default()
    };
    let run = load_all(&flags, &scene(FLOOR)).unwrap();
    assert_eq!(run.particles.len(), 1);
    assert_eq!((run.settings.dt, run.settings.material.k_n), (1e-5, 3e5));
    flags.inputs.particles = Some(path("two.csv"));
    assert_eq!(load_all(&flags, &scene(FLOOR)).unwrap().particles.len(), 2);

    // Errors name the file and the line.
    write(
        "bad.par",
        "dDelta = 0\niForceOverrideOption = 2\niCheckInterval = 0\n",
    );
    flags.inputs.par = Some(path("bad.par"));
    let e = load_all(&flags, &scene(FLOOR)).unwrap_err();
    assert!(matches!(e, ConfigError::File(_)));
    assert_eq!(
        e.to_string(),
        format!(
            "{}: line 1: `dDelta` is `0`; it must be greater than 0",
            path("bad.par")
        )
    );
    write("none.csv", "mass,radius,x,y,z,vx,vy,vz\n");
    let flags = Flags {
        inputs: Inputs {
            particles: Some(path("none.csv")),
            ..Inputs::default()
        },
        ..Flags::default()
    };
    // A file with no particles runs the walls alone.
    let run = load_all(&flags, &scene(FLOOR)).unwrap();
    assert!(run.particles.is_empty());
    let flags = Flags {
        inputs: Inputs {
            particles: Some(path("missing.csv")),
            ..Inputs::default()
        },
        ..Flags::default()
    };
    let e = load_all(&flags, &scene(FLOOR)).unwrap_err();
    assert!(
        e.to_string()
            .starts_with(&format!("cannot read {}: ", path("missing.csv")))
    );
}

#[test]
fn nsteps_is_the_last_step_counted_exactly() {
    // 20,000 steps of 1.05309e-12 accumulate to less than 20,000·dDelta: a run that
    // stopped by accumulated time would take a 20,001st step; pkdgrav counts, and its
    // time accumulates step by step (the .ss headers hold that time).
    let (dt, n) = (1.05309e-12, 20_000u64);
    let t = (0..n).fold(0.0, |t, _| t + dt);
    assert!(
        t < n as f64 * dt - dt * 1e-9,
        "the accumulated time falls short"
    );
    let par = Params {
        dt: Some(dt),
        steps: Some(n),
        k_n: Some(1e-13),
        ..Params::default()
    };
    // A ball far from the floor: nothing but steps.
    let far = vec![particle([0.0, 0.0, 1e3], [0.0, 0.0, 0.0])];
    let run = resolve(&Flags::default(), Some(&par), &scene(FLOOR), Some(far)).unwrap();
    assert_eq!(run.settings.last_step, Some(n));
    let out = walls_sim::run::run(&scene(FLOOR), run.particles, &run.settings);
    assert_eq!(out.steps, n);
    assert_eq!(out.t, t, "time accumulates step by step, as in pkdgrav");
}

#[test]
fn istartstep_sets_the_first_step_number_and_the_start_time() {
    let par = Params {
        dt: Some(0.01),
        steps: Some(25),
        start_step: Some(5),
        k_n: Some(1e4),
        ..Params::default()
    };
    let run = resolve(&Flags::default(), Some(&par), &scene(FLOOR), Some(ball())).unwrap();
    assert_eq!((run.settings.start_step, run.settings.t_start()), (5, 0.05));
    let mut seen = Vec::new();
    let out = walls_sim::run::run_observed(
        &scene(FLOOR),
        run.particles,
        &run.settings,
        &mut |step, _, _| seen.push(step),
    );
    assert_eq!(seen, (6..=25).collect::<Vec<u64>>());
    assert_eq!(out.steps, 20);
    // A --t-end flag runs by time instead.
    let flags = Flags {
        inputs: Inputs {
            t_end: Some(0.1),
            ..Inputs::default()
        },
        ..Flags::default()
    };
    let run = resolve(&flags, Some(&par), &scene(FLOOR), Some(ball())).unwrap();
    assert_eq!(run.settings.last_step, None);
}

#[test]
fn a_par_run_takes_pkdgravs_defaults_and_sentinels() {
    let par = Params {
        k_n: Some(7e4),
        ..Params::default()
    };
    let m = resolve(&Flags::default(), Some(&par), &scene(FLOOR), Some(ball()))
        .unwrap()
        .settings
        .material;
    // dKt = -1 (or left out) is 2/7·dKn; ε 1 and no friction are pkdgrav's defaults.
    assert_eq!(m.k_t, KT_PER_KN * 7e4);
    assert_eq!((m.eps_n, m.eps_t), (1.0, 1.0));
    assert_eq!((m.mu_s, m.mu_r, m.mu_t), (0.0, 0.0, 0.0));
    // dKt = -1 follows a k_n given on the command line.
    let flags = Flags {
        inputs: Inputs {
            k_n: Some(1e5),
            ..Inputs::default()
        },
        ..Flags::default()
    };
    let m = resolve(&flags, Some(&par), &scene(FLOOR), Some(ball()))
        .unwrap()
        .settings
        .material;
    assert_eq!(m.k_t, KT_PER_KN * 1e5);
    // dKn = 0: pkdgrav's spring-less run, with a timestep from the scene's spring.
    let par = Params {
        k_n: Some(0.0),
        ..Params::default()
    };
    let run = resolve(&Flags::default(), Some(&par), &scene(FLOOR), Some(ball())).unwrap();
    assert_eq!(run.settings.material.k_n, 0.0);
    assert!(run.settings.dt.is_finite() && run.settings.dt > 0.0);
}

#[test]
fn the_walls_file_from_the_argument_else_beside_the_par_file() {
    let par = Params {
        walls_file: Some("walls.dat".into()),
        ..Params::default()
    };
    let flags = Flags {
        inputs: Inputs {
            par: Some("runs/a/ss.par".into()),
            ..Inputs::default()
        },
        ..Flags::default()
    };
    let beside = std::path::Path::new("runs/a").join("walls.dat");
    assert_eq!(
        walls_file(None, &flags, Some(&par)).as_deref(),
        beside.to_str()
    );
    assert_eq!(
        walls_file(Some("mine.walls"), &flags, Some(&par)).as_deref(),
        Some("mine.walls")
    );
    // Neither names one.
    assert_eq!(walls_file(None, &flags, Some(&Params::default())), None);
    assert_eq!(walls_file(None, &Flags::default(), None), None);
}

#[test]
fn the_sliding_rule_is_pkdgrav_s_reset_unless_given_and_the_clamp_needs_its_contact_law() {
    use walls_sim::contact::ssdem::Sliding;
    use walls_sim::run::{ContactModel, Integrator};
    let run = resolve(&Flags::default(), Some(&par()), &scene(FLOOR), Some(ball())).unwrap();
    assert_eq!(run.settings.sliding, Sliding::Reset);
    let clamp = Flags {
        stepping: Stepping {
            sliding: Sliding::Clamp,
            ..Stepping::default()
        },
        ..Flags::default()
    };
    let run = resolve(&clamp, None, &scene(FLOOR), Some(ball())).unwrap();
    assert_eq!(run.settings.sliding, Sliding::Clamp);
    let refused = |flags: Flags| {
        resolve(&flags, None, &scene(FLOOR), Some(ball()))
            .unwrap_err()
            .to_string()
    };
    assert_eq!(
        refused(Flags {
            stepping: Stepping {
                integrator: Integrator::Leapfrog,
                ..clamp.stepping
            },
            ..clamp.clone()
        }),
        "--sliding clamp changes pkdgrav's contact law, which only --integrator pkdgrav runs (the comparison integrators' law resets the spring): leave one of them out"
    );
    assert_eq!(
        refused(Flags {
            inputs: Inputs {
                method: ContactModel::Hsdem,
                ..clamp.inputs
            },
            ..clamp
        }),
        "--sliding clamp is a rule of the soft-sphere shear spring; hard spheres have none: leave it out, or run --method ssdem"
    );
}

#[test]
fn the_ss_outputs_never_take_a_folder_from_achoutname() {
    assert_eq!(ss_base(None), ("ss".into(), None));
    assert_eq!(ss_base(Some("run")), ("run".into(), None));
    for (name, base) in [
        ("../../e", "e"),
        ("/scratch/run/e", "e"),
        ("out/ss", "ss"),
        ("..", "ss"),
        ("/", "ss"),
    ] {
        let (got, warning) = ss_base(Some(name));
        assert_eq!(got, base, "{name}");
        assert!(warning.unwrap().contains(name), "{name}");
    }
}

#[test]
fn a_par_file_pkdgrav_refuses_is_refused_unless_the_command_line_sets_the_key() {
    let dir = tempfile::tempdir().unwrap();
    let par = dir.path().join("run.par");
    std::fs::write(
        &par,
        "dDelta = 1e-5\nnSteps = 10\niForceOverrideOption = 2\niCheckInterval = 0\n",
    )
    .unwrap();
    let mut flags = Flags {
        inputs: Inputs {
            par: Some(par.to_string_lossy().into_owned()),
            ..Inputs::default()
        },
        ..Flags::default()
    };
    // pkdgrav stops without an input file ...
    let e = read_par(&flags).unwrap_err().to_string();
    assert!(
        e.contains("no input file (`achInFile`) [A11]") && e.contains("[P008]"),
        "{e}"
    );
    // ... which the command line's particle file is.
    flags.inputs.particles = Some("ball.csv".into());
    assert!(read_par(&flags).unwrap().is_some());
    // A line pkdgrav refuses is named, with what pkdgrav would do.
    std::fs::write(&par, "achInFile = b.csv\ndDelta = 1e-5 ! s\n").unwrap();
    let e = read_par(&flags).unwrap_err().to_string();
    assert!(
        e.contains("line 2: `!` is not a comment in a .par file"),
        "{e}"
    );
}

#[test]
fn the_overlap_levels_come_from_the_par_file_else_pkdgrav_s_defaults() {
    let flags = Flags::default();
    let given = Params {
        overlap_fracs: [None, Some(0.1), Some(0.25)],
        ..par()
    };
    let run = resolve(&flags, Some(&given), &scene(FLOOR), Some(ball())).unwrap();
    let levels = run.settings.overlap_levels;
    assert_eq!(
        (levels.minor, levels.major, levels.error),
        (0.03, 0.1, 0.25)
    );
    let run = resolve(&flags, None, &scene(FLOOR), Some(ball())).unwrap();
    assert_eq!(
        run.settings.overlap_levels,
        walls_sim::run::OverlapLevels::default()
    );
}

#[test]
fn wallsreact_lines_follow_ired_out_interval_when_above_0() {
    let flags = Flags::default();
    let with = |n: Option<u64>| Params {
        red_out_interval: n,
        ..par()
    };
    let reduced = |p: Params| walls_sim::config::outputs(&flags, Some(&p)).reduced;
    assert_eq!(reduced(with(Some(20))), Some(20));
    assert_eq!(reduced(with(Some(0))), None);
    assert_eq!(reduced(with(None)), None);
}

/// `walls-sim run` reads its particles straight into the states its run starts from
/// (`load_as`): the same settings, and a run of them the same as of the particles, to
/// the bit, with a particle stuck to a wall from the start (its negative colour) and one
/// of another size: bouncing, meeting, spinning.
#[test]
fn particles_read_as_states_run_as_the_particles() {
    use walls_sim::run::{Outcome, State, run_watched};
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("balls.csv");
    std::fs::write(
        &csv,
        "mass,radius,x,y,z,vx,vy,vz,wx,wy,wz,color\n\
         1,0.1,0,0,0.3,0,0,-2,0,1,0,3\n\
         1,0.1,0.15,0,0.45,0,0,-1,0,0,0,5\n\
         2,0.15,0,0,-0.85,0,0,0,0,0,0,-2\n",
    )
    .unwrap();
    let flags = Flags {
        inputs: Inputs {
            particles: Some(csv.to_string_lossy().into_owned()),
            t_end: Some(0.2),
            ..Inputs::default()
        },
        ..Flags::default()
    };
    let walls =
        scene("wall type plane origin 0 0 0 epsn 0.5\nwall type plane origin 0 0 -1 epsn 0\n");
    let particles = load(&flags, None, &walls).unwrap();
    let states = walls_sim::config::load_as::<State>(&flags, None, &walls).unwrap();
    assert_eq!(particles.settings, states.settings);
    let held: Vec<_> = states
        .particles
        .iter()
        .map(|s| s.particle.clone())
        .collect();
    assert_eq!(held, particles.particles);
    let run = |outcome: Outcome| {
        let bits = |s: &State| {
            let p = &s.particle;
            let v = [p.pos, p.vel, p.spin].map(|v| v.map(f64::to_bits));
            (
                v,
                s.alive,
                s.stuck_to
                    .as_deref()
                    .map(|&(w, at)| (w, at.map(f64::to_bits))),
            )
        };
        let states: Vec<_> = outcome.particles.iter().map(bits).collect();
        (
            outcome.steps,
            states,
            outcome.events.len(),
            outcome.energy.1.to_bits(),
        )
    };
    let settings = &particles.settings;
    let go =
        |particles: Vec<_>| run_watched(&walls, particles, settings, &mut |_, _, _| {}, &|| false);
    let from_particles = go(particles.particles);
    let from_states = run_watched(
        &walls,
        states.particles,
        settings,
        &mut |_, _, _| {},
        &|| false,
    );
    assert!(from_particles.steps > 1000);
    assert!(from_particles.particles[2].stuck_to.is_some());
    // A finished run's states (stuck, accelerated, spinning, one removed as a death
    // wall leaves it) start a run as their particles do: a state's particle alone is
    // taken.
    let mut ended = from_states.particles.clone();
    ended[1].alive = false;
    let as_particles: Vec<_> = ended.iter().map(|s| s.particle.clone()).collect();
    let again = run_watched(&walls, ended, settings, &mut |_, _, _| {}, &|| false);
    assert_eq!(run(again), run(go(as_particles)));
    assert_eq!(run(from_particles), run(from_states));
}
