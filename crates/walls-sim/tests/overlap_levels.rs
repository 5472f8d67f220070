//! pkdgrav's overlap levels in a soft-sphere run (docs/pkdgrav-physics.md §15): the
//! `.par` file's `dMinorFrac`, `dMajorFrac` and `dErrorFrac` (defaults 0.03, 0.15, 0.5),
//! an overlap x checked against frac·min(r₁, r₂) for pairs and frac·r for walls (strict
//! `>`, worst level first), every event counted at its level for pairs and walls apart,
//! the first of each warning level warned of, and the run stopped past the error level,
//! at t₀ too.

use walls_geometry::Particle;
use walls_sim::run::{
    LevelCounts, OverlapLevel, OverlapLevels, Overlapping, ParticleMaterial, Settings, Stop,
    Warning, default_dt, run, run_observed,
};
use walls_test_support::{ball, scene};

/// A soft run (k_n = 10³) of `particles` with the overlap `levels`: a particle at speed
/// 2 sinks deep into what it meets.
fn soft(particles: &[Particle], levels: OverlapLevels) -> Settings {
    let k_n = 1e3;
    Settings {
        overlap_levels: levels,
        ..Settings::new(
            default_dt(particles, k_n),
            1.0,
            ParticleMaterial {
                eps_n: 0.9,
                ..walls_sim::run::defaults::default_material(k_n)
            },
        )
    }
}

/// The counts a run should report from the overlaps seen after each step (`fractions`),
/// and the one past the error level it stopped at.
fn counted(fractions: &[f64], levels: &OverlapLevels) -> LevelCounts {
    let mut counts = LevelCounts::default();
    for f in fractions {
        match levels.level_of(*f) {
            Some(OverlapLevel::Minor) => counts.minor += 1,
            Some(OverlapLevel::Major) => counts.major += 1,
            Some(OverlapLevel::Error) => counts.error += 1,
            None => {}
        }
    }
    counts.error += 1;
    counts
}

/// The levels a run's overlap warnings name, with their codes.
fn levels_warned(warnings: &[Warning]) -> Vec<(&'static str, f64)> {
    warnings
        .iter()
        .filter_map(|w| match w {
            Warning::OverlapMinor { level, .. }
            | Warning::OverlapMajor { level, .. }
            | Warning::OverlapStop { level, .. } => Some((w.code(), *level)),
            _ => None,
        })
        .collect()
}

#[test]
fn a_particle_sinking_into_a_wall_is_counted_at_each_level_and_stops_past_the_error_one() {
    for levels in [
        OverlapLevels::default(),
        OverlapLevels {
            minor: 0.01,
            major: 0.05,
            error: 0.2,
        },
    ] {
        let ps = vec![ball([0.0, 0.0, 0.5], [0.0, 0.0, -2.0])];
        let s = soft(&ps, levels);
        let r = ps[0].radius;
        // The overlap after each step the run completed: r − z against the plane z = 0.
        let mut seen = Vec::new();
        let out = run_observed(&scene("wall type plane\n"), ps, &s, &mut |_, _, snap| {
            seen.push((r - snap.look().0[0].particle.pos.z) / r);
        });
        assert_eq!(out.stopped, Some(Stop::Overlap));
        let expected = counted(&seen, &levels);
        assert_eq!(out.overlaps.walls, expected, "{levels:?}");
        assert!(expected.minor > 0 && expected.major > 0, "{expected:?}");
        assert_eq!(out.overlaps.pairs, LevelCounts::default());
        // The first minor and major events, then the stop, each naming its level.
        assert_eq!(
            levels_warned(&out.warnings),
            [
                ("W101", levels.minor),
                ("W102", levels.major),
                ("W103", levels.error)
            ]
        );
        let Some(Warning::OverlapStop { fraction, .. }) = out.warnings.last() else {
            panic!("{:?}", out.warnings);
        };
        assert!(*fraction > levels.error && *fraction <= 2.0 * levels.error);
        assert!(out.warnings.last().unwrap().to_string().contains(&format!(
            "above dErrorFrac = {} of the particle's radius",
            levels.error
        )));
    }
}

#[test]
fn an_overlap_at_a_level_exactly_is_not_past_it() {
    let levels = OverlapLevels::default();
    assert_eq!(levels.level_of(0.03), None);
    assert_eq!(levels.level_of(0.15), Some(OverlapLevel::Minor));
    assert_eq!(levels.level_of(0.5), Some(OverlapLevel::Major));
    assert_eq!(levels.level_of(0.5000001), Some(OverlapLevel::Error));
    // With dMinorFrac = dMajorFrac, no overlap is a minor one.
    let equal = OverlapLevels {
        minor: 0.1,
        major: 0.1,
        error: 0.5,
    };
    assert_eq!(equal.level_of(0.1), None);
    assert_eq!(equal.level_of(0.11), Some(OverlapLevel::Major));
}

#[test]
fn a_pair_is_measured_against_the_smaller_radius_and_counted_apart_from_walls() {
    // Head-on, a large and a small particle, no walls.
    let mut big = ball([-0.2, 0.0, 0.0], [1.0, 0.0, 0.0]);
    big.radius = 0.15;
    let mut small = ball([0.2, 0.0, 0.0], [-1.0, 0.0, 0.0]);
    small.radius = 0.05;
    let ps = vec![big, small];
    let levels = OverlapLevels::default();
    let s = soft(&ps, levels);
    let mut seen = Vec::new();
    let out = run_observed(&[], ps, &s, &mut |_, t, snap| {
        let p = snap.look().0;
        let x = 0.15 + 0.05 - (p[0].particle.pos - p[1].particle.pos).norm();
        seen.push((t, x / 0.05));
    });
    assert_eq!(out.stopped, Some(Stop::Overlap));
    let fractions: Vec<f64> = seen.iter().map(|(_, f)| *f).collect();
    assert_eq!(out.overlaps.pairs, counted(&fractions, &levels));
    assert_eq!(out.overlaps.walls, LevelCounts::default());
    // The first minor event's fraction is the overlap over the smaller radius then.
    let Some(Warning::OverlapMinor {
        fraction, what, t, ..
    }) = out.warnings.first()
    else {
        panic!("{:?}", out.warnings);
    };
    assert_eq!(*what, Overlapping::Particles(0, 1));
    let (_, f) = seen.iter().find(|(at, _)| at == t).expect("observed");
    assert!((fraction - f).abs() < 1e-9, "{fraction} against {f}");
    assert!(
        out.warnings[0]
            .to_string()
            .contains("above dMinorFrac = 0.03 of the smaller radius")
    );
}

#[test]
fn an_initial_overlap_past_the_error_level_stops_the_run_at_t0() {
    // 60 % of the smaller radius at t₀: pkdgrav's first force evaluation aborts.
    let a = ball([0.0, 0.0, 0.0], [0.0; 3]);
    let b = ball([0.2 - 0.06, 0.0, 0.0], [0.0; 3]);
    let ps = vec![a, b];
    let out = run(&[], ps.clone(), &soft(&ps, OverlapLevels::default()));
    assert_eq!(out.stopped, Some(Stop::Overlap));
    assert_eq!(out.steps, 0);
    assert_eq!(
        out.overlaps.pairs,
        LevelCounts {
            minor: 0,
            major: 0,
            error: 1
        }
    );
    // With dErrorFrac = 0.7 it is a major event, and the run goes on.
    let lenient = OverlapLevels {
        error: 0.7,
        ..OverlapLevels::default()
    };
    let out = run(&[], ps.clone(), &soft(&ps, lenient));
    assert_eq!(out.stopped, None);
    assert_eq!(out.overlaps.pairs.error, 0);
    assert!(out.overlaps.pairs.major >= 1);
    assert_eq!(levels_warned(&out.warnings)[0], ("W102", 0.15));
}

#[test]
fn pairs_of_two_stuck_particles_are_not_counted() {
    // Two particles stuck to a wall from the start (colour −1: wall 0), overlapping by
    // 60 %: they meet nothing, and the run goes on.
    let mut a = ball([0.0, 0.0, 1.0], [0.0; 3]);
    let mut b = ball([0.14, 0.0, 1.0], [0.0; 3]);
    a.color = -1;
    b.color = -1;
    let ps = vec![a, b];
    let walls = scene("wall type plane\n  epsn 0\n");
    let out = run(&walls, ps.clone(), &soft(&ps, OverlapLevels::default()));
    assert_eq!(out.stopped, None, "{:?}", out.warnings);
    assert_eq!(out.overlaps.pairs, LevelCounts::default());
}
